// Stage 6, depth test: the nearer fragment wins whatever the drawing order, a tie keeps
// the earlier triangle, and depths at vertices and inside are those of P' by hand.
#include <QtTest>

#include "pipeline/fast/depth_test_fast.h"
#include "pipeline/stages/depth_test.h"
#include "pipeline/stages/probe.h"
#include "pipeline/stages/scan_conversion.h"
#include "tests/test_support.h"

using namespace rl;

namespace {

using testing::screen;
using testing::screenTriangles;

DepthTest depthOf(const Scene& scene, const Projection& pr) {
    const ScanConversion scan = ScanConversionStage().run({scene, pr});
    return DepthTestStage().run({scene, pr, scan});
}

}  // namespace

class TestDepthTest : public QObject {
    Q_OBJECT

private slots:
    void runEndFindsTheFirstOtherId() {
        // Every run length up to 40 from four starting offsets, the other id at every place
        // (in the first and second sixteen) or nowhere; for an id and for kNoTriangle.
        for (const std::uint32_t t : {7u, kNoTriangle}) {
            for (int from = 0; from < 4; ++from) {
                for (int length = 0; length <= 40; ++length) {
                    const int limit = from + length;
                    for (int other = -1; other < length; ++other) {
                        // Past the limit the ids are t too: a read past it would show.
                        std::vector<std::uint32_t> ids(static_cast<std::size_t>(limit + 20), t);
                        if (other >= 0) ids[static_cast<std::size_t>(from + other)] = t ^ 1u;
                        const int expected = other >= 0 ? from + other : limit;
                        QCOMPARE(fast::runEnd(ids.data(), from, limit, t), expected);
                    }
                }
            }
        }
    }

    void nearerWinsInEitherOrder() {
        // Two squares' worth of triangles over the same pixels, at depths 5 and 3.
        const std::vector<dvec2> p = {{0, 0}, {8, 0}, {0, 8}, {0, 0}, {8, 0}, {0, 8}};
        const std::vector<float> z = {5, 5, 5, 3, 3, 3};
        for (bool nearFirst : {false, true}) {
            const auto order =
                nearFirst ? std::vector<std::array<std::uint32_t, 3>>{{3, 4, 5}, {0, 1, 2}}
                          : std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}, {3, 4, 5}};
            const Scene scene = screen(10, 10);
            const DepthTest d = depthOf(scene, screenTriangles(p, order, z));
            const std::uint32_t nearTriangle = nearFirst ? 0 : 1;
            QCOMPARE(d.depth.at(2, 2), 3.0f);
            QCOMPARE(d.triangle.at(2, 2), nearTriangle);
            QCOMPARE(d.fragments, std::size_t(2 * 45));
            // Drawn far first, every near fragment passes too; drawn near first, every far
            // fragment is rejected.
            QCOMPARE(d.passed, std::size_t(nearFirst ? 45 : 90));
            QCOMPARE(d.rejected, std::size_t(nearFirst ? 45 : 0));
        }
    }

    void tieKeepsTheEarlierTriangle() {
        const DepthTest d =
            depthOf(screen(10, 10),
                    screenTriangles({{0, 0}, {8, 0}, {0, 8}}, {{0, 1, 2}, {0, 1, 2}}, {4, 4, 4}));
        QCOMPARE(d.triangle.at(1, 1), 0u);  // z < stored is strict
        QCOMPARE(d.rejected, std::size_t(45));
    }

    void depthIsInterpolatedWithScreenBarycentrics() {
        // Vertices (0,0) z=10, (8,0) z=20, (0,8) z=30. At pixel (2,4): beta = 2/8, gamma = 4/8,
        // alpha = 1/4, so z = 10/4 + 20/4 + 30/2 = 22.5.
        const DepthTest d = depthOf(
            screen(10, 10), screenTriangles({{0, 0}, {8, 0}, {0, 8}}, {{0, 1, 2}}, {10, 20, 30}));
        RL_COMPARE_NEAR(d.depth.at(2, 4), 22.5, 1e-5);
        RL_COMPARE_VEC(d.barycentric.at(2, 4), vec2(0.25f, 0.5f), 1e-7);
        // At the vertices the depth is the vertex's.
        QCOMPARE(d.depth.at(0, 0), 10.0f);
        QCOMPARE(d.depth.at(8, 0), 20.0f);
        QCOMPARE(d.depth.at(0, 8), 30.0f);
        // Outside: cleared to +infinity, no triangle.
        QVERIFY(std::isinf(d.depth.at(9, 9)) && d.depth.at(9, 9) > 0);
        QCOMPARE(d.triangle.at(9, 9), kNoTriangle);
        QCOMPARE(d.coveredPixels(), std::size_t(45));
    }

    void depthAlongARowIsMonotonic() {
        // A slanted triangle: depth grows with x on every row.
        const DepthTest d = depthOf(
            screen(64, 64), screenTriangles({{0, 0}, {63, 0}, {0, 63}}, {{0, 1, 2}}, {1, 100, 1}));
        for (int y = 0; y < 63; ++y)
            for (int x = 1; x + y <= 63; ++x) QVERIFY(d.depth.at(x, y) > d.depth.at(x - 1, y));
    }

    void probeSeesBothDepthsAndTheVerdict() {
        const Projection pr = screenTriangles({{0, 0}, {8, 0}, {0, 8}, {0, 0}, {8, 0}, {0, 8}},
                                              {{3, 4, 5}, {0, 1, 2}}, {5, 5, 5, 3, 3, 3});
        const Scene scene = screen(10, 10);
        const ScanConversion scan = ScanConversionStage().run({scene, pr});
        auto probe = RecordingProbe::forPixel(1, 2);
        const DepthTest traced = DepthTestStage().run({scene, pr, scan}, probe);
        const DepthTest plain = DepthTestStage().run({scene, pr, scan});
        QCOMPARE(traced.depth, plain.depth);
        QCOMPARE(traced.triangle, plain.triangle);
        QCOMPARE(probe.events().size(), std::size_t(2));
        const auto& first = std::get<DepthTestEvent>(probe.events()[0]);
        const auto& second = std::get<DepthTestEvent>(probe.events()[1]);
        QCOMPARE(first.triangle, 0u);
        QVERIFY(first.passed);
        QVERIFY(std::isinf(first.stored));
        QCOMPARE(first.depth, 3.0f);
        QCOMPARE(second.triangle, 1u);
        QVERIFY(!second.passed);
        QCOMPARE(second.depth, 5.0f);
        QCOMPARE(second.stored, 3.0f);
    }
};

QTEST_GUILESS_MAIN(TestDepthTest)
#include "tst_depth_test.moc"
