// Shows a rendered image: fit to the window or zoom around the mouse with the wheel, pan
// by dragging, and at high zoom a pixel grid with the pixels' sample points (their centres,
// or their corners under the course's rules), so single pixels
// can be told apart. Reports the pixel under the mouse and the pixel clicked.
#pragma once

#include <QImage>
#include <QPoint>
#include <QPointF>
#include <QWidget>

#include <array>
#include <optional>
#include <vector>

namespace rasterlab {

// What is drawn over the image while stepping and inspecting, in image coordinates: pixel
// (x, y) is the square [x, x + 1) x [y, y + 1) and is sampled at (x + o, y + o), o the rules'
// sample offset (0: the course samples pixel corners; 0.5: centres).
struct ImageOverlay {
    double sampleOffset = 0.5;
    std::optional<std::array<QPointF, 3>> currentTriangle;   // screen vertices, pixels
    std::optional<std::array<QPointF, 3>> selectedTriangle;  // screen vertices, pixels
    int scanline = -1;                                       // the current row, or -1
    int spanBegin = 0, spanEnd = 0;                          // its pixels [begin, end)
    std::optional<std::pair<double, double>> crossings;      // the edges' x on that row
    std::vector<QPoint> coveredPixels;  // the current triangle's pixels tested so far
    QPoint currentPixel{-1, -1};        // the last fragment tested
    QPoint pickedPixel{-1, -1};
    std::vector<QPointF> vertices;  // selected vertices (screen, pixels)
    QImage coverage;                // a translucent mask over the whole image, or null
    double lineWidth = 1.5;
};

class FrameImageView : public QWidget {
    Q_OBJECT
public:
    explicit FrameImageView(QWidget* parent = nullptr);

    void setImage(const QImage& image);  // keeps the zoom and pan if the size is unchanged
    const QImage& image() const { return m_image; }
    void setOverlay(ImageOverlay overlay);
    // Whether the arrow keys move the picked pixel (off in presentation mode: they step).
    void setArrowsMovePick(bool on) { m_arrowsMovePick = on; }
    const ImageOverlay& overlay() const { return m_overlay; }
    // The widget position of an image point (pixels, fractional).
    QPointF widgetPoint(const QPointF& imagePoint) const;

    double zoom() const { return m_zoom; }
    bool fitsWindow() const { return m_fit; }
    // The image point at the view's centre; showAt puts an image point there, at a zoom.
    QPointF centrePoint() const;
    void showAt(double zoom, const QPointF& imagePoint);
    // The image pixel under a widget position, or (-1, -1) outside the image.
    QPoint pixelAt(const QPointF& widgetPos) const;

    QSize sizeHint() const override { return m_preferredSize; }
    // The size asked of a layout (800 x 600 unless set): small where the view only takes
    // the room that others leave.
    void setPreferredSize(QSize size) {
        m_preferredSize = size;
        updateGeometry();
    }

public slots:
    void fitToWindow();
    void zoomToActualSize();
    void zoomIn();
    void zoomOut();

signals:
    void pixelHovered(QPoint pixel);  // (-1, -1) when the mouse leaves the image
    void pixelPicked(QPoint pixel);   // clicked, or the picked one moved with the arrow keys
    void zoomChanged(double zoom);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    bool event(QEvent* event) override;

private:
    void setZoomAround(double zoom, const QPointF& widgetPos);
    void paintOverlay(QPainter& painter) const;
    static std::optional<QPoint> arrowStep(int key);
    double fitZoom() const;
    QPointF imageOrigin() const;  // widget position of the image's top-left corner
    QRect visiblePixels() const;  // the image's pixels the widget shows, wholly or in part

    static constexpr double kMinZoom = 0.05;
    static constexpr double kMaxZoom = 64.0;
    static constexpr double kGridFromZoom = 8.0;  // draw the pixel grid from this zoom on

    QImage m_image;
    ImageOverlay m_overlay;
    double m_zoom = 1.0;
    bool m_fit = true;
    QPointF m_offset;  // pan, in widget pixels, of the image centre from the widget centre
    QPoint m_dragStart;
    QPointF m_offsetAtDragStart;
    bool m_dragging = false;
    bool m_arrowsMovePick = true;
    QSize m_preferredSize{800, 600};
};

}  // namespace rasterlab
