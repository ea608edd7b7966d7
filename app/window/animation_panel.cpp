#include "animation_panel.h"

#include <QAction>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

#include "pipeline/render/animation.h"
#include "pipeline/render/frame_trace.h"
#include "views/number_text.h"
#include "views/wrapping_check_box.h"

namespace rasterlab {

AnimationPanel::AnimationPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("animationPanel"));
    auto* layout = new QVBoxLayout(this);

    m_enabled = new WrappingCheckBox(tr("Animate: each draw moved by M(t)"), this);
    m_enabled->setObjectName(QStringLiteral("animationEnabled"));
    layout->addWidget(m_enabled);

    auto* transport = new QHBoxLayout;
    m_playAction = new QAction(tr("Play"), this);
    m_playAction->setObjectName(QStringLiteral("animationPlayAction"));
    m_playAction->setCheckable(true);
    m_playAction->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
    m_playAction->setToolTip(
        tr("Play or pause the animation; paused, every stage view "
           "inspects the frame shown"));
    m_playButton = new QToolButton(this);
    m_playButton->setObjectName(QStringLiteral("animationPlayButton"));
    m_playButton->setDefaultAction(m_playAction);
    m_playButton->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    transport->addWidget(m_playButton);
    m_slider = new QSlider(Qt::Horizontal, this);
    m_slider->setObjectName(QStringLiteral("animationFrameSlider"));
    m_slider->setRange(0, 47);
    transport->addWidget(m_slider, 1);
    layout->addLayout(transport);
    m_frameLabel = new QLabel(this);
    m_frameLabel->setObjectName(QStringLiteral("animationFrameLabel"));
    layout->addWidget(m_frameLabel);

    auto* form = new QFormLayout;
    m_frames = new QSpinBox(this);
    m_frames->setObjectName(QStringLiteral("animationFrames"));
    m_frames->setRange(1, 100000);
    m_frames->setValue(48);
    form->addRow(tr("Frames:"), m_frames);
    m_fps = numberBox(0.1, 240.0, 24.0, 1, 1.0);
    m_fps->setObjectName(QStringLiteral("animationFps"));
    form->addRow(tr("Frames a second:"), m_fps);
    m_speed = numberBox(-3600.0, 3600.0, 36.0, 2, 5.0);
    m_speed->setObjectName(QStringLiteral("animationSpeed"));
    m_speed->setSuffix(tr(" °/s"));
    form->addRow(tr("Turn:"), m_speed);
    m_cameraUp = new WrappingCheckBox(tr("Turn about the camera's up (a turntable)"), this);
    m_cameraUp->setObjectName(QStringLiteral("animationCameraUp"));
    m_cameraUp->setChecked(true);
    // Long rows (Portuguese, presentation mode) put their field below their label.
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    layout->addLayout(form);
    layout->addWidget(m_cameraUp);  // outside the form, where its text can wrap
    // The three vectors in a grid, a column per world axis, narrow enough for a side dock.
    auto* grid = new QGridLayout;
    grid->setHorizontalSpacing(4);
    const QString axes[] = {QStringLiteral("x"), QStringLiteral("y"), QStringLiteral("z")};
    for (int k = 0; k < 3; ++k) {
        auto* heading = new QLabel(axes[k], this);
        heading->setAlignment(Qt::AlignCenter);
        grid->addWidget(heading, 0, k + 1);
    }
    const auto row = [&](int r, const QString& label, std::array<QDoubleSpinBox*, 3>& boxes,
                         double value, double range, const QString& name) {
        grid->addWidget(new QLabel(label, this), r, 0);
        for (int k = 0; k < 3; ++k) {
            QDoubleSpinBox* box = numberBox(-range, range, value, 2, 0.1);
            box->setObjectName(name + QString::number(k));
            box->setMinimumWidth(40);
            box->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
            grid->addWidget(box, r, k + 1);
            boxes[std::size_t(k)] = box;
        }
    };
    row(1, tr("Axis:"), m_axis, 0.0, 100.0, QStringLiteral("animationAxis"));
    m_axis[1]->setValue(1.0);
    row(2, tr("Moves (units/s):"), m_velocity, 0.0, 10000.0, QStringLiteral("animationVelocity"));
    row(3, tr("Scale:"), m_scale, 1.0, 100.0, QStringLiteral("animationScale"));
    for (int k = 1; k <= 3; ++k) grid->setColumnStretch(k, 1);
    layout->addLayout(grid);

    m_matrix = new QLabel(this);
    m_matrix->setObjectName(QStringLiteral("animationMatrix"));
    m_matrix->setTextFormat(Qt::RichText);
    m_matrix->setWordWrap(true);
    m_matrix->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_matrix);
    auto* note = new QLabel(
        tr("<i>The animation belongs to this session: course files have no such field, and "
           "saving the camera or lighting does not write it.</i>"),
        this);
    note->setObjectName(QStringLiteral("animationSessionNote"));
    note->setWordWrap(true);
    layout->addWidget(note);
    layout->addStretch(1);

    connect(m_enabled, &QCheckBox::toggled, this, &AnimationPanel::onEdited);
    connect(m_slider, &QSlider::valueChanged, this, &AnimationPanel::onEdited);
    connect(m_frames, &QSpinBox::valueChanged, this, [this](int n) {
        m_slider->setMaximum(n - 1);  // a frame past the end moves to the last (valueChanged)
        onEdited();
    });
    connect(m_fps, &QDoubleSpinBox::valueChanged, this, [this](double fps) {
        if (isPlaying()) m_timer.setInterval(int(std::lround(1000.0 / fps)));
        onEdited();
    });
    connect(m_cameraUp, &QCheckBox::toggled, this, [this](bool up) {
        for (QDoubleSpinBox* box : m_axis) box->setEnabled(!up);
        onEdited();
    });
    for (QDoubleSpinBox* box : m_axis) box->setEnabled(false);
    for (QDoubleSpinBox* box : {m_speed, m_axis[0], m_axis[1], m_axis[2], m_velocity[0],
                                m_velocity[1], m_velocity[2], m_scale[0], m_scale[1], m_scale[2]})
        connect(box, &QDoubleSpinBox::valueChanged, this, &AnimationPanel::onEdited);
    connect(m_playAction, &QAction::toggled, this, &AnimationPanel::setPlaying);
    connect(&m_timer, &QTimer::timeout, this, [this] { setFrame((frame() + 1) % frameCount()); });
    updateFrameLabel();
}

QDoubleSpinBox* AnimationPanel::numberBox(double lo, double hi, double value, int decimals,
                                          double step) {
    auto* box = new QDoubleSpinBox(this);
    box->setRange(lo, hi);
    box->setDecimals(decimals);
    box->setSingleStep(step);
    box->setValue(value);
    box->setKeyboardTracking(false);
    return box;
}

SceneDocument::Animation AnimationPanel::settings() const {
    SceneDocument::Animation a;
    a.enabled = m_enabled->isChecked();
    a.motion.degreesPerSecond = m_speed->value();
    if (!m_cameraUp->isChecked())
        a.motion.axis = rl::dvec3(m_axis[0]->value(), m_axis[1]->value(), m_axis[2]->value());
    a.motion.velocity =
        rl::dvec3(m_velocity[0]->value(), m_velocity[1]->value(), m_velocity[2]->value());
    a.motion.scale = rl::dvec3(m_scale[0]->value(), m_scale[1]->value(), m_scale[2]->value());
    a.time = frame() / framesPerSecond();
    return a;
}

void AnimationPanel::setSettings(const SceneDocument::Animation& a) {
    m_showing = true;
    m_enabled->setChecked(a.enabled);
    m_speed->setValue(a.motion.degreesPerSecond);
    m_cameraUp->setChecked(!a.motion.axis);
    if (a.motion.axis)
        for (int k = 0; k < 3; ++k) m_axis[std::size_t(k)]->setValue((*a.motion.axis)[k]);
    for (int k = 0; k < 3; ++k) {
        m_velocity[std::size_t(k)]->setValue(a.motion.velocity[k]);
        m_scale[std::size_t(k)]->setValue(a.motion.scale[k]);
    }
    const int wanted = int(std::lround(a.time * framesPerSecond()));
    if (wanted >= frameCount()) m_frames->setValue(wanted + 1);
    m_slider->setValue(wanted);
    m_showing = false;
    updateFrameLabel();
}

int AnimationPanel::frame() const {
    return m_slider->value();
}
int AnimationPanel::frameCount() const {
    return m_frames->value();
}
double AnimationPanel::framesPerSecond() const {
    return m_fps->value();
}

void AnimationPanel::setFrame(int frame) {
    m_slider->setValue(frame);  // clamps; valueChanged -> onEdited
}

void AnimationPanel::setPlaying(bool playing) {
    if (playing == isPlaying()) return;
    if (playing) {
        m_enabled->setChecked(true);
        m_timer.start(int(std::lround(1000.0 / framesPerSecond())));
    } else {
        m_timer.stop();
    }
    {
        const QSignalBlocker block(m_playAction);
        m_playAction->setChecked(playing);
    }
    m_playAction->setText(playing ? tr("Pause") : tr("Play"));
    m_playAction->setIcon(
        style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    emit playingChanged(playing);
}

void AnimationPanel::onEdited() {
    updateFrameLabel();
    if (!m_showing) emit changed();
}

void AnimationPanel::updateFrameLabel() {
    m_frameLabel->setText(tr("Frame %1 of %2, t = %3 / %4 = %5 s")
                              .arg(frame())
                              .arg(frameCount())
                              .arg(frame())
                              .arg(number(framesPerSecond()))
                              .arg(number(frame() / framesPerSecond(), 4)));
}

void AnimationPanel::showFrame(const rl::FrameTrace& frame) {
    const rl::Scene& scene = *frame.scene;
    const rl::Draw* draw = nullptr;
    std::size_t drawIndex = 0;
    for (; drawIndex < scene.draws.size(); ++drawIndex)
        if (scene.draws[drawIndex].animation) {
            draw = &scene.draws[drawIndex];
            break;
        }
    if (!draw) {
        m_matrix->setText(
            tr("<p>M(t) = T(v t) · T(c) · R(axis, ω t) · S · T(−c): not applied "
               "(the animation is off, so M is the identity).</p>"));
        return;
    }
    const rl::Animation& a = *draw->animation;
    const rl::dvec3 c = frame.view->pivot[drawIndex].centre;
    const rl::dvec3 axis = frame.view->pivot[drawIndex].axis;
    const rl::dmat4 m = rl::animationMatrix(a, c, axis, scene.time);
    QString rows;
    for (int r = 0; r < 4; ++r) {
        rows += QStringLiteral("<tr>");
        for (int col = 0; col < 4; ++col)
            rows += QStringLiteral("<td align=\"right\">&nbsp;%1&nbsp;</td>")
                        .arg(number(std::abs(m[col][r]) < 1e-12 ? 0.0 : m[col][r], 4));
        rows += QStringLiteral("</tr>");
    }
    m_matrix->setText(tr("<p>M(t) = T(v t) · T(c) · R(axis, ω t) · S · T(−c), at t = %1 s:<br>"
                         "c = %2 (the centre of the bounding box), axis = %3,<br>"
                         "ω t = %4 °/s · %1 s = %5°, v t = %6, S = diag%7</p>")
                          .arg(number(scene.time, 4), vector(c, 'g', 4), vector(axis, 'g', 4),
                               number(a.degreesPerSecond),
                               number(a.degreesPerSecond * scene.time, 4),
                               vector(a.velocity * scene.time, 'g', 4), vector(a.scale, 'g', 4)) +
                      QStringLiteral("<table>") + rows + QStringLiteral("</table>") +
                      tr("<p>Normals are moved by the inverse transpose of M (stage 3).</p>"));
}

}  // namespace rasterlab
