// A student's image against ours, and the mistakes that would explain the difference
// (`rasterlab-cli compare`). Each mistake is a hypothesis: our image transformed (mirrored,
// shifted, its bytes made another way), the scene rendered again with other rules (fill
// rule, sample offset, shading model, depth ties, the light moved where a transform mistake
// puts it ...), or our frame shaded again with the lighting formula changed ("what-if"
// shading, from the frame's triangles, barycentrics, interpolated P' and N, lights and
// material, with phong.h's own functions). Mistakes compose: the image of several at once is
// rendered with all of them. The diagnosis is greedy, as matching pursuit is: the mistake that
// removes most of the difference (the sum over pixels and channels of |ours - theirs|) is
// applied first, the rest ranked again on what remains (a few hypotheses kept at each step,
// so that one mistake imitating another does not hide the right pair), and what no mistake
// removes is said as unexplained. The lecture's stages know nothing of these mistakes.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/analysis/screen_map.h"
#include "pipeline/core/diagnostics.h"
#include "pipeline/core/math.h"
#include "pipeline/core/message.h"
#include "pipeline/io/hw2_reader.h"
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
    VertexSnap,    // vertices rounded against truncated (or, Slip::amount kKeptFractional,
                   // kept fractional)
    FillRule,      // inclusive edges against top-left
    ByteRounding,  // bytes rounded against truncated: off by one
    ColourWrap,    // bytes wrap past 255 instead of clamping
    PainterOrder,  // the painter's order instead of the z-buffer
    DepthTies,     // <= against < in the depth test
    Background,    // another colour (or alpha) where no triangle is
    Alpha,         // another alpha where a triangle is
    // The transform stages and the rest of seed 000's lighting.
    LightInWorld,           // the light's world position used as its view position
    LightWithoutC,          // the light taken to view coordinates without - C
    ViewVectorReversed,     // V = P' instead of -P' (or L = P' - Pl: the same image)
    AmbientIaOnly,          // ambient Ia instead of Ia ka
    TermsTruncated,         // each Phong term truncated to a whole byte before the sum
    EpsilonSpecialCases,    // V.N, N.L and R.V tested against Slip::amount (or
                            // kSpecialCaseEpsilon), not 0
    DepthReversed,          // the farther fragment wins the depth test
    ColourOffset,           // every covered byte off by a constant (Slip::amount)
    ColourScale,            // every colour multiplied by a constant (Slip::amount)
    VertexNormalsUnnormalised,  // the sums of the triangle normals left at their length
    AreaWeightedNormals,        // triangle normals summed before they are normalised
    BasisNNotNormalised,        // N not normalised before V - (V.N) N, nor after
    BasisUReversed,             // U = V x N instead of N x V
    ScreenMap,  // the screen mapped another way: stretched, flipped, turned, shifted (Slip::map)
    NormalsSharedByPosition,  // vertex normals summed over every vertex at one position
    CommandMisread,  // a command file's command misread (compareCommandFile; Finding::command)
    FittedLighting,  // the lighting their colours say they used (lighting_fit.h)
};

// The mistakes the search composes (CommandMisread is found by compareCommandFile alone).
inline constexpr std::size_t kMistakeCount = 35;

// VertexSnap's amount for vertices never made whole: kept fractional.
inline constexpr double kKeptFractional = 2.0;

// The small number a student tests the special cases against (EpsilonSpecialCases).
inline constexpr float kSpecialCaseEpsilon = 1e-3f;

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

// One mistake with what it needs: Shifted its shift, Background and Alpha the colour or
// alpha of `value`, ColourOffset (bytes) and ColourScale their amount, ScreenMap its map.
struct Slip {
    Mistake mistake{};
    ivec2 shift = ivec2(1, 0);
    std::array<std::uint8_t, 4> value{};
    double amount = 0.0;
    rl::ScreenMap map;
};

// Our image as it would be with all these mistakes at once; none when one of them cannot
// happen in this scene (no Phong draw to shade Gouraud, no colour above the scale to wrap
// ...) or two cannot go together (Gouraud and Flat).
Result<std::optional<Rgba8Image>> imageWithMistakes(const OurFrame& ours,
                                                    const std::vector<Slip>& slips);
// The same for one mistake.
Result<std::optional<Rgba8Image>> imageWithMistake(const OurFrame& ours, Mistake mistake,
                                                   ivec2 shift = ivec2(1, 0),
                                                   std::array<std::uint8_t, 4> value = {},
                                                   double amount = 0.0);

struct PixelExample {
    int x = 0;
    int y = 0;
    std::array<std::uint8_t, 4> ours{}, theirs{};
};

struct Finding {
    Mistake mistake{};
    Slip slip;  // the mistake with its shift, colour or amount
    // Messages (pipeline/core/message.h), so that the window shows them translated.
    Message title;              // "the ambient term multiplied by the object colour: ..."
    Message evidence;           // how the hypothesis made their pixels, and what it would spoil
    Message advice;             // what to look at in one's code
    // With the findings above it applied: the differing pixels it makes match, the pixels
    // that matched and would not, and the difference it removes (of the sum over pixels and
    // channels of |ours - theirs|), as a share of the whole difference.
    std::size_t explained = 0;
    std::size_t spoiled = 0;
    std::uint64_t removed = 0;
    double share = 0.0;
    std::vector<PixelExample> examples;
    Hw2Misreading command;  // CommandMisread: the line and how it was misread
    bool given = false;     // one of CompareOptions::given
};

// A mistake that removes less than this share of the difference is not reported: chance, or
// a rounding that another mistake's bytes happen to share; unless it removes kLaterShare of
// what the findings before it leave (covered pixels diagnosed after a background), and at
// least kTinyShare of the whole.
inline constexpr double kLeastShare = 0.005;
inline constexpr double kLaterShare = 0.05;
inline constexpr double kTinyShare = 0.0005;
// The diagnosis composes at most this many mistakes, and keeps this many hypotheses at each
// step of its search.
inline constexpr std::size_t kMostFindings = 6;
inline constexpr std::size_t kBeamWidth = 3;

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
    std::uint64_t difference = 0;  // the sum over pixels and channels of |ours - theirs|
    // The mistakes in the order the greedy search applied them, each removing what it removes
    // given those above it.
    std::vector<Finding> diagnosis;
    // What stays with every finding applied: the share of the difference, and the pixels that
    // still differ.
    double unexplained = 0.0;
    std::size_t unexplainedPixels = 0;
    // Most of the difference, or most of the differing pixels, stays unexplained.
    bool mostlyUnexplained() const { return unexplained > 0.5 || unexplainedPixels * 2 > differing; }
    // Their image unlit: one colour wherever it is not their background. Then only coverage
    // is compared (our covered pixels in their colour), with the projection and scan
    // conversion mistakes alone.
    bool unlit = false;
    std::array<std::uint8_t, 4> unlitColour{};
    // Unlit in white: also what a lit image becomes with every colour multiplied by 255.
    bool unlitWhite() const {
        return unlit && unlitColour[0] == 255 && unlitColour[1] == 255 && unlitColour[2] == 255;
    }
    std::size_t coveredByBoth = 0;
    // Our image darkened, differing pixels from yellow (a small difference) to red (large),
    // magenta where only we cover a pixel, cyan where only they do.
    Rgba8Image differenceImage;
};

// How a comparison runs.
struct CompareOptions {
    // A lossy image (JPEG) is compared with a tolerance: channels that differ by at most that
    // much count as the same.
    int tolerance = 0;
    // Whether the general map of the screen is fitted (compareCommandFile tries the commands
    // misread first: a translation ignored is a shift, better named by its line).
    bool screenMap = true;
    // Mistakes already found elsewhere (check's stages): each applied first, in this order,
    // when it brings ours nearer theirs; and mistakes ruled out (a stage that passed
    // contradicts them), never tried.
    std::vector<Slip> given;
    std::vector<Mistake> excluded;
    // Set from another thread, it stops the comparison with the error "comparison cancelled".
    const std::atomic<bool>* cancel = nullptr;
    bool cancelled() const { return cancel && cancel->load(); }
};

// Compares their image (our size) with our frame and ranks the mistakes.
Result<ImageComparison> compareWithOurs(const OurFrame& ours, const Rgba8Image& theirs,
                                        const CompareOptions& options = {});

// A command file's image (image `index` of the text): the comparison as compareWithOurs
// makes it, unless one command misread (each of possibleMisreadings in turn: ignored,
// multiplied on the other side, transposed, its angle in radians, lookat's side vector
// unnormalised) leaves less unexplained with the catalogue's mistakes on top. Then that
// command is the first finding, "line 12: 'multmv' ignored", and the rest are ranked on it.
// colourOnly: their format has no alpha, so theirs holds ours and only colours count.
Result<ImageComparison> compareCommandFile(const OurFrame& ours, const Rgba8Image& theirs,
                                           const CompareOptions& options, std::string_view text,
                                           const std::string& fileName,
                                           const TextureLoader& loadTexture, std::size_t index,
                                           bool colourOnly);

// A comparison with `first` put first: base (ours against theirs) gives the summary, the
// alternative image (ours with the first finding) its share, and onAlternative (compared on
// that image's frame) the findings after it; shares and what stays unexplained are of the
// whole difference.
ImageComparison firstFinding(ImageComparison base, const OurFrame& ours,
                             const Rgba8Image& alternative, Finding first,
                             ImageComparison onAlternative, const Rgba8Image& theirs);

// The map of the screen a finding moves our image by (a mirror, upside down, a shift, the
// fitted screen map); none for the other mistakes.
std::optional<rl::ScreenMap> screenMapOf(const Finding& finding, int width, int height);
// Their image moved first of all: the first finding's map, when it is a move and removes at
// least half the difference. Their colour of our pixel's point of the surface is then theirs
// where the map takes it (a move found further down may stand in for something else).
std::optional<rl::ScreenMap> dominantMove(const ImageComparison& comparison);

// Where their larger image holds ours exactly (a screenshot with a window border): the
// offset of our top-left pixel in theirs; none when no offset matches 95% of ours.
std::optional<ivec2> findEmbedded(const Rgba8Image& ours, const Rgba8Image& theirs);

}  // namespace rl
