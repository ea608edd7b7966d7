#include "mistakes.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "pipeline/analysis/painter.h"
#include "pipeline/render/renderer.h"
#include "pipeline/stages/phong.h"
#include "pipeline/stages/probe.h"
#include "pipeline/stages/shading.h"

namespace rl {

namespace {

using Bytes = std::array<std::uint8_t, 4>;

// The names of the mistakes, in the order of the enum.
constexpr std::array<const char*, kMistakeCount> kIds = {
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

Result<Rgba8Image> renderImage(std::shared_ptr<const Scene> scene) {
    auto trace = renderFrame(scene);
    if (!trace) return trace.error();
    return colourImage(*trace->shading, *trace->depth, scene->conventions);
}

// The changed lighting formulas of the what-if shading.
enum class Formula : std::uint8_t { AmbientTimesOd, NoFlip, SpecularRv, LightBehind, Unnormalised };

// The colour of point p with interpolated normal n lit by the formula (the scene's own when
// none): phong.h's functions, with the one step the mistake changes.
vec3 lightWith(const FrameLighting& lighting, const Draw& draw, const vec3& od, const vec3& p,
               const vec3& n, std::optional<Formula> formula) {
    const Scene& scene = lighting.scene();
    const std::vector<ViewLight>& lights = lighting.view().lights;
    const std::size_t count = std::min(draw.lightCount, lights.size());
    const bool flip = scene.conventions.flipNormalsTowardViewer;
    if (!formula) return lighting.light(draw, od, p, n).colour();
    if (draw.lighting == LightingModel::Lambert && *formula == Formula::NoFlip)
        return hw2Lighting(od, draw.material.shininess, lights.data(), count, p, n, false).colour();
    if (draw.lighting != LightingModel::CoursePhong) return lighting.light(draw, od, p, n).colour();
    const Material& m = draw.material;
    const vec3& ia = scene.ambientIntensity;
    switch (*formula) {
        case Formula::NoFlip:
            return phong(m, od, ia, lights.data(), count, p, n, false, draw.specular).colour();
        case Formula::AmbientTimesOd: {
            PhongSample s = phong(m, od, ia, lights.data(), count, p, n, flip, draw.specular);
            s.ambient = ia * m.ka * od;
            return s.colour();
        }
        case Formula::SpecularRv:
        case Formula::LightBehind: {
            // The scene's sample plus the terms the missing check lets through.
            const PhongSample s = phong(m, od, ia, lights.data(), count, p, n, flip, draw.specular);
            if (s.noNormal) return s.colour();
            vec3 extra(0.0f);
            for (std::size_t i = 0; i < count; ++i) {
                const vec3 l = towardLight(lights[i], p);
                if (l == vec3(0.0f)) continue;
                const float nDotL = glm::dot(s.n, l);
                const bool behind = nDotL < 0.0f;
                if (behind != (*formula == Formula::LightBehind)) continue;
                const float factor =
                    lights[i].plain() ? 1.0f : lightFactor(lights[i], p, l, nullptr).value;
                const vec3 il = lights[i].intensity * factor;
                // With the light behind: a negative diffuse term, as N.L is.
                if (behind) extra += il * od * m.kd * nDotL;
                if (m.ks == 0.0f || draw.specular != SpecularModel::Phong) continue;
                const vec3 r = 2.0f * nDotL * s.n - l;
                const float rDotV = glm::dot(r, s.v);
                // Without the R.V check (C's pow: a negative base to a whole exponent keeps a
                // sign, to any other it is NaN); with the light behind, R.V still checked.
                if (behind ? rDotV < 0.0f : rDotV >= 0.0f) continue;
                const float power = std::pow(rDotV, m.shininess);
                if (std::isfinite(power)) extra += il * m.ks * power;
            }
            return s.colour() + extra;
        }
        case Formula::Unnormalised: {
            // phong() with N as interpolated: its length below 1 scales N.L and R.
            PhongSample s;
            s.ambient = ia * m.ka;
            s.emission = m.emission;
            const float vLength = glm::length(p);
            s.v = vLength > 0.0f ? -p * (1.0f / vLength) : vec3(0.0f);
            if (!(glm::length(n) > 0.0f)) return s.colour();
            s.n = flip && glm::dot(s.v, n) < 0.0f ? -n : n;
            for (std::size_t i = 0; i < count; ++i)
                addLight(lightTerms(m, od, lights[i], p, s.n, s.v, draw.specular), i == 0, s);
            return s.colour();
        }
    }
    return lighting.light(draw, od, p, n).colour();
}

// A frame shaded again, pixel by pixel, from its triangles and barycentrics: each draw by the
// model `asked` gives it (the frame's own scene, or the scene asked for when the frame is the
// painter's), lit by the formula.
Rgba8Image reshade(const FrameTrace& frame, const Scene& asked, std::optional<Formula> formula) {
    const Scene& scene = *frame.scene;
    const FrameLighting lighting(scene, *frame.view, *frame.normals, *frame.projection);
    const DepthTest& depth = *frame.depth;
    const Conventions& conv = scene.conventions;
    Rgba8Image out;
    out.width = scene.width;
    out.height = scene.height;
    out.rgba.resize(static_cast<std::size_t>(out.width) * out.height * 4);
    const Bytes background = backgroundBytes(conv);
    const float third = 1.0f / 3.0f;
    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) {
            const std::uint32_t t = depth.triangle.at(x, y);
            if (t == kNoTriangle) {
                put(out, x, y, background);
                continue;
            }
            const ScreenTriangle& tri = frame.projection->triangles[t];
            const Draw& draw = scene.draws[tri.draw];
            const vec2 b = depth.barycentricsKept ? depth.barycentric.at(x, y) : vec2(0.0f);
            float beta = b.x, gamma = b.y;
            lighting.attributeWeights(tri, beta, gamma);
            const DrawVertices& dv = lighting.vertices(tri.draw);
            vec3 colour(0.0f);
            switch (asked.draws[tri.draw].shading) {
                case ShadingModel::Phong: {
                    const vec3 p =
                        dv.pView.empty() ? vec3(0.0f) : interpolate(dv.pView, tri.v, beta, gamma);
                    colour = lightWith(lighting, draw, lighting.colourAt(tri, beta, gamma), p,
                                       lighting.normalAt(tri, beta, gamma), formula);
                    break;
                }
                case ShadingModel::Flat:
                case ShadingModel::Painter: {
                    vec3 p(0.0f), n(0.0f);
                    lighting.flatSample(tri, &p, &n);
                    const ScreenTriangle whole{tri.draw, tri.source,
                                               draw.mesh->triangles[tri.source]};
                    colour = lightWith(lighting, draw, lighting.colourAt(whole, third, third), p, n,
                                       formula);
                    break;
                }
                case ShadingModel::Gouraud: {
                    std::array<vec3, 3> c;
                    for (int k = 0; k < 3; ++k) {
                        const std::uint32_t v = tri.v[k];
                        const ScreenTriangle at{tri.draw, 0, {v, v, v}};
                        c[k] = lightWith(lighting, draw, lighting.colourAt(at, 0.0f, 0.0f),
                                         dv.pView.empty() ? vec3(0.0f) : dv.pView[v],
                                         dv.nView.empty() ? vec3(0.0f) : dv.nView[v], formula);
                    }
                    colour = c[0] + beta * (c[1] - c[0]) + gamma * (c[2] - c[0]);
                    break;
                }
            }
            put(out, x, y, colourBytes(colour, conv));
        }
    }
    return out;
}

std::shared_ptr<const Scene> withModel(const Scene& scene, ShadingModel model) {
    auto copy = std::make_shared<Scene>(scene);
    for (Draw& draw : copy->draws) draw.shading = model;
    return copy;
}

bool anyDraw(const Scene& scene, ShadingModel model) {
    return std::any_of(scene.draws.begin(), scene.draws.end(),
                       [model](const Draw& d) { return d.shading == model; });
}

bool anyLit(const Scene& scene, LightingModel model) {
    return std::any_of(scene.draws.begin(), scene.draws.end(),
                       [model](const Draw& d) { return d.lighting == model; });
}

// A channel as a C program that skips the clamp writes it: (unsigned char)(int) of the value
// in 0..255, wrapping modulo 256.
std::uint8_t wrappedByte(float value, const Conventions& conv) {
    const float scaled = value * (255.0f / conv.colourScale);
    if (!std::isfinite(scaled) || std::abs(scaled) > 1e9f) return 0;
    const float rounded =
        conv.rounding == ByteRounding::Nearest ? std::floor(scaled + 0.5f) : std::trunc(scaled);
    return static_cast<std::uint8_t>(static_cast<long long>(rounded) & 0xFF);
}

// The scene with other rules or conventions, when the change makes a difference.
template <typename Change>
Result<std::optional<Rgba8Image>> renderChanged(const Scene& scene, Change change) {
    auto copy = std::make_shared<Scene>(scene);
    change(*copy);
    auto image = renderImage(copy);
    if (!image) return image.error();
    return std::optional<Rgba8Image>(std::move(image.value()));
}

// The shading model a Gouraud, Flat or Phong mistake renders with.
ShadingModel modelOf(Mistake mistake) {
    return mistake == Mistake::Gouraud ? ShadingModel::Gouraud
           : mistake == Mistake::Flat  ? ShadingModel::Flat
                                       : ShadingModel::Phong;
}

// The one shading model every draw uses, if they agree.
std::optional<ShadingModel> sceneModel(const Scene& scene) {
    if (scene.draws.empty()) return std::nullopt;
    const ShadingModel first = scene.draws.front().shading;
    const bool same = std::all_of(scene.draws.begin(), scene.draws.end(),
                                  [first](const Draw& d) { return d.shading == first; });
    return same ? std::optional(first) : std::nullopt;
}

Message bytesMessage(const Bytes& b) {
    return "(%1, %2, %3, %4)"_msg(int(b[0]), int(b[1]), int(b[2]), int(b[3]));
}

Message titleOf(const OurFrame& ours, Mistake mistake, ivec2 shift, const Bytes& value) {
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
            const char* model = shadingModelName(modelOf(mistake));
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

// Our image mirrored, turned upside down or moved by `shift` (what leaves it, background).
Rgba8Image movedImage(const Rgba8Image& image, Mistake mistake, ivec2 shift,
                      const Bytes& background) {
    const int w = image.width, h = image.height;
    Rgba8Image out = image;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            int sx = x, sy = y;
            if (mistake == Mistake::MirroredLeftRight) sx = w - 1 - x;
            if (mistake == Mistake::UpsideDown) sy = h - 1 - y;
            if (mistake == Mistake::Shifted) sx = x - shift.x, sy = y - shift.y;
            const bool inside = sx >= 0 && sx < w && sy >= 0 && sy < h;
            put(out, x, y, inside ? bytesAt(image, sx, sy) : background);
        }
    }
    return out;
}

// The scene drawn in the painter's order: flat colours as the painter paints them, other
// models shaded at the painter's triangles.
Result<std::optional<Rgba8Image>> painterOrderImage(const Scene& scene) {
    using Optional = std::optional<Rgba8Image>;
    const auto painter = painterSceneOf(scene);
    if (std::all_of(scene.draws.begin(), scene.draws.end(),
                    [](const Draw& d) { return d.shading == ShadingModel::Flat; })) {
        auto rendered = renderImage(painter);
        if (!rendered) return rendered.error();
        return Optional(std::move(rendered.value()));
    }
    // The painter's triangles at each pixel, shaded by the model asked: the lecture's
    // stages keep every barycentric and normal (a probe on no pixel records nothing).
    RecordingProbe nowhere = RecordingProbe::forPixel(-1, -1);
    auto trace = traceFrame(painter, {}, nowhere);
    if (!trace) return trace.error();
    return Optional(reshade(trace.value(), scene, std::nullopt));
}

}  // namespace

Result<std::optional<Rgba8Image>> imageWithMistake(const OurFrame& ours, Mistake mistake,
                                                   ivec2 shift, std::array<std::uint8_t, 4> value) {
    const FrameTrace& frame = *ours.trace;
    const Scene& scene = *frame.scene;
    const Rgba8Image& image = ours.image;
    const int w = image.width, h = image.height;
    const Bytes background = backgroundBytes(scene.conventions);
    using Optional = std::optional<Rgba8Image>;
    const auto shaded = [&](Formula formula) -> Optional { return reshade(frame, scene, formula); };
    switch (mistake) {
        case Mistake::AmbientTimesOd:
            if (!anyLit(scene, LightingModel::CoursePhong)) return Optional();
            return shaded(Formula::AmbientTimesOd);
        case Mistake::NormalNotFlipped:
            if (!scene.conventions.flipNormalsTowardViewer) return Optional();
            return shaded(Formula::NoFlip);
        case Mistake::SpecularWhereRvNegative:
            if (!anyLit(scene, LightingModel::CoursePhong)) return Optional();
            return shaded(Formula::SpecularRv);
        case Mistake::LightBehindNotSkipped:
            if (!anyLit(scene, LightingModel::CoursePhong)) return Optional();
            return shaded(Formula::LightBehind);
        case Mistake::NormalNotNormalised:
            if (!anyDraw(scene, ShadingModel::Phong)) return Optional();
            return shaded(Formula::Unnormalised);
        case Mistake::Gouraud:
        case Mistake::Flat:
        case Mistake::Phong: {
            const ShadingModel model = modelOf(mistake);
            if (!scene.lit() || paintersAlgorithm(scene) || sceneModel(scene) == model)
                return Optional();
            auto rendered = renderImage(withModel(scene, model));
            if (!rendered) return rendered.error();
            return Optional(std::move(rendered.value()));
        }
        case Mistake::MirroredLeftRight:
        case Mistake::UpsideDown:
        case Mistake::Shifted:
            return Optional(movedImage(image, mistake, shift, background));
        case Mistake::SampleOffset:
            return renderChanged(scene, [](Scene& s) {
                s.rules.sampleOffset = s.rules.sampleOffset == 0.0 ? 0.5 : 0.0;
            });
        case Mistake::VertexSnap:
            return renderChanged(scene, [](Scene& s) {
                s.rules.snap = s.rules.snap == RasterRules::VertexSnap::Truncate
                                   ? RasterRules::VertexSnap::Nearest
                                   : RasterRules::VertexSnap::Truncate;
            });
        case Mistake::FillRule:
            return renderChanged(scene, [](Scene& s) {
                s.rules.fill = s.rules.fill == RasterRules::FillRule::Inclusive
                                   ? RasterRules::FillRule::TopLeft
                                   : RasterRules::FillRule::Inclusive;
            });
        case Mistake::DepthTies:
            if (paintersAlgorithm(scene)) return Optional();
            return renderChanged(scene, [](Scene& s) {
                s.conventions.depthWinsOnTie = !s.conventions.depthWinsOnTie;
            });
        case Mistake::ByteRounding: {
            Conventions other = scene.conventions;
            other.rounding = other.rounding == ByteRounding::Truncate ? ByteRounding::Nearest
                                                                      : ByteRounding::Truncate;
            return Optional(colourImage(*frame.shading, *frame.depth, other));
        }
        case Mistake::ColourWrap: {
            if (frame.shading->clampedPixels == 0) return Optional();
            Rgba8Image out = image;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    if (ours.covered(x, y)) {
                        const vec3 c = frame.shading->colour.at(x, y);
                        put(out, x, y,
                            {wrappedByte(c.r, scene.conventions),
                             wrappedByte(c.g, scene.conventions),
                             wrappedByte(c.b, scene.conventions), 255});
                    }
            return Optional(std::move(out));
        }
        case Mistake::PainterOrder:
            if (paintersAlgorithm(scene)) return Optional();
            return painterOrderImage(scene);
        case Mistake::Background: {
            if (value == background) return Optional();
            Rgba8Image out = image;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    if (!ours.covered(x, y)) put(out, x, y, value);
            return Optional(std::move(out));
        }
        case Mistake::Alpha: {
            if (value[3] == 255) return Optional();
            Rgba8Image out = image;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    if (ours.covered(x, y))
                        out.rgba[(static_cast<std::size_t>(y) * w + x) * 4 + 3] = value[3];
            return Optional(std::move(out));
        }
    }
    return Optional();
}

namespace {

// How far a hypothesis's image takes ours toward theirs.
Finding judge(const OurFrame& ours, const Rgba8Image& theirs, const Rgba8Image& candidate,
              std::size_t differing, int tolerance) {
    Finding f;
    const int w = theirs.width, h = theirs.height;
    const auto explains = [&](int x, int y, int before) {
        const int after = distance(bytesAt(candidate, x, y), bytesAt(theirs, x, y));
        return after < before && after <= std::max(1, tolerance);
    };
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const int before = distance(bytesAt(ours.image, x, y), bytesAt(theirs, x, y));
            if (before <= tolerance) {
                if (distance(bytesAt(candidate, x, y), bytesAt(theirs, x, y)) > tolerance)
                    ++f.spoiled;
            } else if (explains(x, y, before)) {
                ++f.explained;
            }
        }
    }
    f.share = differing > 0 ? double(f.explained) / double(differing) : 0.0;
    // Three examples spread over the pixels explained, in reading order.
    const std::array<std::size_t, 3> wanted = {f.explained / 6, f.explained / 2,
                                               f.explained * 5 / 6};
    std::size_t k = 0;
    for (int y = 0; y < h && f.explained > 0; ++y) {
        for (int x = 0; x < w; ++x) {
            const int before = distance(bytesAt(ours.image, x, y), bytesAt(theirs, x, y));
            if (before <= tolerance || !explains(x, y, before)) continue;
            if (std::find(wanted.begin(), wanted.end(), k) != wanted.end() &&
                (f.examples.empty() || f.examples.back().x != x || f.examples.back().y != y))
                f.examples.push_back({x, y, bytesAt(ours.image, x, y), bytesAt(theirs, x, y)});
            ++k;
        }
    }
    return f;
}

// The colour most of their pixels take where `where` holds.
template <typename Where>
std::optional<Bytes> mostCommon(const Rgba8Image& theirs, Where where) {
    std::map<Bytes, std::size_t> counts;
    for (int y = 0; y < theirs.height; ++y)
        for (int x = 0; x < theirs.width; ++x)
            if (where(x, y)) ++counts[bytesAt(theirs, x, y)];
    if (counts.empty()) return std::nullopt;
    return std::max_element(counts.begin(), counts.end(),
                            [](const auto& a, const auto& b) { return a.second < b.second; })
        ->first;
}

}  // namespace

Result<ImageComparison> compareWithOurs(const OurFrame& ours, const Rgba8Image& theirs,
                                        int tolerance) {
    const Scene& scene = *ours.trace->scene;
    const Bytes background = backgroundBytes(scene.conventions);
    ImageComparison out;
    out.width = theirs.width;
    out.height = theirs.height;
    out.tolerance = std::max(0, tolerance);
    out.compared = static_cast<std::size_t>(theirs.width) * theirs.height;
    std::array<double, 4> sum{};
    out.difference = ours.image;
    for (int y = 0; y < theirs.height; ++y) {
        for (int x = 0; x < theirs.width; ++x) {
            const Bytes a = bytesAt(ours.image, x, y), b = bytesAt(theirs, x, y);
            const bool weCover = ours.covered(x, y), theyCover = distance(b, background) > out.tolerance;
            out.onlyOurs += weCover && !theyCover ? 1 : 0;
            out.onlyTheirs += !weCover && theyCover ? 1 : 0;
            const int d = distance(a, b);
            Bytes shown = {std::uint8_t(a[0] / 3), std::uint8_t(a[1] / 3), std::uint8_t(a[2] / 3),
                           255};
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
            put(out.difference, x, y, shown);
        }
    }
    for (int c = 0; c < 4; ++c)
        out.mean[c] = out.differing > 0 ? sum[c] / double(out.differing) : 0.0;
    if (out.differing == 0) return out;

    for (std::size_t i = 0; i < kMistakeCount; ++i) {
        const Mistake mistake = static_cast<Mistake>(i);
        ivec2 shift(1, 0);
        Bytes value{};
        std::optional<Finding> best;
        std::vector<ivec2> shifts = {shift};
        if (mistake == Mistake::Shifted)
            shifts = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, -1}, {1, -1}, {-1, 1}};
        if (mistake == Mistake::Background) {
            const auto common =
                mostCommon(theirs, [&](int x, int y) { return !ours.covered(x, y); });
            if (!common) continue;
            value = *common;
        }
        if (mistake == Mistake::Alpha) {
            const auto common =
                mostCommon(theirs, [&](int x, int y) { return ours.covered(x, y); });
            if (!common) continue;
            value = *common;
        }
        for (const ivec2& s : shifts) {
            auto candidate = imageWithMistake(ours, mistake, s, value);
            if (!candidate) return candidate.error();
            if (!candidate.value()) continue;
            Finding f = judge(ours, theirs, *candidate.value(), out.differing, out.tolerance);
            if (!best || f.explained > best->explained) {
                f.title = titleOf(ours, mistake, s, value);
                best = std::move(f);
            }
        }
        if (!best || best->explained <= best->spoiled || best->share < kLeastShare) continue;
        best->mistake = mistake;
        best->evidence =
            best->spoiled == 0
                ? "%1; no pixel that matches now would change"_msg(mechanismOf(mistake))
                : counted(static_cast<long long>(best->spoiled),
                          "%2; %1 pixel that matches now would differ"_msg,
                          "%2; %1 pixels that match now would differ"_msg, mechanismOf(mistake));
        best->advice = hintOf(mistake);
        out.diagnosis.push_back(std::move(*best));
    }
    // A mistake that spoils pixels that match now is less likely than one that spoils none.
    const auto net = [](const Finding& f) {
        return static_cast<long long>(f.explained) - static_cast<long long>(f.spoiled);
    };
    std::stable_sort(out.diagnosis.begin(), out.diagnosis.end(),
                     [&](const Finding& a, const Finding& b) { return net(a) > net(b); });
    return out;
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
