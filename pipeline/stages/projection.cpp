#include "projection.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "pipeline/core/format.h"
#include "pipeline/stages/painters_algorithm.h"

namespace rl {

dmat4 courseClipFromView(const CourseCamera& camera) {
    dmat4 m(0.0);
    m[0][0] = camera.d / camera.hx;
    m[1][1] = camera.d / camera.hy;
    m[2][2] = 1.0;
    m[2][3] = 1.0;  // w = z
    return m;
}

dmat4 clipFromViewOf(const Scene& scene, const Draw& draw) {
    if (draw.clipFromView) return *draw.clipFromView;
    if (scene.camera) return courseClipFromView(*scene.camera);
    return dmat4(1.0);
}

// The counter of a projection that counts the triangles of a fate.
std::size_t& tally(Projection& out, TriangleFate fate) {
    switch (fate) {
        case TriangleFate::Inside:
            return out.inside;
        case TriangleFate::Clipped:
            return out.clipped;
        case TriangleFate::Behind:
            return out.behind;
        case TriangleFate::ClippedAway:
            return out.clippedAway;
        case TriangleFate::Culled:
            return out.culled;
        case TriangleFate::BackFace:
            return out.backFaces;
        case TriangleFate::BeyondGuardBand:
            return out.beyondGuardBand;
        case TriangleFate::NonFinite:
            break;
    }
    return out.nonFinite;
}

std::size_t trianglesBehindEye(const Projection& projection, const Scene& scene) {
    std::size_t count = 0;
    for (std::size_t d = 0; d < scene.draws.size() && d < projection.draws.size(); ++d) {
        const Draw& draw = scene.draws[d];
        const DrawProjection& proj = projection.draws[d];
        if (!draw.mesh) continue;
        for (const auto& tri : draw.mesh->triangles)
            count += proj.pClip[tri[0]].w < 0.0 && proj.pClip[tri[1]].w < 0.0 &&
                             proj.pClip[tri[2]].w < 0.0
                         ? 1
                         : 0;
    }
    return count;
}

// Step 1 ---------------------------------------------------------------------------------

Projection projectionOf(const ProjectionInput& in) {
    Projection out;
    out.mode = in.scene.nearPlane.mode;
    out.draws.resize(in.scene.draws.size());
    for (std::size_t d = 0; d < in.scene.draws.size(); ++d) {
        DrawProjection& proj = out.draws[d];
        proj.clipFromView = clipFromViewOf(in.scene, in.scene.draws[d]);
        const std::size_t count = in.view.pView[d].size();
        proj.originalVertexCount = static_cast<std::uint32_t>(count);
        proj.pView.resize(count);
        proj.pClip.resize(count);
    }
    return out;
}

double toClipSpace(const ProjectionInput& in, std::size_t d, DrawProjection& proj,
                   std::size_t first, std::size_t end) {
    const std::vector<dvec4>& pView = in.view.pView[d];
    double wMax = 0.0;
    for (std::size_t i = first; i < end; ++i) {
        proj.pView[i] = pView[i];
        proj.pClip[i] = proj.clipFromView * pView[i];
        const double w = proj.pClip[i].w;
        if (w > wMax && isFinite(w)) wMax = w;
    }
    return wMax;
}

double nearPlaneW(const Scene& scene, double wMax) {
    // The near plane must lie strictly in front of the camera, or a vertex at w = 0 would be
    // divided by 0.
    const double requested =
        scene.nearPlane.fixedW ? *scene.nearPlane.fixedW : scene.nearPlane.autoFraction * wMax;
    return std::max(requested, std::numeric_limits<double>::min());
}

// Steps 2 to 6, one draw ------------------------------------------------------------------

DrawProjector::DrawProjector(const ProjectionInput& in, std::size_t d, Projection& out,
                             bool keepExact)
    : m_scene(in.scene),
      m_draw(in.scene.draws[d]),
      m_proj(out.draws[d]),
      m_out(out),
      m_index(static_cast<std::uint32_t>(d)),
      m_keepExact(keepExact),
      m_grid(std::ldexp(1.0, in.scene.rules.subpixelBits)),
      m_cell(std::ldexp(1.0, -in.scene.rules.subpixelBits)),
      m_gx(kGuardBand / in.scene.width),
      m_gy(kGuardBand / in.scene.height),
      m_nearPlane(m_draw.clipPlanes.size()),
      m_nearActive(out.mode == NearPlane::Mode::Clip) {
    // Hidden back faces (step 6): only for a closed surface seen from outside (every vertex
    // beyond the near plane) through the course camera, with nothing cutting it open. A
    // mirroring transform turns its winding over.
    if (m_scene.cullHiddenBackFaces && m_draw.mesh->closedWinding != 0 && !m_draw.clipFromView &&
        m_scene.camera && m_draw.clipPlanes.empty()) {
        bool beyondNear = true;
        for (std::uint32_t i = 0; i < m_proj.originalVertexCount && beyondNear; ++i)
            beyondNear = m_proj.pClip[i].w > out.nearW && m_proj.pView[i].w == 1.0;
        const double det = glm::determinant(dmat3(in.view.viewFromModel[d]));
        if (beyondNear && det != 0.0)
            m_hiddenWinding = det > 0.0 ? m_draw.mesh->closedWinding : -m_draw.mesh->closedWinding;
    }
    resizeVertices(m_proj.pView.size());
    choosePlanes();
}

void DrawProjector::resizeVertices(std::size_t n) {
    if (m_out.mode == NearPlane::Mode::Naive) m_pulledIn.resize(n, 0);
    if (m_keepExact) {
        m_proj.pNdc.resize(n, dvec2(0.0));
        m_proj.pScreenExact.resize(n, dvec2(0.0));
    }
    m_proj.pScreen.resize(n);
    m_proj.depth.resize(n);
    m_proj.inFront.resize(n);
}

void DrawProjector::choosePlanes() {
    m_planes.clear();
    for (std::size_t k = 0; k < m_nearPlane; ++k) m_planes.push_back(k);
    if (m_nearActive) m_planes.push_back(m_nearPlane);
    if (m_guardActive)
        for (std::size_t k = 1; k <= 4; ++k) m_planes.push_back(m_nearPlane + k);
}

TriangleFate DrawProjector::outsideFate(std::size_t plane) const {
    return plane == m_nearPlane  ? TriangleFate::Behind
           : plane < m_nearPlane ? TriangleFate::ClippedAway
                                 : TriangleFate::BeyondGuardBand;  // far off the image
}

// A vertex where the edge from a (inside) to b (outside) crosses a plane. Always computed from
// the inside vertex, so that two triangles sharing the edge get the same point, bit for bit.
std::uint32_t DrawProjector::addClipVertex(std::size_t plane, std::uint32_t a, std::uint32_t b) {
    const double t = crossingFraction(distance(plane, a), distance(plane, b));
    const auto index = static_cast<std::uint32_t>(m_proj.pView.size());
    const dvec4 pView = glm::mix(m_proj.pView[a], m_proj.pView[b], t);
    dvec4 pClip = glm::mix(m_proj.pClip[a], m_proj.pClip[b], t);
    if (plane == m_nearPlane) pClip.w = m_out.nearW;  // exactly on it
    m_proj.pView.push_back(pView);
    m_proj.pClip.push_back(pClip);
    m_proj.generated.push_back({a, b, t});
    resizeVertices(m_proj.pView.size());
    projectIfInFront(index);
    return index;
}

// Which planes a triangle meets when its w differ in sign: the plain divide clips none (and
// leaves out the guard band, which would draw the triangle's other side); same side clips
// at the near plane.
void DrawProjector::classifyAcrossTheEye(const std::array<std::uint32_t, 3>& tri) {
    const auto& c = m_proj.pClip;
    const auto positive = [&](std::uint32_t v) { return c[v].w > 0.0; };
    const auto negative = [&](std::uint32_t v) { return c[v].w < 0.0; };
    const bool allPositive = std::all_of(tri.begin(), tri.end(), positive);
    const bool allNegative = std::all_of(tri.begin(), tri.end(), negative);
    m_side = allNegative ? -1.0 : 1.0;
    if (m_out.mode == NearPlane::Mode::Naive) {
        m_out.behindEye += allNegative ? 1 : 0;
        m_out.acrossEye += !allNegative && !allPositive ? 1 : 0;
        m_guardActive = allNegative || allPositive;
    } else if (m_out.mode == NearPlane::Mode::SameSide) {
        m_nearActive = !allNegative && !allPositive;
        m_out.acrossInfinity += m_nearActive ? 1 : 0;
    }
}

// Emits one screen triangle of mesh triangle t, unless a coordinate is not finite or cull
// drops it (its fate then says which).
bool DrawProjector::emitTriangle(std::size_t t, const std::array<std::uint32_t, 3>& v) {
    bool finiteAll = true;
    for (std::uint32_t i : v) finiteAll = finiteAll && finite(i);
    const TriangleFate fate = !finiteAll  ? TriangleFate::NonFinite
                              : culled(v) ? TriangleFate::Culled
                                          : TriangleFate::Inside;
    if (fate != TriangleFate::Inside) {
        m_proj.fate[t] = fate;
        return false;
    }
    m_out.triangles.push_back({m_index, static_cast<std::uint32_t>(t), v});
    for (std::uint32_t i : v)
        if (!m_pulledIn.empty() && m_pulledIn[i] == 1) {
            m_pulledIn[i] = 2;
            ++m_out.outsideGuardBand;
        }
    return true;
}

// Sutherland-Hodgman, one plane after the other: walk the polygon's edges, keep the vertices
// inside and add one where an edge crosses the plane. The winding is kept; the polygon left
// is cut into a fan.
void DrawProjector::clipTriangle(std::size_t t) {
    const auto& tri = m_draw.mesh->triangles[t];
    m_polygon.assign(tri.begin(), tri.end());
    for (std::size_t plane : m_planes) {
        if (m_polygon.size() < 3) break;
        m_clipped.clear();
        clipPolygonAgainstPlane(
            m_polygon, m_clipped, [&](std::uint32_t v) { return distance(plane, v) >= 0.0; },
            [&](std::uint32_t in, std::uint32_t outside) {
                return addClipVertex(plane, in, outside);
            });
        m_polygon.swap(m_clipped);
    }
    // The fan; a piece culled or not finite writes that fate, which stands when no piece is
    // drawn.
    bool any = false;
    for (std::size_t k = 1; k + 1 < m_polygon.size(); ++k)
        any = emitTriangle(t, {m_polygon[0], m_polygon[k], m_polygon[k + 1]}) || any;
    if (m_polygon.size() < 3) {
        m_proj.fate[t] = TriangleFate::ClippedAway;  // only an edge or a point was left
        ++m_out.clippedAway;
    } else if (any) {
        m_proj.fate[t] = TriangleFate::Clipped;
        ++m_out.clipped;
    } else {
        ++tally(m_out, m_proj.fate[t]);
    }
}

void DrawProjector::projectTriangle(std::size_t t) {
    const auto& tri = m_draw.mesh->triangles[t];
    if (m_hiddenWinding != 0 && facesAway(tri)) {
        m_proj.fate[t] = TriangleFate::BackFace;
        ++m_out.backFaces;
        return;
    }
    if (m_out.mode != NearPlane::Mode::Clip) {
        classifyAcrossTheEye(tri);
        choosePlanes();
    }
    // Which planes cut the triangle, and is it wholly outside one of them (the first such)?
    bool cut = false;
    for (std::size_t plane : m_planes) {
        int inside = 0;
        for (std::uint32_t v : tri) inside += distance(plane, v) >= 0.0 ? 1 : 0;
        if (inside == 0) {
            m_proj.fate[t] = outsideFate(plane);
            ++tally(m_out, m_proj.fate[t]);
            return;
        }
        cut = cut || inside < 3;
    }
    if (cut) {
        clipTriangle(t);
    } else if (emitTriangle(t, tri)) {
        m_proj.fate[t] = TriangleFate::Inside;
        ++m_out.inside;
    } else {
        ++tally(m_out, m_proj.fate[t]);
    }
}

// The stage ---------------------------------------------------------------------------------

Projection ProjectionStage::run(const ProjectionInput& in, Diagnostics& diagnostics) const {
    const Scene& scene = in.scene;
    // Step 1, every vertex to clip space first: the near plane is a plane of clip space.
    Projection out = projectionOf(in);
    double wMax = 0.0;
    for (std::size_t d = 0; d < scene.draws.size(); ++d)
        wMax = std::max(wMax, toClipSpace(in, d, out.draws[d], 0, out.draws[d].pView.size()));
    out.nearW = nearPlaneW(scene, wMax);
    // Steps 2 to 6, draw by draw, vertex by vertex and triangle by triangle.
    for (std::size_t d = 0; d < scene.draws.size(); ++d) {
        if (!scene.draws[d].mesh) continue;
        DrawProjector draw(in, d, out, true);
        for (std::uint32_t i = 0; i < out.draws[d].originalVertexCount; ++i)
            draw.projectIfInFront(i);
        const std::size_t triangles = scene.draws[d].mesh->triangles.size();
        out.draws[d].fate.assign(triangles, TriangleFate::Inside);
        for (std::size_t t = 0; t < triangles; ++t) draw.projectTriangle(t);
    }
    reportProjection(scene, out, diagnostics);
    if (paintersAlgorithm(scene)) sortFarToNear(scene, out);  // seed 004 (painters_algorithm.h)
    return out;
}

// What the user is told -------------------------------------------------------------------

namespace {

// The note on the triangles clipped at the near plane (or the guard band) and those left out
// wholly: "3 triangles were clipped against ...; 2 lie wholly behind the near plane, not drawn".
Message clippingNote(const Scene& scene, const Projection& out) {
    bool planes = false;
    for (const Draw& draw : scene.draws) planes = planes || !draw.clipPlanes.empty();
    Message against, left;  // where the triangles were clipped, and those left out wholly
    if (out.mode == NearPlane::Mode::Clip) {
        const std::string z = formatNumber(out.nearW);
        against = planes ? "the near plane z = %1 and the clip planes"_msg(z)
                         : "the near plane z = %1"_msg(z);
        left = counted(out.behind, "%1 lies wholly behind the near plane"_msg,
                       "%1 lie wholly behind the near plane"_msg);
        if (out.clippedAway > 0)
            left = "%1 and %2 wholly outside a clip plane"_msg(left, out.clippedAway);
    } else {
        against = planes ? "the clip planes or the guard band 2^28 pixels around the image"_msg
                         : "the guard band 2^28 pixels around the image"_msg;
        left = "%1 lie wholly outside a clip plane"_msg(out.clippedAway);
    }
    const Message clipped = counted(out.clipped, "%1 triangle was clipped against %2"_msg,
                                    "%1 triangles were clipped against %2"_msg, against);
    return "%1; %2, not drawn"_msg(clipped, left);
}

// The warning when nothing is in front of the camera, with what the plain divide would draw.
Message everythingBehindWarning(const Scene& scene, const Projection& out) {
    const Message behind =
        "every triangle is behind the camera (is N pointing away from the object?): the image is "
        "empty"_msg;
    const std::size_t total = scene.triangleCount();
    const std::size_t mirrored = trianglesBehindEye(out, scene);
    if (mirrored == 0) return behind;
    if (total == 1)
        return "%1. The plain divide of seed 000, x/z and y/z with z < 0, would draw it: the "
               "object's point reflection through the eye (turned half a turn on the screen), "
               "where the z-buffer, keeping the smallest z, keeps the side farthest from the "
               "camera"_msg(behind);
    return (mirrored == total
                ? "%1. The plain divide of seed 000, x/z and y/z with z < 0, would draw all %2 of "
                  "them: the object's point reflection through the eye (turned half a turn on the "
                  "screen), where the z-buffer, keeping the smallest z, keeps the side farthest "
                  "from the camera"_msg
                : "%1. The plain divide of seed 000, x/z and y/z with z < 0, would draw %2 of "
                  "them: the object's point reflection through the eye (turned half a turn on the "
                  "screen), where the z-buffer, keeping the smallest z, keeps the side farthest "
                  "from the camera"_msg)(behind, mirrored);
}

// The warnings on triangles drawn wrong or distorted, or not drawn for want of coordinates.
void warnDistorted(const Projection& out, const SourceLocation& where, Diagnostics& diagnostics) {
    if (out.acrossEye > 0)
        diagnostics.warn(where,
                         counted(out.acrossEye,
                                 "plain divide: %1 triangle reaches from in front of the eye to at "
                                 "or behind it (w of different signs, or 0): divided by w without "
                                 "clipping, it wraps through infinity and is drawn wrong (clipping "
                                 "at the near plane draws its front part)"_msg,
                                 "plain divide: %1 triangles reach from in front of the eye to at "
                                 "or behind it (w of different signs, or 0): divided by w without "
                                 "clipping, it wraps through infinity and is drawn wrong (clipping "
                                 "at the near plane draws its front part)"_msg));
    if (out.outsideGuardBand > 0)
        diagnostics.warn(where,
                         "%1 vertices project more than 2^28 pixels from the image and were "
                         "pulled in to that distance: triangles through them may be distorted on "
                         "screen"_msg(out.outsideGuardBand));
    if (out.nonFinite > 0)
        diagnostics.warn(where,
                         "%1 triangles project to infinite or undefined coordinates and were not "
                         "drawn"_msg(out.nonFinite));
}

}  // namespace

void reportProjection(const Scene& scene, const Projection& out, Diagnostics& diagnostics) {
    const SourceLocation where{scene.name, 0, 0};
    if (everyTriangleBehind(out, scene))
        diagnostics.warn(where, everythingBehindWarning(scene, out));
    else if (out.behind + out.clipped + out.clippedAway > 0)
        diagnostics.note(where, clippingNote(scene, out));
    if (out.backFaces > 0)
        diagnostics.note(where,
                         counted(out.backFaces,
                                 "%1 triangle faces away from the camera on a closed surface "
                                 "seen from outside: hidden, so not drawn (back-face "
                                 "culling)"_msg,
                                 "%1 triangles face away from the camera on a closed surface "
                                 "seen from outside: hidden, so not drawn (back-face "
                                 "culling)"_msg));
    if (out.culled > 0)
        diagnostics.note(where,
                         counted(out.culled, "%1 triangle is clockwise on screen and culled"_msg,
                                 "%1 triangles are clockwise on screen and culled"_msg));
    if (out.acrossInfinity > 0)
        diagnostics.note(where,
                         counted(out.acrossInfinity,
                                 "%1 triangle reaches from in front of the eye to at or behind it "
                                 "(w of different signs): only the part with w >= %2 is drawn"_msg,
                                 "%1 triangles reach from in front of the eye to at or behind it "
                                 "(w of different signs): only the part with w >= %2 is drawn"_msg,
                                 formatNumber(out.nearW)));
    if (out.behindEye > 0)
        diagnostics.note(
            where, counted(out.behindEye,
                           "plain divide: %1 triangle lies wholly behind the eye (w < 0), "
                           "drawn without clipping as the point reflection through the eye"_msg,
                           "plain divide: %1 triangles lie wholly behind the eye (w < 0), "
                           "drawn without clipping as the point reflection through the eye"_msg));
    warnDistorted(out, where, diagnostics);
}

}  // namespace rl
