// The fast paths' kernels against the stage functions they must equal, bit for bit, on seeded
// random inputs: the Phong lanes and points against phong(), Gouraud's lanes against
// interpolate(), the span depth test against the stage's pixel loop, runEnd against a scan
// one id at a time, and the depth test and shading in bands against the two stages run one
// after the other on random triangle soups.
#include <QtTest>

#include <cstring>
#include <random>

#include "pipeline/core/multiversion.h"
#include "pipeline/core/parallel.h"
#include "pipeline/fast/depth_test_fast.h"
#include "pipeline/fast/phong_kernel.h"
#include "pipeline/fast/shading_fast.h"
#include "pipeline/render/renderer.h"
#include "pipeline/stages/phong.h"
#include "pipeline/stages/shading.h"
#include "tests/test_support.h"

using namespace rl;

namespace {

// The bits of a value: the comparisons below are exact.
template <typename T>
bool sameBits(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

class Random {
public:
    explicit Random(std::uint32_t seed) : m_engine(seed) {}
    float real(float lo, float hi) {
        return std::uniform_real_distribution<float>(lo, hi)(m_engine);
    }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(m_engine); }
    bool chance(double p) { return std::bernoulli_distribution(p)(m_engine); }
    vec3 vector(float lo, float hi) { return vec3(real(lo, hi), real(lo, hi), real(lo, hi)); }

private:
    std::mt19937 m_engine;
};

// A material and one plain light, at random; sometimes no highlight (ks = 0), a shininess
// below 1, a directional light, a light 1e25 away, or the light on the far side.
struct LitSetup {
    Material material;
    ViewLight light;
    vec3 ambient;
    bool flip = true;
};

LitSetup randomSetup(Random& r) {
    LitSetup s;
    s.material.ka = r.real(0.0f, 1.0f);
    s.material.kd = r.vector(0.0f, 1.0f);
    s.material.od = r.vector(0.0f, 1.0f);
    s.material.ks = r.chance(0.2) ? 0.0f : r.real(0.0f, 1.0f);
    s.material.shininess = r.chance(0.2) ? r.real(0.1f, 1.0f) : r.real(1.0f, 120.0f);
    s.ambient = r.vector(0.0f, 80.0f);
    s.light.intensity = r.vector(0.0f, 300.0f);
    s.light.pView = r.chance(0.3) ? dvec4(dvec3(r.vector(-1.0f, 1.0f)), 0.0)
                                  : dvec4(dvec3(r.vector(-200.0f, 200.0f)), 1.0);
    // Sometimes so far that the square of its distance overflows float (towardLight).
    if (r.chance(0.1)) s.light.pView = dvec4(dvec3(r.vector(-1.0f, 1.0f)) * 1e25, 1.0);
    s.flip = r.chance(0.7);
    return s;
}

// A normal, sometimes zero (a vertex of degenerate triangles only).
vec3 randomNormal(Random& r) {
    return r.chance(0.05) ? vec3(0.0f) : r.vector(-1.0f, 1.0f);
}

}  // namespace

class TestKernels : public QObject {
    Q_OBJECT

private slots:
    // Every test at both kernel widths: eight lanes, and the baseline's four.
    void initTestCase_data() { testing::kernelLaneRows(); }
    void init() { testing::useKernelLanesOfRow(); }
    void cleanupTestCase() { rl::setKernelLanes(0); }

    void phongLanesEqualPhong() {
        // shadeCoursePhongRun (fast/phong_kernel.h) against phong() (stages/phong.h) at the
        // same interpolated point and normal, for runs of 1 to 40 pixels (whole groups of
        // lanes and the rest).
        Random r(2024);
        std::size_t pixels = 0;
        for (int trial = 0; trial < 400; ++trial) {
            const LitSetup s = randomSetup(r);
            const std::array<vec3, 3> p = {r.vector(-50.0f, 50.0f), r.vector(-50.0f, 50.0f),
                                           r.vector(-50.0f, 50.0f)};
            const std::array<vec3, 3> n = {randomNormal(r), randomNormal(r), randomNormal(r)};
            CoursePhongRun run = coursePhongRun(s.material, s.light, s.ambient, s.flip);
            run.p0 = p[0];
            run.dp1 = p[1] - p[0];
            run.dp2 = p[2] - p[0];
            run.n0 = n[0];
            run.dn1 = n[1] - n[0];
            run.dn2 = n[2] - n[0];
            const int count = r.integer(1, 40);
            std::vector<vec2> bary;
            for (int i = 0; i < count; ++i)
                bary.emplace_back(r.real(-0.1f, 1.0f), r.real(-0.1f, 1.0f));
            std::vector<vec3> colour(static_cast<std::size_t>(count)), normal(static_cast<std::size_t>(count));
            CoursePhongCounts counts;
            shadeCoursePhongRun(run, bary.data(), count, colour.data(), normal.data(), 255.0f,
                                counts);
            CoursePhongCounts expected;
            for (int i = 0; i < count; ++i) {
                const std::array<std::uint32_t, 3> v = {0, 1, 2};
                const float beta = bary[std::size_t(i)].x, gamma = bary[std::size_t(i)].y;
                const PhongSample ref =
                    phong(s.material, s.material.od, s.ambient, &s.light, 1,
                          interpolate(p, v, beta, gamma), interpolate(n, v, beta, gamma), s.flip);
                const vec3 c = ref.colour();
                QVERIFY2(sameBits(colour[std::size_t(i)], c),
                         qPrintable(QStringLiteral("trial %1 pixel %2").arg(trial).arg(i)));
                QVERIFY(sameBits(normal[std::size_t(i)], ref.n));
                expected.flipped += ref.flipped ? 1 : 0;
                expected.lightBehind += ref.lightBehind ? 1 : 0;
                expected.noSpecular += ref.noSpecular ? 1 : 0;
                expected.noNormal += ref.noNormal ? 1 : 0;
                expected.clamped += c.r > 255.0f || c.g > 255.0f || c.b > 255.0f ? 1 : 0;
            }
            QCOMPARE(counts.flipped, expected.flipped);
            QCOMPARE(counts.lightBehind, expected.lightBehind);
            QCOMPARE(counts.noSpecular, expected.noSpecular);
            QCOMPARE(counts.noNormal, expected.noNormal);
            QCOMPARE(counts.clamped, expected.clamped);
            pixels += std::size_t(count);
        }
        QVERIFY(pixels > 5000);
    }

    void phongPointsEqualPhong() {
        // shadeCoursePhongPoints: every point, or those listed, lit as phong() lights it.
        Random r(7);
        for (int trial = 0; trial < 200; ++trial) {
            const LitSetup s = randomSetup(r);
            const CoursePhongRun run = coursePhongRun(s.material, s.light, s.ambient, s.flip);
            const int count = r.integer(1, 50);
            std::vector<vec3> p, n;
            for (int i = 0; i < count; ++i) {
                p.push_back(r.vector(-50.0f, 50.0f));
                n.push_back(randomNormal(r));
            }
            std::vector<std::uint32_t> at;
            for (int i = 0; i < count; ++i)
                if (r.chance(0.6)) at.push_back(std::uint32_t(i));
            const bool listed = r.chance(0.5);
            std::vector<vec3> colour(std::size_t(count), vec3(-1.0f)), normal(colour);
            CoursePhongCounts counts;
            shadeCoursePhongPoints(run, p.data(), n.data(), listed ? at.data() : nullptr,
                                   listed ? at.size() : std::size_t(count), colour.data(),
                                   normal.data(), counts);
            std::size_t lit = 0;
            for (int i = 0; i < count; ++i) {
                const bool wanted =
                    !listed || std::find(at.begin(), at.end(), std::uint32_t(i)) != at.end();
                if (!wanted) {
                    QVERIFY(colour[std::size_t(i)] == vec3(-1.0f));  // left alone
                    continue;
                }
                ++lit;
                const PhongSample ref = phong(s.material, s.material.od, s.ambient, &s.light, 1,
                                              p[std::size_t(i)], n[std::size_t(i)], s.flip);
                QVERIFY(sameBits(colour[std::size_t(i)], ref.colour()));
                QVERIFY(sameBits(normal[std::size_t(i)], ref.n));
            }
            QVERIFY(lit > 0 || (listed && at.empty()));
        }
    }

    void gouraudLanesEqualInterpolate() {
        // shadeGouraudRun against interpolate(), the stage's c0 + beta (c1 - c0) + gamma
        // (c2 - c0), with colours above the scale counted.
        Random r(11);
        for (int trial = 0; trial < 300; ++trial) {
            const std::array<vec3, 3> c = {r.vector(0.0f, 400.0f), r.vector(0.0f, 400.0f),
                                           r.vector(0.0f, 400.0f)};
            const int count = r.integer(1, 40);
            std::vector<vec2> bary;
            for (int i = 0; i < count; ++i)
                bary.emplace_back(r.real(0.0f, 1.0f), r.real(0.0f, 1.0f));
            std::vector<vec3> colour(static_cast<std::size_t>(count));
            const std::size_t clamped = shadeGouraudRun(c[0], c[1] - c[0], c[2] - c[0], bary.data(),
                                                        count, colour.data(), 255.0f);
            std::size_t expected = 0;
            for (int i = 0; i < count; ++i) {
                const vec3 ref = interpolate(c, std::array<std::uint32_t, 3>{0, 1, 2},
                                             bary[std::size_t(i)].x, bary[std::size_t(i)].y);
                QVERIFY(sameBits(colour[std::size_t(i)], ref));
                expected += ref.r > 255.0f || ref.g > 255.0f || ref.b > 255.0f ? 1 : 0;
            }
            QCOMPARE(clamped, expected);
        }
    }

    void spanDepthTestEqualsPixelLoop() {
        // fast::testSpan (eight or four pixels a lane group) against testSpanPixels (the stage's
        // loop) on random triangles and spans, over rows holding random depths, some of them the
        // very depths the span computes (ties), under both tie rules, with and without
        // barycentrics, painted or tested, with and without the depth range clip.
        Random r(99);
        constexpr int kWidth = 80;
        for (int trial = 0; trial < 600; ++trial) {
            Scene scene;
            scene.width = kWidth;
            scene.height = 4;
            scene.conventions.depthWinsOnTie = r.chance(0.5);
            scene.conventions.depthRangeClip = r.chance(0.25);
            scene.rules.sampleOffset = r.chance(0.5) ? 0.5 : 0.0;
            Projection projection;
            projection.draws.resize(1);
            DrawProjection& draw = projection.draws[0];
            for (int k = 0; k < 3; ++k) {
                draw.pScreen.push_back(dvec2(r.real(-20.0f, 100.0f), r.real(-20.0f, 24.0f)));
                draw.depth.push_back(r.real(0.05f, 1.5f));
            }
            projection.triangles.push_back(ScreenTriangle{0, 0, {0, 1, 2}});
            const TrianglePlane plane(projection, 0, r.chance(0.3));
            if (!(std::abs(plane.area) > 1e-3)) continue;
            const int xBegin = r.integer(0, kWidth - 1);
            const Span span{r.integer(0, 3), xBegin, r.integer(xBegin, kWidth)};
            const bool painted = r.chance(0.1);
            const bool withBary = r.chance(0.7);
            std::vector<float> depth(kWidth);
            std::vector<std::uint32_t> ids(kWidth);
            std::vector<vec2> bary(kWidth);
            double beta0 = 0.0, gamma0 = 0.0;
            plane.spanStart(span.xBegin, span.y, scene.rules.sampleOffset, beta0, gamma0);
            for (int x = 0; x < kWidth; ++x) {
                const bool tie = x >= span.xBegin && x < span.xEnd && r.chance(0.3);
                depth[std::size_t(x)] =
                    tie ? plane.fragment(beta0, gamma0, x - span.xBegin).depth : r.real(0.0f, 1.6f);
                ids[std::size_t(x)] = std::uint32_t(r.integer(0, 5));
                bary[std::size_t(x)] = vec2(r.real(0.0f, 1.0f), r.real(0.0f, 1.0f));
            }
            auto depthA = depth, depthB = depth;
            auto idsA = ids, idsB = ids;
            auto baryA = bary, baryB = bary;
            DepthCounts a, b;
            NullProbe none;
            testSpanPixels(scene, plane, 9, span,
                           DepthRows{depthA.data(), idsA.data(), withBary ? baryA.data() : nullptr},
                           painted, a, none);
            fast::testSpan(scene, plane, 9, span,
                           DepthRows{depthB.data(), idsB.data(), withBary ? baryB.data() : nullptr},
                           painted, b);
            QVERIFY2(std::memcmp(depthA.data(), depthB.data(), sizeof(float) * kWidth) == 0,
                     qPrintable(QStringLiteral("trial %1: depths").arg(trial)));
            QVERIFY2(idsA == idsB, qPrintable(QStringLiteral("trial %1: ids").arg(trial)));
            QVERIFY2(std::memcmp(baryA.data(), baryB.data(), sizeof(vec2) * kWidth) == 0,
                     qPrintable(QStringLiteral("trial %1: barycentrics").arg(trial)));
            QCOMPARE(b.fragments, a.fragments);
            QCOMPARE(b.passed, a.passed);
            QCOMPARE(b.outsideDepthRange, a.outsideDepthRange);
        }
    }

    void runEndEqualsAScan() {
        // fast::runEnd against a scan one id at a time, on random rows of few ids (long runs).
        Random r(5);
        for (int trial = 0; trial < 2000; ++trial) {
            const int length = r.integer(1, 200);
            std::vector<std::uint32_t> ids(std::size_t(length) + 32);
            std::uint32_t id = 0;
            for (auto& v : ids) {
                if (r.chance(0.08))
                    id = r.chance(0.3) ? kNoTriangle : std::uint32_t(r.integer(0, 3));
                v = id;
            }
            const int from = r.integer(0, length - 1), limit = r.integer(from, length);
            const std::uint32_t t = ids[std::size_t(from)];
            int expected = from + 1;
            while (expected < limit && ids[std::size_t(expected)] == t) ++expected;
            QCOMPARE(fast::runEnd(ids.data(), from + 1, limit, t), std::max(expected, from + 1));
        }
    }

    void cacheDescriptionsRead() {
        // sysfs' shared_cpu_list and size (l2CachePerThread); anything else is not known.
        QCOMPARE(processorsInList("0"), 1);
        QCOMPARE(processorsInList("0-1"), 2);
        QCOMPARE(processorsInList("0-1,4"), 3);
        QCOMPARE(processorsInList("0,2,4-7"), 6);
        for (const char* bad : {"", "3-1", "0;1", "0 1", "0-", "0,", "-1", "a", "0-99999999"})
            QVERIFY2(processorsInList(bad) == 0, bad);
        QCOMPARE(cacheBytes("512K"), std::size_t(512 * 1024));
        QCOMPARE(cacheBytes("1M"), std::size_t(1 << 20));
        QCOMPARE(cacheBytes("65536"), std::size_t(65536));
        for (const char* bad : {"", "K", "-512K", "512KB", "512 K", "1G", "99999999999999M"})
            QVERIFY2(cacheBytes(bad) == 0, bad);
        // Two threads have the L2 of one each, or half of it where they share one core's.
        const std::size_t one = l2CachePerThread(1), two = l2CachePerThread(2);
        QVERIFY(two == one || two == one / 2);
    }

    void bandShadingEqualsTheStages() {
        // The depth test and shading in bands (fast::depthTestAndShading) against the two
        // stages one after the other, on random soups of triangles in front of the axis camera
        // (overlapping, crossing, some edge-on), in every shading model, on 1 to 3 threads,
        // in bands of 8, 4, 3 and 1 rows, 120 and 117 rows high (the last chunk of 5 rows).
        Random r(31);
        for (int trial = 0; trial < 24; ++trial) {
            std::vector<dvec3> positions;
            std::vector<std::array<std::uint32_t, 3>> triangles;
            const int count = r.integer(5, 120);
            for (int t = 0; t < count; ++t) {
                const dvec3 centre(r.real(-3.0f, 3.0f), r.real(-2.0f, 2.0f), r.real(4.0f, 12.0f));
                for (int k = 0; k < 3; ++k)
                    positions.push_back(centre + dvec3(r.vector(-2.0f, 2.0f)));
                const auto base = std::uint32_t(3 * t);
                triangles.push_back({base, base + 1, base + 2});
            }
            const ShadingModel model = std::array{ShadingModel::Phong, ShadingModel::Gouraud,
                                                  ShadingModel::Flat}[std::size_t(trial % 3)];
            auto scene = std::make_shared<Scene>(
                testing::makeScene(testing::axisCamera(),
                                   testing::makeMesh(std::move(positions), std::move(triangles)),
                                   160, trial % 2 ? 117 : 120, model));
            scene->lights.push_back({dvec4(dvec3(r.vector(-20.0f, 20.0f)), 1.0), vec3(180.0f), {}});
            const auto stages = testing::renderTrace(scene, RenderOptions{});  // a first frame
            auto probe = RecordingProbe::forPixel(-1, -1);
            auto lecture = traceFrame(scene, {}, probe);
            QVERIFY(lecture.ok());
            for (int threads : {1, 2, 3}) {
                double share = 0.0;
                const FrameLighting lighting(*scene, *lecture->view, *lecture->normals,
                                             *lecture->projection);
                const int rows = std::array{8, 4, 3, 1}[std::size_t(trial + threads) % 4];
                auto [depth, shading] = fast::depthTestAndShading(lighting, *lecture->scan, threads,
                                                                  rows, nullptr, share);
                QVERIFY2(shading.colour == lecture->shading->colour,
                         qPrintable(QStringLiteral("trial %1, %2 threads, bands of %3 rows")
                                        .arg(trial)
                                        .arg(threads)
                                        .arg(rows)));
                QCOMPARE(depth.fragments, lecture->depth->fragments);
                QCOMPARE(depth.passed, lecture->depth->passed);
                QCOMPARE(shading.shadedPixels, lecture->shading->shadedPixels);
                for (int y = 0; y < scene->height; ++y)
                    for (int x = 0; x < scene->width; ++x)
                        QCOMPARE(shading.covered.at(x, y) != 0,
                                 lecture->depth->triangle.at(x, y) != kNoTriangle);
            }
            QVERIFY(stages->shading->colour == lecture->shading->colour);
        }
    }
};

QTEST_GUILESS_MAIN(TestKernels)
#include "tst_kernels.moc"
