// Seed 004's painter's algorithm. The triangles of the frame (every draw's) are sorted by the
// distance |b| of their view-space barycentre b to the camera (the origin of view space), far
// to near, and painted in that order without a depth test: each fragment is written over
// whatever an earlier triangle left, so the nearest triangle is seen only when it is painted
// last. Every triangle is lit once, at its barycentre, with its normal (as flat shading).
//
// Where this fails: the barycentre's distance orders whole triangles, but visibility is decided
// per pixel. A long triangle whose barycentre is far may still pass in front of a small one
// whose barycentre is nearer; it is painted first and then covered. Triangles that cross each
// other, or overlap in a cycle, have no correct order at all.
//
// A triangle cut by the near plane or a clip plane is sorted by the barycentre of the mesh
// triangle it comes from (the one flat shading lights it at), not by its pieces': the pieces
// of one triangle stay together, in the order clipping made them. Ties keep the order of the
// draws and of the mesh (a stable sort).
//
// ProjectionStage sorts Projection::triangles this way when paintersAlgorithm(scene), so the
// later stages, the replay and the views see the triangles in painted order; the depth test
// writes every fragment (DepthTest::painted) and keeps the depth of the last one painted.
#pragma once

#include <cstdint>
#include <vector>

#include "pipeline/core/math.h"
#include "pipeline/scene/scene.h"
#include "pipeline/stages/projection.h"

namespace rl {

// The view-space barycentre of mesh triangle `source` of a draw: the mean of its vertices'
// (x, y, z) / w.
dvec3 viewBarycentre(const DrawProjection& draw, const Mesh& mesh, std::uint32_t source);
// The distance to the camera the painter sorts projected triangle t by: |b| of its source
// triangle's view-space barycentre b.
double painterDistance(const Scene& scene, const Projection& projection, std::uint32_t t);

// The painter's order of projection.triangles as they are: their indices, far to near.
std::vector<std::uint32_t> painterOrder(const Scene& scene, const Projection& projection);
// Puts projection.triangles in the painter's order.
void sortFarToNear(const Scene& scene, Projection& projection);

}  // namespace rl
