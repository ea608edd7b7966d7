// What every teaching view looks at: the frame shown, its replay and the buffers at the
// stepping cursor, the stage selected in the strip, the stepping granularity and
// breakpoints, the pixel picked and the triangle and vertices selected. Views read it and
// follow its signals; a view that changes the selection (a vertex row, a pixel clicked) goes
// through it, so every other view follows. Only the UI thread touches it.
//
// Without a replay (not built yet, or a frame too large to step through) the cursor is the
// end of the frame and the buffers are the frame's own.
#pragma once

#include <QImage>
#include <QObject>
#include <QPoint>

#include <memory>
#include <optional>
#include <vector>

#include "pipeline/core/stage_id.h"
#include "pipeline/render/frame_trace.h"
#include "pipeline/render/replay.h"

namespace rasterlab {

// A vertex of a draw as the projection numbers them: the draw's own vertices, then those
// made by clipping.
struct VertexRef {
    std::uint32_t draw = 0;
    std::uint32_t vertex = 0;
    bool operator==(const VertexRef&) const = default;
};

class Inspection : public QObject {
    Q_OBJECT
public:
    explicit Inspection(QObject* parent = nullptr);

    // A new frame: the replay of the previous one is dropped and the cursor is at the end.
    // The picked pixel stays when it is still on the image, its triangle selected again.
    // image: the frame's final image. Emits frameChanged, cursorChanged, selectionChanged.
    void setFrame(std::shared_ptr<const rl::FrameTrace> frame, QImage image);
    // The replay of the frame shown (ignored when it belongs to another frame); the cursor
    // moves to `at` (the end by default).
    void setReplay(std::shared_ptr<const rl::FrameReplay> replay,
                   std::optional<rl::ReplayCursor> at = std::nullopt);
    const std::shared_ptr<const rl::FrameTrace>& frame() const { return m_frame; }
    const rl::FrameReplay* replay() const { return m_replay.get(); }
    std::shared_ptr<const rl::FrameReplay> replayPtr() const { return m_replay; }
    bool canStep() const { return m_state != nullptr; }
    // Why the frame shown cannot be stepped through (too many fragments ...); empty while its
    // replay is being built or once it is there.
    QString replayError() const { return m_replayError; }
    void setReplayError(const QString& message);

    // The stage selected in the strip.
    rl::StageId stage() const { return m_stage; }
    void setStage(rl::StageId stage);

    rl::StepGranularity granularity() const { return m_granularity; }
    void setGranularity(rl::StepGranularity granularity);
    rl::ReplayCursor cursor() const;
    bool atStart() const;
    bool atEnd() const;
    void seek(rl::ReplayCursor cursor);
    // One step at the granularity. At stage granularity the strip's stage moves; the buffers
    // are empty up to scan conversion and whole from the depth test on. False at an end.
    bool stepForward();
    bool stepBack();
    void toStart();
    void toEnd();
    // One step forward that stops on a breakpoint met on the way (play and continue use
    // it): true if a breakpoint stopped it (breakpointHit is emitted).
    bool advance(bool& moved);
    // Forward to the next breakpoint, or to the end; true if a breakpoint stopped it.
    bool continueToBreakpoint();

    const std::vector<rl::Breakpoint>& breakpoints() const { return m_breakpoints; }
    void setBreakpoints(std::vector<rl::Breakpoint> breakpoints);

    // What the cursor is on: the current row (the triangle being drawn, its scanline and
    // span) and the last fragment tested in it.
    const rl::ReplayRow* currentRow() const;
    std::optional<std::uint32_t> currentTriangle() const;
    std::optional<std::uint32_t> currentFragment() const;
    // "triangle 12 of 2120, scanline 240, span [311, 330), pixel 318", or "end of frame".
    QString positionText() const;

    // The image and the depth-test buffers at the cursor (the frame's without a replay).
    // The image shares the buffer it shows: it changes as the cursor moves. It is read-only:
    // drawing on it draws on a copy.
    QImage image() const;
    // The whole frame, as rendered (whatever the cursor).
    const QImage& frameImage() const { return m_frameImage; }
    const rl::DepthTest* buffers() const;
    // The same, held as long as the caller keeps it (a view that draws them later).
    std::shared_ptr<const rl::DepthTest> sharedBuffers() const;
    std::uint32_t triangleAt(QPoint pixel) const;

    // The pixel picked ((-1, -1) for none); picking selects the triangle holding it at the
    // cursor and that triangle's vertices.
    QPoint pickedPixel() const { return m_picked; }
    void pickPixel(QPoint pixel);
    // A projected triangle (Projection::triangles) and the vertices selected.
    std::optional<std::uint32_t> selectedTriangle() const { return m_triangle; }
    void selectTriangle(std::optional<std::uint32_t> triangle);
    const std::vector<VertexRef>& selectedVertices() const { return m_vertices; }
    void selectVertices(std::vector<VertexRef> vertices);

    // Presentation mode: views draw thicker lines and larger text.
    bool presentation() const { return m_presentation; }
    void setPresentation(bool on);
    // The width of overlay lines in device-independent pixels (thicker when presenting).
    double lineWidth() const { return m_presentation ? 3.0 : 1.5; }
    // How much a view enlarges its text when presenting: `factor` on its own, 1 in a window
    // that enlarges the whole application's text itself (the main window: the two would
    // multiply, and the views outgrow a small screen).
    double textScale(double factor) const {
        return m_presentation && !m_windowScalesText ? factor : 1.0;
    }
    void setWindowScalesText(bool on) { m_windowScalesText = on; }

signals:
    void frameChanged();   // a new frame, without a replay yet (setReplay may follow)
    void replayChanged();  // the frame's replay arrived, or why it cannot
    void cursorChanged();  // the buffers at the cursor changed
    void stageChanged(rl::StageId stage);
    void granularityChanged(rl::StepGranularity granularity);
    void breakpointsChanged();
    void breakpointHit(int index);
    void pixelPicked(QPoint pixel);  // by pickPixel (a new frame keeps the pixel picked)
    void selectionChanged();         // the triangle or the vertices selected
    void presentationChanged(bool on);

private:
    void updateCursorStage();
    std::optional<std::uint32_t> triangleOf(QPoint pixel) const;  // triangleAt, if any
    std::optional<rl::BreakpointHit> nextHit();

    std::shared_ptr<const rl::FrameTrace> m_frame;
    std::shared_ptr<const rl::FrameReplay> m_replay;
    std::shared_ptr<rl::ReplayState> m_state;
    rl::StageId m_stage = rl::StageId::Shading;
    rl::StepGranularity m_granularity = rl::StepGranularity::Scanline;
    std::vector<rl::Breakpoint> m_breakpoints;
    // The next breakpoint after m_hitFrom, worked out once and kept while the cursor only
    // moves forward toward it.
    std::optional<rl::BreakpointHit> m_hit;
    std::optional<rl::ReplayCursor> m_hitFrom;
    QPoint m_picked{-1, -1};
    std::optional<std::uint32_t> m_triangle;
    std::vector<VertexRef> m_vertices;
    bool m_presentation = false;
    bool m_windowScalesText = false;
    QImage m_frameImage;  // the frame's image when there is no replay
    QString m_replayError;
};

}  // namespace rasterlab
