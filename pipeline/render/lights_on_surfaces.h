// A warning the renderer gives before shading: a point light so near a surface that float
// cannot tell on which side of it the light lies. Not a stage of the lecture: a check on
// stage 2's output (view space).
#pragma once

#include <cstddef>
#include <vector>

#include "pipeline/scene/scene.h"
#include "pipeline/stages/view_transform.h"

namespace rl {

// Float keeps a view-space point to about 1.2e-7 of its distance from the eye, so the shading
// cannot tell on which side of a surface a light nearer to it than about that lies. Below
// kLightSurfaceRatio times the light's distance from the eye, the sweep of docs/accuracy.md
// measures float and double apart by a byte step or more, and the renderer warns.
inline constexpr double kLightSurfaceRatio = 1e-5;

struct LightOnSurface {
    std::size_t light = 0;  // in ViewTransform::lights
    std::size_t draw = 0, triangle = 0;
    double height = 0.0;  // from the triangle's plane, above the triangle itself
    double limit = 0.0;   // kLightSurfaceRatio times the light's distance from the eye
};
// Each positional light within its limit of a triangle it lies above, with the nearest such.
std::vector<LightOnSurface> lightsOnSurfaces(const Scene& scene, const ViewTransform& view);

}  // namespace rl
