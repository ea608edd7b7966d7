#include "painter_view.h"

#include <QAbstractTableModel>
#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QTableView>
#include <QVBoxLayout>

#include <vector>

#include "pipeline/render/output_image.h"
#include "views/frame_image_view.h"
#include "views/inspection.h"
#include "views/messages/pipeline_messages.h"
#include "views/number_text.h"
#include "views/on_screen.h"
#include "views/view_font.h"
#include "views/wrapping_check_box.h"

namespace rasterlab {

namespace {

QImage toQImage(const rl::Rgba8Image& image) {
    return QImage(image.rgba.data(), image.width, image.height, image.width * 4,
                  QImage::Format_RGBA8888)
        .copy();
}

// Painted rank r of n as a colour: the first painted (farthest) blue, the last red.
QColor rankColour(std::uint32_t rank, std::size_t n) {
    const double t = n > 1 ? double(rank) / double(n - 1) : 1.0;
    return QColor::fromHsvF(float((1.0 - t) * 240.0 / 360.0), 0.85f, 0.95f);
}

}  // namespace

// The triangles in painted order: rank, draw, mesh triangle, the barycentre's distance, and
// the pixels where a triangle painted later hides it wrongly.
class PainterOrderModel : public QAbstractTableModel {
public:
    using QAbstractTableModel::QAbstractTableModel;

    void setComparison(std::shared_ptr<const rl::PainterComparison> comparison) {
        beginResetModel();
        m_comparison = std::move(comparison);
        m_distance.clear();
        if (m_comparison) {
            const rl::FrameTrace& p = *m_comparison->painter;
            m_distance.resize(p.projection->triangles.size());
            for (std::size_t r = 0; r < m_distance.size(); ++r)
                m_distance[r] =
                    rl::painterDistance(*p.scene, *p.projection, static_cast<std::uint32_t>(r));
        }
        endResetModel();
    }
    double distance(std::uint32_t rank) const { return m_distance[rank]; }

    int rowCount(const QModelIndex& parent = {}) const override {
        return parent.isValid() ? 0 : static_cast<int>(m_distance.size());
    }
    int columnCount(const QModelIndex& parent = {}) const override {
        return parent.isValid() ? 0 : 5;
    }
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override {
        if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
        switch (section) {
            case 0:
                return PainterView::tr("Painted");
            case 1:
                return PainterView::tr("Draw");
            case 2:
                return PainterView::tr("Triangle");
            case 3:
                return PainterView::tr("|b| (distance)");
            case 4:
                return PainterView::tr("Hidden wrongly");
        }
        return {};
    }
    QVariant data(const QModelIndex& index, int role) const override {
        if (!m_comparison || !index.isValid()) return {};
        const auto rank = static_cast<std::uint32_t>(index.row());
        const rl::FrameTrace& p = *m_comparison->painter;
        const rl::ScreenTriangle& tri = p.projection->triangles[rank];
        if (role == Qt::TextAlignmentRole)
            return index.column() == 1 ? int(Qt::AlignLeft | Qt::AlignVCenter)
                                       : int(Qt::AlignRight | Qt::AlignVCenter);
        if (role == Qt::DecorationRole && index.column() == 0)
            return rankColour(rank, m_distance.size());
        if (role == Qt::ForegroundRole && index.column() == 4 &&
            m_comparison->hiddenWrongly[rank] > 0)
            return QColor(200, 0, 0);
        if (role != Qt::DisplayRole) return {};
        switch (index.column()) {
            case 0:
                return rank + 1;
            case 1:
                return QString::fromStdString(p.scene->draws[tri.draw].name);
            case 2:
                return tri.source + 1;
            case 3:
                return number(m_distance[rank]);
            case 4:
                return m_comparison->hiddenWrongly[rank];
        }
        return {};
    }

private:
    std::shared_ptr<const rl::PainterComparison> m_comparison;
    std::vector<double> m_distance;  // per rank
};

PainterView::PainterView(Inspection* inspection, QWidget* parent)
    : QWidget(parent), m_inspection(inspection) {
    setObjectName(QStringLiteral("painterView"));
    m_explanation = new QLabel(this);
    m_explanation->setObjectName(QStringLiteral("painterExplanation"));
    m_explanation->setWordWrap(true);
    m_explanation->setTextFormat(Qt::RichText);
    m_explanation->setTextInteractionFlags(Qt::TextSelectableByMouse);

    m_model = new PainterOrderModel(this);
    m_table = new QTableView(this);
    m_table->setObjectName(QStringLiteral("painterOrderTable"));
    m_table->setModel(m_model);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->verticalHeader()->hide();
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->setToolTip(
        tr("The triangles in the order the painter paints them: farthest "
           "barycentre first. Click a row to select its triangle."));

    m_leftChoice = new QComboBox(this);
    m_leftChoice->setObjectName(QStringLiteral("painterLeftImage"));
    m_leftChoice->addItem(tr("Painter's image"));
    m_leftChoice->addItem(tr("Painted order (first blue, last red)"));
    // The dock takes no more room than the stage views beside it: nothing here sets a wide
    // minimum (the captions and the choice shrink).
    m_leftChoice->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_leftChoice->setMinimumContentsLength(12);
    m_marksTies = new WrappingCheckBox(tr("Mark ties on shared edges"), this);
    m_marksTies->setObjectName(QStringLiteral("painterMarksTies"));
    m_marksTies->setToolTip(
        tr("Pixels on an edge two triangles share, at the same depth: the "
           "z-buffer keeps the first drawn, the painter the last."));
    m_painterCaption = new QLabel(this);
    m_zBufferCaption = new QLabel(this);
    // Under a narrow dock the captions wrap rather than widen it.
    for (QLabel* caption : {m_painterCaption, m_zBufferCaption}) caption->setWordWrap(true);
    m_painterImage = new FrameImageView(this);
    m_painterImage->setObjectName(QStringLiteral("painterImage"));
    m_zBufferImage = new FrameImageView(this);
    m_zBufferImage->setObjectName(QStringLiteral("painterZBufferImage"));
    for (FrameImageView* view : {m_painterImage, m_zBufferImage}) {
        view->setMinimumSize(80, 60);
        connect(view, &FrameImageView::pixelPicked, m_inspection, &Inspection::pickPixel);
    }

    auto* left = new QWidget(this);
    auto* leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    leftLayout->addWidget(m_leftChoice);
    leftLayout->addWidget(m_painterCaption);
    leftLayout->addWidget(m_painterImage, 1);
    auto* right = new QWidget(this);
    auto* rightLayout = new QVBoxLayout(right);
    rightLayout->setContentsMargins(0, 0, 0, 0);
    rightLayout->addWidget(m_zBufferCaption);
    rightLayout->addWidget(m_zBufferImage, 1);
    auto* images = new QSplitter(Qt::Horizontal, this);
    images->addWidget(left);
    images->addWidget(right);
    auto* imagesAndTies = new QWidget(this);
    auto* imagesLayout = new QVBoxLayout(imagesAndTies);
    imagesLayout->setContentsMargins(0, 0, 0, 0);
    imagesLayout->addWidget(images, 1);
    imagesLayout->addWidget(m_marksTies);
    // The table above the images: beside them, a dock on a small screen left the table too
    // narrow for its columns.
    auto* split = new QSplitter(Qt::Vertical, this);
    m_split = split;
    split->addWidget(m_table);
    split->addWidget(imagesAndTies);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 2);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_explanation);
    layout->addWidget(split, 1);

    connect(m_leftChoice, &QComboBox::currentIndexChanged, this, [this] { showImages(); });
    connect(m_marksTies, &QCheckBox::toggled, this, [this] {
        makeMask();
        showSelection();
    });
    connect(m_table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex& current) {
                if (!current.isValid() || m_following) return;
                const auto frameTriangle =
                    frameTriangleOf(static_cast<std::uint32_t>(current.row()));
                if (frameTriangle && m_inspection->selectedTriangle() != frameTriangle)
                    m_inspection->selectTriangle(frameTriangle);
            });
    connect(m_inspection, &Inspection::frameChanged, this, [this] { refreshWhenShown(); });
    connect(m_inspection, &Inspection::selectionChanged, this, [this] { showSelection(); });
    connect(m_inspection, &Inspection::presentationChanged, this, [this] { applyPresentation(); });
}

void PainterView::setLeftImage(int which) {
    m_leftChoice->setCurrentIndex(which);
}

void PainterView::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    if (!m_splitSet && height() > 0) {
        // A third for the table, the rest for the two images, once the height is known.
        m_split->setSizes({height() / 3, height() - height() / 3});
        m_splitSet = true;
    }
    // A frame that came while hidden is another than the one compared.
    if (m_comparedFrame.lock() != m_inspection->frame()) recompute();
}

void PainterView::refreshWhenShown() {
    if (onScreen(this)) recompute();
}

bool PainterView::event(QEvent* event) {
    if (event->type() == kRaisedEvent) {
        if (m_comparedFrame.lock() != m_inspection->frame()) recompute();
        return true;
    }
    return QWidget::event(event);
}

void PainterView::recompute() {
    const std::shared_ptr<const rl::FrameTrace>& frame = m_inspection->frame();
    m_comparedFrame = frame;
    m_comparison.reset();
    m_error.clear();
    m_zBufferPixels.clear();
    if (frame && frame->scene) {
        // A frame whose draws are all flat is the z-buffer's render: it is used as it is. A
        // painter frame is rendered again: the dock's render checks the window's (the same
        // bytes, tst_painter_view).
        auto result = frame->depth && frame->depth->painted ? rl::compareWithZBuffer(frame->scene)
                                                            : rl::compareWithZBuffer(frame);
        if (result)
            m_comparison = std::make_shared<const rl::PainterComparison>(std::move(result).value());
        else
            m_error = rasterlab::translated(result.error());
    }
    m_model->setComparison(m_comparison);
    m_table->setColumnHidden(1, !m_comparison || m_comparison->painter->scene->draws.size() < 2);
    m_painted = m_order = m_zImage = m_mask = QImage();
    if (m_comparison) {
        const rl::PainterComparison& c = *m_comparison;
        const rl::FrameTrace& p = *c.painter;
        const rl::FrameTrace& z = *c.zBuffer;
        m_painted = toQImage(c.painterImage);
        m_zImage = toQImage(c.zBufferImage);
        const int w = p.scene->width, h = p.scene->height;
        m_order = QImage(w, h, QImage::Format_RGB32);
        m_zBufferPixels.assign(c.zBufferIndex.size(), 0);
        const std::size_t n = p.projection->triangles.size();
        // Each rank's colour once, when a pixel first shows it (0: not yet; a colour is opaque).
        std::vector<QRgb> colours(n, 0);
        for (int y = 0; y < h; ++y) {
            auto* orderRow = reinterpret_cast<QRgb*>(m_order.scanLine(y));
            for (int x = 0; x < w; ++x) {
                const std::uint32_t t = p.depth->triangle.at(x, y);
                if (t == rl::kNoTriangle) {
                    orderRow[x] = qRgb(0, 0, 0);
                } else {
                    if (colours[t] == 0) colours[t] = rankColour(t, n).rgb();
                    orderRow[x] = colours[t];
                }
                const std::uint32_t nearest = z.depth->triangle.at(x, y);
                if (nearest != rl::kNoTriangle) ++m_zBufferPixels[c.painterRank[nearest]];
            }
        }
    }
    makeMask();
    showImages();
    showSelection();
}

void PainterView::makeMask() {
    m_mask = QImage();
    if (!m_comparison) return;
    const rl::Image<rl::PixelDifference>& mask = m_comparison->mask;
    const bool ties = m_marksTies->isChecked();
    m_mask = QImage(mask.width(), mask.height(), QImage::Format_ARGB32);
    m_mask.fill(Qt::transparent);
    for (int y = 0; y < mask.height(); ++y) {
        auto* row = reinterpret_cast<QRgb*>(m_mask.scanLine(y));
        for (int x = 0; x < mask.width(); ++x) {
            const rl::PixelDifference d = mask.at(x, y);
            if (d == rl::PixelDifference::WrongOrder)
                row[x] = qRgba(255, 0, 0, 200);
            else if (d == rl::PixelDifference::Tie && ties)
                row[x] = qRgba(255, 220, 0, 170);
        }
    }
}

std::optional<std::uint32_t> PainterView::rankOf(std::uint32_t frameTriangle) const {
    const auto& frame = m_inspection->frame();
    if (!m_comparison || !frame || frameTriangle >= m_comparison->zBufferIndex.size())
        return std::nullopt;
    // A painter frame is numbered in painted order; any other in the z-buffer's (draw) order.
    if (frame->depth && frame->depth->painted) return frameTriangle;
    return m_comparison->painterRank[frameTriangle];
}

std::optional<std::uint32_t> PainterView::frameTriangleOf(std::uint32_t rank) const {
    const auto& frame = m_inspection->frame();
    if (!m_comparison || !frame || rank >= m_comparison->zBufferIndex.size()) return std::nullopt;
    if (frame->depth && frame->depth->painted) return rank;
    return m_comparison->zBufferIndex[rank];
}

void PainterView::showImages() {
    const bool order = m_leftChoice->currentIndex() == 1;
    m_painterImage->setImage(order ? m_order : m_painted);
    m_zBufferImage->setImage(m_zImage);
    if (!m_comparison) {
        m_painterCaption->setText(m_error);
        m_zBufferCaption->clear();
        return;
    }
    const rl::PainterComparison& c = *m_comparison;
    m_painterCaption->setText(order ? tr("rank of the last triangle painted")
                                    : tr("painted far to near, no depth test"));
    m_zBufferCaption->setText(
        tr("Z-buffer (the same flat colours): %n pixel(s) differ", nullptr, int(c.differing)));
}

void PainterView::showSelection() {
    ImageOverlay overlay;
    overlay.lineWidth = m_inspection->lineWidth();
    overlay.coverage = m_mask;
    const auto& frame = m_inspection->frame();
    std::optional<std::uint32_t> rank;
    if (m_comparison && frame && m_inspection->selectedTriangle())
        rank = rankOf(*m_inspection->selectedTriangle());
    if (m_comparison) {
        const rl::FrameTrace& p = *m_comparison->painter;
        overlay.sampleOffset = p.scene->rules.sampleOffset;
        if (rank) {
            const auto v = rl::screenVertices(*p.projection, p.projection->triangles[*rank]);
            overlay.selectedTriangle = std::array<QPointF, 3>{
                QPointF(v[0].x, v[0].y), QPointF(v[1].x, v[1].y), QPointF(v[2].x, v[2].y)};
        }
    }
    overlay.pickedPixel = m_inspection->pickedPixel();
    m_painterImage->setOverlay(overlay);
    m_zBufferImage->setOverlay(overlay);
    if (rank) {
        const QModelIndex index = m_model->index(static_cast<int>(*rank), 0);
        if (m_table->currentIndex().row() != index.row()) {
            m_following = true;
            m_table->selectionModel()->setCurrentIndex(
                index, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
            m_following = false;
        }
        // Once the table has laid out its rows (a new model may still be pending).
        QMetaObject::invokeMethod(
            m_table, [table = m_table, index] { table->scrollTo(index); }, Qt::QueuedConnection);
    }
    m_explanation->setText(explanation());
}

QString PainterView::explanation() const {
    const auto& frame = m_inspection->frame();
    if (!frame) return tr("No frame.");
    if (!m_comparison) return m_error.isEmpty() ? tr("Not worked out yet.") : m_error;
    const rl::PainterComparison& c = *m_comparison;
    const rl::FrameTrace& p = *c.painter;
    const std::size_t n = p.projection->triangles.size();
    QString text =
        tr("<b>Painter's algorithm</b> (seed 004): the %n triangle(s) are sorted by the distance "
           "|b| of their barycentre b (view space) to the camera, far to near, each lit once at "
           "b, and painted in that order <i>without a depth test</i>: the last painted stays.",
           nullptr, int(n));
    if (!(frame->depth && frame->depth->painted))
        text += QLatin1Char(' ') + tr("The frame shown uses the z-buffer; this view renders the "
                                      "scene again as the painter would.");
    text += QStringLiteral("<br>") +
            tr("Against the z-buffer with the same colours, %1 pixels differ: "
               "<span style='color:#d00000'>%2 where a farther triangle was painted after a "
               "nearer one</span> (the order of whole triangles is not the order of their "
               "pixels), <span style='color:#b08800'>%3 on edges two triangles share at the same "
               "depth</span> (the z-buffer keeps the first drawn, the painter the last).")
                .arg(c.differing)
                .arg(c.wrongOrder)
                .arg(c.ties);
    const auto selected = m_inspection->selectedTriangle();
    const auto rank = selected ? rankOf(*selected) : std::nullopt;
    if (rank) {
        const rl::ScreenTriangle& tri = p.projection->triangles[*rank];
        const rl::dvec3 b = rl::viewBarycentre(p.projection->draws[tri.draw],
                                               *p.scene->draws[tri.draw].mesh, tri.source);
        text += QStringLiteral("<br>") +
                tr("Triangle %1: b = %2, |b| = %3, painted %4 of %5. The z-buffer shows it at "
                   "%6 pixels; a triangle painted after it covers %7 of them though it is "
                   "farther there; it covers %8 pixels of nearer triangles painted before it.")
                    .arg(p.scene->draws.size() > 1
                             ? QStringLiteral("%1 (%2)")
                                   .arg(tri.source + 1)
                                   .arg(QString::fromStdString(p.scene->draws[tri.draw].name))
                             : QString::number(tri.source + 1))
                    .arg(vector(b), number(glm::length(b)))
                    .arg(*rank + 1)
                    .arg(n)
                    .arg(m_zBufferPixels[*rank])
                    .arg(c.hiddenWrongly[*rank])
                    .arg(c.coversWrongly[*rank]);
    }
    return text;
}

void PainterView::applyPresentation() {
    const QFont font = scaledFont(this, m_inspection->textScale(1.5));
    m_explanation->setFont(font);
    m_table->setFont(font);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);
    showSelection();
}

void PainterView::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    // Another font (the dock's, presentation mode's): the rows as high as its lines.
    if (event->type() == QEvent::FontChange)
        QMetaObject::invokeMethod(this, &PainterView::applyPresentation, Qt::QueuedConnection);
}

}  // namespace rasterlab
