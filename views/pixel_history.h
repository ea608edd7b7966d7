// The history of the pixel picked, the model behind the pixel inspector's table: every
// fragment that reached the pixel in drawing order (like PIX's pixel history), between the
// cleared pixel and the final one, with the marks of the stepping cursor, and the verdict
// that sums it up. Without a replay (a frame too large to step through) the frame is traced
// again for the pixel (renderer.h, traceFrame with a RecordingProbe).
#pragma once

#include <QCoreApplication>
#include <QPoint>
#include <QString>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "pipeline/render/replay.h"
#include "pipeline/stages/probe.h"

namespace rasterlab {

class Inspection;

// A row of the history: a fragment's depth test as the replay keeps it (the base: its
// triangle, depth, stored depth, barycentrics and verdict) and how the table writes it.
// The final row holds the fragment that wrote the pixel last (if any), with the depth left in
// the buffer; the initial row only the cleared depth.
struct PixelHistoryRow : rl::ReplayFragment {
    enum class Kind : std::uint8_t { Initial, Fragment, Final };
    Kind kind = Kind::Fragment;
    // The fragment's number (FrameReplay::fragments(); its order in the traced frame's log
    // without a replay), or kNoFragment.
    std::uint32_t fragment = rl::kNoFragment;
    std::uint32_t meshTriangle = 0;  // the draw's triangle number, from 1 (0: none)
    QString triangleText;            // "12", or "12 (calice2.byu)" with several draws
    QString depthText;               // "0.5 < 1", "2 >= 1", "cleared to +inf"
    QString resultText;              // "written", "rejected: farther", ...
    // The colour before and after, as bytes; none where it is not known (without a replay,
    // the colours of the writes that were overwritten are not kept).
    std::optional<std::array<std::uint8_t, 4>> before, after;
    bool reached = true;    // at or before the stepping cursor
    bool atCursor = false;  // holds the pixel at the cursor
};

class PixelHistory {
    // The texts are the inspector's: they keep its translation context.
    Q_DECLARE_TR_FUNCTIONS(rasterlab::PixelInspector)

public:
    // The history of the inspection's picked pixel in its frame, from the replay (or the frame
    // traced again when the replay failed).
    void rebuild(const Inspection& inspection);
    // Marks the rows the inspection's cursor has reached and the one holding the pixel there;
    // true when a row's marks changed.
    bool updateCursorMarks(const Inspection& inspection);
    // The row holding the pixel at the cursor, when a fragment holds it; else -1.
    int defaultRow() const;

    QPoint pixel() const { return m_pixel; }  // (-1, -1): none
    // Initial, the fragments in drawing order, Final.
    const std::vector<PixelHistoryRow>& rows() const { return m_rows; }
    QString verdict() const { return m_verdict; }
    // True when the history comes from tracing the frame again (no replay).
    bool traced() const { return m_traced; }
    // The final shading, without a replay.
    const std::optional<rl::ShadeEvent>& tracedShade() const { return m_tracedShade; }

    struct Source;  // what the rows are worked out from (pixel_history.cpp)

private:
    // rebuild's parts: the fragments' rows from the replay, or from the frame traced again
    // (none when it cannot be: the verdict says why), each returning the row of the last
    // write (0: none); the final row; the verdict.
    std::uint32_t addReplayedRows(const Source& source, const rl::FrameReplay& replay,
                                  PixelHistoryRow& finalRow);
    std::optional<std::uint32_t> addTracedRows(const Source& source, PixelHistoryRow& finalRow);
    void addFinalRow(const Source& source, PixelHistoryRow finalRow, std::uint32_t finalWriterRow);
    void writeVerdict(const Source& source, const rl::FrameReplay* replay,
                      std::uint32_t finalWriterRow);

    QPoint m_pixel{-1, -1};
    std::vector<PixelHistoryRow> m_rows;
    std::optional<rl::ShadeEvent> m_tracedShade;
    bool m_traced = false;
    QString m_verdict;
};

}  // namespace rasterlab
