// Seed 002's per-object animation matrix M: each frame, every vertex of a draw is moved by M
// and every normal by M's inverse transpose. A draw with an Animation is placed in the world
// at time t by
//
//     worldFromModel(t) = M(t) * worldFromModel,
//     M(t) = T(velocity t) * T(c) * R(axis, degreesPerSecond t) * S(scale) * T(-c)
//
// read right to left: move the centre c to the origin, scale along the world axes, turn about
// the axis, put the centre back, then translate by velocity * t. By default it is a turntable:
// the axis is the camera's up (the course camera's V made perpendicular to N; world y when
// there is no course camera) through c, the centre of the draw's bounding box in the world.
// M(0) with scale (1, 1, 1) is the identity, so frame 0 is the scene as it was loaded.
//
// The scale is there to teach normals: under a non-uniform scale, M applied to a normal no
// longer gives a vector perpendicular to the surface; the inverse transpose of M does.
#pragma once

#include <array>
#include <optional>

#include "pipeline/core/diagnostics.h"
#include "pipeline/core/math.h"
#include "pipeline/scene/scene.h"

namespace rl {

// Where a draw's M turns: the animation's own centre and axis, or else the centre of the
// draw's bounding box in the world (a pass over its vertices) and the turntable's axis.
struct AnimationPivot {
    dvec3 centre = dvec3(0.0);
    dvec3 axis = dvec3(0.0);
};
AnimationPivot animationPivot(const Scene& scene, const Draw& draw);

// M of a draw at time t (seconds); the identity for a draw without an animation. The one
// function every stage, view and front end uses.
dmat4 animationMatrix(const Scene& scene, const Draw& draw, double t);
// M(scene.time) * draw.worldFromModel: where the draw is in the world in this frame. With
// pivot given, the pivot M turned about is written there (for a draw with an animation).
dmat4 animatedWorldFromModel(const Scene& scene, const Draw& draw,
                             AnimationPivot* pivot = nullptr);

// M(t) from its parts, as written above (axis of any non-zero length; a zero axis turns
// nothing).
dmat4 animationMatrix(const Animation& animation, const dvec3& centre, const dvec3& axis, double t);
// The turntable's axis: the course camera's up made perpendicular to its view direction,
// normalised; world y without a course camera (or when V is parallel to N).
dvec3 turntableAxis(const Scene& scene);
// The centre of the bounding box of the draw's vertices, placed by worldFromModel (the
// origin for a draw without vertices).
dvec3 worldBoundingBoxCentre(const Draw& draw);

// Puts `motion` on every draw and sets the scene's time: the animation of the window's panel
// and of the CLI's --time and --animate.
void animateEveryDraw(Scene& scene, const Animation& motion, double t);

// A mesh triangle's normal n = (P2 - P1) x (P3 - P1) / |...| in model space, carried by a
// matrix A (viewFromModel, say) the right way, A^-T n, and the wrong way, A n, both made unit.
// Both are multiplied by the sign of det A, so that the right one is the normal of the
// carried triangle, (A P2 - A P1) x (A P3 - A P1) normalised (a mirroring A, such as the
// course's [U; V; N], turns the cross product over). Zero vectors for a degenerate triangle.
struct CarriedNormal {
    dvec3 nModel = dvec3(0.0);
    dvec3 right = dvec3(0.0);  // sign(det A) A^-T n, unit: perpendicular to the carried triangle
    dvec3 wrong = dvec3(0.0);  // sign(det A) A n, unit: tilted under a non-uniform scale
    // A (P2 - P1) and A (P3 - P1): two tangents of the carried triangle.
    std::array<dvec3, 2> edges{dvec3(0.0), dvec3(0.0)};
};
CarriedNormal carriedTriangleNormal(const dmat4& a, const Mesh& mesh, std::size_t triangle);

}  // namespace rl
