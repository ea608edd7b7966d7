// The independent reference for the accuracy report: for each sample point of each pixel, a
// ray from the eye through it is cast against every triangle in double precision (a bounding
// volume hierarchy finds the nearest hit), and the hit is shaded with the exact barycentrics of
// the point on the triangle, which are the perspective-correct ones. It shares no code with
// projection, scan conversion or the depth test: only the view-space vertices and normals of
// the geometry stages, which are what the rasterizer starts from too.
//
// Shading, in double, is the course's formula (phong.h) with std::pow:
//     Phong    the interpolated normal N and the point P itself;
//     Gouraud  the colours of the three vertices (P and N of each), interpolated;
//     flat     one evaluation at the triangle's barycentre with the triangle's normal.
// Supported: course scenes (the course camera, view z as depth, the course's lighting with the
// material's colour). Anything else is an Unsupported error that says what is not.
#pragma once

#include <cstdint>
#include <limits>

#include "pipeline/core/diagnostics.h"
#include "pipeline/core/image.h"
#include "pipeline/core/math.h"
#include "pipeline/scene/scene.h"
#include "pipeline/stages/normals.h"
#include "pipeline/stages/view_transform.h"

namespace rl {

struct ReferenceImage {
    int samplesPerAxis = 1;  // samples at (x + (i + 0.5) / k, y + (j + 0.5) / k)
    // Per pixel: the mean of its samples' colours, each clamped to [0, colour scale] and
    // divided by it (0..1); samples that hit nothing count as the background.
    Image<dvec3> colour;
    Image<std::uint16_t> hits;  // samples that hit a triangle (0 .. k * k)
    // View z of the nearest hit (k = 1), or the mean over the samples that hit (k > 1);
    // +infinity where nothing is hit.
    Image<double> depth;
    // The hit triangle of the centre sample (k = 1): flat index, draw by draw in mesh order;
    // kNoHit where nothing is hit.
    Image<std::uint32_t> triangle;
    std::size_t triangles = 0;     // in the hierarchy
    std::size_t rays = 0;          // cast
    double buildMilliseconds = 0;  // the hierarchy
    double castMilliseconds = 0;   // the rays and the shading

    static constexpr std::uint32_t kNoHit = std::numeric_limits<std::uint32_t>::max();
};

struct ReferenceOptions {
    int samplesPerAxis = 1;
    int threads = 0;  // rows shared out; 0 for one per core
    // View-space z below which hits are ignored, as the rasterizer's near plane clips them
    // (Projection::nearW).
    double nearZ = 0.0;
};

// One ray's colour at a view-space point: the course's formula in double (exposed for tests).
dvec3 referencePhong(const Scene& scene, const Draw& draw, const std::vector<ViewLight>& lights,
                     const dvec3& pView, const dvec3& nView);

Result<ReferenceImage> renderReference(const Scene& scene, const ViewTransform& view,
                                       const Normals& normals, const ReferenceOptions& options);

}  // namespace rl
