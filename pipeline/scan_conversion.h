// Stage 5, scan conversion: each screen triangle becomes a list of spans, one per
// scanline, by edge walking with coherence. The vertices are sorted by y; the long edge
// runs from the top vertex to the bottom one, the two short edges meet at the middle
// vertex. Walking down the scanlines, the x of each edge changes by its constant dx/dy
// from one scanline to the next, and the span between the two edges is filled.
//
// The walk is exact: the snapped vertices are integers, so each edge's x on a scanline is
// xTop + q + r/dy with an integer quotient q and remainder 0 <= r < dy, both stepped by
// constants per scanline (Bresenham's idea). No rounding error can open a crack between
// two triangles or drop a pixel at a shared vertex.
//
// Rules (seed 000 as written): pixel (x, y) is sampled at the integer point (x, y), where
// the truncated vertices lie; a sample exactly on an edge belongs to the triangle, so shared
// edges are covered by both triangles (no cracks, some pixels twice). Scanlines and spans
// are clipped to the screen before walking, so a triangle a thousand times the screen
// costs no more than the pixels it covers. Triangles of zero area on screen have no
// interior and are counted, not scanned.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "math.h"
#include "projection.h"
#include "scene.h"

namespace rl {

// Pixels xBegin <= x < xEnd on row y.
struct Span {
    std::int32_t y = 0;
    std::int32_t xBegin = 0;
    std::int32_t xEnd = 0;
    bool operator==(const Span&) const = default;
};

// An edge as the scanline walk sees it: from its top end to its bottom end, in pixels.
struct ScanEdge {
    std::int64_t xTop = 0, yTop = 0;
    std::int64_t xBottom = 0, yBottom = 0;
    double dxdy = 0.0;  // change of x from one scanline to the next (for display)

    // The x where the edge crosses row y, exactly: xTop + (y - yTop) dx / dy.
    double xAt(std::int64_t y) const;
};

// The edge table of one triangle.
struct TriangleSetup {
    std::array<dvec2, 3> sorted{};            // vertices sorted by y, top first
    std::array<int, 3> order{};               // sorted[k] is the triangle's vertex order[k]
    std::int64_t doubleArea = 0;              // (s1 - s0) x (s2 - s0) of the sorted vertices
    ScanEdge longEdge, upperEdge, lowerEdge;  // top-bottom, top-middle, middle-bottom
    bool longEdgeOnLeft = false;              // the middle vertex lies right of the long edge
    std::int32_t yFirst = 0, yLast = -1;      // sampled rows, before screen clipping
    bool degenerate() const { return doubleArea == 0; }
};

// Screen vertices are integers (snapped) within the guard band of projection.h.
TriangleSetup setupTriangle(const std::array<dvec2, 3>& pScreen);

struct ScanConversion {
    std::vector<std::uint32_t> spanStart;  // spans of triangle t: [spanStart[t], spanStart[t+1])
    std::vector<Span> spans;
    std::size_t degenerate = 0;  // zero area on screen: not scanned
    std::size_t offscreen = 0;   // no sampled pixel on the screen
    std::size_t pixels = 0;      // covered samples, all triangles together

    std::size_t triangleCount() const { return spanStart.empty() ? 0 : spanStart.size() - 1; }
};

// The recording probe's view of scan conversion (see probe.h).
struct NullProbe;

class ScanConversionStage {
public:
    template <typename Probe>
    ScanConversion run(const Scene& scene, const Projection& projection, Probe& probe) const;
    ScanConversion run(const Scene& scene, const Projection& projection) const;
};

// The three screen vertices of a screen triangle.
inline std::array<dvec2, 3> screenVertices(const Projection& projection, const ScreenTriangle& t) {
    const auto& p = projection.draws[t.draw].pScreen;
    return {p[t.v[0]], p[t.v[1]], p[t.v[2]]};
}

}  // namespace rl
