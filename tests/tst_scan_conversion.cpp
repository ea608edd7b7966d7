// Stage 5, scan conversion: spans worked out by hand, clipping to the screen, and the
// exactness of the edge walk: on random triangles its pixels are exactly those whose
// sample point lies inside or on the triangle (an independent brute-force test), so a
// fan of triangles has no cracks.
#include <QtTest>

#include <map>
#include <random>
#include <set>

#include "pipeline/stages/probe.h"
#include "pipeline/stages/scan_conversion.h"
#include "tests/test_support.h"

using namespace rl;

namespace {

using testing::screen;
using testing::screenTriangles;

std::vector<Span> spansOf(const ScanConversion& scan, std::size_t t) {
    return {scan.spans.begin() + scan.spanStart[t], scan.spans.begin() + scan.spanStart[t + 1]};
}

// Brute force: pixels whose sample (x, y) is inside or on the triangle, by edge functions.
std::set<std::pair<int, int>> insidePixels(const std::array<dvec2, 3>& p, int width, int height) {
    std::set<std::pair<int, int>> inside;
    auto edge = [](const dvec2& a, const dvec2& b, double x, double y) {
        return (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x);  // exact for small integers
    };
    const double area = edge(p[0], p[1], p[2].x, p[2].y);
    if (area == 0.0) return inside;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const double w0 = edge(p[1], p[2], x, y);
            const double w1 = edge(p[2], p[0], x, y);
            const double w2 = edge(p[0], p[1], x, y);
            const bool in =
                area > 0 ? (w0 >= 0 && w1 >= 0 && w2 >= 0) : (w0 <= 0 && w1 <= 0 && w2 <= 0);
            if (in) inside.insert({x, y});
        }
    return inside;
}

std::set<std::pair<int, int>> pixelsOf(const std::vector<Span>& spans) {
    std::set<std::pair<int, int>> pixels;
    for (const Span& s : spans)
        for (int x = s.xBegin; x < s.xEnd; ++x) pixels.insert({x, s.y});
    return pixels;
}

// Brute force for any rules, in exact integer grid arithmetic: whether pixel (x, y)'s sample
// is inside. Inclusive: on every edge's inner side or on it, rows top..bottom. Top-left
// (seed 001's DDA): rows top <= y < bottom; on an edge, inside only if the edge is a left
// boundary (the inside lies toward +x) or horizontal (the rows decide).
bool sampleInside(const std::array<dvec2, 3>& p, const RasterRules& rules, int x, int y) {
    const std::int64_t g = std::int64_t(1) << rules.subpixelBits;
    const auto grid = [&](double v) { return std::int64_t(std::llround(v * double(g))); };
    const std::int64_t offset = grid(rules.sampleOffset);
    const std::int64_t sx = x * g + offset, sy = y * g + offset;
    std::array<std::int64_t, 3> px{}, py{};
    for (int k = 0; k < 3; ++k) {
        px[std::size_t(k)] = grid(p[std::size_t(k)].x);
        py[std::size_t(k)] = grid(p[std::size_t(k)].y);
    }
    const std::int64_t area = (px[1] - px[0]) * (py[2] - py[0]) - (py[1] - py[0]) * (px[2] - px[0]);
    if (area == 0) return false;
    const std::int64_t o = area > 0 ? 1 : -1;
    const std::int64_t top = std::min({py[0], py[1], py[2]});
    const std::int64_t bottom = std::max({py[0], py[1], py[2]});
    const bool topLeft = rules.fill == RasterRules::FillRule::TopLeft;
    if (sy < top || sy > bottom || (topLeft && sy == bottom)) return false;
    for (int k = 0; k < 3; ++k) {
        const std::size_t a = std::size_t(k), b = std::size_t((k + 1) % 3);
        const std::int64_t e =
            o * ((px[b] - px[a]) * (sy - py[a]) - (py[b] - py[a]) * (sx - px[a]));
        if (e < 0) return false;
        if (e == 0 && topLeft && py[a] != py[b] && !(o * (py[a] - py[b]) > 0)) return false;
    }
    return true;
}

std::set<std::pair<int, int>> insideByRule(const std::array<dvec2, 3>& p, const RasterRules& rules,
                                           int width, int height) {
    std::set<std::pair<int, int>> inside;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            if (sampleInside(p, rules, x, y)) inside.insert({x, y});
    return inside;
}

// Whether the point q lies inside the triangle by more than 1e-9 pixel from each edge.
bool clearlyInside(const std::array<dvec2, 3>& p, const dvec2& q) {
    const auto side = [](const dvec2& a, const dvec2& b, const dvec2& c) {
        return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    };
    const double area = side(p[0], p[1], p[2]);
    if (area == 0.0) return false;
    for (std::size_t k = 0; k < 3; ++k) {
        const dvec2& a = p[k];
        const dvec2& b = p[(k + 1) % 3];
        if (side(a, b, q) * (area > 0 ? 1.0 : -1.0) / glm::length(b - a) <= 1e-9) return false;
    }
    return true;
}

// The rules of the current row of subPixelRulesMatchBruteForce_data.
RasterRules rulesOfRow() {
    QFETCH(int, bits);
    QFETCH(double, offset);
    QFETCH(bool, topLeft);
    RasterRules rules;
    rules.subpixelBits = bits;
    rules.sampleOffset = offset;
    rules.fill = topLeft ? RasterRules::FillRule::TopLeft : RasterRules::FillRule::Inclusive;
    return rules;
}

Scene screenWith(int width, int height, const RasterRules& rules) {
    Scene scene = screen(width, height);
    scene.rules = rules;
    return scene;
}

}  // namespace

class TestScanConversion : public QObject {
    Q_OBJECT

private slots:
    void rightTriangleByHand() {
        // (0,0), (4,0), (0,4): row y covers x = 0 .. 4 - y, edges included.
        const Projection pr = screenTriangles({{0, 0}, {4, 0}, {0, 4}}, {{0, 1, 2}});
        const ScanConversion scan = ScanConversionStage().run({screen(10, 10), pr});
        const std::vector<Span> expected = {{0, 0, 5}, {1, 0, 4}, {2, 0, 3}, {3, 0, 2}, {4, 0, 1}};
        QCOMPARE(spansOf(scan, 0), expected);
        QCOMPARE(scan.pixels, std::size_t(15));
    }

    void slopedEdgeByHand() {
        // (0,0), (5,0), (0,3): the right edge is x = 5 - 5y/3: 5, 3.33, 1.67, 0 on rows 0..3.
        const Projection pr = screenTriangles({{0, 0}, {5, 0}, {0, 3}}, {{0, 1, 2}});
        const ScanConversion scan = ScanConversionStage().run({screen(10, 10), pr});
        const std::vector<Span> expected = {{0, 0, 6}, {1, 0, 4}, {2, 0, 2}, {3, 0, 1}};
        QCOMPARE(spansOf(scan, 0), expected);
    }

    void generalTriangleByHand() {
        // Top (4,1), middle (9,4), bottom (1,7). Long edge x = 4 - (y-1)/2; upper edge
        // x = 4 + 5(y-1)/3; lower edge x = 9 - 8(y-4)/3.
        //   y=1: [4, 4]        y=2: [3.5, 5.67] -> 4..5   y=3: [3, 7.33] -> 3..7
        //   y=4: [2.5, 9] -> 3..9   y=5: [2, 6.33] -> 2..6   y=6: [1.5, 3.67] -> 2..3
        //   y=7: [1, 1] -> 1..1
        const Projection pr = screenTriangles({{9, 4}, {1, 7}, {4, 1}}, {{0, 1, 2}});
        const ScanConversion scan = ScanConversionStage().run({screen(20, 20), pr});
        const std::vector<Span> expected = {{1, 4, 5}, {2, 4, 6}, {3, 3, 8}, {4, 3, 10},
                                            {5, 2, 7}, {6, 2, 4}, {7, 1, 2}};
        QCOMPARE(spansOf(scan, 0), expected);
        const TriangleSetup s =
            setupTriangle({dvec2(9, 4), dvec2(1, 7), dvec2(4, 1)}, RasterRules::course());
        QCOMPARE(s.order, (std::array<int, 3>{2, 0, 1}));
        QCOMPARE(s.yFirst, 1);
        QCOMPARE(s.yLast, 7);
        RL_COMPARE_NEAR(s.longEdge.dxdy(), -0.5, 0.0);
        RL_COMPARE_NEAR(s.upperEdge.dxdy(), 5.0 / 3.0, 1e-15);
        RL_COMPARE_NEAR(s.lowerEdge.dxdy(), -8.0 / 3.0, 1e-15);
        RL_COMPARE_NEAR(s.longEdge.xAt(5), 2.0, 0.0);
        QVERIFY(s.longEdgeOnLeft);
    }

    void vertexOrderDoesNotMatter() {
        const std::vector<dvec2> points = {{9, 4}, {1, 7}, {4, 1}};
        const std::array<std::array<std::uint32_t, 3>, 6> orders = {
            {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
        std::vector<Span> first;
        for (const auto& order : orders) {
            const ScanConversion scan =
                ScanConversionStage().run({screen(20, 20), screenTriangles(points, {order})});
            if (first.empty()) first = spansOf(scan, 0);
            QCOMPARE(spansOf(scan, 0), first);
        }
    }

    void flatTopAndFlatBottom() {
        const Projection pr =
            screenTriangles({{1, 1}, {5, 1}, {3, 3}, {3, 5}}, {{0, 1, 2}, {0, 3, 1}});
        const ScanConversion scan = ScanConversionStage().run({screen(10, 10), pr});
        // Flat top (1,1)-(5,1) down to (3,3): rows 1..3 shrink by one pixel a side.
        QCOMPARE(spansOf(scan, 0), (std::vector<Span>{{1, 1, 6}, {2, 2, 5}, {3, 3, 4}}));
        // (1,1), (5,1), (3,5): edges x = 1 + (y-1)/2 and x = 5 - (y-1)/2.
        QCOMPARE(spansOf(scan, 1),
                 (std::vector<Span>{{1, 1, 6}, {2, 2, 5}, {3, 2, 5}, {4, 3, 4}, {5, 3, 4}}));
    }

    void degenerateAndOffscreenAreCounted() {
        const Projection pr =
            screenTriangles({{0, 0}, {2, 2}, {4, 4}, {50, 50}, {60, 50}, {55, 60}, {3, 3}},
                            {{0, 1, 2}, {3, 4, 5}, {0, 0, 6}});
        const ScanConversion scan = ScanConversionStage().run({screen(10, 10), pr});
        QCOMPARE(scan.degenerate, std::size_t(2));  // collinear, repeated vertex
        QCOMPARE(scan.offscreen, std::size_t(1));
        QCOMPARE(scan.spans.size(), std::size_t(0));
        QCOMPARE(scan.triangleCount(), std::size_t(3));
    }

    void gargantuanTriangleFillsTheScreenFast() {
        // A triangle a million times the screen: only the screen's rows and columns are
        // walked, so it costs one span per row.
        const double big = 1e8;
        const Projection pr = screenTriangles({{-big, -big}, {big, -big}, {0, big}}, {{0, 1, 2}});
        QElapsedTimer timer;
        timer.start();
        const ScanConversion scan = ScanConversionStage().run({screen(640, 480), pr});
        QCOMPARE(scan.spans.size(), std::size_t(480));
        QCOMPARE(scan.pixels, std::size_t(640 * 480));
        for (const Span& s : scan.spans)
            QCOMPARE((std::pair{s.xBegin, s.xEnd}), (std::pair{0, 640}));
        qInfo("gargantuan triangle scanned in %lld us",
              static_cast<long long>(timer.nsecsElapsed() / 1000));
    }

    void partlyOffscreenIsClipped() {
        const Projection pr = screenTriangles({{-5, -5}, {5, -5}, {-5, 5}}, {{0, 1, 2}});
        const ScanConversion scan = ScanConversionStage().run({screen(10, 10), pr});
        // Rows 0..5 of the screen; row y covers x = -5 .. -y, i.e. 0..-y on screen.
        QCOMPARE(spansOf(scan, 0), (std::vector<Span>{{0, 0, 1}}));
    }

    void randomTrianglesMatchBruteForce() {
        std::mt19937 rng(7);
        std::uniform_int_distribution<int> coord(-6, 38);
        int compared = 0;
        for (int i = 0; i < 3000; ++i) {
            std::vector<dvec2> p = {{double(coord(rng)), double(coord(rng))},
                                    {double(coord(rng)), double(coord(rng))},
                                    {double(coord(rng)), double(coord(rng))}};
            const ScanConversion scan =
                ScanConversionStage().run({screen(32, 32), screenTriangles(p, {{0, 1, 2}})});
            const auto expected = insidePixels({p[0], p[1], p[2]}, 32, 32);
            const auto actual = pixelsOf(spansOf(scan, 0));
            if (actual != expected)
                QFAIL(qPrintable(QStringLiteral("triangle %1 (%2, %3, %4): %5 pixels, expected %6")
                                     .arg(i)
                                     .arg(testing::describe(p[0]), testing::describe(p[1]),
                                          testing::describe(p[2]))
                                     .arg(actual.size())
                                     .arg(expected.size())));
            ++compared;
        }
        QCOMPARE(compared, 3000);
    }

    void subPixelRulesMatchBruteForce_data() {
        QTest::addColumn<int>("bits");
        QTest::addColumn<double>("offset");
        QTest::addColumn<bool>("topLeft");
        QTest::newRow("hw2: 1/65536 grid, samples at integers, top-left") << 16 << 0.0 << true;
        QTest::newRow("1/16 grid, samples at integers, top-left") << 4 << 0.0 << true;
        QTest::newRow("1/16 grid, centres at +0.5, top-left") << 4 << 0.5 << true;
        QTest::newRow("1/16 grid, centres at +0.5, inclusive") << 4 << 0.5 << false;
        QTest::newRow("integers, top-left") << 0 << 0.0 << true;
    }

    void subPixelRulesMatchBruteForce() {
        const RasterRules rules = rulesOfRow();
        const double g = std::ldexp(1.0, rules.subpixelBits);
        std::mt19937 rng(23);
        // Vertices on the grid, often on sample rows and columns (edges through samples).
        std::uniform_int_distribution<int> coord(-4 * int(g), 36 * int(g));
        std::uniform_int_distribution<int> snapToPixel(0, 2);
        for (int i = 0; i < 2000; ++i) {
            std::array<dvec2, 3> p{};
            for (auto& v : p) {
                v = {coord(rng) / g, coord(rng) / g};
                if (snapToPixel(rng) == 0) v = glm::floor(v) + rules.sampleOffset;
            }
            const ScanConversion scan = ScanConversionStage().run(
                {screenWith(32, 32, rules), screenTriangles({p[0], p[1], p[2]}, {{0, 1, 2}})});
            const auto expected = insideByRule(p, rules, 32, 32);
            const auto actual = pixelsOf(spansOf(scan, 0));
            if (actual != expected)
                QFAIL(qPrintable(QStringLiteral("triangle %1 (%2, %3, %4): %5 pixels, expected %6")
                                     .arg(i)
                                     .arg(testing::describe(p[0]), testing::describe(p[1]),
                                          testing::describe(p[2]))
                                     .arg(actual.size())
                                     .arg(expected.size())));
        }
    }

    void topLeftCoversEachPixelOnce() {
        // Fans around a centre under the top-left rule: every pixel of the fan is covered
        // exactly once, shared edges and shared vertices included. The spokes are less than
        // half a turn apart, so the triangles tile the fan without overlapping.
        // The exact walk on a grid of 1/16 pixel, samples at integer points.
        RasterRules rules = RasterRules::hw2();
        rules.subpixelBits = 4;
        rules.snap = RasterRules::VertexSnap::Nearest;
        rules.scan = RasterRules::Scan::ExactWalk;
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> jitter(0.0, 0.4);
        std::uniform_int_distribution<int> spokes(3, 12);
        std::uniform_real_distribution<double> radius(2.0, 300.0);
        std::uniform_int_distribution<int> centre(0, 63);
        for (int f = 0; f < 2000; ++f) {
            const int n = spokes(rng);
            std::vector<double> angles(static_cast<std::size_t>(n));
            for (std::size_t k = 0; k < angles.size(); ++k)
                angles[k] = (double(k) + jitter(rng)) / n;
            std::vector<dvec2> points = {{double(centre(rng)), double(centre(rng))}};
            for (double a : angles) {
                const double r = radius(rng);
                points.push_back(
                    {std::round(16.0 * (points[0].x + r * std::cos(6.283185307179586 * a))) / 16.0,
                     std::round(16.0 * (points[0].y + r * std::sin(6.283185307179586 * a))) /
                         16.0});
            }
            std::vector<std::array<std::uint32_t, 3>> fan;
            for (int k = 1; k <= n; ++k)
                fan.push_back(
                    {0, static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(k % n + 1)});
            const ScanConversion scan = ScanConversionStage().run(
                {screenWith(64, 64, rules), screenTriangles(points, fan)});
            std::map<std::pair<int, int>, int> hits;
            std::set<std::pair<int, int>> expected;
            for (std::size_t t = 0; t < fan.size(); ++t) {
                const auto& tri = fan[t];
                const auto in =
                    insideByRule({points[tri[0]], points[tri[1]], points[tri[2]]}, rules, 64, 64);
                expected.insert(in.begin(), in.end());
                for (const auto& px : pixelsOf(spansOf(scan, t))) ++hits[px];
            }
            for (const auto& px : expected)
                if (hits[px] != 1)
                    QFAIL(qPrintable(QStringLiteral("fan %1: pixel (%2, %3) covered %4 times")
                                         .arg(f)
                                         .arg(px.first)
                                         .arg(px.second)
                                         .arg(hits[px])));
            QCOMPARE(hits.size(), expected.size());
        }
    }

    void randomFansHaveNoCracks() {
        // Fans of random triangles around a centre: every pixel inside the fan's outline is
        // covered at least once (the inclusive rule covers shared edges twice, never zero
        // times). 2,000 fans of 3 to 12 triangles with vertices far off screen too.
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> angle(0.0, 1.0);
        std::uniform_int_distribution<int> spokes(3, 12);
        std::uniform_real_distribution<double> radius(2.0, 400.0);
        std::uniform_int_distribution<int> centre(0, 63);
        long long doubleHits = 0;
        for (int f = 0; f < 2000; ++f) {
            const int n = spokes(rng);
            std::vector<double> angles(static_cast<std::size_t>(n));
            for (auto& a : angles) a = angle(rng);
            std::sort(angles.begin(), angles.end());
            std::vector<dvec2> points = {{double(centre(rng)), double(centre(rng))}};
            for (double a : angles) {
                const double r = radius(rng);
                points.push_back({std::trunc(points[0].x + r * std::cos(6.283185307179586 * a)),
                                  std::trunc(points[0].y + r * std::sin(6.283185307179586 * a))});
            }
            std::vector<std::array<std::uint32_t, 3>> fan;
            for (int k = 1; k <= n; ++k)
                fan.push_back(
                    {0, static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(k % n + 1)});
            const Projection pr = screenTriangles(points, fan);
            const ScanConversion scan = ScanConversionStage().run({screen(64, 64), pr});
            std::set<std::pair<int, int>> expected;
            std::map<std::pair<int, int>, int> hits;
            for (std::size_t t = 0; t < fan.size(); ++t) {
                const auto& tri = fan[t];
                const auto in =
                    insidePixels({points[tri[0]], points[tri[1]], points[tri[2]]}, 64, 64);
                expected.insert(in.begin(), in.end());
                for (const auto& px : pixelsOf(spansOf(scan, t))) ++hits[px];
            }
            for (const auto& px : expected)
                if (hits[px] == 0)
                    QFAIL(qPrintable(QStringLiteral("fan %1: crack at (%2, %3)")
                                         .arg(f)
                                         .arg(px.first)
                                         .arg(px.second)));
            for (const auto& [px, count] : hits) doubleHits += count > 1 ? count - 1 : 0;
        }
        qInfo("inclusive rule: %lld pixels covered more than once in 2,000 fans (shared edges)",
              doubleHits);
        QVERIFY(doubleHits > 0);
    }

    void scanRowIsTheWalksRow_data() { subPixelRulesMatchBruteForce_data(); }

    void scanRowIsTheWalksRow() {
        // Any row worked out on its own (scanRow, edgeCrossing) is, bit for bit, the row the
        // walk reaches by stepping, empty rows and rows cut by the screen's sides included.
        const RasterRules rules = rulesOfRow();
        const double g = std::ldexp(1.0, rules.subpixelBits);
        std::mt19937 rng(31);
        std::uniform_int_distribution<int> coord(-12 * int(g), 44 * int(g));
        std::size_t rows = 0, empty = 0;
        for (int i = 0; i < 1000; ++i) {
            std::array<dvec2, 3> p{};
            for (auto& v : p) v = {coord(rng) / g, coord(rng) / g};
            ReplayProbe walk;
            ScanConversionStage().run(
                {screenWith(32, 32, rules), screenTriangles({p[0], p[1], p[2]}, {{0, 1, 2}})},
                walk);
            const TriangleSetup s = setupTriangle(p, rules);
            const std::int32_t upperLast = lastUpperRow(s, rules);
            for (const ReplayRowEvent& e : walk.rows) {
                const ScanRow row = scanRow(s, rules, e.y, 32);
                QCOMPARE(row.xLeft, e.xLeft);
                QCOMPARE(row.xRight, e.xRight);
                QCOMPARE(row.xBegin, e.xBegin);
                QCOMPARE(row.xEnd, e.xEnd);
                QCOMPARE(row.upperPart, e.y <= upperLast);
                const ScanEdge& shortEdge = row.upperPart ? s.upperEdge : s.lowerEdge;
                QCOMPARE(edgeCrossing(s.longEdge, rules, e.y),
                         s.longEdgeOnLeft ? e.xLeft : e.xRight);
                QCOMPARE(edgeCrossing(shortEdge, rules, e.y),
                         s.longEdgeOnLeft ? e.xRight : e.xLeft);
                ++rows;
                empty += row.empty() ? 1 : 0;
            }
        }
        QVERIFY(rows > 1000);
        QVERIFY(empty > 0);
    }

    void ddaTriangleByHand() {
        // Seed 001's DDA (hw2 rules). Top (2.5, 0.5), middle (8.5, 3.5), bottom (0.5, 4.5).
        // Long edge: dx/dy = -2/4 = -0.5, rows ceil(0.5) = 1 to 4 (y < 4.5), x = 2.5 + 0.5 *
        // (-0.5) = 2.25 on row 1, then 1.75, 1.25, 0.75. Upper edge: dx/dy = 6/3 = 2, rows 1
        // to 3, x = 2.5 + 0.5 * 2 = 3.5, then 5.5, 7.5. Lower edge: dx/dy = -8/1, row 4 only,
        // x = 8.5 + 0.5 * (-8) = 4.5. Pixels ceil(x_left) <= x < x_right: row 1 [3, 4), row 2
        // [2, 6), row 3 [2, 8), row 4 [1, 5). Every number is exact in binary.
        const Projection pr = screenTriangles({{2.5, 0.5}, {8.5, 3.5}, {0.5, 4.5}}, {{0, 1, 2}});
        auto probe = RecordingProbe::forTriangle(0);
        const ScanConversion scan =
            ScanConversionStage().run({screenWith(10, 10, RasterRules::hw2()), pr}, probe);
        const std::vector<Span> expected = {{1, 3, 4}, {2, 2, 6}, {3, 2, 8}, {4, 1, 5}};
        QCOMPARE(spansOf(scan, 0), expected);
        QCOMPARE(scan.pixels, std::size_t(1 + 4 + 6 + 4));
        // The probe hears the accumulated crossings.
        const std::vector<std::pair<double, double>> crossings = {
            {2.25, 3.5}, {1.75, 5.5}, {1.25, 7.5}, {0.75, 4.5}};
        std::size_t k = 0;
        for (const ProbeEvent& e : probe.events()) {
            if (!std::holds_alternative<SpanEvent>(e)) continue;
            const auto& span = std::get<SpanEvent>(e);
            QVERIFY(k < crossings.size());
            QCOMPARE(span.xLeft, crossings[k].first);
            QCOMPARE(span.xRight, crossings[k].second);
            ++k;
        }
        QCOMPARE(k, crossings.size());
        // A row worked out on its own is the walk's.
        const TriangleSetup s =
            setupTriangle({dvec2(2.5, 0.5), dvec2(8.5, 3.5), dvec2(0.5, 4.5)}, RasterRules::hw2());
        QCOMPARE(s.yFirst, 1);
        QCOMPARE(s.yLast, 4);
        QCOMPARE(lastUpperRow(s, RasterRules::hw2()), 3);
        const ScanRow row3 = scanRow(s, RasterRules::hw2(), 3, 10);
        QCOMPARE(row3.xLeft, 1.25);
        QCOMPARE(row3.xRight, 7.5);
        QCOMPARE(row3.xBegin, 2);
        QCOMPARE(row3.xEnd, 8);
        QVERIFY(row3.upperPart);
    }

    void ddaStepsTheAttributesByHand() {
        // The triangle of ddaTriangleByHand with depths 0.25 (top, vertex 1), 1 (middle,
        // vertex 2) and 0.5 (bottom, vertex 3), under the hw2 conventions (NDC z). Weights
        // (beta, gamma, z) at the vertices: (0, 0, 0.25), (1, 0, 1), (0, 1, 0.5).
        // Long edge, 4 rows high: per row (0, 1/4, 1/16); on row 1, half a row down,
        // (0, 0.125, 0.28125); on row 3 (0, 0.625, 0.40625). Upper edge, 3 rows high: per row
        // (1/3, 0, 1/4) with 1/3 rounded; on row 1 (1/6, 0, 0.375), on row 3 two additions on.
        Scene scene = screenWith(10, 10, RasterRules::hw2());
        scene.conventions = Conventions::hw2();
        const Projection pr =
            screenTriangles({{2.5, 0.5}, {8.5, 3.5}, {0.5, 4.5}}, {{0, 1, 2}}, {0.25f, 1.0f, 0.5f});
        const ScanConversion scan = ScanConversionStage().run({scene, pr});
        QCOMPARE(scan.ddaSpans.size(), scan.spans.size());
        const double third = 1.0 / 3.0;
        double upperBeta = 0.5 * third;
        upperBeta += third;
        upperBeta += third;  // 0.8333333333333333, one step below 2.5 / 3
        QVERIFY(upperBeta < 2.5 / 3.0);
        // Row 1: from x_left 2.25 (long edge) to x_right 3.5 (upper edge), 1.25 apart;
        // per pixel ((1/6) / 1.25, -0.125 / 1.25, 0.09375 / 1.25); pixel 3 is 0.75 on.
        const DdaSpan& row1 = scan.ddaSpans[0];
        QCOMPARE(scan.spans[0], (Span{1, 3, 4}));
        QVERIFY(row1.perPixel.beta == 0.5 * third / 1.25);
        QVERIFY(row1.perPixel.gamma == -0.1);
        QVERIFY(row1.perPixel.z == 0.075);
        QVERIFY(row1.values.beta == 0.75 * (0.5 * third / 1.25));
        QVERIFY(row1.values.gamma == 0.125 + 0.75 * -0.1);
        QVERIFY(row1.values.z == 0.28125 + 0.75 * 0.075);
        // Row 3: from x_left 1.25 to x_right 7.5; pixel 2 is 0.75 on; then one addition of
        // the increment a pixel up to pixel 7. Each stays within 1e-15 of the exact plane (at
        // pixel (x, 3): beta = (4x - 5) / 30, gamma = (22.5 - 3x) / 30), but the sums are not
        // the plane's bits: gamma reaches 0.0500000000000001 at pixel 7, not 0.05.
        const DdaSpan& row3 = scan.ddaSpans[2];
        QCOMPARE(scan.spans[2], (Span{3, 2, 8}));
        const DdaValues left{0.0, 0.625, 0.40625}, right{upperBeta, 0.0, 0.875};
        QVERIFY(row3.perPixel.beta == (right.beta - left.beta) / 6.25);
        QVERIFY(row3.perPixel.gamma == -0.625 / 6.25);
        QVERIFY(row3.perPixel.z == (0.875 - 0.40625) / 6.25);
        DdaSpan stepped = row3;
        DdaValues v;
        for (int x = 2; x < 8; ++x) {
            v = stepped.next();
            RL_COMPARE_NEAR(v.beta, (4.0 * x - 5.0) / 30.0, 1e-15);
            RL_COMPARE_NEAR(v.gamma, (22.5 - 3.0 * x) / 30.0, 1e-15);
            RL_COMPARE_NEAR(v.z, 0.25 + 0.75 * v.beta + 0.25 * v.gamma, 1e-15);
        }
        QVERIFY(v.gamma != 0.05 && std::abs(v.gamma - 0.05) < 1e-15);
        // The span worked out on its own, as the views do, is the walk's.
        const DdaSpan again = ddaSpanAt(scene, pr, 0, 3, 2);
        QVERIFY(again.values.beta == row3.values.beta && again.values.z == row3.values.z &&
                again.perPixel.gamma == row3.perPixel.gamma);
        // The exact walk keeps no attributes.
        QVERIFY(ScanConversionStage()
                    .run({screenWith(10, 10, RasterRules::gpu()), pr})
                    .ddaSpans.empty());
    }

    void ddaHalfOpenByHand() {
        // (0, 0), (4, 0), (0, 4) under the DDA: rows 0 to 3 (y < 4); the lower edge's x = 4,
        // 3, 2, 1; pixels 0 <= x < x_right. The bottom vertex's row and the right edge's
        // samples belong to the neighbours.
        const Projection pr = screenTriangles({{0, 0}, {4, 0}, {0, 4}}, {{0, 1, 2}});
        const ScanConversion scan =
            ScanConversionStage().run({screenWith(10, 10, RasterRules::hw2()), pr});
        const std::vector<Span> expected = {{0, 0, 4}, {1, 0, 3}, {2, 0, 2}, {3, 0, 1}};
        QCOMPARE(spansOf(scan, 0), expected);
    }

    void ddaScreenClippingStartsOnTheScreen() {
        // Top (3, -2.5), bottom (-1, 5.5), middle (7, 1.5). Long edge: dx/dy = -4/8 = -0.5;
        // its first row on the screen is 0, x = 3 + (0 - (-2.5)) * (-0.5) = 1.75, then 1.25,
        // 0.75, 0.25, -0.25, -0.75 (rows 0 to 5). Upper edge: dx/dy = 4/4 = 1, rows 0 and 1,
        // x = 3 + 2.5 = 5.5, 6.5. Lower edge: dx/dy = -8/4 = -2, rows 2 to 5, x = 7 + 0.5 *
        // (-2) = 6, 4, 2, 0. Pixels from ceil(x_left), at least 0, while x < x_right.
        const Projection pr = screenTriangles({{3, -2.5}, {-1, 5.5}, {7, 1.5}}, {{0, 1, 2}});
        const ScanConversion scan =
            ScanConversionStage().run({screenWith(10, 10, RasterRules::hw2()), pr});
        const std::vector<Span> expected = {{0, 2, 6}, {1, 2, 7}, {2, 1, 6}, {3, 1, 4}, {4, 0, 2}};
        QCOMPARE(spansOf(scan, 0), expected);  // row 5: [0, 0), no pixel
    }

    void ddaAndExactWalkDifferByATie() {
        // The left edge from (0, 0) to (2, 18) crosses row 9 at exactly x = 1. The exact walk
        // sees the sample (1, 9) on a left edge: inside. The DDA adds dx/dy = 1/9 (rounded)
        // nine times and reaches 1.0000000000000002: ceil gives 2, and pixel (1, 9) is left
        // out. Every other row is the same under both.
        const std::vector<dvec2> points = {{0, 0}, {2, 18}, {6, 18}};
        const Projection pr = screenTriangles(points, {{0, 1, 2}});
        RasterRules exact = RasterRules::hw2();
        exact.snap = RasterRules::VertexSnap::Nearest;
        exact.scan = RasterRules::Scan::ExactWalk;
        auto probe = RecordingProbe::forTriangle(0);
        const std::vector<Span> dda = spansOf(
            ScanConversionStage().run({screenWith(8, 20, RasterRules::hw2()), pr}, probe), 0);
        const std::vector<Span> walk =
            spansOf(ScanConversionStage().run({screenWith(8, 20, exact), pr}), 0);
        QCOMPARE(dda.size(), walk.size());
        int differing = 0;
        for (std::size_t k = 0; k < dda.size(); ++k) {
            QCOMPARE(dda[k].y, walk[k].y);
            QCOMPARE(dda[k].xEnd, walk[k].xEnd);
            if (dda[k].xBegin == walk[k].xBegin) continue;
            ++differing;
            QCOMPARE(dda[k].y, 9);
            QCOMPARE(dda[k].xBegin, 2);
            QCOMPARE(walk[k].xBegin, 1);
        }
        QCOMPARE(differing, 1);
        // The x the DDA accumulated on row 9, which the stepper shows.
        double x = 0.0;
        for (int k = 0; k < 9; ++k) x += 2.0 / 18.0;
        QVERIFY(x > 1.0);
        bool seen = false;
        for (const ProbeEvent& e : probe.events())
            if (const auto* span = std::get_if<SpanEvent>(&e); span && span->span.y == 9) {
                QCOMPARE(span->xLeft, x);
                seen = true;
            }
        QVERIFY(seen);
        const TriangleSetup s =
            setupTriangle({points[0], points[1], points[2]}, RasterRules::hw2());
        QCOMPARE(scanRow(s, RasterRules::hw2(), 9, 8).xLeft, x);
    }

    void ddaCoversEachPixelOnce() {
        // Fans of unsnapped triangles under the DDA: a shared edge is walked from the same
        // top with the same dx/dy by both its triangles, so they split every row at the same
        // x and no pixel is covered twice; every pixel whose sample is clearly inside (by
        // 1e-9 pixel) is covered.
        const RasterRules rules = RasterRules::hw2();
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> jitter(0.0, 0.4);
        std::uniform_int_distribution<int> spokes(3, 12);
        std::uniform_real_distribution<double> radius(2.0, 300.0);
        std::uniform_real_distribution<double> centre(0.0, 63.0);
        for (int f = 0; f < 1000; ++f) {
            const int n = spokes(rng);
            std::vector<dvec2> points = {{centre(rng), centre(rng)}};
            for (int k = 0; k < n; ++k) {
                const double a = 6.283185307179586 * (double(k) + jitter(rng)) / n;
                const double r = radius(rng);
                points.push_back({points[0].x + r * std::cos(a), points[0].y + r * std::sin(a)});
            }
            std::vector<std::array<std::uint32_t, 3>> fan;
            for (int k = 1; k <= n; ++k)
                fan.push_back(
                    {0, static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(k % n + 1)});
            const ScanConversion scan = ScanConversionStage().run(
                {screenWith(64, 64, rules), screenTriangles(points, fan)});
            std::map<std::pair<int, int>, int> hits;
            for (std::size_t t = 0; t < fan.size(); ++t)
                for (const auto& px : pixelsOf(spansOf(scan, t))) ++hits[px];
            for (const auto& [px, count] : hits)
                if (count != 1)
                    QFAIL(qPrintable(QStringLiteral("fan %1: pixel (%2, %3) covered %4 times")
                                         .arg(f)
                                         .arg(px.first)
                                         .arg(px.second)
                                         .arg(count)));
            for (const auto& tri : fan) {
                const std::array<dvec2, 3> p = {points[tri[0]], points[tri[1]], points[tri[2]]};
                for (int y = 0; y < 64; ++y)
                    for (int x = 0; x < 64; ++x)
                        if (clearlyInside(p, dvec2(x, y)) && !hits.count({x, y}))
                            QFAIL(qPrintable(QStringLiteral("fan %1: pixel (%2, %3) missed")
                                                 .arg(f)
                                                 .arg(x)
                                                 .arg(y)));
            }
        }
    }

    void recordingProbeLogsTriangleAndSpans() {
        const Projection pr = screenTriangles({{0, 0}, {4, 0}, {0, 4}, {9, 9}, {8, 9}, {9, 8}},
                                              {{0, 1, 2}, {3, 4, 5}});
        auto probe = RecordingProbe::forTriangle(0);
        const ScanConversion traced = ScanConversionStage().run({screen(10, 10), pr}, probe);
        const ScanConversion plain = ScanConversionStage().run({screen(10, 10), pr});
        QCOMPARE(traced.spans, plain.spans);
        QCOMPARE(probe.events().size(), std::size_t(1 + 5));
        QVERIFY(std::holds_alternative<TriangleEvent>(probe.events()[0]));
        const auto& span = std::get<SpanEvent>(probe.events()[2]);
        QCOMPARE(span.span, (Span{1, 0, 4}));
        RL_COMPARE_NEAR(span.xLeft, 0.0, 0.0);
        RL_COMPARE_NEAR(span.xRight, 3.0, 0.0);
    }
};

QTEST_GUILESS_MAIN(TestScanConversion)
#include "tst_scan_conversion.moc"
