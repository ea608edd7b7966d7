// Labels that fit their text to the room they are given.
//
// ElidedLabel: a one-line label that elides its text ("…") when it is narrower than the text, with the
// whole text in its tooltip then: for a note in a toolbar or a row that cannot grow.
#pragma once

#include <QLabel>

namespace rasterlab {

class ElidedLabel : public QLabel {
    Q_OBJECT
public:
    explicit ElidedLabel(QWidget* parent = nullptr);

    void setFullText(const QString& text);
    QString fullText() const { return m_text; }
    int wholeWidth(const QString& text) const;  // the width that shows `text` unelided
    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;

protected:
    void showEvent(QShowEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    void elide();

    QString m_text;
};

// A word-wrapped label whose minimum height is the height of its lines at its width: a
// splitter, unlike a layout, does not ask a label how high its wrapped text is, and would
// squeeze the last lines away.
class WrappedLabel : public QLabel {
    Q_OBJECT
public:
    explicit WrappedLabel(QWidget* parent = nullptr);

    // QLabel::setText, then the minimum height for the new text (hides QLabel's).
    void setText(const QString& text);

protected:
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    void fitHeight();
};

}  // namespace rasterlab
