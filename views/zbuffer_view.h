// Stage 6's view: the z-buffer as an image. Each pixel a triangle holds is coloured by its
// depth over a range (automatic: the nearest and farthest depth drawn; or set by hand), in
// grey (near white, far dark) or in false colour (near red, far blue); pixels no triangle
// holds show a checkerboard. Beside it, a histogram of the drawn depths in the same colours,
// and the value under the cursor.
#pragma once

#include <QImage>
#include <QPoint>
#include <QRgb>
#include <QWidget>
#include <memory>
#include <vector>

#include "pipeline/render/frame_trace.h"
#include "pipeline/stages/depth_test.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QBoxLayout;
class QLabel;
class QScrollArea;

namespace rasterlab {

class KeyFigures;

class FrameImageView;

struct DepthRange {
    float nearest = 0.0f, farthest = 1.0f;
    bool valid = false;  // false: no pixel holds a triangle
};

enum class DepthPalette { Grey, FalseColour };

// The nearest and farthest depth among the pixels a triangle holds.
DepthRange coveredDepthRange(const rl::DepthTest& depth);

// The colour of depth z: t = (z - nearest) / (farthest - nearest), clamped to [0, 1]
// (t = 0 when the range is a single value); grey 255 - 239 t, or the false-colour ramp.
QRgb depthColour(float z, const DepthRange& range, DepthPalette palette);

// The colour of a pixel no triangle holds: a checkerboard of 8-pixel squares.
QRgb emptyPixelColour(int x, int y);

QImage depthImage(const rl::DepthTest& depth, const DepthRange& range, DepthPalette palette);

struct DepthHistogram {
    std::vector<int> counts;   // covered pixels per bin, bins of equal width over the range
    int below = 0, above = 0;  // covered pixels outside the range
};
DepthHistogram depthHistogram(const rl::DepthTest& depth, const DepthRange& range, int bins);

// Paints a DepthHistogram as bars in the palette's colours.
class DepthHistogramWidget : public QWidget {
public:
    explicit DepthHistogramWidget(QWidget* parent = nullptr);
    void setHistogram(DepthHistogram histogram, const DepthRange& range, DepthPalette palette);
    QSize sizeHint() const override { return {240, 90}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    DepthHistogram m_histogram;
    DepthRange m_range;
    DepthPalette m_palette = DepthPalette::Grey;
};

class ZBufferView : public QWidget {
    Q_OBJECT
public:
    explicit ZBufferView(QWidget* parent = nullptr);

    // The frame, and the buffers at the stepping cursor (held until the next setBuffers or
    // setFrame), or null for the frame's own; `tested` and `written` fragments so far. While the
    // view is hidden the image waits until it is shown.
    void setFrame(std::shared_ptr<const rl::FrameTrace> frame);
    void setBuffers(std::shared_ptr<const rl::DepthTest> buffers, std::size_t tested,
                    std::size_t written);
    QString explanation() const;
    void setAutomaticRange(bool automatic);
    void setManualRange(float nearest, float farthest);  // also turns the automatic range off
    void setPalette(DepthPalette palette);

    DepthRange range() const { return m_range; }
    bool automaticRange() const;
    DepthPalette palette() const { return m_palette; }
    const QImage& image() const { return m_image; }
    const DepthHistogram& histogram() const { return m_histogram; }
    // What the pixel holds: its depth and triangle, or that no triangle covers it.
    QString valueText(QPoint pixel) const;
    FrameImageView* imageView() const { return m_view; }
    // Pixels marked red over the buffer until the next frame: where a student's z-buffer keeps
    // another triangle than ours (Check My Renderer...).
    void markPixels(const std::vector<QPoint>& pixels);
    std::size_t markedPixels() const { return m_marked; }

protected:
    void showEvent(QShowEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;
    bool event(QEvent* event) override;  // kRaisedEvent (on_screen.h)

private:
    void arrange();  // the words beside the image or below it, by the view's shape
    void refresh();
    void refreshWhenShown();
    void showValue(QPoint pixel);
    const rl::DepthTest* shown() const;

    std::shared_ptr<const rl::FrameTrace> m_frame;
    std::shared_ptr<const rl::DepthTest> m_buffers;
    std::size_t m_tested = 0, m_written = 0;
    std::size_t m_marked = 0;
    bool m_stale = false;
    QLabel* m_explanation = nullptr;
    DepthRange m_range;
    DepthPalette m_palette = DepthPalette::Grey;
    QImage m_image;
    DepthHistogram m_histogram;
    FrameImageView* m_view = nullptr;
    DepthHistogramWidget* m_histogramWidget = nullptr;
    QCheckBox* m_automatic = nullptr;
    QDoubleSpinBox* m_nearest = nullptr;
    QDoubleSpinBox* m_farthest = nullptr;
    QComboBox* m_paletteBox = nullptr;
    QLabel* m_rangeLabel = nullptr;
    QLabel* m_valueLabel = nullptr;
    KeyFigures* m_figures = nullptr;  // the fragments' counts and the depths, large
    QScrollArea* m_panel = nullptr;
    QBoxLayout* m_layout = nullptr;
};

}  // namespace rasterlab
