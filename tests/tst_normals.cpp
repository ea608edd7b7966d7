// Stage 3, normals: triangle normals by hand, vertex normals as normalised sums, and
// degenerate triangles counted and left out.
#include <QtTest>

#include "pipeline/fast/normals_fast.h"
#include "pipeline/scene/benchmark_scenes.h"
#include "pipeline/stages/camera_basis.h"
#include "pipeline/stages/normals.h"
#include "pipeline/stages/view_transform.h"
#include "tests/test_support.h"

using namespace rl;

class TestNormals : public QObject {
    Q_OBJECT

private:
    static Normals normalsOf(const Scene& scene) {
        Diagnostics diagnostics;
        auto basis = CameraBasisStage().run(scene, diagnostics);
        const ViewTransform view = ViewTransformStage().run(scene, basis.value());
        return NormalsStage().run({scene, view});
    }

private slots:
    void seedTriangleNormal() {
        // In world space the triangle (50,0,0), (0,50,0), (0,0,50) has the normal
        // (1, 1, 1)/sqrt(3). The view basis [U; V; N] has determinant -1, so in view space
        // the cross product is -[U; V; N] (1, 1, 1)/sqrt(3) = -(U.1, V.1, N.1)/sqrt(3).
        const Scene scene = testing::makeScene(
            testing::seedCamera(),
            testing::makeMesh({{50, 0, 0}, {0, 50, 0}, {0, 0, 50}}, {{0, 1, 2}}), 8, 8);
        const Normals normals = normalsOf(scene);
        QVERIFY(!normals.skipped);
        const vec3 expected(-0.8006776946789038f, -0.5941845525145079f, 0.07655028933198321f);
        RL_COMPARE_VEC(normals.draws[0].triangle[0], expected, 1e-6);
        for (int v = 0; v < 3; ++v)
            RL_COMPARE_VEC(normals.draws[0].vertex[std::size_t(v)], expected, 1e-6);
    }

    void vertexNormalsAreNormalisedSums() {
        // Axis camera: view = (-x, y, z). Two triangles folded along the y axis: one in the
        // plane z = 0 and one in the plane x = 0.
        const Scene scene = testing::makeScene(
            testing::axisCamera(),
            testing::makeMesh({{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}}, {{0, 1, 2}, {0, 3, 1}}),
            8, 8);
        const Normals normals = normalsOf(scene);
        const auto& n = normals.draws[0];
        // View points: (0,0,0), (0,1,0), (-1,0,0), (0,0,1).
        // Triangle 0: (0,1,0) x (-1,0,0) = (0, 0, 1).  Triangle 1: (0,0,1) x (0,1,0) = (-1, 0, 0).
        RL_COMPARE_VEC(n.triangle[0], vec3(0, 0, 1), 1e-7);
        RL_COMPARE_VEC(n.triangle[1], vec3(-1, 0, 0), 1e-7);
        // Shared vertices 0 and 1: (0,0,1) + (-1,0,0), normalised.
        const float h = std::sqrt(0.5f);
        RL_COMPARE_VEC(n.vertex[0], vec3(-h, 0, h), 1e-7);
        RL_COMPARE_VEC(n.vertex[1], vec3(-h, 0, h), 1e-7);
        RL_COMPARE_VEC(n.vertex[2], vec3(0, 0, 1), 1e-7);
        RL_COMPARE_VEC(n.vertex[3], vec3(-1, 0, 0), 1e-7);
        QCOMPARE(n.degenerateTriangles, std::size_t(0));
        QCOMPARE(n.verticesWithoutNormal, std::size_t(0));
    }

    void largeAndSmallTrianglesWeighEqually() {
        // Each triangle's normal is normalised before it is summed (seed 000), so a huge
        // triangle does not outweigh a tiny one.
        const Scene scene = testing::makeScene(
            testing::axisCamera(),
            testing::makeMesh({{0, 0, 0}, {0, 1000, 0}, {1000, 0, 0}, {0, 0, 0.001}},
                              {{0, 1, 2}, {0, 3, 1}}),
            8, 8);
        const Normals normals = normalsOf(scene);
        const float h = std::sqrt(0.5f);
        RL_COMPARE_VEC(normals.draws[0].vertex[0], vec3(-h, 0, h), 1e-6);
    }

    void degenerateTrianglesContributeNothing() {
        // Triangle 1 repeats a vertex, triangle 2 is collinear: both have zero area.
        const Scene scene = testing::makeScene(
            testing::axisCamera(),
            testing::makeMesh({{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {2, 0, 0}, {5, 5, 5}},
                              {{0, 1, 2}, {0, 0, 1}, {0, 2, 3}}),
            8, 8);
        const Normals normals = normalsOf(scene);
        const auto& n = normals.draws[0];
        QCOMPARE(n.degenerateTriangles, std::size_t(2));
        QCOMPARE(normals.degenerateTriangles, std::size_t(2));
        RL_COMPARE_VEC(n.triangle[1], vec3(0.0f), 0.0);
        RL_COMPARE_VEC(n.triangle[2], vec3(0.0f), 0.0);
        // Vertex 0 touches all three: only triangle 0 counts.
        RL_COMPARE_VEC(n.vertex[0], vec3(0, 0, 1), 1e-7);
        // Vertex 3 is only in the collinear triangle, vertex 4 in none: no normal, counted.
        RL_COMPARE_VEC(n.vertex[3], vec3(0.0f), 0.0);
        RL_COMPARE_VEC(n.vertex[4], vec3(0.0f), 0.0);
        QCOMPARE(n.verticesWithoutNormal, std::size_t(2));
    }

    void normalsAreUnitLength() {
        const Scene scene = testing::makeScene(
            testing::seedCamera(),
            testing::makeMesh({{50, 0, 0}, {0, 50, 0}, {0, 0, 50}, {-30, 4, 9}, {1e-3, 0, 0}},
                              {{0, 1, 2}, {1, 3, 2}, {0, 4, 1}}),
            8, 8);
        const Normals normals = normalsOf(scene);
        for (const vec3& n : normals.draws[0].vertex) RL_COMPARE_NEAR(glm::length(n), 1.0, 1e-6);
        for (const vec3& n : normals.draws[0].triangle) RL_COMPARE_NEAR(glm::length(n), 1.0, 1e-6);
    }

    void fastPathSameBitsOnAnyNumberOfThreads() {
        // The 100k-triangle torus with one triangle made degenerate (two equal corners) and
        // one vertex used by nothing: the fast path on 1, 2, 3 and 7 threads gives the stage's
        // normals, bit for bit, and the same counts.
        auto scene = makeBenchmarkScene("torus-100k", 64, 48, ShadingModel::Phong);
        QVERIFY(scene);
        auto mesh = std::make_shared<Mesh>(*scene->draws[0].mesh);
        mesh->triangles[5000][1] = mesh->triangles[5000][0];
        mesh->positions.push_back(dvec4(0.0, 0.0, 0.0, 1.0));
        scene->draws[0].mesh = mesh;
        Diagnostics diagnostics;
        auto basis = CameraBasisStage().run(*scene, diagnostics);
        const ViewTransform view = ViewTransformStage().run(*scene, basis.value());
        const Normals one = NormalsStage().run({*scene, view});
        QCOMPARE(one.draws[0].degenerateTriangles, std::size_t(1));
        QVERIFY(one.draws[0].verticesWithoutNormal >= 1);
        for (int threads : {1, 2, 3, 7}) {
            const Normals many = fast::normals({*scene, view}, threads, fast::NormalsScope::All);
            QVERIFY(many.draws[0].triangle == one.draws[0].triangle);
            QVERIFY(many.draws[0].vertex == one.draws[0].vertex);
            QCOMPARE(many.draws[0].degenerateTriangles, one.draws[0].degenerateTriangles);
            QCOMPARE(many.draws[0].verticesWithoutNormal, one.draws[0].verticesWithoutNormal);
            QCOMPARE(many.degenerateTriangles, one.degenerateTriangles);
        }
    }

    void readScopeKeepsWhatTheShadingReads() {
        // The 100k torus, on 1 and 3 threads: the fast path's flat (and Phong with flat normals)
        // keeps the triangle normals alone, Gouraud (with flat normals or not) and Phong the vertex
        // normals alone; each the same bits as the full set, with the same counts.
        for (auto [model, flatNormals, triangle, vertex] :
             {std::tuple{ShadingModel::Flat, false, true, false},
              std::tuple{ShadingModel::Painter, false, true, false},
              std::tuple{ShadingModel::Phong, true, true, false},
              std::tuple{ShadingModel::Phong, false, false, true},
              std::tuple{ShadingModel::Gouraud, false, false, true},
              std::tuple{ShadingModel::Gouraud, true, false, true}}) {
            auto scene = makeBenchmarkScene("torus-100k", 64, 48, model);
            QVERIFY(scene);
            auto mesh = std::make_shared<Mesh>(*scene->draws[0].mesh);
            mesh->triangles[5000][1] = mesh->triangles[5000][0];  // degenerate
            scene->draws[0].mesh = mesh;
            scene->draws[0].flatNormals = flatNormals;
            const NormalsRead read = normalsRead(scene->draws[0]);
            QCOMPARE(read.triangle, triangle);
            QCOMPARE(read.vertex, vertex);
            Diagnostics diagnostics;
            auto basis = CameraBasisStage().run(*scene, diagnostics);
            const ViewTransform view = ViewTransformStage().run(*scene, basis.value());
            const Normals all = NormalsStage().run({*scene, view});
            QCOMPARE(all.triangleNormalsLeftOut + all.vertexNormalsLeftOut, std::size_t(0));
            for (int threads : {1, 3}) {
                const Normals kept =
                    fast::normals({*scene, view}, threads, fast::NormalsScope::Read);
                const DrawNormals& n = kept.draws[0];
                QCOMPARE(n.triangle.empty(), !triangle);
                QCOMPARE(n.vertex.empty(), !vertex);
                if (triangle) QVERIFY(n.triangle == all.draws[0].triangle);
                if (vertex) QVERIFY(n.vertex == all.draws[0].vertex);
                QCOMPARE(kept.triangleNormalsLeftOut, std::size_t(triangle ? 0 : 1));
                QCOMPARE(kept.vertexNormalsLeftOut, std::size_t(vertex ? 0 : 1));
                QCOMPARE(n.degenerateTriangles, std::size_t(1));
                QCOMPARE(kept.degenerateTriangles, std::size_t(1));
            }
        }
    }

    void unlitSceneSkips() {
        Scene scene = testing::makeScene(
            testing::axisCamera(),
            testing::makeMesh({{0, 0, 1}, {0, 1, 1}, {1, 0, 1}}, {{0, 1, 2}}), 8, 8);
        scene.ambientIntensity = vec3(0.0f);
        scene.lights.clear();
        const Normals normals = normalsOf(scene);
        QVERIFY(normals.skipped);
        QCOMPARE(QString::fromStdString(normals.skipReason),
                 QStringLiteral("the scene has no lights: nothing reads the normals"));
        QVERIFY(normals.draws.empty());
    }
};

QTEST_GUILESS_MAIN(TestNormals)
#include "tst_normals.moc"
