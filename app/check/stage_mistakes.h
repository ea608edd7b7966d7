// The known mistakes of each stage, as what they would answer: each stage's catalogue of
// mistakes (stage_findings.h composes them) and its answer made with any set of them at once.
// Written in double from the formulas, beside the lecture's stages, not from them: with no
// mistake each is the lecture's formula, and each mistake does one step the way students get
// it wrong (the cross product's order, normals not normalised, rounding against truncation, y
// not flipped, a span's end, the z-buffer's comparison, a Phong special case ...).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/check/stage_findings.h"
#include "pipeline/core/math.h"

namespace rasterlab::check {

using Row = std::vector<double>;
using Mistakes = std::vector<StageMistake>;

inline Row rowOf(const rl::dvec3& v) {
    return {v.x, v.y, v.z};
}
inline Row rowOf(const rl::vec3& v) {
    return {double(v.x), double(v.y), double(v.z)};
}
inline rl::dvec3 vecOf(const Row& r) {
    return {r[0], r[1], r[2]};
}

struct Fragment {
    std::uint32_t t = 0;
    std::int32_t x = 0, y = 0;
    float z = 0.0f;
};

struct Sample {
    rl::vec3 p = rl::vec3(0.0f);  // P' in view coordinates
    rl::vec3 n = rl::vec3(0.0f);  // its unit normal, not yet turned toward the viewer
    // The vertex it was taken at and whether its normal was turned around (for a chained
    // run, which takes both from the student's answers); none for a made-up sample.
    std::optional<std::uint32_t> vertex;
    bool reversed = false;
};

// The course's lighting, the light in view coordinates.
struct Lighting {
    rl::dvec3 light = rl::dvec3(0.0);
    rl::vec3 ia = rl::vec3(0.0f), il = rl::vec3(0.0f);
    float ka = 0.0f, kd = 0.0f;
    rl::vec3 od = rl::vec3(0.0f);
    float ks = 0.0f, n = 1.0f;
};

// basis: rows U, V, N from the camera file's N and V.
Mistakes basisCatalogue();
std::vector<Row> basisAnswer(const rl::dvec3& n, const rl::dvec3& v, const Mistakes& applied);

// view: the light's row, then the vertices', from the basis sent.
Mistakes viewCatalogue();
std::vector<Row> viewAnswer(const rl::dvec3& c, const std::array<rl::dvec3, 3>& uvn,
                            const rl::dvec3& light, const std::vector<Row>& vertices,
                            const Mistakes& applied);

// normals: the triangles' rows, then the vertices'. `screen` (a row x y per vertex, or empty)
// is where the vertices land on the screen, for the mistakes that leave out triangles of small
// screen area; their areas are the fitted values.
Mistakes normalsCatalogue(const std::vector<Row>& screen,
                          const std::vector<std::array<std::uint32_t, 3>>& triangles);
std::vector<Row> normalsAnswer(const std::vector<Row>& vertices,
                               const std::vector<std::array<std::uint32_t, 3>>& triangles,
                               const std::vector<Row>& screen, const Mistakes& applied);

// projection: rows x y.
Mistakes projectionCatalogue();
std::vector<Row> projectionAnswer(double d, double hx, double hy, int width, int height,
                                  const std::vector<Row>& vertices, const Mistakes& applied);
// The exact x and y before the (int) cast, of the seed's projection.
std::array<double, 2> projectionExact(double d, double hx, double hy, int width, int height,
                                      const Row& vertex);

// scan: rows t y first last, from the screen triangles (x1 y1 x2 y2 x3 y3 rows, whole or not).
Mistakes scanCatalogue();
std::vector<Row> scanAnswer(const std::vector<Row>& triangles, int width, int height,
                            const Mistakes& applied);

// zbuffer: rows x y t z for every pixel reached.
Mistakes zbufferCatalogue();
std::vector<Row> zbufferAnswer(const std::vector<Fragment>& fragments, const Mistakes& applied);

// lighting: rows r g b; the epsilon of the special cases is fitted among `epsilons`.
Mistakes lightingCatalogue(const std::vector<double>& epsilons);
std::vector<Row> lightingAnswer(const Lighting& lighting, const std::vector<Sample>& samples,
                                const Mistakes& applied);
// The same at one point P' and its normal N, in double.
Row lightingAt(const Lighting& lighting, const rl::dvec3& p, const rl::dvec3& n,
               const Mistakes& applied);
// The terms the lecture gives a sample (before the clamp), and its N.L and R.V with N turned
// toward the viewer: what a bias in their colours is held against.
struct PhongTerms {
    rl::dvec3 ambient{0.0}, diffuse{0.0}, specular{0.0};
    double nDotL = 0.0, rDotV = 0.0, vDotN = 0.0;
};
PhongTerms phongTerms(const Lighting& lighting, const Sample& sample);

}  // namespace rasterlab::check
