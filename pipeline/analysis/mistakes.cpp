#include "mistakes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <set>

#include "pipeline/analysis/mistake_images.h"
#include "pipeline/core/format.h"
#include "pipeline/render/renderer.h"

namespace rl {

namespace {

using Bytes = std::array<std::uint8_t, 4>;

// The names of the mistakes, in the order of the enum.
constexpr std::array<const char*, kMistakeCount + 2> kIds = {
    "ambient-times-od",
    "normal-not-flipped",
    "specular-where-rv-negative",
    "light-behind-not-skipped",
    "normal-not-normalised",
    "gouraud",
    "flat",
    "phong",
    "mirrored-left-right",
    "upside-down",
    "shifted",
    "sample-offset",
    "vertex-snap",
    "fill-rule",
    "byte-rounding",
    "colour-wrap",
    "painter-order",
    "depth-ties",
    "background",
    "alpha",
    "light-in-world",
    "light-without-c",
    "view-vector-reversed",
    "ambient-ia-only",
    "terms-truncated",
    "epsilon-special-cases",
    "depth-reversed",
    "colour-offset",
    "colour-scale",
    "vertex-normals-unnormalised",
    "area-weighted-normals",
    "basis-n-not-normalised",
    "basis-u-reversed",
    "screen-map",
    "normals-shared-by-position",
    "command-misread",
    "fitted-lighting",
};

Bytes bytesAt(const Rgba8Image& image, int x, int y) {
    const std::uint8_t* p = image.pixel(x, y);
    return {p[0], p[1], p[2], p[3]};
}

void put(Rgba8Image& image, int x, int y, const Bytes& b) {
    std::uint8_t* p = image.rgba.data() + (static_cast<std::size_t>(y) * image.width + x) * 4;
    std::copy(b.begin(), b.end(), p);
}

// The largest difference of a channel between two pixels.
int distance(const Bytes& a, const Bytes& b) {
    int d = 0;
    for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
    return d;
}

const char* modelName(Mistake mistake) {
    return shadingModelName(mistake == Mistake::Gouraud ? ShadingModel::Gouraud
                            : mistake == Mistake::Flat  ? ShadingModel::Flat
                                                        : ShadingModel::Phong);
}

Message bytesMessage(const Bytes& b) {
    return "(%1, %2, %3, %4)"_msg(int(b[0]), int(b[1]), int(b[2]), int(b[3]));
}

// A number of the map as the title shows it: `decimals` after the point at most.
Message mapNumber(double value, int decimals) {
    const double unit = std::pow(10.0, decimals);
    const double shown = std::round(value * unit) / unit;
    return Message::untranslated(formatNumber(shown == 0.0 ? 0.0 : shown));
}

// The fitted screen map in words (mirrored, swapped, turned, stretched, its centre moved)
// and as its formula.
Message screenMapTitle(const ScreenMap& m, int width, int height) {
    std::vector<Message> parts;
    const double size = std::sqrt(std::abs(m.determinant()));
    double across = 1.0, down = 1.0;
    if (std::abs(m.xy) + std::abs(m.yx) < 0.02 * size) {
        if (m.xx < 0.0) parts.push_back("mirrored left-right"_msg);
        if (m.yy < 0.0) parts.push_back("upside down"_msg);
        across = std::abs(m.xx), down = std::abs(m.yy);
    } else if (std::abs(m.xx) + std::abs(m.yy) < 0.02 * size) {
        // Their x from our y, their y from our x; with y down, (1, 0) to (0, 1) turns clockwise.
        parts.push_back(m.xy > 0.0 && m.yx > 0.0   ? "x and y swapped (transposed)"_msg
                        : m.xy < 0.0 && m.yx < 0.0 ? "x and y swapped and both mirrored"_msg
                        : m.yx > 0.0               ? "turned 90 degrees clockwise"_msg
                                                   : "turned 90 degrees counter-clockwise"_msg);
        across = std::abs(m.xy), down = std::abs(m.yx);
    } else {
        const double angle = std::atan2(m.yx, m.xx) * 180.0 / std::numbers::pi;
        parts.push_back(angle > 0.0 ? "turned %1 degrees clockwise"_msg(mapNumber(angle, 1))
                                    : "turned %1 degrees counter-clockwise"_msg(mapNumber(-angle, 1)));
        across = std::hypot(m.xx, m.yx), down = std::hypot(m.xy, m.yy);
    }
    const bool wider = std::abs(across - 1.0) > 0.005, taller = std::abs(down - 1.0) > 0.005;
    if (wider && taller)
        parts.push_back("stretched %1 times across and %2 times up and down"_msg(
            mapNumber(across, 3), mapNumber(down, 3)));
    else if (wider || taller)
        parts.push_back(wider ? "stretched %1 times across"_msg(mapNumber(across, 3))
                              : "stretched %1 times up and down"_msg(mapNumber(down, 3)));
    // One of the image's sides where the other belongs: the stretch is their ratio.
    const double sides = double(width) / height, ratio = down / across;
    if (width != height && (std::abs(ratio - sides) < 0.002 * sides ||
                            std::abs(ratio - 1.0 / sides) < 0.002 / sides))
        parts.push_back("the ratio of the image's sides (one size used for both axes)"_msg);
    const dvec2 centre(width / 2.0, height / 2.0);
    const dvec2 moved = m.theirPoint(centre) - centre;
    if (glm::length(moved) > 0.5)
        parts.push_back("its centre moved by (%1, %2) pixels"_msg(mapNumber(moved.x, 1),
                                                                  mapNumber(moved.y, 1)));
    Message words = parts.empty() ? Message() : parts.front();
    for (std::size_t k = 1; k < parts.size(); ++k) words = "%1, %2"_msg(words, parts[k]);
    return "the screen mapped another way: theirs is ours %1 (x' = %2 x + %3 y + %4, y' = %5 x + "
           "%6 y + %7)"_msg(words, mapNumber(m.xx, 3), mapNumber(m.xy, 3), mapNumber(m.tx, 1),
                            mapNumber(m.yx, 3), mapNumber(m.yy, 3), mapNumber(m.ty, 1));
}

// The titles of the transform stages', the constants' and the normals' mistakes, and of the
// screen map (the catalogue's later part); titleOf gives the others.
Message laterTitleOf(const Scene& scene, const Slip& slip) {
    switch (slip.mistake) {
        case Mistake::LightInWorld:
            return "the light not taken to view coordinates: its world position used as "
                   "Pl_view"_msg;
        case Mistake::LightWithoutC:
            return "the light taken to view coordinates without subtracting C: [I] Pl instead "
                   "of [I](Pl - C)"_msg;
        case Mistake::ViewVectorReversed:
            return "V = P' instead of -P' (L = P' - Pl gives the same image)"_msg;
        case Mistake::AmbientIaOnly:
            return "the ambient term Ia instead of Ia*ka"_msg;
        case Mistake::TermsTruncated:
            return "each Phong term truncated to a whole byte before the sum"_msg;
        case Mistake::EpsilonSpecialCases:
            return "V.N, N.L and R.V tested against %1 instead of 0"_msg(
                formatNumber(slip.amount > 0.0 ? slip.amount : double(kSpecialCaseEpsilon)));
        case Mistake::DepthReversed:
            return "the depth test reversed: the farther fragment wins (> against a buffer "
                   "cleared to -infinity, or to 0)"_msg;
        case Mistake::ColourOffset:
            return "every covered pixel's colour off by %1 (a constant offset)"_msg(
                static_cast<int>(std::lround(slip.amount)));
        case Mistake::ColourScale:
            if (slip.amount == 255.0)
                return "every colour multiplied by 255: a colour scaled by 255 where it was "
                       "already 0..255"_msg;
            if (slip.amount == 1.0 / 255.0)
                return "every colour divided by 255: a colour scaled to 0..1 where the scene's "
                       "are 0..255"_msg;
            return "every colour multiplied by %1 (a constant scale)"_msg(formatNumber(slip.amount));
        case Mistake::VertexNormalsUnnormalised:
            return "the vertex normals left at the length of their sums (not normalised)"_msg;
        case Mistake::AreaWeightedNormals:
            return "the triangle normals summed at their length (area-weighted) instead of "
                   "normalised first"_msg;
        case Mistake::BasisNNotNormalised:
            return "the camera's N not normalised before V - (V.N)N, nor after"_msg;
        case Mistake::BasisUReversed:
            return "the camera's U = V x N instead of N x V (x runs the other way)"_msg;
        case Mistake::ScreenMap:
            return screenMapTitle(slip.map, scene.width, scene.height);
        case Mistake::NormalsSharedByPosition:
            return "the vertex normals summed over every vertex at the same position instead of "
                   "by the vertex's index (a faceted mesh drawn smooth)"_msg;
        default:
            return {};  // CommandMisread, FittedLighting: titled where found
    }
}

Message titleOf(const OurFrame& ours, const Slip& slip) {
    const Mistake mistake = slip.mistake;
    const ivec2 shift = slip.shift;
    const Bytes& value = slip.value;
    const Scene& scene = *ours.trace->scene;
    const RasterRules& rules = scene.rules;
    const bool truncated = rules.snap == RasterRules::VertexSnap::Truncate;
    switch (mistake) {
        case Mistake::AmbientTimesOd:
            return "the ambient term multiplied by the object colour: Ia*ka*Od instead of Ia*ka"_msg;
        case Mistake::NormalNotFlipped:
            return "the normal not turned toward the viewer where V.N < 0"_msg;
        case Mistake::SpecularWhereRvNegative:
            return "specular added where R.V < 0 (no check before (R.V)^n)"_msg;
        case Mistake::LightBehindNotSkipped:
            return "diffuse and specular computed where N.L < 0 (the light is behind the "
                   "surface)"_msg;
        case Mistake::NormalNotNormalised:
            return "the interpolated normal not normalised"_msg;
        case Mistake::Gouraud:
        case Mistake::Flat:
        case Mistake::Phong: {
            const char* model = modelName(mistake);
            const auto asked = sceneModel(scene);
            if (!asked) return "%1 shading where another model was asked"_msg(model);
            return "%1 shading where %2 was asked"_msg(model, shadingModelName(*asked));
        }
        case Mistake::MirroredLeftRight:
            return "the image mirrored left-right (x runs the other way)"_msg;
        case Mistake::UpsideDown:
            return "the image upside down (row 0 at the bottom: y not flipped)"_msg;
        case Mistake::Shifted:
            return "the image shifted by one pixel: (%1, %2)"_msg(shift.x, shift.y);
        case Mistake::SampleOffset:
            return rules.sampleOffset == 0.0
                       ? "pixels sampled at their centres (x + 0.5) instead of their corners"_msg
                       : "pixels sampled at their corners instead of their centres (x + 0.5)"_msg;
        case Mistake::VertexSnap:
            if (slip.amount == kKeptFractional)
                return "vertex positions kept fractional (never made whole) instead of "
                       "truncated to whole pixels"_msg;
            if (rules.snap == RasterRules::VertexSnap::None)
                return "vertex positions truncated to the sub-pixel grid instead of kept as "
                       "computed"_msg;
            if (rules.subpixelBits == 0)
                return truncated ? "vertex positions rounded instead of truncated to whole "
                                   "pixels"_msg
                                 : "vertex positions truncated instead of rounded to whole "
                                   "pixels"_msg;
            return truncated ? "vertex positions rounded instead of truncated to the sub-pixel "
                               "grid"_msg
                             : "vertex positions truncated instead of rounded to the sub-pixel "
                               "grid"_msg;
        case Mistake::FillRule:
            return rules.fill == RasterRules::FillRule::Inclusive
                       ? "the top-left fill rule where edges are inclusive"_msg
                       : "inclusive edges where the fill rule is top-left"_msg;
        case Mistake::ByteRounding:
            return scene.conventions.rounding == ByteRounding::Truncate
                       ? "colour bytes rounded instead of truncated (off by one)"_msg
                       : "colour bytes truncated instead of rounded (off by one)"_msg;
        case Mistake::ColourWrap:
            return "colours above 255 wrap around instead of clamping"_msg;
        case Mistake::PainterOrder:
            return "the painter's order (far to near, no depth test) instead of the z-buffer"_msg;
        case Mistake::DepthTies:
            return scene.conventions.depthWinsOnTie
                       ? "z < stored instead of z <= stored in the depth test (ties keep the "
                         "earlier triangle)"_msg
                       : "z <= stored instead of z < stored in the depth test (ties go to the "
                         "later triangle)"_msg;
        case Mistake::Background:
            return "a different background: %1 where the scene's is %2"_msg(
                bytesMessage(value), bytesMessage(backgroundBytes(scene.conventions)));
        case Mistake::Alpha:
            return "alpha %1 on covered pixels instead of 255"_msg(int(value[3]));
        default:
            return laterTitleOf(scene, slip);
    }
    return {};
}

// How the hypothesis made its image.
Message mechanismOf(Mistake mistake) {
    switch (mistake) {
        case Mistake::AmbientTimesOd:
        case Mistake::NormalNotFlipped:
        case Mistake::SpecularWhereRvNegative:
        case Mistake::LightBehindNotSkipped:
        case Mistake::NormalNotNormalised:
        case Mistake::ViewVectorReversed:
        case Mistake::AmbientIaOnly:
        case Mistake::TermsTruncated:
        case Mistake::EpsilonSpecialCases:
        case Mistake::VertexNormalsUnnormalised:
        case Mistake::AreaWeightedNormals:
        case Mistake::NormalsSharedByPosition:
            return "our pixels lit again with that formula (the same triangles, barycentrics, "
                   "P', N, lights and material) give theirs"_msg;
        case Mistake::Gouraud:
        case Mistake::Flat:
        case Mistake::Phong:
            return "the scene rendered again in that shading model gives their pixels"_msg;
        case Mistake::MirroredLeftRight:
        case Mistake::UpsideDown:
        case Mistake::Shifted:
            return "our image moved that way gives their pixels"_msg;
        case Mistake::SampleOffset:
        case Mistake::VertexSnap:
        case Mistake::FillRule:
        case Mistake::DepthTies:
            return "the scene rendered again with that rule gives their pixels"_msg;
        case Mistake::ByteRounding:
        case Mistake::ColourWrap:
            return "our float colours made bytes that way give their pixels"_msg;
        case Mistake::PainterOrder:
            return "the scene painted far to near without a depth test gives their pixels"_msg;
        case Mistake::Background:
            return "their pixels where no triangle of ours is take that colour"_msg;
        case Mistake::Alpha:
            return "their pixels where a triangle of ours is take that alpha"_msg;
        case Mistake::LightInWorld:
        case Mistake::LightWithoutC:
            return "the scene rendered again with the light where that transform puts it gives "
                   "their pixels"_msg;
        case Mistake::DepthReversed:
            return "the scene rendered again with the farther fragment winning gives their "
                   "pixels"_msg;
        case Mistake::BasisNNotNormalised:
        case Mistake::BasisUReversed:
            return "the scene rendered again in view coordinates made with that basis gives "
                   "their pixels"_msg;
        case Mistake::ScreenMap:
            return "our image carried by that map of the screen (each pixel from the nearest of "
                   "ours) gives their pixels"_msg;
        case Mistake::CommandMisread:
            return "the command file read again with that command so gives their pixels"_msg;
        case Mistake::FittedLighting:
            return "the scene rendered again with the fitted lighting gives their pixels"_msg;
        case Mistake::ColourOffset:
            return "our bytes moved by that constant give their pixels"_msg;
        case Mistake::ColourScale:
            return "our colours multiplied by that constant give their pixels"_msg;
    }
    return {};
}

// What to look at in one's code for each mistake.
Message hintOf(Mistake mistake) {
    switch (mistake) {
        case Mistake::AmbientTimesOd:
            return "seed 000's ambient term is Ia*ka, without the object colour Od"_msg;
        case Mistake::NormalNotFlipped:
            return "seed 000: if V.N < 0, N := -N before the lighting"_msg;
        case Mistake::SpecularWhereRvNegative:
            return "seed 000: if R.V < 0, no specular term"_msg;
        case Mistake::LightBehindNotSkipped:
            return "seed 000: if N.L < 0, neither diffuse nor specular"_msg;
        case Mistake::NormalNotNormalised:
            return "the interpolated N is shorter than 1: normalise it before N.L and R"_msg;
        case Mistake::Gouraud:
        case Mistake::Flat:
        case Mistake::Phong:
            return "check where the lighting is evaluated: per pixel, per vertex or per "
                   "triangle"_msg;
        case Mistake::MirroredLeftRight:
            return "check the sign of x in the projection or the screen mapping"_msg;
        case Mistake::UpsideDown:
            return "screen row 0 is the top: y = (1 - y_ndc) * height / 2"_msg;
        case Mistake::Shifted:
            return "check the screen mapping's offsets and the first pixel of each span"_msg;
        case Mistake::SampleOffset:
            return "where a pixel is sampled decides which pixels an edge covers (--rules)"_msg;
        case Mistake::VertexSnap:
            return "check how screen coordinates become whole pixels ((int) truncates)"_msg;
        case Mistake::FillRule:
            return "the pixels exactly on an edge: which triangle (or both) covers them"_msg;
        case Mistake::ByteRounding:
            return "check how the colour becomes a byte: (int) truncates, + 0.5 rounds"_msg;
        case Mistake::ColourWrap:
            return "clamp each channel to 255 before writing it as a byte"_msg;
        case Mistake::PainterOrder:
            return "keep a depth buffer and write a pixel only when the fragment is nearer"_msg;
        case Mistake::DepthTies:
            return "the comparison of the depth test: < keeps the first of two equal depths"_msg;
        case Mistake::Background:
            return "the colour (and alpha) of the pixels no triangle covers"_msg;
        case Mistake::Alpha:
            return "the alpha written with each shaded pixel"_msg;
        case Mistake::LightInWorld:
            return "seed 000: the light goes to view coordinates as the vertices do, Pl_view = "
                   "[I](Pl - C)"_msg;
        case Mistake::LightWithoutC:
            return "seed 000: Pl_view = [I](Pl - C): subtract C before the change of basis"_msg;
        case Mistake::ViewVectorReversed:
            return "V points from the surface to the camera: V = -P' in view coordinates, and "
                   "L = Pl - P'"_msg;
        case Mistake::AmbientIaOnly:
            return "seed 000's ambient term is Ia*ka"_msg;
        case Mistake::TermsTruncated:
            return "add the terms as real numbers and make a byte once, at the end"_msg;
        case Mistake::EpsilonSpecialCases:
            return "seed 000's special cases test against 0: V.N < 0, N.L < 0, R.V < 0"_msg;
        case Mistake::DepthReversed:
            return "the z-buffer starts at +infinity and a fragment is written when its z is "
                   "smaller"_msg;
        case Mistake::ColourOffset:
            return "look for a constant added to every colour, or bytes made with an offset"_msg;
        case Mistake::ColourScale:
            return "look for a factor on every colour: an intensity scaled, or another colour "
                   "scale"_msg;
        case Mistake::VertexNormalsUnnormalised:
            return "seed 000: each vertex normal is the normalised sum of its triangles' "
                   "normals"_msg;
        case Mistake::AreaWeightedNormals:
            return "normalise each triangle's normal before adding it to its vertices"_msg;
        case Mistake::BasisNNotNormalised:
            return "seed 000's Gram-Schmidt: normalise N first, then V - (V.N)N is V's part "
                   "across N"_msg;
        case Mistake::BasisUReversed:
            return "seed 000: U = N x V, so that U, V, N is right-handed"_msg;
        case Mistake::NormalsSharedByPosition:
            return "seed 000: a vertex's normal sums the normals of the triangles that use that "
                   "vertex, by its index; vertices repeated at one position keep their own"_msg;
        case Mistake::ScreenMap:
            return "check the screen formulas, x = (x_ndc + 1) * width / 2 and y = (1 - y_ndc) * "
                   "height / 2, each with its own size, and that pixel (x, y) is written at "
                   "column x of row y"_msg;
        case Mistake::CommandMisread:
            return {};  // misreadingHint: it depends on how the command was misread
        case Mistake::FittedLighting:
            return "compare the light's position, the intensities and the coefficients your "
                   "program uses with the fitted ones"_msg;
    }
    return {};
}

}  // namespace

const char* mistakeId(Mistake mistake) {
    return kIds[static_cast<std::size_t>(mistake)];
}

std::optional<Mistake> mistakeFromId(std::string_view id) {
    for (std::size_t i = 0; i < kIds.size(); ++i)
        if (id == kIds[i]) return static_cast<Mistake>(i);
    return std::nullopt;
}

Result<OurFrame> renderOurFrame(std::shared_ptr<const Scene> scene) {
    RenderOptions options;  // keeps the z-buffer, ids and barycentrics
    auto trace = renderFrame(scene, options);
    if (!trace) return trace.error();
    OurFrame frame;
    frame.trace = std::make_shared<const FrameTrace>(std::move(trace.value()));
    frame.image = colourImage(*frame.trace->shading, *frame.trace->depth, scene->conventions);
    return frame;
}

namespace {

// The sum over pixels and channels of |a - b|.
std::uint64_t differenceOf(const Rgba8Image& a, const Rgba8Image& b) {
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i)
        sum += static_cast<std::uint64_t>(std::abs(int(a.rgba[i]) - int(b.rgba[i])));
    return sum;
}

// The colour most of their pixels take where `where` holds.
template <typename Where>
std::optional<Bytes> mostCommon(const Rgba8Image& theirs, Where where, std::size_t* count = nullptr,
                                std::size_t* total = nullptr) {
    std::map<Bytes, std::size_t> counts;
    std::size_t all = 0;
    for (int y = 0; y < theirs.height; ++y)
        for (int x = 0; x < theirs.width; ++x)
            if (where(x, y)) ++counts[bytesAt(theirs, x, y)], ++all;
    if (counts.empty()) return std::nullopt;
    const auto best = std::max_element(
        counts.begin(), counts.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
    if (count) *count = best->second;
    if (total) *total = all;
    return best->first;
}

// The mistakes that change only which pixels are covered: all an unlit image can show.
bool changesCoverage(Mistake mistake) {
    switch (mistake) {
        case Mistake::MirroredLeftRight:
        case Mistake::UpsideDown:
        case Mistake::Shifted:
        case Mistake::SampleOffset:
        case Mistake::VertexSnap:
        case Mistake::FillRule:
        case Mistake::ScreenMap:
            return true;
        default:
            return false;
    }
}

// A hypothesis's mistakes, in any order, with what each needs.
std::string keyOf(std::vector<Slip> slips) {
    std::sort(slips.begin(), slips.end(),
              [](const Slip& a, const Slip& b) { return a.mistake < b.mistake; });
    std::string key;
    for (const Slip& s : slips) {
        char text[192];
        std::snprintf(text, sizeof text, "%s %d %d %d %d %d %d %g %g %g %g %g %g %g;",
                      mistakeId(s.mistake), s.shift.x, s.shift.y, s.value[0], s.value[1],
                      s.value[2], s.value[3], s.amount, s.map.xx, s.map.xy, s.map.yx, s.map.yy,
                      s.map.tx, s.map.ty);
        key += text;
    }
    return key;
}

// The search: hypotheses composed on the frames their render-changing mistakes make
// (each frame rendered once), their images scored by the difference to theirs.
class Search {
public:
    Search(const OurFrame& ours, const Rgba8Image& theirs, int tolerance,
           const CompareOptions& options)
        : m_ours(ours), m_theirs(theirs), m_tolerance(tolerance), m_options(options) {}

    bool cancelled() const { return m_options.cancelled(); }

    // Compare coverage only: an image's covered pixels in `colour`, the rest `background`.
    void coverageOnly(const Bytes& colour, const Bytes& background) {
        m_flat = std::pair(colour, background);
    }

    Rgba8Image flattened(Rgba8Image image) const {
        if (!m_flat) return image;
        const Bytes ourBackground = backgroundBytes(m_ours.trace->scene->conventions);
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                put(image, x, y, bytesAt(image, x, y) == ourBackground ? m_flat->second : m_flat->first);
        return image;
    }

    Result<std::optional<Rgba8Image>> image(const std::vector<Slip>& slips) {
        std::string key;
        std::vector<Slip> rendering;
        for (const Slip& slip : slips)
            if (changesTheRender(slip.mistake)) {
                char amount[32];
                std::snprintf(amount, sizeof amount, " %.17g;", slip.amount);
                key += mistakeId(slip.mistake) + std::string(amount);
                rendering.push_back(slip);
            }
        auto found = m_frames.find(key);
        if (found == m_frames.end()) {
            auto frame = frameWithMistakes(m_ours, rendering);
            if (!frame) return frame.error();
            found = m_frames.emplace(key, std::move(frame.value())).first;
        }
        if (!found->second) return std::optional<Rgba8Image>();
        auto image = imageOnFrame(m_ours, *found->second, slips);
        if (!image) return image.error();
        if (image.value()) *image.value() = flattened(std::move(*image.value()));
        return image;
    }

    // The variants of a mistake worth trying against their image, `current` the image with
    // the findings so far: each shift, the background and alpha they use, the constant
    // offset or scale their bytes show.
    std::vector<Slip> variants(Mistake mistake, const Rgba8Image& current) const {
        Slip slip{mistake, ivec2(1, 0), {}, 0.0, {}};
        switch (mistake) {
            case Mistake::Shifted: {
                std::vector<Slip> out;
                for (ivec2 s : {ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1), ivec2(1, 1),
                                ivec2(-1, -1), ivec2(1, -1), ivec2(-1, 1)})
                    out.push_back({mistake, s, {}, 0.0, {}});
                return out;
            }
            case Mistake::VertexSnap: {
                // Rounded against truncated, and (where the rules snap to whole pixels) kept
                // fractional, the (int) cast left out.
                std::vector<Slip> out{slip};
                const RasterRules& rules = m_ours.trace->scene->rules;
                if (rules.snap != RasterRules::VertexSnap::None && rules.subpixelBits == 0)
                    out.push_back({mistake, ivec2(1, 0), {}, kKeptFractional, {}});
                return out;
            }
            case Mistake::ScreenMap:
                if (!screenFit()) return {};
                slip.map = screenFit()->map;
                return {slip};
            case Mistake::Background:
            case Mistake::Alpha: {
                const bool covered = mistake == Mistake::Alpha;
                const auto common = mostCommon(
                    m_theirs, [&](int x, int y) { return m_ours.covered(x, y) == covered; });
                if (!common) return {};
                slip.value = *common;
                return {slip};
            }
            case Mistake::ColourOffset: {
                // The most common non-zero difference of a covered channel, when at least half
                // the channels that differ differ by it: a constant, not a mistake whose
                // differences vary from pixel to pixel.
                std::map<int, std::size_t> counts;
                std::size_t differing = 0;
                forCoveredChannels(current, [&](int ours, int theirs) {
                    if (theirs != ours && ours > 0 && ours < 255) ++counts[theirs - ours], ++differing;
                });
                if (counts.empty()) return {};
                const auto mode = std::max_element(
                    counts.begin(), counts.end(), [](auto& a, auto& b) { return a.second < b.second; });
                if (mode->second * 2 < differing) return {};
                slip.amount = mode->first;
                return {slip};
            }
            case Mistake::ColourScale: {
                // Least squares over the channels neither side clamps, theirs = s ours, on
                // the values the bytes stand for (a truncated byte b for b + 0.5); then the
                // estimate and its neighbours a thousandth apart, for the difference to decide.
                const bool truncated =
                    m_ours.trace->scene->conventions.rounding == ByteRounding::Truncate;
                const double half = truncated ? 0.5 : 0.0;
                // In the same pass, colours taken in 0..1 where the scene's are 0..255, or the
                // other way: theirs all but black (at most 1) or all white where ours is
                // neither; too far off for the fit, which leaves out the channels either side
                // clamps. Tried beside the fit's estimate (a large scale such as 10 saturates
                // most channels too), for the difference to decide.
                double oursTheirs = 0.0, oursSquared = 0.0;
                std::size_t mid = 0, black = 0, white = 0;
                forCoveredChannels(current, [&](int ours, int theirs) {
                    if (ours < 8 || ours > 247) return;
                    ++mid;
                    black += theirs <= 1 ? 1 : 0;
                    white += theirs == 255 ? 1 : 0;
                    if (theirs == 0 || theirs == 255) return;
                    oursTheirs += (ours + half) * (theirs + half);
                    oursSquared += (ours + half) * (ours + half);
                });
                std::vector<Slip> out;
                if (mid > 0 && std::max(black, white) * 10 >= mid * 9) {
                    slip.amount = black > white ? 1.0 / 255.0 : 255.0;
                    out.push_back(slip);
                }
                if (oursSquared == 0.0) return out;
                const double estimate = std::round(oursTheirs / oursSquared * 1000.0) / 1000.0;
                if (std::abs(estimate - 1.0) < 0.004) return out;
                // A scale when at least half those channels are within 2 of it.
                std::size_t near = 0, all = 0;
                forCoveredChannels(current, [&](int ours, int theirs) {
                    if (ours < 8 || ours > 247 || theirs == 0 || theirs == 255) return;
                    ++all;
                    near += std::abs(theirs - ours * estimate) <= 2.0 ? 1 : 0;
                });
                if (near * 2 < all) return out;
                for (double step : {0.0, -0.001, 0.001}) {
                    slip.amount = estimate + step;
                    out.push_back(slip);
                }
                return out;
            }
            default:
                return {slip};
        }
    }

    std::uint64_t differenceTo(const Rgba8Image& image) const { return differenceOf(image, m_theirs); }
    const Rgba8Image& theirs() const { return m_theirs; }

    // The map of the screen that carries our coverage onto theirs (their pixels unlike their
    // background), fitted once; none when it does not halve the pixels covered by one side
    // only, or is one of the image's plain moves (mirrors, a shift of a pixel).
    const std::optional<ScreenMapFit>& screenFit() const {
        if (m_screenFitted) return m_screenFit;
        m_screenFitted = true;
        if (!m_options.screenMap) return m_screenFit;
        const auto background =
            m_flat ? std::optional(m_flat->second)
                   : mostCommon(m_theirs, [&](int x, int y) { return !m_ours.covered(x, y); });
        if (!background) return m_screenFit;
        const int w = m_theirs.width, h = m_theirs.height;
        Coverage ours(w, h), theirs(w, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                ours.at(x, y) = m_ours.covered(x, y) ? 1 : 0;
                theirs.at(x, y) = distance(bytesAt(m_theirs, x, y), *background) > m_tolerance ? 1 : 0;
            }
        // Too few pixels apart for a map to be told from the rules of the scan.
        if (pixelsApart(ours, theirs, ScreenMap{}) < 32) return m_screenFit;
        auto fit = fitScreenMap(ours, theirs);
        if (fit && fit->apartAfter * 2 <= fit->apartBefore && !isPlainMove(fit->map, w, h))
            m_screenFit = fit;
        return m_screenFit;
    }

private:
    template <typename Visit>
    void forCoveredChannels(const Rgba8Image& current, Visit visit) const {
        for (int y = 0; y < current.height; ++y)
            for (int x = 0; x < current.width; ++x)
                if (m_ours.covered(x, y))
                    for (int c = 0; c < 3; ++c)
                        visit(int(current.pixel(x, y)[c]), int(m_theirs.pixel(x, y)[c]));
    }

    const OurFrame& m_ours;
    const Rgba8Image& m_theirs;
    int m_tolerance = 0;
    const CompareOptions& m_options;
    std::optional<std::pair<Bytes, Bytes>> m_flat;
    mutable bool m_screenFitted = false;
    mutable std::optional<ScreenMapFit> m_screenFit;
    std::map<std::string, std::optional<MistakeFrame>> m_frames;
};

// How the finding's hypothesis made their pixels, and what it would spoil.
Message evidenceOf(const Finding& f) {
    if (f.spoiled == 0) return "%1; no pixel that matches now would change"_msg(mechanismOf(f.mistake));
    return counted(static_cast<long long>(f.spoiled), "%2; %1 pixel that matches now would differ"_msg,
                   "%2; %1 pixels that match now would differ"_msg, mechanismOf(f.mistake));
}

// An offset's or a scale's evidence, from the histogram of theirs - ours over the covered
// channels that differ (before the finding): how many are the offset itself, or within 2 of
// the scale times ours.
Message constantEvidence(const OurFrame& ours, const Rgba8Image& before, const Rgba8Image& theirs,
                         const Finding& f) {
    long long differing = 0, agreeing = 0;
    for (int y = 0; y < theirs.height; ++y)
        for (int x = 0; x < theirs.width; ++x) {
            if (!ours.covered(x, y)) continue;
            for (int c = 0; c < 3; ++c) {
                const int o = before.pixel(x, y)[c], t = theirs.pixel(x, y)[c];
                if (o == t) continue;
                ++differing;
                agreeing += f.mistake == Mistake::ColourOffset
                                ? (t - o == static_cast<int>(std::lround(f.slip.amount)) ? 1 : 0)
                                : (std::abs(t - o * f.slip.amount) <= 2.0 ? 1 : 0);
            }
        }
    if (f.mistake == Mistake::ColourOffset)
        return "theirs - ours is %1 in %2 of the %3 covered channels that differ"_msg(
            static_cast<int>(std::lround(f.slip.amount)), agreeing, differing);
    return "theirs is within 2 of %1 times ours in %2 of the %3 covered channels that differ"_msg(
        formatNumber(f.slip.amount), agreeing, differing);
}

// What a finding changes, from the image before it to the image with it: the differing
// pixels it makes match, those it spoils, and three examples spread over the first.
void countPixels(const Rgba8Image& before, const Rgba8Image& after, const Rgba8Image& theirs,
                 int tolerance, Finding& f) {
    std::vector<ivec2> made;
    for (int y = 0; y < theirs.height; ++y) {
        for (int x = 0; x < theirs.width; ++x) {
            const Bytes t = bytesAt(theirs, x, y);
            const bool matched = distance(bytesAt(before, x, y), t) <= tolerance;
            const bool matches = distance(bytesAt(after, x, y), t) <= tolerance;
            if (!matched && matches) made.push_back({x, y});
            if (matched && !matches) ++f.spoiled;
        }
    }
    f.explained = made.size();
    for (std::size_t k : {made.size() / 6, made.size() / 2, made.size() * 5 / 6}) {
        if (k >= made.size()) continue;
        const ivec2 p = made[k];
        if (!f.examples.empty() && f.examples.back().x == p.x && f.examples.back().y == p.y)
            continue;
        f.examples.push_back({p.x, p.y, bytesAt(before, p.x, p.y), bytesAt(theirs, p.x, p.y)});
    }
}

// Their image unlit: one colour (99% of the pixels at least) wherever it is not their
// background, while ours has several and covers at most ten times as many pixels. Their background is what they show most where we
// cover nothing.
std::optional<std::pair<Bytes, Bytes>> unlitColours(const OurFrame& ours, const Rgba8Image& theirs,
                                                    int tolerance) {
    auto background = mostCommon(theirs, [&](int x, int y) { return !ours.covered(x, y); });
    if (!background) return std::nullopt;
    std::size_t count = 0, total = 0;
    const auto colour = mostCommon(
        theirs, [&](int x, int y) { return distance(bytesAt(theirs, x, y), *background) > tolerance; },
        &count, &total);
    if (!colour || count * 100 < total * 99) return std::nullopt;
    std::size_t ourCount = 0, ourTotal = 0;
    mostCommon(ours.image, [&](int x, int y) { return ours.covered(x, y); }, &ourCount, &ourTotal);
    // Ours lit, and theirs covering a tenth of what ours does at least: a few dark pixels
    // (a scene drawn far too small) are not an unlit drawing.
    if (ourCount * 100 >= ourTotal * 99 || total * 10 < ourTotal) return std::nullopt;
    return std::pair(*colour, *background);
}

// The summary of their image against ours (or our coverage): the pixels that differ, by how
// much, and the difference image.
void summarise(const OurFrame& ours, const Rgba8Image& oursShown, const Rgba8Image& theirs,
               const Bytes& theirBackground, ImageComparison& out) {
    std::array<double, 4> sum{};
    out.differenceImage = ours.image;
    for (int y = 0; y < theirs.height; ++y) {
        for (int x = 0; x < theirs.width; ++x) {
            const Bytes a = bytesAt(oursShown, x, y), b = bytesAt(theirs, x, y);
            const bool weCover = ours.covered(x, y),
                       theyCover = distance(b, theirBackground) > out.tolerance;
            out.onlyOurs += weCover && !theyCover ? 1 : 0;
            out.onlyTheirs += !weCover && theyCover ? 1 : 0;
            out.coveredByBoth += weCover && theyCover ? 1 : 0;
            const int d = distance(a, b);
            const Bytes dim = bytesAt(ours.image, x, y);
            Bytes shown = {std::uint8_t(dim[0] / 3), std::uint8_t(dim[1] / 3),
                           std::uint8_t(dim[2] / 3), 255};
            if (d > out.tolerance) {
                ++out.differing;
                for (int c = 0; c < 4; ++c) {
                    const int dc = std::abs(int(a[c]) - int(b[c]));
                    out.largest[c] = std::max(out.largest[c], dc);
                    sum[c] += dc;
                }
                const int t = std::min(255, d * 4);  // yellow for 1, red from 64 up
                shown = weCover && !theyCover   ? Bytes{255, 0, 255, 255}
                        : !weCover && theyCover ? Bytes{0, 255, 255, 255}
                                                : Bytes{255, std::uint8_t(255 - t), 0, 255};
            }
            put(out.differenceImage, x, y, shown);
        }
    }
    for (int c = 0; c < 4; ++c)
        out.mean[c] = out.differing > 0 ? sum[c] / double(out.differing) : 0.0;
    out.difference = differenceOf(oursShown, theirs);
}

// A set of mistakes, the image they make and its difference to theirs.
struct Hypothesis {
    std::vector<Slip> slips;
    Rgba8Image image;
    std::uint64_t difference = 0;
};

Error cancelledError() {
    return makeError(ErrorCode::Usage, {}, "comparison cancelled"_msg);
}

// Greedy, as matching pursuit is, but keeping the kBeamWidth best hypotheses of each round
// rather than one (a beam search): a mistake that imitates another (V reversed for the far
// faces drawn) must not hide the pair that really made their image. A hypothesis grows by a
// mistake only when that removes at least `least`; the best is the one with the least
// difference, each mistake counted as `least` more.
// What a finding must remove from a hypothesis whose difference is `left`: `least` (a share
// of the whole), or kLaterShare of what is left, but never below kTinyShare of the whole.
double enoughOf(double least, double left) {
    return std::max(least * (kTinyShare / kLeastShare), std::min(least, kLaterShare * left));
}

Result<Hypothesis> beamSearch(Search& search, Hypothesis start, double least, bool unlit,
                              const std::vector<Mistake>& excluded) {
    const auto enough = [&](const Hypothesis& h) { return enoughOf(least, double(h.difference)); };
    const auto nearer = [](const Hypothesis& a, const Hypothesis& b) {
        return a.difference < b.difference;
    };
    std::vector<Hypothesis> beam{start};
    Hypothesis chosen = std::move(start);
    for (std::size_t round = 0; round < kMostFindings && !beam.empty(); ++round) {
        std::vector<Hypothesis> next;  // the best few, least difference first
        std::set<std::string> seen;
        for (const Hypothesis& parent : beam) {
            for (std::size_t i = 0; i < kMistakeCount; ++i) {
                const Mistake mistake = static_cast<Mistake>(i);
                if ((unlit && !changesCoverage(mistake)) ||
                    std::find(excluded.begin(), excluded.end(), mistake) != excluded.end() ||
                    std::any_of(parent.slips.begin(), parent.slips.end(),
                                [&](const Slip& s) { return s.mistake == mistake; }))
                    continue;
                if (search.cancelled()) return cancelledError();
                for (const Slip& slip : search.variants(mistake, parent.image)) {
                    std::vector<Slip> trial = parent.slips;
                    trial.push_back(slip);
                    if (!seen.insert(keyOf(trial)).second) continue;
                    auto candidate = search.image(trial);
                    if (!candidate) return candidate.error();
                    if (!candidate.value()) continue;
                    const std::uint64_t d = search.differenceTo(*candidate.value());
                    if (d >= parent.difference || double(parent.difference - d) < enough(parent))
                        continue;
                    if (next.size() == kBeamWidth && d >= next.back().difference) continue;
                    Hypothesis h{std::move(trial), std::move(*candidate.value()), d};
                    next.insert(std::upper_bound(next.begin(), next.end(), h, nearer), std::move(h));
                    if (next.size() > kBeamWidth) next.pop_back();
                }
            }
        }
        if (!next.empty() && next.front().difference < chosen.difference) chosen = next.front();
        if (chosen.difference == 0) break;  // their image made exactly: nothing left to find
        beam = std::move(next);
    }
    return chosen;
}

// The hypothesis the search starts from: each mistake found elsewhere, in order, kept when it
// brings ours nearer theirs.
Result<Hypothesis> withGiven(Search& search, Hypothesis h, const std::vector<Slip>& given) {
    for (const Slip& slip : given) {
        std::vector<Slip> trial = h.slips;
        trial.push_back(slip);
        auto image = search.image(trial);
        if (!image) return image.error();
        if (!image.value()) continue;
        const std::uint64_t d = search.differenceTo(*image.value());
        if (d < h.difference) h = {std::move(trial), std::move(*image.value()), d};
    }
    return h;
}

// An offset or scale was measured before the mistakes found after it: measured again with
// all the others applied, kept when that brings ours nearer theirs.
Status remeasureConstants(Search& search, Hypothesis& h) {
    for (Slip& slip : h.slips) {
        if (slip.mistake != Mistake::ColourOffset && slip.mistake != Mistake::ColourScale) continue;
        std::vector<Slip> others;
        for (const Slip& s : h.slips)
            if (s.mistake != slip.mistake) others.push_back(s);
        auto without = search.image(others);
        if (!without) return without.error();
        if (!without.value()) continue;
        for (const Slip& again : search.variants(slip.mistake, *without.value())) {
            const Slip kept = slip;
            slip = again;
            auto image = search.image(h.slips);
            if (!image) return image.error();
            const std::uint64_t d = image.value() ? search.differenceTo(*image.value()) : 0;
            if (image.value() && d < h.difference) {
                h.difference = d;
                h.image = std::move(*image.value());
            } else {
                slip = kept;
            }
        }
    }
    return success();
}

// A finding the others make redundant, whose leaving out costs less than `least`, is left
// out.
Status dropRedundant(Search& search, Hypothesis& h, double least) {
    for (bool dropped = true; dropped && h.slips.size() > 1;) {
        dropped = false;
        for (std::size_t k = 0; k < h.slips.size() && !dropped; ++k) {
            std::vector<Slip> others = h.slips;
            others.erase(others.begin() + std::ptrdiff_t(k));
            auto image = search.image(others);
            if (!image) return image.error();
            if (!image.value()) continue;
            const std::uint64_t d = search.differenceTo(*image.value());
            if (double(d) >= double(h.difference) + enoughOf(least, double(d))) continue;
            h = {std::move(others), std::move(*image.value()), d};
            dropped = true;
        }
    }
    return success();
}

// The findings of the mistakes applied in order, each with the share it removes given those
// above it.
// `before` is our image as compared (flattened for an unlit image).
Result<std::vector<Finding>> findingsInOrder(Search& search, const OurFrame& ours,
                                             Rgba8Image before, const std::vector<Slip>& applied,
                                             const ImageComparison& out) {
    const Rgba8Image& theirs = search.theirs();
    std::vector<Finding> findings;
    std::uint64_t left = out.difference;
    for (std::size_t k = 0; k < applied.size(); ++k) {
        const std::vector<Slip> upTo(applied.begin(), applied.begin() + std::ptrdiff_t(k) + 1);
        auto image = search.image(upTo);
        if (!image) return image.error();
        Rgba8Image after = image.value() ? std::move(*image.value()) : before;
        const std::uint64_t d = differenceOf(after, theirs);
        Finding f;
        f.mistake = applied[k].mistake;
        f.slip = applied[k];
        f.removed = left > d ? left - d : 0;
        f.share = double(f.removed) / double(out.difference);
        countPixels(before, after, theirs, out.tolerance, f);
        f.title = titleOf(ours, f.slip);
        const auto& fit = search.screenFit();
        f.evidence = f.mistake == Mistake::ColourOffset || f.mistake == Mistake::ColourScale
                         ? constantEvidence(ours, before, theirs, f)
                     : f.mistake == Mistake::ScreenMap && fit
                         ? "%1; pixels covered by one side only: %2 as ours is, %3 with ours "
                           "carried by the map"_msg(evidenceOf(f), fit->apartBefore,
                                                     fit->apartAfter)
                         : evidenceOf(f);
        f.advice = hintOf(f.mistake);
        findings.push_back(std::move(f));
        before = std::move(after);
        left = d;
    }
    return findings;
}

}  // namespace

Result<ImageComparison> compareWithOurs(const OurFrame& ours, const Rgba8Image& theirs,
                                        const CompareOptions& options) {
    ImageComparison out;
    out.width = theirs.width;
    out.height = theirs.height;
    out.tolerance = std::max(0, options.tolerance);
    out.compared = static_cast<std::size_t>(theirs.width) * theirs.height;
    Search search(ours, theirs, out.tolerance, options);
    Bytes theirBackground = backgroundBytes(ours.trace->scene->conventions);
    if (const auto unlit = unlitColours(ours, theirs, out.tolerance)) {
        out.unlit = true;
        out.unlitColour = unlit->first;
        theirBackground = unlit->second;
        search.coverageOnly(unlit->first, unlit->second);
    }
    const Rgba8Image start = search.flattened(ours.image);
    summarise(ours, start, theirs, theirBackground, out);
    out.unexplainedPixels = out.differing;
    out.unexplained = out.differing > 0 ? 1.0 : 0.0;
    if (out.differing == 0) return out;

    const double least = kLeastShare * double(out.difference);
    auto given = withGiven(search, {{}, start, out.difference}, options.given);
    if (!given) return given.error();
    auto found = beamSearch(search, std::move(given.value()), least, out.unlit, options.excluded);
    if (!found) return found.error();
    Hypothesis chosen = std::move(found.value());
    if (Status s = remeasureConstants(search, chosen); !s) return s.error();
    if (Status s = dropRedundant(search, chosen, least); !s) return s.error();
    auto findings = findingsInOrder(search, ours, start, chosen.slips, out);
    if (!findings) return findings.error();
    out.diagnosis = std::move(findings.value());
    for (Finding& f : out.diagnosis)
        f.given = std::any_of(options.given.begin(), options.given.end(),
                              [&](const Slip& g) { return g.mistake == f.mistake; });
    out.unexplained = double(chosen.difference) / double(out.difference);
    out.unexplainedPixels = 0;
    for (int y = 0; y < theirs.height; ++y)
        for (int x = 0; x < theirs.width; ++x)
            out.unexplainedPixels +=
                distance(bytesAt(chosen.image, x, y), bytesAt(theirs, x, y)) > out.tolerance ? 1 : 0;
    return out;
}

namespace {

// How every occurrence of a command was misread.
Message everywhereTitle(const Hw2Misreading& m) {
    using Kind = Hw2Misreading::Kind;
    switch (m.kind) {
        case Kind::Ignored:
            return "every '%1' ignored (%2 of them, from line %3): the command never "
                   "implemented"_msg(m.keyword, m.count, m.line);
        case Kind::OtherSide:
            return "every '%1' multiplied on the other side (M = A M instead of M A), from line "
                   "%2"_msg(m.keyword, m.line);
        case Kind::Transposed:
            return "every '%1' read column by column (the matrix transposed), from line %2"_msg(
                m.keyword, m.line);
        case Kind::Radians:
            return "every '%1' with its angle taken as radians, from line %2"_msg(m.keyword,
                                                                                 m.line);
        case Kind::UnnormalisedSide:
            return "every '%1' with s = f x up not normalised, from line %2"_msg(m.keyword,
                                                                                m.line);
    }
    return {};
}

// How a command was misread, for the finding's title and advice.
Message misreadingTitle(const Hw2Misreading& m) {
    using Kind = Hw2Misreading::Kind;
    if (m.everywhere) return everywhereTitle(m);
    switch (m.kind) {
        case Kind::Ignored:
            return "line %1: '%2' ignored"_msg(m.line, m.keyword);
        case Kind::OtherSide:
            return "line %1: '%2' multiplied on the other side (M = A M instead of M A)"_msg(
                m.line, m.keyword);
        case Kind::Transposed:
            return "line %1: '%2' read column by column (the matrix transposed)"_msg(m.line,
                                                                                   m.keyword);
        case Kind::Radians:
            return "line %1: '%2' with its angle taken as radians"_msg(m.line, m.keyword);
        case Kind::UnnormalisedSide:
            return "line %1: '%2' with s = f x up not normalised (the image stretched "
                   "across)"_msg(m.line, m.keyword);
    }
    return {};
}

Message misreadingHint(const Hw2Misreading& m) {
    using Kind = Hw2Misreading::Kind;
    switch (m.kind) {
        case Kind::Ignored:
            return "check that your program reads '%1' and applies it"_msg(m.keyword);
        case Kind::OtherSide:
            return "seed 001: a transform multiplies the model/view on the right, M = M A"_msg;
        case Kind::Transposed:
            return "seed 001 writes a matrix row by row: the first four numbers are its first "
                   "row"_msg;
        case Kind::Radians:
            return "seed 001's angles are in degrees: convert them before sin and cos"_msg;
        case Kind::UnnormalisedSide:
            return "lookat: normalise s = f x up before it goes into the matrix"_msg;
    }
    return {};
}

}  // namespace

Result<ImageComparison> compareCommandFile(const OurFrame& ours, const Rgba8Image& theirs,
                                           const CompareOptions& options, std::string_view text,
                                           const std::string& fileName,
                                           const TextureLoader& loadTexture, std::size_t index,
                                           bool colourOnly) {
    // The commands misread are tried before the general screen map, which would take a
    // translation ignored for a shift; the map is fitted when no command explains more.
    CompareOptions noMap = options;
    noMap.screenMap = false;
    auto base = compareWithOurs(ours, theirs, noMap);
    if (!base || base->differing == 0 || base->unlit) return base;
    const double whole = double(base->difference);
    const auto withMap = [&]() { return options.screenMap ? compareWithOurs(ours, theirs, options) : base; };
    // The catalogue explains all but what a finding must remove at least: nothing to gain.
    if (base->unexplained * whole <= kLeastShare * whole) return base;
    // The misreadings whose frames come nearest theirs; of the three nearest, the one that
    // leaves least with the catalogue's mistakes on top.
    struct Candidate {
        Hw2Misreading misreading;
        OurFrame frame;
        std::uint64_t difference = 0;
    };
    std::vector<Candidate> candidates;
    for (const Hw2Misreading& misreading : possibleMisreadings(text)) {
        if (options.cancelled()) return cancelledError();
        Diagnostics quiet;
        auto file = readHw2(text, fileName, loadTexture, quiet, &misreading);
        if (!file || index >= file->images.size()) continue;
        auto frame = renderOurFrame(std::make_shared<const Scene>(file->images[index].scene));
        if (!frame || frame->image.width != theirs.width || frame->image.height != theirs.height)
            continue;
        // Their format has no alpha: theirs was given ours (compare_image.h), and colours
        // alone are compared.
        if (colourOnly)
            for (std::size_t i = 3; i < frame->image.rgba.size(); i += 4)
                frame->image.rgba[i] = theirs.rgba[i];
        const std::uint64_t d = differenceOf(frame->image, theirs);
        if (double(base->difference) - double(d) >= kLeastShare * whole)
            candidates.push_back({misreading, std::move(frame.value()), d});
    }
    std::sort(candidates.begin(), candidates.end(),
              [](const Candidate& a, const Candidate& b) { return a.difference < b.difference; });
    if (candidates.size() > kBeamWidth) candidates.resize(kBeamWidth);
    const Candidate* best = nullptr;
    std::optional<ImageComparison> onIt;
    double left = base->unexplained * whole - kLeastShare * whole;  // one finding's worth less
    for (const Candidate& c : candidates) {
        auto composed = compareWithOurs(c.frame, theirs, options);
        if (!composed) return composed.error();
        const double remains = composed->unexplained * double(composed->difference);
        if (remains < left) {
            left = remains;
            best = &c;
            onIt = std::move(composed.value());
        }
    }
    if (!best) return withMap();
    Finding f;
    f.mistake = f.slip.mistake = Mistake::CommandMisread;
    f.command = best->misreading;
    f.title = misreadingTitle(best->misreading);
    f.advice = misreadingHint(best->misreading);
    return firstFinding(std::move(base.value()), ours, best->frame.image, std::move(f),
                        std::move(*onIt), theirs);
}

ImageComparison firstFinding(ImageComparison base, const OurFrame& ours,
                             const Rgba8Image& alternative, Finding first,
                             ImageComparison onAlternative, const Rgba8Image& theirs) {
    const double whole = double(base.difference);
    first.removed = base.difference - std::min(base.difference, differenceOf(alternative, theirs));
    first.share = double(first.removed) / whole;
    countPixels(ours.image, alternative, theirs, base.tolerance, first);
    first.evidence = evidenceOf(first);
    base.diagnosis.clear();
    base.diagnosis.push_back(std::move(first));
    for (Finding& g : onAlternative.diagnosis) {
        g.share = double(g.removed) / whole;
        base.diagnosis.push_back(std::move(g));
    }
    base.unexplained = onAlternative.unexplained * double(onAlternative.difference) / whole;
    base.unexplainedPixels = onAlternative.unexplainedPixels;
    return base;
}

std::optional<ScreenMap> screenMapOf(const Finding& finding, int width, int height) {
    const Slip& s = finding.slip;
    switch (finding.mistake) {
        case Mistake::MirroredLeftRight:
            return ScreenMap{-1.0, 0.0, 0.0, 1.0, double(width), 0.0};
        case Mistake::UpsideDown:
            return ScreenMap{1.0, 0.0, 0.0, -1.0, 0.0, double(height)};
        case Mistake::Shifted:
            return ScreenMap{1.0, 0.0, 0.0, 1.0, double(s.shift.x), double(s.shift.y)};
        case Mistake::ScreenMap:
            return s.map;
        default:
            return std::nullopt;
    }
}

std::optional<ScreenMap> dominantMove(const ImageComparison& comparison) {
    const std::vector<Finding>& found = comparison.diagnosis;
    if (found.empty() || found.front().share < 0.5) return std::nullopt;
    return screenMapOf(found.front(), comparison.width, comparison.height);
}

std::optional<ivec2> findEmbedded(const Rgba8Image& ours, const Rgba8Image& theirs) {
    if (theirs.width < ours.width || theirs.height < ours.height || ours.width == 0 ||
        ours.height == 0)
        return std::nullopt;
    // A grid of about 2000 of our pixels, tried at every offset; a candidate offset is then
    // checked on every pixel.
    std::vector<ivec2> samples;
    const int step = std::max(1, int(std::sqrt(double(ours.width) * ours.height / 2000.0)));
    for (int y = step / 2; y < ours.height; y += step)
        for (int x = step / 2; x < ours.width; x += step) samples.push_back({x, y});
    // Our pixels unlike the corner's (most likely the background) first: at a wrong offset
    // they stop the count soonest.
    const Bytes corner = bytesAt(ours, 0, 0);
    std::stable_partition(samples.begin(), samples.end(),
                          [&](const ivec2& s) { return bytesAt(ours, s.x, s.y) != corner; });
    const std::size_t allowed = samples.size() / 20;
    std::optional<ivec2> best;
    std::size_t bestMismatches = 0;
    for (int oy = 0; oy <= theirs.height - ours.height; ++oy) {
        for (int ox = 0; ox <= theirs.width - ours.width; ++ox) {
            std::size_t mismatches = 0;
            for (const ivec2& s : samples) {
                if (bytesAt(ours, s.x, s.y) != bytesAt(theirs, s.x + ox, s.y + oy) &&
                    ++mismatches > allowed)
                    break;
            }
            if (mismatches > allowed) continue;
            std::size_t all = 0;
            for (int y = 0; y < ours.height; ++y)
                for (int x = 0; x < ours.width; ++x)
                    all += bytesAt(ours, x, y) != bytesAt(theirs, x + ox, y + oy) ? 1 : 0;
            if (all * 20 <= std::size_t(ours.width) * ours.height &&
                (!best || all < bestMismatches)) {
                best = ivec2(ox, oy);
                bestMismatches = all;
            }
        }
    }
    return best;
}

}  // namespace rl
