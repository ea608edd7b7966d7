#include "normals_view.h"

#include <QApplication>
#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QSplitter>
#include <QTabWidget>
#include <QTextBrowser>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "animation.h"
#include "frame_image_view.h"
#include "inspection.h"
#include "mesh_topology.h"
#include "number_text.h"
#include "output_image.h"
#include "painter.h"
#include "shading.h"

namespace rasterlab {

namespace {

// Hairs drawn at most, of each kind: more would hide the mesh they stand on.
constexpr std::size_t kMostHairs = 600;
// Projected triangles drawn at most in the wireframe.
constexpr std::size_t kMostWireTriangles = 200000;

const QColor kFrontColour(200, 204, 214);
const QColor kBackColour(235, 64, 52);
const QColor kInconsistentColour(235, 60, 235);
const QColor kSelectedColour(255, 214, 10);
const QColor kTriangleHairColour(255, 160, 40);
const QColor kVertexHairColour(70, 200, 255);
const QColor kWrongHairColour(150, 255, 80);

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
                                              scene.conventions.ndcYUp);
        return QPointF(s.x, s.y);
    };
    const auto a = toScreen(foot);
    const auto b = toScreen(foot + length * rl::dvec3(n));
    if (!a || !b) return std::nullopt;
    return QLineF(*a, *b);
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
        out.none = skipped ? QString::fromStdString(m_frame->normals ? m_frame->normals->skipReason
                                                                     : std::string())
                           : NormalsView::tr("the draw is unlit: shading reads no normal");
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
        out.none = NormalsView::tr("the interpolated normal is zero");
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

NormalsCanvas::NormalsCanvas(QWidget* parent) : QWidget(parent) {
    setMouseTracking(false);
    setMinimumSize(160, 120);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void NormalsCanvas::setPicture(const NormalsPicture* picture) {
    m_picture = picture;
    const QRectF focus = m_picture ? m_picture->focus : QRectF();
    if (focus != m_view.content()) {
        m_view.setContent(focus);
        m_view.fit();
    }
    redraw();
}

void NormalsCanvas::redraw() {
    m_cacheValid = false;
    update();
}

void NormalsCanvas::setLineWidth(double width) {
    m_lineWidth = width;
    redraw();
}

void NormalsCanvas::setHairs(bool triangles, bool vertices) {
    m_triangleHairs = triangles;
    m_vertexHairs = vertices;
    redraw();
}

void NormalsCanvas::setWrongHairs(bool on) {
    m_wrongHairs = on;
    redraw();
}

void NormalsCanvas::resizeEvent(QResizeEvent*) {
    m_cacheValid = false;
}

void NormalsCanvas::paintCache() {
    const qreal dpr = devicePixelRatioF();
    m_cache = QImage(size() * dpr, QImage::Format_ARGB32_Premultiplied);
    m_cache.setDevicePixelRatio(dpr);
    m_cache.fill(QColor(40, 40, 44));
    m_cacheValid = true;
    if (!m_picture) return;
    QPainter painter(&m_cache);
    const double s = m_view.scale();
    const QPointF o = m_view.offset();
    painter.fillRect(QRectF(o, m_picture->screen * s), QColor(22, 22, 26));
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setTransform(QTransform(s, 0, 0, s, o.x(), o.y()));
    const auto pen = [&](const QColor& colour, double width) {
        QPen p(colour, width);
        p.setCosmetic(true);  // widths in widget pixels, whatever the zoom
        p.setCapStyle(Qt::RoundCap);
        return p;
    };
    const double thin = std::max(0.6, m_lineWidth * 0.45);

    // Back faces first, under the front faces; then the triangles wound the wrong way, filled.
    std::vector<QLineF> lines;
    const auto edges = [&](NormalsPicture::Face face) {
        lines.clear();
        for (const auto& t : m_picture->triangles) {
            if (t.face != face) continue;
            lines.emplace_back(t.p[0], t.p[1]);
            lines.emplace_back(t.p[1], t.p[2]);
            lines.emplace_back(t.p[2], t.p[0]);
        }
        return lines.size();
    };
    QColor backFill = kBackColour;
    backFill.setAlpha(40);
    painter.setPen(Qt::NoPen);
    painter.setBrush(backFill);
    for (const auto& t : m_picture->triangles)
        if (t.face == NormalsPicture::Face::Back) painter.drawPolygon(t.p.data(), 3);
    if (edges(NormalsPicture::Face::Back) > 0) {
        QColor c = kBackColour;
        c.setAlpha(100);
        painter.setPen(pen(c, thin));
        painter.drawLines(lines.data(), static_cast<int>(lines.size()));
    }
    if (edges(NormalsPicture::Face::Front) > 0) {
        QColor c = kFrontColour;
        c.setAlpha(130);
        painter.setPen(pen(c, thin));
        painter.drawLines(lines.data(), static_cast<int>(lines.size()));
    }
    QColor inconsistentFill = kInconsistentColour;
    inconsistentFill.setAlpha(110);
    painter.setPen(pen(kInconsistentColour, thin));
    painter.setBrush(inconsistentFill);
    for (const auto& t : m_picture->triangles)
        if (t.face == NormalsPicture::Face::Inconsistent) painter.drawPolygon(t.p.data(), 3);

    const double hair = std::max(0.8, m_lineWidth * 0.6);
    if (m_vertexHairs && !m_picture->vertexHairs.empty()) {
        painter.setPen(pen(kVertexHairColour, hair));
        painter.drawLines(m_picture->vertexHairs.data(),
                          static_cast<int>(m_picture->vertexHairs.size()));
    }
    if (m_triangleHairs && !m_picture->triangleHairs.empty()) {
        painter.setPen(pen(kTriangleHairColour, hair));
        painter.drawLines(m_picture->triangleHairs.data(),
                          static_cast<int>(m_picture->triangleHairs.size()));
    }
    if (m_wrongHairs && !m_picture->wrongHairs.empty()) {
        painter.setPen(pen(kWrongHairColour, hair));
        painter.drawLines(m_picture->wrongHairs.data(),
                          static_cast<int>(m_picture->wrongHairs.size()));
    }
}

void NormalsCanvas::paintEvent(QPaintEvent*) {
    if (!m_cacheValid || m_cache.size() != size() * devicePixelRatioF()) paintCache();
    QPainter painter(this);
    painter.drawImage(QPoint(0, 0), m_cache);
    if (!m_picture || !m_picture->selected) return;
    // The selected triangle and its hairs, over everything (not cached: it changes alone).
    const double s = m_view.scale();
    const QPointF o = m_view.offset();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setTransform(QTransform(s, 0, 0, s, o.x(), o.y()));
    QPen outline(kSelectedColour, m_lineWidth);
    outline.setCosmetic(true);
    outline.setJoinStyle(Qt::RoundJoin);
    QColor fill = kSelectedColour;
    fill.setAlpha(70);
    painter.setPen(outline);
    painter.setBrush(fill);
    painter.drawPolygon(m_picture->selected->data(), 3);
    QPen hairPen(kVertexHairColour, m_lineWidth * 1.2);
    hairPen.setCosmetic(true);
    hairPen.setCapStyle(Qt::RoundCap);
    painter.setPen(hairPen);
    painter.drawLines(m_picture->selectedVertexHairs.data(),
                      static_cast<int>(m_picture->selectedVertexHairs.size()));
    hairPen.setColor(kTriangleHairColour);
    painter.setPen(hairPen);
    painter.drawLines(m_picture->selectedTriangleHairs.data(),
                      static_cast<int>(m_picture->selectedTriangleHairs.size()));
    if (m_wrongHairs) {
        hairPen.setColor(kWrongHairColour);
        painter.setPen(hairPen);
        painter.drawLines(m_picture->selectedWrongHairs.data(),
                          static_cast<int>(m_picture->selectedWrongHairs.size()));
    }
}

void NormalsCanvas::wheelEvent(QWheelEvent* event) {
    if (!m_picture) return;
    m_view.zoomAround(event->position(), std::pow(1.25, event->angleDelta().y() / 120.0), 0.25,
                      64.0);
    redraw();
}

void NormalsCanvas::mousePressEvent(QMouseEvent* event) {
    m_view.press(event->position());
}

void NormalsCanvas::mouseMoveEvent(QMouseEvent* event) {
    if ((event->buttons() & Qt::LeftButton) && m_view.drag(event->position())) redraw();
}

void NormalsCanvas::mouseReleaseEvent(QMouseEvent* event) {
    if (m_view.dragging() || !m_picture || event->button() != Qt::LeftButton) return;
    const QPointF p = m_view.fromWidget(event->position());
    const QPoint pixel(static_cast<int>(std::floor(p.x())), static_cast<int>(std::floor(p.y())));
    if (pixel.x() >= 0 && pixel.y() >= 0 && pixel.x() < m_picture->screen.width() &&
        pixel.y() < m_picture->screen.height())
        emit pixelPicked(pixel);
}

void NormalsCanvas::mouseDoubleClickEvent(QMouseEvent*) {
    m_view.fit();
    redraw();
}

// ---------------------------------------------------------------------------------------

NormalsView::NormalsView(Inspection* inspection, QWidget* parent)
    : QWidget(parent), m_inspection(inspection) {
    setObjectName(QStringLiteral("normalsView"));
    m_canvas = new NormalsCanvas(this);
    m_canvas->setObjectName(QStringLiteral("normalsCanvas"));
    m_canvas->setPicture(&m_picture);
    m_mapView = new FrameImageView(this);
    m_mapView->setObjectName(QStringLiteral("normalMapImage"));
    m_triangleHairs = new QCheckBox(tr("Triangle normals"), this);
    m_triangleHairs->setObjectName(QStringLiteral("normalsTriangleHairs"));
    m_triangleHairs->setChecked(true);
    m_vertexHairs = new QCheckBox(tr("Vertex normals"), this);
    m_vertexHairs->setObjectName(QStringLiteral("normalsVertexHairs"));
    m_vertexHairs->setChecked(false);
    m_onlyVisible = new QCheckBox(tr("Only on triangles that are seen"), this);
    m_onlyVisible->setObjectName(QStringLiteral("normalsOnlyVisible"));
    m_onlyVisible->setToolTip(
        tr("Hairs only on the triangles that hold a pixel at the end of the frame, and on "
           "their corners"));
    m_onlyVisible->setChecked(true);
    m_wrong = new QCheckBox(tr("Normals by M (wrong)"), this);
    m_wrong->setObjectName(QStringLiteral("normalsWrong"));
    m_wrong->setToolTip(
        tr("Beside each triangle normal, the model normal carried by viewFromModel itself "
           "instead of its inverse transpose: it leaves the surface under a non-uniform scale "
           "(set one in the Animation panel)"));
    m_legend = new QLabel(this);
    m_legend->setObjectName(QStringLiteral("normalsLegend"));
    m_legend->setWordWrap(true);
    m_legend->setTextFormat(Qt::RichText);
    m_pixelValue = new QLabel(this);
    m_pixelValue->setObjectName(QStringLiteral("normalMapValue"));
    m_pixelValue->setWordWrap(true);
    m_explanation = new QTextBrowser(this);
    m_explanation->setObjectName(QStringLiteral("normalsExplanation"));

    auto* meshPage = new QWidget(this);
    auto* toggles = new QHBoxLayout;
    toggles->addWidget(m_triangleHairs);
    toggles->addWidget(m_vertexHairs);
    toggles->addWidget(m_onlyVisible);
    toggles->addStretch(1);
    // On a line of its own: the dock keeps the width it had without it.
    auto* wrongLine = new QHBoxLayout;
    wrongLine->addWidget(m_wrong);
    wrongLine->addStretch(1);
    auto* meshLayout = new QVBoxLayout(meshPage);
    meshLayout->setContentsMargins(0, 0, 0, 0);
    meshLayout->addLayout(toggles);
    meshLayout->addLayout(wrongLine);
    meshLayout->addWidget(m_canvas, 1);
    auto* mapPage = new QWidget(this);
    auto* mapLayout = new QVBoxLayout(mapPage);
    mapLayout->setContentsMargins(0, 0, 0, 0);
    auto* caption = new QLabel(
        tr("Per pixel at the stepping cursor, the unit normal shading uses there: the vertex "
           "normals interpolated with the pixel's barycentrics and normalised (the triangle's "
           "normal for flat shading), turned toward the viewer as the course does before "
           "lighting; shown as RGB = (n + 1) / 2. Red grows to the right, green upward, blue "
           "away from the camera: turned normals face the camera, so blue is mostly below "
           "128. Black: no triangle."),
        this);
    caption->setObjectName(QStringLiteral("normalMapCaption"));
    caption->setWordWrap(true);
    mapLayout->addWidget(m_mapView, 1);
    mapLayout->addWidget(m_pixelValue);
    mapLayout->addWidget(caption);
    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName(QStringLiteral("normalsTabs"));
    m_tabs->addTab(meshPage, tr("Mesh and normals"));
    m_tabs->addTab(mapPage, tr("Normal map"));
    // The legend below the tabs, where it always has the height its lines need.
    auto* top = new QWidget(this);
    auto* topLayout = new QVBoxLayout(top);
    topLayout->setContentsMargins(0, 0, 0, 0);
    topLayout->addWidget(m_tabs, 1);
    topLayout->addWidget(m_legend);
    m_legend->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Minimum);
    auto* splitter = new QSplitter(Qt::Vertical, this);
    splitter->addWidget(top);
    splitter->addWidget(m_explanation);
    splitter->setStretchFactor(0, 2);
    splitter->setStretchFactor(1, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(splitter);

    const auto hairs = [this] {
        m_canvas->setHairs(m_triangleHairs->isChecked(), m_vertexHairs->isChecked());
    };
    connect(m_triangleHairs, &QCheckBox::toggled, this, hairs);
    connect(m_vertexHairs, &QCheckBox::toggled, this, hairs);
    connect(m_onlyVisible, &QCheckBox::toggled, this, [this] {
        m_geometryDirty = true;
        if (isVisible()) refreshGeometry();
    });
    connect(m_wrong, &QCheckBox::toggled, this, [this](bool on) {
        m_canvas->setWrongHairs(on);
        m_geometryDirty = true;
        if (isVisible()) refreshGeometry();
    });
    m_canvas->setHairs(true, false);
    connect(m_tabs, &QTabWidget::currentChanged, this, [this] {
        m_legend->setVisible(!mapShown());  // it describes the mesh tab
        if (mapShown() && m_mapDirty) refreshMap();
    });
    connect(m_canvas, &NormalsCanvas::pixelPicked, m_inspection, &Inspection::pickPixel);
    connect(m_mapView, &FrameImageView::pixelPicked, m_inspection, &Inspection::pickPixel);
    connect(m_mapView, &FrameImageView::pixelHovered, this, &NormalsView::showPixelValue);

    connect(m_inspection, &Inspection::frameChanged, this, [this] {
        m_geometryDirty = m_mapDirty = true;
        m_pixelNormals.reset();
        if (isVisible()) refreshGeometry();
    });
    connect(m_inspection, &Inspection::cursorChanged, this, [this] {
        m_mapDirty = true;
        if (!isVisible()) return;
        if (mapShown()) refreshMap();
        refreshExplanation();
    });
    // A picked pixel selects its triangle: the explanation's pixel follows from here too.
    connect(m_inspection, &Inspection::selectionChanged, this, [this] {
        if (isVisible() && !m_geometryDirty) refreshSelection();
    });
    connect(m_inspection, &Inspection::presentationChanged, this, [this](bool on) {
        m_canvas->setLineWidth(m_inspection->lineWidth());
        QFont f = QApplication::font(this);
        if (on) f.setPointSizeF(f.pointSizeF() * 1.4);
        m_explanation->setFont(f);
        m_legend->setFont(f);
    });
    m_canvas->setLineWidth(m_inspection->lineWidth());
}

void NormalsView::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    // The selection, the pixel picked and the cursor may have moved while hidden.
    if (m_geometryDirty)
        refreshGeometry();
    else
        refreshSelection();
    if (mapShown() && m_mapDirty) refreshMap();
}

bool NormalsView::mapShown() const {
    return m_tabs->currentIndex() == 1;
}

void NormalsView::setTriangleHairs(bool on) {
    m_triangleHairs->setChecked(on);
}

void NormalsView::setVertexHairs(bool on) {
    m_vertexHairs->setChecked(on);
}

void NormalsView::setOnlyVisibleHairs(bool on) {
    m_onlyVisible->setChecked(on);
}

void NormalsView::setWrongNormals(bool on) {
    m_wrong->setChecked(on);
}

bool NormalsView::wrongNormals() const {
    return m_wrong->isChecked();
}

bool NormalsView::onlyVisibleHairs() const {
    return m_onlyVisible->isChecked();
}

void NormalsView::showNormalMap(bool on) {
    m_tabs->setCurrentIndex(on ? 1 : 0);
}

const QImage& NormalsView::normalMap() {
    if (m_mapDirty) refreshMap();
    return m_map;
}

QString NormalsView::legendText() const {
    return m_legend->text();
}

QString NormalsView::explanationText() const {
    return m_explanation->toPlainText();
}

void NormalsView::refreshGeometry() {
    m_geometryDirty = false;
    m_picture = NormalsPicture{};
    const auto& frame = m_inspection->frame();
    if (!frame || !frame->projection) {
        m_canvas->setPicture(&m_picture);
        refreshLegend();
        refreshSelection();
        return;
    }
    const rl::Scene& scene = *frame->scene;
    const rl::Projection& projection = *frame->projection;
    m_picture.screen = QSizeF(scene.width, scene.height);
    m_picture.normalsSkipped = !frame->normals || frame->normals->skipped;

    // Per draw: back faces and winding of every mesh triangle. What depends on the mesh alone
    // is kept from frame to frame while the mesh is the same (moving the camera keeps it).
    m_picture.viewWinding.assign(scene.draws.size(), 0);
    std::vector<std::vector<std::uint8_t>> backFace(scene.draws.size());
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
        const double det = glm::determinant(rl::dmat3(frame->view->viewFromModel[d]));
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

    // The wireframe: the projected triangles at their snapped screen positions.
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

    // Which mesh triangles hold a pixel at the end of the frame, and how many pixels show a
    // back face there.
    std::vector<std::vector<std::uint8_t>> visible(scene.draws.size());
    for (std::size_t d = 0; d < scene.draws.size(); ++d)
        if (scene.draws[d].mesh) visible[d].assign(scene.draws[d].mesh->triangles.size(), 0);
    if (frame->depth) {
        const auto& ids = frame->depth->triangle;
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

    // The hairs: the view-space normal from its foot, both ends projected by the draw's matrix,
    // on the triangles drawn (those holding a pixel at the end, when asked) and their corners.
    if (!m_picture.normalsSkipped) {
        const bool onlyVisible = m_onlyVisible->isChecked();
        std::vector<std::vector<std::uint8_t>> hairTriangles(scene.draws.size());
        std::vector<std::vector<std::uint8_t>> hairVertices(scene.draws.size());
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
        m_picture.triangleHairStep = std::max<int>(
            1, static_cast<int>((m_picture.hairTriangles + kMostHairs - 1) / kMostHairs));
        m_picture.vertexHairStep =
            std::max<int>(1, static_cast<int>((vertexCount + kMostHairs - 1) / kMostHairs));
        std::size_t triangleIndex = 0, vertexIndex = 0;  // counted over every draw
        m_picture.drawHairLength.assign(scene.draws.size(), 0.0);
        for (std::size_t d = 0; d < scene.draws.size(); ++d) {
            const rl::Draw& draw = scene.draws[d];
            if (!draw.mesh) continue;
            const rl::DrawProjection& proj = projection.draws[d];
            const rl::DrawNormals& normals = frame->normals->draws[d];
            // L: a fraction of the mesh's size in view space, larger for meshes of few
            // triangles, and at most half the nearest vertex's depth, so that no hair reaches
            // the camera's plane.
            rl::dvec3 low(std::numeric_limits<double>::max()), high(-low);
            double nearest = std::numeric_limits<double>::max();
            for (std::uint32_t v = 0; v < proj.originalVertexCount; ++v) {
                const rl::dvec3 p = rl::cartesian(proj.pView[v]);
                low = glm::min(low, p);
                high = glm::max(high, p);
                if (proj.pClip[v].w > projection.nearW)
                    nearest = std::min(nearest, proj.pClip[v].w);
            }
            const double size = proj.originalVertexCount > 0 ? glm::length(high - low) : 0.0;
            const double fraction = std::clamp(
                0.3 / std::sqrt(double(std::max<std::size_t>(1, draw.mesh->triangles.size()))),
                0.04, 0.3);
            const double length = std::min(size * fraction, 0.5 * nearest);
            m_picture.drawHairLength[d] = length;
            if (m_picture.hairLength == 0.0) {
                m_picture.hairLength = length;
                m_picture.hairFraction = size > 0.0 ? length / size : 0.0;
            }
            const auto hair = [&](const rl::dvec3& foot, const rl::vec3& n) {
                return hairLine(scene, projection, proj, length, foot, n);
            };
            const bool wrong = m_wrong->isChecked() && frame->view;
            for (std::size_t t = 0; t < draw.mesh->triangles.size(); ++t) {
                if (!hairTriangles[d][t]) continue;
                if (triangleIndex++ % static_cast<std::size_t>(m_picture.triangleHairStep) != 0)
                    continue;
                const rl::dvec3 foot =
                    rl::viewBarycentre(proj, *draw.mesh, static_cast<std::uint32_t>(t));
                if (const auto line = hair(foot, normals.triangle[t]))
                    m_picture.triangleHairs.push_back(*line);
                if (!wrong) continue;
                const rl::CarriedNormal carried =
                    rl::carriedTriangleNormal(frame->view->viewFromModel[d], *draw.mesh, t);
                if (const auto line = hair(foot, rl::vec3(carried.wrong)))
                    m_picture.wrongHairs.push_back(*line);
            }
            for (std::uint32_t v = 0; v < proj.originalVertexCount; ++v) {
                if (!hairVertices[d][v]) continue;
                if (vertexIndex++ % static_cast<std::size_t>(m_picture.vertexHairStep) != 0)
                    continue;
                if (const auto line = hair(rl::cartesian(proj.pView[v]), normals.vertex[v]))
                    m_picture.vertexHairs.push_back(*line);
            }
        }
    }
    m_canvas->setPicture(&m_picture);
    refreshLegend();
    refreshSelection();
}

void NormalsView::refreshSelection() {
    m_picture.selected.reset();
    m_picture.selectedTriangleHairs.clear();
    m_picture.selectedVertexHairs.clear();
    m_picture.selectedWrongHairs.clear();
    const auto& frame = m_inspection->frame();
    const std::optional<std::uint32_t> t = m_inspection->selectedTriangle();
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
            if (m_wrong->isChecked() && frame->view)
                add(m_picture.selectedWrongHairs, foot,
                    rl::vec3(rl::carriedTriangleNormal(frame->view->viewFromModel[tri.draw], mesh,
                                                       tri.source)
                                 .wrong));
        }
    }
    m_canvas->update();
    refreshExplanation();
}

void NormalsView::refreshMap() {
    const auto& frame = m_inspection->frame();
    const rl::DepthTest* buffers = m_inspection->buffers();
    if (!frame || !buffers) {
        m_map = QImage();
    } else {
        if (!m_pixelNormals) m_pixelNormals = std::make_unique<PixelNormals>(frame);
        m_map = m_pixelNormals->image(*buffers);
    }
    m_mapDirty = false;
    m_mapView->setImage(m_map);
}

void NormalsView::refreshLegend() {
    const auto& frame = m_inspection->frame();
    if (!frame || !frame->projection) {
        m_legend->setText(tr("No frame yet."));
        return;
    }
    const NormalsPicture& p = m_picture;
    QStringList parts;
    QString front = swatch(kFrontColour) + QLatin1Char(' ') +
                    tr("front faces %1").arg(p.meshTriangles - p.backFaces);
    if (p.culledFront > 0)
        front += QLatin1Char(' ') + tr("(%1 hidden, left out by culling)").arg(p.culledFront);
    QString back = swatch(kBackColour) + QLatin1Char(' ') +
                   tr("back faces (n · pView &gt; 0) %1").arg(p.backFaces);
    if (p.culledBack > 0)
        back += QLatin1Char(' ') + tr("(%1 hidden, left out by culling)").arg(p.culledBack);
    parts << front << back;
    parts << swatch(kInconsistentColour) + QLatin1Char(' ') +
                 tr("inconsistent winding: %1 triangles, %2 edges run the same way by two "
                    "triangles")
                     .arg(p.inconsistentTriangles)
                     .arg(p.inconsistentEdges);
    QString text = parts.join(QStringLiteral(" &nbsp; "));
    if (std::find(p.viewWinding.begin(), p.viewWinding.end(), -1) != p.viewWinding.end())
        text += QStringLiteral("<br>") +
                tr("%1% of the pixels seen are back faces: the surface is closed and its "
                   "normals point inward in view space (the course's [U; V; N] mirrors, so a "
                   "file wound counter-clockwise seen from outside turns over). Shading turns "
                   "every normal toward the viewer: the image does not change.")
                    .arg(p.coveredPixels > 0 ? (100 * p.backFacePixels) / p.coveredPixels : 0);
    if (p.normalsSkipped) {
        text += QStringLiteral("<br>") +
                tr("No normals: %1.")
                    .arg(QString::fromStdString(frame->normals ? frame->normals->skipReason
                                                               : std::string()));
    } else {
        text += QStringLiteral("<br>") + swatch(kTriangleHairColour) + QLatin1Char(' ') +
                tr("triangle normals") + QStringLiteral(" &nbsp; ") + swatch(kVertexHairColour) +
                QLatin1Char(' ') + tr("vertex normals") + QStringLiteral(" &nbsp; ") +
                tr("length L = %1 (%2% of the mesh's size)")
                    .arg(number(p.hairLength, 3))
                    .arg(number(p.hairFraction * 100.0, 2));
        if (m_wrong->isChecked())
            text += QStringLiteral(" &nbsp; ") + swatch(kWrongHairColour) + QLatin1Char(' ') +
                    tr("triangle normals carried by M itself (wrong)");
        if (m_onlyVisible->isChecked())
            text += QStringLiteral(", ") +
                    tr("on the %1 triangles seen and their corners").arg(p.hairTriangles);
        if (p.triangleHairStep > 1 || p.vertexHairStep > 1)
            text += QStringLiteral("<br>") +
                    tr("Large mesh: one triangle normal in %1 and one vertex normal in %2 are "
                       "drawn; the selected triangle's always.")
                        .arg(p.triangleHairStep)
                        .arg(p.vertexHairStep);
    }
    if (p.wireStep > 1)
        text += QStringLiteral("<br>") +
                tr("One triangle in %1 of the wireframe is drawn.").arg(p.wireStep);
    m_legend->setText(text);
}

QString NormalsView::wrongNormalHtml(const rl::FrameTrace& frame, std::uint32_t d,
                                     std::uint32_t t) const {
    const rl::Draw& draw = frame.scene->draws[d];
    const rl::dmat4& a = frame.view->viewFromModel[d];
    const rl::CarriedNormal n = rl::carriedTriangleNormal(a, *draw.mesh, t);
    if (n.nModel == rl::dvec3(0.0)) return {};
    const auto unit = [](const rl::dvec3& v) {
        const double l = glm::length(v);
        return l > 0.0 ? v / l : rl::dvec3(0.0);
    };
    const rl::dvec3 e1 = unit(n.edges[0]), e2 = unit(n.edges[1]);
    const double between =
        std::acos(std::clamp(glm::dot(n.right, n.wrong), -1.0, 1.0)) * 180.0 / std::numbers::pi;
    QString html = tr("<p><b>Normals by M, right and wrong</b>: A = viewFromModel = "
                      "viewFromWorld · M(t) · worldFromModel (M: the animation matrix, the "
                      "identity when the animation is off). The model-space normal n = %1, "
                      "det A = %2; the carried edges, made unit: e1 = A (P2 − P1) / |…| = %3, "
                      "e2 = A (P3 − P1) / |…| = %4.<br>")
                       .arg(vector(n.nModel, 'f', 4), number(glm::determinant(rl::dmat3(a)), 4),
                            vector(e1, 'f', 4), vector(e2, 'f', 4));
    html += tr("Right: A<sup>−T</sup> n, normalised = <b>%1</b>; its dots with e1 and e2 are %2 "
               "and %3: perpendicular to the surface.<br>")
                .arg(vector(n.right, 'f', 4), number(glm::dot(n.right, e1), 3, 'f'),
                     number(glm::dot(n.right, e2), 3, 'f'));
    html += tr("Wrong: A n, normalised = <b>%1</b>; its dots with e1 and e2 are %2 and %3: "
               "%4° off the surface's normal.</p>")
                .arg(vector(n.wrong, 'f', 4), number(glm::dot(n.wrong, e1), 3, 'f'),
                     number(glm::dot(n.wrong, e2), 3, 'f'), number(between, 4));
    if (between < 0.01)
        html +=
            tr("<p>Here both agree: A has no non-uniform scale. Set a scale such as "
               "(2, 1, 1) in the Animation panel to see them part.</p>");
    return html;
}

void NormalsView::refreshExplanation() {
    const auto& frame = m_inspection->frame();
    if (!frame || !frame->projection) {
        m_explanation->setHtml(tr("<p>No frame yet.</p>"));
        return;
    }
    QString html =
        tr("<p><b>Stage 3, normals</b>, in view space: each triangle's normal "
           "n = (P2 − P1) × (P3 − P1) / |(P2 − P1) × (P3 − P1)|, and each vertex's "
           "normal the normalised sum of the normals of the triangles around it. "
           "A triangle faces away from the camera (at the origin) when n · P1 &gt; 0; "
           "the course turns such normals toward the viewer when it shades.</p>");
    const bool skipped = m_picture.normalsSkipped;
    if (skipped)
        html += tr("<p>Skipped for this frame: %1.</p>")
                    .arg(QString::fromStdString(frame->normals ? frame->normals->skipReason
                                                               : std::string())
                             .toHtmlEscaped());

    const std::optional<std::uint32_t> selected = m_inspection->selectedTriangle();
    if (selected && *selected < frame->projection->triangles.size()) {
        const rl::ScreenTriangle& tri = frame->projection->triangles[*selected];
        const rl::Draw& draw = frame->scene->draws[tri.draw];
        const rl::DrawProjection& proj = frame->projection->draws[tri.draw];
        const auto& c = draw.mesh->triangles[tri.source];
        const rl::dvec3 p1 = rl::cartesian(proj.pView[c[0]]), p2 = rl::cartesian(proj.pView[c[1]]),
                        p3 = rl::cartesian(proj.pView[c[2]]);
        const rl::dvec3 cross = glm::cross(p2 - p1, p3 - p1);
        const double length = glm::length(cross);
        html += tr("<p><b>Triangle %1</b> (vertices %2, %3, %4):<br>P1 = %5, P2 = %6, P3 = %7<br>"
                   "(P2 − P1) × (P3 − P1) = %8 × %9")
                    .arg(tri.source + 1)
                    .arg(c[0] + 1)
                    .arg(c[1] + 1)
                    .arg(c[2] + 1)
                    .arg(vector(p1), vector(p2), vector(p3), vector(p2 - p1), vector(p3 - p1));
        html += tr(" = %1, length %2<br>").arg(vector(cross), number(length));
        if (length > 0.0) {
            const rl::dvec3 n = cross / length;
            const double facing = glm::dot(n, p1);
            html += tr("n = <b>%1</b>; n · P1 = %2: %3</p>")
                        .arg(vector(n, 'f', 4), number(facing, 4),
                             facing > 0.0 ? tr("a back face, drawn in red") : tr("a front face"));
        } else {
            html += tr("a degenerate triangle: no normal.</p>");
        }
        if (tri.draw < m_meshFacts.size() &&
            m_meshFacts[tri.draw].winding.inconsistent.size() > tri.source &&
            m_meshFacts[tri.draw].winding.inconsistent[tri.source])
            html +=
                tr("<p>It runs an edge in the same direction as a neighbour does: the two "
                   "are wound inconsistently (magenta), and one of their normals points "
                   "the wrong way.</p>");
        if (m_wrong->isChecked() && frame->view)
            html += wrongNormalHtml(*frame, tri.draw, tri.source);
        if (!skipped) {
            const rl::DrawNormals& normals = frame->normals->draws[tri.draw];
            html += tr("<p>Vertex normals: N1 = %1 (vertex %2), N2 = %3 (vertex %4), N3 = %5 "
                       "(vertex %6)</p>")
                        .arg(vector(normals.vertex[c[0]], 'f', 4), QString::number(c[0] + 1),
                             vector(normals.vertex[c[1]], 'f', 4), QString::number(c[1] + 1),
                             vector(normals.vertex[c[2]], 'f', 4), QString::number(c[2] + 1));
        }
    } else {
        html +=
            tr("<p>Pick a pixel (here or in any image) to select its triangle and see its "
               "normal worked out.</p>");
    }

    // The picked pixel's normal, as the normal map shows it.
    const QPoint pixel = m_inspection->pickedPixel();
    const rl::DepthTest* buffers = m_inspection->buffers();
    if (pixel.x() >= 0 && buffers) {
        if (!m_pixelNormals) m_pixelNormals = std::make_unique<PixelNormals>(frame);
        const PixelNormal n = m_pixelNormals->at(*buffers, pixel.x(), pixel.y());
        html += tr("<p><b>Pixel (%1, %2)</b>: ").arg(pixel.x()).arg(pixel.y());
        if (!n.covered) {
            html += tr("no triangle holds it at the cursor (black in the normal map).</p>");
        } else if (n.n == rl::vec3(0.0f)) {
            html += tr("no normal: %1 (grey in the normal map).</p>").arg(n.none.toHtmlEscaped());
        } else {
            if (n.flat)
                html += tr("the triangle's normal (flat) %1").arg(vector(n.interpolated, 'f', 4));
            else
                html += tr("N = α N1 + β N2 + γ N3 with (α, β, γ) = %1: %2, normalised %3")
                            .arg(vector(n.weights, 'f', 4), vector(n.interpolated, 'f', 4),
                                 vector(n.flipped ? -n.n : n.n, 'f', 4));
            if (n.flipped)
                html += tr("; V · N &lt; 0, turned toward the viewer: <b>%1</b>")
                            .arg(vector(n.n, 'f', 4));
            const QRgb rgb = normalColour(n.n);
            html += tr(". Colour (N + 1) / 2 = (%1, %2, %3).</p>")
                        .arg(qRed(rgb))
                        .arg(qGreen(rgb))
                        .arg(qBlue(rgb));
        }
    }
    m_explanation->setHtml(html);
}

void NormalsView::showPixelValue(QPoint pixel) {
    const rl::DepthTest* buffers = m_inspection->buffers();
    const auto& frame = m_inspection->frame();
    if (pixel.x() < 0 || !buffers || !frame) {
        m_pixelValue->clear();
        return;
    }
    if (!m_pixelNormals) m_pixelNormals = std::make_unique<PixelNormals>(frame);
    const PixelNormal n = m_pixelNormals->at(*buffers, pixel.x(), pixel.y());
    if (!n.covered) {
        m_pixelValue->setText(tr("x %1, y %2: no triangle").arg(pixel.x()).arg(pixel.y()));
        return;
    }
    const QRgb rgb = normalColour(n.n);
    m_pixelValue->setText(tr("x %1, y %2: triangle %3, N = %4, colour (%5, %6, %7)")
                              .arg(pixel.x())
                              .arg(pixel.y())
                              .arg(frame->projection->triangles[n.triangle].source + 1)
                              .arg(vector(n.n, 'f', 4))
                              .arg(qRed(rgb))
                              .arg(qGreen(rgb))
                              .arg(qBlue(rgb)));
}

}  // namespace rasterlab
