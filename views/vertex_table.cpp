#include "vertex_table.h"

#include <QApplication>
#include <QCheckBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelection>
#include <QLabel>
#include <QScrollBar>
#include <QSortFilterProxyModel>
#include <QSplitter>
#include <QTableView>
#include <QTextBrowser>
#include <QTextDocument>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

#include "pipeline/stages/shading.h"
#include "views/number_text.h"
#include "views/view_font.h"
#include "views/wrapping_check_box.h"

namespace rasterlab {

namespace {

// Keeps the rows of one triangle's vertices, or all rows.
class TriangleFilter : public QSortFilterProxyModel {
public:
    using QSortFilterProxyModel::QSortFilterProxyModel;
    void setRows(std::optional<std::vector<int>> rows) {
        if (rows) std::sort(rows->begin(), rows->end());
        if (rows == m_rows) return;
        m_rows = std::move(rows);
        invalidateFilter();
    }

protected:
    bool filterAcceptsRow(int row, const QModelIndex&) const override {
        return !m_rows || std::binary_search(m_rows->begin(), m_rows->end(), row);
    }

private:
    std::optional<std::vector<int>> m_rows;  // sorted; nothing: every row
};

}  // namespace

// ---------------------------------------------------------------------------------------

VertexTableModel::VertexTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void VertexTableModel::setFrame(std::shared_ptr<const rl::FrameTrace> frame) {
    beginResetModel();
    m_frame = std::move(frame);
    m_firstRow.assign(1, 0);
    if (m_frame && m_frame->projection) {
        for (const rl::DrawProjection& d : m_frame->projection->draws)
            m_firstRow.push_back(m_firstRow.back() + static_cast<int>(d.pView.size()));
    }
    endResetModel();
}

int VertexTableModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() || m_firstRow.empty() ? 0 : m_firstRow.back();
}

int VertexTableModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

int VertexTableModel::rowOf(VertexRef vertex) const {
    if (vertex.draw + 1 >= m_firstRow.size()) return -1;
    const int row = m_firstRow[vertex.draw] + static_cast<int>(vertex.vertex);
    return row < m_firstRow[vertex.draw + 1] ? row : -1;
}

VertexRef VertexTableModel::vertexAt(int row) const {
    // The last draw whose first row is at or before row.
    const auto it = std::upper_bound(m_firstRow.begin(), m_firstRow.end() - 1, row);
    const auto draw = static_cast<std::uint32_t>(std::distance(m_firstRow.begin(), it) - 1);
    return {draw, static_cast<std::uint32_t>(row - m_firstRow[draw])};
}

rl::dvec4 VertexTableModel::worldHomogeneous(std::uint32_t draw, std::uint32_t vertex) const {
    const rl::DrawProjection& proj = m_frame->projection->draws[draw];
    if (vertex >= proj.originalVertexCount) {
        // Clipping is a lerp in view space, and view = (affine) * world: the same lerp.
        const rl::ClipVertex& g = proj.generated[vertex - proj.originalVertexCount];
        const rl::dvec4 a = worldHomogeneous(draw, g.a);
        return a + g.t * (worldHomogeneous(draw, g.b) - a);
    }
    // M(t) * worldFromModel, as the view transform used it (animation.h).
    return m_frame->view->worldFromModel[draw] *
           m_frame->scene->draws[draw].mesh->positions[vertex];
}

rl::dvec3 VertexTableModel::worldOf(VertexRef vertex) const {
    return rl::cartesian(worldHomogeneous(vertex.draw, vertex.vertex));
}

std::optional<rl::vec3> VertexTableModel::normalOf(VertexRef vertex) const {
    if (!m_frame || !m_frame->normals || m_frame->normals->skipped ||
        vertex.draw >= m_frame->normals->draws.size())
        return std::nullopt;
    // As shading extends the normals to made vertices: mixed, not normalised.
    return rl::projectedValue(m_frame->normals->draws[vertex.draw].vertex,
                              m_frame->projection->draws[vertex.draw], vertex.vertex);
}

void VertexTableModel::setStacked(bool on) {
    if (on == m_stacked) return;
    m_stacked = on;
    emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
    if (rowCount() > 0) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
}

QString VertexTableModel::shown(const QString& vectorText, int role) const {
    // "(x, y, z)" as x, y and z on three lines.
    if (!m_stacked || role != Qt::DisplayRole || !vectorText.startsWith(QLatin1Char('(')))
        return vectorText;
    return vectorText.mid(1, vectorText.size() - 2).split(QStringLiteral(", ")).join(QLatin1Char('\n'));
}

QVariant VertexTableModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || !m_frame || index.row() >= rowCount()) return {};
    if (role != Qt::DisplayRole && role != Qt::ToolTipRole) return {};
    const VertexRef ref = vertexAt(index.row());
    const rl::DrawProjection& proj = m_frame->projection->draws[ref.draw];
    const std::uint32_t v = ref.vertex;
    const bool made = v >= proj.originalVertexCount;
    const bool inFront = proj.inFront[v] != 0;
    switch (index.column()) {
        case Draw:
            if (role == Qt::ToolTipRole)
                return QString::fromStdString(m_frame->scene->draws[ref.draw].name);
            return ref.draw + 1;
        case Vertex: {
            if (!made) return v + 1;
            const rl::ClipVertex& g = proj.generated[v - proj.originalVertexCount];
            const QString text = tr("%1 made by clipping (edge %2-%3, t = %4)")
                                     .arg(v + 1)
                                     .arg(g.a + 1)
                                     .arg(g.b + 1)
                                     .arg(number(g.t, 4));
            if (role == Qt::ToolTipRole)
                return text + QLatin1Char('\n') +
                       tr("pView = pView(%1) + t (pView(%2) - pView(%1)), on the plane that "
                          "cut the edge")
                           .arg(g.a + 1)
                           .arg(g.b + 1);
            return text;
        }
        case World:
            return shown(vector(worldOf(ref)), role);
        case View:
            return shown(vector(rl::cartesian(proj.pView[v])), role);
        case Ndc:
            if (!inFront) {
                if (role == Qt::ToolTipRole)
                    return tr(
                        "At or behind the near plane: not projected; the triangles "
                        "through it are clipped");
                return tr("behind");
            }
            return shown(vector(proj.pNdc[v], 'f', 4), role);
        case Screen:
            if (!inFront) return role == Qt::ToolTipRole ? QVariant() : QVariant(tr("behind"));
            if (role == Qt::ToolTipRole)
                return tr("Exact: %1").arg(vector(proj.pScreenExact[v], 'g', 10));
            return shown(vector(proj.pScreen[v], 'g', 10), role);
        case Normal: {
            const std::optional<rl::vec3> n = normalOf(ref);
            if (!n) {
                if (role == Qt::ToolTipRole)
                    return QString::fromStdString(m_frame->normals ? m_frame->normals->skipReason
                                                                   : std::string());
                return QStringLiteral("-");
            }
            if (role == Qt::ToolTipRole && made)
                return tr(
                    "Mixed along the edge it was made on, as shading does (normalised "
                    "per pixel)");
            return shown(vector(*n, 'f', 4), role);
        }
        default:
            return {};
    }
}

QVariant VertexTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal)
        return QAbstractTableModel::headerData(section, orientation, role);
    if (role == Qt::DisplayRole && m_stacked) {
        // The name above its symbol.
        QString title = headerData(section, orientation, Qt::UserRole).toString();
        if (const qsizetype space = title.indexOf(QLatin1Char(' ')); space > 0)
            title[space] = QLatin1Char('\n');
        return title;
    }
    if (role == Qt::DisplayRole || role == Qt::UserRole) {
        switch (section) {
            case Draw:
                return tr("Draw");
            case Vertex:
                return tr("Vertex");
            case World:
                return tr("World (x, y, z)");
            case View:
                return tr("View pView");
            case Ndc:
                return tr("NDC pNdc");
            case Screen:
                return tr("Screen pScreen");
            case Normal:
                return tr("Normal nView");
            default:
                return {};
        }
    }
    if (role == Qt::ToolTipRole) {
        switch (section) {
            case Draw:
                return tr("The draw (object) the vertex belongs to");
            case Vertex:
                return tr(
                    "The vertex number as in the file (1-based); vertices made by "
                    "clipping come after the draw's own");
            case World:
                return tr("P = worldFromModel · P_model");
            case View:
                return tr(
                    "pView = [U; V; N](P − C) for the course camera, or the draw's "
                    "view matrix times P_model");
            case Ndc:
                return tr(
                    "pNdc = ((d/hx) x/z, (d/hy) y/z) for the course camera, or "
                    "pClip.xy / pClip.w with pClip = clipFromView · pView");
            case Screen:
                return tr(
                    "pScreen = ((x_ndc + 1) w/2, (1 − y_ndc) h/2), truncated (snapped "
                    "to the rules' grid); the tooltip holds the exact value");
            case Normal:
                return tr(
                    "The view-space vertex normal: the normalised sum of the normals of "
                    "the triangles around it (stage 3)");
            default:
                return {};
        }
    }
    return {};
}

// ---------------------------------------------------------------------------------------

VertexTableView::VertexTableView(Inspection* inspection, QWidget* parent)
    : QWidget(parent), m_inspection(inspection) {
    setObjectName(QStringLiteral("vertexTableView"));
    m_model = new VertexTableModel(this);
    m_proxy = new TriangleFilter(this);
    m_proxy->setSourceModel(m_model);

    m_table = new QTableView(this);
    m_table->setObjectName(QStringLiteral("vertexTable"));
    m_table->setModel(m_proxy);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_table->setAlternatingRowColors(true);
    m_table->setWordWrap(false);
    m_table->verticalHeader()->hide();
    // Fixed row heights and column widths measured on a few rows: nothing walks every row.
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_table->horizontalHeader()->setResizeContentsPrecision(64);
    m_table->horizontalHeader()->setStretchLastSection(true);
    // A column for each coordinate of each space: too many for a dock, it scrolls sideways
    // (tests/tst_legibility.cpp lets it; each column still fits its text).
    m_table->setProperty("scrollsSideways", true);

    m_onlyTriangle = new WrappingCheckBox(tr("Only the selected triangle's vertices"), this);
    m_onlyTriangle->setObjectName(QStringLiteral("vertexTableOnlyTriangle"));
    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("vertexTableSummary"));
    m_explanation = new QTextBrowser(this);
    m_explanation->setObjectName(QStringLiteral("vertexTableExplanation"));

    auto* top = new QHBoxLayout;
    top->addWidget(m_onlyTriangle);
    top->addStretch(1);
    top->addWidget(m_summary);
    auto* splitter = new QSplitter(Qt::Vertical, this);
    splitter->addWidget(m_table);
    splitter->addWidget(m_explanation);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addWidget(splitter, 1);

    connect(m_onlyTriangle, &QCheckBox::toggled, this, &VertexTableView::setOnlySelectedTriangle);
    connect(m_table->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &VertexTableView::tableSelectionChanged);
    connect(m_table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& current) {
                if (m_selecting || !current.isValid()) return;
                explain(m_model->vertexAt(m_proxy->mapToSource(current).row()));
            });
    connect(m_inspection, &Inspection::frameChanged, this, [this] {
        m_dirty = true;
        if (isVisible()) refreshFrame();
    });
    connect(m_inspection, &Inspection::selectionChanged, this, [this] {
        if (!m_selecting && isVisible()) followSelection();
    });
    connect(m_inspection, &Inspection::presentationChanged, this,
            &VertexTableView::applyPresentation);
    applyPresentation();
}

void VertexTableView::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    if (m_dirty) refreshFrame();
    followSelection();
}

void VertexTableView::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    // Another font (the dock's, presentation mode's): the rows and columns measured again,
    // once the table has taken it.
    if (event->type() == QEvent::FontChange)
        QMetaObject::invokeMethod(this, &VertexTableView::applyPresentation,
                                  Qt::QueuedConnection);
}

void VertexTableView::refreshFrame() {
    m_dirty = false;
    const auto& frame = m_inspection->frame();
    m_selecting = true;  // the reset drops the table's selection: not a user's choice
    m_model->setFrame(frame && frame->projection ? frame : nullptr);
    m_selecting = false;
    m_explained.reset();
    fitColumns();
    std::size_t made = 0;
    if (frame && frame->projection)
        for (const rl::DrawProjection& d : frame->projection->draws) made += d.generated.size();
    m_summary->setText(
        made > 0 ? tr("%1 vertices, %2 of them made by clipping").arg(m_model->rowCount()).arg(made)
                 : tr("%1 vertices").arg(m_model->rowCount()));
    followSelection();
}

void VertexTableView::fitColumns() {
    // One draw: its number is 1 on every row.
    const auto& frame = m_model->frame();
    m_table->setColumnHidden(VertexTableModel::Draw,
                             frame && frame->scene && frame->scene->draws.size() <= 1);
    // On one line when every column fits across the table, else each vector on three lines
    // (a dock): every column in view, none scrolled out sideways.
    m_table->horizontalHeader()->setStretchLastSection(false);  // measured as the others
    m_model->setStacked(false);
    // The room across, less a vertical scroll bar, shown or about to be.
    const int across = m_table->width() - 2 * m_table->frameWidth() -
                       m_table->verticalScrollBar()->sizeHint().width();
    if (measureColumns() > across) {
        m_model->setStacked(true);
        measureColumns();
    }
    m_table->horizontalHeader()->setStretchLastSection(true);
    const int lines = m_model->stacked() ? 3 : 1;
    m_table->verticalHeader()->setDefaultSectionSize(lines * m_table->fontMetrics().height() + 6);
}

int VertexTableView::measureColumns() {
    // The widths of a few rows, but at least those of wide values (negative, hundreds), so
    // that rows further down are not cut short.
    m_table->resizeColumnsToContents();
    const QFontMetrics metrics(m_table->font());
    const bool stacked = m_model->stacked();
    const auto atLeast = [&](int column, const QString& line, const QString& widest) {
        const int w = metrics.horizontalAdvance(stacked ? widest : line) + 10;
        if (m_table->columnWidth(column) < w) m_table->setColumnWidth(column, w);
    };
    atLeast(VertexTableModel::World, QStringLiteral("(-000.000, -000.000, -000.000)"),
            QStringLiteral("-000.000"));
    atLeast(VertexTableModel::View, QStringLiteral("(-000.000, -000.000, -000.000)"),
            QStringLiteral("-000.000"));
    atLeast(VertexTableModel::Ndc, QStringLiteral("(-0.0000, -0.0000)"), QStringLiteral("-0.0000"));
    atLeast(VertexTableModel::Screen, QStringLiteral("(0000, 0000)"), QStringLiteral("0000"));
    atLeast(VertexTableModel::Normal, QStringLiteral("(-0.0000, -0.0000, -0.0000)"),
            QStringLiteral("-0.0000"));
    int sum = 0;
    for (int c = 0; c < VertexTableModel::ColumnCount; ++c)
        if (!m_table->isColumnHidden(c)) sum += m_table->columnWidth(c);
    return sum;
}

void VertexTableView::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    // After the layout has given the table its new width.
    QMetaObject::invokeMethod(this, &VertexTableView::fitColumns, Qt::QueuedConnection);
}

int VertexTableView::visibleRowCount() const {
    return m_proxy->rowCount();
}

void VertexTableView::setOnlySelectedTriangle(bool on) {
    {
        const QSignalBlocker block(m_onlyTriangle);
        m_onlyTriangle->setChecked(on);
    }
    followSelection();
}

std::vector<int> VertexTableView::selectedRows() const {
    std::vector<int> rows;
    for (const QModelIndex& index : m_table->selectionModel()->selectedRows())
        rows.push_back(m_proxy->mapToSource(index).row());
    std::sort(rows.begin(), rows.end());
    return rows;
}

void VertexTableView::tableSelectionChanged() {
    if (m_selecting) return;
    std::vector<VertexRef> vertices;
    for (int row : selectedRows()) vertices.push_back(m_model->vertexAt(row));
    m_selecting = true;
    m_inspection->selectVertices(std::move(vertices));
    m_selecting = false;
}

void VertexTableView::followSelection() {
    // The filter first (the triangle may have changed), then the rows of the vertices.
    auto* filter = static_cast<TriangleFilter*>(m_proxy);
    const auto& frame = m_model->frame();
    std::optional<std::vector<int>> triangleRows;
    if (m_onlyTriangle->isChecked()) {
        triangleRows.emplace();
        const std::optional<std::uint32_t> t = m_inspection->selectedTriangle();
        if (frame && t && *t < frame->projection->triangles.size()) {
            const rl::ScreenTriangle& tri = frame->projection->triangles[*t];
            for (std::uint32_t v : tri.v) {
                const int row = m_model->rowOf({tri.draw, v});
                if (row >= 0) triangleRows->push_back(row);
            }
        }
    }
    m_selecting = true;
    filter->setRows(std::move(triangleRows));
    QItemSelection selection;
    QModelIndex first;
    for (const VertexRef& ref : m_inspection->selectedVertices()) {
        const int row = m_model->rowOf(ref);
        if (row < 0) continue;
        const QModelIndex index = m_proxy->mapFromSource(m_model->index(row, 0));
        if (!index.isValid()) continue;  // filtered out
        if (!first.isValid()) first = index;
        selection.select(index, index);
    }
    QItemSelectionModel* model = m_table->selectionModel();
    model->select(selection, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    if (first.isValid()) {
        model->setCurrentIndex(first, QItemSelectionModel::NoUpdate);
        m_table->scrollTo(first, QAbstractItemView::PositionAtCenter);
    }
    m_selecting = false;
    const auto& selected = m_inspection->selectedVertices();
    explain(selected.empty() ? std::nullopt : std::optional<VertexRef>(selected.front()));
}

void VertexTableView::explain(std::optional<VertexRef> vertex) {
    if (vertex && m_model->rowOf(*vertex) < 0) vertex.reset();
    m_explained = vertex;
    if (!vertex) {
        m_explanation->setHtml(
            m_model->frame()
                ? tr("<p>Select a row, or pick a pixel in the image: its triangle's three "
                     "vertices are selected. The numbers of the selected vertex are worked "
                     "through each formula here.</p>")
                : tr("<p>No frame yet.</p>"));
        return;
    }
    m_explanation->setHtml(explanationHtml(*vertex));
}

QString VertexTableView::explanationText() const {
    return m_explanation->toPlainText();
}

QString VertexTableView::explanationHtml(VertexRef ref) const {
    const rl::FrameTrace& frame = *m_model->frame();
    const rl::Scene& scene = *frame.scene;
    const rl::Draw& draw = scene.draws[ref.draw];
    const rl::DrawProjection& proj = frame.projection->draws[ref.draw];
    const std::uint32_t v = ref.vertex;
    const bool made = v >= proj.originalVertexCount;
    const rl::dvec3 pView = rl::cartesian(proj.pView[v]);
    const bool course =
        scene.camera && !draw.clipFromView && frame.cameraBasis && !frame.cameraBasis->skipped;
    QString html;
    const QString drawName = QString::fromStdString(draw.name).toHtmlEscaped();
    html += QStringLiteral("<p><b>") +
            (scene.draws.size() > 1
                 ? tr("Vertex %1 of draw %2 (%3)").arg(v + 1).arg(ref.draw + 1).arg(drawName)
                 : tr("Vertex %1 of %2").arg(v + 1).arg(drawName)) +
            QStringLiteral("</b></p>");

    // World and view.
    if (made) {
        const rl::ClipVertex& g = proj.generated[v - proj.originalVertexCount];
        const rl::dvec3 a = rl::cartesian(proj.pView[g.a]), b = rl::cartesian(proj.pView[g.b]);
        html += tr("<p>Made by clipping the edge %1-%2 where it crosses a plane (the near plane "
                   "or a clip plane), at t = %3:<br>pView = pView<sub>%1</sub> + t "
                   "(pView<sub>%2</sub> − pView<sub>%1</sub>) = %4 + %3 (%5 − %4) = "
                   "<b>%6</b><br>World: P = %7 (the same interpolation).</p>")
                    .arg(g.a + 1)
                    .arg(g.b + 1)
                    .arg(number(g.t))
                    .arg(vector(a), vector(b), vector(pView), vector(m_model->worldOf(ref)));
    } else {
        const rl::dvec3 world = m_model->worldOf(ref);
        if (draw.animation)
            html += tr("<p>World: P = M(t) · worldFromModel · %1 = <b>%2</b> (M: the "
                       "animation matrix at t = %3 s)</p>")
                        .arg(vector(rl::cartesian(draw.mesh->positions[v])), vector(world),
                             number(frame.scene->time));
        else if (draw.worldFromModel == rl::dmat4(1.0))
            html += tr("<p>World: P = P<sub>model</sub> = <b>%1</b> (worldFromModel is the "
                       "identity)</p>")
                        .arg(vector(world));
        else
            html += tr("<p>World: P = worldFromModel · %1 = <b>%2</b></p>")
                        .arg(vector(rl::cartesian(draw.mesh->positions[v])), vector(world));
        if (course) {
            const rl::CameraBasis& basis = *frame.cameraBasis;
            const rl::dvec3 d = world - basis.c;
            html +=
                tr("<p>View: pView = [U; V; N](P − C), with C = %1:<br>P − C = %2<br>"
                   "x = U · (P − C) = %3 · %2 = %4<br>"
                   "y = V · (P − C) = %5 · %2 = %6<br>"
                   "z = N · (P − C) = %7 · %2 = %8<br>pView = <b>%9</b></p>")
                    .arg(vector(basis.c), vector(d), vector(basis.u), number(glm::dot(basis.u, d)),
                         vector(basis.v), number(glm::dot(basis.v, d)), vector(basis.n),
                         number(glm::dot(basis.n, d)), vector(pView));
        } else {
            html += tr("<p>View: pView = viewFromModel · P<sub>model</sub> (the draw's own view "
                       "matrix) = <b>%1</b></p>")
                        .arg(vector(pView));
        }
    }

    // Projection.
    if (!proj.inFront[v]) {
        html += tr("<p>z = %1 is not beyond the near plane (w = %2): the vertex is behind, "
                   "not projected; the triangles through it are clipped there.</p>")
                    .arg(number(proj.pClip[v].w))
                    .arg(number(frame.projection->nearW));
    } else {
        const rl::dvec2 ndc = proj.pNdc[v];
        if (course) {
            const rl::CourseCamera& cam = *scene.camera;
            html += tr("<p>NDC: pNdc = ((d/hx) x/z, (d/hy) y/z) = ((%1/%2) · %3/%4, (%1/%5) · "
                       "%6/%4) = <b>%7</b></p>")
                        .arg(number(cam.d), number(cam.hx), operand(pView.x), operand(pView.z),
                             number(cam.hy), operand(pView.y), vector(ndc));
        } else {
            html += tr("<p>Clip: pClip = clipFromView · pView = %1<br>NDC: pNdc = pClip.xy / "
                       "pClip.w = <b>%2</b></p>")
                        .arg(vector(proj.pClip[v]), vector(ndc));
        }
        const rl::dvec2 exact = proj.pScreenExact[v];
        const rl::dvec2 snapped = proj.pScreen[v];
        const rl::RasterRules& rules = scene.rules;
        QString rounding;
        if (rules.snap == rl::RasterRules::VertexSnap::None)
            rounding = tr("not snapped");
        else if (rules.subpixelBits == 0 && rules.snap == rl::RasterRules::VertexSnap::Truncate)
            rounding = tr("truncated, as C's (int) does");
        else if (rules.snap == rl::RasterRules::VertexSnap::Truncate)
            rounding = tr("truncated to a grid of 1/%1 pixel").arg(1 << rules.subpixelBits);
        else
            rounding = tr("rounded to the nearest 1/%1 pixel").arg(1 << rules.subpixelBits);
        const QString yFormula = scene.conventions.ndcYUp ? tr("(1 − y<sub>ndc</sub>) h/2")
                                                          : tr("(y<sub>ndc</sub> + 1) h/2");
        const QString ySubstituted =
            scene.conventions.ndcYUp
                ? QStringLiteral("(1 − %1) · %2").arg(operand(ndc.y), number(scene.height / 2.0))
                : QStringLiteral("(%1 + 1) · %2").arg(number(ndc.y), number(scene.height / 2.0));
        if (scene.conventions.viewport == rl::ViewportFormula::ScaleThenShift)
            html += tr("<p>Screen: pScreen = (x<sub>ndc</sub> w/2 + w/2, y<sub>ndc</sub> h/2 + "
                       "h/2) = (%1 · %2 + %2, %3 · %4 + %4) = %5, %6: <b>%7</b></p>")
                        .arg(number(ndc.x), number(scene.width / 2.0), number(ndc.y),
                             number(scene.height / 2.0), vector(exact, 'g', 10), rounding,
                             vector(snapped, 'g', 10));
        else
            html += tr("<p>Screen: pScreen = ((x<sub>ndc</sub> + 1) w/2, %1) = ((%2 + 1) · %3, "
                       "%4) = %5, %6: <b>%7</b></p>")
                        .arg(yFormula, number(ndc.x), number(scene.width / 2.0), ySubstituted,
                             vector(exact, 'g', 10), rounding, vector(snapped, 'g', 10));
    }

    // Normal.
    if (const std::optional<rl::vec3> n = m_model->normalOf(ref)) {
        if (made) {
            html += tr("<p>Normal: mixed along the edge like pView, %1; shading normalises it "
                       "per pixel.</p>")
                        .arg(vector(*n, 'f', 4));
        } else if (!draw.mesh->normals.empty()) {
            html += tr("<p>Normal: the file's normal carried to view space by the inverse "
                       "transpose of viewFromModel: nView = <b>%1</b></p>")
                        .arg(vector(*n, 'f', 4));
        } else {
            int around = 0;
            for (const auto& t : draw.mesh->triangles)
                around += (t[0] == v || t[1] == v || t[2] == v) ? 1 : 0;
            html += tr("<p>Normal: the normalised sum of the normals of the %1 triangles around "
                       "it: nView = <b>%2</b></p>")
                        .arg(around)
                        .arg(vector(*n, 'f', 4));
        }
    } else {
        html += tr("<p>Normal: none, %1.</p>")
                    .arg(QString::fromStdString(frame.normals ? frame.normals->skipReason
                                                              : std::string())
                             .toHtmlEscaped());
    }
    return html;
}

void VertexTableView::applyPresentation() {
    const QFont tableFont = scaledFont(this, m_inspection->textScale(1.4));
    m_table->setFont(tableFont);
    m_explanation->setFont(tableFont);
    fitColumns();
}

}  // namespace rasterlab
