#include "zbuffer_view.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPainter>
#include <QResizeEvent>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "views/frame_image_view.h"
#include "views/key_figures.h"
#include "views/on_screen.h"
#include "views/wrapping_check_box.h"

namespace rasterlab {

namespace {

// Where z falls in the range, 0 (nearest) to 1 (farthest).
double rangePosition(float z, const DepthRange& range) {
    const double span = double(range.farthest) - double(range.nearest);
    if (!(span > 0.0)) return 0.0;
    return std::clamp((double(z) - double(range.nearest)) / span, 0.0, 1.0);
}

// The false-colour ramp, near to far: dark red, orange, yellow, green, light blue, dark blue.
QRgb falseColour(double t) {
    static constexpr std::array<std::array<int, 3>, 6> stops{{{122, 4, 3},
                                                              {249, 117, 29},
                                                              {225, 220, 55},
                                                              {100, 253, 106},
                                                              {40, 170, 230},
                                                              {48, 18, 59}}};
    const double at = t * double(stops.size() - 1);
    const auto i = std::min(static_cast<std::size_t>(at), stops.size() - 2);
    const double f = at - double(i);
    std::array<int, 3> c{};
    for (std::size_t k = 0; k < 3; ++k)
        c[k] = static_cast<int>(std::lround(stops[i][k] + f * (stops[i + 1][k] - stops[i][k])));
    return qRgb(c[0], c[1], c[2]);
}

}  // namespace

DepthRange coveredDepthRange(const rl::DepthTest& depth) {
    DepthRange range;
    range.nearest = std::numeric_limits<float>::infinity();
    range.farthest = -std::numeric_limits<float>::infinity();
    for (int y = 0; y < depth.depth.height(); ++y) {
        const std::uint32_t* triangles = depth.triangle.row(y);
        const float* depths = depth.depth.row(y);
        for (int x = 0; x < depth.depth.width(); ++x) {
            const float z = depths[x];
            if (triangles[x] == rl::kNoTriangle || !std::isfinite(z)) continue;
            range.nearest = std::min(range.nearest, z);
            range.farthest = std::max(range.farthest, z);
        }
    }
    range.valid = range.nearest <= range.farthest;
    if (!range.valid) return DepthRange{};
    return range;
}

QRgb depthColour(float z, const DepthRange& range, DepthPalette palette) {
    const double t = rangePosition(z, range);
    if (palette == DepthPalette::FalseColour) return falseColour(t);
    const int grey = static_cast<int>(std::lround(255.0 - 239.0 * t));
    return qRgb(grey, grey, grey);
}

QRgb emptyPixelColour(int x, int y) {
    return ((x / 8 + y / 8) % 2 == 0) ? qRgb(58, 60, 70) : qRgb(78, 80, 92);
}

QImage depthImage(const rl::DepthTest& depth, const DepthRange& range, DepthPalette palette) {
    QImage image(depth.depth.width(), depth.depth.height(), QImage::Format_RGB32);
    const int width = image.width();
    for (int y = 0; y < image.height(); ++y) {
        auto* line = reinterpret_cast<QRgb*>(image.scanLine(y));
        const std::uint32_t* triangles = depth.triangle.row(y);
        const float* depths = depth.depth.row(y);
        // The empty pixels' 8 x 8 checkerboard (emptyPixelColour), a row at a time.
        const QRgb empty[2] = {emptyPixelColour(0, y), emptyPixelColour(8, y)};
        for (int x = 0; x < width; ++x)
            line[x] = triangles[x] != rl::kNoTriangle ? depthColour(depths[x], range, palette)
                                                      : empty[(x >> 3) & 1];
    }
    return image;
}

DepthHistogram depthHistogram(const rl::DepthTest& depth, const DepthRange& range, int bins) {
    DepthHistogram out;
    out.counts.assign(static_cast<std::size_t>(std::max(1, bins)), 0);
    const double span = double(range.farthest) - double(range.nearest);
    for (int y = 0; y < depth.depth.height(); ++y) {
        const std::uint32_t* triangles = depth.triangle.row(y);
        const float* depths = depth.depth.row(y);
        for (int x = 0; x < depth.depth.width(); ++x) {
            if (triangles[x] == rl::kNoTriangle) continue;
            const float z = depths[x];
            if (z < range.nearest) {
                ++out.below;
            } else if (z > range.farthest) {
                ++out.above;
            } else {
                const double t = span > 0.0 ? (double(z) - double(range.nearest)) / span : 0.0;
                const auto bin = std::min(static_cast<std::size_t>(t * double(out.counts.size())),
                                          out.counts.size() - 1);
                ++out.counts[bin];
            }
        }
    }
    return out;
}

DepthHistogramWidget::DepthHistogramWidget(QWidget* parent) : QWidget(parent) {
    setMinimumHeight(60);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
}

void DepthHistogramWidget::setHistogram(DepthHistogram histogram, const DepthRange& range,
                                        DepthPalette palette) {
    m_histogram = std::move(histogram);
    m_range = range;
    m_palette = palette;
    update();
}

void DepthHistogramWidget::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), QColor(36, 36, 40));
    const auto& counts = m_histogram.counts;
    if (counts.empty()) return;
    const int most = *std::max_element(counts.begin(), counts.end());
    if (most <= 0) return;
    const double barWidth = double(width()) / double(counts.size());
    for (std::size_t i = 0; i < counts.size(); ++i) {
        // Square-root heights, so that small bins stay visible beside the largest.
        const double h = std::sqrt(double(counts[i]) / double(most)) * (height() - 2);
        const double t = (double(i) + 0.5) / double(counts.size());
        const float z =
            static_cast<float>(m_range.nearest + t * (double(m_range.farthest) - m_range.nearest));
        painter.fillRect(QRectF(i * barWidth, height() - h, std::max(1.0, barWidth - 1.0), h),
                         QColor(depthColour(z, m_range, m_palette)));
    }
}

ZBufferView::ZBufferView(QWidget* parent) : QWidget(parent) {
    m_view = new FrameImageView(this);
    m_view->setObjectName(QStringLiteral("zbufferImage"));
    m_histogramWidget = new DepthHistogramWidget(this);
    m_histogramWidget->setObjectName(QStringLiteral("zbufferHistogram"));
    m_automatic = new WrappingCheckBox(tr("Automatic range (nearest to farthest drawn)"), this);
    m_automatic->setObjectName(QStringLiteral("zbufferAutomatic"));
    m_automatic->setChecked(true);
    m_nearest = new QDoubleSpinBox(this);
    m_farthest = new QDoubleSpinBox(this);
    m_nearest->setObjectName(QStringLiteral("zbufferNearest"));
    m_farthest->setObjectName(QStringLiteral("zbufferFarthest"));
    for (QDoubleSpinBox* box : {m_nearest, m_farthest}) {
        box->setDecimals(6);
        box->setLocale(QLocale::c());  // a decimal point, as every number the views show
        box->setRange(-1e9, 1e9);
        box->setKeyboardTracking(false);
        box->setEnabled(false);
    }
    m_paletteBox = new QComboBox(this);
    m_paletteBox->setObjectName(QStringLiteral("zbufferPalette"));
    // Short names: the rows above them say which colour is near and which far.
    m_paletteBox->addItem(tr("Grey"));
    m_paletteBox->addItem(tr("False colour"));
    m_rangeLabel = new QLabel(this);
    m_rangeLabel->setObjectName(QStringLiteral("zbufferRangeLabel"));
    m_rangeLabel->setWordWrap(true);
    m_valueLabel = new QLabel(this);
    m_valueLabel->setObjectName(QStringLiteral("zbufferValue"));
    m_valueLabel->setWordWrap(true);
    m_valueLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto* form = new QFormLayout;
    // Long rows (Portuguese, presentation mode) put their field below their label.
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    form->addRow(tr("Nearest (white / red):"), m_nearest);
    form->addRow(tr("Farthest (dark / blue):"), m_farthest);
    form->addRow(tr("Colours:"), m_paletteBox);
    m_explanation = new QLabel(this);
    m_explanation->setObjectName(QStringLiteral("zbufferExplanation"));
    m_explanation->setWordWrap(true);
    m_explanation->setTextFormat(Qt::RichText);
    // The words and controls in a column of their own that scrolls, so that the image is
    // always fitted whole to what is left of the view, however small the dock.
    auto* panel = new QWidget;
    panel->setObjectName(QStringLiteral("zbufferPanel"));
    auto* panelLayout = new QVBoxLayout(panel);
    panelLayout->setContentsMargins(0, 0, 0, 0);
    m_figures = new KeyFigures(this);
    m_figures->setParent(panel);
    panelLayout->addWidget(m_figures);
    panelLayout->addWidget(m_explanation);
    panelLayout->addWidget(m_histogramWidget);
    panelLayout->addWidget(m_rangeLabel);
    panelLayout->addWidget(m_automatic);  // outside the form, where its text can wrap
    panelLayout->addLayout(form);
    panelLayout->addWidget(m_valueLabel);
    panelLayout->addStretch(1);
    m_panel = new QScrollArea(this);
    m_panel->setObjectName(QStringLiteral("zbufferPanelScroll"));
    m_panel->setFrameShape(QFrame::NoFrame);
    m_panel->setWidgetResizable(true);
    m_panel->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_panel->setWidget(panel);
    m_view->setPreferredSize(QSize(160, 120));
    m_view->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    m_layout = new QBoxLayout(QBoxLayout::LeftToRight, this);
    m_layout->addWidget(m_view, 3);
    m_layout->addWidget(m_panel, 2);
    arrange();

    connect(m_automatic, &QCheckBox::toggled, this, &ZBufferView::setAutomaticRange);
    const auto manual = [this] {
        setManualRange(float(m_nearest->value()), float(m_farthest->value()));
    };
    connect(m_nearest, &QDoubleSpinBox::valueChanged, this, manual);
    connect(m_farthest, &QDoubleSpinBox::valueChanged, this, manual);
    connect(m_paletteBox, &QComboBox::currentIndexChanged, this, [this](int index) {
        setPalette(index == 1 ? DepthPalette::FalseColour : DepthPalette::Grey);
    });
    connect(m_view, &FrameImageView::pixelHovered, this, &ZBufferView::showValue);
    connect(m_view, &FrameImageView::pixelPicked, this, &ZBufferView::showValue);
}

void ZBufferView::setFrame(std::shared_ptr<const rl::FrameTrace> frame) {
    if (frame != m_frame) m_view->setOverlay({});  // marks belong to the frame they were made on
    m_frame = std::move(frame);
    m_buffers.reset();
    m_tested = m_frame && m_frame->depth ? m_frame->depth->fragments : 0;
    m_written = m_frame && m_frame->depth ? m_frame->depth->passed : 0;
    refreshWhenShown();
}

void ZBufferView::markPixels(const std::vector<QPoint>& pixels) {
    ImageOverlay overlay;
    overlay.sampleOffset = m_frame ? m_frame->scene->rules.sampleOffset : 0.5;
    if (!pixels.empty() && m_frame) {
        QImage mask(m_frame->scene->width, m_frame->scene->height, QImage::Format_ARGB32);
        mask.fill(Qt::transparent);
        for (const QPoint& p : pixels)
            if (mask.rect().contains(p)) mask.setPixelColor(p, QColor(255, 30, 30, 220));
        overlay.coverage = mask;
    }
    m_marked = pixels.size();
    m_view->setOverlay(std::move(overlay));
}

void ZBufferView::setBuffers(std::shared_ptr<const rl::DepthTest> buffers, std::size_t tested,
                             std::size_t written) {
    m_buffers = std::move(buffers);
    m_tested = tested;
    m_written = written;
    refreshWhenShown();
}

void ZBufferView::refreshWhenShown() {
    if (onScreen(this))
        refresh();
    else
        m_stale = true;
}

void ZBufferView::arrange() {
    // Wider than tall (a dock, the window filled, the lecture layout): the column beside the
    // image; taller: below it. The image takes three fifths either way.
    const bool beside = width() >= height();
    m_layout->setDirection(beside ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom);
    // The column as wide as its widest control (larger text, another language): it scrolls
    // up and down, never sideways.
    m_panel->setMinimumWidth(m_panel->widget()->minimumSizeHint().width() +
                             m_panel->verticalScrollBar()->sizeHint().width());
}

void ZBufferView::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange || event->type() == QEvent::LanguageChange)
        arrange();
}

void ZBufferView::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    arrange();
}

void ZBufferView::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    if (m_stale) refresh();
}

bool ZBufferView::event(QEvent* event) {
    if (event->type() == kRaisedEvent) {
        if (m_stale) refresh();
        return true;
    }
    return QWidget::event(event);
}

const rl::DepthTest* ZBufferView::shown() const {
    if (m_buffers) return m_buffers.get();
    return m_frame ? m_frame->depth.get() : nullptr;
}

QString ZBufferView::explanation() const {
    if (!m_frame || !m_frame->scene) return {};
    const rl::Conventions& c = m_frame->scene->conventions;
    const QString clear =
        std::isinf(c.depthClear) ? tr("+&infin;") : QString::number(double(c.depthClear));
    const QString stored =
        QStringLiteral("z<sub>%1</sub>").arg(tr("stored", "subscript: the depth the z-buffer holds"));
    const QString test =
        (c.depthWinsOnTie ? QStringLiteral("z &le; %1") : QStringLiteral("z &lt; %1")).arg(stored);
    const QString what =
        c.depth == rl::DepthSource::ViewZ ? tr("the view-space z of P'") : tr("the NDC z");
    const bool reciprocal = rl::perspectiveDepth(*m_frame->scene);
    const QString formula =
        reciprocal ? QStringLiteral(
                         "1/z = &alpha;/z<sub>1</sub> + &beta;/z<sub>2</sub> + "
                         "&gamma;/z<sub>3</sub>")
                   : QStringLiteral(
                         "z = &alpha;z<sub>1</sub> + &beta;z<sub>2</sub> + &gamma;z<sub>3</sub>");
    return tr("<b>Z-buffer.</b> Every pixel starts at %1. Each fragment's depth %2 (%3) is "
              "compared with the stored one; it is written, with its colour, only when %4. "
              "So far: %5 fragments tested, %6 written, %7 rejected.")
        .arg(clear, formula, what, test)
        .arg(m_tested)
        .arg(m_written)
        .arg(m_tested - std::min(m_tested, m_written));
}

bool ZBufferView::automaticRange() const {
    return m_automatic->isChecked();
}

void ZBufferView::setAutomaticRange(bool automatic) {
    {
        const QSignalBlocker block(m_automatic);
        m_automatic->setChecked(automatic);
    }
    m_nearest->setEnabled(!automatic);
    m_farthest->setEnabled(!automatic);
    refresh();
}

void ZBufferView::setManualRange(float nearest, float farthest) {
    {
        const QSignalBlocker blockAutomatic(m_automatic);
        const QSignalBlocker blockNearest(m_nearest);
        const QSignalBlocker blockFarthest(m_farthest);
        m_automatic->setChecked(false);
        m_nearest->setEnabled(true);
        m_farthest->setEnabled(true);
        m_nearest->setValue(nearest);
        m_farthest->setValue(farthest);
    }
    m_range = DepthRange{std::min(nearest, farthest), std::max(nearest, farthest), true};
    refresh();
}

void ZBufferView::setPalette(DepthPalette palette) {
    m_palette = palette;
    {
        const QSignalBlocker block(m_paletteBox);
        m_paletteBox->setCurrentIndex(palette == DepthPalette::FalseColour ? 1 : 0);
    }
    refresh();
}

void ZBufferView::refresh() {
    m_stale = false;
    m_explanation->setText(explanation());
    m_figures->setText(tr("%1 tested · %2 written · %3 rejected")
                           .arg(m_tested)
                           .arg(m_written)
                           .arg(m_tested - std::min(m_tested, m_written)));
    if (!m_frame || !m_frame->depth) {
        m_image = QImage();
        m_histogram = DepthHistogram{};
        m_view->setImage(m_image);
        m_histogramWidget->setHistogram(m_histogram, m_range, m_palette);
        m_rangeLabel->setText(tr("No frame yet."));
        return;
    }
    const rl::DepthTest& depth = *shown();
    const DepthRange drawn = coveredDepthRange(depth);
    if (automaticRange()) {
        m_range = drawn;
        const QSignalBlocker blockNearest(m_nearest);
        const QSignalBlocker blockFarthest(m_farthest);
        m_nearest->setValue(drawn.nearest);
        m_farthest->setValue(drawn.farthest);
    }
    m_image = depthImage(depth, m_range, m_palette);
    m_histogram = depthHistogram(depth, m_range, 64);
    m_view->setImage(m_image);
    m_histogramWidget->setHistogram(m_histogram, m_range, m_palette);
    if (!drawn.valid) {
        m_rangeLabel->setText(tr("No pixel holds a triangle: the buffer is all clear value."));
        return;
    }
    m_figures->setText(m_figures->text() + QLatin1Char('\n') +
                       QStringLiteral("z %1 – %2")
                           .arg(double(drawn.nearest), 0, 'g', 6)
                           .arg(double(drawn.farthest), 0, 'g', 6));
    QString text = tr("Drawn depths from %1 to %2; shown from %3 to %4.")
                       .arg(double(drawn.nearest), 0, 'g', 6)
                       .arg(double(drawn.farthest), 0, 'g', 6)
                       .arg(double(m_range.nearest), 0, 'g', 6)
                       .arg(double(m_range.farthest), 0, 'g', 6);
    if (m_histogram.below > 0 || m_histogram.above > 0)
        text += QLatin1Char(' ') + tr("%1 pixels nearer and %2 farther than the range are drawn "
                                      "at its ends.")
                                       .arg(m_histogram.below)
                                       .arg(m_histogram.above);
    m_rangeLabel->setText(text);
}

QString ZBufferView::valueText(QPoint pixel) const {
    if (!m_frame || !m_frame->depth) return {};
    const rl::DepthTest& depth = *shown();
    if (!depth.depth.contains(pixel.x(), pixel.y())) return {};
    const std::uint32_t t = depth.triangle.at(pixel.x(), pixel.y());
    const float z = depth.depth.at(pixel.x(), pixel.y());
    if (t == rl::kNoTriangle) {
        const QString clear = std::isinf(z) ? tr("+inf") : QString::number(double(z), 'g', 6);
        return tr("x %1, y %2: no triangle; the depth stays at the clear value %3")
            .arg(pixel.x())
            .arg(pixel.y())
            .arg(clear);
    }
    return tr("x %1, y %2: depth %3, triangle %4")
        .arg(pixel.x())
        .arg(pixel.y())
        .arg(double(z), 0, 'g', 8)
        .arg(t);
}

void ZBufferView::showValue(QPoint pixel) {
    m_valueLabel->setText(pixel.x() < 0 ? QString() : valueText(pixel));
}

}  // namespace rasterlab
