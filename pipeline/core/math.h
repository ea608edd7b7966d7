// The only header of the pipeline that includes GLM.
//
// Conventions used everywhere in the pipeline:
// - Matrices are named aFromB (viewFromWorld, clipFromView) and read right to left:
//   pView = viewFromWorld * pWorld.
// - Points and vectors carry their space in their name: pWorld, pView, pClip, pNdc,
//   pScreen, nView.
// - Geometry (camera, vertices, projection) is computed in double precision; the
//   per-pixel loops work in float.
// - The course's view space (seed 000) has U to the right, V up and N forward, so a point
//   is in front of the camera when its view z is positive. Its matrix [U; V; N] has a
//   negative determinant: it mirrors handedness, which the course never notices because it
//   turns every normal toward the viewer.
// - Screen space: x to the right, y down, origin at the top-left corner of the image.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace rl {

using glm::dmat3;
using glm::dmat4;
using glm::dvec2;
using glm::dvec3;
using glm::dvec4;
using glm::ivec2;
using glm::mat3;
using glm::mat4;
using glm::vec2;
using glm::vec3;
using glm::vec4;

// A column-major GLM matrix from 16 values given row by row, as people write matrices.
inline dmat4 matrixFromRows(const double (&rows)[16]) {
    dmat4 m(0.0);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m[c][r] = rows[r * 4 + c];
    return m;
}

// The point a homogeneous position stands for: (x, y, z) / w (w = 0, a direction, as it is).
inline dvec3 cartesian(const dvec4& p) {
    return p.w != 0.0 && p.w != 1.0 ? dvec3(p) / p.w : dvec3(p);
}

// The matrix that carries normals: the inverse transpose of m's upper 3x3.
inline dmat3 normalMatrix(const dmat4& m) {
    return glm::transpose(glm::inverse(dmat3(m)));
}

inline bool isFinite(double v) {
    return v - v == 0.0;
}
inline bool isFinite(const dvec3& v) {
    return isFinite(v.x) && isFinite(v.y) && isFinite(v.z);
}
inline bool isFinite(const vec3& v) {
    return isFinite(v.x) && isFinite(v.y) && isFinite(v.z);
}

}  // namespace rl
