// The whole frame: all seven stages in order, recording and plain runs giving identical
// buffers, and the course's real files rendered with no holes, no NaN and a highlight.
#include <QtTest>

#include "course_scene.h"
#include "default_scene_resource.h"
#include "output_image.h"
#include "renderer.h"
#include "test_support.h"

using namespace rl;

namespace {

std::shared_ptr<const Scene> defaultScene(ShadingModel model = ShadingModel::Phong,
                                          int width = 800, int height = 600) {
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
            QCOMPARE((*traced)->depth->barycentric, plain->depth->barycentric);
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
        QCOMPARE(spans, std::size_t(plain->scan->spanStart[visible + 1] - plain->scan->spanStart[visible]));
        std::size_t covered = 0, visiblePixels = 0;
        for (std::size_t k = plain->scan->spanStart[visible]; k < plain->scan->spanStart[visible + 1]; ++k)
            covered += std::size_t(plain->scan->spans[k].xEnd - plain->scan->spans[k].xBegin);
        for (std::uint32_t t : plain->depth->triangle.pixels()) visiblePixels += t == visible ? 1 : 0;
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
        for (const auto& [name, model] : {std::pair{"phong", ShadingModel::Phong},
                                          std::pair{"flat", ShadingModel::Flat},
                                          std::pair{"gouraud", ShadingModel::Gouraud}}) {
            QTest::newRow(qPrintable(QStringLiteral("calice2 ") + QString::fromUtf8(name)))
                << "/course/ufpe/calice2.byu" << "/course/ufpe/calice2.cfg" << int(model);
            QTest::newRow(qPrintable(QStringLiteral("vaso ") + QString::fromUtf8(name)))
                << "/course/ufpe/vaso.byu" << "/course/ufpe/vaso.cfg" << int(model);
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
              trace->projection->clipped, trace->projection->behind,
              trace->depth->coveredPixels());
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
