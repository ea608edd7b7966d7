#include "accuracy_panel.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMouseEvent>
#include <QProgressBar>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <utility>
#include <vector>

#include "app/plots/accuracy_plot.h"
#include "app/plots/stability_plot.h"
#include "views/messages/pipeline_messages.h"

namespace rasterlab {

namespace {

// A picture that follows the room it is given: its size hint is its minimum, not its pixmap's
// (a layout short of room then shares it out without laying one picture over the next).
class PictureLabel : public QLabel {
public:
    using QLabel::QLabel;
    QSize sizeHint() const override { return minimumSizeHint(); }
    QSize minimumSizeHint() const override { return minimumSize(); }
};

// A plot scaled smoothly into its label, keeping its proportions.
void fitPicture(QLabel* label, const QImage& image) {
    if (image.isNull()) return;
    label->setPixmap(QPixmap::fromImage(image).scaled(label->size(), Qt::KeepAspectRatio,
                                                      Qt::SmoothTransformation));
}

QString percent(double share) {
    return QString::number(100.0 * share, 'f', 3) + QStringLiteral(" %");
}

QString bytes(const rl::dvec3& c) {
    return QStringLiteral("(%1, %2, %3)")
        .arg(c.r * 255.0, 0, 'f', 2)
        .arg(c.g * 255.0, 0, 'f', 2)
        .arg(c.b * 255.0, 0, 'f', 2);
}

// Runs a measurement on the worker: its report, or whether it was cancelled (its flag is
// set, as ReplayBuilder tells), or its error in the user's language.
template <typename Outcome, typename Measure>
Outcome runJob(quint64 generation, const std::atomic<bool>& cancel, Measure measure) {
    Outcome outcome;
    outcome.generation = generation;
    try {
        auto report = measure();
        if (report)
            outcome.report = std::make_shared<typename decltype(outcome.report)::element_type>(
                std::move(report.value()));
        else if (!(outcome.cancelled = cancel.load()))
            outcome.error = translated(report.error());
    } catch (const std::exception& e) {
        outcome.error = QString::fromUtf8(e.what());
    }
    return outcome;
}

QString scientific(double v) {
    return QString::number(v, 'g', 3);
}

// What the axis does to the scene, from its mildest to its stiffest value.
QString axisDescription(const rl::StiffnessAxisInfo& info) {
    QString text;
    switch (info.axis) {
        case rl::StiffnessAxis::Offset:
            text = AccuracyPanel::tr(
                "The scene, camera and lights moved %1 to %2 units from the "
                "origin");
            break;
        case rl::StiffnessAxis::Scale:
            text = AccuracyPanel::tr("Everything scaled by %1 to %2 about the origin");
            break;
        case rl::StiffnessAxis::Distance:
            text =
                AccuracyPanel::tr("Everything scaled by %1 to %2 about the eye: the object nearer");
            break;
        case rl::StiffnessAxis::Sliver:
            text = AccuracyPanel::tr("Each triangle cut around a sliver of %1 to %2 degrees");
            break;
        case rl::StiffnessAxis::Shininess:
            text = AccuracyPanel::tr("Every material's shininess n set to %1 to %2");
            break;
        case rl::StiffnessAxis::Grazing:
            text = AccuracyPanel::tr("The camera's V %1 to %2 degrees from N");
            break;
        case rl::StiffnessAxis::LightOnSurface:
            text = AccuracyPanel::tr(
                "The first light %1 to %2 times the scene's size above its "
                "surface");
            break;
    }
    return text.arg(scientific(info.values.front()), scientific(info.values.back()));
}

// A line per axis: the largest float-double difference and where, the largest RMSE of each
// precision, and the points that could not be rendered, with the first one's reason.
QString summaryOf(const rl::StabilityReport& report) {
    QStringList lines;
    std::optional<rl::StiffnessAxis> axis;
    for (std::size_t first = 0; first < report.points.size();) {
        axis = report.points[first].axis;
        std::size_t end = first;
        while (end < report.points.size() && report.points[end].axis == *axis) ++end;
        double worstDiff = -1.0, worstAt = 0.0;
        std::vector<std::pair<rl::RuleSet, std::array<double, 2>>> rmse;  // float, double
        int refused = 0;
        const rl::StabilityPoint* firstRefused = nullptr;
        for (std::size_t i = first; i < end; ++i) {
            const rl::StabilityPoint& p = report.points[i];
            if (p.error) {
                ++refused;
                if (!firstRefused) firstRefused = &p;
                continue;
            }
            if (!std::isnan(p.floatDoubleMax) && p.floatDoubleMax > worstDiff) {
                worstDiff = p.floatDoubleMax;
                worstAt = p.value;
            }
            auto rules = std::find_if(rmse.begin(), rmse.end(),
                                      [&](const auto& r) { return r.first == p.row.mode.rules; });
            if (rules == rmse.end())
                rules = rmse.insert(rmse.end(), {p.row.mode.rules, {0.0, 0.0}});
            double& worst = rules->second[p.row.precision == "double" ? 1 : 0];
            if (std::isfinite(p.row.metrics.rmse)) worst = std::max(worst, p.row.metrics.rmse);
        }
        QStringList perRules;
        for (const auto& [rules, worst] : rmse)
            perRules << QStringLiteral("%1 %2 / %3")
                            .arg(QString::fromLatin1(rl::ruleSetName(rules)),
                                 scientific(worst[0] * 255.0), scientific(worst[1] * 255.0));
        QString line = QString::fromLatin1(rl::axisInfo(*axis).name) + QStringLiteral(": ");
        if (worstDiff >= 0.0)
            line += AccuracyPanel::tr(
                        "float and double differ by up to %1 byte steps (at %2); "
                        "largest RMSE, float / double: %3.")
                        .arg(scientific(worstDiff * 255.0), scientific(worstAt),
                             perRules.join(QStringLiteral(", ")));
        if (firstRefused) {
            if (worstDiff >= 0.0) line += QLatin1Char(' ');
            line += AccuracyPanel::tr("%1 of %2 points not rendered (the first at %3): %4")
                        .arg(refused)
                        .arg(int(end - first))
                        .arg(scientific(firstRefused->value),
                             translated(firstRefused->error->translatable));
        }
        lines << line;
        first = end;
    }
    return lines.join(QLatin1Char('\n'));
}

}  // namespace

AccuracyPanel::AccuracyPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("accuracyPanel"));
    auto* layout = new QVBoxLayout(this);
    auto* controls = new QHBoxLayout;
    m_measure = new QPushButton(tr("&Measure"), this);
    m_measure->setObjectName(QStringLiteral("measureAccuracy"));
    m_measure->setToolTip(
        tr("Render the scene in every mode and compare each with an exact "
           "ray-cast reference"));
    m_cancelButton = new QPushButton(tr("Cancel"), this);
    m_cancelButton->setObjectName(QStringLiteral("cancelAccuracy"));
    m_cancelButton->setEnabled(false);
    m_samples = new QComboBox(this);
    m_samples->setObjectName(QStringLiteral("accuracySamples"));
    m_samples->addItem(tr("1 sample a pixel"), 1);
    m_samples->addItem(tr("also 2x2 samples"), 2);
    m_samples->addItem(tr("also 4x4 samples"), 4);
    controls->addWidget(m_measure);
    controls->addWidget(m_cancelButton);
    controls->addWidget(m_samples, 1);
    layout->addLayout(controls);

    auto* sweepControls = new QHBoxLayout;
    m_sweep = new QPushButton(tr("&Stability sweep"), this);
    m_sweep->setObjectName(QStringLiteral("stabilitySweep"));
    m_sweep->setToolTip(
        tr("Make the scene stiffer step by step and measure float and double under the course "
           "and gpu rules against the exact reference at each step"));
    m_axes = new QComboBox(this);
    m_axes->setObjectName(QStringLiteral("stabilityAxes"));
    m_axes->addItem(tr("every axis"), -1);
    for (const rl::StiffnessAxisInfo& info : rl::stiffnessAxes()) {
        m_axes->addItem(QString::fromLatin1(info.name), int(info.axis));
        m_axes->setItemData(m_axes->count() - 1, axisDescription(info), Qt::ToolTipRole);
    }
    m_axes->setToolTip(tr("The axes of stiffness to sweep"));
    sweepControls->addWidget(m_sweep);
    sweepControls->addWidget(m_axes, 1);
    layout->addLayout(sweepControls);
    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("stabilityProgress"));
    m_progress->setFormat(tr("%v of %m points"));
    m_progress->setVisible(false);
    layout->addWidget(m_progress);

    m_status = new QLabel(tr("Measures the error of each mode against an exact reference."), this);
    m_status->setObjectName(QStringLiteral("accuracyStatus"));
    m_status->setWordWrap(true);
    layout->addWidget(m_status);
    m_results = new QTabWidget(this);
    m_results->setObjectName(QStringLiteral("accuracyResults"));
    m_results->setDocumentMode(true);
    m_results->addTab(makeModesPage(), tr("Modes"));
    m_results->addTab(makeStabilityPage(), tr("Stability"));
    layout->addWidget(m_results, 1);

    connect(m_measure, &QPushButton::clicked, this, &AccuracyPanel::measure);
    connect(m_sweep, &QPushButton::clicked, this, &AccuracyPanel::sweep);
    connect(m_cancelButton, &QPushButton::clicked, this, &AccuracyPanel::cancel);
    connect(&m_watcher, &QFutureWatcher<Outcome>::finished, this, &AccuracyPanel::onFinished);
    connect(&m_sweepWatcher, &QFutureWatcher<SweepOutcome>::finished, this,
            &AccuracyPanel::onSweepFinished);
    connect(m_table, &QTableWidget::currentCellChanged, this, [this](int row) { selectRow(row); });
    connect(m_results, &QTabWidget::currentChanged, this, [this] { refreshImages(); });
}

QWidget* AccuracyPanel::makeModesPage() {
    auto* page = new QWidget(this);
    auto* layout = new QVBoxLayout(page);
    layout->setContentsMargins(0, 0, 0, 0);
    m_table = new QTableWidget(0, 8, page);
    m_table->setObjectName(QStringLiteral("accuracyTable"));
    m_table->setHorizontalHeaderLabels({tr("Mode"), tr("Rules"), tr("Precision"), tr("Samples"),
                                        tr("ms"), tr("RMSE"), tr("Max error"), tr("Within 1/255")});
    m_table->setToolTip(tr("Errors in byte steps (1/255) over the pixels both images cover"));
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->setVisible(false);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    // Eight columns of figures: more than a side dock holds, it scrolls sideways
    // (tests/tst_legibility.cpp lets it; each column still fits its text).
    m_table->setProperty("scrollsSideways", true);
    layout->addWidget(m_table, 2);

    m_plotLabel = new PictureLabel(page);
    m_plotLabel->setObjectName(QStringLiteral("accuracyPlot"));
    m_plotLabel->setMinimumHeight(120);
    // The pictures follow the dock's size, never the other way round.
    m_plotLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Expanding);
    m_plotLabel->setAlignment(Qt::AlignCenter);
    layout->addWidget(m_plotLabel, 3);
    m_heatLabel = new PictureLabel(page);
    m_heatLabel->setObjectName(QStringLiteral("accuracyHeatMap"));
    m_heatLabel->setMinimumHeight(120);
    m_heatLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Expanding);
    m_heatLabel->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_heatLabel->setCursor(Qt::CrossCursor);
    m_heatLabel->setToolTip(tr("Click a pixel to compare the mode with the reference there"));
    m_heatLabel->installEventFilter(this);
    layout->addWidget(m_heatLabel, 3);
    // Its minimum height its wrapped lines': the pictures above cannot squeeze it.
    m_pick = new WrappedLabel(page);
    m_pick->setObjectName(QStringLiteral("accuracyPick"));
    m_pick->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_pick);
    return page;
}

QWidget* AccuracyPanel::makeStabilityPage() {
    auto* page = new QWidget(this);
    auto* layout = new QVBoxLayout(page);
    layout->setContentsMargins(0, 0, 0, 0);
    m_stabilityLabel = new PictureLabel(page);
    m_stabilityLabel->setObjectName(QStringLiteral("stabilityPlot"));
    m_stabilityLabel->setMinimumHeight(120);
    m_stabilityLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Expanding);
    m_stabilityLabel->setAlignment(Qt::AlignCenter);
    // Drawn again at its own size: inside the tabs, it is resized after the panel.
    m_stabilityLabel->installEventFilter(this);
    layout->addWidget(m_stabilityLabel, 1);
    m_summary = new QLabel(page);
    m_summary->setWordWrap(true);
    m_summary->setObjectName(QStringLiteral("stabilitySummary"));
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_summary->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_summary->setText(
        tr("The sweep makes the scene stiffer along each axis: where a curve leaves the floor, "
           "the arithmetic loses accuracy."));
    layout->addWidget(m_summary);
    return page;
}

AccuracyPanel::~AccuracyPanel() {
    if (m_cancel) m_cancel->store(true);
    if (m_sweepCancel) m_sweepCancel->store(true);
    m_watcher.waitForFinished();
    m_sweepWatcher.waitForFinished();
}

void AccuracyPanel::setScene(std::shared_ptr<const rl::Scene> scene) {
    if (scene == m_scene) return;
    m_scene = std::move(scene);
    if (m_running && m_cancel) m_cancel->store(true);
    if (m_sweeping && m_sweepCancel) m_sweepCancel->store(true);
    ++m_generation;  // a result on its way is for the old scene
    ++m_sweepGeneration;
    const bool hadResults = m_report != nullptr || m_stability != nullptr;
    m_report.reset();
    m_stability.reset();
    m_stabilityPlot = QImage();
    m_stabilityLabel->clear();
    m_summary->clear();
    m_progress->setVisible(false);
    m_selected = -1;
    m_table->setRowCount(0);
    m_plot = m_heatMap = QImage();
    m_plotLabel->clear();
    m_heatLabel->clear();
    m_pick->clear();
    if (hadResults || m_running || m_sweeping)
        m_status->setText(tr("The scene changed: measure again."));
}

void AccuracyPanel::measure() {
    if (!m_scene || m_sweeping) return;
    if (m_running && m_cancel) m_cancel->store(true);
    m_watcher.waitForFinished();
    const quint64 generation = ++m_generation;
    m_cancel = std::make_shared<std::atomic<bool>>(false);
    rl::AccuracyOptions options;
    const int k = m_samples->currentData().toInt();
    std::vector<int> samples = {1};
    if (k > 1) samples.push_back(k);
    options.modes = rl::defaultAccuracyModes(
        {rl::ShadingModel::Flat, rl::ShadingModel::Gouraud, rl::ShadingModel::Phong},
        {rl::RuleSet::Course, rl::RuleSet::Gpu, rl::RuleSet::Hw2}, samples);
    options.repeats = 3;
    options.keepImages = true;
    options.cancel = m_cancel.get();
    m_running = true;
    setBusy(true);
    m_results->setCurrentIndex(0);
    m_status->setText(tr("Measuring %n mode(s) against the exact reference...", nullptr,
                         int(options.modes.size())));
    // The cancel flag lives as long as the worker holds its pointer.
    m_watcher.setFuture(QtConcurrent::run([generation, scene = m_scene, options, flag = m_cancel] {
        return runJob<Outcome>(generation, *flag,
                               [&] { return rl::measureAccuracy(*scene, options); });
    }));
}

void AccuracyPanel::cancel() {
    if (m_running && m_cancel) m_cancel->store(true);
    if (m_sweeping && m_sweepCancel) m_sweepCancel->store(true);
}

void AccuracyPanel::onFinished() {
    const Outcome outcome = m_watcher.result();
    m_running = false;
    setBusy(false);
    if (outcome.generation != m_generation) {
        emit finished();
        return;  // for a scene no longer shown, or a measurement replaced
    }
    if (!outcome.report) {
        m_status->setText(outcome.cancelled ? tr("Cancelled.")
                                            : tr("The measurement failed: %1").arg(outcome.error));
        emit finished();
        return;
    }
    m_report = outcome.report;
    const rl::AccuracyReport& report = *m_report;
    m_status->setText(tr("%1 at %2x%3: %4 modes; the exact reference cast %5 rays in %6 ms.")
                          .arg(QString::fromStdString(m_scene->name))
                          .arg(m_scene->width)
                          .arg(m_scene->height)
                          .arg(report.rows.size())
                          .arg(report.referenceRays)
                          .arg(report.referenceMilliseconds, 0, 'f', 0));
    m_table->setRowCount(int(report.rows.size()));
    for (int r = 0; r < int(report.rows.size()); ++r) {
        const rl::AccuracyRow& row = report.rows[std::size_t(r)];
        const rl::AccuracyMetrics& m = row.metrics;
        const QStringList cells = {
            QString::fromLatin1(rl::shadingModelName(row.mode.shading)),
            QString::fromLatin1(rl::ruleSetName(row.mode.rules)),
            QString::fromStdString(row.precision),
            QString::number(row.mode.supersample * row.mode.supersample),
            QString::number(row.milliseconds, 'f', 2),
            QString::number(m.rmse * 255.0, 'f', 4),
            QString::number(m.maxError * 255.0, 'f', 2),
            percent(m.within1Of255),
        };
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            if (c >= 3) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_table->setItem(r, c, item);
        }
    }
    m_plot = accuracyPlot(report, tr("Error against run time: %1, %2x%3")
                                      .arg(QString::fromStdString(m_scene->name))
                                      .arg(m_scene->width)
                                      .arg(m_scene->height));
    // The mode that is interesting first: Phong under the GPU-like rules, if measured.
    int first = 0;
    for (int r = 0; r < int(report.rows.size()); ++r) {
        const rl::AccuracyRow& row = report.rows[std::size_t(r)];
        if (row.mode.shading == rl::ShadingModel::Phong && row.mode.rules == rl::RuleSet::Gpu &&
            row.precision == "float" && row.mode.supersample == 1)
            first = r;
    }
    m_table->setCurrentCell(first, 0);
    selectRow(first);
    emit finished();
}

void AccuracyPanel::setSweepAxis(std::optional<rl::StiffnessAxis> axis) {
    const int index = m_axes->findData(axis ? int(*axis) : -1);
    if (index >= 0) m_axes->setCurrentIndex(index);
}

void AccuracyPanel::sweep() {
    if (!m_scene || m_running) return;
    if (m_sweeping && m_sweepCancel) m_sweepCancel->store(true);
    m_sweepWatcher.waitForFinished();
    const quint64 generation = ++m_sweepGeneration;
    m_sweepCancel = std::make_shared<std::atomic<bool>>(false);
    rl::StabilityOptions options;
    if (const int axis = m_axes->currentData().toInt(); axis >= 0)
        options.axes = {rl::StiffnessAxis(axis)};
    options.cancel = m_sweepCancel.get();
    // Called on the worker thread: the numbers go to the panel's thread as an event (dropped
    // with the panel, which waits for the worker before it goes).
    options.progress = [this, generation](int done, int total) {
        QMetaObject::invokeMethod(
            this, [this, generation, done, total] { onSweepProgress(generation, done, total); },
            Qt::QueuedConnection);
    };
    m_sweeping = true;
    setBusy(true);
    m_progress->setRange(0, 0);  // busy until the first point: the references come first
    m_progress->setVisible(true);
    m_results->setCurrentIndex(1);
    m_status->setText(tr("Sweeping %1 along %2...")
                          .arg(QString::fromStdString(m_scene->name), m_axes->currentText()));
    m_sweepWatcher.setFuture(
        QtConcurrent::run([generation, scene = m_scene, options, flag = m_sweepCancel] {
            return runJob<SweepOutcome>(generation, *flag,
                                        [&] { return rl::measureStability(*scene, options); });
        }));
}

void AccuracyPanel::onSweepProgress(quint64 generation, int done, int total) {
    if (!m_sweeping || generation != m_sweepGeneration) return;
    m_progress->setRange(0, total);
    m_progress->setValue(done);
}

void AccuracyPanel::onSweepFinished() {
    const SweepOutcome outcome = m_sweepWatcher.result();
    m_sweeping = false;
    setBusy(false);
    m_progress->setVisible(false);
    if (outcome.generation != m_sweepGeneration) {
        emit sweepFinished();
        return;  // for a scene no longer shown, or a sweep replaced
    }
    if (!outcome.report) {
        m_status->setText(outcome.cancelled ? tr("Sweep cancelled.")
                                            : tr("The sweep failed: %1").arg(outcome.error));
        emit sweepFinished();
        return;
    }
    m_stability = outcome.report;
    m_stabilityPlot =
        rasterlab::stabilityPlot(*m_stability,
                                 tr("Error against stiffness: %1, %2x%3, %4 triangles")
                                     .arg(QString::fromStdString(m_scene->name))
                                     .arg(m_scene->width)
                                     .arg(m_scene->height)
                                     .arg(m_scene->triangleCount()),
                                 stabilityPlotSize(*m_stability));
    m_status->setText(tr("%1 at %2x%3: %4 points in %5 s.")
                          .arg(QString::fromStdString(m_scene->name))
                          .arg(m_scene->width)
                          .arg(m_scene->height)
                          .arg(m_stability->points.size())
                          .arg(m_stability->milliseconds / 1000.0, 0, 'f', 1));
    m_summary->setText(summaryOf(*m_stability));
    m_results->setCurrentIndex(1);
    refreshImages();
    emit sweepFinished();
}

QString AccuracyPanel::stabilitySummary() const {
    return m_summary->text();
}

QString AccuracyPanel::statusText() const {
    return m_status->text();
}

void AccuracyPanel::setBusy(bool busy) {
    m_measure->setEnabled(!busy);
    m_sweep->setEnabled(!busy);
    m_cancelButton->setEnabled(busy);
}

void AccuracyPanel::selectRow(int row) {
    if (!m_report || row < 0 || row >= int(m_report->rows.size())) return;
    m_selected = row;
    const rl::AccuracyRow& r = m_report->rows[std::size_t(row)];
    if (r.image && r.reference) {
        // The map of the part of the image either covers (and a margin), so that a small
        // object is not lost in black.
        const rl::Image<float> full = rl::errorMap(*r.image, *r.reference);
        int x0 = full.width(), y0 = full.height(), x1 = -1, y1 = -1;
        for (int y = 0; y < full.height(); ++y)
            for (int x = 0; x < full.width(); ++x)
                if (!std::isnan(full.at(x, y))) {
                    x0 = std::min(x0, x);
                    y0 = std::min(y0, y);
                    x1 = std::max(x1, x);
                    y1 = std::max(y1, y);
                }
        if (x1 < 0) x0 = y0 = 0, x1 = full.width() - 1, y1 = full.height() - 1;
        const int margin = 8;
        x0 = std::max(0, x0 - margin);
        y0 = std::max(0, y0 - margin);
        x1 = std::min(full.width() - 1, x1 + margin);
        y1 = std::min(full.height() - 1, y1 + margin);
        rl::Image<float> part(x1 - x0 + 1, y1 - y0 + 1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) part.at(x - x0, y - y0) = full.at(x, y);
        m_heatOrigin = QPoint(x0, y0);
        m_heatMap = errorHeatMap(part, 8.0f / 255.0f);
    }
    const rl::AccuracyMetrics& m = r.metrics;
    m_pick->setText(tr("%1 (%2): coverage differs on %3 pixels (%4); the largest error, %5 byte "
                       "steps, is at (%6, %7). Click the map to compare a pixel.")
                        .arg(QString::fromStdString(rl::accuracyModeName(r.mode)),
                             QString::fromStdString(r.precision))
                        .arg(m.coverageMismatch)
                        .arg(percent(m.coverageMismatchShare()))
                        .arg(m.maxError * 255.0, 0, 'f', 2)
                        .arg(m.worstX)
                        .arg(m.worstY));
    refreshImages();
}

void AccuracyPanel::pickPixel(int x, int y) {
    if (!m_report || m_selected < 0) return;
    const rl::AccuracyRow& r = m_report->rows[std::size_t(m_selected)];
    if (!r.image || !r.reference || !r.image->colour.contains(x, y)) return;
    const rl::dvec3 ours = r.image->colour.at(x, y), exact = r.reference->colour.at(x, y);
    const int oursHits = r.image->hits.at(x, y), exactHits = r.reference->hits.at(x, y);
    const int samples = r.mode.supersample * r.mode.supersample;
    QString text = tr("Pixel (%1, %2), %3: mode %4, reference %5, difference %6 (byte steps).")
                       .arg(x)
                       .arg(y)
                       .arg(QString::fromStdString(rl::accuracyModeName(r.mode)), bytes(ours),
                            bytes(exact), bytes(ours - exact));
    if (oursHits != exactHits)
        text += QLatin1Char(' ') + tr("Coverage differs: %1 of %2 samples covered by the mode, "
                                      "%3 by the reference.")
                                       .arg(oursHits)
                                       .arg(samples)
                                       .arg(exactHits);
    m_pick->setText(text);
}

QString AccuracyPanel::pickText() const {
    return m_pick->text();
}

bool AccuracyPanel::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_stabilityLabel && event->type() == QEvent::Resize)
        fitPicture(m_stabilityLabel, m_stabilityPlot);
    if (watched == m_heatLabel && event->type() == QEvent::MouseButtonPress && m_report &&
        m_selected >= 0) {
        const auto* mouse = static_cast<QMouseEvent*>(event);
        const rl::AccuracyRow& r = m_report->rows[std::size_t(m_selected)];
        const QPixmap shown = m_heatLabel->pixmap();
        if (r.image && !shown.isNull() && !m_heatMap.isNull()) {
            // The map is drawn scaled at the label's top left.
            const double scale = double(shown.width()) / double(m_heatMap.width());
            const QPointF at = mouse->position() / scale;
            const int x = int(std::floor(at.x())) + m_heatOrigin.x(),
                      y = int(std::floor(at.y())) + m_heatOrigin.y();
            if (x < r.image->colour.width() && y < r.image->colour.height() && x >= 0 && y >= 0)
                pickPixel(x, y);
        }
        return true;
    }
    return QWidget::eventFilter(watched, event);
}

void AccuracyPanel::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    refreshImages();
}

void AccuracyPanel::refreshImages() {
    fitPicture(m_plotLabel, m_plot);
    fitPicture(m_stabilityLabel, m_stabilityPlot);
    // The heat map keeps its pixels sharp when enlarged.
    if (!m_heatMap.isNull())
        m_heatLabel->setPixmap(QPixmap::fromImage(m_heatMap).scaled(
            m_heatLabel->size(), Qt::KeepAspectRatio, Qt::FastTransformation));
}

}  // namespace rasterlab
