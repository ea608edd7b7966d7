// Seed 000's whole frame made by the stages' own answers (stage_mistakes.h) with any of their
// mistakes applied: the basis, the view coordinates, the normals, the projection, the spans,
// the z-buffer and Phong at each pixel kept, in double. With no mistake it is the lecture's
// frame to within a byte; with the mistakes check found in the stages it is the frame those
// stages make, so that the frame's diagnosis starts from them.
#pragma once

#include <map>
#include <vector>

#include "app/check/stage_mistakes.h"
#include "app/check/stage_protocol.h"
#include "pipeline/render/output_image.h"

namespace rasterlab::check {

// What the frame request carries.
struct FrameScene {
    int width = 0, height = 0;
    rl::dvec3 c{0.0}, n{0.0}, v{0.0};
    double d = 1.0, hx = 1.0, hy = 1.0;
    rl::dvec3 lightWorld{0.0};
    Lighting lighting;  // its light is replaced by the view stage's
    std::vector<Row> world;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

// The frame with each stage's mistakes applied (a stage missing from `applied` has none):
// r g b bytes, black where no triangle is kept.
rl::Rgba8Image modelFrame(const FrameScene& scene, const std::map<Stage, Mistakes>& applied);

}  // namespace rasterlab::check
