// Stage 7, shading: one pixel's Phong colour worked out term by term, the same pixel
// flat and Gouraud, each special case of seed 000 (flip, N.L < 0, R.V < 0), and the
// conversion to bytes (clamp at 255, truncate).
#include <QtTest>

#include <cmath>

#include "pipeline/core/fast_pow.h"

#include "pipeline/render/output_image.h"
#include "pipeline/render/renderer.h"
#include "pipeline/stages/phong.h"
#include "tests/test_support.h"

using namespace rl;

namespace {

// Axis camera (view = (-x, y, z)), 800x600, d = hx = hy = 1. The triangle's view vertices
// (-10,10,10), (10,10,10), (0,-10,10) project exactly to pixels (0,0), (800,0), (400,600);
// pixel (400,300) has barycentrics (1/4, 1/4, 1/2) and P' = (0, 0, 10). Its view normal is
// (20,0,0) x (10,-20,0) = (0,0,-400) -> (0,0,-1). The light is at view (0, 10, 0).
Scene handScene(ShadingModel model) {
    Scene scene = testing::makeScene(
        testing::axisCamera(),
        testing::makeMesh({{10, 10, 10}, {-10, 10, 10}, {0, -10, 10}}, {{0, 1, 2}}), 800, 600,
        model);
    Material& m = scene.draws[0].material;
    m.ka = 0.2f;
    m.kd = vec3(0.5f);
    m.od = vec3(1.0f, 0.5f, 0.25f);
    m.ks = 0.4f;
    m.shininess = 2.0f;
    scene.ambientIntensity = vec3(100.0f, 50.0f, 25.0f);
    scene.lights = {{dvec4(0.0, 10.0, 0.0, 1.0), vec3(200.0f, 200.0f, 100.0f), {}}};
    return scene;
}

struct Pixel {
    vec3 colour;
    std::array<int, 3> bytes;
};

Pixel renderPixel(const Scene& scene, int x, int y) {
    auto trace = renderFrame(std::make_shared<const Scene>(scene));
    if (!trace) qFatal("render failed: %s", trace.error().toString().c_str());
    const Rgba8Image image = colourImage(*trace->shading, *trace->depth, scene.conventions);
    const std::uint8_t* p = image.pixel(x, y);
    return {trace->shading->colour.at(x, y), {p[0], p[1], p[2]}};
}

Material unitMaterial() {
    Material m;
    m.ka = 0.1f;
    m.kd = vec3(1.0f);
    m.od = vec3(1.0f);
    m.ks = 1.0f;
    m.shininess = 1.0f;
    return m;
}

}  // namespace

class TestShading : public QObject {
    Q_OBJECT

private slots:
    void fastPowerAgainstPow() {
        // fast_pow.h: the relative error stays below 3e-5 for n up to 200 (a hundredth of a
        // level of 255 at most), C's special cases hold, and it is monotonic in x.
        double worst = 0.0;
        for (float n : {0.5f, 1.0f, 2.0f, 7.0f, 32.0f, 100.0f, 200.0f}) {
            float previous = 0.0f;
            for (int i = 1; i <= 20000; ++i) {
                const float x = float(i) / 20000.0f;
                const double exact = std::pow(double(x), double(n));
                const float fast = fastPow(x, n);
                if (exact > 1e-30) worst = std::max(worst, std::abs(fast - exact) / exact);
                QVERIFY(fast >= previous);
                previous = fast;
            }
        }
        qInfo("fastPow: worst relative error %.3g", worst);
        QVERIFY(worst < 3e-5);
        QCOMPARE(fastPow(0.0f, 0.0f), 1.0f);
        QCOMPARE(fastPow(0.0f, 32.0f), 0.0f);
        QCOMPARE(fastPow(0.25f, 0.0f), 1.0f);
        QCOMPARE(fastPow(1e-30f, 1e6f), 0.0f);
        QVERIFY(std::abs(fastPow(1.0f, 1e6f) - 1.0f) < 1e-6f);
        QVERIFY(std::isfinite(fastPow(0.5f, -300.0f)));  // n < 0 is warned about, never Inf
    }

    void phongPixelByHand() {
        // V = -P'/|P'| = (0,0,-1); N = (0,0,-1), V.N = 1 > 0: no flip.
        // L = (0,10,0) - (0,0,10) = (0,10,-10) -> (0, 0.70711, -0.70711); N.L = 0.70711.
        // R = 2 (N.L) N - L = (0, -0.70711, -0.70711); R.V = 0.70711; (R.V)^2 = 0.5.
        // ambient  = Ia ka            = (100, 50, 25) * 0.2                  = (20, 10, 5)
        // diffuse  = Il Od kd (N.L)   = (200*1, 200*0.5, 100*0.25) * 0.5 * 0.70711
        //                             = (70.711, 35.355, 8.839)
        // specular = Il ks (R.V)^n    = (200, 200, 100) * 0.4 * 0.5          = (40, 40, 20)
        // sum = (130.711, 85.355, 33.839) -> bytes (130, 85, 33)
        const Pixel p = renderPixel(handScene(ShadingModel::Phong), 400, 300);
        RL_COMPARE_VEC(p.colour, vec3(130.71068f, 85.35534f, 33.83883f), 1e-3);
        QCOMPARE(p.bytes, (std::array<int, 3>{130, 85, 33}));
    }

    void flatPixelByHand() {
        // One evaluation at the barycentre (0, 10/3, 10) with the triangle normal (0,0,-1):
        // V = (0, -0.31623, -0.94868); L = (0, 20/3, -10) -> (0, 0.55470, -0.83205);
        // N.L = 0.83205; R = (0, -0.55470, -0.83205); R.V = 0.96476; (R.V)^2 = 0.93077.
        // ambient (20, 10, 5); diffuse (200, 100, 25) * 0.5 * 0.83205 = (83.205, 41.603, 10.401);
        // specular (80, 80, 40) * 0.93077 = (74.462, 74.462, 37.231).
        // sum = (177.667, 126.064, 52.631) -> bytes (177, 126, 52), on every pixel.
        const Scene scene = handScene(ShadingModel::Flat);
        for (auto [x, y] : {std::pair{400, 300}, std::pair{10, 3}, std::pair{400, 599}}) {
            const Pixel p = renderPixel(scene, x, y);
            RL_COMPARE_VEC(p.colour, vec3(177.66657f, 126.06405f, 52.63140f), 1e-3);
            QCOMPARE(p.bytes, (std::array<int, 3>{177, 126, 52}));
        }
    }

    void gouraudPixelByHand() {
        // Vertex (-10,10,10): V = (0.57735, -0.57735, -0.57735), L = (0.70711, 0, -0.70711),
        //   N.L = 0.70711, R = (-0.70711, 0, -0.70711), R.V = 0: specular 0.
        //   colour = (20,10,5) + (70.711, 35.355, 8.839) = (90.711, 45.355, 13.839).
        // Vertex (10,10,10): the mirror image, the same colour.
        // Vertex (0,-10,10): L = (0, 0.89443, -0.44721), N.L = 0.44721,
        //   R = (0, -0.89443, -0.44721), V = (0, 0.70711, -0.70711), R.V = -0.31623 < 0: no
        //   specular; colour = (20,10,5) + (100,50,12.5) * 0.44721 = (64.721, 32.361, 10.590).
        // Pixel (400,300) = 1/4 c1 + 1/4 c2 + 1/2 c3 = (77.716, 38.858, 12.215) -> (77, 38, 12).
        const Pixel p = renderPixel(handScene(ShadingModel::Gouraud), 400, 300);
        RL_COMPARE_VEC(p.colour, vec3(77.71602f, 38.85801f, 12.21450f), 1e-3);
        QCOMPARE(p.bytes, (std::array<int, 3>{77, 38, 12}));
    }

    void windingDoesNotMatter() {
        // Seed 000 turns N toward the viewer, so reversing the triangle's vertex order (its
        // normal flips) gives the same image.
        Scene reversed = handScene(ShadingModel::Phong);
        auto mesh = std::make_shared<Mesh>(*reversed.draws[0].mesh);
        mesh->triangles[0] = {0, 2, 1};
        reversed.draws[0].mesh = mesh;
        auto a = renderFrame(std::make_shared<const Scene>(handScene(ShadingModel::Phong)));
        auto b = renderFrame(std::make_shared<const Scene>(reversed));
        QCOMPARE(b->shading->flipped, b->shading->shadedPixels);
        QCOMPARE(a->shading->flipped, std::size_t(0));
        // Same pixels covered; colours equal up to float rounding (the barycentrics are
        // summed in another order), which can move a truncated byte by one.
        QCOMPARE(a->depth->triangle, b->depth->triangle);
        float worst = 0.0f;
        for (int y = 0; y < 600; ++y)
            for (int x = 0; x < 800; ++x)
                for (int k = 0; k < 3; ++k)
                    worst = std::max(worst, std::abs(a->shading->colour.at(x, y)[k] -
                                                     b->shading->colour.at(x, y)[k]));
        qInfo("largest colour difference between the two windings: %g (of 255)", double(worst));
        QVERIFY(worst < 1e-3f);
    }

    void flipTowardTheViewer() {
        const ViewLight light{dvec4(0.0, 0.0, 0.0, 1.0), vec3(100.0f)};
        // P' = (0,0,10), N = (0,0,1) points away from the viewer: V.N = -1 < 0, N := (0,0,-1).
        const PhongSample s = phong(unitMaterial(), vec3(1.0f), vec3(50.0f), &light, 1,
                                    vec3(0, 0, 10), vec3(0, 0, 1), true);
        QVERIFY(s.flipped);
        RL_COMPARE_VEC(s.n, vec3(0, 0, -1), 0.0);
        // Light at the eye: N.L = 1, R = V, R.V = 1: diffuse 100, specular 100.
        RL_COMPARE_VEC(s.colour(), vec3(5.0f + 100.0f + 100.0f), 1e-4);
        // Without the flip (a convention of other formats) the light is behind the surface.
        const PhongSample unflipped = phong(unitMaterial(), vec3(1.0f), vec3(50.0f), &light, 1,
                                            vec3(0, 0, 10), vec3(0, 0, 1), false);
        QVERIFY(!unflipped.flipped);
        QVERIFY(unflipped.lightBehind);
        RL_COMPARE_VEC(unflipped.colour(), vec3(5.0f), 1e-6);
    }

    void lightBehindTheSurface() {
        // N = (0,0,-1) faces the viewer; the light at (0,0,20) is behind the surface z = 10.
        const ViewLight light{dvec4(0.0, 0.0, 20.0, 1.0), vec3(100.0f)};
        const PhongSample s = phong(unitMaterial(), vec3(1.0f), vec3(50.0f), &light, 1,
                                    vec3(0, 0, 10), vec3(0, 0, -1), true);
        QVERIFY(s.lightBehind);
        QVERIFY(!s.noSpecular);
        RL_COMPARE_NEAR(s.nDotL, -1.0, 1e-6);
        RL_COMPARE_VEC(s.diffuse, vec3(0.0f), 0.0);
        RL_COMPARE_VEC(s.specular, vec3(0.0f), 0.0);
        RL_COMPARE_VEC(s.colour(), vec3(5.0f), 1e-6);
    }

    void reflectionAwayFromTheViewer() {
        // P' = (0,0,10), N = (0,0,-1), V = (0,0,-1). Light at (100, 0, 10.1), nearly grazing:
        // L = (0.99999, 0, 0.001) (normalised), N.L = -0.001 < 0 would be behind; use
        // (100, 0, 0): L = (100, 0, -10)/100.499 = (0.99504, 0, -0.09950), N.L = 0.09950,
        // R = 2 (N.L) N - L = (-0.99504, 0, -0.09950), R.V = 0.09950 > 0. To get R.V < 0 the
        // viewer must sit on the far side of the reflection: move P' off axis.
        // P' = (50, 0, 10): V = (-0.98058, 0, -0.19612); N = (0,0,-1); light at (0, 0, 0):
        // L = V; R = 2 (N.V) N - V = (0.98058, 0, -0.19612); R.V = -0.96154 + 0.03846 < 0.
        const ViewLight light{dvec4(0.0, 0.0, 0.0, 1.0), vec3(100.0f)};
        const PhongSample s = phong(unitMaterial(), vec3(1.0f), vec3(0.0f), &light, 1,
                                    vec3(50, 0, 10), vec3(0, 0, -1), true);
        QVERIFY(!s.lightBehind);
        QVERIFY(s.noSpecular);
        RL_COMPARE_NEAR(s.rDotV, -0.923077, 1e-5);
        RL_COMPARE_VEC(s.specular, vec3(0.0f), 0.0);
        RL_COMPARE_VEC(s.diffuse, vec3(100.0f * 0.196116f), 1e-4);  // N.L = 0.19612
    }

    void degenerateVectors() {
        const ViewLight light{dvec4(0.0, 0.0, 10.0, 1.0), vec3(100.0f)};
        // Zero normal: ambient only, flagged.
        const PhongSample noNormal = phong(unitMaterial(), vec3(1.0f), vec3(50.0f), &light, 1,
                                           vec3(0, 0, 5), vec3(0.0f), true);
        QVERIFY(noNormal.noNormal);
        RL_COMPARE_VEC(noNormal.colour(), vec3(5.0f), 0.0);
        // The light on the point itself: L = 0, ambient only, flagged; no NaN.
        const PhongSample atPoint = phong(unitMaterial(), vec3(1.0f), vec3(50.0f), &light, 1,
                                          vec3(0, 0, 10), vec3(0, 0, -1), true);
        QVERIFY(atPoint.lightAtPoint);
        RL_COMPARE_VEC(atPoint.colour(), vec3(5.0f), 0.0);
        // A light 1e25 away, straight in front of the surface: the square of its distance
        // overflows float, but it is not at the point. L = (0, 0, -1) = N, so N.L = 1: the
        // whole diffuse term (100) over the ambient (5); V = L, so R.V = 1 and the highlight
        // is whole too (100).
        const ViewLight far{dvec4(0.0, 0.0, -1e25, 1.0), vec3(100.0f)};
        const PhongSample lit = phong(unitMaterial(), vec3(1.0f), vec3(50.0f), &far, 1,
                                      vec3(0, 0, 10), vec3(0, 0, -1), true);
        QVERIFY(!lit.lightAtPoint);
        RL_COMPARE_VEC(lit.l, vec3(0, 0, -1), 1e-6);
        RL_COMPARE_NEAR(lit.nDotL, 1.0, 1e-6);
        RL_COMPARE_VEC(lit.colour(), vec3(205.0f), 1e-3);
    }

    void exponentZeroAndSeveralLights() {
        Material m = unitMaterial();
        m.shininess = 0.0f;  // (R.V)^0 = 1 whenever R.V >= 0
        m.kd = vec3(0.0f);
        const ViewLight lights[2] = {{dvec4(0.0, 0.0, 0.0, 1.0), vec3(10.0f, 0.0f, 0.0f)},
                                     {dvec4(0.0, 0.0, -1.0, 0.0), vec3(0.0f, 20.0f, 0.0f)}};
        // Light 1 at the eye, light 2 directional toward -z (behind the viewer): both have
        // N.L = 1 on the surface facing the viewer; the specular terms add up.
        const PhongSample s =
            phong(m, m.od, vec3(0.0f), lights, 2, vec3(0, 0, 10), vec3(0, 0, -1), true);
        RL_COMPARE_VEC(s.specular, vec3(10.0f, 20.0f, 0.0f), 1e-5);
    }

    // The lecture slides' lighting (seed 003), worked out by hand.
    void attenuatedLight() {
        // A positional light at the eye, Il = 100, kc kl kq = 1, 0.1, 0.01; P' = (0, 0, 10),
        // N = (0, 0, -1): d = 10, 1 / (1 + 0.1 * 10 + 0.01 * 100) = 1/3. N.L = 1, R = V,
        // R.V = 1: diffuse 100/3, specular 100/3, ambient 50 * 0.1 = 5; 71.667 in all.
        ViewLight light{dvec4(0.0, 0.0, 0.0, 1.0), vec3(100.0f)};
        light.attenuation = vec3(1.0f, 0.1f, 0.01f);
        light.attenuated = true;
        LightTerms terms;
        const PhongSample s =
            phong(unitMaterial(), vec3(1.0f), vec3(50.0f), &light, 1, vec3(0, 0, 10),
                  vec3(0, 0, -1), true, SpecularModel::Phong, &terms);
        RL_COMPARE_NEAR(terms.distance, 10.0, 1e-5);
        RL_COMPARE_NEAR(terms.attenuation, 1.0 / 3.0, 1e-7);
        RL_COMPARE_VEC(s.diffuse, vec3(100.0f / 3.0f), 1e-4);
        RL_COMPARE_VEC(s.specular, vec3(100.0f / 3.0f), 1e-4);
        RL_COMPARE_VEC(s.colour(), vec3(5.0f + 200.0f / 3.0f), 1e-4);
        RL_COMPARE_VEC(terms.diffuse, s.diffuse, 0.0);
        // A directional light is not attenuated (the view transform sets attenuated only
        // for w != 0).
        Light directional;
        directional.pWorld = dvec4(0.0, 0.0, -1.0, 0.0);
        directional.attenuation = vec3(1.0f, 0.1f, 0.01f);
        QVERIFY(!directional.attenuated());
    }

    void spotConeEdge() {
        // A spot at the eye pointing along +z, cutoff 45 degrees, exponent 2, Il = 100.
        // P' = (9.9, 0, 10): -L = P'/|P'|, -L.D = 10/14.07125 = 0.710651 >= cos 45 = 0.707107:
        // inside; spot = 0.710651^2 = 0.505025; N = (0,0,-1), N.L = 0.710651:
        // diffuse = 100 * 0.505025 * 0.710651 = 35.8897; R.V = 0.01005:
        // specular = 100 * 0.505025 * 0.01005 = 0.50755.
        // P' = (10.1, 0, 10): -L.D = 0.703580 < 0.707107: outside, no light from it.
        Light spot;
        spot.spotCutoff = 45.0f;
        QVERIFY(spot.spot());
        ViewLight light{dvec4(0.0, 0.0, 0.0, 1.0), vec3(100.0f)};
        light.spot = true;
        light.spotDirection = vec3(0.0f, 0.0f, 1.0f);
        light.spotCosCutoff = std::cos(glm::radians(45.0f));
        light.spotExponent = 2.0f;
        LightTerms inside;
        const PhongSample in =
            phong(unitMaterial(), vec3(1.0f), vec3(50.0f), &light, 1, vec3(9.9f, 0, 10),
                  vec3(0, 0, -1), true, SpecularModel::Phong, &inside);
        RL_COMPARE_NEAR(inside.spotCos, 0.710651, 1e-5);
        RL_COMPARE_NEAR(inside.spot, 0.505025, 1e-5);
        QVERIFY(!inside.outsideCone);
        RL_COMPARE_VEC(in.diffuse, vec3(35.8897f), 1e-3);
        RL_COMPARE_VEC(in.specular, vec3(0.50755f), 1e-3);
        LightTerms outside;
        const PhongSample out =
            phong(unitMaterial(), vec3(1.0f), vec3(50.0f), &light, 1, vec3(10.1f, 0, 10),
                  vec3(0, 0, -1), true, SpecularModel::Phong, &outside);
        RL_COMPARE_NEAR(outside.spotCos, 0.703580, 1e-5);
        QVERIFY(outside.outsideCone);
        QVERIFY(out.outsideCone);
        QCOMPARE(outside.spot, 0.0f);
        RL_COMPARE_VEC(out.colour(), vec3(5.0f), 0.0);
    }

    void blinnPhongBesidePhong() {
        // P' = (50, 0, 10), N = (0, 0, -1), light at the eye: L = V = (-0.98058, 0, -0.19612).
        // Phong: R = 2 (N.L) N - L = (0.98058, 0, -0.19612), R.V = -0.92308 < 0: no highlight.
        // Blinn-Phong: H = (L + V)/|L + V| = L, N.H = 0.19612: highlight 100 * 0.19612.
        const ViewLight light{dvec4(0.0, 0.0, 0.0, 1.0), vec3(100.0f)};
        const PhongSample phongSample = phong(unitMaterial(), vec3(1.0f), vec3(0.0f), &light, 1,
                                              vec3(50, 0, 10), vec3(0, 0, -1), true);
        QVERIFY(phongSample.noSpecular);
        RL_COMPARE_VEC(phongSample.specular, vec3(0.0f), 0.0);
        const PhongSample blinn =
            phong(unitMaterial(), vec3(1.0f), vec3(0.0f), &light, 1, vec3(50, 0, 10),
                  vec3(0, 0, -1), true, SpecularModel::BlinnPhong);
        QVERIFY(!blinn.noSpecular);
        RL_COMPARE_NEAR(blinn.rDotV, 0.196116, 1e-5);
        RL_COMPARE_VEC(blinn.r, vec3(-0.980581f, 0.0f, -0.196116f), 1e-5);
        RL_COMPARE_VEC(blinn.specular, vec3(19.6116f), 1e-3);
        RL_COMPARE_VEC(blinn.diffuse, phongSample.diffuse, 0.0);
    }

    void emissionAndOneSided() {
        // Ke = (10, 20, 30) is added whatever the lights: with a zero normal (ambient only),
        // 5 + Ke.
        Material m = unitMaterial();
        m.emission = vec3(10.0f, 20.0f, 30.0f);
        const ViewLight light{dvec4(0.0, 0.0, 0.0, 1.0), vec3(100.0f)};
        const PhongSample s =
            phong(m, vec3(1.0f), vec3(50.0f), &light, 1, vec3(0, 0, 10), vec3(0.0f), true);
        RL_COMPARE_VEC(s.colour(), vec3(15.0f, 25.0f, 35.0f), 0.0);
        // One-sided: the back of a surface (N = (0,0,1) away from the viewer at the origin)
        // is not turned round, so the light at the eye is behind it: 5 + Ke only.
        const PhongSample back =
            phong(m, vec3(1.0f), vec3(50.0f), &light, 1, vec3(0, 0, 10), vec3(0, 0, 1), false);
        QVERIFY(back.lightBehind);
        RL_COMPARE_VEC(back.colour(), vec3(15.0f, 25.0f, 35.0f), 0.0);
    }

    void perLightTermsAddUp() {
        // Two lights: a plain one at the eye and an attenuated one at (0, 10, 10) (d = 10,
        // 1 / (1 + 0.1 * 10) = 0.5). N = (0,0,-1) at P' = (0,0,10): light 2 has N.L = 0
        // (grazing): no diffuse; its R = -L, R.V = 0: (R.V)^1 = 0, no highlight.
        ViewLight lights[2] = {{dvec4(0.0, 0.0, 0.0, 1.0), vec3(100.0f)},
                               {dvec4(0.0, 10.0, 10.0, 1.0), vec3(60.0f)}};
        lights[1].attenuation = vec3(1.0f, 0.1f, 0.0f);
        lights[1].attenuated = true;
        LightTerms terms[2];
        const PhongSample s =
            phong(unitMaterial(), vec3(1.0f), vec3(50.0f), lights, 2, vec3(0, 0, 10),
                  vec3(0, 0, -1), true, SpecularModel::Phong, terms);
        RL_COMPARE_VEC(terms[0].diffuse, vec3(100.0f), 1e-4);
        RL_COMPARE_VEC(terms[1].diffuse, vec3(0.0f), 1e-5);
        RL_COMPARE_NEAR(terms[1].attenuation, 0.5, 1e-7);
        RL_COMPARE_VEC(s.diffuse, terms[0].diffuse + terms[1].diffuse, 0.0);
        RL_COMPARE_VEC(s.specular, terms[0].specular + terms[1].specular, 0.0);
    }

    void normalsImageIsTheUsedNormal_data() {
        QTest::addColumn<int>("model");
        QTest::addColumn<bool>("reversed");
        for (auto [name, model] :
             {std::pair{"phong", ShadingModel::Phong}, std::pair{"gouraud", ShadingModel::Gouraud},
              std::pair{"flat", ShadingModel::Flat}}) {
            QTest::newRow(name) << int(model) << false;
            QTest::newRow(
                qPrintable(QStringLiteral("%1, reversed winding").arg(QString::fromUtf8(name))))
                << int(model) << true;
        }
    }

    void normalsImageIsTheUsedNormal() {
        // The triangle faces the viewer: in every model the normal used is (0, 0, -1), also
        // when its winding is reversed (the computed normal (0, 0, 1) is turned toward the
        // viewer). As colour (N + 1)/2: (128, 128, 0).
        QFETCH(int, model);
        QFETCH(bool, reversed);
        Scene scene = handScene(ShadingModel(model));
        if (reversed) {
            auto mesh = std::make_shared<Mesh>(*scene.draws[0].mesh);
            mesh->triangles[0] = {0, 2, 1};
            scene.draws[0].mesh = mesh;
        }
        RenderOptions options;
        options.shading.keepNormals = true;
        auto trace = renderFrame(std::make_shared<const Scene>(scene), options);
        QVERIFY(trace.ok());
        for (auto [x, y] : {std::pair{400, 300}, std::pair{5, 2}, std::pair{400, 590}}) {
            RL_COMPARE_VEC(trace->shading->normal.at(x, y), vec3(0, 0, -1), 1e-6);
            const Rgba8Image image = normalImage(trace->shading->normal, *trace->depth);
            const std::uint8_t* p = image.pixel(x, y);
            QCOMPARE((std::array<int, 3>{p[0], p[1], p[2]}), (std::array<int, 3>{128, 128, 0}));
        }
        QCOMPARE(int(normalImage(trace->shading->normal, *trace->depth).pixel(799, 599)[0]), 0);
    }

    void bytesAreClampedAndTruncated() {
        const Conventions course;
        QCOMPARE(int(toByte(130.711f, course)), 130);
        QCOMPARE(int(toByte(255.9f, course)), 255);
        QCOMPARE(int(toByte(1e9f, course)), 255);
        QCOMPARE(int(toByte(-3.0f, course)), 0);
        QCOMPARE(int(toByte(std::numeric_limits<float>::quiet_NaN(), course)), 0);
        QCOMPARE(int(toByte(std::numeric_limits<float>::infinity(), course)), 255);
        Conventions unit;
        unit.colourScale = 1.0f;
        unit.rounding = ByteRounding::Nearest;
        QCOMPARE(int(toByte(0.5f, unit)), 128);
        QCOMPARE(int(toByte(0.499f, unit)), 127);
    }

    void clampedPixelsAreCounted() {
        Scene scene = handScene(ShadingModel::Phong);
        scene.lights[0].intensity = vec3(2000.0f);
        auto trace = renderFrame(std::make_shared<const Scene>(scene));
        QVERIFY(trace->shading->clampedPixels > 0);
        QCOMPARE(trace->shading->shadedPixels, trace->depth->coveredPixels());
        const Rgba8Image image = colourImage(*trace->shading, *trace->depth, scene.conventions);
        QCOMPARE(int(image.pixel(400, 300)[0]), 255);
    }
};

QTEST_GUILESS_MAIN(TestShading)
#include "tst_shading.moc"
