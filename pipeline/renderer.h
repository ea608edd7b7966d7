// Runs the seven stages in lecture order on a scene and keeps every output in a
// FrameTrace. renderFrame is the plain render; traceFrame runs the same code with a
// RecordingProbe to log what happens at one pixel or to one triangle. Both are pure
// functions of the scene: no global state, so two renders can run at the same time.
#pragma once

#include <memory>

#include "diagnostics.h"
#include "frame_trace.h"
#include "probe.h"
#include "scene.h"
#include "shading.h"

namespace rl {

struct RenderOptions {
    ShadingOptions shading;
};

Result<FrameTrace> renderFrame(std::shared_ptr<const Scene> scene,
                               const RenderOptions& options = {});
Result<FrameTrace> traceFrame(std::shared_ptr<const Scene> scene, const RenderOptions& options,
                              RecordingProbe& probe);

}  // namespace rl
