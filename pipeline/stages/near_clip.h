// Seed 002's clipping of one triangle against the near plane, recorded step by step for
// the view that teaches it. The seed (OpenGL's camera, looking along -z) clips against the
// plane z = -eps, P = [0, 0, -1, eps]: a point A is kept when dot(P, A) >= 0. The course
// camera looks along +z, and the projection stage clips against w = near in clip space, so
// here dot(P, A) = w(A) - near with w(A) the w of clipFromView * A; for the course camera
// w is the view z and P = [0, 0, 1, -near] (the plane z = near).
//
//   Start with an empty output polygon. For each vertex A (B the next one around):
//     if dot(P, A) >= 0, add A;
//     if dot(P, A) and dot(P, B) differ in sign,
//       t = (0 - dot(P, A)) / (dot(P, B) - dot(P, A)), add C = lerp(t, A, B).
//   A polygon of four vertices q0 q1 q2 q3 is split into the triangles q0 q1 q2, q0 q2 q3.
//
// The numbers are the projection stage's own: the same distances, the stage's walk
// (clipPolygonAgainstPlane, projection.h), and each C computed as the stage computes it, from
// the end in front (t' = 1 - t when A is the end behind), so that two triangles sharing an
// edge get the same point bit for bit. The polygon and its fan are the stage's, as long as
// no clip plane of the draw cut the triangle first and the guard band did not cut it after
// (tst_clip_trapezoid checks this on real scenes).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "pipeline/core/math.h"
#include "pipeline/stages/projection.h"

namespace rl {

// What the algorithm found at one vertex A = vertex k and on its edge A-B, B = vertex k+1.
struct NearClipEdge {
    std::size_t a = 0, b = 0;  // vertex indices of the triangle, b = (a + 1) % 3
    double distanceA = 0.0;    // dot(P, A)
    double distanceB = 0.0;    // dot(P, B)
    bool keptA = false;        // dot(P, A) >= 0
    bool crosses = false;      // the two distances differ in sign
    double t = 0.0;            // the seed's (0 - dot(P, A)) / (dot(P, B) - dot(P, A))
    double tFromInside = 0.0;  // the stage's, from the end in front (t, or 1 - t)
    dvec4 pView{0.0};          // C, when the edge crosses
};

// One vertex of the output polygon: a vertex of the triangle or a point made on an edge.
struct NearClipPoint {
    bool made = false;
    std::size_t index = 0;  // the triangle's vertex, or the edge (= its vertex A) it was made on
    dvec4 pView{0.0};
};

struct NearClipRecord {
    dvec4 plane{0.0};  // P in view space: dot(P, pView) = w - near (for display)
    double nearW = 0.0;
    std::array<dvec4, 3> pView{};
    std::array<NearClipEdge, 3> edges{};  // in the algorithm's order: vertex 0, 1, 2
    std::vector<NearClipPoint> polygon;   // the output polygon, in order
    // The triangles drawn: a fan over the polygon (indices into polygon): none, one, or
    // two for a quad.
    std::vector<std::array<std::size_t, 3>> triangles;

    std::size_t keptCount() const;
    bool untouched() const { return keptCount() == 3; }  // wholly in front
    bool gone() const { return polygon.size() < 3; }     // wholly behind (or a sliver)
};

// The plane w = near of clip space as a plane of view space: dot(P, pView) = w - near.
dvec4 nearPlaneInView(const dmat4& clipFromView, double nearW);

// The clipping of the triangle pView against the plane w = near, where w is the w of
// clipFromView * pView.
NearClipRecord clipAgainstNearPlane(const std::array<dvec4, 3>& pView, const dmat4& clipFromView,
                                    double nearW);

// The same for mesh triangle `source` of draw `draw` of a projected frame.
NearClipRecord nearClipOf(const Scene& scene, const Projection& projection, std::uint32_t draw,
                          std::uint32_t source);

// The projected triangles (indices into projection.triangles) that mesh triangle `source`
// of draw `draw` became, in the order the stage emitted them.
std::vector<std::uint32_t> screenTrianglesOf(const Projection& projection, std::uint32_t draw,
                                             std::uint32_t source);

}  // namespace rl
