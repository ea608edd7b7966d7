#include "output_image.h"

#include <algorithm>
#include <cmath>

namespace rl {

std::uint8_t toByte(float value, const Conventions& conventions) {
    if (!(value > 0.0f)) return 0;  // also NaN
    const float scaled =
        std::min(value, conventions.colourScale) * (255.0f / conventions.colourScale);
    const float rounded = conventions.rounding == ByteRounding::Nearest ? std::floor(scaled + 0.5f)
                                                                        : std::floor(scaled);
    return static_cast<std::uint8_t>(std::clamp(rounded, 0.0f, 255.0f));
}

namespace {

Rgba8Image blank(int width, int height) {
    Rgba8Image image;
    image.width = width;
    image.height = height;
    image.rgba.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
    return image;
}

void put(Rgba8Image& image, int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b,
         std::uint8_t a) {
    std::uint8_t* p =
        image.rgba.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                             static_cast<std::size_t>(x)) *
                                4;
    p[0] = r;
    p[1] = g;
    p[2] = b;
    p[3] = a;
}

std::uint8_t unitToByte(float v) {
    return static_cast<std::uint8_t>(std::clamp(std::floor(v * 255.0f + 0.5f), 0.0f, 255.0f));
}

}  // namespace

std::array<std::uint8_t, 4> colourBytes(const vec3& colour, const Conventions& conventions) {
    return {toByte(colour.r, conventions), toByte(colour.g, conventions),
            toByte(colour.b, conventions), 255};
}

std::array<std::uint8_t, 4> normalBytes(const vec3& n) {
    return {unitToByte(n.x * 0.5f + 0.5f), unitToByte(n.y * 0.5f + 0.5f),
            unitToByte(n.z * 0.5f + 0.5f), 255};
}

std::array<std::uint8_t, 4> backgroundBytes(const Conventions& conventions) {
    const vec4 bg = conventions.background;
    return {unitToByte(bg.r), unitToByte(bg.g), unitToByte(bg.b), unitToByte(bg.a)};
}

Rgba8Image colourImage(const Shading& shading, const DepthTest& depth,
                       const Conventions& conventions) {
    const int w = shading.colour.width();
    const int h = shading.colour.height();
    Rgba8Image image = blank(w, h);
    const std::array<std::uint8_t, 4> bg = backgroundBytes(conventions);
    // Which pixels a triangle won: the depth test's ids, or when it kept none (shaded in
    // bands) the shading's covered.
    const bool ids = depth.fragmentsKept;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const bool won =
                ids ? depth.triangle.at(x, y) != kNoTriangle : shading.covered.at(x, y);
            const std::array<std::uint8_t, 4> c =
                won ? colourBytes(shading.colour.at(x, y), conventions) : bg;
            put(image, x, y, c[0], c[1], c[2], c[3]);
        }
    }
    return image;
}

DepthRange depthRange(const Image<float>& depth) {
    DepthRange range;
    for (float z : depth.pixels()) {
        if (!std::isfinite(z)) continue;
        if (range.empty) {
            range.nearest = range.farthest = z;
            range.empty = false;
        } else {
            range.nearest = std::min(range.nearest, z);
            range.farthest = std::max(range.farthest, z);
        }
    }
    return range;
}

Rgba8Image depthImage(const Image<float>& depth, const DepthRange& range) {
    Rgba8Image image = blank(depth.width(), depth.height());
    const float span = range.farthest - range.nearest;
    for (int y = 0; y < depth.height(); ++y) {
        for (int x = 0; x < depth.width(); ++x) {
            const float z = depth.at(x, y);
            if (!std::isfinite(z)) {
                put(image, x, y, 0, 0, 0, 255);
                continue;
            }
            // Near white (255), far dark grey (40), so the farthest surface stays visible
            // against the black background.
            const float t = span > 0.0f ? (z - range.nearest) / span : 0.0f;
            const std::uint8_t g =
                unitToByte((255.0f - 215.0f * std::clamp(t, 0.0f, 1.0f)) / 255.0f);
            put(image, x, y, g, g, g, 255);
        }
    }
    return image;
}

Rgba8Image normalImage(const Image<vec3>& normals, const DepthTest& depth) {
    Rgba8Image image = blank(depth.triangle.width(), depth.triangle.height());
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (depth.triangle.at(x, y) == kNoTriangle || normals.empty()) {
                put(image, x, y, 0, 0, 0, 255);
                continue;
            }
            const std::array<std::uint8_t, 4> c = normalBytes(normals.at(x, y));
            put(image, x, y, c[0], c[1], c[2], c[3]);
        }
    }
    return image;
}

}  // namespace rl
