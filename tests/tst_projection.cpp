// Stage 4, projection: seed 000's triangle to [-1, 1] and to pixels by hand, and clipping
// against the near plane (a quad splits in two, nothing behind the camera is divided).
#include <QtTest>

#include "pipeline/fast/projection_fast.h"
#include "pipeline/scene/benchmark_scenes.h"
#include "pipeline/stages/camera_basis.h"
#include "pipeline/stages/projection.h"
#include "pipeline/stages/view_transform.h"
#include "tests/test_support.h"

using namespace rl;

class TestProjection : public QObject {
    Q_OBJECT

private:
    struct Run {
        Projection projection;
        Diagnostics diagnostics;
    };
    // The stage as the lecture writes it.
    static Run project(const Scene& scene) {
        Run run;
        auto basis = CameraBasisStage().run(scene, run.diagnostics);
        const ViewTransform view = ViewTransformStage().run(scene, basis.value());
        run.projection = ProjectionStage().run({scene, view}, run.diagnostics);
        return run;
    }
    // The fast path (projection_fast.h).
    static Run projectFast(const Scene& scene, int threads, bool keepExact = true) {
        Run run;
        auto basis = CameraBasisStage().run(scene, run.diagnostics);
        const ViewTransform view = ViewTransformStage().run(scene, basis.value());
        run.projection = fast::projection({scene, view}, run.diagnostics, threads, keepExact);
        return run;
    }

private slots:
    void seedTriangleToPixels() {
        // pNdc = ((d/hx) x/z, (d/hy) y/z) with d = 65, hx = 0.5, hy = 0.6 and the view
        // coordinates of tst_view_transform; pixels x = (int)((x + 1) 800/2),
        // y = (int)((1 - y) 600/2). C's (int) truncates toward zero: -3896.87 -> -3896.
        const Scene scene = testing::makeScene(
            testing::seedCamera(),
            testing::makeMesh({{50, 0, 0}, {0, 50, 0}, {0, 0, 50}}, {{0, 1, 2}}), 800, 600);
        const Run run = project(scene);
        const DrawProjection& p = run.projection.draws[0];
        RL_COMPARE_VEC(p.pNdc[0], dvec2(13.785787171292036, -1.5237054350210493), 1e-9);
        RL_COMPARE_VEC(p.pNdc[1], dvec2(-0.029144280268794183, 13.989582790515481), 1e-9);
        RL_COMPARE_VEC(p.pNdc[2], dvec2(11.13910004881189, 1.4483556510447515), 1e-9);
        RL_COMPARE_VEC(p.pScreenExact[0], dvec2(5914.314868516814, 757.1116305063147), 1e-6);
        RL_COMPARE_VEC(p.pScreenExact[1], dvec2(388.3422878924823, -3896.8748371546444), 1e-6);
        RL_COMPARE_VEC(p.pScreenExact[2], dvec2(4855.640019524756, -134.50669531342544), 1e-6);
        QCOMPARE(p.pScreen[0], dvec2(5914, 757));
        QCOMPARE(p.pScreen[1], dvec2(388, -3896));
        QCOMPARE(p.pScreen[2], dvec2(4855, -134));
        // The depth compared by the z-buffer is the view z.
        RL_COMPARE_NEAR(p.depth[0], 391.4669354893107, 1e-4);
        QCOMPARE(run.projection.inside, std::size_t(1));
        QCOMPARE(run.projection.triangles.size(), std::size_t(1));
        QCOMPARE(p.fate[0], TriangleFate::Inside);
    }

    void exactPositionsLeftOutChangeNothingElse() {
        // Without keepExact (a frame that keeps only its image), pNdc and pScreenExact are
        // empty and every other vertex and triangle array is the same bits: a quad made by
        // the near plane (clipping on one thread) and the 100k torus (emitted on three).
        Scene quad = testing::makeScene(
            testing::axisCamera(),
            testing::makeMesh({{0, 1, 10}, {1, -1, 10}, {0, 0, -10}}, {{0, 1, 2}}), 100, 100);
        quad.nearPlane.fixedW = 1.0;
        auto torus = makeBenchmarkScene("torus-100k", 320, 240, ShadingModel::Phong);
        QVERIFY(torus);
        for (const auto& [scene, threads] : {std::pair{&quad, 1}, std::pair{&*torus, 3}}) {
            const Run kept = projectFast(*scene, threads, true);
            const Run lean = projectFast(*scene, threads, false);
            const DrawProjection& a = kept.projection.draws[0];
            const DrawProjection& b = lean.projection.draws[0];
            QCOMPARE(a.pNdc.size(), a.pView.size());
            QCOMPARE(a.pScreenExact.size(), a.pView.size());
            QVERIFY(b.pNdc.empty() && b.pScreenExact.empty());
            QVERIFY(a.pView == b.pView && a.pClip == b.pClip && a.pScreen == b.pScreen);
            QVERIFY(a.depth == b.depth && a.inFront == b.inFront && a.fate == b.fate);
            QCOMPARE(b.generated.size(), a.generated.size());
            QCOMPARE(lean.projection.triangles.size(), kept.projection.triangles.size());
            for (std::size_t k = 0; k < kept.projection.triangles.size(); ++k)
                QCOMPARE(lean.projection.triangles[k].v, kept.projection.triangles[k].v);
            QCOMPARE(lean.projection.clipped, kept.projection.clipped);
            QCOMPARE(lean.projection.inside, kept.projection.inside);
        }
        QCOMPARE(projectFast(quad, 1, false).projection.triangles.size(), std::size_t(2));
    }

    void courseMatrix() {
        CourseCamera c = testing::seedCamera();
        const dmat4 m = courseClipFromView(c);
        const dvec4 clip = m * dvec4(2.0, 3.0, 4.0, 1.0);
        RL_COMPARE_VEC(clip, dvec4(65.0 / 0.5 * 2.0, 65.0 / 0.6 * 3.0, 4.0, 4.0), 1e-12);
    }

    void negativeHalfSizeMirrors() {
        CourseCamera c = testing::axisCamera();
        c.hx = -1.0;
        const Scene scene = testing::makeScene(
            c, testing::makeMesh({{-5, 0, 10}, {0, 5, 10}, {5, 0, 10}}, {{0, 1, 2}}), 100, 100);
        const Run run = project(scene);
        // View x of world (-5, 0, 10) is 5; with hx = -1 the NDC x is -0.5.
        RL_COMPARE_VEC(run.projection.draws[0].pNdc[0], dvec2(-0.5, 0.0), 1e-12);
        QCOMPARE(run.projection.draws[0].pScreen[0], dvec2(25, 50));
    }

    void oneVertexBehindMakesAQuad() {
        // Axis camera (view = (-x, y, z)), near plane fixed at z = 1. A = (0,1,10) and
        // B = (1,-1,10) are in front, C = (0,0,-10) behind. Edge B->C crosses z = 1 at
        // t = (1 - 10)/(-10 - 10) = 0.45: view (-1 + 0.45, -1 + 0.45, 1); edge A->C at
        // t = 0.45 too: view (0, 1 - 0.45, 1). The quad A, B, BC, AC becomes two triangles.
        Scene scene = testing::makeScene(
            testing::axisCamera(),
            testing::makeMesh({{0, 1, 10}, {1, -1, 10}, {0, 0, -10}}, {{0, 1, 2}}), 100, 100);
        scene.nearPlane.fixedW = 1.0;
        const Run run = project(scene);
        const Projection& pr = run.projection;
        const DrawProjection& p = pr.draws[0];
        QCOMPARE(p.fate[0], TriangleFate::Clipped);
        QCOMPARE(pr.clipped, std::size_t(1));
        QCOMPARE(pr.triangles.size(), std::size_t(2));
        QCOMPARE(p.generated.size(), std::size_t(2));
        QCOMPARE(p.originalVertexCount, 3u);
        // First made vertex: on B->C; second: on C->A, stored from the front vertex A.
        QCOMPARE(p.generated[0].a, 1u);
        QCOMPARE(p.generated[0].b, 2u);
        RL_COMPARE_NEAR(p.generated[0].t, 0.45, 1e-15);
        RL_COMPARE_VEC(p.pView[3], dvec4(-0.55, -0.55, 1.0, 1.0), 1e-12);
        RL_COMPARE_VEC(p.pClip[3], dvec4(-0.55, -0.55, 1.0, 1.0), 1e-12);
        QCOMPARE(p.generated[1].a, 0u);
        QCOMPARE(p.generated[1].b, 2u);
        RL_COMPARE_VEC(p.pView[4], dvec4(0.0, 0.55, 1.0, 1.0), 1e-12);
        QCOMPARE(p.pClip[3].w, 1.0);  // exactly on the plane w = near (w is the view z)
        QCOMPARE((std::array<std::uint32_t, 3>{0, 1, 3}), pr.triangles[0].v);
        QCOMPARE((std::array<std::uint32_t, 3>{0, 3, 4}), pr.triangles[1].v);
        // The behind vertex was never projected.
        QCOMPARE(p.inFront[2], std::uint8_t(0));
        // NDC of the vertex made on B->C: (-0.55 / 1, -0.55 / 1).
        RL_COMPARE_VEC(p.pNdc[3], dvec2(-0.55, -0.55), 1e-12);
        QVERIFY(run.diagnostics.contains(
            "1 triangle was clipped against the near plane z = 1; 0 lie wholly behind the near "
            "plane, not drawn"));
    }

    void twoVerticesBehindMakeOneTriangle() {
        Scene scene = testing::makeScene(
            testing::axisCamera(),
            testing::makeMesh({{0, 1, 10}, {1, -1, -10}, {0, 0, -10}}, {{0, 1, 2}}), 100, 100);
        scene.nearPlane.fixedW = 1.0;
        const Run run = project(scene);
        QCOMPARE(run.projection.triangles.size(), std::size_t(1));
        QCOMPARE(run.projection.draws[0].generated.size(), std::size_t(2));
        for (std::uint32_t v : run.projection.triangles[0].v)
            QVERIFY(run.projection.draws[0].pView[v].z >= 1.0);
    }

    void vertexOnThePlaneIsInFront() {
        Scene scene = testing::makeScene(
            testing::axisCamera(),
            testing::makeMesh({{0, 1, 1}, {1, -1, 10}, {-1, -1, 10}}, {{0, 1, 2}}), 100, 100);
        scene.nearPlane.fixedW = 1.0;
        const Run run = project(scene);
        QCOMPARE(run.projection.draws[0].fate[0], TriangleFate::Inside);
        QCOMPARE(run.projection.draws[0].generated.size(), std::size_t(0));
    }

    void sharedEdgeClipsIdentically() {
        // Two triangles share the edge (1,0,10)-(0,0,-10), which crosses the near plane:
        // both must place the clip vertex at exactly the same point (no crack).
        Scene scene =
            testing::makeScene(testing::axisCamera(),
                               testing::makeMesh({{1, 0, 10}, {0, 0, -10}, {0, 2, 10}, {0, -2, 10}},
                                                 {{0, 1, 2}, {1, 0, 3}}),
                               100, 100);
        scene.nearPlane.fixedW = 0.5;
        const Run run = project(scene);
        const DrawProjection& p = run.projection.draws[0];
        std::vector<dvec4> onSharedEdge;
        for (std::size_t i = 0; i < p.generated.size(); ++i) {
            const ClipVertex& g = p.generated[i];
            if ((g.a == 0 && g.b == 1) || (g.a == 1 && g.b == 0))
                onSharedEdge.push_back(p.pView[p.originalVertexCount + i]);
        }
        QCOMPARE(onSharedEdge.size(), std::size_t(2));
        QCOMPARE(onSharedEdge[0], onSharedEdge[1]);  // bit for bit
    }

    void wholeObjectBehindIsEmptyAndSaysSo() {
        Scene scene = testing::makeScene(
            testing::axisCamera(),
            testing::makeMesh({{0, 1, -10}, {1, -1, -10}, {-1, -1, -10}, {0, 0, -20}},
                              {{0, 1, 2}, {0, 1, 3}}),
            100, 100);
        scene.name = "behind.byu";
        const Run run = project(scene);
        QCOMPARE(run.projection.behind, std::size_t(2));
        QCOMPARE(run.projection.triangles.size(), std::size_t(0));
        QCOMPARE(run.projection.draws[0].fate[1], TriangleFate::Behind);
        QCOMPARE(run.diagnostics.size(), std::size_t(1));
        QVERIFY(everyTriangleBehind(run.projection, scene));
        QCOMPARE(trianglesBehindEye(run.projection, scene), std::size_t(2));
        QCOMPARE(QString::fromStdString(run.diagnostics.items()[0].toString()),
                 QStringLiteral("behind.byu: warning: every triangle is behind the camera (is N "
                                "pointing away from the object?): the image is empty. The plain "
                                "divide of seed 000, x/z and y/z with z < 0, would draw all 2 of "
                                "them: the object's point reflection through the eye (turned "
                                "half a turn on the screen), where the z-buffer, keeping the "
                                "smallest z, keeps the side farthest from the camera"));
    }

    void vertexAtTheEyeUnderNaiveProjectionIsDropped() {
        // x/0 is infinite: the triangle must be dropped, not pulled in to the guard band.
        Scene scene = testing::makeScene(
            testing::axisCamera(),
            testing::makeMesh({{5, 3, 0}, {1, -1, 10}, {-1, -1, 10}}, {{0, 1, 2}}), 100, 100);
        scene.nearPlane.mode = NearPlane::Mode::Naive;
        const Run run = project(scene);
        QCOMPARE(run.projection.draws[0].fate[0], TriangleFate::NonFinite);
        QCOMPARE(run.projection.triangles.size(), std::size_t(0));
        QCOMPARE(run.projection.outsideGuardBand, std::size_t(0));
    }

    void autoNearPlaneIsAThousandthOfTheFarthestVertex() {
        Scene scene = testing::makeScene(
            testing::axisCamera(),
            testing::makeMesh({{0, 1, 600}, {1, -1, 10}, {-1, -1, -5}}, {{0, 1, 2}}), 100, 100);
        const Run run = project(scene);
        RL_COMPARE_NEAR(run.projection.nearW, 0.6, 1e-15);
        QCOMPARE(run.projection.clipped, std::size_t(1));
    }

    void vertexAtTheEyeIsClipped() {
        // A vertex at the camera's position (z = 0): never divided by 0.
        Scene scene = testing::makeScene(
            testing::axisCamera(),
            testing::makeMesh({{0, 0, 0}, {1, -1, 10}, {-1, -1, 10}}, {{0, 1, 2}}), 100, 100);
        const Run run = project(scene);
        QCOMPARE(run.projection.draws[0].fate[0], TriangleFate::Clipped);
        for (const ScreenTriangle& t : run.projection.triangles)
            for (std::uint32_t v : t.v) {
                const dvec2 s = run.projection.draws[0].pScreen[v];
                QVERIFY(std::isfinite(s.x) && std::isfinite(s.y));
            }
    }

    void drawWithItsOwnProjection() {
        // A draw that brings its own matrix (as command files will): OpenGL's glFrustum(-1, 1,
        // -1, 1, 1, 10), which looks down -z and puts w = -z. No course camera in the scene:
        // view coordinates are the draw's own. The triangle at z = -2 is in front; one at
        // z = +2 is behind.
        Scene scene;
        scene.name = "frustum";
        scene.width = 100;
        scene.height = 100;
        Draw draw;
        draw.mesh = testing::makeMesh(
            {{-1, -1, -2}, {1, -1, -2}, {0, 1, -2}, {0, 0, 2}, {1, 0, 2}, {0, 1, 2}},
            {{0, 1, 2}, {3, 4, 5}});
        const double n = 1.0, f = 10.0;
        dmat4 frustum(0.0);
        frustum[0][0] = n;
        frustum[1][1] = n;
        frustum[2][2] = -(f + n) / (f - n);
        frustum[2][3] = -1.0;
        frustum[3][2] = -2.0 * f * n / (f - n);
        draw.clipFromView = frustum;
        scene.draws.push_back(draw);
        scene.nearPlane.fixedW = 1.0;
        const Run run = project(scene);
        const DrawProjection& p = run.projection.draws[0];
        QCOMPARE(p.fate[0], TriangleFate::Inside);
        QCOMPARE(p.fate[1], TriangleFate::Behind);
        // (-1, -1, -2): clip (-1, -1, ., 2), NDC (-0.5, -0.5): pixel x = 25, y = (1 + 0.5) 50 = 75.
        RL_COMPARE_VEC(p.pNdc[0], dvec2(-0.5, -0.5), 1e-12);
        QCOMPARE(p.pScreen[0], dvec2(25, 75));
        QCOMPARE(clipFromViewOf(scene, scene.draws[0]), frustum);
    }

    // Seed 000's plain divide against clipping, for the three kinds of course scene: an
    // object wholly behind the camera, one straddling z = 0, one in front.
    void plainDivideWhollyBehind() {
        // The same triangle at z = +10 and at z = -10: divided by z < 0, each vertex lands at
        // minus its NDC in front, the point reflection through the eye (x and y mirrored).
        const auto scene = [](double z) {
            Scene s = testing::makeScene(
                testing::axisCamera(),
                testing::makeMesh({{1, 2, z}, {4, -1, z}, {-3, -2, z}}, {{0, 1, 2}}), 100, 100);
            s.nearPlane.mode = NearPlane::Mode::Naive;
            return s;
        };
        const Run front = project(scene(10)), behind = project(scene(-10));
        for (std::uint32_t v = 0; v < 3; ++v)
            RL_COMPARE_VEC(behind.projection.draws[0].pNdc[v], -front.projection.draws[0].pNdc[v],
                           1e-15);
        QCOMPARE(behind.projection.triangles.size(), std::size_t(1));
        QCOMPARE(behind.projection.behindEye, std::size_t(1));
        QCOMPARE(behind.projection.acrossEye, std::size_t(0));
        QVERIFY(behind.diagnostics.contains(
            "plain divide: 1 triangle lies wholly behind the eye (w < 0), drawn without "
            "clipping as the point reflection through the eye"));
        QCOMPARE(front.projection.behindEye + front.projection.acrossEye, std::size_t(0));
        // Clipping draws nothing of it and offers the plain divide in its warning.
        Scene clipped = scene(-10);
        clipped.nearPlane.mode = NearPlane::Mode::Clip;
        const Run none = project(clipped);
        QVERIFY(everyTriangleBehind(none.projection, clipped));
        QCOMPARE(none.projection.triangles.size(), std::size_t(0));
        QVERIFY(none.diagnostics.contains("would draw it: the object's point reflection"));
    }

    void plainDivideStraddling() {
        // From z = 10 to z = -5: the plain divide draws the triangle through infinity, wrong,
        // and says so; clipping draws its front part (a quad: two fan triangles).
        Scene scene = testing::makeScene(
            testing::axisCamera(),
            testing::makeMesh({{-1, -1, 10}, {1, -1, 10}, {0, 1, -5}}, {{0, 1, 2}}), 100, 100);
        scene.nearPlane.mode = NearPlane::Mode::Naive;
        const Run plain = project(scene);
        QCOMPARE(plain.projection.acrossEye, std::size_t(1));
        QCOMPARE(plain.projection.triangles.size(), std::size_t(1));
        QVERIFY(plain.diagnostics.contains("it wraps through infinity and is drawn wrong"));
        scene.nearPlane.mode = NearPlane::Mode::Clip;
        const Run clipped = project(scene);
        QCOMPARE(clipped.projection.clipped, std::size_t(1));
        QCOMPARE(clipped.projection.triangles.size(), std::size_t(2));
        QVERIFY(!everyTriangleBehind(clipped.projection, scene));
        QVERIFY(!clipped.diagnostics.contains("plain divide"));
    }

    void plainDivideInFront() {
        // Wholly in front: both give the same screen triangles, and neither warns.
        Scene scene = testing::makeScene(
            testing::axisCamera(),
            testing::makeMesh({{-1, -1, 10}, {1, -1, 10}, {0, 1, 5}}, {{0, 1, 2}}), 100, 100);
        scene.nearPlane.mode = NearPlane::Mode::Naive;
        const Run plain = project(scene);
        scene.nearPlane.mode = NearPlane::Mode::Clip;
        const Run clipped = project(scene);
        QCOMPARE(plain.projection.triangles.size(), std::size_t(1));
        QCOMPARE(clipped.projection.triangles.size(), std::size_t(1));
        for (std::uint32_t v = 0; v < 3; ++v)
            QCOMPARE(plain.projection.draws[0].pScreen[v], clipped.projection.draws[0].pScreen[v]);
        QVERIFY(plain.diagnostics.empty());
        QVERIFY(clipped.diagnostics.empty());
    }

    void naiveProjectionDividesByNegativeZ() {
        Scene scene =
            testing::makeScene(testing::axisCamera(),
                               testing::makeMesh({{0, 1, 10}, {1, -1, 10}, {2, 4, -10}, {0, 0, 0}},
                                                 {{0, 1, 2}, {0, 1, 3}}),
                               100, 100);
        scene.nearPlane.mode = NearPlane::Mode::Naive;
        const Run run = project(scene);
        const DrawProjection& p = run.projection.draws[0];
        // (2, 4, -10) in view is (-2, 4, -10): NDC (0.2, -0.4), mirrored through the centre.
        RL_COMPARE_VEC(p.pNdc[2], dvec2(0.2, -0.4), 1e-12);
        QCOMPARE(p.fate[0], TriangleFate::Inside);
        // The vertex at z = 0 projects to infinity: that triangle is dropped and counted.
        QCOMPARE(p.fate[1], TriangleFate::NonFinite);
        QCOMPARE(run.projection.nonFinite, std::size_t(1));
        // Both reach from in front of the eye to behind it (z = -10) or onto it (z = 0).
        QCOMPARE(run.projection.acrossEye, std::size_t(2));
        QCOMPARE(run.projection.behindEye, std::size_t(0));
        QVERIFY(run.diagnostics.contains(
            "plain divide: 2 triangles reach from in front of the eye to at or behind it"));
    }
    void severalThreadsEmitTheSameTriangles() {
        // Nothing crosses a plane, so several threads emit the triangles. Draw 0: a closed
        // torus of 5,120 triangles 8 in front of the axis camera, its hidden back faces left
        // out. Draw 1 (cull set): 6,000 separate triangles with legs d = 0.25 at z = 5, on a
        // 200x200 screen (x = (1 - x/z) 100, y = (1 - y/z) 100): every fifth lies at z = -5,
        // wholly behind the camera (1,200); of the others, those with i % 3 == 0 keep the
        // order (0,0) (d,0) (0,d), whose screen edges (-5, 0) and (0, -5) have the cross
        // product +25, clockwise on screen: 2,000 - 400 = 1,600 culled; the rest are
        // reversed and kept: 3,200.
        auto torus = torusMesh(64, 40);
        for (dvec4& p : torus->positions) p.z += 8.0;
        std::vector<dvec3> positions;
        std::vector<std::array<std::uint32_t, 3>> separate;
        const double d = 0.25;
        for (std::uint32_t i = 0; i < 6000; ++i) {
            const double x = -2.0 + 4.0 * (i % 80) / 80.0, y = -2.0 + 4.0 * (i / 80) / 75.0;
            const double z = i % 5 == 0 ? -5.0 : 5.0;
            positions.push_back({x, y, z});
            positions.push_back({x + d, y, z});
            positions.push_back({x, y + d, z});
            separate.push_back(i % 3 == 0 ? std::array{3 * i, 3 * i + 1, 3 * i + 2}
                                          : std::array{3 * i, 3 * i + 2, 3 * i + 1});
        }
        Scene scene = testing::makeScene(testing::axisCamera(), torus, 200, 200);
        scene.cullHiddenBackFaces = true;
        Draw grid = scene.draws[0];
        grid.mesh = testing::makeMesh(std::move(positions), std::move(separate));
        grid.cull = true;
        scene.draws.push_back(grid);

        const Run one = project(scene);  // the stage
        const Projection& a = one.projection;
        QCOMPARE(a.clipped, std::size_t(0));
        QCOMPARE(a.behind, std::size_t(1200));
        QCOMPARE(a.culled, std::size_t(1600));
        QVERIFY(a.backFaces > 2000 && a.backFaces < 3120);
        QCOMPARE(a.inside, 5120 - a.backFaces + 3200);
        QCOMPARE(a.triangles.size(), a.inside);
        for (int threads : {1, 2, 3, 7}) {  // the fast path
            const Run several = projectFast(scene, threads);
            const Projection& b = several.projection;
            QCOMPARE(b.triangles.size(), a.triangles.size());
            for (std::size_t k = 0; k < a.triangles.size(); ++k) {
                QCOMPARE(b.triangles[k].draw, a.triangles[k].draw);
                QCOMPARE(b.triangles[k].source, a.triangles[k].source);
                QCOMPARE(b.triangles[k].v, a.triangles[k].v);
            }
            for (std::size_t draw = 0; draw < 2; ++draw)
                QVERIFY(b.draws[draw].fate == a.draws[draw].fate);
            QCOMPARE(b.inside, a.inside);
            QCOMPARE(b.backFaces, a.backFaces);
            QCOMPARE(b.behind, a.behind);
            QCOMPARE(b.culled, a.culled);
            QCOMPARE(b.clippedAway, a.clippedAway);
            QCOMPARE(b.beyondGuardBand, a.beyondGuardBand);
            QCOMPARE(b.nonFinite, a.nonFinite);
            QCOMPARE(several.diagnostics.size(), one.diagnostics.size());
        }
    }
};

QTEST_GUILESS_MAIN(TestProjection)
#include "tst_projection.moc"
