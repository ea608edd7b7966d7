// Bezier patches of seed 001, subdivided into triangles by de Casteljau's algorithm: the
// point at a parameter is found by interpolating every control quad (or triangle), making
// a patch of one degree less, until one point is left; the last quad's diagonals (or the
// last triangle's edges) give the surface normal there. Colours and texture coordinates
// are interpolated the same way.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "pipeline/core/math.h"

namespace rl {

struct PatchPoint {
    dvec4 p = dvec4(0.0, 0.0, 0.0, 1.0);  // homogeneous: a rational patch when w varies
    vec3 colour = vec3(1.0f);
    vec2 st = vec2(0.0f);
};

struct PatchVertex {
    dvec4 p = dvec4(0.0, 0.0, 0.0, 1.0);
    vec3 colour = vec3(1.0f);
    vec2 st = vec2(0.0f);
    vec3 normal = vec3(0.0f);  // unit, from the last step of de Casteljau
};

struct PatchMesh {
    std::vector<PatchVertex> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

// A bicubic patch: control points row by row, four to a row (s along a row, t across rows).
// Subdivided into 2^subdivisions x 2^subdivisions quads, each split into two triangles
// along the diagonal from (s + ds, t) to (s, t + dt).
PatchVertex evaluateRectBezier(const std::array<PatchPoint, 16>& control, double s, double t);
PatchMesh subdivideRectBezier(const std::array<PatchPoint, 16>& control, int subdivisions);

// A cubic triangular patch: rows of 4, 3, 2 and 1 control points from one edge to the
// opposite corner. At barycentric (u, v, w) the corners are: first point (u = 1), fourth
// point (v = 1), last point (w = 1). Subdivided into 2^subdivisions triangles along each side.
PatchVertex evaluateTriBezier(const std::array<PatchPoint, 10>& control, double u, double v,
                              double w);
PatchMesh subdivideTriBezier(const std::array<PatchPoint, 10>& control, int subdivisions);

// Tensor-product Bezier surfaces of any degrees m x n (the course's superficie.byu). The
// (m + 1) x (n + 1) control points come row by row: P(i, j) = control[i * (n + 1) + j].
// The point at (u, v) in [0, 1]^2 is sum_i sum_j B(i, m)(u) B(j, n)(v) P(i, j): u runs across
// the rows (i), v along a row (j); the corners (0, 0), (0, 1), (1, 0), (1, 1) are P(0, 0),
// P(0, n), P(m, 0), P(m, n).

// The degree + 1 Bernstein weights B(k, degree)(t), by de Casteljau's recurrence (stable).
std::vector<double> bernsteinWeights(int degree, double t);
// The point at (u, v) by de Casteljau's algorithm: along each row in v, then down the column
// of the results in u.
dvec3 evaluateBezierSurface(std::span<const dvec3> control, int m, int n, double u, double v);
// The surface on an evaluations x evaluations grid (evaluations >= 2), u = a / (evaluations
// - 1) and v = b / (evaluations - 1), stored at a * evaluations + b; the Bernstein weights of
// each parameter are computed once.
std::vector<dvec3> evaluateBezierSurfaceGrid(std::span<const dvec3> control, int m, int n,
                                             int evaluations);

}  // namespace rl
