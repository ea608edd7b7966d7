// The teaching window in-process (offscreen): stepping through the frame and back, the
// image and the overlays at the cursor, breakpoints, the clicker's keys in presentation mode,
// the stage strip's skipped stages, opening any file or a folder, recent files, drag and drop,
// reading a file again when it changes on disk (also when saved by renaming), and the exports.
#include <QtTest>

#include <QAction>
#include <QDockWidget>
#include <QFile>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMimeData>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QTemporaryDir>
#include <QToolButton>

#include "app/window/main_window.h"
#include "app/window/replay_builder.h"
#include "tests/test_support.h"
#include "views/breakpoints_view.h"
#include "views/frame_image_view.h"
#include "views/inspection.h"
#include "views/painted_labels.h"
#include "views/pixel_inspector.h"
#include "views/stage_strip.h"
#include "views/stepping_bar.h"

using namespace rasterlab;

namespace {

constexpr int kTimeoutMs = 15000;

QString writeFixture(const QString& path, const QByteArray& content) {
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(content) != content.size()) return {};
    return path;
}

// A tetrahedron around the origin, where the default camera looks (4 triangles).
const QByteArray kTetrahedron =
    "4 4\n-80 -80 -80\n80 80 -80\n80 -80 80\n-80 80 80\n1 2 3\n1 4 2\n1 3 4\n2 4 3\n";
// One triangle of it.
const QByteArray kOneTriangle = "3 1\n-80 -80 -80\n80 80 -80\n80 -80 80\n1 2 3\n";
const QByteArray kCamera = "0 0 -500\n0 0 1\n0 1 0\n5 1 1\n";  // UFPE: C; N; V; d hx hy
const QByteArray kLighting =
    "0 0 -500\n0.2\n100 100 100\n0.7\n1 0.5 0.2\n0.5\n255 255 255\n8\n";  // UFPE lighting

// Waits until the window shows a frame that can be stepped through.
bool waitForReplay(MainWindow& window) {
    return QTest::qWaitFor([&] { return window.isReadyToStep(); }, kTimeoutMs);
}

int differingPixels(const QImage& a, const QImage& b) {
    const QImage x = a.convertToFormat(QImage::Format_RGBA8888);
    const QImage y = b.convertToFormat(QImage::Format_RGBA8888);
    int n = 0;
    for (int j = 0; j < x.height(); ++j)
        for (int i = 0; i < x.width(); ++i) n += x.pixel(i, j) != y.pixel(i, j) ? 1 : 0;
    return n;
}

}  // namespace

class TestTeaching : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        // Settings of our own, in a folder that goes away.
        QCoreApplication::setOrganizationName(QStringLiteral("RasterLabTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_teaching"));
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settings.path());
    }

    void stepForwardAndBack() {
        MainWindow window;
        QVERIFY(waitForReplay(window));
        Inspection* inspection = window.inspection();
        const rl::FrameReplay* replay = inspection->replay();
        QVERIFY(inspection->atEnd());
        QVERIFY(window.imageView()->image() == window.currentImage());
        inspection->setGranularity(rl::StepGranularity::Scanline);
        window.steppingBar()->toStartAction()->trigger();
        QVERIFY(inspection->atStart());
        const QImage empty = window.imageView()->image().copy();
        QCOMPARE(differingPixels(empty, window.currentImage()) > 1000, true);
        // One scanline: exactly the pixels its fragments wrote change.
        window.steppingBar()->stepForwardAction()->trigger();
        const rl::ReplayCursor one = inspection->cursor();
        QCOMPARE(one, replay->next(replay->start(), rl::StepGranularity::Scanline));
        const rl::ReplayRow& row = replay->rows()[0];
        QCOMPARE(differingPixels(window.imageView()->image(), empty),
                 static_cast<int>(replay->writtenBefore(row.fragmentEnd)));
        QCOMPARE(window.stageStrip()->findChild<QLabel*>(QStringLiteral("stageNote"))->text(),
                 QStringLiteral("while stepping, stages 5-7 run together, fragment by fragment"));
        QVERIFY(window.steppingBar()->positionLabel()->text().contains(
            QStringLiteral("scanline %1").arg(row.y)));
        // The overlay shows the triangle, its scanline and span.
        const ImageOverlay& overlay = window.imageView()->overlay();
        QVERIFY(overlay.currentTriangle.has_value());
        QCOMPARE(overlay.scanline, row.y);
        QCOMPARE(overlay.spanBegin, row.xBegin);
        QCOMPARE(overlay.spanEnd, row.xEnd);
        QCOMPARE(static_cast<int>(overlay.coveredPixels.size()), row.xEnd - row.xBegin);
        // Back: the empty image again.
        window.steppingBar()->stepBackAction()->trigger();
        QVERIFY(inspection->atStart());
        QCOMPARE(differingPixels(window.imageView()->image(), empty), 0);
        // The timeline scrubs: half way, then the end is the frame.
        const int half = window.steppingBar()->timeline()->maximum() / 2;
        window.steppingBar()->timeline()->setValue(half);
        QCOMPARE(inspection->cursor(), replay->atFragment(static_cast<std::uint32_t>(half)));
        window.steppingBar()->toEndAction()->trigger();
        QCOMPARE(differingPixels(window.imageView()->image(), window.currentImage()), 0);
        // Stage granularity walks the strip: nothing drawn up to scan conversion.
        inspection->setGranularity(rl::StepGranularity::Stage);
        window.steppingBar()->toStartAction()->trigger();
        QCOMPARE(inspection->stage(), rl::StageId::CameraBasis);
        QVERIFY(inspection->atStart());
        for (int k = 0; k < 5; ++k) window.steppingBar()->stepForwardAction()->trigger();
        QCOMPARE(inspection->stage(), rl::StageId::DepthTest);
        QVERIFY(inspection->atEnd());
    }

    void playStopsAtTheEndAndAtBreakpoints() {
        MainWindow window;
        const QTemporaryDir dir;
        window.openPart(SceneDocument::Part::Camera,
                        writeFixture(dir.filePath(QStringLiteral("c.cfg")), kCamera));
        window.openPart(SceneDocument::Part::Lighting,
                        writeFixture(dir.filePath(QStringLiteral("l.txt")), kLighting));
        window.openPart(SceneDocument::Part::Object,
                        writeFixture(dir.filePath(QStringLiteral("t.byu")), kTetrahedron));
        QVERIFY(waitForReplay(window));
        Inspection* inspection = window.inspection();
        const rl::FrameReplay* replay = inspection->replay();
        QVERIFY(replay->fragments().size() > 100);
        // Triangle 3 of the file: the replay stops as its first row is reached.
        QVERIFY(window.breakpointsView()->add(rl::Breakpoint::Kind::Triangle, 3));
        inspection->setGranularity(rl::StepGranularity::Scanline);
        window.steppingBar()->toStartAction()->trigger();
        QSignalSpy hits(inspection, &Inspection::breakpointHit);
        window.steppingBar()->setSpeed(240);
        window.steppingBar()->setPlaying(true);
        QVERIFY(hits.wait(kTimeoutMs));
        QVERIFY(!window.steppingBar()->isPlaying());
        const auto* row = inspection->currentRow();
        QVERIFY(row);
        QCOMPARE(window.currentFrame()->projection->triangles[row->triangle].source, 2u);
        QCOMPARE(inspection->cursor(), replay->atRowStart(replay->firstRow(row->triangle)));
        // Continue (F8) finds no further one: the end.
        window.steppingBar()->continueAction()->trigger();
        QVERIFY(inspection->atEnd());
        // Play from the end starts again and runs to the end.
        window.breakpointsView()->clear();
        inspection->setGranularity(rl::StepGranularity::Triangle);
        window.steppingBar()->setPlaying(true);
        QTRY_VERIFY_WITH_TIMEOUT(!window.steppingBar()->isPlaying(), kTimeoutMs);
        QVERIFY(inspection->atEnd());
    }

    void clickerKeysInPresentationMode() {
        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(waitForReplay(window));
        Inspection* inspection = window.inspection();
        inspection->setGranularity(rl::StepGranularity::Triangle);
        inspection->toStart();
        const QFont before = QApplication::font();
        QTest::keyClick(&window, Qt::Key_F5);
        QVERIFY(window.presentationMode());
        QVERIFY(QApplication::font().pointSizeF() > before.pointSizeF());
        QCOMPARE(inspection->lineWidth(), 3.0);
        // In presentation mode the arrows step even with a pixel picked on the image.
        inspection->pickPixel(QPoint(10, 10));
        QWidget* image = window.imageView();
        image->setFocus();
        QTest::keyClick(image, Qt::Key_Right);
        const rl::ReplayCursor one = inspection->replay()->next({}, rl::StepGranularity::Triangle);
        QCOMPARE(inspection->cursor(), one);
        QTest::keyClick(image, Qt::Key_PageDown);
        QCOMPARE(inspection->cursor(),
                 inspection->replay()->next(one, rl::StepGranularity::Triangle));
        QTest::keyClick(image, Qt::Key_PageUp);
        QCOMPARE(inspection->cursor(), one);
        QCOMPARE(inspection->pickedPixel(), QPoint(10, 10));
        QTest::keyClick(image, Qt::Key_Space);
        QVERIFY(window.steppingBar()->isPlaying());
        QTest::keyClick(image, Qt::Key_Space);
        QVERIFY(!window.steppingBar()->isPlaying());
        QTest::keyClick(image, Qt::Key_Escape);
        QVERIFY(!window.presentationMode());
        QCOMPARE(QApplication::font(), before);
        // Not presenting, the arrows on the image move the picked pixel.
        inspection->pickPixel(QPoint(400, 300));
        window.imageView()->setFocus();
        const rl::ReplayCursor here = inspection->cursor();
        QTest::keyClick(window.imageView(), Qt::Key_Right);
        QCOMPARE(inspection->pickedPixel(), QPoint(401, 300));
        QTest::keyClick(window.imageView(), Qt::Key_Up);
        QCOMPARE(inspection->pickedPixel(), QPoint(401, 299));
        QCOMPARE(inspection->cursor(), here);
        // Esc lets go of the pixel; then the arrows step.
        QTest::keyClick(window.imageView(), Qt::Key_Escape);
        QCOMPARE(inspection->pickedPixel(), QPoint(-1, -1));
        QTest::keyClick(window.imageView(), Qt::Key_Right);
        QCOMPARE(inspection->cursor(),
                 inspection->replay()->next(here, rl::StepGranularity::Triangle));
    }

    void pickingSelectsTheTriangle() {
        MainWindow window;
        QVERIFY(waitForReplay(window));
        Inspection* inspection = window.inspection();
        // The knot's lower band covers (400, 350).
        inspection->pickPixel(QPoint(400, 350));
        const std::uint32_t t = window.currentFrame()->depth->triangle.at(400, 350);
        QCOMPARE(inspection->selectedTriangle(), std::optional<std::uint32_t>(t));
        QCOMPARE(inspection->selectedVertices().size(), std::size_t(3));
        const ImageOverlay& overlay = window.imageView()->overlay();
        QCOMPARE(overlay.pickedPixel, QPoint(400, 350));
        QVERIFY(overlay.selectedTriangle.has_value());
        QCOMPARE(overlay.vertices.size(), std::size_t(3));
        // At the start of the frame nothing holds it.
        inspection->setGranularity(rl::StepGranularity::Pixel);
        inspection->toStart();
        inspection->pickPixel(QPoint(400, 350));
        QVERIFY(!inspection->selectedTriangle());
    }

    void skippedStagesAreMarked() {
        MainWindow window;
        QVERIFY(waitForReplay(window));
        QVERIFY(!window.stageStrip()
                     ->button(rl::StageId::CameraBasis)
                     ->text()
                     .contains(QStringLiteral("skipped")));
        const QTemporaryDir dir;
        // An unlit command file: no course camera, nothing lit.
        const QString path = writeFixture(dir.filePath(QStringLiteral("unlit.txt")),
                                          "png 20 10 a.png\ncolor 1 0 0\nxyz -1 -1 0\n"
                                          "xyz 1 -1 0\nxyz 0 1 0\ntrif 1 2 3\n");
        QVERIFY(window.openPath(path));
        QVERIFY(waitForReplay(window));
        for (rl::StageId stage :
             {rl::StageId::CameraBasis, rl::StageId::Normals, rl::StageId::Shading})
            QVERIFY2(
                window.stageStrip()->button(stage)->text().endsWith(QStringLiteral("(skipped)")),
                qPrintable(window.stageStrip()->button(stage)->text()));
        QCOMPARE(window.stageStrip()->button(rl::StageId::Normals)->toolTip(),
                 QStringLiteral("Normals is skipped: nothing is lit: no light reads a normal"));
        QVERIFY(!window.stageStrip()
                     ->button(rl::StageId::Projection)
                     ->text()
                     .contains(QStringLiteral("skipped")));
    }

    void phongWorkedOutByHandInTheInspector() {
        // Camera at the origin looking along +z, V = y: view = (-x, y, z). A square at z = 2
        // filling the 800x600 image; pixel (400, 300) is sampled at its corner, NDC (0, 0):
        // the view point P' = (0, 0, 2).
        // N = (P2 - P1) x (P3 - P1) in view space = (-8, 0, 0) x (-8, 8, 0) / 64 = (0, 0, -1),
        // toward the viewer already (not flipped); the light at (0, 2, 0):
        // L = (0, 2, -2) / (2 sqrt 2) = (0, 0.70711, -0.70711); N.L = 0.70711;
        // R = 2 (N.L) N - L = (0, -0.70711, -0.70711); V = (0, 0, -1); R.V = 0.70711.
        // Ia ka = 100 x 0.2 = 20; Il Od kd (N.L) = 200 x (1, 0.5, 0.25) x 0.5 x 0.70711 =
        // (70.711, 35.355, 17.678); Il ks (R.V)^3 = 200 x 0.25 x 0.35355 = 17.678.
        // I = (108.39, 73.03, 55.36): bytes (108, 73, 55).
        MainWindow window;
        window.resize(1400, 900);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const QTemporaryDir dir;
        QVERIFY(window.openPath(
            writeFixture(dir.filePath(QStringLiteral("c.cfg")), "0 0 0\n0 0 1\n0 1 0\n1 1 1\n")));
        QVERIFY(window.openPath(writeFixture(dir.filePath(QStringLiteral("l.txt")),
                                             "0 2 0\n0.2\n100 100 100\n0.5\n1 0.5 0.25\n0.25\n"
                                             "200 200 200\n3\n")));
        QVERIFY(
            window.openPath(writeFixture(dir.filePath(QStringLiteral("square.byu")),
                                         "4 2\n-4 -4 2\n4 -4 2\n4 4 2\n-4 4 2\n1 2 3\n1 3 4\n")));
        QVERIFY(waitForReplay(window));
        const auto frame = window.currentFrame();
        const QPoint pixel(frame->scene->width / 2, frame->scene->height / 2);
        QCOMPARE(frame->scene->width % 2, 0);
        // Click on the pixel in the image.
        window.imageView()->fitToWindow();
        const QPointF at = window.imageView()->widgetPoint(QPointF(pixel) + QPointF(0.5, 0.5));
        QTest::mouseClick(window.imageView(), Qt::LeftButton, Qt::NoModifier, at.toPoint());
        QCOMPARE(window.inspection()->pickedPixel(), pixel);
        PixelInspector* inspector = window.pixelInspector();
        inspector->show();
        QTRY_VERIFY_WITH_TIMEOUT(inspector->breakdown().has_value(), kTimeoutMs);
        const LightingBreakdown& b = *inspector->breakdown();
        QVERIFY(!b.has(LightingFlag::Flipped));
        QVERIFY(!b.has(LightingFlag::LightBehind));
        RL_COMPARE_VEC(b.ambient, rl::vec3(20.0f), 1e-4);
        RL_COMPARE_VEC(b.diffuse, rl::vec3(70.7107f, 35.3553f, 17.6777f), 1e-3);
        RL_COMPARE_VEC(b.specular, rl::vec3(17.6777f), 1e-3);
        RL_COMPARE_NEAR(b.event.sample.nDotL, 0.707107, 1e-5);
        RL_COMPARE_NEAR(b.event.sample.rDotV, 0.707107, 1e-5);
        QCOMPARE(b.bytes, (std::array<std::uint8_t, 4>{108, 73, 55, 255}));
        QVERIFY2(inspector->formulaText().contains(QStringLiteral("70.71")),
                 qPrintable(inspector->formulaText()));
        QCOMPARE(window.currentImage().pixelColor(pixel), QColor(108, 73, 55));
    }

    // The bars' dashed colour scale (white) never crosses a total's digits: on the goblet's
    // highlight the red total, 237.4, ends its bar just short of the scale at 255.
    void inspectorTotalsStayClearOfTheScale() {
        MainWindow window;
        window.resize(1400, 900);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.openExample(QStringLiteral("goblet")));
        QVERIFY(waitForReplay(window));
        window.inspection()->pickPixel(QPoint(352, 148));
        PixelInspector* inspector = window.pixelInspector();
        inspector->show();
        QTRY_VERIFY_WITH_TIMEOUT(inspector->breakdown().has_value(), kTimeoutMs);
        QCOMPARE(inspector->breakdown()->bytes[0], std::uint8_t(237));
        auto* bars = inspector->findChild<QWidget*>(QStringLiteral("pixelTermBars"));
        auto* labels = dynamic_cast<rasterlab::PaintedLabels*>(bars);
        QVERIFY(bars && labels);
        int crossedAt = -1;
        for (int width = 240; width <= 640 && crossedAt < 0; width += 10) {
            bars->resize(width, bars->height());
            const QImage image = bars->grab().toImage();
            for (const QRect& r : labels->labelRects())
                for (int y = r.top(); y <= r.bottom(); ++y)
                    for (int x = r.left(); x <= r.right(); ++x)
                        if (image.rect().contains(x, y) && image.pixelColor(x, y) == Qt::white)
                            crossedAt = width;
        }
        QCOMPARE(crossedAt, -1);
    }

    void languageChoiceIsKept() {
        MainWindow window;
        QSignalSpy spy(&window, &MainWindow::languageChangeRequested);
        auto* portuguese = window.findChild<QAction*>(QStringLiteral("language_pt_BR"));
        QVERIFY(portuguese);
        portuguese->trigger();
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(0).toString(), QStringLiteral("pt_BR"));
        QCOMPARE(QSettings().value(QStringLiteral("language")).toString(), QStringLiteral("pt_BR"));
        window.findChild<QAction*>(QStringLiteral("language_system"))->trigger();
        QCOMPARE(QSettings().value(QStringLiteral("language")).toString(), QString());
    }

    void anotherWindowTakesTheDocument() {
        // A new language builds the window again: the new one takes the old one's document,
        // edits not saved included, and the old one closes without asking about them.
        auto first = std::make_unique<MainWindow>();
        QVERIFY(waitForReplay(*first));
        first->setShading(rl::ShadingModel::Gouraud);
        SceneDocument edited = first->document();
        edited.setValue(SceneDocument::Field::Ks, {0.125, 0.0, 0.0});
        QVERIFY(edited.isModified());
        MainWindow second;
        second.adoptDocument(edited);
        QVERIFY(second.document().isModified());
        QCOMPARE(second.document().value(SceneDocument::Field::Ks)[0], 0.125);
        QCOMPARE(second.document().settings().shading, rl::ShadingModel::Gouraud);
        QVERIFY(waitForReplay(second));
        QCOMPARE(second.currentFrame()->scene->draws[0].shading, rl::ShadingModel::Gouraud);
        QCOMPARE(second.currentFrame()->scene->draws[0].material.ks, 0.125f);
        QVERIFY(second.isWindowModified());
        first->show();
        QVERIFY(first->handOver());  // no question asked: it would block here
        QVERIFY(!first->isVisible());
    }

    void detectsWhatAFileHolds() {
        const QTemporaryDir dir;
        auto file = [&](const char* name, const QByteArray& text) {
            return writeFixture(dir.filePath(QLatin1String(name)), text);
        };
        QCOMPARE(detectFileKind(file("a.byu", kTetrahedron)), FileKind::Object);
        QCOMPARE(detectFileKind(file("object.txt", kTetrahedron)), FileKind::Object);
        QCOMPARE(detectFileKind(file("camera.txt", kCamera)), FileKind::Camera);
        QCOMPARE(detectFileKind(file("light.txt", kLighting)), FileKind::Lighting);
        QCOMPARE(detectFileKind(file("kv.txt",
                                     "C = 0 0 -5\nN = 0 0 1\nV = 0 1 0\nd = 1\n"
                                     "hx = 1\nhy = 1\n")),
                 FileKind::Camera);
        QCOMPARE(detectFileKind(file("kvl.txt", "Iamb = 1 1 1\nKa = 0.1\nPl = 0 0 0\n")),
                 FileKind::Lighting);
        QCOMPARE(detectFileKind(file("both.txt", "C = 0 0 -5\nN = 0 0 1\nIamb = 1 1 1\n")),
                 FileKind::CameraAndLighting);
        QCOMPARE(detectFileKind(file("hw2.txt", "png 4 4 x.png\nxyz 0 0 0\n")),
                 FileKind::CommandFile);
        QCOMPARE(detectFileKind(file("notes.txt", "hello there\n")), FileKind::Unknown);
    }

    void opensAFolderAndRemembersFiles() {
        QSettings().remove(QStringLiteral("recentFiles"));
        MainWindow window;
        QVERIFY(waitForReplay(window));
        const QTemporaryDir dir;
        const QString camera = writeFixture(dir.filePath(QStringLiteral("cam.cfg")), kCamera);
        const QString lighting = writeFixture(dir.filePath(QStringLiteral("luz.txt")), kLighting);
        const QString object =
            writeFixture(dir.filePath(QStringLiteral("tetra.byu")), kTetrahedron);
        QVERIFY(window.openPath(dir.path()));
        QCOMPARE(window.document().source(SceneDocument::Part::Camera), camera);
        QCOMPARE(window.document().source(SceneDocument::Part::Lighting), lighting);
        QCOMPARE(window.document().source(SceneDocument::Part::Object), object);
        QCOMPARE(window.recentFiles().first(), object);
        QCOMPARE(window.recentFiles().size(), 3);
        auto* recent = window.findChild<QMenu*>(QStringLiteral("recentMenu"));
        QVERIFY(recent->actions().first()->text().endsWith(QStringLiteral("tetra.byu")));
        QCOMPARE(window.watchedFiles().size(), 3);
        // A folder with nothing RasterLab reads: the error, and the scene stays.
        const QTemporaryDir empty;
        writeFixture(empty.filePath(QStringLiteral("readme.txt")), "nothing\n");
        QVERIFY(!window.openPath(empty.path()));
        QCOMPARE(window.document().source(SceneDocument::Part::Object), object);
        QVERIFY(window.messages()->item(0)->text().contains(QStringLiteral("no course camera")));
    }

    void dropOpensFiles() {
        MainWindow window;
        QVERIFY(waitForReplay(window));
        const QTemporaryDir dir;
        const QString object = writeFixture(dir.filePath(QStringLiteral("drop.byu")), kTetrahedron);
        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(object)});
        QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &mime, Qt::LeftButton,
                              Qt::NoModifier);
        QCoreApplication::sendEvent(&window, &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(&window, &drop);
        QCOMPARE(window.document().source(SceneDocument::Part::Object), object);
    }

    void readsAChangedFileAgain() {
        MainWindow window;
        QVERIFY(waitForReplay(window));
        const QTemporaryDir dir;
        const QString object = writeFixture(dir.filePath(QStringLiteral("w.byu")), kTetrahedron);
        QVERIFY(window.openPart(SceneDocument::Part::Object, object));
        QTRY_COMPARE_WITH_TIMEOUT(window.currentFrame()->scene->triangleCount(), std::size_t(4),
                                  kTimeoutMs);
        // Saved in place.
        writeFixture(object, kOneTriangle);
        QTRY_COMPARE_WITH_TIMEOUT(window.currentFrame()->scene->triangleCount(), std::size_t(1),
                                  kTimeoutMs);
        // Saved by writing another file and renaming it over this one (as many editors do):
        // still watched.
        const QString temporary =
            writeFixture(dir.filePath(QStringLiteral("w.byu.tmp")), kTetrahedron);
        QVERIFY(QFile::remove(object));
        QVERIFY(QFile::rename(temporary, object));
        QTRY_COMPARE_WITH_TIMEOUT(window.currentFrame()->scene->triangleCount(), std::size_t(4),
                                  kTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(window.watchedFiles().contains(object), kTimeoutMs);
        // A bad save: the message, and the scene stays.
        QByteArray bad = kTetrahedron;
        bad.replace("80 80 -80", "80 8x0 -80");
        writeFixture(object, bad);
        QTRY_VERIFY_WITH_TIMEOUT(
            window.messages()->count() > 0 &&
                window.messages()->item(0)->text().startsWith(
                    QStringLiteral("Error: ") + object + QStringLiteral(":3:4: expected a number")),
            kTimeoutMs);
        QCOMPARE(window.currentFrame()->scene->triangleCount(), std::size_t(4));
        QCOMPARE(window.document().parts().object.mesh->triangles.size(), std::size_t(4));
    }

    void exports() {
        MainWindow window;
        window.resize(1200, 800);
        const QTemporaryDir dir;
        window.openPart(SceneDocument::Part::Object,
                        writeFixture(dir.filePath(QStringLiteral("t.byu")), kTetrahedron));
        QVERIFY(waitForReplay(window));
        Inspection* inspection = window.inspection();
        // The steps, one image per triangle stop and one for the start.
        inspection->setGranularity(rl::StepGranularity::Triangle);
        int stops = 1;
        for (rl::ReplayCursor c; c != inspection->replay()->end();
             c = inspection->replay()->next(c, rl::StepGranularity::Triangle))
            ++stops;
        const QString steps = dir.filePath(QStringLiteral("steps"));
        QCOMPARE(window.exportSequence(steps, 1000), stops);
        QVERIFY(QFile::exists(steps + QStringLiteral("/step-00000.png")));
        QVERIFY(QFile::exists(
            steps + QStringLiteral("/step-%1.png").arg(stops - 1, 5, 10, QLatin1Char('0'))));
        QVERIFY(inspection->atEnd());  // where it was
        QCOMPARE(window.exportSequence(dir.filePath(QStringLiteral("two")), 2), 2);
        // The image as displayed; the depth buffer at the start (all empty: black).
        const QString shown = dir.filePath(QStringLiteral("shown.png"));
        QVERIFY(window.exportDisplayed(shown));
        QCOMPARE(QImage(shown).size(),
                 window.imageView()->size() * window.imageView()->devicePixelRatio());
        inspection->toStart();
        const QString depth = dir.filePath(QStringLiteral("depth.png"));
        QVERIFY(window.exportDepthBuffer(depth));
        const QImage z(depth);
        QCOMPARE(z.size(), QSize(800, 600));
        QCOMPARE(z.pixel(400, 300), qRgba(0, 0, 0, 255));
        inspection->toEnd();
        QVERIFY(window.exportDepthBuffer(depth));
        QVERIFY(QImage(depth).pixel(400, 300) != qRgba(0, 0, 0, 255));
        QVERIFY(window.exportNormalBuffer(dir.filePath(QStringLiteral("n.png"))));
        QVERIFY(window.exportDock(QStringLiteral("zbufferDock"),
                                  dir.filePath(QStringLiteral("z.png"))));
        QVERIFY(!window.exportDock(QStringLiteral("noSuchDock"),
                                   dir.filePath(QStringLiteral("x.png"))));
        // An unwritable place: the error, nothing else lost.
        QVERIFY(!window.exportDisplayed(dir.filePath(QStringLiteral("no/such/folder/x.png"))));
    }

private:
    QTemporaryDir m_settings;
};

QTEST_MAIN(TestTeaching)
#include "tst_teaching.moc"
