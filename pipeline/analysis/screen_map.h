// The 2D map of the screen that carries our coverage onto theirs (compare's screen-map
// mistake): a student's projection or pixel writing with another stretch, flip, turn or shift
// than the seed's (y scaled by the width, x and y swapped in the pixel's index ...). Fitted
// from the two coverages alone: their centroids and second moments give a first guess for
// each way the axes may go, and a pattern search on the pixels covered by one side only
// refines the best.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "pipeline/core/image.h"
#include "pipeline/core/math.h"
#include "pipeline/render/output_image.h"

namespace rl {

// Their point (x', y') of our point (x, y), both in pixels with a pixel's centre at + 0.5:
// x' = xx x + xy y + tx, y' = yx x + yy y + ty.
struct ScreenMap {
    double xx = 1.0, xy = 0.0, yx = 0.0, yy = 1.0;
    double tx = 0.0, ty = 0.0;

    double determinant() const { return xx * yy - xy * yx; }
    // Our point that lands on their point p (the map must not be singular).
    dvec2 ourPoint(dvec2 p) const;
    // Where the map takes the point p of ours.
    dvec2 theirPoint(dvec2 p) const { return {xx * p.x + xy * p.y + tx, yx * p.x + yy * p.y + ty}; }
    bool operator==(const ScreenMap&) const = default;
};

// 1 where a pixel is drawn, 0 elsewhere.
using Coverage = Image<std::uint8_t>;

struct ScreenMapFit {
    ScreenMap map;
    std::size_t apartBefore = 0;  // pixels covered by one side only, ours as it is
    std::size_t apartAfter = 0;   // the same with ours carried by the map
};

// The map that best carries our coverage onto theirs (the same size); none when either
// covers fewer than 16 pixels.
std::optional<ScreenMapFit> fitScreenMap(const Coverage& ours, const Coverage& theirs);

// The pixels covered by one side only, with ours carried by the map.
std::size_t pixelsApart(const Coverage& ours, const Coverage& theirs, const ScreenMap& map);

// Our image carried by the map: each of its pixels takes the colour of ours whose centre it
// comes from (the nearest pixel), `fill` where that is outside ours.
Rgba8Image mappedImage(const Rgba8Image& image, const ScreenMap& map,
                       const std::array<std::uint8_t, 4>& fill);

// Their image carried back onto ours: each of our pixels takes their pixel where the map puts
// its centre, zero bytes where that is outside theirs.
Rgba8Image carriedBack(const Rgba8Image& theirs, const ScreenMap& map);

// A map that is one of the image's plain moves within a pixel: the identity, a mirror in x,
// in y or both, with or without a shift of at most a pixel (compare names these apart).
bool isPlainMove(const ScreenMap& map, int width, int height);

}  // namespace rl
