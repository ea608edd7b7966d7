// Seed 004's painter's algorithm next to the z-buffer: both renders of a scene, and the
// pixels where the painter's order shows a farther triangle (painters_algorithm.h has the
// algorithm itself).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "pipeline/core/diagnostics.h"
#include "pipeline/core/image.h"
#include "pipeline/core/math.h"
#include "pipeline/render/frame_trace.h"
#include "pipeline/render/output_image.h"
#include "pipeline/render/renderer.h"
#include "pipeline/scene/scene.h"
#include "pipeline/stages/painters_algorithm.h"
#include "pipeline/stages/projection.h"

namespace rl {

// The scene with every draw painted (ShadingModel::Painter), and with every draw flat under
// the z-buffer: the same colours (both light each triangle once at its barycentre), so the
// two images differ only where visibility does.
std::shared_ptr<const Scene> painterSceneOf(const Scene& scene);
std::shared_ptr<const Scene> zBufferSceneOf(const Scene& scene);

// What a pixel of the comparison shows.
enum class PixelDifference : std::uint8_t {
    Same,        // both images have the same bytes there
    WrongOrder,  // the painter shows a triangle farther there than the z-buffer's
    // Both triangles are as near there (within kPainterDepthTolerance): an edge they share,
    // or coplanar faces.
    Tie,
};

// Depths closer than this fraction of the nearer one count as a tie: two triangles that share
// an edge interpolate its depth from different vertices, and the floats differ in their last
// bits (on the default trefoil at 800x600, 525 edge pixels differ by less than 1e-6 of the
// depth; the 5 pixels where a farther triangle really covers a nearer one, by 1e-3).
inline constexpr float kPainterDepthTolerance = 1e-5f;

// The painter's render of a scene beside the z-buffer's, and where they disagree.
struct PainterComparison {
    std::shared_ptr<const FrameTrace> painter;  // painterSceneOf(scene)
    std::shared_ptr<const FrameTrace> zBuffer;  // zBufferSceneOf(scene)
    Image<PixelDifference> mask;
    std::size_t differing = 0;   // pixels whose bytes differ
    std::size_t wrongOrder = 0;  // of those, where a farther triangle was painted last
    std::size_t ties = 0;        // of those, where the two triangles are as near
    // The two images, as colourImage makes them.
    Rgba8Image painterImage, zBufferImage;
    // Per triangle of the painter's frame (its painted rank): the z-buffer frame's index of
    // the same triangle; and back, per triangle of the z-buffer's frame: its painted rank.
    std::vector<std::uint32_t> zBufferIndex, painterRank;
    // Per triangle of the painter's frame: the pixels where it is the nearest (the z-buffer
    // shows it) but a triangle painted after it covers it, and the pixels where it covers a
    // nearer triangle painted before it.
    std::vector<std::uint32_t> hiddenWrongly, coversWrongly;
};

Result<PainterComparison> compareWithZBuffer(const std::shared_ptr<const Scene>& scene,
                                             const RenderOptions& options = {});
// The same for a frame already rendered (of frame->scene), which is one of the two renders
// when every draw of its scene is painted (the painter's) or flat (the z-buffer's): it is
// used as it is, and only the other one is rendered, unless it did not keep its z-buffer
// (RenderOptions::keepDepth; the comparison reads depths): then it is rendered again.
Result<PainterComparison> compareWithZBuffer(const std::shared_ptr<const FrameTrace>& frame,
                                             const RenderOptions& options = {});

// The comparison as a picture: the z-buffer image at a third of its brightness, the pixels
// where a farther triangle was painted last red (255, 0, 0), ties yellow (255, 220, 0).
Rgba8Image differenceImage(const PainterComparison& comparison);

}  // namespace rl
