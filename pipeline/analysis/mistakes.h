// A student's image against ours, and the mistakes that would explain the difference
// (`rasterlab-cli compare`). Each mistake is a hypothesis: our image transformed (mirrored,
// shifted, its bytes made another way), the scene rendered again with other rules (fill
// rule, sample offset, shading model, depth ties ...), or our frame shaded again with the
// lighting formula changed ("what-if" shading, from the frame's triangles, barycentrics,
// interpolated P' and N, lights and material, with phong.h's own functions). A hypothesis
// explains a differing pixel when its image comes nearer to theirs there (to within one
// unit); its share is the fraction of the differing pixels it explains. The lecture's stages
// know nothing of these mistakes.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/core/diagnostics.h"
#include "pipeline/core/math.h"
#include "pipeline/core/message.h"
#include "pipeline/render/frame_trace.h"
#include "pipeline/render/output_image.h"
#include "pipeline/scene/scene.h"

namespace rl {

// The mistakes recognised, most common first.
enum class Mistake : std::uint8_t {
    AmbientTimesOd,           // ambient Ia ka Od instead of Ia ka
    NormalNotFlipped,         // N not turned toward the viewer where V.N < 0
    SpecularWhereRvNegative,  // Il ks (R.V)^n added where R.V < 0
    LightBehindNotSkipped,    // diffuse and specular computed where N.L < 0
    NormalNotNormalised,      // the interpolated N used at its own length
    Gouraud,                  // another shading model than the one asked
    Flat,
    Phong,
    MirroredLeftRight,
    UpsideDown,
    Shifted,       // by one pixel in some direction
    SampleOffset,  // pixel corners against pixel centres (half a pixel)
    VertexSnap,    // vertices rounded against truncated
    FillRule,      // inclusive edges against top-left
    ByteRounding,  // bytes rounded against truncated: off by one
    ColourWrap,    // bytes wrap past 255 instead of clamping
    PainterOrder,  // the painter's order instead of the z-buffer
    DepthTies,     // <= against < in the depth test
    Background,    // another colour (or alpha) where no triangle is
    Alpha,         // another alpha where a triangle is
};

inline constexpr std::size_t kMistakeCount = 20;

const char* mistakeId(Mistake mistake);  // "ambient-times-od", "mirrored-left-right" ...
std::optional<Mistake> mistakeFromId(std::string_view id);

// Our frame: the trace (z-buffer, triangle ids, barycentrics and float colours kept) and its
// image.
struct OurFrame {
    std::shared_ptr<const FrameTrace> trace;
    Rgba8Image image;
    bool covered(int x, int y) const { return trace->depth->triangle.at(x, y) != kNoTriangle; }
};
Result<OurFrame> renderOurFrame(std::shared_ptr<const Scene> scene);

// Our image as it would be with the mistake; none when the mistake cannot happen in this
// scene (no Phong draw to shade Gouraud, no colour above the scale to wrap ...). Shifted moves
// the image by shift; Background and Alpha take the colour or alpha from `value`.
Result<std::optional<Rgba8Image>> imageWithMistake(const OurFrame& ours, Mistake mistake,
                                                   ivec2 shift = ivec2(1, 0),
                                                   std::array<std::uint8_t, 4> value = {});

struct PixelExample {
    int x = 0;
    int y = 0;
    std::array<std::uint8_t, 4> ours{}, theirs{};
};

struct Finding {
    Mistake mistake{};
    // Messages (pipeline/core/message.h), so that the window shows them translated.
    Message title;              // "the ambient term multiplied by the object colour: ..."
    Message evidence;           // how the hypothesis made their pixels, and what it would spoil
    Message advice;             // what to look at in one's code
    std::size_t explained = 0;  // differing pixels it makes match
    double share = 0.0;         // explained / differing
    std::size_t spoiled = 0;    // pixels that match now and would not with the mistake
    std::vector<PixelExample> examples;
};

// Below this share a match is chance: a highlight's pixel or two that another rule happens to
// give (2 of the 76,508 pixels the goblet's ambient mistake changes match sampling at centres).
inline constexpr double kLeastShare = 0.001;

struct ImageComparison {
    int width = 0;
    int height = 0;
    int tolerance = 0;  // a difference of at most this in every channel counts as the same
    std::size_t compared = 0;
    std::size_t differing = 0;     // some channel differs by more than the tolerance
    std::array<int, 4> largest{};  // largest difference per channel, RGBA
    std::array<double, 4> mean{};  // mean difference per channel over the differing pixels
    std::size_t onlyOurs = 0;      // covered in our depth buffer, their pixel the background
    std::size_t onlyTheirs = 0;    // not covered by us, their pixel not the background
    // Ranked by the pixels explained less those spoiled; a mistake that spoils as many as it
    // explains, or explains less than kLeastShare of the differing pixels, is left out.
    std::vector<Finding> diagnosis;
    // Our image darkened, differing pixels from yellow (a small difference) to red (large),
    // magenta where only we cover a pixel, cyan where only they do.
    Rgba8Image difference;
};

// Compares their image (our size) with our frame and ranks the mistakes. A lossy image (JPEG)
// is compared with a tolerance: channels that differ by at most that much count as the same.
Result<ImageComparison> compareWithOurs(const OurFrame& ours, const Rgba8Image& theirs,
                                        int tolerance = 0);

// Where their larger image holds ours exactly (a screenshot with a window border): the
// offset of our top-left pixel in theirs; none when no offset matches 95% of ours.
std::optional<ivec2> findEmbedded(const Rgba8Image& ours, const Rgba8Image& theirs);

}  // namespace rl
