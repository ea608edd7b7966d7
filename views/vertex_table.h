// The vertices of a frame as a table: one row per vertex of every draw as the projection
// numbers them (the draw's own vertices, then those made by clipping), with its position in
// every space the pipeline carries it through (world, view, NDC, screen) and its view-space
// normal. Values are worked out when a cell is shown, so a 46,000-vertex model costs only
// the rows on screen. Selecting rows selects those vertices in the Inspection; a pixel picked
// elsewhere selects its triangle's three rows. Below the table, the selected vertex's
// numbers substituted in each formula.
#pragma once

#include <QAbstractTableModel>
#include <QWidget>

#include <memory>
#include <optional>
#include <vector>

#include "pipeline/render/frame_trace.h"
#include "views/inspection.h"

class QCheckBox;
class QLabel;
class QSortFilterProxyModel;
class QTableView;
class QTextBrowser;

namespace rasterlab {

class VertexTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Draw, Vertex, World, View, Ndc, Screen, Normal, ColumnCount };

    explicit VertexTableModel(QObject* parent = nullptr);

    void setFrame(std::shared_ptr<const rl::FrameTrace> frame);
    const std::shared_ptr<const rl::FrameTrace>& frame() const { return m_frame; }

    int rowCount(const QModelIndex& parent = QModelIndex()) const override;
    int columnCount(const QModelIndex& parent = QModelIndex()) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    // Vectors written one component a line, and the titles on two lines, for a narrow table.
    void setStacked(bool on);
    bool stacked() const { return m_stacked; }

    // Rows and vertices, both ways: -1 for a vertex the frame does not have.
    int rowOf(VertexRef vertex) const;
    VertexRef vertexAt(int row) const;  // row in [0, rowCount())

    // The vertex's position in world space, (x, y, z) / w: worldFromModel * the mesh's
    // position, or, for a vertex made by clipping, interpolated along its edge as pView is.
    rl::dvec3 worldOf(VertexRef vertex) const;
    // Its view-space normal as shading reads it (made vertices: mixed along their edge,
    // not normalised), or nothing when the normals stage was skipped.
    std::optional<rl::vec3> normalOf(VertexRef vertex) const;

private:
    QString shown(const QString& vectorText, int role) const;
    rl::dvec4 worldHomogeneous(std::uint32_t draw, std::uint32_t vertex) const;

    std::shared_ptr<const rl::FrameTrace> m_frame;
    std::vector<int> m_firstRow;  // per draw, then the total
    bool m_stacked = false;
};

class VertexTableView : public QWidget {
    Q_OBJECT
public:
    explicit VertexTableView(Inspection* inspection, QWidget* parent = nullptr);

    VertexTableModel* model() const { return m_model; }
    QTableView* table() const { return m_table; }
    // The rows (of the model) selected in the table, in order.
    std::vector<int> selectedRows() const;
    // The rows shown: all, or only those of the selected triangle.
    int visibleRowCount() const;
    void setOnlySelectedTriangle(bool on);
    // The vertex explained below the table, and the explanation as plain text.
    std::optional<VertexRef> explainedVertex() const { return m_explained; }
    QString explanationText() const;

protected:
    void showEvent(QShowEvent* event) override;
    void changeEvent(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void refreshFrame();
    void followSelection();
    void tableSelectionChanged();
    void explain(std::optional<VertexRef> vertex);
    QString explanationHtml(VertexRef vertex) const;
    void applyPresentation();
    void fitColumns();
    int measureColumns();  // the columns' widths for the model's layout, and their sum

    Inspection* m_inspection = nullptr;
    VertexTableModel* m_model = nullptr;
    QSortFilterProxyModel* m_proxy = nullptr;
    QTableView* m_table = nullptr;
    QCheckBox* m_onlyTriangle = nullptr;
    QLabel* m_summary = nullptr;
    QTextBrowser* m_explanation = nullptr;
    std::optional<VertexRef> m_explained;
    bool m_dirty = true;       // a frame came while hidden
    bool m_selecting = false;  // the table is being set from the Inspection, or the other way
};

}  // namespace rasterlab
