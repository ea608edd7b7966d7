// Seed 002's animation rendered frame after frame (animation_matrix.h has M(t)): what the
// command line's --animate and the window's frame export write.
#pragma once

#include <functional>
#include <string>

#include "pipeline/core/diagnostics.h"
#include "pipeline/render/frame_trace.h"
#include "pipeline/scene/animation_matrix.h"
#include "pipeline/scene/scene.h"

namespace rl {

// Renders frames 0 .. frames - 1 of the scene's animation one after the other, frame k being
// the scene at t = k / framesPerSecond, and hands each to `use`, which returns false to stop.
// A frame that fails to render ends it with its error (`use` has then seen the frames before).
Status renderAnimationFrames(
    const Scene& scene, int frames, double framesPerSecond,
    const std::function<bool(int frame, double t, const FrameTrace& trace)>& use);
// The file an animation's frame is written to: frame_0000.png, frame_0001.png ...
std::string animationFrameFileName(int frame);

}  // namespace rl
