// The matrices of the command language of seed 001, as OpenGL documents them. All take and
// return column-major GLM matrices; angles are in degrees where the commands give degrees.
#pragma once

#include "pipeline/core/math.h"

namespace rl {

dmat4 translationMatrix(const dvec3& d);
dmat4 scaleMatrix(const dvec3& s);
// glRotate: a counter-clockwise rotation by `degrees` about `axis` (normalised here).
dmat4 rotationMatrix(double degrees, const dvec3& axis);
// gluLookAt: the camera at eye looking at center, with up as close to `up` as they allow.
dmat4 lookAtMatrix(const dvec3& eye, const dvec3& center, const dvec3& up);
// glFrustum(l, r, b, t, n, f).
dmat4 frustumMatrix(double l, double r, double b, double t, double n, double f);
// Seed 001's ortho: the box [l, r] x [b, t] x [-f, -n]; glOrtho's matrix with the near value
// 2n - f, as the seed says, so that z = -n lands on NDC z = 0 and z = -f on 1.
dmat4 orthoMatrix(double l, double r, double b, double t, double n, double f);

}  // namespace rl
