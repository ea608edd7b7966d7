#include "renderer.h"

#include <chrono>

#include "pipeline/core/format.h"
#include "pipeline/core/parallel.h"
#include "pipeline/fast/depth_test_fast.h"
#include "pipeline/fast/normals_fast.h"
#include "pipeline/fast/projection_fast.h"
#include "pipeline/fast/scan_conversion_fast.h"
#include "pipeline/fast/shading_fast.h"
#include "pipeline/render/lights_on_surfaces.h"

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

// A light so near a surface that float cannot tell its side there (view_transform.h): a
// warning, worked out once per scene when a context remembers it.
void warnOfLightsOnSurfaces(FrameTrace& trace, const std::shared_ptr<const Scene>& scenePtr,
                            RenderContext* context) {
    if (context && context->lightsChecked.lock() == scenePtr) {
        trace.diagnostics.append(context->lightWarnings);
        return;
    }
    const Scene& scene = *scenePtr;
    Diagnostics found;
    for (const LightOnSurface& near : lightsOnSurfaces(scene, *trace.view))
        found.warn(near.light < scene.lights.size() ? scene.lights[near.light].where
                                                    : SourceLocation{scene.name, 0, 0},
                   "light %1 is %2 above triangle %3 of %4, nearer than float can resolve "
                   "points there (%5): the pixels under it may be lit from the wrong side"_msg(
                       near.light + 1, formatNumber(near.height), near.triangle + 1,
                       scene.draws[near.draw].name, formatNumber(near.limit)));
    trace.diagnostics.append(found);
    if (context) {
        context->lightsChecked = scenePtr;
        context->lightWarnings = std::move(found);
    }
}

// A buffer of the context that no earlier trace still holds, to be recycled.
template <typename T>
T* recyclable(const std::shared_ptr<T>& held) {
    return held && held.use_count() == 1 ? held.get() : nullptr;
}

// Runs body, and keeps its time as the stage's.
template <typename Body>
void timed(FrameTrace& trace, StageId stage, Body&& body) {
    const auto start = Clock::now();
    body();
    trace.stageMilliseconds[static_cast<std::size_t>(stage)] = millisecondsSince(start);
}

// Stages 3 to 7 as the lecture writes them, each on one thread, the probe hearing of every
// triangle, span, depth test and pixel shaded.
template <typename Probe>
void runLectureStages(FrameTrace& trace, Probe& probe) {
    const Scene& scene = *trace.scene;
    timed(trace, StageId::Normals, [&] {
        trace.normals = std::make_shared<const Normals>(NormalsStage().run({scene, *trace.view}));
    });
    timed(trace, StageId::Projection, [&] {
        trace.projection = std::make_shared<const Projection>(
            ProjectionStage().run({scene, *trace.view}, trace.diagnostics));
    });
    timed(trace, StageId::ScanConversion, [&] {
        trace.scan = std::make_shared<const ScanConversion>(
            ScanConversionStage().run({scene, *trace.projection}, probe));
    });
    timed(trace, StageId::DepthTest, [&] {
        trace.depth = std::make_shared<const DepthTest>(
            DepthTestStage().run({scene, *trace.projection, *trace.scan}, probe));
    });
    timed(trace, StageId::Shading, [&] {
        trace.shading = std::make_shared<const Shading>(ShadingStage().run(
            {scene, *trace.view, *trace.normals, *trace.projection, *trace.depth}, probe));
    });
}

// The depth test and shading together (fast::depthTestAndShading): their time is the pair's,
// split in the proportion the threads spent on each.
void runDepthTestAndShadingInBands(FrameTrace& trace, int threads, int bandRows,
                                   RenderContext* context) {
    const auto start = Clock::now();
    trace.bandRows = bandRowsFor(bandRows);
    Shading* recycled = context ? recyclable(context->shading) : nullptr;
    double depthShare = 0.0;
    const FrameLighting lighting(*trace.scene, *trace.view, *trace.normals, *trace.projection);
    auto [depth, shading] = fast::depthTestAndShading(lighting, *trace.scan, threads,
                                                      trace.bandRows, recycled, depthShare);
    const double both = millisecondsSince(start);
    trace.stageMilliseconds[static_cast<std::size_t>(StageId::DepthTest)] = both * depthShare;
    trace.stageMilliseconds[static_cast<std::size_t>(StageId::Shading)] = both * (1.0 - depthShare);
    auto shared = std::make_shared<Shading>(std::move(shading));
    if (context) {
        context->shading = shared;
        context->depth.reset();
    }
    trace.depth = std::make_shared<const DepthTest>(std::move(depth));
    trace.shading = std::move(shared);
}

// Stages 3 to 7 by the fast paths, keeping what the options ask for.
void runFastStages(FrameTrace& trace, const RenderOptions& options, int threads,
                   RenderContext* context) {
    const Scene& scene = *trace.scene;
    timed(trace, StageId::Normals, [&] {
        const auto scope = options.keepForViews || options.shading.keepNormals
                               ? fast::NormalsScope::All
                               : fast::NormalsScope::Read;
        trace.normals =
            std::make_shared<const Normals>(fast::normals({scene, *trace.view}, threads, scope));
    });
    timed(trace, StageId::Projection, [&] {
        trace.projection = std::make_shared<const Projection>(fast::projection(
            {scene, *trace.view}, trace.diagnostics, threads, options.keepForViews));
    });
    timed(trace, StageId::ScanConversion, [&] {
        trace.scan = std::make_shared<const ScanConversion>(
            fast::scanConversion({scene, *trace.projection}, threads));
    });
    if (!options.keepDepth && !options.keepFragments && !options.shading.keepNormals &&
        fast::shadeInBands(scene, *trace.projection, *trace.scan)) {
        runDepthTestAndShadingInBands(trace, threads, options.bandRows, context);
        return;
    }
    timed(trace, StageId::DepthTest, [&] {
        DepthTest* recycled = context ? recyclable(context->depth) : nullptr;
        auto depth = std::make_shared<DepthTest>(fast::depthTest(
            {scene, *trace.projection, *trace.scan}, threads, recycled, options.keepDepth));
        if (context) context->depth = depth;
        trace.depth = std::move(depth);
    });
    timed(trace, StageId::Shading, [&] {
        Shading* recycled = context ? recyclable(context->shading) : nullptr;
        auto shading = std::make_shared<Shading>(
            fast::shading({scene, *trace.view, *trace.normals, *trace.projection, *trace.depth},
                          {threads, options.shading.keepNormals, recycled}));
        if (context) context->shading = shading;
        trace.shading = std::move(shading);
    });
}

template <typename Probe>
Result<FrameTrace> run(std::shared_ptr<const Scene> scenePtr, const RenderOptions& options,
                       Probe& probe, RenderContext* context) {
    if (!scenePtr)
        return makeError(ErrorCode::Usage, SourceLocation{"<scene>", 0, 0},
                         "no scene to render"_msg);
    const Scene& scene = *scenePtr;
    if (scene.width <= 0 || scene.height <= 0)
        return makeError(ErrorCode::Usage, SourceLocation{scene.name, 0, 0},
                         "the image size %1x%2 is empty"_msg(scene.width, scene.height));
    FrameTrace trace;
    trace.scene = scenePtr;
    const int threads = Probe::enabled ? 1 : resolveThreads(options.threads);
    trace.threads = threads;
    const auto frameStart = Clock::now();

    Result<CameraBasis> basis = CameraBasis{};
    timed(trace, StageId::CameraBasis,
          [&] { basis = CameraBasisStage().run(scene, trace.diagnostics); });
    if (!basis) return basis.error();
    trace.cameraBasis = std::make_shared<const CameraBasis>(std::move(basis).value());
    timed(trace, StageId::ViewTransform, [&] {
        trace.view = std::make_shared<const ViewTransform>(
            ViewTransformStage().run(scene, *trace.cameraBasis));
    });
    warnOfLightsOnSurfaces(trace, scenePtr, context);
    if constexpr (Probe::enabled)
        runLectureStages(trace, probe);
    else
        runFastStages(trace, options, threads, context);

    if (trace.scan->spans.empty() && trace.scan->offscreen > 0) {
        trace.diagnostics.warn(
            SourceLocation{scene.name, 0, 0},
            "no triangle covers a pixel: all %1 triangles in front of the "
            "camera project outside the image (check N, d, hx and hy)"_msg(trace.scan->offscreen));
    }
    if (trace.normals->degenerateTriangles > 0) {
        trace.diagnostics.note(
            SourceLocation{scene.name, 0, 0},
            "%1 triangles have zero area and no normal"_msg(trace.normals->degenerateTriangles));
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
