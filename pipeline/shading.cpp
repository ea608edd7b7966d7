#include "shading.h"

#include <optional>

#include "phong.h"
#include "probe.h"

namespace rl {

namespace {

// Everything shading needs about one draw's projected vertices, in float: view positions
// and normals, including the vertices made by near-plane clipping (interpolated along the
// edge they came from).
struct DrawVertices {
    std::vector<vec3> pView;  // positions
    std::vector<vec3> nView;  // vertex normals (zero where a vertex has none)
};

DrawVertices drawVertices(const DrawProjection& proj, const DrawNormals* normals) {
    DrawVertices out;
    out.pView.reserve(proj.pView.size());
    for (const dvec4& p : proj.pView) out.pView.emplace_back(p);
    if (normals && !normals->vertex.empty()) {
        out.nView = normals->vertex;
        out.nView.resize(proj.pView.size());
        for (std::size_t i = 0; i < proj.generated.size(); ++i) {
            const ClipVertex& g = proj.generated[i];
            out.nView[proj.originalVertexCount + i] =
                glm::mix(normals->vertex[g.a], normals->vertex[g.b], static_cast<float>(g.t));
        }
    } else {
        out.nView.assign(proj.pView.size(), vec3(0.0f));
    }
    return out;
}

// alpha A + beta B + gamma C with alpha = 1 - beta - gamma, written as
// A + beta (B - A) + gamma (C - A) so that equal values interpolate to exactly themselves.
vec3 interpolate(const std::vector<vec3>& values, const ScreenTriangle& tri, float beta,
                 float gamma) {
    const vec3& a = values[tri.v[0]];
    return a + beta * (values[tri.v[1]] - a) + gamma * (values[tri.v[2]] - a);
}

// A normal normalised and, when the convention says so, turned toward the viewer at pView
// (as phong() does); zero stays zero.
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
    const ViewLight* lights = view.lights.data();
    const std::size_t lightCount = view.lights.size();
    const bool flip = conv.flipNormalsTowardViewer;

    std::vector<DrawVertices> vertices;
    vertices.reserve(projection.draws.size());
    for (std::size_t d = 0; d < projection.draws.size(); ++d)
        vertices.push_back(
            drawVertices(projection.draws[d], normals.skipped ? nullptr : &normals.draws[d]));

    // Flat and Gouraud colours, computed the first time a visible pixel needs them.
    struct FlatShade {
        vec3 colour;
        vec3 normal;  // the triangle's normal as the evaluation used it (turned if need be)
    };
    std::vector<std::vector<std::optional<FlatShade>>> flatShades(projection.draws.size());
    std::vector<std::vector<std::optional<vec3>>> vertexColours(projection.draws.size());

    // Seed 004: one evaluation at the barycentre of the (unclipped) triangle, with the
    // triangle's normal.
    auto flatPhong = [&](const ScreenTriangle& tri) {
        const Draw& draw = scene.draws[tri.draw];
        const auto& corners = draw.mesh->triangles[tri.source];
        const auto& pv = vertices[tri.draw].pView;
        const vec3 barycentre = (pv[corners[0]] + pv[corners[1]] + pv[corners[2]]) / 3.0f;
        const vec3 n = normals.skipped ? vec3(0.0f) : normals.draws[tri.draw].triangle[tri.source];
        return phong(draw.material, scene.ambientIntensity, lights, lightCount, barycentre, n,
                     flip);
    };
    auto flatShade = [&](const ScreenTriangle& tri) -> const FlatShade& {
        auto& cache = flatShades[tri.draw];
        if (cache.empty()) cache.resize(scene.draws[tri.draw].mesh->triangles.size());
        auto& slot = cache[tri.source];
        if (!slot) {
            const PhongSample sample = flatPhong(tri);
            count(out, sample);
            slot = FlatShade{sample.colour(), sample.n};
        }
        return *slot;
    };

    // Gouraud: the colour of a projected vertex; a vertex made by clipping takes the colour
    // interpolated along its edge, as if clipping had happened after vertex lighting.
    auto vertexColour = [&](std::uint32_t d, std::uint32_t v) -> vec3 {
        const DrawProjection& proj = projection.draws[d];
        auto& cache = vertexColours[d];
        if (cache.empty()) cache.resize(proj.pView.size());
        auto& slot = cache[v];
        if (!slot) {
            if (v >= proj.originalVertexCount) {
                const ClipVertex& g = proj.generated[v - proj.originalVertexCount];
                const auto lit = [&](std::uint32_t i) {
                    auto& s = cache[i];
                    if (!s) {
                        const PhongSample sample =
                            phong(scene.draws[d].material, scene.ambientIntensity, lights,
                                  lightCount, vertices[d].pView[i], vertices[d].nView[i], flip);
                        count(out, sample);
                        s = sample.colour();
                    }
                    return *s;
                };
                slot = glm::mix(lit(g.a), lit(g.b), static_cast<float>(g.t));
            } else {
                const PhongSample sample =
                    phong(scene.draws[d].material, scene.ambientIntensity, lights, lightCount,
                          vertices[d].pView[v], vertices[d].nView[v], flip);
                count(out, sample);
                slot = sample.colour();
            }
        }
        return *slot;
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
            const float beta = baryRow[x].x;
            const float gamma = baryRow[x].y;
            vec3 colour(0.0f);
            vec3 usedNormal(0.0f);
            [[maybe_unused]] ShadeEvent event;
            switch (draw.shading) {
                case ShadingModel::Phong: {
                    const DrawVertices& dv = vertices[tri.draw];
                    const vec3 p = interpolate(dv.pView, tri, beta, gamma);
                    const vec3 n = interpolate(dv.nView, tri, beta, gamma);
                    const PhongSample s = phong(draw.material, scene.ambientIntensity, lights,
                                                lightCount, p, n, flip);
                    count(out, s);
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
                    if constexpr (Probe::enabled) event.sample = flatPhong(tri);
                    break;
                }
                case ShadingModel::Gouraud: {
                    const vec3 c0 = vertexColour(tri.draw, tri.v[0]);
                    const vec3 c1 = vertexColour(tri.draw, tri.v[1]);
                    const vec3 c2 = vertexColour(tri.draw, tri.v[2]);
                    colour = c0 + beta * (c1 - c0) + gamma * (c2 - c0);
                    if (options.keepNormals) {
                        // The normal Phong would use here: interpolated, normalised, turned
                        // toward the viewer, so that the normals image means the same in
                        // every shading model.
                        const vec3 p = interpolate(vertices[tri.draw].pView, tri, beta, gamma);
                        const vec3 n = interpolate(vertices[tri.draw].nView, tri, beta, gamma);
                        usedNormal = orientedNormal(n, p, flip);
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
