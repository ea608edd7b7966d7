// The text a custom-painted view drew on its last paint, kept as rectangles (widget
// coordinates), and label placement that keeps each label off the ones already drawn. A view
// derives from PaintedLabels beside QWidget, clears the labels when its paint begins and draws
// its text through drawLabel(); tests/tst_legibility.cpp checks that no two rectangles meet
// and that each lies inside the view.
#pragma once

#include <QList>
#include <QPointF>
#include <QRect>
#include <QRectF>
#include <QString>
#include <QStringList>

#include <initializer_list>
#include <span>
#include <vector>

class QPainter;

namespace rasterlab {

class PaintedLabels {
public:
    virtual ~PaintedLabels() = default;

    // The rectangles of the text drawn on the last paint.
    QList<QRect> labelRects() const { return m_rects; }
    // Their texts, in the same order (empty for text recorded without it).
    QStringList labelTexts() const { return m_texts; }

protected:
    void clearLabels() {
        m_rects.clear();
        m_texts.clear();
    }
    // Text with its baseline starting at `baseline`; returns the rectangle it covers.
    QRectF drawLabel(QPainter& painter, QPointF baseline, const QString& text);
    // Text in `box` with Qt alignment and wrapping flags; the rectangle it covers.
    QRectF drawLabel(QPainter& painter, const QRectF& box, int flags, const QString& text);
    // Records text drawn some other way (a rich-text layout, a cached picture).
    void recordLabel(const QRectF& rect, const QString& text = {});
    // Whether `rect` would cover a label already drawn, or leave `bounds`.
    bool isFree(const QRectF& rect, const QRectF& bounds) const;
    // The first of `offsets` (added to `rect`) that is free within `bounds`; `rect` itself
    // when none is.
    QRectF freePlace(const QRectF& rect, const QRectF& bounds,
                     std::initializer_list<QPointF> offsets) const;

private:
    QList<QRect> m_rects;
    QStringList m_texts;
};

// Items of the given widths laid out from `left`, `gap` apart, on a new line wherever the
// next would pass `right` (a legend on as many lines as the width needs): each one's left x
// and line, from 0.
struct FlowPlace {
    double x = 0.0;
    int line = 0;
};
std::vector<FlowPlace> flowPlaces(std::span<const double> widths, double left, double right,
                                  double gap = 12.0);

// The rectangle a text covers when drawn with its baseline at `baseline`.
QRectF textBox(const QPainter& painter, QPointF baseline, const QString& text);

}  // namespace rasterlab
