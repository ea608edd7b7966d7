#include "camera_basis.h"

#include <algorithm>
#include <cmath>

#include "pipeline/core/format.h"

namespace rl {

double CameraBasis::maxResidual() const {
    return std::max({std::abs(uDotV), std::abs(uDotN), std::abs(vDotNResidual),
                     std::abs(uLengthError), std::abs(vLengthError), std::abs(nLengthError)});
}

Result<CameraBasis> CameraBasisStage::run(const Scene& scene, Diagnostics& diagnostics) const {
    CameraBasis basis;
    if (!scene.camera) {
        basis.skipped = true;
        basis.skipReason = "the scene gives its model/view matrices directly";
        return basis;
    }
    const CourseCamera& camera = *scene.camera;
    basis.c = camera.c;
    basis.nGiven = camera.n;
    basis.vGiven = camera.v;

    // Reject what makes the basis or the projection undefined.
    if (!isFinite(camera.c) || !isFinite(camera.n) || !isFinite(camera.v))
        return makeError(ErrorCode::Degenerate, camera.where.c,
                         "the camera's C, N and V must be finite numbers"_msg);
    basis.nLength = glm::length(camera.n);
    if (basis.nLength == 0.0)
        return makeError(ErrorCode::Degenerate, camera.where.n,
                         "N, the view direction, is the zero vector: it must point from the "
                         "camera toward the scene"_msg);
    if (glm::length(camera.v) == 0.0)
        return makeError(ErrorCode::Degenerate, camera.where.v,
                         "V, the up vector, is the zero vector: it must say which way is up"_msg);
    if (camera.d == 0.0)
        return makeError(ErrorCode::Degenerate, camera.where.d,
                         "d, the distance to the projection plane, is 0: the projection "
                         "(d/hx) x/z would squash every point to the centre"_msg);
    if (camera.hx == 0.0)
        return makeError(ErrorCode::Degenerate, camera.where.hx,
                         "hx, the horizontal half-size of the window, is 0: the projection "
                         "(d/hx) x/z divides by it"_msg);
    if (camera.hy == 0.0)
        return makeError(ErrorCode::Degenerate, camera.where.hy,
                         "hy, the vertical half-size of the window, is 0: the projection "
                         "(d/hy) y/z divides by it"_msg);

    // How far V is from N (atan2 stays accurate where acos of the dot product does not).
    basis.angleNV = glm::degrees(
        std::atan2(glm::length(glm::cross(camera.n, camera.v)), glm::dot(camera.n, camera.v)));

    // Gram-Schmidt: normalise N, remove from V its component along N, normalise V.
    basis.n = camera.n / basis.nLength;
    basis.vDotN = glm::dot(camera.v, basis.n);
    basis.vProjection = basis.vDotN * basis.n;
    basis.vOrthogonal = camera.v - basis.vProjection;
    basis.vOrthogonalLength = glm::length(basis.vOrthogonal);
    if (!(basis.vOrthogonalLength > 1e-12 * glm::length(camera.v)))
        return makeError(ErrorCode::Degenerate, camera.where.v,
                         "V %1 is parallel to N %2: Gram-Schmidt leaves nothing of V, so 'up' is "
                         "undefined; choose a V that is not along N"_msg(formatVector(camera.v),
                                                                         formatVector(camera.n)));
    basis.v = basis.vOrthogonal / basis.vOrthogonalLength;
    basis.u = glm::cross(basis.n, basis.v);

    basis.uDotV = glm::dot(basis.u, basis.v);
    basis.uDotN = glm::dot(basis.u, basis.n);
    basis.vDotNResidual = glm::dot(basis.v, basis.n);
    basis.uLengthError = glm::length(basis.u) - 1.0;
    basis.vLengthError = glm::length(basis.v) - 1.0;
    basis.nLengthError = glm::length(basis.n) - 1.0;

    // viewFromWorld: pView = [U; V; N] (pWorld - C).
    dmat4 rotation(1.0);
    for (int k = 0; k < 3; ++k) {
        rotation[k][0] = basis.u[k];
        rotation[k][1] = basis.v[k];
        rotation[k][2] = basis.n[k];
    }
    dmat4 translation(1.0);
    translation[3] = dvec4(-camera.c, 1.0);
    basis.viewFromWorld = rotation * translation;

    const double fromAxis = std::min(basis.angleNV, 180.0 - basis.angleNV);
    if (fromAxis < CameraBasisStage::kWarnAngleDegrees)
        diagnostics.warn(camera.where.v,
                         "V is %1 degrees from the line of N: Gram-Schmidt keeps only that "
                         "much of V, and the basis is orthonormal only to %2, less than a "
                         "float's precision; choose a V farther from N"_msg(
                             formatNumber(fromAxis), formatNumber(basis.maxResidual())));
    if (camera.hx < 0.0)
        diagnostics.warn(camera.where.hx,
                         "hx is negative: the image is mirrored left to right"_msg);
    if (camera.hy < 0.0)
        diagnostics.warn(camera.where.hy,
                         "hy is negative: the image is mirrored top to bottom"_msg);
    if (camera.d < 0.0)
        diagnostics.warn(camera.where.d,
                         "d is negative: the image is turned upside down and mirrored"_msg);
    return basis;
}

}  // namespace rl
