// The normals view's model: what the frame's normals look like on the screen. Per mesh
// triangle, whether it faces away from the camera and whether its winding agrees with its
// neighbours'; the wireframe of the projected triangles; the normal "hairs" (each triangle's
// from its centroid, each vertex's from the vertex) carried to the screen by the draw's
// projection; and per pixel, the normal shading uses there (the normal map).
#pragma once

#include <QImage>
#include <QLineF>
#include <QPointF>
#include <QRectF>
#include <QRgb>
#include <QSizeF>
#include <QString>

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "pipeline/render/frame_trace.h"
#include "pipeline/stages/depth_test.h"

namespace rasterlab {

// Per mesh triangle, 1 where its normal (P2 - P1) x (P3 - P1) points away from the camera at
// the origin of view space: n . P1 > 0 (P1 lies on the triangle, so this is n . pView for
// any of its points). Degenerate triangles are not back faces. pView: the draw's vertices.
std::vector<std::uint8_t> backFaces(std::span<const rl::dvec4> pView, const rl::Mesh& mesh);

// Triangles whose winding disagrees with a neighbour's: an edge run a -> b by two triangles
// (a consistently wound surface runs a shared edge once each way). Corners compared by index.
struct WindingReport {
    std::vector<std::uint8_t> inconsistent;  // per triangle
    std::size_t edges = 0;                   // edges run the same way by two or more triangles
    std::size_t triangles = 0;               // triangles with such an edge
};
WindingReport inconsistentWinding(const rl::Mesh& mesh);

// The normal shading uses at a pixel, worked out from the depth-test buffers (its triangle
// and barycentrics) as the renderer does: the vertex normals interpolated and normalised (the
// triangle's normal for flat shading or flat normals), turned toward the viewer when the
// scene's convention says so. Equal to what ShadingOptions::keepNormals keeps.
struct PixelNormal {
    bool covered = false;
    std::uint32_t triangle = rl::kNoTriangle;  // Projection::triangles
    rl::vec3 weights = rl::vec3(0.0f);         // (alpha, beta, gamma) the attributes use
    bool flat = false;                         // the triangle's normal, not interpolated
    rl::vec3 interpolated = rl::vec3(0.0f);    // before normalising (or the triangle's)
    rl::vec3 n = rl::vec3(0.0f);               // unit, toward the viewer; zero for none
    bool flipped = false;                      // turned toward the viewer (V . N < 0)
    QString none;                              // why there is no normal, when n is zero
};

class PixelNormals {
public:
    explicit PixelNormals(std::shared_ptr<const rl::FrameTrace> frame);
    PixelNormal at(const rl::DepthTest& buffers, int x, int y) const;
    // (n + 1) / 2 per channel, as rl::normalImage writes it; pixels no triangle holds black.
    QImage image(const rl::DepthTest& buffers) const;

private:
    struct DrawData {
        std::vector<rl::vec3> pView;  // (x, y, z) / w, own and made vertices
        std::vector<rl::vec3> nView;  // vertex normals, extended to made vertices
        std::vector<double> invW;     // 1 / clip w (perspective-correct rules)
    };
    std::shared_ptr<const rl::FrameTrace> m_frame;
    std::vector<DrawData> m_draws;
};

// (n + 1) / 2 as a colour, each channel rounded as rl::normalImage does.
QRgb normalColour(const rl::vec3& n);

// What the screen-space drawing holds, in image pixels (x right, y down).
struct NormalsPicture {
    QSizeF screen;
    QRectF focus;  // what the drawing fits to the widget: the mesh's box within the image
    enum class Face : std::uint8_t { Front, Back, Inconsistent };
    struct Triangle {
        std::array<QPointF, 3> p;
        Face face = Face::Front;
    };
    std::vector<Triangle> triangles;  // the projected triangles (maybe one in wireStep)
    std::vector<QLineF> triangleHairs, vertexHairs;
    // The selected projected triangle, its hair and its corners' hairs (always drawn).
    std::optional<std::array<QPointF, 3>> selected;
    std::vector<QLineF> selectedTriangleHairs, selectedVertexHairs;
    // Triangle normals carried by A = viewFromModel itself, not A^-T (rl::carriedTriangleNormal):
    // drawn when asked, beside the right ones.
    std::vector<QLineF> wrongHairs, selectedWrongHairs;

    std::size_t meshTriangles = 0;  // over every draw
    std::size_t backFaces = 0;      // mesh triangles facing away
    // Mesh triangles the projection left out as hidden back faces of a closed surface (not
    // drawn), by this view's test: front (n . P1 <= 0) and back.
    std::size_t culledFront = 0, culledBack = 0;
    std::size_t inconsistentEdges = 0;  // WindingReport, summed over the draws
    std::size_t inconsistentTriangles = 0;
    std::vector<int> viewWinding;    // per draw: closed surface with normals out (+1), in (-1)
    std::size_t coveredPixels = 0;   // pixels a triangle holds at the end of the frame
    std::size_t backFacePixels = 0;  // of them, held by a back face
    std::size_t hairTriangles = 0;   // triangles that may carry a hair (before subsampling)
    int wireStep = 1;                // one projected triangle in wireStep is drawn
    int triangleHairStep = 1, vertexHairStep = 1;
    double hairLength = 0.0;             // L, view units (of the first draw with hairs)
    double hairFraction = 0.0;           // L over the size of its mesh
    std::vector<double> drawHairLength;  // L of each draw
    bool normalsSkipped = false;
};

// Works out the NormalsPicture of a frame, and of the triangle selected in it.
class NormalsModel {
public:
    const NormalsPicture& picture() const { return m_picture; }
    // The picture of the frame (empty without a frame or its projection). onlyVisible: hairs
    // only on the triangles holding a pixel at the end of the frame (and their corners);
    // wrongNormals: the triangle normals carried by viewFromModel itself too.
    void rebuild(const std::shared_ptr<const rl::FrameTrace>& frame, bool onlyVisible,
                 bool wrongNormals);
    // The selected projected triangle (an index into the frame's triangles, or none) and its
    // hairs, in the picture of the same frame.
    void select(const std::shared_ptr<const rl::FrameTrace>& frame,
                std::optional<std::uint32_t> triangle, bool wrongNormals);
    // True when the mesh triangle's winding disagrees with a neighbour's (WindingReport).
    bool inconsistent(std::uint32_t draw, std::uint32_t triangle) const;

private:
    // Per draw, one byte per mesh triangle (or vertex); none for a draw without a mesh.
    using PerDraw = std::vector<std::vector<std::uint8_t>>;
    // rebuild's parts: the faces (the back faces per draw, returned), the wireframe, the
    // triangles holding a pixel (returned), the hairs and each draw's.
    PerDraw addFaces(const rl::FrameTrace& frame);
    void addWireframe(const rl::Projection& projection, const PerDraw& backFace);
    PerDraw markVisible(const rl::FrameTrace& frame, const PerDraw& backFace);
    void addHairs(const rl::FrameTrace& frame, const PerDraw& visible, bool onlyVisible,
                  bool wrong);
    void addDrawHairs(const rl::FrameTrace& frame, std::size_t d, const PerDraw& hairTriangles,
                      const PerDraw& hairVertices, bool wrong, std::size_t& triangleIndex,
                      std::size_t& vertexIndex);

    NormalsPicture m_picture;
    // Per draw, what depends on its mesh alone: its winding checks, kept from frame to frame
    // while the frame uses the mesh (no mesh: none).
    struct MeshFacts {
        std::shared_ptr<const rl::Mesh> mesh;
        WindingReport winding;
        int closed = 0;  // rl::closedSurfaceWinding
    };
    std::vector<MeshFacts> m_meshFacts;
};

}  // namespace rasterlab
