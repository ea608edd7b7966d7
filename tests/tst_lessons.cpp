// The lessons that ship (pipeline/scene/lessons.h, app/documents/examples.h): their files are the
// generator's output, each scene shows what its text promises, and lesson files
// (app/documents/lesson_file.h) keep a teacher's setup, also across processes and language switches.
#include <QAction>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QListWidget>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

#include "app/documents/default_scene_resource.h"
#include "app/documents/examples.h"
#include "app/documents/input_file.h"
#include "app/documents/lesson_file.h"
#include "app/image_io.h"
#include "app/window/edit_panel.h"
#include "app/window/main_window.h"
#include "pipeline/analysis/painter.h"
#include "pipeline/io/course_scene.h"
#include "pipeline/render/output_image.h"
#include "pipeline/scene/lessons.h"
#include "pipeline/scene/mesh_topology.h"
#include "tests/test_support.h"
#include "views/breakpoints_view.h"
#include "views/frame_image_view.h"

using namespace rasterlab;
using testing::CliRun;

namespace {

constexpr int kTimeoutMs = 30000;

// A shipped lesson's scene, with the settings it opens with.
std::shared_ptr<const rl::Scene> lessonScene(const QString& name,
                                             std::optional<rl::ShadingModel> shading = {},
                                             rl::NearPlane::Mode mode = rl::NearPlane::Mode::Clip) {
    rl::Diagnostics diagnostics;
    const QString folder = exampleFolder(name) + QLatin1Char('/');
    auto camera = loadCamera(folder + QStringLiteral("camera.cfg"), diagnostics);
    auto lighting = loadLighting(folder + QStringLiteral("lighting.txt"), diagnostics);
    auto object = loadObject(folder + name + QStringLiteral(".byu"), diagnostics);
    if (!camera || !lighting || !object) return nullptr;
    const Lesson lesson = exampleLesson(name);
    rl::CourseSceneSettings settings;
    settings.width = lesson.imageSize->width();
    settings.height = lesson.imageSize->height();
    settings.shading = shading.value_or(*lesson.shading);
    settings.nearPlane.fixedW = lesson.nearW;
    settings.nearPlane.mode = mode;
    return std::make_shared<const rl::Scene>(
        rl::makeCourseScene({camera.value(), lighting.value(), object.value()}, settings));
}

// The same scene with only one of its triangles.
std::shared_ptr<const rl::Scene> oneTriangle(const rl::Scene& scene, std::uint32_t t) {
    rl::Scene single = scene;
    auto mesh = std::make_shared<rl::Mesh>(*scene.draws.front().mesh);
    mesh->triangles = {mesh->triangles[t]};
    mesh->triangleLines.clear();
    single.draws.front().mesh = mesh;
    return std::make_shared<const rl::Scene>(std::move(single));
}

QRgb pixelOf(const std::shared_ptr<const rl::Scene>& scene, int x, int y) {
    const auto trace = testing::renderTrace(scene);
    const rl::Rgba8Image image = rl::colourImage(*trace->shading, *trace->depth, scene->conventions);
    const std::uint8_t* p = image.pixel(x, y);
    return qRgb(p[0], p[1], p[2]);
}

bool waitUntilReady(const MainWindow& window) {
    QElapsedTimer timer;
    timer.start();
    while (window.lessonViewPending() || !window.isReadyToStep()) {
        if (timer.elapsed() > kTimeoutMs) return false;
        QTest::qWait(20);
    }
    return true;
}

QString writeText(const QTemporaryDir& dir, const QString& name, const QByteArray& text) {
    QFile file(dir.filePath(name));
    if (!file.open(QIODevice::WriteOnly) || file.write(text) != text.size()) return {};
    return file.fileName();
}

}  // namespace

class TestLessons : public QObject {
    Q_OBJECT

private slots:
    void namesAgree();
    void resourcesAreTheGeneratorsOutput();
    void everyLessonLoadsCleanly_data();
    void everyLessonLoadsCleanly();
    void triangleCoversItsPixels();
    void zbufferTrianglesCross();
    void nearPlaneClipsIntoTwoTriangles();
    void closedSurfaces();
    void lightsOfThreeKinds();
    void painterCycleHasNoOrder();
    void gouraudMissesTheHighlight();
    void lessonFileRoundTrip();
    void badLessonFiles_data();
    void badLessonFiles();
    void unknownKeyWarns();
    void documentedExampleReads();
    void examplesMenuOpensEveryLesson();
    void shadingSideBySide();
    void savedLessonReopensInAnotherProcess();
    void lessonSavedPresentingGivesTheLayoutBack();
    void missingFileOpensTheRest();
    void inputFilesReadWithinTheLimit();
    void languageSwitchKeepsTheView();
    void cliRendersALesson();
};

void TestLessons::namesAgree() {
    QStringList pipelineNames;
    for (const std::string& name : rl::lessonNames()) {
        pipelineNames << QString::fromStdString(name);
        const auto files = rl::generateLesson(name);
        QVERIFY(files);
        QCOMPARE(files->name, name);
        QCOMPARE(files->objectFile, name + ".byu");  // the name the window opens
    }
    QCOMPARE(pipelineNames, exampleNames());
    QVERIFY(!rl::generateLesson("nope"));
    for (const QString& name : exampleNames()) {
        QVERIFY(!exampleTitle(name).isEmpty());
        QVERIFY(exampleNotes(name).size() > 100);
    }
}

void TestLessons::resourcesAreTheGeneratorsOutput() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    CliRun run;
    QVERIFY2(testing::runCli({QStringLiteral("generate-lessons"), QStringLiteral("--dir"),
                              QStringLiteral("out")},
                             dir.path(), run),
             qPrintable(run.problem));
    QCOMPARE(run.err, QString());
    QCOMPARE(run.exitCode, 0);
    QCOMPARE(run.out.count(QStringLiteral("wrote ")), 4 * int(exampleNames().size()));
    const QDir committed(testing::sourceDir() + QStringLiteral("/resources/lessons"));
    QCOMPARE(committed.entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name),
             [] {
                 QStringList names = exampleNames();
                 names.sort();
                 return names;
             }());
    for (const QString& name : exampleNames()) {
        const QStringList files = QDir(committed.filePath(name)).entryList(QDir::Files, QDir::Name);
        QStringList expected = {QStringLiteral("camera.cfg"), QStringLiteral("lighting.txt"),
                                name + QStringLiteral(".byu"), name + QStringLiteral(".rasterlab")};
        expected.sort();
        QCOMPARE(files, expected);
        for (const QString& file : files) {
            const QString relative = name + QLatin1Char('/') + file;
            QVERIFY2(testing::readFile(dir.filePath(QStringLiteral("out/") + relative)) ==
                         testing::readFile(committed.filePath(relative)),
                     qPrintable(relative + QStringLiteral(" differs from the generator's output; "
                                                          "run rasterlab-cli generate-lessons "
                                                          "--dir resources/lessons")));
        }
    }
}

void TestLessons::everyLessonLoadsCleanly_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("triangles");
    // triangle counts: 1, 2, 1, a goblet of 40 turns of a 21-point profile (two points on
    // the axis), 2 x 12 x 7, a 24 x 24 floor and a 32 x 16 ball, 3, a 10 x 7 ball and a square
    const int counts[] = {1, 2, 1, 40 * 2 * 19, 168, 24 * 24 * 2 + 2 * 32 * 15, 3, 2 * 10 * 6 + 2};
    int i = 0;
    for (const QString& name : exampleNames()) QTest::newRow(qPrintable(name)) << name << counts[i++];
}

void TestLessons::everyLessonLoadsCleanly() {
    QFETCH(QString, name);
    QFETCH(int, triangles);
    rl::Diagnostics diagnostics;
    const QString folder = exampleFolder(name) + QLatin1Char('/');
    QVERIFY(loadCamera(folder + QStringLiteral("camera.cfg"), diagnostics));
    QVERIFY(loadLighting(folder + QStringLiteral("lighting.txt"), diagnostics));
    QVERIFY(loadObject(folder + name + QStringLiteral(".byu"), diagnostics));
    QCOMPARE(diagnostics.size(), std::size_t(0));  // no warning, and no note on the layouts
    const auto scene = lessonScene(name);
    QVERIFY(scene);
    QCOMPARE(int(scene->triangleCount()), triangles);
    const auto trace = testing::renderTrace(scene);
    QVERIFY(trace->depth->coveredPixels() > 0);
    QCOMPARE(trace->projection->behind, std::size_t(0));
    // Its example lesson file reads back as the lesson the catalogue describes.
    rl::Diagnostics warnings;
    const auto lesson = readLesson(exampleLessonPath(name), warnings);
    QVERIFY(lesson);
    QVERIFY(warnings.empty());
    QCOMPARE(*lesson, exampleLesson(name));
}

// The triangle's vertices, worked out by hand: x = (x_world / 4 + 1) 16, y = (1 - y_world / 3)
// 12, truncated: (-2.6, -2.1) -> (5.6, 20.4) -> (5, 20); (3.1, -0.9) -> (28, 15);
// (-0.4, 2.45) -> (14.4, 2.2) -> (14, 2). The course samples pixels at their corners and keeps
// those on an edge: the pixels it covers are the integer points inside or on the triangle.
void TestLessons::triangleCoversItsPixels() {
    const auto trace = testing::renderTrace(lessonScene(QStringLiteral("triangle")));
    const std::array<rl::dvec2, 3> v =
        rl::screenVertices(*trace->projection, trace->projection->triangles.front());
    QCOMPARE(v[0], rl::dvec2(5, 20));
    QCOMPARE(v[1], rl::dvec2(28, 15));
    QCOMPARE(v[2], rl::dvec2(14, 2));
    const auto edge = [](rl::dvec2 a, rl::dvec2 b, rl::dvec2 p) {
        return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    };
    int inside = 0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 32; ++x) {
            const rl::dvec2 p(x, y);
            const double e0 = edge(v[0], v[1], p), e1 = edge(v[1], v[2], p), e2 = edge(v[2], v[0], p);
            const bool in = (e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0);
            inside += in;
            QCOMPARE(trace->depth->triangle.at(x, y) != rl::kNoTriangle, in);
        }
    QCOMPARE(int(trace->depth->coveredPixels()), inside);
}

void TestLessons::zbufferTrianglesCross() {
    const auto trace = testing::renderTrace(lessonScene(QStringLiteral("zbuffer")));
    // Each triangle wins some pixels, and the second loses some to the first: neither order
    // of the two whole triangles would draw them right.
    std::array<int, 2> won{};
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x)
            if (const std::uint32_t t = trace->depth->triangle.at(x, y); t != rl::kNoTriangle) ++won[t];
    QVERIFY(won[0] > 200);
    QVERIFY(won[1] > 200);
    QVERIFY(trace->depth->rejected > 50);
}

void TestLessons::nearPlaneClipsIntoTwoTriangles() {
    const auto clipped = testing::renderTrace(lessonScene(QStringLiteral("near-plane")));
    QCOMPARE(clipped->projection->clipped, std::size_t(1));
    QCOMPARE(clipped->projection->triangles.size(), std::size_t(2));  // the quad, split
    // The quad's near edge lies on the near plane w = 2 (view z), whose floor points are at
    // y_ndc = -(1 / 0.6)(1 / 2) = -5/6: row (1 + 5/6) 60 = 110 on the 120-row image.
    int lowest = 0;
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 160; ++x)
            if (clipped->depth->triangle.at(x, y) != rl::kNoTriangle) lowest = std::max(lowest, y);
    QCOMPARE(lowest, 110);
    // Divided without clipping, the corner behind the eye (view z = -6) lands above the
    // horizon (row 60): y_ndc = (1 / 0.6)(-1 / -6) > 0.
    const auto plain = testing::renderTrace(lessonScene(QStringLiteral("near-plane"), std::nullopt,
                                                        rl::NearPlane::Mode::Naive));
    const auto v = rl::screenVertices(*plain->projection, plain->projection->triangles.front());
    QVERIFY(std::min({v[0].y, v[1].y, v[2].y}) < 60.0);
}

void TestLessons::closedSurfaces() {
    // The goblet and the spheres are closed solids (every edge shared by two triangles, wound
    // the same way); the lights' floor is open.
    for (const char* name : {"goblet", "sphere"}) {
        const auto scene = lessonScene(QString::fromLatin1(name));
        QVERIFY2(rl::closedSurfaceWinding(*scene->draws.front().mesh) != 0, name);
    }
    QCOMPARE(rl::closedSurfaceWinding(*lessonScene(QStringLiteral("lights"))->draws.front().mesh), 0);
}

void TestLessons::lightsOfThreeKinds() {
    const auto scene = lessonScene(QStringLiteral("lights"));
    QCOMPARE(scene->lights.size(), std::size_t(3));
    QVERIFY(scene->lights[0].spot());
    QCOMPARE(scene->lights[0].spotCutoff, 25.0f);
    QCOMPARE(scene->lights[1].pWorld.w, 0.0);  // directional
    QVERIFY(scene->lights[2].attenuated());
    QCOMPARE(scene->lights[2].attenuation, rl::vec3(1.0f, 0.0f, 0.6f));
}

// Rendered one by one, each pair of blades overlaps somewhere, and there one is always in
// front: blade 0 before 1, 1 before 2 and 2 before 0 (or the reverse), a cycle.
void TestLessons::painterCycleHasNoOrder() {
    const auto scene = lessonScene(QStringLiteral("painter-cycle"), rl::ShadingModel::Flat);
    rl::RenderOptions keep;
    keep.keepDepth = true;
    std::vector<std::shared_ptr<const rl::FrameTrace>> single;
    for (std::uint32_t t = 0; t < 3; ++t) single.push_back(testing::renderTrace(oneTriangle(*scene, t), keep));
    const auto inFront = [&](int a, int b) {  // +1: a always nearer, -1: b always, 0: mixed
        int nearer = 0, farther = 0;
        for (int y = 0; y < scene->height; ++y)
            for (int x = 0; x < scene->width; ++x) {
                const float za = single[std::size_t(a)]->depth->depth.at(x, y);
                const float zb = single[std::size_t(b)]->depth->depth.at(x, y);
                if (std::isinf(za) || std::isinf(zb)) continue;
                (za < zb ? nearer : farther)++;
            }
        return nearer > 0 && farther == 0 ? 1 : farther > 0 && nearer == 0 ? -1 : 0;
    };
    const int r01 = inFront(0, 1), r12 = inFront(1, 2), r20 = inFront(2, 0);
    QVERIFY(r01 != 0);
    QCOMPARE(r12, r01);
    QCOMPARE(r20, r01);
    const auto painted = rl::compareWithZBuffer(lessonScene(QStringLiteral("painter-cycle")));
    QVERIFY(painted);
    QVERIFY(painted->wrongOrder > 100);
}

// The square's centre (2.1, 0, 0) is at pixel (488, 240); its highlight is there. Phong
// lights that pixel near white; Gouraud, lighting the corners only, leaves it the square's red.
void TestLessons::gouraudMissesTheHighlight() {
    const QRgb phong = pixelOf(lessonScene(QStringLiteral("gouraud"), rl::ShadingModel::Phong), 488, 240);
    const QRgb gouraud = pixelOf(lessonScene(QStringLiteral("gouraud")), 488, 240);
    QVERIFY2(qRed(phong) == 255 && qGreen(phong) > 220, qPrintable(QString::number(phong, 16)));
    QVERIFY2(qGreen(gouraud) < 140, qPrintable(QString::number(gouraud, 16)));
}

void TestLessons::lessonFileRoundTrip() {
    Lesson l;
    l.title = QStringLiteral("Aula 3 — \"z-buffer\"");
    l.notes = QStringLiteral("Line one\nline two");
    l.camera = QStringLiteral("../course/calice2.cfg");
    l.lighting = QStringLiteral(":/lessons/lights/lighting.txt");
    l.object = QStringLiteral("calice2.byu");
    l.cameraLayout = rl::CameraLayout::Ufrpe6;
    l.lightingLayout = rl::LightingLayout::KeyValue;
    l.edits = {{SceneDocument::Field::C, 0, {0.1, -2.5, 1e-7}},
               {SceneDocument::Field::D, 0, {1.0 / 3.0, 0, 0}},
               {SceneDocument::Field::Ka, 0, {0.25, 0, 0}},
               {SceneDocument::Field::LightPosition, 0, {1, 2, 3}},
               {SceneDocument::Field::LightSpotCutoff, 1, {30, 0, 0}}};
    l.lightCount = 2;
    l.shading = rl::ShadingModel::Gouraud;
    l.rules = rl::RuleSet::Gpu;
    l.projection = rl::NearPlane::Mode::SameSide;
    l.nearW = 0.5;
    l.imageSize = QSize(320, 200);
    SceneDocument::Animation a;
    a.enabled = true;
    a.time = 1.25;
    a.motion.axis = rl::dvec3(0, 0, 1);
    a.motion.velocity = rl::dvec3(1, 0, 0);
    l.animation = a;
    l.granularity = rl::StepGranularity::Span;
    l.stage = rl::StageId::DepthTest;
    l.cursor = rl::ReplayCursor{12, 345};
    l.pixel = QPoint(7, 9);
    rl::Breakpoint scanline;
    scanline.kind = rl::Breakpoint::Kind::Scanline;
    scanline.y = 40;
    scanline.enabled = false;
    rl::Breakpoint nth;
    nth.kind = rl::Breakpoint::Kind::NthWrite;
    nth.x = 3;
    nth.y = 4;
    nth.n = 3;
    l.breakpoints = std::vector<rl::Breakpoint>{scanline, nth};
    l.zoom = 6.5;
    l.centre = QPointF(12.25, 7.5);
    l.docksShown = QStringList{QStringLiteral("zbufferDock"), QStringLiteral("editDock")};
    l.docksRaised = QStringList{QStringLiteral("zbufferDock")};
    l.dockState = QByteArray("\x00\x01state\xff", 9);
    l.presentation = true;
    const QByteArray json = lessonJson(l);
    rl::Diagnostics warnings;
    const auto back = parseLesson(json, QStringLiteral("l.rasterlab"), warnings);
    QVERIFY2(back, back ? "" : back.error().toString().c_str());
    QVERIFY(warnings.empty());
    QVERIFY(*back == l);
    QCOMPARE(lessonJson(*back), json);
    QVERIFY(json.startsWith("{\n    \"rasterlab_lesson\": 1,\n    \"title\": "));
    QVERIFY(json.contains("\"image_size\": [320, 200],"));
    QVERIFY(json.contains("\"d\": 0.3333333333333333"));  // shortest text that reads back
}

void TestLessons::badLessonFiles_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("message");
    QTest::newRow("not JSON") << QByteArray("{\n  \"rasterlab_lesson\": 1,\n  oops\n}")
                              << QStringLiteral("l.rasterlab:3:4: not a lesson file: unterminated "
                                                "object");
    QTest::newRow("not a lesson") << QByteArray("[1, 2]")
                                  << QStringLiteral("l.rasterlab:1:1: expected a lesson file: a JSON "
                                                    "object with \"rasterlab_lesson\": 1");
    QTest::newRow("shading") << QByteArray("{\"rasterlab_lesson\": 1, \"shading\": \"toon\"}")
                             << QStringLiteral("l.rasterlab:1:25: expected one of phong, flat, "
                                               "gouraud, painter for \"shading\", found the text "
                                               "'toon'");
    QTest::newRow("image size")
        << QByteArray("{\"rasterlab_lesson\": 1,\n \"image_size\": [0, 5]}")
        << QStringLiteral("l.rasterlab:2:2: expected [width, height], whole numbers from 1 to "
                          "4096 for \"image_size\", found a list");
    QTest::newRow("cursor")
        << QByteArray("{\"rasterlab_lesson\": 1, \"stepping\": {\"cursor\": [3]}}")
        << QStringLiteral("l.rasterlab:1:38: expected a list of 2 numbers for \"cursor\", found a "
                          "list");
    QTest::newRow("zoom") << QByteArray("{\"rasterlab_lesson\": 1, \"window\": {\"zoom\": -2}}")
                          << QStringLiteral("l.rasterlab:1:36: expected a positive number or "
                                            "\"fit\" for \"zoom\", found a number");
    QTest::newRow("text zoom")
        << QByteArray("{\"rasterlab_lesson\": 1, \"window\": {\"text_zoom\": \"big\"}}")
        << QStringLiteral("l.rasterlab:1:36: expected a number for \"text_zoom\", found the text "
                          "'big'");
    QTest::newRow("breakpoint")
        << QByteArray("{\"rasterlab_lesson\": 1, \"stepping\": {\"breakpoints\": [{\"kind\": "
                      "\"pixel\"}]}}")
        << QStringLiteral("l.rasterlab:1:55: expected one of triangle, scanline, depth-rejection, "
                          "light-behind, nth-write for \"kind\", found the text 'pixel'");
    QTest::newRow("edit") << QByteArray("{\"rasterlab_lesson\": 1, \"edits\": {\"camera\": "
                                        "{\"C\": [1, 2]}}}")
                          << QStringLiteral("l.rasterlab:1:46: expected a list of 3 numbers for "
                                            "\"C\", found a list");
}

void TestLessons::badLessonFiles() {
    QFETCH(QByteArray, text);
    QFETCH(QString, message);
    rl::Diagnostics warnings;
    const auto lesson = parseLesson(text, QStringLiteral("l.rasterlab"), warnings);
    QVERIFY(!lesson);
    QCOMPARE(QString::fromStdString(lesson.error().toString()), message);
}

void TestLessons::unknownKeyWarns() {
    rl::Diagnostics warnings;
    const auto lesson = parseLesson("{\"rasterlab_lesson\": 1,\n\"colour\": 3}",
                                    QStringLiteral("l.rasterlab"), warnings);
    QVERIFY(lesson);
    QCOMPARE(warnings.size(), std::size_t(1));
    QVERIFY(QString::fromStdString(warnings.items().front().toString())
                .startsWith(QStringLiteral("l.rasterlab:2:1: warning: unknown key \"colour\" "
                                           "ignored (known here: rasterlab_lesson, title, notes")));
}

void TestLessons::documentedExampleReads() {
    // The example of docs/lesson-files.md is a valid lesson, read without a warning.
    QFile doc(testing::sourceDir() + QStringLiteral("/docs/lesson-files.md"));
    QVERIFY(doc.open(QIODevice::ReadOnly));
    const QByteArray text = doc.readAll();
    const qsizetype begin = text.indexOf("```json\n");
    QVERIFY(begin >= 0);
    const qsizetype end = text.indexOf("```", begin + 8);
    rl::Diagnostics diagnostics;
    const auto lesson = parseLesson(text.mid(begin + 8, end - begin - 8), QStringLiteral("doc"),
                                    diagnostics);
    QVERIFY2(lesson, lesson ? "" : lesson.error().toString().c_str());
    QVERIFY(diagnostics.items().empty());
    QCOMPARE(lesson->example, QStringLiteral("zbuffer"));
    QCOMPARE(lesson->edits.size(), std::size_t(3));  // Ka, and the light's Pl and Il
    QCOMPARE(lesson->lightCount, std::optional<std::size_t>(1));
    QCOMPARE(lesson->breakpoints->size(), std::size_t(1));
    QCOMPARE(lesson->cursor, std::optional<rl::ReplayCursor>(rl::ReplayCursor{0, 0}));
    QCOMPARE(*lesson->zoom, 8.0);
    QCOMPARE(lesson->presentation, std::optional<bool>(false));
}

void TestLessons::examplesMenuOpensEveryLesson() {
    MainWindow window;
    window.resize(1600, 1000);
    window.show();
    QVERIFY(waitUntilReady(window));
    for (const QString& name : exampleNames()) {
        auto* action = window.findChild<QAction*>(QStringLiteral("example_") + name);
        QVERIFY2(action, qPrintable(name));
        QCOMPARE(action->text(), exampleTitle(name));
        action->trigger();
        QVERIFY2(waitUntilReady(window), qPrintable(name));
        const Lesson lesson = exampleLesson(name);
        QCOMPARE(window.document().source(SceneDocument::Part::Object),
                 exampleFolder(name) + QLatin1Char('/') + name + QStringLiteral(".byu"));
        QCOMPARE(window.document().settings().shading, *lesson.shading);
        QCOMPARE(window.currentImage().size(), *lesson.imageSize);
        QCOMPARE(window.inspection()->granularity(), *lesson.granularity);
        QCOMPARE(window.inspection()->pickedPixel(), lesson.pixel.value_or(QPoint(-1, -1)));
        QCOMPARE(window.inspection()->atStart(), lesson.cursor.has_value());
        QCOMPARE(window.lessonTitle(), exampleTitle(name));
        // No error and no warning; the near-plane lesson's note says what clipping did.
        QStringList messages;
        for (int i = 0; i < window.messages()->count(); ++i) messages << window.messages()->item(i)->text();
        QCOMPARE(messages, name == QStringLiteral("near-plane")
                               ? QStringList{QStringLiteral(
                                     "near-plane.byu: note: 1 triangle was clipped against the "
                                     "near plane z = 2; 0 lie wholly behind the near plane, not "
                                     "drawn")}
                               : QStringList());
        // The lesson's dock and its text (the Scene dock) are on top of their tab groups;
        // a dock behind another tab has no visible region.
        const auto onTop = [&](const char* dock) {
            auto* d = window.findChild<QDockWidget*>(QLatin1String(dock));
            return d && d->isVisible() && !d->visibleRegion().isEmpty();
        };
        QVERIFY2(onTop(qPrintable(lesson.docksRaised.front())), qPrintable(name));
        QVERIFY2(onTop("sceneDock"), qPrintable(name));
        QVERIFY2(!onTop("messagesDock"), qPrintable(name));
    }
}

void TestLessons::shadingSideBySide() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    MainWindow window;
    window.resize(1600, 1000);
    window.show();
    QVERIFY(window.openExample(QStringLiteral("sphere")));
    QVERIFY(waitUntilReady(window));
    const QString path = dir.filePath(QStringLiteral("sheet.png"));
    QVERIFY(window.exportShadingSideBySide(path));
    const QImage sheet(path);
    // Three 640 x 480 panels 12 pixels apart, a caption strip of 640 / 14 pixels below.
    QCOMPARE(sheet.size(), QSize(3 * 640 + 2 * 12, 480 + 45));
    const rl::ShadingModel models[] = {rl::ShadingModel::Flat, rl::ShadingModel::Gouraud,
                                       rl::ShadingModel::Phong};
    QImage previous;
    for (int i = 0; i < 3; ++i) {
        const auto scene = lessonScene(QStringLiteral("sphere"), models[i]);
        const auto trace = testing::renderTrace(scene);
        const QImage expected =
            toQImage(rl::colourImage(*trace->shading, *trace->depth, scene->conventions))
                .convertToFormat(QImage::Format_RGB32);
        const QImage panel = sheet.copy(i * (640 + 12), 0, 640, 480).convertToFormat(QImage::Format_RGB32);
        QCOMPARE(panel, expected);
        QVERIFY(panel != previous);
        previous = panel;
    }
    // The caption strip holds dark text on white.
    const QImage strip = sheet.copy(0, 480, 640, 45);
    int dark = 0;
    for (int y = 0; y < strip.height(); ++y)
        for (int x = 0; x < strip.width(); ++x) dark += qGray(strip.pixel(x, y)) < 128;
    QVERIFY(dark > 20);
    // The lesson opens in flat shading; the export leaves it so.
    QCOMPARE(window.document().settings().shading, rl::ShadingModel::Flat);
}

void TestLessons::savedLessonReopensInAnotherProcess() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    MainWindow window;
    window.resize(1600, 1000);
    window.show();
    QVERIFY(window.openExample(QStringLiteral("zbuffer")));
    QVERIFY(waitUntilReady(window));
    // A teacher's setup: a light moved, Gouraud, stepping by pixel 37 steps in, a pixel
    // picked, two breakpoints, zoomed on the crossing, the accuracy dock closed.
    window.editPanel()->spinBox(SceneDocument::Field::LightPosition, 0)->setValue(-2.5);
    window.setShading(rl::ShadingModel::Gouraud);
    QVERIFY(waitUntilReady(window));
    window.inspection()->setGranularity(rl::StepGranularity::Pixel);
    window.inspection()->toStart();
    for (int i = 0; i < 37; ++i) QVERIFY(window.inspection()->stepForward());
    window.inspection()->pickPixel(QPoint(20, 30));
    rl::Breakpoint scanline;
    scanline.kind = rl::Breakpoint::Kind::Scanline;
    scanline.y = 12;
    rl::Breakpoint rejection;
    rejection.kind = rl::Breakpoint::Kind::DepthRejection;
    rejection.x = 30;
    rejection.y = 25;
    window.breakpointsView()->setEntries({scanline, rejection});
    window.imageView()->showAt(6.0, QPointF(20.5, 18.25));
    window.findChild<QDockWidget*>(QStringLiteral("accuracyDock"))->close();
    const QString saved = dir.filePath(QStringLiteral("class.rasterlab"));
    QVERIFY(window.saveLesson(saved));

    const QString again = dir.filePath(QStringLiteral("again.rasterlab"));
    QProcess reopen;
    reopen.start(QStringLiteral(RASTERLAB_LESSON_REOPEN), {saved, again});
    QVERIFY(reopen.waitForFinished(90000));
    QVERIFY2(reopen.exitCode() == 0, reopen.readAllStandardError().constData());
    rl::Diagnostics warnings;
    const auto first = readLesson(saved, warnings);
    const auto second = readLesson(again, warnings);
    QVERIFY(first && second);
    QCOMPARE(first->example, QStringLiteral("zbuffer"));
    QCOMPARE(first->cursor, window.inspection()->cursor());
    QCOMPARE(second->cursor, first->cursor);
    QCOMPARE(second->pixel, std::optional<QPoint>(QPoint(20, 30)));
    QVERIFY(second->breakpoints == first->breakpoints);
    QCOMPARE(second->breakpoints->size(), std::size_t(2));
    QCOMPARE(second->zoom, std::optional<double>(6.0));
    QCOMPARE(second->centre, first->centre);
    QVERIFY(std::abs(first->centre->x() - 20.5) < 1e-9 && std::abs(first->centre->y() - 18.25) < 1e-9);
    QCOMPARE(second->granularity, std::optional(rl::StepGranularity::Pixel));
    QCOMPARE(second->shading, std::optional(rl::ShadingModel::Gouraud));
    QVERIFY(second->edits == first->edits);
    QVERIFY(!first->edits.empty());
    QCOMPARE(second->docksShown, first->docksShown);
    QVERIFY(!second->docksShown.contains(QStringLiteral("accuracyDock")));
    QCOMPARE(second->docksRaised, first->docksRaised);
    QCOMPARE(second->imageSize, std::optional<QSize>(QSize(64, 48)));
}

void TestLessons::lessonSavedPresentingGivesTheLayoutBack() {
    // Saved in presentation mode, opened again: presenting, and leaving it gives back the
    // docks presentation mode put away, where they were.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString saved = dir.filePath(QStringLiteral("presenting.rasterlab"));
    const QStringList sideDocks = {QStringLiteral("editDock"), QStringLiteral("messagesDock")};
    {
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        QVERIFY(window.openExample(QStringLiteral("triangle")));
        QVERIFY(waitUntilReady(window));
        window.setPresentationMode(true);
        for (const QString& name : sideDocks)
            QVERIFY(window.findChild<QDockWidget*>(name)->isHidden());
        QVERIFY(window.saveLesson(saved));
        window.setPresentationMode(false);
    }
    MainWindow window;
    window.resize(1600, 1000);
    window.show();
    // Opened outside presentation mode, then again while presenting: presenting, the docks
    // put away; after it, back on the left.
    for (const bool alreadyPresenting : {false, true}) {
        window.setPresentationMode(alreadyPresenting);
        QVERIFY(window.openLesson(saved));
        QVERIFY(waitUntilReady(window));
        QVERIFY(window.presentationMode());
        for (const QString& name : sideDocks)
            QVERIFY2(window.findChild<QDockWidget*>(name)->isHidden(), qPrintable(name));
        window.setPresentationMode(false);
        for (const QString& name : sideDocks) {
            auto* dock = window.findChild<QDockWidget*>(name);
            QVERIFY2(!dock->isHidden(), qPrintable(name));
            if (name == QStringLiteral("editDock"))
                QCOMPARE(window.dockWidgetArea(dock), Qt::LeftDockWidgetArea);
        }
        auto* inspector = window.findChild<QDockWidget*>(QStringLiteral("pixelInspectorDock"));
        QCOMPARE(window.dockWidgetArea(inspector), Qt::LeftDockWidgetArea);
    }
}

void TestLessons::missingFileOpensTheRest() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(!writeText(dir, QStringLiteral("tri.byu"), "3 1\n0 0 0\n100 0 0\n0 100 0\n1 2 3\n").isEmpty());
    const QString path = writeText(dir, QStringLiteral("l.rasterlab"),
                                   "{\"rasterlab_lesson\": 1, \"scene\": {\"camera\": \"gone.cfg\", "
                                   "\"object\": \"tri.byu\"}}");
    MainWindow window;
    QVERIFY(waitUntilReady(window));
    const QString cameraBefore = window.document().source(SceneDocument::Part::Camera);
    QVERIFY(window.openLesson(path));
    QCOMPARE(window.document().source(SceneDocument::Part::Object), dir.filePath(QStringLiteral("tri.byu")));
    QCOMPARE(window.document().source(SceneDocument::Part::Camera), cameraBefore);
    const auto missing = readInputFile(dir.filePath(QStringLiteral("gone.cfg")));
    QVERIFY(!missing);
    QCOMPARE(window.lessonProblems(),
             QStringList{path + QStringLiteral(": the camera was not restored, the one shown "
                                               "stays: ") +
                         QString::fromStdString(missing.error().toString())});
    QCOMPARE(window.messages()->item(0)->text(), window.lessonProblems().front());
}

// An input file is read whole up to the limit, across the chunks it is read in; one byte
// more, from a file or from a device with no size, is refused.
void TestLessons::inputFilesReadWithinTheLimit() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QByteArray text((5 << 20) / 2, 'a');
    for (qsizetype i = 0; i < text.size(); i += 4099) text[i] = char('0' + i % 10);
    const QString path = writeText(dir, QStringLiteral("big.txt"), text);
    const auto whole = readInputFile(path, text.size());
    QVERIFY(whole);
    QVERIFY(whole.value() == text);
    QVERIFY(!readInputFile(path, text.size() - 1));
    const auto over = readInputFile(path, qint64(2) << 20);
    QVERIFY(!over);
    QCOMPARE(QString::fromStdString(over.error().toString()),
             path + QStringLiteral(": the file has 3 MiB, more than the 2 MiB an input file "
                                   "may have"));
    const auto device = readInputFile(QStringLiteral("/dev/zero"), qint64(3) << 20);
    QVERIFY(!device);
    QCOMPARE(QString::fromStdString(device.error().toString()),
             QStringLiteral("/dev/zero: the file has more than the 3 MiB an input file may have"));
}

// What gui_main does when the language changes: the new window adopts the document and
// restores the view of the old one.
void TestLessons::languageSwitchKeepsTheView() {
    MainWindow before;
    before.resize(1400, 900);
    before.show();
    QVERIFY(before.openExample(QStringLiteral("triangle")));
    QVERIFY(waitUntilReady(before));
    for (int i = 0; i < 50; ++i) QVERIFY(before.inspection()->stepForward());
    before.inspection()->pickPixel(QPoint(10, 17));
    rl::Breakpoint b;
    b.kind = rl::Breakpoint::Kind::Scanline;
    b.y = 9;
    before.breakpointsView()->setEntries({b});
    before.imageView()->showAt(12.0, QPointF(16, 12));
    const Lesson view = before.currentLesson(QDir());
    MainWindow after;
    after.resize(1400, 900);
    after.show();
    after.adoptDocument(before.document());
    after.restoreView(view);
    QVERIFY(waitUntilReady(after));
    QCOMPARE(after.inspection()->cursor(), before.inspection()->cursor());
    QCOMPARE(after.inspection()->pickedPixel(), QPoint(10, 17));
    QVERIFY(after.inspection()->breakpoints() == before.inspection()->breakpoints());
    QCOMPARE(after.imageView()->zoom(), 12.0);
    QCOMPARE(after.imageView()->centrePoint(), QPointF(16, 12));
    QCOMPARE(after.inspection()->granularity(), rl::StepGranularity::Pixel);
    QCOMPARE(after.lessonTitle(), exampleTitle(QStringLiteral("triangle")));
}

void TestLessons::cliRendersALesson() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    CliRun run;
    QVERIFY2(testing::runCli({QStringLiteral("render"), QStringLiteral("--scene"),
                              QStringLiteral("triangle"), QStringLiteral("--output"),
                              QStringLiteral("t.png")},
                             dir.path(), run),
             qPrintable(run.problem));
    QCOMPARE(run.err, QString());
    QCOMPARE(run.exitCode, 0);
    // The lesson's own size and shading; 205 pixels as triangleCoversItsPixels counts them.
    QVERIFY2(run.out.startsWith(QStringLiteral("rendering triangle\nwrote ")), qPrintable(run.out));
    QVERIFY2(run.out.contains(QStringLiteral("(image, 32x24)\n  1 triangle, phong shading, ")),
             qPrintable(run.out));
    QCOMPARE(QImage(dir.filePath(QStringLiteral("t.png"))).size(), QSize(32, 24));
}

QTEST_MAIN(TestLessons)
#include "tst_lessons.moc"
