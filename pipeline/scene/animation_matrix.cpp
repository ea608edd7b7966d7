#include "animation_matrix.h"

#include <algorithm>
#include <limits>
#include <numbers>


namespace rl {

namespace {

dmat4 translation(const dvec3& d) {
    dmat4 m(1.0);
    m[3] = dvec4(d, 1.0);
    return m;
}

// Rodrigues' rotation by `radians` about the unit vector k (right-handed).
dmat4 rotation(const dvec3& k, double radians) {
    const double c = std::cos(radians), s = std::sin(radians), C = 1.0 - c;
    dmat4 m(1.0);
    // Column-major: m[column][row].
    m[0] = dvec4(c + k.x * k.x * C, k.y * k.x * C + k.z * s, k.z * k.x * C - k.y * s, 0.0);
    m[1] = dvec4(k.x * k.y * C - k.z * s, c + k.y * k.y * C, k.z * k.y * C + k.x * s, 0.0);
    m[2] = dvec4(k.x * k.z * C + k.y * s, k.y * k.z * C - k.x * s, c + k.z * k.z * C, 0.0);
    return m;
}

}  // namespace

dmat4 animationMatrix(const Animation& animation, const dvec3& centre, const dvec3& axis,
                      double t) {
    const double length = glm::length(axis);
    const double radians = animation.degreesPerSecond * t * std::numbers::pi / 180.0;
    const dmat4 turn = length > 0.0 ? rotation(axis / length, radians) : dmat4(1.0);
    dmat4 scale(1.0);
    scale[0][0] = animation.scale.x;
    scale[1][1] = animation.scale.y;
    scale[2][2] = animation.scale.z;
    return translation(animation.velocity * t) * translation(centre) * turn * scale *
           translation(-centre);
}

dvec3 turntableAxis(const Scene& scene) {
    if (scene.camera) {
        const dvec3 n = scene.camera->n, v = scene.camera->v;
        const double nn = glm::dot(n, n);
        if (nn > 0.0) {
            const dvec3 up = v - (glm::dot(v, n) / nn) * n;  // Gram-Schmidt, as the basis does
            const double length = glm::length(up);
            if (length > 0.0 && isFinite(up / length)) return up / length;
        }
    }
    return dvec3(0.0, 1.0, 0.0);
}

dvec3 worldBoundingBoxCentre(const Draw& draw) {
    if (!draw.mesh || draw.mesh->positions.empty()) return dvec3(0.0);
    dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (const dvec4& pModel : draw.mesh->positions) {
        const dvec3 pWorld = cartesian(draw.worldFromModel * pModel);
        lo = glm::min(lo, pWorld);
        hi = glm::max(hi, pWorld);
    }
    return 0.5 * (lo + hi);
}

AnimationPivot animationPivot(const Scene& scene, const Draw& draw) {
    if (!draw.animation) return {};
    const Animation& a = *draw.animation;
    return {a.centre ? *a.centre : worldBoundingBoxCentre(draw),
            a.axis ? *a.axis : turntableAxis(scene)};
}

dmat4 animationMatrix(const Scene& scene, const Draw& draw, double t) {
    if (!draw.animation) return dmat4(1.0);
    const AnimationPivot pivot = animationPivot(scene, draw);
    return animationMatrix(*draw.animation, pivot.centre, pivot.axis, t);
}

dmat4 animatedWorldFromModel(const Scene& scene, const Draw& draw, AnimationPivot* pivot) {
    // Without an animation the matrix is used as it is (not multiplied by an identity), so
    // such scenes render bit for bit as before.
    if (!draw.animation) return draw.worldFromModel;
    const AnimationPivot resolved = animationPivot(scene, draw);
    if (pivot) *pivot = resolved;
    return animationMatrix(*draw.animation, resolved.centre, resolved.axis, scene.time) *
           draw.worldFromModel;
}

void animateEveryDraw(Scene& scene, const Animation& motion, double t) {
    for (Draw& draw : scene.draws) draw.animation = motion;
    scene.time = t;
}

CarriedNormal carriedTriangleNormal(const dmat4& a, const Mesh& mesh, std::size_t triangle) {
    CarriedNormal out;
    const auto& c = mesh.triangles[triangle];
    const dvec3 p1 = cartesian(mesh.positions[c[0]]), p2 = cartesian(mesh.positions[c[1]]),
                p3 = cartesian(mesh.positions[c[2]]);
    const dvec3 cross = glm::cross(p2 - p1, p3 - p1);
    const double length = glm::length(cross);
    const dmat3 a3(a);
    out.edges = {a3 * (p2 - p1), a3 * (p3 - p1)};
    if (!(length > 0.0) || !isFinite(length)) return out;
    out.nModel = cross / length;
    const double sign = glm::determinant(a3) < 0.0 ? -1.0 : 1.0;
    const auto unit = [](const dvec3& v) {
        const double l = glm::length(v);
        return l > 0.0 && isFinite(l) ? v / l : dvec3(0.0);
    };
    out.right = sign * unit(normalMatrix(a) * out.nModel);
    out.wrong = sign * unit(a3 * out.nModel);
    return out;
}

}  // namespace rl
