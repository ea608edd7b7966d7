#include "pipeline/analysis/screen_map.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace rl {

dvec2 ScreenMap::ourPoint(dvec2 p) const {
    const double det = determinant();
    const double x = p.x - tx, y = p.y - ty;
    return {(yy * x - xy * y) / det, (xx * y - yx * x) / det};
}

namespace {

// The pixel of a width x height image whose square holds point p; none outside the image.
std::optional<ivec2> pixelAt(dvec2 p, int width, int height) {
    const double fx = std::floor(p.x), fy = std::floor(p.y);
    if (!(fx >= 0.0 && fy >= 0.0 && fx < width && fy < height)) return std::nullopt;
    return ivec2(int(fx), int(fy));
}

// A coverage's area, centroid and second moments about the centroid (pixel centres).
struct Moments {
    double count = 0.0;
    dvec2 centre{0.0};
    double cxx = 0.0, cyy = 0.0, cxy = 0.0;
};

Moments momentsOf(const Coverage& c) {
    Moments m;
    double sx = 0.0, sy = 0.0, sxx = 0.0, syy = 0.0, sxy = 0.0;
    for (int y = 0; y < c.height(); ++y)
        for (int x = 0; x < c.width(); ++x) {
            if (!c.at(x, y)) continue;
            const double px = x + 0.5, py = y + 0.5;
            m.count += 1.0;
            sx += px, sy += py, sxx += px * px, syy += py * py, sxy += px * py;
        }
    if (m.count == 0.0) return m;
    m.centre = dvec2(sx, sy) / m.count;
    m.cxx = sxx / m.count - m.centre.x * m.centre.x;
    m.cyy = syy / m.count - m.centre.y * m.centre.y;
    m.cxy = sxy / m.count - m.centre.x * m.centre.y;
    return m;
}

// The principal axes of the second moments: the angle of the first, and the variances along
// the first and the second.
struct Axes {
    double angle = 0.0, first = 0.0, second = 0.0;
};

Axes axesOf(const Moments& m) {
    const double mean = (m.cxx + m.cyy) / 2.0, half = std::hypot((m.cxx - m.cyy) / 2.0, m.cxy);
    return {0.5 * std::atan2(2.0 * m.cxy, m.cxx - m.cyy), mean + half, mean - half};
}

// The six numbers a pattern search moves: the matrix, and the shift of our centroid's image
// from their centroid.
struct Guess {
    double a[4];  // xx, xy, yx, yy
    dvec2 shift{0.0};
    ScreenMap map(const Moments& ours, const Moments& theirs) const {
        ScreenMap m{a[0], a[1], a[2], a[3], 0.0, 0.0};
        const dvec2 t = theirs.centre + shift - m.theirPoint(ours.centre);
        m.tx = t.x;
        m.ty = t.y;
        return m;
    }
};

// The first guesses: the axes kept, swapped, or turned onto the principal axes, each with
// either sign, scaled so that the second moments agree.
std::vector<Guess> firstGuesses(const Moments& o, const Moments& t) {
    std::vector<Guess> out;
    const auto ratio = [](double a, double b) { return b > 1e-9 ? std::sqrt(a / b) : 0.0; };
    const double sx = ratio(t.cxx, o.cxx), sy = ratio(t.cyy, o.cyy);
    const double ax = ratio(t.cxx, o.cyy), ay = ratio(t.cyy, o.cxx);
    const Axes ao = axesOf(o), at = axesOf(t);
    for (double fx : {1.0, -1.0}) {
        for (double fy : {1.0, -1.0}) {
            if (sx > 0.0 && sy > 0.0) out.push_back({{fx * sx, 0.0, 0.0, fy * sy}});
            if (ax > 0.0 && ay > 0.0) out.push_back({{0.0, fx * ax, fy * ay, 0.0}});
            // R(theirs) diag(f1 s1, f2 s2) R(-ours), each pairing of the axes.
            for (bool crossed : {false, true}) {
                const double s1 = ratio(crossed ? at.second : at.first, ao.first),
                             s2 = ratio(crossed ? at.first : at.second, ao.second);
                if (!(s1 > 0.0 && s2 > 0.0)) continue;
                const double angle = at.angle + (crossed ? std::numbers::pi / 2.0 : 0.0);
                const double ct = std::cos(angle), st = std::sin(angle), co = std::cos(ao.angle),
                             so = std::sin(ao.angle);
                const double d1 = fx * s1, d2 = fy * s2;
                // [ct -st; st ct] [d1 0; 0 d2] [co so; -so co]
                out.push_back({{ct * d1 * co + st * d2 * so, ct * d1 * so - st * d2 * co,
                                st * d1 * co - ct * d2 * so, st * d1 * so + ct * d2 * co}});
            }
        }
    }
    return out;
}

// The bounding box of a coverage, [x0, x1) x [y0, y1); empty when it covers nothing.
struct Box {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

Box boxOf(const Coverage& c) {
    Box b{c.width(), c.height(), 0, 0};
    for (int y = 0; y < c.height(); ++y)
        for (int x = 0; x < c.width(); ++x)
            if (c.at(x, y)) {
                b.x0 = std::min(b.x0, x), b.x1 = std::max(b.x1, x + 1);
                b.y0 = std::min(b.y0, y), b.y1 = std::max(b.y1, y + 1);
            }
    return b;
}

// Their pixels where ours carried by the map may cover: our box's corners mapped, with a
// pixel's margin, inside the image.
Box mappedBox(const Box& b, const ScreenMap& map, int width, int height) {
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (double x : {double(b.x0), double(b.x1)})
        for (double y : {double(b.y0), double(b.y1)}) {
            const dvec2 p = map.theirPoint({x, y});
            x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
            y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
        }
    const auto clampTo = [](double v, int limit) {
        return static_cast<int>(std::clamp(v, 0.0, double(limit)));
    };
    return {clampTo(std::floor(x0) - 1, width), clampTo(std::floor(y0) - 1, height),
            clampTo(std::ceil(x1) + 1, width), clampTo(std::ceil(y1) + 1, height)};
}

// Whether our pixel whose centre lands on their pixel (x, y)'s is covered.
bool coveredAt(const Coverage& ours, const ScreenMap& map, int x, int y) {
    const auto q = pixelAt(map.ourPoint({x + 0.5, y + 0.5}), ours.width(), ours.height());
    return q && ours.at(q->x, q->y) != 0;
}

// The two coverages at one level of detail: blocks of `block` x `block` pixels, a block
// covered when half its pixels are; the pixels apart counted only where either side may
// cover (their box and ours mapped), in the level's blocks.
class Level {
public:
    Level(const Coverage& ours, const Coverage& theirs, int block)
        : m_block(block), m_ours(reduced(ours, block)), m_theirs(reduced(theirs, block)) {
        m_ourBox = boxOf(m_ours);
        m_theirBox = boxOf(m_theirs);
        m_theirCount =
            std::size_t(std::count(m_theirs.pixels().begin(), m_theirs.pixels().end(), 1));
    }

    // The map is in whole pixels; in blocks its shift is divided by the block's size.
    std::size_t apart(ScreenMap map) const {
        if (!(std::abs(map.determinant()) > 1e-9)) return std::size_t(-1);
        map.tx /= m_block, map.ty /= m_block;
        const Box m = mappedBox(m_ourBox, map, m_theirs.width(), m_theirs.height());
        const Box u{std::min(m.x0, m_theirBox.x0), std::min(m.y0, m_theirBox.y0),
                    std::max(m.x1, m_theirBox.x1), std::max(m.y1, m_theirBox.y1)};
        std::size_t apart = 0, theirsSeen = 0;
        for (int y = u.y0; y < u.y1; ++y)
            for (int x = u.x0; x < u.x1; ++x) {
                const bool t = m_theirs.at(x, y) != 0;
                theirsSeen += t ? 1 : 0;
                apart += t != coveredAt(m_ours, map, x, y) ? 1 : 0;
            }
        return apart + (m_theirCount - theirsSeen);
    }

private:
    static Coverage reduced(const Coverage& c, int block) {
        if (block == 1) return c;
        Coverage out((c.width() + block - 1) / block, (c.height() + block - 1) / block);
        for (int y = 0; y < out.height(); ++y)
            for (int x = 0; x < out.width(); ++x) {
                int covered = 0, all = 0;
                for (int v = y * block; v < std::min(c.height(), (y + 1) * block); ++v)
                    for (int u = x * block; u < std::min(c.width(), (x + 1) * block); ++u)
                        covered += c.at(u, v), ++all;
                out.at(x, y) = covered * 2 >= all ? 1 : 0;
            }
        return out;
    }

    int m_block;
    Coverage m_ours, m_theirs;
    Box m_ourBox, m_theirBox;
    std::size_t m_theirCount = 0;
};

// A pattern search: each number (the matrix's too when `matrix`) moved up and down by its
// step, a move kept when it leaves fewer pixels apart; the steps halved when no move helps.
// `pixel`: the size of the pixels counted, which sets the steps and where they stop.
template <typename Apart>
void refine(Guess& best, std::size_t& least, bool matrix, double pixel, const Apart& apart) {
    const double scale = std::sqrt(std::abs(best.a[0] * best.a[3] - best.a[1] * best.a[2]));
    double matrixStep = 0.05 * scale, shiftStep = 2.0 * pixel;
    for (int evaluations = 0;
         evaluations < 3000 && (matrixStep > 1e-4 * scale * pixel || shiftStep > 0.02 * pixel);) {
        bool moved = false;
        for (int k = matrix ? 0 : 4; k < 6; ++k) {
            for (double sign : {1.0, -1.0}) {
                Guess g = best;
                double& value = k < 4 ? g.a[k] : (k == 4 ? g.shift.x : g.shift.y);
                value += sign * (k < 4 ? matrixStep : shiftStep);
                const std::size_t a = apart(g);
                ++evaluations;
                if (a < least) {
                    best = g, least = a, moved = true;
                    break;
                }
            }
        }
        if (!moved) matrixStep /= 2.0, shiftStep /= 2.0;
    }
}

}  // namespace

std::size_t pixelsApart(const Coverage& ours, const Coverage& theirs, const ScreenMap& map) {
    if (!(std::abs(map.determinant()) > 1e-12))
        return std::size_t(std::count(theirs.pixels().begin(), theirs.pixels().end(), 1));
    std::size_t apart = 0;
    for (int y = 0; y < theirs.height(); ++y)
        for (int x = 0; x < theirs.width(); ++x)
            apart += (theirs.at(x, y) != 0) != coveredAt(ours, map, x, y) ? 1 : 0;
    return apart;
}

std::optional<ScreenMapFit> fitScreenMap(const Coverage& ours, const Coverage& theirs) {
    const Moments o = momentsOf(ours), t = momentsOf(theirs);
    if (o.count < 16.0 || t.count < 16.0) return std::nullopt;
    // Each first guess refined on coverages about 80x60 (blocks of `block` pixels, where the
    // pixels apart change smoothly with the numbers), the three best again on the whole.
    const int block = std::max(
        1, static_cast<int>(std::lround(std::sqrt(double(ours.width()) * ours.height() / 5000.0))));
    const Level fine(ours, theirs, 1), coarse(ours, theirs, block);
    const auto apartOn = [&](const Level& level) {
        return [&](const Guess& g) { return level.apart(g.map(o, t)); };
    };
    std::vector<std::pair<std::size_t, Guess>> refined;
    for (Guess g : firstGuesses(o, t)) {
        std::size_t a = coarse.apart(g.map(o, t));
        refine(g, a, true, double(block), apartOn(coarse));
        refined.emplace_back(a, g);
    }
    if (refined.empty()) return std::nullopt;
    std::sort(refined.begin(), refined.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    refined.resize(std::min<std::size_t>(refined.size(), 3));
    std::optional<Guess> best;
    std::size_t least = 0;
    for (auto& [unused, g] : refined) {
        std::size_t a = fine.apart(g.map(o, t));
        refine(g, a, true, 1.0, apartOn(fine));
        if (!best || a < least) best = g, least = a;
    }
    // Simpler numbers where they fit as well: each entry of the matrix tried at 0, +-1 and
    // +-the ratios of the image's sides (one size used for both axes), the shift searched
    // again, kept when at most a tenth more pixels (and 8) are apart: about what the nearest
    // pixel's sampling along the edges makes of a map that is right.
    const double wide = double(ours.width()) / ours.height();
    for (int k = 0; k < 4; ++k) {
        for (double nice : {0.0, 1.0, -1.0, wide, -wide, 1.0 / wide, -1.0 / wide}) {
            if (best->a[k] == nice ||
                std::abs(best->a[k] - nice) > 0.03 * std::max(1.0, std::abs(nice)))
                continue;
            Guess g = *best;
            g.a[k] = nice;
            std::size_t a = fine.apart(g.map(o, t));
            refine(g, a, false, 1.0, apartOn(fine));
            if (a <= least + std::max<std::size_t>(8, least / 10)) {
                best = g, least = a;
                break;
            }
        }
    }
    ScreenMapFit fit;
    fit.map = best->map(o, t);
    fit.apartBefore = pixelsApart(ours, theirs, ScreenMap{});
    fit.apartAfter = least;
    return fit;
}

Rgba8Image carriedBack(const Rgba8Image& theirs, const ScreenMap& map) {
    Rgba8Image out = theirs;
    for (int y = 0; y < theirs.height; ++y) {
        for (int x = 0; x < theirs.width; ++x) {
            const auto p = pixelAt(map.theirPoint({x + 0.5, y + 0.5}), theirs.width, theirs.height);
            const std::uint8_t none[4] = {0, 0, 0, 0};
            const std::uint8_t* from = p ? theirs.pixel(p->x, p->y) : none;
            std::copy(from, from + 4, out.rgba.data() + (std::size_t(y) * theirs.width + x) * 4);
        }
    }
    return out;
}

Rgba8Image mappedImage(const Rgba8Image& image, const ScreenMap& map,
                       const std::array<std::uint8_t, 4>& fill) {
    Rgba8Image out = image;
    const bool invertible = std::abs(map.determinant()) > 1e-12;
    // Our point of each pixel's centre, stepped along the row: one pixel right adds the
    // inverse's first column.
    const dvec2 step =
        invertible ? map.ourPoint({1.0, 0.0}) - map.ourPoint({0.0, 0.0}) : dvec2(0.0);
    for (int y = 0; y < image.height; ++y) {
        dvec2 q = invertible ? map.ourPoint({0.5, y + 0.5}) : dvec2(-1.0);
        std::uint8_t* to = out.rgba.data() + std::size_t(y) * image.width * 4;
        for (int x = 0; x < image.width; ++x, q += step, to += 4) {
            const auto p = pixelAt(q, image.width, image.height);
            const std::uint8_t* from = p ? image.pixel(p->x, p->y) : fill.data();
            std::copy(from, from + 4, to);
        }
    }
    return out;
}

bool isPlainMove(const ScreenMap& map, int width, int height) {
    // Within a pixel and a half of a plain move at every corner of the image (a mirror in x
    // takes x to width - x, in y y to height - y).
    for (double fx : {1.0, -1.0}) {
        for (double fy : {1.0, -1.0}) {
            const ScreenMap plain{
                fx, 0.0, 0.0, fy, fx < 0.0 ? double(width) : 0.0, fy < 0.0 ? double(height) : 0.0};
            bool near = true;
            for (double x : {0.0, double(width)})
                for (double y : {0.0, double(height)})
                    near = near &&
                           glm::length(map.theirPoint({x, y}) - plain.theirPoint({x, y})) <= 1.5;
            if (near) return true;
        }
    }
    return false;
}

}  // namespace rl
