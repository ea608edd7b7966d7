#include "stage_strip.h"

#include <QButtonGroup>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>

#include <algorithm>

namespace rasterlab {

StageStrip::StageStrip(Inspection* inspection, QWidget* parent)
    : QWidget(parent), m_inspection(inspection) {
    setObjectName(QStringLiteral("stageStrip"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    layout->setSpacing(2);
    auto* group = new QButtonGroup(this);
    group->setExclusive(true);
    for (rl::StageId stage : rl::kAllStages) {
        const auto i = static_cast<std::size_t>(stage);
        if (i > 0) {
            auto* arrow = new QLabel(QStringLiteral("\u2192"), this);
            arrow->setEnabled(false);
            layout->addWidget(arrow);
        }
        auto* button = new QToolButton(this);
        button->setCheckable(true);
        button->setAutoRaise(true);
        button->setObjectName(QStringLiteral("stage_%1").arg(i + 1));
        button->setToolButtonStyle(Qt::ToolButtonTextOnly);
        group->addButton(button, static_cast<int>(i));
        layout->addWidget(button);
        m_buttons[i] = button;
        connect(button, &QToolButton::clicked, this,
                [this, stage] { m_inspection->setStage(stage); });
    }
    m_note = new ElidedLabel(this);
    m_note->setObjectName(QStringLiteral("stageNote"));
    layout->addSpacing(8);
    layout->addWidget(m_note, 1);
    // The strip chooses its texts for its width (fitTexts), so its layout must not hold it
    // to the width of the long ones.
    layout->setSizeConstraint(QLayout::SetNoConstraint);
    connect(inspection, &Inspection::frameChanged, this, &StageStrip::refresh);
    connect(inspection, &Inspection::stageChanged, this, &StageStrip::refresh);
    connect(inspection, &Inspection::presentationChanged, this, &StageStrip::refresh);
    // A step changes only the note.
    connect(inspection, &Inspection::cursorChanged, this, &StageStrip::updateNote);
    connect(inspection, &Inspection::granularityChanged, this, [this] {
        updateNote();
        fitTexts();
    });
    refresh();
}

QString StageStrip::stageName(rl::StageId stage) {
    switch (stage) {
        case rl::StageId::CameraBasis:
            return tr("Camera basis");
        case rl::StageId::ViewTransform:
            return tr("View coordinates");
        case rl::StageId::Normals:
            return tr("Normals");
        case rl::StageId::Projection:
            return tr("Projection");
        case rl::StageId::ScanConversion:
            return tr("Scan conversion");
        case rl::StageId::DepthTest:
            return tr("Z-buffer");
        case rl::StageId::Shading:
            return tr("Lighting");
    }
    return {};
}

QString StageStrip::shortStageName(rl::StageId stage) {
    switch (stage) {
        case rl::StageId::CameraBasis:
            return tr("Camera");
        case rl::StageId::ViewTransform:
            return tr("View");
        case rl::StageId::ScanConversion:
            return tr("Scan");
        default:
            return stageName(stage);
    }
}

QString StageStrip::skipReason(const rl::FrameTrace& frame, rl::StageId stage) {
    switch (stage) {
        case rl::StageId::CameraBasis:
            if (frame.cameraBasis && frame.cameraBasis->skipped)
                return tr("no course camera: each draw brings its own view matrix");
            break;
        case rl::StageId::Normals:
            if (frame.normals && frame.normals->skipped)
                return tr("nothing is lit: no light reads a normal");
            break;
        case rl::StageId::Shading: {
            const auto& draws = frame.scene->draws;
            const bool anyLitDraw = std::any_of(draws.begin(), draws.end(), [](const rl::Draw& d) {
                return d.lighting != rl::LightingModel::Unlit;
            });
            if (!frame.scene->lit() || !anyLitDraw)
                return tr("nothing is lit: each pixel takes its object's own colour");
            break;
        }
        default:
            break;
    }
    return {};
}

QString StageStrip::modeName(const rl::FrameTrace& frame, rl::StageId stage) {
    if (stage != rl::StageId::Projection || !frame.projection) return {};
    switch (frame.projection->mode) {
        case rl::NearPlane::Mode::Clip:
            return tr("near clip");
        case rl::NearPlane::Mode::Naive:
            return tr("plain divide");
        case rl::NearPlane::Mode::SameSide:
            return tr("same side");
    }
    return {};
}

QString StageStrip::modeDescription(const rl::FrameTrace& frame, rl::StageId stage) {
    if (stage != rl::StageId::Projection || !frame.projection) return {};
    switch (frame.projection->mode) {
        case rl::NearPlane::Mode::Clip:
            return tr(
                "triangles are clipped at the near plane before the divide, so nothing at "
                "or behind the eye is divided by its w (the course and GPU-like rules)");
        case rl::NearPlane::Mode::Naive:
            return tr(
                "every vertex is divided by its w without clipping, as seed 000 writes it "
                "and seed 001's HW2 does (\"we won't add it\"): a triangle behind the eye "
                "lands mirrored through the centre, one across the eye plane wraps "
                "through infinity");
        case rl::NearPlane::Mode::SameSide:
            return tr(
                "triangles wholly in front of or wholly behind the eye are divided as they "
                "are; those across the eye plane are clipped at the near plane");
    }
    return {};
}

void StageStrip::refresh() {
    const auto& frame = m_inspection->frame();
    QFont font = this->font();
    font.setPointSizeF(font.pointSizeF() * m_inspection->textScale(1.3));
    for (rl::StageId stage : rl::kAllStages) {
        const auto i = static_cast<std::size_t>(stage);
        QToolButton* button = m_buttons[i];
        const QString reason = frame ? skipReason(*frame, stage) : QString();
        const QString mode = frame ? modeName(*frame, stage) : QString();
        // The short name keeps what the frame does with the stage: only the name shrinks.
        QString state;
        if (!reason.isEmpty()) state += QStringLiteral(" ") + tr("(skipped)");
        if (!mode.isEmpty()) state += QStringLiteral(" \u00b7 ") + mode;
        // A tick or a cross: what the check of the student's renderer said of the stage.
        if (m_marks[i] != CheckMark::None)
            state += m_marks[i] == CheckMark::Passed ? QStringLiteral(" \u2713")
                                                     : QStringLiteral(" \u2717");
        m_longTexts[i] = QStringLiteral("%1 %2").arg(i + 1).arg(stageName(stage)) + state;
        m_shortTexts[i] = QStringLiteral("%1 %2").arg(i + 1).arg(shortStageName(stage)) + state;
        QString tip = !reason.isEmpty() ? tr("%1 is skipped: %2").arg(stageName(stage), reason)
                      : !mode.isEmpty()
                          ? tr("%1: %2").arg(stageName(stage), modeDescription(*frame, stage))
                          : stageName(stage);
        if (m_marks[i] != CheckMark::None)
            tip +=
                QLatin1Char('\n') + (m_marks[i] == CheckMark::Passed
                                         ? tr("Your renderer's stage passed the check.")
                                         : tr("Your renderer's stage departs from the lecture's: "
                                              "see the Check dock."));
        button->setToolTip(tip);
        QFont f = font;
        f.setItalic(!reason.isEmpty());
        f.setBold(stage == m_inspection->stage());
        button->setFont(f);
        QPalette p = palette();
        if (!reason.isEmpty()) p.setColor(QPalette::ButtonText, QColor(140, 140, 140));
        if (m_marks[i] == CheckMark::Failed) p.setColor(QPalette::ButtonText, QColor(200, 30, 30));
        button->setPalette(p);
        button->setChecked(stage == m_inspection->stage());
    }
    m_note->setFont(font);
    updateNote();
    fitTexts();
}

void StageStrip::setCheckMarks(const std::array<CheckMark, rl::kStageCount>& marks) {
    m_marks = marks;
    refresh();
}

int StageStrip::textsWidth(const std::array<QString, rl::kStageCount>& texts) const {
    // The buttons (bold for the stage shown: measured bold), the arrows and the spacing.
    int width = 0;
    for (std::size_t i = 0; i < texts.size(); ++i) {
        QFont bold = m_buttons[i]->font();
        bold.setBold(true);
        width += QFontMetrics(bold).horizontalAdvance(texts[i]) + 16;
    }
    const QFontMetrics metrics(m_note->font());
    width += int(texts.size() - 1) * (metrics.horizontalAdvance(QStringLiteral("\u2192")) + 8);
    return width + 8 + 8;  // the margins and the note's spacing
}

void StageStrip::fitTexts() {
    // The long names while the note, whenever stepping finer than by stage may show it, has
    // its whole width beside them.
    int note = m_note->minimumSizeHint().width();
    if (m_inspection->granularity() != rl::StepGranularity::Stage)
        note = std::max(note, m_note->wholeWidth(noteText()));
    const bool whole = width() >= textsWidth(m_longTexts) + note;
    for (std::size_t i = 0; i < m_buttons.size(); ++i)
        m_buttons[i]->setText(whole ? m_longTexts[i] : m_shortTexts[i]);
}

QSize StageStrip::minimumSizeHint() const {
    return {textsWidth(m_shortTexts) + m_note->minimumSizeHint().width(),
            QWidget::minimumSizeHint().height()};
}

void StageStrip::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange && m_inspection) refresh();
}

void StageStrip::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    fitTexts();
}

void StageStrip::updateNote() {
    const bool midFrame = m_inspection->canStep() && !m_inspection->atStart() &&
                          !m_inspection->atEnd() &&
                          m_inspection->granularity() != rl::StepGranularity::Stage;
    m_note->setFullText(midFrame ? noteText() : QString());
}

QString StageStrip::noteText() {
    return tr("while stepping, stages 5-7 run together, fragment by fragment");
}

}  // namespace rasterlab
