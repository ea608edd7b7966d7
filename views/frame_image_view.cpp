#include "frame_image_view.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
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

QPointF FrameImageView::centrePoint() const {
    return (QPointF(width() / 2.0, height() / 2.0) - imageOrigin()) / m_zoom;
}

void FrameImageView::showAt(double zoom, const QPointF& imagePoint) {
    m_zoom = std::clamp(zoom, kMinZoom, kMaxZoom);
    m_fit = false;
    m_offset = QPointF(m_image.width() * m_zoom / 2.0, m_image.height() * m_zoom / 2.0) -
               imagePoint * m_zoom;
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
        // The pixel grid and the sample points over the visible part of the image.
        const QRect visible = visiblePixels();
        const int x0 = visible.left(), y0 = visible.top();
        const int x1 = x0 + visible.width(), y1 = y0 + visible.height();
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
        // Where each pixel is sampled: its centre, or its corner under the course's rules.
        const double o = m_overlay.sampleOffset;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x)
                painter.drawEllipse(
                    QPointF(origin.x() + (x + o) * m_zoom, origin.y() + (y + o) * m_zoom), r, r);
    }
    paintOverlay(painter);
}

void FrameImageView::setOverlay(ImageOverlay overlay) {
    m_overlay = std::move(overlay);
    update();
}

QPointF FrameImageView::widgetPoint(const QPointF& imagePoint) const {
    return imageOrigin() + imagePoint * m_zoom;
}

QRect FrameImageView::visiblePixels() const {
    const QPointF origin = imageOrigin();
    const int x0 = std::max(0, static_cast<int>(std::floor(-origin.x() / m_zoom)));
    const int y0 = std::max(0, static_cast<int>(std::floor(-origin.y() / m_zoom)));
    const int x1 =
        std::min(m_image.width(), static_cast<int>(std::ceil((width() - origin.x()) / m_zoom)));
    const int y1 =
        std::min(m_image.height(), static_cast<int>(std::ceil((height() - origin.y()) / m_zoom)));
    return QRect(x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0));
}

void FrameImageView::paintOverlay(QPainter& painter) const {
    const ImageOverlay& o = m_overlay;
    const double w = o.lineWidth;
    auto pixelRect = [&](int x, int y, int n = 1) {
        return QRectF(widgetPoint(QPointF(x, y)), QSizeF(n * m_zoom, m_zoom));
    };
    painter.setRenderHint(QPainter::Antialiasing, true);
    if (!o.coverage.isNull()) {
        painter.setRenderHint(QPainter::SmoothPixmapTransform, false);
        painter.drawImage(QRectF(widgetPoint({0, 0}), QSizeF(m_image.size()) * m_zoom), o.coverage);
    }
    if (o.scanline >= 0) {
        // The row being walked, and the span on it.
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor(255, 210, 0, 45));
        painter.drawRect(pixelRect(0, o.scanline, m_image.width()));
        if (o.spanEnd > o.spanBegin) {
            painter.setBrush(Qt::NoBrush);
            painter.setPen(QPen(QColor(255, 140, 0), w));
            painter.drawRect(pixelRect(o.spanBegin, o.scanline, o.spanEnd - o.spanBegin));
        }
        if (o.crossings) {
            // Where the edges cross the row's sample line.
            const double ys = o.scanline + o.sampleOffset;
            painter.setPen(QPen(QColor(255, 140, 0), w));
            for (double x : {o.crossings->first, o.crossings->second}) {
                const QPointF p = widgetPoint({x, ys});
                painter.drawLine(p + QPointF(0, -6 * w), p + QPointF(0, 6 * w));
            }
        }
    }
    if (m_zoom >= 4.0 && !o.coveredPixels.empty()) {
        // The samples of the current triangle's pixels tested so far, those on the screen
        // (a large triangle seen close up has many more).
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor(60, 220, 90, 220));
        const double r = std::max(1.5, m_zoom / 10.0);
        const QRect visible = visiblePixels();
        for (const QPoint& p : o.coveredPixels)
            if (visible.contains(p))
                painter.drawEllipse(widgetPoint({p.x() + o.sampleOffset, p.y() + o.sampleOffset}),
                                    r, r);
    }
    auto outline = [&](const std::array<QPointF, 3>& t, const QColor& colour) {
        QPainterPath path;
        path.moveTo(widgetPoint(t[0]));
        path.lineTo(widgetPoint(t[1]));
        path.lineTo(widgetPoint(t[2]));
        path.closeSubpath();
        painter.setBrush(Qt::NoBrush);
        painter.setPen(QPen(QColor(0, 0, 0, 160), w + 2));
        painter.drawPath(path);
        painter.setPen(QPen(colour, w));
        painter.drawPath(path);
    };
    if (o.selectedTriangle) outline(*o.selectedTriangle, QColor(0, 220, 255));
    if (o.currentTriangle) outline(*o.currentTriangle, QColor(255, 230, 0));
    for (const QPointF& v : o.vertices) {
        painter.setBrush(QColor(0, 220, 255));
        painter.setPen(QPen(Qt::black, 1));
        painter.drawEllipse(widgetPoint(v), 3 * w, 3 * w);
    }
    auto square = [&](QPoint p, const QColor& colour) {
        if (p.x() < 0) return;
        QRectF r = pixelRect(p.x(), p.y());
        const double grow = std::max(0.0, 4.0 - m_zoom);  // visible when small
        r.adjust(-grow, -grow, grow, grow);
        painter.setBrush(Qt::NoBrush);
        painter.setPen(QPen(Qt::black, w + 2));
        painter.drawRect(r);
        painter.setPen(QPen(colour, w));
        painter.drawRect(r);
    };
    square(o.currentPixel, QColor(255, 60, 60));
    square(o.pickedPixel, QColor(255, 0, 255));
}

std::optional<QPoint> FrameImageView::arrowStep(int key) {
    switch (key) {
        case Qt::Key_Left:
            return QPoint(-1, 0);
        case Qt::Key_Right:
            return QPoint(1, 0);
        case Qt::Key_Up:
            return QPoint(0, -1);
        case Qt::Key_Down:
            return QPoint(0, 1);
        default:
            return std::nullopt;
    }
}

bool FrameImageView::event(QEvent* event) {
    // With a pixel picked, the arrow keys move it (before any window shortcut steps).
    if (event->type() == QEvent::ShortcutOverride && m_arrowsMovePick &&
        m_overlay.pickedPixel.x() >= 0) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (key->modifiers() == Qt::NoModifier &&
            (arrowStep(key->key()) || key->key() == Qt::Key_Escape)) {
            event->accept();
            return true;
        }
    }
    return QWidget::event(event);
}

void FrameImageView::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Escape && m_arrowsMovePick && m_overlay.pickedPixel.x() >= 0) {
        emit pixelPicked(QPoint(-1, -1));  // Esc lets go of the pixel: the arrows step again
        return;
    }
    const std::optional<QPoint> step = arrowStep(event->key());
    if (step && m_arrowsMovePick && m_overlay.pickedPixel.x() >= 0 && !m_image.isNull()) {
        const QPoint p = m_overlay.pickedPixel + *step;
        emit pixelPicked(QPoint(std::clamp(p.x(), 0, m_image.width() - 1),
                                std::clamp(p.y(), 0, m_image.height() - 1)));
        return;
    }
    QWidget::keyPressEvent(event);
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
