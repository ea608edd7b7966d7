// Stepping is replay: the fragments of a frame in drawing order, the cursor's stops at each
// granularity worked out by hand on a small scene, breakpoints, and the buffers at the end of
// the replay equal to the frame's, bit for bit, whichever way the cursor went there.
#include <QtTest>

#include <random>

#include "pipeline/render/output_image.h"
#include "pipeline/render/renderer.h"
#include "pipeline/render/replay.h"
#include "pipeline/scene/benchmark_scenes.h"
#include "tests/course_scenes.h"
#include "tests/test_support.h"

using namespace rl;

namespace {

// testing::handScene, with a specular term: ks = 0.5, n = 2.
std::shared_ptr<const Scene> handScene(ShadingModel model = ShadingModel::Phong) {
    Scene scene = testing::handScene(model);
    scene.draws[0].material.ks = 0.5f;
    scene.draws[0].material.shininess = 2.0f;
    return std::make_shared<const Scene>(std::move(scene));
}

std::shared_ptr<const FrameTrace> render(std::shared_ptr<const Scene> scene, int threads = 2) {
    RenderOptions options;
    options.threads = threads;
    return testing::renderTrace(std::move(scene), options);
}

using testing::replayOf;

QString at(ReplayCursor c) {
    return QStringLiteral("(%1, %2)").arg(c.rows).arg(c.fragments);
}

}  // namespace

class TestReplay : public QObject {
    Q_OBJECT
private slots:
    void rowsAndFragmentsOfTheHandScene() {
        const auto replay = replayOf(render(handScene()));
        const auto& rows = replay->rows();
        const auto& fragments = replay->fragments();
        QCOMPARE(rows.size(), std::size_t(19));  // 5 + 5 + 5 + 4
        QCOMPARE(fragments.size(), std::size_t(49));
        QCOMPARE(replay->writtenCount(), std::size_t(33));
        QCOMPARE(replay->writtenBefore(0), std::size_t(0));
        QCOMPARE(replay->writtenBefore(20), std::size_t(15));  // triangle 0, none of 1
        QCOMPARE(replay->writtenBefore(31), std::size_t(16));
        QCOMPARE(replay->writtenBefore(49), std::size_t(33));
        // Triangle 0, row 2: pixels 0..2, fragments 9..11.
        QCOMPARE(rows[2].y, 2);
        QCOMPARE(rows[2].xBegin, 0);
        QCOMPARE(rows[2].xEnd, 3);
        QCOMPARE(rows[2].fragmentBegin, 9u);
        QCOMPARE(rows[2].fragmentEnd, 12u);
        QCOMPARE(rows[2].xLeft, 0.0);
        QCOMPARE(rows[2].xRight, 2.0);
        // Triangle 1 is rejected everywhere, behind triangle 0 (depth 2 against 1).
        for (std::uint32_t i = 15; i < 30; ++i) {
            QCOMPARE(fragments[i].triangle, 1u);
            QVERIFY(fragments[i].verdict == FragmentVerdict::Rejected);
            QCOMPARE(fragments[i].depth, 2.0f);
            QCOMPARE(fragments[i].stored, 1.0f);
        }
        // Triangle 2 writes (2, 2) again: its second write, replacing triangle 0's fragment
        // (row 2 of triangle 0, x = 2: fragment 11).
        const std::uint32_t overwrite = 30;
        QCOMPARE(fragments[overwrite].x, 2);
        QCOMPARE(fragments[overwrite].y, 2);
        QVERIFY(fragments[overwrite].verdict == FragmentVerdict::Written);
        QCOMPARE(fragments[overwrite].writeNumber, 2u);
        QCOMPARE(fragments[overwrite].previous, 11u);
        QCOMPARE(fragments[overwrite].stored, 1.0f);
        QCOMPARE(fragments[overwrite].depth, 0.5f);
        // Triangle 3: rows 0..3, the second empty; (6, 2) rejected behind triangle 2.
        QCOMPARE(replay->firstRow(3), 15u);
        QCOMPARE(replay->endRow(3), 19u);
        QVERIFY(!rows[15].empty());
        QVERIFY(rows[16].empty());
        QCOMPARE(rows[16].y, 1);
        RL_COMPARE_NEAR(rows[16].xLeft, 5.0 + 1.0 / 3.0, 1e-12);
        RL_COMPARE_NEAR(rows[16].xRight, 5.0 + 2.0 / 3.0, 1e-12);
        QCOMPARE(rows[16].fragmentBegin, rows[16].fragmentEnd);
        const ReplayFragment& hidden = fragments[rows[17].fragmentBegin];
        QCOMPARE(hidden.x, 6);
        QCOMPARE(hidden.y, 2);
        QVERIFY(hidden.verdict == FragmentVerdict::Rejected);
        QCOMPARE(hidden.stored, 0.5f);
        // The history of (2, 2): triangle 0 writes, 1 is rejected, 2 writes.
        const std::vector<std::uint32_t> history = replay->fragmentsAt(2, 2);
        QCOMPARE(history.size(), std::size_t(3));
        QCOMPARE(fragments[history[0]].triangle, 0u);
        QCOMPARE(fragments[history[1]].triangle, 1u);
        QCOMPARE(fragments[history[2]].triangle, 2u);
    }

    void stopsAtEachGranularity() {
        const auto replay = replayOf(render(handScene()));
        using G = StepGranularity;
        const ReplayCursor start = replay->start();
        QCOMPARE(replay->end(), (ReplayCursor{19, 49}));
        // Pixel: one fragment at a time; back over the start of a row.
        QCOMPARE(replay->next(start, G::Pixel), (ReplayCursor{1, 1}));
        QCOMPARE(replay->next({1, 5}, G::Pixel), (ReplayCursor{2, 6}));
        QCOMPARE(replay->previous({2, 6}, G::Pixel), (ReplayCursor{1, 5}));
        QCOMPARE(replay->previous({2, 5}, G::Pixel), (ReplayCursor{1, 5}));
        QCOMPARE(replay->previous({1, 1}, G::Pixel), start);
        // Scanline: the end of each row, the empty one included.
        QCOMPARE(replay->next(start, G::Scanline), (ReplayCursor{1, 5}));
        QCOMPARE(replay->next({1, 5}, G::Scanline), (ReplayCursor{2, 9}));
        QCOMPARE(replay->next({2, 7}, G::Scanline), (ReplayCursor{2, 9}));      // mid-row
        QCOMPARE(replay->next({16, 46}, G::Scanline), (ReplayCursor{17, 46}));  // empty row
        QCOMPARE(replay->previous({2, 7}, G::Scanline), (ReplayCursor{1, 5}));
        QCOMPARE(replay->previous({2, 9}, G::Scanline), (ReplayCursor{1, 5}));
        // Span: rows with pixels only; the empty row 16 is passed over both ways.
        QCOMPARE(replay->next({16, 46}, G::Span), (ReplayCursor{18, 47}));
        QCOMPARE(replay->previous({18, 47}, G::Span), (ReplayCursor{16, 46}));
        QCOMPARE(replay->next({16, 46}, G::Scanline), (ReplayCursor{17, 46}));
        // Triangle: the end of each triangle's last row.
        QCOMPARE(replay->next(start, G::Triangle), (ReplayCursor{5, 15}));
        QCOMPARE(replay->next({5, 15}, G::Triangle), (ReplayCursor{10, 30}));
        QCOMPARE(replay->next({12, 35}, G::Triangle), (ReplayCursor{15, 45}));
        QCOMPARE(replay->next({15, 45}, G::Triangle), replay->end());
        QCOMPARE(replay->previous({10, 30}, G::Triangle), (ReplayCursor{5, 15}));
        QCOMPARE(replay->previous({12, 35}, G::Triangle), (ReplayCursor{10, 30}));
        QCOMPARE(replay->previous({5, 15}, G::Triangle), start);
        // The ends stay where they are.
        QCOMPARE(replay->next(replay->end(), G::Pixel), replay->end());
        QCOMPARE(replay->previous(start, G::Triangle), start);
        // Every stop is a valid cursor, and stepping forward then back returns.
        for (G g : {G::Triangle, G::Scanline, G::Span, G::Pixel}) {
            ReplayCursor c = start;
            int steps = 0;
            while (c != replay->end()) {
                const ReplayCursor n = replay->next(c, g);
                QVERIFY2(c < n, qPrintable(at(c)));
                QVERIFY(replay->valid(n));
                QCOMPARE(replay->previous(n, g), c);
                c = n;
                ++steps;
            }
            const int expected = g == G::Triangle   ? 4
                                 : g == G::Scanline ? 19
                                 : g == G::Span     ? 18
                                                    : 49;
            QCOMPARE(steps, expected);
        }
        QCOMPARE(replay->currentFragment({2, 6}), std::optional<std::uint32_t>(5u));
        QCOMPARE(replay->currentFragment({2, 5}), std::nullopt);
        QCOMPARE(replay->currentRow({2, 5})->y, 1);
    }

    void breakpoints() {
        const auto replay = replayOf(render(handScene()));
        using K = Breakpoint::Kind;
        auto hit = [&](Breakpoint bp, ReplayCursor from = {}) {
            return replay->findBreakpoint(from, {bp});
        };
        // Triangle 2: its first row reached, nothing of it drawn.
        auto h = hit({K::Triangle, 2});
        QVERIFY(h);
        QCOMPARE(h->cursor, (ReplayCursor{11, 30}));
        // Scanline 3: triangle 0's row 3 (fragments 12.. begin there); from there on, the next.
        Breakpoint scan{K::Scanline};
        scan.y = 3;
        QCOMPARE(hit(scan)->cursor, (ReplayCursor{4, 12}));
        QCOMPARE(hit(scan, {4, 12})->cursor, (ReplayCursor{9, 27}));
        // First depth rejection at (1, 1): triangle 1, row 1 (fragments 20..23), x = 1.
        Breakpoint reject{K::DepthRejection};
        reject.x = 1;
        reject.y = 1;
        h = hit(reject);
        QCOMPARE(h->fragment, 21u);
        QCOMPARE(h->cursor, (ReplayCursor{7, 22}));
        // N.L < 0 at (1, 1): the light is behind; triangle 0 writes it first (fragment 6).
        Breakpoint behind{K::LightBehind};
        behind.x = 1;
        behind.y = 1;
        h = hit(behind);
        QCOMPARE(h->fragment, 6u);
        QCOMPARE(h->cursor, (ReplayCursor{2, 7}));
        QVERIFY(!hit(behind, h->cursor));  // nothing writes (1, 1) again
        // A pixel written the second time: (2, 2), by triangle 2.
        Breakpoint twice{K::NthWrite};
        twice.n = 2;
        h = hit(twice);
        QCOMPARE(h->fragment, 30u);
        QCOMPARE(h->cursor, (ReplayCursor{11, 31}));
        twice.n = 3;
        QVERIFY(!hit(twice));
        // The earliest of several; disabled ones are left out.
        std::vector<Breakpoint> all = {{K::Triangle, 2}, reject};
        QCOMPARE(replay->findBreakpoint({}, all)->breakpoint, std::size_t(1));
        all[1].enabled = false;
        QCOMPARE(replay->findBreakpoint({}, all)->breakpoint, std::size_t(0));
    }

    void shadingSamplesOfFragments() {
        const auto replay = replayOf(render(handScene()));
        // (1, 1) of triangle 0: N turned toward the viewer (0, 0, -1); the light behind.
        const std::vector<ShadeEvent> events = replay->shade({6});
        QCOMPARE(events.size(), std::size_t(1));
        QCOMPARE(events[0].x, 1);
        QCOMPARE(events[0].y, 1);
        QCOMPARE(events[0].triangle, 0u);
        QVERIFY(events[0].sample.lightBehind);
        RL_COMPARE_VEC(events[0].sample.n, vec3(0.0f, 0.0f, -1.0f), 1e-6);
        RL_COMPARE_VEC(events[0].sample.ambient, vec3(10.0f), 1e-6);  // Ia ka = 10 * 1
        RL_COMPARE_VEC(events[0].sample.diffuse, vec3(0.0f), 0.0);
        RL_COMPARE_VEC(replay->fragments()[6].colour, vec3(10.0f), 1e-6);
    }

    void theEndIsTheFrame_data() {
        QTest::addColumn<std::shared_ptr<const Scene>>("scene");
        QTest::newRow("hand") << handScene();
        for (ShadingModel model : {ShadingModel::Phong, ShadingModel::Gouraud, ShadingModel::Flat})
            for (RuleSet rules : {RuleSet::Course, RuleSet::Gpu})
                QTest::newRow(qPrintable(QStringLiteral("trefoil %1 %2")
                                             .arg(QLatin1String(shadingModelName(model)),
                                                  QLatin1String(ruleSetName(rules)))))
                    << testing::defaultCourseScene(model, rules, 200, 150);
        auto sphere = makeBenchmarkScene("sphere-1k", 160, 120, ShadingModel::Phong);
        QVERIFY(sphere);
        QTest::newRow("sphere, back faces culled")
            << std::make_shared<const Scene>(std::move(*sphere));
        testing::addHw2Rows({"hw2depth", "hw2texture", "hw2sun1g", "hw2clipplane"});
    }

    void theEndIsTheFrame() {
        QFETCH(std::shared_ptr<const Scene>, scene);
        const auto trace = render(scene);
        const auto replay = replayOf(trace);
        const Rgba8Image frameImage =
            colourImage(*trace->shading, *trace->depth, scene->conventions);
        QCOMPARE(replay->fragments().size(), trace->depth->fragments);
        QCOMPARE(replay->writtenCount(), trace->depth->passed);
        QCOMPARE(replay->writtenBefore(static_cast<std::uint32_t>(replay->fragments().size())),
                 trace->depth->passed);
        const auto half = static_cast<std::uint32_t>(replay->fragments().size() / 2 + 3);
        std::size_t written = 0;
        for (std::uint32_t i = 0; i < half; ++i)
            written += replay->fragments()[i].verdict == FragmentVerdict::Written ? 1 : 0;
        QCOMPARE(replay->writtenBefore(half), written);
        // Forward to the end, by spans.
        ReplayState state(replay);
        while (state.cursor() != replay->end())
            state.seek(replay->next(state.cursor(), StepGranularity::Span));
        QVERIFY(state.image() == frameImage);
        QVERIFY(state.depth() == trace->depth->depth);
        for (int y = 0; y < scene->height; ++y)
            for (int x = 0; x < scene->width; ++x)
                QCOMPARE(state.triangleAt(x, y), trace->depth->triangle.at(x, y));
        QVERIFY(testing::sameCoveredBarycentrics(state.buffers(), *trace->depth));
        // Back to the start, by triangles: the cleared buffers.
        while (state.cursor() != replay->start())
            state.seek(replay->previous(state.cursor(), StepGranularity::Triangle));
        const ReplayState fresh(replay);
        QVERIFY(state.image() == fresh.image());
        QVERIFY(state.depth() == fresh.depth());
        // A jump to the end (from the end's buffers) is the frame as well.
        state.seek(replay->end());
        QVERIFY(state.image() == frameImage);
    }

    void anyPathGivesTheSameBuffers() {
        const auto replay = replayOf(
            render(testing::defaultCourseScene(ShadingModel::Phong, RuleSet::Course, 160, 120)));
        const auto count = static_cast<std::uint32_t>(replay->fragments().size());
        QVERIFY(count > 5000);
        std::mt19937 random(7);
        ReplayState walker(replay);
        for (int k = 0; k < 40; ++k) {
            const ReplayCursor target = replay->atFragment(random() % (count + 1));
            walker.seek(target);
            ReplayState direct(replay);
            direct.seek(target);
            QCOMPARE(walker.cursor(), target);
            QVERIFY2(walker.image() == direct.image(), qPrintable(at(target)));
            QVERIFY(walker.depth() == direct.depth());
            QVERIFY(walker.writer() == direct.writer());
        }
    }

    void depthOnlyComesNearer() {
        // Along the replay, a pixel's depth never grows (z < stored writes).
        const auto replay = replayOf(
            render(testing::defaultCourseScene(ShadingModel::Gouraud, RuleSet::Course, 120, 90)));
        ReplayState state(replay);
        Image<float> before = state.depth();
        while (state.cursor() != replay->end()) {
            state.seek(replay->next(state.cursor(), StepGranularity::Scanline));
            const auto& now = state.depth().pixels();
            for (std::size_t i = 0; i < now.size(); ++i) QVERIFY(now[i] <= before.pixels()[i]);
            before = state.depth();
        }
    }

    void writtenCountsAtEveryThousandAndTwentyFourth() {
        // A 32x32 screen covered by two triangles under the GPU's rules (pixel centres, top-left
        // fill): each of the 1024 pixels is one fragment, written (the buffer starts at +inf).
        // The counts are kept every 1024 fragments: the end falls on one of those marks.
        // Axis camera: screen x = (1 - x) 16, y = (1 - y) 16 at z = 1.
        auto mesh = testing::makeMesh({{1, 1, 1}, {-1, 1, 1}, {-1, -1, 1}, {1, -1, 1}},
                                      {{0, 1, 2}, {0, 2, 3}});
        Scene scene = testing::makeScene(testing::axisCamera(), mesh, 32, 32);
        scene.rules = rulesOf(RuleSet::Gpu);
        const auto replay = replayOf(render(std::make_shared<const Scene>(std::move(scene))));
        QCOMPARE(replay->fragments().size(), std::size_t(1024));
        QCOMPARE(replay->writtenCount(), std::size_t(1024));
        QCOMPARE(replay->writtenBefore(1023), std::size_t(1023));
        QCOMPARE(replay->writtenBefore(1024), std::size_t(1024));
        QCOMPARE(replay->writtenBefore(5000), std::size_t(1024));  // past the end: all of them
    }

    void tooManyFragmentsIsAClearError() {
        const auto trace = render(handScene());
        ReplayLimits limits;
        limits.maxFragments = 40;
        auto replay = FrameReplay::build(trace, limits);
        QVERIFY(!replay);
        QCOMPARE(QString::fromStdString(replay.error().toString()),
                 QStringLiteral("<test>: stepping keeps at most 40 fragments, and this frame has "
                                "49: the final image and the views still work"));
        std::atomic<bool> cancel{true};
        QVERIFY(!FrameReplay::build(trace, {}, &cancel));
    }
};

QTEST_GUILESS_MAIN(TestReplay)
#include "tst_replay.moc"
