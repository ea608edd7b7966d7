#include "probe.h"

namespace rl {

RecordingProbe RecordingProbe::forPixel(int x, int y) {
    RecordingProbe probe;
    probe.m_pixel = ivec2(x, y);
    return probe;
}

RecordingProbe RecordingProbe::forTriangle(std::uint32_t triangle) {
    RecordingProbe probe;
    probe.m_triangle = triangle;
    return probe;
}

bool RecordingProbe::wants(std::uint32_t triangle, int x, int y) const {
    if (m_triangle && *m_triangle != triangle) return false;
    if (m_pixel && (m_pixel->x != x || m_pixel->y != y)) return false;
    return true;
}

void RecordingProbe::onTriangle(std::uint32_t triangle, const TriangleSetup& setup) {
    if (m_triangle && *m_triangle != triangle) return;
    if (m_pixel) {
        // Whether this triangle touches the pixel is known only once its spans are walked.
        m_pendingTriangle = TriangleEvent{triangle, setup};
        return;
    }
    m_events.emplace_back(TriangleEvent{triangle, setup});
}

void RecordingProbe::onSpan(std::uint32_t triangle, const Span& span, double xLeft, double xRight) {
    if (m_triangle && *m_triangle != triangle) return;
    if (m_pixel) {
        if (span.y != m_pixel->y || m_pixel->x < span.xBegin || m_pixel->x >= span.xEnd) return;
        if (m_pendingTriangle && m_pendingTriangle->triangle == triangle) {
            m_events.emplace_back(*m_pendingTriangle);
            m_pendingTriangle.reset();
        }
    }
    m_events.emplace_back(SpanEvent{triangle, span, xLeft, xRight});
}

void RecordingProbe::onDepthTest(const DepthTestEvent& event) {
    if (wants(event.triangle, event.x, event.y)) m_events.emplace_back(event);
}

void RecordingProbe::onShade(const ShadeEvent& event) {
    if (wants(event.triangle, event.x, event.y)) m_events.emplace_back(event);
}

}  // namespace rl
