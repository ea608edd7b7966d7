#include "trapezoids.h"

#include <algorithm>
#include <cmath>

namespace rl {

TrapezoidPoint lerp(double t, const TrapezoidPoint& a, const TrapezoidPoint& b) {
    TrapezoidPoint out;
    out.p = a.p + t * (b.p - a.p);
    out.pz = a.pz + t * (b.pz - a.pz);
    out.colour = a.colour + static_cast<float>(t) * (b.colour - a.colour);
    return out;
}

namespace {

// The x where the line through an edge's ends crosses the line y (see trapezoids.h).
double xOnEdge(const std::array<dvec2, 2>& edge, double y) {
    const dvec2& top = edge[0];
    const dvec2& bottom = edge[1];
    if (bottom.y == top.y) return top.x;
    return top.x + (y - top.y) * (bottom.x - top.x) / (bottom.y - top.y);
}

std::int32_t toRow(double v) {
    return static_cast<std::int32_t>(std::clamp(v, -double(1 << 30), double(1 << 30)));
}

}  // namespace

TrapezoidSplit splitIntoTrapezoids(const TriangleSetup& s,
                                   const std::array<TrapezoidPoint, 3>& values,
                                   const RasterRules& rules) {
    TrapezoidSplit out;
    for (std::size_t k = 0; k < 3; ++k) {
        out.sorted[k] = values[static_cast<std::size_t>(s.order[k])];
        out.sorted[k].p = s.sorted[k];  // the snapped position the scan uses
    }
    const TrapezoidPoint& top = out.sorted[0];
    const TrapezoidPoint& middle = out.sorted[1];
    const TrapezoidPoint& bottom = out.sorted[2];
    if (s.degenerate()) return out;
    out.s = (middle.p.y - top.p.y) / (bottom.p.y - top.p.y);
    out.split = lerp(out.s, top, bottom);
    out.split.p = {xOnEdge({top.p, bottom.p}, middle.p.y), middle.p.y};

    const bool topLeft = rules.fill == RasterRules::FillRule::TopLeft;
    const double offset = rules.sampleOffset;
    // The first row sampled at or below y, and the last row sampled above y.
    const auto firstAtOrBelow = [&](double y) { return toRow(std::ceil(y - offset)); };
    const auto lastAbove = [&](double y) { return firstAtOrBelow(y) - 1; };
    // The last row of a triangle whose bottom vertex is at y: the inclusive rule keeps a row
    // exactly on it, the top-left rule does not.
    const auto lastRow = [&](double y) {
        return topLeft ? lastAbove(y) : toRow(std::floor(y - offset));
    };
    // The long edge is on the left when the middle vertex lies right of it.
    const auto sides = [&](const TrapezoidPoint& onLong, const TrapezoidPoint& onShort) {
        return s.longEdgeOnLeft ? std::pair{onLong, onShort} : std::pair{onShort, onLong};
    };
    const std::array<dvec2, 2> longEdge{top.p, bottom.p};
    const bool hasUpper = middle.p.y > top.p.y;
    const bool hasLower = bottom.p.y > middle.p.y;
    if (hasUpper) {
        Trapezoid t;
        t.upper = true;
        t.tl = t.tr = top;
        std::tie(t.bl, t.br) = sides(out.split, middle);
        const std::array<dvec2, 2> shortEdge{top.p, middle.p};
        t.leftEdge = s.longEdgeOnLeft ? longEdge : shortEdge;
        t.rightEdge = s.longEdgeOnLeft ? shortEdge : longEdge;
        t.firstRow = firstAtOrBelow(top.p.y);
        t.lastRow = hasLower ? lastAbove(middle.p.y) : lastRow(middle.p.y);
        out.parts.push_back(t);
    }
    if (hasLower) {
        Trapezoid t;
        t.upper = false;
        std::tie(t.tl, t.tr) = sides(out.split, middle);
        t.bl = t.br = bottom;
        const std::array<dvec2, 2> shortEdge{middle.p, bottom.p};
        t.leftEdge = s.longEdgeOnLeft ? longEdge : shortEdge;
        t.rightEdge = s.longEdgeOnLeft ? shortEdge : longEdge;
        t.firstRow = firstAtOrBelow(middle.p.y);
        t.lastRow = lastRow(bottom.p.y);
        out.parts.push_back(t);
    }
    return out;
}

TrapezoidRow trapezoidRow(const Trapezoid& trapezoid, const RasterRules& rules, std::int32_t j,
                          std::int32_t width) {
    TrapezoidRow row;
    row.j = j;
    const double y = j + rules.sampleOffset;
    row.tj = (y - trapezoid.tl.p.y) / (trapezoid.bl.p.y - trapezoid.tl.p.y);
    row.left = lerp(row.tj, trapezoid.tl, trapezoid.bl);
    row.right = lerp(row.tj, trapezoid.tr, trapezoid.br);
    row.left.p = {xOnEdge(trapezoid.leftEdge, y), y};
    row.right.p = {xOnEdge(trapezoid.rightEdge, y), y};
    // Samples L_i <= i + offset <= R_i (inclusive) or L_i <= i + offset < R_i (top-left).
    const double first = std::ceil(row.left.p.x - rules.sampleOffset);
    const double end = rules.fill == RasterRules::FillRule::TopLeft
                           ? std::ceil(row.right.p.x - rules.sampleOffset)
                           : std::floor(row.right.p.x - rules.sampleOffset) + 1.0;
    const double w = width;
    row.xBegin = static_cast<std::int32_t>(std::clamp(first, 0.0, w));
    row.xEnd = static_cast<std::int32_t>(std::clamp(end, double(row.xBegin), w));
    return row;
}

TrapezoidPoint trapezoidPixel(const TrapezoidRow& row, const RasterRules& rules, std::int32_t i,
                              double* ti) {
    const double dx = row.right.p.x - row.left.p.x;
    const double t = dx != 0.0 ? (i + rules.sampleOffset - row.left.p.x) / dx : 0.0;
    if (ti) *ti = t;
    TrapezoidPoint out = lerp(t, row.left, row.right);
    out.p = {i + rules.sampleOffset, row.left.p.y};
    return out;
}

}  // namespace rl
