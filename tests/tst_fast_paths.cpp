// The fast paths against the plain render, bit for bit: a recording probe (which records
// nothing here) forces the one-pixel, one-thread loops of every stage; renderFrame with 1 to
// 5 threads takes the banded depth test, the vector kernels and the threaded stages. Every
// buffer and every count must be the same. Also: closed surfaces and the back faces that
// culling leaves out.
#include <QtTest>

#include <cstdlib>
#include <cstring>
#include <thread>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

// Sanitizers bring their own allocator, which has none of the C library's settings.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define RL_OWN_ALLOCATOR 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define RL_OWN_ALLOCATOR 1
#endif
#endif

#include "app/documents/default_scene_resource.h"
#include "pipeline/core/frame_memory.h"
#include "pipeline/core/multiversion.h"
#include "pipeline/core/parallel.h"
#include "pipeline/fast/shading_fast.h"
#include "pipeline/io/course_scene.h"
#include "pipeline/render/output_image.h"
#include "pipeline/render/renderer.h"
#include "pipeline/scene/benchmark_scenes.h"
#include "pipeline/scene/mesh_topology.h"
#include "tests/course_scenes.h"
#include "tests/test_support.h"

using namespace rl;

namespace {

std::shared_ptr<const Scene> defaultScene(ShadingModel model, int width, int height) {
    Diagnostics diagnostics;
    auto parts = rasterlab::loadDefaultCourseScene(diagnostics);
    if (!parts) qFatal("%s", parts.error().toString().c_str());
    CourseSceneSettings settings;
    settings.shading = model;
    settings.width = width;
    settings.height = height;
    return std::make_shared<const Scene>(makeCourseScene(parts.value(), settings));
}

// A recording probe that records nothing: its only effect is the plain loops.
RecordingProbe silentProbe() {
    return RecordingProbe::forPixel(-1, -1);
}

QString normalsDifference(const Normals& a, const Normals& b) {
    if (a.skipped != b.skipped) return QStringLiteral("normals skipped");
    if (a.draws.size() != b.draws.size()) return QStringLiteral("normals' draws");
    for (std::size_t d = 0; d < a.draws.size(); ++d) {
        if (a.draws[d].triangle != b.draws[d].triangle || a.draws[d].vertex != b.draws[d].vertex ||
            a.draws[d].degenerateTriangles != b.draws[d].degenerateTriangles)
            return QStringLiteral("normals");
    }
    if (a.degenerateTriangles != b.degenerateTriangles ||
        a.triangleNormalsLeftOut != b.triangleNormalsLeftOut ||
        a.vertexNormalsLeftOut != b.vertexNormalsLeftOut)
        return QStringLiteral("normals' counts");
    return {};
}

// A frame's normals as a frame that keeps only those its draws' shading reads has them
// (RenderOptions::keepForViews false): the others emptied and counted as left out.
FrameTrace withNormalsAsRead(const FrameTrace& a) {
    auto normals = std::make_shared<Normals>(*a.normals);
    for (std::size_t d = 0; d < normals->draws.size(); ++d) {
        const NormalsRead read = normalsRead(a.scene->draws[d]);
        if (!read.triangle) {
            normals->draws[d].triangle.clear();
            ++normals->triangleNormalsLeftOut;
        }
        if (!read.vertex) {
            normals->draws[d].vertex.clear();
            ++normals->vertexNormalsLeftOut;
        }
    }
    FrameTrace out = a;
    out.normals = std::move(normals);
    return out;
}

// Compares two frames buffer by buffer and count by count; the first difference, or empty.
QString difference(const FrameTrace& a, const FrameTrace& b) {
    if (QString n = normalsDifference(*a.normals, *b.normals); !n.isEmpty()) return n;
    if (a.projection->triangles.size() != b.projection->triangles.size())
        return QStringLiteral("screen triangles");
    if (a.projection->backFaces != b.projection->backFaces) return QStringLiteral("back faces");
    if (a.scan->spans != b.scan->spans) return QStringLiteral("spans");
    if (a.scan->spanStart != b.scan->spanStart) return QStringLiteral("span starts");
    if (a.scan->pixels != b.scan->pixels) return QStringLiteral("scanned pixels");
    if (a.depth->depthKept != b.depth->depthKept) return QStringLiteral("z-buffer kept");
    if (a.depth->depth != b.depth->depth) return QStringLiteral("depth buffer");
    if (a.depth->triangle != b.depth->triangle) return QStringLiteral("triangle buffer");
    if (!testing::sameCoveredBarycentrics(*a.depth, *b.depth))
        return QStringLiteral("barycentrics");
    if (a.depth->fragments != b.depth->fragments || a.depth->passed != b.depth->passed ||
        a.depth->outsideDepthRange != b.depth->outsideDepthRange)
        return QStringLiteral("depth counts");
    const Shading& x = *a.shading;
    const Shading& y = *b.shading;
    if (x.colour != y.colour) return QStringLiteral("colour buffer");
    // The stage always keeps the normals it lit with; the fast path when asked.
    if (!y.normal.empty() && x.normal != y.normal) return QStringLiteral("normal buffer");
    if (x.shadedPixels != y.shadedPixels) return QStringLiteral("shaded pixels");
    if (x.phongEvaluations != y.phongEvaluations) return QStringLiteral("Phong evaluations");
    if (x.flipped != y.flipped) return QStringLiteral("flipped normals");
    if (x.lightBehind != y.lightBehind) return QStringLiteral("lights behind");
    if (x.noSpecular != y.noSpecular) return QStringLiteral("no specular");
    if (x.noNormal != y.noNormal) return QStringLiteral("no normal");
    if (x.clampedPixels != y.clampedPixels) return QStringLiteral("clamped pixels");
    return {};
}

// The same, for a frame b rendered without its z-buffer (RenderOptions::keepDepth): every
// other buffer and count as a's.
QString differenceWithoutZBuffer(const FrameTrace& a, const FrameTrace& b) {
    if (b.depth->depthKept || !b.depth->depth.empty()) return QStringLiteral("z-buffer kept");
    FrameTrace withoutZ = a;
    auto depth = std::make_shared<DepthTest>(*a.depth);
    depth->depth = Image<float>();
    depth->depthKept = false;
    withoutZ.depth = depth;
    return difference(withoutZ, b);
}

// The same, for a frame b whose depth test and shading ran in bands
// (fast::depthTestAndShading): no per-pixel buffer but the image and which pixels are
// covered, and the counts a's. Flat and Gouraud draws light every triangle with a fragment
// first, so their lighting counts may be larger; Phong's are the same.
QString differenceInBands(const FrameTrace& a, const FrameTrace& b) {
    if (QString n = normalsDifference(*a.normals, *b.normals); !n.isEmpty()) return n;
    const DepthTest& p = *a.depth;
    const DepthTest& q = *b.depth;
    if (q.fragmentsKept || q.depthKept) return QStringLiteral("per-pixel buffers kept");
    if (!q.triangle.empty() || !q.barycentric.empty() || !q.depth.empty())
        return QStringLiteral("per-pixel buffers not empty");
    if (p.fragments != q.fragments || p.passed != q.passed || p.rejected != q.rejected ||
        p.outsideDepthRange != q.outsideDepthRange)
        return QStringLiteral("depth counts");
    if (p.coveredPixels() != q.coveredPixels()) return QStringLiteral("covered pixels");
    const Shading& x = *a.shading;
    const Shading& y = *b.shading;
    if (y.covered.width() != p.triangle.width() || y.covered.height() != p.triangle.height())
        return QStringLiteral("covered size");
    for (int row = 0; row < p.triangle.height(); ++row)
        for (int col = 0; col < p.triangle.width(); ++col)
            if ((y.covered.at(col, row) != 0) != (p.triangle.at(col, row) != kNoTriangle))
                return QStringLiteral("covered at %1,%2").arg(col).arg(row);
    if (x.colour != y.colour) return QStringLiteral("colour buffer");
    const Conventions& conventions = a.scene->conventions;
    if (colourImage(x, p, conventions).rgba != colourImage(y, q, conventions).rgba)
        return QStringLiteral("image");
    if (x.shadedPixels != y.shadedPixels) return QStringLiteral("shaded pixels");
    if (x.clampedPixels != y.clampedPixels) return QStringLiteral("clamped pixels");
    bool perTriangle = false;
    for (const Draw& draw : a.scene->draws)
        perTriangle = perTriangle || draw.shading != ShadingModel::Phong;
    if (perTriangle ? y.phongEvaluations < x.phongEvaluations
                    : y.phongEvaluations != x.phongEvaluations || y.flipped != x.flipped ||
                          y.lightBehind != x.lightBehind || y.noSpecular != x.noSpecular ||
                          y.noNormal != x.noNormal)
        return QStringLiteral("lighting counts");
    return {};
}

// A tetrahedron with outward normals by the right-hand rule.
Mesh tetrahedron() {
    Mesh m;
    m.positions = {{0, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}

}  // namespace

class TestFastPaths : public QObject {
    Q_OBJECT

private slots:
    // Every test at both kernel widths: eight lanes, and the baseline's four.
    void initTestCase_data() { testing::kernelLaneRows(); }
    void init() { testing::useKernelLanesOfRow(); }
    void cleanupTestCase() { rl::setKernelLanes(0); }

    void frameMemoryIsKept() {
#if defined(RL_OWN_ALLOCATOR)
        QSKIP("a sanitizer's allocator replaces the C library's");
#elif defined(__GLIBC__)
        // After keepFrameMemory, an array of 8 MiB comes from the heap (not a fresh mapping,
        // as above 128 KiB by default), and freeing it leaves the heap as large as it was:
        // the next frame's arrays reuse those pages instead of faulting in new ones.
        keepFrameMemory();
        const struct mallinfo2 before = mallinfo2();
        void* block = std::malloc(std::size_t(8) << 20);
        QVERIFY(block);
        std::memset(block, 1, std::size_t(8) << 20);
        const struct mallinfo2 held = mallinfo2();
        QCOMPARE(held.hblkhd, before.hblkhd);  // not mapped on its own
        QVERIFY(held.arena >= before.arena + (std::size_t(8) << 20) - 4096 ||
                held.arena >= (std::size_t(8) << 20));
        std::free(block);
        const struct mallinfo2 after = mallinfo2();
        QCOMPARE(after.arena, held.arena);  // the heap's top is not trimmed
#else
        QSKIP("only the GNU C library has these settings");
#endif
    }

    void fastPathsEqualThePlainRender_data() {
        QTest::addColumn<std::shared_ptr<const Scene>>("scene");
        for (auto [name, model] :
             {std::pair{"phong", ShadingModel::Phong}, std::pair{"flat", ShadingModel::Flat},
              std::pair{"gouraud", ShadingModel::Gouraud},
              std::pair{"painter", ShadingModel::Painter}}) {
            QTest::newRow((std::string("default scene, ") + name).c_str())
                << defaultScene(model, 400, 300);
            for (const char* bench : {"sphere-1k", "torus-1k", "full-screen"}) {
                auto scene = makeBenchmarkScene(bench, 320, 240, model);
                QVERIFY(scene);
                QTest::newRow((std::string(bench) + ", " + name).c_str())
                    << std::make_shared<const Scene>(std::move(*scene));
            }
        }
        // Seed 001's DDA (the hw2 rules) on scenes with more than 1,024 triangles, so that
        // scan conversion runs on several threads.
        for (const char* bench : {"sphere-100k", "torus-100k"}) {
            auto dda = makeBenchmarkScene(bench, 160, 120, ShadingModel::Phong);
            QVERIFY(dda);
            dda->rules = RasterRules::hw2();
            QTest::newRow((std::string(bench) + ", hw2 rules").c_str())
                << std::make_shared<const Scene>(std::move(*dda));
        }
        // The camera inside the torus: near-plane clipping, no culling, many flipped normals.
        auto inside = makeBenchmarkScene("torus-1k", 320, 240, ShadingModel::Phong);
        QVERIFY(inside);
        inside->camera->c = dvec3(1.0, 0.0, 0.0);
        inside->camera->n = dvec3(0.0, 0.0, 1.0);
        QTest::newRow("inside the torus") << std::make_shared<const Scene>(std::move(*inside));
        // Several lights (the kernel takes one; the others take the plain loop).
        auto lights = makeBenchmarkScene("sphere-1k", 320, 240, ShadingModel::Phong);
        QVERIFY(lights);
        lights->lights.push_back({dvec4(-3.0, 2.0, -4.0, 1.0), vec3(90.0f, 40.0f, 200.0f), {}});
        lights->lights.push_back({dvec4(0.0, 0.0, -1.0, 0.0), vec3(300.0f), {}});  // clamps
        QTest::newRow("three lights") << std::make_shared<const Scene>(std::move(*lights));
        // Directional light, ks = 0, n = 0.5.
        auto matte = makeBenchmarkScene("sphere-1k", 320, 240, ShadingModel::Phong);
        QVERIFY(matte);
        matte->lights[0].pWorld = dvec4(1.0, 1.0, -1.0, 0.0);
        matte->draws[0].material.ks = 0.0f;
        QTest::newRow("directional, no specular") << std::make_shared<const Scene>(Scene(*matte));
        matte->draws[0].material.ks = 0.8f;
        matte->draws[0].material.shininess = 0.5f;
        QTest::newRow("directional, n = 0.5") << std::make_shared<const Scene>(Scene(*matte));
        // A light so far that the square of its distance overflows float (towardLight).
        matte->lights[0].pWorld = dvec4(-220.0, -1.7e25, 0.0, 1.0);
        matte->draws[0].material.shininess = 0.0f;
        QTest::newRow("a light 1.7e25 away") << std::make_shared<const Scene>(std::move(*matte));
        // The lecture slides' lighting: an attenuated spot and a directional light, emission,
        // Blinn-Phong, one-sided (the kernel takes none of these; flat and Gouraud light
        // their triangles and vertices with it too).
        for (auto [name, model] :
             {std::pair{"phong", ShadingModel::Phong}, std::pair{"flat", ShadingModel::Flat},
              std::pair{"gouraud", ShadingModel::Gouraud}}) {
            auto slides = makeBenchmarkScene("sphere-1k", 320, 240, model);
            QVERIFY(slides);
            Light& spot = slides->lights[0];
            spot.attenuation = vec3(1.0f, 0.05f, 0.01f);
            spot.spotDirection = -dvec3(spot.pWorld);
            spot.spotCutoff = 12.0f;
            spot.spotExponent = 3.0f;
            slides->lights.push_back({dvec4(0.0, 1.0, -1.0, 0.0), vec3(80.0f), {}});
            slides->draws[0].material.emission = vec3(10.0f, 0.0f, 20.0f);
            slides->draws[0].specular = SpecularModel::BlinnPhong;
            slides->conventions.flipNormalsTowardViewer = false;
            QTest::newRow((std::string("slides' lighting, ") + name).c_str())
                << std::make_shared<const Scene>(std::move(*slides));
        }
        // HW2 command files: perspective-correct attributes, textures, Lambert, depth range.
        testing::addHw2Rows({"hw2texture", "hw2clipplane", "hw2sun1g", "hw2depth"});
    }

    void fastPathsEqualThePlainRender() {
        QFETCH(std::shared_ptr<const Scene>, scene);
        RenderOptions options;
        options.shading.keepNormals = false;
        auto probe = silentProbe();
        auto plain = traceFrame(scene, options, probe);
        QVERIFY(plain.ok());
        QCOMPARE(plain->threads, 1);
        QVERIFY(plain->depth->coveredPixels() > 0);
        RenderContext context;  // reused buffers must not leak one frame into the next
        for (int threads : {1, 2, 3, 5}) {
            options.threads = threads;
            auto fast = renderFrame(scene, options, &context);
            QVERIFY(fast.ok());
            QCOMPARE(fast->threads, threads);
            const QString diff = difference(*plain, *fast);
            QVERIFY2(diff.isEmpty(),
                     qPrintable(QStringLiteral("%1 thread(s): %2 differ").arg(threads).arg(diff)));
        }
        // Without the z-buffer (each thread's band of depths instead), through the same
        // context and back (each frame let go before the next, so its buffers are reused):
        // every other buffer the same.
        for (int threads : {1, 2, 3}) {
            options.threads = threads;
            {
                options.keepDepth = false;
                auto banded = renderFrame(scene, options, &context);
                QVERIFY(banded.ok());
                const QString diff = differenceWithoutZBuffer(*plain, *banded);
                QVERIFY2(diff.isEmpty(),
                         qPrintable(QStringLiteral("%1 thread(s), no z-buffer: %2 differ")
                                        .arg(threads)
                                        .arg(diff)));
            }
            options.keepDepth = true;
            auto kept = renderFrame(scene, options, &context);
            QVERIFY(kept.ok());
            QCOMPARE(difference(*plain, *kept), QString());
        }
        // In bands where that pays (shadeInBands), through the same context and back: a
        // frame that keeps nothing per pixel after one that kept everything, and the other
        // way round. It keeps only the normals its shading reads, as the bench's frames do.
        // Bands of a chunk's 8 rows (0), and of 4, 1 and 3 (a chunk tested in three bands,
        // the last of 2).
        const bool bands = fast::shadeInBands(*scene, *plain->projection, *plain->scan);
        const FrameTrace plainAsRead = withNormalsAsRead(*plain);
        for (auto [threads, rows] : {std::pair{1, 0}, {2, 4}, {3, 1}, {5, 3}}) {
            options.threads = threads;
            options.bandRows = rows;
            {
                options.keepDepth = false;
                options.keepFragments = false;
                options.keepForViews = false;
                auto banded = renderFrame(scene, options, &context);
                options.keepForViews = true;
                QVERIFY(banded.ok());
                QCOMPARE(banded->depth->fragmentsKept, !bands);
                QCOMPARE(banded->bandRows, !bands ? 0 : rows > 0 ? rows : kRowChunk);
                const QString diff = bands ? differenceInBands(plainAsRead, *banded)
                                           : differenceWithoutZBuffer(plainAsRead, *banded);
                QVERIFY2(diff.isEmpty(),
                         qPrintable(QStringLiteral("%1 thread(s), bands of %2 rows: %3 differ")
                                        .arg(threads)
                                        .arg(rows)
                                        .arg(diff)));
            }
            options.keepDepth = true;
            options.keepFragments = true;
            auto kept = renderFrame(scene, options, &context);
            QVERIFY(kept.ok());
            QCOMPARE(difference(*plain, *kept), QString());
        }
        // With the normals kept, too (the kernels also write them).
        options.shading.keepNormals = true;
        auto probeWithNormals = silentProbe();
        auto plainNormals = traceFrame(scene, options, probeWithNormals);
        options.threads = 2;
        auto fastNormals = renderFrame(scene, options);
        QVERIFY(plainNormals.ok() && fastNormals.ok());
        QVERIFY(!fastNormals->shading->normal.empty());
        QCOMPARE(difference(*plainNormals, *fastNormals), QString());
    }

    void bufferReuseDoesNotLeakAcrossSizes() {
        // A larger frame, then a smaller one, then the larger again, through one context.
        RenderContext context;
        RenderOptions options;
        options.threads = 2;
        const auto large = defaultScene(ShadingModel::Phong, 400, 300);
        const auto small = defaultScene(ShadingModel::Gouraud, 160, 90);
        Image<vec3> expected;
        {
            auto first = renderFrame(large, options, &context);  // let go at the brace
            QVERIFY(first.ok());
            expected = first->shading->colour;
        }
        QVERIFY(renderFrame(small, options, &context).ok());
        auto again = renderFrame(large, options, &context);
        QVERIFY(again.ok());
        QCOMPARE(again->shading->colour, expected);
    }

    void concurrentRendersEqualOneAtATime() {
        // The GUI renders on a worker while the accuracy panel or an export renders on
        // another: three callers at once share the kept threads (parallel.cpp) or, finding
        // them busy, start their own. Every frame must equal the same frame rendered alone.
        std::vector<std::shared_ptr<const Scene>> scenes;
        for (auto [name, model] : {std::pair{"full-screen", ShadingModel::Gouraud},
                                   std::pair{"sphere-1k", ShadingModel::Phong},
                                   std::pair{"torus-1k", ShadingModel::Flat}}) {
            auto scene = makeBenchmarkScene(name, 320, 240, model);
            QVERIFY(scene);
            scenes.push_back(std::make_shared<const Scene>(std::move(*scene)));
        }
        RenderOptions options;
        options.threads = 3;
        std::vector<FrameTrace> alone;
        for (const auto& scene : scenes) {
            auto frame = renderFrame(scene, options);
            QVERIFY(frame.ok());
            alone.push_back(std::move(frame).value());
        }
        constexpr int kFrames = 12;
        std::vector<std::vector<QString>> differences(scenes.size());
        std::vector<std::thread> callers;
        for (std::size_t s = 0; s < scenes.size(); ++s) {
            callers.emplace_back([&, s] {
                RenderContext context;
                for (int i = 0; i < kFrames; ++i) {
                    auto frame = renderFrame(scenes[s], options, &context);
                    differences[s].push_back(frame.ok() ? difference(alone[s], *frame)
                                                        : QStringLiteral("failed"));
                }
            });
        }
        for (auto& caller : callers) caller.join();
        for (std::size_t s = 0; s < scenes.size(); ++s) {
            QCOMPARE(differences[s].size(), std::size_t(kFrames));
            for (int i = 0; i < kFrames; ++i)
                QVERIFY2(differences[s][static_cast<std::size_t>(i)].isEmpty(),
                         qPrintable(QStringLiteral("scene %1, frame %2: %3")
                                        .arg(s)
                                        .arg(i)
                                        .arg(differences[s][static_cast<std::size_t>(i)])));
        }
    }

    void reusedBuffersEqualFreshOnes() {
        // Through one context: an object moving across the screen, one filling it, a
        // different background, and back. Each frame equals a render with fresh buffers
        // (the reused ones clear and repaint only the columns that changed).
        auto base = makeBenchmarkScene("sphere-1k", 320, 240, ShadingModel::Phong);
        QVERIFY(base);
        std::vector<std::shared_ptr<const Scene>> frames;
        for (double shift : {0.0, 1.5, -1.5}) {
            Scene moved = *base;
            moved.camera->c += dvec3(shift, 0.4 * shift, 0.0);
            frames.push_back(std::make_shared<const Scene>(moved));
        }
        auto full = makeBenchmarkScene("full-screen", 320, 240, ShadingModel::Gouraud);
        QVERIFY(full);
        frames.push_back(std::make_shared<const Scene>(*full));
        Scene grey = *base;
        grey.conventions.background = vec4(0.5f, 0.5f, 0.5f, 1.0f);
        frames.push_back(std::make_shared<const Scene>(grey));
        frames.push_back(frames[1]);
        frames.push_back(frames[0]);
        RenderContext context;
        RenderOptions options;
        options.threads = 2;
        for (std::size_t i = 0; i < frames.size(); ++i) {
            auto reused = renderFrame(frames[i], options, &context);
            auto fresh = renderFrame(frames[i], options);
            QVERIFY(reused.ok() && fresh.ok());
            const QString diff = difference(*fresh, *reused);
            QVERIFY2(diff.isEmpty(), qPrintable(QStringLiteral("frame %1: %2").arg(i).arg(diff)));
        }
    }

    void zBufferKeptOrNotThroughReusedBuffers() {
        // Through one context, frames that keep the z-buffer and frames that do not, of a
        // sphere filling the image and of a small one: each equals a fresh render, and the
        // triangle buffer is reused from frame to frame (each frame let go before the next).
        auto full = makeBenchmarkScene("full-screen", 320, 240, ShadingModel::Gouraud);
        auto small = makeBenchmarkScene("sphere-1k", 320, 240, ShadingModel::Gouraud);
        QVERIFY(full && small);
        small->camera->c += dvec3(0.8, 0.3, -2.0);
        const auto a = std::make_shared<const Scene>(std::move(*full));
        const auto b = std::make_shared<const Scene>(std::move(*small));
        const std::vector<std::pair<std::shared_ptr<const Scene>, bool>> frames = {
            {a, true},  {b, false}, {a, true}, {b, false},
            {b, false}, {a, false}, {b, true}, {a, true}};
        RenderContext context;
        RenderOptions options;
        options.threads = 2;
        const void* ids = nullptr;
        for (std::size_t i = 0; i < frames.size(); ++i) {
            const auto& [scene, keep] = frames[i];
            options.keepDepth = keep;
            auto reused = renderFrame(scene, options, &context);
            options.keepDepth = true;
            auto fresh = renderFrame(scene, options);
            QVERIFY(reused.ok() && fresh.ok());
            QCOMPARE(reused->depth->depthKept, keep);
            const QString diff =
                keep ? difference(*fresh, *reused) : differenceWithoutZBuffer(*fresh, *reused);
            QVERIFY2(diff.isEmpty(), qPrintable(QStringLiteral("frame %1: %2").arg(i).arg(diff)));
            const void* now = reused->depth->triangle.pixels().data();
            if (i > 0) QCOMPARE(now, ids);
            ids = now;
        }
        // The small sphere leaves part of what the full one covered to be cleared.
        auto covers = renderFrame(a, options), leaves = renderFrame(b, options);
        QVERIFY(covers.ok() && leaves.ok());
        QVERIFY(leaves->depth->coveredPixels() > 0);
        QVERIFY(leaves->depth->coveredPixels() < covers->depth->coveredPixels() / 2);
    }

    void closedSurfaces_data() {
        QTest::addColumn<int>("expected");
        QTest::addColumn<QString>("change");
        QTest::newRow("tetrahedron") << 1 << QString();
        QTest::newRow("turned inside out") << -1 << QStringLiteral("flip");
        QTest::newRow("a face missing") << 0 << QStringLiteral("open");
        QTest::newRow("one face wound the wrong way") << 0 << QStringLiteral("one");
        QTest::newRow("a repeated corner") << 0 << QStringLiteral("repeat");
        QTest::newRow("a third face on an edge") << 0 << QStringLiteral("fin");
        QTest::newRow("two, one inside out") << 0 << QStringLiteral("pair");
        QTest::newRow("two, both outward") << 1 << QStringLiteral("twins");
    }

    void closedSurfaces() {
        QFETCH(int, expected);
        QFETCH(QString, change);
        Mesh m = tetrahedron();
        const auto addCopy = [&](bool flip) {
            const auto offset = static_cast<std::uint32_t>(m.positions.size());
            for (std::size_t v = 0; v < 4; ++v)
                m.positions.push_back(m.positions[v] + dvec4(5.0, 0.0, 0.0, 0.0));
            for (std::size_t t = 0; t < 4; ++t) {
                auto tri = m.triangles[t];
                if (flip) std::swap(tri[1], tri[2]);
                m.triangles.push_back({tri[0] + offset, tri[1] + offset, tri[2] + offset});
            }
        };
        if (change == QStringLiteral("flip"))
            for (auto& t : m.triangles) std::swap(t[1], t[2]);
        if (change == QStringLiteral("open")) m.triangles.pop_back();
        if (change == QStringLiteral("one")) std::swap(m.triangles[0][1], m.triangles[0][2]);
        if (change == QStringLiteral("repeat")) m.triangles[0][1] = m.triangles[0][0];
        if (change == QStringLiteral("fin")) {
            m.positions.push_back({1, 1, 1, 1});
            m.triangles.push_back({0, 1, 4});
        }
        if (change == QStringLiteral("pair")) addCopy(true);
        if (change == QStringLiteral("twins")) addCopy(false);
        QCOMPARE(closedSurfaceWinding(m), expected);
    }

    void generatedMeshesAreClosed() {
        QCOMPARE(closedSurfaceWinding(*uvSphere(25, 21)), 1);
        QCOMPARE(closedSurfaceWinding(*torusMesh(25, 20)), 1);
        Diagnostics diagnostics;
        auto parts = rasterlab::loadDefaultCourseScene(diagnostics);
        QVERIFY(parts);
        QCOMPARE(parts->object.mesh->closedWinding, closedSurfaceWinding(*parts->object.mesh));
    }

    void bandsWhenPixelsOutnumberLitPoints() {
        // In bands, a flat draw lights each triangle with a fragment before the depth test, a
        // Gouraud draw each vertex of one; bands are chosen only when those points are at most
        // one in fast::kBandsFragmentsPerPoint fragments (shadeInBands bounds them from above
        // without going through the triangles).
        const auto check = [](const char* name, int width, int height, ShadingModel model) {
            auto scene = makeBenchmarkScene(name, width, height, model);
            if (!scene) qFatal("no %s", name);
            auto shared = std::make_shared<const Scene>(std::move(*scene));
            RenderOptions options;
            options.keepDepth = false;
            options.keepFragments = false;
            options.threads = 2;
            auto frame = renderFrame(shared, options);
            if (!frame.ok()) qFatal("%s", frame.error().toString().c_str());
            const bool bands = !frame->depth->fragmentsKept;
            if (fast::shadeInBands(*shared, *frame->projection, *frame->scan) != bands)
                qFatal("%s %dx%d: shadeInBands disagrees with the frame", name, width, height);
            // The points lit ahead, counted one by one.
            std::vector<std::uint8_t> vertexLit(frame->projection->draws[0].pView.size(), 0);
            std::size_t points = 0;
            for (std::size_t t = 0; t + 1 < frame->scan->spanStart.size(); ++t) {
                if (frame->scan->spanStart[t] == frame->scan->spanStart[t + 1]) continue;
                if (model == ShadingModel::Flat) ++points;
                if (model != ShadingModel::Gouraud) continue;
                for (std::uint32_t v : frame->projection->triangles[t].v)
                    if (!vertexLit[v]) {
                        vertexLit[v] = 1;
                        ++points;
                    }
            }
            if (bands && points * fast::kBandsFragmentsPerPoint > frame->depth->fragments)
                qFatal("%s %dx%d: in bands with %zu points for %zu fragments", name, width, height,
                       points, frame->depth->fragments);
            return bands;
        };
        // A sphere filling the screen: 76,800 fragments, at most 3,000 points.
        QVERIFY(check("full-screen", 320, 240, ShadingModel::Gouraud));
        QVERIFY(check("full-screen", 320, 240, ShadingModel::Flat));
        // The 100k sphere (about 50,000 vertices, half as many facing the camera as its
        // triangles with a fragment): at 960x720, 234,933 fragments, in bands in both modes;
        // at 640x480, 148,599 fragments, flat's triangles with a fragment are few enough, but
        // not Gouraud's bound (every vertex of the draw).
        QVERIFY(check("sphere-100k", 960, 720, ShadingModel::Gouraud));
        QVERIFY(check("sphere-100k", 960, 720, ShadingModel::Flat));
        QVERIFY(!check("sphere-100k", 640, 480, ShadingModel::Gouraud));
        QVERIFY(check("sphere-100k", 640, 480, ShadingModel::Flat));
        // 100,000 triangles on 32x24 pixels: about a fragment per triangle that has one.
        QVERIFY(!check("sphere-100k", 32, 24, ShadingModel::Gouraud));
        QVERIFY(!check("sphere-100k", 32, 24, ShadingModel::Flat));
        // Phong lights nothing before the depth test: always in bands.
        QVERIFY(check("sphere-100k", 32, 24, ShadingModel::Phong));
    }

    void hiddenBackFacesAreLeftOut() {
        // A unit sphere seen from outside: the triangles left out are exactly those whose
        // normal points away from the camera, and the image hardly changes.
        auto culled = makeBenchmarkScene("sphere-1k", 320, 240, ShadingModel::Phong);
        QVERIFY(culled && culled->cullHiddenBackFaces);
        Scene all = *culled;
        all.cullHiddenBackFaces = false;
        auto withCulling = renderFrame(std::make_shared<const Scene>(*culled));
        auto without = renderFrame(std::make_shared<const Scene>(all));
        QVERIFY(withCulling.ok() && without.ok());
        QCOMPARE(without->projection->backFaces, std::size_t(0));
        // The course's view basis (U, V, N) is left-handed, so the view transform mirrors
        // and the outward normal in view space is (c - a) x (b - a).
        const auto& pView = withCulling->view->pView[0];
        QVERIFY(glm::determinant(dmat3(withCulling->view->viewFromModel[0])) < 0.0);
        std::size_t away = 0;
        for (const auto& t : culled->draws[0].mesh->triangles) {
            const dvec3 a(pView[t[0]]), b(pView[t[1]]), c(pView[t[2]]);
            away += glm::dot(glm::cross(c - a, b - a), a) > 0.0 ? 1 : 0;
        }
        QVERIFY(away > 550 && away < 700);  // about 1 - (1 - r/d) / 2 of them, d = 2.98 r
        QCOMPARE(withCulling->projection->backFaces, away);
        QCOMPARE(withCulling->projection->triangles.size() + away,
                 without->projection->triangles.size());
        // Only silhouette pixels change, where the course's integer vertices let a back face
        // poke out beside the front faces or win the depth test (why course files draw
        // every triangle unless asked).
        const std::size_t coveredWith = withCulling->depth->coveredPixels();
        const std::size_t coveredWithout = without->depth->coveredPixels();
        QVERIFY(coveredWith <= coveredWithout &&
                (coveredWithout - coveredWith) * 1000 < coveredWithout);
        int changed = 0;
        for (int y = 0; y < 240; ++y)
            for (int x = 0; x < 320; ++x)
                changed +=
                    withCulling->shading->colour.at(x, y) != without->shading->colour.at(x, y) ? 1
                                                                                               : 0;
        qInfo("hidden back faces left out: %d of %zu covered pixels change, %zu uncovered", changed,
              coveredWithout, coveredWithout - coveredWith);
        QVERIFY(changed * 100 < int(without->depth->coveredPixels()));
        QVERIFY(withCulling->scan->pixels < without->scan->pixels);
        bool noted = false;
        for (const Diagnostic& d : withCulling->diagnostics.items())
            noted = noted || d.message.find("away from the camera") != std::string::npos;
        QVERIFY(noted);
    }

    void backFacesStayWhenTheSurfaceIsOpenOrCut() {
        // The camera inside the sphere: every vertex is not beyond the near plane.
        auto inside = makeBenchmarkScene("sphere-1k", 160, 120, ShadingModel::Phong);
        QVERIFY(inside);
        inside->camera->c = dvec3(0.0, 0.0, 0.0);
        auto trace = renderFrame(std::make_shared<const Scene>(std::move(*inside)));
        QVERIFY(trace.ok());
        QCOMPARE(trace->projection->backFaces, std::size_t(0));
        QVERIFY(trace->depth->coveredPixels() == 160u * 120u);  // the inside of the sphere
        // A clip plane cuts the surface open: the back faces behind the cut show.
        auto cut = makeBenchmarkScene("sphere-1k", 160, 120, ShadingModel::Phong);
        QVERIFY(cut);
        cut->draws[0].clipPlanes.push_back(dvec4(0.0, 0.0, -1.0, 3.0));
        auto cutTrace = renderFrame(std::make_shared<const Scene>(std::move(*cut)));
        QVERIFY(cutTrace.ok());
        QCOMPARE(cutTrace->projection->backFaces, std::size_t(0));
        // Course files draw every triangle unless asked.
        const auto course = defaultScene(ShadingModel::Phong, 160, 120);
        QVERIFY(!course->cullHiddenBackFaces);
        auto courseTrace = renderFrame(course);
        QVERIFY(courseTrace.ok());
        QCOMPARE(courseTrace->projection->backFaces, std::size_t(0));
    }
};

QTEST_GUILESS_MAIN(TestFastPaths)
#include "tst_fast_paths.moc"
