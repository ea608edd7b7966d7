// Stage 5's view: the scan conversion of one triangle, where the stepping cursor is (the
// triangle, scanline and pixel being drawn), or, at the start and the end of the frame, of
// the triangle selected. It shows the triangle's edge table (long, upper and lower edge:
// ends, x on the first row, dx/dy, rows, side), the current scanline with its exact edge
// crossings and the pixels of its span, the depth and normal interpolated at both ends of
// the span (exactly as the depth test and shading work them out), a drawing of the triangle
// on the pixel grid around the scanline, and the lecture's explanation with these numbers.
#pragma once

#include <map>
#include <memory>
#include <utility>

#include <QRect>
#include <QString>

#include <array>
#include <cstdint>
#include <optional>

#include "pipeline/render/frame_trace.h"
#include "pipeline/stages/scan_conversion.h"
#include "views/explained_view.h"

namespace rasterlab {

class Inspection;
class ScanlineCanvas;

// One edge of a triangle's edge table.
struct ScanEdgeEntry {
    rl::dvec2 top{0.0}, bottom{0.0};  // its ends, pixels
    double dxdy = 0.0;                // the change of x from one scanline to the next
    // The rows the edge walk follows it on, before screen clipping ([firstRow, lastRow],
    // none when firstRow > lastRow), and its x on the first of them (where the walk starts).
    int firstRow = 0, lastRow = -1;
    double xFirstRow = 0.0;
    bool onLeft = false;      // it bounds the spans on the left
    bool horizontal = false;  // top.y == bottom.y: no row is walked on it
    bool walked() const { return firstRow <= lastRow; }
};

// A pixel at an end of the span, its sample's barycentrics with respect to the screen
// triangle, the depth the depth test gives it and the normal shading interpolates there.
struct SpanEnd {
    int x = 0, y = 0;
    rl::dvec2 sample{0.0};                          // where pixel (x, y) is sampled
    float alpha = 0.0f, beta = 0.0f, gamma = 0.0f;  // as the depth test computes them
    float depth = 0.0f;
    bool hasNormal = false;            // false when the scene is unlit (no normals)
    rl::vec3 normal = rl::vec3(0.0f);  // interpolated and normalised (zero: no normal)
};

// One scanline of the triangle's edge walk (the crossings of the sampled line y + offset,
// its pixels on the screen) and the ends of its span.
struct ScanRowInfo : rl::ScanRow {
    std::optional<SpanEnd> first, last;
};

// What the view shows of triangle t.
struct ScanlineModel {
    std::uint32_t triangle = 0;  // Projection::triangles
    rl::TriangleSetup setup;
    std::array<ScanEdgeEntry, 3> edges{};  // long, upper, lower
    ScreenRows rows;                       // the rows walked on the screen
    std::optional<ScanRowInfo> row;        // the scanline shown, if the triangle has one
    std::optional<int> currentPixel;       // x of the pixel at the cursor (or picked)
};

// The model of triangle t (an index into frame.projection->triangles) at scanline y, or
// without a scanline when y is not one of the rows walked on the screen.
ScanlineModel scanlineModel(const rl::FrameTrace& frame, std::uint32_t triangle,
                            std::optional<int> y);
// The span end at pixel x of row y of triangle t, as the depth test and shading compute it
// (the depth test's barycentrics step from the span's first pixel xBegin).
SpanEnd spanEnd(const rl::FrameTrace& frame, std::uint32_t triangle, int y, int xBegin, int x);

class ScanlineView : public ExplainedView {
    Q_OBJECT
public:
    explicit ScanlineView(Inspection* inspection, QWidget* parent = nullptr);

    // What is shown (nothing when there is no frame or no triangle to follow).
    const std::optional<ScanlineModel>& model() const { return m_model; }
    // True when the view follows the stepping cursor, false when it shows the triangle
    // selected (at the start or the end of the frame, or without a replay).
    bool followsCursor() const { return m_followsCursor; }
    QString titleText() const;
    // A student's spans (Check My Renderer...), for the frame they were checked on: each
    // (triangle, row) to its first and last pixel; the explanation puts them beside ours.
    using TheirSpans = std::map<std::pair<std::uint32_t, int>, std::pair<int, int>>;
    void setTheirSpans(std::shared_ptr<const rl::FrameTrace> frame, TheirSpans spans);
    // Where their spans of the triangle shown depart from ours, in the window drawn: the grid
    // marks these pixels, and outlines their span of the row shown.
    struct TheirCoverage {
        std::vector<QPoint> onlyOurs, onlyTheirs;
        std::optional<std::pair<int, int>> rowSpan;  // first and last pixel, both included
    };
    const std::optional<TheirCoverage>& theirCoverage() const { return m_theirCoverage; }
    // The window of pixels drawn: [left, left + width) x [top, top + height).
    QRect drawnWindow() const;

protected:
    // A canvas resized shows more or fewer pixels.
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void refresh() override;
    // Their span of the row shown beside ours, or nothing when no check gave spans.
    QString theirSpanHtml(const ScanlineModel& m) const;
    // Their coverage of the model's triangle in the window, when a check gave spans.
    std::optional<TheirCoverage> theirCoverageIn(const QRect& window) const;
    std::weak_ptr<const rl::FrameTrace> m_theirFrame;
    TheirSpans m_theirSpans;
    std::optional<TheirCoverage> m_theirCoverage;
    // The lecture's explanation with this triangle's numbers, section by section.
    QString explanationHtml() const;
    QString edgeTableHtml(const ScanlineModel& m) const;
    QString scanlineHtml(const ScanlineModel& m, const rl::Scene& scene) const;
    QString spanEndsHtml(const ScanlineModel& m, const rl::FrameTrace& frame) const;
    QString ddaSpanEndsHtml(const ScanlineModel& m, const rl::FrameTrace& frame) const;
    static std::vector<const SpanEnd*> spanEnds(const ScanRowInfo& row);
    QString spanEndsTable(const ScanRowInfo& row) const;
    static std::array<QString, 3> edgeNames();  // long, upper, lower

    std::optional<ScanlineModel> m_model;
    bool m_followsCursor = false;
    ScanlineCanvas* m_canvas = nullptr;
};

}  // namespace rasterlab
