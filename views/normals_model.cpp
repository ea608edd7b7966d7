#include "normals_model.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <limits>

#include "pipeline/analysis/painter.h"
#include "pipeline/render/animation.h"
#include "pipeline/render/output_image.h"
#include "pipeline/scene/mesh_topology.h"
#include "pipeline/stages/shading.h"

namespace rasterlab {

namespace {

// Hairs drawn at most, of each kind: more would hide the mesh they stand on.
constexpr std::size_t kMostHairs = 600;
// Projected triangles drawn at most in the wireframe.
constexpr std::size_t kMostWireTriangles = 200000;

// A normal's hair: from its foot in view space, `length` long, both ends carried to image
// pixels by the draw's projection; none for a zero normal or an end at or behind the near
// plane (or not finite).
std::optional<QLineF> hairLine(const rl::Scene& scene, const rl::Projection& projection,
                               const rl::DrawProjection& proj, double length, const rl::dvec3& foot,
                               const rl::vec3& n) {
    if (n == rl::vec3(0.0f)) return std::nullopt;
    const auto toScreen = [&](const rl::dvec3& p) -> std::optional<QPointF> {
        const rl::dvec4 c = proj.clipFromView * rl::dvec4(p, 1.0);
        if (!(c.w > projection.nearW) || !rl::isFinite(rl::dvec3(c))) return std::nullopt;
        const rl::dvec2 s = rl::screenFromNdc(rl::dvec2(c) / c.w, scene.width, scene.height,
                                              scene.conventions);
        return QPointF(s.x, s.y);
    };
    const auto a = toScreen(foot);
    const auto b = toScreen(foot + length * rl::dvec3(n));
    if (!a || !b) return std::nullopt;
    return QLineF(*a, *b);
}

// The hairs' length L for a draw: a fraction of the mesh's size in view space, larger for
// meshes of few triangles, and at most half the nearest vertex's depth, so that no hair
// reaches the camera's plane. With the mesh's size.
struct HairLength {
    double length = 0.0, size = 0.0;
};
HairLength hairLength(const rl::Projection& projection, const rl::DrawProjection& proj,
                      const rl::Mesh& mesh) {
    rl::dvec3 low(std::numeric_limits<double>::max()), high(-low);
    double nearest = std::numeric_limits<double>::max();
    for (std::uint32_t v = 0; v < proj.originalVertexCount; ++v) {
        const rl::dvec3 p = rl::cartesian(proj.pView[v]);
        low = glm::min(low, p);
        high = glm::max(high, p);
        if (proj.pClip[v].w > projection.nearW) nearest = std::min(nearest, proj.pClip[v].w);
    }
    const double size = proj.originalVertexCount > 0 ? glm::length(high - low) : 0.0;
    const double fraction = std::clamp(
        0.3 / std::sqrt(double(std::max<std::size_t>(1, mesh.triangles.size()))), 0.04, 0.3);
    const double length = std::min(size * fraction, 0.5 * nearest);
    return {length, size};
}

}  // namespace

// ---------------------------------------------------------------------------------------

std::vector<std::uint8_t> backFaces(std::span<const rl::dvec4> pView, const rl::Mesh& mesh) {
    std::vector<std::uint8_t> out(mesh.triangles.size(), 0);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        if (tri[0] >= pView.size() || tri[1] >= pView.size() || tri[2] >= pView.size()) continue;
        const rl::dvec3 p1 = rl::cartesian(pView[tri[0]]);
        const rl::dvec3 n =
            glm::cross(rl::cartesian(pView[tri[1]]) - p1, rl::cartesian(pView[tri[2]]) - p1);
        out[t] = glm::dot(n, p1) > 0.0 ? 1 : 0;
    }
    return out;
}

WindingReport inconsistentWinding(const rl::Mesh& mesh) {
    WindingReport report;
    report.inconsistent.assign(mesh.triangles.size(), 0);
    // Every directed edge a -> b with its triangle, sorted: equal neighbours run it the same way.
    struct Edge {
        std::uint32_t a, b, triangle;
    };
    std::vector<Edge> edges;
    edges.reserve(mesh.triangles.size() * 3);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = tri[k], b = tri[(k + 1) % 3];
            if (a != b) edges.push_back({a, b, static_cast<std::uint32_t>(t)});
        }
    }
    std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
        return x.a != y.a ? x.a < y.a : (x.b != y.b ? x.b < y.b : x.triangle < y.triangle);
    });
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i + 1;
        while (j < edges.size() && edges[j].a == edges[i].a && edges[j].b == edges[i].b) ++j;
        if (j - i > 1) {
            ++report.edges;
            for (std::size_t k = i; k < j; ++k) report.inconsistent[edges[k].triangle] = 1;
        }
        i = j;
    }
    report.triangles = static_cast<std::size_t>(
        std::count(report.inconsistent.begin(), report.inconsistent.end(), std::uint8_t{1}));
    return report;
}

QRgb normalColour(const rl::vec3& n) {
    const std::array<std::uint8_t, 4> c = rl::normalBytes(n);
    return qRgb(c[0], c[1], c[2]);
}

// ---------------------------------------------------------------------------------------

PixelNormals::PixelNormals(std::shared_ptr<const rl::FrameTrace> frame)
    : m_frame(std::move(frame)) {
    if (!m_frame || !m_frame->projection) return;
    const bool perspective =
        m_frame->scene->rules.interpolation == rl::RasterRules::Interpolation::PerspectiveCorrect;
    const bool withNormals = m_frame->normals && !m_frame->normals->skipped;
    m_draws.resize(m_frame->projection->draws.size());
    for (std::size_t d = 0; d < m_draws.size(); ++d) {
        const rl::DrawProjection& proj = m_frame->projection->draws[d];
        DrawData& out = m_draws[d];
        out.pView.reserve(proj.pView.size());
        for (const rl::dvec4& p : proj.pView) out.pView.emplace_back(rl::cartesian(p));
        if (withNormals && d < m_frame->normals->draws.size())
            out.nView = m_frame->normals->draws[d].vertex;
        out.nView.resize(proj.originalVertexCount, rl::vec3(0.0f));
        // Made vertices: mixed along their edge, as shading extends the normals.
        rl::extendByClipping(out.nView, proj);
        if (perspective) {
            out.invW.reserve(proj.pClip.size());
            for (const rl::dvec4& p : proj.pClip) out.invW.push_back(1.0 / p.w);
        }
    }
}

PixelNormal PixelNormals::at(const rl::DepthTest& buffers, int x, int y) const {
    PixelNormal out;
    if (!m_frame || !buffers.triangle.contains(x, y)) return out;
    const std::uint32_t t = buffers.triangle.at(x, y);
    if (t == rl::kNoTriangle || t >= m_frame->projection->triangles.size()) return out;
    out.covered = true;
    out.triangle = t;
    const rl::ScreenTriangle& tri = m_frame->projection->triangles[t];
    const rl::Scene& scene = *m_frame->scene;
    const rl::Draw& draw = scene.draws[tri.draw];
    const DrawData& dv = m_draws[tri.draw];
    const bool skipped = !m_frame->normals || m_frame->normals->skipped;
    if (skipped || draw.lighting == rl::LightingModel::Unlit) {
        out.none = skipped
                       ? QString::fromStdString(m_frame->normals ? m_frame->normals->skipReason
                                                                 : std::string())
                       : QCoreApplication::translate("rasterlab::NormalsView",
                                                     "the draw is unlit: shading reads no normal");
        return out;
    }
    const rl::vec3 triangleNormal = m_frame->normals->draws[tri.draw].triangle[tri.source];
    rl::vec3 p;
    if (rl::litPerTriangle(draw.shading)) {
        // One normal per triangle, turned toward the viewer at the whole triangle's centre.
        out.flat = true;
        out.weights = rl::vec3(1.0f / 3.0f);
        const float third = 1.0f / 3.0f;
        p = rl::interpolate(dv.pView, draw.mesh->triangles[tri.source], third, third);
        out.interpolated = triangleNormal;
    } else {
        float beta = buffers.barycentric.at(x, y).x;
        float gamma = buffers.barycentric.at(x, y).y;
        if (!dv.invW.empty())  // perspective-correct rules
            rl::perspectiveWeights(beta, gamma, dv.invW[tri.v[0]], dv.invW[tri.v[1]],
                                   dv.invW[tri.v[2]]);
        out.weights = rl::vec3(1.0f - beta - gamma, beta, gamma);
        p = rl::interpolate(dv.pView, tri.v, beta, gamma);
        out.flat = draw.flatNormals;
        out.interpolated =
            draw.flatNormals ? triangleNormal : rl::interpolate(dv.nView, tri.v, beta, gamma);
    }
    if (!(glm::length(out.interpolated) > 0.0f)) {
        out.none = QCoreApplication::translate("rasterlab::NormalsView",
                                               "the interpolated normal is zero");
        return out;
    }
    out.n = rl::orientedNormal(out.interpolated, p, scene.conventions.flipNormalsTowardViewer,
                               &out.flipped);
    return out;
}

QImage PixelNormals::image(const rl::DepthTest& buffers) const {
    const int width = buffers.triangle.width(), height = buffers.triangle.height();
    QImage image(width, height, QImage::Format_RGB32);
    for (int y = 0; y < height; ++y) {
        auto* line = reinterpret_cast<QRgb*>(image.scanLine(y));
        for (int x = 0; x < width; ++x) {
            const PixelNormal n = at(buffers, x, y);
            line[x] = n.covered ? normalColour(n.n) : qRgb(0, 0, 0);
        }
    }
    return image;
}

// ---------------------------------------------------------------------------------------

void NormalsModel::rebuild(const std::shared_ptr<const rl::FrameTrace>& frame, bool onlyVisible,
                           bool wrongNormals) {
    m_picture = NormalsPicture{};
    if (!frame || !frame->projection) return;
    const rl::Scene& scene = *frame->scene;
    m_picture.screen = QSizeF(scene.width, scene.height);
    m_picture.normalsSkipped = !frame->normals || frame->normals->skipped;
    const PerDraw backFace = addFaces(*frame);
    addWireframe(*frame->projection, backFace);
    const PerDraw visible = markVisible(*frame, backFace);
    // The hairs: the view-space normal from its foot, both ends projected by the draw's matrix,
    // on the triangles drawn (those holding a pixel at the end, when asked) and their corners.
    if (!m_picture.normalsSkipped)
        addHairs(*frame, visible, onlyVisible, wrongNormals && frame->view);
}

// Per draw: back faces and winding of every mesh triangle. What depends on the mesh alone
// is kept from frame to frame while the mesh is the same (moving the camera keeps it).
NormalsModel::PerDraw NormalsModel::addFaces(const rl::FrameTrace& frame) {
    const rl::Scene& scene = *frame.scene;
    const rl::Projection& projection = *frame.projection;
    m_picture.viewWinding.assign(scene.draws.size(), 0);
    PerDraw backFace(scene.draws.size());
    std::vector<MeshFacts> facts(scene.draws.size());
    for (std::size_t d = 0; d < scene.draws.size(); ++d) {
        const rl::Draw& draw = scene.draws[d];
        const rl::DrawProjection& proj = projection.draws[d];
        if (!draw.mesh) continue;
        const auto known = std::find_if(m_meshFacts.begin(), m_meshFacts.end(),
                                        [&](const MeshFacts& f) { return f.mesh == draw.mesh; });
        facts[d] = known != m_meshFacts.end()
                       ? *known
                       : MeshFacts{draw.mesh, inconsistentWinding(*draw.mesh),
                                   rl::closedSurfaceWinding(*draw.mesh)};
        backFace[d] = backFaces(proj.pView, *draw.mesh);
        const auto& back = backFace[d];
        m_picture.meshTriangles += draw.mesh->triangles.size();
        m_picture.backFaces +=
            static_cast<std::size_t>(std::count(back.begin(), back.end(), std::uint8_t{1}));
        m_picture.inconsistentEdges += facts[d].winding.edges;
        m_picture.inconsistentTriangles += facts[d].winding.triangles;
        // A closed surface: do its normals point out of it in view space? The file's winding
        // (right-hand rule, outward +1) turned over by a mirroring view matrix (the course's
        // [U; V; N] always mirrors: det = -1).
        const double det = glm::determinant(rl::dmat3(frame.view->viewFromModel[d]));
        m_picture.viewWinding[d] = facts[d].closed * (det > 0.0 ? 1 : (det < 0.0 ? -1 : 0));
        // Triangles the projection left out as hidden back faces (its own test, which knows
        // the surface's winding), counted where this view's test puts them.
        for (std::size_t t = 0; t < proj.fate.size(); ++t) {
            if (proj.fate[t] != rl::TriangleFate::BackFace) continue;
            if (back[t])
                ++m_picture.culledBack;
            else
                ++m_picture.culledFront;
        }
    }
    m_meshFacts = std::move(facts);
    return backFace;
}

// The wireframe: the projected triangles at their snapped screen positions.
void NormalsModel::addWireframe(const rl::Projection& projection, const PerDraw& backFace) {
    const std::size_t count = projection.triangles.size();
    m_picture.wireStep = static_cast<int>((count + kMostWireTriangles - 1) / kMostWireTriangles);
    m_picture.wireStep = std::max(1, m_picture.wireStep);
    m_picture.triangles.reserve(count / static_cast<std::size_t>(m_picture.wireStep) + 1);
    QPointF boxLow(std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
    QPointF boxHigh(-boxLow);
    for (std::size_t i = 0; i < count; i += static_cast<std::size_t>(m_picture.wireStep)) {
        const rl::ScreenTriangle& tri = projection.triangles[i];
        const rl::DrawProjection& proj = projection.draws[tri.draw];
        NormalsPicture::Triangle t;
        for (int k = 0; k < 3; ++k)
            t.p[static_cast<std::size_t>(k)] =
                QPointF(proj.pScreen[tri.v[static_cast<std::size_t>(k)]].x,
                        proj.pScreen[tri.v[static_cast<std::size_t>(k)]].y);
        if (m_meshFacts[tri.draw].winding.inconsistent[tri.source])
            t.face = NormalsPicture::Face::Inconsistent;
        else if (backFace[tri.draw][tri.source])
            t.face = NormalsPicture::Face::Back;
        m_picture.triangles.push_back(t);
        for (const QPointF& q : t.p) {
            boxLow = QPointF(std::min(boxLow.x(), q.x()), std::min(boxLow.y(), q.y()));
            boxHigh = QPointF(std::max(boxHigh.x(), q.x()), std::max(boxHigh.y(), q.y()));
        }
    }
    // The drawing opens on the mesh: its box with a margin, within the image and a border.
    const QRectF image(QPointF(0, 0), m_picture.screen);
    if (!m_picture.triangles.empty()) {
        const QRectF box(boxLow, boxHigh);
        const double margin = 0.08 * std::max(box.width(), box.height()) + 2.0;
        m_picture.focus = box.adjusted(-margin, -margin, margin, margin)
                              .intersected(image.adjusted(-4.0, -4.0, 4.0, 4.0));
    }
    if (m_picture.focus.isEmpty()) m_picture.focus = image;
}

// Which mesh triangles hold a pixel at the end of the frame, and how many pixels show a
// back face there.
NormalsModel::PerDraw NormalsModel::markVisible(const rl::FrameTrace& frame,
                                                const PerDraw& backFace) {
    const rl::Scene& scene = *frame.scene;
    const rl::Projection& projection = *frame.projection;
    const std::size_t count = projection.triangles.size();
    PerDraw visible(scene.draws.size());
    for (std::size_t d = 0; d < scene.draws.size(); ++d)
        if (scene.draws[d].mesh) visible[d].assign(scene.draws[d].mesh->triangles.size(), 0);
    if (frame.depth) {
        const auto& ids = frame.depth->triangle;
        for (int y = 0; y < ids.height(); ++y) {
            const std::uint32_t* row = ids.row(y);
            for (int x = 0; x < ids.width(); ++x) {
                if (row[x] == rl::kNoTriangle || row[x] >= count) continue;
                const rl::ScreenTriangle& tri = projection.triangles[row[x]];
                visible[tri.draw][tri.source] = 1;
                ++m_picture.coveredPixels;
                m_picture.backFacePixels += backFace[tri.draw][tri.source];
            }
        }
    }
    return visible;
}

// The triangles and vertices that carry a hair, and one in how many of each is drawn.
void NormalsModel::addHairs(const rl::FrameTrace& frame, const PerDraw& visible, bool onlyVisible,
                            bool wrong) {
    const rl::Scene& scene = *frame.scene;
    const rl::Projection& projection = *frame.projection;
    PerDraw hairTriangles(scene.draws.size());
    PerDraw hairVertices(scene.draws.size());
    std::size_t vertexCount = 0;
    for (std::size_t d = 0; d < scene.draws.size(); ++d) {
        const rl::Draw& draw = scene.draws[d];
        if (!draw.mesh) continue;
        const rl::DrawProjection& proj = projection.draws[d];
        hairTriangles[d].assign(draw.mesh->triangles.size(), 0);
        hairVertices[d].assign(proj.originalVertexCount, 0);
        for (std::size_t t = 0; t < draw.mesh->triangles.size(); ++t) {
            const rl::TriangleFate fate = proj.fate[t];
            if (fate != rl::TriangleFate::Inside && fate != rl::TriangleFate::Clipped) continue;
            if (onlyVisible && !visible[d][t]) continue;
            hairTriangles[d][t] = 1;
            ++m_picture.hairTriangles;
            for (std::uint32_t v : draw.mesh->triangles[t])
                if (v < hairVertices[d].size()) hairVertices[d][v] = 1;
        }
        vertexCount += static_cast<std::size_t>(
            std::count(hairVertices[d].begin(), hairVertices[d].end(), std::uint8_t{1}));
    }
    m_picture.triangleHairStep =
        std::max<int>(1, static_cast<int>((m_picture.hairTriangles + kMostHairs - 1) / kMostHairs));
    m_picture.vertexHairStep =
        std::max<int>(1, static_cast<int>((vertexCount + kMostHairs - 1) / kMostHairs));
    std::size_t triangleIndex = 0, vertexIndex = 0;  // counted over every draw
    m_picture.drawHairLength.assign(scene.draws.size(), 0.0);
    for (std::size_t d = 0; d < scene.draws.size(); ++d)
        if (scene.draws[d].mesh)
            addDrawHairs(frame, d, hairTriangles, hairVertices, wrong, triangleIndex, vertexIndex);
}

// One draw's hairs, of the triangles and vertices chosen: one in triangleHairStep (and
// vertexHairStep), counted over every draw by triangleIndex (and vertexIndex).
void NormalsModel::addDrawHairs(const rl::FrameTrace& frame, std::size_t d,
                                const PerDraw& hairTriangles, const PerDraw& hairVertices,
                                bool wrong, std::size_t& triangleIndex, std::size_t& vertexIndex) {
    const rl::Scene& scene = *frame.scene;
    const rl::Projection& projection = *frame.projection;
    const rl::Draw& draw = scene.draws[d];
    const rl::DrawProjection& proj = projection.draws[d];
    const rl::DrawNormals& normals = frame.normals->draws[d];
    const auto [length, size] = hairLength(projection, proj, *draw.mesh);
    m_picture.drawHairLength[d] = length;
    if (m_picture.hairLength == 0.0) {
        m_picture.hairLength = length;
        m_picture.hairFraction = size > 0.0 ? length / size : 0.0;
    }
    const auto hair = [&](const rl::dvec3& foot, const rl::vec3& n) {
        return hairLine(scene, projection, proj, length, foot, n);
    };
    for (std::size_t t = 0; t < draw.mesh->triangles.size(); ++t) {
        if (!hairTriangles[d][t]) continue;
        if (triangleIndex++ % static_cast<std::size_t>(m_picture.triangleHairStep) != 0) continue;
        const rl::dvec3 foot = rl::viewBarycentre(proj, *draw.mesh, static_cast<std::uint32_t>(t));
        if (const auto line = hair(foot, normals.triangle[t]))
            m_picture.triangleHairs.push_back(*line);
        if (!wrong) continue;
        const rl::CarriedNormal carried =
            rl::carriedTriangleNormal(frame.view->viewFromModel[d], *draw.mesh, t);
        if (const auto line = hair(foot, rl::vec3(carried.wrong)))
            m_picture.wrongHairs.push_back(*line);
    }
    for (std::uint32_t v = 0; v < proj.originalVertexCount; ++v) {
        if (!hairVertices[d][v]) continue;
        if (vertexIndex++ % static_cast<std::size_t>(m_picture.vertexHairStep) != 0) continue;
        if (const auto line = hair(rl::cartesian(proj.pView[v]), normals.vertex[v]))
            m_picture.vertexHairs.push_back(*line);
    }
}

void NormalsModel::select(const std::shared_ptr<const rl::FrameTrace>& frame,
                          std::optional<std::uint32_t> t, bool wrongNormals) {
    m_picture.selected.reset();
    m_picture.selectedTriangleHairs.clear();
    m_picture.selectedVertexHairs.clear();
    m_picture.selectedWrongHairs.clear();
    if (frame && frame->projection && t && *t < frame->projection->triangles.size()) {
        const rl::Projection& projection = *frame->projection;
        const rl::ScreenTriangle& tri = projection.triangles[*t];
        const rl::DrawProjection& proj = projection.draws[tri.draw];
        std::array<QPointF, 3> p;
        for (std::size_t k = 0; k < 3; ++k)
            p[k] = QPointF(proj.pScreen[tri.v[k]].x, proj.pScreen[tri.v[k]].y);
        m_picture.selected = p;
        if (!m_picture.normalsSkipped) {
            const rl::Scene& scene = *frame->scene;
            const rl::DrawNormals& normals = frame->normals->draws[tri.draw];
            const rl::Mesh& mesh = *scene.draws[tri.draw].mesh;
            const auto& c = mesh.triangles[tri.source];
            const double length = tri.draw < m_picture.drawHairLength.size()
                                      ? m_picture.drawHairLength[tri.draw]
                                      : 0.0;
            const auto add = [&](std::vector<QLineF>& to, const rl::dvec3& foot,
                                 const rl::vec3& n) {
                if (const auto line = hairLine(scene, projection, proj, length, foot, n))
                    to.push_back(*line);
            };
            const rl::dvec3 foot = rl::viewBarycentre(proj, mesh, tri.source);
            add(m_picture.selectedTriangleHairs, foot, normals.triangle[tri.source]);
            for (std::uint32_t v : c)
                add(m_picture.selectedVertexHairs, rl::cartesian(proj.pView[v]), normals.vertex[v]);
            if (wrongNormals && frame->view)
                add(m_picture.selectedWrongHairs, foot,
                    rl::vec3(rl::carriedTriangleNormal(frame->view->viewFromModel[tri.draw], mesh,
                                                       tri.source)
                                 .wrong));
        }
    }
}

bool NormalsModel::inconsistent(std::uint32_t draw, std::uint32_t triangle) const {
    return draw < m_meshFacts.size() && m_meshFacts[draw].winding.inconsistent.size() > triangle &&
           m_meshFacts[draw].winding.inconsistent[triangle];
}

}  // namespace rasterlab
