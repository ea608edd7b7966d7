#include "projection_view.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QSplitter>
#include <QTextBrowser>
#include <QToolButton>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "views/elided_label.h"
#include "views/inspection.h"
#include "views/key_figures.h"
#include "views/number_text.h"
#include "views/view_font.h"

namespace rasterlab {

namespace {

using rl::TriangleFate;

const QColor kBackground(48, 48, 52);
const QColor kWindowFill(62, 62, 70);
const QColor kWindowEdge(205, 205, 210);
const QColor kText(225, 225, 230);
const QColor kHiddenColour(110, 110, 120);
const QColor kDrawnColour(160, 190, 235, 200);  // a little translucent: dense parts show
const QColor kClippedColour(255, 150, 40);
const QColor kBehindColour(225, 80, 80);
const QColor kSelectedColour(0, 220, 255);  // as the image views show the selection
const QColor kCurrentColour(255, 230, 0);   // and the triangle being drawn

QString pair(double a, double b) {
    return QStringLiteral("(%1, %2)").arg(number(a), number(b));
}

// The part of a line inside a rectangle (Liang-Barsky), so that lines reaching far off the
// screen (up to the 2^28-pixel guard band) never reach the rasterizer's fixed point.
bool clipLine(QLineF& line, const QRectF& r) {
    double t0 = 0.0, t1 = 1.0;
    const double dx = line.dx(), dy = line.dy();
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {line.x1() - r.left(), r.right() - line.x1(), line.y1() - r.top(),
                         r.bottom() - line.y1()};
    for (int k = 0; k < 4; ++k) {
        if (p[k] == 0.0) {
            if (q[k] < 0.0) return false;
            continue;
        }
        const double t = q[k] / p[k];
        if (p[k] < 0.0) {
            t0 = std::max(t0, t);
        } else {
            t1 = std::min(t1, t);
        }
        if (t0 > t1) return false;
    }
    const QPointF a = line.p1();
    line = QLineF(a + t0 * QPointF(dx, dy), a + t1 * QPointF(dx, dy));
    return true;
}

// Edges (a < b) of one draw, each once.
std::vector<std::uint64_t> uniqueEdges(std::vector<std::uint64_t> keys) {
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    return keys;
}

void addEdges(std::vector<std::uint64_t>& keys, const std::array<std::uint32_t, 3>& v) {
    for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = v[k], b = v[(k + 1) % 3];
        keys.push_back((std::uint64_t(std::min(a, b)) << 32) | std::max(a, b));
    }
}

// One line per edge (each once), between the points of its two vertices.
template <typename PointOf>
void appendLines(QVector<QLineF>& lines, std::vector<std::uint64_t> keys, const PointOf& pointOf) {
    for (std::uint64_t key : uniqueEdges(std::move(keys)))
        lines.append(QLineF(pointOf(static_cast<std::uint32_t>(key >> 32)),
                            pointOf(static_cast<std::uint32_t>(key & 0xffffffffu))));
}

bool isCourseDraw(const rl::Scene& scene, std::uint32_t draw) {
    return scene.camera && draw < scene.draws.size() && !scene.draws[draw].clipFromView;
}

// Text with its baseline starting at `at`, on a dark backing so lines under it do not hide it.
void drawBoxedText(QPainter& painter, const QPointF& at, const QString& text,
                   const QColor& colour) {
    const QFontMetricsF metrics(painter.font());
    const QRectF box(at.x() - 3.0, at.y() - metrics.ascent() - 1.0,
                     metrics.horizontalAdvance(text) + 6.0, metrics.height() + 2.0);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(kBackground.red(), kBackground.green(), kBackground.blue(), 190));
    painter.drawRoundedRect(box, 3.0, 3.0);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(colour);
    painter.drawText(at, text);
}

// The cached layer of a canvas: the widget's size in device pixels, the background colour.
QImage blankLayer(const QWidget& widget) {
    const qreal ratio = widget.devicePixelRatioF();
    QImage layer(widget.size() * ratio, QImage::Format_ARGB32_Premultiplied);
    layer.setDevicePixelRatio(ratio);
    layer.fill(kBackground);
    return layer;
}

// The widget-space lines of a batch: transformed, clipped to the widget (with a margin) and
// drawn in one call.
void drawBatch(QPainter& painter, const QVector<QLineF>& lines, const QRectF& bounds,
               const std::function<QPointF(const QPointF&)>& map) {
    QVector<QLineF> out;
    out.reserve(lines.size());
    for (const QLineF& l : lines) {
        QLineF w(map(l.p1()), map(l.p2()));
        if (clipLine(w, bounds)) out.append(w);
    }
    painter.drawLines(out);
}

}  // namespace

FateCounts countFates(const rl::Projection& projection) {
    // The projection counts each mesh triangle once, by the fate it ends with.
    FateCounts c{.inside = projection.inside,
                 .clipped = projection.clipped,
                 .behind = projection.behind,
                 .clippedAway = projection.clippedAway,
                 .culled = projection.culled,
                 .backFaces = projection.backFaces,
                 .beyondGuardBand = projection.beyondGuardBand,
                 .nonFinite = projection.nonFinite};
    for (const rl::ScreenTriangle& t : projection.triangles)
        if (projection.draws[t.draw].fate[t.source] == TriangleFate::Clipped) ++c.fanTriangles;
    return c;
}

// ---------------------------------------------------------------------------------------
// ProjectionCanvas

ProjectionCanvas::ProjectionCanvas(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("projectionCanvas"));
    setMinimumSize(200, 150);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setToolTip(
        tr("Click a triangle to select it; wheel to zoom, drag to pan, double-click to "
           "fit."));
    fit();
}

void ProjectionCanvas::setFrame(std::shared_ptr<const rl::FrameTrace> frame,
                                ProjectionSpace space) {
    if (frame != m_frame) m_theirs.clear();
    const bool sizeChanged = !m_frame || !frame || m_frame->scene->width != frame->scene->width ||
                             m_frame->scene->height != frame->scene->height;
    m_frame = std::move(frame);
    m_space = space;
    buildLines();
    if (sizeChanged) fit();
    m_layerValid = false;
    update();
}

void ProjectionCanvas::setHighlights(std::optional<std::uint32_t> current,
                                     std::optional<std::uint32_t> selected) {
    if (current == m_current && selected == m_selected) return;
    m_current = current;
    m_selected = selected;
    update();  // the layer stays: only the highlights are drawn again
}

void ProjectionCanvas::setLineWidth(double width) {
    m_lineWidth = width;
    m_layerValid = false;
    update();
}

QPointF ProjectionCanvas::spacePoint(std::uint32_t draw, std::uint32_t vertex) const {
    const rl::DrawProjection& proj = m_frame->projection->draws[draw];
    const rl::dvec2 p = m_space == ProjectionSpace::Ndc ? proj.pNdc[vertex] : proj.pScreen[vertex];
    return {p.x, p.y};
}

QPointF ProjectionCanvas::layoutPoint(const QPointF& p) const {
    if (m_space == ProjectionSpace::Pixels || !m_frame) return p;
    const rl::Scene& scene = *m_frame->scene;
    const rl::dvec2 s =
        rl::screenFromNdc(rl::dvec2(p.x(), p.y()), scene.width, scene.height, scene.conventions);
    return {s.x, s.y};
}

QPointF ProjectionCanvas::spaceFromLayout(const QPointF& l) const {
    if (m_space == ProjectionSpace::Pixels || !m_frame) return l;
    const rl::Scene& scene = *m_frame->scene;
    const double x = 2.0 * l.x() / scene.width - 1.0;
    const double yFromTop = 2.0 * l.y() / scene.height;
    return {x, scene.conventions.ndcYUp ? 1.0 - yFromTop : yFromTop - 1.0};
}

QPointF ProjectionCanvas::toWidget(const QPointF& spacePoint) const {
    return m_view.toWidget(layoutPoint(spacePoint));
}

QPointF ProjectionCanvas::fromWidget(const QPointF& widgetPoint) const {
    return spaceFromLayout(m_view.fromWidget(widgetPoint));
}

QPointF ProjectionCanvas::widgetCentroid(std::uint32_t triangle) const {
    const rl::ScreenTriangle& t = m_frame->projection->triangles.at(triangle);
    QPointF sum;
    for (std::uint32_t v : t.v) sum += toWidget(spacePoint(t.draw, v));
    return sum / 3.0;
}

std::optional<std::uint32_t> ProjectionCanvas::triangleAt(const QPointF& widgetPoint) const {
    if (!m_frame || !m_frame->projection) return std::nullopt;
    const QPointF p = fromWidget(widgetPoint);
    const auto& triangles = m_frame->projection->triangles;
    std::optional<std::uint32_t> best;
    double bestDepth = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const rl::ScreenTriangle& t = triangles[i];
        const QPointF a = spacePoint(t.draw, t.v[0]), b = spacePoint(t.draw, t.v[1]),
                      c = spacePoint(t.draw, t.v[2]);
        auto edge = [](const QPointF& from, const QPointF& to, const QPointF& q) {
            return (to.x() - from.x()) * (q.y() - from.y()) -
                   (to.y() - from.y()) * (q.x() - from.x());
        };
        const double area = edge(a, b, c);
        if (area == 0.0) continue;
        const double wa = edge(b, c, p) / area, wb = edge(c, a, p) / area,
                     wc = edge(a, b, p) / area;
        if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
        // Of the triangles under the point, the nearest: the one the image shows there.
        const auto& depth = m_frame->projection->draws[t.draw].depth;
        const double z = wa * depth[t.v[0]] + wb * depth[t.v[1]] + wc * depth[t.v[2]];
        if (z < bestDepth) {
            bestDepth = z;
            best = static_cast<std::uint32_t>(i);
        }
    }
    return best;
}

void ProjectionCanvas::buildLines() {
    for (auto& lines : m_lines) lines.clear();
    m_triangles.fill(0);
    if (!m_frame || !m_frame->projection) return;
    const rl::Projection& projection = *m_frame->projection;
    const rl::Scene& scene = *m_frame->scene;
    const std::size_t draws = projection.draws.size();
    std::array<std::vector<std::vector<std::uint64_t>>, GroupCount> keys;
    for (auto& perDraw : keys) perDraw.resize(draws);

    for (const rl::ScreenTriangle& t : projection.triangles) {
        const bool clipped = projection.draws[t.draw].fate[t.source] == TriangleFate::Clipped;
        const Group group = clipped ? Clipped : Drawn;
        addEdges(keys[group][t.draw], t.v);
        ++m_triangles[group];
    }
    // Culled triangles and hidden back faces were never emitted: their own vertices are
    // drawn, when all three were projected.
    for (std::size_t d = 0; d < draws; ++d) {
        const rl::DrawProjection& proj = projection.draws[d];
        if (d >= scene.draws.size() || !scene.draws[d].mesh) continue;
        const auto& triangles = scene.draws[d].mesh->triangles;
        for (std::size_t i = 0; i < proj.fate.size() && i < triangles.size(); ++i) {
            const TriangleFate fate = proj.fate[i];
            if (fate != TriangleFate::Culled && fate != TriangleFate::BackFace) continue;
            const auto& tri = triangles[i];
            if (!proj.inFront[tri[0]] || !proj.inFront[tri[1]] || !proj.inFront[tri[2]]) continue;
            addEdges(keys[Hidden][d], tri);
            ++m_triangles[Hidden];
        }
    }
    for (int g = 0; g < GroupCount; ++g) {
        for (std::size_t d = 0; d < draws; ++d) {
            const auto draw = static_cast<std::uint32_t>(d);
            appendLines(m_lines[g], std::move(keys[g][d]),
                        [&](std::uint32_t v) { return layoutPoint(spacePoint(draw, v)); });
        }
    }
}

void ProjectionCanvas::fit() {
    const double w = m_frame ? m_frame->scene->width : 800.0;
    const double h = m_frame ? m_frame->scene->height : 600.0;
    m_view.setContent(QRectF(-0.25 * w, -0.25 * h, 1.5 * w, 1.5 * h));
    m_view.fit();
    m_layerValid = false;
    update();
}

void ProjectionCanvas::paintLayer() {
    m_layer = blankLayer(*this);
    m_layerValid = true;
    if (!m_frame || !m_frame->projection) return;
    QPainter painter(&m_layer);
    const rl::Scene& scene = *m_frame->scene;
    const double scale = m_view.scale();
    const QPointF offset = m_view.offset();
    const QRectF window(offset, QSizeF(scene.width * scale, scene.height * scale));
    painter.fillRect(window, kWindowFill);

    // NDC's axes, faint, through the window's centre.
    if (m_space == ProjectionSpace::Ndc) {
        painter.setPen(QPen(QColor(255, 255, 255, 40), 1.0, Qt::DashLine));
        painter.drawLine(QPointF(window.center().x(), window.top()),
                         QPointF(window.center().x(), window.bottom()));
        painter.drawLine(QPointF(window.left(), window.center().y()),
                         QPointF(window.right(), window.center().y()));
    }

    const QRectF bounds = QRectF(rect()).adjusted(-8, -8, 8, 8);
    const auto map = [scale, offset](const QPointF& l) { return l * scale + offset; };
    const double w = std::max(1.0, m_lineWidth - 0.5);
    const QColor colours[GroupCount] = {kHiddenColour, kDrawnColour, kClippedColour};
    for (int g = 0; g < GroupCount; ++g) {
        QPen pen(colours[g], w);
        pen.setCosmetic(true);
        painter.setPen(pen);
        drawBatch(painter, m_lines[g], bounds, map);
    }

    // The window over the lines, and the coordinates of two of its corners.
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(QPen(kWindowEdge, m_lineWidth));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(window);
    painter.setPen(kText);
    const QPointF topLeft = spaceFromLayout(QPointF(0.0, 0.0));
    const QPointF bottomRight = spaceFromLayout(QPointF(scene.width, scene.height));
    const QFontMetricsF metrics(painter.font());
    const QString first = pair(topLeft.x(), topLeft.y());
    const QString last = pair(bottomRight.x(), bottomRight.y());
    drawBoxedText(painter, window.topLeft() + QPointF(0.0, -metrics.descent() - 4.0), first, kText);
    drawBoxedText(
        painter,
        window.bottomRight() + QPointF(-metrics.horizontalAdvance(last), metrics.ascent() + 4.0),
        last, kText);
}

void ProjectionCanvas::drawTriangle(QPainter& painter, std::uint32_t triangle, const QColor& colour,
                                    bool fill) const {
    const auto& triangles = m_frame->projection->triangles;
    if (triangle >= triangles.size()) return;
    const rl::ScreenTriangle& t = triangles[triangle];
    QPolygonF polygon;
    for (std::uint32_t v : t.v) polygon << toWidget(spacePoint(t.draw, v));
    // Huge triangles (a vertex far out in the guard band): their part on the widget.
    QRectF bounds = QRectF(rect()).adjusted(-50, -50, 50, 50);
    QPainterPath path;
    path.addPolygon(polygon);
    path.closeSubpath();
    QPainterPath clip;
    clip.addRect(bounds);
    const bool huge = !bounds.contains(polygon.boundingRect());
    const QPainterPath shape = huge ? path.intersected(clip) : path;
    painter.setBrush(fill ? QColor(colour.red(), colour.green(), colour.blue(), 60)
                          : QColor(Qt::transparent));
    painter.setPen(QPen(QColor(0, 0, 0, 170), m_lineWidth + 2.0));
    painter.drawPath(shape);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(colour, m_lineWidth));
    painter.drawPath(shape);
}

void ProjectionCanvas::paintEvent(QPaintEvent*) {
    if (!m_layerValid || m_layer.size() != size() * devicePixelRatioF()) paintLayer();
    QPainter painter(this);
    painter.drawImage(0, 0, m_layer);
    if (!m_frame || !m_frame->projection) {
        painter.setPen(kText);
        painter.drawText(rect(), Qt::AlignCenter, tr("No frame yet."));
        return;
    }
    painter.setRenderHint(QPainter::Antialiasing, true);
    if (m_selected) drawTriangle(painter, *m_selected, kSelectedColour, true);
    if (m_current) drawTriangle(painter, *m_current, kCurrentColour, false);
    // The student's vertices: layout coordinates are pixels, whatever the space shown.
    for (const auto& [ours, theirs] : m_theirs) {
        const QPointF a = m_view.toWidget(ours), b = m_view.toWidget(theirs);
        painter.setPen(QPen(QColor(255, 255, 255, 150), 1));
        painter.drawLine(a, b);
        painter.setPen(QPen(QColor(230, 30, 30), 2));
        painter.drawLine(b + QPointF(-4, -4), b + QPointF(4, 4));
        painter.drawLine(b + QPointF(-4, 4), b + QPointF(4, -4));
    }
}

void ProjectionCanvas::setTheirVertices(std::vector<VertexPair> pairs) {
    m_theirs = std::move(pairs);
    update();
}

void ProjectionCanvas::resizeEvent(QResizeEvent*) {
    // Fitted, the view follows the widget's size; zoomed or panned, the wireframe stays put.
    if (!m_view.fitted()) m_view.keepPlace();
    m_layerValid = false;
}

void ProjectionCanvas::wheelEvent(QWheelEvent* event) {
    const double steps = event->angleDelta().y() / 120.0;
    if (steps == 0.0) return;
    // Zoom around the mouse, to between 1e-9 and 1e9 widget pixels per layout unit.
    const double fit = m_view.fitScale();
    m_view.zoomAround(event->position(), std::pow(1.25, steps), 1e-9 / fit, 1e9 / fit);
    m_layerValid = false;
    update();
}

void ProjectionCanvas::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) return;
    m_pressed = true;
    m_view.press(event->position());
}

void ProjectionCanvas::mouseMoveEvent(QMouseEvent* event) {
    if (!m_pressed || !m_view.drag(event->position())) return;
    m_layerValid = false;
    update();
}

void ProjectionCanvas::mouseReleaseEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton || !m_pressed) return;
    m_pressed = false;
    if (!m_view.dragging() && m_frame) emit triangleClicked(triangleAt(event->position()));
}

void ProjectionCanvas::mouseDoubleClickEvent(QMouseEvent*) {
    fit();
}

// ---------------------------------------------------------------------------------------
// ProjectionSideView

ProjectionSideView::ProjectionSideView(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("projectionSideView"));
    setMinimumSize(200, 110);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void ProjectionSideView::setFrame(std::shared_ptr<const rl::FrameTrace> frame) {
    m_frame = std::move(frame);
    m_lines.clear();
    m_cutLines.clear();
    m_keptLines.clear();
    m_behindLines.clear();
    m_made.clear();
    m_layerValid = false;
    update();
    if (!m_frame || !m_frame->projection) return;
    const rl::Projection& projection = *m_frame->projection;
    const rl::Scene& scene = *m_frame->scene;

    // A vertex as (w, y): the clip w (the view z for the course camera) and the view y.
    const auto at = [&](std::size_t d, std::uint32_t v) {
        const rl::DrawProjection& proj = projection.draws[d];
        return QPointF(proj.pClip[v].w, proj.pView[v].y);
    };
    double wMin = 0.0, wMax = 0.0, yMin = 0.0, yMax = 0.0;  // the camera is at (0, 0)
    for (std::size_t d = 0; d < projection.draws.size(); ++d) {
        const rl::DrawProjection& proj = projection.draws[d];
        for (std::uint32_t v = 0; v < proj.originalVertexCount; ++v) {
            const QPointF p = at(d, v);
            if (!std::isfinite(p.x()) || !std::isfinite(p.y())) continue;
            wMin = std::min(wMin, p.x());
            wMax = std::max(wMax, p.x());
            yMin = std::min(yMin, p.y());
            yMax = std::max(yMax, p.y());
        }
    }
    if (!(wMax > wMin)) wMax = wMin + 1.0;
    if (!(yMax > yMin)) yMax = yMin + 1.0;
    const double padW = 0.06 * (wMax - wMin), padY = 0.08 * (yMax - yMin);
    m_wMin = wMin - padW;
    m_wMax = wMax + padW;
    m_yMin = yMin - padY;
    m_yMax = yMax + padY;

    for (std::size_t d = 0; d < projection.draws.size() && d < scene.draws.size(); ++d) {
        const rl::DrawProjection& proj = projection.draws[d];
        if (!scene.draws[d].mesh) continue;
        const auto& triangles = scene.draws[d].mesh->triangles;
        std::vector<std::uint64_t> plain, cut, behind;
        for (std::size_t i = 0; i < triangles.size() && i < proj.fate.size(); ++i) {
            switch (proj.fate[i]) {
                case TriangleFate::Clipped:
                    addEdges(cut, triangles[i]);
                    break;
                case TriangleFate::Behind:
                    addEdges(behind, triangles[i]);
                    break;
                default:
                    addEdges(plain, triangles[i]);
                    break;
            }
        }
        const auto pointOf = [&](std::uint32_t v) { return at(d, v); };
        appendLines(m_lines, std::move(plain), pointOf);
        appendLines(m_cutLines, std::move(cut), pointOf);
        appendLines(m_behindLines, std::move(behind), pointOf);
        for (std::uint32_t v = proj.originalVertexCount; v < proj.pView.size(); ++v)
            m_made.append(at(d, v));
    }
    // What is left of the clipped triangles: their fan triangles.
    std::vector<std::vector<std::uint64_t>> kept(projection.draws.size());
    for (const rl::ScreenTriangle& t : projection.triangles)
        if (projection.draws[t.draw].fate[t.source] == TriangleFate::Clipped)
            addEdges(kept[t.draw], t.v);
    for (std::size_t d = 0; d < kept.size(); ++d)
        appendLines(m_keptLines, std::move(kept[d]), [&](std::uint32_t v) { return at(d, v); });
}

void ProjectionSideView::setSelected(std::optional<std::uint32_t> triangle) {
    if (triangle == m_selected) return;
    m_selected = triangle;
    update();
}

void ProjectionSideView::setLineWidth(double width) {
    m_lineWidth = width;
    m_layerValid = false;
    update();
}

QPointF ProjectionSideView::toWidget(double w, double y) const {
    const double left = 34.0, right = width() - 12.0, top = 10.0, bottom = height() - 22.0;
    return {left + (w - m_wMin) / (m_wMax - m_wMin) * (right - left),
            bottom - (y - m_yMin) / (m_yMax - m_yMin) * (bottom - top)};
}

void ProjectionSideView::paintLayer() {
    m_layer = blankLayer(*this);
    m_layerValid = true;
    if (!m_frame || !m_frame->projection) return;
    QPainter painter(&m_layer);
    const rl::Projection& projection = *m_frame->projection;
    const rl::Scene& scene = *m_frame->scene;
    const QRectF bounds = QRectF(rect()).adjusted(-8, -8, 8, 8);
    const auto map = [this](const QPointF& p) { return toWidget(p.x(), p.y()); };
    const double w = std::max(1.0, m_lineWidth - 0.5);

    // The frustum's top and bottom, |y| <= (hy/d) z, for the course camera.
    const QPointF eye = toWidget(0.0, 0.0);
    if (scene.camera && !scene.draws.empty() && isCourseDraw(scene, 0) && scene.camera->d != 0.0) {
        const double slope = std::abs(scene.camera->hy / scene.camera->d);
        QLineF up(eye, toWidget(m_wMax, slope * m_wMax)),
            down(eye, toWidget(m_wMax, -slope * m_wMax));
        painter.setPen(QPen(QColor(255, 255, 255, 70), 1.0, Qt::DashLine));
        if (clipLine(up, bounds)) painter.drawLine(up);
        if (clipLine(down, bounds)) painter.drawLine(down);
    }

    QPen pen(kHiddenColour.lighter(120), w);
    pen.setCosmetic(true);
    painter.setPen(pen);
    drawBatch(painter, m_lines, bounds, map);
    pen.setColor(kBehindColour);
    painter.setPen(pen);
    drawBatch(painter, m_behindLines, bounds, map);
    pen.setColor(QColor(kClippedColour.red(), kClippedColour.green(), kClippedColour.blue(), 120));
    pen.setStyle(Qt::DashLine);
    painter.setPen(pen);
    drawBatch(painter, m_cutLines, bounds, map);
    pen.setColor(kClippedColour);
    pen.setStyle(Qt::SolidLine);
    pen.setWidthF(w + 0.5);
    painter.setPen(pen);
    drawBatch(painter, m_keptLines, bounds, map);

    painter.setRenderHint(QPainter::Antialiasing, true);
    // The near plane; under the plain divide there is none, only the eye plane w = 0.
    const bool plainDivide = projection.mode == rl::NearPlane::Mode::Naive;
    const double nearW = plainDivide ? 0.0 : projection.nearW;
    const QPointF nearTop = toWidget(nearW, m_yMax), nearBottom = toWidget(nearW, m_yMin);
    painter.setPen(
        QPen(QColor(255, 90, 90), m_lineWidth, plainDivide ? Qt::DashLine : Qt::SolidLine));
    painter.drawLine(nearTop, nearBottom);
    // N, the direction the camera looks in (w grows along it).
    const QPointF nTip = eye + QPointF(std::min(70.0, 0.3 * width()), 0.0);
    painter.setPen(QPen(kText, m_lineWidth));
    painter.drawLine(eye, nTip);
    painter.drawLine(nTip, nTip + QPointF(-7.0, -4.0));
    painter.drawLine(nTip, nTip + QPointF(-7.0, 4.0));
    // The vertices clipping made, on the near plane (or another plane it met).
    painter.setPen(QPen(Qt::black, 1.0));
    painter.setBrush(kClippedColour);
    const double r = 2.0 + m_lineWidth;
    for (const QPointF& p : m_made) {
        const QPointF q = toWidget(p.x(), p.y());
        if (bounds.contains(q)) painter.drawEllipse(q, r, r);
    }
    // The camera, and the axes' names.
    painter.setBrush(kText);
    painter.drawEllipse(eye, 3.0, 3.0);
    painter.setPen(kText);
    const QFontMetricsF metrics(painter.font());
    const bool course = isCourseDraw(scene, 0);
    const QString axis = course ? tr("view z (= w) →") : tr("clip w →");
    drawBoxedText(painter,
                  QPointF(width() - 12.0 - metrics.horizontalAdvance(axis), height() - 6.0), axis,
                  kText);
    drawBoxedText(painter, QPointF(4.0, 4.0 + metrics.ascent()), tr("y ↑"), kText);
    drawBoxedText(painter,
                  eye + QPointF(-metrics.horizontalAdvance(QStringLiteral("C")) - 5.0,
                                metrics.ascent() + 2.0),
                  QStringLiteral("C"), kText);
    // The near plane's label beside its line, at the top; the count of made vertices in the
    // top right corner, out of the way of the geometry near the plane.
    drawBoxedText(painter,
                  nTip + QPointF(-metrics.horizontalAdvance(QStringLiteral("N")) / 2.0, -6.0),
                  QStringLiteral("N"), kText);
    drawBoxedText(painter, nearTop + QPointF(6.0, metrics.ascent()),
                  plainDivide ? tr("eye plane w = 0: the plain divide clips nothing")
                              : tr("near plane w = %1").arg(number(nearW, 4)),
                  QColor(255, 120, 120));
    if (rl::everyTriangleBehind(projection, scene)) {
        const QString behind = tr("the object lies behind the eye (w < 0): N points away from it");
        drawBoxedText(painter, QPointF(40.0, height() - 28.0), behind, kBehindColour.lighter(130));
    }
    if (!m_made.isEmpty()) {
        const QString made = tr("● made by clipping: %1").arg(m_made.size());
        drawBoxedText(
            painter,
            QPointF(width() - 12.0 - metrics.horizontalAdvance(made), 4.0 + metrics.ascent()), made,
            kClippedColour);
    }
}

void ProjectionSideView::paintEvent(QPaintEvent*) {
    if (!m_layerValid || m_layer.size() != size() * devicePixelRatioF()) paintLayer();
    QPainter painter(this);
    painter.drawImage(0, 0, m_layer);
    if (!m_frame || !m_frame->projection || !m_selected) return;
    const rl::Projection& projection = *m_frame->projection;
    if (*m_selected >= projection.triangles.size()) return;
    const rl::ScreenTriangle& t = projection.triangles[*m_selected];
    const rl::DrawProjection& proj = projection.draws[t.draw];
    QPolygonF polygon;
    for (std::uint32_t v : t.v) polygon << toWidget(proj.pClip[v].w, proj.pView[v].y);
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(QPen(QColor(0, 0, 0, 170), m_lineWidth + 2.0));
    painter.drawPolygon(polygon);
    painter.setPen(QPen(kSelectedColour, m_lineWidth));
    painter.drawPolygon(polygon);
}

void ProjectionSideView::resizeEvent(QResizeEvent*) {
    m_layerValid = false;
}

// ---------------------------------------------------------------------------------------
// ProjectionView

ProjectionView::ProjectionView(Inspection* inspection, QWidget* parent)
    : QWidget(parent), m_inspection(inspection) {
    setObjectName(QStringLiteral("projectionView"));
    m_canvas = new ProjectionCanvas(this);
    m_side = new ProjectionSideView(this);

    m_ndcButton = new QToolButton(this);
    m_ndcButton->setObjectName(QStringLiteral("projectionNdc"));
    m_ndcButton->setText(tr("NDC"));
    m_ndcButton->setToolTip(tr("Show the vertices in normalised device coordinates, [-1, 1]"));
    m_pixelsButton = new QToolButton(this);
    m_pixelsButton->setObjectName(QStringLiteral("projectionPixels"));
    m_pixelsButton->setText(tr("Pixels"));
    m_pixelsButton->setToolTip(
        tr("Show the vertices in pixels, snapped as scan conversion "
           "receives them"));
    for (QToolButton* b : {m_ndcButton, m_pixelsButton}) {
        b->setCheckable(true);
        b->setAutoExclusive(true);
    }
    m_ndcButton->setChecked(true);
    auto* fitButton = new QToolButton(this);
    fitButton->setObjectName(QStringLiteral("projectionFit"));
    fitButton->setText(tr("Fit"));
    fitButton->setToolTip(tr("Show the whole window and its margin"));

    m_figures = new KeyFigures(this);
    m_legend = new WrappedLabel(this);
    m_legend->setObjectName(QStringLiteral("projectionLegend"));
    m_legend->setWordWrap(true);
    m_legend->setTextFormat(Qt::RichText);
    m_explanation = new QTextBrowser(this);
    m_explanation->setObjectName(QStringLiteral("projectionExplanation"));
    m_explanation->setOpenLinks(false);

    auto* controls = new QHBoxLayout;
    controls->addWidget(m_ndcButton);
    controls->addWidget(m_pixelsButton);
    controls->addStretch();
    controls->addWidget(fitButton);

    auto* pictures = new QSplitter(Qt::Vertical);
    pictures->addWidget(m_canvas);
    pictures->addWidget(m_side);
    pictures->setStretchFactor(0, 3);
    pictures->setStretchFactor(1, 1);
    auto* left = new QWidget;
    auto* leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    leftLayout->addLayout(controls);
    leftLayout->addWidget(pictures, 1);

    auto* panel = new QWidget;
    auto* panelLayout = new QVBoxLayout(panel);
    panelLayout->setContentsMargins(4, 4, 4, 0);
    panelLayout->addWidget(m_figures);
    panelLayout->addWidget(m_legend);
    panelLayout->addWidget(m_explanation, 1);

    m_splitter = new QSplitter(Qt::Vertical, this);
    m_splitter->addWidget(left);
    m_splitter->addWidget(panel);
    m_splitter->setChildrenCollapsible(false);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_splitter);

    connect(m_ndcButton, &QToolButton::toggled, this, [this](bool on) {
        if (on) setSpace(ProjectionSpace::Ndc);
    });
    connect(m_pixelsButton, &QToolButton::toggled, this, [this](bool on) {
        if (on) setSpace(ProjectionSpace::Pixels);
    });
    connect(fitButton, &QToolButton::clicked, m_canvas, &ProjectionCanvas::fit);
    if (m_inspection) {
        connect(m_canvas, &ProjectionCanvas::triangleClicked, m_inspection,
                &Inspection::selectTriangle);
        connect(m_inspection, &Inspection::frameChanged, this, [this] {
            m_dirty = true;
            refresh();
        });
        connect(m_inspection, &Inspection::selectionChanged, this, [this] {
            if (isVisible() && !m_dirty) refreshSelection();
        });
        // A step moves the triangle being drawn, not the selection the text explains.
        connect(m_inspection, &Inspection::cursorChanged, this, [this] {
            if (isVisible() && !m_dirty) refreshHighlights();
        });
        connect(m_inspection, &Inspection::presentationChanged, this,
                &ProjectionView::applyPresentation);
    }
    applyPresentation();
    refresh();
}

void ProjectionView::setSpace(ProjectionSpace space) {
    if (space == m_space) return;
    m_space = space;
    (space == ProjectionSpace::Ndc ? m_ndcButton : m_pixelsButton)->setChecked(true);
    if (isVisible() && !m_dirty) {
        m_canvas->setFrame(m_frame, m_space);
    } else {
        m_dirty = true;
    }
}

void ProjectionView::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    // The selection and the cursor may have moved while hidden.
    if (m_dirty)
        refresh();
    else
        refreshSelection();
}

void ProjectionView::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    // Side by side when wide, one above the other when tall (a narrow dock); the pictures
    // get 65% when the orientation changes, then whatever the user drags them to.
    const Qt::Orientation orientation = width() > 1.25 * height() ? Qt::Horizontal : Qt::Vertical;
    if (orientation != m_splitter->orientation() || !m_splitterPlaced) {
        m_splitter->setOrientation(orientation);
        const int total = orientation == Qt::Horizontal ? width() : height();
        m_splitter->setSizes({total * 13 / 20, total - total * 13 / 20});
        m_splitterPlaced = true;
    }
}

void ProjectionView::applyPresentation() {
    const double width = m_inspection ? m_inspection->lineWidth() : 1.5;
    m_canvas->setLineWidth(width);
    m_side->setLineWidth(width);
    setFont(scaledFont(parentWidget(), m_inspection ? m_inspection->textScale(1.35) : 1.0));
}

void ProjectionView::refresh() {
    if (!isVisible()) {
        m_dirty = true;
        return;
    }
    m_dirty = false;
    m_frame = m_inspection ? m_inspection->frame() : nullptr;
    if (m_frame && !m_frame->projection) m_frame.reset();
    m_canvas->setFrame(m_frame, m_space);
    m_side->setFrame(m_frame);
    m_counts = m_frame ? countFates(*m_frame->projection) : FateCounts{};
    if (!m_frame) {
        m_legendText.clear();
        m_figures->setText(QString());
        m_legend->setText(tr("No frame yet."));
        refreshSelection();
        return;
    }
    const FateCounts& c = m_counts;
    m_legendText = tr("inside %1, clipped %2 (%3 on screen), culled %4, back faces %5; "
                      "behind %6, clipped away %7")
                       .arg(c.inside)
                       .arg(c.clipped)
                       .arg(c.fanTriangles)
                       .arg(c.culled)
                       .arg(c.backFaces)
                       .arg(c.behind)
                       .arg(c.clippedAway);
    if (c.beyondGuardBand > 0)
        m_legendText +=
            QStringLiteral(", ") + tr("beyond the guard band %1").arg(c.beyondGuardBand);
    if (c.nonFinite > 0)
        m_legendText += QStringLiteral(", ") + tr("not finite %1").arg(c.nonFinite);
    m_figures->setText(tr("%1 inside · %2 clipped · %3 culled · %4 behind")
                           .arg(c.inside)
                           .arg(c.clipped)
                           .arg(c.culled + c.backFaces)
                           .arg(c.behind));

    QString html = tr("%1 drawn whole (inside): %2<br>").arg(swatch(kDrawnColour)).arg(c.inside);
    html += tr("%1 clipped: %2, drawn as %3 fan triangles<br>")
                .arg(swatch(kClippedColour))
                .arg(c.clipped)
                .arg(c.fanTriangles);
    html += tr("%1 culled (clockwise on screen): %2; hidden back faces: %3<br>")
                .arg(swatch(kHiddenColour))
                .arg(c.culled)
                .arg(c.backFaces);
    html += tr("Nothing on screen: behind the near plane %1; outside a clip plane %2")
                .arg(c.behind)
                .arg(c.clippedAway);
    if (c.beyondGuardBand > 0) html += tr("; beyond the guard band %1").arg(c.beyondGuardBand);
    if (c.nonFinite > 0) html += tr("; not finite %1").arg(c.nonFinite);
    const rl::Projection& projection = *m_frame->projection;
    if (projection.mode == rl::NearPlane::Mode::Naive) {
        html += QStringLiteral("<br>") +
                tr("%1 screen triangles go to scan conversion. The plain divide clips nothing "
                   "(seed 000 as written; seed 001's HW2): %2 wholly behind the eye, drawn "
                   "mirrored through the centre; %3 across the eye plane, drawn wrong.")
                    .arg(projection.triangles.size())
                    .arg(projection.behindEye)
                    .arg(projection.acrossEye);
    } else {
        html += QStringLiteral("<br>") +
                tr("%1 screen triangles go to scan conversion; the near plane is w = %2.")
                    .arg(projection.triangles.size())
                    .arg(number(projection.nearW, 4));
    }
    html += QStringLiteral("<br>") +
            tr("%1 selected, %2 being drawn").arg(swatch(kSelectedColour), swatch(kCurrentColour));
    m_legend->setText(html);
    refreshSelection();
}

void ProjectionView::refreshHighlights() {
    const std::optional<std::uint32_t> selected =
        m_inspection && m_frame ? m_inspection->selectedTriangle() : std::nullopt;
    const std::optional<std::uint32_t> current =
        m_inspection && m_frame ? m_inspection->currentTriangle() : std::nullopt;
    m_canvas->setHighlights(current, selected);
    m_side->setSelected(selected);
}

void ProjectionView::refreshSelection() {
    refreshHighlights();
    const std::optional<std::uint32_t> selected =
        m_inspection && m_frame ? m_inspection->selectedTriangle() : std::nullopt;

    const bool plainDivide = m_frame && m_frame->projection->mode == rl::NearPlane::Mode::Naive;
    QString html =
        plainDivide
            ? tr("<p><b>Projection.</b> Every vertex goes to clip space, pClip = "
                 "clipFromView · pView, and is divided by its w without any clipping, as "
                 "seed 000 writes the formula and seed 001's HW2 does (\"frustum clipping "
                 "happens here in OpenGL, but we won't add it\"): pNdc = pClip.xy / w. A "
                 "vertex behind the eye (w &lt; 0) lands mirrored through the centre; a "
                 "triangle across the eye plane wraps through infinity. Clipping at the near "
                 "plane (Shading &gt; Projection) draws only what lies in front.</p>")
            : tr("<p><b>Projection.</b> Every vertex goes to clip space, pClip = "
                 "clipFromView · pView. A triangle crossing the near plane w = near is "
                 "clipped (Sutherland-Hodgman) and its polygon cut into a fan, so nothing "
                 "is divided by a w at or behind the camera. Then pNdc = pClip.xy / w, and "
                 "the pixels are x = (x_ndc + 1) W/2, y = (1 − y_ndc) H/2.</p>");
    if (m_frame && m_frame->scene->camera)
        html +=
            tr("<p>For the course camera pClip = ((d/hx) x, (d/hy) y, z, z): "
               "x_ndc = (d/hx) x/z, y_ndc = (d/hy) y/z, and the pixel coordinates are "
               "truncated.</p>");
    if (!m_frame) {
        html.clear();
    } else if (selected && *selected < m_frame->projection->triangles.size()) {
        html += vertexExplanation(*selected);
    } else {
        html += tr("<p>Click a triangle to see the numbers of its first vertex.</p>");
    }
    m_explanationHtml = html;
    m_explanation->setHtml(html);
}

QString ProjectionView::vertexExplanation(std::uint32_t triangle) const {
    const rl::Projection& projection = *m_frame->projection;
    const rl::Scene& scene = *m_frame->scene;
    const rl::ScreenTriangle& t = projection.triangles[triangle];
    const rl::DrawProjection& proj = projection.draws[t.draw];
    const std::uint32_t v = t.v[0];
    const rl::dvec4& pView = proj.pView[v];
    const rl::dvec4& pClip = proj.pClip[v];
    const rl::dvec2& pNdc = proj.pNdc[v];
    const rl::dvec2& exact = proj.pScreenExact[v];
    const rl::dvec2& pScreen = proj.pScreen[v];
    const double w = scene.width, h = scene.height;

    const bool clipped = proj.fate[t.source] == TriangleFate::Clipped;
    QString html = tr("<p><b>Triangle %1</b> (mesh triangle %2%3), its first vertex, vertex %4:")
                       .arg(triangle + 1)
                       .arg(t.source + 1)
                       .arg(clipped ? tr(", clipped") : QString())
                       .arg(v + 1);
    if (v >= proj.originalVertexCount) {
        const rl::ClipVertex& made = proj.generated[v - proj.originalVertexCount];
        html += QStringLiteral("<br>") +
                tr("made by clipping, on the edge from vertex %1 to vertex %2 at t = %3")
                    .arg(made.a + 1)
                    .arg(made.b + 1)
                    .arg(number(made.t));
    }
    html += QStringLiteral("<br>pView = (x, y, z) = (%1, %2, %3)")
                .arg(number(pView.x), number(pView.y), number(pView.z));
    if (isCourseDraw(scene, t.draw)) {
        const rl::CourseCamera& cam = *scene.camera;
        html += QStringLiteral("<br>x_ndc = (d/hx) x/z = (%1/%2) · %3 / %4 = %5")
                    .arg(number(cam.d), number(cam.hx), operand(pView.x), operand(pView.z),
                         number(pNdc.x));
        html += QStringLiteral("<br>y_ndc = (d/hy) y/z = (%1/%2) · %3 / %4 = %5")
                    .arg(number(cam.d), number(cam.hy), operand(pView.y), operand(pView.z),
                         number(pNdc.y));
    } else {
        html += QStringLiteral("<br>pClip = clipFromView · pView = (%1, %2, %3, %4)")
                    .arg(number(pClip.x), number(pClip.y), number(pClip.z), number(pClip.w));
        html += QStringLiteral("<br>x_ndc = x_clip / w = %1, y_ndc = y_clip / w = %2")
                    .arg(number(pNdc.x), number(pNdc.y));
    }
    // How the exact position becomes the one scan conversion receives.
    const rl::RasterRules& rules = scene.rules;
    QString rounding;
    if (rules.snap == rl::RasterRules::VertexSnap::None)
        rounding = tr("not snapped");
    else if (rules.subpixelBits == 0)
        rounding =
            rules.snap == rl::RasterRules::VertexSnap::Truncate ? tr("truncated") : tr("rounded");
    else
        rounding =
            (rules.snap == rl::RasterRules::VertexSnap::Truncate ? tr("truncated to 1/%1 pixel")
                                                                 : tr("rounded to 1/%1 pixel"))
                .arg(1 << rules.subpixelBits);
    if (scene.conventions.viewport == rl::ViewportFormula::ScaleThenShift) {
        // Seed 001's formula (its y points down the screen).
        html += QStringLiteral("<br>x = x_ndc W/2 + W/2 = %1 · %2/2 + %2/2 = %3 → %4 (%5)")
                    .arg(operand(pNdc.x), number(w), number(exact.x), number(pScreen.x), rounding);
        html += QStringLiteral("<br>y = y_ndc H/2 + H/2 = %1 · %2/2 + %2/2 = %3 → %4 (%5)")
                    .arg(operand(pNdc.y), number(h), number(exact.y), number(pScreen.y), rounding);
        return html + QStringLiteral("</p>");
    }
    html += QStringLiteral("<br>x = (x_ndc + 1) W/2 = (%1 + 1) · %2/2 = %3 → %4 (%5)")
                .arg(operand(pNdc.x), number(w), number(exact.x), number(pScreen.x), rounding);
    if (scene.conventions.ndcYUp)
        html += QStringLiteral("<br>y = (1 − y_ndc) H/2 = (1 − %1) · %2/2 = %3 → %4 (%5)")
                    .arg(operand(pNdc.y), number(h), number(exact.y), number(pScreen.y), rounding);
    else
        html += QStringLiteral("<br>y = (y_ndc + 1) H/2 = (%1 + 1) · %2/2 = %3 → %4 (%5)")
                    .arg(operand(pNdc.y), number(h), number(exact.y), number(pScreen.y), rounding);
    html += QStringLiteral("</p>");
    return html;
}

}  // namespace rasterlab
