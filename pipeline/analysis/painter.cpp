#include "painter.h"

#include <algorithm>
#include <cmath>

#include "pipeline/render/output_image.h"

namespace rl {

namespace {

std::shared_ptr<const Scene> withShading(const Scene& scene, ShadingModel model) {
    auto copy = std::make_shared<Scene>(scene);
    for (Draw& draw : copy->draws) draw.shading = model;
    return copy;
}

}  // namespace

std::shared_ptr<const Scene> painterSceneOf(const Scene& scene) {
    return withShading(scene, ShadingModel::Painter);
}

std::shared_ptr<const Scene> zBufferSceneOf(const Scene& scene) {
    return withShading(scene, ShadingModel::Flat);
}

namespace {

bool everyDraw(const Scene& scene, ShadingModel model) {
    return std::all_of(scene.draws.begin(), scene.draws.end(),
                       [model](const Draw& draw) { return draw.shading == model; });
}

// `frame` when there is one that kept its z-buffer (the comparison reads it), else a render
// of `scene` that keeps it.
Result<std::shared_ptr<const FrameTrace>> reuseOrRender(std::shared_ptr<const FrameTrace> frame,
                                                        std::shared_ptr<const Scene> scene,
                                                        const RenderOptions& options) {
    if (frame && frame->depth->depthKept) return frame;
    RenderOptions withDepth = options;
    withDepth.keepDepth = true;
    Result<FrameTrace> rendered = renderFrame(std::move(scene), withDepth);
    if (!rendered) return rendered.error();
    return std::make_shared<const FrameTrace>(std::move(rendered).value());
}

// The comparison of a painter's frame (of painterSceneOf(scene)) with a z-buffer's (of
// zBufferSceneOf(scene)): the given ones, or renders of them.
Result<PainterComparison> compare(const Scene& scene, std::shared_ptr<const FrameTrace> painter,
                                  std::shared_ptr<const FrameTrace> zBuffer,
                                  const RenderOptions& options) {
    auto painted = reuseOrRender(std::move(painter), painterSceneOf(scene), options);
    if (!painted) return painted.error();
    auto tested = reuseOrRender(std::move(zBuffer), zBufferSceneOf(scene), options);
    if (!tested) return tested.error();
    PainterComparison out;
    out.painter = std::move(painted).value();
    out.zBuffer = std::move(tested).value();
    const FrameTrace& p = *out.painter;
    const FrameTrace& z = *out.zBuffer;
    // The projection is the same but for the order: the z-buffer frame's, sorted, is the
    // painter's.
    out.zBufferIndex = painterOrder(*z.scene, *z.projection);
    out.painterRank.resize(out.zBufferIndex.size());
    for (std::size_t rank = 0; rank < out.zBufferIndex.size(); ++rank)
        out.painterRank[out.zBufferIndex[rank]] = static_cast<std::uint32_t>(rank);
    out.hiddenWrongly.assign(out.zBufferIndex.size(), 0);
    out.coversWrongly.assign(out.zBufferIndex.size(), 0);

    out.painterImage = colourImage(*p.shading, *p.depth, p.scene->conventions);
    out.zBufferImage = colourImage(*z.shading, *z.depth, z.scene->conventions);
    const Rgba8Image& painterImage = out.painterImage;
    const Rgba8Image& zImage = out.zBufferImage;
    out.mask.reset(scene.width, scene.height, PixelDifference::Same);
    for (int y = 0; y < scene.height; ++y) {
        for (int x = 0; x < scene.width; ++x) {
            if (std::equal(painterImage.pixel(x, y), painterImage.pixel(x, y) + 4,
                           zImage.pixel(x, y)))
                continue;
            ++out.differing;
            const std::uint32_t shown = p.depth->triangle.at(x, y);
            const std::uint32_t winner = z.depth->triangle.at(x, y);
            // The painter's buffer holds the depth of the last triangle painted here.
            const float last = p.depth->depth.at(x, y), nearest = z.depth->depth.at(x, y);
            if (last - nearest > kPainterDepthTolerance * std::abs(nearest)) {
                out.mask.at(x, y) = PixelDifference::WrongOrder;
                ++out.wrongOrder;
                if (shown != kNoTriangle) ++out.coversWrongly[shown];
                if (winner != kNoTriangle) ++out.hiddenWrongly[out.painterRank[winner]];
            } else {
                out.mask.at(x, y) = PixelDifference::Tie;
                ++out.ties;
            }
        }
    }
    return out;
}

}  // namespace

Result<PainterComparison> compareWithZBuffer(const std::shared_ptr<const Scene>& scene,
                                             const RenderOptions& options) {
    if (!scene)
        return makeError(ErrorCode::Usage, SourceLocation{"<scene>", 0, 0},
                         "no scene to render"_msg);
    return compare(*scene, nullptr, nullptr, options);
}

Result<PainterComparison> compareWithZBuffer(const std::shared_ptr<const FrameTrace>& frame,
                                             const RenderOptions& options) {
    if (!frame || !frame->scene)
        return makeError(ErrorCode::Usage, SourceLocation{"<scene>", 0, 0},
                         "no scene to render"_msg);
    const Scene& scene = *frame->scene;
    return compare(scene, everyDraw(scene, ShadingModel::Painter) ? frame : nullptr,
                   everyDraw(scene, ShadingModel::Flat) ? frame : nullptr, options);
}

Rgba8Image differenceImage(const PainterComparison& comparison) {
    Rgba8Image out = comparison.zBufferImage;
    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) {
            std::uint8_t* p = out.rgba.data() + (static_cast<std::size_t>(y) * out.width + x) * 4;
            switch (comparison.mask.at(x, y)) {
                case PixelDifference::Same:
                    for (int c = 0; c < 3; ++c) p[c] = static_cast<std::uint8_t>(p[c] / 3);
                    break;
                case PixelDifference::WrongOrder:
                    p[0] = 255, p[1] = 0, p[2] = 0;
                    break;
                case PixelDifference::Tie:
                    p[0] = 255, p[1] = 220, p[2] = 0;
                    break;
            }
            p[3] = 255;
        }
    }
    return out;
}

}  // namespace rl
