#include "animation.h"

#include <cstdio>
#include <memory>

#include "pipeline/render/renderer.h"

namespace rl {

Status renderAnimationFrames(
    const Scene& scene, int frames, double framesPerSecond,
    const std::function<bool(int frame, double t, const FrameTrace& trace)>& use) {
    // The pivots do not move with time: found once (a pass over each animated mesh), not in
    // every frame's view transform.
    Scene pinned = scene;
    for (Draw& draw : pinned.draws) {
        if (!draw.animation) continue;
        const AnimationPivot pivot = animationPivot(scene, draw);
        draw.animation->centre = pivot.centre;
        draw.animation->axis = pivot.axis;
    }
    RenderContext context;  // the buffers of one frame serve the next
    for (int k = 0; k < frames; ++k) {
        const double t = k / framesPerSecond;
        auto frameScene = std::make_shared<Scene>(pinned);
        frameScene->time = t;
        Result<FrameTrace> trace = renderFrame(std::move(frameScene), {}, &context);
        if (!trace) return trace.error();
        if (!use(k, t, trace.value())) break;
    }
    return success();
}

std::string animationFrameFileName(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", frame);
    return name;
}

}  // namespace rl
