#include "near_clip.h"

namespace rl {

std::size_t NearClipRecord::keptCount() const {
    std::size_t n = 0;
    for (const NearClipEdge& e : edges) n += e.keptA ? 1 : 0;
    return n;
}

dvec4 nearPlaneInView(const dmat4& clipFromView, double nearW) {
    // w = row 3 of clipFromView times pView; w - near subtracts near times pView.w (= 1).
    return {clipFromView[0][3], clipFromView[1][3], clipFromView[2][3], clipFromView[3][3] - nearW};
}

NearClipRecord clipAgainstNearPlane(const std::array<dvec4, 3>& pView, const dmat4& clipFromView,
                                    double nearW) {
    NearClipRecord out;
    out.plane = nearPlaneInView(clipFromView, nearW);
    out.nearW = nearW;
    out.pView = pView;
    // The distances exactly as the projection stage works them out: (clipFromView pView).w
    // minus near.
    std::array<double, 3> distance{};
    for (std::size_t k = 0; k < 3; ++k) distance[k] = (clipFromView * pView[k]).w - nearW;
    std::array<NearClipPoint, 3> corners{};
    for (std::size_t k = 0; k < 3; ++k) {
        NearClipEdge& e = out.edges[k];
        e.a = k;
        e.b = (k + 1) % 3;
        e.distanceA = distance[e.a];
        e.distanceB = distance[e.b];
        e.keptA = e.distanceA >= 0.0;
        e.crosses = e.keptA != (e.distanceB >= 0.0);
        corners[k] = {false, k, pView[k]};
    }
    // The stage's own walk (projection.h); each point made is recorded on its edge, the edge
    // A-B named by A in the triangle's order.
    clipPolygonAgainstPlane(
        corners, out.polygon, [&](const NearClipPoint& p) { return distance[p.index] >= 0.0; },
        [&](const NearClipPoint& in, const NearClipPoint& behind) {
            NearClipEdge& e =
                out.edges[(in.index + 1) % 3 == behind.index ? in.index : behind.index];
            e.t = (0.0 - e.distanceA) / (e.distanceB - e.distanceA);
            e.tFromInside = crossingFraction(distance[in.index], distance[behind.index]);
            e.pView = glm::mix(in.pView, behind.pView, e.tFromInside);
            return NearClipPoint{true, e.a, e.pView};
        });
    for (std::size_t k = 1; k + 1 < out.polygon.size(); ++k) out.triangles.push_back({0, k, k + 1});
    return out;
}

NearClipRecord nearClipOf(const Scene& scene, const Projection& projection, std::uint32_t draw,
                          std::uint32_t source) {
    const DrawProjection& proj = projection.draws[draw];
    const std::array<std::uint32_t, 3>& tri = scene.draws[draw].mesh->triangles[source];
    return clipAgainstNearPlane({proj.pView[tri[0]], proj.pView[tri[1]], proj.pView[tri[2]]},
                                proj.clipFromView, projection.nearW);
}

std::vector<std::uint32_t> screenTrianglesOf(const Projection& projection, std::uint32_t draw,
                                             std::uint32_t source) {
    std::vector<std::uint32_t> out;
    for (std::size_t t = 0; t < projection.triangles.size(); ++t) {
        const ScreenTriangle& s = projection.triangles[t];
        if (s.draw == draw && s.source == source) out.push_back(static_cast<std::uint32_t>(t));
    }
    return out;
}

}  // namespace rl
