// The Check dock (File > Check My Renderer...): a student's program, given as a command and
// the folder it runs in, asked for every stage of the scene shown over the stage protocol
// (app/check/), on a worker thread with a progress bar and Cancel, so that the window never
// waits on it. Each stage's verdict is listed; the stage selected shows its first departure,
// the formula and the likely cause, and its departures drawn over our image: their vertices
// beside ours, the pixels only one side covers or wins. Stop at the First Departure steps
// the frame to it.
#pragma once

#include <QFutureWatcher>
#include <QImage>
#include <QWidget>

#include <array>
#include <atomic>
#include <optional>

#include "app/check/check_session.h"
#include "pipeline/core/stage_id.h"
#include "pipeline/render/frame_trace.h"

class QCheckBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QSplitter;
class QPushButton;
class QTreeWidget;

namespace rasterlab {

class Inspection;
class DepartureCanvas;

class CheckPanel : public QWidget {
    Q_OBJECT
public:
    explicit CheckPanel(Inspection* inspection, QWidget* parent = nullptr);
    ~CheckPanel() override;  // cancels a check that runs, and waits for its worker

    QString command() const;
    void setCommand(const QString& command);
    QString folder() const;
    void setFolder(const QString& folder);

    // Starts checking the frame shown: an empty string, or why it cannot start.
    QString start();
    void cancel();
    bool isRunning() const { return m_watcher.isRunning(); }
    const check::CheckReport* report() const { return m_report ? &*m_report : nullptr; }
    // The frame the last check ran on.
    const std::shared_ptr<const rl::FrameTrace>& checkedFrame() const { return m_frame; }

    // The lecture's stage a protocol stage belongs to (the frame: shading, its last).
    static rl::StageId lectureStage(check::Stage stage);
    // The worst verdict of the last check for a lecture stage, if the check asked for it (the
    // frame, the whole pipeline, is no stage's).
    std::optional<check::Verdict> verdict(rl::StageId stage) const;

    // The stage selected in the list, and what is said of it.
    std::optional<check::Stage> selectedStage() const;
    const check::StageResult* selectedResult() const;
    // Their frame as the last check read it (null when its frame stage gave none).
    QImage theirFrame() const;
    QString detailsText() const;
    // Steps the frame to the selected stage's first departure: the pixel picked and the
    // frame stepped to its first fragment, or the triangle selected. False when it has none.
    bool stopAtFirstDeparture();

    QPushButton* checkButton() const { return m_run; }
    QCheckBox* chainBox() const { return m_chain; }
    QPushButton* cancelButton() const { return m_cancel; }
    QPushButton* stopButton() const { return m_stop; }
    QProgressBar* progressBar() const { return m_progress; }
    QTreeWidget* stageList() const { return m_stages; }
    const DepartureCanvas* canvas() const { return m_canvas; }

    // A verdict's name, translated.
    static QString verdictText(check::Verdict verdict);
    // What the picture shows of a stage's departures (empty when there are none).
    static QString legend(check::Stage stage, bool any);

    QPushButton* compareButton() const { return m_compare; }

signals:
    void finished();  // a check ended, or was cancelled: the verdicts changed
    // Compare Their Frame: their frame's image, for the Compare dock (its pixels' colours
    // beside ours and the Phong term that would have to change).
    void compareFrame(const QImage& theirs);
    void settingsChanged();

private:
    void onFinished();
    void showReport();
    void showSelected();
    void fitSplit();
    void setProgress(int done, int total, const QString& what);

    Inspection* m_inspection = nullptr;
    QLineEdit* m_command = nullptr;
    QLineEdit* m_folder = nullptr;
    QPushButton* m_browse = nullptr;
    QPushButton* m_run = nullptr;
    QCheckBox* m_chain = nullptr;
    QPushButton* m_cancel = nullptr;
    QPushButton* m_stop = nullptr;
    QPushButton* m_compare = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_protections = nullptr;
    QTreeWidget* m_stages = nullptr;
    QSplitter* m_split = nullptr;  // the list, the words, the picture
    QLabel* m_details = nullptr;
    DepartureCanvas* m_canvas = nullptr;
    QLabel* m_legend = nullptr;

    std::atomic<bool> m_cancelled{false};
    QFutureWatcher<check::CheckReport> m_watcher;
    std::optional<check::CheckReport> m_report;
    QImage m_image;  // our frame when the check started
    std::shared_ptr<const rl::FrameTrace> m_frame;
};

// Our image with a stage's departures over it.
class DepartureCanvas : public QWidget {
    Q_OBJECT
public:
    explicit DepartureCanvas(QWidget* parent = nullptr);
    void show(const QImage& image, const std::vector<check::Departure>& departures);
    const std::vector<check::Departure>& departures() const { return m_departures; }
    QSize sizeHint() const override { return {320, 240}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QImage m_image;
    std::vector<check::Departure> m_departures;
};

}  // namespace rasterlab
