// Stage 7, shading: the colour of every visible pixel, by the draw's shading model.
// - Phong (seed 000): P' = alpha P1 + beta P2 + gamma P3 and N = alpha N1 + beta N2 +
//   gamma N3 with the pixel's screen barycentrics, then the lighting model of phong.h.
// - Flat (seed 004): one evaluation per triangle at its barycentre, with the triangle's
//   normal; every pixel of the triangle gets that colour.
// - Gouraud: one evaluation per vertex with the vertex normal; the pixel's colour is
//   alpha C1 + beta C2 + gamma C3.
// Only pixels that won the depth test are shaded, and flat and Gouraud evaluate only the
// triangles and vertices that are visible. Colours stay unclamped floats in the scene's
// scale (0..255 for course files); clamping happens when the image becomes bytes.
#pragma once

#include <cstdint>

#include "depth_test.h"
#include "image.h"
#include "math.h"
#include "normals.h"
#include "projection.h"
#include "scene.h"
#include "view_transform.h"

namespace rl {

struct ShadingOptions {
    bool keepNormals = false;  // also return the unit normal used at each pixel
};

struct Shading {
    Image<vec3> colour;  // unclamped, scene colour scale; background where empty
    Image<vec3> normal;  // unit normal used per pixel (only with keepNormals)
    std::size_t shadedPixels = 0;
    std::size_t phongEvaluations = 0;
    std::size_t flipped = 0;        // V.N < 0: the normal was turned toward the viewer
    std::size_t lightBehind = 0;    // N.L < 0: no diffuse, no specular
    std::size_t noSpecular = 0;     // R.V < 0: no specular
    std::size_t noNormal = 0;       // zero normal: ambient only
    std::size_t clampedPixels = 0;  // a channel above the colour scale (becomes 255)
    // Per chunk of kRowChunk rows (parallel.h), the columns that may hold other than the
    // background (the depth test's DepthTest::touched); empty when not tracked. The next
    // frame that reuses these buffers writes the background only where it is missing.
    std::vector<ColumnRange> touched;
    vec3 background = vec3(0.0f);  // of the pixels outside touched
};

class ShadingStage {
public:
    // threads: the rows are shared out between them (parallel.h); the result does not depend
    // on their number. recycled: an earlier frame's buffers, whose memory is reused.
    template <typename Probe>
    Shading run(const Scene& scene, const ViewTransform& view, const Normals& normals,
                const Projection& projection, const DepthTest& depth, const ShadingOptions& options,
                Probe& probe, int threads = 1, Shading* recycled = nullptr) const;
    Shading run(const Scene& scene, const ViewTransform& view, const Normals& normals,
                const Projection& projection, const DepthTest& depth,
                const ShadingOptions& options = {}, int threads = 1,
                Shading* recycled = nullptr) const;
};

}  // namespace rl
