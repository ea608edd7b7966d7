// Stage 7, shading: the colour of every visible pixel, by the draw's shading model.
// - Phong (seed 000): P' = alpha P1 + beta P2 + gamma P3 and N = alpha N1 + beta N2 +
//   gamma N3 with the pixel's screen barycentrics, then the lighting model of phong.h.
// - Flat (seed 004): one evaluation per triangle at its barycentre, with the triangle's
//   normal; every pixel of the triangle gets that colour.
// - Gouraud: one evaluation per vertex with the vertex normal; the pixel's colour is
//   alpha C1 + beta C2 + gamma C3.
// Only pixels that won the depth test are shaded, and flat and Gouraud evaluate only the
// triangles and vertices that are visible. Colours stay unclamped floats in the scene's
// scale (0..255 for course files); clamping happens when the image becomes bytes.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "pipeline/core/image.h"
#include "pipeline/core/math.h"
#include "pipeline/scene/scene.h"
#include "pipeline/stages/depth_test.h"
#include "pipeline/stages/normals.h"
#include "pipeline/stages/phong.h"
#include "pipeline/stages/projection.h"
#include "pipeline/stages/view_transform.h"

namespace rl {

struct Shading {
    Image<vec3> colour;  // unclamped, scene colour scale; background where empty
    Image<vec3> normal;  // unit normal used per pixel (the fast path keeps it when asked)
    std::size_t shadedPixels = 0;
    std::size_t phongEvaluations = 0;
    std::size_t flipped = 0;        // V.N < 0: the normal was turned toward the viewer
    std::size_t lightBehind = 0;    // N.L < 0: no diffuse, no specular
    std::size_t noSpecular = 0;     // R.V < 0: no specular
    std::size_t noNormal = 0;       // zero normal: ambient only
    std::size_t clampedPixels = 0;  // a channel above the colour scale (becomes 255)
    // Per chunk of kRowChunk rows (parallel.h), the columns that may hold other than the
    // background (the depth test's DepthTest::touched); empty when not tracked. The next
    // frame that reuses these buffers writes the background only where it is missing.
    std::vector<ColumnRange> touched;
    vec3 background = vec3(0.0f);  // of the pixels outside touched
    // 1 where a triangle won the pixel, 0 elsewhere: only when the fast path shaded it in
    // bands, whose depth test keeps no ids; empty otherwise.
    Image<std::uint8_t> covered;
};

// The pieces of per-pixel shading that the views explain: the very code the stage runs.

// alpha A + beta B + gamma C with alpha = 1 - beta - gamma, written as
// A + beta (B - A) + gamma (C - A) so that equal values interpolate to exactly themselves.
// values: anything indexed by vertex.
template <typename Values>
auto interpolate(const Values& values, const std::array<std::uint32_t, 3>& v, float beta,
                 float gamma) {
    const auto a = values[v[0]];
    return a + beta * (values[v[1]] - a) + gamma * (values[v[2]] - a);
}

// Values given per vertex of a draw's mesh, extended to the vertices made by clipping: each
// mixes those at the ends of the edge it was made on (which may be made vertices too, made
// earlier).
template <typename T>
void extendByClipping(std::vector<T>& values, const DrawProjection& proj) {
    values.resize(proj.pView.size());
    for (std::size_t i = 0; i < proj.generated.size(); ++i) {
        const ClipVertex& g = proj.generated[i];
        values[proj.originalVertexCount + i] =
            glm::mix(values[g.a], values[g.b], static_cast<float>(g.t));
    }
}

// The same value at one projected vertex v, without extending the whole list (zero where the
// mesh has none).
template <typename T>
T projectedValue(const std::vector<T>& values, const DrawProjection& proj, std::uint32_t v) {
    if (v < proj.originalVertexCount) return v < values.size() ? values[v] : T(0.0f);
    const ClipVertex& g = proj.generated[v - proj.originalVertexCount];
    return glm::mix(projectedValue(values, proj, g.a), projectedValue(values, proj, g.b),
                    static_cast<float>(g.t));
}

// A mesh's per-vertex values seen at a draw's projected vertices (projectedValue), for
// interpolate and objectColour.
template <typename T>
struct ProjectedValues {
    const std::vector<T>& values;
    const DrawProjection& proj;
    bool empty() const { return values.empty(); }
    T operator[](std::uint32_t v) const { return projectedValue(values, proj, v); }
};

// Under perspective-correct rules, the weights attributes are interpolated with: each screen
// barycentric over its vertex's clip w (invW = 1 / w) and renormalised; unchanged when the
// sum is 0 or not finite.
inline void perspectiveWeights(float& beta, float& gamma, double invW0, double invW1,
                               double invW2) {
    const double w0 = double(1.0f - beta - gamma) * invW0;
    const double w1 = double(beta) * invW1;
    const double w2 = double(gamma) * invW2;
    const double sum = w0 + w1 + w2;
    if (sum != 0.0 && std::isfinite(sum)) {
        beta = static_cast<float>(w1 / sum);
        gamma = static_cast<float>(w2 / sum);
    }
}
// The weights for the vertices v of a draw under the rules: the screen barycentrics, or
// perspectiveWeights under perspective-correct rules.
void attributeWeights(const RasterRules& rules, const DrawProjection& proj,
                      const std::array<std::uint32_t, 3>& v, float& beta, float& gamma);

// The texel (i, j) of a w x h texture at (s, t), under a rule of texel rounding: the one
// nearest to (s w, t h), the coordinates wrapping around (seed 001), or the HW2 reference
// images' truncation (RasterRules::TexelRounding). The texture is not empty.
ivec2 texelIndex(const Texture& texture, const vec2& st, RasterRules::TexelRounding rule);
// That texel's value; zero for an empty texture.
vec4 sampleTexture(const Texture& texture, const vec2& st, RasterRules::TexelRounding rule);

// Where a fragment of a textured draw reads its texture, under both rules of texel rounding:
// seed 001's text and the HW2 reference images disagree where s w + 0.5 < 0 (or t h + 0.5),
// and the pixel inspector and --explain-pixel say so.
struct TexelLookup {
    vec2 st = vec2(0.0f);        // interpolated under the scene's rules
    ivec2 used = ivec2(0);       // the texel read, under the scene's rules
    ivec2 nearest = ivec2(0);    // seed 001's text: nearest to (s w, t h) once wrapped
    ivec2 truncated = ivec2(0);  // the HW2 images: (int)(s w + 0.5) mod w
    bool rulesDisagree() const { return nearest != truncated; }
};
// The lookup of a fragment of screen triangle tri at its screen weights (beta, gamma); none
// when its draw does not read a texture.
std::optional<TexelLookup> texelLookup(const Scene& scene, const DrawProjection& proj,
                                       const std::array<std::uint32_t, 3>& v, std::uint32_t draw,
                                       float beta, float gamma);

// The object colour (the course's Od) of a draw at the weights (beta, gamma) of its projected
// vertices v: the material's, the vertex colours interpolated, or the texel there (decals:
// over the vertex colours, by the texel's alpha). colours and texcoords are indexed by
// projected vertex, empty when the draw's colour source does not read them or the mesh has
// none.
template <typename Colours, typename Texcoords>
vec3 objectColour(const Draw& draw, RasterRules::TexelRounding texel, const Colours& colours,
                  const Texcoords& texcoords, const std::array<std::uint32_t, 3>& v, float beta,
                  float gamma) {
    switch (draw.colour) {
        case ColourSource::Material:
            return draw.material.od;
        case ColourSource::Vertex:
            return colours.empty() ? draw.material.od : interpolate(colours, v, beta, gamma);
        case ColourSource::Texture: {
            if (!draw.texture || texcoords.empty()) return draw.material.od;
            const vec4 value =
                sampleTexture(*draw.texture, interpolate(texcoords, v, beta, gamma), texel);
            if (!draw.decals || colours.empty()) return vec3(value);
            // Decals: the texture over the object colour, by the texel's alpha.
            return glm::mix(interpolate(colours, v, beta, gamma), vec3(value), value.a);
        }
    }
    return draw.material.od;
}

// A normal normalised and, when the convention says so, turned toward the viewer at pView
// (as the lighting models do); zero stays zero. flipped, when given, tells whether it was
// turned.
inline vec3 orientedNormal(const vec3& n, const vec3& pView, bool flip, bool* flipped = nullptr) {
    if (flipped) *flipped = false;
    const float length = glm::length(n);
    if (!(length > 0.0f)) return vec3(0.0f);
    const vec3 unit = n / length;
    if (!flip || !(glm::dot(-pView, unit) < 0.0f)) return unit;
    if (flipped) *flipped = true;
    return -unit;
}

struct ShadingInput {
    const Scene& scene;
    const ViewTransform& view;
    const Normals& normals;
    const Projection& projection;
    const DepthTest& depth;
};

class ShadingStage {
public:
    // Every pixel of the image: the background where no triangle won it, else the colour of
    // its winning fragment by the draw's shading model, and the normal used there. A probe
    // (probe.h) hears of every pixel shaded, with its lighting terms.
    Shading run(const ShadingInput& in) const;
    template <typename Probe>
    Shading run(const ShadingInput& in, Probe& probe) const;
};

// The stage's pieces, which the fast path (fast/shading_fast.h) uses too ------------------

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

// How the points of a frame's draws are lit, by each draw's lighting model.
class FrameLighting {
public:
    FrameLighting(const Scene& scene, const ViewTransform& view, const Normals& normals,
                  const Projection& projection);

    const Scene& scene() const { return m_scene; }
    const ViewTransform& view() const { return m_view; }
    const Normals& normals() const { return m_normals; }
    const Projection& projection() const { return m_projection; }
    const DrawVertices& vertices(std::size_t draw) const { return m_vertices[draw]; }
    bool perspective() const { return m_perspective; }

    // The light at point p with normal n of a draw whose object colour is objectColour.
    PhongSample light(const Draw& draw, const vec3& objectColour, const vec3& p,
                      const vec3& n) const;
    // The screen weights of a triangle's pixel made perspective-correct when the rules say so.
    void attributeWeights(const ScreenTriangle& tri, float& beta, float& gamma) const;
    // The object colour at weights (beta, gamma) of a screen triangle.
    vec3 colourAt(const ScreenTriangle& tri, float beta, float gamma) const;
    // The normal to light a point with: the triangle's (flat normals) or interpolated; none
    // for an unlit draw.
    vec3 normalAt(const ScreenTriangle& tri, float beta, float gamma) const;
    // Phong (seed 000): P' and N interpolated at the weights, then lit.
    PhongSample pixelSample(const ScreenTriangle& tri, float beta, float gamma, vec3* point,
                            vec3* normal) const;
    // Flat (seed 004): one evaluation at the barycentre of the (unclipped) triangle, with the
    // triangle's normal; the point and normal lit are given back when asked.
    PhongSample flatSample(const ScreenTriangle& tri, vec3* point = nullptr,
                           vec3* normal = nullptr) const;
    // Gouraud: vertex v of draw d lit with its normal.
    PhongSample vertexSample(std::size_t d, std::uint32_t v) const;

private:
    const Scene& m_scene;
    const ViewTransform& m_view;
    const Normals& m_normals;
    const Projection& m_projection;
    bool m_flip = true;
    bool m_perspective = false;
    std::vector<DrawVertices> m_vertices;
};

// Flat and Gouraud colours, lit before the pixels for the triangles that hold a pixel: per
// mesh triangle of a flat draw, the colour and the normal used; per projected vertex of a
// Gouraud draw, the colour (a vertex made by clipping takes the colour interpolated along
// its edge, as if clipping had happened after vertex lighting).
struct DrawColours {
    std::vector<vec3> flatColour, flatNormal;  // per mesh triangle
    std::vector<vec3> vertexColour;            // per projected vertex
    std::vector<std::uint8_t> state;           // per entry: kNotNeeded, kNeeded or kLit
    static constexpr std::uint8_t kNotNeeded = 0, kNeeded = 1, kLit = 2;
};
struct ColourTables {
    std::vector<DrawColours> draws;
};
// Marks what the visible triangles (visible[t] != 0, per projected triangle) need lit.
ColourTables neededColours(const FrameLighting& lighting, const std::vector<std::uint8_t>& visible);
// Lights entry i of draw d's table (a flat triangle or a Gouraud vertex), counted in counts.
void lightEntry(const FrameLighting& lighting, ColourTables& tables, std::size_t d, std::size_t i,
                Shading& counts);
// The colours of Gouraud vertices made by clipping, from those of their edge's ends.
void colourClippedVertices(const FrameLighting& lighting, ColourTables& tables, Shading& counts);

// The colour of a fragment of screen triangle t at screen weights (beta, gamma), at pixel
// (x, y), by its draw's shading model (the tables hold the flat and Gouraud colours); counted
// in counts. usedNormal, when given, receives the unit normal it was lit with.
template <typename Probe>
vec3 shadeFragment(const FrameLighting& lighting, const ColourTables& tables, std::uint32_t t,
                   int x, int y, float beta, float gamma, vec3* usedNormal, Shading& counts,
                   Probe& probe);

// A lit point counted: evaluations, flipped normals, lights behind, no specular, no normal.
void countSample(Shading& counts, const PhongSample& s);
// The counts of several frames' parts added up.
void addCounts(Shading& total, const Shading& part);

}  // namespace rl
