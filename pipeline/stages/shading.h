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

#include "depth_test.h"
#include "image.h"
#include "math.h"
#include "normals.h"
#include "projection.h"
#include "scene.h"
#include "view_transform.h"

namespace rl {

struct ShadingOptions {
    bool keepNormals = false;  // also return the unit normal used at each pixel
};

struct Shading {
    Image<vec3> colour;  // unclamped, scene colour scale; background where empty
    Image<vec3> normal;  // unit normal used per pixel (only with keepNormals)
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
    // 1 where a triangle won the pixel, 0 elsewhere: only when shaded in bands
    // (ShadingStage::runWithDepthTest), whose depth test keeps no ids; empty otherwise.
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

class ShadingStage {
public:
    // threads: the rows are shared out between them (parallel.h); the result does not depend
    // on their number. recycled: an earlier frame's buffers, whose memory is reused.
    template <typename Probe>
    Shading run(const Scene& scene, const ViewTransform& view, const Normals& normals,
                const Projection& projection, const DepthTest& depth, const ShadingOptions& options,
                Probe& probe, int threads = 1, Shading* recycled = nullptr) const;
    Shading run(const Scene& scene, const ViewTransform& view, const Normals& normals,
                const Projection& projection, const DepthTest& depth,
                const ShadingOptions& options = {}, int threads = 1,
                Shading* recycled = nullptr) const;
    // The depth test and shading together, for a frame that keeps its image alone: each
    // thread shades a chunk of rows as soon as it has tested it, from the band it tested it
    // in (DepthTestStage::runBands), so that the ids and barycentrics never leave its cache;
    // only the colours (and covered) go to memory. The image is the same bits as run's after
    // the depth test's; the depth test keeps no per-pixel buffer. Flat and Gouraud colours
    // are worked out first, for every triangle with a fragment (shadeInBands: when they are
    // few next to the pixels). depthShare: of the threads' time, the part spent testing.
    std::pair<DepthTest, Shading> runWithDepthTest(const Scene& scene, const ViewTransform& view,
                                                   const Normals& normals,
                                                   const Projection& projection,
                                                   const ScanConversion& scan, int threads,
                                                   Shading* recycled, double& depthShare) const;
};

// Whether shading in bands (ShadingStage::runWithDepthTest) pays: the points its flat and
// Gouraud draws light before the depth test (those of every triangle with a fragment, not
// only those that keep a pixel: a flat draw's triangles, a Gouraud draw's vertices) are at
// most one per kBandsFragmentsPerPoint fragments, counted by an upper bound that costs no
// pass over the triangles.
inline constexpr std::size_t kBandsFragmentsPerPoint = 4;
bool shadeInBands(const Scene& scene, const Projection& projection, const ScanConversion& scan);

}  // namespace rl
