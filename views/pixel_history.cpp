#include "pixel_history.h"

#include <algorithm>
#include <cmath>

#include "pipeline/render/output_image.h"
#include "pipeline/render/renderer.h"
#include "views/inspection.h"
#include "views/messages/pipeline_messages.h"
#include "views/pixel_text.h"

namespace rasterlab {

// What the rows of the pixel's history are worked out from.
struct PixelHistory::Source {
    const rl::FrameTrace& frame;
    const rl::Scene& scene;
    const rl::Conventions& conv;
    int x = 0, y = 0;
    std::array<std::uint8_t, 4> background{};
};

namespace {

void describeTriangle(const PixelHistory::Source& source, PixelHistoryRow& row) {
    const rl::Scene& scene = source.scene;
    const rl::ScreenTriangle& tri = source.frame.projection->triangles[row.triangle];
    row.meshTriangle = tri.source + 1;
    row.triangleText = QString::number(row.meshTriangle);
    if (scene.draws.size() > 1)
        row.triangleText +=
            QStringLiteral(" (%1)").arg(QString::fromStdString(scene.draws[tri.draw].name));
}

void describeTest(const PixelHistory::Source& source, PixelHistoryRow& row) {
    const bool tie = source.conv.depthWinsOnTie;
    switch (row.verdict) {
        case rl::FragmentVerdict::Written:
            if (source.frame.depth->painted) {
                // The painter's algorithm compares nothing: the last painted stays.
                row.depthText = PixelHistory::tr("%1 over %2").arg(num(row.depth), num(row.stored));
                row.resultText = PixelHistory::tr("painted, no depth test");
                break;
            }
            row.depthText =
                QStringLiteral("%1 %2 %3")
                    .arg(num(row.depth), tie ? QStringLiteral("<=") : QStringLiteral("<"),
                         num(row.stored));
            row.resultText = PixelHistory::tr("written");
            break;
        case rl::FragmentVerdict::Rejected:
            row.depthText =
                QStringLiteral("%1 %2 %3")
                    .arg(num(row.depth), tie ? QStringLiteral(">") : QStringLiteral(">="),
                         num(row.stored));
            if (std::isnan(row.depth))
                row.resultText = PixelHistory::tr("rejected: the depth is not a number");
            else if (row.depth == row.stored)
                row.resultText = PixelHistory::tr("rejected: as far, the earlier keeps it");
            else
                row.resultText = PixelHistory::tr("rejected: farther");
            break;
        case rl::FragmentVerdict::OutsideDepthRange:
            row.depthText = PixelHistory::tr("%1 outside [0, 1]").arg(num(row.depth));
            row.resultText = PixelHistory::tr("discarded: depth outside [0, 1]");
            break;
    }
}

// A fragment's row: its triangle, the depth test and its verdict.
PixelHistoryRow fragmentRow(const PixelHistory::Source& source, std::uint32_t id,
                            const rl::ReplayFragment& f) {
    PixelHistoryRow row;
    static_cast<rl::ReplayFragment&>(row) = f;
    row.fragment = id;
    describeTriangle(source, row);
    describeTest(source, row);
    return row;
}

PixelHistoryRow initialRow(const PixelHistory::Source& source) {
    const rl::Conventions& conv = source.conv;
    PixelHistoryRow initial;
    initial.kind = PixelHistoryRow::Kind::Initial;
    initial.depth = conv.depthClear;
    initial.depthText = PixelHistory::tr("cleared to %1").arg(num(conv.depthClear));
    initial.resultText = PixelHistory::tr("the background");
    initial.after = source.background;
    return initial;
}

// Why the fragment that holds the pixel, lit as `event` says, leaves it black.
QString whyBlack(const PixelHistory::Source& source, const rl::ShadeEvent& event) {
    const rl::FrameTrace& frame = source.frame;
    const rl::ScreenTriangle& tri = frame.projection->triangles[event.triangle];
    const rl::Draw& draw = source.scene.draws[tri.draw];
    const rl::PhongSample& s = event.sample;
    const bool ambient = s.ambient.r > 0.0f || s.ambient.g > 0.0f || s.ambient.b > 0.0f;
    const std::size_t lights =
        std::min(draw.lightCount, frame.view ? frame.view->lights.size() : 0);
    if (event.model == rl::ShadingModel::Gouraud)
        return PixelHistory::tr("black: the vertex colours mixed here are black");
    if (draw.lighting == rl::LightingModel::Unlit)
        return PixelHistory::tr("black: the object colour is black");
    if (ambient) return PixelHistory::tr("black: the light takes away what the ambient term adds");
    if (s.noNormal) return PixelHistory::tr("black: zero normal and no ambient");
    if (lights == 0) return PixelHistory::tr("black: no light and no ambient");
    if (s.lightAtPoint) return PixelHistory::tr("black: the light is at the point and no ambient");
    if (s.lightBehind) return PixelHistory::tr("black: N.L < 0 and no ambient");
    return PixelHistory::tr(
        "black: the diffuse and specular terms are 0 here and there is no "
        "ambient");
}

}  // namespace

void PixelHistory::rebuild(const Inspection& inspection) {
    m_rows.clear();
    m_tracedShade.reset();
    m_traced = false;
    m_verdict.clear();
    m_pixel = inspection.pickedPixel();
    const std::shared_ptr<const rl::FrameTrace>& frame = inspection.frame();
    if (!frame || !frame->scene || !frame->depth || m_pixel.x() < 0 ||
        !frame->depth->depth.contains(m_pixel.x(), m_pixel.y())) {
        m_pixel = QPoint(-1, -1);
        m_verdict = frame ? tr("Pick a pixel on the image to see its history.") : QString();
        return;
    }
    const rl::Conventions& conv = frame->scene->conventions;
    const Source source{*frame,      *frame->scene, conv,
                        m_pixel.x(), m_pixel.y(),   rl::backgroundBytes(conv)};
    m_rows.push_back(initialRow(source));

    PixelHistoryRow finalRow;
    finalRow.kind = PixelHistoryRow::Kind::Final;
    finalRow.resultText = tr("the final pixel");
    std::uint32_t finalWriterRow = 0;  // index in m_rows of the last write, 0: none

    if (const rl::FrameReplay* replay = inspection.replay()) {
        finalWriterRow = addReplayedRows(source, *replay, finalRow);
    } else if (inspection.replayError().isEmpty()) {
        // The replay is on its way (replayChanged brings it).
        m_rows.clear();
        m_verdict = tr("Preparing the stepping of this frame: the pixel's history follows.");
        return;
    } else {
        const std::optional<std::uint32_t> writer = addTracedRows(source, finalRow);
        if (!writer) return;
        finalWriterRow = *writer;
    }
    addFinalRow(source, std::move(finalRow), finalWriterRow);
    writeVerdict(source, inspection.replay(), finalWriterRow);
}

std::uint32_t PixelHistory::addReplayedRows(const Source& source, const rl::FrameReplay& replay,
                                            PixelHistoryRow& finalRow) {
    std::uint32_t finalWriterRow = 0;
    std::array<std::uint8_t, 4> current = source.background;
    for (std::uint32_t id : replay.fragmentsAt(source.x, source.y)) {
        const rl::ReplayFragment& f = replay.fragments()[id];
        PixelHistoryRow row = fragmentRow(source, id, f);
        row.before = current;
        if (f.verdict == rl::FragmentVerdict::Written) {
            current = replay.bytesOf(id);
            finalWriterRow = static_cast<std::uint32_t>(m_rows.size());
        }
        row.after = current;
        m_rows.push_back(row);
    }
    finalRow.after = current;
    return finalWriterRow;
}

std::optional<std::uint32_t> PixelHistory::addTracedRows(const Source& source,
                                                         PixelHistoryRow& finalRow) {
    // No replay (a frame too large to step through): the frame traced again for this
    // pixel, its depth tests and the shading of the fragment that won.
    m_traced = true;
    const rl::FrameTrace& frame = source.frame;
    const int x = source.x, y = source.y;
    rl::RecordingProbe probe = rl::RecordingProbe::forPixel(x, y);
    const auto traced = rl::traceFrame(frame.scene, rl::RenderOptions{}, probe);
    if (!traced) {
        m_verdict = tr("The frame could not be traced again: %1")
                        .arg(rasterlab::translated(traced.error()));
        return std::nullopt;
    }
    std::uint32_t finalWriterRow = 0;
    std::uint32_t order = 0;
    for (const rl::ProbeEvent& event : probe.events()) {
        if (const auto* test = std::get_if<rl::DepthTestEvent>(&event)) {
            const PixelHistoryRow row = fragmentRow(source, order++, rl::fragmentOf(*test));
            if (row.verdict == rl::FragmentVerdict::Written)
                finalWriterRow = static_cast<std::uint32_t>(m_rows.size());
            m_rows.push_back(row);
        } else if (const auto* shade = std::get_if<rl::ShadeEvent>(&event)) {
            m_tracedShade = *shade;
        }
    }
    // Colours are known up to the first write, and from the last write on (the final
    // colour); those of writes overwritten later are not kept without a replay.
    const bool covered = frame.depth->triangle.at(x, y) != rl::kNoTriangle;
    const std::array<std::uint8_t, 4> finalBytes =
        covered && frame.shading && frame.shading->colour.contains(x, y)
            ? rl::colourBytes(frame.shading->colour.at(x, y), source.conv)
            : source.background;
    std::optional<std::array<std::uint8_t, 4>> current = source.background;
    for (std::size_t i = 1; i < m_rows.size(); ++i) {
        PixelHistoryRow& row = m_rows[i];
        row.before = current;
        if (row.verdict == rl::FragmentVerdict::Written)
            current = i == finalWriterRow ? std::optional(finalBytes) : std::nullopt;
        row.after = current;
    }
    finalRow.after = finalBytes;
    return finalWriterRow;
}

void PixelHistory::addFinalRow(const Source& source, PixelHistoryRow finalRow,
                               std::uint32_t finalWriterRow) {
    const float finalDepth = source.frame.depth->depth.at(source.x, source.y);
    if (finalWriterRow > 0) {
        static_cast<rl::ReplayFragment&>(finalRow) = m_rows[finalWriterRow];
        finalRow.fragment = m_rows[finalWriterRow].fragment;
        describeTriangle(source, finalRow);
        finalRow.depthText = tr("depth %1").arg(num(finalDepth));
    } else {
        finalRow.triangleText = tr("none");
        finalRow.depthText = tr("depth %1 (cleared)").arg(num(finalDepth));
    }
    finalRow.depth = finalDepth;
    m_rows.push_back(std::move(finalRow));
}

void PixelHistory::writeVerdict(const Source& source, const rl::FrameReplay* replay,
                                std::uint32_t finalWriterRow) {
    std::size_t written = 0, rejected = 0;
    for (const PixelHistoryRow& row : m_rows) {
        if (row.kind != PixelHistoryRow::Kind::Fragment) continue;
        if (row.verdict == rl::FragmentVerdict::Written)
            ++written;
        else
            ++rejected;
    }
    const std::size_t fragments = written + rejected;
    const std::array<std::uint8_t, 4>& background = source.background;
    if (fragments == 0) {
        m_verdict = tr("Nothing drew here: the pixel keeps the background %1.")
                        .arg(QStringLiteral("(%1, %2, %3)")
                                 .arg(background[0])
                                 .arg(background[1])
                                 .arg(background[2]));
        return;
    }
    if (written == 0) {
        m_verdict = fragments == 1
                        ? tr("The only fragment was rejected: the pixel keeps the background.")
                        : tr("Every fragment was rejected (%1): the pixel keeps the background.")
                              .arg(fragments);
        return;
    }
    m_verdict = tr("Written by triangle %1").arg(m_rows[finalWriterRow].triangleText);
    if (written == 2)
        m_verdict += QStringLiteral(", ") + tr("over 1 earlier write");
    else if (written > 2)
        m_verdict += QStringLiteral(", ") + tr("over %1 earlier writes").arg(written - 1);
    if (rejected == 1)
        m_verdict += QStringLiteral("; ") + tr("1 fragment rejected");
    else if (rejected > 1)
        m_verdict += QStringLiteral("; ") + tr("%1 fragments rejected").arg(rejected);
    const std::array<std::uint8_t, 4> finalBytes = *m_rows.back().after;
    if (finalBytes[0] == 0 && finalBytes[1] == 0 && finalBytes[2] == 0) {
        // Why black: from the lighting of the fragment that holds it.
        std::optional<rl::ShadeEvent> event = m_tracedShade;
        if (replay) event = replay->shade({m_rows[finalWriterRow].fragment}).front();
        if (event) m_verdict += QStringLiteral("; ") + whyBlack(source, *event);
    }
    m_verdict += QLatin1Char('.');
}

bool PixelHistory::updateCursorMarks(const Inspection& inspection) {
    if (m_rows.empty()) return false;
    // Fragments [0, reached) have been tested at the cursor (all of them without a replay).
    const rl::FrameReplay* replay = inspection.replay();
    const std::uint32_t reached =
        replay && !m_traced ? inspection.cursor().fragments : rl::kNoFragment;
    std::size_t holder = 0;  // the row holding the pixel at the cursor: the initial one
    bool moved = false;
    for (std::size_t i = 0; i < m_rows.size(); ++i) {
        PixelHistoryRow& row = m_rows[i];
        bool isReached = true;  // the initial row
        if (row.kind == PixelHistoryRow::Kind::Fragment) {
            isReached = reached == rl::kNoFragment || row.fragment < reached;
            if (isReached && row.verdict == rl::FragmentVerdict::Written) holder = i;
        } else if (row.kind == PixelHistoryRow::Kind::Final) {
            isReached = inspection.atEnd();
        }
        moved = moved || row.reached != isReached;
        row.reached = isReached;
    }
    for (std::size_t i = 0; i < m_rows.size(); ++i) {
        moved = moved || m_rows[i].atCursor != (i == holder);
        m_rows[i].atCursor = i == holder;
    }
    return moved;
}

int PixelHistory::defaultRow() const {
    for (std::size_t i = 0; i < m_rows.size(); ++i)
        if (m_rows[i].atCursor && m_rows[i].kind == PixelHistoryRow::Kind::Fragment)
            return static_cast<int>(i);
    return -1;
}

}  // namespace rasterlab
