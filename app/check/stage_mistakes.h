// The known mistakes of each stage, as what they would answer: a student's answer that equals
// one of these (within the stage's tolerance) names its likely cause. Written in double from
// the formulas, beside the lecture's stages, not from them: each is the lecture's formula
// with one step done the way students get it wrong.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/core/math.h"

namespace rasterlab::check {

using Row = std::vector<double>;

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

// A mistake and the rows it answers with (in the stage's answer order).
struct Alternative {
    std::string cause;
    std::vector<Row> rows;
};

// basis: rows U, V, N.
std::vector<Alternative> basisMistakes(const rl::dvec3& n, const rl::dvec3& v);
// view: the light's row, then the vertices'.
std::vector<Alternative> viewMistakes(const rl::dvec3& c, const std::array<rl::dvec3, 3>& uvn,
                                      const rl::dvec3& light, const std::vector<Row>& vertices);
// normals: the triangles' rows, then the vertices'.
std::vector<Alternative> normalsMistakes(
    const std::vector<Row>& vertices, const std::vector<std::array<std::uint32_t, 3>>& triangles);
// projection: rows x y.
std::vector<Alternative> projectionMistakes(double d, double hx, double hy, int width, int height,
                                            const std::vector<Row>& vertices);
// The exact x and y before the (int) cast, of the seed's projection.
std::array<double, 2> projectionExact(double d, double hx, double hy, int width, int height,
                                      const Row& vertex);
// scan: rows t y first last, from the screen triangles (x1 y1 x2 y2 x3 y3 rows).
std::vector<Alternative> scanMistakes(const std::vector<Row>& triangles, int width, int height);
// The spans of the seed's rule with pixels sampled at (x, y): inside when every edge function
// is >= 0 (strict: > 0), in exact integer arithmetic.
std::vector<Row> scanSpans(const std::vector<Row>& triangles, int width, int height, bool strict);
// zbuffer: rows x y t z for every pixel reached.
std::vector<Alternative> zbufferMistakes(const std::vector<Fragment>& fragments);
// lighting: rows r g b.
std::vector<Alternative> lightingMistakes(const Lighting& lighting,
                                          const std::vector<Sample>& samples);

}  // namespace rasterlab::check
