// Seed 002's near-plane clipping of one triangle, one step of the algorithm at a time
// (near_clip.h): a side view of the triangle and the plane w = near (for the course camera
// the plane z = near of view space: w is the view z), each vertex tested (its distance
// dot(P, A), kept or dropped), each edge whose ends lie on both sides cut (t, C), the output
// polygon, its split into two triangles when it is a quad, and the triangles the projection
// stage drew from it, on the screen. Back, Next and All move through the steps; the text
// beside the picture gives each step's numbers.
//
// The triangle shown is the one selected (Inspection), else the one being drawn at the
// stepping cursor; a list offers the triangles of the frame that the near plane cut or hid.
#pragma once

#include <QPolygonF>
#include <QRectF>
#include <QString>

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "pipeline/render/frame_trace.h"
#include "pipeline/stages/near_clip.h"
#include "views/explained_view.h"

class QComboBox;
class QLabel;
class QPushButton;

namespace rasterlab {

class Inspection;
class NearClipCanvas;

// The steps, in the algorithm's order: the triangle and the plane; vertex A0, edge A0-A1,
// vertex A1, edge A1-A2, vertex A2, edge A2-A0; the output polygon; its split; the
// projected triangles.
enum class NearClipStep {
    Plane,
    Vertex0,
    Edge0,
    Vertex1,
    Edge1,
    Vertex2,
    Edge2,
    Polygon,
    Split,
    Projected
};
inline constexpr int kNearClipSteps = 10;

struct NearClipModel {
    std::uint32_t draw = 0, source = 0;  // the mesh triangle
    rl::TriangleFate fate = rl::TriangleFate::Inside;
    rl::NearClipRecord record;
    std::vector<std::uint32_t> projected;  // Projection::triangles it became
    bool nearClipping = true;              // the scene clips against the near plane
    bool otherPlanes = false;              // the draw has clip planes (cut before the near one)
};

// The part of a polygon inside a rectangle, so that a triangle reaching the guard band
// (2^28 pixels) is drawn without huge coordinates.
QPolygonF clipPolygonToRect(QPolygonF polygon, const QRectF& rect);

NearClipModel nearClipModel(const rl::FrameTrace& frame, std::uint32_t draw, std::uint32_t source);

class NearClipView : public ExplainedView {
    Q_OBJECT
public:
    explicit NearClipView(Inspection* inspection, QWidget* parent = nullptr);

    const std::optional<NearClipModel>& model() const { return m_model; }
    int step() const { return m_step; }
    void setStep(int step);
    // Shows mesh triangle `source` of draw `draw` (as choosing it in the list does).
    void showTriangle(std::uint32_t draw, std::uint32_t source);
    // The triangles the list offers (the near plane cut or hid them), without the first
    // entry (the one selected).
    int listedTriangles() const;
    // The mesh triangle (draw, source) of the list's entry `index`, 1 .. listedTriangles();
    // none for entry 0 (the one selected) or past the end.
    std::optional<std::pair<std::uint32_t, std::uint32_t>> listedTriangle(int index) const;
    QString titleText() const;

private:
    void refresh() override;
    void frameChanged() override;
    void presentationChanged() override;
    void rebuildList();
    void updateStep();
    QString explanationHtml() const;

    std::optional<NearClipModel> m_model;
    const rl::FrameTrace* m_modelFrame = nullptr;  // the frame m_model was made for
    std::optional<std::pair<std::uint32_t, std::uint32_t>> m_chosen;  // from the list
    std::optional<std::uint32_t> m_selectionAtChoice;                 // the triangle selected then
    int m_step = 0;
    const rl::FrameTrace* m_listFrame = nullptr;  // the frame the list was made for
    QComboBox* m_triangles = nullptr;
    QComboBox* m_axis = nullptr;
    QPushButton* m_back = nullptr;
    QPushButton* m_next = nullptr;
    QPushButton* m_all = nullptr;
    QLabel* m_stepLabel = nullptr;
    NearClipCanvas* m_canvas = nullptr;
};

}  // namespace rasterlab
