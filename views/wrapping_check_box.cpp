#include "wrapping_check_box.h"

#include <QRegularExpression>
#include <QStyleOptionButton>
#include <QStylePainter>

#include <algorithm>

namespace rasterlab {

namespace {

constexpr int kTextFlags = Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap | Qt::TextShowMnemonic;

}  // namespace

WrappingCheckBox::WrappingCheckBox(const QString& text, QWidget* parent)
    : QCheckBox(text, parent) {
    // QCheckBox's Minimum policy would hold it to its one-line width; Preferred lets it shrink
    // to minimumSizeHint() and take the height of its wrapped lines, as a word-wrapped QLabel.
    QSizePolicy policy(QSizePolicy::Preferred, QSizePolicy::Preferred, QSizePolicy::CheckBox);
    policy.setHeightForWidth(true);
    setSizePolicy(policy);
}

QSize WrappingCheckBox::frame() const {
    const QSize line = QCheckBox::sizeHint();
    return {line.width() - fontMetrics().size(Qt::TextShowMnemonic, text()).width(),
            std::max(0, line.height() - fontMetrics().height())};
}

QRect WrappingCheckBox::textRect(int width) const {
    return fontMetrics().boundingRect(QRect(0, 0, std::max(1, width - frame().width()), 100000),
                                      kTextFlags, text());
}

QSize WrappingCheckBox::minimumSizeHint() const {
    int widest = 0;
    static const QRegularExpression space(QStringLiteral("\\s+"));
    for (const QString& word : text().split(space, Qt::SkipEmptyParts))
        widest = std::max(widest, fontMetrics().size(Qt::TextShowMnemonic, word).width());
    return {frame().width() + widest, QCheckBox::sizeHint().height()};
}

int WrappingCheckBox::heightForWidth(int width) const {
    return std::max(QCheckBox::sizeHint().height(), textRect(width).height() + frame().height());
}

void WrappingCheckBox::paintEvent(QPaintEvent* event) {
    if (width() >= QCheckBox::sizeHint().width()) {
        QCheckBox::paintEvent(event);  // one line: the style's own check box
        return;
    }
    QStylePainter painter(this);
    QStyleOptionButton option;
    initStyleOption(&option);
    // The indicator beside the first line, the text wrapped beside it.
    const int firstLine = QCheckBox::sizeHint().height();
    QStyleOptionButton indicator = option;
    indicator.rect = style()->subElementRect(QStyle::SE_CheckBoxIndicator, &option, this);
    indicator.rect.moveTop((firstLine - indicator.rect.height()) / 2);
    painter.drawPrimitive(QStyle::PE_IndicatorCheckBox, indicator);
    QRect text = style()->subElementRect(QStyle::SE_CheckBoxContents, &option, this);
    text.setTop(frame().height() / 2);
    text.setBottom(height());
    painter.drawItemText(text, kTextFlags, palette(), isEnabled(), this->text(),
                         QPalette::WindowText);
    if (option.state & QStyle::State_HasFocus) {
        QStyleOptionFocusRect focus;
        focus.QStyleOption::operator=(option);
        focus.rect = fontMetrics().boundingRect(text, kTextFlags, this->text()).adjusted(-1, 0, 1, 0);
        painter.drawPrimitive(QStyle::PE_FrameFocusRect, focus);
    }
}

}  // namespace rasterlab
