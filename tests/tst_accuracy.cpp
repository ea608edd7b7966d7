// The exact reference (ray cast per sample) and the accuracy report: the reference's pixels
// on a single lit triangle worked out by hand, the metrics on images made by hand, and the
// report's promises on a generated sphere (the GPU-like rules agree with the reference, the
// course rules do not, and say by how much).
#include <QtTest>

#include <cmath>
#include <set>

#include "pipeline/analysis/accuracy.h"
#include "pipeline/analysis/reference.h"
#include "pipeline/render/renderer.h"
#include "pipeline/scene/benchmark_scenes.h"
#include "tests/test_support.h"

using namespace rl;

namespace {

// A 4x4 image seen from the origin along +z (d = hx = hy = 1), one triangle in the plane
// z = 2 with corners (-2, -2), (2, -2), (0, 2): on the screen, (-1, -1), (1, -1), (0, 1) in
// NDC. Pixel centres sit at NDC +-0.25 and +-0.75; the triangle holds those with
// ny >= -1 and |nx| <= (1 - ny) / 2: rows 1 and 2 at x = 1, 2, and all of row 3.
// The light sits at the eye (200 each channel), Ia = 100, ka = 0.2, kd = 0.5,
// Od = (1, 0.5, 0.25).
Scene triangleScene(ShadingModel shading, float ks, float n) {
    Scene scene;
    scene.width = 4;
    scene.height = 4;
    CourseCamera camera;
    camera.c = dvec3(0.0);
    camera.n = dvec3(0.0, 0.0, 1.0);
    camera.v = dvec3(0.0, 1.0, 0.0);
    camera.d = 1.0;
    camera.hx = 1.0;
    camera.hy = 1.0;
    scene.camera = camera;
    scene.conventions = Conventions::course();
    scene.ambientIntensity = vec3(100.0f);
    scene.lights.push_back({dvec4(0.0, 0.0, 0.0, 1.0), vec3(200.0f), {}});
    auto mesh = std::make_shared<Mesh>();
    mesh->positions = {dvec4(-2.0, -2.0, 2.0, 1.0), dvec4(2.0, -2.0, 2.0, 1.0),
                       dvec4(0.0, 2.0, 2.0, 1.0)};
    mesh->triangles = {{0, 1, 2}};
    Draw draw;
    draw.name = "triangle";
    draw.mesh = mesh;
    draw.material.ka = 0.2f;
    draw.material.kd = vec3(0.5f);
    draw.material.od = vec3(1.0f, 0.5f, 0.25f);
    draw.material.ks = ks;
    draw.material.shininess = n;
    draw.shading = shading;
    scene.draws.push_back(draw);
    return scene;
}

ReferenceImage referenceOf(const Scene& scene, int samples = 1) {
    auto shared = std::make_shared<const Scene>(scene);
    auto trace = renderFrame(shared);
    if (!trace) qFatal("render failed: %s", trace.error().toString().c_str());
    ReferenceOptions options;
    options.samplesPerAxis = samples;
    options.nearZ = trace->projection->nearW;
    auto reference = renderReference(scene, *trace->view, *trace->normals, options);
    if (!reference) qFatal("reference failed: %s", reference.error().toString().c_str());
    return std::move(reference.value());
}

const std::set<std::pair<int, int>> kCovered = {{1, 1}, {2, 1}, {1, 2}, {2, 2},
                                                {0, 3}, {1, 3}, {2, 3}, {3, 3}};

}  // namespace

class TestAccuracy : public QObject {
    Q_OBJECT

private slots:
    void referenceFlatTriangleByHand() {
        // Flat: one evaluation at the barycentre P = (0, -2/3, 2), N = (0, 0, -1) (toward the
        // eye), L = V = -P / |P|, |P| = sqrt(40/9): N.L = 2 / |P| = 0.9486833.
        // I = 20 + 200 * 0.5 * 0.9486833 * Od = (114.86833, 67.43416, 43.71708), / 255.
        const ReferenceImage r = referenceOf(triangleScene(ShadingModel::Flat, 0.0f, 1.0f));
        const dvec3 expected(0.45046404, 0.26444771, 0.17143954);
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) {
                const bool covered = kCovered.count({x, y}) > 0;
                QCOMPARE(int(r.hits.at(x, y)), covered ? 1 : 0);
                QCOMPARE(r.triangle.at(x, y), covered ? 0u : ReferenceImage::kNoHit);
                if (!covered) {
                    QCOMPARE(r.colour.at(x, y), dvec3(0.0));
                    QVERIFY(std::isinf(r.depth.at(x, y)));
                    continue;
                }
                RL_COMPARE_VEC(r.colour.at(x, y), expected, 1e-7);
                QCOMPARE(r.depth.at(x, y), 2.0);
            }
        QCOMPARE(r.rays, std::size_t(16));
        QCOMPARE(r.triangles, std::size_t(1));
    }

    void referencePhongPixelByHand() {
        // Pixel (1, 3): NDC (-0.25, -0.75), P = 2 (-0.25, -0.75, 1) = (-0.5, -1.5, 2),
        // |P| = sqrt(6.5); N.L = 2 / |P| = 0.7844645; R.V = 2 (N.L)^2 - 1 = 3/13 = 0.2307692;
        // with ks = 0.5 and n = 2: I = 20 + 100 * 0.7844645 * Od + 200 * 0.5 * (3/13)^2
        // = (103.77190, 64.54867, 44.93706).
        const ReferenceImage r = referenceOf(triangleScene(ShadingModel::Phong, 0.5f, 2.0f));
        RL_COMPARE_VEC(r.colour.at(1, 3), dvec3(103.77190, 64.54867, 44.93706) / 255.0, 1e-7);
        // The pixel straight below the eye's axis mirrors it: (2, 3) is the same.
        RL_COMPARE_VEC(r.colour.at(2, 3), r.colour.at(1, 3), 1e-12);
    }

    void referenceFollowsTheSlidesLighting() {
        // The exact reference (double) and the render's phong() (float) agree on the slides'
        // lighting: an attenuated spot, a directional light, emission, Blinn-Phong.
        Scene scene = triangleScene(ShadingModel::Phong, 0.5f, 8.0f);
        Draw& draw = scene.draws[0];
        draw.material.emission = vec3(3.0f, 2.0f, 1.0f);
        draw.specular = SpecularModel::BlinnPhong;
        std::vector<ViewLight> lights(2);
        lights[0].pView = dvec4(0.5, 1.0, -1.0, 1.0);
        lights[0].intensity = vec3(200.0f, 150.0f, 100.0f);
        lights[0].attenuation = vec3(1.0f, 0.2f, 0.05f);
        lights[0].attenuated = true;
        lights[0].spot = true;
        lights[0].spotDirection = glm::normalize(vec3(-0.5f, -1.5f, 3.0f));
        lights[0].spotCosCutoff = std::cos(glm::radians(25.0f));
        lights[0].spotExponent = 3.0f;
        lights[1].pView = dvec4(0.0, 0.0, -1.0, 0.0);
        lights[1].intensity = vec3(40.0f);
        const vec3 n = glm::normalize(vec3(0.1f, 0.2f, -1.0f));
        for (const vec3 p : {vec3(-0.5f, -1.5f, 2.0f), vec3(0.0f, -0.5f, 2.0f)}) {
            LightTerms terms[2];
            const PhongSample s =
                phong(draw.material, draw.material.od, scene.ambientIntensity, lights.data(), 2, p,
                      n, true, SpecularModel::BlinnPhong, terms);
            QVERIFY(terms[0].attenuation < 1.0f && terms[0].spot > 0.5f && !terms[0].behind);
            const dvec3 exact = referencePhong(scene, draw, lights, dvec3(p), dvec3(n));
            RL_COMPARE_VEC(dvec3(s.colour()), exact, 1e-3);
        }
    }

    void referenceSupersamplesCountHits() {
        // 2x2 samples: at the corner pixel (0, 3) samples at NDC x = -0.875 and -0.625, y =
        // -0.625 and -0.875; inside when |x| <= (1 - y) / 2: 0.8125 and 0.9375 bound them,
        // so (-0.875, -0.625) is out and the other three in.
        const ReferenceImage r = referenceOf(triangleScene(ShadingModel::Flat, 0.0f, 1.0f), 2);
        QCOMPARE(int(r.hits.at(0, 3)), 3);
        QCOMPARE(int(r.hits.at(1, 3)), 4);
        RL_COMPARE_VEC(r.colour.at(0, 3), 0.75 * dvec3(0.45046404, 0.26444771, 0.17143954), 1e-7);
    }

    void referenceRefusesWhatItCannotDo() {
        Scene scene = triangleScene(ShadingModel::Phong, 0.0f, 1.0f);
        scene.draws[0].lighting = LightingModel::Lambert;
        auto shared = std::make_shared<const Scene>(scene);
        auto trace = renderFrame(shared);
        QVERIFY(trace);
        auto r = renderReference(scene, *trace->view, *trace->normals, {});
        QVERIFY(!r);
        QCOMPARE(r.error().code, ErrorCode::Unsupported);
        QCOMPARE(QString::fromStdString(r.error().message),
                 QStringLiteral("the exact reference handles course scenes (the course camera, "
                                "view z as depth, the course's Phong lighting with the "
                                "material's colour); triangle is not lit by the course's Phong "
                                "model"));
    }

    void metricsByHand() {
        // 2x2: the reference covers (0, 0), (1, 0), (0, 1) in grey 0.5; the render covers
        // (0, 0) exactly, (1, 0) with red 2/255 too high, and (1, 1).
        ReferenceImage ref;
        ref.colour.reset(2, 2, dvec3(0.0));
        ref.hits.reset(2, 2, 0);
        ref.depth.reset(2, 2, std::numeric_limits<double>::infinity());
        SampledImage ours;
        ours.colour.reset(2, 2, dvec3(0.0));
        ours.hits.reset(2, 2, 0);
        ours.depth.reset(2, 2, std::numeric_limits<double>::quiet_NaN());
        for (auto [x, y] : {std::pair{0, 0}, {1, 0}, {0, 1}}) {
            ref.colour.at(x, y) = dvec3(0.5);
            ref.hits.at(x, y) = 1;
        }
        ref.depth.at(0, 0) = 2.0;
        ref.depth.at(1, 0) = 3.0;
        ours.colour.at(0, 0) = dvec3(0.5);
        ours.colour.at(1, 0) = dvec3(0.5 + 2.0 / 255.0, 0.5, 0.5);
        ours.colour.at(1, 1) = dvec3(0.25);
        for (auto [x, y] : {std::pair{0, 0}, {1, 0}, {1, 1}}) ours.hits.at(x, y) = 1;
        ours.depth.at(0, 0) = 2.2;
        ours.depth.at(1, 0) = 3.0;
        const AccuracyMetrics m = compareWithReference(ours, ref);
        QCOMPARE(m.bothCovered, std::size_t(2));
        QCOMPARE(m.eitherCovered, std::size_t(4));
        QCOMPARE(m.coverageMismatch, std::size_t(2));
        QCOMPARE(m.coverageMismatchShare(), 0.5);
        // RMSE over 2 pixels x 3 channels, one of them 2/255 off: (2/255) / sqrt(6).
        QVERIFY(std::abs(m.rmse - (2.0 / 255.0) / std::sqrt(6.0)) < 1e-12);
        QVERIFY(std::abs(m.maxError - 2.0 / 255.0) < 1e-12);
        QVERIFY(std::abs(m.psnr - 20.0 * std::log10(255.0 * std::sqrt(6.0) / 2.0)) < 1e-9);
        QCOMPARE(m.within1Of255, 0.5);
        QCOMPARE(m.worstX, 1);
        QCOMPARE(m.worstY, 0);
        QVERIFY(std::abs(m.depthMeanRelative - 0.05) < 1e-12);
        QVERIFY(std::abs(m.depthMaxRelative - 0.1) < 1e-12);

        const Image<float> map = errorMap(ours, ref);
        QCOMPARE(map.at(0, 0), 0.0f);
        QCOMPARE(map.at(1, 0), float(2.0 / 255.0));
        QCOMPARE(map.at(0, 1), -1.0f);
        QCOMPARE(map.at(1, 1), -1.0f);

        // Identical images: no error, infinite PSNR.
        ours.colour.at(1, 0) = dvec3(0.5);
        ours.hits.at(1, 1) = 0;
        ours.hits.at(0, 1) = 1;
        ours.colour.at(0, 1) = dvec3(0.5);
        const AccuracyMetrics same = compareWithReference(ours, ref);
        QCOMPARE(same.rmse, 0.0);
        QVERIFY(std::isinf(same.psnr));
        QCOMPARE(same.coverageMismatch, std::size_t(0));
        QCOMPARE(same.within1Of255, 1.0);
    }

    void gpuRulesAgreeWithTheReference() {
        // The generated 1k sphere at 200x150 in every shading model under the course and the
        // GPU-like rules. The GPU-like Phong agrees within 1/255 on at least 99.9 % of the
        // pixels both cover and its depth within 1e-5 on average (at the silhouette, where the
        // surface is edge-on, a 1/256-pixel snap moves it by up to 1e-3); the course's
        // screen-affine Phong, half a pixel off the centres, is clearly worse.
        auto scene = makeBenchmarkScene("sphere-1k", 200, 150, ShadingModel::Phong);
        QVERIFY(scene);
        AccuracyOptions options;
        options.repeats = 1;
        options.modes =
            defaultAccuracyModes({ShadingModel::Flat, ShadingModel::Gouraud, ShadingModel::Phong},
                                 {RuleSet::Course, RuleSet::Gpu}, {1});
        auto report = measureAccuracy(*scene, options);
        QVERIFY(report);
        QCOMPARE(report->rows.size(), std::size_t(12));  // each mode in float, then double
        const auto row = [&](ShadingModel s, RuleSet r, const char* precision = "float") {
            for (const AccuracyRow& x : report->rows)
                if (x.mode.shading == s && x.mode.rules == r && x.precision == precision)
                    return x.metrics;
            qFatal("no row");
        };
        const AccuracyMetrics gpu = row(ShadingModel::Phong, RuleSet::Gpu);
        const AccuracyMetrics course = row(ShadingModel::Phong, RuleSet::Course);
        QVERIFY2(gpu.within1Of255 >= 0.999, qPrintable(QString::number(gpu.within1Of255)));
        QVERIFY2(gpu.bothCovered > 5000, qPrintable(QString::number(gpu.bothCovered)));
        QVERIFY2(gpu.coverageMismatchShare() < 0.001,
                 qPrintable(QString::number(gpu.coverageMismatchShare())));
        QVERIFY2(gpu.depthMeanRelative < 1e-5 && gpu.depthMaxRelative < 1e-3,
                 qPrintable(
                     QStringLiteral("%1 %2").arg(gpu.depthMeanRelative).arg(gpu.depthMaxRelative)));
        QVERIFY(course.rmse > 10.0 * gpu.rmse);
        QVERIFY(course.coverageMismatchShare() > 0.005);
        QVERIFY2(course.depthMeanRelative > 10.0 * gpu.depthMeanRelative,
                 qPrintable(QStringLiteral("%1").arg(course.depthMeanRelative)));
        // Double precision changes next to nothing: the error is the rules', not the float's.
        const AccuracyMetrics gpuDouble = row(ShadingModel::Phong, RuleSet::Gpu, "double");
        QVERIFY(gpuDouble.within1Of255 >= gpu.within1Of255 - 1e-3);
        QVERIFY(std::abs(gpuDouble.rmse - gpu.rmse) < 0.05 / 255.0);
        QCOMPARE(gpuDouble.coverageMismatch, gpu.coverageMismatch);
        for (const AccuracyRow& x : report->rows) {
            QVERIFY(x.milliseconds > 0.0);
            QVERIFY(std::isfinite(x.metrics.rmse));
        }
        QCOMPARE(report->referenceRays, std::size_t(3 * 200 * 150));
    }

    void doublePrecisionByHand() {
        // The triangle faces the eye (z = 2 everywhere), so screen-affine and perspective
        // interpolation agree; under the gpu rules its corners, pixels (0, 4), (4, 4) and
        // (2, 0), lie on the 1/256 grid and the samples at pixel centres: the frame shaded in
        // double is the reference, pixel for pixel.
        Scene scene = triangleScene(ShadingModel::Phong, 0.5f, 2.0f);
        scene.rules = RasterRules::gpu();
        const ReferenceImage reference = referenceOf(scene);
        auto trace = renderFrame(std::make_shared<const Scene>(scene));
        QVERIFY(trace);
        double ms = -1.0;
        const SampledImage inDouble = shadeFrameInDouble(trace.value(), 1, ms);
        QVERIFY(ms >= 0.0);
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) {
                QCOMPARE(int(inDouble.hits.at(x, y)), int(reference.hits.at(x, y)));
                RL_COMPARE_VEC(inDouble.colour.at(x, y), reference.colour.at(x, y), 1e-12);
                if (reference.hits.at(x, y)) QCOMPARE(inDouble.depth.at(x, y), 2.0);
            }
        RL_COMPARE_VEC(inDouble.colour.at(1, 3), dvec3(103.77190, 64.54867, 44.93706) / 255.0,
                       1e-7);
        // The float frame is within float rounding of it.
        const SampledImage inFloat = sampleFrame(trace.value(), 1);
        RL_COMPARE_VEC(inFloat.colour.at(1, 3), inDouble.colour.at(1, 3), 1e-5);
    }

    void supersamplingKeepsTheGpuRulesExact() {
        auto scene = makeBenchmarkScene("sphere-1k", 120, 90, ShadingModel::Gouraud);
        QVERIFY(scene);
        AccuracyOptions options;
        options.repeats = 1;
        options.modes = {{ShadingModel::Gouraud, RuleSet::Gpu, 2}};
        options.withDouble = false;
        auto report = measureAccuracy(*scene, options);
        QVERIFY(report);
        QCOMPARE(report->rows.size(), std::size_t(1));
        const AccuracyMetrics& m = report->rows.at(0).metrics;
        QCOMPARE(accuracyModeName(report->rows.at(0).mode), std::string("gouraud/gpu x4"));
        QVERIFY2(m.within1Of255 >= 0.999, qPrintable(QString::number(m.within1Of255)));
        QVERIFY(std::isnan(m.depthMeanRelative));  // depth is compared at one sample a pixel
    }
};

QTEST_GUILESS_MAIN(TestAccuracy)
#include "tst_accuracy.moc"
