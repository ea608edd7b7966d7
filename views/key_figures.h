// A stage's key numbers on one line (wrapped when narrow), half as large again as the text of
// the view around them and bold, so that a class reads them from the back of the room (and
// OCR on a screenshot shrunk to half size). The size follows the view's font: the dock's,
// which presentation mode and the window's text zoom enlarge. A WrappedLabel: in a splitter
// it keeps the height of its lines. Shown only where the view has the room (16 of its lines
// high, or more): a short dock keeps its drawing and its text.
#pragma once

#include <QPointer>

#include "views/elided_label.h"

namespace rasterlab {

class KeyFigures : public WrappedLabel {
    Q_OBJECT
public:
    // `view`: the widget whose font it follows (its parent).
    explicit KeyFigures(QWidget* view);

    // WrappedLabel::setText, and shown or not by the room.
    void setText(const QString& text);

    static constexpr double kScale = 1.5;
    static constexpr int kLeastLines = 16;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void follow();
    void showByRoom();

    QWidget* m_view;
    QPointer<QWidget> m_room;  // the view's parent (a dock's viewport): the height it shows
};

}  // namespace rasterlab
