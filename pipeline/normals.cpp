#include "normals.h"

#include <limits>

namespace rl {

Normals NormalsStage::run(const Scene& scene, const ViewTransform& view) const {
    Normals out;
    if (!scene.lit()) {
        out.skipped = true;
        out.skipReason = "the scene has no lights: nothing reads the normals";
        return out;
    }
    out.draws.resize(scene.draws.size());
    for (std::size_t d = 0; d < scene.draws.size(); ++d) {
        const Draw& draw = scene.draws[d];
        DrawNormals& normals = out.draws[d];
        if (!draw.mesh) continue;
        const auto& pView = view.pView[d];
        const auto& triangles = draw.mesh->triangles;
        std::vector<dvec3> sum(pView.size(), dvec3(0.0));
        normals.triangle.resize(triangles.size(), vec3(0.0f));

        // Triangle normals, summed into their vertices.
        for (std::size_t t = 0; t < triangles.size(); ++t) {
            const auto& tri = triangles[t];
            // Points, not homogeneous coordinates: (x, y, z) / w (w = 1 in course files).
            const auto point = [&](std::uint32_t v) {
                const dvec4& p = pView[v];
                return p.w != 0.0 && p.w != 1.0 ? dvec3(p) / p.w : dvec3(p);
            };
            const dvec3 p1 = point(tri[0]);
            const dvec3 p2 = point(tri[1]);
            const dvec3 p3 = point(tri[2]);
            const dvec3 cross = glm::cross(p2 - p1, p3 - p1);
            const double length = glm::length(cross);
            if (!(length > std::numeric_limits<double>::min()) || !isFinite(length)) {
                ++normals.degenerateTriangles;
                continue;
            }
            const dvec3 n = cross / length;
            normals.triangle[t] = vec3(n);
            for (std::uint32_t v : tri) sum[v] += n;
        }

        // Vertex normals: the file's own, carried to view space by the inverse transpose of
        // viewFromModel (seed 002; a non-uniform scale would bend them otherwise), or else
        // the normalised sums of the triangle normals (seed 000).
        normals.vertex.resize(pView.size(), vec3(0.0f));
        const auto& given = draw.mesh->normals;
        const dmat3 normalFromModel =
            given.empty() ? dmat3(1.0) : glm::transpose(glm::inverse(dmat3(view.viewFromModel[d])));
        for (std::size_t v = 0; v < sum.size(); ++v) {
            const dvec3 n = given.empty() ? sum[v] : normalFromModel * dvec3(given[v]);
            const double length = glm::length(n);
            if (length > std::numeric_limits<double>::min() && isFinite(length))
                normals.vertex[v] = vec3(n / length);
            else
                ++normals.verticesWithoutNormal;
        }
        out.degenerateTriangles += normals.degenerateTriangles;
    }
    return out;
}

}  // namespace rl
