// The font a view's part takes: the view's own (the dock's, which the window sizes for
// presentation mode and the text zoom), or, where a view enlarges text itself, that times
// a factor. A part whose font is set to an explicit size no longer follows its parents', so
// the factor 1 sets nothing.
#pragma once

#include <QFont>
#include <QWidget>

namespace rasterlab {

// For part->setFont(): nothing set (the parent's font, whatever its size) when `scale` is 1;
// otherwise the parent's font `scale` times as large. Call again on QEvent::FontChange of
// the parent.
inline QFont scaledFont(const QWidget* parent, double scale) {
    if (scale == 1.0) return QFont();
    QFont font = parent ? parent->font() : QFont();
    font.setPointSizeF(font.pointSizeF() * scale);
    return font;
}

// The font a custom-painted view draws its labels with: its own, `factor` times as large
// (0.9: a little smaller than the text around it, as labels on a drawing are).
inline QFont labelFont(const QWidget* view, double factor) {
    QFont font = view->font();
    font.setPointSizeF(font.pointSizeF() * factor);
    return font;
}

}  // namespace rasterlab
