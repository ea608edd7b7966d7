#include "app/check/stage_frame.h"

#include <algorithm>
#include <cmath>

namespace rasterlab::check {

using rl::dvec3;

namespace {

const Mistakes& of(const std::map<Stage, Mistakes>& applied, Stage stage) {
    static const Mistakes none;
    const auto it = applied.find(stage);
    return it == applied.end() ? none : it->second;
}

// Screen barycentrics of the sample (x, y) in the triangle t of the screen rows.
std::array<double, 3> weights(const std::vector<Row>& screen, const std::array<std::uint32_t, 3>& t,
                              double x, double y) {
    const Row &a = screen[t[0]], &b = screen[t[1]], &c = screen[t[2]];
    const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    const double beta = ((x - a[0]) * (c[1] - a[1]) - (y - a[1]) * (c[0] - a[0])) / area;
    const double gamma = ((b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])) / area;
    return {1.0 - beta - gamma, beta, gamma};
}

// A channel as the frame's byte: clamped (or wrapped, when the lighting left out the clamp)
// and truncated.
std::uint8_t byteOf(double v, bool wrap) {
    if (!std::isfinite(v)) return 0;
    if (wrap) return std::uint8_t(std::int64_t(std::trunc(std::max(v, 0.0))) & 0xff);
    return std::uint8_t(std::clamp(std::trunc(v), 0.0, 255.0));
}

}  // namespace

rl::Rgba8Image modelFrame(const FrameScene& s, const std::map<Stage, Mistakes>& applied) {
    rl::Rgba8Image image;
    image.width = s.width;
    image.height = s.height;
    image.rgba.assign(std::size_t(s.width) * std::size_t(s.height) * 4, 0);
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;

    const std::vector<Row> basis = basisAnswer(s.n, s.v, of(applied, Stage::Basis));
    const std::array<dvec3, 3> uvn = {vecOf(basis[0]), vecOf(basis[1]), vecOf(basis[2])};
    std::vector<Row> view = viewAnswer(s.c, uvn, s.lightWorld, s.world, of(applied, Stage::View));
    Lighting lighting = s.lighting;
    lighting.light = vecOf(view.front());
    view.erase(view.begin());
    const std::vector<Row> screen =
        projectionAnswer(s.d, s.hx, s.hy, s.width, s.height, view, of(applied, Stage::Projection));
    const std::vector<Row> normals = normalsAnswer(view, s.triangles, screen, of(applied, Stage::Normals));
    const std::size_t m = s.triangles.size();

    std::vector<Row> triangles;
    for (const auto& t : s.triangles)
        triangles.push_back({screen[t[0]][0], screen[t[0]][1], screen[t[1]][0], screen[t[1]][1],
                             screen[t[2]][0], screen[t[2]][1]});
    std::vector<Fragment> fragments;
    for (const Row& span : scanAnswer(triangles, s.width, s.height, of(applied, Stage::Scan))) {
        const auto t = std::uint32_t(span[0]);
        for (double x = span[2]; x <= span[3]; ++x) {
            const auto w = weights(screen, s.triangles[t], x, span[1]);
            double z = 0.0;
            for (std::size_t k = 0; k < 3; ++k) z += w[k] * view[s.triangles[t][k]][2];
            fragments.push_back({t, std::int32_t(x), std::int32_t(span[1]), float(z)});
        }
    }
    const Mistakes& shading = of(applied, Stage::Lighting);
    const bool wrap = std::any_of(shading.begin(), shading.end(),
                                  [](const StageMistake& a) { return a.id == "no-clamp"; });
    for (const Row& kept : zbufferAnswer(fragments, of(applied, Stage::ZBuffer))) {
        const int x = int(kept[0]), y = int(kept[1]);
        if (x < 0 || y < 0 || x >= s.width || y >= s.height) continue;
        const auto& t = s.triangles[std::size_t(kept[2])];
        const auto w = weights(screen, t, x, y);
        dvec3 p(0.0), n(0.0);
        for (std::size_t k = 0; k < 3; ++k) {
            p += w[k] * vecOf(view[t[k]]);
            n += w[k] * vecOf(normals[m + t[k]]);
        }
        const Row colour = lightingAt(lighting, p, n, shading);
        std::uint8_t* px = &image.rgba[(std::size_t(y) * std::size_t(s.width) + std::size_t(x)) * 4];
        for (std::size_t k = 0; k < 3; ++k) px[k] = byteOf(colour[k], wrap);
    }
    return image;
}

}  // namespace rasterlab::check
