// Seed 002's two presentations: the clipping of a triangle against the near plane, step by
// step (near_clip.h), worked out by hand and checked against what the projection stage did
// on real scenes with the camera inside the object; and the split of each triangle into
// trapezoids (trapezoids.h), worked out by hand and checked to cover exactly the rows and
// pixels of the scan converter, under the course and the gpu rules.
#include <QtTest>

#include <QComboBox>
#include <QElapsedTimer>
#include <QPushButton>

#include <cmath>

#include "pipeline/stages/depth_test.h"
#include "pipeline/stages/near_clip.h"
#include "pipeline/stages/scan_conversion.h"
#include "pipeline/stages/trapezoids.h"
#include "tests/course_scenes.h"
#include "tests/test_support.h"
#include "views/inspection.h"
#include "views/near_clip_view.h"
#include "views/trapezoid_view.h"

using namespace rl;
using rasterlab::Inspection;
using rasterlab::NearClipView;
using rasterlab::TrapezoidView;
using testing::lookAt;

namespace {

// The course camera's projection with d = hx = hy = 1: w is the view z.
dmat4 courseProjection() {
    CourseCamera camera;
    return courseClipFromView(camera);
}

bool near(double a, double b) {
    return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b));
}
bool near(const dvec4& a, const dvec4& b) {
    return near(a.x, b.x) && near(a.y, b.y) && near(a.z, b.z) && near(a.w, b.w);
}

// The default course scene (the trefoil) or the chalice, the camera put at the centre of
// the object's box, looking toward the object's first vertex: the object surrounds it, so
// triangles reach from in front of the camera to behind it.
// nearFraction: the near plane at this fraction of the farthest vertex's w.
std::shared_ptr<const Scene> cameraInside(CourseSceneParts parts, RuleSet rules,
                                          ShadingModel shading, double nearFraction = 1e-3) {
    dvec3 lo(1e300), hi(-1e300);
    for (const dvec4& p : parts.object.mesh->positions) {
        lo = glm::min(lo, dvec3(p));
        hi = glm::max(hi, dvec3(p));
    }
    parts.camera.c = (lo + hi) * 0.5;
    parts.camera.n = glm::normalize(dvec3(parts.object.mesh->positions[0]) - parts.camera.c);
    parts.camera.v = std::abs(parts.camera.n.z) < 0.9 ? dvec3(0, 0, 1) : dvec3(0, 1, 0);
    CourseSceneSettings settings;
    settings.width = 320;
    settings.height = 240;
    settings.shading = shading;
    settings.rules = rulesOf(rules);
    settings.nearPlane.autoFraction = nearFraction;
    return std::make_shared<const Scene>(makeCourseScene(parts, settings));
}

// The axis camera (view = (-x, y, z), d = hx = hy = 1) on a 64x64 image, the near plane
// fixed at z = 1, and quadByHand's triangle: view A0 = (0, 0, 3), A1 = (2, 0, 3),
// A2 = (0, 4, -3), so world (0, 0, 3), (-2, 0, 3), (0, 4, -3). On the screen, x = (x/z + 1)
// 32 and y = (1 - y/z) 32, truncated: A0 (32, 32), A1 (53.3 -> 53, 32), C12 = (4/3, 4/3, 1)
// (74.7 -> 74, -10.7 -> -10), C20 = (0, 4/3, 1) (32, -10).
std::shared_ptr<const Scene> clipHandScene() {
    Scene scene = testing::makeScene(
        testing::axisCamera(), testing::makeMesh({{0, 0, 3}, {-2, 0, 3}, {0, 4, -3}}, {{0, 1, 2}}),
        64, 64);
    scene.nearPlane.fixedW = 1.0;
    return std::make_shared<const Scene>(std::move(scene));
}

// The trapezoidsByHand triangle as a scene: screen (2, 0), (8, 4), (0, 8) with view z 2, 4,
// 6 on a 16x16 image (x = (x/z + 1) 8, y = (1 - y/z) 8): view (-1.5, 2, 2), (0, 2, 4),
// (-6, 0, 6), world (1.5, 2, 2), (0, 2, 4), (6, 0, 6).
std::shared_ptr<const Scene> trapezoidHandScene(ShadingModel shading) {
    return std::make_shared<const Scene>(testing::makeScene(
        testing::axisCamera(), testing::makeMesh({{1.5, 2, 2}, {0, 2, 4}, {6, 0, 6}}, {{0, 1, 2}}),
        16, 16, shading));
}

// The first entry of the near clip view's list after the first (the triangle selected) whose
// mesh triangle (draw, source) is wanted, or -1.
template <typename Wanted>
int firstListed(const NearClipView& view, Wanted wanted) {
    for (int k = 1; k <= view.listedTriangles(); ++k) {
        const auto [draw, source] = *view.listedTriangle(k);
        if (wanted(draw, source)) return k;
    }
    return -1;
}

}  // namespace

class TestClipTrapezoid : public QObject {
    Q_OBJECT
private slots:
    // One vertex behind the plane z = 1 (P = [0, 0, 1, -1]):
    //   A0 = (0, 0, 3): dot(P, A0) = 3 - 1 = 2 >= 0, kept; edge A0-A1: 2 and 2, no crossing;
    //   A1 = (2, 0, 3): 2, kept; edge A1-A2: 2 and -4 differ:
    //     t = (0 - 2) / (-4 - 2) = 1/3, C = A1 + (A2 - A1)/3 = (2 - 2/3, 4/3, 3 - 2)
    //       = (4/3, 4/3, 1);
    //   A2 = (0, 4, -3): -3 - 1 = -4, dropped; edge A2-A0: -4 and 2 differ:
    //     t = (0 + 4) / (2 + 4) = 2/3, C = A2 + 2/3 (A0 - A2) = (0, 4 - 8/3, -3 + 4)
    //       = (0, 4/3, 1); the stage computes it from A0, the end in front: t' = 2/6 = 1/3.
    // Output polygon A0 A1 C12 C20, a quad: triangles A0 A1 C12 and A0 C12 C20.
    void quadByHand() {
        const NearClipRecord r = clipAgainstNearPlane(
            {dvec4(0, 0, 3, 1), dvec4(2, 0, 3, 1), dvec4(0, 4, -3, 1)}, courseProjection(), 1.0);
        QCOMPARE(r.plane, dvec4(0, 0, 1, -1));
        QCOMPARE(r.edges[0].distanceA, 2.0);
        QCOMPARE(r.edges[1].distanceA, 2.0);
        QCOMPARE(r.edges[2].distanceA, -4.0);
        QVERIFY(r.edges[0].keptA && r.edges[1].keptA && !r.edges[2].keptA);
        QVERIFY(!r.edges[0].crosses);
        QVERIFY(r.edges[1].crosses);
        QVERIFY(near(r.edges[1].t, 1.0 / 3.0));
        QVERIFY(near(r.edges[1].tFromInside, 1.0 / 3.0));  // A1 is in front: the same t
        QVERIFY(near(r.edges[1].pView, dvec4(4.0 / 3.0, 4.0 / 3.0, 1.0, 1.0)));
        QVERIFY(r.edges[2].crosses);
        QVERIFY(near(r.edges[2].t, 2.0 / 3.0));
        QVERIFY(near(r.edges[2].tFromInside, 1.0 / 3.0));  // from A0: 1 - t
        QVERIFY(near(r.edges[2].pView, dvec4(0.0, 4.0 / 3.0, 1.0, 1.0)));
        // The seed's C = lerp(t, A, B) is the same point.
        QVERIFY(near(r.edges[2].pView, glm::mix(r.pView[2], r.pView[0], r.edges[2].t)));
        QCOMPARE(r.polygon.size(), std::size_t(4));
        QVERIFY(!r.polygon[0].made && r.polygon[0].index == 0);
        QVERIFY(!r.polygon[1].made && r.polygon[1].index == 1);
        QVERIFY(r.polygon[2].made && r.polygon[2].index == 1);  // made on edge A1-A2
        QVERIFY(r.polygon[3].made && r.polygon[3].index == 2);  // made on edge A2-A0
        QCOMPARE(r.triangles.size(), std::size_t(2));
        QCOMPARE(r.triangles[0], (std::array<std::size_t, 3>{0, 1, 2}));
        QCOMPARE(r.triangles[1], (std::array<std::size_t, 3>{0, 2, 3}));
        QCOMPARE(r.keptCount(), std::size_t(2));
    }

    // Two vertices behind z = 1: A0 = (0, 0, 3) (distance 2), A1 = (2, 0, -1) and
    // A2 = (0, 2, -1) (distance -2 each). Edge A0-A1: t = -2 / (-2 - 2) = 0.5, C = (1, 0, 1);
    // edge A1-A2 does not cross; edge A2-A0: t = 2 / 4 = 0.5, C = (0, 1, 1). One triangle
    // A0 C01 C20.
    void triangleByHand() {
        const NearClipRecord r = clipAgainstNearPlane(
            {dvec4(0, 0, 3, 1), dvec4(2, 0, -1, 1), dvec4(0, 2, -1, 1)}, courseProjection(), 1.0);
        QCOMPARE(r.keptCount(), std::size_t(1));
        QCOMPARE(r.edges[0].t, 0.5);
        QCOMPARE(r.edges[0].pView, dvec4(1, 0, 1, 1));
        QVERIFY(!r.edges[1].crosses);
        QCOMPARE(r.edges[2].t, 0.5);
        QCOMPARE(r.edges[2].pView, dvec4(0, 1, 1, 1));
        QCOMPARE(r.polygon.size(), std::size_t(3));
        QCOMPARE(r.triangles.size(), std::size_t(1));
        QCOMPARE(r.triangles[0], (std::array<std::size_t, 3>{0, 1, 2}));
    }

    // Wholly in front (z = 2 > 1, distances 1): untouched. Wholly behind (z = 0.5, distances
    // -0.5): nothing. A vertex on the plane (distance 0) is kept and makes no point.
    void inFrontBehindOnThePlane() {
        const NearClipRecord front = clipAgainstNearPlane(
            {dvec4(0, 0, 2, 1), dvec4(1, 0, 2, 1), dvec4(0, 1, 2, 1)}, courseProjection(), 1.0);
        QVERIFY(front.untouched());
        QCOMPARE(front.polygon.size(), std::size_t(3));
        for (const NearClipEdge& e : front.edges) {
            QCOMPARE(e.distanceA, 1.0);
            QVERIFY(!e.crosses);
        }
        QCOMPARE(front.triangles.size(), std::size_t(1));

        const NearClipRecord behind =
            clipAgainstNearPlane({dvec4(0, 0, 0.5, 1), dvec4(1, 0, 0.5, 1), dvec4(0, 1, 0.5, 1)},
                                 courseProjection(), 1.0);
        QVERIFY(behind.gone());
        QVERIFY(behind.polygon.empty());
        QVERIFY(behind.triangles.empty());
        QCOMPARE(behind.edges[1].distanceA, -0.5);

        const NearClipRecord on = clipAgainstNearPlane(
            {dvec4(0, 0, 1, 1), dvec4(1, 0, 2, 1), dvec4(0, 1, 2, 1)}, courseProjection(), 1.0);
        QCOMPARE(on.edges[0].distanceA, 0.0);
        QVERIFY(on.untouched());
        QCOMPARE(on.polygon.size(), std::size_t(3));
    }

    // A projection matrix of seed 001 (OpenGL's frustum, w = -z): the plane w = near is
    // z = -near in view space; with near = 0.5, P = (0, 0, -1, -0.5), keeping z <= -0.5. The
    // point (0, 0, -2) is at distance 2 - 0.5 = 1.5, (0, 1, 1) at -1 - 0.5 = -1.5.
    void openGlPlane() {
        dmat4 frustum(0.0);
        frustum[0][0] = frustum[1][1] = 1.0;
        frustum[2][3] = -1.0;  // w = -z
        frustum[3][2] = -1.0;
        QCOMPARE(nearPlaneInView(frustum, 0.5), dvec4(0, 0, -1, -0.5));
        const NearClipRecord r = clipAgainstNearPlane(
            {dvec4(0, 0, -2, 1), dvec4(1, 0, -2, 1), dvec4(0, 1, 1, 1)}, frustum, 0.5);
        QCOMPARE(r.edges[0].distanceA, 1.5);
        QCOMPARE(r.edges[2].distanceA, -1.5);
        QCOMPARE(r.polygon.size(), std::size_t(4));
    }

    // For every triangle of a frame with the camera inside the object: the record agrees
    // with what the projection stage did (its fate; the made points, bit for bit, with the
    // stage's t; the fan it emitted).
    void agreesWithTheProjectionStage_data() {
        QTest::addColumn<std::shared_ptr<const Scene>>("scene");
        QTest::newRow("trefoil, camera at its centre")
            << cameraInside(testing::defaultCourseParts(), RuleSet::Course, ShadingModel::Phong);
        if (std::optional<CourseSceneParts> parts = testing::calice2Parts())
            QTest::newRow("chalice, camera inside the cup")
                << cameraInside(*parts, RuleSet::Course, ShadingModel::Gouraud);
    }
    void agreesWithTheProjectionStage() {
        QFETCH(std::shared_ptr<const Scene>, scene);
        const auto trace = testing::renderTrace(scene);
        const Projection& projection = *trace->projection;
        std::size_t clipped = 0, quads = 0, compared = 0;
        for (std::uint32_t d = 0; d < scene->draws.size(); ++d) {
            const DrawProjection& proj = projection.draws[d];
            QVERIFY(scene->draws[d].clipPlanes.empty());
            for (std::uint32_t t = 0; t < proj.fate.size(); ++t) {
                const NearClipRecord r = nearClipOf(*scene, projection, d, t);
                const std::vector<std::uint32_t> emitted = screenTrianglesOf(projection, d, t);
                switch (proj.fate[t]) {
                    case TriangleFate::Inside:
                        QVERIFY(r.untouched());
                        QCOMPARE(emitted.size(), std::size_t(1));
                        continue;
                    case TriangleFate::Behind:
                        QVERIFY(r.gone() && r.keptCount() == 0);
                        QVERIFY(emitted.empty());
                        continue;
                    case TriangleFate::Clipped:
                        break;
                    default:
                        continue;
                }
                ++clipped;
                QVERIFY(!r.untouched());
                QCOMPARE(emitted.size(), r.triangles.size());
                quads += r.polygon.size() == 4 ? 1 : 0;
                for (std::size_t k = 0; k < emitted.size(); ++k) {
                    const ScreenTriangle& s = projection.triangles[emitted[k]];
                    for (std::size_t c = 0; c < 3; ++c) {
                        const NearClipPoint& point = r.polygon[r.triangles[k][c]];
                        const std::uint32_t v = s.v[c];
                        QCOMPARE(proj.pView[v], point.pView);  // bit for bit
                        QCOMPARE(v >= proj.originalVertexCount, point.made);
                        if (!point.made) {
                            QCOMPARE(v, scene->draws[d].mesh->triangles[t][point.index]);
                            continue;
                        }
                        // The stage's made vertex: from the end in front, the same t.
                        const ClipVertex& g = proj.generated[v - proj.originalVertexCount];
                        const NearClipEdge& e = r.edges[point.index];
                        const std::size_t in = e.keptA ? e.a : e.b;
                        QCOMPARE(g.a, scene->draws[d].mesh->triangles[t][in]);
                        QCOMPARE(g.t, e.tFromInside);
                        QVERIFY(near(e.tFromInside, e.keptA ? e.t : 1.0 - e.t));
                        QCOMPARE(proj.pClip[v].w, projection.nearW);
                    }
                    ++compared;
                }
            }
        }
        qInfo("%zu triangles clipped (%zu into a quad), %zu projected triangles compared", clipped,
              quads, compared);
        QVERIFY(clipped > 0);
        QVERIFY(quads > 0);
        QVERIFY(quads < clipped);  // some lose two vertices: one triangle
    }

    // Screen triangle (2, 0) (8, 4) (0, 8), course rules, values pz = 2, 4, 6 and colours red,
    // green, blue. Sorted: top (2, 0), middle (8, 4), bottom (0, 8); the long edge from (2, 0)
    // to (0, 8) meets the middle row y = 4 at s = 4/8 = 0.5, M' = (2 - 0.5 * 2, 4) = (1, 4),
    // pz 2 + 0.5 (6 - 2) = 4, colour (127.5, 0, 127.5). The middle vertex is right of the
    // long edge ((6, 4) x (-2, 8) = 48 + 8 = 56 > 0): the long edge is on the left.
    // Upper: TL = TR = (2, 0), BL = M' (1, 4), BR = (8, 4), rows 0..3 (row 4 is the lower's).
    // Lower: TL = M' (1, 4), TR = (8, 4), BL = BR = (0, 8), rows 4..8.
    // Row 2: t_j = (2 - 0)/(4 - 0) = 0.5; L = lerp(0.5, TL, BL) = (1.5, 2), pz 3,
    //   colour (191.25, 0, 63.75); R = lerp(0.5, TR, BR) = (5, 2), pz 3, colour
    //   (127.5, 127.5, 0); pixels ceil(1.5) = 2 to floor(5) = 5. Pixel 3: t_i = (3 - 1.5) /
    //   (5 - 1.5) = 3/7, colour (191.25 - 3/7 63.75, 3/7 127.5, 63.75 - 3/7 63.75)
    //   = (163.92857, 54.64286, 36.42857), pz 3.
    // Row 6: t_j = (6 - 4)/(8 - 4) = 0.5; L = lerp(0.5, (1, 4), (0, 8)) = (0.5, 6), pz 5,
    //   colour (63.75, 0, 191.25); R = (4, 6), pz 5, colour (0, 127.5, 127.5); pixels 1..4.
    void trapezoidsByHand() {
        const RasterRules rules = RasterRules::course();
        const std::array<dvec2, 3> p{dvec2(2, 0), dvec2(8, 4), dvec2(0, 8)};
        const TriangleSetup s = setupTriangle(p, rules);
        const std::array<TrapezoidPoint, 3> values{TrapezoidPoint{p[0], 2.0, vec3(255, 0, 0)},
                                                   TrapezoidPoint{p[1], 4.0, vec3(0, 255, 0)},
                                                   TrapezoidPoint{p[2], 6.0, vec3(0, 0, 255)}};
        const TrapezoidSplit split = splitIntoTrapezoids(s, values, rules);
        QCOMPARE(split.s, 0.5);
        QCOMPARE(split.split.p, dvec2(1, 4));
        QCOMPARE(split.split.pz, 4.0);
        QCOMPARE(split.split.colour, vec3(127.5f, 0.0f, 127.5f));
        QCOMPARE(split.parts.size(), std::size_t(2));
        const Trapezoid& upper = split.parts[0];
        const Trapezoid& lower = split.parts[1];
        QVERIFY(upper.upper && !lower.upper);
        QCOMPARE(upper.tl.p, dvec2(2, 0));
        QCOMPARE(upper.tr.p, dvec2(2, 0));
        QCOMPARE(upper.bl.p, dvec2(1, 4));
        QCOMPARE(upper.br.p, dvec2(8, 4));
        QCOMPARE(upper.firstRow, 0);
        QCOMPARE(upper.lastRow, 3);
        QCOMPARE(lower.tl.p, dvec2(1, 4));
        QCOMPARE(lower.tr.p, dvec2(8, 4));
        QCOMPARE(lower.bl.p, dvec2(0, 8));
        QCOMPARE(lower.br.p, dvec2(0, 8));
        QCOMPARE(lower.firstRow, 4);
        QCOMPARE(lower.lastRow, 8);

        const TrapezoidRow row2 = trapezoidRow(s, upper, rules, 2, 10);
        QCOMPARE(row2.tj, 0.5);
        QCOMPARE(row2.left.p, dvec2(1.5, 2));
        QCOMPARE(row2.left.pz, 3.0);
        QCOMPARE(row2.left.colour, vec3(191.25f, 0.0f, 63.75f));
        QCOMPARE(row2.right.p, dvec2(5, 2));
        QCOMPARE(row2.right.pz, 3.0);
        QCOMPARE(row2.right.colour, vec3(127.5f, 127.5f, 0.0f));
        QCOMPARE(row2.xBegin, 2);
        QCOMPARE(row2.xEnd, 6);
        double ti = 0.0;
        const TrapezoidPoint pixel = trapezoidPixel(row2, rules, 3, &ti);
        QCOMPARE(ti, 3.0 / 7.0);
        QCOMPARE(pixel.pz, 3.0);
        QVERIFY(std::abs(pixel.colour.r - 163.92857f) < 1e-3f);
        QVERIFY(std::abs(pixel.colour.g - 54.64286f) < 1e-3f);
        QVERIFY(std::abs(pixel.colour.b - 36.42857f) < 1e-3f);

        const TrapezoidRow row6 = trapezoidRow(s, lower, rules, 6, 10);
        QCOMPARE(row6.tj, 0.5);
        QCOMPARE(row6.left.p, dvec2(0.5, 6));
        QCOMPARE(row6.left.pz, 5.0);
        QCOMPARE(row6.left.colour, vec3(63.75f, 0.0f, 191.25f));
        QCOMPARE(row6.right.p, dvec2(4, 6));
        QCOMPARE(row6.right.colour, vec3(0.0f, 127.5f, 127.5f));
        QCOMPARE(row6.xBegin, 1);
        QCOMPARE(row6.xEnd, 5);
        // Row 4, the middle row (t_j = 0): from M' to the middle vertex, pixels 1..8; row 8,
        // the bottom vertex alone.
        QCOMPARE(trapezoidRow(s, lower, rules, 4, 10).xBegin, 1);
        QCOMPARE(trapezoidRow(s, lower, rules, 4, 10).xEnd, 9);
        QCOMPARE(trapezoidRow(s, lower, rules, 8, 10).xBegin, 0);
        QCOMPARE(trapezoidRow(s, lower, rules, 8, 10).xEnd, 1);

        // The same triangle under the gpu rules (samples at +0.5, top-left): rows sampled
        // at 0.5 .. 3.5 are the upper's (0..3), 4.5 .. 7.5 the lower's (4..7): the bottom
        // vertex's row 8 (sampled at 8.5) is below the triangle.
        const RasterRules gpu = RasterRules::gpu();
        const TriangleSetup sGpu = setupTriangle(p, gpu);
        const TrapezoidSplit g = splitIntoTrapezoids(sGpu, values, gpu);
        QCOMPARE(g.parts.size(), std::size_t(2));
        QCOMPARE(g.parts[0].lastRow, 3);
        QCOMPARE(g.parts[1].firstRow, 4);
        QCOMPARE(g.parts[1].lastRow, 7);
        // Row 2 sampled at 2.5: t_j = 2.5/4 = 0.625, L = 2 - 0.625 = 1.375, R = 2 + 0.625 * 6
        // = 5.75; samples 1.375 <= i + 0.5 < 5.75: i = 1..5.
        const TrapezoidRow r = trapezoidRow(sGpu, g.parts[0], gpu, 2, 10);
        QCOMPARE(r.tj, 0.625);
        QCOMPARE(r.left.p.x, 1.375);
        QCOMPARE(r.right.p.x, 5.75);
        QCOMPARE(r.xBegin, 1);
        QCOMPARE(r.xEnd, 6);
    }

    // Flat bottom and flat top: one trapezoid, two of whose corners are the same vertex.
    void flatTriangles() {
        const RasterRules rules = RasterRules::course();
        const std::array<TrapezoidPoint, 3> none{};
        // Flat bottom (0, 0) (4, 4) (0, 4): one upper trapezoid, rows 0..4.
        const TrapezoidSplit bottom = splitIntoTrapezoids(
            setupTriangle({dvec2(0, 0), dvec2(4, 4), dvec2(0, 4)}, rules), none, rules);
        QCOMPARE(bottom.parts.size(), std::size_t(1));
        QVERIFY(bottom.parts[0].upper);
        QCOMPARE(bottom.parts[0].tl.p, bottom.parts[0].tr.p);
        QCOMPARE(bottom.parts[0].firstRow, 0);
        QCOMPARE(bottom.parts[0].lastRow, 4);
        // Flat top (0, 0) (4, 0) (0, 4): one lower trapezoid, BL = BR, rows 0..4.
        const TrapezoidSplit top = splitIntoTrapezoids(
            setupTriangle({dvec2(0, 0), dvec2(4, 0), dvec2(0, 4)}, rules), none, rules);
        QCOMPARE(top.parts.size(), std::size_t(1));
        QVERIFY(!top.parts[0].upper);
        QCOMPARE(top.parts[0].bl.p, top.parts[0].br.p);
        QCOMPARE(top.parts[0].tl.p, dvec2(0, 0));
        QCOMPARE(top.parts[0].tr.p, dvec2(4, 0));
        QCOMPARE(top.parts[0].firstRow, 0);
        QCOMPARE(top.parts[0].lastRow, 4);
        // Zero area: no trapezoid (not scanned).
        QVERIFY(splitIntoTrapezoids(setupTriangle({dvec2(0, 0), dvec2(2, 2), dvec2(4, 4)}, rules),
                                    none, rules)
                    .parts.empty());
    }

    // On every triangle of real frames, the trapezoids' rows and pixels (cut to the screen)
    // are exactly the scan converter's spans, in the same order.
    void trapezoidsAreTheSameScan_data() {
        QTest::addColumn<std::shared_ptr<const Scene>>("scene");
        for (RuleSet rules : {RuleSet::Course, RuleSet::Gpu, RuleSet::Hw2}) {
            const QByteArray name = ruleSetName(rules);
            QTest::newRow(("trefoil, " + name).constData())
                << testing::defaultCourseScene(ShadingModel::Gouraud, rules, 320, 240);
            QTest::newRow(("trefoil, camera inside, " + name).constData())
                << cameraInside(testing::defaultCourseParts(), rules, ShadingModel::Phong);
        }
        if (std::shared_ptr<const Scene> calice = testing::calice2Scene())
            QTest::newRow("chalice, course") << calice;
    }
    void trapezoidsAreTheSameScan() {
        QFETCH(std::shared_ptr<const Scene>, scene);
        const auto trace = testing::renderTrace(scene);
        const Projection& projection = *trace->projection;
        const ScanConversion& scan = *trace->scan;
        const RasterRules& rules = scene->rules;
        std::size_t triangles = 0, rows = 0, twoParts = 0, depthsCompared = 0;
        double worst = 0.0;  // the largest relative difference of the depths
        for (std::uint32_t t = 0; t < projection.triangles.size(); ++t) {
            const ScreenTriangle& tri = projection.triangles[t];
            const TriangleSetup s = setupTriangle(screenVertices(projection, tri), rules);
            // Under the course's rules the depth is interpolated linearly on the screen, as the
            // seed's lerps do: the first pixel of each row gets the depth test's depth (which
            // works in float from the barycentrics). The values carried change no row or pixel.
            const bool compareDepths = rules == RasterRules::course() && !s.degenerate();
            std::array<TrapezoidPoint, 3> depths{};
            if (compareDepths)
                for (std::size_t k = 0; k < 3; ++k)
                    depths[k].pz = projection.draws[tri.draw].depth[tri.v[k]];
            const TrapezoidSplit split = splitIntoTrapezoids(s, depths, rules);
            std::vector<Span> spans;
            for (const Trapezoid& part : split.parts) {
                for (std::int32_t j = std::max(part.firstRow, 0);
                     j <= std::min(part.lastRow, scene->height - 1); ++j) {
                    const TrapezoidRow row = trapezoidRow(s, part, rules, j, scene->width);
                    ++rows;
                    if (row.empty()) continue;
                    spans.push_back({j, row.xBegin, row.xEnd});
                    if (!compareDepths) continue;
                    const double lerped = trapezoidPixel(row, rules, row.xBegin).pz;
                    const float depth =
                        fragmentDepth(*scene, projection, t, j, row.xBegin, row.xBegin).depth;
                    worst = std::max(worst, std::abs(lerped - depth) / std::abs(lerped));
                    ++depthsCompared;
                }
            }
            const std::vector<Span> expected(scan.spans.begin() + scan.spanStart[t],
                                             scan.spans.begin() + scan.spanStart[t + 1]);
            if (spans != expected) {
                qWarning("triangle %u: %zu spans, the converter %zu", t, spans.size(),
                         expected.size());
                QFAIL("the trapezoids scan other pixels than the converter");
            }
            QCOMPARE(split.parts.empty(), s.degenerate());
            twoParts += split.parts.size() == 2 ? 1 : 0;
            ++triangles;
        }
        qInfo("%zu triangles (%zu in two trapezoids), %zu rows compared, %zu pixels", triangles,
              twoParts, rows, scan.pixels);
        QVERIFY(scan.pixels > 0);
        QVERIFY(twoParts > 0);
        if (depthsCompared > 0) {
            qInfo("depths of %zu rows' first pixels: largest relative difference %g",
                  depthsCompared, worst);
            QVERIFY(worst < 1e-6);  // a few float roundings
        }
    }

    // The view of quadByHand's triangle: the steps reveal the numbers worked out there, and
    // the stage drew the quad's two triangles where the comment of clipHandScene says.
    void nearClipViewByHand() {
        Inspection inspection;
        NearClipView view(&inspection);
        view.resize(900, 640);
        view.show();
        const auto trace = testing::renderTrace(clipHandScene());
        QCOMPARE(trace->projection->draws[0].fate[0], TriangleFate::Clipped);
        inspection.setFrame(trace, QImage());
        // Nothing selected: the first clipped triangle of the list, at the first step.
        QCOMPARE(view.listedTriangles(), 1);
        QVERIFY(view.model());
        QCOMPARE(view.model()->source, 0u);
        QCOMPARE(view.step(), 0);
        QVERIFY(
            view.explanationText().contains(QStringLiteral("here near = 1, so P = (0, 0, 1, -1)")));
        QVERIFY(
            view.explanationText().contains(QStringLiteral("A0 = (0, 0, 3), A1 = (2, 0, 3), "
                                                           "A2 = (0, 4, -3)")));
        lookAt(view, QStringLiteral("near_clip_hand_step1"));
        auto* next = view.findChild<QPushButton*>(QStringLiteral("nearClipNext"));
        auto* back = view.findChild<QPushButton*>(QStringLiteral("nearClipBack"));
        auto* all = view.findChild<QPushButton*>(QStringLiteral("nearClipAll"));
        QVERIFY(next && back && all);
        QVERIFY(!back->isEnabled());
        for (int k = 0; k < 4; ++k) next->click();
        QCOMPARE(view.step(), 4);
        const QString edge12 = view.explanationText();
        QVERIFY2(edge12.contains(QStringLiteral(
                     "Edge A1–A2: dot(P, A1) = 2 and dot(P, A2) = -4 differ in sign: t = (0 − 2) "
                     "/ ((-4) − 2) = 0.333333, C = lerp(t, A1, A2) = (1.33333, 1.33333, 1), added "
                     "as q2.")),
                 qPrintable(edge12));
        QVERIFY(!edge12.contains(QStringLiteral("Vertex A2")));  // not yet
        lookAt(view, QStringLiteral("near_clip_hand_step5"));
        next->click();
        next->click();
        const QString edge20 = view.explanationText();
        QVERIFY(
            edge20.contains(QStringLiteral("Vertex A2: dot(P, A2) = -4 < 0: behind the "
                                           "plane, left out.")));
        QVERIFY2(edge20.contains(QStringLiteral("t = (0 − (-4)) / (2 − (-4)) = 0.666667, C = "
                                                "lerp(t, A2, A0) = (0, 1.33333, 1), added as "
                                                "q3. (The stage computes the same point from "
                                                "A0, the end in front, with t' = 1 − t = "
                                                "0.333333")),
                 qPrintable(edge20));
        back->click();
        QCOMPARE(view.step(), 5);
        all->click();
        QCOMPARE(view.step(), rasterlab::kNearClipSteps - 1);
        QVERIFY(!all->isEnabled() && !next->isEnabled());
        const QString end = view.explanationText();
        QVERIFY(
            end.contains(QStringLiteral("Output polygon, 4 vertices: q0 = (0, 0, 3), q1 = "
                                        "(2, 0, 3), q2 = (1.33333, 1.33333, 1), q3 = (0, "
                                        "1.33333, 1).")));
        QVERIFY(
            end.contains(QStringLiteral("split along the diagonal q0–q2 into the "
                                        "triangles q0 q1 q2 and q0 q2 q3")));
        QVERIFY2(end.contains(QStringLiteral("Triangle 1: (32, 32), (53, 32), (74, -10) "
                                             "(pixels)")),
                 qPrintable(end));
        QVERIFY(end.contains(QStringLiteral("Triangle 2: (32, 32), (74, -10), (32, -10)")));
        lookAt(view, QStringLiteral("near_clip_hand_all"));
        inspection.setPresentation(true);
        lookAt(view, QStringLiteral("near_clip_hand_presentation"));
    }

    // The trapezoid view of trapezoidsByHand's triangle, pixel (3, 2) picked: the corners and
    // row 2's numbers worked out there.
    void trapezoidViewByHand() {
        Inspection inspection;
        TrapezoidView view(&inspection);
        view.resize(800, 700);
        view.show();
        const auto trace = testing::renderTrace(trapezoidHandScene(ShadingModel::Phong));
        QCOMPARE(screenVertices(*trace->projection, trace->projection->triangles[0]),
                 (std::array<dvec2, 3>{dvec2(2, 0), dvec2(8, 4), dvec2(0, 8)}));
        inspection.setFrame(trace, QImage());
        inspection.pickPixel(QPoint(3, 2));
        QVERIFY(view.model());
        QVERIFY(!view.followsCursor());
        QCOMPARE(view.model()->split.parts.size(), std::size_t(2));
        QCOMPARE(view.model()->row->j, 2);
        QCOMPARE(*view.model()->pixel, 3);
        QVERIFY(!view.model()->hasColour);
        const QString text = view.explanationText();
        QVERIFY2(text.contains(QStringLiteral("s = (4 − 0) / (8 − 0) = 0.5: M' = lerp(s, top, "
                                              "bottom) = (1, 4), pz = 4.")),
                 qPrintable(text));
        QVERIFY(
            text.contains(QStringLiteral("t_j = (j − TL_j) / (BL_j − TL_j) = (2 − 0) / (4 − "
                                         "0) = 0.5")));
        QVERIFY(text.contains(QStringLiteral("L = lerp(t_j, TL, BL): i = 1.5, pz = 3")));
        QVERIFY(text.contains(QStringLiteral("R = lerp(t_j, TR, BR): i = 5, pz = 3")));
        QVERIFY(text.contains(QStringLiteral("Pixels i from ceil(L_i) to floor(R_i): 2 to 5.")));
        QVERIFY(
            text.contains(QStringLiteral("t_i = (i − L_i) / (R_i − L_i) = (3 − 1.5) / (5 − "
                                         "1.5) = 0.428571")));
        QVERIFY(text.contains(QStringLiteral("The depth test's z there: 3 ")));
        lookAt(view, QStringLiteral("trapezoid_hand"));
    }

    // A real frame, the trefoil cut open by the near plane, Gouraud shading, with a replay:
    // the near clip view lists the clipped triangles; the trapezoid view follows the stepping
    // cursor and carries the vertex colours.
    void viewsOnARealFrame() {
        Inspection inspection;
        NearClipView clip(&inspection);
        clip.resize(900, 640);
        clip.show();
        TrapezoidView trapezoids(&inspection);
        trapezoids.resize(800, 760);
        trapezoids.show();
        // The default trefoil, the near plane moved to about halfway through it (between the
        // nearest and the farthest vertex): what it cuts is in the picture.
        Scene cut = *testing::defaultCourseScene(ShadingModel::Gouraud, RuleSet::Course, 480, 360);
        double wMin = 1e300, wMax = -1e300;
        const auto whole = testing::renderTrace(std::make_shared<const Scene>(cut));
        for (const dvec4& p : whole->projection->draws[0].pClip) {
            wMin = std::min(wMin, p.w);
            wMax = std::max(wMax, p.w);
        }
        cut.nearPlane.fixedW = wMin + 0.45 * (wMax - wMin);
        const auto scene = std::make_shared<const Scene>(std::move(cut));
        const auto trace = testing::renderTrace(scene);
        inspection.setFrame(trace, QImage());
        const auto replay = testing::replayOf(trace);
        inspection.setReplay(replay);
        // Every triangle the near plane cut or hid, up to 5000.
        QCOMPARE(
            std::size_t(clip.listedTriangles()),
            std::min<std::size_t>(trace->projection->clipped + trace->projection->behind, 5000));
        QVERIFY(trace->projection->clipped > 0);
        // A triangle clipped into a quad whose first half has pixels on the screen, from the
        // list: the view selects what it drew.
        auto* list = clip.findChild<QComboBox*>(QStringLiteral("nearClipTriangles"));
        const auto fragmentsOf = [&](std::uint32_t t) {
            std::uint32_t n = 0;
            for (std::uint32_t r = replay->firstRow(t); r < replay->endRow(t); ++r)
                n += replay->rows()[r].fragmentEnd - replay->rows()[r].fragmentBegin;
            return n;
        };
        const int quad = firstListed(clip, [&](std::uint32_t draw, std::uint32_t source) {
            const NearClipRecord r = nearClipOf(*scene, *trace->projection, draw, source);
            const auto drawn = screenTrianglesOf(*trace->projection, draw, source);
            return r.polygon.size() == 4 && !drawn.empty() && fragmentsOf(drawn.front()) > 0;
        });
        QVERIFY(quad > 0);
        list->setCurrentIndex(quad);
        emit list->activated(quad);
        QVERIFY(clip.model() && clip.model()->record.polygon.size() == 4);
        QCOMPARE(clip.model()->projected.size(), std::size_t(2));
        QCOMPARE(inspection.selectedTriangle(), clip.model()->projected.front());
        QCOMPARE(list->currentIndex(), quad);
        clip.setStep(4);
        lookAt(clip, QStringLiteral("near_clip_trefoil_step5"));
        clip.setStep(rasterlab::kNearClipSteps - 1);
        lookAt(clip, QStringLiteral("near_clip_trefoil_all"));
        // A triangle wholly behind, chosen while another is selected: shown, nothing drawn.
        const int behind = firstListed(clip, [&](std::uint32_t draw, std::uint32_t source) {
            return trace->projection->draws[draw].fate[source] == TriangleFate::Behind;
        });
        QVERIFY(behind > 0);
        const auto selectedBefore = inspection.selectedTriangle();
        list->setCurrentIndex(behind);
        emit list->activated(behind);
        QCOMPARE(clip.model()->fate, TriangleFate::Behind);
        QVERIFY(clip.model()->record.gone());
        QCOMPARE(inspection.selectedTriangle(), selectedBefore);
        QCOMPARE(list->currentIndex(), behind);
        clip.setStep(rasterlab::kNearClipSteps - 1);
        QVERIFY(clip.explanationText().contains(
            QStringLiteral("Output polygon: empty. The triangle lies wholly behind the plane")));
        QVERIFY(
            clip.explanationText().contains(QStringLiteral("Nothing was drawn from this "
                                                           "triangle (wholly behind).")));
        // Another triangle selected elsewhere: the view follows the selection again.
        inspection.selectTriangle(0u);
        QCOMPARE(clip.model()->source, trace->projection->triangles[0].source);
        QVERIFY(!clip.model()->record.gone());
        // And back to the quad, from the list.
        list->setCurrentIndex(quad);
        emit list->activated(quad);
        QCOMPARE(list->currentIndex(), quad);
        QCOMPARE(clip.model()->record.polygon.size(), std::size_t(4));

        // The trapezoid view: the triangle selected (the cursor is at the end), its colours.
        QVERIFY(trapezoids.model());
        QCOMPARE(trapezoids.model()->triangle, *inspection.selectedTriangle());
        QVERIFY(trapezoids.model()->hasColour);
        // Step to a row in the middle of the frame's largest triangle.
        std::uint32_t largest = 0, most = 0;
        for (std::uint32_t t = 0; t < replay->triangleCount(); ++t) {
            const std::uint32_t fragments = fragmentsOf(t);
            if (fragments > most) {
                most = fragments;
                largest = t;
            }
        }
        const std::uint32_t row = (replay->firstRow(largest) + replay->endRow(largest)) / 2;
        inspection.seek(replay->atFragment(replay->rows()[row].fragmentBegin + 2));
        QVERIFY(trapezoids.followsCursor());
        QCOMPARE(trapezoids.model()->triangle, largest);
        QCOMPARE(trapezoids.model()->row->j, replay->rows()[row].y);
        QCOMPARE(trapezoids.model()->row->xBegin, replay->rows()[row].xBegin);
        QCOMPARE(trapezoids.model()->row->xEnd, replay->rows()[row].xEnd);
        QVERIFY(trapezoids.model()->hasColour);
        QVERIFY(trapezoids.explanationText().contains(QStringLiteral("(r, g, b)")));
        lookAt(trapezoids, QStringLiteral("trapezoid_trefoil"));

        // What the two views cost a step (a figure, not a check): 300 scanlines forward.
        inspection.setGranularity(StepGranularity::Scanline);
        QElapsedTimer timer;
        timer.start();
        int steps = 0;
        for (; steps < 300 && inspection.stepForward(); ++steps) {
        }
        qInfo("%d scanline steps with both views shown: %.3f ms a step", steps,
              double(timer.nsecsElapsed()) / 1e6 / std::max(steps, 1));
        QVERIFY(trapezoids.followsCursor());
    }
};

QTEST_MAIN(TestClipTrapezoid)
#include "tst_clip_trapezoid.moc"
