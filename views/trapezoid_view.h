// Seed 002's presentation of scan conversion (trapezoids.h), beside the edge walk of the
// scanline view: the triangle being drawn split at its middle vertex's row into an upper
// and a lower trapezoid, their corners TL, TR, BL, BR with (i, j), pz and, under Gouraud
// shading, (r, g, b); for the current scanline j, t_j, L = lerp(t_j, TL, BL) and
// R = lerp(t_j, TR, BR), the pixels between them and, for the pixel at the cursor, t_i and
// the values lerp(t_i, L, R). It is the same scan as the edge walk: the same rows and the
// same pixels. Like the scanline view, it follows the stepping cursor, and at the start or
// the end of the frame shows the triangle selected.
#pragma once

#include <QString>

#include <array>
#include <cstdint>
#include <optional>

#include "pipeline/render/frame_trace.h"
#include "pipeline/stages/trapezoids.h"
#include "views/explained_view.h"

namespace rasterlab {

class Inspection;
class TrapezoidCanvas;

struct TrapezoidModel {
    std::uint32_t triangle = 0;  // Projection::triangles
    rl::TriangleSetup setup;
    rl::TrapezoidSplit split;
    bool hasColour = false;           // the corners carry the Gouraud vertex colours
    bool inverseDepth = false;        // pz is 1/z (the depth test interpolates 1/z)
    std::optional<std::size_t> part;  // the trapezoid holding the current row
    std::optional<rl::TrapezoidRow> row;
    std::optional<int> pixel;  // the pixel at the cursor (or picked) on the row
};

// The model of projected triangle t at scanline y (no row when y is not one of its rows on
// the screen). colours: the vertex colours Gouraud shading mixes (in the triangle's order).
TrapezoidModel trapezoidModel(const rl::FrameTrace& frame, std::uint32_t triangle,
                              std::optional<int> y,
                              const std::optional<std::array<rl::vec3, 3>>& colours);

class TrapezoidView : public ExplainedView {
    Q_OBJECT
public:
    explicit TrapezoidView(Inspection* inspection, QWidget* parent = nullptr);

    const std::optional<TrapezoidModel>& model() const { return m_model; }
    bool followsCursor() const { return m_followsCursor; }
    QString titleText() const;

private:
    void refresh() override;
    QString explanationHtml() const;
    std::optional<std::array<rl::vec3, 3>> gouraudColours(std::uint32_t triangle) const;

    std::optional<TrapezoidModel> m_model;
    bool m_followsCursor = false;
    TrapezoidCanvas* m_canvas = nullptr;
};

}  // namespace rasterlab
