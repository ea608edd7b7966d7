// Stage 5, scan conversion: each screen triangle becomes a list of spans, one per
// scanline, by edge walking with coherence. The vertices are sorted by y; the long edge
// runs from the top vertex to the bottom one, the two short edges meet at the middle
// vertex. Walking down the scanlines, the x of each edge changes by its constant dx/dy
// from one scanline to the next, and the span between the two edges is filled.
//
// The walk is exact: the snapped vertices lie on a grid of 1/2^bits pixel (bits = 0 for the
// course: integers), so each edge's x on a scanline is a whole number of grid steps plus a
// remainder r/D, and both are stepped by constants per scanline (Bresenham's idea). No
// rounding error can open a crack between two triangles or drop a pixel at a shared vertex.
// The course and gpu rules walk this way. The hw2 rules (RasterRules::Scan::Dda) walk as
// seed 001's lecture does instead, in double on unsnapped vertices (dda.h): the same rows
// and spans but where the doubles' rounding decides a tie.
//
// Rules (RasterRules): pixel (x, y) is sampled at (x + offset, y + offset). Under the
// course's inclusive rule a sample exactly on an edge belongs to the triangle, so shared
// edges are covered by both triangles (no cracks, some pixels twice); under the top-left
// rule (rows top <= y < bottom, pixels left <= x < right, as seed 001's DDA has them) it
// belongs to exactly one. Scanlines and spans are clipped to the screen before walking,
// so a triangle a thousand times the screen costs no more than the pixels it covers.
// Triangles of zero area on screen have no interior and are counted, not scanned.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "pipeline/core/math.h"
#include "pipeline/scene/scene.h"
#include "pipeline/stages/dda.h"
#include "pipeline/stages/projection.h"

namespace rl {

// Pixels xBegin <= x < xEnd on row y.
struct Span {
    std::int32_t y = 0;
    std::int32_t xBegin = 0;
    std::int32_t xEnd = 0;
    bool operator==(const Span&) const = default;
};

// An edge as the scanline walk sees it: from its top end to its bottom end, in grid units
// (1/2^bits of a pixel).
struct ScanEdge {
    std::int64_t xTop = 0, yTop = 0;
    std::int64_t xBottom = 0, yBottom = 0;
    int bits = 0;

    // The change of x from one scanline to the next (for display; 0 when horizontal).
    double dxdy() const {
        const std::int64_t dy = yBottom - yTop;
        return dy > 0 ? double(xBottom - xTop) / double(dy) : 0.0;
    }

    // The x in pixels where the edge crosses the line y (in pixels).
    double xAt(double y) const;
};

// The edge table of one triangle.
struct TriangleSetup {
    std::array<dvec2, 3> sorted{};  // vertices sorted by y, top first (pixels)
    std::array<int, 3> order{};     // sorted[k] is the triangle's vertex order[k]
    int orientation = 0;            // the exact sign of (s1 - s0) x (s2 - s0): -1, 0 or +1
    ScanEdge longEdge, upperEdge, lowerEdge;  // top-bottom, top-middle, middle-bottom
    bool longEdgeOnLeft = false;              // the middle vertex lies right of the long edge
    std::int32_t yFirst = 0, yLast = -1;      // sampled rows, before screen clipping
    bool degenerate() const { return orientation == 0; }
    // (s1 - s0) x (s2 - s0), pixels^2 (for display; exact but for the last rounding).
    double doubleArea() const;
};

// Screen vertices lie on the rules' sub-pixel grid within the guard band of projection.h.
TriangleSetup setupTriangle(const std::array<dvec2, 3>& pScreen, const RasterRules& rules);

// One row of a triangle's edge walk: where the row's sampled line crosses the two edges that
// bound it, and the pixels between them on the screen. The walk's arithmetic is exact, so
// the numbers of row y worked out directly are the very ones the walk reaches row by row.
struct ScanRow {
    std::int32_t y = 0;
    double xLeft = 0.0, xRight = 0.0;   // the exact crossings (pixels)
    std::int32_t xBegin = 0, xEnd = 0;  // its pixels [xBegin, xEnd), clipped to the screen
    bool upperPart = true;              // bounded by the upper edge (else by the lower)
    bool empty() const { return xBegin >= xEnd; }
};

// The last row the walk follows the upper edge on (yLast when the bottom is flat), before
// screen clipping; the lower edge bounds the rows after it.
std::int32_t lastUpperRow(const TriangleSetup& s, const RasterRules& rules);
// Row y, yFirst <= y <= yLast, of a triangle that is not degenerate, on a screen `width`
// pixels wide.
ScanRow scanRow(const TriangleSetup& s, const RasterRules& rules, std::int32_t y,
                std::int32_t width);
// Where an edge that is not horizontal crosses the sampled line of row y, exactly as the
// walk has it (pixels).
double edgeCrossing(const ScanEdge& e, const RasterRules& rules, std::int32_t y);

// Whether depth is interpolated as 1/z rather than z: view z under perspective-correct rules
// (1/z is linear on the screen; NDC z already is). The DDA steps it, the depth test reads it.
bool perspectiveDepth(const Scene& scene);
// The attributes the DDA steps (dda.h) at the vertices of screen triangle t whose set-up is
// s, in s's sorted order: the weights (0, 0), (1, 0), (0, 1) and each vertex's depth.
std::array<DdaValues, 3> ddaVertexValues(const Scene& scene, const Projection& projection,
                                         std::size_t t, const TriangleSetup& s);
// Row y of a triangle the DDA walks (its set-up s, the attributes v at s's sorted vertices):
// the long edge and the short edge that bounds the row, each stepped from its first row on
// the screen to y, as the walk has them there.
struct DdaRowEdges {
    DdaEdge longEdge, shortEdge;
};
DdaRowEdges ddaEdgesAtRow(const TriangleSetup& s, const std::array<DdaValues, 3>& v,
                          std::int32_t y);
// The attributes of the span that starts at pixel xBegin on row y of screen triangle t,
// stepped as the DDA's walk steps them (the same bits: the views and the stage check show
// them).
DdaSpan ddaSpanAt(const Scene& scene, const Projection& projection, std::size_t t, std::int32_t y,
                  std::int32_t xBegin);

struct ScanConversion {
    std::vector<std::uint32_t> spanStart;  // spans of triangle t: [spanStart[t], spanStart[t+1])
    std::vector<Span> spans;
    // Under the DDA (RasterRules::Scan::Dda) only: span k's attributes at its first pixel and
    // their increment a pixel, as the walk stepped them (dda.h); empty otherwise.
    std::vector<DdaSpan> ddaSpans;
    std::size_t degenerate = 0;  // zero area on screen: not scanned
    std::size_t offscreen = 0;   // no sampled pixel on the screen
    std::size_t pixels = 0;      // covered samples, all triangles together

    std::size_t triangleCount() const { return spanStart.empty() ? 0 : spanStart.size() - 1; }
};

struct ScanConversionInput {
    const Scene& scene;
    const Projection& projection;
};

class ScanConversionStage {
public:
    // Every screen triangle in order, into its spans. A probe (probe.h) hears of each
    // triangle's set-up, each span and each row walked.
    ScanConversion run(const ScanConversionInput& in) const;
    template <typename Probe>
    ScanConversion run(const ScanConversionInput& in, Probe& probe) const;
};

// Scan converts triangles [first, end) of the projection into out: spanStart gets one entry
// per triangle (the index of its first span in out.spans), spans, pixels and the counts
// theirs. The stage runs it on every triangle; the fast path (scan_conversion_fast.h) on
// ranges of them at once.
template <typename Probe>
void scanTriangles(const ScanConversionInput& in, std::size_t first, std::size_t end,
                   ScanConversion& out, Probe& probe);

// The three screen vertices of a screen triangle.
inline std::array<dvec2, 3> screenVertices(const Projection& projection, const ScreenTriangle& t) {
    const auto& p = projection.draws[t.draw].pScreen;
    return {p[t.v[0]], p[t.v[1]], p[t.v[2]]};
}

}  // namespace rl
