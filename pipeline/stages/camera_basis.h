// Stage 1, camera basis (seed 000): from the course camera (C, N, V) build the orthonormal
// basis {U, V, N} of view space by Gram-Schmidt:
//     N := N / |N|;   V := V - (V.N) N;   V := V / |V|;   U := N x V
// and the matrix viewFromWorld = [U; V; N] * translate(-C). Every intermediate vector and
// the orthogonality residuals are kept, so the view can show the steps with numbers.
// Degenerate cameras (a zero vector, N parallel to V, d = 0, hx = 0 or hy = 0) are errors
// that name the values. V close to N is ill-conditioned: V - (V.N) N keeps only sin(angle) of
// V, so rounding grows as 1e-16 / sin(angle); under kWarnAngleDegrees the residuals pass a
// float's precision and the stage warns, and under sin(angle) = 1e-12 it is an error. A scene
// without a course camera (its draws carry their own view matrices) skips this stage.
#pragma once

#include <string>

#include "pipeline/core/diagnostics.h"
#include "pipeline/core/math.h"
#include "pipeline/scene/scene.h"

namespace rl {

struct CameraBasis {
    bool skipped = false;  // the scene has no course camera
    std::string skipReason;

    // Inputs, as given.
    dvec3 c = dvec3(0.0);
    dvec3 nGiven = dvec3(0.0);
    dvec3 vGiven = dvec3(0.0);

    // The angle between the given N and V, in degrees: the basis's conditioning.
    double angleNV = 90.0;

    // Gram-Schmidt, step by step.
    double nLength = 0.0;            // |N| before normalisation
    dvec3 n = dvec3(0.0, 0.0, 1.0);  // N / |N|
    double vDotN = 0.0;              // V.N, with N normalised
    dvec3 vProjection = dvec3(0.0);  // proj_N(V) = (V.N) N
    dvec3 vOrthogonal = dvec3(0.0);  // V - proj_N(V)
    double vOrthogonalLength = 0.0;
    dvec3 v = dvec3(0.0, 1.0, 0.0);  // normalised
    dvec3 u = dvec3(1.0, 0.0, 0.0);  // N x V

    // Orthonormality residuals of the result: all zero up to rounding.
    double uDotV = 0.0, uDotN = 0.0, vDotNResidual = 0.0;
    double uLengthError = 0.0, vLengthError = 0.0, nLengthError = 0.0;
    double maxResidual() const;

    dmat4 viewFromWorld = dmat4(1.0);  // rows U, V, N; then the translation by -C
};

class CameraBasisStage {
public:
    // Below this angle between N and V the basis is orthonormal only to about 2e-8 or worse
    // (the rounding of V - (V.N) N over sin(angle)): more than a float holds.
    static constexpr double kWarnAngleDegrees = 1e-6;

    Result<CameraBasis> run(const Scene& scene, Diagnostics& diagnostics) const;
};

}  // namespace rl
