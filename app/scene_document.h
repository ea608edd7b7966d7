// The scene being shown: either a course scene, its three parts (camera, lighting, object)
// with where each came from, their warnings and the render settings, or a command file
// (seed 001) and the image of it being shown. Each course part is replaced on its own; a
// file that fails to load leaves everything as it was.
#pragma once

#include <QString>
#include <QStringList>

#include <memory>
#include <optional>

#include "course_scene.h"
#include "default_scene_resource.h"
#include "diagnostics.h"
#include "hw2_reader.h"
#include "scene.h"

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
    void setSize(int width, int height);

    std::shared_ptr<const rl::Scene> scene() const;

private:
    static std::size_t index(Part part) { return static_cast<std::size_t>(part); }

    bool m_loaded = false;
    rl::CourseSceneParts m_parts;
    QString m_sources[3];
    rl::Diagnostics m_partDiagnostics[3];
    rl::CourseSceneSettings m_settings;
    rl::CameraLayout m_cameraLayout = rl::CameraLayout::Auto;
    rl::LightingLayout m_lightingLayout = rl::LightingLayout::Auto;
    std::optional<rl::Hw2File> m_commandFile;
    QString m_commandFilePath;
    rl::Diagnostics m_commandFileDiagnostics;
    int m_imageIndex = 0;
};

}  // namespace rasterlab
