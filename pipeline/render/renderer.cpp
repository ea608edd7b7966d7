#include "renderer.h"

#include <chrono>

#include "parallel.h"

namespace rl {

std::string FrameTrace::skipReason(StageId stage) const {
    switch (stage) {
        case StageId::CameraBasis:
            return cameraBasis ? cameraBasis->skipReason : "";
        case StageId::Normals:
            return normals ? normals->skipReason : "";
        default:
            return "";
    }
}

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// A buffer of the context that no earlier trace still holds, to be recycled.
template <typename T>
T* recyclable(const std::shared_ptr<T>& held) {
    return held && held.use_count() == 1 ? held.get() : nullptr;
}

template <typename Probe>
Result<FrameTrace> run(std::shared_ptr<const Scene> scenePtr, const RenderOptions& options,
                       Probe& probe, RenderContext* context) {
    if (!scenePtr)
        return makeError(ErrorCode::Usage, SourceLocation{"<scene>", 0, 0}, "no scene to render");
    const Scene& scene = *scenePtr;
    if (scene.width <= 0 || scene.height <= 0)
        return makeError(ErrorCode::Usage, SourceLocation{scene.name, 0, 0},
                         "the image size " + std::to_string(scene.width) + "x" +
                             std::to_string(scene.height) + " is empty");
    FrameTrace trace;
    trace.scene = scenePtr;
    const int threads = Probe::enabled ? 1 : resolveThreads(options.threads);
    trace.threads = threads;
    const auto frameStart = Clock::now();
    auto timed = [&](StageId stage, auto&& body) {
        const auto start = Clock::now();
        body();
        trace.stageMilliseconds[static_cast<std::size_t>(stage)] = millisecondsSince(start);
    };

    Result<CameraBasis> basis = CameraBasis{};
    timed(StageId::CameraBasis, [&] { basis = CameraBasisStage().run(scene, trace.diagnostics); });
    if (!basis) return basis.error();
    trace.cameraBasis = std::make_shared<const CameraBasis>(std::move(basis).value());

    timed(StageId::ViewTransform, [&] {
        trace.view = std::make_shared<const ViewTransform>(
            ViewTransformStage().run(scene, *trace.cameraBasis));
    });
    timed(StageId::Normals, [&] {
        const NormalsScope scope =
            Probe::enabled || options.keepForViews || options.shading.keepNormals
                ? NormalsScope::All
                : NormalsScope::Read;
        trace.normals =
            std::make_shared<const Normals>(NormalsStage().run(scene, *trace.view, threads, scope));
    });
    timed(StageId::Projection, [&] {
        trace.projection = std::make_shared<const Projection>(
            ProjectionStage().run(scene, *trace.view, trace.diagnostics, threads,
                                  Probe::enabled || options.keepForViews));
    });
    timed(StageId::ScanConversion, [&] {
        trace.scan = std::make_shared<const ScanConversion>(
            ScanConversionStage().run(scene, *trace.projection, probe, threads));
    });
    // Depth test and shading together: their time is the pair's, split in the proportion the
    // threads spent on each.
    if (!Probe::enabled && !options.keepDepth && !options.keepFragments &&
        !options.shading.keepNormals && shadeInBands(scene, *trace.projection, *trace.scan)) {
        const auto start = Clock::now();
        Shading* recycled = context ? recyclable(context->shading) : nullptr;
        double depthShare = 0.0;
        auto [depth, shading] =
            ShadingStage().runWithDepthTest(scene, *trace.view, *trace.normals, *trace.projection,
                                            *trace.scan, threads, recycled, depthShare);
        const double both = millisecondsSince(start);
        trace.stageMilliseconds[static_cast<std::size_t>(StageId::DepthTest)] = both * depthShare;
        trace.stageMilliseconds[static_cast<std::size_t>(StageId::Shading)] =
            both * (1.0 - depthShare);
        auto shared = std::make_shared<Shading>(std::move(shading));
        if (context) {
            context->shading = shared;
            context->depth.reset();
        }
        trace.depth = std::make_shared<const DepthTest>(std::move(depth));
        trace.shading = std::move(shared);
    } else {
        timed(StageId::DepthTest, [&] {
            DepthTest* recycled = context ? recyclable(context->depth) : nullptr;
            auto depth = std::make_shared<DepthTest>(
                DepthTestStage().run(scene, *trace.projection, *trace.scan, probe, threads,
                                     recycled, options.keepDepth));
            if (context) context->depth = depth;
            trace.depth = std::move(depth);
        });
        timed(StageId::Shading, [&] {
            Shading* recycled = context ? recyclable(context->shading) : nullptr;
            auto shading = std::make_shared<Shading>(
                ShadingStage().run(scene, *trace.view, *trace.normals, *trace.projection,
                                   *trace.depth, options.shading, probe, threads, recycled));
            if (context) context->shading = shading;
            trace.shading = std::move(shading);
        });
    }
    if (trace.scan->spans.empty() && trace.scan->offscreen > 0) {
        trace.diagnostics.warn(SourceLocation{scene.name, 0, 0},
                               "no triangle covers a pixel: all " +
                                   std::to_string(trace.scan->offscreen) +
                                   " triangles in front of the camera project outside the "
                                   "image (check N, d, hx and hy)");
    }
    if (trace.normals->degenerateTriangles > 0) {
        trace.diagnostics.note(SourceLocation{scene.name, 0, 0},
                               std::to_string(trace.normals->degenerateTriangles) +
                                   " triangles have zero area and no normal");
    }
    trace.totalMilliseconds = millisecondsSince(frameStart);
    return trace;
}

}  // namespace

Result<FrameTrace> renderFrame(std::shared_ptr<const Scene> scene, const RenderOptions& options,
                               RenderContext* context) {
    NullProbe probe;
    return run(std::move(scene), options, probe, context);
}

Result<FrameTrace> traceFrame(std::shared_ptr<const Scene> scene, const RenderOptions& options,
                              RecordingProbe& probe) {
    return run(std::move(scene), options, probe, nullptr);
}

}  // namespace rl
