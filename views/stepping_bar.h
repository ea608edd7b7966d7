// Stepping through the frame (stepping is replay, pipeline/replay.h): the granularity
// (stage, triangle, scanline, span, pixel), step back and forward, play and pause at a chosen
// number of steps a second (stopping at breakpoints), jump to the start or the end, continue
// to the next breakpoint, a timeline to scrub the frame fragment by fragment, and where the
// cursor is. The actions carry the shortcuts; the window puts them in its menu too.
#pragma once

#include <QTimer>
#include <QWidget>

#include "views/elided_label.h"
#include "views/inspection.h"

class QAction;
class QComboBox;
class QLabel;
class QSlider;
class QSpinBox;
class QToolButton;

namespace rasterlab {

class SteppingBar : public QWidget {
    Q_OBJECT
public:
    explicit SteppingBar(Inspection* inspection, QWidget* parent = nullptr);

    QAction* stepBackAction() const { return m_back; }
    QAction* stepForwardAction() const { return m_forward; }
    QAction* playAction() const { return m_play; }
    QAction* toStartAction() const { return m_start; }
    QAction* toEndAction() const { return m_end; }
    QAction* continueAction() const { return m_continue; }
    QList<QAction*> granularityActions() const { return m_granularityActions; }

    bool isPlaying() const { return m_timer.isActive(); }
    void setPlaying(bool playing);
    void setSpeed(int stepsPerSecond);  // how many steps a second Play makes
    QSlider* timeline() const { return m_timeline; }
    // The position, elided when narrow (ElidedLabel::fullText() whole).
    ElidedLabel* positionLabel() const { return m_position; }

    static QString granularityName(rl::StepGranularity granularity);

protected:
    void changeEvent(QEvent* event) override;

private:
    void tick();
    void refresh();
    void updateIcons();  // drawn in the palette's text colour (visible on any background)

    Inspection* m_inspection;
    QTimer m_timer;
    QAction* m_back = nullptr;
    QAction* m_forward = nullptr;
    QAction* m_play = nullptr;
    QAction* m_start = nullptr;
    QAction* m_end = nullptr;
    QAction* m_continue = nullptr;
    QList<QAction*> m_granularityActions;
    QComboBox* m_granularity = nullptr;
    QSpinBox* m_speed = nullptr;
    QSlider* m_timeline = nullptr;
    ElidedLabel* m_position = nullptr;
};

}  // namespace rasterlab
