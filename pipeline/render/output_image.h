// The one place where the pipeline's float buffers become 8-bit RGBA images: the final
// colour (clamped to the scene's colour scale, rounded by the scene's rule), the depth
// buffer as grey levels, and the normals as colours.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "pipeline/core/image.h"
#include "pipeline/core/math.h"
#include "pipeline/scene/scene.h"
#include "pipeline/stages/depth_test.h"
#include "pipeline/stages/shading.h"

namespace rl {

struct Rgba8Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // row-major, 4 bytes per pixel, top row first

    const std::uint8_t* pixel(int x, int y) const {
        return rgba.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                              static_cast<std::size_t>(x)) *
                                 4;
    }
    bool operator==(const Rgba8Image&) const = default;
};

// A channel in the scene's colour scale as a byte: clamped to [0, scale], then rounded by
// the scene's rule; NaN becomes 0.
std::uint8_t toByte(float value, const Conventions& conventions);

// A shaded colour as opaque RGBA bytes, and the background's RGBA bytes.
std::array<std::uint8_t, 4> colourBytes(const vec3& colour, const Conventions& conventions);
std::array<std::uint8_t, 4> backgroundBytes(const Conventions& conventions);
// A unit normal as opaque RGBA bytes, (n + 1) / 2 per channel (as normalImage writes it).
std::array<std::uint8_t, 4> normalBytes(const vec3& n);

// The final image: shaded pixels opaque, the others the scene's background.
Rgba8Image colourImage(const Shading& shading, const DepthTest& depth,
                       const Conventions& conventions);

// The depth buffer: near is white, far is dark grey, over the range of the depths drawn;
// pixels never written are black.
struct DepthRange {
    float nearest = 0.0f;
    float farthest = 0.0f;
    bool empty = true;
};
DepthRange depthRange(const Image<float>& depth);
Rgba8Image depthImage(const Image<float>& depth, const DepthRange& range);

// Unit normals as colours, (n + 1) / 2 per channel; pixels without a normal are black.
Rgba8Image normalImage(const Image<vec3>& normals, const DepthTest& depth);

}  // namespace rl
