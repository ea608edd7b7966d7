// Whether a mesh is the closed surface of a solid, and which way its triangles turn: what
// back-face culling needs to know to leave out triangles without changing the picture.
#pragma once

#include "pipeline/scene/scene.h"

namespace rl {

// +1 when every edge of the mesh is shared by exactly two triangles that run along it in
// opposite directions (a closed, consistently wound surface) and every connected piece
// encloses a positive volume with its corners counter-clockwise seen from outside (the
// right-hand rule gives outward normals); -1 when every piece is wound the other way;
// 0 otherwise (open, non-manifold, inconsistently wound, a repeated corner, flat pieces,
// or pieces wound in different ways). Triangle corners are compared by index only.
int closedSurfaceWinding(const Mesh& mesh);

}  // namespace rl
