// The camera basis and projection views: Gram-Schmidt's steps on a camera worked out by
// hand, what the 3D drawing shows at each step, the matrix and the residuals; a nearly
// parallel N and V flagged, a rejected camera shown until the next frame, a HW2 scene's
// skipped stage; the projection's fates counted by hand on a scene with a triangle inside,
// one culled, one crossing the near plane and one behind it; the formulas' numbers; the
// side view's vertices made by clipping; selection by clicking; the highlights following
// the inspection; and both views on the trefoil and on calice2.
#include <QtTest>

#include <QSlider>
#include <QToolButton>

#include <algorithm>

#include "app/documents/command_file.h"
#include "app/documents/default_scene_resource.h"
#include "pipeline/io/course_scene.h"
#include "pipeline/render/renderer.h"
#include "pipeline/render/replay.h"
#include "pipeline/scene/benchmark_scenes.h"
#include "tests/course_scenes.h"
#include "tests/test_support.h"
#include "views/camera_basis_view.h"
#include "views/inspection.h"
#include "views/projection_view.h"

using rasterlab::CameraBasisView;
using rasterlab::Inspection;
using rasterlab::ProjectionCanvas;
using rasterlab::ProjectionSpace;
using rasterlab::ProjectionView;
using testing::lookAt;

namespace {

std::shared_ptr<const rl::FrameTrace> render(rl::Scene scene) {
    rl::RenderOptions options;
    options.threads = 1;
    return testing::renderTrace(std::make_shared<const rl::Scene>(std::move(scene)), options);
}

// C = (1, 2, 3), N = (0, 0, 2), V = (0, 3, 4): |N| = 2, N = (0, 0, 1); V.N = 4,
// (V.N) N = (0, 0, 4), V' = (0, 3, 0); |V'| = 3, V = (0, 1, 0); U = N x V = (-1, 0, 0).
// viewFromWorld rows: U and -U.C = 1; V and -V.C = -2; N and -N.C = -3.
rl::CourseCamera handCamera() {
    rl::CourseCamera camera;
    camera.c = {1.0, 2.0, 3.0};
    camera.n = {0.0, 0.0, 2.0};
    camera.v = {0.0, 3.0, 4.0};
    return camera;
}

rl::Scene cameraScene(const rl::CourseCamera& camera) {
    auto mesh = testing::makeMesh({{1, 2, 8}, {0, 2, 8}, {1, 3, 8}}, {{0, 1, 2}});
    return testing::makeScene(camera, mesh, 40, 30);
}

// The axis camera (view = (-x, y, z), d = hx = hy = 1) on a 100 x 100 image, cull on, the
// near plane at w = 0.5. Screen x = (1 - x/z) 50, y = (1 - y/z) 50, truncated.
//   T0 (0, 1, 2), z = 2: NDC (0.25, 0.25), (0.5, 0.25), (0.25, 0.5); pixels (62, 37),
//      (75, 37), (62, 25): counter-clockwise on screen, drawn whole.
//   T1 (3, 4, 5), z = 2: pixels (62, 62), (75, 62), (62, 75): clockwise, culled.
//   T2 (6, 7, 8): G = (0.5, 0.5, -1) behind the camera, H = (0.5, -0.5, 3) at (41, 58),
//      I = (-0.5, -0.5, 3) at (58, 58). The edges from H and I to G cross z = 0.5 at
//      t = (3 - 0.5) / (3 + 1) = 0.625: vertex 12 = (0.5, 0.125, 0.5) at (0, 37) and
//      vertex 13 = (0.125, 0.125, 0.5) at (37, 37). Its polygon (12, H, I, 13) becomes the
//      fan (12, 7, 8), (12, 8, 13): screen triangles 1 and 2.
//   T3 (9, 10, 11), z = -1: wholly behind the near plane.
// How many mesh triangles ended with a fate, counted from DrawProjection::fate.
std::size_t fateCount(const rl::Projection& projection, rl::TriangleFate fate) {
    std::size_t n = 0;
    for (const rl::DrawProjection& d : projection.draws)
        n += static_cast<std::size_t>(std::count(d.fate.begin(), d.fate.end(), fate));
    return n;
}

// The view's counts are the fates of the mesh triangles.
void compareWithFates(const rasterlab::FateCounts& c, const rl::Projection& p) {
    QCOMPARE(c.inside, fateCount(p, rl::TriangleFate::Inside));
    QCOMPARE(c.clipped, fateCount(p, rl::TriangleFate::Clipped));
    QCOMPARE(c.behind, fateCount(p, rl::TriangleFate::Behind));
    QCOMPARE(c.clippedAway, fateCount(p, rl::TriangleFate::ClippedAway));
    QCOMPARE(c.culled, fateCount(p, rl::TriangleFate::Culled));
    QCOMPARE(c.backFaces, fateCount(p, rl::TriangleFate::BackFace));
    QCOMPARE(c.beyondGuardBand, fateCount(p, rl::TriangleFate::BeyondGuardBand));
    QCOMPARE(c.nonFinite, fateCount(p, rl::TriangleFate::NonFinite));
}

std::shared_ptr<const rl::FrameTrace> clippingFrame() {
    auto mesh = testing::makeMesh({{-0.5, 0.5, 2},
                                   {-1, 0.5, 2},
                                   {-0.5, 1, 2},
                                   {-0.5, -0.5, 2},
                                   {-1, -0.5, 2},
                                   {-0.5, -1, 2},
                                   {0.5, 0.5, -1},
                                   {0.5, -0.5, 3},
                                   {-0.5, -0.5, 3},
                                   {0, 0, -1},
                                   {1, 0, -1},
                                   {0, 1, -1}},
                                  {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}});
    rl::Scene scene = testing::makeScene(testing::axisCamera(), mesh, 100, 100);
    scene.draws[0].cull = true;
    scene.nearPlane.fixedW = 0.5;
    return render(std::move(scene));
}

// The trefoil as the course draws it; with its hidden back faces left out; or seen from a
// tenth of the distance, C = (0, -38, 33), where some of it is behind the camera.
enum class Trefoil { Course, BackFaces, Close };
std::shared_ptr<const rl::FrameTrace> defaultFrame(Trefoil variant = Trefoil::Course) {
    rl::Diagnostics diagnostics;
    auto parts = rasterlab::loadDefaultCourseScene(diagnostics);
    if (!parts) qFatal("%s", parts.error().toString().c_str());
    rl::CourseSceneSettings settings;
    settings.cullHiddenBackFaces = variant == Trefoil::BackFaces;
    if (variant == Trefoil::Close) parts->camera.c *= 0.1;
    return render(rl::makeCourseScene(parts.value(), settings));
}

std::shared_ptr<const rl::FrameTrace> caliceFrame() {
    const auto scene = testing::calice2Scene();
    return scene ? render(*scene) : nullptr;
}

// A view on an Inspection of its own, resized and shown.
template <typename View>
struct Shown {
    explicit Shown(QSize size) {
        view.resize(size);
        view.show();
    }
    Inspection inspection;
    View view{&inspection};
};
constexpr QSize kBasisSize(900, 600), kProjectionSize(900, 700);

}  // namespace

class TestGeometryViews : public QObject {
    Q_OBJECT
private slots:
    void gramSchmidtStepsByHand();
    void stepsRevealTheDrawing();
    void orbitCamera();
    void labelsKeepToTheirVectors();
    void nearlyParallelIsIllConditioned();
    void rejectedCameraShowsUntilNextFrame();
    void hw2SceneSkipsTheStage();
    void fatesCountedByHand();
    void formulasOfTheSelectedVertex();
    void sideViewMarksClipping();
    void clickSelects();
    void highlightsFollowTheInspection();
    void largeScenes();
    void hundredThousandTriangles();
};

void TestGeometryViews::gramSchmidtStepsByHand() {
    Shown<CameraBasisView> shown(kBasisSize);
    auto& [inspection, view] = shown;
    QCOMPARE(view.objectName(), QStringLiteral("cameraBasisView"));
    inspection.setFrame(render(cameraScene(handCamera())), QImage());
    QCOMPARE(view.step(), 4);
    const QStringList steps = view.stepTexts();
    QCOMPARE(steps.size(), 4);
    QCOMPARE(steps[0], QStringLiteral("1. N := N / |N| = (0, 0, 2) / 2 = (0, 0, 1)"));
    QCOMPARE(steps[1], QStringLiteral("2. V := V − (V·N) N: V·N = 4, (V·N) N = (0, 0, 4), "
                                      "V − (V·N) N = (0, 3, 0)"));
    QCOMPARE(steps[2], QStringLiteral("3. V := V / |V| = (0, 3, 0) / 3 = (0, 1, 0)"));
    QCOMPARE(steps[3], QStringLiteral("4. U := N × V = (0, 0, 1) × (0, 1, 0) = (-1, 0, 0)"));
    QCOMPARE(view.matrixText(), QStringLiteral("-1 0 0 1\n0 1 0 -2\n0 0 1 -3\n0 0 0 1"));
    QCOMPARE(view.residualText(),
             QStringLiteral("U·V = 0, U·N = 0, V·N = 0, |U| − 1 = 0, |V| − 1 = 0, |N| − 1 = 0; "
                            "largest 0; N and V 36.8699 degrees apart (under 1e-06 degrees from "
                            "the line of N, the residuals pass a float's precision)"));
    QCOMPARE(view.conditionRatio(), 0.6);  // |V'| / |V| = 3 / 5
    QVERIFY(!view.illConditioned());
    QCOMPARE(view.statusText(), QString());
    // Vertex 1, (1, 2, 8): P - C = (0, 0, 5), pView = (0, 0, 5).
    QVERIFY2(view.explanationHtml().contains(
                 QStringLiteral("P = (1, 2, 8), P − C = (0, 0, 5), pView = (U·(P − C), V·(P − "
                                "C), N·(P − C)) = (0, 0, 5), in front of the camera")),
             qPrintable(view.explanationHtml()));
    QCOMPARE(view.canvas()->cloudPointCount(), 3);
    lookAt(view, QStringLiteral("camera-basis-hand"));
}

void TestGeometryViews::stepsRevealTheDrawing() {
    Shown<CameraBasisView> shown(kBasisSize);
    auto& [inspection, view] = shown;
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    inspection.setFrame(render(cameraScene(handCamera())), QImage());
    auto* slider = view.findChild<QSlider*>(QStringLiteral("cameraBasisStep"));
    auto* back = view.findChild<QToolButton*>(QStringLiteral("cameraBasisStepBack"));
    auto* forward = view.findChild<QToolButton*>(QStringLiteral("cameraBasisStepForward"));
    QVERIFY(slider && back && forward);
    QVERIFY(!forward->isEnabled());  // at step 4

    const auto drawn = [&] {
        view.canvas()->repaint();
        return view.canvas()->drawnItems();
    };
    view.setStep(0);
    QCOMPARE(slider->value(), 0);
    QVERIFY(view.stepTexts().isEmpty());
    QVERIFY(!back->isEnabled());
    QCOMPARE(drawn(), (QStringList{QStringLiteral("cloud"), QStringLiteral("axes"),
                                   QStringLiteral("N given"), QStringLiteral("V given"),
                                   QStringLiteral("C")}));
    forward->click();
    QCOMPARE(view.step(), 1);
    QCOMPARE(view.stepTexts().size(), 1);
    QVERIFY(drawn().contains(QStringLiteral("N")));
    QVERIFY(!drawn().contains(QStringLiteral("V'")));
    slider->setValue(2);
    QCOMPARE(view.step(), 2);
    QCOMPARE(view.stepTexts().size(), 2);
    QVERIFY(drawn().contains(QStringLiteral("(V.N) N")));
    QVERIFY(drawn().contains(QStringLiteral("V'")));
    QVERIFY(!drawn().contains(QStringLiteral("V")));
    view.setStep(3);
    QVERIFY(drawn().contains(QStringLiteral("V")));
    QVERIFY(!drawn().contains(QStringLiteral("U")));
    QVERIFY(!drawn().contains(QStringLiteral("frustum")));
    view.setStep(4);
    const QStringList all = drawn();
    for (const char* item : {"U", "V", "N", "window", "frustum", "N given", "V given"})
        QVERIFY2(all.contains(QLatin1String(item)), item);
    QVERIFY(!all.contains(QStringLiteral("V'")));  // the intermediate steps are gone
    view.setStep(9);
    QCOMPARE(view.step(), 4);
    // The step chosen stays for the next frame.
    view.setStep(2);
    inspection.setFrame(render(cameraScene(handCamera())), QImage());
    QCOMPARE(view.stepTexts().size(), 2);
}

void TestGeometryViews::orbitCamera() {
    Shown<CameraBasisView> shown(kBasisSize);
    auto& [inspection, view] = shown;
    inspection.setFrame(render(cameraScene(handCamera())), QImage());
    rasterlab::CameraBasisCanvas* canvas = view.canvas();
    const double yaw = canvas->yaw(), pitch = canvas->pitch();
    const QPointF before = canvas->toWidget(rl::dvec3(1.0, 2.0, 8.0));
    QTest::mousePress(canvas, Qt::LeftButton, {}, QPoint(100, 100));
    QTest::mouseMove(canvas, QPoint(150, 120));
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, QPoint(150, 120));
    RL_COMPARE_NEAR(canvas->yaw(), yaw - 0.5, 1e-12);  // 0.01 rad per pixel
    RL_COMPARE_NEAR(canvas->pitch(), pitch + 0.2, 1e-12);
    QVERIFY(canvas->toWidget(rl::dvec3(1.0, 2.0, 8.0)) != before);
    // The centre of the picture stays at the widget's centre, at any angle and zoom.
    canvas->setOrbit(1.0, -0.3, 3.0);
    const QPointF centre = canvas->toWidget(canvas->picture().centre);
    RL_COMPARE_NEAR(centre.x(), canvas->width() / 2.0, 1e-9);
    RL_COMPARE_NEAR(centre.y(), canvas->height() / 2.0, 1e-9);
    canvas->setOrbit(0.0, 5.0, 1.0);
    QCOMPARE(canvas->pitch(), 1.5);  // never over the top
    QTest::mouseDClick(canvas, Qt::LeftButton, {}, QPoint(10, 10));
    QCOMPARE(canvas->yaw(), yaw);
    QCOMPARE(canvas->pitch(), pitch);
    QCOMPARE(canvas->zoom(), 1.0);
}

void TestGeometryViews::labelsKeepToTheirVectors() {
    // The default scene's camera (|N| = 503.3, the trefoil filling the frustum) in the dock's
    // sizes at 1280x720 and 1920x1080, and the canvas's own.
    const auto frame = defaultFrame();
    for (const QSize size : {QSize(262, 172), QSize(300, 320), QSize(520, 420)}) {
        Shown<CameraBasisView> shown(kBasisSize);
        auto& [inspection, view] = shown;
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        inspection.setFrame(frame, QImage());
        rasterlab::CameraBasisCanvas* canvas = view.canvas();
        canvas->resize(size);
        canvas->repaint();
        const auto placed = canvas->placedLabels();
        QStringList texts;
        for (const auto& label : placed) texts << label.text;
        for (const char* text : {"C", "N", "V", "U", "N given, |N| = 503.3", "V given, |V| = 1",
                                 "X", "Y", "Z", "frustum"})
            QVERIFY2(texts.contains(QLatin1String(text)), text);
        for (qsizetype i = 0; i < placed.size(); ++i) {
            const auto& label = placed[i];
            const QString where =
                QStringLiteral("%1 at %2x%3").arg(label.text).arg(size.width()).arg(size.height());
            QVERIFY2(QRectF(canvas->rect()).contains(label.box), qPrintable(where));
            for (qsizetype j = 0; j < i; ++j)
                QVERIFY2(!label.box.intersects(placed[j].box),
                         qPrintable(where + QStringLiteral(" meets ") + placed[j].text));
            // The camera and the basis the step made are labelled first, at their tips.
            const QPointF nearest(
                std::clamp(label.anchor.x(), label.box.left(), label.box.right()),
                std::clamp(label.anchor.y(), label.box.top(), label.box.bottom()));
            const double away =
                std::hypot(nearest.x() - label.anchor.x(), nearest.y() - label.anchor.y());
            if (label.text.size() == 1 && QStringLiteral("CNVU").contains(label.text))
                QVERIFY2(away <= 12.0, qPrintable(where));
        }
    }
}

void TestGeometryViews::nearlyParallelIsIllConditioned() {
    Shown<CameraBasisView> shown(kBasisSize);
    auto& [inspection, view] = shown;
    // V = (0, 1e-4, 1), N = (0, 0, 1): V.N = 1, V' = (0, 1e-4, 0), |V'| / |V| = 1e-4 /
    // sqrt(1 + 1e-8).
    rl::CourseCamera camera = handCamera();
    camera.n = {0.0, 0.0, 1.0};
    camera.v = {0.0, 1e-4, 1.0};
    inspection.setFrame(render(cameraScene(camera)), QImage());
    QVERIFY(view.illConditioned());
    RL_COMPARE_NEAR(view.conditionRatio(), 1e-4 / std::sqrt(1.0 + 1e-8), 1e-18);
    QCOMPARE(view.statusText(),
             QStringLiteral("N and V are nearly parallel: |V − (V·N) N| / |V| = 0.0001, below "
                            "0.001. The basis is ill-conditioned: a tiny change of N or V turns "
                            "U and V a lot. Choose a V further from N."));
    // The numbers are still shown: the basis exists, it is only fragile.
    QCOMPARE(view.stepTexts().size(), 4);
    QCOMPARE(view.stepTexts()[2], QStringLiteral("3. V := V / |V| = (0, 0.0001, 0) / 0.0001 = "
                                                 "(0, 1, 0)"));
    // Just above the threshold: V = (0, 0.01, 1) leaves 0.01 / sqrt(1.0001) = 0.0099995.
    camera.v = {0.0, 0.01, 1.0};
    inspection.setFrame(render(cameraScene(camera)), QImage());
    QVERIFY(!view.illConditioned());
    QCOMPARE(view.statusText(), QString());
}

void TestGeometryViews::rejectedCameraShowsUntilNextFrame() {
    Shown<CameraBasisView> shown(kBasisSize);
    auto& [inspection, view] = shown;
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    inspection.setFrame(render(cameraScene(handCamera())), QImage());
    view.canvas()->repaint();
    QVERIFY(view.canvas()->drawnItems().contains(QStringLiteral("U")));
    // N and V parallel: the stage rejects the camera, and the window passes the error on.
    rl::CourseCamera parallel = handCamera();
    parallel.v = {0.0, 0.0, 5.0};
    parallel.where.v = rl::SourceLocation{"calice2.cfg", 3, 1};
    auto failed = rl::renderFrame(std::make_shared<const rl::Scene>(cameraScene(parallel)));
    QVERIFY(!failed);
    const QString error = QString::fromStdString(failed.error().toString());
    QVERIFY2(error.startsWith(QStringLiteral("calice2.cfg:3:1: V (0, 0, 5) is parallel to N")),
             qPrintable(error));
    view.setError(error);
    QCOMPARE(view.statusText(), QStringLiteral("The camera was rejected: ") + error);
    QVERIFY(view.stepTexts().isEmpty());
    QVERIFY(view.residualText().isEmpty());
    QVERIFY(view.matrixText().isEmpty());
    QCOMPARE(view.canvas()->message(), view.statusText());
    view.canvas()->repaint();
    QVERIFY(view.canvas()->drawnItems().isEmpty());
    // The next frame clears it.
    inspection.setFrame(render(cameraScene(handCamera())), QImage());
    QCOMPARE(view.statusText(), QString());
    QCOMPARE(view.stepTexts().size(), 4);
    QCOMPARE(view.canvas()->message(), QString());
}

void TestGeometryViews::hw2SceneSkipsTheStage() {
    const QString dir = testing::samplesDir();
    if (dir.isEmpty()) QSKIP("the course samples are not here");
    rl::Diagnostics diagnostics;
    auto hw2 = rasterlab::loadCommandFile(dir + QStringLiteral("/hw2/hw2depth.txt"), diagnostics);
    QVERIFY(hw2);
    Shown<CameraBasisView> shown(kBasisSize);
    auto& [inspection, view] = shown;
    inspection.setFrame(render(hw2->images.at(0).scene), QImage());
    QCOMPARE(view.statusText(), QStringLiteral("This stage is skipped: the scene gives its "
                                               "model/view matrices directly."));
    QVERIFY(view.stepTexts().isEmpty());
    QVERIFY(view.matrixText().isEmpty());
    QCOMPARE(view.canvas()->message(), view.statusText());
    // The projection view draws the HW2 scene in its own clip space.
    ProjectionView projection(&inspection);
    projection.resize(kProjectionSize);
    projection.show();
    const rl::Projection& p = *inspection.frame()->projection;
    QCOMPARE(projection.counts().inside, p.inside);
    QCOMPARE(projection.canvas()->triangleCount(ProjectionCanvas::Drawn), p.inside);
    inspection.selectTriangle(0u);
    QVERIFY(projection.explanationHtml().contains(QStringLiteral("pClip = clipFromView · pView")));
    lookAt(view, QStringLiteral("camera-basis-hw2"));
    lookAt(projection, QStringLiteral("projection-hw2"));
}

void TestGeometryViews::fatesCountedByHand() {
    Shown<ProjectionView> shown(kProjectionSize);
    auto& [inspection, view] = shown;
    QCOMPARE(view.objectName(), QStringLiteral("projectionView"));
    const auto frame = clippingFrame();
    inspection.setFrame(frame, QImage());
    const rl::Projection& p = *frame->projection;
    // The stage's own counters, as worked out above.
    QCOMPARE(p.inside, std::size_t(1));
    QCOMPARE(p.culled, std::size_t(1));
    QCOMPARE(p.clipped, std::size_t(1));
    QCOMPARE(p.behind, std::size_t(1));
    QCOMPARE(p.triangles.size(), std::size_t(3));
    // The view shows those counts, and they are the fates of the triangles.
    const rasterlab::FateCounts& c = view.counts();
    QCOMPARE(c.inside, p.inside);
    QCOMPARE(c.culled, p.culled);
    QCOMPARE(c.clipped, p.clipped);
    QCOMPARE(c.behind, p.behind);
    QCOMPARE(c.clippedAway, p.clippedAway);
    QCOMPARE(c.backFaces, p.backFaces);
    compareWithFates(c, p);
    QCOMPARE(c.fanTriangles, std::size_t(2));
    QCOMPARE(view.legendText(),
             QStringLiteral("inside 1, clipped 1 (2 on screen), culled 1, back faces 0; behind 1, "
                            "clipped away 0"));
    // What is drawn in each colour: T0 (3 edges); the fan, 5 edges (one shared); T1 grey.
    ProjectionCanvas* canvas = view.canvas();
    QCOMPARE(canvas->triangleCount(ProjectionCanvas::Drawn), std::size_t(1));
    QCOMPARE(canvas->triangleCount(ProjectionCanvas::Clipped), std::size_t(2));
    QCOMPARE(canvas->triangleCount(ProjectionCanvas::Hidden), std::size_t(1));
    QCOMPARE(canvas->lineCount(ProjectionCanvas::Drawn), std::size_t(3));
    QCOMPARE(canvas->lineCount(ProjectionCanvas::Clipped), std::size_t(5));
    QCOMPARE(canvas->lineCount(ProjectionCanvas::Hidden), std::size_t(3));
    // The vertices in each space: T0's first vertex is NDC (0.25, 0.25), pixels (62, 37).
    QCOMPARE(canvas->spacePoint(0, 0), QPointF(0.25, 0.25));
    view.setSpace(ProjectionSpace::Pixels);
    QCOMPARE(canvas->spacePoint(0, 0), QPointF(62, 37));
    QCOMPARE(canvas->spacePoint(0, 12), QPointF(0, 37));  // made by clipping
    QCOMPARE(canvas->spacePoint(0, 13), QPointF(37, 37));
    lookAt(view, QStringLiteral("projection-hand"));
}

void TestGeometryViews::formulasOfTheSelectedVertex() {
    Shown<ProjectionView> shown(kProjectionSize);
    auto& [inspection, view] = shown;
    inspection.setFrame(clippingFrame(), QImage());
    QVERIFY(view.explanationHtml().contains(QStringLiteral("Click a triangle")));
    inspection.selectTriangle(0u);
    const QString html = view.explanationHtml();
    // Vertex 1, world (-0.5, 0.5, 2), view (0.5, 0.5, 2).
    for (const QString& line :
         {QStringLiteral("<b>Triangle 1</b> (mesh triangle 1), its first vertex, vertex 1:"),
          QStringLiteral("pView = (x, y, z) = (0.5, 0.5, 2)"),
          QStringLiteral("x_ndc = (d/hx) x/z = (1/1) · 0.5 / 2 = 0.25"),
          QStringLiteral("y_ndc = (d/hy) y/z = (1/1) · 0.5 / 2 = 0.25"),
          QStringLiteral("x = (x_ndc + 1) W/2 = (0.25 + 1) · 100/2 = 62.5 → 62 (truncated)"),
          QStringLiteral("y = (1 − y_ndc) H/2 = (1 − 0.25) · 100/2 = 37.5 → 37 (truncated)")})
        QVERIFY2(html.contains(line), qPrintable(line + QStringLiteral("\n in \n") + html));
    // The first fan triangle starts at vertex 13 (index 12), made on the edge from H
    // (vertex 8) toward G (vertex 7) at t = 0.625: view (-0.5, 0.125, 0.5), NDC (-1, 0.25).
    inspection.selectTriangle(1u);
    const QString made = view.explanationHtml();
    for (const QString& line :
         {QStringLiteral("<b>Triangle 2</b> (mesh triangle 3, clipped), its first vertex, "
                         "vertex 13:"),
          QStringLiteral("made by clipping, on the edge from vertex 8 to vertex 7 at t = 0.625"),
          QStringLiteral("x_ndc = (d/hx) x/z = (1/1) · (-0.5) / 0.5 = -1"),
          QStringLiteral("x = (x_ndc + 1) W/2 = ((-1) + 1) · 100/2 = 0 → 0 (truncated)")})
        QVERIFY2(made.contains(line), qPrintable(line + QStringLiteral("\n in \n") + made));
}

void TestGeometryViews::sideViewMarksClipping() {
    Shown<ProjectionView> shown(kProjectionSize);
    auto& [inspection, view] = shown;
    inspection.setFrame(clippingFrame(), QImage());
    // The two vertices the near plane made; T0's and T1's edges plain; T2 and T3 apart.
    QCOMPARE(view.sideView()->madeVertexCount(), std::size_t(2));
    QCOMPARE(view.sideView()->lineCount(), std::size_t(6));
}

void TestGeometryViews::clickSelects() {
    Shown<ProjectionView> shown(kProjectionSize);
    auto& [inspection, view] = shown;
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    inspection.setFrame(clippingFrame(), QImage());
    ProjectionCanvas* canvas = view.canvas();
    for (ProjectionSpace space : {ProjectionSpace::Ndc, ProjectionSpace::Pixels}) {
        view.setSpace(space);
        for (std::uint32_t t : {0u, 1u, 2u}) {
            const QPoint at = canvas->widgetCentroid(t).toPoint();
            QCOMPARE(canvas->triangleAt(at), std::optional<std::uint32_t>(t));
            QTest::mouseClick(canvas, Qt::LeftButton, {}, at);
            QCOMPARE(inspection.selectedTriangle(), std::optional<std::uint32_t>(t));
            QCOMPARE(canvas->selectedTriangle(), std::optional<std::uint32_t>(t));
        }
        // The culled triangle was never sent on: clicking it selects nothing.
        const QPointF culled = (canvas->toWidget(canvas->spacePoint(0, 3)) +
                                canvas->toWidget(canvas->spacePoint(0, 4)) +
                                canvas->toWidget(canvas->spacePoint(0, 5))) /
                               3.0;
        QTest::mouseClick(canvas, Qt::LeftButton, {}, culled.toPoint());
        QCOMPARE(inspection.selectedTriangle(), std::nullopt);
    }
    // Presenting: thicker lines and larger text, the selection still drawn.
    inspection.selectTriangle(1u);
    inspection.setPresentation(true);
    QVERIFY(view.font().pointSizeF() > QFont().pointSizeF());
    lookAt(view, QStringLiteral("projection-hand-presenting"));
    inspection.setPresentation(false);
    QCOMPARE(view.font().pointSizeF(), QFont().pointSizeF());
    // A drag pans instead of selecting.
    inspection.selectTriangle(0u);
    const QPointF before = canvas->toWidget(QPointF(0.0, 0.0));
    QTest::mousePress(canvas, Qt::LeftButton, {}, QPoint(20, 20));
    QTest::mouseMove(canvas, QPoint(60, 50));
    QTest::mouseRelease(canvas, Qt::LeftButton, {}, QPoint(60, 50));
    QCOMPARE(canvas->toWidget(QPointF(0.0, 0.0)), before + QPointF(40, 30));
    QCOMPARE(inspection.selectedTriangle(), std::optional<std::uint32_t>(0u));
}

void TestGeometryViews::highlightsFollowTheInspection() {
    Shown<ProjectionView> shown(kProjectionSize);
    auto& [inspection, view] = shown;
    const auto frame = clippingFrame();
    inspection.setFrame(frame, QImage());
    auto replay = rl::FrameReplay::build(frame);
    QVERIFY(replay);
    inspection.setReplay(replay.value());
    inspection.setGranularity(rl::StepGranularity::Triangle);
    inspection.toStart();
    QCOMPARE(view.canvas()->currentTriangle(), std::nullopt);
    QVERIFY(inspection.stepForward());
    QCOMPARE(view.canvas()->currentTriangle(), inspection.currentTriangle());
    QCOMPARE(view.canvas()->currentTriangle(), std::optional<std::uint32_t>(0u));
    QVERIFY(inspection.stepForward());
    QCOMPARE(view.canvas()->currentTriangle(), std::optional<std::uint32_t>(1u));
    // A hidden view does no work, and catches up when shown.
    view.hide();
    inspection.setFrame(render(cameraScene(handCamera())), QImage());
    QCOMPARE(view.counts().inside, std::size_t(1));
    QCOMPARE(view.counts().culled, std::size_t(1));  // still the previous frame's
    view.show();
    QCOMPARE(view.counts().culled, std::size_t(0));
    QCOMPARE(view.counts().inside, std::size_t(1));
    // The selection and the cursor moved while hidden, on the same frame: shown as they are
    // now, not as they were when it was hidden.
    inspection.setFrame(frame, QImage());
    inspection.setReplay(rl::FrameReplay::build(frame).value());
    inspection.toStart();
    QVERIFY(inspection.stepForward());
    inspection.selectTriangle(0u);
    QCOMPARE(view.canvas()->selectedTriangle(), std::optional<std::uint32_t>(0u));
    QCOMPARE(view.canvas()->currentTriangle(), std::optional<std::uint32_t>(0u));
    view.hide();
    inspection.selectTriangle(1u);
    QVERIFY(inspection.stepForward());
    view.show();
    QCOMPARE(view.canvas()->selectedTriangle(), std::optional<std::uint32_t>(1u));
    QCOMPARE(view.canvas()->currentTriangle(), std::optional<std::uint32_t>(1u));
    QVERIFY2(view.explanationHtml().contains(QStringLiteral("<b>Triangle 2</b>")),
             qPrintable(view.explanationHtml()));
}

void TestGeometryViews::largeScenes() {
    std::vector<std::pair<QString, std::shared_ptr<const rl::FrameTrace>>> frames{
        {QStringLiteral("trefoil"), defaultFrame()},
        {QStringLiteral("trefoil-backfaces"), defaultFrame(Trefoil::BackFaces)},
        {QStringLiteral("trefoil-close"), defaultFrame(Trefoil::Close)}};
    // The variants exercise the other groups of the wireframe.
    QVERIFY(frames[1].second->projection->backFaces > 0);
    QVERIFY(frames[2].second->projection->clipped > 0);
    QVERIFY(frames[2].second->projection->behind > 0);
    if (auto calice = caliceFrame()) frames.emplace_back(QStringLiteral("calice2"), calice);
    for (const auto& [name, frame] : frames) {
        Inspection inspection;
        CameraBasisView basis(&inspection);
        ProjectionView projection(&inspection);
        basis.resize(1000, 620);
        projection.resize(1100, 720);
        basis.show();
        projection.show();
        inspection.setFrame(frame, QImage());
        const rl::Projection& p = *frame->projection;
        const rasterlab::FateCounts& c = projection.counts();
        QCOMPARE(c.inside, p.inside);
        QCOMPARE(c.clipped, p.clipped);
        QCOMPARE(c.culled, p.culled);
        QCOMPARE(c.behind, p.behind);
        QCOMPARE(c.backFaces, p.backFaces);
        compareWithFates(c, p);
        QCOMPARE(projection.canvas()->triangleCount(ProjectionCanvas::Drawn), p.inside);
        QCOMPARE(projection.canvas()->triangleCount(ProjectionCanvas::Clipped),
                 p.triangles.size() - p.inside);
        QCOMPARE(projection.canvas()->triangleCount(ProjectionCanvas::Hidden),
                 p.backFaces + p.culled);
        QCOMPARE(c.inside + c.clipped + c.culled + c.behind + c.backFaces + c.clippedAway,
                 frame->scene->triangleCount());
        QVERIFY(basis.canvas()->cloudPointCount() > 0);
        QVERIFY(basis.canvas()->cloudPointCount() <= 3000);
        QCOMPARE(basis.stepTexts().size(), 4);
        QVERIFY(frame->cameraBasis->maxResidual() < 1e-12);
        lookAt(basis, QStringLiteral("camera-basis-") + name);
        basis.setStep(2);
        lookAt(basis, QStringLiteral("camera-basis-step2-") + name);
        basis.resize(480, 800);
        lookAt(basis, QStringLiteral("camera-basis-narrow-") + name);
        // A click on a triangle's centroid selects the nearest triangle there.
        const auto middle = static_cast<std::uint32_t>(p.triangles.size() / 2);
        const QPoint at = projection.canvas()->widgetCentroid(middle).toPoint();
        QTest::mouseClick(projection.canvas(), Qt::LeftButton, {}, at);
        QVERIFY(inspection.selectedTriangle().has_value());
        QCOMPARE(inspection.selectedTriangle(), projection.canvas()->triangleAt(at));
        lookAt(projection, QStringLiteral("projection-") + name);
        projection.setSpace(ProjectionSpace::Pixels);
        projection.resize(500, 900);
        lookAt(projection, QStringLiteral("projection-narrow-pixels-") + name);
    }
}

void TestGeometryViews::hundredThousandTriangles() {
    auto sphere = rl::makeBenchmarkScene("sphere-100k", 800, 600, rl::ShadingModel::Flat);
    QVERIFY(sphere);
    const auto frame = render(std::move(*sphere));
    Inspection inspection;
    ProjectionView view(&inspection);
    view.resize(1100, 720);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QElapsedTimer timer;
    timer.start();
    inspection.setFrame(frame, QImage());
    view.canvas()->repaint();
    view.sideView()->repaint();
    const qint64 whole = timer.elapsed();
    const rl::Projection& p = *frame->projection;
    QCOMPARE(view.counts().inside, p.inside);
    QCOMPARE(view.canvas()->triangleCount(ProjectionCanvas::Drawn), p.inside);
    // A new selection only draws the highlight over the cached wireframe.
    timer.restart();
    for (std::uint32_t t = 0; t < 20; ++t) {
        inspection.selectTriangle(t);
        view.canvas()->repaint();
    }
    const qint64 selections = timer.elapsed();
    qInfo("%zu triangles: frame shown in %lld ms, 20 selections in %lld ms", p.triangles.size(),
          whole, selections);
    // Drawing the whole wireframe 20 times would take about 20 times as long as showing it.
    QVERIFY2(selections < 5 * std::max<qint64>(whole, 10), "selecting redraws the wireframe");
    lookAt(view, QStringLiteral("projection-sphere-100k"));
}

QTEST_MAIN(TestGeometryViews)
#include "tst_geometry_views.moc"
