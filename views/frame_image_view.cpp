#include "frame_image_view.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace rasterlab {

FrameImageView::FrameImageView(QWidget* parent) : QWidget(parent) {
    setMouseTracking(true);
    setFocusPolicy(Qt::StrongFocus);
    setAutoFillBackground(true);
    QPalette p = palette();
    p.setColor(QPalette::Window, QColor(48, 48, 52));
    setPalette(p);
}

void FrameImageView::setImage(const QImage& image) {
    const bool sizeChanged = image.size() != m_image.size();
    m_image = image;
    if (sizeChanged && m_fit) m_zoom = fitZoom();
    update();
}

double FrameImageView::fitZoom() const {
    if (m_image.isNull() || width() <= 0 || height() <= 0) return 1.0;
    const double z =
        std::min(double(width()) / m_image.width(), double(height()) / m_image.height());
    return std::clamp(z, kMinZoom, kMaxZoom);
}

QPointF FrameImageView::imageOrigin() const {
    const QPointF centre(width() / 2.0, height() / 2.0);
    return centre + m_offset -
           QPointF(m_image.width() * m_zoom / 2.0, m_image.height() * m_zoom / 2.0);
}

QPoint FrameImageView::pixelAt(const QPointF& widgetPos) const {
    if (m_image.isNull()) return {-1, -1};
    const QPointF p = (widgetPos - imageOrigin()) / m_zoom;
    const int x = static_cast<int>(std::floor(p.x()));
    const int y = static_cast<int>(std::floor(p.y()));
    if (x < 0 || y < 0 || x >= m_image.width() || y >= m_image.height()) return {-1, -1};
    return {x, y};
}

void FrameImageView::fitToWindow() {
    m_fit = true;
    m_offset = {};
    m_zoom = fitZoom();
    emit zoomChanged(m_zoom);
    update();
}

void FrameImageView::zoomToActualSize() {
    setZoomAround(1.0, QPointF(width() / 2.0, height() / 2.0));
}

void FrameImageView::zoomIn() {
    setZoomAround(m_zoom * 2.0, QPointF(width() / 2.0, height() / 2.0));
}

void FrameImageView::zoomOut() {
    setZoomAround(m_zoom / 2.0, QPointF(width() / 2.0, height() / 2.0));
}

void FrameImageView::setZoomAround(double zoom, const QPointF& widgetPos) {
    zoom = std::clamp(zoom, kMinZoom, kMaxZoom);
    // Keep the image point under widgetPos where it is.
    const QPointF imagePoint = (widgetPos - imageOrigin()) / m_zoom;
    m_zoom = zoom;
    m_fit = false;
    const QPointF centre(width() / 2.0, height() / 2.0);
    m_offset = widgetPos - centre - imagePoint * m_zoom +
               QPointF(m_image.width() * m_zoom / 2.0, m_image.height() * m_zoom / 2.0);
    emit zoomChanged(m_zoom);
    update();
}

void FrameImageView::paintEvent(QPaintEvent*) {
    if (m_image.isNull()) return;
    QPainter painter(this);
    const QPointF origin = imageOrigin();
    const QRectF target(origin, QSizeF(m_image.width() * m_zoom, m_image.height() * m_zoom));
    // Nearest-neighbour when magnified: a pixel is a square, not a blur.
    painter.setRenderHint(QPainter::SmoothPixmapTransform, m_zoom < 1.0);
    painter.drawImage(target, m_image);

    if (m_zoom >= kGridFromZoom) {
        // Pixel grid and pixel centres over the visible part of the image.
        const int x0 = std::max(0, static_cast<int>(std::floor(-origin.x() / m_zoom)));
        const int y0 = std::max(0, static_cast<int>(std::floor(-origin.y() / m_zoom)));
        const int x1 =
            std::min(m_image.width(), static_cast<int>(std::ceil((width() - origin.x()) / m_zoom)));
        const int y1 = std::min(m_image.height(),
                                static_cast<int>(std::ceil((height() - origin.y()) / m_zoom)));
        painter.setPen(QPen(QColor(128, 128, 128, 110), 0));
        for (int x = x0; x <= x1; ++x)
            painter.drawLine(QPointF(origin.x() + x * m_zoom, origin.y() + y0 * m_zoom),
                             QPointF(origin.x() + x * m_zoom, origin.y() + y1 * m_zoom));
        for (int y = y0; y <= y1; ++y)
            painter.drawLine(QPointF(origin.x() + x0 * m_zoom, origin.y() + y * m_zoom),
                             QPointF(origin.x() + x1 * m_zoom, origin.y() + y * m_zoom));
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor(255, 255, 255, 140));
        const double r = std::max(1.0, m_zoom / 16.0);
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x)
                painter.drawEllipse(
                    QPointF(origin.x() + (x + 0.5) * m_zoom, origin.y() + (y + 0.5) * m_zoom), r,
                    r);
    }
}

void FrameImageView::resizeEvent(QResizeEvent*) {
    if (m_fit) m_zoom = fitZoom();
}

void FrameImageView::wheelEvent(QWheelEvent* event) {
    const double steps = event->angleDelta().y() / 120.0;
    if (steps == 0.0) return;
    setZoomAround(m_zoom * std::pow(1.25, steps), event->position());
    event->accept();
}

void FrameImageView::mousePressEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton) {
        m_dragStart = event->position().toPoint();
        m_offsetAtDragStart = m_offset;
        m_dragging = false;
    }
}

void FrameImageView::mouseMoveEvent(QMouseEvent* event) {
    if (event->buttons() & Qt::LeftButton) {
        const QPoint delta = event->position().toPoint() - m_dragStart;
        if (m_dragging || delta.manhattanLength() > 3) {
            m_dragging = true;
            m_fit = false;
            m_offset = m_offsetAtDragStart + QPointF(delta);
            update();
        }
    }
    emit pixelHovered(pixelAt(event->position()));
}

void FrameImageView::mouseReleaseEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton && !m_dragging) {
        const QPoint pixel = pixelAt(event->position());
        if (pixel.x() >= 0) emit pixelPicked(pixel);
    }
    m_dragging = false;
}

void FrameImageView::leaveEvent(QEvent*) {
    emit pixelHovered({-1, -1});
}

}  // namespace rasterlab
