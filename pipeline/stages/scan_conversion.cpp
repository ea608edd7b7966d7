#include "scan_conversion.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "pipeline/stages/dda.h"
#include "pipeline/stages/probe.h"

namespace rl {

namespace {

// 128-bit integers for the products of grid coordinates (up to 2^45 each).
__extension__ using Int128 = __int128;

// Floor of a / b for b > 0.
template <typename T>
T floorDiv(T a, T b) {
    const T q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

// Snapped coordinates are exact multiples of 1/2^bits: the product is exact, and the
// conversion to an integer only drops a zero fraction.
std::int64_t toGrid(double pixels, int bits) {
    return static_cast<std::int64_t>(pixels * double(std::int64_t(1) << bits));
}

ScanEdge makeEdge(const dvec2& top, const dvec2& bottom, int bits) {
    const std::int64_t xTop = toGrid(top.x, bits), yTop = toGrid(top.y, bits);
    const std::int64_t xBottom = toGrid(bottom.x, bits), yBottom = toGrid(bottom.y, bits);
    // Every member given: nothing is zeroed first only to be written again.
    return ScanEdge{
        .xTop = xTop, .yTop = yTop, .xBottom = xBottom, .yBottom = yBottom, .bits = bits};
}

// The sampling grid: pixel index p is sampled at p * grid + offset (grid units), grid =
// 2^bits.
struct Grid {
    int bits = 0;
    std::int64_t offset = 0;
    bool topLeft = false;
    // The first pixel index whose sample is at or after v (grid units), and at or before it:
    // a ceiling and a floor division by 2^bits, as arithmetic shifts (C++20 defines >> of a
    // negative number as one).
    std::int64_t firstAtOrAfter(std::int64_t v) const { return -((offset - v) >> bits); }
    std::int64_t lastAtOrBefore(std::int64_t v) const { return (v - offset) >> bits; }
    std::int64_t grid() const { return std::int64_t(1) << bits; }
    std::int64_t sample(std::int64_t p) const { return p * grid() + offset; }
};

// Walks one edge down the scanlines. On a row sampled at ys, the edge's x gives
// (x - offset) / grid = q + r / D exactly, with D = grid * dy and 0 <= r < D; moving to the
// next row adds grid * dx / D = step + stepRemainder / D: integers only.
class EdgeWalker {
public:
    EdgeWalker(const ScanEdge& e, const Grid& g, std::int64_t firstRow) {
        const std::int64_t dy = e.yBottom - e.yTop;
        const std::int64_t dx = e.xBottom - e.xTop;
        m_d = g.grid() * dy;
        const std::int64_t dxFloor = floorDiv(dx, dy);
        m_step = dxFloor;
        m_stepRemainder = g.grid() * (dx - dxFloor * dy);
        const std::int64_t a = e.xTop - g.offset;
        const std::int64_t b = g.sample(firstRow) - e.yTop;
        constexpr std::int64_t kSmall = std::int64_t(1) << 30;
        if (a > -kSmall && a < kSmall && b > -kSmall && b < kSmall && dx > -kSmall && dx < kSmall &&
            dy < kSmall) {
            // The usual case: a dy + b dx fits in 62 bits, and 64-bit division is exact too.
            const std::int64_t v = a * dy + b * dx;
            m_q = floorDiv(v, m_d);
            m_r = v - m_q * m_d;
        } else {
            const Int128 v = Int128(a) * dy + Int128(b) * dx;
            const Int128 q = floorDiv<Int128>(v, m_d);
            m_q = static_cast<std::int64_t>(q);
            m_r = static_cast<std::int64_t>(v - q * m_d);
        }
        m_grid = g;
    }
    std::int64_t floorX() const { return m_q; }
    std::int64_t ceilX() const { return m_q + (m_r > 0 ? 1 : 0); }
    double exactX() const {  // pixels
        return (double(m_q) + double(m_r) / double(m_d)) +
               double(m_grid.offset) / double(m_grid.grid());
    }
    void nextRow() {
        m_q += m_step;
        m_r += m_stepRemainder;
        if (m_r >= m_d) {
            m_r -= m_d;
            ++m_q;
        }
    }

private:
    std::int64_t m_d = 1, m_step = 0, m_stepRemainder = 0, m_q = 0, m_r = 0;
    Grid m_grid;
};

std::int32_t toRow(std::int64_t v) {
    return static_cast<std::int32_t>(std::clamp<std::int64_t>(v, -(1ll << 30), 1ll << 30));
}

Grid gridOf(const RasterRules& rules) {
    Grid g;
    g.bits = rules.subpixelBits;
    g.offset = toGrid(rules.sampleOffset, rules.subpixelBits);
    g.topLeft = rules.fill == RasterRules::FillRule::TopLeft;
    return g;
}

// The pixels of a row between its two edges: the samples left <= x <= right (inclusive) or
// left <= x < right (top-left), clipped to the screen's columns [0, width). Empty when
// begin >= end.
struct RowPixels {
    std::int64_t begin = 0, end = 0;
};
RowPixels rowPixels(const EdgeWalker& left, const EdgeWalker& right, const Grid& g,
                    std::int64_t width) {
    return {std::max<std::int64_t>(left.ceilX(), 0),
            std::min<std::int64_t>(g.topLeft ? right.ceilX() : right.floorX() + 1, width)};
}

// The row's pixels as the stepper records them: [xBegin, xEnd) within [0, width], xBegin <=
// xEnd (an empty row keeps where its span would start).
std::pair<std::int32_t, std::int32_t> recordedPixels(const RowPixels& p, std::int64_t width) {
    const auto xBegin = static_cast<std::int32_t>(std::min(p.begin, width));
    return {xBegin, static_cast<std::int32_t>(std::clamp<std::int64_t>(p.end, xBegin, width))};
}

// Rows sampled above the middle vertex are bounded by the upper edge (every row when the
// bottom is flat), the others by the lower edge.
std::int32_t lastUpperRow(const TriangleSetup& s, const Grid& g) {
    const std::int64_t yMiddle = s.upperEdge.yBottom;
    if (s.lowerEdge.yBottom == yMiddle) return s.yLast;
    return std::min(s.yLast, toRow(g.firstAtOrAfter(yMiddle) - 1));
}

// The DDA's rows: the upper edge covers ceil(yTop) <= y < yMiddle, the lower edge the rest.
std::int32_t lastUpperDdaRow(const TriangleSetup& s) {
    return std::min(s.yLast, toRow(static_cast<std::int64_t>(std::ceil(s.sorted[1].y)) - 1));
}

// Row y of the DDA, the long edge and the short one stepped from their first rows on the
// screen: the very x the walk accumulates (views only; the walk steps once a row).
ScanRow ddaRow(const TriangleSetup& s, std::int32_t y, std::int32_t width) {
    ScanRow row;
    row.y = y;
    row.upperPart = y <= lastUpperDdaRow(s);
    const auto [longEdge, shortEdge] = ddaEdgesAtRow(s, {}, y);
    row.xLeft = std::min(longEdge.x, shortEdge.x);
    row.xRight = std::max(longEdge.x, shortEdge.x);
    const DdaPixels p = ddaPixels(longEdge.x, shortEdge.x, width);
    std::tie(row.xBegin, row.xEnd) = recordedPixels({p.begin, p.end}, width);
    return row;
}

}  // namespace

std::int32_t lastUpperRow(const TriangleSetup& s, const RasterRules& rules) {
    if (rules.scan == RasterRules::Scan::Dda) return lastUpperDdaRow(s);
    return lastUpperRow(s, gridOf(rules));
}

ScanRow scanRow(const TriangleSetup& s, const RasterRules& rules, std::int32_t y,
                std::int32_t width) {
    if (rules.scan == RasterRules::Scan::Dda) return ddaRow(s, y, width);
    const Grid g = gridOf(rules);
    ScanRow row;
    row.y = y;
    row.upperPart = y <= lastUpperRow(s, g);
    const EdgeWalker longWalker(s.longEdge, g, y);
    const EdgeWalker shortWalker(row.upperPart ? s.upperEdge : s.lowerEdge, g, y);
    const EdgeWalker& left = s.longEdgeOnLeft ? longWalker : shortWalker;
    const EdgeWalker& right = s.longEdgeOnLeft ? shortWalker : longWalker;
    row.xLeft = left.exactX();
    row.xRight = right.exactX();
    std::tie(row.xBegin, row.xEnd) = recordedPixels(rowPixels(left, right, g, width), width);
    return row;
}

double edgeCrossing(const ScanEdge& e, const RasterRules& rules, std::int32_t y) {
    return EdgeWalker(e, gridOf(rules), y).exactX();
}

bool perspectiveDepth(const Scene& scene) {
    return scene.rules.interpolation == RasterRules::Interpolation::PerspectiveCorrect &&
           scene.conventions.depth == DepthSource::ViewZ;
}

std::array<DdaValues, 3> ddaVertexValues(const Scene& scene, const Projection& projection,
                                         std::size_t t, const TriangleSetup& s) {
    const ScreenTriangle& tri = projection.triangles[t];
    const auto& depth = projection.draws[tri.draw].depth;
    const bool reciprocal = perspectiveDepth(scene);
    const auto at = [&](int k) {
        const double z = depth[tri.v[static_cast<std::size_t>(k)]];
        return DdaValues{k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0, reciprocal ? 1.0 / z : z};
    };
    return {at(s.order[0]), at(s.order[1]), at(s.order[2])};
}

DdaRowEdges ddaEdgesAtRow(const TriangleSetup& s, const std::array<DdaValues, 3>& v,
                          std::int32_t y) {
    const auto& p = s.sorted;
    return {ddaEdgeAtRow(p[0], p[2], y, v[0], v[2]), y <= lastUpperDdaRow(s)
                                                         ? ddaEdgeAtRow(p[0], p[1], y, v[0], v[1])
                                                         : ddaEdgeAtRow(p[1], p[2], y, v[1], v[2])};
}

DdaSpan ddaSpanAt(const Scene& scene, const Projection& projection, std::size_t t, std::int32_t y,
                  std::int32_t xBegin) {
    const TriangleSetup s =
        setupTriangle(screenVertices(projection, projection.triangles[t]), scene.rules);
    const DdaRowEdges e = ddaEdgesAtRow(s, ddaVertexValues(scene, projection, t, s), y);
    return ddaSpan(e.longEdge, e.shortEdge, xBegin);
}

double ScanEdge::xAt(double y) const {
    const double scale = std::ldexp(1.0, -bits);
    const std::int64_t dy = yBottom - yTop;
    if (dy <= 0) return double(xTop) * scale;
    return (double(xTop) + (y / scale - double(yTop)) * double(xBottom - xTop) / double(dy)) *
           scale;
}

namespace {

// (s1 - s0) x (s2 - s0) of the edges s0 s1 (upper) and s0 s2 (long), exactly: 128 bits hold
// the products of grid coordinates.
Int128 crossOf(const ScanEdge& upper, const ScanEdge& longEdge) {
    return Int128(upper.xBottom - upper.xTop) * (longEdge.yBottom - longEdge.yTop) -
           Int128(upper.yBottom - upper.yTop) * (longEdge.xBottom - longEdge.xTop);
}

// A triangle's orientation and the rows it samples, before screen clipping.
struct Rows {
    int orientation = 0;
    std::int32_t yFirst = 0, yLast = -1;
};

// The edge walk's: the exact sign of (s1 - s0) x (s2 - s0) on the grid; rows sampled top <=
// sample <= bottom (inclusive) or top <= sample < bottom (top-left).
Rows exactRows(const ScanEdge& upper, const ScanEdge& longEdge, const RasterRules& rules) {
    const Int128 area = crossOf(upper, longEdge);
    const Grid g = gridOf(rules);
    return {.orientation = area > 0 ? 1 : (area < 0 ? -1 : 0),
            .yFirst = toRow(g.firstAtOrAfter(longEdge.yTop)),
            .yLast = toRow(g.topLeft ? g.firstAtOrAfter(longEdge.yBottom) - 1
                                     : g.lastAtOrBefore(longEdge.yBottom))};
}

// The DDA's: the sign of (s1 - s0) x (s2 - s0) in double; rows ceil(yTop) <= y < yBottom.
Rows ddaRows(const std::array<dvec2, 3>& sorted) {
    const double area = screenArea(sorted[0], sorted[1], sorted[2]);
    return {.orientation = area > 0.0 ? 1 : (area < 0.0 ? -1 : 0),
            .yFirst = toRow(static_cast<std::int64_t>(std::ceil(sorted[0].y))),
            .yLast = toRow(static_cast<std::int64_t>(std::ceil(sorted[2].y)) - 1)};
}

}  // namespace

double TriangleSetup::doubleArea() const {
    const double scale = double(std::uint64_t(1) << (2 * longEdge.bits));
    return double(crossOf(upperEdge, longEdge)) / scale;  // exact scaling
}

TriangleSetup setupTriangle(const std::array<dvec2, 3>& p, const RasterRules& rules) {
    // Sort by y, top first; ties keep the triangle's vertex order (an insertion sort of
    // three, which is stable and needs no buffer).
    std::array<int, 3> order = {0, 1, 2};
    const auto above = [&](int a, int b) {
        return p[static_cast<std::size_t>(a)].y < p[static_cast<std::size_t>(b)].y;
    };
    if (above(order[1], order[0])) std::swap(order[0], order[1]);
    if (above(order[2], order[1])) {
        std::swap(order[1], order[2]);
        if (above(order[1], order[0])) std::swap(order[0], order[1]);
    }
    const std::array<dvec2, 3> sorted = {p[static_cast<std::size_t>(order[0])],
                                         p[static_cast<std::size_t>(order[1])],
                                         p[static_cast<std::size_t>(order[2])]};
    const int bits = rules.subpixelBits;
    const ScanEdge l = makeEdge(sorted[0], sorted[2], bits);
    const ScanEdge u = makeEdge(sorted[0], sorted[1], bits);
    const Rows rows =
        rules.scan == RasterRules::Scan::Dda ? ddaRows(sorted) : exactRows(u, l, rules);
    // Every member given, so that none is zeroed first only to be written again.
    return TriangleSetup{.sorted = sorted,
                         .order = order,
                         .orientation = rows.orientation,
                         .longEdge = l,
                         .upperEdge = u,
                         .lowerEdge = makeEdge(sorted[1], sorted[2], bits),
                         // The middle vertex is right of the long edge when the area is positive.
                         .longEdgeOnLeft = rows.orientation > 0,
                         .yFirst = rows.yFirst,
                         .yLast = rows.yLast};
}

namespace {

// Adds row y's span, if it has pixels, and tells the probe of the row with its crossings
// (crossings() gives x_left and x_right; worked out only for a probe that records).
template <typename Probe, typename Crossings>
void addRow(ScanConversion& out, Probe& probe, [[maybe_unused]] std::uint32_t triangle,
            std::int32_t y, const RowPixels& pixels, [[maybe_unused]] const Crossings& crossings,
            [[maybe_unused]] std::int64_t width) {
    if (pixels.begin < pixels.end) {
        const Span span{y, static_cast<std::int32_t>(pixels.begin),
                        static_cast<std::int32_t>(pixels.end)};
        out.spans.push_back(span);
        out.pixels += static_cast<std::size_t>(span.xEnd - span.xBegin);
        RL_PROBE_HOOK(([&] {
            const auto [xLeft, xRight] = crossings();
            probe.onSpan(triangle, span, xLeft, xRight);
        }()));
    }
    // Every row walked, empty ones included (the stepper's scanlines).
    RL_PROBE_HOOK(([&] {
        const auto [xLeft, xRight] = crossings();
        const auto [xBegin, xEnd] = recordedPixels(pixels, width);
        probe.onRow(triangle, y, xLeft, xRight, xBegin, xEnd);
    }()));
}

// Seed 001's DDA (dda.h) on rows [first, last] of the screen: the long edge in lock-step
// with the upper edge, then with the lower one, each x and the attributes v at the sorted
// vertices stepped by their increments; each span keeps its attributes for the depth test.
template <typename Probe>
void walkDda(const TriangleSetup& s, const std::array<DdaValues, 3>& v, std::int32_t first,
             std::int32_t last, std::int64_t width, std::uint32_t triangle, ScanConversion& out,
             Probe& probe) {
    DdaEdge longEdge = ddaEdge(s.sorted[0], s.sorted[2], v[0], v[2]);
    DdaEdge upper = ddaEdge(s.sorted[0], s.sorted[1], v[0], v[1]);
    DdaEdge lower = ddaEdge(s.sorted[1], s.sorted[2], v[1], v[2]);
    for (std::int32_t y = first; y <= last; ++y) {
        DdaEdge& shortEdge = upper.done() ? lower : upper;
        const DdaPixels p = ddaPixels(longEdge.x, shortEdge.x, width);
        if (p.begin < p.end) out.ddaSpans.push_back(ddaSpan(longEdge, shortEdge, p.begin));
        addRow(
            out, probe, triangle, y, {p.begin, p.end},
            [&] { return std::minmax(longEdge.x, shortEdge.x); }, width);
        longEdge.nextRow();
        shortEdge.nextRow();
    }
}

}  // namespace

template <typename Probe>
void scanTriangles(const ScanConversionInput& in, std::size_t firstTriangle,
                   std::size_t endTriangle, ScanConversion& out, Probe& probe) {
    const Scene& scene = in.scene;
    const Projection& projection = in.projection;
    const std::int64_t width = scene.width;
    const std::int32_t height = scene.height;
    const Grid g = gridOf(scene.rules);
    out.spanStart.reserve(endTriangle - firstTriangle + 1);

    for (std::size_t t = firstTriangle; t < endTriangle; ++t) {
        out.spanStart.push_back(static_cast<std::uint32_t>(out.spans.size()));
        [[maybe_unused]] const auto triangle = static_cast<std::uint32_t>(t);
        const TriangleSetup s =
            setupTriangle(screenVertices(projection, projection.triangles[t]), scene.rules);
        RL_PROBE_HOOK(probe.onTriangle(triangle, s));
        if (s.degenerate()) {
            ++out.degenerate;
            continue;
        }
        // Efficient screen clipping: walk only the scanlines on the screen.
        const std::int32_t rowBegin = std::max(s.yFirst, 0);
        const std::int32_t rowEnd = std::min(s.yLast, height - 1);
        if (rowBegin > rowEnd) {
            ++out.offscreen;
            continue;
        }
        const std::size_t spansBefore = out.spans.size();
        if (scene.rules.scan == RasterRules::Scan::Dda) {
            walkDda(s, ddaVertexValues(scene, projection, t, s), rowBegin, rowEnd, width, triangle,
                    out, probe);
            if (out.spans.size() == spansBefore) ++out.offscreen;
            continue;
        }

        // Fill rows [first, last] between the long edge and one short edge.
        EdgeWalker longWalker(s.longEdge, g, rowBegin);
        auto walk = [&](const ScanEdge& shortEdge, std::int32_t first, std::int32_t last) {
            EdgeWalker shortWalker(shortEdge, g, first);
            const EdgeWalker& left = s.longEdgeOnLeft ? longWalker : shortWalker;
            const EdgeWalker& right = s.longEdgeOnLeft ? shortWalker : longWalker;
            for (std::int32_t y = first; y <= last; ++y) {
                addRow(
                    out, probe, triangle, y, rowPixels(left, right, g, width),
                    [&] { return std::pair(left.exactX(), right.exactX()); }, width);
                longWalker.nextRow();
                shortWalker.nextRow();
            }
        };
        // Upper part: rows sampled above the middle vertex (all rows when the bottom is
        // flat); lower part: from the middle vertex's row down.
        const std::int32_t upperLast = std::min(rowEnd, lastUpperRow(s, g));
        if (rowBegin <= upperLast) walk(s.upperEdge, rowBegin, upperLast);
        const std::int32_t lowerFirst = std::max(rowBegin, upperLast + 1);
        if (lowerFirst <= rowEnd) walk(s.lowerEdge, lowerFirst, rowEnd);
        if (out.spans.size() == spansBefore) ++out.offscreen;
    }
}

template <typename Probe>
ScanConversion ScanConversionStage::run(const ScanConversionInput& in, Probe& probe) const {
    ScanConversion out;
    scanTriangles(in, 0, in.projection.triangles.size(), out, probe);
    out.spanStart.push_back(static_cast<std::uint32_t>(out.spans.size()));
    return out;
}

ScanConversion ScanConversionStage::run(const ScanConversionInput& in) const {
    NullProbe probe;
    return run(in, probe);
}

template ScanConversion ScanConversionStage::run<NullProbe>(const ScanConversionInput&,
                                                            NullProbe&) const;
template ScanConversion ScanConversionStage::run<RecordingProbe>(const ScanConversionInput&,
                                                                 RecordingProbe&) const;
template ScanConversion ScanConversionStage::run<ReplayProbe>(const ScanConversionInput&,
                                                              ReplayProbe&) const;
template void scanTriangles<NullProbe>(const ScanConversionInput&, std::size_t, std::size_t,
                                       ScanConversion&, NullProbe&);

}  // namespace rl
