// Stage 6, depth test (z-buffer). For every pixel of every span, the screen barycentrics
// (alpha, beta, gamma) of its sample with respect to the triangle's screen vertices give
// the fragment's depth, z = alpha z1 + beta z2 + gamma z3: for the course the z of
// P' = alpha P1 + beta P2 + gamma P3 in view coordinates (seed 000), for command files the
// NDC z (seed 001). Under the hw2 rules' DDA the weights and z are those scan conversion
// stepped to the pixel, one addition at a time (dda.h). Under perspective-correct rules
// (RasterRules::gpu, hw2) view z is found as 1 / (alpha / z1 + beta / z2 + gamma / z3), the
// depth of the point on the triangle. The buffer starts at the convention's clear value
// (+infinity, or 1) and the nearer fragment wins: z < stored writes; on a tie the earlier
// triangle stays, unless the convention says z <= stored (seed 001). Seed 001 also discards
// fragments whose z is outside [0, 1] (per-pixel clipping). Under the painter's algorithm
// (paintersAlgorithm(scene)) there is no test: every fragment is written.
//
// The buffer remembers, for each pixel, the winning triangle and its barycentrics, so
// shading runs once per visible pixel: the image equals that of shading each fragment as
// it passes, in triangle order, but no light is computed for fragments that are hidden.
// The fast path (fast/depth_test_fast.h) tests chunks of rows on several threads, eight
// pixels at a time.
#pragma once

#include <cstdint>
#include <limits>

#include "pipeline/core/image.h"
#include "pipeline/core/math.h"
#include "pipeline/scene/scene.h"
#include "pipeline/stages/projection.h"
#include "pipeline/stages/scan_conversion.h"

namespace rl {

inline constexpr std::uint32_t kNoTriangle = std::numeric_limits<std::uint32_t>::max();

struct DepthTest {
    // The z-buffer: the clear value where nothing was drawn. Empty when !depthKept (the fast
    // path's frames that keep their image alone test each band of rows in a buffer of their
    // own).
    Image<float> depth;
    bool depthKept = true;
    // Whether triangle and barycentric are kept: not by the fast path's frames whose depth
    // test and shading ran together band by band.
    bool fragmentsKept = true;
    Image<std::uint32_t> triangle;  // index into Projection::triangles, or kNoTriangle
    // (beta, gamma) of the winning fragment, alpha = 1 - beta - gamma; meaningful only where
    // triangle holds one, and only when barycentricsKept (the fast path leaves them out when
    // every draw is flat: nothing reads them then).
    Image<vec2> barycentric;
    bool barycentricsKept = true;
    // The painter's algorithm (painters_algorithm.h): no depth test, every fragment is written
    // over what was there, so the buffer holds the depth of the last painted fragment.
    bool painted = false;
    std::size_t fragments = 0;          // tested
    std::size_t passed = 0;             // written (including those overwritten later)
    std::size_t rejected = 0;           // farther than (or as far as) what was stored
    std::size_t outsideDepthRange = 0;  // discarded: depth outside [0, 1] (seed 001)
    float clearedTo = 0.0f;             // the clear value of the untouched pixels

    // What the fast path keeps for the next frame and for shading (empty from the stage):
    // per chunk of kRowChunk rows (parallel.h), the columns this frame's spans fell in, the
    // only pixels that can differ from the cleared state (the next frame that reuses these
    // buffers clears only those); and per projected triangle, 1 where it holds a pixel at the
    // end (the triangles flat and Gouraud shading light), when some draw is flat or Gouraud.
    std::vector<ColumnRange> touched;
    std::vector<std::uint8_t> visible;

    // The pixels a triangle won: counted where triangle is kept, otherwise covered.
    std::size_t coveredPixels() const;
    std::size_t covered = 0;  // only when !fragmentsKept: counted by the shading of the bands
};

struct DepthTestInput {
    const Scene& scene;
    const Projection& projection;
    const ScanConversion& scan;
};

class DepthTestStage {
public:
    // Every span of every triangle in order, pixel by pixel, into a full z-buffer. A probe
    // (probe.h) hears of every depth test, with both depths and the verdict.
    DepthTest run(const DepthTestInput& in) const;
    template <typename Probe>
    DepthTest run(const DepthTestInput& in, Probe& probe) const;
};

// One fragment as the depth test works it out.
struct FragmentDepth {
    float beta = 0.0f, gamma = 0.0f;  // screen barycentrics, alpha = 1 - beta - gamma
    float depth = 0.0f;
};

// What the depth test of one triangle's spans needs, worked out once per triangle: the
// screen barycentrics of a sample s, from s = P1 + beta (P2 - P1) + gamma (P3 - P1),
// beta = (s - P1) x (P3 - P1) / A and gamma = (P2 - P1) x (s - P1) / A, A = (P2 - P1) x
// (P3 - P1); both are linear in x along a scanline. The fragment's depth is
// z = z1 + beta (z2 - z1) + gamma (z3 - z1), the lecture's alpha z1 + beta z2 + gamma z3 with
// alpha = 1 - beta - gamma, written so that equal depths give exactly themselves. With
// reciprocal, the plane interpolated is that of 1/z, and a fragment's depth is one over it
// (view z is not linear on the screen, 1/z is: perspective-correct depth).
struct TrianglePlane {
    dvec2 p0, e1, e2;
    double area = 0.0, betaDx = 0.0, gammaDx = 0.0;
    float z0 = 0.0f, dz1 = 0.0f, dz2 = 0.0f;
    bool reciprocal = false;

    TrianglePlane(const Projection& projection, std::size_t t, bool reciprocal);
    // The barycentrics of the sample of pixel (xBegin, y), (xBegin + offset, y + offset),
    // where a span starts.
    void spanStart(std::int32_t xBegin, std::int32_t y, double offset, double& beta0,
                   double& gamma0) const;
    // Pixel i of a span whose first pixel has the barycentrics beta0, gamma0: they step by
    // betaDx and gammaDx from there, so the bits depend on where the span starts.
    FragmentDepth fragment(double beta0, double gamma0, std::int32_t i) const {
        FragmentDepth f;
        f.beta = static_cast<float>(beta0 + double(i) * betaDx);
        f.gamma = static_cast<float>(gamma0 + double(i) * gammaDx);
        f.depth = z0 + f.beta * dz1 + f.gamma * dz2;
        if (reciprocal) f.depth = 1.0f / f.depth;
        return f;
    }
};

inline TrianglePlane::TrianglePlane(const Projection& projection, std::size_t t, bool inverse)
    : reciprocal(inverse) {
    const ScreenTriangle& tri = projection.triangles[t];
    const DrawProjection& draw = projection.draws[tri.draw];
    const std::array<dvec2, 3> p = screenVertices(projection, tri);
    const auto depthOf = [&](std::uint32_t v) {
        return reciprocal ? 1.0f / draw.depth[v] : draw.depth[v];
    };
    z0 = depthOf(tri.v[0]);
    dz1 = depthOf(tri.v[1]) - z0;
    dz2 = depthOf(tri.v[2]) - z0;
    p0 = p[0];
    e1 = p[1] - p[0];
    e2 = p[2] - p[0];
    area = e1.x * e2.y - e1.y * e2.x;
    betaDx = e2.y / area;
    gammaDx = -e1.y / area;
}

inline void TrianglePlane::spanStart(std::int32_t xBegin, std::int32_t y, double offset,
                                     double& beta0, double& gamma0) const {
    const dvec2 s0 = dvec2(xBegin + offset, y + offset) - p0;
    beta0 = (s0.x * e2.y - s0.y * e2.x) / area;
    gamma0 = (e1.x * s0.y - e1.y * s0.x) / area;
}

// Pixel x of the span that starts at pixel xBegin on row y of projected triangle t, as the
// depth test works it out (xBegin must be where scan conversion starts the span for the
// bits to agree).
FragmentDepth fragmentDepth(const Scene& scene, const Projection& projection, std::uint32_t t,
                            std::int32_t y, std::int32_t xBegin, std::int32_t x);

// The rows of the buffers one span writes (barycentrics null when none are kept).
struct DepthRows {
    float* depth;
    std::uint32_t* ids;
    vec2* bary;
};
struct DepthCounts {
    std::size_t fragments = 0, passed = 0, outsideDepthRange = 0;
};

// The depth test of one span of triangle id, pixel by pixel, the lecture's inner loop:
// rows are the span's row of each buffer; painted: the painter's algorithm (no test).
template <typename Probe>
void testSpanPixels(const Scene& scene, const TrianglePlane& plane, std::uint32_t id,
                    const Span& span, const DepthRows& rows, bool painted, DepthCounts& counts,
                    Probe& probe);
// The same loop for a span the DDA walked (dda.h): each pixel's weights and depth are the
// span's attributes, stepped one addition a pixel from its first.
template <typename Probe>
void testDdaSpanPixels(const Scene& scene, const DdaSpan& dda, std::uint32_t id, const Span& span,
                       const DepthRows& rows, bool painted, DepthCounts& counts, Probe& probe);
// A DDA fragment: the span's attributes at a pixel as the depth test reads them.
FragmentDepth ddaFragment(const DdaValues& v, bool reciprocal);

}  // namespace rl
