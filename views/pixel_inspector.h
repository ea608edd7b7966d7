// The pixel inspector: the story of the pixel picked. Its history lists every fragment that
// reached it in drawing order (like PIX's pixel history): the triangle, its depth against
// the stored one with the test's operator, written or rejected and why, the colour before
// and after, between the cleared pixel and the final one; the rows the stepping cursor has
// not reached yet are greyed, the one holding the pixel at the cursor marked. A one-line
// verdict sums it up ("written by triangle 12; 2 fragments rejected", "black: N.L < 0 and
// no ambient"). Below, the lighting of the history row selected, term by term: ambient,
// diffuse and specular per channel as numbers and as stacked bars against the colour scale,
// the formula with the numbers filled in, the vectors N, L, V, R, and every special case.
// Without a replay (a frame too large to step through: Inspection::replayError) the frame is
// traced again for the pixel (renderer.h, traceFrame with a RecordingProbe).
#pragma once

#include <QImage>
#include <QPointer>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "pipeline/render/replay.h"
#include "pipeline/stages/probe.h"
#include "views/lighting_breakdown.h"
#include "views/pixel_history.h"

class QGridLayout;
class QVBoxLayout;
class QLabel;
class QTableWidget;

namespace rasterlab {

class Inspection;
class TermBars;
class LightingVectors;

class PixelInspector : public QWidget {
    Q_OBJECT
public:
    explicit PixelInspector(Inspection* inspection, QWidget* parent = nullptr);

    QPoint pixel() const { return m_history.pixel(); }
    // Initial, the fragments in drawing order, Final.
    const std::vector<PixelHistoryRow>& history() const { return m_history.rows(); }
    QString verdictText() const { return m_history.verdict(); }
    // The history row whose lighting is shown (-1: none) and its breakdown. By default the
    // row holding the pixel at the cursor; a row selected (by hand, or here) stays while the
    // cursor moves, until another pixel is picked.
    int selectedRow() const { return m_selected; }
    void selectRow(int row);
    const std::optional<LightingBreakdown>& breakdown() const { return m_breakdown; }
    QString formulaText() const;  // the formula lines, joined by newlines
    // A student's frame (Check My Renderer...), for the frame it was checked on: the verdict
    // then gives their colour at the pixel beside ours, until another frame is shown.
    void setTheirFrame(std::shared_ptr<const rl::FrameTrace> frame, QImage theirs);
    // "Your renderer's colour here: ...", or empty without their frame for the frame shown.
    QString theirColourText() const;
    // True when the history comes from tracing the frame again (no replay).
    bool traced() const { return m_history.traced(); }
    QTableWidget* historyTable() const { return m_table; }

protected:
    void showEvent(QShowEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void refresh();
    void applyPresentation();  // the fonts, larger when presenting on its own
    void followFont();
    void arrange();
    void widenHistory();  // the history's column as wide as its table asks, side by side  // the history and the lighting side by side, or one above the other         // the bold and fixed-width parts at the inspector's size
    void updateBreakdown();
    void fillTable();
    void fitColumns();
    void fitTableHeight();
    void showBreakdown();

    Inspection* m_inspection = nullptr;
    // What the history was built from: rebuilt only when one of them changes. The cursor
    // marks are worked out on every step; the table is filled again only when they move.
    std::weak_ptr<const rl::FrameTrace> m_builtFrame;
    std::weak_ptr<const rl::FrameReplay> m_builtReplay;
    QPoint m_builtPixel{-1, -1};
    bool m_builtWithoutReplay = false;  // built after the replay failed (traced)
    bool m_presenting = false;          // the fonts and sizes are presentation mode's

    PixelHistory m_history;
    int m_selected = -1;
    bool m_userSelected = false;  // a row the user chose stays until the pixel changes
    std::optional<LightingBreakdown> m_breakdown;
    std::weak_ptr<const rl::FrameTrace> m_theirFrame;
    QImage m_theirs;

    QLabel* m_verdictLabel = nullptr;
    QTableWidget* m_table = nullptr;
    QStringList m_titles;  // the columns' titles, on one line (fitColumns may wrap them)
    QLabel* m_legend = nullptr;
    QLabel* m_breakdownTitle = nullptr;
    TermBars* m_bars = nullptr;
    QGridLayout* m_grid = nullptr;
    QWidget* m_pictures = nullptr;  // the bars and the vectors
    QWidget* m_historyBox = nullptr;
    QWidget* m_lightingBox = nullptr;
    QVBoxLayout* m_historyLayout = nullptr;
    QVBoxLayout* m_lightingLayout = nullptr;
    bool m_beside = false;          // the history and the lighting side by side
    int m_wholeTableWidth = 0;      // the history's table with every column whole
    QString m_formulaWidthKey;      // the formula's font and text m_formulaWidth is for
    int m_formulaWidth = 0;         // the width its lines need to take three lines at most
    QPointer<QWidget> m_room;  // the widget it is shown in, watched for its size
    LightingVectors* m_vectors = nullptr;
    QLabel* m_formula = nullptr;
    QLabel* m_flags = nullptr;
};

}  // namespace rasterlab
