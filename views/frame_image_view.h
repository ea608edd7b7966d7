// Shows a rendered image: fit to the window or zoom around the mouse with the wheel, pan
// by dragging, and at high zoom a pixel grid with the pixel centres, so single pixels
// can be told apart. Reports the pixel under the mouse and the pixel clicked.
#pragma once

#include <QImage>
#include <QPoint>
#include <QPointF>
#include <QWidget>

namespace rasterlab {

class FrameImageView : public QWidget {
    Q_OBJECT
public:
    explicit FrameImageView(QWidget* parent = nullptr);

    void setImage(const QImage& image);  // keeps the zoom and pan if the size is unchanged
    const QImage& image() const { return m_image; }

    double zoom() const { return m_zoom; }
    bool fitsWindow() const { return m_fit; }
    // The image pixel under a widget position, or (-1, -1) outside the image.
    QPoint pixelAt(const QPointF& widgetPos) const;

    QSize sizeHint() const override { return {800, 600}; }

public slots:
    void fitToWindow();
    void zoomToActualSize();
    void zoomIn();
    void zoomOut();

signals:
    void pixelHovered(QPoint pixel);  // (-1, -1) when the mouse leaves the image
    void pixelPicked(QPoint pixel);
    void zoomChanged(double zoom);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;

private:
    void setZoomAround(double zoom, const QPointF& widgetPos);
    double fitZoom() const;
    QPointF imageOrigin() const;  // widget position of the image's top-left corner

    static constexpr double kMinZoom = 0.05;
    static constexpr double kMaxZoom = 64.0;
    static constexpr double kGridFromZoom = 8.0;  // draw the pixel grid from this zoom on

    QImage m_image;
    double m_zoom = 1.0;
    bool m_fit = true;
    QPointF m_offset;  // pan, in widget pixels, of the image centre from the widget centre
    QPoint m_dragStart;
    QPointF m_offsetAtDragStart;
    bool m_dragging = false;
};

}  // namespace rasterlab
