// Bezier patches of seed 001, subdivided into triangles by de Casteljau's algorithm: the
// point at a parameter is found by interpolating every control quad (or triangle), making
// a patch of one degree less, until one point is left; the last quad's diagonals (or the
// last triangle's edges) give the surface normal there. Colours and texture coordinates
// are interpolated the same way.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "math.h"

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
// Subdivided into 2^subdivisions x 2^subdivisions quads, each split into two triangles.
PatchVertex evaluateRectBezier(const std::array<PatchPoint, 16>& control, double s, double t);
PatchMesh subdivideRectBezier(const std::array<PatchPoint, 16>& control, int subdivisions);

// A cubic triangular patch: rows of 4, 3, 2 and 1 control points from one edge to the
// opposite corner. At barycentric (u, v, w) the corners are: first point (u = 1), fourth
// point (v = 1), last point (w = 1). Subdivided into 2^subdivisions triangles along each side.
PatchVertex evaluateTriBezier(const std::array<PatchPoint, 10>& control, double u, double v,
                              double w);
PatchMesh subdivideTriBezier(const std::array<PatchPoint, 10>& control, int subdivisions);

}  // namespace rl
