// The main window in-process (offscreen): it renders the default scene, keeps the scene and
// the image when a file is bad and says why (file:line:col), switches shading, exports the
// image; and its render controller always ends with the newest request.
#include <QtTest>

#include <QLabel>
#include <QToolButton>

#include <QMenu>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QThreadPool>

#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QListWidget>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>

#include <set>

#include "app/documents/scene_document.h"
#include "app/plots/stability_plot.h"
#include "app/window/accuracy_panel.h"
#include "app/window/main_window.h"
#include "app/window/render_controller.h"
#include "pipeline/scene/benchmark_scenes.h"
#include "tests/test_support.h"
#include "views/explained_view.h"
#include "views/inspection.h"
#include "views/painter_view.h"
#include "views/stage_strip.h"

using rasterlab::AccuracyPanel;
using rasterlab::MainWindow;
using rasterlab::RenderController;
using rasterlab::RenderedFrame;
using rasterlab::SceneDocument;

Q_DECLARE_METATYPE(SceneDocument::Part)

namespace {

constexpr int kFrameTimeoutMs = 10000;
constexpr std::size_t kDefaultTriangles = 7776;  // the trefoil's header: 3888 7776

RenderedFrame frameAt(const QSignalSpy& spy, qsizetype i) {
    return spy.at(i).at(0).value<RenderedFrame>();
}

bool isBlack(QRgb c) {
    return qRed(c) == 0 && qGreen(c) == 0 && qBlue(c) == 0;
}

bool hasLitPixel(const QImage& image) {
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (!isBlack(image.pixel(x, y))) return true;
    return false;
}

QString writeFixture(const QTemporaryDir& dir, const QString& name, const QByteArray& content) {
    const QString path = dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(content) != content.size()) return {};
    return path;
}

// A tetrahedron around the origin, where the default camera looks.
const QByteArray kTetrahedron =
    "4 4\n"
    "-80 -80 -80\n"
    "80 80 -80\n"
    "80 -80 80\n"
    "-80 80 80\n"
    "1 2 3\n"
    "1 4 2\n"
    "1 3 4\n"
    "2 4 3\n";

}  // namespace

class TestMainWindow : public QObject {
    Q_OBJECT

private slots:
    void defaultScene();
    void badFileKeepsScene_data();
    void badFileKeepsScene();
    void missingCameraKeepsScene();
    void degenerateCameraKeepsScene_data();
    void degenerateCameraKeepsScene();
    void openGoodObject();
    void flatShading();
    void rulesMenu();
    void plainDivideForAnObjectBehind();
    void commandFileProjection();
    void accuracyDock();
    void stabilitySweep();
    void lastShadingWins();
    void exportImage();
    void exportToMissingFolder();
    void docks();
    void presentationFontsComeBack();
    void presentationAfterFillGivesTheLayoutBack();
    void coveredViewsRefreshWhenRaised();
    void layoutSavedAndReset();
    void newestRequestWins();
    void failedRenderKeepsTheLastImage();
    void commandFile();
    void courseFileLayouts();
    void controllerDestroyedWhileRendering();
};

// Waits for the window's first frame (the default scene); fails the test after 10 s.
#define WAIT_FOR_FIRST_FRAME(spy) \
    QVERIFY2((spy).count() > 0 || (spy).wait(kFrameTimeoutMs), "no frame within 10 s")

void TestMainWindow::defaultScene() {
    MainWindow window;
    QSignalSpy spy(window.controller(), &RenderController::frameReady);
    WAIT_FOR_FIRST_FRAME(spy);
    QCOMPARE(spy.count(), 1);
    // The window names what it shows: the object, or the command file.
    QCOMPARE(window.windowTitle(), QStringLiteral("trefoil.byu (built in)[*] - RasterLab"));
    QVERIFY(window.document().isLoaded());

    const QImage& image = window.currentImage();
    QCOMPARE(image.size(), QSize(800, 600));
    QCOMPARE(image.pixel(0, 0), qRgba(0, 0, 0, 255));
    QVERIFY(!isBlack(image.pixel(400, 350)));  // on the knot's lower band
    QVERIFY(image == frameAt(spy, 0).image);

    const auto frame = window.currentFrame();
    QVERIFY(frame);
    QCOMPARE(frame->scene->triangleCount(), kDefaultTriangles);
    QCOMPARE(window.document().parts().object.mesh->triangles.size(), kDefaultTriangles);
    QCOMPARE(frame->scene->width, 800);
    QCOMPARE(frame->scene->draws.front().shading, rl::ShadingModel::Phong);
    QCOMPARE(frame->scene->draws.front().name, std::string("trefoil.byu"));
    QCOMPARE(window.messages()->count(), 0);  // the default scene loads without warnings
    QVERIFY(window.imageView());
}

void TestMainWindow::badFileKeepsScene_data() {
    QTest::addColumn<SceneDocument::Part>("part");
    QTest::addColumn<QString>("fileName");
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("message");  // %1: the file's path

    // Line 3 is "1.0   a 0.0": the 'a' is at column 7.
    QTest::newRow("object letter")
        << SceneDocument::Part::Object << "letter.byu"
        << QByteArray("3 1\n0 0 0\n1.0   a 0.0\n0 1 0\n1 2 3\n")
        << "%1:3:7: expected a number for the y coordinate of vertex 2 of 3, found 'a'";
    // Line 7 is "2  4 5": the 5 is at column 6.
    QTest::newRow("object index out of range")
        << SceneDocument::Part::Object << "range.byu"
        << QByteArray("4 2\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n1 2 3\n2  4 5\n")
        << "%1:7:6: triangle 2 refers to vertex 5, but the file declares only 4 vertices";
    // Line 2 has two numbers: the end of the line is column 6.
    QTest::newRow("camera short N") << SceneDocument::Part::Camera << "short.cfg"
                                    << QByteArray("0 -380 330\n0 380\n0 0 1\n1 0.4 0.3\n")
                                    << "%1:2:6: expected 3 numbers for N, found 2";
    QTest::newRow("lighting decimal comma")
        << SceneDocument::Part::Lighting << "comma.txt"
        << QByteArray(
               "-260 -420 520\n0.35\n60 60 72\n0,85\n0.88 0.42 0.18\n0.6\n255 248 235\n"
               "40\n")
        << "%1:4:1: expected a number for kd, found '0,85' (the decimal separator is '.')";
}

void TestMainWindow::badFileKeepsScene() {
    QFETCH(SceneDocument::Part, part);
    QFETCH(QString, fileName);
    QFETCH(QByteArray, content);
    QFETCH(QString, message);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = writeFixture(dir, fileName, content);
    QVERIFY(!path.isEmpty());
    const QString expected = message.arg(path);

    MainWindow window;
    QSignalSpy spy(window.controller(), &RenderController::frameReady);
    WAIT_FOR_FIRST_FRAME(spy);
    const auto frameBefore = window.currentFrame();
    const QImage imageBefore = window.currentImage();
    const auto meshBefore = window.document().parts().object.mesh;
    const QString sourceBefore = window.document().source(part);
    spy.clear();

    QVERIFY(!window.openPart(part, path));
    QCOMPARE(window.messages()->count(), 1);
    QCOMPARE(window.messages()->item(0)->text(), QStringLiteral("Error: ") + expected);
    QCOMPARE(window.statusBar()->currentMessage(), expected);
    QCOMPARE(window.document().source(part), sourceBefore);
    QCOMPARE(window.document().parts().object.mesh, meshBefore);
    QVERIFY(!spy.wait(300));  // nothing to re-render
    QCOMPARE(window.currentFrame(), frameBefore);
    QCOMPARE(window.currentFrame()->scene->triangleCount(), kDefaultTriangles);
    QVERIFY(window.currentImage() == imageBefore);

    // The scene is still whole: the next render is the default scene again.
    window.setShading(rl::ShadingModel::Phong);
    QVERIFY(spy.wait(kFrameTimeoutMs));
    QCOMPARE(window.currentFrame()->scene->triangleCount(), kDefaultTriangles);
    QVERIFY(window.currentImage() == imageBefore);
    // The error stays listed until a file loads.
    QCOMPARE(window.messages()->item(0)->text(), QStringLiteral("Error: ") + expected);
}

void TestMainWindow::missingCameraKeepsScene() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("absent.cfg");
    MainWindow window;
    QSignalSpy spy(window.controller(), &RenderController::frameReady);
    WAIT_FOR_FIRST_FRAME(spy);
    const auto frameBefore = window.currentFrame();
    const QString cameraBefore = window.document().source(SceneDocument::Part::Camera);

    QVERIFY(!window.openPart(SceneDocument::Part::Camera, path));
    QCOMPARE(window.messages()->count(), 1);
    const QString prefix = QStringLiteral("Error: %1: cannot open: ").arg(path);
    const QString text = window.messages()->item(0)->text();
    QVERIFY2(text.startsWith(prefix) && text.size() > prefix.size(), qPrintable(text));
    QCOMPARE(window.statusBar()->currentMessage(), text.mid(int(qstrlen("Error: "))));
    QCOMPARE(window.document().source(SceneDocument::Part::Camera), cameraBefore);
    QCOMPARE(window.currentFrame(), frameBefore);
    QCOMPARE(window.currentFrame()->scene->triangleCount(), kDefaultTriangles);
}

void TestMainWindow::degenerateCameraKeepsScene_data() {
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("message");  // %1: the file's path

    // Well-formed files whose camera has no basis: refused like a syntax error.
    QTest::newRow("N zero") << QByteArray("0 -380 330\n0 0 0\n0 0 1\n1 0.4 0.3\n")
                            << "%1:2:1: N, the view direction, is the zero vector: it must point "
                               "from the camera toward the scene";
    // Line 4 is "1   0 0.3": hx is at column 5.
    QTest::newRow("hx zero") << QByteArray("0 -380 330\n0 380 -330\n0 0 1\n1   0 0.3\n")
                             << "%1:4:5: hx, the horizontal half-size of the window, is 0: the "
                                "projection (d/hx) x/z divides by it";
}

void TestMainWindow::degenerateCameraKeepsScene() {
    QFETCH(QByteArray, content);
    QFETCH(QString, message);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = writeFixture(dir, "degenerate.cfg", content);
    QVERIFY(!path.isEmpty());
    const QString expected = message.arg(path);

    MainWindow window;
    QSignalSpy spy(window.controller(), &RenderController::frameReady);
    QSignalSpy failures(window.controller(), &RenderController::failed);
    WAIT_FOR_FIRST_FRAME(spy);
    const QImage imageBefore = window.currentImage();
    const QString cameraBefore = window.document().source(SceneDocument::Part::Camera);
    spy.clear();

    QVERIFY(!window.openPart(SceneDocument::Part::Camera, path));
    QCOMPARE(window.messages()->count(), 1);
    QCOMPARE(window.messages()->item(0)->text(), QStringLiteral("Error: ") + expected);
    QCOMPARE(window.statusBar()->currentMessage(), expected);
    QCOMPARE(window.document().source(SceneDocument::Part::Camera), cameraBefore);

    // The previous camera still renders.
    window.setShading(rl::ShadingModel::Phong);
    QVERIFY(spy.wait(kFrameTimeoutMs));
    QCOMPARE(failures.count(), 0);
    QVERIFY(window.currentImage() == imageBefore);
}

void TestMainWindow::openGoodObject() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = writeFixture(dir, "tetra.byu", kTetrahedron);
    QVERIFY(!path.isEmpty());
    const QString badPath = writeFixture(dir, "bad.byu", "3 1\n0 0 0\n1 0 0\n");
    QVERIFY(!badPath.isEmpty());

    MainWindow window;
    QSignalSpy spy(window.controller(), &RenderController::frameReady);
    WAIT_FOR_FIRST_FRAME(spy);
    QVERIFY(!window.openPart(SceneDocument::Part::Object, badPath));  // an error first
    QCOMPARE(window.messages()->count(), 1);
    spy.clear();

    QVERIFY(window.openPart(SceneDocument::Part::Object, path));
    QCOMPARE(window.document().source(SceneDocument::Part::Object), path);
    QCOMPARE(window.messages()->count(), 0);  // a good file clears the error
    QVERIFY(spy.wait(kFrameTimeoutMs));
    QCOMPARE(spy.count(), 1);
    const auto frame = window.currentFrame();
    QCOMPARE(frame->scene->triangleCount(), std::size_t(4));
    QCOMPARE(frame->scene->vertexCount(), std::size_t(4));
    QCOMPARE(frame->scene->draws.front().name, std::string("tetra.byu"));
    QCOMPARE(window.currentImage().size(), QSize(800, 600));
    QVERIFY(hasLitPixel(window.currentImage()));
    QCOMPARE(window.currentImage().pixel(0, 0), qRgba(0, 0, 0, 255));
}

void TestMainWindow::rulesMenu() {
    MainWindow window;
    QSignalSpy spy(window.controller(), &RenderController::frameReady);
    WAIT_FOR_FIRST_FRAME(spy);
    const QImage course = window.currentImage();
    QCOMPARE(window.currentFrame()->scene->rules, rl::RasterRules::course());
    auto* gpu = window.findChild<QAction*>(QStringLiteral("rules_gpu"));
    QVERIFY(gpu);
    QVERIFY(!gpu->isChecked());
    QVERIFY(window.findChild<QAction*>(QStringLiteral("rules_course"))->isChecked());
    spy.clear();
    gpu->trigger();
    QVERIFY(gpu->isChecked());
    QVERIFY(spy.wait(kFrameTimeoutMs));
    QCOMPARE(window.currentFrame()->scene->rules, rl::RasterRules::gpu());
    QCOMPARE(window.document().settings().rules, rl::RasterRules::gpu());
    QVERIFY(window.currentImage() != course);
    // Shading is kept when the rules change.
    QCOMPARE(window.currentFrame()->scene->draws.front().shading, rl::ShadingModel::Phong);
}

void TestMainWindow::plainDivideForAnObjectBehind() {
    // A course camera whose N points away from the object (as some of the course's own files
    // do): clipping leaves nothing; the bar above the image says what seed 000's formula
    // would draw and draws it in one click; the stage strip says so.
    MainWindow window;
    QSignalSpy spy(window.controller(), &RenderController::frameReady);
    WAIT_FOR_FIRST_FRAME(spy);
    QVERIFY(!window.behindBanner()->isVisibleTo(&window));
    QCOMPARE(window.document().projection(), rl::NearPlane::Mode::Clip);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path =
        writeFixture(dir, QStringLiteral("away.cfg"), "0 -380 330\n0 -380 330\n0 0 1\n1 0.4 0.3\n");
    QVERIFY(window.openPart(SceneDocument::Part::Camera, path));
    QVERIFY2(spy.wait(kFrameTimeoutMs), "no frame for the camera");
    QVERIFY(!hasLitPixel(window.currentImage()));
    QVERIFY(window.behindBanner()->isVisibleTo(&window));
    auto* text = window.behindBanner()->findChild<QLabel*>();
    QVERIFY(text && text->text().contains(QStringLiteral("draw 7776 of the 7776 triangles")));
    auto* projection = window.stageStrip()->button(rl::StageId::Projection);
    QVERIFY2(projection->text().endsWith(QStringLiteral("near clip")),
             qPrintable(projection->text()));
    spy.clear();
    window.behindBannerButton()->click();
    QVERIFY2(spy.wait(kFrameTimeoutMs), "no frame with the plain divide");
    QCOMPARE(window.document().projection(), rl::NearPlane::Mode::Naive);
    QCOMPARE(window.currentFrame()->projection->behindEye, kDefaultTriangles);
    QVERIFY(hasLitPixel(window.currentImage()));
    QVERIFY(!window.behindBanner()->isVisibleTo(&window));
    QVERIFY2(projection->text().endsWith(QStringLiteral("plain divide")),
             qPrintable(projection->text()));
    QVERIFY(window
                .findChild<QAction*>(
                    QStringLiteral("projection_%1").arg(int(rl::NearPlane::Mode::Naive)))
                ->isChecked());
}

void TestMainWindow::commandFileProjection() {
    // Seed 001's xyzw file: the hw2 rules divide by w without clipping; the projection menu
    // stays open for command files and can clip instead (the part with w > 0).
    MainWindow window;
    QSignalSpy spy(window.controller(), &RenderController::frameReady);
    WAIT_FOR_FIRST_FRAME(spy);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = writeFixture(dir, QStringLiteral("xyzw.txt"),
                                      "png 120 120 xyzw.png\nxyz 0.5 0 0\nxyzw 1 2 1 2\n"
                                      "xyzw 1 1 -0.5 -1\ncolor 0 0 0\ntrif 1 2 3\n");
    QVERIFY(window.openCommandFile(path));
    QVERIFY2(spy.wait(kFrameTimeoutMs), "no frame for the command file");
    QCOMPARE(window.currentFrame()->projection->mode, rl::NearPlane::Mode::Naive);
    QCOMPARE(window.currentFrame()->projection->acrossEye, std::size_t(1));
    QVERIFY(window.stageStrip()
                ->button(rl::StageId::Projection)
                ->text()
                .endsWith(QStringLiteral("plain divide")));
    QVERIFY(!window.findChild<QMenu*>(QStringLiteral("rulesMenu"))->isEnabled());
    auto* clip = window.findChild<QAction*>(
        QStringLiteral("projection_%1").arg(int(rl::NearPlane::Mode::Clip)));
    QVERIFY(clip && clip->isEnabled());
    spy.clear();
    clip->trigger();
    QVERIFY2(spy.wait(kFrameTimeoutMs), "no frame with clipping");
    QCOMPARE(window.currentFrame()->projection->clipped, std::size_t(1));
    // Opening the file again gives it its own projection back.
    QVERIFY(window.openCommandFile(path));
    QCOMPARE(window.document().projection(), rl::NearPlane::Mode::Naive);
}

void TestMainWindow::accuracyDock() {
    MainWindow window;
    QSignalSpy spy(window.controller(), &RenderController::frameReady);
    WAIT_FOR_FIRST_FRAME(spy);
    AccuracyPanel* panel = window.accuracyPanel();
    QVERIFY(panel);
    QVERIFY(window.findChild<QDockWidget*>(QStringLiteral("accuracyDock"))->isAncestorOf(panel));
    QVERIFY(!panel->report());
    QSignalSpy done(panel, &AccuracyPanel::finished);
    auto* measure = panel->findChild<QPushButton*>(QStringLiteral("measureAccuracy"));
    QVERIFY(measure);
    measure->click();
    QVERIFY(panel->isMeasuring());
    QVERIFY(done.wait(60000));
    QVERIFY(!panel->isMeasuring());
    QVERIFY(panel->report());
    // Three shading models under three rule sets, each in float and double.
    QCOMPARE(panel->report()->rows.size(), std::size_t(18));
    auto* table = panel->findChild<QTableWidget*>(QStringLiteral("accuracyTable"));
    QCOMPARE(table->rowCount(), 18);
    // Phong under the GPU-like rules is selected first: its heat map and its numbers.
    const rl::AccuracyRow& row = panel->report()->rows.at(std::size_t(panel->selectedRow()));
    QCOMPARE(row.mode.shading, rl::ShadingModel::Phong);
    QCOMPARE(row.mode.rules, rl::RuleSet::Gpu);
    QCOMPARE(row.precision, std::string("float"));
    QVERIFY(row.metrics.within1Of255 >= 0.999);
    QCOMPARE(table->item(panel->selectedRow(), 1)->text(), QStringLiteral("gpu"));
    QVERIFY(!panel->plot().isNull());
    // Cropped to the knot and a margin: smaller than the image, bar included.
    QVERIFY(panel->heatMap().width() > 200 && panel->heatMap().width() < 800 + 110);
    QVERIFY(panel->heatMapOrigin().x() > 0);
    // Picking a covered pixel names both values; the default scene covers the centre.
    panel->pickPixel(400, 300);
    QVERIFY2(panel->pickText().startsWith(QStringLiteral("Pixel (400, 300), phong/gpu: mode (")),
             qPrintable(panel->pickText()));
    QVERIFY(panel->pickText().contains(QStringLiteral("reference (")));
    // The course rules are worse, and the table says so.
    double courseRmse = 0.0;
    for (const rl::AccuracyRow& r : panel->report()->rows)
        if (r.mode.shading == rl::ShadingModel::Phong && r.mode.rules == rl::RuleSet::Course &&
            r.precision == "float")
            courseRmse = r.metrics.rmse;
    QVERIFY(courseRmse > 10.0 * row.metrics.rmse);
    // A new scene clears the results: they were for the old one.
    window.setShading(rl::ShadingModel::Flat);
    QVERIFY(!panel->report());
    QCOMPARE(table->rowCount(), 0);
}

void TestMainWindow::stabilitySweep() {
    AccuracyPanel panel;
    panel.resize(520, 900);
    panel.show();
    auto scene = std::make_shared<const rl::Scene>(
        *rl::makeBenchmarkScene("sphere-1k", 160, 120, rl::ShadingModel::Phong));
    panel.setScene(scene);
    auto* sweep = panel.findChild<QPushButton*>(QStringLiteral("stabilitySweep"));
    auto* measure = panel.findChild<QPushButton*>(QStringLiteral("measureAccuracy"));
    auto* progress = panel.findChild<QProgressBar*>(QStringLiteral("stabilityProgress"));
    auto* picture = panel.findChild<QLabel*>(QStringLiteral("stabilityPlot"));
    QVERIFY(sweep && measure && progress && picture);
    QSignalSpy done(&panel, &AccuracyPanel::sweepFinished);
    int highest = 0;
    connect(progress, &QProgressBar::valueChanged, this,
            [&](int value) { highest = std::max(highest, value); });

    // One axis to the end: every point counted, the plot two panels wide, a line for the axis.
    panel.setSweepAxis(rl::StiffnessAxis::Shininess);
    sweep->click();
    QVERIFY(panel.isSweeping());
    QVERIFY(!measure->isEnabled() && !sweep->isEnabled());
    QVERIFY(progress->isVisible());
    QVERIFY(done.wait(120000));
    QVERIFY(!panel.isSweeping());
    QVERIFY(measure->isEnabled() && sweep->isEnabled());
    QVERIFY(!progress->isVisible());
    const rl::StabilityReport* report = panel.stabilityReport();
    QVERIFY(report);
    const int points = int(rl::axisInfo(rl::StiffnessAxis::Shininess).values.size()) * 2;
    QCOMPARE(int(report->points.size()), 2 * points);  // float and double at each
    QCOMPARE(progress->maximum(), points);
    QCOMPARE(highest, points);
    QCOMPARE(panel.stabilityPlot().size(), rasterlab::stabilityPlotSize(1));
    QVERIFY(panel.stabilityPlot().width() > panel.stabilityPlot().height());
    QVERIFY(!picture->pixmap().isNull());
    // Scaled to the dock: as wide as the label, or as high, with the plot's proportions.
    const QSize shown = picture->pixmap().size();
    QVERIFY2(shown.width() == picture->width() || shown.height() == picture->height(),
             qPrintable(QStringLiteral("%1x%2 in %3x%4")
                            .arg(shown.width())
                            .arg(shown.height())
                            .arg(picture->width())
                            .arg(picture->height())));
    QVERIFY(std::abs(double(shown.width()) / shown.height() -
                     double(rasterlab::stabilityPlotSize(1).width()) /
                         rasterlab::stabilityPlotSize(1).height()) < 0.02);
    QVERIFY2(panel.stabilitySummary().startsWith(
                 QStringLiteral("shininess: float and double differ by up to ")),
             qPrintable(panel.stabilitySummary()));
    QVERIFY(!panel.stabilitySummary().contains(QStringLiteral("offset")));
    QVERIFY(panel.stabilitySummary().contains(QStringLiteral("course ")) &&
            panel.stabilitySummary().contains(QStringLiteral("gpu ")));
    QVERIFY2(panel.statusText().contains(QStringLiteral("28 points")),
             qPrintable(panel.statusText()));

    // Every axis, cancelled after its first point: idle again, and it says so.
    panel.setSweepAxis(std::nullopt);
    highest = 0;
    done.clear();
    sweep->click();
    QVERIFY(QTest::qWaitFor([&] { return highest >= 1; }, 60000));
    panel.findChild<QPushButton*>(QStringLiteral("cancelAccuracy"))->click();
    QVERIFY(done.wait(60000));
    QVERIFY(!panel.isSweeping());
    QVERIFY(sweep->isEnabled());
    QCOMPARE(panel.statusText(), QStringLiteral("Sweep cancelled."));
    QVERIFY(highest < progress->maximum());

    // A new scene while it sweeps: the result is dropped, and the old one cleared.
    highest = 0;
    done.clear();
    sweep->click();
    QVERIFY(QTest::qWaitFor([&] { return highest >= 1; }, 60000));
    auto other = std::make_shared<rl::Scene>(*scene);
    other->name = "other";
    panel.setScene(other);
    QVERIFY(!panel.stabilityReport());
    QVERIFY(panel.stabilityPlot().isNull());
    QVERIFY(done.wait(60000));
    QVERIFY(!panel.isSweeping());
    QVERIFY(!panel.stabilityReport());
    QCOMPARE(panel.statusText(), QStringLiteral("The scene changed: measure again."));

    // No course camera: the sweep says why, and nothing breaks.
    auto cameraless = std::make_shared<rl::Scene>(*scene);
    cameraless->camera.reset();
    panel.setScene(cameraless);
    done.clear();
    sweep->click();
    QVERIFY(done.wait(60000));
    QVERIFY(!panel.stabilityReport());
    QVERIFY2(panel.statusText().startsWith(QStringLiteral("The sweep failed: ")) &&
                 panel.statusText().contains(QStringLiteral("no course camera")),
             qPrintable(panel.statusText()));
    QVERIFY(sweep->isEnabled());
}

void TestMainWindow::flatShading() {
    MainWindow window;
    QSignalSpy spy(window.controller(), &RenderController::frameReady);
    WAIT_FOR_FIRST_FRAME(spy);
    const QImage phong = window.currentImage();
    QCOMPARE(window.currentFrame()->scene->draws.front().shading, rl::ShadingModel::Phong);
    spy.clear();

    window.setShading(rl::ShadingModel::Flat);
    QCOMPARE(window.document().settings().shading, rl::ShadingModel::Flat);
    QVERIFY(spy.wait(kFrameTimeoutMs));
    QCOMPARE(spy.count(), 1);
    const auto frame = window.currentFrame();
    QCOMPARE(frame->scene->draws.front().shading, rl::ShadingModel::Flat);
    QCOMPARE(frame->scene->triangleCount(), kDefaultTriangles);
    const QImage& flat = window.currentImage();
    QCOMPARE(flat.size(), phong.size());
    QVERIFY(flat != phong);
    // Same coverage, other colours.
    qsizetype differing = 0;
    for (int y = 0; y < flat.height(); ++y) {
        for (int x = 0; x < flat.width(); ++x) {
            QCOMPARE(isBlack(flat.pixel(x, y)), isBlack(phong.pixel(x, y)));
            differing += flat.pixel(x, y) != phong.pixel(x, y) ? 1 : 0;
        }
    }
    QVERIFY2(differing > 1000, qPrintable(QString::number(differing)));
}

void TestMainWindow::lastShadingWins() {
    MainWindow window;
    QSignalSpy spy(window.controller(), &RenderController::frameReady);
    WAIT_FOR_FIRST_FRAME(spy);
    spy.clear();
    window.setShading(rl::ShadingModel::Flat);
    window.setShading(rl::ShadingModel::Phong);
    window.setShading(rl::ShadingModel::Gouraud);
    while (spy.isEmpty() || frameAt(spy, spy.count() - 1).trace->scene->draws.front().shading !=
                                rl::ShadingModel::Gouraud)
        QVERIFY2(spy.wait(kFrameTimeoutMs), "no Gouraud frame within 10 s");
    QVERIFY(!spy.wait(300));  // and nothing after it
    // Flat started at once; Phong waited and was replaced by Gouraud, the newest.
    QCOMPARE(spy.count(), 2);
    QCOMPARE(frameAt(spy, 0).trace->scene->draws.front().shading, rl::ShadingModel::Flat);
    QCOMPARE(window.currentFrame()->scene->draws.front().shading, rl::ShadingModel::Gouraud);
    QVERIFY(!window.controller()->isBusy());
}

void TestMainWindow::exportImage() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    MainWindow window;
    QSignalSpy spy(window.controller(), &RenderController::frameReady);
    WAIT_FOR_FIRST_FRAME(spy);
    const QString path = dir.filePath("export.png");
    QVERIFY(window.exportImage(path));
    QCOMPARE(window.statusBar()->currentMessage(),
             QStringLiteral("Exported %1").arg(QFileInfo(path).absoluteFilePath()));
    QCOMPARE(window.messages()->count(), 0);

    const QImage exported(path);
    QVERIFY(!exported.isNull());
    QCOMPARE(exported.size(), QSize(800, 600));
    const QImage shown = window.currentImage().convertToFormat(QImage::Format_RGBA8888);
    QVERIFY(exported.convertToFormat(QImage::Format_RGBA8888) == shown);
    QCOMPARE(exported.pixel(400, 350), window.currentImage().pixel(400, 350));
}

void TestMainWindow::exportToMissingFolder() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    MainWindow window;
    QSignalSpy spy(window.controller(), &RenderController::frameReady);
    WAIT_FOR_FIRST_FRAME(spy);
    const auto frameBefore = window.currentFrame();
    const QString path = dir.filePath("no-such-folder/export.png");
    QVERIFY(!window.exportImage(path));
    QVERIFY(!QFile::exists(path));
    QCOMPARE(window.messages()->count(), 1);
    const QString prefix = QStringLiteral("Error: %1: cannot export the image: ").arg(path);
    const QString text = window.messages()->item(0)->text();
    QVERIFY2(text.startsWith(prefix) && text.size() > prefix.size(), qPrintable(text));
    QCOMPARE(window.statusBar()->currentMessage(), text.mid(int(qstrlen("Error: "))));
    QCOMPARE(window.currentFrame(), frameBefore);
}

void TestMainWindow::presentationFontsComeBack() {
    MainWindow window;
    window.show();
    QSignalSpy spy(window.controller(), &RenderController::frameReady);
    WAIT_FOR_FIRST_FRAME(spy);
    QToolButton* button = window.stageStrip()->button(rl::StageId::Projection);
    const qreal normal = button->font().pointSizeF();
    // Half as large again on a 1080-pixel screen, and no less than a quarter larger on
    // smaller ones.
    QCOMPARE(rasterlab::presentationTextScale(1080), 1.5);
    QCOMPARE(rasterlab::presentationTextScale(2160), 1.5);
    QCOMPARE(rasterlab::presentationTextScale(900), 1.25);
    QCOMPARE(rasterlab::presentationTextScale(720), 1.25);
    QCOMPARE(rasterlab::presentationTextScale(1000), 1.5 * 1000 / 1080);
    window.setPresentationMode(true);
    // The stage strip's buttons follow the larger application font, and come back with it
    // (they stayed large until the next scene).
    QTRY_COMPARE(button->font().pointSizeF(),
                 normal * rasterlab::presentationTextScale(window.screen()->size().height()));
    window.setPresentationMode(false);
    QTRY_COMPARE(button->font().pointSizeF(), normal);
}

void TestMainWindow::presentationAfterFillGivesTheLayoutBack() {
    // A dock fills the window (F11), then presentation mode: the docks come back first, and
    // all of them again after presentation mode, with the image.
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    const auto shown = [&] {
        QStringList names;
        for (const QDockWidget* dock : window.findChildren<QDockWidget*>())
            if (!dock->isHidden()) names << dock->objectName();
        names.sort();
        return names;
    };
    const QStringList before = shown();
    auto* normals = window.findChild<QDockWidget*>(QStringLiteral("normalsDock"));
    QVERIFY(normals);
    window.toggleFill(normals);
    QVERIFY(window.isFilled());
    window.setLectureLayout(false);  // the teacher's own layout: the image stays
    window.setPresentationMode(true);
    QVERIFY(!window.isFilled());
    QVERIFY(!window.centralWidget()->isHidden());
    window.setPresentationMode(false);
    QCOMPARE(shown(), before);
    QVERIFY(!window.centralWidget()->isHidden());
}

void TestMainWindow::coveredViewsRefreshWhenRaised() {
    // A view tabbed behind another is covered but visible to Qt: it leaves the steps out and
    // catches up when its tab comes to the front.
    MainWindow window;
    window.resize(1600, 1000);
    window.show();
    QVERIFY(window.openExample(QStringLiteral("triangle")));
    QTRY_VERIFY_WITH_TIMEOUT(window.isReadyToStep(), kFrameTimeoutMs);
    auto* scanDock = window.findChild<QDockWidget*>(QStringLiteral("scanlineDock"));
    auto* trapezoidDock = window.findChild<QDockWidget*>(QStringLiteral("trapezoidDock"));
    auto* trapezoids = window.findChild<rasterlab::ExplainedView*>(QStringLiteral("trapezoidView"));
    QVERIFY(scanDock && trapezoidDock && trapezoids);
    scanDock->raise();
    QTRY_VERIFY(trapezoids->visibleRegion().isEmpty());
    QVERIFY(trapezoids->isVisible());
    for (int i = 0; i < 6; ++i) window.inspection()->stepForward();
    const QString covered = trapezoids->explanationText();
    trapezoidDock->raise();
    QTRY_VERIFY(!trapezoids->visibleRegion().isEmpty());
    QTRY_VERIFY(trapezoids->explanationText() != covered);
    // What it shows now is what it shows after one more refresh at the same cursor.
    const QString raised = trapezoids->explanationText();
    scanDock->raise();
    trapezoidDock->raise();
    QCOMPARE(trapezoids->explanationText(), raised);

    // The painter's comparison (a second render) is made for a new frame only when its dock
    // is on top.
    auto* painterDock = window.findChild<QDockWidget*>(QStringLiteral("painterDock"));
    rasterlab::PainterView* painter = window.painterView();
    QVERIFY(painterDock && painter);
    scanDock->raise();
    QTRY_VERIFY(painter->visibleRegion().isEmpty());
    const rl::PainterComparison* before = painter->comparison();
    window.setShading(rl::ShadingModel::Flat);
    QTRY_VERIFY_WITH_TIMEOUT(
        window.isReadyToStep() && window.currentFrame() &&
            window.currentFrame()->scene->draws.front().shading == rl::ShadingModel::Flat,
        kFrameTimeoutMs);
    QCOMPARE(painter->comparison(), before);  // not worked out while covered
    painterDock->raise();
    QTRY_VERIFY(painter->comparison() != before);
}

void TestMainWindow::docks() {
    MainWindow window;
    const QList<QDockWidget*> docks = window.findChildren<QDockWidget*>();
    QCOMPARE(docks.size(), 18);
    std::set<QString> names;
    for (const QDockWidget* dock : docks) {
        QVERIFY2(!dock->objectName().isEmpty(), qPrintable(dock->windowTitle()));
        QVERIFY(dock->widget());
        names.insert(dock->objectName());
    }
    const std::set<QString> expected = {
        QStringLiteral("messagesDock"),    QStringLiteral("sceneDock"),
        QStringLiteral("accuracyDock"),    QStringLiteral("zbufferDock"),
        QStringLiteral("breakpointsDock"), QStringLiteral("editDock"),
        QStringLiteral("cameraBasisDock"), QStringLiteral("projectionDock"),
        QStringLiteral("scanlineDock"),    QStringLiteral("pixelInspectorDock"),
        QStringLiteral("vertexTableDock"), QStringLiteral("normalsDock"),
        QStringLiteral("animationDock"),   QStringLiteral("nearClipDock"),
        QStringLiteral("trapezoidDock"),   QStringLiteral("painterDock"),
        QStringLiteral("compareDock"),     QStringLiteral("checkDock")};
    QCOMPARE(names, expected);
    const auto* messagesDock = window.findChild<QDockWidget*>(QStringLiteral("messagesDock"));
    QVERIFY(messagesDock);
    QCOMPARE(messagesDock->widget(), window.messages());
    // Unique object names let saveState/restoreState find the docks again.
    QVERIFY(!window.saveState().isEmpty());
}

void TestMainWindow::layoutSavedAndReset() {
    // Settings of our own, in a temporary folder: the user's are not touched.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, dir.path());
    QCoreApplication::setOrganizationName(QStringLiteral("RasterLabLayoutTest"));
    const auto zbufferShown = [](const MainWindow& window) {
        return !window.findChild<QDockWidget*>(QStringLiteral("zbufferDock"))->isHidden();
    };
    {
        MainWindow window;
        QVERIFY(zbufferShown(window));  // nothing saved yet: the default layout
        window.findChild<QDockWidget*>(QStringLiteral("zbufferDock"))->hide();
        window.close();  // saves the layout
    }
    {
        MainWindow window;
        QVERIFY(!zbufferShown(window));  // restored as it was left
        auto* reset = window.findChild<QAction*>(QStringLiteral("resetLayoutAction"));
        QVERIFY(reset);
        reset->trigger();
        QVERIFY(zbufferShown(window));
        window.findChild<QDockWidget*>(QStringLiteral("zbufferDock"))->hide();
        window.close();
    }
    {
        // A layout written by another version is not restored.
        QSettings settings;
        QCOMPARE(settings.value(QStringLiteral("layout/version")).toInt(),
                 MainWindow::kLayoutVersion);
        settings.setValue(QStringLiteral("layout/version"), MainWindow::kLayoutVersion + 1);
    }
    {
        MainWindow window;
        QVERIFY(zbufferShown(window));
    }
    QCoreApplication::setOrganizationName(QString());
}

void TestMainWindow::newestRequestWins() {
    RenderController controller;
    QSignalSpy frames(&controller, &RenderController::frameReady);
    QSignalSpy failures(&controller, &RenderController::failed);
    QSignalSpy busy(&controller, &RenderController::busyChanged);

    // One triangle in front of the axis camera; the scenes differ in their width.
    const auto mesh =
        testing::makeMesh({{-1.0, -1.0, 5.0}, {1.0, -1.0, 5.0}, {0.0, 1.0, 5.0}}, {{0, 1, 2}});
    std::vector<std::shared_ptr<const rl::Scene>> scenes;
    for (int width = 40; width <= 400; width += 40)
        scenes.push_back(std::make_shared<const rl::Scene>(
            testing::makeScene(testing::axisCamera(), mesh, width, 30)));
    for (const auto& scene : scenes) controller.request(scene);
    QVERIFY(controller.isBusy());

    const auto newest = scenes.back();
    while (frames.isEmpty() || frameAt(frames, frames.count() - 1).trace->scene != newest)
        QVERIFY2(frames.wait(kFrameTimeoutMs), "no frame for the newest request within 10 s");
    QVERIFY(!frames.wait(300));  // nothing after the newest

    // The first request started at once; the eight in between were replaced by the newest.
    QCOMPARE(frames.count(), 2);
    QCOMPARE(frameAt(frames, 0).trace->scene, scenes.front());
    const RenderedFrame last = frameAt(frames, 1);
    QCOMPARE(last.trace->scene, newest);
    QCOMPARE(last.image.size(), QSize(400, 30));
    QVERIFY(hasLitPixel(last.image));
    QCOMPARE(failures.count(), 0);
    QVERIFY(!controller.isBusy());
    QVERIFY(!busy.isEmpty());
    QCOMPARE(busy.first().at(0).toBool(), true);
    QCOMPARE(busy.last().at(0).toBool(), false);
}

void TestMainWindow::failedRenderKeepsTheLastImage() {
    RenderController controller;
    QSignalSpy frames(&controller, &RenderController::frameReady);
    QSignalSpy failures(&controller, &RenderController::failed);
    QSignalSpy busy(&controller, &RenderController::busyChanged);
    rl::Scene scene = testing::makeScene(
        testing::axisCamera(),
        testing::makeMesh({{-1.0, -1.0, 5.0}, {1.0, -1.0, 5.0}, {0.0, 1.0, 5.0}}, {{0, 1, 2}}), 0,
        30);
    scene.name = "empty.byu";
    controller.request(std::make_shared<const rl::Scene>(scene));
    QVERIFY2(failures.wait(kFrameTimeoutMs), "no failure reported within 10 s");
    QCOMPARE(failures.first().at(0).toString(),
             QStringLiteral("empty.byu: the image size 0x30 is empty"));
    QCOMPARE(frames.count(), 0);
    QCOMPARE(busy.count(), 2);  // true, then false: one busy period
    QVERIFY(!controller.isBusy());
}

void TestMainWindow::controllerDestroyedWhileRendering() {
    // A render still running when its controller goes (the window closes): no crash, and
    // the result is simply dropped.
    auto* controller = new RenderController;
    const auto mesh =
        testing::makeMesh({{-1.0, -1.0, 5.0}, {1.0, -1.0, 5.0}, {0.0, 1.0, 5.0}}, {{0, 1, 2}});
    controller->request(std::make_shared<const rl::Scene>(
        testing::makeScene(testing::axisCamera(), mesh, 2000, 2000)));
    QVERIFY(controller->isBusy());
    delete controller;
    QThreadPool::globalInstance()->waitForDone();
    QCoreApplication::processEvents();
}

void TestMainWindow::commandFile() {
    MainWindow window;
    QSignalSpy spy(window.controller(), &RenderController::frameReady);
    WAIT_FOR_FIRST_FRAME(spy);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    // Two images; the first is shown; a red triangle over the left half of a 20x10 image.
    const QString path = writeFixture(dir, QStringLiteral("two.txt"),
                                      "png 20 10 first.png\ncolor 1 0 0\nxyz -1 -1 0\n"
                                      "xyz 0 -1 0\nxyz -1 1 0\ntrif 1 2 3\n"
                                      "png 8 8 second.png\ntrif 1 2 3\n");
    QVERIFY(window.openCommandFile(path));
    QVERIFY2(spy.wait(kFrameTimeoutMs), "no frame for the command file");
    const RenderedFrame frame = frameAt(spy, spy.count() - 1);
    QCOMPARE(frame.image.size(), QSize(20, 10));
    QCOMPARE(frame.image.pixelColor(1, 1), QColor(255, 0, 0, 255));
    QCOMPARE(frame.image.pixelColor(19, 9).alpha(), 0);  // untouched: transparent
    QCOMPARE(window.windowTitle(), QStringLiteral("two.txt[*] - RasterLab"));
    QVERIFY(window.document().showsCommandFile());
    QCOMPARE(window.document().imageNames(), QStringList({"first.png", "second.png"}));
    auto* imageMenu = window.findChild<QMenu*>(QStringLiteral("imageMenu"));
    QVERIFY(imageMenu && imageMenu->isEnabled());
    QCOMPARE(imageMenu->actions().size(), 2);
    imageMenu->actions().at(1)->trigger();
    QVERIFY2(spy.wait(kFrameTimeoutMs), "no frame for the second image");
    QCOMPARE(frameAt(spy, spy.count() - 1).image.size(), QSize(8, 8));
    // A bad command file keeps what is shown.
    const QString bad =
        writeFixture(dir, QStringLiteral("bad.txt"), "png 8 8 x.png\nxyz 1 two 3\n");
    const int frames = int(spy.count());
    QVERIFY(!window.openCommandFile(bad));
    QCOMPARE(
        window.messages()->item(0)->text(),
        QStringLiteral("Error: %1:2:7: expected a number in 'xyz' (x y z), found 'two'").arg(bad));
    QVERIFY(!spy.wait(300));
    QCOMPARE(int(spy.count()), frames);
    QCOMPARE(window.document().imageIndex(), 1);
    // Opening a course part shows the course scene again.
    QVERIFY(window.openPart(SceneDocument::Part::Camera,
                            rasterlab::defaultScenePath(rasterlab::CoursePart::Camera)));
    QVERIFY(!window.document().showsCommandFile());
}

void TestMainWindow::courseFileLayouts() {
    MainWindow window;
    QSignalSpy spy(window.controller(), &RenderController::frameReady);
    WAIT_FOR_FIRST_FRAME(spy);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    // The default camera as UFRPE six lines: N; V; d; hx; hy; C. Detected, with a note.
    const QString path = writeFixture(dir, QStringLiteral("six.cfg"),
                                      "0 380 -330\n0 0 1\n1\n0.4\n0.3\n0 -380 330\n");
    QVERIFY(window.openPart(SceneDocument::Part::Camera, path));
    QVERIFY2(spy.wait(kFrameTimeoutMs), "no frame for the camera");
    QCOMPARE(window.document().parts().camera.c, rl::dvec3(0, -380, 330));
    bool noted = false;
    for (int i = 0; i < window.messages()->count(); ++i)
        noted =
            noted || window.messages()->item(i)->text().contains(QStringLiteral("six.cfg: note:"));
    QVERIFY(noted);
    // Forcing the UFPE layout does not fit the file: an error, the camera stays.
    QVERIFY(!window.setCameraLayout(rl::CameraLayout::Ufpe));
    QVERIFY(window.messages()->item(0)->text().startsWith(QStringLiteral("Error: ") + path));
    QCOMPARE(window.document().parts().camera.c, rl::dvec3(0, -380, 330));
    QCOMPARE(window.document().cameraLayout(), rl::CameraLayout::Ufpe);
    // Back to detection: it reads again.
    QVERIFY(window.setCameraLayout(rl::CameraLayout::Auto));
    auto* menu = window.findChild<QMenu*>(QStringLiteral("layoutMenu"));
    QVERIFY(menu);
}

QTEST_MAIN(TestMainWindow)
#include "tst_main_window.moc"
