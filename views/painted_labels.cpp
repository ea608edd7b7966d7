#include "painted_labels.h"

#include <QFontMetricsF>
#include <QPainter>

namespace rasterlab {

QRectF textBox(const QPainter& painter, QPointF baseline, const QString& text) {
    const QFontMetricsF metrics(painter.font());
    return QRectF(baseline.x(), baseline.y() - metrics.ascent(), metrics.horizontalAdvance(text),
                  metrics.ascent() + metrics.descent());
}

QRectF PaintedLabels::drawLabel(QPainter& painter, QPointF baseline, const QString& text) {
    painter.drawText(baseline, text);
    const QRectF box = textBox(painter, baseline, text);
    recordLabel(box, text);
    return box;
}

QRectF PaintedLabels::drawLabel(QPainter& painter, const QRectF& box, int flags,
                                const QString& text) {
    QRectF covered;
    painter.drawText(box, flags, text, &covered);
    recordLabel(covered, text);
    return covered;
}

void PaintedLabels::recordLabel(const QRectF& rect, const QString& text) {
    if (rect.isEmpty()) return;
    m_rects.append(rect.toRect());
    m_texts.append(text);
}

bool PaintedLabels::isFree(const QRectF& rect, const QRectF& bounds) const {
    if (!bounds.contains(rect)) return false;
    const QRect r = rect.toRect();
    for (const QRect& used : m_rects)
        if (used.intersects(r)) return false;
    return true;
}

QRectF PaintedLabels::freePlace(const QRectF& rect, const QRectF& bounds,
                                std::initializer_list<QPointF> offsets) const {
    for (const QPointF& offset : offsets)
        if (isFree(rect.translated(offset), bounds)) return rect.translated(offset);
    return rect;
}

std::vector<FlowPlace> flowPlaces(std::span<const double> widths, double left, double right,
                                  double gap) {
    std::vector<FlowPlace> places;
    double x = left;
    int line = 0;
    for (const double w : widths) {
        if (x > left && x + w > right) {
            x = left;
            ++line;
        }
        places.push_back({x, line});
        x += w + gap;
    }
    return places;
}

}  // namespace rasterlab
