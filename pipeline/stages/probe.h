// Observation of the inner loops. Scan conversion, the depth test and shading take a
// probe type as a template parameter and call its hooks inside `if constexpr
// (Probe::enabled)`: with NullProbe (the default) the hooks compile to nothing, so the
// plain render carries no trace code. RecordingProbe logs every event that touches a
// chosen pixel or a chosen triangle: triangle set-up with its edge table, spans, each
// depth test with both depths and the verdict, and the shading terms.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "pipeline/core/math.h"
#include "pipeline/scene/scene.h"
#include "pipeline/stages/phong.h"
#include "pipeline/stages/scan_conversion.h"

namespace rl {

struct NullProbe {
    static constexpr bool enabled = false;
};

// RL_PROBE_HOOK(statements): a hook of an inner loop, run only when the probe records. A
// build configured with RASTERLAB_PROBE_HOOKS=OFF leaves every hook out, so that the
// default build's null probe can be compared with a build that has no probes at all
// (scripts/probe-cost.sh); its recording probe records nothing.
#if defined(RL_NO_PROBE_HOOKS)
#define RL_PROBE_HOOK(...) static_cast<void>(probe)
#else
#define RL_PROBE_HOOK(...)              \
    do {                                \
        if constexpr (Probe::enabled) { \
            __VA_ARGS__;                \
        }                               \
    } while (false)
#endif

struct TriangleEvent {
    std::uint32_t triangle = 0;  // index into Projection::triangles
    TriangleSetup setup;
};

struct SpanEvent {
    std::uint32_t triangle = 0;
    Span span;
    double xLeft = 0.0, xRight = 0.0;  // exact edge crossings on this scanline
};

struct DepthTestEvent {
    std::uint32_t triangle = 0;
    int x = 0, y = 0;
    float alpha = 0.0f, beta = 0.0f, gamma = 0.0f;  // screen barycentrics
    float depth = 0.0f;                             // the fragment's interpolated depth
    float stored = 0.0f;                            // the depth buffer before the test
    bool passed = false;
    bool outsideDepthRange = false;  // discarded before the test: depth outside [0, 1]
};

struct ShadeEvent {
    std::uint32_t triangle = 0;
    int x = 0, y = 0;
    ShadingModel model = ShadingModel::Phong;
    vec3 pView = vec3(0.0f);              // P' (Phong), the barycentre (flat, painter)
    vec3 nInterpolated = vec3(0.0f);      // interpolated (Phong), the triangle's (flat, painter)
    PhongSample sample;                   // Phong: at P'; flat: at the barycentre
    std::array<vec3, 3> vertexColours{};  // Gouraud: the colours being interpolated
    vec3 colour = vec3(0.0f);             // before clamping
};

using ProbeEvent = std::variant<TriangleEvent, SpanEvent, DepthTestEvent, ShadeEvent>;

class RecordingProbe {
public:
    static constexpr bool enabled = true;

    static RecordingProbe forPixel(int x, int y);
    static RecordingProbe forTriangle(std::uint32_t triangle);

    void onTriangle(std::uint32_t triangle, const TriangleSetup& setup);
    void onSpan(std::uint32_t triangle, const Span& span, double xLeft, double xRight);
    void onRow(std::uint32_t, std::int32_t, double, double, std::int32_t, std::int32_t) {}
    void onDepthTest(const DepthTestEvent& event);
    void onShade(const ShadeEvent& event);

    const std::vector<ProbeEvent>& events() const { return m_events; }
    std::optional<ivec2> pixel() const { return m_pixel; }
    std::optional<std::uint32_t> triangle() const { return m_triangle; }

private:
    bool wants(std::uint32_t triangle, int x, int y) const;

    std::optional<ivec2> m_pixel;
    std::optional<std::uint32_t> m_triangle;
    std::vector<ProbeEvent> m_events;
    std::optional<TriangleEvent> m_pendingTriangle;  // pixel mode: kept until a span covers it
};

// What the stepper (replay.h) keeps of scan conversion and the depth test, compactly: every
// row the edge walk visits (empty ones too) and every fragment's depth test, in drawing
// order. Scan conversion and the depth test run on one thread with it.
struct ReplayRowEvent {
    std::uint32_t triangle = 0;
    std::int32_t y = 0;
    std::int32_t xBegin = 0, xEnd = 0;  // the span's pixels [xBegin, xEnd); empty when equal
    double xLeft = 0.0, xRight = 0.0;   // the exact edge crossings on this row
};

inline constexpr std::uint32_t kNoFragment = 0xffffffffu;

enum class FragmentVerdict : std::uint8_t {
    Written,            // nearer than what was stored: depth and colour written
    Rejected,           // as far as or farther than what was stored
    OutsideDepthRange,  // discarded before the test: depth outside [0, 1] (seed 001)
};

// One fragment: a pixel of a triangle's span, tested against the depth buffer.
struct ReplayFragment {
    std::int32_t x = 0, y = 0;
    std::uint32_t triangle = 0;       // Projection::triangles
    std::uint32_t row = 0;            // FrameReplay::rows()
    float depth = 0.0f;               // the fragment's interpolated depth
    float stored = 0.0f;              // the buffer's depth before the test
    float beta = 0.0f, gamma = 0.0f;  // screen barycentrics (alpha = 1 - beta - gamma)
    // Written: the fragment whose values it replaced (kNoFragment: the cleared buffer), and
    // how many fragments have written this pixel, this one included.
    std::uint32_t previous = kNoFragment;
    std::uint32_t writeNumber = 0;
    FragmentVerdict verdict = FragmentVerdict::Rejected;
    vec3 colour = vec3(0.0f);  // Written: the colour it writes (unclamped, the scene's scale)
};

// A depth test as a fragment: where, which triangle, both depths, the barycentrics and the
// verdict (the replay fills in row, previous, writeNumber and colour).
inline ReplayFragment fragmentOf(const DepthTestEvent& e) {
    ReplayFragment f;
    f.x = e.x;
    f.y = e.y;
    f.triangle = e.triangle;
    f.depth = e.depth;
    f.stored = e.stored;
    f.beta = e.beta;
    f.gamma = e.gamma;
    f.verdict = e.outsideDepthRange ? FragmentVerdict::OutsideDepthRange
                : e.passed          ? FragmentVerdict::Written
                                    : FragmentVerdict::Rejected;
    return f;
}

class ReplayProbe {
public:
    static constexpr bool enabled = true;

    void onTriangle(std::uint32_t, const TriangleSetup&) {}
    void onSpan(std::uint32_t, const Span&, double, double) {}
    void onRow(std::uint32_t triangle, std::int32_t y, double xLeft, double xRight,
               std::int32_t xBegin, std::int32_t xEnd) {
        rows.push_back({triangle, y, xBegin, xEnd, xLeft, xRight});
    }
    void onDepthTest(const DepthTestEvent& e) { fragments.push_back(fragmentOf(e)); }
    void onShade(const ShadeEvent&) {}

    std::vector<ReplayRowEvent> rows;
    std::vector<ReplayFragment> fragments;
};

}  // namespace rl
