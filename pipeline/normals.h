// Stage 3, normals (seed 000): in view coordinates, each triangle's normal
// (P2 - P1) x (P3 - P1), normalised, is added to the normals of its three vertices; then
// every vertex normal is normalised. Normals given by the file (seed 001's `normal`) are
// used instead, carried to view space by the inverse transpose of the model/view matrix. Degenerate
// (zero-area) triangles have no normal and contribute nothing; they are counted, as are vertices
// left without a normal. Skipped when the scene is not lit (nothing would read the normals).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "math.h"
#include "scene.h"
#include "view_transform.h"

namespace rl {

struct DrawNormals {
    std::vector<vec3> triangle;  // unit length, or zero for a degenerate triangle
    std::vector<vec3> vertex;    // unit length, or zero for a vertex with no normal
    std::size_t degenerateTriangles = 0;
    std::size_t verticesWithoutNormal = 0;  // used by no triangle, or only by degenerate ones
};

struct Normals {
    bool skipped = false;
    std::string skipReason;
    std::vector<DrawNormals> draws;
    std::size_t degenerateTriangles = 0;
};

class NormalsStage {
public:
    // threads: the triangles and vertices are shared out between them (parallel.h); each
    // vertex still sums its triangles' normals in triangle order, so the result is the same
    // bits for any number.
    Normals run(const Scene& scene, const ViewTransform& view, int threads = 1) const;
};

}  // namespace rl
