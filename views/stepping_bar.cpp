#include "stepping_bar.h"

#include <QAction>
#include <QActionGroup>
#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QSlider>
#include <QSpinBox>
#include <QToolButton>

namespace rasterlab {

namespace {

enum class Glyph { Start, Back, Play, Pause, Forward, End, Continue };

// A media glyph in a colour: triangles and bars on a transparent square.
QIcon glyphIcon(Glyph glyph, const QColor& colour) {
    QPixmap pixmap(32, 32);
    pixmap.fill(Qt::transparent);
    QPainter p(&pixmap);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::NoPen);
    p.setBrush(colour);
    const auto left = [&](double x) {  // a triangle pointing left, its tip at x
        p.drawPolygon(QPolygonF({QPointF(x, 16), QPointF(x + 11, 7), QPointF(x + 11, 25)}));
    };
    const auto right = [&](double x) {  // a triangle pointing right, its tip at x
        p.drawPolygon(QPolygonF({QPointF(x, 16), QPointF(x - 11, 7), QPointF(x - 11, 25)}));
    };
    switch (glyph) {
        case Glyph::Start:
            p.drawRect(QRectF(7, 7, 3, 18));
            left(11);
            break;
        case Glyph::Back:
            left(5);
            left(16);
            break;
        case Glyph::Play:
            p.drawPolygon(QPolygonF({QPointF(10, 6), QPointF(25, 16), QPointF(10, 26)}));
            break;
        case Glyph::Pause:
            p.drawRect(QRectF(9, 7, 5, 18));
            p.drawRect(QRectF(18, 7, 5, 18));
            break;
        case Glyph::Forward:
            right(16);
            right(27);
            break;
        case Glyph::End:
            right(21);
            p.drawRect(QRectF(22, 7, 3, 18));
            break;
        case Glyph::Continue:  // a bar, then a triangle: run on from here
            p.drawRect(QRectF(7, 7, 3, 18));
            right(26);
            break;
    }
    return QIcon(pixmap);
}

constexpr rl::StepGranularity kGranularities[] = {
    rl::StepGranularity::Stage, rl::StepGranularity::Triangle, rl::StepGranularity::Scanline,
    rl::StepGranularity::Span, rl::StepGranularity::Pixel};

}  // namespace

QString SteppingBar::granularityName(rl::StepGranularity granularity) {
    switch (granularity) {
        case rl::StepGranularity::Stage:
            return tr("Stage");
        case rl::StepGranularity::Triangle:
            return tr("Triangle");
        case rl::StepGranularity::Scanline:
            return tr("Scanline");
        case rl::StepGranularity::Span:
            return tr("Span");
        case rl::StepGranularity::Pixel:
            return tr("Pixel");
    }
    return {};
}

SteppingBar::SteppingBar(Inspection* inspection, QWidget* parent)
    : QWidget(parent), m_inspection(inspection) {
    setObjectName(QStringLiteral("steppingBar"));
    auto action = [&](const QString& text, QList<QKeySequence> keys, const char* name) {
        auto* a = new QAction(text, this);
        a->setShortcuts(keys);
        a->setObjectName(QLatin1String(name));
        // The tooltip without the menu's mnemonic marker.
        const QString plain = QString(text).remove(QLatin1Char('&'));
        a->setToolTip(keys.isEmpty() ? plain
                                     : QStringLiteral("%1 (%2)").arg(
                                           plain, keys.first().toString(QKeySequence::NativeText)));
        return a;
    };
    m_start =
        action(tr("Jump to &Start"), {QKeySequence(Qt::CTRL | Qt::Key_Home)}, "toStartAction");
    m_back = action(tr("Step &Back"),
                    {QKeySequence(Qt::SHIFT | Qt::Key_F10), QKeySequence(Qt::Key_PageUp)},
                    "stepBackAction");
    m_play = action(tr("&Play / Pause"), {QKeySequence(Qt::Key_F6)}, "playAction");
    m_play->setCheckable(true);
    m_forward =
        action(tr("Step &Forward"), {QKeySequence(Qt::Key_F10), QKeySequence(Qt::Key_PageDown)},
               "stepForwardAction");
    m_end = action(tr("Jump to &End"), {QKeySequence(Qt::CTRL | Qt::Key_End)}, "toEndAction");
    m_continue =
        action(tr("&Continue to Breakpoint"), {QKeySequence(Qt::Key_F8)}, "continueAction");
    connect(m_start, &QAction::triggered, this, [this] {
        setPlaying(false);
        m_inspection->toStart();
    });
    connect(m_back, &QAction::triggered, this, [this] {
        setPlaying(false);
        m_inspection->stepBack();
    });
    connect(m_forward, &QAction::triggered, this, [this] {
        setPlaying(false);
        bool moved = false;
        m_inspection->advance(moved);
    });
    connect(m_end, &QAction::triggered, this, [this] {
        setPlaying(false);
        m_inspection->toEnd();
    });
    connect(m_continue, &QAction::triggered, this, [this] {
        setPlaying(false);
        m_inspection->continueToBreakpoint();
    });
    connect(m_play, &QAction::toggled, this, [this](bool on) { setPlaying(on); });

    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    auto* stepLabel = new QLabel(tr("Step by"), this);
    layout->addWidget(stepLabel);
    m_granularity = new QComboBox(this);
    m_granularity->setObjectName(QStringLiteral("granularityBox"));
    stepLabel->setBuddy(m_granularity);
    auto* group = new QActionGroup(this);
    int key = Qt::Key_1;
    for (rl::StepGranularity g : kGranularities) {
        m_granularity->addItem(granularityName(g), static_cast<int>(g));
        auto* a = new QAction(granularityName(g), group);
        a->setCheckable(true);
        a->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | key++));
        a->setData(static_cast<int>(g));
        connect(a, &QAction::triggered, this, [this, g] { m_inspection->setGranularity(g); });
        m_granularityActions.append(a);
    }
    connect(m_granularity, &QComboBox::activated, this, [this](int index) {
        m_inspection->setGranularity(
            static_cast<rl::StepGranularity>(m_granularity->itemData(index).toInt()));
    });
    layout->addWidget(m_granularity);
    for (QAction* a : {m_start, m_back, m_play, m_forward, m_end}) {
        auto* button = new QToolButton(this);
        button->setDefaultAction(a);
        button->setAutoRaise(true);
        layout->addWidget(button);
    }
    m_speed = new QSpinBox(this);
    m_speed->setObjectName(QStringLiteral("speedBox"));
    m_speed->setRange(1, 240);
    m_speed->setValue(10);
    m_speed->setSuffix(tr(" steps/s"));
    m_speed->setToolTip(tr("How many steps a second Play makes"));
    connect(m_speed, &QSpinBox::valueChanged, this,
            [this](int v) { m_timer.setInterval(1000 / std::max(1, v)); });
    layout->addWidget(m_speed);
    m_timeline = new QSlider(Qt::Horizontal, this);
    m_timeline->setObjectName(QStringLiteral("timeline"));
    m_timeline->setToolTip(tr("The frame, fragment by fragment: drag to scrub"));
    m_timeline->setMinimumWidth(160);
    connect(m_timeline, &QSlider::valueChanged, this, [this](int value) {
        if (const rl::FrameReplay* replay = m_inspection->replay())
            m_inspection->seek(replay->atFragment(static_cast<std::uint32_t>(value)));
    });
    layout->addWidget(m_timeline, 1);
    // The position elided on a narrow screen, whole in its tooltip.
    m_position = new ElidedLabel(this);
    m_position->setObjectName(QStringLiteral("positionLabel"));
    layout->addWidget(m_position, 2);

    m_timer.setInterval(100);
    connect(&m_timer, &QTimer::timeout, this, &SteppingBar::tick);
    updateIcons();
    connect(inspection, &Inspection::replayChanged, this, &SteppingBar::refresh);
    connect(inspection, &Inspection::cursorChanged, this, &SteppingBar::refresh);
    connect(inspection, &Inspection::granularityChanged, this, &SteppingBar::refresh);
    connect(inspection, &Inspection::stageChanged, this, &SteppingBar::refresh);
    connect(inspection, &Inspection::breakpointHit, this, [this] { setPlaying(false); });
    refresh();
}

void SteppingBar::setSpeed(int stepsPerSecond) {
    m_speed->setValue(stepsPerSecond);
}

void SteppingBar::setPlaying(bool playing) {
    if (playing && m_inspection->atEnd() &&
        m_inspection->granularity() != rl::StepGranularity::Stage)
        m_inspection->toStart();  // play again from the start
    if (playing)
        m_timer.start();
    else
        m_timer.stop();
    const QSignalBlocker block(m_play);
    m_play->setChecked(playing);
    updateIcons();
}

void SteppingBar::updateIcons() {
    const QColor colour = palette().color(QPalette::ButtonText);
    m_start->setIcon(glyphIcon(Glyph::Start, colour));
    m_back->setIcon(glyphIcon(Glyph::Back, colour));
    m_play->setIcon(glyphIcon(isPlaying() ? Glyph::Pause : Glyph::Play, colour));
    m_forward->setIcon(glyphIcon(Glyph::Forward, colour));
    m_end->setIcon(glyphIcon(Glyph::End, colour));
    m_continue->setIcon(glyphIcon(Glyph::Continue, colour));
}

void SteppingBar::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() == QEvent::PaletteChange) updateIcons();
}

void SteppingBar::tick() {
    bool moved = false;
    const bool hit = m_inspection->advance(moved);
    const bool finished = m_inspection->granularity() == rl::StepGranularity::Stage
                              ? m_inspection->stage() == rl::StageId::Shading
                              : m_inspection->atEnd();
    if (hit || !moved || finished) setPlaying(false);
}

void SteppingBar::refresh() {
    const rl::FrameReplay* replay = m_inspection->replay();
    const bool stageSteps = m_inspection->granularity() == rl::StepGranularity::Stage;
    const bool can = m_inspection->canStep() || (stageSteps && m_inspection->frame());
    for (QAction* a : {m_start, m_back, m_play, m_forward, m_end}) a->setEnabled(can);
    m_continue->setEnabled(m_inspection->canStep());
    m_timeline->setEnabled(replay != nullptr);
    {
        const QSignalBlocker block(m_timeline);
        m_timeline->setRange(0, replay ? static_cast<int>(replay->fragments().size()) : 0);
        m_timeline->setValue(replay ? static_cast<int>(m_inspection->cursor().fragments) : 0);
        m_timeline->setPageStep(std::max(1, m_timeline->maximum() / 50));
    }
    const int index = m_granularity->findData(static_cast<int>(m_inspection->granularity()));
    m_granularity->setCurrentIndex(index);
    for (QAction* a : m_granularityActions)
        a->setChecked(a->data().toInt() == static_cast<int>(m_inspection->granularity()));
    QString text = m_inspection->positionText();
    if (m_inspection->frame() && !m_inspection->canStep())
        text = m_inspection->replayError().isEmpty()
                   ? tr("stepping is being prepared")
                   : tr("no stepping: %1").arg(m_inspection->replayError());
    m_position->setFullText(text);
}

}  // namespace rasterlab
