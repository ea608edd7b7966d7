// Stage 4, projection (seed 000), with clipping and culling:
//  1. every vertex to clip space, pClip = clipFromView * pView; for the course camera
//     pClip = ((d/hx) x, (d/hy) y, z, z), so w is the view z;
//  2. each triangle is clipped against the draw's clip planes (view space, seed 001's
//     clipplane) and against the near plane w = near (Sutherland-Hodgman, one plane after
//     the other); the polygon left is cut into a fan of triangles, so nothing is ever
//     divided by a w at or behind the camera;
//  3. every vertex in front is projected to [-1, 1], pNdc = pClip.xy / pClip.w: for the
//     course, ((d/hx) x/z, (d/hy) y/z);
//  4. then to pixels, as the seed writes it:
//     x = (int)((pNdc.x + 1) * width / 2),  y = (int)((1 - pNdc.y) * height / 2),
//     snapped to the rules' sub-pixel grid and kept within a guard band of +-2^28 pixels
//     so that scan conversion's integer arithmetic is exact (a vertex beyond it is pulled
//     in, and a warning says so);
//  5. with cull set, triangles that are clockwise on screen are dropped;
//  6. back faces of a closed surface (Mesh::closedWinding) are left out before any of this
//     when the scene allows it (Scene::cullHiddenBackFaces): the draw uses the course
//     camera, has no clip planes, and every vertex lies beyond the near plane, so the camera
//     is outside the surface and nothing cuts it open; then every ray from the camera meets
//     a front face first, and a triangle whose normal points away from the camera,
//     n . P' > 0 in view space, is hidden.
// Vertices made by clipping are appended after a draw's own vertices and remember the
// edge and parameter they came from (possibly another made vertex), so later stages
// interpolate any attribute for them.
#pragma once

#include <array>
#include <cstdint>
#include <iterator>
#include <string>
#include <vector>

#include "buffer.h"
#include "diagnostics.h"
#include "math.h"
#include "scene.h"
#include "view_transform.h"

namespace rl {

enum class TriangleFate : std::uint8_t {
    Inside,           // wholly inside every plane: projected as is
    Clipped,          // crossed the near plane or a clip plane: the part inside is drawn
    Behind,           // wholly at or behind the near plane: not drawn
    ClippedAway,      // wholly outside one of the draw's clip planes: not drawn
    Culled,           // clockwise on screen in a draw with cull set: not drawn
    BackFace,         // faces away from the camera on a closed surface seen from outside
    BeyondGuardBand,  // wholly more than 2^28 pixels off the image: not drawn
    NonFinite,        // a coordinate is NaN or infinite (only with the naive projection)
};

// A vertex made by clipping: the point lerp(pView[a], pView[b], t), with a inside the plane
// that cut the edge (a or b may themselves be made vertices, made earlier).
struct ClipVertex {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    double t = 0.0;
};

// Trivial, with no default member values, so that the projection's list of them is made
// without being zeroed first (Buffer); one made by hand is brace-initialised.
struct ScreenTriangle {
    std::uint32_t draw;
    std::uint32_t source;            // index of the mesh triangle it comes from
    std::array<std::uint32_t, 3> v;  // indices into the draw's projected vertices
};

struct DrawProjection {
    dmat4 clipFromView = dmat4(1.0);
    std::uint32_t originalVertexCount = 0;
    // Per vertex: first the draw's own vertices, then those made by clipping.
    Buffer<dvec4> pView;
    Buffer<dvec4> pClip;                // clipFromView * pView (w = near on made vertices)
    std::vector<dvec2> pNdc;            // [-1, 1] on screen; meaningless where !inFront
    std::vector<dvec2> pScreenExact;    // pixels, before snapping
                                        // (these two are empty unless kept: run's keepExact)
    Buffer<dvec2> pScreen;              // pixels, after snapping (what is rasterized)
    Buffer<float> depth;                // what the depth buffer compares (view z)
    Buffer<std::uint8_t> inFront;       // 1 when the vertex was projected
    std::vector<ClipVertex> generated;  // vertex originalVertexCount + i comes from generated[i]
    std::vector<TriangleFate> fate;     // per mesh triangle
};

struct Projection {
    double nearW = 0.0;  // the near plane, w = nearW in clip space
    NearPlane::Mode mode = NearPlane::Mode::Clip;
    std::vector<DrawProjection> draws;
    Buffer<ScreenTriangle> triangles;  // what scan conversion receives, in draw order

    std::size_t inside = 0, clipped = 0, behind = 0, clippedAway = 0, culled = 0, nonFinite = 0;
    std::size_t backFaces = 0;  // hidden back faces of closed surfaces, left out
    // The plain divide (NearPlane::Mode::Naive): triangles with every w < 0, drawn as their
    // point reflection through the eye, and those whose w differ in sign or reach 0, which
    // wrap through infinity and are drawn wrong.
    std::size_t behindEye = 0;
    std::size_t acrossEye = 0;
    std::size_t acrossInfinity = 0;    // SameSide: triangles whose w differ in sign (clipped)
    std::size_t beyondGuardBand = 0;   // wholly more than 2^28 pixels off the image
    std::size_t outsideGuardBand = 0;  // vertices pulled in to the guard band
};

// The triangles of a scene whose three vertices all lie behind the eye (w < 0 in clip
// space): what the plain divide draws as the point reflection through the eye when near-plane
// clipping leaves the image empty.
std::size_t trianglesBehindEye(const Projection& projection, const Scene& scene);
// Whether near-plane clipping left nothing to draw because every triangle lies behind the
// near plane: then the warning, the window and the command line offer the plain divide.
inline bool everyTriangleBehind(const Projection& projection, const Scene& scene) {
    const std::size_t total = scene.triangleCount();
    return projection.mode == NearPlane::Mode::Clip && total > 0 && projection.behind == total;
}

// Pixels from NDC, before snapping: x = (x_ndc + 1) W/2, and y = (1 - y_ndc) H/2 when NDC's
// y points up (the course's convention), (y_ndc + 1) H/2 otherwise.
inline dvec2 screenFromNdc(const dvec2& pNdc, double width, double height, bool ndcYUp) {
    const double yFromTop = ndcYUp ? 1.0 - pNdc.y : pNdc.y + 1.0;
    return {(pNdc.x + 1.0) * width / 2.0, yFromTop * height / 2.0};
}

// One plane of Sutherland-Hodgman clipping (step 2): walks the polygon's edges A-B in order,
// B the vertex after A (the first after the last); adds A when inside(A), and where A and B
// lie on different sides, the point crossing(in, out) made from the end inside and the end
// outside (always from the inside end, so two polygons sharing the edge get the same point,
// bit for bit). The output is appended to `out`, in order: the winding is kept. The
// projection stage clips with it plane after plane; the near-plane recorder (near_clip.h)
// and the views cutting polygons to a rectangle use it too.
template <typename Polygon, typename Out, typename Inside, typename Crossing>
void clipPolygonAgainstPlane(const Polygon& polygon, Out& out, Inside&& inside,
                             Crossing&& crossing) {
    const auto first = std::begin(polygon), last = std::end(polygon);
    for (auto it = first; it != last; ++it) {
        const auto next = std::next(it);
        const auto& a = *it;
        const auto& b = next == last ? *first : *next;
        const bool aIn = inside(a);
        const bool bIn = inside(b);
        if (aIn) out.push_back(a);
        if (aIn != bIn) out.push_back(aIn ? crossing(a, b) : crossing(b, a));
    }
}

// Where an edge from a point inside a plane (signed distance dIn >= 0) to one outside it
// (dOut < 0) crosses it, as the fraction of the way from the inside end.
inline double crossingFraction(double dIn, double dOut) {
    return dIn / (dIn - dOut);
}

// Snapped screen coordinates are kept within +-kGuardBand pixels.
inline constexpr double kGuardBand = double(1 << 28);

// The projection matrix of the course camera: pClip = ((d/hx) x, (d/hy) y, z, z).
dmat4 courseClipFromView(const CourseCamera& camera);
// A draw's projection: its own matrix, else the course camera's, else the identity.
dmat4 clipFromViewOf(const Scene& scene, const Draw& draw);

class ProjectionStage {
public:
    // threads: vertices and per-triangle verdicts are worked out on several; triangles are
    // emitted on several when none needs clipping, else emitted and clipped in order on one
    // (the result does not depend on their number).
    // keepExact: whether pNdc and pScreenExact are kept (only the views read them; without
    // them they are empty).
    Projection run(const Scene& scene, const ViewTransform& view, Diagnostics& diagnostics,
                   int threads = 1, bool keepExact = true) const;
};

}  // namespace rl
