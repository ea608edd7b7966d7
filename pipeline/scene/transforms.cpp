#include "transforms.h"

#include <cmath>

namespace rl {

dmat4 translationMatrix(const dvec3& d) {
    dmat4 m(1.0);
    m[3] = dvec4(d, 1.0);
    return m;
}

dmat4 scaleMatrix(const dvec3& s) {
    dmat4 m(1.0);
    m[0][0] = s.x;
    m[1][1] = s.y;
    m[2][2] = s.z;
    return m;
}

dmat4 rotationMatrix(double degrees, const dvec3& axis) {
    const double length = glm::length(axis);
    if (!(length > 0.0)) return dmat4(1.0);
    const dvec3 a = axis / length;
    const double radians = degrees * 3.14159265358979323846 / 180.0;
    const double c = std::cos(radians), s = std::sin(radians), k = 1.0 - c;
    // The matrix of glRotate's documentation, written row by row.
    // clang-format off
    const double rows[16] = {
        a.x * a.x * k + c,       a.x * a.y * k - a.z * s, a.x * a.z * k + a.y * s, 0.0,
        a.y * a.x * k + a.z * s, a.y * a.y * k + c,       a.y * a.z * k - a.x * s, 0.0,
        a.x * a.z * k - a.y * s, a.y * a.z * k + a.x * s, a.z * a.z * k + c,       0.0,
        0.0,                     0.0,                     0.0,                     1.0};
    // clang-format on
    return matrixFromRows(rows);
}

dmat4 lookAtMatrix(const dvec3& eye, const dvec3& center, const dvec3& up) {
    // gluLookAt: f = (center - eye)/|.|, s = f x up/|.|, u = s x f; rows s, u, -f; then
    // the translation by -eye.
    const dvec3 f = glm::normalize(center - eye);
    const dvec3 s = glm::normalize(glm::cross(f, up));
    const dvec3 u = glm::cross(s, f);
    // clang-format off
    const double rows[16] = { s.x,  s.y,  s.z, 0.0,
                              u.x,  u.y,  u.z, 0.0,
                             -f.x, -f.y, -f.z, 0.0,
                              0.0,  0.0,  0.0, 1.0};
    // clang-format on
    return matrixFromRows(rows) * translationMatrix(-eye);
}

dmat4 frustumMatrix(double l, double r, double b, double t, double n, double f) {
    // clang-format off
    const double rows[16] = {2.0 * n / (r - l), 0.0, (r + l) / (r - l), 0.0,
                             0.0, 2.0 * n / (t - b), (t + b) / (t - b), 0.0,
                             0.0, 0.0, -(f + n) / (f - n), -2.0 * f * n / (f - n),
                             0.0, 0.0, -1.0, 0.0};
    // clang-format on
    return matrixFromRows(rows);
}

dmat4 orthoMatrix(double l, double r, double b, double t, double n, double f) {
    const double nearValue = 2.0 * n - f;
    // clang-format off
    const double rows[16] = {2.0 / (r - l), 0.0, 0.0, -(r + l) / (r - l),
                             0.0, 2.0 / (t - b), 0.0, -(t + b) / (t - b),
                             0.0, 0.0, -2.0 / (f - nearValue), -(f + nearValue) / (f - nearValue),
                             0.0, 0.0, 0.0, 1.0};
    // clang-format on
    return matrixFromRows(rows);
}

}  // namespace rl
