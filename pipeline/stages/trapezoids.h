// Seed 002's presentation of scan conversion: each triangle is split at its middle
// vertex's row into two trapezoids (a flat-top or flat-bottom triangle is one trapezoid,
// two of whose corners are the same vertex). Each trapezoid has corners TL, TR, BL, BR,
// each a pixel position (i, j) carrying (r, g, b, pz), and is scanned row by row:
//   t_j = (j - TL_j) / (BL_j - TL_j),  L = lerp(t_j, TL, BL),  R = lerp(t_j, TR, BR),
//   for the pixels i from L_i to R_i: t_i = (i - L_i) / (R_i - L_i), (r, g, b, pz) =
//   lerp(t_i, L, R).
// It is the same scan as the edge walk of scan_conversion.h, row for row and pixel for
// pixel, because its rows and pixels are the walk's own (tst_clip_trapezoid checks it on
// real scenes under the course and the gpu rules):
// - a row is sampled at j + offset (the rules' sample offset; 0 for the course), so t_j
//   and t_i use j + offset and i + offset;
// - the rows are split where the walk changes from the upper to the lower edge
//   (lastUpperRow): the row through the middle vertex belongs to the lower trapezoid only,
//   so no row of a triangle is scanned twice; the last row of the lower one is included
//   under the inclusive rule and left out when it lies exactly on the bottom vertex under
//   the top-left rule;
// - the pixels of a row are the walk's (scanRow): i <= R_i or i < R_i by the rule, cut to
//   the screen;
// - L_i and R_i are worked out from the ends of the triangle's edge they lie on
//   (ScanEdge::xAt), x = x_top + (j - y_top)(x_bottom - x_top) / (y_bottom - y_top): the
//   same line as the lerp between the corners, written so that a crossing exactly on a
//   sample is exactly on it (the corners on the long edge at the split are rounded).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "pipeline/core/math.h"
#include "pipeline/scene/scene.h"
#include "pipeline/stages/scan_conversion.h"

namespace rl {

// A corner or an edge point: its position in pixels and the values it carries.
struct TrapezoidPoint {
    dvec2 p{0.0};
    double pz = 0.0;
    vec3 colour{0.0f};
};

TrapezoidPoint lerp(double t, const TrapezoidPoint& a, const TrapezoidPoint& b);

struct Trapezoid {
    bool upper = true;  // above the middle vertex's row (else below it)
    TrapezoidPoint tl, tr, bl, br;
    // The rows it covers, before cutting to the screen (none when firstRow > lastRow).
    std::int32_t firstRow = 0, lastRow = -1;
};

struct TrapezoidSplit {
    // The vertices sorted by y (top, middle, bottom) with their values, and the point of the
    // long edge on the middle vertex's row, M' = lerp(s, top, bottom).
    std::array<TrapezoidPoint, 3> sorted{};
    TrapezoidPoint split;
    double s = 0.0;
    std::vector<Trapezoid> parts;  // upper then lower; one when flat; none when degenerate
};

// The split of the triangle set up as s; values[k] are the values carried by the triangle's
// vertex k (in its own order, not sorted).
TrapezoidSplit splitIntoTrapezoids(const TriangleSetup& s,
                                   const std::array<TrapezoidPoint, 3>& values,
                                   const RasterRules& rules);

// Row j of a trapezoid (firstRow <= j <= lastRow) of the triangle set up as s, on a screen
// `width` pixels wide.
struct TrapezoidRow {
    std::int32_t j = 0;
    double tj = 0.0;
    TrapezoidPoint left, right;         // L and R (their x exactly on the edges)
    std::int32_t xBegin = 0, xEnd = 0;  // the pixels [xBegin, xEnd), cut to the screen
    bool empty() const { return xBegin >= xEnd; }
};
TrapezoidRow trapezoidRow(const TriangleSetup& s, const Trapezoid& trapezoid,
                          const RasterRules& rules, std::int32_t j, std::int32_t width);

// Pixel i of a row: t_i = (i + offset - L_i) / (R_i - L_i) and the values lerp(t_i, L, R).
TrapezoidPoint trapezoidPixel(const TrapezoidRow& row, const RasterRules& rules, std::int32_t i,
                              double* ti = nullptr);

}  // namespace rl
