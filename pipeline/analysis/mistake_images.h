// How mistakes.h's hypotheses make their images, in two steps so that a search can reuse the
// first: the frame (the scene rendered again when a mistake changes its rules, its lights or
// its depth test), then the image on that frame (the lighting formula, the bytes, the image
// moved).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "pipeline/analysis/mistakes.h"

namespace rl {

// A frame to compose mistakes on: ours, or the scene rendered with the mistakes that change
// the render itself. `asked` is the scene as the student was asked to draw it, whose shading
// models a painted frame is shaded again by.
struct MistakeFrame {
    std::shared_ptr<const FrameTrace> trace;
    std::shared_ptr<const Scene> asked;
    bool painted = false;  // drawn in the painter's order: its colours are shaded again
};

// The one shading model every draw uses, if they agree.
std::optional<ShadingModel> sceneModel(const Scene& scene);

// Whether the mistake changes the render (and so needs a frame of its own).
bool changesTheRender(Mistake mistake);

// The frame of the slips that change the render (the others are left for imageOnFrame);
// none when one of them cannot happen in this scene or two of them cannot go together.
Result<std::optional<MistakeFrame>> frameWithMistakes(const OurFrame& ours,
                                                      const std::vector<Slip>& slips);

// The image of the slips that do not change the render, on that frame.
Result<std::optional<Rgba8Image>> imageOnFrame(const OurFrame& ours, const MistakeFrame& frame,
                                               const std::vector<Slip>& slips);

}  // namespace rl
