#include "scan_conversion.h"

#include <algorithm>
#include <cmath>

#include "probe.h"

namespace rl {

namespace {

// Floor of a / b for b > 0, rounding toward minus infinity.
std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
    const std::int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

ScanEdge makeEdge(const dvec2& top, const dvec2& bottom) {
    ScanEdge e;
    e.xTop = static_cast<std::int64_t>(top.x);
    e.yTop = static_cast<std::int64_t>(top.y);
    e.xBottom = static_cast<std::int64_t>(bottom.x);
    e.yBottom = static_cast<std::int64_t>(bottom.y);
    const std::int64_t dy = e.yBottom - e.yTop;
    e.dxdy = dy > 0 ? double(e.xBottom - e.xTop) / double(dy) : 0.0;
    return e;
}

// Walks one edge down the scanlines: x on row y is xTop + q + r/dy, 0 <= r < dy.
// Moving to the next row adds dx/dy = step + stepRemainder/dy: integers only.
class EdgeWalker {
public:
    EdgeWalker(const ScanEdge& e, std::int64_t firstRow) : m_edge(e) {
        m_dy = e.yBottom - e.yTop;
        const std::int64_t dx = e.xBottom - e.xTop;
        m_step = floorDiv(dx, m_dy);
        m_stepRemainder = dx - m_step * m_dy;
        const std::int64_t n = (firstRow - e.yTop) * dx;  // |n| < 2^61 in the guard band
        m_q = floorDiv(n, m_dy);
        m_r = n - m_q * m_dy;
    }
    std::int64_t floorX() const { return m_edge.xTop + m_q; }
    std::int64_t ceilX() const { return m_edge.xTop + m_q + (m_r > 0 ? 1 : 0); }
    double exactX() const { return double(m_edge.xTop + m_q) + double(m_r) / double(m_dy); }
    void nextRow() {
        m_q += m_step;
        m_r += m_stepRemainder;
        if (m_r >= m_dy) {
            m_r -= m_dy;
            ++m_q;
        }
    }

private:
    const ScanEdge& m_edge;
    std::int64_t m_dy = 1, m_step = 0, m_stepRemainder = 0, m_q = 0, m_r = 0;
};

std::int32_t toRow(std::int64_t v) {
    return static_cast<std::int32_t>(std::clamp<std::int64_t>(v, -(1ll << 30), 1ll << 30));
}

}  // namespace

double ScanEdge::xAt(std::int64_t y) const {
    const std::int64_t dy = yBottom - yTop;
    if (dy <= 0) return double(xTop);
    return double(xTop) + double((y - yTop) * (xBottom - xTop)) / double(dy);
}

TriangleSetup setupTriangle(const std::array<dvec2, 3>& p) {
    TriangleSetup s;
    s.order = {0, 1, 2};
    // Sort by y, top first; ties keep the triangle's vertex order.
    std::stable_sort(s.order.begin(), s.order.end(), [&](int a, int b) {
        return p[static_cast<std::size_t>(a)].y < p[static_cast<std::size_t>(b)].y;
    });
    for (std::size_t k = 0; k < 3; ++k) s.sorted[k] = p[static_cast<std::size_t>(s.order[k])];
    s.longEdge = makeEdge(s.sorted[0], s.sorted[2]);
    s.upperEdge = makeEdge(s.sorted[0], s.sorted[1]);
    s.lowerEdge = makeEdge(s.sorted[1], s.sorted[2]);
    const ScanEdge& l = s.longEdge;
    const ScanEdge& u = s.upperEdge;
    // (s1 - s0) x (s2 - s0): exact in 64 bits inside the guard band (|coordinate| <= 2^29).
    s.doubleArea =
        (u.xBottom - u.xTop) * (l.yBottom - l.yTop) - (u.yBottom - u.yTop) * (l.xBottom - l.xTop);
    // The middle vertex is right of the long edge when the area is positive.
    s.longEdgeOnLeft = s.doubleArea > 0;
    // Inclusive rule: every row from the top vertex's to the bottom vertex's.
    s.yFirst = toRow(l.yTop);
    s.yLast = toRow(l.yBottom);
    return s;
}

template <typename Probe>
ScanConversion ScanConversionStage::run(const Scene& scene, const Projection& projection,
                                        Probe& probe) const {
    ScanConversion out;
    const std::int64_t width = scene.width;
    const std::int32_t height = scene.height;
    out.spanStart.reserve(projection.triangles.size() + 1);

    for (std::size_t t = 0; t < projection.triangles.size(); ++t) {
        out.spanStart.push_back(static_cast<std::uint32_t>(out.spans.size()));
        const auto triangle = static_cast<std::uint32_t>(t);
        const TriangleSetup s = setupTriangle(screenVertices(projection, projection.triangles[t]));
        if constexpr (Probe::enabled) probe.onTriangle(triangle, s);
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

        // Fill rows [first, last] between the long edge and one short edge.
        EdgeWalker longWalker(s.longEdge, rowBegin);
        auto walk = [&](const ScanEdge& shortEdge, std::int32_t first, std::int32_t last) {
            EdgeWalker shortWalker(shortEdge, first);
            const EdgeWalker& left = s.longEdgeOnLeft ? longWalker : shortWalker;
            const EdgeWalker& right = s.longEdgeOnLeft ? shortWalker : longWalker;
            for (std::int32_t y = first; y <= last; ++y) {
                // Inclusive rule: pixels ceil(xLeft) .. floor(xRight), clipped to the screen.
                const std::int64_t begin = std::max<std::int64_t>(left.ceilX(), 0);
                const std::int64_t end = std::min<std::int64_t>(right.floorX() + 1, width);
                if (begin < end) {
                    const Span span{y, static_cast<std::int32_t>(begin),
                                    static_cast<std::int32_t>(end)};
                    out.spans.push_back(span);
                    out.pixels += static_cast<std::size_t>(span.xEnd - span.xBegin);
                    if constexpr (Probe::enabled)
                        probe.onSpan(triangle, span, left.exactX(), right.exactX());
                }
                longWalker.nextRow();
                shortWalker.nextRow();
            }
        };
        // Upper part: rows above the middle vertex (all rows when the bottom is flat);
        // lower part: from the middle vertex's row down.
        const std::int64_t yMiddle = s.upperEdge.yBottom;
        const bool flatBottom = s.lowerEdge.yBottom == yMiddle;
        const std::int32_t upperLast =
            flatBottom ? rowEnd : std::min<std::int32_t>(rowEnd, toRow(yMiddle - 1));
        if (rowBegin <= upperLast) walk(s.upperEdge, rowBegin, upperLast);
        if (!flatBottom) {
            const std::int32_t lowerFirst = std::max(rowBegin, upperLast + 1);
            if (lowerFirst <= rowEnd) walk(s.lowerEdge, lowerFirst, rowEnd);
        }
        if (out.spans.size() == spansBefore) ++out.offscreen;
    }
    out.spanStart.push_back(static_cast<std::uint32_t>(out.spans.size()));
    return out;
}

ScanConversion ScanConversionStage::run(const Scene& scene, const Projection& projection) const {
    NullProbe probe;
    return run(scene, projection, probe);
}

template ScanConversion ScanConversionStage::run<NullProbe>(const Scene&, const Projection&,
                                                            NullProbe&) const;
template ScanConversion ScanConversionStage::run<RecordingProbe>(const Scene&, const Projection&,
                                                                 RecordingProbe&) const;

}  // namespace rl
