// Stage 3's view: the normals. The mesh as the frame projected it, a thin wireframe in screen
// space, with normal "hairs" (each triangle's from its centroid, each vertex's from the
// vertex), the view-space normal carried to the screen by the draw's projection. Back faces
// (n . pView > 0: the normal points away from the camera at the origin) are drawn in red,
// triangles whose winding disagrees with a neighbour's (a shared edge run the same way by
// both) in magenta, with their counts. A second tab shows the normal map: per pixel, the
// normal shading uses there (interpolated with the pixel's barycentrics at the stepping
// cursor, normalised and turned toward the viewer) as the colour (n + 1) / 2. On request,
// beside each triangle normal, the wrong one (seed 002): the model-space normal carried by
// viewFromModel itself instead of its inverse transpose, which leaves the surface under a
// non-uniform scale (the animation panel's scale).
#pragma once

#include <QImage>
#include <QPoint>
#include <QString>
#include <QWidget>

#include <cstdint>
#include <memory>

#include "pipeline/render/frame_trace.h"
#include "views/normals_canvas.h"
#include "views/normals_model.h"

class QCheckBox;
class QLabel;
class QSplitter;
class QTabWidget;
class QTextBrowser;

namespace rasterlab {

class KeyFigures;

class FrameImageView;
class Inspection;

class NormalsView : public QWidget {
    Q_OBJECT
public:
    explicit NormalsView(Inspection* inspection, QWidget* parent = nullptr);

    const NormalsPicture& picture() const { return m_model.picture(); }
    // The normal map at the cursor (worked out while its tab is shown, or when asked here).
    const QImage& normalMap();
    void setTriangleHairs(bool on);
    void setVertexHairs(bool on);
    // Hairs only on the triangles holding a pixel at the end of the frame (and their corners).
    void setOnlyVisibleHairs(bool on);
    bool onlyVisibleHairs() const;
    // Beside each triangle normal, the normal carried by viewFromModel instead of its inverse
    // transpose (wrong under a non-uniform scale), and both worked out for the selected one.
    void setWrongNormals(bool on);
    bool wrongNormals() const;
    void showNormalMap(bool on);  // the normal-map tab, or the mesh
    QString legendText() const;
    QString explanationText() const;
    NormalsCanvas* canvas() const { return m_canvas; }
    FrameImageView* normalMapView() const { return m_mapView; }

protected:
    void showEvent(QShowEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void refreshGeometry();
    void refreshSelection();
    void refreshMap();
    void refreshLegend();
    void refreshExplanation();
    QString wrongNormalHtml(const rl::FrameTrace& frame, std::uint32_t draw,
                            std::uint32_t triangle) const;
    void showPixelValue(QPoint pixel);
    bool mapShown() const;

    Inspection* m_inspection = nullptr;
    NormalsModel m_model;
    std::unique_ptr<PixelNormals> m_pixelNormals;
    QImage m_map;
    bool m_geometryDirty = true, m_mapDirty = true;
    QTabWidget* m_tabs = nullptr;
    NormalsCanvas* m_canvas = nullptr;
    FrameImageView* m_mapView = nullptr;
    QCheckBox* m_triangleHairs = nullptr;
    QCheckBox* m_vertexHairs = nullptr;
    QCheckBox* m_onlyVisible = nullptr;
    QCheckBox* m_wrong = nullptr;
    QLabel* m_legend = nullptr;
    QLabel* m_pixelValue = nullptr;
    QTextBrowser* m_explanation = nullptr;
    KeyFigures* m_figures = nullptr;  // the selected triangle's normal, large
    QSplitter* m_splitter = nullptr;
    QWidget* m_words = nullptr;  // the switches, the legend and the explanation
    bool m_splitMoved = false;  // the splitter's handle moved by hand
};

}  // namespace rasterlab
