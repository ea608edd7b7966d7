#include "elided_label.h"

#include <QEvent>
#include <QSplitter>

namespace rasterlab {

ElidedLabel::ElidedLabel(QWidget* parent) : QLabel(parent) {
    setTextFormat(Qt::PlainText);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
}

void ElidedLabel::setFullText(const QString& text) {
    if (text == m_text) return;
    m_text = text;
    updateGeometry();
    elide();
}

int ElidedLabel::wholeWidth(const QString& text) const {
    const int margins = contentsMargins().left() + contentsMargins().right() + 2 * margin();
    return fontMetrics().horizontalAdvance(text) + margins;
}

QSize ElidedLabel::sizeHint() const {
    return {wholeWidth(m_text), QLabel::minimumSizeHint().height()};
}

QSize ElidedLabel::minimumSizeHint() const {
    // A few letters and the ellipsis.
    return {std::min(sizeHint().width(), fontMetrics().horizontalAdvance(QStringLiteral("MMM\u2026"))),
            sizeHint().height()};
}

void ElidedLabel::showEvent(QShowEvent* event) {
    QLabel::showEvent(event);
    elide();
}

void ElidedLabel::resizeEvent(QResizeEvent* event) {
    QLabel::resizeEvent(event);
    elide();
}

void ElidedLabel::changeEvent(QEvent* event) {
    QLabel::changeEvent(event);
    if (event->type() == QEvent::FontChange) elide();
}

void ElidedLabel::elide() {
    // Until it is shown, the label has no width of its own yet: whole.
    const QString shown =
        !isVisible() ? m_text
                     : fontMetrics().elidedText(m_text, Qt::ElideRight,
                                                contentsRect().width() - 2 * margin());
    setText(shown);
    setToolTip(shown == m_text ? QString() : m_text);
}

WrappedLabel::WrappedLabel(QWidget* parent) : QLabel(parent) {
    setWordWrap(true);
}

void WrappedLabel::setText(const QString& text) {
    QLabel::setText(text);
    fitHeight();
}

void WrappedLabel::resizeEvent(QResizeEvent* event) {
    QLabel::resizeEvent(event);
    fitHeight();
}

void WrappedLabel::changeEvent(QEvent* event) {
    QLabel::changeEvent(event);
    if (event->type() == QEvent::FontChange) fitHeight();
}

void WrappedLabel::fitHeight() {
    // QLabel::heightForWidth is never below the minimum height: without it for the measure,
    // or a label made wider would keep the height of its narrower lines.
    const int before = minimumHeight();
    setMinimumHeight(0);
    const int height = width() > 0 ? heightForWidth(width()) : 0;
    if (height <= 0 || height == before) {
        setMinimumHeight(before);
        return;
    }
    setMinimumHeight(height);
    // A splitter above moves its handles for the new minimum only when told.
    for (QWidget* w = parentWidget(); w; w = w->parentWidget())
        if (auto* splitter = qobject_cast<QSplitter*>(w)) {
            splitter->refresh();
            break;
        }
}

}  // namespace rasterlab
