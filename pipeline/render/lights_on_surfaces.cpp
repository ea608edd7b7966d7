#include "lights_on_surfaces.h"

#include <cmath>
#include <limits>
#include <optional>

namespace rl {

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
