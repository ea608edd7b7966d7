#include "shading.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "phong.h"
#include "probe.h"

namespace rl {

namespace {

// What shading reads about one draw's projected vertices, in float: one entry per vertex,
// the draw's own and then those made by clipping (interpolated along the edge they came
// from). Only what the draw's lighting and colour source read is filled.
struct DrawVertices {
    std::vector<vec3> pView;     // positions (x, y, z) / w
    std::vector<vec3> nView;     // vertex normals (zero where a vertex has none)
    std::vector<vec3> colour;    // object colours per vertex
    std::vector<vec2> texcoord;  // texture coordinates
    std::vector<double> invW;    // 1 / clip w, for perspective-correct weights (double: a
                                 // float 1/w would overflow for |w| < 3e-39)
};

// Values for the vertices made by clipping, interpolated from their edges' ends (which
// may be made vertices too, made earlier).
template <typename T>
void extendByClipping(std::vector<T>& values, const DrawProjection& proj) {
    values.resize(proj.pView.size());
    for (std::size_t i = 0; i < proj.generated.size(); ++i) {
        const ClipVertex& g = proj.generated[i];
        values[proj.originalVertexCount + i] =
            glm::mix(values[g.a], values[g.b], static_cast<float>(g.t));
    }
}

DrawVertices drawVertices(const Draw& draw, const DrawProjection& proj, const DrawNormals* normals,
                          bool perspective) {
    DrawVertices out;
    const bool lit = draw.lighting != LightingModel::Unlit;
    if (lit) {
        out.pView.reserve(proj.pView.size());
        for (const dvec4& p : proj.pView)
            out.pView.emplace_back(p.w != 0.0 && p.w != 1.0 ? dvec3(p) / p.w : dvec3(p));
        if (normals && !normals->vertex.empty()) {
            out.nView = normals->vertex;
            extendByClipping(out.nView, proj);
        } else {
            out.nView.assign(proj.pView.size(), vec3(0.0f));
        }
    }
    const bool vertexColours = draw.colour == ColourSource::Vertex ||
                               (draw.colour == ColourSource::Texture && draw.decals);
    if (vertexColours && !draw.mesh->colours.empty()) {
        out.colour = draw.mesh->colours;
        extendByClipping(out.colour, proj);
    }
    if (draw.colour == ColourSource::Texture && !draw.mesh->texcoords.empty()) {
        out.texcoord = draw.mesh->texcoords;
        extendByClipping(out.texcoord, proj);
    }
    if (perspective) {
        out.invW.reserve(proj.pClip.size());
        for (const dvec4& p : proj.pClip) out.invW.push_back(1.0 / p.w);
    }
    return out;
}

// alpha A + beta B + gamma C with alpha = 1 - beta - gamma, written as
// A + beta (B - A) + gamma (C - A) so that equal values interpolate to exactly themselves.
template <typename T>
T interpolate(const std::vector<T>& values, const ScreenTriangle& tri, float beta, float gamma) {
    const T& a = values[tri.v[0]];
    return a + beta * (values[tri.v[1]] - a) + gamma * (values[tri.v[2]] - a);
}

// The texel nearest to (s w, t h), the coordinates wrapping around (seed 001).
vec4 sampleTexture(const Texture& texture, const vec2& st) {
    if (texture.width <= 0 || texture.height <= 0) return vec4(0.0f);
    const auto wrap = [](float u, int size) {
        const float f = u - std::floor(u);  // -1.3, -0.3, 0.7, 1.7 all give 0.7
        const int i = static_cast<int>(std::floor(f * float(size) + 0.5f)) % size;
        return std::clamp(i, 0, size - 1);
    };
    return texture.at(wrap(st.x, texture.width), wrap(st.y, texture.height));
}

// A normal normalised and, when the convention says so, turned toward the viewer at pView
// (as the lighting models do); zero stays zero.
vec3 orientedNormal(const vec3& n, const vec3& pView, bool flip) {
    const float length = glm::length(n);
    if (!(length > 0.0f)) return vec3(0.0f);
    const vec3 unit = n / length;
    return flip && glm::dot(-pView, unit) < 0.0f ? -unit : unit;
}

void count(Shading& out, const PhongSample& s) {
    ++out.phongEvaluations;
    out.flipped += s.flipped ? 1 : 0;
    out.lightBehind += s.lightBehind ? 1 : 0;
    out.noSpecular += s.noSpecular ? 1 : 0;
    out.noNormal += s.noNormal ? 1 : 0;
}

}  // namespace

template <typename Probe>
Shading ShadingStage::run(const Scene& scene, const ViewTransform& view, const Normals& normals,
                          const Projection& projection, const DepthTest& depth,
                          const ShadingOptions& options, Probe& probe) const {
    Shading out;
    const Conventions& conv = scene.conventions;
    const vec3 background = vec3(conv.background) * conv.colourScale;
    out.colour = Image<vec3>(scene.width, scene.height, background);
    if (options.keepNormals) out.normal = Image<vec3>(scene.width, scene.height, vec3(0.0f));
    const bool flip = conv.flipNormalsTowardViewer;
    const bool perspective =
        scene.rules.interpolation == RasterRules::Interpolation::PerspectiveCorrect;

    std::vector<DrawVertices> vertices;
    vertices.reserve(projection.draws.size());
    for (std::size_t d = 0; d < projection.draws.size(); ++d)
        vertices.push_back(drawVertices(scene.draws[d], projection.draws[d],
                                        normals.skipped ? nullptr : &normals.draws[d],
                                        perspective));

    // The light at a point of a draw, by its lighting model.
    auto light = [&](const Draw& draw, const vec3& objectColour, const vec3& p, const vec3& n) {
        const std::size_t lightCount = std::min(draw.lightCount, view.lights.size());
        switch (draw.lighting) {
            case LightingModel::CoursePhong:
                return phong(draw.material, objectColour, scene.ambientIntensity,
                             view.lights.data(), lightCount, p, n, flip);
            case LightingModel::Lambert:
                return lambert(objectColour, draw.material.shininess, view.lights.data(),
                               lightCount, p, n, flip);
            case LightingModel::Unlit:
                break;
        }
        PhongSample s;
        s.unlit = objectColour;
        return s;
    };
    // The object colour of a draw at the weights (beta, gamma) of a screen triangle.
    auto objectColour = [&](const Draw& draw, const DrawVertices& dv, const ScreenTriangle& tri,
                            float beta, float gamma) -> vec3 {
        switch (draw.colour) {
            case ColourSource::Material:
                return draw.material.od;
            case ColourSource::Vertex:
                return dv.colour.empty() ? draw.material.od
                                         : interpolate(dv.colour, tri, beta, gamma);
            case ColourSource::Texture: {
                if (!draw.texture || dv.texcoord.empty()) return draw.material.od;
                const vec4 texel =
                    sampleTexture(*draw.texture, interpolate(dv.texcoord, tri, beta, gamma));
                if (!draw.decals || dv.colour.empty()) return vec3(texel);
                // Decals: the texture over the object colour, by the texel's alpha.
                return glm::mix(interpolate(dv.colour, tri, beta, gamma), vec3(texel), texel.a);
            }
        }
        return draw.material.od;
    };
    // The normal to light a point with: the triangle's (flat normals) or interpolated.
    auto normalAt = [&](const Draw& draw, const DrawVertices& dv, const ScreenTriangle& tri,
                        float beta, float gamma) -> vec3 {
        if (normals.skipped) return vec3(0.0f);
        if (draw.flatNormals) return normals.draws[tri.draw].triangle[tri.source];
        return interpolate(dv.nView, tri, beta, gamma);
    };

    // Flat and Gouraud colours, computed the first time a visible pixel needs them.
    struct FlatShade {
        vec3 colour;
        vec3 normal;  // the triangle's normal as the evaluation used it (turned if need be)
    };
    std::vector<std::vector<std::optional<FlatShade>>> flatShades(projection.draws.size());
    std::vector<std::vector<std::optional<vec3>>> vertexColours(projection.draws.size());

    // Seed 004: one evaluation at the barycentre of the (unclipped) triangle, with the
    // triangle's normal.
    auto flatSample = [&](const ScreenTriangle& tri) {
        const Draw& draw = scene.draws[tri.draw];
        const auto& corners = draw.mesh->triangles[tri.source];
        const DrawVertices& dv = vertices[tri.draw];
        const ScreenTriangle whole{tri.draw, tri.source, corners};
        const float third = 1.0f / 3.0f;
        const vec3 barycentre =
            dv.pView.empty() ? vec3(0.0f) : interpolate(dv.pView, whole, third, third);
        const vec3 n = normals.skipped ? vec3(0.0f) : normals.draws[tri.draw].triangle[tri.source];
        return light(draw, objectColour(draw, dv, whole, third, third), barycentre, n);
    };
    auto flatShade = [&](const ScreenTriangle& tri) -> const FlatShade& {
        auto& cache = flatShades[tri.draw];
        if (cache.empty()) cache.resize(scene.draws[tri.draw].mesh->triangles.size());
        auto& slot = cache[tri.source];
        if (!slot) {
            const PhongSample sample = flatSample(tri);
            count(out, sample);
            slot = FlatShade{sample.colour(), sample.n};
        }
        return *slot;
    };

    // Gouraud: the colour of a projected vertex; a vertex made by clipping takes the colour
    // interpolated along its edge, as if clipping had happened after vertex lighting.
    auto vertexColour = [&](std::uint32_t d, std::uint32_t v) -> vec3 {
        auto& cache = vertexColours[d];
        if (!cache.empty() && cache[v]) return *cache[v];  // the common case, kept short
        const DrawProjection& proj = projection.draws[d];
        const Draw& draw = scene.draws[d];
        const DrawVertices& dv = vertices[d];
        if (cache.empty()) cache.resize(proj.pView.size());
        const auto lit = [&](std::uint32_t i, const auto& self) -> vec3 {
            auto& slot = cache[i];
            if (!slot) {
                if (i >= proj.originalVertexCount) {
                    const ClipVertex& g = proj.generated[i - proj.originalVertexCount];
                    slot = glm::mix(self(g.a, self), self(g.b, self), static_cast<float>(g.t));
                } else {
                    const ScreenTriangle at{std::uint32_t(d), 0, {i, i, i}};
                    const PhongSample sample = light(draw, objectColour(draw, dv, at, 0.0f, 0.0f),
                                                     dv.pView.empty() ? vec3(0.0f) : dv.pView[i],
                                                     dv.nView.empty() ? vec3(0.0f) : dv.nView[i]);
                    count(out, sample);
                    slot = sample.colour();
                }
            }
            return *slot;
        };
        return lit(v, lit);
    };

    for (int y = 0; y < scene.height; ++y) {
        const std::uint32_t* idRow = depth.triangle.row(y);
        const vec2* baryRow = depth.barycentric.row(y);
        vec3* colourRow = out.colour.row(y);
        for (int x = 0; x < scene.width; ++x) {
            const std::uint32_t t = idRow[x];
            if (t == kNoTriangle) continue;
            const ScreenTriangle& tri = projection.triangles[t];
            const Draw& draw = scene.draws[tri.draw];
            const DrawVertices& dv = vertices[tri.draw];
            float beta = baryRow[x].x;
            float gamma = baryRow[x].y;
            if (perspective) {
                // Barycentrics for attributes: each weight over its vertex's w, renormalised.
                const double w0 = double(1.0f - beta - gamma) * dv.invW[tri.v[0]];
                const double w1 = double(beta) * dv.invW[tri.v[1]];
                const double w2 = double(gamma) * dv.invW[tri.v[2]];
                const double sum = w0 + w1 + w2;
                if (sum != 0.0 && std::isfinite(sum)) {
                    beta = static_cast<float>(w1 / sum);
                    gamma = static_cast<float>(w2 / sum);
                }
            }
            vec3 colour(0.0f);
            vec3 usedNormal(0.0f);
            [[maybe_unused]] ShadeEvent event;
            switch (draw.shading) {
                case ShadingModel::Phong: {
                    const vec3 p =
                        dv.pView.empty() ? vec3(0.0f) : interpolate(dv.pView, tri, beta, gamma);
                    const vec3 n = normalAt(draw, dv, tri, beta, gamma);
                    const PhongSample s =
                        light(draw, objectColour(draw, dv, tri, beta, gamma), p, n);
                    if (draw.lighting != LightingModel::Unlit) count(out, s);
                    colour = s.colour();
                    usedNormal = s.n;
                    if constexpr (Probe::enabled) {
                        event.pView = p;
                        event.nInterpolated = n;
                        event.sample = s;
                    }
                    break;
                }
                case ShadingModel::Flat: {
                    const FlatShade& shade = flatShade(tri);
                    colour = shade.colour;
                    usedNormal = shade.normal;
                    if constexpr (Probe::enabled) event.sample = flatSample(tri);
                    break;
                }
                case ShadingModel::Gouraud: {
                    const vec3 c0 = vertexColour(tri.draw, tri.v[0]);
                    const vec3 c1 = vertexColour(tri.draw, tri.v[1]);
                    const vec3 c2 = vertexColour(tri.draw, tri.v[2]);
                    colour = c0 + beta * (c1 - c0) + gamma * (c2 - c0);
                    if (options.keepNormals && !dv.pView.empty()) {
                        // The normal Phong would use here: interpolated, normalised, turned
                        // toward the viewer, so that the normals image means the same in
                        // every shading model.
                        const vec3 p = interpolate(dv.pView, tri, beta, gamma);
                        usedNormal = orientedNormal(normalAt(draw, dv, tri, beta, gamma), p, flip);
                    }
                    if constexpr (Probe::enabled) event.vertexColours = {c0, c1, c2};
                    break;
                }
            }
            colourRow[x] = colour;
            ++out.shadedPixels;
            const float scale = conv.colourScale;
            out.clampedPixels += (colour.r > scale || colour.g > scale || colour.b > scale) ? 1 : 0;
            if (options.keepNormals) out.normal.at(x, y) = usedNormal;
            if constexpr (Probe::enabled) {
                event.triangle = t;
                event.x = x;
                event.y = y;
                event.model = draw.shading;
                event.colour = colour;
                probe.onShade(event);
            }
        }
    }
    return out;
}

Shading ShadingStage::run(const Scene& scene, const ViewTransform& view, const Normals& normals,
                          const Projection& projection, const DepthTest& depth,
                          const ShadingOptions& options) const {
    NullProbe probe;
    return run(scene, view, normals, projection, depth, options, probe);
}

template Shading ShadingStage::run<NullProbe>(const Scene&, const ViewTransform&, const Normals&,
                                              const Projection&, const DepthTest&,
                                              const ShadingOptions&, NullProbe&) const;
template Shading ShadingStage::run<RecordingProbe>(const Scene&, const ViewTransform&,
                                                   const Normals&, const Projection&,
                                                   const DepthTest&, const ShadingOptions&,
                                                   RecordingProbe&) const;

}  // namespace rl
