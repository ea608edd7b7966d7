// The animation panel (seed 002's per-object matrix M): whether the scene moves, play and
// pause, the frame slider (frame number and time t = frame / fps), the length of the animation
// and its frame rate, the turntable's speed and axis, a translation and a scale, and M(t) with
// the numbers of the frame shown. Paused at any frame, every stage view inspects that frame.
// The settings live in the document (SceneDocument::Animation): part of the session, not of
// the course files.
#pragma once

#include <QTimer>
#include <QWidget>

#include <array>

#include "app/documents/scene_document.h"
#include "pipeline/scene/scene.h"

namespace rl {
struct FrameTrace;
}

class QAction;
class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QSlider;
class QSpinBox;
class QToolButton;

namespace rasterlab {

class AnimationPanel : public QWidget {
    Q_OBJECT
public:
    explicit AnimationPanel(QWidget* parent = nullptr);

    // The settings as the panel holds them (time = frame / fps).
    SceneDocument::Animation settings() const;
    // Shows a document's settings (a window handed over, say); the frame is the one nearest
    // the time. Sends no signal.
    void setSettings(const SceneDocument::Animation& animation);

    int frame() const;
    int frameCount() const;
    double framesPerSecond() const;
    void setFrame(int frame);  // clamped to the animation; sends changed()
    bool isPlaying() const { return m_timer.isActive(); }
    void setPlaying(bool playing);  // playing turns the animation on
    QAction* playAction() const { return m_playAction; }

    // The frame shown, for M(t) with its numbers (its pivot as the view transform found it).
    void showFrame(const rl::FrameTrace& frame);

signals:
    void changed();  // a setting or the time: the scene must be rendered again
    void playingChanged(bool playing);

private:
    void onEdited();
    void updateFrameLabel();
    QDoubleSpinBox* numberBox(double lo, double hi, double value, int decimals, double step);

    QCheckBox* m_enabled = nullptr;
    QAction* m_playAction = nullptr;
    QToolButton* m_playButton = nullptr;
    QSlider* m_slider = nullptr;
    QLabel* m_frameLabel = nullptr;
    QSpinBox* m_frames = nullptr;
    QDoubleSpinBox* m_fps = nullptr;
    QDoubleSpinBox* m_speed = nullptr;
    QCheckBox* m_cameraUp = nullptr;
    std::array<QDoubleSpinBox*, 3> m_axis{};
    std::array<QDoubleSpinBox*, 3> m_velocity{};
    std::array<QDoubleSpinBox*, 3> m_scale{};
    QLabel* m_matrix = nullptr;
    QTimer m_timer;
    bool m_showing = false;  // setSettings in progress: no signals
};

}  // namespace rasterlab
