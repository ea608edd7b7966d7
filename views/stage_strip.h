// The seven stages in the lecture's order, as a strip of buttons: the selected one shows its
// view; a stage the scene does not use is marked skipped, with the reason in its tooltip and
// beside its name. While the frame is stepped through pixel by pixel, the last three stages
// (scan conversion, depth test, shading) run together, one fragment at a time: the strip says so.
#pragma once

#include <QPointer>
#include <QWidget>

#include <array>

#include "pipeline/core/stage_id.h"
#include "views/elided_label.h"
#include "views/inspection.h"

class QToolButton;

namespace rasterlab {

class StageStrip : public QWidget {
    Q_OBJECT
public:
    explicit StageStrip(Inspection* inspection, QWidget* parent = nullptr);

    // The lecture's name of a stage, translated ("Camera basis").
    static QString stageName(rl::StageId stage);
    // A shorter name, one word ("Camera"), for a narrow strip and a dock's tab.
    static QString shortStageName(rl::StageId stage);
    // Why the frame shown does not use a stage, translated; empty when it does.
    static QString skipReason(const rl::FrameTrace& frame, rl::StageId stage);
    // How the frame shown runs a stage when it has a choice (the projection's handling of
    // triangles behind the eye): a few words for the strip, and a sentence for its tooltip.
    static QString modeName(const rl::FrameTrace& frame, rl::StageId stage);
    static QString modeDescription(const rl::FrameTrace& frame, rl::StageId stage);

    // What a check of a student's renderer (Check My Renderer...) said of each stage, shown
    // beside its name until the next check or the next scene.
    enum class CheckMark { None, Passed, Failed };
    void setCheckMarks(const std::array<CheckMark, rl::kStageCount>& marks);
    CheckMark checkMark(rl::StageId stage) const {
        return m_marks[static_cast<std::size_t>(stage)];
    }

    QToolButton* button(rl::StageId stage) const {
        return m_buttons[static_cast<std::size_t>(stage)];
    }

    // Short enough for a small screen: the buttons' short names and a few letters of the note.
    QSize minimumSizeHint() const override;

protected:
    void resizeEvent(QResizeEvent* event) override;
    // The buttons' fonts are made from the strip's: a new application font (presentation
    // mode) reaches the strip after the mode's refresh, so it refreshes them again.
    void changeEvent(QEvent* event) override;

private:
    void refresh();
    void updateNote();  // the note beside the strip, which follows the cursor
    static QString noteText();  // what the note says mid-frame, stepping finer than by stage
    // The stages' names, whole or short (number and first word), whichever the width holds.
    void fitTexts();
    int textsWidth(const std::array<QString, rl::kStageCount>& texts) const;

    // Guarded: the main window deletes its Inspection before the toolbar that releases
    // this strip, and the release sends a font change.
    QPointer<Inspection> m_inspection;
    std::array<QToolButton*, rl::kStageCount> m_buttons{};
    std::array<QString, rl::kStageCount> m_longTexts, m_shortTexts;
    std::array<CheckMark, rl::kStageCount> m_marks{};
    ElidedLabel* m_note = nullptr;
};

}  // namespace rasterlab
