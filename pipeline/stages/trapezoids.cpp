#include "trapezoids.h"

#include <tuple>
#include <utility>

namespace rl {

TrapezoidPoint lerp(double t, const TrapezoidPoint& a, const TrapezoidPoint& b) {
    TrapezoidPoint out;
    out.p = a.p + t * (b.p - a.p);
    out.pz = a.pz + t * (b.pz - a.pz);
    out.colour = a.colour + static_cast<float>(t) * (b.colour - a.colour);
    return out;
}

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
    out.split.p = {s.longEdge.xAt(middle.p.y), middle.p.y};

    // The rows as the edge walk divides them: the upper edge bounds the rows up to
    // lastUpperRow (every row when the bottom is flat), the lower edge the rest.
    const std::int32_t upperLast = lastUpperRow(s, rules);
    // The long edge is on the left when the middle vertex lies right of it.
    const auto sides = [&](const TrapezoidPoint& onLong, const TrapezoidPoint& onShort) {
        return s.longEdgeOnLeft ? std::pair{onLong, onShort} : std::pair{onShort, onLong};
    };
    const auto part = [&](bool upper) {
        Trapezoid t;
        t.upper = upper;
        if (upper) {
            t.tl = t.tr = top;
            std::tie(t.bl, t.br) = sides(out.split, middle);
        } else {
            std::tie(t.tl, t.tr) = sides(out.split, middle);
            t.bl = t.br = bottom;
        }
        t.firstRow = upper ? s.yFirst : upperLast + 1;
        t.lastRow = upper ? upperLast : s.yLast;
        out.parts.push_back(t);
    };
    if (middle.p.y > top.p.y) part(true);
    if (bottom.p.y > middle.p.y) part(false);
    return out;
}

TrapezoidRow trapezoidRow(const TriangleSetup& s, const Trapezoid& trapezoid,
                          const RasterRules& rules, std::int32_t j, std::int32_t width) {
    TrapezoidRow row;
    row.j = j;
    const double y = j + rules.sampleOffset;
    row.tj = (y - trapezoid.tl.p.y) / (trapezoid.bl.p.y - trapezoid.tl.p.y);
    row.left = lerp(row.tj, trapezoid.tl, trapezoid.bl);
    row.right = lerp(row.tj, trapezoid.tr, trapezoid.br);
    // The sides lie on the long edge and the short edge of the trapezoid's half.
    const ScanEdge& shortEdge = trapezoid.upper ? s.upperEdge : s.lowerEdge;
    row.left.p = {(s.longEdgeOnLeft ? s.longEdge : shortEdge).xAt(y), y};
    row.right.p = {(s.longEdgeOnLeft ? shortEdge : s.longEdge).xAt(y), y};
    // The pixels the edge walk fills on this row (the fill rule, cut to the screen).
    const ScanRow scan = scanRow(s, rules, j, width);
    row.xBegin = scan.xBegin;
    row.xEnd = scan.xEnd;
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
