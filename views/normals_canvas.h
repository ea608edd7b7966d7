// The normals view's canvas: the wireframe and the normal hairs of a NormalsPicture.
#pragma once

#include <QColor>
#include <QImage>
#include <QPoint>
#include <QWidget>

#include "views/zoom_pan.h"

namespace rasterlab {

struct NormalsPicture;

// Paints a NormalsPicture fitted to the widget: wheel to zoom around the mouse, drag to
// pan, double-click to fit; a click picks the pixel under it.
class NormalsCanvas : public QWidget {
    Q_OBJECT
public:
    explicit NormalsCanvas(QWidget* parent = nullptr);
    // Repaints; null for nothing. Fitted again when the picture's focus moved (another mesh
    // or framing); the same focus (a step, a selection) keeps the zoom.
    void setPicture(const NormalsPicture* picture);
    void setLineWidth(double width);
    void setHairs(bool triangles, bool vertices);
    void setWrongHairs(bool on);
    QSize sizeHint() const override { return {640, 480}; }

    // The colours of the drawing, which the view's legend names too.
    static inline const QColor kFrontColour{200, 204, 214};
    static inline const QColor kBackColour{235, 64, 52};
    static inline const QColor kInconsistentColour{235, 60, 235};
    static inline const QColor kSelectedColour{255, 214, 10};
    static inline const QColor kTriangleHairColour{255, 160, 40};
    static inline const QColor kVertexHairColour{70, 200, 255};
    static inline const QColor kWrongHairColour{150, 255, 80};

signals:
    void pixelPicked(QPoint pixel);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;

private:
    void redraw();  // the cached layer is out of date
    void paintCache();

    const NormalsPicture* m_picture = nullptr;
    double m_lineWidth = 1.5;
    bool m_triangleHairs = true, m_vertexHairs = false, m_wrongHairs = false;
    ZoomPan m_view{this, 4.0};  // image pixels to widget; fits the picture's focus
    QImage m_cache;             // the wireframe and hairs at the current size, zoom and pan
    bool m_cacheValid = false;
};

}  // namespace rasterlab
