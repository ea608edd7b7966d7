#include "inspection.h"

namespace rasterlab {

namespace {

// Keeps the replay state alive while a QImage shows its bytes.
void releaseState(void* info) {
    delete static_cast<std::shared_ptr<rl::ReplayState>*>(info);
}

}  // namespace

Inspection::Inspection(QObject* parent) : QObject(parent) {}

void Inspection::setFrame(std::shared_ptr<const rl::FrameTrace> frame, QImage image) {
    m_frame = std::move(frame);
    m_frameImage = std::move(image);
    m_replay.reset();
    m_state.reset();
    m_replayError.clear();
    m_hit.reset();
    m_hitFrom.reset();
    const bool onImage = m_frame && m_picked.x() >= 0 && m_picked.x() < m_frame->scene->width &&
                         m_picked.y() >= 0 && m_picked.y() < m_frame->scene->height;
    if (!onImage) m_picked = QPoint(-1, -1);
    // Triangle numbers belong to a frame's projection: selected again from the pixel (which
    // stays), once the views have the new frame. The replay dropped is part of frameChanged;
    // cursorChanged says the buffers are the new frame's.
    m_vertices.clear();
    m_triangle.reset();
    emit frameChanged();
    emit cursorChanged();
    selectTriangle(triangleOf(m_picked));
}

void Inspection::setReplay(std::shared_ptr<const rl::FrameReplay> replay,
                           std::optional<rl::ReplayCursor> at) {
    if (replay && replay->tracePtr() != m_frame) return;
    m_replay = std::move(replay);
    m_state = m_replay ? std::make_shared<rl::ReplayState>(m_replay) : nullptr;
    m_hit.reset();
    m_hitFrom.reset();
    if (m_state) {
        m_state->seek(m_replay->end());
        if (at && m_replay->valid(*at)) m_state->seek(*at);
    }
    emit replayChanged();
    emit cursorChanged();
}

void Inspection::setReplayError(const QString& message) {
    m_replayError = message;
    emit replayChanged();
}

void Inspection::setStage(rl::StageId stage) {
    if (stage == m_stage) return;
    m_stage = stage;
    emit stageChanged(stage);
}

void Inspection::setGranularity(rl::StepGranularity granularity) {
    if (granularity == m_granularity) return;
    m_granularity = granularity;
    emit granularityChanged(granularity);
}

rl::ReplayCursor Inspection::cursor() const {
    if (m_state) return m_state->cursor();
    return m_replay ? m_replay->end() : rl::ReplayCursor{};
}

bool Inspection::atStart() const {
    return m_state && m_state->cursor() == m_replay->start();
}

bool Inspection::atEnd() const {
    return !m_state || m_state->cursor() == m_replay->end();
}

void Inspection::seek(rl::ReplayCursor cursor) {
    if (!m_state || !m_replay->valid(cursor) || cursor == m_state->cursor()) return;
    m_state->seek(cursor);
    emit cursorChanged();
}

void Inspection::updateCursorStage() {
    // Up to scan conversion nothing is in the buffers yet; the depth test fills them.
    const bool drawn = m_stage == rl::StageId::DepthTest || m_stage == rl::StageId::Shading;
    if (m_replay) seek(drawn ? m_replay->end() : m_replay->start());
}

bool Inspection::stepForward() {
    if (m_granularity == rl::StepGranularity::Stage) {
        if (m_stage == rl::StageId::Shading) return false;
        setStage(static_cast<rl::StageId>(static_cast<int>(m_stage) + 1));
        updateCursorStage();
        return true;
    }
    if (!m_state || atEnd()) return false;
    seek(m_replay->next(m_state->cursor(), m_granularity));
    return true;
}

bool Inspection::stepBack() {
    if (m_granularity == rl::StepGranularity::Stage) {
        if (m_stage == rl::StageId::CameraBasis) return false;
        setStage(static_cast<rl::StageId>(static_cast<int>(m_stage) - 1));
        updateCursorStage();
        return true;
    }
    if (!m_state || atStart()) return false;
    seek(m_replay->previous(m_state->cursor(), m_granularity));
    return true;
}

void Inspection::toStart() {
    if (m_granularity == rl::StepGranularity::Stage) setStage(rl::StageId::CameraBasis);
    if (m_replay) seek(m_replay->start());
}

void Inspection::toEnd() {
    if (m_granularity == rl::StepGranularity::Stage) setStage(rl::StageId::Shading);
    if (m_replay) seek(m_replay->end());
}

std::optional<rl::BreakpointHit> Inspection::nextHit() {
    if (!m_replay) return std::nullopt;
    const rl::ReplayCursor c = cursor();
    if (m_hitFrom && !(c < *m_hitFrom) && (!m_hit || c < m_hit->cursor)) return m_hit;
    m_hit = m_replay->findBreakpoint(c, m_breakpoints);
    m_hitFrom = c;
    return m_hit;
}

bool Inspection::advance(bool& moved) {
    moved = false;
    if (m_granularity == rl::StepGranularity::Stage) {
        moved = stepForward();
        return false;
    }
    if (!m_state || atEnd()) return false;
    const rl::ReplayCursor next = m_replay->next(m_state->cursor(), m_granularity);
    const std::optional<rl::BreakpointHit> hit = nextHit();
    moved = true;
    if (hit && !(next < hit->cursor)) {
        seek(hit->cursor);
        emit breakpointHit(static_cast<int>(hit->breakpoint));
        return true;
    }
    seek(next);
    return false;
}

bool Inspection::continueToBreakpoint() {
    if (!m_state) return false;
    if (const std::optional<rl::BreakpointHit> hit = nextHit()) {
        seek(hit->cursor);
        emit breakpointHit(static_cast<int>(hit->breakpoint));
        return true;
    }
    seek(m_replay->end());
    return false;
}

void Inspection::setBreakpoints(std::vector<rl::Breakpoint> breakpoints) {
    m_breakpoints = std::move(breakpoints);
    m_hit.reset();
    m_hitFrom.reset();
    emit breakpointsChanged();
}

const rl::ReplayRow* Inspection::currentRow() const {
    return m_state ? m_replay->currentRow(m_state->cursor()) : nullptr;
}

std::optional<std::uint32_t> Inspection::currentTriangle() const {
    const rl::ReplayRow* row = currentRow();
    if (!row) return std::nullopt;
    return row->triangle;
}

std::optional<std::uint32_t> Inspection::currentFragment() const {
    if (!m_state) return std::nullopt;
    return m_replay->currentFragment(m_state->cursor());
}

QString Inspection::positionText() const {
    if (!m_frame) return {};
    if (!m_state) return tr("end of frame");
    if (atStart()) return tr("start of frame: nothing drawn yet");
    if (atEnd()) return tr("end of frame");
    const rl::ReplayRow* row = currentRow();
    const rl::ScreenTriangle& tri = m_frame->projection->triangles[row->triangle];
    const rl::Draw& draw = m_frame->scene->draws[tri.draw];
    QString text = tr("triangle %1 of %2").arg(tri.source + 1).arg(draw.mesh->triangles.size());
    if (m_frame->scene->draws.size() > 1)
        text += QStringLiteral(" (%1)").arg(QString::fromStdString(draw.name));
    text += QStringLiteral(", ") + tr("scanline %1").arg(row->y);
    text +=
        QStringLiteral(", ") +
        (row->empty() ? tr("no pixel on it") : tr("span [%1, %2)").arg(row->xBegin).arg(row->xEnd));
    if (const std::optional<std::uint32_t> f = currentFragment())
        text += QStringLiteral(", ") + tr("pixel %1").arg(m_replay->fragments()[*f].x);
    return text;
}

QImage Inspection::image() const {
    if (!m_state) return m_frameImage;
    const rl::Rgba8Image& bytes = m_state->image();
    // Read-only: whoever draws on the image gets a copy, the replay's buffer stays as it is.
    const uchar* data = bytes.rgba.data();
    return QImage(data, bytes.width, bytes.height, bytes.width * 4, QImage::Format_RGBA8888,
                  &releaseState, new std::shared_ptr<rl::ReplayState>(m_state));
}

const rl::DepthTest* Inspection::buffers() const {
    if (m_state) return &m_state->buffers();
    return m_frame ? m_frame->depth.get() : nullptr;
}

std::shared_ptr<const rl::DepthTest> Inspection::sharedBuffers() const {
    if (m_state) return std::shared_ptr<const rl::DepthTest>(m_state, &m_state->buffers());
    return m_frame ? m_frame->depth : nullptr;
}

std::uint32_t Inspection::triangleAt(QPoint pixel) const {
    const rl::DepthTest* b = buffers();
    if (!b || !b->triangle.contains(pixel.x(), pixel.y())) return rl::kNoTriangle;
    return b->triangle.at(pixel.x(), pixel.y());
}

std::optional<std::uint32_t> Inspection::triangleOf(QPoint pixel) const {
    const std::uint32_t t = triangleAt(pixel);
    return t == rl::kNoTriangle ? std::nullopt : std::optional<std::uint32_t>(t);
}

void Inspection::pickPixel(QPoint pixel) {
    m_picked = pixel;
    emit pixelPicked(pixel);
    selectTriangle(triangleOf(pixel));
}

void Inspection::selectTriangle(std::optional<std::uint32_t> triangle) {
    m_triangle = triangle;
    m_vertices.clear();
    if (triangle && m_frame && *triangle < m_frame->projection->triangles.size()) {
        const rl::ScreenTriangle& tri = m_frame->projection->triangles[*triangle];
        for (std::uint32_t v : tri.v) m_vertices.push_back({tri.draw, v});
    }
    emit selectionChanged();
}

void Inspection::selectVertices(std::vector<VertexRef> vertices) {
    m_vertices = std::move(vertices);
    emit selectionChanged();
}

void Inspection::setPresentation(bool on) {
    if (on == m_presentation) return;
    m_presentation = on;
    emit presentationChanged(on);
}

}  // namespace rasterlab
