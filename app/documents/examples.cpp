#include "examples.h"

#include <QCoreApplication>

#include <vector>

namespace rasterlab {

namespace {

// A shipped lesson: its name (pipeline/scene/lessons.h), its title and text (translated in
// the "Lessons" context), and how it opens.
struct Example {
    const char* name;
    const char* title;
    const char* notes;
    rl::ShadingModel shading;
    QSize imageSize;
    rl::StepGranularity granularity;
    std::optional<QPoint> pixel;
    const char* raised;  // the dock raised when it opens
    double nearW = 0.0;         // the near plane's w; 0: automatic
    bool fromStart = false;     // the cursor at the start of the frame, not its end
    int breakAtTriangle = 0;    // a breakpoint at this triangle's first row (1-based), if any
};

const std::vector<Example>& examples() {
    static const std::vector<Example> all = {
        {"triangle", QT_TRANSLATE_NOOP("Lessons", "One triangle"),
         QT_TRANSLATE_NOOP("Lessons",
                           "A single triangle in a 32 x 24 image, large enough to read from the "
                           "back of the room. Step by pixel (Page Down, or Right and Left in "
                           "presentation mode, F5) and "
                           "watch the scanline fill from its left edge to its right; pick a "
                           "pixel to see its barycentric coordinates, its interpolated P and N, "
                           "and its Phong terms in the pixel inspector."),
         rl::ShadingModel::Phong, QSize(32, 24), rl::StepGranularity::Pixel, QPoint(14, 12),
         "scanlineDock", 0.0, true},
        {"zbuffer", QT_TRANSLATE_NOOP("Lessons", "Two triangles that cross (the z-buffer)"),
         QT_TRANSLATE_NOOP("Lessons",
                           "Two triangles that pass through each other: each is nearer the "
                           "camera over half of the other, so no order of whole triangles draws "
                           "them right. It opens at the start of the frame with a breakpoint at "
                           "the second triangle: Continue to Breakpoint (F8) draws the first, then step by "
                           "scanline through the second and watch "
                           "the z-buffer dock: its pixels are kept above the crossing line and "
                           "rejected below it. Pick a pixel near the crossing to compare both "
                           "depths."),
         rl::ShadingModel::Phong, QSize(64, 48), rl::StepGranularity::Scanline, QPoint(32, 26),
         "zbufferDock", 0.0, true, 2},
        {"near-plane", QT_TRANSLATE_NOOP("Lessons", "A triangle through the near plane"),
         QT_TRANSLATE_NOOP("Lessons",
                           "A triangle on the floor whose far corner is behind the camera. The "
                           "near-plane clipping dock shows it cut at the near plane into a "
                           "quad, and the quad split into two triangles. Then choose Shading > "
                           "Projection > Plain Divide: the corner behind the eye is divided by "
                           "a negative z and lands above the horizon."),
         rl::ShadingModel::Phong, QSize(160, 120), rl::StepGranularity::Triangle, std::nullopt,
         "nearClipDock", 2.0},
        {"goblet", QT_TRANSLATE_NOOP("Lessons", "A goblet turned from a profile"),
         QT_TRANSLATE_NOOP("Lessons",
                           "A goblet made by turning a profile around the y axis (the course's "
                           "chalice idea, 1,520 triangles of our own). Start at the camera "
                           "basis dock, then follow the stages in order: view coordinates, "
                           "normals, projection, scan conversion, z-buffer and lighting. Pick "
                           "a pixel on the highlight of the bowl to see why it is bright."),
         rl::ShadingModel::Phong, QSize(800, 600), rl::StepGranularity::Stage, QPoint(353, 157),
         "cameraBasisDock"},
        {"sphere", QT_TRANSLATE_NOOP("Lessons", "A low-polygon sphere: flat, Gouraud, Phong"),
         QT_TRANSLATE_NOOP("Lessons",
                           "A sphere of 168 triangles. It opens in flat shading, one colour per "
                           "triangle; press the Shading menu's Gouraud and then Phong to compare "
                           "(File > Export More > Shading Side by Side puts the three in one "
                           "picture). Gouraud smooths the facets but blurs the highlight; Phong "
                           "draws it round."),
         rl::ShadingModel::Flat, QSize(640, 480), rl::StepGranularity::Triangle, QPoint(250, 160),
         "normalsDock"},
        {"lights", QT_TRANSLATE_NOOP("Lessons", "Several lights: spot, directional, attenuated"),
         QT_TRANSLATE_NOOP("Lessons",
                           "A floor and a ball under three lights of the lecture slides: a "
                           "yellow spot (the bright disc, with a soft edge from its exponent), a "
                           "dim blue directional light from the right, and a red positional "
                           "light whose strength falls with distance. Pick pixels inside and "
                           "outside the spot's cone and compare the pixel inspector's terms "
                           "light by light; change the lights in the Edit dock."),
         rl::ShadingModel::Phong, QSize(800, 600), rl::StepGranularity::Scanline, QPoint(330, 400),
         "pixelInspectorDock"},
        {"painter-cycle", QT_TRANSLATE_NOOP("Lessons", "Three triangles in a cycle (the painter)"),
         QT_TRANSLATE_NOOP("Lessons",
                           "Three triangles that each lie in front of the next: no order of "
                           "whole triangles can draw them right, so the painter's algorithm "
                           "(far to near by barycentre) must fail somewhere. Step by triangle "
                           "and see one painted over a nearer one; the painter's algorithm dock "
                           "marks the pixels that differ from the z-buffer's image."),
         rl::ShadingModel::Painter, QSize(320, 240), rl::StepGranularity::Triangle, std::nullopt,
         "painterDock", 0.0, true},
        {"gouraud", QT_TRANSLATE_NOOP("Lessons", "Gouraud's faults: Mach bands, a missed highlight"),
         QT_TRANSLATE_NOOP("Lessons",
                           "Left, a coarse sphere in Gouraud shading: the brightness bends at "
                           "every edge and the eye sees bands there (Mach bands). Right, a "
                           "square of two triangles whose highlight falls between its corners: "
                           "Gouraud lights only the corners and misses it. Switch to Phong "
                           "shading and the highlight appears in the middle of the square."),
         rl::ShadingModel::Gouraud, QSize(640, 480), rl::StepGranularity::Scanline, QPoint(440, 240),
         "pixelInspectorDock"},
    };
    return all;
}

const Example* find(const QString& name) {
    for (const Example& e : examples())
        if (name == QLatin1String(e.name)) return &e;
    return nullptr;
}

}  // namespace

QStringList exampleNames() {
    QStringList names;
    for (const Example& e : examples()) names << QString::fromLatin1(e.name);
    return names;
}

bool isExample(const QString& name) {
    return find(name) != nullptr;
}

QString exampleTitle(const QString& name) {
    const Example* e = find(name);
    return e ? QCoreApplication::translate("Lessons", e->title) : QString();
}

QString exampleNotes(const QString& name) {
    const Example* e = find(name);
    return e ? QCoreApplication::translate("Lessons", e->notes) : QString();
}

QString exampleFolder(const QString& name) {
    return QStringLiteral(":/lessons/") + name;
}

QString exampleLessonPath(const QString& name) {
    return exampleFolder(name) + QLatin1Char('/') + name + QStringLiteral(".rasterlab");
}

std::optional<QString> exampleOfPath(const QString& path) {
    const QString prefix = QStringLiteral(":/lessons/");
    if (!path.startsWith(prefix)) return std::nullopt;
    const QString name = path.mid(prefix.size()).section(QLatin1Char('/'), 0, 0);
    if (!isExample(name)) return std::nullopt;
    return name;
}

Lesson exampleLesson(const QString& name) {
    Lesson lesson;
    const Example* e = find(name);
    if (!e) return lesson;
    lesson.example = name;
    lesson.shading = e->shading;
    lesson.rules = rl::RuleSet::Course;
    lesson.projection = rl::NearPlane::Mode::Clip;
    lesson.imageSize = e->imageSize;
    lesson.granularity = e->granularity;
    lesson.pixel = e->pixel;
    // The lesson's own dock, and the Scene dock, whose text says what to show with it.
    lesson.docksRaised = QStringList{QString::fromLatin1(e->raised), QStringLiteral("sceneDock")};
    if (e->nearW > 0.0) lesson.nearW = e->nearW;
    if (e->fromStart) lesson.cursor = rl::ReplayCursor{0, 0};
    if (e->breakAtTriangle > 0) {
        rl::Breakpoint b;
        b.kind = rl::Breakpoint::Kind::Triangle;
        b.triangle = std::uint32_t(e->breakAtTriangle);
        lesson.breakpoints = std::vector<rl::Breakpoint>{b};
    }
    return lesson;
}

}  // namespace rasterlab
