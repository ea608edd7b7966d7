#include "key_figures.h"

#include <QEvent>

namespace rasterlab {

KeyFigures::KeyFigures(QWidget* view) : WrappedLabel(view), m_view(view) {
    setObjectName(QStringLiteral("keyFigures"));
    setTextFormat(Qt::PlainText);
    setTextInteractionFlags(Qt::TextSelectableByMouse);
    // The height of its lines, at the top: a column's spare height goes below it.
    setAlignment(Qt::AlignLeft | Qt::AlignTop);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Maximum);
    m_view->installEventFilter(this);
    follow();
    setVisible(false);
}

void KeyFigures::setText(const QString& text) {
    WrappedLabel::setText(text);
    showByRoom();
}

bool KeyFigures::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_view && event->type() == QEvent::FontChange) follow();
    if (watched == m_view && event->type() == QEvent::ParentChange) showByRoom();
    if ((watched == m_view || watched == m_room) && event->type() == QEvent::Resize)
        showByRoom();
    return WrappedLabel::eventFilter(watched, event);
}

void KeyFigures::follow() {
    QFont font = m_view->font();
    font.setPointSizeF(font.pointSizeF() * kScale);
    font.setBold(true);
    setFont(font);
    showByRoom();
}

void KeyFigures::showByRoom() {
    // The room is what the view's parent shows (the view itself may be taller, scrolled).
    QWidget* room = m_view->parentWidget() ? m_view->parentWidget() : m_view;
    if (room != m_room) {
        if (m_room && m_room != m_view) m_room->removeEventFilter(this);
        m_room = room;
        if (m_room != m_view) m_room->installEventFilter(this);
    }
    const int least = kLeastLines * m_view->fontMetrics().lineSpacing();
    const bool shown = !text().isEmpty() && room->height() >= least;
    if (shown == isHidden()) setVisible(shown);
}

}  // namespace rasterlab
