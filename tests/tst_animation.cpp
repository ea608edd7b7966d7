// Seed 002's per-object animation matrix M (pipeline/animation.h): M(t) and the inverse-transpose
// normal worked out by hand, frames that render exactly as the scene without animation (t = 0)
// or with M(t) baked into worldFromModel, the CLI's --time and --animate, the normals view's
// right and wrong normals, and the window's animation panel: play, pause, the frame slider, the
// stage views following, and the frames exported.
#include <QtTest>

#include <QCheckBox>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QSettings>
#include <QSlider>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTextBrowser>

#include <cmath>
#include <numbers>

#include "app/image_io.h"
#include "app/window/animation_panel.h"
#include "app/window/main_window.h"
#include "app/window/replay_builder.h"
#include "pipeline/render/animation.h"
#include "pipeline/render/output_image.h"
#include "tests/course_scenes.h"
#include "tests/test_support.h"
#include "views/inspection.h"
#include "views/normals_view.h"
#include "views/vertex_table.h"

using namespace rl;
using rasterlab::AnimationPanel;
using rasterlab::MainWindow;

namespace {

constexpr int kTimeoutMs = 20000;

// The default course scene at 240x180 with the default settings (Phong, the course's rules).
std::shared_ptr<const Scene> trefoil() {
    return testing::defaultCourseScene(ShadingModel::Phong, RuleSet::Course, 240, 180);
}

std::shared_ptr<const Scene> withAnimation(const Scene& scene, const Animation& animation,
                                           double t) {
    auto copy = std::make_shared<Scene>(scene);
    animateEveryDraw(*copy, animation, t);
    return copy;
}

// Whether two frames wrote the same bytes and the same depth buffer, bit for bit.
bool sameFrame(const FrameTrace& a, const FrameTrace& b) {
    const Rgba8Image x = colourImage(*a.shading, *a.depth, a.scene->conventions);
    const Rgba8Image y = colourImage(*b.shading, *b.depth, b.scene->conventions);
    if (x.rgba != y.rgba) return false;
    const auto& da = a.depth->depth;
    const auto& db = b.depth->depth;
    if (da.width() != db.width() || da.height() != db.height()) return false;
    for (int j = 0; j < da.height(); ++j)
        if (std::memcmp(da.row(j), db.row(j), sizeof(float) * std::size_t(da.width())) != 0)
            return false;
    return true;
}

int differingPixels(const QImage& a, const QImage& b) {
    const QImage x = a.convertToFormat(QImage::Format_RGBA8888);
    const QImage y = b.convertToFormat(QImage::Format_RGBA8888);
    if (x.size() != y.size()) return -1;
    int n = 0;
    for (int j = 0; j < x.height(); ++j)
        for (int i = 0; i < x.width(); ++i) n += x.pixel(i, j) != y.pixel(i, j) ? 1 : 0;
    return n;
}

QImage qimage(const FrameTrace& frame) {
    return rasterlab::toQImage(colourImage(*frame.shading, *frame.depth, frame.scene->conventions));
}

// The triangle of the normals case: in the plane x + y = 2, its normal
// (P2 - P1) x (P3 - P1) = (0, 0, 1) x (1, -1, 0) = (0*0 - 1*(-1), 1*1 - 0*0, 0) = (1, 1, 0).
std::shared_ptr<const Mesh> slantedTriangle() {
    return testing::makeMesh({{1, 1, 5}, {1, 1, 6}, {2, 0, 5}}, {{0, 1, 2}});
}

// The window's stage views show a frame at time t, ready to step.
bool waitForTime(MainWindow& window, double t) {
    return QTest::qWaitFor(
        [&] {
            const auto frame = window.currentFrame();
            return window.isReadyToStep() && frame && frame->scene->time == t;
        },
        kTimeoutMs);
}

}  // namespace

class TestAnimation : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("RasterLabTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_animation"));
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settings.path());
    }

    void matrixByHand() {
        // 90 degrees a second about y through c = (1, 0, 0), moving (0, 0.5, 0) a second.
        Animation a;
        a.degreesPerSecond = 90.0;
        a.velocity = dvec3(0.0, 0.5, 0.0);
        const dvec3 c(1.0, 0.0, 0.0), y(0.0, 1.0, 0.0);
        // t = 1: P = (2, 0, 0); P - c = (1, 0, 0); R_y(90°) (x, y, z) = (z, y, -x) gives
        // (0, 0, -1); + c = (1, 0, -1); + v t = (0, 0.5, 0): (1, 0.5, -1).
        RL_COMPARE_VEC(dvec3(animationMatrix(a, c, y, 1.0) * dvec4(2, 0, 0, 1)),
                       dvec3(1.0, 0.5, -1.0), 1e-12);
        // t = 0.5: 45°, (cos 45°, 0, -sin 45°) + c + (0, 0.25, 0) = (1.70711, 0.25, -0.70711).
        const double h = std::sqrt(0.5);
        RL_COMPARE_VEC(dvec3(animationMatrix(a, c, y, 0.5) * dvec4(2, 0, 0, 1)),
                       dvec3(1.0 + h, 0.25, -h), 1e-12);
        // The centre only moves by v t; the axis' length does not matter.
        RL_COMPARE_VEC(dvec3(animationMatrix(a, c, 5.0 * y, 1.0) * dvec4(c, 1.0)),
                       dvec3(1.0, 0.5, 0.0), 1e-12);
        // At t = 0 without a scale, M is exactly the identity.
        QCOMPARE(animationMatrix(a, c, y, 0.0), dmat4(1.0));
        // Scale (2, 1, 1) about c: (2, 0, 0) -> c + 2 (1, 0, 0) = (3, 0, 0) at t = 0.
        a.scale = dvec3(2.0, 1.0, 1.0);
        RL_COMPARE_VEC(dvec3(animationMatrix(a, c, y, 0.0) * dvec4(2, 0, 0, 1)),
                       dvec3(3.0, 0.0, 0.0), 1e-12);
    }

    void turntableDefaults() {
        // Camera up: V - (V.N / N.N) N = (0, 3, 1) - (2 / 4) (0, 0, 2) = (0, 3, 0) -> (0, 1, 0).
        Scene scene = testing::makeScene(testing::axisCamera(), slantedTriangle(), 8, 8);
        scene.camera->n = dvec3(0, 0, 2);
        scene.camera->v = dvec3(0, 3, 1);
        RL_COMPARE_VEC(turntableAxis(scene), dvec3(0, 1, 0), 1e-15);
        // (1, 1, 0) - (1 / 1) (0, 1, 0) = (1, 0, 0).
        scene.camera->n = dvec3(0, 1, 0);
        scene.camera->v = dvec3(1, 1, 0);
        RL_COMPARE_VEC(turntableAxis(scene), dvec3(1, 0, 0), 1e-15);
        scene.camera.reset();
        RL_COMPARE_VEC(turntableAxis(scene), dvec3(0, 1, 0), 0.0);
        // Bounding box of (0,0,0) (2,4,0) (1,1,6) moved by (10, 0, 0): x 10..12, y 0..4,
        // z 0..6, centre (11, 2, 3).
        Draw draw;
        draw.mesh = testing::makeMesh({{0, 0, 0}, {2, 4, 0}, {1, 1, 6}}, {{0, 1, 2}});
        draw.worldFromModel[3] = dvec4(10, 0, 0, 1);
        RL_COMPARE_VEC(worldBoundingBoxCentre(draw), dvec3(11, 2, 3), 0.0);
        // The scene's M uses them: a point at the centre stays there at any t.
        draw.animation = Animation{};
        scene.draws = {draw};
        RL_COMPARE_VEC(dvec3(animationMatrix(scene, draw, 3.7) * dvec4(11, 2, 3, 1)),
                       dvec3(11, 2, 3), 1e-12);
        // No animation: the identity, and worldFromModel as it is.
        draw.animation.reset();
        QCOMPARE(animationMatrix(scene, draw, 3.7), dmat4(1.0));
        QCOMPARE(animatedWorldFromModel(scene, draw), draw.worldFromModel);
    }

    void inverseTransposeNormalByHand() {
        // M = scale (2, 1, 1); n = (1, 1, 0)/sqrt 2 on the plane x + y = 0 (tangent (1, -1, 0)).
        Animation a;
        a.scale = dvec3(2.0, 1.0, 1.0);
        const dmat4 m = animationMatrix(a, dvec3(0.0), dvec3(0, 1, 0), 0.0);
        const dvec3 n = dvec3(1, 1, 0) / std::sqrt(2.0);
        // M^-T = diag(1/2, 1, 1): (0.5, 1, 0)/sqrt 2, normalised (1, 2, 0)/sqrt 5.
        const dvec3 right = glm::normalize(normalMatrix(m) * n);
        RL_COMPARE_VEC(right, dvec3(1, 2, 0) / std::sqrt(5.0), 1e-15);
        // M n = (2, 1, 0)/sqrt 2, normalised (2, 1, 0)/sqrt 5.
        const dvec3 wrong = glm::normalize(dmat3(m) * n);
        RL_COMPARE_VEC(wrong, dvec3(2, 1, 0) / std::sqrt(5.0), 1e-15);
        // The tangent becomes M (1, -1, 0) = (2, -1, 0): (1, 2, 0).(2, -1, 0) = 0, while
        // (2, 1, 0).(2, -1, 0) / (sqrt 5 sqrt 5) = 3/5.
        const dvec3 tangent = glm::normalize(dmat3(m) * dvec3(1, -1, 0));
        RL_COMPARE_NEAR(glm::dot(right, tangent), 0.0, 1e-15);
        RL_COMPARE_NEAR(glm::dot(wrong, tangent), 0.6, 1e-15);
        // The two are acos(4/5) = 36.87 degrees apart.
        RL_COMPARE_NEAR(std::acos(glm::dot(right, wrong)) * 180.0 / std::numbers::pi,
                        36.869897645844, 1e-9);
        // Turned 90 degrees about y as well (t = 1 at 90°/s): M^-T = R S^-1, and R_y(90°)
        // takes (1, 2, 0)/sqrt 5 to (0, 2, -1)/sqrt 5.
        a.degreesPerSecond = 90.0;
        const dmat4 turned = animationMatrix(a, dvec3(0.0), dvec3(0, 1, 0), 1.0);
        RL_COMPARE_VEC(glm::normalize(normalMatrix(turned) * n), dvec3(0, 2, -1) / std::sqrt(5.0),
                       1e-15);
    }

    void carriedTriangleNormalByHand() {
        // The axis camera's view is (-x, y, z): viewFromWorld = diag(-1, 1, 1), det -1. With
        // scale (2, 1, 1), A = diag(-2, 1, 1) (the translations do not touch normals), det -2.
        // n = (1, 1, 0)/sqrt 2. Right: A^-T n = (-0.5, 1, 0)/sqrt 2 -> (-1, 2, 0)/sqrt 5, times
        // sign(det A) = -1: (1, -2, 0)/sqrt 5. Wrong: A n = (-2, 1, 0) -> times -1:
        // (2, -1, 0)/sqrt 5. Edges: A (0, 0, 1) = (0, 0, 1), A (1, -1, 0) = (-2, -1, 0).
        Scene scene = testing::makeScene(testing::axisCamera(), slantedTriangle(), 8, 8);
        Animation a;
        a.scale = dvec3(2.0, 1.0, 1.0);
        scene.draws[0].animation = a;
        const auto frame = testing::renderTrace(std::make_shared<const Scene>(scene));
        const dmat4& viewFromModel = frame->view->viewFromModel[0];
        const CarriedNormal n = carriedTriangleNormal(viewFromModel, *scene.draws[0].mesh, 0);
        RL_COMPARE_VEC(n.nModel, dvec3(1, 1, 0) / std::sqrt(2.0), 1e-15);
        RL_COMPARE_VEC(n.right, dvec3(1, -2, 0) / std::sqrt(5.0), 1e-15);
        RL_COMPARE_VEC(n.wrong, dvec3(2, -1, 0) / std::sqrt(5.0), 1e-15);
        RL_COMPARE_VEC(n.edges[0], dvec3(0, 0, 1), 1e-15);
        RL_COMPARE_VEC(n.edges[1], dvec3(-2, -1, 0), 1e-15);
        // The right one is the pipeline's own: the moved view vertices P1 = (-0.5, 1, 5),
        // P2 = (-0.5, 1, 6), P3 = (-2.5, 0, 5) (x: 1.5 + 2 (x - 1.5), then -x) give
        // (0, 0, 1) x (-2, -1, 0) = (1, -2, 0).
        RL_COMPARE_VEC(dvec3(cartesian(frame->view->pView[0][0])), dvec3(-0.5, 1, 5), 1e-12);
        RL_COMPARE_VEC(dvec3(cartesian(frame->view->pView[0][2])), dvec3(-2.5, 0, 5), 1e-12);
        RL_COMPARE_VEC(dvec3(frame->normals->draws[0].triangle[0]),
                       dvec3(1, -2, 0) / std::sqrt(5.0), 1e-7);
        // The wrong one leaves the surface: (2, -1, 0).(-2, -1, 0) / 5 = -3/5.
        RL_COMPARE_NEAR(glm::dot(n.right, glm::normalize(n.edges[1])), 0.0, 1e-15);
        RL_COMPARE_NEAR(glm::dot(n.wrong, glm::normalize(n.edges[1])), -0.6, 1e-15);
    }

    void fileNormalsTakeTheInverseTranspose() {
        // A vertex normal given by the file, (1, 1, 0)/sqrt 2 in model space, under scale
        // (2, 1, 1): A^-T n = diag(-1/2, 1, 1) n -> (-1, 2, 0)/sqrt 5 in view space (no turn
        // by det here: the pipeline carries given normals by A^-T as they are).
        auto mesh = std::make_shared<Mesh>(*slantedTriangle());
        mesh->normals.assign(3, vec3(1, 1, 0) / std::sqrt(2.0f));
        Scene scene = testing::makeScene(testing::axisCamera(), mesh, 8, 8);
        Animation a;
        a.scale = dvec3(2.0, 1.0, 1.0);
        scene.draws[0].animation = a;
        const auto frame = testing::renderTrace(std::make_shared<const Scene>(scene));
        RL_COMPARE_VEC(dvec3(frame->normals->draws[0].vertex[1]), dvec3(-1, 2, 0) / std::sqrt(5.0),
                       1e-7);
    }

    void turntableAtZeroRendersAsWithout() {
        const auto still = trefoil();
        const auto atZero = withAnimation(*still, Animation{}, 0.0);
        const auto a = testing::renderTrace(still);
        const auto b = testing::renderTrace(atZero);
        QVERIFY(sameFrame(*a, *b));
        QVERIFY(a->depth->coveredPixels() > 5000);  // the trefoil is there (240x180)
    }

    void frameAtTimeIsMBakedIn() {
        const auto still = trefoil();
        Animation a;
        a.degreesPerSecond = 50.0;
        a.velocity = dvec3(3.0, -2.0, 1.0);
        a.scale = dvec3(1.5, 1.0, 0.75);
        const double t = 0.7;
        const auto moving = withAnimation(*still, a, t);
        auto baked = std::make_shared<Scene>(*still);
        for (Draw& draw : baked->draws)
            draw.worldFromModel =
                animationMatrix(*moving, moving->draws[0], t) * draw.worldFromModel;
        const auto x = testing::renderTrace(moving);
        const auto y = testing::renderTrace(baked);
        QVERIFY(sameFrame(*x, *y));
        // And it moved: many pixels differ from the still frame.
        const auto z = testing::renderTrace(still);
        QVERIFY2(differingPixels(qimage(*x), qimage(*z)) > 2000,
                 qPrintable(QString::number(differingPixels(qimage(*x), qimage(*z)))));
    }

    void frameLoopRendersEachTime() {
        // renderAnimationFrames: frame k is the scene at t = k / fps, as rendered on its own;
        // `use` returning false stops it.
        const auto still = trefoil();
        Animation a;
        a.degreesPerSecond = 90.0;
        auto moving = std::make_shared<Scene>(*still);
        animateEveryDraw(*moving, a, 5.0);  // the scene's own time is not used
        QCOMPARE(moving->time, 5.0);
        QVERIFY(moving->draws[0].animation == a);
        std::vector<int> frames;
        std::vector<double> times;
        int same = 0;
        const auto use = [&](int k, double t, const FrameTrace& f) {
            frames.push_back(k);
            times.push_back(t);
            same += sameFrame(f, *testing::renderTrace(withAnimation(*still, a, k / 8.0))) ? 1 : 0;
            return true;
        };
        QVERIFY(renderAnimationFrames(*moving, 3, 8.0, use).ok());
        QCOMPARE(frames, (std::vector<int>{0, 1, 2}));
        QCOMPARE(same, 3);
        QCOMPARE(times, (std::vector<double>{0.0, 0.125, 0.25}));
        int calls = 0;
        QVERIFY(renderAnimationFrames(*moving, 5, 8.0, [&](int, double, const FrameTrace&) {
                    return ++calls < 2;
                }).ok());
        QCOMPARE(calls, 2);
        QCOMPARE(animationFrameFileName(7), std::string("frame_0007.png"));
        QCOMPARE(animationFrameFileName(12345), std::string("frame_12345.png"));
    }

    void cliWritesNumberedFrames() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        testing::CliRun run;
        testing::runCli(
            {QStringLiteral("render"), QStringLiteral("--size"), QStringLiteral("160x120"),
             QStringLiteral("--animate"), QStringLiteral("3"), QStringLiteral("--fps"),
             QStringLiteral("2"), QStringLiteral("--output"), QStringLiteral("frames")},
            dir.path(), run);
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains(QStringLiteral("frame 2, t = 1.000 s")), qPrintable(run.out));
        const QDir frames(dir.filePath(QStringLiteral("frames")));
        QCOMPARE(frames.entryList({QStringLiteral("*.png")}, QDir::Files, QDir::Name),
                 (QStringList{QStringLiteral("frame_0000.png"), QStringLiteral("frame_0001.png"),
                              QStringLiteral("frame_0002.png")}));
        const QImage f0(frames.filePath(QStringLiteral("frame_0000.png")));
        const QImage f1(frames.filePath(QStringLiteral("frame_0001.png")));
        const QImage f2(frames.filePath(QStringLiteral("frame_0002.png")));
        QCOMPARE(f0.size(), QSize(160, 120));
        QVERIFY(differingPixels(f0, f1) > 100);
        QVERIFY(differingPixels(f1, f2) > 100);
        // Frame 0 is the still scene, and --time 0.5 is frame 1 (t = 1 / 2).
        testing::runCli(
            {QStringLiteral("render"), QStringLiteral("--size"), QStringLiteral("160x120"),
             QStringLiteral("--output"), QStringLiteral("still.png")},
            dir.path(), run);
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(differingPixels(QImage(dir.filePath(QStringLiteral("still.png"))), f0), 0);
        testing::runCli({QStringLiteral("render"), QStringLiteral("--size"),
                         QStringLiteral("160x120"), QStringLiteral("--time"), QStringLiteral("0.5"),
                         QStringLiteral("--output"), QStringLiteral("half.png")},
                        dir.path(), run);
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(differingPixels(QImage(dir.filePath(QStringLiteral("half.png"))), f1), 0);
    }

    void cliRejectsBadAnimationOptions() {
        QTemporaryDir dir;
        testing::CliRun run;
        testing::runCli(
            {QStringLiteral("render"), QStringLiteral("--scale"), QStringLiteral("0,1,1"),
             QStringLiteral("--output"), QStringLiteral("x.png")},
            dir.path(), run);
        QCOMPARE(run.exitCode, 2);
        QCOMPARE(run.err.split(QLatin1Char('\n')).first(),
                 QStringLiteral("rasterlab-cli: --scale expects X,Y,Z, none zero, such as 2,1,1, "
                                "found '0,1,1'"));
        testing::runCli({QStringLiteral("render"), QStringLiteral("--animate"), QStringLiteral("2"),
                         QStringLiteral("--time"), QStringLiteral("1"), QStringLiteral("--output"),
                         QStringLiteral("d")},
                        dir.path(), run);
        QCOMPARE(run.exitCode, 2);
        QCOMPARE(run.err.split(QLatin1Char('\n')).first(),
                 QStringLiteral("rasterlab-cli: --time and --animate exclude each other"));
        QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("d"))));
    }

    void normalsViewShowsRightAndWrong() {
        // The slanted triangle scaled by (2, 1, 1), its normals worked out in the view.
        Scene scene = testing::makeScene(testing::axisCamera(), slantedTriangle(), 64, 64);
        scene.camera->d = 4.0;
        Animation a;
        a.scale = dvec3(2.0, 1.0, 1.0);
        scene.draws[0].animation = a;
        const auto frame = testing::renderTrace(std::make_shared<const Scene>(scene));
        rasterlab::Inspection inspection;
        rasterlab::NormalsView view(&inspection);
        view.resize(900, 700);
        view.show();
        inspection.setFrame(frame, qimage(*frame));
        inspection.selectTriangle(0u);
        QVERIFY(view.picture().wrongHairs.empty());
        QVERIFY(!view.explanationText().contains(QStringLiteral("Normals by M")));
        view.setWrongNormals(true);
        QCOMPARE(view.picture().wrongHairs.size(), view.picture().triangleHairs.size());
        QCOMPARE(view.picture().selectedWrongHairs.size(), std::size_t(1));
        QVERIFY(view.picture().wrongHairs[0] != view.picture().triangleHairs[0]);
        const QString text = view.explanationText();
        QVERIFY2(text.contains(QStringLiteral("A−T n, normalised = (0.4472, -0.8944, 0.0000); "
                                              "its dots with e1 and e2 are 0.000 and 0.000")),
                 qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("A n, normalised = (0.8944, -0.4472, 0.0000); its "
                                              "dots with e1 and e2 are 0.000 and -0.600: 36.87° "
                                              "off")),
                 qPrintable(text));
        QVERIFY(text.contains(QStringLiteral("det A = -2")));
    }

    void panelMovesTimeAndStagesFollow() {
        MainWindow window;
        window.resize(1400, 900);
        window.show();
        QVERIFY(waitForTime(window, 0.0));
        AnimationPanel* panel = window.animationPanel();
        QVERIFY(panel);
        QVERIFY(!window.document().animation().enabled);
        const QImage still = window.currentImage();
        auto* slider = panel->findChild<QSlider*>(QStringLiteral("animationFrameSlider"));
        auto* enabled = panel->findChild<QCheckBox*>(QStringLiteral("animationEnabled"));
        QVERIFY(slider && enabled);

        // Frame 12 at 24 frames a second: t = 0.5 s, the trefoil turned 18 degrees.
        enabled->setChecked(true);
        slider->setValue(12);
        QVERIFY(waitForTime(window, 0.5));
        QCOMPARE(window.document().animation().time, 0.5);
        auto* label = panel->findChild<QLabel*>(QStringLiteral("animationFrameLabel"));
        QCOMPARE(label->text(), QStringLiteral("Frame 12 of 48, t = 12 / 24 = 0.5 s"));
        QVERIFY(differingPixels(window.currentImage(), still) > 1000);
        // The stage views inspect that frame: the vertex table's world position is M(t) P.
        const auto frame = window.currentFrame();
        const Scene& scene = *frame->scene;
        const dmat4 m = animationMatrix(scene, scene.draws[0], 0.5);
        auto* table = window.vertexTableView();
        const dvec3 expected =
            cartesian(m * scene.draws[0].worldFromModel * scene.draws[0].mesh->positions[0]);
        RL_COMPARE_VEC(table->model()->worldOf({0, 0}), expected, 1e-9);
        QVERIFY(glm::length(expected - cartesian(scene.draws[0].mesh->positions[0])) > 1.0);
        // Its explanation names M(t) and the time.
        window.findChild<QDockWidget*>(QStringLiteral("vertexTableDock"))->raise();
        window.inspection()->selectVertices({{0, 0}});
        QTRY_VERIFY_WITH_TIMEOUT(table->explanationText().contains(
                                     QStringLiteral("World: P = M(t) · worldFromModel · ")) &&
                                     table->explanationText().contains(
                                         QStringLiteral("(M: the animation matrix at t = 0.5 s)")),
                                 kTimeoutMs);
        QCOMPARE(window.inspection()->frame(), frame);
        QVERIFY(window.inspection()->replay());
        auto* matrix = panel->findChild<QLabel*>(QStringLiteral("animationMatrix"));
        QVERIFY2(matrix->text().contains(QStringLiteral("36 °/s · 0.5 s = 18°")),
                 qPrintable(matrix->text()));

        // Play: time moves on, no replay is built for frames replaced while playing.
        panel->setPlaying(true);
        QVERIFY(panel->isPlaying());
        QVERIFY(QTest::qWaitFor([&] { return panel->frame() >= 16; }, kTimeoutMs));
        QVERIFY(
            QTest::qWaitFor([&] { return window.currentFrame()->scene->time > 0.5; }, kTimeoutMs));
        QVERIFY(panel->isPlaying());
        QVERIFY(!window.inspection()->replay());
        QVERIFY(!window.replayBuilder()->isBusy());
        // Pause anywhere: that frame is shown and can be stepped through.
        panel->setPlaying(false);
        const double paused = panel->settings().time;
        QVERIFY(paused > 0.5);
        QVERIFY(waitForTime(window, paused));
        QVERIFY(window.inspection()->replay());
        QVERIFY(window.inspection()->stepBack());

        // The settings are the document's session, and stay when a window adopts it.
        MainWindow other;
        other.adoptDocument(window.document());
        QCOMPARE(other.animationPanel()->settings(), window.document().animation());
        QVERIFY(waitForTime(other, paused));
    }

    void exportWritesTheFrames() {
        MainWindow window;
        QVERIFY(waitForTime(window, 0.0));
        auto* frames =
            window.animationPanel()->findChild<QSpinBox*>(QStringLiteral("animationFrames"));
        frames->setValue(3);
        QTemporaryDir dir;
        QCOMPARE(window.exportAnimationFrames(dir.path()), 3);
        const QDir folder(dir.path());
        QCOMPARE(folder.entryList({QStringLiteral("*.png")}, QDir::Files, QDir::Name),
                 (QStringList{QStringLiteral("frame_0000.png"), QStringLiteral("frame_0001.png"),
                              QStringLiteral("frame_0002.png")}));
        // Frame 0 is the still image; frame 2 (t = 2/24 s, 3 degrees) differs from it.
        const QImage f0(folder.filePath(QStringLiteral("frame_0000.png")));
        QCOMPARE(differingPixels(f0, window.currentImage()), 0);
        QVERIFY(differingPixels(f0, QImage(folder.filePath(QStringLiteral("frame_0002.png")))) >
                50);
        // The window's own scene did not start moving.
        QVERIFY(!window.document().animation().enabled);
    }

private:
    QTemporaryDir m_settings;
};

QTEST_MAIN(TestAnimation)
#include "tst_animation.moc"
