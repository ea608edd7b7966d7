// Stage 3, normals (seed 000): in view coordinates, each triangle's normal
// (P2 - P1) x (P3 - P1), normalised, is added to the normals of its three vertices; then
// every vertex normal is normalised. Normals given by the file (seed 001's `normal`) are
// used instead, carried to view space by the inverse transpose of the model/view matrix.
// Degenerate (zero-area) triangles have no normal and contribute nothing; they are counted,
// as are vertices left without a normal. Skipped when the scene is not lit (nothing would
// read the normals). The fast path (fast/normals_fast.h) can leave out what no draw's shading
// reads (normalsRead).
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "pipeline/core/math.h"
#include "pipeline/scene/scene.h"
#include "pipeline/stages/view_transform.h"

namespace rl {

struct DrawNormals {
    // Unit length, or zero for a degenerate triangle or a vertex with no normal. Empty when
    // left out (by the fast path's NormalsScope::Read).
    std::vector<vec3> triangle;
    std::vector<vec3> vertex;
    std::size_t degenerateTriangles = 0;
    // Vertices whose normal is zero: used by no triangle or only by degenerate ones, or given
    // as zero by the file (0 when the vertex normals are left out).
    std::size_t verticesWithoutNormal = 0;
};

struct Normals {
    bool skipped = false;
    std::string skipReason;
    std::vector<DrawNormals> draws;
    std::size_t degenerateTriangles = 0;
    // Draws whose triangle normals, or vertex normals, were left out (fast/normals_fast.h):
    // their vectors are empty.
    std::size_t triangleNormalsLeftOut = 0, vertexNormalsLeftOut = 0;
};

// What a draw's shading reads of the normals for its colours: the triangles' when it is lit
// once per triangle (flat, painter) or Phong shaded with flat normals; the vertices' when
// Gouraud (its vertices are lit with theirs, flat normals or not) or Phong shaded with
// interpolated normals. The lighting model does not enter: an unlit draw gets what its
// shading model would read. (The normals image also reads a Gouraud draw's triangle normals
// when it has flat normals; a frame that keeps that image keeps every normal.)
struct NormalsRead {
    bool triangle = false;
    bool vertex = false;
};
NormalsRead normalsRead(const Draw& draw);

// The triangle's unit normal (P2 - P1) x (P3 - P1) / |...| of three points given in
// homogeneous coordinates (each divided by its w), into n; false when it is degenerate.
inline bool unitNormal(const dvec4& q1, const dvec4& q2, const dvec4& q3, dvec3& n) {
    const dvec3 p1 = cartesian(q1);
    const dvec3 cross = glm::cross(cartesian(q2) - p1, cartesian(q3) - p1);
    const double length = glm::length(cross);
    if (!(length > std::numeric_limits<double>::min()) || !isFinite(length)) return false;
    n = cross / length;
    return true;
}

struct NormalsInput {
    const Scene& scene;
    const ViewTransform& view;
};

class NormalsStage {
public:
    // The lecture's normals of every draw: every triangle's and every vertex's.
    Normals run(const NormalsInput& in) const;
};

// The normals of one draw, given its view-space vertices: each triangle's normal, and each
// vertex's, either the file's own (carried to view space by normalFromModel) or the
// normalised sum of the normals of the triangles around it, added in triangle order.
DrawNormals drawNormals(const Mesh& mesh, const std::vector<dvec4>& pView,
                        const dmat3& normalFromModel);

}  // namespace rl
