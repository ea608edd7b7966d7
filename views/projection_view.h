// Stage 4's view: the projected triangles as a wireframe on the screen, in NDC or in pixels,
// with the image's window [-1, 1] drawn and a margin around it, each triangle coloured by
// its fate (drawn, clipped, culled, a hidden back face); a side view of view space showing
// the near plane and what clipping made there; the triangle being drawn and the one
// selected highlighted (a click selects); and the formulas with the numbers of the selected
// triangle's first vertex.
#pragma once

#include <QImage>
#include <QLineF>
#include <QPointF>
#include <QString>
#include <QVector>
#include <QWidget>

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "pipeline/render/frame_trace.h"
#include "pipeline/stages/projection.h"
#include "views/elided_label.h"
#include "views/zoom_pan.h"

class QLabel;
class QSplitter;
class QTextBrowser;
class QToolButton;

namespace rasterlab {

class KeyFigures;

class Inspection;

// What the wireframe's coordinates are: NDC as the projection divides (pNdc), or the pixels
// scan conversion receives (pScreen, after snapping). Either way the window is laid out as
// the image is, so the toggle only changes the numbers, and the snapping shows.
enum class ProjectionSpace { Ndc, Pixels };

// How many mesh triangles met each fate (the projection's counts), and how many screen
// triangles the clipped ones became.
struct FateCounts {
    std::size_t inside = 0, clipped = 0, behind = 0, clippedAway = 0, culled = 0, backFaces = 0,
                beyondGuardBand = 0, nonFinite = 0;
    std::size_t fanTriangles = 0;  // screen triangles of the clipped ones
};
FateCounts countFates(const rl::Projection& projection);

// The wireframe. Lines are built once per frame and space, and drawn (batched) into a cached
// layer that only a new frame, space, zoom, pan or size redraws; the current and the selected
// triangle are drawn over it. Wheel to zoom, drag to pan, click to select, double-click to fit.
class ProjectionCanvas : public QWidget {
    Q_OBJECT
public:
    // The colour groups of the wireframe.
    enum Group { Hidden, Drawn, Clipped, GroupCount };

    explicit ProjectionCanvas(QWidget* parent = nullptr);

    void setFrame(std::shared_ptr<const rl::FrameTrace> frame, ProjectionSpace space);
    void setHighlights(std::optional<std::uint32_t> current, std::optional<std::uint32_t> selected);
    void setLineWidth(double width);
    // A student's vertices where they depart from ours (Check My Renderer...): each pair ours
    // and theirs, in pixels; drawn as a red cross joined to ours until set again or the frame
    // changes.
    using VertexPair = std::pair<QPointF, QPointF>;
    void setTheirVertices(std::vector<VertexPair> pairs);
    const std::vector<VertexPair>& theirVertices() const { return m_theirs; }

    // Triangles drawn in each group: Hidden counts the culled triangles and the back faces,
    // Drawn the inside ones, Clipped the fan triangles of the clipped ones.
    std::size_t triangleCount(Group group) const { return m_triangles[group]; }
    std::size_t lineCount(Group group) const { return std::size_t(m_lines[group].size()); }
    std::optional<std::uint32_t> currentTriangle() const { return m_current; }
    std::optional<std::uint32_t> selectedTriangle() const { return m_selected; }

    // A vertex of a draw in the current space's own coordinates (pNdc or pScreen).
    QPointF spacePoint(std::uint32_t draw, std::uint32_t vertex) const;
    // Where a point of the current space lands in the widget, and back.
    QPointF toWidget(const QPointF& spacePoint) const;
    QPointF fromWidget(const QPointF& widgetPoint) const;
    // The widget position of a screen triangle's centroid (Projection::triangles index).
    QPointF widgetCentroid(std::uint32_t triangle) const;
    // The nearest screen triangle under a widget position.
    std::optional<std::uint32_t> triangleAt(const QPointF& widgetPoint) const;

    QSize sizeHint() const override { return {640, 480}; }

public slots:
    void fit();

signals:
    void triangleClicked(std::optional<std::uint32_t> triangle);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;

private:
    // Space coordinates to layout coordinates, where the image is [0, W] x [0, H], y down.
    QPointF layoutPoint(const QPointF& spacePoint) const;
    QPointF spaceFromLayout(const QPointF& layout) const;
    void buildLines();
    void paintLayer();
    void drawTriangle(QPainter& painter, std::uint32_t triangle, const QColor& colour,
                      bool fill) const;

    std::shared_ptr<const rl::FrameTrace> m_frame;
    std::vector<VertexPair> m_theirs;
    ProjectionSpace m_space = ProjectionSpace::Ndc;
    std::array<QVector<QLineF>, GroupCount> m_lines;  // layout coordinates
    std::array<std::size_t, GroupCount> m_triangles{};
    std::optional<std::uint32_t> m_current, m_selected;
    double m_lineWidth = 1.5;
    // Layout to widget. It fits the image and a margin of a quarter of it on every side, where
    // clipped and culled triangles that fall outside the window still show; it follows the
    // widget's size until the user zooms or pans.
    ZoomPan m_view{this, 0.0};
    QImage m_layer;  // the cached wireframe
    bool m_layerValid = false;
    bool m_pressed = false;
};

// View space from the side: view z (the clip w) to the right, y up, the camera at the origin,
// the near plane w = near, the frustum's top and bottom, every triangle's edges, the clipped
// triangles in orange with the vertices clipping made marked, and the selected triangle.
class ProjectionSideView : public QWidget {
    Q_OBJECT
public:
    explicit ProjectionSideView(QWidget* parent = nullptr);

    void setFrame(std::shared_ptr<const rl::FrameTrace> frame);
    void setSelected(std::optional<std::uint32_t> triangle);
    void setLineWidth(double width);

    std::size_t madeVertexCount() const { return std::size_t(m_made.size()); }
    std::size_t lineCount() const { return std::size_t(m_lines.size()); }
    QSize sizeHint() const override { return {640, 180}; }

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    QPointF toWidget(double w, double y) const;
    void paintLayer();

    std::shared_ptr<const rl::FrameTrace> m_frame;
    std::optional<std::uint32_t> m_selected;
    double m_lineWidth = 1.5;
    QVector<QLineF> m_lines, m_cutLines, m_keptLines, m_behindLines;  // (w, y)
    QVector<QPointF> m_made;
    double m_wMin = 0.0, m_wMax = 1.0, m_yMin = -1.0, m_yMax = 1.0;
    QImage m_layer;
    bool m_layerValid = false;
};

class ProjectionView : public QWidget {
    Q_OBJECT
public:
    explicit ProjectionView(Inspection* inspection, QWidget* parent = nullptr);

    void setSpace(ProjectionSpace space);

    // The fates counted from the frame shown.
    const FateCounts& counts() const { return m_counts; }
    // The legend as plain text ("inside 7776, clipped 0 (0 on screen), ...").
    QString legendText() const { return m_legendText; }
    QString explanationHtml() const { return m_explanationHtml; }
    ProjectionCanvas* canvas() const { return m_canvas; }
    ProjectionSideView* sideView() const { return m_side; }

protected:
    void showEvent(QShowEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void refresh();
    void refreshSelection();   // the highlights and the explanation
    void refreshHighlights();  // the triangles selected and being drawn
    void applyPresentation();
    QString vertexExplanation(std::uint32_t triangle) const;

    Inspection* m_inspection = nullptr;
    std::shared_ptr<const rl::FrameTrace> m_frame;
    ProjectionSpace m_space = ProjectionSpace::Ndc;
    bool m_dirty = true;
    FateCounts m_counts;
    QString m_legendText, m_explanationHtml;
    KeyFigures* m_figures = nullptr;  // the fates' counts, large

    QSplitter* m_splitter = nullptr;
    bool m_splitterPlaced = false;
    ProjectionCanvas* m_canvas = nullptr;
    ProjectionSideView* m_side = nullptr;
    QToolButton* m_ndcButton = nullptr;
    QToolButton* m_pixelsButton = nullptr;
    WrappedLabel* m_legend = nullptr;
    QTextBrowser* m_explanation = nullptr;
};

}  // namespace rasterlab
