#include "normals_fast.h"

#include <algorithm>
#include <limits>

#include "pipeline/core/parallel.h"
#include "pipeline/stages/normals.h"

namespace rl::fast {

Normals normals(const NormalsInput& in, int threads, NormalsScope scope) {
    const Scene& scene = in.scene;
    const ViewTransform& view = in.view;
    if (!scene.lit()) return NormalsStage().run(in);  // skipped, with the reason
    Normals out;
    out.draws.resize(scene.draws.size());
    for (std::size_t d = 0; d < scene.draws.size(); ++d) {
        const Draw& draw = scene.draws[d];
        DrawNormals& kept = out.draws[d];
        if (!draw.mesh) continue;
        const NormalsRead read =
            scope == NormalsScope::All ? NormalsRead{true, true} : normalsRead(draw);
        out.triangleNormalsLeftOut += read.triangle ? 0 : 1;
        out.vertexNormalsLeftOut += read.vertex ? 0 : 1;
        const auto& pView = view.pView[d];
        const auto& triangles = draw.mesh->triangles;
        const std::size_t triangleCount = triangles.size();
        const std::size_t vertexCount = pView.size();
        if (read.triangle) kept.triangle.resize(triangleCount, vec3(0.0f));
        if (read.vertex) kept.vertex.resize(vertexCount, vec3(0.0f));
        const int parts = triangleCount < 4096 ? 1 : std::max(1, threads);
        const auto& given = draw.mesh->normals;
        const dmat3 normalFromModel =
            given.empty() ? dmat3(1.0) : normalMatrix(view.viewFromModel[d]);
        std::vector<std::size_t> degenerateCounts(static_cast<std::size_t>(parts), 0);
        std::vector<std::size_t> withoutCounts(static_cast<std::size_t>(parts), 0);

        if (!read.vertex) {
            // Triangle normals alone: each part takes a range of triangles.
            runParts(parts, [&](int part) {
                std::size_t degenerate = 0;  // on the thread's stack
                const std::size_t last = rangeBegin(triangleCount, part + 1, parts);
                for (std::size_t t = rangeBegin(triangleCount, part, parts); t < last; ++t) {
                    const auto& tri = triangles[t];
                    dvec3 n;
                    if (!unitNormal(pView[tri[0]], pView[tri[1]], pView[tri[2]], n))
                        ++degenerate;
                    else if (read.triangle)
                        kept.triangle[t] = vec3(n);
                }
                degenerateCounts[static_cast<std::size_t>(part)] = degenerate;
            });
        } else {
            // Each part owns a range of vertices and goes through every triangle in order: it
            // works out the normal of each triangle with a corner in its range, adds it to
            // those corners only (so every sum is made in triangle order, whatever the number
            // of parts), and keeps it when it owns the first corner (so each is kept once).
            runParts(parts, [&](int part) {
                const std::size_t first = rangeBegin(vertexCount, part, parts);
                const std::size_t last = rangeBegin(vertexCount, part + 1, parts);
                // One part owns every vertex: no range checks.
                const bool all = parts == 1;
                const auto mine = [&](std::uint32_t v) { return all || (v >= first && v < last); };
                // The sums of triangle normals, needed only where the file gives no normals.
                const bool summing = given.empty();
                std::vector<dvec3> sum(summing ? last - first : 0, dvec3(0.0));
                std::size_t degenerate = 0;  // on the thread's stack
                for (std::size_t t = 0; t < triangleCount; ++t) {
                    const auto& tri = triangles[t];
                    if (!all && !mine(tri[0]) && !mine(tri[1]) && !mine(tri[2])) continue;
                    dvec3 n;
                    if (!unitNormal(pView[tri[0]], pView[tri[1]], pView[tri[2]], n)) {
                        degenerate += mine(tri[0]) ? 1 : 0;
                        continue;
                    }
                    if (read.triangle && mine(tri[0])) kept.triangle[t] = vec3(n);
                    if (summing)
                        for (std::uint32_t v : tri)
                            if (mine(v)) sum[v - first] += n;
                }
                degenerateCounts[static_cast<std::size_t>(part)] = degenerate;

                // Vertex normals: the file's own, carried to view space by the inverse
                // transpose of viewFromModel (seed 002; a non-uniform scale would bend them
                // otherwise), or else the normalised sums of the triangle normals (seed 000).
                std::size_t without = 0;
                for (std::size_t v = first; v < last; ++v) {
                    const dvec3 n =
                        given.empty() ? sum[v - first] : normalFromModel * dvec3(given[v]);
                    const double length = glm::length(n);
                    if (length > std::numeric_limits<double>::min() && isFinite(length))
                        kept.vertex[v] = vec3(n / length);
                    else
                        ++without;
                }
                withoutCounts[static_cast<std::size_t>(part)] = without;
            });
        }
        for (std::size_t c : degenerateCounts) kept.degenerateTriangles += c;
        for (std::size_t c : withoutCounts) kept.verticesWithoutNormal += c;
        out.degenerateTriangles += kept.degenerateTriangles;
    }
    return out;
}

}  // namespace rl::fast
