#include "shading.h"

#include "pipeline/stages/probe.h"

namespace rl {

namespace {

DrawVertices drawVertices(const Draw& draw, const DrawProjection& proj, const DrawNormals* normals,
                          bool perspective) {
    DrawVertices out;
    const bool lit = draw.lighting != LightingModel::Unlit;
    if (lit) {
        out.pView.reserve(proj.pView.size());
        for (const dvec4& p : proj.pView) out.pView.emplace_back(cartesian(p));
        if (normals && !normals->vertex.empty()) {
            out.nView = normals->vertex;
            extendByClipping(out.nView, proj);
        } else if (!normals) {  // the scene is not lit
            out.nView.assign(proj.pView.size(), vec3(0.0f));
        }  // else left out by the normals stage (NormalsScope::Read): nothing reads them
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

}  // namespace

void countSample(Shading& counts, const PhongSample& s) {
    ++counts.phongEvaluations;
    counts.flipped += s.flipped ? 1 : 0;
    counts.lightBehind += s.lightBehind ? 1 : 0;
    counts.noSpecular += s.noSpecular ? 1 : 0;
    counts.noNormal += s.noNormal ? 1 : 0;
}

void addCounts(Shading& total, const Shading& part) {
    total.shadedPixels += part.shadedPixels;
    total.phongEvaluations += part.phongEvaluations;
    total.flipped += part.flipped;
    total.lightBehind += part.lightBehind;
    total.noSpecular += part.noSpecular;
    total.noNormal += part.noNormal;
    total.clampedPixels += part.clampedPixels;
}

void attributeWeights(const RasterRules& rules, const DrawProjection& proj,
                      const std::array<std::uint32_t, 3>& v, float& beta, float& gamma) {
    if (rules.interpolation != RasterRules::Interpolation::PerspectiveCorrect) return;
    perspectiveWeights(beta, gamma, 1.0 / proj.pClip[v[0]].w, 1.0 / proj.pClip[v[1]].w,
                       1.0 / proj.pClip[v[2]].w);
}

ivec2 texelIndex(const Texture& texture, const vec2& st, RasterRules::TexelRounding rule) {
    const auto pick = [rule](float u, int size) {
        if (rule == RasterRules::TexelRounding::Truncate) {
            // (int)(u size + 0.5) mod size; a coordinate too large for an int wraps as 0.
            const float scaled = u * float(size) + 0.5f;
            const auto whole =
                std::abs(scaled) < 2e9f ? static_cast<long long>(scaled) : 0LL;  // toward 0
            const auto i = static_cast<int>(whole % size);
            return i < 0 ? i + size : i;
        }
        const float f = u - std::floor(u);  // -1.3, -0.3, 0.7, 1.7 all give 0.7
        const int i = static_cast<int>(std::floor(f * float(size) + 0.5f)) % size;
        return std::clamp(i, 0, size - 1);
    };
    return {pick(st.x, texture.width), pick(st.y, texture.height)};
}

vec4 sampleTexture(const Texture& texture, const vec2& st, RasterRules::TexelRounding rule) {
    if (texture.width <= 0 || texture.height <= 0) return vec4(0.0f);
    const ivec2 texel = texelIndex(texture, st, rule);
    return texture.at(texel.x, texel.y);
}

std::optional<TexelLookup> texelLookup(const Scene& scene, const DrawProjection& proj,
                                       const std::array<std::uint32_t, 3>& v, std::uint32_t draw,
                                       float beta, float gamma) {
    const Draw& d = scene.draws[draw];
    if (d.colour != ColourSource::Texture || !d.texture || !d.mesh || d.mesh->texcoords.empty() ||
        d.texture->width <= 0 || d.texture->height <= 0)
        return std::nullopt;
    attributeWeights(scene.rules, proj, v, beta, gamma);
    TexelLookup out;
    out.st = interpolate(ProjectedValues<vec2>{d.mesh->texcoords, proj}, v, beta, gamma);
    out.used = texelIndex(*d.texture, out.st, scene.rules.texel);
    out.nearest = texelIndex(*d.texture, out.st, RasterRules::TexelRounding::Nearest);
    out.truncated = texelIndex(*d.texture, out.st, RasterRules::TexelRounding::Truncate);
    return out;
}

// The lighting of points ---------------------------------------------------------------

FrameLighting::FrameLighting(const Scene& scene, const ViewTransform& view, const Normals& normals,
                             const Projection& projection)
    : m_scene(scene),
      m_view(view),
      m_normals(normals),
      m_projection(projection),
      m_flip(scene.conventions.flipNormalsTowardViewer),
      m_perspective(scene.rules.interpolation == RasterRules::Interpolation::PerspectiveCorrect) {
    m_vertices.reserve(projection.draws.size());
    for (std::size_t d = 0; d < projection.draws.size(); ++d)
        m_vertices.push_back(drawVertices(scene.draws[d], projection.draws[d],
                                          normals.skipped ? nullptr : &normals.draws[d],
                                          m_perspective));
}

PhongSample FrameLighting::light(const Draw& draw, const vec3& objectColour, const vec3& p,
                                 const vec3& n) const {
    const std::size_t lightCount = std::min(draw.lightCount, m_view.lights.size());
    switch (draw.lighting) {
        case LightingModel::CoursePhong:
            return phong(draw.material, objectColour, m_scene.ambientIntensity,
                         m_view.lights.data(), lightCount, p, n, m_flip, draw.specular);
        case LightingModel::Lambert:
            return hw2Lighting(objectColour, draw.material.shininess, m_view.lights.data(),
                               lightCount, p, n, m_flip);
        case LightingModel::Unlit:
            break;
    }
    PhongSample s;
    s.unlit = objectColour;
    return s;
}

void FrameLighting::attributeWeights(const ScreenTriangle& tri, float& beta, float& gamma) const {
    if (!m_perspective) return;
    const DrawVertices& dv = m_vertices[tri.draw];
    perspectiveWeights(beta, gamma, dv.invW[tri.v[0]], dv.invW[tri.v[1]], dv.invW[tri.v[2]]);
}

vec3 FrameLighting::colourAt(const ScreenTriangle& tri, float beta, float gamma) const {
    const DrawVertices& dv = m_vertices[tri.draw];
    return objectColour(m_scene.draws[tri.draw], m_scene.rules.texel, dv.colour, dv.texcoord, tri.v,
                        beta, gamma);
}

vec3 FrameLighting::normalAt(const ScreenTriangle& tri, float beta, float gamma) const {
    // An unlit draw (HW2 geometry before the first light, in a lit scene) has none: nothing
    // reads it.
    const Draw& draw = m_scene.draws[tri.draw];
    if (m_normals.skipped || draw.lighting == LightingModel::Unlit) return vec3(0.0f);
    if (draw.flatNormals) return m_normals.draws[tri.draw].triangle[tri.source];
    return interpolate(m_vertices[tri.draw].nView, tri.v, beta, gamma);
}

PhongSample FrameLighting::pixelSample(const ScreenTriangle& tri, float beta, float gamma,
                                       vec3* point, vec3* normal) const {
    const DrawVertices& dv = m_vertices[tri.draw];
    const vec3 p = dv.pView.empty() ? vec3(0.0f) : interpolate(dv.pView, tri.v, beta, gamma);
    const vec3 n = normalAt(tri, beta, gamma);
    if (point) *point = p;
    if (normal) *normal = n;
    return light(m_scene.draws[tri.draw], colourAt(tri, beta, gamma), p, n);
}

PhongSample FrameLighting::flatSample(const ScreenTriangle& tri, vec3* point, vec3* normal) const {
    const Draw& draw = m_scene.draws[tri.draw];
    const ScreenTriangle whole{tri.draw, tri.source, draw.mesh->triangles[tri.source]};
    const DrawVertices& dv = m_vertices[tri.draw];
    const float third = 1.0f / 3.0f;
    const vec3 barycentre =
        dv.pView.empty() ? vec3(0.0f) : interpolate(dv.pView, whole.v, third, third);
    const vec3 n = m_normals.skipped ? vec3(0.0f) : m_normals.draws[tri.draw].triangle[tri.source];
    if (point) *point = barycentre;
    if (normal) *normal = n;
    return light(draw, colourAt(whole, third, third), barycentre, n);
}

PhongSample FrameLighting::vertexSample(std::size_t d, std::uint32_t v) const {
    const DrawVertices& dv = m_vertices[d];
    const ScreenTriangle at{static_cast<std::uint32_t>(d), 0, {v, v, v}};
    return light(m_scene.draws[d], colourAt(at, 0.0f, 0.0f),
                 dv.pView.empty() ? vec3(0.0f) : dv.pView[v],
                 dv.nView.empty() ? vec3(0.0f) : dv.nView[v]);
}

// Flat and Gouraud colours, lit before the pixels --------------------------------------

ColourTables neededColours(const FrameLighting& lighting,
                           const std::vector<std::uint8_t>& visible) {
    const Scene& scene = lighting.scene();
    const Projection& projection = lighting.projection();
    ColourTables tables;
    tables.draws.resize(projection.draws.size());
    for (std::size_t t = 0; t < projection.triangles.size(); ++t) {
        if (!visible[t]) continue;
        const ScreenTriangle& tri = projection.triangles[t];
        const Draw& draw = scene.draws[tri.draw];
        DrawColours& table = tables.draws[tri.draw];
        if (litPerTriangle(draw.shading)) {
            if (table.state.empty()) {
                table.flatColour.resize(draw.mesh->triangles.size());
                table.flatNormal.resize(draw.mesh->triangles.size());
                table.state.assign(draw.mesh->triangles.size(), DrawColours::kNotNeeded);
            }
            table.state[tri.source] = DrawColours::kNeeded;
        } else if (draw.shading == ShadingModel::Gouraud) {
            if (table.state.empty()) {
                const std::size_t n = projection.draws[tri.draw].pView.size();
                table.vertexColour.resize(n);
                table.state.assign(n, DrawColours::kNotNeeded);
            }
            for (std::uint32_t v : tri.v) table.state[v] = DrawColours::kNeeded;
        }
    }
    return tables;
}

void lightEntry(const FrameLighting& lighting, ColourTables& tables, std::size_t d, std::size_t i,
                Shading& counts) {
    const Draw& draw = lighting.scene().draws[d];
    DrawColours& table = tables.draws[d];
    if (litPerTriangle(draw.shading)) {
        const ScreenTriangle tri{static_cast<std::uint32_t>(d), static_cast<std::uint32_t>(i),
                                 draw.mesh->triangles[i]};
        const PhongSample sample = lighting.flatSample(tri);
        countSample(counts, sample);
        table.flatColour[i] = sample.colour();
        table.flatNormal[i] = sample.n;
    } else {
        const PhongSample sample = lighting.vertexSample(d, static_cast<std::uint32_t>(i));
        countSample(counts, sample);
        table.vertexColour[i] = sample.colour();
    }
    table.state[i] = DrawColours::kLit;
}

namespace {

// A Gouraud vertex's colour; one made by clipping mixes those of its edge's ends (which may
// be made by clipping too), an end no visible triangle uses is lit now.
vec3 gouraudColour(const FrameLighting& lighting, ColourTables& tables, std::size_t d,
                   std::uint32_t v, Shading& counts) {
    DrawColours& table = tables.draws[d];
    if (table.state[v] == DrawColours::kLit) return table.vertexColour[v];
    const DrawProjection& proj = lighting.projection().draws[d];
    if (v < proj.originalVertexCount) {
        lightEntry(lighting, tables, d, v, counts);
        return table.vertexColour[v];
    }
    const ClipVertex& g = proj.generated[v - proj.originalVertexCount];
    const vec3 a = gouraudColour(lighting, tables, d, g.a, counts);
    const vec3 b = gouraudColour(lighting, tables, d, g.b, counts);
    table.vertexColour[v] = glm::mix(a, b, static_cast<float>(g.t));
    table.state[v] = DrawColours::kLit;
    return table.vertexColour[v];
}

}  // namespace

void colourClippedVertices(const FrameLighting& lighting, ColourTables& tables, Shading& counts) {
    const Projection& projection = lighting.projection();
    for (std::size_t d = 0; d < tables.draws.size(); ++d) {
        DrawColours& table = tables.draws[d];
        if (table.state.empty() || lighting.scene().draws[d].shading != ShadingModel::Gouraud)
            continue;
        for (std::size_t v = projection.draws[d].originalVertexCount; v < table.state.size(); ++v)
            if (table.state[v] == DrawColours::kNeeded)
                gouraudColour(lighting, tables, d, static_cast<std::uint32_t>(v), counts);
    }
}

// The stage ---------------------------------------------------------------------------------

namespace {

// The projected triangles that hold a pixel at the end: those flat and Gouraud shading light.
std::vector<std::uint8_t> visibleTriangles(const ShadingInput& in) {
    std::vector<std::uint8_t> visible(in.projection.triangles.size(), 0);
    for (std::uint32_t t : in.depth.triangle.pixels())
        if (t != kNoTriangle) visible[t] = 1;
    return visible;
}

// Every flat triangle and Gouraud vertex the visible triangles need, lit once.
ColourTables lightTrianglesAndVertices(const ShadingInput& in, const FrameLighting& lighting,
                                       Shading& counts) {
    ColourTables tables = neededColours(lighting, visibleTriangles(in));
    for (std::size_t d = 0; d < tables.draws.size(); ++d) {
        const DrawColours& table = tables.draws[d];
        // Flat: every triangle; Gouraud: the vertices the projection did not make.
        const std::size_t own = litPerTriangle(in.scene.draws[d].shading)
                                    ? table.state.size()
                                    : in.projection.draws[d].originalVertexCount;
        for (std::size_t i = 0; i < std::min(own, table.state.size()); ++i)
            if (table.state[i] == DrawColours::kNeeded) lightEntry(lighting, tables, d, i, counts);
    }
    colourClippedVertices(lighting, tables, counts);
    return tables;
}

}  // namespace

template <typename Probe>
vec3 shadeFragment(const FrameLighting& lighting, const ColourTables& tables, std::uint32_t t,
                   int x, int y, float beta, float gamma, vec3* usedNormal, Shading& counts,
                   Probe& probe) {
    const Scene& scene = lighting.scene();
    const ScreenTriangle& tri = lighting.projection().triangles[t];
    const Draw& draw = scene.draws[tri.draw];
    const DrawColours& table = tables.draws[tri.draw];
    [[maybe_unused]] ShadeEvent event;
    lighting.attributeWeights(tri, beta, gamma);
    vec3 colour(0.0f);
    vec3 normal(0.0f);
    switch (draw.shading) {
        case ShadingModel::Phong: {
            vec3 p(0.0f), n(0.0f);
            const PhongSample s = lighting.pixelSample(tri, beta, gamma, &p, &n);
            if (draw.lighting != LightingModel::Unlit) countSample(counts, s);
            colour = s.colour();
            normal = s.n;
            RL_PROBE_HOOK(event.pView = p; event.nInterpolated = n; event.sample = s);
            break;
        }
        case ShadingModel::Flat:
        case ShadingModel::Painter:
            colour = table.flatColour[tri.source];
            normal = table.flatNormal[tri.source];
            RL_PROBE_HOOK(event.sample =
                              lighting.flatSample(tri, &event.pView, &event.nInterpolated));
            break;
        case ShadingModel::Gouraud: {
            const vec3 c0 = table.vertexColour[tri.v[0]];
            const vec3 c1 = table.vertexColour[tri.v[1]];
            const vec3 c2 = table.vertexColour[tri.v[2]];
            colour = c0 + beta * (c1 - c0) + gamma * (c2 - c0);
            // The normal Phong would use here, so that the normals image means the same in
            // every shading model.
            const DrawVertices& dv = lighting.vertices(tri.draw);
            if (usedNormal && !dv.pView.empty())
                normal = orientedNormal(lighting.normalAt(tri, beta, gamma),
                                        interpolate(dv.pView, tri.v, beta, gamma),
                                        scene.conventions.flipNormalsTowardViewer);
            RL_PROBE_HOOK(event.vertexColours = {c0, c1, c2});
            break;
        }
    }
    if (usedNormal) *usedNormal = normal;
    const float scale = scene.conventions.colourScale;
    ++counts.shadedPixels;
    counts.clampedPixels += (colour.r > scale || colour.g > scale || colour.b > scale) ? 1 : 0;
    RL_PROBE_HOOK(event.triangle = t; event.x = x; event.y = y; event.model = draw.shading;
                  event.colour = colour; probe.onShade(event));
    return colour;
}

template <typename Probe>
Shading ShadingStage::run(const ShadingInput& in, Probe& probe) const {
    const Scene& scene = in.scene;
    Shading out;
    out.background = vec3(scene.conventions.background) * scene.conventions.colourScale;
    out.colour.reset(scene.width, scene.height, out.background);
    out.normal.reset(scene.width, scene.height, vec3(0.0f));
    const FrameLighting lighting(scene, in.view, in.normals, in.projection);
    // Flat and Gouraud light their triangles and vertices first, once each.
    bool anyPerTriangle = false;
    for (const Draw& draw : scene.draws)
        anyPerTriangle = anyPerTriangle || draw.shading != ShadingModel::Phong;
    ColourTables tables;
    if (anyPerTriangle) tables = lightTrianglesAndVertices(in, lighting, out);
    tables.draws.resize(in.projection.draws.size());
    // Then every pixel a triangle won.
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            const std::uint32_t t = in.depth.triangle.at(x, y);
            if (t == kNoTriangle) continue;
            const vec2 b = in.depth.barycentric.at(x, y);
            out.colour.at(x, y) = shadeFragment(lighting, tables, t, x, y, b.x, b.y,
                                                &out.normal.at(x, y), out, probe);
        }
    return out;
}

Shading ShadingStage::run(const ShadingInput& in) const {
    NullProbe probe;
    return run(in, probe);
}

template Shading ShadingStage::run<NullProbe>(const ShadingInput&, NullProbe&) const;
template Shading ShadingStage::run<RecordingProbe>(const ShadingInput&, RecordingProbe&) const;
template vec3 shadeFragment<NullProbe>(const FrameLighting&, const ColourTables&, std::uint32_t,
                                       int, int, float, float, vec3*, Shading&, NullProbe&);

}  // namespace rl
