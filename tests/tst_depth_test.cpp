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

    void ddaDepthIsTheSteppedSum() {
        // Under the hw2 rules the depth test reads the weights and the depth the DDA stepped
        // (tst_scan_conversion works them out by hand for this triangle): at pixel (7, 3),
        // five additions of the row's increments from pixel 2. The z-buffer and the
        // barycentrics hold those sums rounded to float, in the stage and the fast path alike.
        Scene scene = screen(10, 10);
        scene.rules = RasterRules::hw2();
        scene.conventions = Conventions::hw2();
        const Projection pr =
            screenTriangles({{2.5, 0.5}, {8.5, 3.5}, {0.5, 4.5}}, {{0, 1, 2}}, {0.25f, 1.0f, 0.5f});
        const ScanConversion scan = ScanConversionStage().run({scene, pr});
        const DepthTest d = DepthTestStage().run({scene, pr, scan});
        DdaSpan row3 = ddaSpanAt(scene, pr, 0, 3, 2);
        for (int x = 2; x < 7; ++x) row3.next();
        QCOMPARE(d.depth.at(7, 3), static_cast<float>(row3.values.z));
        QCOMPARE(d.barycentric.at(7, 3),
                 vec2(static_cast<float>(row3.values.beta), static_cast<float>(row3.values.gamma)));
        RL_COMPARE_NEAR(d.depth.at(7, 3), 0.25 + 0.75 * (23.0 / 30) + 0.25 * (1.5 / 30), 1e-7);
        QCOMPARE(fragmentDepth(scene, pr, 0, 3, 2, 7).depth, d.depth.at(7, 3));
        QCOMPARE(d.coveredPixels(), std::size_t(15));
        // Pixel (3, 1), worked out by hand in tst_scan_conversion: z = 0.28125 + 0.75 *
        // 0.075 = 0.3375 in double, then rounded to float. The plane's direct evaluation (the
        // exact walk's depth test, in float) rounds differently there and at five other pixels.
        QCOMPARE(d.depth.at(3, 1), 0.3375f);
        const TrianglePlane plane(pr, 0, false);
        int otherBits = 0;
        for (const Span& span : scan.spans) {
            double beta0 = 0.0, gamma0 = 0.0;
            plane.spanStart(span.xBegin, span.y, 0.0, beta0, gamma0);
            for (int x = span.xBegin; x < span.xEnd; ++x) {
                const float z = plane.fragment(beta0, gamma0, x - span.xBegin).depth;
                RL_COMPARE_NEAR(z, d.depth.at(x, span.y), 1e-7);
                otherBits += z != d.depth.at(x, span.y) ? 1 : 0;
            }
        }
        QCOMPARE(otherBits, 6);
        for (int threads : {1, 2}) {
            const DepthTest f = fast::depthTest({scene, pr, scan}, threads, nullptr, true);
            QCOMPARE(f.depth, d.depth);
            QCOMPARE(f.triangle, d.triangle);
            QVERIFY(testing::sameCoveredBarycentrics(f, d));
        }
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
