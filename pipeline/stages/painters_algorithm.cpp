#include "painters_algorithm.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rl {

dvec3 viewBarycentre(const DrawProjection& draw, const Mesh& mesh, std::uint32_t source) {
    const auto& corners = mesh.triangles[source];
    return (cartesian(draw.pView[corners[0]]) + cartesian(draw.pView[corners[1]]) +
            cartesian(draw.pView[corners[2]])) /
           3.0;
}

double painterDistance(const Scene& scene, const Projection& projection, std::uint32_t t) {
    const ScreenTriangle& tri = projection.triangles[t];
    return glm::length(
        viewBarycentre(projection.draws[tri.draw], *scene.draws[tri.draw].mesh, tri.source));
}

std::vector<std::uint32_t> painterOrder(const Scene& scene, const Projection& projection) {
    const std::size_t n = projection.triangles.size();
    std::vector<double> distance(n);
    for (std::size_t t = 0; t < n; ++t)
        distance[t] = painterDistance(scene, projection, static_cast<std::uint32_t>(t));
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return distance[a] > distance[b]; });
    return order;
}

void sortFarToNear(const Scene& scene, Projection& projection) {
    const std::vector<std::uint32_t> order = painterOrder(scene, projection);
    Buffer<ScreenTriangle> sorted;
    sorted.reserve(order.size());
    for (std::uint32_t t : order) sorted.push_back(projection.triangles[t]);
    projection.triangles = std::move(sorted);
}

}  // namespace rl
