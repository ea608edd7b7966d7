// Stage 2, view transform: seed 000's triangle and light in view coordinates, by hand.
#include <QtTest>

#include "pipeline/stages/camera_basis.h"
#include "pipeline/stages/view_transform.h"
#include "tests/test_support.h"

using namespace rl;

class TestViewTransform : public QObject {
    Q_OBJECT

private slots:
    void seedTriangleByHand() {
        // pView = [U; V; N] (P - C) with the basis of tst_camera_basis; e.g. for
        // P1 = (50, 0, 0): P1 - C = (250, 50, -300), U.(P1 - C) = 0.83192 * 250 + 0.55489 * -300.
        Scene scene = testing::makeScene(
            testing::seedCamera(),
            testing::makeMesh({{50, 0, 0}, {0, 50, 0}, {0, 0, 50}}, {{0, 1, 2}}), 800, 600);
        scene.lights.push_back({dvec4(-200.0, -50.0, 300.0, 1.0), vec3(0.0f, 255.0f, 0.0f), {}});
        Diagnostics diagnostics;
        auto basis = CameraBasisStage().run(scene, diagnostics);
        QVERIFY(basis.ok());
        const ViewTransform view = ViewTransformStage().run(scene, basis.value());
        QCOMPARE(view.pView.size(), std::size_t(1));
        const auto& p = view.pView[0];
        RL_COMPARE_VEC(p[0], dvec4(41.512921978873436, -5.50597197448705, 391.4669354893107, 1.0),
                       1e-9);
        RL_COMPARE_VEC(p[1], dvec4(-0.08319222841453211, 47.919847992076285, 371.084466459416, 1.0),
                       1e-9);
        RL_COMPARE_VEC(p[2], dvec4(27.661415947846535, 4.315993349021351, 322.8253680694431, 1.0),
                       1e-9);
        // The light sits at the camera: the origin of view space.
        RL_COMPARE_VEC(view.lights[0].pView, dvec4(0.0, 0.0, 0.0, 1.0), 1e-12);
        QCOMPARE(view.verticesInFront, std::size_t(3));
        QCOMPARE(view.verticesBehind, std::size_t(0));
    }

    void axisCameraMirrorsX() {
        // C = 0, N = +z, V = +y: U = N x V = -x, so view = (-x, y, z).
        Scene scene = testing::makeScene(
            testing::axisCamera(),
            testing::makeMesh({{1, 2, 3}, {-4, 5, -6}, {0, 0, 0}}, {{0, 1, 2}}), 10, 10);
        Diagnostics diagnostics;
        auto basis = CameraBasisStage().run(scene, diagnostics);
        const ViewTransform view = ViewTransformStage().run(scene, basis.value());
        RL_COMPARE_VEC(view.pView[0][0], dvec4(-1, 2, 3, 1), 1e-15);
        RL_COMPARE_VEC(view.pView[0][1], dvec4(4, 5, -6, 1), 1e-15);
        QCOMPARE(view.verticesInFront, std::size_t(1));
        QCOMPARE(view.verticesBehind, std::size_t(2));  // z = -6 and z = 0
    }

    void modelMatrixApplies() {
        Scene scene =
            testing::makeScene(testing::axisCamera(), testing::makeMesh({{1, 0, 0}}, {}), 10, 10);
        scene.draws[0].worldFromModel = dmat4(1.0);
        scene.draws[0].worldFromModel[3] = dvec4(0.0, 0.0, 5.0, 1.0);  // translate by +5 z
        Diagnostics diagnostics;
        auto basis = CameraBasisStage().run(scene, diagnostics);
        const ViewTransform view = ViewTransformStage().run(scene, basis.value());
        RL_COMPARE_VEC(view.pView[0][0], dvec4(-1, 0, 5, 1), 1e-15);
    }

    void distancesArePreserved() {
        // The change of basis is rigid: distances between points do not change.
        Scene scene = testing::makeScene(
            testing::seedCamera(),
            testing::makeMesh({{50, 0, 0}, {0, 50, 0}, {0, 0, 50}, {-300, 20, 7}}, {}), 8, 8);
        Diagnostics diagnostics;
        auto basis = CameraBasisStage().run(scene, diagnostics);
        const ViewTransform view = ViewTransformStage().run(scene, basis.value());
        const auto& world = scene.draws[0].mesh->positions;
        for (std::size_t i = 0; i < world.size(); ++i)
            for (std::size_t j = 0; j < world.size(); ++j)
                RL_COMPARE_NEAR(glm::distance(dvec3(view.pView[0][i]), dvec3(view.pView[0][j])),
                                glm::distance(dvec3(world[i]), dvec3(world[j])), 1e-9);
    }
};

QTEST_GUILESS_MAIN(TestViewTransform)
#include "tst_view_transform.moc"
