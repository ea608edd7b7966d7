#include "dda.h"

#include <algorithm>
#include <cmath>

namespace rl {

namespace {

// A row or a column index from a coordinate within the guard band (+-2^28 pixels).
std::int64_t index(double v) {
    return static_cast<std::int64_t>(std::clamp(v, -double(1 << 30), double(1 << 30)));
}

}  // namespace

DdaEdge ddaEdge(const dvec2& top, const dvec2& bottom, const DdaValues& atTop,
                const DdaValues& atBottom) {
    DdaEdge e;
    e.yEnd = static_cast<std::int32_t>(index(std::ceil(bottom.y)));
    const double first = std::max(std::ceil(top.y), 0.0);  // on the screen
    e.y = static_cast<std::int32_t>(index(first));
    if (!(top.y < bottom.y)) {  // horizontal: no row
        e.y = e.yEnd;
        e.x = top.x;
        e.values = atTop;
        return e;
    }
    const double dy = bottom.y - top.y;
    e.dxdy = (bottom.x - top.x) / dy;
    e.x = top.x + (first - top.y) * e.dxdy;
    e.perRow = (atBottom - atTop) / dy;
    e.values = atTop + (first - top.y) * e.perRow;
    return e;
}

DdaEdge ddaEdgeAtRow(const dvec2& top, const dvec2& bottom, std::int32_t y, const DdaValues& atTop,
                     const DdaValues& atBottom) {
    DdaEdge e = ddaEdge(top, bottom, atTop, atBottom);
    while (e.y < y) e.nextRow();
    return e;
}

DdaPixels ddaPixels(double xa, double xb, std::int64_t width) {
    const double left = std::min(xa, xb), right = std::max(xa, xb);
    return {std::max<std::int64_t>(index(std::ceil(left)), 0),
            std::min<std::int64_t>(index(std::ceil(right)), width)};
}

DdaSpan ddaSpan(const DdaEdge& a, const DdaEdge& b, std::int64_t xBegin) {
    const DdaEdge& left = a.x <= b.x ? a : b;
    const DdaEdge& right = a.x <= b.x ? b : a;
    DdaSpan s;
    const double dx = right.x - left.x;
    if (dx > 0.0) s.perPixel = (right.values - left.values) / dx;
    s.values = left.values + (double(xBegin) - left.x) * s.perPixel;
    return s;
}

}  // namespace rl
