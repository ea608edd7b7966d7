// Shading on several threads, with many-pixel kernels for the common cases, and the depth
// test and shading together band by band. It must equal ShadingStage::run
// (stages/shading.h) bit for bit in every colour (and normal, when kept) and count.
#pragma once

#include <utility>

#include "pipeline/fast/depth_test_fast.h"
#include "pipeline/stages/shading.h"

namespace rl::fast {

// What the fast path keeps and reuses; none of it changes the image.
struct ShadingExecution {
    int threads = 1;              // the rows are shared out between them (parallel.h)
    bool keepNormals = false;     // the normal used at each pixel (the normals image)
    Shading* recycled = nullptr;  // an earlier frame's buffers, whose memory is reused
};

Shading shading(const ShadingInput& in, const ShadingExecution& execution);

// The depth test and shading together, for a frame that keeps its image alone: each thread
// shades a band of rows as soon as it has tested it there (depthTestInBands), so that the ids and
// barycentrics never leave its cache; only the colours (and covered) go to memory. The image is the
// same bits as the stages' one after the other; the depth test keeps no per-pixel buffer. Flat and
// Gouraud colours are worked out first, for every triangle with a fragment (shadeInBands: when they
// are few next to the pixels). bandRows: each band's rows (bandRowsFor).
// depthShare: of the threads' time, the part spent testing.
std::pair<DepthTest, Shading> depthTestAndShading(const FrameLighting& lighting,
                                                  const ScanConversion& scan, int threads,
                                                  int bandRows, Shading* recycled,
                                                  double& depthShare);

// Whether shading in bands pays: the points its flat and Gouraud draws light before the
// depth test (those of every triangle with a fragment, not only those that keep a pixel) are
// at most one per kBandsFragmentsPerPoint fragments, counted by an upper bound that costs no
// pass over the triangles.
inline constexpr std::size_t kBandsFragmentsPerPoint = 4;
bool shadeInBands(const Scene& scene, const Projection& projection, const ScanConversion& scan);

}  // namespace rl::fast
