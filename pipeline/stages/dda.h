// Seed 001's DDA (digital differential analyser), the scan conversion its lecture teaches and
// the hw2 rules use (RasterRules::Scan::Dda). Everything is in double, as the lecture writes
// it, with no snapping:
//  - the vertices are sorted by y; the long edge runs from the top vertex to the bottom one,
//    the two short edges meet at the middle vertex;
//  - an edge from (xTop, yTop) to (xBottom, yBottom) covers the rows ceil(yTop) <= y <
//    yBottom. Its increment is dx/dy = (xBottom - xTop) / (yBottom - yTop); on its first row
//    x = xTop + (ceil(yTop) - yTop) dx/dy, and from one row to the next x += dx/dy, the
//    rounding of every addition carried along;
//  - the long edge is walked in lock-step with the upper short edge, then with the lower one;
//  - in each row the pixels are x = ceil(x_left), x_left + 1, ... while x < x_right, the two
//    crossings taken in increasing order;
//  - every attribute is stepped the same way: down each edge by its own per-row increment,
//    then along the row from its value at x_left by (value_right - value_left) / (x_right -
//    x_left) a pixel. The DDA steps the fragment's depth and its screen weights (beta, gamma)
//    of the triangle's second and third vertices (DdaValues): every other attribute a (colour,
//    normal, texture coordinates, P') is a1 + beta (a2 - a1) + gamma (a3 - a1), so stepping
//    the weights steps it by its own increment, up to the last rounding.
// Pixels are sampled at integer coordinates. A row or a pixel whose sample lies exactly on an
// edge is drawn by one triangle only (the half-open ranges above), but only where the doubles
// put it: an edge that lands a hair below row 16 in double leaves row 16 to the triangle
// above, where the exact edge walk (scan_conversion.h) would see the edge through the row.
//
// Efficient screen clipping (seed 001): the first step on each edge goes not to ceil(yTop)
// but to the first such row on the screen, max(ceil(yTop), 0), by the same formula; rows and
// pixels stop at the screen's bottom and right.
#pragma once

#include <cstdint>

#include "pipeline/core/math.h"

namespace rl {

// The attributes the DDA steps besides x: a fragment's screen weights of the triangle's
// vertices 2 and 3 (vertex 1's is alpha = 1 - beta - gamma) and its depth (1/z where the
// depth test interpolates the reciprocal).
struct DdaValues {
    double beta = 0.0, gamma = 0.0, z = 0.0;

    DdaValues& operator+=(const DdaValues& d) {
        beta += d.beta;
        gamma += d.gamma;
        z += d.z;
        return *this;
    }
    friend DdaValues operator+(DdaValues a, const DdaValues& b) { return a += b; }
    friend DdaValues operator-(const DdaValues& a, const DdaValues& b) {
        return {a.beta - b.beta, a.gamma - b.gamma, a.z - b.z};
    }
    friend DdaValues operator*(double k, const DdaValues& a) {
        return {k * a.beta, k * a.gamma, k * a.z};
    }
    friend DdaValues operator/(const DdaValues& a, double k) {
        return {a.beta / k, a.gamma / k, a.z / k};
    }
};

// One edge of the DDA, on row y.
struct DdaEdge {
    std::int32_t y = 0;     // the row x belongs to
    std::int32_t yEnd = 0;  // the first row past the edge: ceil(yBottom)
    double x = 0.0;         // the edge's x on row y, accumulated
    double dxdy = 0.0;      // the increment per row (0 for a horizontal edge)
    DdaValues values;       // the attributes on row y, accumulated
    DdaValues perRow;       // their increments per row

    bool done() const { return y >= yEnd; }
    void nextRow() {
        x += dxdy;
        values += perRow;
        ++y;
    }
};

// The edge from top to bottom (top.y <= bottom.y), whose ends hold the attributes atTop and
// atBottom, on its first row on the screen. A horizontal edge covers no row (done() from the
// start).
DdaEdge ddaEdge(const dvec2& top, const dvec2& bottom, const DdaValues& atTop = {},
                const DdaValues& atBottom = {});
// The same edge stepped on to row y (at or after its first row), one addition of each
// increment a row: the very values the walk has accumulated there (the views show them).
DdaEdge ddaEdgeAtRow(const dvec2& top, const dvec2& bottom, std::int32_t y,
                     const DdaValues& atTop = {}, const DdaValues& atBottom = {});

// The pixels between two crossings xa and xb of a row, in either order: ceil(min) <= x <
// max, clipped to the screen's columns [0, width). Empty when begin >= end.
struct DdaPixels {
    std::int64_t begin = 0, end = 0;
};
DdaPixels ddaPixels(double xa, double xb, std::int64_t width);

// The attributes along a row between the crossings of edges a and b, from its first pixel
// xBegin on: at xBegin, value_left + (xBegin - x_left) * increment, then one addition of the
// increment a pixel (DdaSpan::next).
struct DdaSpan {
    DdaValues values;    // at the current pixel, accumulated
    DdaValues perPixel;  // the increment from one pixel to the next

    DdaValues next() {
        const DdaValues here = values;
        values += perPixel;
        return here;
    }
};
DdaSpan ddaSpan(const DdaEdge& a, const DdaEdge& b, std::int64_t xBegin);

}  // namespace rl
