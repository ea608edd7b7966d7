#include "normals_canvas.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <vector>

#include "views/normals_model.h"

namespace rasterlab {

NormalsCanvas::NormalsCanvas(QWidget* parent) : QWidget(parent) {
    setMouseTracking(false);
    setMinimumSize(120, 72);  // small: a short dock keeps its switches and the drawing
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

}  // namespace rasterlab
