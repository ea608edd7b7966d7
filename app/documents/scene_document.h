// The scene being shown: either a course scene, its three parts (camera, lighting, object)
// with where each came from, their warnings and the render settings, or a command file
// (seed 001) and the image of it being shown. Each course part is replaced on its own; a
// file that fails to load leaves everything as it was.
//
// The course scene's camera and lighting can also be edited in place (the edit panel) and
// saved back to their files, in the layout each was read in (course_writers.h). A part is
// modified while its values differ from its file's (as read or as last saved), so undoing
// every change makes it unmodified again.
#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>

#include "app/documents/default_scene_resource.h"
#include "pipeline/core/diagnostics.h"
#include "pipeline/io/course_scene.h"
#include "pipeline/io/hw2_reader.h"
#include "pipeline/scene/scene.h"

namespace rasterlab {

class SceneDocument {
public:
    using Part = CoursePart;

    // The embedded default scene; fails only if the resources are broken.
    rl::Status loadDefault();
    // Replaces one part from a file, and shows the course scene again if a command file
    // was shown; on error nothing changes. A command file opened as the object is opened
    // as a command file.
    rl::Status open(Part part, const QString& path);
    // Shows a command file's first image; on error nothing changes.
    rl::Status openCommandFile(const QString& path);

    bool isLoaded() const { return m_loaded; }
    bool showsCommandFile() const { return m_commandFile.has_value(); }
    QString commandFilePath() const { return m_commandFilePath; }
    // The names of the command file's images (its png commands), and which one is shown.
    QStringList imageNames() const;
    int imageIndex() const { return m_imageIndex; }
    void setImageIndex(int index);
    const rl::CourseSceneParts& parts() const { return m_parts; }
    QString source(Part part) const { return m_sources[index(part)]; }
    rl::Diagnostics diagnostics() const;  // of all three parts in order, or of the command file

    // The layouts camera and lighting files are read in (Auto: detected). Setting one
    // re-reads the current file of that part in it; on error the layout is set and the
    // previous part stays.
    rl::CameraLayout cameraLayout() const { return m_cameraLayout; }
    rl::LightingLayout lightingLayout() const { return m_lightingLayout; }
    rl::Status setCameraLayout(rl::CameraLayout layout);
    rl::Status setLightingLayout(rl::LightingLayout layout);

    rl::CourseSceneSettings settings() const { return m_settings; }
    void setShading(rl::ShadingModel model) { m_settings.shading = model; }
    void setRules(rl::RuleSet rules) { m_settings.rules = rl::rulesOf(rules); }
    // What happens to triangles at or behind the eye: the course scene's choice (clipping at
    // the near plane unless chosen otherwise), or the command file's (seed 001's plain divide
    // unless chosen otherwise, reset when a command file is opened).
    rl::NearPlane::Mode projection() const;
    void setProjection(rl::NearPlane::Mode mode);
    void setSize(int width, int height);
    // The near plane's fixed w (the course's view z), or automatic (nullopt).
    void setNearW(std::optional<double> w) { m_settings.nearPlane.fixedW = w; }

    std::shared_ptr<const rl::Scene> scene() const;

    // ---- Animation (seed 002's M) ----------------------------------------------------
    // Part of the session, not of the course files (they have no such field): saving writes
    // none of it, and opening a file keeps it. When on, every draw of scene() gets the
    // animation and the scene the time.
    struct Animation {
        bool enabled = false;
        rl::Animation motion;
        double time = 0.0;  // seconds
        bool operator==(const Animation&) const = default;
    };
    const Animation& animation() const { return m_animation; }
    void setAnimation(const Animation& animation) { m_animation = animation; }

    // ---- Editing without files -------------------------------------------------------
    // The values of the course scene, changed in place one field at a time (the sources,
    // warnings and layouts stay those of the files), as up to three numbers (x y z, r g b, or
    // one number in [0]): what the edit panel and its undo commands hold. Shading is the
    // ShadingModel's value (as setShading); it belongs to no file. A light out of range reads
    // as zeros and is not set.
    enum class Field : std::uint8_t {
        C,
        N,
        V,
        D,
        Hx,
        Hy,
        LightPosition,   // Pl of one light (x y z)
        LightIntensity,  // Il of one light
        // The lecture slides' lighting (seed 003), of one light: 1 for a directional light
        // (w = 0, Pl the direction toward it), 0 for a positional one; attenuation kc kl kq;
        // spot direction, cutoff (degrees, 180: not a spot) and exponent.
        LightDirectional,
        LightAttenuation,
        LightSpotDirection,
        LightSpotCutoff,
        LightSpotExponent,
        Ambient,  // Ia
        Ka,
        Kd,  // per channel
        Od,
        Ks,
        Shininess,   // n
        Emission,    // Ke
        TwoSided,    // 1: N turned toward the viewer (the course's), 0: one-sided
        BlinnPhong,  // 1: Blinn-Phong highlights, 0: Phong's
        Shading,
    };
    // Whether a field is one light's (set with the light's index).
    static bool isLightField(Field field);
    using Numbers = std::array<double, 3>;
    static int componentCount(Field field);          // 3 or 1
    static std::optional<Part> partOf(Field field);  // Camera, Lighting, or none (Shading)
    Numbers value(Field field, std::size_t light = 0) const;
    void setValue(Field field, const Numbers& value, std::size_t light = 0);
    // Lights added or removed (the edit panel's Add and Remove, undoable): insertLight puts
    // `light` at `index` (at most the count), takeLight removes the light at `index` and
    // returns it; the lighting keeps one light at least (false / nullopt otherwise).
    bool insertLight(std::size_t index, const rl::Light& light);
    std::optional<rl::Light> takeLight(std::size_t index);

    // Whether the camera (lighting) differs from its file; the object is never modified.
    bool isModified(Part part) const;
    bool isModified() const;
    // Bumped whenever the camera or lighting is replaced from a file (open, a layout chosen,
    // the default scene): what was edited before no longer applies (the edit panel clears its
    // undo history).
    std::uint64_t partsReplaced() const { return m_partsReplaced; }

    // The layout each file is in, which save() writes: the one chosen (cameraLayout()) or, for
    // Auto, the one detected when it was read (UFPE for the embedded default scene); after
    // saveAs, the one written.
    rl::CameraLayout cameraFileLayout() const { return m_cameraFileLayout; }
    rl::LightingLayout lightingFileLayout() const { return m_lightingFileLayout; }
    // Whether save(part) needs a path first: the part comes from the resources (":/...").
    bool needsPath(Part part) const;
    // Writes the camera or lighting to its file in its layout, atomically (QSaveFile: the old
    // file stays whole if anything fails), then reads the text back to check it and to point
    // the warnings at the new lines; the part is then unmodified. A key = value file keeps its
    // other lines (course_writers.h), a file its line ending. A camera without a basis (N or V
    // zero or parallel, d, hx or hy zero) is not saved: it would not load again. On error
    // nothing changes.
    rl::Status save(Part part);
    // The same to another file, which the part comes from afterwards: in the part's file
    // layout, or in the one given.
    rl::Status saveAs(Part part, const QString& path);
    rl::Status saveCameraAs(const QString& path, rl::CameraLayout layout);
    rl::Status saveLightingAs(const QString& path, rl::LightingLayout layout);
    // Whether the part's file holds the bytes this document last saved there (a file watcher
    // can then tell the document's own save from another program's change).
    bool fileHoldsLastSave(Part part) const;

private:
    static std::size_t index(Part part) { return static_cast<std::size_t>(part); }
    rl::Status writePart(Part part, const QString& path, rl::CameraLayout cameraLayout,
                         rl::LightingLayout lightingLayout);

    bool m_loaded = false;
    rl::CourseSceneParts m_parts;
    QString m_sources[3];
    rl::Diagnostics m_partDiagnostics[3];
    rl::CourseSceneSettings m_settings;
    rl::CameraLayout m_cameraLayout = rl::CameraLayout::Auto;
    rl::LightingLayout m_lightingLayout = rl::LightingLayout::Auto;
    std::optional<rl::Hw2File> m_commandFile;
    rl::NearPlane::Mode m_commandFileProjection = rl::NearPlane::Mode::Naive;
    QString m_commandFilePath;
    rl::Diagnostics m_commandFileDiagnostics;
    int m_imageIndex = 0;

    // Editing: the values of the files (as read or last saved), their layouts, what was saved.
    rl::CourseCamera m_fileCamera;
    rl::CourseLighting m_fileLighting;
    rl::CameraLayout m_cameraFileLayout = rl::CameraLayout::Ufpe;
    rl::LightingLayout m_lightingFileLayout = rl::LightingLayout::Ufpe;
    QByteArray m_lastSaved[2];  // camera, lighting
    std::uint64_t m_partsReplaced = 0;
    Animation m_animation;
};

}  // namespace rasterlab
