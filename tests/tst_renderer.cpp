// The whole frame: all seven stages in order, recording and plain runs giving identical
// buffers, and the course's real files rendered with no holes, no NaN and a highlight.
#include <QtTest>

#include "app/documents/default_scene_resource.h"
#include "pipeline/io/course_scene.h"
#include "pipeline/render/output_image.h"
#include "pipeline/render/renderer.h"
#include "pipeline/stages/phong.h"
#include "tests/test_support.h"

using namespace rl;

namespace {

std::shared_ptr<const Scene> defaultScene(ShadingModel model = ShadingModel::Phong, int width = 800,
                                          int height = 600) {
    Diagnostics diagnostics;
    auto parts = rasterlab::loadDefaultCourseScene(diagnostics);
    if (!parts) qFatal("%s", parts.error().toString().c_str());
    CourseSceneSettings settings;
    settings.shading = model;
    settings.width = width;
    settings.height = height;
    return std::make_shared<const Scene>(makeCourseScene(parts.value(), settings));
}

std::optional<CourseSceneParts> sampleParts(const QString& camera, const QString& lighting,
                                            const QString& object) {
    const QString dir = testing::samplesDir();
    if (dir.isEmpty()) return std::nullopt;
    Diagnostics diagnostics;
    auto c = rasterlab::loadCamera(dir + camera, diagnostics);
    auto l = rasterlab::loadLighting(dir + lighting, diagnostics);
    auto o = rasterlab::loadObject(dir + object, diagnostics);
    if (!c || !l || !o) qFatal("cannot load the samples");
    return CourseSceneParts{c.value(), l.value(), o.value()};
}

// Uncovered pixels whose four neighbours are all covered: a crack or a pinhole.
int holes(const DepthTest& depth) {
    int n = 0;
    const auto& t = depth.triangle;
    for (int y = 1; y + 1 < t.height(); ++y)
        for (int x = 1; x + 1 < t.width(); ++x)
            if (t.at(x, y) == kNoTriangle && t.at(x - 1, y) != kNoTriangle &&
                t.at(x + 1, y) != kNoTriangle && t.at(x, y - 1) != kNoTriangle &&
                t.at(x, y + 1) != kNoTriangle)
                ++n;
    return n;
}

// Whether the sample (x, y) lies inside or on a screen triangle (integer vertices), by
// edge functions in exact integer arithmetic: an independent check of scan conversion.
bool covers(const std::array<dvec2, 3>& p, std::int64_t x, std::int64_t y) {
    auto edge = [&](const dvec2& a, const dvec2& b) {
        return (std::int64_t(b.x) - std::int64_t(a.x)) * (y - std::int64_t(a.y)) -
               (std::int64_t(b.y) - std::int64_t(a.y)) * (x - std::int64_t(a.x));
    };
    const std::int64_t w0 = edge(p[1], p[2]), w1 = edge(p[2], p[0]), w2 = edge(p[0], p[1]);
    return (w0 >= 0 && w1 >= 0 && w2 >= 0) || (w0 <= 0 && w1 <= 0 && w2 <= 0);
}

// The frame's coverage against brute force: a pixel is covered exactly when some
// non-degenerate screen triangle covers its sample, and its winner is one of those.
// Returns the number of pixels where the two disagree.
std::size_t coverageMismatches(const FrameTrace& trace) {
    const Scene& scene = *trace.scene;
    Image<std::uint8_t> expected(scene.width, scene.height, 0);
    for (const ScreenTriangle& tri : trace.projection->triangles) {
        const auto p = screenVertices(*trace.projection, tri);
        const double area =
            (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[1].y - p[0].y) * (p[2].x - p[0].x);
        if (area == 0.0) continue;
        const int x0 = int(std::max(0.0, std::min({p[0].x, p[1].x, p[2].x})));
        const int x1 = int(std::min(scene.width - 1.0, std::max({p[0].x, p[1].x, p[2].x})));
        const int y0 = int(std::max(0.0, std::min({p[0].y, p[1].y, p[2].y})));
        const int y1 = int(std::min(scene.height - 1.0, std::max({p[0].y, p[1].y, p[2].y})));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
                if (covers(p, x, y)) expected.at(x, y) = 1;
    }
    std::size_t mismatches = 0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            const std::uint32_t winner = trace.depth->triangle.at(x, y);
            const bool covered = winner != kNoTriangle;
            if (covered != bool(expected.at(x, y)))
                ++mismatches;
            else if (covered &&
                     !covers(screenVertices(*trace.projection, trace.projection->triangles[winner]),
                             x, y))
                ++mismatches;
        }
    return mismatches;
}

bool allFinite(const Image<vec3>& image) {
    for (const vec3& c : image.pixels())
        if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b)) return false;
    return true;
}

}  // namespace

class TestRenderer : public QObject {
    Q_OBJECT

private slots:
    void everyStageIsKept() {
        auto trace = renderFrame(defaultScene());
        QVERIFY(trace.ok());
        QVERIFY(trace->cameraBasis && trace->view && trace->normals && trace->projection &&
                trace->scan && trace->depth && trace->shading);
        QVERIFY(!trace->cameraBasis->skipped);
        QVERIFY(!trace->normals->skipped);
        for (double ms : trace->stageMilliseconds) QVERIFY(ms >= 0.0);
        QVERIFY(trace->totalMilliseconds > 0.0);
        // The counts agree from one stage to the next.
        QCOMPARE(trace->depth->fragments, trace->scan->pixels);
        QCOMPARE(trace->depth->passed + trace->depth->rejected, trace->depth->fragments);
        QCOMPARE(trace->shading->shadedPixels, trace->depth->coveredPixels());
        QCOMPARE(trace->projection->triangles.size(), std::size_t(7776));
        QVERIFY(trace->diagnostics.empty());
        QVERIFY(allFinite(trace->shading->colour));
    }

    void recordingAndPlainRunsAgree_data() {
        QTest::addColumn<int>("model");
        QTest::newRow("phong") << int(ShadingModel::Phong);
        QTest::newRow("flat") << int(ShadingModel::Flat);
        QTest::newRow("gouraud") << int(ShadingModel::Gouraud);
    }

    void recordingAndPlainRunsAgree() {
        QFETCH(int, model);
        const auto scene = defaultScene(ShadingModel(model));
        auto plain = renderFrame(scene);
        // Pixel (460, 355) lies on the knot's front strand (see the rendered image).
        const int px = 460, py = 355;
        auto pixelProbe = RecordingProbe::forPixel(px, py);
        auto byPixel = traceFrame(scene, {}, pixelProbe);
        const std::uint32_t visible = plain->depth->triangle.at(px, py);
        QVERIFY(visible != kNoTriangle);
        auto triangleProbe = RecordingProbe::forTriangle(visible);
        auto byTriangle = traceFrame(scene, {}, triangleProbe);
        for (const auto* traced : {&byPixel, &byTriangle}) {
            QCOMPARE((*traced)->depth->depth, plain->depth->depth);
            QCOMPARE((*traced)->depth->triangle, plain->depth->triangle);
            QVERIFY(testing::sameCoveredBarycentrics(*(*traced)->depth, *plain->depth));
            QCOMPARE((*traced)->shading->colour, plain->shading->colour);
        }
        // The pixel's log: its depth tests end with the stored depth, and the shading event
        // holds the colour of the image.
        float lastWritten = std::numeric_limits<float>::infinity();
        int shades = 0;
        for (const ProbeEvent& e : pixelProbe.events()) {
            if (const auto* d = std::get_if<DepthTestEvent>(&e)) {
                QCOMPARE(d->x, px);
                QCOMPARE(d->y, py);
                QCOMPARE(d->stored, lastWritten);
                if (d->passed) lastWritten = d->depth;
            }
            if (const auto* s = std::get_if<ShadeEvent>(&e)) {
                ++shades;
                QCOMPARE(s->triangle, visible);
                QCOMPARE(s->colour, plain->shading->colour.at(px, py));
            }
        }
        QCOMPARE(lastWritten, plain->depth->depth.at(px, py));
        QCOMPARE(shades, 1);
        // The triangle's log has its set-up, spans, every fragment and every shaded pixel.
        std::size_t spans = 0, tests = 0, shaded = 0;
        for (const ProbeEvent& e : triangleProbe.events()) {
            spans += std::holds_alternative<SpanEvent>(e) ? 1 : 0;
            tests += std::holds_alternative<DepthTestEvent>(e) ? 1 : 0;
            shaded += std::holds_alternative<ShadeEvent>(e) ? 1 : 0;
        }
        QVERIFY(std::holds_alternative<TriangleEvent>(triangleProbe.events().front()));
        QCOMPARE(spans, std::size_t(plain->scan->spanStart[visible + 1] -
                                    plain->scan->spanStart[visible]));
        std::size_t covered = 0, visiblePixels = 0;
        for (std::size_t k = plain->scan->spanStart[visible];
             k < plain->scan->spanStart[visible + 1]; ++k)
            covered += std::size_t(plain->scan->spans[k].xEnd - plain->scan->spans[k].xBegin);
        for (std::uint32_t t : plain->depth->triangle.pixels())
            visiblePixels += t == visible ? 1 : 0;
        QCOMPARE(tests, covered);
        QCOMPARE(shaded, visiblePixels);
    }

    void rendersAreDeterministic() {
        const auto scene = defaultScene();
        auto a = renderFrame(scene);
        auto b = renderFrame(scene);
        QCOMPARE(a->shading->colour, b->shading->colour);
        QCOMPARE(a->depth->depth, b->depth->depth);
    }

    void coverageDoesNotDependOnShading() {
        auto phong = renderFrame(defaultScene(ShadingModel::Phong));
        auto flat = renderFrame(defaultScene(ShadingModel::Flat));
        auto gouraud = renderFrame(defaultScene(ShadingModel::Gouraud));
        QCOMPARE(flat->depth->triangle, phong->depth->triangle);
        QCOMPARE(gouraud->depth->triangle, phong->depth->triangle);
        // Flat evaluates once per visible triangle, Gouraud once per vertex of one, Phong
        // once per pixel.
        QCOMPARE(phong->shading->phongEvaluations, phong->shading->shadedPixels);
        QVERIFY(flat->shading->phongEvaluations < 7776);
        QVERIFY(gouraud->shading->phongEvaluations <= 3888);
        QCOMPARE(holes(*phong->depth), 0);
        QCOMPARE(coverageMismatches(*phong), std::size_t(0));
    }

    void clippedTrianglesAreShadedFromTheirEdges() {
        // Axis camera (view = (-x, y, z)), near plane w = z = 1. The triangle A (-2,-2,10),
        // B (2,-2,10), C (0, 6, -10) crosses it: clipping makes vertices on B->C and C->A.
        Scene scene = testing::makeScene(
            testing::axisCamera(),
            testing::makeMesh({{-2, -2, 10}, {2, -2, 10}, {0, 6, -10}}, {{0, 1, 2}}), 200, 200,
            ShadingModel::Gouraud);
        scene.nearPlane.fixedW = 1.0;
        scene.lights = {{dvec4(0.0, 5.0, 0.0, 1.0), vec3(200.0f), {}}};
        scene.draws[0].material.ks = 0.5f;
        scene.draws[0].material.shininess = 4.0f;
        auto plain = renderFrame(std::make_shared<const Scene>(scene));
        QVERIFY(plain.ok());
        const Projection& pr = *plain->projection;
        QCOMPARE(pr.clipped, std::size_t(1));
        QCOMPARE(pr.triangles.size(), std::size_t(2));
        // Gouraud: a made vertex's colour is the colours of its edge's ends, interpolated.
        const DrawProjection& dp = pr.draws[0];
        const auto& normals = plain->normals->draws[0].vertex;
        auto litAt = [&](std::uint32_t v) {
            return phong(scene.draws[0].material, scene.draws[0].material.od,
                         scene.ambientIntensity, plain->view->lights.data(), 1, vec3(dp.pView[v]),
                         normals[v], true)
                .colour();
        };
        int checked = 0;
        for (int y = 0; y < 200 && checked < 50; ++y)
            for (int x = 0; x < 200 && checked < 50; ++x) {
                const std::uint32_t t = plain->depth->triangle.at(x, y);
                if (t == kNoTriangle) continue;
                auto probe = RecordingProbe::forPixel(x, y);
                auto traced = traceFrame(std::make_shared<const Scene>(scene), {}, probe);
                const auto& shade = std::get<ShadeEvent>(probe.events().back());
                for (int k = 0; k < 3; ++k) {
                    const std::uint32_t v = pr.triangles[t].v[std::size_t(k)];
                    vec3 expected = v < dp.originalVertexCount ? litAt(v) : vec3(0.0f);
                    if (v >= dp.originalVertexCount) {
                        const ClipVertex& g = dp.generated[v - dp.originalVertexCount];
                        expected = glm::mix(litAt(g.a), litAt(g.b), float(g.t));
                    }
                    RL_COMPARE_VEC(shade.vertexColours[std::size_t(k)], expected, 1e-3);
                }
                ++checked;
                x += 37;  // spread the probes over the triangle
            }
        QVERIFY(checked > 10);
        // Phong: P' on every covered pixel lies on the triangle's plane, on both halves of
        // the clipped quad (its made vertices lie on the edges).
        scene.draws[0].shading = ShadingModel::Phong;
        for (int y = 0; y < 200; y += 7)
            for (int x = 0; x < 200; x += 7) {
                if (plain->depth->triangle.at(x, y) == kNoTriangle) continue;
                auto probe = RecordingProbe::forPixel(x, y);
                auto traced = traceFrame(std::make_shared<const Scene>(scene), {}, probe);
                const auto& shade = std::get<ShadeEvent>(probe.events().back());
                // The view plane through (2,-2,10), (-2,-2,10), (0,6,-10) is 5 y + 2 z = 10.
                RL_COMPARE_NEAR(5.0 * shade.pView.y + 2.0 * shade.pView.z, 10.0, 1e-3);
            }
    }

    void emptyImageSaysWhy() {
        // Seed 000's own scene: its triangle projects entirely outside the 800x600 window.
        Scene scene = testing::makeScene(
            testing::seedCamera(),
            testing::makeMesh({{50, 0, 0}, {0, 50, 0}, {0, 0, 50}}, {{0, 1, 2}}), 800, 600);
        scene.name = "objeto.byu";
        auto trace = renderFrame(std::make_shared<const Scene>(scene));
        QVERIFY(trace.ok());
        QCOMPARE(trace->depth->coveredPixels(), std::size_t(0));
        QCOMPARE(QString::fromStdString(trace->diagnostics.items().back().toString()),
                 QStringLiteral("objeto.byu: warning: no triangle covers a pixel: all 1 triangles "
                                "in front of the camera project outside the image (check N, d, "
                                "hx and hy)"));
    }

    void badSizeIsAnError() {
        Scene scene = *defaultScene();
        scene.width = 0;
        auto trace = renderFrame(std::make_shared<const Scene>(scene));
        QVERIFY(!trace.ok());
        QCOMPARE(QString::fromStdString(trace.error().toString()),
                 QStringLiteral("trefoil.byu: the image size 0x600 is empty"));
    }

    void courseSamples_data() {
        QTest::addColumn<QString>("object");
        QTest::addColumn<QString>("camera");
        QTest::addColumn<int>("model");
        for (const auto& [name, model] :
             {std::pair{"phong", ShadingModel::Phong}, std::pair{"flat", ShadingModel::Flat},
              std::pair{"gouraud", ShadingModel::Gouraud}}) {
            QTest::newRow(qPrintable(QStringLiteral("calice2 ") + QString::fromUtf8(name)))
                << "/course/ufpe/calice2.byu"
                << "/course/ufpe/calice2.cfg" << int(model);
            QTest::newRow(qPrintable(QStringLiteral("vaso ") + QString::fromUtf8(name)))
                << "/course/ufpe/vaso.byu"
                << "/course/ufpe/vaso.cfg" << int(model);
        }
    }

    void courseSamples() {
        QFETCH(QString, object);
        QFETCH(QString, camera);
        QFETCH(int, model);
        auto parts = sampleParts(camera, QStringLiteral("/course/ufpe/iluminacao.txt"), object);
        if (!parts) QSKIP("course samples not found: set RASTERLAB_SAMPLES to the samples folder");
        CourseSceneSettings settings;
        settings.shading = ShadingModel(model);
        const auto scene = std::make_shared<const Scene>(makeCourseScene(*parts, settings));
        auto trace = renderFrame(scene);
        QVERIFY(trace.ok());
        const std::size_t covered = trace->depth->coveredPixels();
        qInfo("%zu pixels covered, %d holes, %.1f ms", covered, holes(*trace->depth),
              trace->totalMilliseconds);
        QVERIFY(covered > 10000);
        QCOMPARE(holes(*trace->depth), 0);
        QCOMPARE(coverageMismatches(trace.value()), std::size_t(0));
        QVERIFY(allFinite(trace->shading->colour));
        // White light on Od = (0, 0.8, 0): green everywhere, red and blue only from the
        // ambient term (Ia ka = 64) and the specular highlight.
        int highlight = 0;
        for (int y = 0; y < 600; ++y)
            for (int x = 0; x < 800; ++x) {
                if (trace->depth->triangle.at(x, y) == kNoTriangle) continue;
                const vec3 c = trace->shading->colour.at(x, y);
                QVERIFY(c.g >= c.r - 1e-3f && std::abs(c.r - c.b) < 1e-3f);
                QVERIFY(c.r >= 64.0f - 1e-3f);
                highlight += c.r > 150.0f ? 1 : 0;
            }
        qInfo("%d pixels in the white highlight", highlight);
        QVERIFY(highlight > 0);
    }

    void objectBehindTheCamera() {
        auto parts = sampleParts(QStringLiteral("/course/ufpe/calice2.cfg"),
                                 QStringLiteral("/course/ufpe/iluminacao.txt"),
                                 QStringLiteral("/course/ufpe/calice2.byu"));
        if (!parts) QSKIP("course samples not found: set RASTERLAB_SAMPLES to the samples folder");
        parts->camera.n = -parts->camera.n;  // look away from the chalice
        auto trace = renderFrame(std::make_shared<const Scene>(makeCourseScene(*parts, {})));
        QVERIFY(trace.ok());
        QCOMPARE(trace->depth->coveredPixels(), std::size_t(0));
        QCOMPARE(trace->projection->behind, std::size_t(2120));
        QVERIFY(trace->diagnostics.contains("every triangle is behind the camera"));
    }

    void cameraInsideTheObject() {
        auto parts = sampleParts(QStringLiteral("/course/ufpe/vaso.cfg"),
                                 QStringLiteral("/course/ufpe/iluminacao.txt"),
                                 QStringLiteral("/course/ufpe/vaso.byu"));
        if (!parts) QSKIP("course samples not found: set RASTERLAB_SAMPLES to the samples folder");
        // Put the camera at the centre of the vase's bounding box.
        dvec3 lo(1e300), hi(-1e300);
        for (const dvec4& p : parts->object.mesh->positions) {
            lo = glm::min(lo, dvec3(p));
            hi = glm::max(hi, dvec3(p));
        }
        parts->camera.c = (lo + hi) / 2.0;
        auto trace = renderFrame(std::make_shared<const Scene>(makeCourseScene(*parts, {})));
        QVERIFY(trace.ok());
        qInfo("inside the vase: %zu clipped, %zu behind, %zu pixels covered",
              trace->projection->clipped, trace->projection->behind, trace->depth->coveredPixels());
        QVERIFY(trace->projection->clipped > 0);
        QVERIFY(trace->projection->behind > 0);
        QVERIFY(trace->depth->coveredPixels() > 0);
        QVERIFY(allFinite(trace->shading->colour));
        for (const auto& draw : trace->projection->draws)
            for (const dvec2& s : draw.pScreen) QVERIFY(std::isfinite(s.x) && std::isfinite(s.y));
    }
};

QTEST_GUILESS_MAIN(TestRenderer)
#include "tst_renderer.moc"
