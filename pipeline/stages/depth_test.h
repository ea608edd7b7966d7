// Stage 6, depth test (z-buffer). For every pixel of every span, the screen barycentrics
// (alpha, beta, gamma) of its sample with respect to the triangle's screen vertices give
// the fragment's depth, z = alpha z1 + beta z2 + gamma z3: for the course the z of
// P' = alpha P1 + beta P2 + gamma P3 in view coordinates (seed 000), for command files the
// NDC z (seed 001). Under perspective-correct rules (RasterRules::gpu, hw2) view z is found
// as 1 / (alpha / z1 + beta / z2 + gamma / z3), the depth of the point on the triangle. The buffer
// starts at the convention's clear value (+infinity, or 1) and the nearer fragment wins: z < stored
// writes; on a tie the earlier triangle stays, unless the convention says z <= stored (seed 001).
// Seed 001 also discards fragments whose z is outside [0, 1] (per-pixel clipping). Under the
// painter's algorithm (paintersAlgorithm(scene)) there is no test: every fragment is written.
//
// The buffer remembers, for each pixel, the winning triangle and its barycentrics, so
// shading runs once per visible pixel: the image equals that of shading each fragment as
// it passes, in triangle order, but no light is computed for fragments that are hidden.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>

#include "image.h"
#include "math.h"
#include "projection.h"
#include "scan_conversion.h"
#include "scene.h"

namespace rl {

inline constexpr std::uint32_t kNoTriangle = std::numeric_limits<std::uint32_t>::max();

struct DepthTest {
    // The clear value where nothing was drawn. Only when depthKept: a caller that needs the
    // image alone (RenderOptions::keepDepth false: the command line's render without
    // --depth-output, painter shading or --explain-pixel, and bench without --keep-depth)
    // lets each thread keep the depths of the band of rows it is testing, in its cache, and
    // this stays empty.
    Image<float> depth;
    bool depthKept = true;
    // Whether triangle and barycentric are kept: not by a frame whose depth test and
    // shading ran together (DepthTestStage::runBands), which keeps the image alone.
    bool fragmentsKept = true;
    Image<std::uint32_t> triangle;  // index into Projection::triangles, or kNoTriangle
    // (beta, gamma) of the winning fragment, alpha = 1 - beta - gamma; meaningful only where
    // triangle holds one (elsewhere, what an earlier frame in these buffers left), and only
    // when barycentricsKept (not when every draw is flat: nothing reads them then).
    Image<vec2> barycentric;
    bool barycentricsKept = true;
    // The painter's algorithm (painter.h): no depth test, every fragment is written over what
    // was there, so the buffer holds the depth of the last painted fragment, not the nearest.
    bool painted = false;
    std::size_t fragments = 0;          // tested
    std::size_t passed = 0;             // written (including those overwritten later)
    std::size_t rejected = 0;           // farther than (or as far as) what was stored
    std::size_t outsideDepthRange = 0;  // discarded: depth outside [0, 1] (seed 001)
    // Per chunk of kRowChunk rows (parallel.h), the columns this frame's spans fell in: the
    // only pixels that can differ from the cleared state. Empty when not tracked (a recording
    // probe's frame): then every pixel may. The next frame that reuses these buffers clears
    // only those columns (a small object on a large screen leaves most of it alone).
    std::vector<ColumnRange> touched;
    float clearedTo = 0.0f;  // the clear value of the untouched pixels
    // Per projected triangle, 1 where it holds a pixel at the end (won the depth test
    // somewhere and kept it): the triangles flat and Gouraud shading evaluate. Worked out
    // chunk by chunk while the chunk is in the cache, only when some draw is flat or
    // Gouraud and nothing records; empty otherwise.
    std::vector<std::uint8_t> visible;

    // The pixels a triangle won: counted where triangle is kept, otherwise covered.
    std::size_t coveredPixels() const;
    std::size_t covered = 0;  // only when !fragmentsKept: counted by the shading of the bands
};

// One chunk of rows (parallel.h) just depth-tested by thread `part` in a band of its own
// (DepthTestStage::runBands): row y's winning ids are ids + (y - y0) * stride, its
// barycentrics bary + (y - y0) * stride (null when none are kept). Valid until the thread's
// next chunk; only columns holds ids (the columns the chunk's spans fell in).
struct TestedBand {
    int part = 0;
    int y0 = 0, y1 = 0;
    ColumnRange columns;
    const std::uint32_t* ids = nullptr;
    const vec2* bary = nullptr;
    std::size_t stride = 0;
};
using BandSink = std::function<void(const TestedBand&)>;

// The end of the run of pixels from `from` on whose triangle is t (at most `limit`): sixteen
// ids (a cache line's worth) checked at once while they can be. Shading and the depth test's
// visible triangles walk every row this way (multiversioned, like the kernels).
int runEnd(const std::uint32_t* ids, int from, int limit, std::uint32_t t);

class DepthTestStage {
public:
    // threads: the rows are shared out between them (parallel.h); the result does not depend
    // on their number. recycled: an earlier frame's buffers, whose memory is reused.
    // keepDepth: false leaves DepthTest::depth empty (a recording probe keeps it anyway).
    template <typename Probe>
    DepthTest run(const Scene& scene, const Projection& projection, const ScanConversion& scan,
                  Probe& probe, int threads = 1, DepthTest* recycled = nullptr,
                  bool keepDepth = true) const;
    DepthTest run(const Scene& scene, const Projection& projection, const ScanConversion& scan,
                  int threads = 1, DepthTest* recycled = nullptr, bool keepDepth = true) const;
    // The same test with nothing kept per pixel: each thread tests its chunks of rows in a band
    // of its own (depths, ids and barycentrics: 184 KB at 1920 pixels wide, in its L2 cache)
    // and hands each chunk to sink, on the same thread, before testing the next. The result
    // has the counts and touched, no z-buffer, ids or barycentrics (fragmentsKept false), and
    // covered left for the sink's owner to count.
    DepthTest runBands(const Scene& scene, const Projection& projection, const ScanConversion& scan,
                       int threads, const BandSink& sink) const;
};

// Whether the depth test interpolates 1/z rather than z: view z under perspective-correct
// rules (1/z is linear on the screen; NDC z already is).
bool perspectiveDepth(const Scene& scene);

// One fragment as the depth test works it out: pixel x of the span that starts at pixel
// xBegin on row y of projected triangle t. The barycentrics step along the span from its
// first pixel, so xBegin must be where scan conversion starts the span for the bits to
// agree.
struct FragmentDepth {
    float beta = 0.0f, gamma = 0.0f;  // screen barycentrics, alpha = 1 - beta - gamma
    float depth = 0.0f;
};
FragmentDepth fragmentDepth(const Scene& scene, const Projection& projection, std::uint32_t t,
                            std::int32_t y, std::int32_t xBegin, std::int32_t x);

}  // namespace rl
