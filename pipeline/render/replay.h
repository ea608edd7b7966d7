// Stepping is replay (DESIGN.md). The renderer runs its stages one after the other over the
// whole frame; the lecture's algorithm runs them interleaved: for each triangle, for each
// scanline of its edge walk, for each pixel of the span, test the depth and, if nearer,
// shade and write. Both give the same buffers, so the frame can be shown at any point of
// the lecture's loop by replaying its fragments in drawing order.
//
// FrameReplay records, once per frame, every row the edge walk visits (empty ones too) and
// every fragment with its depth-test verdict, the depth it replaced, the fragment it
// replaced and the colour it writes (shaded by the frame's own shading stage, so the last
// fragment written to a pixel has the frame's colour, bit for bit). ReplayState holds the
// buffers at a cursor and moves it by applying fragments forward or undoing them backward:
// a step costs the pixels it crosses, whichever way it goes.
//
// A cursor is (rows reached, fragments tested). Stops by granularity:
//   pixel:    after each fragment;
//   span:     after each row whose span holds a pixel;
//   scanline: after each row the edge walk visits on the screen, empty ones included;
//   triangle: after the last row of each triangle that has one;
// and the start and the end of the frame. Breakpoints stop on the row or the fragment they
// name.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "pipeline/core/diagnostics.h"
#include "pipeline/core/image.h"
#include "pipeline/render/frame_trace.h"
#include "pipeline/render/output_image.h"
#include "pipeline/stages/depth_test.h"
#include "pipeline/stages/probe.h"

namespace rl {

enum class StepGranularity : std::uint8_t { Stage, Triangle, Scanline, Span, Pixel };

// One row of a triangle's edge walk (triangle, y, the span [xBegin, xEnd) on the screen and
// the exact edge crossings xLeft, xRight), and the fragments its pixels made.
struct ReplayRow : ReplayRowEvent {
    std::uint32_t fragmentBegin = 0, fragmentEnd = 0;
    bool empty() const { return xBegin >= xEnd; }
};

struct ReplayCursor {
    std::uint32_t rows = 0;       // rows reached; the last of them is the current row
    std::uint32_t fragments = 0;  // fragments tested
    bool operator==(const ReplayCursor&) const = default;
    bool operator<(const ReplayCursor& o) const {
        return rows != o.rows ? rows < o.rows : fragments < o.fragments;
    }
};

struct ReplayLimits {
    // Each fragment takes 56 bytes: 8 million is about 450 MB.
    std::size_t maxFragments = 8'000'000;
};

// A breakpoint of the stepper.
struct Breakpoint {
    enum class Kind : std::uint8_t {
        Triangle,        // when triangle `triangle`'s first row is reached
        Scanline,        // when a row y is reached
        DepthRejection,  // after the first fragment at (x, y) the depth test rejects
        LightBehind,     // after the first fragment written at (x, y) with N.L < 0
        NthWrite,        // after a pixel ((x, y), or any when x < 0) is written the n-th time
    };
    Kind kind = Kind::Triangle;
    std::uint32_t triangle = 0;
    int x = -1, y = -1;
    std::uint32_t n = 2;
    bool enabled = true;
    bool operator==(const Breakpoint&) const = default;
};

struct BreakpointHit {
    ReplayCursor cursor;
    std::size_t breakpoint = 0;            // index into the list searched
    std::uint32_t fragment = kNoFragment;  // the fragment it stopped on, if any
};

class FrameReplay {
public:
    // Records the frame (one thread for the edge walk and the depth test; shading on the
    // frame's threads). Fails when the frame has more fragments than the limits allow, or
    // when cancel becomes true.
    static Result<std::shared_ptr<const FrameReplay>> build(
        std::shared_ptr<const FrameTrace> trace, const ReplayLimits& limits = {},
        const std::atomic<bool>* cancel = nullptr);

    const FrameTrace& trace() const { return *m_trace; }
    const std::shared_ptr<const FrameTrace>& tracePtr() const { return m_trace; }
    const std::vector<ReplayRow>& rows() const { return m_rows; }
    const std::vector<ReplayFragment>& fragments() const { return m_fragments; }
    // The rows of projected triangle t: [firstRow(t), endRow(t)).
    std::uint32_t firstRow(std::uint32_t t) const { return m_rowStart[t]; }
    std::uint32_t endRow(std::uint32_t t) const { return m_rowStart[t + 1]; }
    std::size_t triangleCount() const { return m_rowStart.size() - 1; }
    // The fragment holding each pixel at the end of the frame, or kNoFragment.
    const Image<std::uint32_t>& finalWriter() const { return m_finalWriter; }
    std::size_t writtenCount() const { return m_written; }
    // How many of the first `count` fragments were written.
    std::size_t writtenBefore(std::uint32_t count) const;

    ReplayCursor start() const { return {}; }
    ReplayCursor end() const {
        return {static_cast<std::uint32_t>(m_rows.size()),
                static_cast<std::uint32_t>(m_fragments.size())};
    }
    bool valid(ReplayCursor c) const;
    // The point just after fragment count - 1 was tested (its row reached); count 0 is the
    // start and the number of fragments the end.
    ReplayCursor atFragment(std::uint32_t count) const;
    // The cursor after the edge walk reached row k (none of its pixels tested yet).
    ReplayCursor atRowStart(std::uint32_t k) const { return {k + 1, m_rows[k].fragmentBegin}; }
    ReplayCursor next(ReplayCursor c, StepGranularity granularity) const;
    ReplayCursor previous(ReplayCursor c, StepGranularity granularity) const;

    // The current row (the last reached), or null at the start.
    const ReplayRow* currentRow(ReplayCursor c) const {
        return c.rows == 0 ? nullptr : &m_rows[c.rows - 1];
    }
    // The last fragment tested, if it belongs to the current row.
    std::optional<std::uint32_t> currentFragment(ReplayCursor c) const;

    // The fragments of pixel (x, y), in drawing order.
    std::vector<std::uint32_t> fragmentsAt(int x, int y) const;
    // The lighting of fragments as the frame's shading stage works it out (for the pixel
    // inspector and the N.L breakpoint): one event per fragment, in the order given.
    std::vector<ShadeEvent> shade(const std::vector<std::uint32_t>& fragments) const;
    // The colour a fragment writes, as bytes (the scene's clamping and rounding).
    std::array<std::uint8_t, 4> bytesOf(std::uint32_t fragment) const;

    // The first enabled breakpoint that fires after `from`, if any.
    std::optional<BreakpointHit> findBreakpoint(ReplayCursor from,
                                                const std::vector<Breakpoint>& breakpoints) const;

private:
    FrameReplay() = default;
    bool stopsAfterRow(std::uint32_t k, StepGranularity granularity) const;
    ReplayCursor rowEnd(std::uint32_t k) const {
        return {k, k == 0 ? 0u : m_rows[k - 1].fragmentEnd};
    }

    std::shared_ptr<const FrameTrace> m_trace;
    std::vector<ReplayRow> m_rows;
    std::vector<std::uint32_t> m_rowStart;  // per projected triangle, and one past the last
    std::vector<ReplayFragment> m_fragments;
    Image<std::uint32_t> m_finalWriter;
    std::size_t m_written = 0;
    std::vector<std::uint32_t> m_writtenPrefix;  // written among the first 1024 k fragments
};

// The buffers at a cursor: the depth buffer, the fragment holding each pixel and the image
// as bytes. Moving the cursor applies or undoes the fragments in between (or starts from the
// end of the frame or from the cleared buffers when that is shorter).
class ReplayState {
public:
    explicit ReplayState(std::shared_ptr<const FrameReplay> replay);

    const FrameReplay& replay() const { return *m_replay; }
    const std::shared_ptr<const FrameReplay>& replayPtr() const { return m_replay; }
    ReplayCursor cursor() const { return m_cursor; }
    void seek(ReplayCursor target);

    const Image<float>& depth() const { return m_buffers.depth; }
    // The depth buffer, the triangle and the barycentrics of each pixel at the cursor, as the
    // depth test leaves them (its counters are not kept).
    const DepthTest& buffers() const { return m_buffers; }
    const Image<std::uint32_t>& writer() const { return m_writer; }
    const Rgba8Image& image() const { return m_image; }
    // The triangle holding pixel (x, y) at the cursor, or kNoTriangle.
    std::uint32_t triangleAt(int x, int y) const { return m_buffers.triangle.at(x, y); }

private:
    void apply(std::uint32_t i);
    void undo(std::uint32_t i);
    void show(int x, int y, std::uint32_t writer);
    void resetTo(bool end);

    std::shared_ptr<const FrameReplay> m_replay;
    ReplayCursor m_cursor;
    DepthTest m_buffers;
    Image<std::uint32_t> m_writer;
    Rgba8Image m_image;
    std::array<std::uint8_t, 4> m_background{};
};

}  // namespace rl
