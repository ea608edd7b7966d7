// Where a canvas draws its picture, and the wheel and drag that move it: a rectangle of the
// picture fitted in the widget, then zoomed around the mouse and panned.
#pragma once

#include <QPointF>
#include <QRectF>
#include <QSize>
#include <QSizeF>
#include <QWidget>

#include <algorithm>

namespace rasterlab {

// widget = picture · scale() + offset(). The zoom is relative to fitting content() in the
// widget (centred, as large as it fits with `margin` widget pixels left on each side), the
// pan in widget pixels from the widget's centre; both are read against the widget's current
// size, so a fitted view follows the widget's size, and a zoomed one keeps what it frames.
class ZoomPan {
public:
    ZoomPan(const QWidget* widget, double margin) : m_widget(widget), m_margin(margin) {}

    const QRectF& content() const { return m_content; }
    void setContent(const QRectF& content) { m_content = content; }

    double fitScale() const { return fitScaleIn(m_widget->size()); }
    double scale() const { return fitScale() * m_zoom; }
    QPointF offset() const { return offsetIn(m_widget->size()); }
    QPointF toWidget(const QPointF& picturePoint) const {
        return picturePoint * scale() + offset();
    }
    QPointF fromWidget(const QPointF& widgetPoint) const {
        return (widgetPoint - offset()) / scale();
    }

    // Fitted: not zoomed or panned since the last fit().
    bool fitted() const { return m_fitted; }
    void fit() {
        m_zoom = 1.0;
        m_pan = {};
        m_fitted = true;
    }
    // Zoom by `factor` around a widget point, which keeps its place; the zoom (relative to
    // fitting) stays within [lowest, highest].
    void zoomAround(const QPointF& widgetPoint, double factor, double lowest, double highest) {
        const QPointF picturePoint = fromWidget(widgetPoint);
        m_zoom = std::clamp(m_zoom * factor, lowest, highest);
        m_pan += widgetPoint - toWidget(picturePoint);
        leaveFit();
    }
    // The widget was resized since the user last zoomed or panned: keep widget = picture ·
    // scale + offset as it was (the picture stays where it was on the widget, at its size)
    // rather than what it framed.
    void keepPlace() {
        const double oldScale = fitScaleIn(m_movedAt) * m_zoom;
        const QPointF oldOffset = offsetIn(m_movedAt);
        m_zoom = oldScale / fitScale();
        m_pan += oldOffset - offset();
        m_movedAt = m_widget->size();
    }

    // A press, then moves: once the mouse has moved 4 widget pixels from the press it is a
    // drag, which pans; a release before that is a click.
    void press(const QPointF& at) {
        m_pressAt = at;
        m_panAtPress = m_pan;
        m_dragging = false;
    }
    // Whether the move panned.
    bool drag(const QPointF& at) {
        const QPointF delta = at - m_pressAt;
        if (!m_dragging && delta.manhattanLength() < 4.0) return false;
        m_dragging = true;
        m_pan = m_panAtPress + delta;
        leaveFit();
        return true;
    }
    bool dragging() const { return m_dragging; }

private:
    // The user zoomed or panned.
    void leaveFit() {
        m_fitted = false;
        m_movedAt = m_widget->size();
    }
    double fitScaleIn(const QSizeF& size) const {
        if (m_content.isEmpty()) return 1.0;
        const double fit = std::min((size.width() - 2.0 * m_margin) / m_content.width(),
                                    (size.height() - 2.0 * m_margin) / m_content.height());
        return std::max(kLeastFitScale, fit);
    }
    QPointF offsetIn(const QSizeF& size) const {
        return QPointF(size.width() / 2.0, size.height() / 2.0) -
               m_content.center() * (fitScaleIn(size) * m_zoom) + m_pan;
    }

    // A widget too small to hold the margins still maps every point somewhere.
    static constexpr double kLeastFitScale = 1e-9;

    const QWidget* m_widget;
    double m_margin;
    QRectF m_content;
    double m_zoom = 1.0;
    QPointF m_pan;
    bool m_fitted = true;
    QSize m_movedAt;  // the widget's size when the user last zoomed or panned
    QPointF m_pressAt, m_panAtPress;
    bool m_dragging = false;
};

}  // namespace rasterlab
