// A check box whose text wraps onto more lines when its dock is narrow (a long option in
// Portuguese, or in presentation mode's larger text), instead of being cut: its minimum
// width is its longest word, its height follows its width. As wide as its text, it looks and
// paints as a plain QCheckBox.
#pragma once

#include <QCheckBox>

namespace rasterlab {

class WrappingCheckBox : public QCheckBox {
    Q_OBJECT
public:
    explicit WrappingCheckBox(const QString& text, QWidget* parent = nullptr);

    QSize minimumSizeHint() const override;
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int width) const override;

protected:
    void paintEvent(QPaintEvent* event) override;
    bool hitButton(const QPoint& pos) const override { return rect().contains(pos); }

private:
    // What the box adds around its text on one line: the indicator, spacing and margins.
    QSize frame() const;
    QRect textRect(int width) const;  // the text wrapped at `width` (the widget's)
};

}  // namespace rasterlab
