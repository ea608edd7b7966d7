#include "view_transform.h"

#include <cmath>
#include <limits>
#include <optional>

#include "animation_matrix.h"

namespace rl {

ViewTransform ViewTransformStage::run(const Scene& scene, const CameraBasis& basis) const {
    ViewTransform out;
    out.worldFromModel.reserve(scene.draws.size());
    out.pivot.assign(scene.draws.size(), AnimationPivot{});
    out.viewFromModel.reserve(scene.draws.size());
    out.pView.reserve(scene.draws.size());
    for (std::size_t d = 0; d < scene.draws.size(); ++d) {
        const Draw& draw = scene.draws[d];
        const dmat4 worldFromModel = animatedWorldFromModel(scene, draw, &out.pivot[d]);
        out.worldFromModel.push_back(worldFromModel);
        const dmat4 viewFromModel = basis.viewFromWorld * worldFromModel;
        out.viewFromModel.push_back(viewFromModel);
        std::vector<dvec4> pView;
        if (draw.mesh) {
            pView.reserve(draw.mesh->positions.size());
            for (const dvec4& pModel : draw.mesh->positions) {
                const dvec4 p = viewFromModel * pModel;
                (p.z > 0.0 ? out.verticesInFront : out.verticesBehind) += 1;
                pView.push_back(p);
            }
        }
        out.pView.push_back(std::move(pView));
    }
    for (const Light& light : scene.lights) {
        ViewLight v;
        v.pView = basis.viewFromWorld * light.pWorld;
        v.intensity = light.intensity;
        v.attenuation = light.attenuation;
        v.attenuated = light.attenuated();
        v.spot = light.spot();
        if (v.spot) {
            // A direction: rotated, not moved (w = 0).
            const dvec3 d = dvec3(basis.viewFromWorld * dvec4(light.spotDirection, 0.0));
            const double length = glm::length(d);
            v.spotDirection = length > 0.0 ? vec3(d / length) : vec3(0.0f);
            v.spotCosCutoff = static_cast<float>(std::cos(glm::radians(double(light.spotCutoff))));
            v.spotExponent = light.spotExponent;
        }
        out.lights.push_back(v);
    }
    return out;
}

namespace {

// The triangle nearest light's point l of those it lies above (its foot inside them), within
// limit.
std::optional<LightOnSurface> nearestTriangleBelow(const Scene& scene, const ViewTransform& view,
                                                   std::size_t light, const dvec3& l,
                                                   double limit) {
    std::optional<LightOnSurface> nearest;
    for (std::size_t d = 0; d < scene.draws.size(); ++d) {
        if (!scene.draws[d].mesh) continue;
        const auto& pView = view.pView[d];
        const auto& triangles = scene.draws[d].mesh->triangles;
        for (std::size_t t = 0; t < triangles.size(); ++t) {
            const dvec4 &a4 = pView[triangles[t][0]], &b4 = pView[triangles[t][1]],
                        &c4 = pView[triangles[t][2]];
            if (a4.w != 1.0 || b4.w != 1.0 || c4.w != 1.0) continue;
            const dvec3 a(a4), b(b4), c(c4);
            const dvec3 n = glm::cross(b - a, c - a);
            const double area2 = glm::dot(n, n);
            if (area2 == 0.0) continue;
            const double height = std::abs(glm::dot(n, l - a)) / std::sqrt(area2);
            if (height >= limit || (nearest && height >= nearest->height)) continue;
            // Above the triangle: the foot's barycentrics are all >= 0.
            const dvec3 foot = l - glm::dot(n, l - a) / area2 * n;
            const bool inside = glm::dot(glm::cross(b - a, foot - a), n) >= 0.0 &&
                                glm::dot(glm::cross(c - b, foot - b), n) >= 0.0 &&
                                glm::dot(glm::cross(a - c, foot - c), n) >= 0.0;
            if (inside) nearest = LightOnSurface{light, d, t, height, limit};
        }
    }
    return nearest;
}

}  // namespace

std::vector<LightOnSurface> lightsOnSurfaces(const Scene& scene, const ViewTransform& view) {
    std::vector<LightOnSurface> found;
    // The box around every vertex, once for all lights: a light outside it (the common case)
    // is near no triangle.
    dvec3 low(std::numeric_limits<double>::infinity()), high(-low);
    for (const auto& pView : view.pView)
        for (const dvec4& p : pView) low = glm::min(low, dvec3(p)), high = glm::max(high, dvec3(p));
    for (std::size_t i = 0; i < view.lights.size(); ++i) {
        const dvec4 pLight = view.lights[i].pView;
        if (pLight.w == 0.0) continue;  // a direction
        const dvec3 l = dvec3(pLight) / pLight.w;
        const double limit = kLightSurfaceRatio * glm::length(l);
        if (glm::any(glm::lessThan(l, low - limit)) || glm::any(glm::greaterThan(l, high + limit)))
            continue;
        if (auto nearest = nearestTriangleBelow(scene, view, i, l, limit))
            found.push_back(*nearest);
    }
    return found;
}

}  // namespace rl
