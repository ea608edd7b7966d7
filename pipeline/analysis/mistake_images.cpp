#include "mistake_images.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "pipeline/analysis/painter.h"
#include "pipeline/render/renderer.h"
#include "pipeline/stages/camera_basis.h"
#include "pipeline/stages/depth_test.h"
#include "pipeline/stages/normals.h"
#include "pipeline/stages/phong.h"
#include "pipeline/stages/probe.h"
#include "pipeline/stages/projection.h"
#include "pipeline/stages/scan_conversion.h"
#include "pipeline/stages/shading.h"
#include "pipeline/stages/view_transform.h"

namespace rl {

namespace {

using Bytes = std::array<std::uint8_t, 4>;

const Slip* slipOf(const std::vector<Slip>& slips, Mistake mistake) {
    const auto it = std::find_if(slips.begin(), slips.end(),
                                 [mistake](const Slip& s) { return s.mistake == mistake; });
    return it == slips.end() ? nullptr : &*it;
}

bool anyDraw(const Scene& scene, ShadingModel model) {
    return std::any_of(scene.draws.begin(), scene.draws.end(),
                       [model](const Draw& d) { return d.shading == model; });
}

bool anyLit(const Scene& scene, LightingModel model) {
    return std::any_of(scene.draws.begin(), scene.draws.end(),
                       [model](const Draw& d) { return d.lighting == model; });
}

bool allFlat(const Scene& scene) {
    return std::all_of(scene.draws.begin(), scene.draws.end(),
                       [](const Draw& d) { return d.shading == ShadingModel::Flat; });
}

ShadingModel modelOf(Mistake mistake) {
    return mistake == Mistake::Gouraud ? ShadingModel::Gouraud
           : mistake == Mistake::Flat  ? ShadingModel::Flat
                                       : ShadingModel::Phong;
}

// The changes a student's lighting code makes to seed 000's formula; any number at once.
struct Formulas {
    bool ambientTimesOd = false;  // Ia ka Od
    bool ambientIaOnly = false;   // Ia
    bool noFlip = false;          // N not turned toward the viewer
    bool specularRv = false;      // highlight where R.V < 0
    bool lightBehind = false;     // diffuse and specular where N.L < 0
    bool unnormalised = false;    // the interpolated N at its own length
    bool vReversed = false;       // V = P' / |P'|
    bool truncated = false;       // each term truncated to a whole byte
    bool epsilon = false;         // the special cases against `small`
    float small = kSpecialCaseEpsilon;
    // Vertex normals made another way (per draw, per vertex of the mesh); empty: the frame's.
    std::vector<std::vector<vec3>> vertexNormals;
    bool any() const {
        return ambientTimesOd || ambientIaOnly || noFlip || specularRv || lightBehind ||
               unnormalised || vReversed || truncated || epsilon || !vertexNormals.empty();
    }
};

// Each vertex's first vertex at the same model position (itself when none comes before it).
std::vector<std::uint32_t> firstAtPosition(const Mesh& mesh) {
    std::map<std::array<double, 4>, std::uint32_t> first;
    std::vector<std::uint32_t> key(mesh.positions.size());
    for (std::uint32_t v = 0; v < key.size(); ++v) {
        const dvec4& p = mesh.positions[v];
        key[v] = first.emplace(std::array<double, 4>{p.x, p.y, p.z, p.w}, v).first->second;
    }
    return key;
}

// Whether a draw the normals stage computes normals for has two vertices at one position.
bool sharesPositions(const Scene& scene) {
    for (const Draw& draw : scene.draws) {
        if (!draw.mesh || !draw.mesh->normals.empty()) continue;
        const std::vector<std::uint32_t> key = firstAtPosition(*draw.mesh);
        for (std::uint32_t v = 0; v < key.size(); ++v)
            if (key[v] != v) return true;
    }
    return false;
}

// How a student's normals stage may make the vertex normals: the triangle normals
// (P2 - P1) x (P3 - P1) summed at their length (area-weighted) or normalised; the sums left
// at their length or normalised; summed over every vertex at the same position rather than
// by the vertex's index.
struct StudentNormals {
    bool areaWeighted = false;
    bool leftUnnormalised = false;
    bool byPosition = false;
    bool any() const { return areaWeighted || leftUnnormalised || byPosition; }
};

// Each draw's vertex normals made that way. Draws whose file gives normals keep none.
std::vector<std::vector<vec3>> studentVertexNormals(const Scene& scene, const ViewTransform& view,
                                                    const StudentNormals& how) {
    std::vector<std::vector<vec3>> out(scene.draws.size());
    for (std::size_t d = 0; d < scene.draws.size(); ++d) {
        const Mesh* mesh = scene.draws[d].mesh.get();
        if (!mesh || !mesh->normals.empty()) continue;
        const std::vector<dvec4>& p = view.pView[d];
        std::vector<std::uint32_t> key(p.size());
        for (std::uint32_t v = 0; v < key.size(); ++v) key[v] = v;
        if (how.byPosition) key = firstAtPosition(*mesh);
        std::vector<dvec3> sum(p.size(), dvec3(0.0));
        for (const auto& tri : mesh->triangles) {
            const dvec3 a = dvec3(p[tri[0]]) / p[tri[0]].w, b = dvec3(p[tri[1]]) / p[tri[1]].w,
                        c = dvec3(p[tri[2]]) / p[tri[2]].w;
            dvec3 n = glm::cross(b - a, c - a);
            const double length = glm::length(n);
            if (!(length > 0.0)) continue;
            if (!how.areaWeighted) n /= length;
            for (std::uint32_t v : tri) sum[key[v]] += n;
        }
        out[d].resize(p.size());
        for (std::size_t v = 0; v < p.size(); ++v) {
            const dvec3& total = sum[key[v]];
            const double length = glm::length(total);
            out[d][v] = vec3(how.leftUnnormalised || !(length > 0.0) ? total : total / length);
        }
    }
    return out;
}

// The colour of point p with interpolated normal n lit with the formulas changed: phong.h's
// own steps (orientNormal, lightTerms), with what each change alters. No change: the scene's
// own lighting, to the bit.
vec3 lightWith(const FrameLighting& lighting, const Draw& draw, const vec3& od, const vec3& p,
               const vec3& n, const Formulas& f) {
    if (!f.any()) return lighting.light(draw, od, p, n).colour();
    const Scene& scene = lighting.scene();
    const std::vector<ViewLight>& lights = lighting.view().lights;
    const std::size_t count = std::min(draw.lightCount, lights.size());
    const bool flip = scene.conventions.flipNormalsTowardViewer && !f.noFlip;
    if (draw.lighting == LightingModel::Lambert && f.noFlip)
        return hw2Lighting(od, draw.material.shininess, lights.data(), count, p, n, false).colour();
    if (draw.lighting != LightingModel::CoursePhong) return lighting.light(draw, od, p, n).colour();
    const Material& m = draw.material;
    const vec3& ia = scene.ambientIntensity;
    const float toByte = 255.0f / scene.conventions.colourScale;
    const auto term = [&](const vec3& t) { return f.truncated ? glm::floor(t * toByte) / toByte : t; };
    PhongSample s;
    s.ambient = term((f.ambientIaOnly ? ia : ia * m.ka) * (f.ambientTimesOd ? od : vec3(1.0f)));
    s.emission = m.emission;
    // V = P'/|P'| is what orientNormal makes of -P'.
    if (!orientNormal(s, f.vReversed ? -p : p, n, flip)) return s.colour();
    if (f.unnormalised) s.n = s.flipped ? -n : n;
    if (f.epsilon && flip && !s.flipped && glm::dot(s.v, s.n) < f.small) s.n = -s.n;
    const bool phongHighlight = m.ks != 0.0f && draw.specular == SpecularModel::Phong;
    for (std::size_t i = 0; i < count; ++i) {
        LightTerms t = lightTerms(m, od, lights[i], p, s.n, s.v, draw.specular);
        if (t.atPoint) continue;
        const float factor = lights[i].plain() ? 1.0f : lightFactor(lights[i], p, t.l, nullptr).value;
        const vec3 il = lights[i].intensity * factor;
        const bool behind = t.behind && f.lightBehind;
        if (behind) {
            // Without the N.L check: a negative diffuse term, and R.V still checked.
            t.diffuse = il * od * m.kd * t.nDotL;
            t.r = 2.0f * t.nDotL * s.n - t.l;
            t.rDotV = glm::dot(t.r, s.v);
        }
        // Without the R.V check, C's pow: a negative base to a whole exponent keeps a sign,
        // to any other it is NaN (left out).
        const bool highlight =
            behind ? t.rDotV >= 0.0f : f.specularRv && !t.behind && t.rDotV < 0.0f;
        if (phongHighlight && highlight) {
            const float power = std::pow(t.rDotV, m.shininess);
            if (std::isfinite(power)) t.specular = il * m.ks * power;
        }
        if (f.epsilon && t.nDotL < f.small) t.diffuse = t.specular = vec3(0.0f);
        if (f.epsilon && t.rDotV < f.small) t.specular = vec3(0.0f);
        if (!(t.nDotL >= 0.0f) && !behind) continue;
        s.diffuse += term(t.diffuse);
        const vec3 specular = term(t.specular);
        if (specular != vec3(0.0f)) s.specular += specular;
    }
    return s.colour();
}

// A frame's colours worked out again, pixel by pixel, from its triangles and barycentrics:
// each draw by the model `asked` gives it (the frame's own scene, or the scene asked for when
// the frame is the painter's), lit with the formulas.
Image<vec3> reshade(const FrameTrace& frame, const Scene& asked, const Formulas& formulas) {
    const Scene& scene = *frame.scene;
    const FrameLighting lighting(scene, *frame.view, *frame.normals, *frame.projection);
    const DepthTest& depth = *frame.depth;
    Image<vec3> out(scene.width, scene.height);
    const float third = 1.0f / 3.0f;
    for (int y = 0; y < scene.height; ++y) {
        for (int x = 0; x < scene.width; ++x) {
            const std::uint32_t t = depth.triangle.at(x, y);
            if (t == kNoTriangle) continue;
            const ScreenTriangle& tri = frame.projection->triangles[t];
            const Draw& draw = scene.draws[tri.draw];
            const vec2 b = depth.barycentricsKept ? depth.barycentric.at(x, y) : vec2(0.0f);
            float beta = b.x, gamma = b.y;
            lighting.attributeWeights(tri, beta, gamma);
            const DrawVertices& dv = lighting.vertices(tri.draw);
            // The student's vertex normals, where the triangle's vertices are the mesh's own
            // (not made by clipping).
            const std::vector<vec3>* own =
                formulas.vertexNormals.empty() ? nullptr : &formulas.vertexNormals[tri.draw];
            if (own && (own->empty() || draw.flatNormals ||
                        std::any_of(tri.v.begin(), tri.v.end(),
                                    [&](std::uint32_t v) { return v >= own->size(); })))
                own = nullptr;
            vec3& colour = out.at(x, y);
            switch (asked.draws[tri.draw].shading) {
                case ShadingModel::Phong: {
                    const vec3 p =
                        dv.pView.empty() ? vec3(0.0f) : interpolate(dv.pView, tri.v, beta, gamma);
                    const vec3 n = own ? interpolate(*own, tri.v, beta, gamma)
                                       : lighting.normalAt(tri, beta, gamma);
                    colour = lightWith(lighting, draw, lighting.colourAt(tri, beta, gamma), p, n,
                                       formulas);
                    break;
                }
                case ShadingModel::Flat:
                case ShadingModel::Painter: {
                    vec3 p(0.0f), n(0.0f);
                    lighting.flatSample(tri, &p, &n);
                    const ScreenTriangle whole{tri.draw, tri.source,
                                               draw.mesh->triangles[tri.source]};
                    colour = lightWith(lighting, draw, lighting.colourAt(whole, third, third), p, n,
                                       formulas);
                    break;
                }
                case ShadingModel::Gouraud: {
                    std::array<vec3, 3> c;
                    for (int k = 0; k < 3; ++k) {
                        const std::uint32_t v = tri.v[k];
                        const ScreenTriangle at{tri.draw, 0, {v, v, v}};
                        c[k] = lightWith(lighting, draw, lighting.colourAt(at, 0.0f, 0.0f),
                                         dv.pView.empty() ? vec3(0.0f) : dv.pView[v],
                                         own              ? (*own)[v]
                                         : dv.nView.empty() ? vec3(0.0f)
                                                            : dv.nView[v],
                                         formulas);
                    }
                    colour = c[0] + beta * (c[1] - c[0]) + gamma * (c[2] - c[0]);
                    break;
                }
            }
        }
    }
    return out;
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

// The scene drawn with the farther fragment winning each pixel: the lecture's stages, with
// the depth test given every depth turned around (-z, or 1 - z where depths are kept to
// [0, 1]), so that its nearest is the farthest. Hidden back faces are kept: they are what
// such a test shows.
Result<FrameTrace> farthestFrame(std::shared_ptr<Scene> scene) {
    scene->cullHiddenBackFaces = false;
    FrameTrace trace;
    trace.scene = scene;
    auto basis = CameraBasisStage().run(*scene, trace.diagnostics);
    if (!basis) return basis.error();
    trace.cameraBasis = std::make_shared<const CameraBasis>(std::move(basis).value());
    trace.view = std::make_shared<const ViewTransform>(
        ViewTransformStage().run(*scene, *trace.cameraBasis));
    trace.normals = std::make_shared<const Normals>(NormalsStage().run({*scene, *trace.view}));
    Projection projection = ProjectionStage().run({*scene, *trace.view}, trace.diagnostics);
    trace.projection = std::make_shared<const Projection>(projection);
    const bool range = scene->conventions.depthRangeClip;
    for (DrawProjection& draw : projection.draws)
        for (float& z : draw.depth) z = range ? 1.0f - z : -z;
    // Scanned with the flipped depths: the same spans, and the DDA (hw2 rules) steps the depths
    // as it scans.
    trace.scan = std::make_shared<const ScanConversion>(
        ScanConversionStage().run({*scene, projection}));
    trace.depth = std::make_shared<const DepthTest>(
        DepthTestStage().run({*scene, projection, *trace.scan}));
    trace.shading = std::make_shared<const Shading>(ShadingStage().run(
        {*scene, *trace.view, *trace.normals, *trace.projection, *trace.depth}));
    return trace;
}

// Moves the scene's positional lights to where a student's view transform puts them: the
// world position used as the view position, or taken to view coordinates without - C. The
// light at X with view(X) equal to their view position draws their image.
bool moveLights(Scene& scene, const CameraBasis& basis, Mistake mistake) {
    const dmat4& viewFromWorld = basis.viewFromWorld;
    const dmat4 worldFromView = glm::inverse(viewFromWorld);
    bool moved = false;
    for (Light& light : scene.lights) {
        if (light.pWorld.w == 0.0) continue;
        const dvec3 p = dvec3(light.pWorld) / light.pWorld.w;
        const dvec3 theirs = mistake == Mistake::LightInWorld
                                 ? p
                                 : dvec3(viewFromWorld * dvec4(p, 0.0));  // [I] Pl
        light.pWorld = worldFromView * dvec4(theirs, 1.0);
        moved = true;
    }
    return moved;
}

// The world moved so that our camera sees, in view coordinates, what a student's basis I'
// sees: W(P) = C + I^T I' (P - C), I the lecture's orthonormal basis. Their basis keeps N at
// its given length (BasisNNotNormalised) or takes U = V x N (BasisUReversed). False when
// theirs is ours.
bool moveToTheirBasis(Scene& scene, const CameraBasis& basis, Mistake mistake) {
    dvec3 u = basis.u, v = basis.v, n = basis.n;
    if (mistake == Mistake::BasisNNotNormalised) {
        if (std::abs(basis.nLength - 1.0) < 1e-9) return false;
        n = basis.nGiven;
        const dvec3 w = basis.vGiven - glm::dot(basis.vGiven, n) * n;
        if (!(glm::length(w) > 0.0)) return false;
        v = glm::normalize(w);
        u = glm::cross(n, v);
    } else {
        u = glm::cross(basis.v, basis.n);
    }
    // Columns u, v, n of I^T (ours), rows of I' (theirs).
    const dmat3 a = dmat3(basis.u, basis.v, basis.n) * glm::transpose(dmat3(u, v, n));
    dmat4 w(a);
    w[3] = dvec4(basis.c - a * basis.c, 1.0);
    for (Draw& draw : scene.draws) draw.worldFromModel = w * draw.worldFromModel;
    for (Light& light : scene.lights) {
        light.pWorld = w * light.pWorld;
        light.spotDirection = a * light.spotDirection;
    }
    // A mirror turns a closed surface's winding: the hidden back faces are no longer known.
    scene.cullHiddenBackFaces = false;
    return true;
}

// Our image mirrored, turned upside down or moved by `shift` (what leaves it, `fill`).
Rgba8Image movedImage(const Rgba8Image& image, Mistake mistake, ivec2 shift, const Bytes& fill) {
    const int w = image.width, h = image.height;
    Rgba8Image out = image;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            int sx = x, sy = y;
            if (mistake == Mistake::MirroredLeftRight) sx = w - 1 - x;
            if (mistake == Mistake::UpsideDown) sy = h - 1 - y;
            if (mistake == Mistake::Shifted) sx = x - shift.x, sy = y - shift.y;
            const bool inside = sx >= 0 && sx < w && sy >= 0 && sy < h;
            const std::uint8_t* from = inside ? image.pixel(sx, sy) : fill.data();
            std::copy(from, from + 4, out.rgba.data() + (std::size_t(y) * w + x) * 4);
        }
    }
    return out;
}

}  // namespace

std::optional<ShadingModel> sceneModel(const Scene& scene) {
    if (scene.draws.empty()) return std::nullopt;
    const ShadingModel first = scene.draws.front().shading;
    const bool same = std::all_of(scene.draws.begin(), scene.draws.end(),
                                  [first](const Draw& d) { return d.shading == first; });
    return same ? std::optional(first) : std::nullopt;
}

bool changesTheRender(Mistake mistake) {
    switch (mistake) {
        case Mistake::Gouraud:
        case Mistake::Flat:
        case Mistake::Phong:
        case Mistake::SampleOffset:
        case Mistake::VertexSnap:
        case Mistake::FillRule:
        case Mistake::DepthTies:
        case Mistake::PainterOrder:
        case Mistake::DepthReversed:
        case Mistake::LightInWorld:
        case Mistake::LightWithoutC:
        case Mistake::BasisNNotNormalised:
        case Mistake::BasisUReversed:
            return true;
        default:
            return false;
    }
}

Result<std::optional<MistakeFrame>> frameWithMistakes(const OurFrame& ours,
                                                      const std::vector<Slip>& slips) {
    using Optional = std::optional<MistakeFrame>;
    const FrameTrace& frame = *ours.trace;
    const Scene& scene = *frame.scene;
    MistakeFrame out{ours.trace, frame.scene, false};
    auto changed = std::make_shared<Scene>(scene);
    bool any = false, model = false, painter = false, farthest = false, lights = false;
    const bool courseCamera = frame.cameraBasis && !frame.cameraBasis->skipped;
    // The basis first: a light mistake then puts the light where it says, in our view.
    for (const Slip& slip : slips) {
        if (slip.mistake != Mistake::BasisNNotNormalised && slip.mistake != Mistake::BasisUReversed)
            continue;
        if (!courseCamera || !moveToTheirBasis(*changed, *frame.cameraBasis, slip.mistake))
            return Optional();
        any = true;
    }
    for (const Slip& slip : slips) {
        if (!changesTheRender(slip.mistake)) continue;
        any = true;
        switch (slip.mistake) {
            case Mistake::Gouraud:
            case Mistake::Flat:
            case Mistake::Phong: {
                const ShadingModel asked = modelOf(slip.mistake);
                if (model || !scene.lit() || paintersAlgorithm(scene) || sceneModel(scene) == asked)
                    return Optional();
                model = true;
                for (Draw& draw : changed->draws) draw.shading = asked;
                break;
            }
            case Mistake::SampleOffset:
                changed->rules.sampleOffset = scene.rules.sampleOffset == 0.0 ? 0.5 : 0.0;
                break;
            case Mistake::VertexSnap:
                if (slip.amount == kKeptFractional) {
                    // Fractional, as near as the exact walk holds: a 1/65536-pixel grid.
                    changed->rules.subpixelBits = 16;
                    changed->rules.snap = RasterRules::VertexSnap::Nearest;
                    break;
                }
                changed->rules.snap = scene.rules.snap == RasterRules::VertexSnap::Truncate
                                          ? RasterRules::VertexSnap::Nearest
                                          : RasterRules::VertexSnap::Truncate;
                break;
            case Mistake::FillRule:
                changed->rules.fill = scene.rules.fill == RasterRules::FillRule::Inclusive
                                          ? RasterRules::FillRule::TopLeft
                                          : RasterRules::FillRule::Inclusive;
                break;
            case Mistake::DepthTies:
                if (paintersAlgorithm(scene)) return Optional();
                changed->conventions.depthWinsOnTie = !scene.conventions.depthWinsOnTie;
                break;
            case Mistake::PainterOrder:
            case Mistake::DepthReversed:
                if (paintersAlgorithm(scene) || painter || farthest) return Optional();
                (slip.mistake == Mistake::PainterOrder ? painter : farthest) = true;
                break;
            case Mistake::LightInWorld:
            case Mistake::LightWithoutC:
                if (lights || !courseCamera ||
                    !anyLit(scene, LightingModel::CoursePhong) ||
                    !moveLights(*changed, *frame.cameraBasis, slip.mistake))
                    return Optional();
                lights = true;
                break;
            default:
                break;
        }
    }
    if (!any) return Optional(out);
    out.asked = changed;
    if (painter) {
        // The painter's triangles at each pixel, shaded again by the model asked unless every
        // draw is flat (the painter lights as flat shading does): the lecture's stages keep
        // every barycentric and normal (a probe on no pixel records nothing).
        RecordingProbe nowhere = RecordingProbe::forPixel(-1, -1);
        auto trace = traceFrame(painterSceneOf(*changed), {}, nowhere);
        if (!trace) return trace.error();
        out.trace = std::make_shared<const FrameTrace>(std::move(trace.value()));
        out.painted = !allFlat(*changed);
        return Optional(out);
    }
    auto trace = farthest ? farthestFrame(changed) : renderFrame(changed, RenderOptions{});
    if (!trace) return trace.error();
    out.trace = std::make_shared<const FrameTrace>(std::move(trace.value()));
    return Optional(out);
}

namespace {

// How a frame's colours become bytes under the colour slips, and the formulas the lighting slips
// change. Empty when a slip asked cannot show in this scene (nothing of it to render).
struct ColourSlips {
    Formulas formulas;
    Conventions conv;
    bool bytes = false;  // the bytes are made again (rounding, wrap, offset or scale)
    bool wrap = false;
    int offset = 0;
    float scale = 1.0f;
};

std::optional<ColourSlips> colourSlipsOf(const OurFrame& ours, const std::vector<Slip>& slips) {
    const Scene& scene = *ours.trace->scene;
    const bool coursePhong = anyLit(scene, LightingModel::CoursePhong);
    ColourSlips c;
    c.conv = scene.conventions;
    Formulas& f = c.formulas;
    for (const Slip& slip : slips) {
        switch (slip.mistake) {
            case Mistake::AmbientTimesOd:
            case Mistake::AmbientIaOnly:
            case Mistake::SpecularWhereRvNegative:
            case Mistake::LightBehindNotSkipped:
            case Mistake::ViewVectorReversed:
            case Mistake::TermsTruncated:
            case Mistake::EpsilonSpecialCases:
                if (!coursePhong) return std::nullopt;
                f.ambientTimesOd |= slip.mistake == Mistake::AmbientTimesOd;
                f.ambientIaOnly |= slip.mistake == Mistake::AmbientIaOnly;
                f.specularRv |= slip.mistake == Mistake::SpecularWhereRvNegative;
                f.lightBehind |= slip.mistake == Mistake::LightBehindNotSkipped;
                f.vReversed |= slip.mistake == Mistake::ViewVectorReversed;
                f.truncated |= slip.mistake == Mistake::TermsTruncated;
                f.epsilon |= slip.mistake == Mistake::EpsilonSpecialCases;
                if (slip.mistake == Mistake::EpsilonSpecialCases && slip.amount > 0.0)
                    f.small = static_cast<float>(slip.amount);
                break;
            case Mistake::NormalNotFlipped:
                if (!c.conv.flipNormalsTowardViewer) return std::nullopt;
                f.noFlip = true;
                break;
            case Mistake::NormalNotNormalised:
                if (!anyDraw(scene, ShadingModel::Phong)) return std::nullopt;
                f.unnormalised = true;
                break;
            case Mistake::VertexNormalsUnnormalised:
            case Mistake::AreaWeightedNormals:
            case Mistake::NormalsSharedByPosition:
                if (!anyDraw(scene, ShadingModel::Phong) && !anyDraw(scene, ShadingModel::Gouraud))
                    return std::nullopt;
                if (slip.mistake == Mistake::NormalsSharedByPosition && !sharesPositions(scene))
                    return std::nullopt;
                break;
            case Mistake::ByteRounding:
                c.conv.rounding = c.conv.rounding == ByteRounding::Truncate ? ByteRounding::Nearest
                                                                            : ByteRounding::Truncate;
                c.bytes = true;
                break;
            case Mistake::ColourWrap:
                if (ours.trace->shading->clampedPixels == 0 && !slipOf(slips, Mistake::ColourScale))
                    return std::nullopt;
                c.wrap = c.bytes = true;
                break;
            case Mistake::ColourOffset:
                c.offset = static_cast<int>(std::lround(slip.amount));
                if (c.offset == 0) return std::nullopt;
                c.bytes = true;
                break;
            case Mistake::ColourScale:
                c.scale = static_cast<float>(slip.amount);
                if (!(c.scale > 0.0f) || c.scale == 1.0f) return std::nullopt;
                c.bytes = true;
                break;
            default:
                break;
        }
    }
    return c;
}

// The covered pixels' colours made bytes as the slips say; the rest the background.
Rgba8Image bytesOf(const Image<vec3>& colours, const DepthTest& depth, const ColourSlips& c,
                   Bytes background) {
    Rgba8Image out;
    out.width = depth.triangle.width();
    out.height = depth.triangle.height();
    out.rgba.resize(std::size_t(out.width) * out.height * 4);
    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) {
            Bytes b = background;
            if (depth.triangle.at(x, y) != kNoTriangle) {
                const vec3 v = colours.at(x, y) * c.scale;
                b = c.wrap ? Bytes{wrappedByte(v.r, c.conv), wrappedByte(v.g, c.conv),
                                   wrappedByte(v.b, c.conv), 255}
                           : colourBytes(v, c.conv);
                for (int k = 0; k < 3; ++k) b[k] = std::uint8_t(std::clamp(b[k] + c.offset, 0, 255));
            }
            std::copy(b.begin(), b.end(), out.rgba.data() + (std::size_t(y) * out.width + x) * 4);
        }
    }
    return out;
}

// Another background on the uncovered pixels, another alpha on the covered ones.
void paintBackgroundAndAlpha(Rgba8Image& out, const DepthTest& depth, const Slip* bg,
                             const Slip* alpha) {
    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) {
            std::uint8_t* p = out.rgba.data() + (std::size_t(y) * out.width + x) * 4;
            const bool covered = depth.triangle.at(x, y) != kNoTriangle;
            if (!covered && bg) std::copy(bg->value.begin(), bg->value.end(), p);
            if (covered && alpha) p[3] = alpha->value[3];
        }
    }
}

}  // namespace

Result<std::optional<Rgba8Image>> imageOnFrame(const OurFrame& ours, const MistakeFrame& mframe,
                                               const std::vector<Slip>& slips) {
    using Optional = std::optional<Rgba8Image>;
    const Scene& scene = *ours.trace->scene;
    const FrameTrace& frame = *mframe.trace;
    std::optional<ColourSlips> colour = colourSlipsOf(ours, slips);
    if (!colour) return Optional();
    Formulas& f = colour->formulas;
    StudentNormals normals;
    normals.leftUnnormalised = slipOf(slips, Mistake::VertexNormalsUnnormalised) != nullptr;
    normals.areaWeighted = slipOf(slips, Mistake::AreaWeightedNormals) != nullptr;
    normals.byPosition = slipOf(slips, Mistake::NormalsSharedByPosition) != nullptr;
    if (normals.any() && frame.view && !frame.normals->skipped)
        f.vertexNormals = studentVertexNormals(*frame.scene, *frame.view, normals);
    const Bytes background = backgroundBytes(scene.conventions);
    const DepthTest& depth = *frame.depth;
    const bool reshaded = f.any() || mframe.painted;
    Rgba8Image out;
    if (reshaded)
        out = bytesOf(reshade(frame, *mframe.asked, f), depth, *colour, background);
    else if (colour->bytes)
        out = bytesOf(frame.shading->colour, depth, *colour, background);
    else
        out = colourImage(*frame.shading, depth, scene.conventions);
    const Slip* bg = slipOf(slips, Mistake::Background);
    const Slip* alpha = slipOf(slips, Mistake::Alpha);
    if ((bg && bg->value == background) || (alpha && alpha->value[3] == 255)) return Optional();
    if (bg || alpha) paintBackgroundAndAlpha(out, depth, bg, alpha);
    const Bytes fill = bg ? bg->value : background;
    for (Mistake move : {Mistake::MirroredLeftRight, Mistake::UpsideDown, Mistake::Shifted})
        if (const Slip* s = slipOf(slips, move)) out = movedImage(out, move, s->shift, fill);
    if (const Slip* s = slipOf(slips, Mistake::ScreenMap)) out = mappedImage(out, s->map, fill);
    return Optional(std::move(out));
}

Result<std::optional<Rgba8Image>> imageWithMistakes(const OurFrame& ours,
                                                    const std::vector<Slip>& slips) {
    auto frame = frameWithMistakes(ours, slips);
    if (!frame) return frame.error();
    if (!frame.value()) return std::optional<Rgba8Image>();
    return imageOnFrame(ours, *frame.value(), slips);
}

Result<std::optional<Rgba8Image>> imageWithMistake(const OurFrame& ours, Mistake mistake,
                                                   ivec2 shift, std::array<std::uint8_t, 4> value,
                                                   double amount) {
    return imageWithMistakes(ours, {Slip{mistake, shift, value, amount, {}}});
}

}  // namespace rl
