// The Accuracy dock: measures every mode of the current scene against the exact reference
// (accuracy.h) on a worker thread, and shows the table, the plot of error against time, and
// the error heat map of the selected mode, with a colour bar. Clicking the heat map picks a
// pixel: its value in the mode, in the reference, and the difference.
//
// It also runs the stability sweep (stability.h) of the scene, along every axis or one, on a
// worker thread with a progress bar, and shows its plot (stability_plot.h) and, per axis, the
// largest float-double difference and the points that could not be rendered.
#pragma once

#include <QFutureWatcher>
#include <QImage>
#include <QWidget>

#include <atomic>
#include <memory>
#include <optional>

#include "pipeline/analysis/accuracy.h"
#include "pipeline/analysis/stability.h"
#include "views/elided_label.h"

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QTabWidget;

namespace rasterlab {

class AccuracyPanel : public QWidget {
    Q_OBJECT
public:
    explicit AccuracyPanel(QWidget* parent = nullptr);
    ~AccuracyPanel() override;

    // The scene to measure; the results of another scene are cleared (and a running
    // measurement's result dropped).
    void setScene(std::shared_ptr<const rl::Scene> scene);
    void measure();
    // The stability sweep along the axis chosen (or every axis) with the course and gpu rules.
    void sweep();
    // Stops the measurement or the sweep that runs; it ends "cancelled".
    void cancel();
    // The row whose heat map is shown; picks the pixel (x, y) of it.
    void selectRow(int row);
    void pickPixel(int x, int y);

    bool isMeasuring() const { return m_running; }
    bool isSweeping() const { return m_sweeping; }
    // The axes chooser: none for every axis.
    void setSweepAxis(std::optional<rl::StiffnessAxis> axis);
    const rl::StabilityReport* stabilityReport() const { return m_stability.get(); }
    const QImage& stabilityPlot() const { return m_stabilityPlot; }
    QString stabilitySummary() const;
    QString statusText() const;
    const rl::AccuracyReport* report() const { return m_report.get(); }
    int selectedRow() const { return m_selected; }
    QString pickText() const;
    // The selected mode's heat map, cropped to the pixels either image covers (and a margin)
    // from heatMapOrigin() on, with its colour bar on the right.
    const QImage& heatMap() const { return m_heatMap; }
    QPoint heatMapOrigin() const { return m_heatOrigin; }
    const QImage& plot() const { return m_plot; }

signals:
    void finished();
    void sweepFinished();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    // What a worker hands back: its report, or why there is none (cancelled, or an error).
    template <typename Report>
    struct JobOutcome {
        quint64 generation = 0;
        std::shared_ptr<Report> report;
        QString error;
        bool cancelled = false;
    };
    using Outcome = JobOutcome<rl::AccuracyReport>;
    using SweepOutcome = JobOutcome<rl::StabilityReport>;
    QWidget* makeModesPage();
    QWidget* makeStabilityPage();
    void onFinished();
    void onSweepProgress(quint64 generation, int done, int total);
    void onSweepFinished();
    void setBusy(bool busy);
    void refreshImages();

    std::shared_ptr<const rl::Scene> m_scene;
    std::shared_ptr<rl::AccuracyReport> m_report;
    QFutureWatcher<Outcome> m_watcher;
    std::shared_ptr<std::atomic<bool>> m_cancel;
    quint64 m_generation = 0;
    bool m_running = false;
    int m_selected = -1;
    QImage m_plot, m_heatMap;
    QPoint m_heatOrigin;  // the image pixel at the heat map's top left

    std::shared_ptr<rl::StabilityReport> m_stability;
    QFutureWatcher<SweepOutcome> m_sweepWatcher;
    std::shared_ptr<std::atomic<bool>> m_sweepCancel;
    quint64 m_sweepGeneration = 0;
    bool m_sweeping = false;
    QImage m_stabilityPlot;

    QPushButton* m_measure = nullptr;
    QPushButton* m_cancelButton = nullptr;
    QComboBox* m_samples = nullptr;
    QLabel* m_status = nullptr;
    QTableWidget* m_table = nullptr;
    QLabel* m_plotLabel = nullptr;
    QLabel* m_heatLabel = nullptr;
    WrappedLabel* m_pick = nullptr;
    QPushButton* m_sweep = nullptr;
    QComboBox* m_axes = nullptr;
    QProgressBar* m_progress = nullptr;
    QTabWidget* m_results = nullptr;
    QLabel* m_stabilityLabel = nullptr;
    QLabel* m_summary = nullptr;
};

}  // namespace rasterlab
