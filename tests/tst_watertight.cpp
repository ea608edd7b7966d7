// Watertightness, the property behind the GPU-like rules: 100,000 random triangle fans and
// meshes, snapped to the 1/256-pixel grid and scan converted under RasterRules::gpu(). Every
// pixel centre inside a fan's outline (or a mesh's) is covered exactly once: no cracks, no
// double hits, shared edges and shared vertices included. The course rules on the same cases
// (vertices truncated to whole pixels, inclusive edges) are counted, not failed: their double
// hits are the lesson.
#include <QtTest>

#include <random>

#include "pipeline/stages/scan_conversion.h"
#include "tests/test_support.h"

using namespace rl;

namespace {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

// A shape: points, triangles, and which triangle edges lie on its outline.
struct Shape {
    std::vector<dvec2> points;
    Triangles triangles;
    std::vector<std::array<std::uint32_t, 2>> outline;  // edges no other triangle shares
};

constexpr int kSize = 48;  // the screen the shapes are drawn on

// Twice the signed area of (a, b, s), exactly: all coordinates are multiples of 1/256 below
// 2^12, so every product is an exact double.
double edge(const dvec2& a, const dvec2& b, const dvec2& s) {
    return (b.x - a.x) * (s.y - a.y) - (b.y - a.y) * (s.x - a.x);
}

bool insideClosed(const dvec2& a, const dvec2& b, const dvec2& c, const dvec2& s) {
    const double area = edge(a, b, c);
    if (area == 0.0) return false;
    const double w0 = edge(b, c, s), w1 = edge(c, a, s), w2 = edge(a, b, s);
    return area > 0 ? (w0 >= 0 && w1 >= 0 && w2 >= 0) : (w0 <= 0 && w1 <= 0 && w2 <= 0);
}

bool onSegment(const dvec2& a, const dvec2& b, const dvec2& s) {
    return edge(a, b, s) == 0.0 && s.x >= std::min(a.x, b.x) && s.x <= std::max(a.x, b.x) &&
           s.y >= std::min(a.y, b.y) && s.y <= std::max(a.y, b.y);
}

double snapTo(double v, double grid) {
    return std::floor(v * grid + 0.5) / grid;
}

// A fan of 3 to 12 triangles around a centre, the spokes less than half a turn apart.
Shape randomFan(std::mt19937& rng, double grid) {
    std::uniform_int_distribution<int> spokes(3, 12);
    std::uniform_real_distribution<double> jitter(0.0, 0.4), radius(1.0, 16.0),
        centre(4.0, kSize - 4.0), unit(0.0, 1.0);
    Shape s;
    const int n = spokes(rng);
    const double turn = unit(rng);
    s.points.push_back({snapTo(centre(rng), grid), snapTo(centre(rng), grid)});
    for (int k = 0; k < n; ++k) {
        const double a = 6.283185307179586 * ((double(k) + jitter(rng)) / n + turn);
        const double r = radius(rng);
        s.points.push_back({snapTo(s.points[0].x + r * std::cos(a), grid),
                            snapTo(s.points[0].y + r * std::sin(a), grid)});
    }
    for (int k = 1; k <= n; ++k) {
        const auto b = static_cast<std::uint32_t>(k), c = static_cast<std::uint32_t>(k % n + 1);
        s.triangles.push_back({0, b, c});
        s.outline.push_back({b, c});
    }
    return s;
}

// A grid of jittered points, each cell split along a random diagonal.
Shape randomMesh(std::mt19937& rng, double grid) {
    std::uniform_int_distribution<int> cells(2, 6), coin(0, 1);
    std::uniform_real_distribution<double> step(3.0, 7.0), jitter(-0.2, 0.2), origin(0.0, 8.0);
    Shape s;
    const int nx = cells(rng), ny = cells(rng);
    const double h = step(rng), x0 = origin(rng), y0 = origin(rng);
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            const bool border = i == 0 || j == 0 || i == nx || j == ny;
            const double jx = border ? 0.0 : jitter(rng) * h, jy = border ? 0.0 : jitter(rng) * h;
            s.points.push_back({snapTo(x0 + i * h + jx, grid), snapTo(y0 + j * h + jy, grid)});
        }
    const auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (nx + 1) + i); };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1),
                                d = at(i, j + 1);
            if (coin(rng)) {
                s.triangles.push_back({a, b, c});
                s.triangles.push_back({a, c, d});
            } else {
                s.triangles.push_back({a, b, d});
                s.triangles.push_back({b, c, d});
            }
        }
    for (int i = 0; i < nx; ++i) {
        s.outline.push_back({at(i, 0), at(i + 1, 0)});
        s.outline.push_back({at(i, ny), at(i + 1, ny)});
    }
    for (int j = 0; j < ny; ++j) {
        s.outline.push_back({at(0, j), at(0, j + 1)});
        s.outline.push_back({at(nx, j), at(nx, j + 1)});
    }
    return s;
}

struct Tally {
    long long inside = 0;      // pixel centres strictly inside an outline
    long long cracks = 0;      // of those, covered by no triangle
    long long doubleHits = 0;  // coverings beyond the first, anywhere
    long long outside = 0;     // pixels covered whose centre is outside every triangle
};

// The pixels whose centres may lie in the closed box of the given points.
template <typename Visit>
void forCentresNear(std::initializer_list<dvec2> points, double offset, const Visit& visit) {
    double lx = 1e300, ly = 1e300, hx = -1e300, hy = -1e300;
    for (const dvec2& p : points) {
        lx = std::min(lx, p.x);
        ly = std::min(ly, p.y);
        hx = std::max(hx, p.x);
        hy = std::max(hy, p.y);
    }
    const int x0 = std::max(0, int(std::ceil(lx - offset))),
              x1 = std::min(kSize - 1, int(std::floor(hx - offset)));
    const int y0 = std::max(0, int(std::ceil(ly - offset))),
              y1 = std::min(kSize - 1, int(std::floor(hy - offset)));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) visit(x, y, dvec2(x + offset, y + offset));
}

// Scan converts the shape under the rules and counts, over the screen, how each pixel centre
// is covered against where it lies (inside a triangle, on the outline).
void check(const Shape& shape, const RasterRules& rules, Tally& tally) {
    Scene scene = testing::screen(kSize, kSize);
    scene.rules = rules;
    const ScanConversion scan =
        ScanConversionStage().run({scene, testing::screenTriangles(shape.points, shape.triangles)});
    std::vector<int> hits(kSize * kSize, 0);
    for (const Span& span : scan.spans)
        for (int x = span.xBegin; x < span.xEnd; ++x) ++hits[std::size_t(span.y * kSize + x)];
    std::vector<std::uint8_t> in(kSize * kSize, 0), onOutline(kSize * kSize, 0);
    const double offset = rules.sampleOffset;
    for (const auto& t : shape.triangles) {
        const dvec2 a = shape.points[t[0]], b = shape.points[t[1]], c = shape.points[t[2]];
        forCentresNear({a, b, c}, offset, [&](int x, int y, const dvec2& s) {
            if (insideClosed(a, b, c, s)) in[std::size_t(y * kSize + x)] = 1;
        });
    }
    for (const auto& e : shape.outline) {
        const dvec2 a = shape.points[e[0]], b = shape.points[e[1]];
        forCentresNear({a, b}, offset, [&](int x, int y, const dvec2& s) {
            if (onSegment(a, b, s)) onOutline[std::size_t(y * kSize + x)] = 1;
        });
    }
    for (std::size_t i = 0; i < hits.size(); ++i) {
        const int h = hits[i];
        if (h > 1) tally.doubleHits += h - 1;
        if (!in[i] && h > 0) ++tally.outside;
        if (in[i] && !onOutline[i]) {
            ++tally.inside;
            if (h == 0) ++tally.cracks;
        }
    }
}

// The course's vertices: truncated to whole pixels, as (int) does.
Shape truncated(Shape shape) {
    for (dvec2& p : shape.points) p = glm::trunc(p);
    return shape;
}

}  // namespace

class TestWatertight : public QObject {
    Q_OBJECT

private slots:
    void gpuRulesCoverEachPixelCentreOnce() {
        const RasterRules gpu = RasterRules::gpu();
        const RasterRules course = RasterRules::course();
        const double grid = double(1 << gpu.subpixelBits);
        std::mt19937 rng(2026);
        Tally fans, meshes, courseTally;
        long long shapes = 0, triangles = 0;
        for (int i = 0; i < 100000; ++i) {
            const bool fan = i % 10 != 0;  // 90,000 fans and 10,000 meshes
            const Shape shape = fan ? randomFan(rng, grid) : randomMesh(rng, grid);
            ++shapes;
            triangles += static_cast<long long>(shape.triangles.size());
            check(shape, gpu, fan ? fans : meshes);
            if (fans.cracks + meshes.cracks + fans.doubleHits + meshes.doubleHits + fans.outside +
                    meshes.outside >
                0)
                QFAIL(qPrintable(QStringLiteral("shape %1 (%2): %3 cracks, %4 double hits, "
                                                "%5 pixels outside")
                                     .arg(i)
                                     .arg(fan ? QStringLiteral("fan") : QStringLiteral("mesh"))
                                     .arg(fans.cracks + meshes.cracks)
                                     .arg(fans.doubleHits + meshes.doubleHits)
                                     .arg(fans.outside + meshes.outside)));
            check(truncated(shape), course, courseTally);
        }
        QCOMPARE(shapes, 100000LL);
        // The shapes are not trivially small: millions of pixel centres are checked.
        QVERIFY(fans.inside > 5'000'000);
        QVERIFY(meshes.inside > 500'000);
        qInfo(
            "gpu rules: %lld shapes, %lld triangles, %lld pixel centres inside, 0 cracks, "
            "0 double hits",
            shapes, triangles, fans.inside + meshes.inside);
        qInfo(
            "course rules on the same shapes (vertices truncated): %lld centres inside, %lld "
            "cracks, %lld double hits, %lld pixels covered outside every triangle",
            courseTally.inside, courseTally.cracks, courseTally.doubleHits, courseTally.outside);
        // The inclusive rule never leaves a crack, but covers shared edges twice.
        QCOMPARE(courseTally.cracks, 0LL);
        QVERIFY(courseTally.doubleHits > 100'000);
    }
};

QTEST_GUILESS_MAIN(TestWatertight)
#include "tst_watertight.moc"
