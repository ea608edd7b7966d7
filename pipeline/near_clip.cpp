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
    for (std::size_t k = 0; k < 3; ++k) {
        NearClipEdge& e = out.edges[k];
        e.a = k;
        e.b = (k + 1) % 3;
        e.distanceA = distance[e.a];
        e.distanceB = distance[e.b];
        e.keptA = e.distanceA >= 0.0;
        const bool keptB = e.distanceB >= 0.0;
        if (e.keptA) out.polygon.push_back({false, k, pView[k]});
        e.crosses = e.keptA != keptB;
        if (!e.crosses) continue;
        e.t = (0.0 - e.distanceA) / (e.distanceB - e.distanceA);
        // The stage's C: from the end in front, t' = d_in / (d_in - d_out).
        const std::size_t in = e.keptA ? e.a : e.b, outside = e.keptA ? e.b : e.a;
        e.tFromInside = distance[in] / (distance[in] - distance[outside]);
        e.pView = glm::mix(pView[in], pView[outside], e.tFromInside);
        out.polygon.push_back({true, k, e.pView});
    }
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
