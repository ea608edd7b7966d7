// The depth test on several threads, chunk of rows by chunk, eight or four pixels at a time
// (kernelLanes). It must
// equal DepthTestStage::run (stages/depth_test.h) bit for bit: the same depths, winning
// triangles, barycentrics and counts.
#pragma once

#include <cstdint>
#include <functional>

#include "pipeline/stages/depth_test.h"

namespace rl::fast {

// Rows [y0, y1) of a chunk (parallel.h) just depth-tested by thread `part` in a band of its
// own (depthTestInBands): row y's winning ids are ids + (y - y0) * stride, its
// barycentrics bary + (y - y0) * stride (null when none are kept). Valid until the thread's
// next band; only columns holds ids (the columns the chunk's spans fell in).
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

// testSpanPixels (stages/depth_test.h) for one span, eight or four pixels at a time
// (kernelLanes) where no depth range clips; the same bits and counts.
void testSpan(const Scene& scene, const TrianglePlane& plane, std::uint32_t id, const Span& span,
              const DepthRows& rows, bool painted, DepthCounts& counts);

// threads: the rows are shared out between them in chunks (parallel.h); the result does not
// depend on their number. recycled: an earlier frame's buffers, whose memory is reused (only
// the columns it touched are cleared). keepDepth: false leaves DepthTest::depth empty.
DepthTest depthTest(const DepthTestInput& in, int threads, DepthTest* recycled, bool keepDepth);
// The same test with nothing kept per pixel: each thread tests its chunks of rows
// bandRowsFor(bandRows) rows at a time (parallel.h), in a band of its own (a depth, an id
// and, unless every draw is flat, two barycentrics a pixel: 240 KB for 8 rows at 1920 pixels
// wide, in its L2 cache), and hands each band to sink, on the same thread, before testing
// the next. The result has the counts and touched, no z-buffer, ids or barycentrics
// (fragmentsKept false), and covered left for the sink's owner to count.
DepthTest depthTestInBands(const DepthTestInput& in, int threads, int bandRows,
                           const BandSink& sink);

}  // namespace rl::fast
