#include "replay.h"

#include <algorithm>
#include <string>

#include "pipeline/stages/depth_test.h"
#include "pipeline/stages/scan_conversion.h"
#include "pipeline/stages/shading.h"

namespace rl {

namespace {

constexpr std::uint32_t kPrefixStep = 1024;

// The shading stage run on a list of (triangle, barycentrics) instead of a depth buffer: the
// fragments are laid out in rows of a stand-in buffer, so the colour of each is worked out by
// the stage's own code. A fragment's colour depends on its triangle and barycentrics only,
// not on where its pixel is.
template <typename Probe>
Shading shadeStandIn(const FrameTrace& trace, const std::vector<ReplayFragment>& all,
                     const std::vector<std::uint32_t>& which, int width, Probe& probe) {
    const auto n = static_cast<int>(which.size());
    const int w = std::max(1, std::min(n, width));
    const int h = std::max(1, (n + w - 1) / w);
    Scene standIn = *trace.scene;
    standIn.width = w;
    standIn.height = h;
    DepthTest depth;
    depth.triangle.reset(w, h, kNoTriangle);
    depth.barycentric.reset(w, h, vec2(0.0f));
    depth.depth.reset(w, h, 0.0f);
    depth.barycentricsKept = true;
    for (int i = 0; i < n; ++i) {
        const ReplayFragment& f = all[which[static_cast<std::size_t>(i)]];
        depth.triangle.at(i % w, i / w) = f.triangle;
        depth.barycentric.at(i % w, i / w) = vec2(f.beta, f.gamma);
    }
    return ShadingStage().run({standIn, *trace.view, *trace.normals, *trace.projection, depth},
                              probe);
}

}  // namespace

Result<std::shared_ptr<const FrameReplay>> FrameReplay::build(
    std::shared_ptr<const FrameTrace> trace, const ReplayLimits& limits,
    const std::atomic<bool>* cancel) {
    const auto cancelled = [&] { return cancel && cancel->load(std::memory_order_relaxed); };
    const SourceLocation where{trace && trace->scene ? trace->scene->name : "<frame>", 0, 0};
    if (!trace || !trace->scene || !trace->projection || !trace->scan || !trace->depth)
        return makeError(ErrorCode::Usage, where, "no frame to step through"_msg);
    const Scene& scene = *trace->scene;
    if (trace->scan->pixels > limits.maxFragments)
        return makeError(
            ErrorCode::Usage, where,
            "stepping keeps at most %1 fragments, and this frame has %2: the final "
            "image and the views still work"_msg(limits.maxFragments, trace->scan->pixels));

    std::shared_ptr<FrameReplay> replay(new FrameReplay());
    replay->m_trace = trace;
    // The edge walk and the depth test again, on one thread, in drawing order.
    ReplayProbe probe;
    probe.fragments.reserve(trace->scan->pixels);
    const ScanConversion scan = ScanConversionStage().run({scene, *trace->projection}, probe);
    if (cancelled()) return makeError(ErrorCode::Usage, where, "cancelled"_msg);
    DepthTestStage().run({scene, *trace->projection, scan}, probe);
    if (cancelled()) return makeError(ErrorCode::Usage, where, "cancelled"_msg);
    replay->m_fragments = std::move(probe.fragments);
    auto& fragments = replay->m_fragments;

    // Rows, with the fragments each produced (a row's pixels, left to right).
    const std::size_t triangles = trace->projection->triangles.size();
    replay->m_rows.reserve(probe.rows.size());
    replay->m_rowStart.assign(triangles + 1, 0);
    std::uint32_t next = 0;
    for (const ReplayRowEvent& e : probe.rows) {
        ReplayRow row;
        static_cast<ReplayRowEvent&>(row) = e;
        row.fragmentBegin = next;
        next += static_cast<std::uint32_t>(std::max(0, e.xEnd - e.xBegin));
        row.fragmentEnd = next;
        const auto index = static_cast<std::uint32_t>(replay->m_rows.size());
        for (std::uint32_t i = row.fragmentBegin; i < row.fragmentEnd; ++i)
            fragments[i].row = index;
        ++replay->m_rowStart[e.triangle + 1];
        replay->m_rows.push_back(row);
    }
    if (next != fragments.size())
        return makeError(ErrorCode::Usage, where,
                         "internal error: the rows hold %1 pixels and the depth test saw %2 "
                         "fragments"_msg(next, fragments.size()));
    for (std::size_t t = 0; t < triangles; ++t) replay->m_rowStart[t + 1] += replay->m_rowStart[t];

    // Which fragment each written one replaced, how many times its pixel has been written
    // (one more than the fragment it replaced), and the count of writes before every 1024th
    // fragment, the end included.
    Image<std::uint32_t> writer(scene.width, scene.height, kNoFragment);
    std::vector<std::uint32_t> written;
    written.reserve(trace->depth->passed);
    replay->m_writtenPrefix.assign(fragments.size() / kPrefixStep + 1, 0);
    for (std::size_t i = 0; i < fragments.size(); ++i) {
        if (i % kPrefixStep == 0)
            replay->m_writtenPrefix[i / kPrefixStep] = static_cast<std::uint32_t>(written.size());
        ReplayFragment& f = fragments[i];
        if (f.verdict != FragmentVerdict::Written) continue;
        f.previous = writer.at(f.x, f.y);
        f.writeNumber = f.previous == kNoFragment ? 1 : fragments[f.previous].writeNumber + 1;
        writer.at(f.x, f.y) = static_cast<std::uint32_t>(i);
        written.push_back(static_cast<std::uint32_t>(i));
    }
    if (fragments.size() % kPrefixStep == 0)
        replay->m_writtenPrefix.back() = static_cast<std::uint32_t>(written.size());
    replay->m_finalWriter = std::move(writer);
    replay->m_written = written.size();
    if (cancelled()) return makeError(ErrorCode::Usage, where, "cancelled"_msg);

    // The colour each written fragment writes, by the frame's own shading stage.
    NullProbe none;
    const Shading shaded = shadeStandIn(*trace, fragments, written, 4096, none);
    const std::vector<vec3>& colours = shaded.colour.pixels();
    for (std::size_t k = 0; k < written.size(); ++k) fragments[written[k]].colour = colours[k];
    return std::shared_ptr<const FrameReplay>(std::move(replay));
}

std::size_t FrameReplay::writtenBefore(std::uint32_t count) const {
    count = std::min<std::uint32_t>(count, static_cast<std::uint32_t>(m_fragments.size()));
    std::size_t n = m_writtenPrefix.empty() ? 0 : m_writtenPrefix[count / kPrefixStep];
    for (std::uint32_t i = count / kPrefixStep * kPrefixStep; i < count; ++i)
        n += m_fragments[i].verdict == FragmentVerdict::Written ? 1 : 0;
    return n;
}

bool FrameReplay::valid(ReplayCursor c) const {
    if (c.rows > m_rows.size() || c.fragments > m_fragments.size()) return false;
    if (c.rows == 0) return c.fragments == 0;
    const ReplayRow& row = m_rows[c.rows - 1];
    return c.fragments >= row.fragmentBegin && c.fragments <= row.fragmentEnd;
}

ReplayCursor FrameReplay::atFragment(std::uint32_t count) const {
    if (count == 0) return start();
    if (count >= m_fragments.size()) return end();
    return {m_fragments[count - 1].row + 1, count};
}

bool FrameReplay::stopsAfterRow(std::uint32_t k, StepGranularity granularity) const {
    if (k == 0 || k >= m_rows.size()) return true;
    switch (granularity) {
        case StepGranularity::Scanline:
            return true;
        case StepGranularity::Span:
            return !m_rows[k - 1].empty();
        case StepGranularity::Triangle:
            return m_rows[k].triangle != m_rows[k - 1].triangle;
        case StepGranularity::Stage:
        case StepGranularity::Pixel:
            break;
    }
    return false;
}

ReplayCursor FrameReplay::next(ReplayCursor c, StepGranularity granularity) const {
    if (c == end()) return c;
    switch (granularity) {
        case StepGranularity::Stage:
            return end();
        case StepGranularity::Pixel:
            return c.fragments >= m_fragments.size() ? end() : atFragment(c.fragments + 1);
        default:
            break;
    }
    // The current row's end first, when the cursor is inside it.
    const bool complete = c.rows == 0 || c.fragments == m_rows[c.rows - 1].fragmentEnd;
    std::uint32_t k = complete ? c.rows + 1 : c.rows;
    while (!stopsAfterRow(k, granularity)) ++k;
    return rowEnd(k);
}

ReplayCursor FrameReplay::previous(ReplayCursor c, StepGranularity granularity) const {
    if (c == start()) return c;
    switch (granularity) {
        case StepGranularity::Stage:
            return start();
        case StepGranularity::Pixel: {
            if (c.fragments == 0) return start();
            const bool justAfter = atFragment(c.fragments) == c;
            return atFragment(justAfter ? c.fragments - 1 : c.fragments);
        }
        default:
            break;
    }
    std::uint32_t k = c.rows - 1;
    while (!stopsAfterRow(k, granularity)) --k;
    return rowEnd(k);
}

std::optional<std::uint32_t> FrameReplay::currentFragment(ReplayCursor c) const {
    const ReplayRow* row = currentRow(c);
    if (!row || c.fragments == row->fragmentBegin) return std::nullopt;
    return c.fragments - 1;
}

std::vector<std::uint32_t> FrameReplay::fragmentsAt(int x, int y) const {
    std::vector<std::uint32_t> out;
    for (std::size_t i = 0; i < m_fragments.size(); ++i)
        if (m_fragments[i].x == x && m_fragments[i].y == y)
            out.push_back(static_cast<std::uint32_t>(i));
    return out;
}

std::vector<ShadeEvent> FrameReplay::shade(const std::vector<std::uint32_t>& fragments) const {
    if (fragments.empty()) return {};
    RecordingProbe probe;
    shadeStandIn(*m_trace, m_fragments, fragments, 1 << 30, probe);
    std::vector<ShadeEvent> out(fragments.size());
    for (const ProbeEvent& e : probe.events()) {
        if (const auto* shade = std::get_if<ShadeEvent>(&e)) {
            ShadeEvent event = *shade;
            const auto k = static_cast<std::size_t>(event.x);
            const ReplayFragment& f = m_fragments[fragments[k]];
            event.x = f.x;
            event.y = f.y;
            out[k] = event;
        }
    }
    return out;
}

std::array<std::uint8_t, 4> FrameReplay::bytesOf(std::uint32_t fragment) const {
    return colourBytes(m_fragments[fragment].colour, m_trace->scene->conventions);
}

std::optional<BreakpointHit> FrameReplay::findBreakpoint(
    ReplayCursor from, const std::vector<Breakpoint>& breakpoints) const {
    std::optional<BreakpointHit> best;
    const auto offer = [&](ReplayCursor at, std::size_t b, std::uint32_t fragment) {
        if (!(from < at)) return false;
        if (!best || at < best->cursor) best = BreakpointHit{at, b, fragment};
        return true;
    };
    const auto n = static_cast<std::uint32_t>(m_fragments.size());
    for (std::size_t b = 0; b < breakpoints.size(); ++b) {
        const Breakpoint& bp = breakpoints[b];
        if (!bp.enabled) continue;
        switch (bp.kind) {
            case Breakpoint::Kind::Triangle:
                if (bp.triangle < triangleCount() && firstRow(bp.triangle) < endRow(bp.triangle))
                    offer(atRowStart(firstRow(bp.triangle)), b, kNoFragment);
                break;
            case Breakpoint::Kind::Scanline:
                for (std::uint32_t k = 0; k < m_rows.size(); ++k)
                    if (m_rows[k].y == bp.y && offer(atRowStart(k), b, kNoFragment)) break;
                break;
            case Breakpoint::Kind::DepthRejection:
                for (std::uint32_t i = 0; i < n; ++i) {
                    const ReplayFragment& f = m_fragments[i];
                    if (f.x == bp.x && f.y == bp.y && f.verdict != FragmentVerdict::Written &&
                        offer(atFragment(i + 1), b, i))
                        break;
                }
                break;
            case Breakpoint::Kind::LightBehind: {
                std::vector<std::uint32_t> candidates;
                for (std::uint32_t i : fragmentsAt(bp.x, bp.y))
                    if (m_fragments[i].verdict == FragmentVerdict::Written &&
                        from < atFragment(i + 1))
                        candidates.push_back(i);
                const std::vector<ShadeEvent> samples = shade(candidates);
                for (std::size_t k = 0; k < candidates.size(); ++k) {
                    if (samples[k].model != ShadingModel::Gouraud &&
                        samples[k].sample.lightBehind) {
                        offer(atFragment(candidates[k] + 1), b, candidates[k]);
                        break;
                    }
                }
                break;
            }
            case Breakpoint::Kind::NthWrite:
                for (std::uint32_t i = 0; i < n; ++i) {
                    const ReplayFragment& f = m_fragments[i];
                    if (f.verdict == FragmentVerdict::Written && f.writeNumber == bp.n &&
                        (bp.x < 0 || (f.x == bp.x && f.y == bp.y)) &&
                        offer(atFragment(i + 1), b, i))
                        break;
                }
                break;
        }
    }
    return best;
}

ReplayState::ReplayState(std::shared_ptr<const FrameReplay> replay) : m_replay(std::move(replay)) {
    const Scene& scene = *m_replay->trace().scene;
    m_background = backgroundBytes(scene.conventions);
    m_image.width = scene.width;
    m_image.height = scene.height;
    resetTo(false);
}

void ReplayState::resetTo(bool end) {
    const Scene& scene = *m_replay->trace().scene;
    const std::size_t pixels =
        static_cast<std::size_t>(scene.width) * static_cast<std::size_t>(scene.height);
    m_image.rgba.resize(pixels * 4);
    m_buffers.depth.reset(scene.width, scene.height, scene.conventions.depthClear);
    m_buffers.triangle.reset(scene.width, scene.height, kNoTriangle);
    m_buffers.barycentric.reset(scene.width, scene.height, vec2(0.0f));
    m_buffers.clearedTo = scene.conventions.depthClear;
    if (!end) {
        m_writer.reset(scene.width, scene.height, kNoFragment);
        for (std::size_t i = 0; i < pixels; ++i)
            std::copy(m_background.begin(), m_background.end(), m_image.rgba.begin() + 4 * i);
        m_cursor = m_replay->start();
        return;
    }
    m_writer = m_replay->finalWriter();
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) show(x, y, m_writer.at(x, y));
    m_cursor = m_replay->end();
}

void ReplayState::show(int x, int y, std::uint32_t writer) {
    const bool empty = writer == kNoFragment;
    const ReplayFragment* f = empty ? nullptr : &m_replay->fragments()[writer];
    m_buffers.depth.at(x, y) = empty ? m_buffers.clearedTo : f->depth;
    m_buffers.triangle.at(x, y) = empty ? kNoTriangle : f->triangle;
    m_buffers.barycentric.at(x, y) = empty ? vec2(0.0f) : vec2(f->beta, f->gamma);
    const std::array<std::uint8_t, 4> bytes = empty ? m_background : m_replay->bytesOf(writer);
    const std::size_t at = (static_cast<std::size_t>(y) * static_cast<std::size_t>(m_image.width) +
                            static_cast<std::size_t>(x)) *
                           4;
    std::copy(bytes.begin(), bytes.end(), m_image.rgba.begin() + static_cast<std::ptrdiff_t>(at));
}

void ReplayState::apply(std::uint32_t i) {
    const ReplayFragment& f = m_replay->fragments()[i];
    if (f.verdict != FragmentVerdict::Written) return;
    m_writer.at(f.x, f.y) = i;
    show(f.x, f.y, i);
}

void ReplayState::undo(std::uint32_t i) {
    const ReplayFragment& f = m_replay->fragments()[i];
    if (f.verdict != FragmentVerdict::Written) return;
    m_writer.at(f.x, f.y) = f.previous;
    show(f.x, f.y, f.previous);
}

void ReplayState::seek(ReplayCursor target) {
    if (!m_replay->valid(target)) return;
    const std::uint32_t from = m_cursor.fragments, to = target.fragments;
    const auto total = static_cast<std::uint32_t>(m_replay->fragments().size());
    const std::size_t pixels = m_writer.pixels().size();
    // Walking from here, or from the cleared buffers, or back from the end: the shortest.
    const std::size_t here = from > to ? from - to : to - from;
    const std::size_t viaStart = pixels / 4 + to;
    const std::size_t viaEnd = pixels / 4 + (total - to);
    std::uint32_t at = from;
    if (viaStart < here && viaStart <= viaEnd) {
        resetTo(false);
        at = 0;
    } else if (viaEnd < here) {
        resetTo(true);
        at = total;
    }
    for (; at < to; ++at) apply(at);
    for (; at > to; --at) undo(at - 1);
    m_cursor = target;
}

}  // namespace rl
