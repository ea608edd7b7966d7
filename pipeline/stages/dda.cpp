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

DdaEdge ddaEdge(const dvec2& top, const dvec2& bottom) {
    DdaEdge e;
    e.yEnd = static_cast<std::int32_t>(index(std::ceil(bottom.y)));
    const double first = std::max(std::ceil(top.y), 0.0);  // on the screen
    e.y = static_cast<std::int32_t>(index(first));
    if (!(top.y < bottom.y)) {  // horizontal: no row
        e.y = e.yEnd;
        e.x = top.x;
        return e;
    }
    e.dxdy = (bottom.x - top.x) / (bottom.y - top.y);
    e.x = top.x + (first - top.y) * e.dxdy;
    return e;
}

DdaEdge ddaEdgeAtRow(const dvec2& top, const dvec2& bottom, std::int32_t y) {
    DdaEdge e = ddaEdge(top, bottom);
    while (e.y < y) e.nextRow();
    return e;
}

DdaPixels ddaPixels(double xa, double xb, std::int64_t width) {
    const double left = std::min(xa, xb), right = std::max(xa, xb);
    return {std::max<std::int64_t>(index(std::ceil(left)), 0),
            std::min<std::int64_t>(index(std::ceil(right)), width)};
}

}  // namespace rl
