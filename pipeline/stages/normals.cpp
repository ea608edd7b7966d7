#include "normals.h"

#include <limits>

namespace rl {

NormalsRead normalsRead(const Draw& draw) {
    const bool phong = draw.shading == ShadingModel::Phong;
    return NormalsRead{
        .triangle = litPerTriangle(draw.shading) || (phong && draw.flatNormals),
        .vertex = draw.shading == ShadingModel::Gouraud || (phong && !draw.flatNormals)};
}

DrawNormals drawNormals(const Mesh& mesh, const std::vector<dvec4>& pView,
                        const dmat3& normalFromModel) {
    DrawNormals out;
    out.triangle.assign(mesh.triangles.size(), vec3(0.0f));
    out.vertex.assign(pView.size(), vec3(0.0f));
    // Each triangle's normal, added to its three corners' sums.
    std::vector<dvec3> sum(pView.size(), dvec3(0.0));
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        dvec3 n;
        if (!unitNormal(pView[tri[0]], pView[tri[1]], pView[tri[2]], n)) {
            ++out.degenerateTriangles;
            continue;
        }
        out.triangle[t] = vec3(n);
        for (std::uint32_t v : tri) sum[v] += n;
    }
    // Each vertex's: the file's own carried to view space, or the sum; made unit length.
    for (std::size_t v = 0; v < pView.size(); ++v) {
        const dvec3 n = mesh.normals.empty() ? sum[v] : normalFromModel * dvec3(mesh.normals[v]);
        const double length = glm::length(n);
        if (length > std::numeric_limits<double>::min() && isFinite(length))
            out.vertex[v] = vec3(n / length);
        else
            ++out.verticesWithoutNormal;
    }
    return out;
}

Normals NormalsStage::run(const NormalsInput& in) const {
    Normals out;
    if (!in.scene.lit()) {
        out.skipped = true;
        out.skipReason = "the scene has no lights: nothing reads the normals";
        return out;
    }
    out.draws.resize(in.scene.draws.size());
    for (std::size_t d = 0; d < in.scene.draws.size(); ++d) {
        const Draw& draw = in.scene.draws[d];
        if (!draw.mesh) continue;
        // The inverse transpose carries normals: under a non-uniform scale the model/view
        // matrix itself would tilt them (seed 002).
        const dmat3 normalFromModel =
            draw.mesh->normals.empty() ? dmat3(1.0) : normalMatrix(in.view.viewFromModel[d]);
        out.draws[d] = drawNormals(*draw.mesh, in.view.pView[d], normalFromModel);
        out.degenerateTriangles += out.draws[d].degenerateTriangles;
    }
    return out;
}

}  // namespace rl
