// The painter's algorithm (seed 004, painter.h): the sort order, the painting without a depth
// test, and where it disagrees with the z-buffer, on scenes whose numbers are worked out by
// hand. The axis camera (test_support.h) sees world (x, y, z) at view (-x, y, z); on an 8x8
// screen pixel x = (int)((1 - x/z) 4), y = (int)((1 - y/z) 4).
#include <QtTest>

#include <cmath>

#include "pipeline/analysis/painter.h"
#include "pipeline/render/explain.h"
#include "pipeline/render/output_image.h"
#include "pipeline/render/renderer.h"
#include "pipeline/render/replay.h"
#include "tests/test_support.h"

using namespace rl;
using testing::renderTrace;

namespace {

using testing::ambientDraw;

Scene twoDraws(Draw first, Draw second) {
    Scene scene = testing::makeScene(testing::axisCamera(), first.mesh, 8, 8);
    scene.draws = {std::move(first), std::move(second)};
    return scene;
}

// painterFailureScene(): the painter's failure, L painted before S though nearer at three
// pixels (numbers in test_support.h).
using testing::painterFailureScene;

// A square at z = 1 cut along its diagonal into two draws: T0 (ka = 1) on screen (0,0) (4,0)
// (0,4), T1 (ka = 0.5) on (4,0) (4,4) (0,4). Barycentres: T0 view (-2/3, 2/3, 1), |b| =
// sqrt(17)/3 = 1.37437; T1 view (-1/3, 1/3, 1), |b| = sqrt(11)/3 = 1.10554. T0 is painted
// first. The course's inclusive rule gives both the five pixels of the diagonal x + y = 4, at
// the same depth 1: the z-buffer keeps the first drawn (T0), the painter the last (T1).
Scene sharedEdgeScene() {
    return twoDraws(
        ambientDraw("T0", testing::makeMesh({{1, 1, 1}, {0, 1, 1}, {1, 0, 1}}, {{0, 1, 2}}), 1.0f),
        ambientDraw("T1", testing::makeMesh({{0, 1, 1}, {0, 0, 1}, {1, 0, 1}}, {{0, 1, 2}}), 0.5f));
}

std::shared_ptr<const Scene> shared(Scene scene) {
    return std::make_shared<const Scene>(std::move(scene));
}

}  // namespace

class TestPainter : public QObject {
    Q_OBJECT

private slots:
    void names() {
        QCOMPARE(std::string(shadingModelName(ShadingModel::Painter)), std::string("painter"));
        QCOMPARE(shadingModelFromName("painter"), std::optional(ShadingModel::Painter));
        QVERIFY(litPerTriangle(ShadingModel::Painter) && litPerTriangle(ShadingModel::Flat));
        QVERIFY(!litPerTriangle(ShadingModel::Phong));
        Scene scene = testing::handScene(ShadingModel::Flat);
        QVERIFY(!paintersAlgorithm(scene));
        scene.draws[0].shading = ShadingModel::Painter;
        QVERIFY(paintersAlgorithm(scene));
    }

    void sortOrderOfTheHandScene() {
        // handScene's triangles (test_support.h), view barycentres and distances:
        //   0: world mean (2/3, 2/3, 1), view (-2/3, 2/3, 1): sqrt(17)/3 = 1.37437
        //   1: (4/3, 4/3, 2), view (-4/3, 4/3, 2): 2 sqrt(17)/3 = 2.74874
        //   2: (1/12, 1/12, 0.5), view (-1/12, 1/12, 0.5): sqrt(38)/12 = 0.51370
        //   3: (-0.5, 0.5, 1), view (0.5, 0.5, 1): sqrt(1.5) = 1.22474
        // Far to near: 1, 0, 3, 2.
        const auto zBuffer = renderTrace(shared(testing::handScene(ShadingModel::Flat)));
        const std::vector<std::uint32_t> expected{1, 0, 3, 2};
        QCOMPARE(painterOrder(*zBuffer->scene, *zBuffer->projection), expected);
        const auto painted = renderTrace(shared(testing::handScene(ShadingModel::Painter)));
        QVERIFY(painted->depth->painted);
        QVERIFY(!zBuffer->depth->painted);
        const double distances[] = {2.0 * std::sqrt(17.0) / 3.0, std::sqrt(17.0) / 3.0,
                                    std::sqrt(1.5), std::sqrt(38.0) / 12.0};
        QCOMPARE(painted->projection->triangles.size(), std::size_t(4));
        for (std::uint32_t rank = 0; rank < 4; ++rank) {
            QCOMPARE(painted->projection->triangles[rank].source, expected[rank]);
            RL_COMPARE_NEAR(painterDistance(*painted->scene, *painted->projection, rank),
                            distances[rank], 1e-12);
        }
        RL_COMPARE_VEC(
            viewBarycentre(painted->projection->draws[0], *painted->scene->draws[0].mesh, 3),
            dvec3(0.5, 0.5, 1.0), 1e-12);
        // The z-buffer's frame keeps the mesh order.
        for (std::uint32_t t = 0; t < 4; ++t) QCOMPARE(zBuffer->projection->triangles[t].source, t);
    }

    void rightOrderEqualsTheZBuffer() {
        // In handScene the nearer of every overlap is also nearer by its barycentre (tri 0 over
        // tri 1 on all of its 15 pixels, tri 2 over tri 0 at (2,2) and over tri 3 at (6,2)):
        // the painter's frame shows the same triangle at every pixel as the z-buffer's.
        const auto comparison = compareWithZBuffer(shared(testing::handScene()));
        QVERIFY(comparison.ok());
        QCOMPARE(comparison->differing, std::size_t(0));
        const std::vector<std::uint32_t> order{1, 0, 3, 2};
        QCOMPARE(comparison->zBufferIndex, order);
        const DepthTest& p = *comparison->painter->depth;
        const DepthTest& z = *comparison->zBuffer->depth;
        std::size_t covered = 0;
        for (int y = 0; y < 8; ++y) {
            for (int x = 0; x < 8; ++x) {
                const std::uint32_t t = p.triangle.at(x, y);
                QCOMPARE(t == kNoTriangle ? kNoTriangle : comparison->zBufferIndex[t],
                         z.triangle.at(x, y));
                covered += t != kNoTriangle ? 1 : 0;
            }
        }
        // Tris 0 and 1: 15 pixels; tri 2: 15, (2,2) among them; tri 3: 4, (6,2) tri 2's.
        QCOMPARE(covered, std::size_t(15 + 15 - 1 + 4 - 1));
        // Every fragment is written: 15 + 15 + 15 + 4 = 49, none rejected; the z-buffer
        // rejects tri 1's 15 and tri 3's at (6,2).
        QCOMPARE(p.fragments, std::size_t(49));
        QCOMPARE(p.passed, std::size_t(49));
        QCOMPARE(p.rejected, std::size_t(0));
        QCOMPARE(z.rejected, std::size_t(15 + 1));
        // Lit as flat: the same bytes as flat shading under the z-buffer.
        const auto flat = renderTrace(shared(testing::handScene(ShadingModel::Flat)));
        QVERIFY(colourImage(*comparison->painter->shading, p,
                            comparison->painter->scene->conventions) ==
                colourImage(*flat->shading, *flat->depth, flat->scene->conventions));
    }

    void longTriangleOverASmallOne() {
        const auto comparison = compareWithZBuffer(shared(painterFailureScene()));
        QVERIFY(comparison.ok());
        const FrameTrace& p = *comparison->painter;
        const FrameTrace& z = *comparison->zBuffer;
        // Painted order: L (draw 1) first, then S (draw 0), across the draws.
        QCOMPARE(p.projection->triangles[0].draw, std::uint32_t(1));
        QCOMPARE(p.projection->triangles[1].draw, std::uint32_t(0));
        RL_COMPARE_NEAR(painterDistance(*p.scene, *p.projection, 0), std::sqrt(443.0) / 3.0, 1e-12);
        RL_COMPARE_NEAR(painterDistance(*p.scene, *p.projection, 1), std::sqrt(21.5), 1e-12);
        QCOMPARE(comparison->zBufferIndex, (std::vector<std::uint32_t>{1, 0}));
        // L covers x <= min(7, 8 - y) on rows 0..7: 8 + 8 + 7 + 6 + 5 + 4 + 3 + 2 = 43 pixels;
        // S's six lie inside it.
        QCOMPARE(p.depth->coveredPixels(), std::size_t(43));
        QCOMPARE(z.depth->coveredPixels(), std::size_t(43));
        // The z-buffer: S first (6 written), then L: 43 - 3 written, rejected where x + y = 2.
        QCOMPARE(z.depth->rejected, std::size_t(3));
        QCOMPARE(p.depth->rejected, std::size_t(0));
        QCOMPARE(p.depth->passed, std::size_t(49));

        const QList<QPoint> wrong{{0, 0}, {1, 0}, {0, 1}};
        QCOMPARE(comparison->differing, std::size_t(3));
        QCOMPARE(comparison->wrongOrder, std::size_t(3));
        QCOMPARE(comparison->ties, std::size_t(0));
        const Rgba8Image pImage = colourImage(*p.shading, *p.depth, p.scene->conventions);
        const Rgba8Image zImage = colourImage(*z.shading, *z.depth, z.scene->conventions);
        for (int y = 0; y < 8; ++y) {
            for (int x = 0; x < 8; ++x) {
                const bool isWrong = wrong.contains(QPoint(x, y));
                QCOMPARE(comparison->mask.at(x, y),
                         isWrong ? PixelDifference::WrongOrder : PixelDifference::Same);
                if (!isWrong) continue;
                QCOMPARE(int(pImage.pixel(x, y)[0]), 10);  // S: 10 ka = 10
                QCOMPARE(int(zImage.pixel(x, y)[0]), 5);   // L: 10 ka = 5
            }
        }
        // The buffers: the painter keeps the last painted depth (S's 3), the z-buffer the
        // nearest (L's 1 and 2.125); where x + y = 2 both hold S's 3 (L's 3.25 is farther).
        QCOMPARE(p.depth->depth.at(0, 0), 3.0f);
        QCOMPARE(z.depth->depth.at(0, 0), 1.0f);
        QCOMPARE(z.depth->depth.at(1, 0), 2.125f);
        QCOMPARE(p.depth->depth.at(2, 0), 3.0f);
        QCOMPARE(z.depth->depth.at(1, 1), 3.0f);
        QCOMPARE(p.depth->depth.at(3, 0), 1.0f + 9.0f * 3.0f / 8.0f);  // L's alone: 4.375
        // L (rank 0) is hidden wrongly at 3 pixels; S (rank 1) covers 3 nearer ones.
        QCOMPARE(comparison->hiddenWrongly, (std::vector<std::uint32_t>{3, 0}));
        QCOMPARE(comparison->coversWrongly, (std::vector<std::uint32_t>{0, 3}));

        const Rgba8Image diff = differenceImage(*comparison);
        QCOMPARE(int(diff.pixel(0, 1)[0]), 255);
        QCOMPARE(int(diff.pixel(0, 1)[1]), 0);
        QCOMPARE(int(diff.pixel(2, 0)[0]), 3);  // S's 10, darkened to a third
        QCOMPARE(int(diff.pixel(7, 7)[0]), 0);  // background
    }

    void sharedEdgeIsATie() {
        const auto comparison = compareWithZBuffer(shared(sharedEdgeScene()));
        QVERIFY(comparison.ok());
        RL_COMPARE_NEAR(
            painterDistance(*comparison->painter->scene, *comparison->painter->projection, 0),
            std::sqrt(17.0) / 3.0, 1e-12);
        RL_COMPARE_NEAR(
            painterDistance(*comparison->painter->scene, *comparison->painter->projection, 1),
            std::sqrt(11.0) / 3.0, 1e-12);
        QCOMPARE(comparison->differing, std::size_t(5));
        QCOMPARE(comparison->ties, std::size_t(5));
        QCOMPARE(comparison->wrongOrder, std::size_t(0));
        for (int x = 0; x <= 4; ++x) QCOMPARE(comparison->mask.at(x, 4 - x), PixelDifference::Tie);
        QCOMPARE(comparison->hiddenWrongly, (std::vector<std::uint32_t>{0, 0}));
    }

    void clippedTrianglesSortByTheirSource() {
        // Near plane z = 1. Q (mesh triangle 0): world (0,0,0.5) (1,0,3) (0,1,3), cut by the
        // plane at (0.2,0,1) and (0,0.2,1) into a quad, two pieces. Its source barycentre is
        // view (-1/3, 1/3, 13/6): |b| = sqrt(1/9 + 1/9 + 169/36) = sqrt(177)/6 = 2.21736.
        // R (mesh triangle 1): world (0,0,2.3) (0.1,0,2.3) (0,0.1,2.3), barycentre view
        // (-1/30, 1/30, 2.3): |b| = sqrt(2/900 + 5.29) = 2.30048. R is farther: painted first,
        // then both pieces of Q, in the order clipping made them. (One piece, with vertices at
        // z = 1, 3, 3, has its own barycentre at z = 7/3, farther than R: sorting pieces by
        // their own barycentres would split Q around R.)
        Scene scene = testing::makeScene(
            testing::axisCamera(),
            testing::makeMesh(
                {{0, 0, 0.5}, {1, 0, 3}, {0, 1, 3}, {0, 0, 2.3}, {0.1, 0, 2.3}, {0, 0.1, 2.3}},
                {{0, 1, 2}, {3, 4, 5}}),
            8, 8, ShadingModel::Painter);
        scene.nearPlane.fixedW = 1.0;
        const auto zScene = zBufferSceneOf(scene);
        const auto z = renderTrace(zScene);
        QCOMPARE(z->projection->draws[0].fate[0], TriangleFate::Clipped);
        QCOMPARE(z->projection->triangles.size(), std::size_t(3));
        const auto p = renderTrace(shared(scene));
        const auto& tris = p->projection->triangles;
        QCOMPARE(tris.size(), std::size_t(3));
        QCOMPARE(tris[0].source, std::uint32_t(1));
        QCOMPARE(tris[1].source, std::uint32_t(0));
        QCOMPARE(tris[2].source, std::uint32_t(0));
        QCOMPARE(tris[1].v, z->projection->triangles[0].v);  // the pieces keep their order
        QCOMPARE(tris[2].v, z->projection->triangles[1].v);
        RL_COMPARE_NEAR(painterDistance(scene, *p->projection, 0), std::sqrt(2.0 / 900.0 + 5.29),
                        1e-12);
        RL_COMPARE_NEAR(painterDistance(scene, *p->projection, 1), std::sqrt(177.0) / 6.0, 1e-12);
        RL_COMPARE_NEAR(painterDistance(scene, *p->projection, 2), std::sqrt(177.0) / 6.0, 1e-12);
        double farthestPiece = 0.0;
        const auto& pView = p->projection->draws[0].pView;
        for (int k = 1; k <= 2; ++k) {
            dvec3 b(0.0);
            for (std::uint32_t v : tris[static_cast<std::size_t>(k)].v) b += dvec3(pView[v]) / 3.0;
            farthestPiece = std::max(farthestPiece, glm::length(b));
        }
        QVERIFY(farthestPiece > std::sqrt(2.0 / 900.0 + 5.29));
    }

    void replayPaintsFarToNear() {
        const auto trace = renderTrace(shared(painterFailureScene()));
        const auto replay = testing::replayOf(trace);
        const auto& fragments = replay->fragments();
        QCOMPARE(fragments.size(), std::size_t(43 + 6));
        // L's 43 fragments (rank 0) come first, then S's 6; every one is written.
        for (std::size_t i = 0; i < fragments.size(); ++i) {
            QCOMPARE(fragments[i].triangle, std::uint32_t(i < 43 ? 0 : 1));
            QCOMPARE(fragments[i].verdict, FragmentVerdict::Written);
        }
        // At (0,0): L at depth 1, then S at 3 painted over it (the stored 1 is not compared).
        const std::vector<std::uint32_t> at = replay->fragmentsAt(0, 0);
        QCOMPARE(at.size(), std::size_t(2));
        QCOMPARE(fragments[at[0]].depth, 1.0f);
        QCOMPARE(fragments[at[1]].depth, 3.0f);
        QCOMPARE(fragments[at[1]].stored, 1.0f);
        QCOMPARE(fragments[at[1]].writeNumber, std::uint32_t(2));
        ReplayState state(replay);
        state.seek(replay->atFragment(43));  // L painted, S not yet
        QCOMPARE(int(state.image().pixel(0, 0)[0]), 5);
        state.seek(replay->end());
        QVERIFY(state.image() ==
                colourImage(*trace->shading, *trace->depth, trace->scene->conventions));
        QVERIFY(state.depth().pixels() == trace->depth->depth.pixels());
    }

    void explainSaysPainted() {
        // Pixel (0,0) of the failure scene: L painted at depth 1 over the cleared buffer, then
        // S at 3 over L's 1, no depth test either time.
        auto probe = RecordingProbe::forPixel(0, 0);
        auto trace = traceFrame(shared(painterFailureScene()), {}, probe);
        QVERIFY(trace.ok());
        const QString text = QString::fromStdString(explainPixel(trace.value(), probe));
        QVERIFY2(text.contains(QStringLiteral("z = 1, over stored +infinity: painted, no depth "
                                              "test (painter's algorithm)")),
                 qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral(
                     "z = 3, over stored 1: painted, no depth test (painter's algorithm)")),
                 qPrintable(text));
    }

    void replayEndEqualsTheFrameOnAMesh() {
        // The hand scene's four triangles plus a fifth, long one from z = 1 to z = 10 across
        // them all (painted first, its barycentre being the farthest).
        const auto trace = renderTrace(shared(testing::handScene(
            ShadingModel::Painter, {{1, 1, 1}, {-10, 10, 10}, {10, -10, 10}}, {{12, 13, 14}})));
        // Its barycentre: view (-1/3, 1/3, 7), sqrt(443)/3 = 7.016, the farthest.
        QCOMPARE(trace->projection->triangles[0].source, std::uint32_t(4));
        const auto replay = testing::replayOf(trace);
        for (std::size_t i = 1; i < replay->fragments().size(); ++i)
            QVERIFY(replay->fragments()[i - 1].triangle <= replay->fragments()[i].triangle);
        ReplayState state(replay);
        state.seek(replay->end());
        QVERIFY(state.image() ==
                colourImage(*trace->shading, *trace->depth, trace->scene->conventions));
        // Threads do not change the painted bits.
        RenderOptions options;
        options.threads = 3;
        const auto threaded = renderTrace(trace->scene, options);
        QVERIFY(threaded->depth->triangle == trace->depth->triangle);
        QVERIFY(threaded->depth->depth.pixels() == trace->depth->depth.pixels());
    }

    void comparisonReusesTheFrame() {
        // A frame that is one of the two renders (every draw painted, or every draw flat) is
        // used as it is; the comparison is the same as when both are rendered.
        const auto expected = compareWithZBuffer(shared(painterFailureScene()));
        QVERIFY(expected.ok());
        const auto check = [&](const PainterComparison& c) {
            QCOMPARE(c.differing, expected->differing);
            QCOMPARE(c.wrongOrder, expected->wrongOrder);
            QCOMPARE(c.ties, expected->ties);
            QVERIFY(c.mask.pixels() == expected->mask.pixels());
            QCOMPARE(c.zBufferIndex, expected->zBufferIndex);
            QCOMPARE(c.painterRank, expected->painterRank);
            QCOMPARE(c.hiddenWrongly, expected->hiddenWrongly);
            QCOMPARE(c.coversWrongly, expected->coversWrongly);
            QVERIFY(c.painterImage == expected->painterImage);
            QVERIFY(c.zBufferImage == expected->zBufferImage);
            QVERIFY(differenceImage(c) == differenceImage(*expected));
        };
        const auto painted = renderTrace(shared(painterFailureScene()));
        const auto fromPainted = compareWithZBuffer(painted);
        QVERIFY(fromPainted.ok());
        QVERIFY(fromPainted->painter == painted);
        check(*fromPainted);
        const auto flat = renderTrace(zBufferSceneOf(*painted->scene));
        const auto fromFlat = compareWithZBuffer(flat);
        QVERIFY(fromFlat.ok());
        QVERIFY(fromFlat->zBuffer == flat);
        check(*fromFlat);
        // Neither (a Phong frame): both rendered.
        Scene phong = painterFailureScene();
        for (Draw& draw : phong.draws) draw.shading = ShadingModel::Phong;
        const auto lit = renderTrace(shared(phong));
        const auto fromLit = compareWithZBuffer(lit);
        QVERIFY(fromLit.ok());
        QVERIFY(fromLit->painter != lit && fromLit->zBuffer != lit);
        check(*fromLit);
        // A painted frame that did not keep its z-buffer (RenderOptions::keepDepth): the
        // comparison reads depths, so it renders the painter's frame again, with them.
        RenderOptions noZBuffer;
        noZBuffer.keepDepth = false;
        auto bare = renderFrame(shared(painterFailureScene()), noZBuffer);
        QVERIFY(bare.ok());
        QVERIFY(bare->depth->depth.empty());
        const auto bareFrame = std::make_shared<const FrameTrace>(std::move(bare).value());
        const auto fromBare = compareWithZBuffer(bareFrame, noZBuffer);
        QVERIFY(fromBare.ok());
        QVERIFY(fromBare->painter != bareFrame && fromBare->painter->depth->depthKept);
        check(*fromBare);
        auto bareFlat = renderFrame(zBufferSceneOf(*painted->scene), noZBuffer);
        QVERIFY(bareFlat.ok());
        const auto bareFlatFrame = std::make_shared<const FrameTrace>(std::move(bareFlat).value());
        const auto fromBareFlat = compareWithZBuffer(bareFlatFrame, noZBuffer);
        QVERIFY(fromBareFlat.ok());
        QVERIFY(fromBareFlat->zBuffer != bareFlatFrame && fromBareFlat->zBuffer->depth->depthKept);
        check(*fromBareFlat);
        QVERIFY(!compareWithZBuffer(std::shared_ptr<const FrameTrace>()).ok());
    }
};

QTEST_GUILESS_MAIN(TestPainter)
#include "tst_painter.moc"
