// Stage 4, projection (seed 000), with clipping and culling:
//  1. every vertex to clip space, pClip = clipFromView * pView; for the course camera
//     pClip = ((d/hx) x, (d/hy) y, z, z), so w is the view z;
//  2. each triangle is clipped against the draw's clip planes (view space, seed 001's
//     clipplane), the near plane w = near and the guard band's four planes (step 4),
//     Sutherland-Hodgman, one plane after the other; the polygon left is cut into a fan of
//     triangles, so nothing is ever divided by a w at or behind the camera;
//  3. every vertex in front is projected to [-1, 1], pNdc = pClip.xy / pClip.w: for the
//     course, ((d/hx) x/z, (d/hy) y/z);
//  4. then to pixels, as the seed writes it:
//     x = (int)((pNdc.x + 1) * width / 2),  y = (int)((1 - pNdc.y) * height / 2),
//     snapped to the rules' sub-pixel grid; clipping keeps every vertex within a guard band
//     of +-2^28 pixels, so that scan conversion's integer arithmetic is exact (under the
//     plain divide, which does not clip, a vertex beyond it is pulled in, and a warning
//     says so);
//  5. with cull set, triangles that are clockwise on screen are dropped;
//  6. back faces of a closed surface (Mesh::closedWinding) are left out before any of this
//     when the scene allows it (Scene::cullHiddenBackFaces): the draw uses the course
//     camera, has no clip planes, and every vertex lies beyond the near plane, so the camera
//     is outside the surface and nothing cuts it open; then every ray from the camera meets
//     a front face first, and a triangle whose normal points away from the camera,
//     n . P' > 0 in view space, is hidden. Not a step of the seeds: a saving for the
//     benchmark scenes (the course's files draw every triangle, as seed 000 does).
// Vertices made by clipping are appended after a draw's own vertices and remember the
// edge and parameter they came from (possibly another made vertex), so later stages
// interpolate any attribute for them.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/core/buffer.h"
#include "pipeline/core/diagnostics.h"
#include "pipeline/core/math.h"
#include "pipeline/scene/scene.h"
#include "pipeline/stages/view_transform.h"

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
    Buffer<float> depth;                // what the depth buffer compares (view z, or NDC z)
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
// y points up (the course's convention), (y_ndc + 1) H/2 otherwise; or, by seed 001's
// formula, x = x_ndc W/2 + W/2 and y = y_ndc H/2 + H/2.
inline dvec2 screenFromNdc(const dvec2& pNdc, double width, double height,
                           const Conventions& conventions) {
    const double yDown = conventions.ndcYUp ? -pNdc.y : pNdc.y;  // NDC y down the screen
    if (conventions.viewport == ViewportFormula::ScaleThenShift)
        return {pNdc.x * width / 2.0 + width / 2.0, yDown * height / 2.0 + height / 2.0};
    return {(pNdc.x + 1.0) * width / 2.0, (yDown + 1.0) * height / 2.0};
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

// A screen coordinate on the rules' sub-pixel grid (or as computed, when the rules do not
// snap).
// grid = 2^subpixelBits and cell = 1 / grid, worked out once by the caller: both are powers
// of two, so multiplying by cell gives the very bits dividing by grid would, without a
// division.
inline double snap(double coordinate, const RasterRules& rules, double grid, double cell) {
    switch (rules.snap) {
        case RasterRules::VertexSnap::Truncate:
            return std::trunc(coordinate * grid) * cell;
        case RasterRules::VertexSnap::Nearest:
            return std::floor(coordinate * grid + 0.5) * cell;
        case RasterRules::VertexSnap::None:
            return coordinate;
    }
    return coordinate;
}

inline bool finite2(const dvec2& p) {
    return isFinite(p.x) && isFinite(p.y);
}

// Twice the signed area in pixels (y down): negative when the triangle is counter-clockwise
// as it appears on the screen.
inline double screenArea(const dvec2& a, const dvec2& b, const dvec2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The projection matrix of the course camera: pClip = ((d/hx) x, (d/hy) y, z, z).
dmat4 courseClipFromView(const CourseCamera& camera);
// A draw's projection: its own matrix, else the course camera's, else the identity.
dmat4 clipFromViewOf(const Scene& scene, const Draw& draw);

struct ProjectionInput {
    const Scene& scene;
    const ViewTransform& view;
};

class ProjectionStage {
public:
    // Steps 1 to 6 above for every draw, triangle by triangle in order; what was clipped,
    // dropped or culled goes to diagnostics. Every array of DrawProjection is kept.
    Projection run(const ProjectionInput& in, Diagnostics& diagnostics) const;
};

// A projection before step 1: its mode, and each draw's matrix and vertex count, with pView
// and pClip sized for them (not yet written).
Projection projectionOf(const ProjectionInput& in);
// Step 1 for vertices [first, end) of draw d: pView kept, pClip = clipFromView * pView
// (proj.clipFromView set, the arrays sized). Returns the largest finite w among them.
double toClipSpace(const ProjectionInput& in, std::size_t d, DrawProjection& proj,
                   std::size_t first, std::size_t end);
// The near plane w = near: fixed, or a fraction of the largest w, and always in front of
// the eye.
double nearPlaneW(const Scene& scene, double wMax);

// Steps 2 to 6 for one draw: its vertices projected, its triangles clipped and emitted into
// the projection. The stage runs it on every vertex and triangle in order; the fast path
// (projection_fast.h) projects ranges of vertices and decides the triangles' fates on
// several threads with the same pieces.
class DrawProjector {
public:
    // keepExact: whether pNdc and pScreenExact are kept (only the views read them).
    DrawProjector(const ProjectionInput& in, std::size_t d, Projection& out, bool keepExact);

    // The per-vertex arrays sized for n vertices (new entries unset): each vertex is then
    // projected, or marked as not projected.
    void resizeVertices(std::size_t n);
    // Vertex i to NDC and to pixels when it is in front of the near plane (or nothing is
    // clipped); otherwise zeros, not in front.
    void projectIfInFront(std::uint32_t i);
    // Steps 2, 5 and 6 for mesh triangle t: its fate, counted, and its screen triangles.
    void projectTriangle(std::size_t t);

    // The pieces of projectTriangle.
    // Hidden back faces (step 6): the winding of the surface as seen in view space, or 0 when
    // nothing is left out.
    int hiddenWinding() const { return m_hiddenWinding; }
    bool facesAway(const std::array<std::uint32_t, 3>& tri) const;
    // The planes that apply to the current triangle, in order, each as a signed distance
    // (inside >= 0): the draw's clip planes, the near plane, the guard band's four.
    const std::vector<std::size_t>& planes() const { return m_planes; }
    void choosePlanes();
    double distance(std::size_t plane, std::uint32_t v) const;
    // A triangle wholly outside plane.
    TriangleFate outsideFate(std::size_t plane) const;
    // Whether cull drops a triangle: not counter-clockwise on the screen.
    bool culled(const std::array<std::uint32_t, 3>& v) const;
    // Whether a vertex's screen position and depth are finite.
    bool finite(std::uint32_t v) const;

private:
    void projectVertex(std::uint32_t i);
    std::uint32_t addClipVertex(std::size_t plane, std::uint32_t a, std::uint32_t b);
    void classifyAcrossTheEye(const std::array<std::uint32_t, 3>& tri);
    bool emitTriangle(std::size_t t, const std::array<std::uint32_t, 3>& v);
    void clipTriangle(std::size_t t);

    const Scene& m_scene;
    const Draw& m_draw;
    DrawProjection& m_proj;
    Projection& m_out;
    std::uint32_t m_index;
    bool m_keepExact;
    double m_grid, m_cell;      // the sub-pixel grid 2^bits, and its cell 1 / 2^bits
    double m_gx, m_gy;          // the guard band in units of w
    std::size_t m_nearPlane;    // the index of the near plane (after the clip planes)
    bool m_nearActive;          // the near plane applies to the current triangle
    bool m_guardActive = true;  // the guard band applies to the current triangle
    double m_side = 1.0;        // the sign of the current triangle's w
    int m_hiddenWinding = 0;
    std::vector<std::size_t> m_planes;
    std::vector<std::uint32_t> m_polygon, m_clipped;
    // The plain divide may pull a vertex in to the guard band: 1 when it was, 2 once a drawn
    // triangle counted it.
    std::vector<std::uint8_t> m_pulledIn;
};

// The small steps of DrawProjector, inline: the fast path calls them for every vertex.

// Steps 3 and 4: pNdc = pClip.xy / pClip.w, then the seed's x = (int)((pNdc.x + 1) width/2),
// y = (int)((1 - pNdc.y) height/2), snapped to the rules' grid.
inline void DrawProjector::projectVertex(std::uint32_t i) {
    const dvec4& pClip = m_proj.pClip[i];
    const dvec2 pNdc = dvec2(pClip) / pClip.w;
    const dvec2 exact = screenFromNdc(pNdc, m_scene.width, m_scene.height, m_scene.conventions);
    if (m_keepExact) {
        m_proj.pNdc[i] = pNdc;
        m_proj.pScreenExact[i] = exact;
    }
    const RasterRules& rules = m_scene.rules;
    dvec2 snapped(snap(exact.x, rules, m_grid, m_cell), snap(exact.y, rules, m_grid, m_cell));
    // An infinite coordinate (w = 0 under the plain divide) stays infinite, so the triangle is
    // dropped as NonFinite. Clipping keeps drawn vertices inside the guard band; only the
    // plain divide (which does not clip across the eye plane) can bring one from beyond it.
    if (finite2(snapped) &&
        (std::abs(snapped.x) > kGuardBand || std::abs(snapped.y) > kGuardBand)) {
        snapped = glm::clamp(snapped, dvec2(-kGuardBand), dvec2(kGuardBand));
        if (!m_pulledIn.empty()) m_pulledIn[i] = 1;
    }
    m_proj.pScreen[i] = snapped;
    m_proj.depth[i] = static_cast<float>(
        m_scene.conventions.depth == DepthSource::ViewZ ? m_proj.pView[i].z : pClip.z / pClip.w);
    m_proj.inFront[i] = 1;
}

inline void DrawProjector::projectIfInFront(std::uint32_t i) {
    if (m_out.mode != NearPlane::Mode::Clip || m_proj.pClip[i].w >= m_out.nearW) {
        projectVertex(i);
        return;
    }
    m_proj.pScreen[i] = dvec2(0.0);
    m_proj.depth[i] = 0.0f;
    m_proj.inFront[i] = 0;
}

inline bool DrawProjector::facesAway(const std::array<std::uint32_t, 3>& tri) const {
    // n . P' > 0 in view space, with n by the right-hand rule turned by the surface's winding.
    const dvec3 a(m_proj.pView[tri[0]]), b(m_proj.pView[tri[1]]), c(m_proj.pView[tri[2]]);
    return double(m_hiddenWinding) * glm::dot(glm::cross(b - a, c - a), a) > 0.0;
}

inline double DrawProjector::distance(std::size_t plane, std::uint32_t v) const {
    // The clip planes are planes of view space; the near plane and the guard band, four
    // planes |x| <= gx |w|, |y| <= gy |w| that keep every vertex within 2^28 pixels of the
    // image without bending an edge, planes of clip space (side: the sign of the triangle's w).
    if (plane < m_nearPlane) return glm::dot(m_draw.clipPlanes[plane], m_proj.pView[v]);
    const dvec4& c = m_proj.pClip[v];
    switch (plane - m_nearPlane) {
        case 0:
            return c.w - m_out.nearW;
        case 1:
            return m_side * m_gx * c.w - c.x;
        case 2:
            return m_side * m_gx * c.w + c.x;
        case 3:
            return m_side * m_gy * c.w - c.y;
        default:
            return m_side * m_gy * c.w + c.y;
    }
}

inline bool DrawProjector::culled(const std::array<std::uint32_t, 3>& v) const {
    const auto& s = m_proj.pScreen;
    return m_draw.cull && !(screenArea(s[v[0]], s[v[1]], s[v[2]]) < 0.0);
}

inline bool DrawProjector::finite(std::uint32_t v) const {
    return finite2(m_proj.pScreen[v]) && std::isfinite(m_proj.depth[v]);
}

// Tells the user what was clipped, dropped, culled or drawn by the plain divide.
void reportProjection(const Scene& scene, const Projection& projection, Diagnostics& diagnostics);

// The counter of a projection that counts the triangles of a fate.
std::size_t& tally(Projection& projection, TriangleFate fate);

}  // namespace rl
