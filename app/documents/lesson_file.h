// A lesson file (.rasterlab): a teacher's setup of a demo, kept as JSON so that it can be read
// and written by hand (docs/lesson-files.md describes every key). It holds the scene (an
// example's name, or course or command files by paths relative to the lesson), the values
// edited and not saved, shading, rules and projection, the image size, the stepping
// granularity and cursor, the picked pixel, the breakpoints, zoom and pan, the docks,
// presentation mode and the text zoom. Every key but "rasterlab_lesson" may be left out: what is absent keeps
// the program's default.
#pragma once

#include <QByteArray>
#include <QPoint>
#include <QPointF>
#include <QSize>
#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

#include "app/documents/scene_document.h"
#include "pipeline/core/diagnostics.h"
#include "pipeline/core/stage_id.h"
#include "pipeline/render/replay.h"

namespace rasterlab {

struct Lesson {
    static constexpr int kVersion = 1;  // "rasterlab_lesson": 1

    QString title;
    QString notes;  // what to show with it, in the teacher's words

    // ---- The scene: an example, course files, or a command file ---------------------
    QString example;  // a shipped lesson's name (File > Examples)
    QString camera, lighting, object;
    QString commandFile;
    int commandImage = 0;  // which of the command file's images
    rl::CameraLayout cameraLayout = rl::CameraLayout::Auto;
    rl::LightingLayout lightingLayout = rl::LightingLayout::Auto;

    // ---- Values edited and not saved to the course files ----------------------------
    struct Edit {
        SceneDocument::Field field = SceneDocument::Field::C;
        std::size_t light = 0;
        SceneDocument::Numbers value{};
        bool operator==(const Edit&) const = default;
    };
    std::vector<Edit> edits;
    std::optional<std::size_t> lightCount;  // when lights were added or removed

    // ---- Rendering ---------------------------------------------------------------------
    std::optional<rl::ShadingModel> shading;
    std::optional<rl::RuleSet> rules;
    std::optional<rl::NearPlane::Mode> projection;
    std::optional<double> nearW;  // the near plane's fixed w; absent: automatic
    std::optional<QSize> imageSize;
    std::optional<SceneDocument::Animation> animation;

    // ---- Stepping ----------------------------------------------------------------------
    std::optional<rl::StepGranularity> granularity;
    std::optional<rl::StageId> stage;
    std::optional<rl::ReplayCursor> cursor;  // absent: the end of the frame
    std::optional<QPoint> pixel;
    // A Triangle breakpoint's `triangle` is the object file's 1-based number.
    std::optional<std::vector<rl::Breakpoint>> breakpoints;

    // ---- The window ----------------------------------------------------------------------
    std::optional<double> zoom;     // absent: the image fits the view
    std::optional<QPointF> centre;  // the image point at the view's centre
    QStringList docksShown;         // object names; empty: as the layout has them
    QStringList docksRaised;        // the docks on top of their tab groups
    QByteArray dockState;           // QMainWindow::saveState, when saved by the program
    std::optional<bool> presentation;
    std::optional<double> textZoom;  // the docks' text size, 1 the window's; absent: 1

    // ---- Check My Renderer: the student's program and its folder ----------------------
    QString checkCommand, checkFolder;

    bool operator==(const Lesson&) const = default;
};

// The lesson in a file's text; fileName names it in messages ("lesson.rasterlab:3:14: ...").
// Keys it does not know are warned about and skipped.
rl::Result<Lesson> parseLesson(const QByteArray& text, const QString& fileName,
                               rl::Diagnostics& diagnostics);
// Reads a lesson file (within the input size limit).
rl::Result<Lesson> readLesson(const QString& path, rl::Diagnostics& diagnostics);
// The lesson as indented JSON, keys in the order of the struct above.
QByteArray lessonJson(const Lesson& lesson);

// Names used in lesson files ("phong", "scanline", "clip" ...).
QString granularityKey(rl::StepGranularity granularity);
std::optional<rl::StepGranularity> granularityFromKey(const QString& key);

}  // namespace rasterlab
