// The scanline view and the pixel inspector on a hand-made 8x8 scene whose numbers are
// worked out by hand: the edge table of a triangle (dx/dy, rows, sides), a row's crossings,
// span and the depth at its ends (equal to the replay's fragments, bit for bit), a row with
// no pixel; the history of a pixel written, rejected and written over, with the depth test's
// operators, verdicts and colours before and after; the Phong terms of a pixel lit straight
// from the front, and the filled-in formula; each special case of the lighting on a scene
// that triggers it; the fallback without a replay. The edge walk and the span ends are also
// checked against every row of the default scene under the course's and the GPU's rules.
#include <QtTest>

#include <QPainter>
#include <QTableWidget>

#include <cmath>

#include "app/documents/command_file.h"
#include "app/image_io.h"
#include "pipeline/io/hw2_reader.h"
#include "pipeline/render/output_image.h"
#include "pipeline/render/renderer.h"
#include "pipeline/render/replay.h"
#include "tests/course_scenes.h"
#include "tests/test_support.h"
#include "views/inspection.h"
#include "views/painted_labels.h"
#include "views/pixel_inspector.h"
#include "views/scanline_view.h"

using namespace rl;
using rasterlab::Inspection;
using rasterlab::LightingFlag;
using rasterlab::PixelHistoryRow;
using rasterlab::PixelInspector;
using rasterlab::ScanlineView;

namespace {

// testing::handScene's four triangles and a fifth, drawn in this order:
//   0: z = 1,   screen (0,0) (4,0) (0,4);
//   1: z = 2,   the same screen triangle, farther: rejected everywhere;
//   2: z = 0.5, screen (2,2) (6,2) (2,6): writes (2, 2) over triangle 0;
//   3: z = 1,   screen (5,0) (6,3) (7,3), wound the other way (its normal faces away);
//               row 1 has no pixel (its edges cross it at 5.33 and 5.67);
//   4: screen (5,4) z = 1, (7,4) z = 2, (5,7) z = 4: tilted, for the depth along a span.
// Material: ka = kd = 1, Od = (1, 0.5, 0.25), ks = 0.5, n = 2; Ia = 10.
// The light, by default at world (0.25, 0.25, -1) = view (-0.25, 0.25, -1), straight in
// front of pixel (2, 2) of triangle 2 (P' = (-0.25, 0.25, 0.5), N = (0, 0, -1)), with
// Il = (100, 200, 50).
struct HandOptions {
    dvec3 light{0.25, 0.25, -1.0};
    vec3 intensity{100.0f, 200.0f, 50.0f};
    float ambient = 10.0f;
    bool fileNormals = false;  // vertex 1 given the normal (0, 0, 1), the others (0, 0, -1)
    bool duplicate = false;    // triangle 0 drawn a second time, last
    bool winsOnTie = false;
    bool depthRangeClip = false;
    ShadingModel model = ShadingModel::Phong;
    vec3 secondLight{0.0f};  // a second light at the first one's place, when not zero
    // The lecture slides' lighting of the first light and the material.
    vec3 attenuation{1.0f, 0.0f, 0.0f};
    float spotCutoff = 180.0f;
    float spotExponent = 0.0f;
    vec3 emission{0.0f};
};

std::shared_ptr<const Scene> handScene(const HandOptions& o = {}) {
    std::vector<std::array<std::uint32_t, 3>> extra{{12, 13, 14}};
    if (o.duplicate) extra.push_back({0, 1, 2});
    Scene scene =
        testing::handScene(o.model, {{-0.25, 0, 1}, {-1.5, 0, 2}, {-1, -3, 4}}, std::move(extra));
    if (o.fileNormals) {
        auto mesh = std::make_shared<Mesh>(*scene.draws[0].mesh);
        mesh->normals.assign(mesh->positions.size(), vec3(0.0f, 0.0f, -1.0f));
        mesh->normals[1] = vec3(0.0f, 0.0f, 1.0f);
        scene.draws[0].mesh = std::move(mesh);
    }
    scene.ambientIntensity = vec3(o.ambient);
    scene.lights = {Light{dvec4(o.light, 1.0), o.intensity, {}}};
    scene.lights[0].attenuation = o.attenuation;
    scene.lights[0].spotDirection = dvec3(0.0, 0.0, 1.0);  // view (0, 0, 1) too
    scene.lights[0].spotCutoff = o.spotCutoff;
    scene.lights[0].spotExponent = o.spotExponent;
    scene.draws[0].material.emission = o.emission;
    if (o.secondLight != vec3(0.0f))
        scene.lights.push_back({dvec4(o.light, 1.0), o.secondLight, {}});
    Material& m = scene.draws[0].material;
    m.od = vec3(1.0f, 0.5f, 0.25f);
    m.ks = 0.5f;
    m.shininess = 2.0f;
    scene.conventions.depthWinsOnTie = o.winsOnTie;
    scene.conventions.depthRangeClip = o.depthRangeClip;
    return std::make_shared<const Scene>(std::move(scene));
}

std::shared_ptr<const FrameTrace> render(std::shared_ptr<const Scene> scene) {
    return testing::renderTrace(std::move(scene));
}

using testing::replayOf;

// The frame shown by an inspection, with its replay (or the replay's failure).
void show(Inspection& inspection, const std::shared_ptr<const FrameTrace>& frame,
          bool withReplay = true) {
    inspection.setFrame(frame, rasterlab::toQImage(colourImage(*frame->shading, *frame->depth,
                                                               frame->scene->conventions)));
    if (withReplay)
        inspection.setReplay(replayOf(frame));
    else
        inspection.setReplayError(QStringLiteral("too many fragments"));
}

std::array<std::uint8_t, 4> rgb(int r, int g, int b) {
    return {std::uint8_t(r), std::uint8_t(g), std::uint8_t(b), 255};
}

// The history rows of the fragments only.
std::vector<PixelHistoryRow> fragmentRows(const PixelInspector& inspector) {
    std::vector<PixelHistoryRow> out;
    for (const PixelHistoryRow& row : inspector.history())
        if (row.kind == PixelHistoryRow::Kind::Fragment) out.push_back(row);
    return out;
}

// The breakdown of the pixel picked on a hand scene with these options (at the end).
struct Picked {
    std::unique_ptr<Inspection> inspection;
    std::unique_ptr<PixelInspector> inspector;
};
Picked pick(const HandOptions& options, QPoint pixel, bool withReplay = true) {
    Picked p;
    p.inspection = std::make_unique<Inspection>();
    p.inspector = std::make_unique<PixelInspector>(p.inspection.get());
    p.inspector->show();
    show(*p.inspection, render(handScene(options)), withReplay);
    p.inspection->pickPixel(pixel);
    return p;
}

}  // namespace

class TestScanlineInspector : public QObject {
    Q_OBJECT
private slots:
    void edgeTableAndSpanAtTheCursor();
    void rowWithNoPixel();
    void flatTopTriangle();
    void selectedTriangleAtTheEnd();
    void ddaStepsACommandFile();
    void walkAndDepthMatchTheReplay_data();
    void walkAndDepthMatchTheReplay();
    void historyOfAPixel();
    void historyFollowsTheCursor();
    void phongTermsByHand();
    void severalLights();
    void slidesLightingByHand();
    void operatorsOnTies();
    void nothingAndEverythingRejected();
    void flags();
    void gouraudAndFlat();
    void blackExplained();
    void fallbackWithoutReplay();
    void imageAtTheCursorIsReadOnly();
    void labelsStayApartAndWhole_data();
    void labelsStayApartAndWhole();
    void screenshots();
};

void TestScanlineInspector::imageAtTheCursorIsReadOnly() {
    Inspection inspection;
    const auto frame = render(handScene());
    show(inspection, frame);
    // (2, 2) at the end: triangle 2's colour. Drawing on the image the Inspection hands out
    // draws on a copy: the buffer of the replay, which every view reads, stays as it is.
    const QRgb written = inspection.image().pixel(2, 2);
    QImage drawn = inspection.image();
    drawn.setPixel(2, 2, qRgb(1, 2, 3));
    QCOMPARE(drawn.pixel(2, 2), qRgb(1, 2, 3));
    QCOMPARE(inspection.image().pixel(2, 2), written);
    {
        QImage painted = inspection.image();
        QPainter painter(&painted);
        painter.fillRect(painted.rect(), Qt::green);
    }
    QCOMPARE(inspection.image().pixel(2, 2), written);
    // An image held while the cursor moves shows the buffer at the cursor.
    const QImage held = inspection.image();
    const std::array<std::uint8_t, 4> background = backgroundBytes(frame->scene->conventions);
    inspection.toStart();
    QCOMPARE(held.pixel(2, 2), qRgba(background[0], background[1], background[2], background[3]));
    inspection.toEnd();
    QCOMPARE(held.pixel(2, 2), written);
}

void TestScanlineInspector::edgeTableAndSpanAtTheCursor() {
    Inspection inspection;
    ScanlineView view(&inspection);
    view.resize(520, 640);
    view.show();
    QCOMPARE(view.objectName(), QStringLiteral("scanlineView"));
    const auto frame = render(handScene());
    show(inspection, frame);
    const FrameReplay& replay = *inspection.replay();
    // Triangle 4's rows are 4..7; row 5 is its second.
    QCOMPARE(replay.endRow(4) - replay.firstRow(4), 4u);
    const std::uint32_t k = replay.firstRow(4) + 1;
    QCOMPARE(replay.rows()[k].y, 5);
    inspection.seek(replay.atFragment(replay.rows()[k].fragmentBegin + 1));  // pixel 5 tested
    QVERIFY(view.followsCursor());
    QVERIFY(view.model());
    const rasterlab::ScanlineModel& m = *view.model();
    QCOMPARE(m.triangle, 4u);
    QCOMPARE(m.currentPixel, std::optional<int>(5));
    // Sorted by y: (5,4), (7,4), (5,7). (s1 - s0) x (s2 - s0) = (2,0) x (0,3) = 6 > 0: the
    // middle vertex is right of the long edge, which bounds the spans on the left.
    QCOMPARE(m.setup.doubleArea(), 6.0);
    const auto& [longEdge, upper, lower] = m.edges;
    QCOMPARE(longEdge.top, dvec2(5, 4));
    QCOMPARE(longEdge.bottom, dvec2(5, 7));
    QCOMPARE(longEdge.dxdy, 0.0);
    QCOMPARE(longEdge.firstRow, 4);
    QCOMPARE(longEdge.lastRow, 7);
    QVERIFY(longEdge.onLeft);
    QVERIFY(upper.horizontal);  // (5,4) -> (7,4): flat top, no row walked on it
    QVERIFY(!upper.walked());
    QVERIFY(!upper.onLeft);
    QCOMPARE(lower.top, dvec2(7, 4));
    QCOMPARE(lower.bottom, dvec2(5, 7));
    RL_COMPARE_NEAR(lower.dxdy, -2.0 / 3.0, 1e-15);
    QCOMPARE(lower.firstRow, 4);
    QCOMPARE(lower.lastRow, 7);
    QCOMPARE(lower.xFirstRow, 7.0);
    QVERIFY(!lower.onLeft);
    // Row 5: x_left = 5, x_right = 7 - 2/3; pixels ceil(5) = 5 to floor(6.33) = 6.
    QVERIFY(m.row);
    const rasterlab::ScanRowInfo& row = *m.row;
    QCOMPARE(row.y, 5);
    QVERIFY(!row.upperPart);
    QCOMPARE(row.xLeft, 5.0);
    RL_COMPARE_NEAR(row.xRight, 7.0 - 2.0 / 3.0, 1e-12);
    QCOMPARE(row.xBegin, 5);
    QCOMPARE(row.xEnd, 7);
    // The span's ends. P1 = (5,4), e1 = (2,0), e2 = (0,3), A = 6. Pixel (5,5): s - P1 =
    // (0,1), beta = 0, gamma = 2/6; z = 1 + 0 (2 - 1) + 1/3 (4 - 1) = 2. Pixel (6,5):
    // beta = 3/6, gamma = 2/6; z = 1 + 0.5 + 1 = 2.5.
    QVERIFY(row.first && row.last);
    QCOMPARE(row.first->x, 5);
    QCOMPARE(row.last->x, 6);
    RL_COMPARE_NEAR(row.first->beta, 0.0, 1e-7);
    RL_COMPARE_NEAR(row.first->gamma, 1.0 / 3.0, 1e-7);
    RL_COMPARE_NEAR(row.first->depth, 2.0, 1e-6);
    RL_COMPARE_NEAR(row.last->beta, 0.5, 1e-7);
    RL_COMPARE_NEAR(row.last->gamma, 1.0 / 3.0, 1e-7);
    RL_COMPARE_NEAR(row.last->depth, 2.5, 1e-6);
    // The depths shown are the depth test's, bit for bit.
    const ReplayRow& walked = replay.rows()[k];
    QVERIFY(row.first->depth == replay.fragments()[walked.fragmentBegin].depth);
    QVERIFY(row.last->depth == replay.fragments()[walked.fragmentEnd - 1].depth);
    // The normal: the view-space vertices (0.25,0,1), (1.5,0,2), (1,-3,4) give
    // (1.25,0,1) x (0.75,-3,3) = (3, -3, -3.75), the same at every vertex.
    const vec3 n = glm::normalize(vec3(3.0f, -3.0f, -3.75f));
    QVERIFY(row.first->hasNormal);
    RL_COMPARE_VEC(row.first->normal, n, 1e-6);
    RL_COMPARE_VEC(row.last->normal, n, 1e-6);
    // The explanation carries the numbers.
    const QString text = view.explanationText();
    QVERIFY2(text.contains(QStringLiteral("x_right(5) = x_right(4) + dx/dy = 7 + (-0.666667) = "
                                          "6.33333 along the lower edge")),
             qPrintable(text));
    QVERIFY(text.contains(QStringLiteral("x_left(5) = x_left(4) + dx/dy = 5 + 0 = 5")));
    QVERIFY(text.contains(
        QStringLiteral("Inclusive rule: the pixels from ceil(x_left) = 5 to floor(x_right) = 6")));
    QVERIFY(text.contains(QStringLiteral("Span [5, 7): 2 pixels.")));
    QVERIFY(text.contains(QStringLiteral("1 + 0 × 1 + 0.333333 × 3 = 2")));
    QVERIFY(text.contains(QStringLiteral("1 + 0.5 × 1 + 0.333333 × 3 = 2.5")));
    QVERIFY(view.titleText().contains(QStringLiteral("scanline 5")));
    // The drawing shows the whole 8x8 screen around the triangle (its box grown by one pixel,
    // then to the smallest window, within the screen).
    QVERIFY(view.drawnWindow().contains(QRect(4, 3, 4, 5)));

    // The first row of the lower edge: x_right starts where the edge crosses it.
    inspection.seek(replay.atRowStart(replay.firstRow(4)));
    QVERIFY(view.explanationText().contains(
        QStringLiteral("x_right(4) = 7, where the lower edge crosses its first row")));
    QCOMPARE(view.model()->currentPixel, std::nullopt);
}

void TestScanlineInspector::rowWithNoPixel() {
    Inspection inspection;
    ScanlineView view(&inspection);
    view.show();
    show(inspection, render(handScene()));
    const FrameReplay& replay = *inspection.replay();
    const std::uint32_t k = replay.firstRow(3) + 1;  // triangle 3, row 1
    inspection.seek(replay.atRowStart(k));
    const rasterlab::ScanlineModel& m = *view.model();
    QCOMPARE(m.triangle, 3u);
    // Sorted: (5,0), (6,3), (7,3); (1,3) x (2,3) = -3 < 0: the long edge is on the right.
    QCOMPARE(m.setup.doubleArea(), -3.0);
    RL_COMPARE_NEAR(m.edges[0].dxdy, 2.0 / 3.0, 1e-15);
    QVERIFY(!m.edges[0].onLeft);
    RL_COMPARE_NEAR(m.edges[1].dxdy, 1.0 / 3.0, 1e-15);
    QVERIFY(m.edges[1].onLeft);
    QCOMPARE(m.edges[1].firstRow, 0);
    QCOMPARE(m.edges[1].lastRow, 3);  // flat bottom: the upper edge bounds every row
    QVERIFY(m.edges[2].horizontal);
    QVERIFY(!m.edges[2].walked());
    QVERIFY(m.row && m.row->empty());
    QCOMPARE(m.row->y, 1);
    RL_COMPARE_NEAR(m.row->xLeft, 5.0 + 1.0 / 3.0, 1e-12);
    RL_COMPARE_NEAR(m.row->xRight, 5.0 + 2.0 / 3.0, 1e-12);
    QCOMPARE(m.row->xLeft, replay.rows()[k].xLeft);
    QCOMPARE(m.row->xRight, replay.rows()[k].xRight);
    QVERIFY(!m.row->first);
    const QString text = view.explanationText();
    QVERIFY2(text.contains(QStringLiteral("ceil(x_left) = 6 to floor(x_right) = 5")),
             qPrintable(text));
    QVERIFY(
        text.contains(QStringLiteral("No pixel on this row: the edges cross it between two "
                                     "samples.")));
}

void TestScanlineInspector::flatTopTriangle() {
    // Triangle 0: (0,0) (4,0) (0,4); the upper edge is horizontal, the long edge (dx/dy = 0)
    // on the left, the lower edge (dx/dy = -1) on the right of rows 0..4.
    const auto frame = render(handScene());
    const rasterlab::ScanlineModel m = rasterlab::scanlineModel(*frame, 0, 2);
    QVERIFY(m.edges[1].horizontal);
    QCOMPARE(m.edges[2].dxdy, -1.0);
    QCOMPARE(m.edges[2].firstRow, 0);
    QCOMPARE(m.edges[2].lastRow, 4);
    QCOMPARE(m.row->xLeft, 0.0);
    QCOMPARE(m.row->xRight, 2.0);
    QCOMPARE(m.row->xBegin, 0);
    QCOMPARE(m.row->xEnd, 3);
    QCOMPARE(m.row->first->depth, 1.0f);
    // A row off the triangle has no scanline.
    QVERIFY(!rasterlab::scanlineModel(*frame, 0, 5).row);
}

void TestScanlineInspector::selectedTriangleAtTheEnd() {
    Inspection inspection;
    ScanlineView view(&inspection);
    view.show();
    show(inspection, render(handScene()));
    QVERIFY(inspection.atEnd());
    QVERIFY(!view.model());              // nothing selected yet
    inspection.pickPixel(QPoint(6, 5));  // held by triangle 4
    QVERIFY(!view.followsCursor());
    QVERIFY(view.model());
    QCOMPARE(view.model()->triangle, 4u);
    QCOMPARE(view.model()->row->y, 5);
    QCOMPARE(view.model()->currentPixel, std::optional<int>(6));
    QVERIFY(view.titleText().contains(QStringLiteral("the triangle selected")));
    // At the start, likewise.
    inspection.toStart();
    QCOMPARE(view.model()->triangle, 4u);
    QVERIFY(!view.followsCursor());
}

void TestScanlineInspector::walkAndDepthMatchTheReplay_data() {
    QTest::addColumn<std::shared_ptr<const Scene>>("scene");
    QTest::newRow("hand") << handScene();
    QTest::newRow("trefoil, course rules")
        << testing::defaultCourseScene(ShadingModel::Phong, RuleSet::Course, 160, 120);
    QTest::newRow("trefoil, gpu rules")
        << testing::defaultCourseScene(ShadingModel::Phong, RuleSet::Gpu, 160, 120);
    QTest::newRow("trefoil, hw2 rules (seed 001's DDA)")
        << testing::defaultCourseScene(ShadingModel::Phong, RuleSet::Hw2, 160, 120);
}

void TestScanlineInspector::ddaStepsACommandFile() {
    // A command file, stepped under the hw2 rules: the triangle (0, 0), (2, 18), (6, 18) on an
    // 8x32 image (NDC (-1, -1), (-0.5, 0.125), (0.5, 0.125), every coordinate exact). Its
    // left edge has dx/dy = 2/18, which the DDA adds row by row: on row 9 it has reached
    // 1.0000000000000002, not 1, so pixel (1, 9) is left out. The view shows the sums.
    const std::string text =
        "png 8 32 tie.png\nxyz -1 -1 0\nxyz -0.5 0.125 0.5\n"
        "xyz 0.5 0.125 0.25\ntrif 1 2 3\n";
    Diagnostics diagnostics;
    const TextureLoader noTextures =
        [](const std::string&,
           const SourceLocation& where) -> Result<std::shared_ptr<const Texture>> {
        return makeError(ErrorCode::Io, where, "no textures here");
    };
    auto file = readHw2(text, "tie.txt", noTextures, diagnostics);
    QVERIFY(file);
    QCOMPARE(file->images.at(0).scene.rules, RasterRules::hw2());
    Inspection inspection;
    ScanlineView view(&inspection);
    view.resize(520, 640);
    view.show();
    show(inspection, render(std::make_shared<const Scene>(file->images.at(0).scene)));
    const FrameReplay& replay = *inspection.replay();
    QCOMPARE(replay.endRow(0) - replay.firstRow(0), 18u);  // rows 0 to 17
    const std::uint32_t k = replay.firstRow(0) + 9;
    QCOMPARE(replay.rows()[k].y, 9);
    // Stepping by row, then by pixel: the row's first fragment is pixel 2.
    inspection.seek(replay.atRowStart(k));
    QVERIFY(view.model() && view.model()->row);
    double x = 0.0;
    for (int i = 0; i < 9; ++i) x += 2.0 / 18.0;
    const rasterlab::ScanRowInfo& row = *view.model()->row;
    QCOMPARE(row.xLeft, x);
    QCOMPARE(row.xBegin, 2);
    QCOMPARE(row.xEnd, 3);
    // Sorted by y, ties in file order: top (0, 0), middle (2, 18), bottom (6, 18). The flat
    // bottom leaves every row to the upper edge, on the left; the long edge is on the right.
    const auto& upperEdge = view.model()->edges[1];
    QCOMPARE(upperEdge.dxdy, 2.0 / 18.0);
    QCOMPARE(upperEdge.xFirstRow, 0.0);
    QVERIFY(upperEdge.onLeft);
    QCOMPARE(view.model()->edges[0].dxdy, 6.0 / 18.0);
    const QString explanation = view.explanationText();
    QVERIFY2(explanation.contains(QStringLiteral("x_left(9) = x_left(8) + dx/dy = "
                                                 "0.88888888888888906 + 0.1111111111111111 = "
                                                 "1.0000000000000002 along the upper edge")),
             qPrintable(explanation));
    QVERIFY(explanation.contains(QStringLiteral("Seed 001's DDA")));
    QVERIFY(explanation.contains(QStringLiteral("Span [2, 3): 1 pixel.")));
    // The depth is stepped the same way, from z = 0 at the top: by 0.5/18 a row down the upper
    // edge (to z = 0.5 at (2, 18)) and by 0.25/18 down the long edge (to 0.25 at (6, 18)),
    // then along the row from x_left by (z_right - z_left) / (x_right - x_left).
    double zLeft = 0.0, zRight = 0.0;
    for (int i = 0; i < 9; ++i) {
        zLeft += 0.5 / 18.0;
        zRight += 0.25 / 18.0;
    }
    const double dzdx = (zRight - zLeft) / (3.0 - x);
    const double z = zLeft + (2.0 - x) * dzdx;
    const auto digits = [](double v) { return QString::number(v, 'g', 17); };
    QVERIFY(dzdx < 0.0);  // shown in brackets after a sign
    QVERIFY2(explanation.contains(QStringLiteral("On this row z = %1 at x_left and %2 at x_right: "
                                                 "z + (%3) a pixel")
                                      .arg(digits(zLeft), digits(zRight), digits(dzdx))),
             qPrintable(explanation));
    QVERIFY2(explanation.contains(QStringLiteral("(2, 9): z = %1 + (2 \u2212 %2) \u00d7 (%3) = %4.")
                                      .arg(digits(zLeft), digits(x), digits(dzdx), digits(z))),
             qPrintable(explanation));
    QCOMPARE(view.model()->row->first->depth, static_cast<float>(z));
    inspection.seek(replay.atFragment(replay.rows()[k].fragmentBegin));
    QCOMPARE(view.model()->currentPixel, std::optional<int>(2));
}

void TestScanlineInspector::walkAndDepthMatchTheReplay() {
    // Every row the view works out is the one the edge walk recorded, and the depths at the
    // span's ends are the fragments', bit for bit; the normals those shading interpolates.
    QFETCH(std::shared_ptr<const Scene>, scene);
    const auto frame = render(scene);
    const auto replay = replayOf(frame);
    std::size_t rows = 0, compared = 0;
    std::vector<std::uint32_t> sampled;
    for (std::uint32_t k = 0; k < replay->rows().size(); ++k) {
        const ReplayRow& walked = replay->rows()[k];
        const rasterlab::ScanlineModel m =
            rasterlab::scanlineModel(*frame, walked.triangle, walked.y);
        QVERIFY(m.row);
        QCOMPARE(m.row->xBegin, walked.xBegin);
        QCOMPARE(m.row->xEnd, walked.xEnd);
        QCOMPARE(m.row->xLeft, walked.xLeft);
        QCOMPARE(m.row->xRight, walked.xRight);
        ++rows;
        if (walked.empty()) continue;
        QVERIFY(m.row->first->depth == replay->fragments()[walked.fragmentBegin].depth);
        QVERIFY(m.row->last->depth == replay->fragments()[walked.fragmentEnd - 1].depth);
        compared += 2;
        if (k % 97 == 0) sampled.push_back(walked.fragmentBegin);
    }
    QCOMPARE(rows, replay->rows().size());
    QVERIFY(compared > 0);
    const std::vector<ShadeEvent> events = replay->shade(sampled);
    for (std::size_t i = 0; i < sampled.size(); ++i) {
        const ReplayFragment& f = replay->fragments()[sampled[i]];
        const rasterlab::SpanEnd end =
            rasterlab::spanEnd(*frame, f.triangle, f.y, replay->rows()[f.row].xBegin, f.x);
        const vec3 n = events[i].nInterpolated;
        if (glm::length(n) == 0.0f) continue;
        RL_COMPARE_VEC(end.normal, glm::normalize(n), 1e-6);
    }
}

void TestScanlineInspector::historyOfAPixel() {
    Picked p = pick({}, QPoint(2, 2));
    PixelInspector& inspector = *p.inspector;
    QCOMPARE(inspector.objectName(), QStringLiteral("pixelInspector"));
    QCOMPARE(inspector.pixel(), QPoint(2, 2));
    QVERIFY(!inspector.traced());
    const auto& history = inspector.history();
    QCOMPARE(history.size(), std::size_t(5));  // initial, three fragments, final
    QVERIFY(history.front().kind == PixelHistoryRow::Kind::Initial);
    QCOMPARE(history.front().depthText, QStringLiteral("cleared to +inf"));
    QCOMPARE(*history.front().after, rgb(0, 0, 0));
    const std::vector<PixelHistoryRow> rows = fragmentRows(inspector);
    QCOMPARE(rows.size(), std::size_t(3));
    // 1. Triangle 1 (index 0), z = 1 against the cleared +inf: written. At (2,2) its
    //    barycentrics are (0, 1/2, 1/2): P' = (-0.5, 0.5, 1), L = (0.25, -0.25, -2)/|.|,
    //    N.L = 0.98473, R.V = 0.70353: (133.2, 157.97, 34.68) -> (133, 157, 34).
    QCOMPARE(rows[0].meshTriangle, 1u);
    QCOMPARE(rows[0].depthText, QStringLiteral("1 < +inf"));
    QCOMPARE(rows[0].resultText, QStringLiteral("written"));
    QCOMPARE(*rows[0].before, rgb(0, 0, 0));
    QCOMPARE(*rows[0].after, rgb(133, 157, 34));
    // 2. Triangle 2, z = 2 against 1: rejected, the colour stays.
    QCOMPARE(rows[1].meshTriangle, 2u);
    QCOMPARE(rows[1].depthText, QStringLiteral("2 >= 1"));
    QCOMPARE(rows[1].resultText, QStringLiteral("rejected: farther"));
    QVERIFY(rows[1].verdict == FragmentVerdict::Rejected);
    QCOMPARE(*rows[1].before, rgb(133, 157, 34));
    QCOMPARE(*rows[1].after, rgb(133, 157, 34));
    // 3. Triangle 3, z = 0.5 against 1: written over, (143.3, 176.7, 39.2) (phongTermsByHand).
    QCOMPARE(rows[2].meshTriangle, 3u);
    QCOMPARE(rows[2].depthText, QStringLiteral("0.5 < 1"));
    QCOMPARE(*rows[2].before, rgb(133, 157, 34));
    QCOMPARE(*rows[2].after, rgb(143, 176, 39));
    const PixelHistoryRow& last = history.back();
    QVERIFY(last.kind == PixelHistoryRow::Kind::Final);
    QCOMPARE(last.meshTriangle, 3u);
    QCOMPARE(last.depthText, QStringLiteral("depth 0.5"));
    QCOMPARE(*last.after, rgb(143, 176, 39));
    QCOMPARE(inspector.verdictText(),
             QStringLiteral("Written by triangle 3, over 1 earlier write; 1 fragment rejected."));
    // At the end every row is reached and the last write holds the pixel.
    for (const PixelHistoryRow& row : history) QVERIFY(row.reached);
    QVERIFY(history[3].atCursor);
    QCOMPARE(inspector.selectedRow(), 3);
    QCOMPARE(inspector.historyTable()->rowCount(), 5);
    QVERIFY(inspector.historyTable()->item(3, 0)->text().startsWith(QStringLiteral("▶")));
    QCOMPARE(inspector.historyTable()->item(2, 4)->text(), QStringLiteral("(133, 157, 34)"));
    QCOMPARE(inspector.historyTable()->item(2, 5)->text(), QStringLiteral("rejected: farther"));
}

void TestScanlineInspector::historyFollowsTheCursor() {
    Picked p = pick({}, QPoint(2, 2));
    Inspection& inspection = *p.inspection;
    PixelInspector& inspector = *p.inspector;
    const FrameReplay& replay = *inspection.replay();
    const std::vector<std::uint32_t> at = replay.fragmentsAt(2, 2);
    QCOMPARE(at.size(), std::size_t(3));
    // Just after triangle 1's fragment: the rest is not reached yet; triangle 1 holds it.
    inspection.seek(replay.atFragment(at[0] + 1));
    const auto& history = inspector.history();
    QVERIFY(history[1].reached && history[1].atCursor);
    QVERIFY(!history[2].reached && !history[3].reached && !history[4].reached);
    QVERIFY(!history[3].atCursor);
    QCOMPARE(inspector.historyTable()->item(2, 5)->toolTip(),
             QStringLiteral("not reached yet by the stepping cursor"));
    QCOMPARE(inspector.historyTable()->item(2, 5)->foreground().color(), QColor(150, 150, 150));
    QCOMPARE(inspector.selectedRow(), 1);
    QVERIFY(inspector.breakdown());
    QCOMPARE(inspector.breakdown()->bytes, rgb(133, 157, 34));
    // At the start, nothing holds it: the cleared row is marked and nothing is lit.
    inspection.toStart();
    QVERIFY(history[0].atCursor);
    QCOMPARE(inspector.selectedRow(), -1);
    QVERIFY(!inspector.breakdown());
    // A row chosen by hand stays while the cursor moves; a rejected fragment's lighting is
    // shown too.
    inspector.selectRow(2);
    inspection.toEnd();
    QCOMPARE(inspector.selectedRow(), 2);
    QVERIFY(inspector.breakdown());
    QCOMPARE(inspector.breakdown()->historyRow, 2);
}

void TestScanlineInspector::phongTermsByHand() {
    // (2, 2) of triangle 3 (index 2): P' = (-0.25, 0.25, 0.5) (its first vertex), N = (0, 0,
    // -1), the light straight in front: L = (0, 0, -1), N.L = 1, R = (0, 0, -1), V = -P'/|P'|
    // so R.V = 0.5 / sqrt(0.375) = 0.816497 and (R.V)^2 = 2/3.
    //   ambient  Ia ka = 10;  diffuse Il Od kd (N.L) = (100, 100, 12.5);
    //   specular Il ks (R.V)^2 = (100, 200, 50) x 0.5 x 2/3 = (33.33, 66.67, 16.67).
    Picked p = pick({}, QPoint(2, 2));
    const auto& b = p.inspector->breakdown();
    QVERIFY(b);
    QVERIFY(b->lighting == LightingModel::CoursePhong);
    QVERIFY(b->event.model == ShadingModel::Phong);
    RL_COMPARE_NEAR(b->event.sample.nDotL, 1.0, 1e-6);
    RL_COMPARE_NEAR(b->event.sample.rDotV, std::sqrt(2.0 / 3.0), 1e-6);
    RL_COMPARE_VEC(b->event.sample.n, vec3(0, 0, -1), 1e-6);
    RL_COMPARE_VEC(b->event.sample.l, vec3(0, 0, -1), 1e-6);
    RL_COMPARE_VEC(b->ambient, vec3(10.0f), 1e-5);
    RL_COMPARE_VEC(b->diffuse, vec3(100.0f, 100.0f, 12.5f), 1e-4);
    RL_COMPARE_VEC(b->specular, vec3(100.0f / 3.0f, 200.0f / 3.0f, 50.0f / 3.0f), 1e-3);
    RL_COMPARE_VEC(b->colour, vec3(430.0f / 3.0f, 530.0f / 3.0f, 117.5f / 3.0f), 1e-3);
    QCOMPARE(b->bytes, rgb(143, 176, 39));
    QVERIFY(b->flags.empty());
    QCOMPARE(p.inspector->formulaText(),
             QStringLiteral("I = Ia ka + Il Od kd (N.L) + Il ks (R.V)^n\n"
                            "N.L = 1, R.V = 0.816497, n = 2\n"
                            "R = 10 × 1 + 100 × 1 × 1 × 1 + 100 × 0.5 × 0.816497^2 = "
                            "10 + 100 + 33.3333 = 143.333 → 143\n"
                            "G = 10 × 1 + 200 × 0.5 × 1 × 1 + 200 × 0.5 × 0.816497^2 = "
                            "10 + 100 + 66.6667 = 176.667 → 176\n"
                            "B = 10 × 1 + 50 × 0.25 × 1 × 1 + 50 × 0.5 × 0.816497^2 = "
                            "10 + 12.5 + 16.6667 = 39.1667 → 39\n"
                            "Ia = (10, 10, 10), ka = 1, Il = (100, 200, 50), Od = (1, 0.5, 0.25), "
                            "kd = (1, 1, 1), ks = 0.5"));
}

void TestScanlineInspector::severalLights() {
    // A second light at the same place, Il = 10: it adds 10 (N.L) + 10 x 0.5 x 2/3 = 13.33 to
    // red; the numbers filled in are the first light's, the others' sum added.
    HandOptions options;
    options.secondLight = vec3(10.0f);
    Picked p = pick(options, QPoint(2, 2));
    const QStringList lines = p.inspector->breakdown()->formula;
    QCOMPARE(lines.value(0), QStringLiteral("2 lights: the diffuse and specular terms are sums "
                                            "over them; the numbers filled in are the first "
                                            "light's."));
    QCOMPARE(lines.value(3), QStringLiteral("R = 10 × 1 + 100 × 1 × 1 × 1 + 100 × 0.5 × "
                                            "0.816497^2 + 13.33 (the other lights) = 10 + 110 + "
                                            "36.6667 = 156.667 → 156"));
}

void TestScanlineInspector::slidesLightingByHand() {
    // (2, 2) as in phongTermsByHand, the light 1.5 away (view (-0.25, 0.25, -1) to P' =
    // (-0.25, 0.25, 0.5)) attenuated by kc kl kq = 0.5, 1, 0: 1 / (0.5 + 1.5) = 0.5, so
    // diffuse (50, 50, 6.25) and specular (16.67, 33.33, 8.33); Ke = (5, 0, 0):
    //   R = 5 + 10 + 50 + 16.667 = 81.667 -> 81, G = 93.333 -> 93, B = 24.583 -> 24.
    // A spot along +z (cutoff 30, exponent 2): -L.D = 1 at (2, 2), factor 1.
    HandOptions options;
    options.attenuation = vec3(0.5f, 1.0f, 0.0f);
    options.emission = vec3(5.0f, 0.0f, 0.0f);
    options.spotCutoff = 30.0f;
    options.spotExponent = 2.0f;
    Picked p = pick(options, QPoint(2, 2));
    const auto& b = p.inspector->breakdown();
    QVERIFY(b);
    QVERIFY(b->slides);
    QCOMPARE(b->perLight.size(), std::size_t(1));
    RL_COMPARE_NEAR(b->perLight[0].distance, 1.5, 1e-6);
    RL_COMPARE_NEAR(b->perLight[0].attenuation, 0.5, 1e-7);
    RL_COMPARE_NEAR(b->perLight[0].spot, 1.0, 1e-6);
    RL_COMPARE_VEC(b->perLight[0].diffuse, vec3(50.0f, 50.0f, 6.25f), 1e-4);
    RL_COMPARE_VEC(b->perLight[0].specular, vec3(50.0f / 3.0f, 100.0f / 3.0f, 25.0f / 3.0f), 1e-3);
    RL_COMPARE_VEC(b->emission, vec3(5.0f, 0.0f, 0.0f), 0.0);
    QCOMPARE(b->bytes, rgb(81, 93, 24));
    const QStringList& f = b->formula;
    QCOMPARE(f.value(0), QStringLiteral("I = Ke + Ia ka + Σ att spot (Il Od kd (N.L) + Il ks "
                                        "(R.V)^n)"));
    QVERIFY2(f.contains(QStringLiteral("R = 5 + 10 + 50 + 16.6667 = 81.6667 → 81")),
             qPrintable(f.join(QLatin1Char('\n'))));
    QVERIFY(f.contains(QStringLiteral("Ke = (5, 0, 0): the material's own light")));
    QVERIFY(f.contains(
        QStringLiteral("  att = 1 / (0.5 + 1 × 1.5 + 0 × 1.5²) = 0.5; spot: −L.D = 1 ≥ cos 30° "
                       "= 0.866, 1^2 = 1")));

    // (5, 2): P' = (0.125, 0.25, 0.5), -L = (0.375, 0, 1.5)/1.546, -L.D = 0.970143 (14.04
    // degrees off the axis): outside a 10-degree cone, nothing from the light; inside a
    // 30-degree one, (16/17) = 0.941176 of it.
    options.spotCutoff = 10.0f;
    Picked outside = pick(options, QPoint(5, 2));
    const auto& o = outside.inspector->breakdown();
    QVERIFY(o);
    QVERIFY(o->perLight.at(0).outsideCone);
    RL_COMPARE_NEAR(o->perLight[0].spotCos, 0.970143, 1e-5);
    QVERIFY(o->has(rasterlab::LightingFlag::OutsideCone));
    RL_COMPARE_VEC(o->colour, vec3(15.0f, 10.0f, 10.0f), 1e-5);  // Ke + Ia ka only
    options.spotCutoff = 30.0f;
    Picked inside = pick(options, QPoint(5, 2));
    RL_COMPARE_NEAR(inside.inspector->breakdown()->perLight.at(0).spot, 16.0 / 17.0, 1e-5);
    QVERIFY(!inside.inspector->breakdown()->has(rasterlab::LightingFlag::OutsideCone));
}

void TestScanlineInspector::operatorsOnTies() {
    // Triangle 1 drawn again, last: at (1, 1) it is as far as the first draw.
    HandOptions options;
    options.duplicate = true;
    Picked strict = pick(options, QPoint(1, 1));
    std::vector<PixelHistoryRow> rows = fragmentRows(*strict.inspector);
    QCOMPARE(rows.size(), std::size_t(3));
    QCOMPARE(rows[2].meshTriangle, 6u);
    QCOMPARE(rows[2].depthText, QStringLiteral("1 >= 1"));
    QCOMPARE(rows[2].resultText, QStringLiteral("rejected: as far, the earlier keeps it"));
    QCOMPARE(strict.inspector->verdictText(),
             QStringLiteral("Written by triangle 1; 2 fragments rejected."));
    // z <= stored writes (seed 001): the later one wins the tie; the farther one is "> ".
    options.winsOnTie = true;
    Picked tie = pick(options, QPoint(1, 1));
    rows = fragmentRows(*tie.inspector);
    QCOMPARE(rows[0].depthText, QStringLiteral("1 <= +inf"));
    QCOMPARE(rows[1].depthText, QStringLiteral("2 > 1"));
    QCOMPARE(rows[1].resultText, QStringLiteral("rejected: farther"));
    QCOMPARE(rows[2].depthText, QStringLiteral("1 <= 1"));
    QCOMPARE(rows[2].resultText, QStringLiteral("written"));
    QCOMPARE(tie.inspector->verdictText(),
             QStringLiteral("Written by triangle 6, over 1 earlier write; 1 fragment rejected."));
}

void TestScanlineInspector::nothingAndEverythingRejected() {
    Picked empty = pick({}, QPoint(7, 7));
    QCOMPARE(fragmentRows(*empty.inspector).size(), std::size_t(0));
    QCOMPARE(empty.inspector->verdictText(),
             QStringLiteral("Nothing drew here: the pixel keeps the background (0, 0, 0)."));
    QCOMPARE(empty.inspector->history().size(), std::size_t(2));  // initial and final
    QCOMPARE(empty.inspector->history().back().triangleText, QStringLiteral("none"));
    // Depths outside [0, 1] discarded: (6, 4) of triangle 5 has z = 1 + 0.5 (2 - 1) = 1.5.
    HandOptions options;
    options.depthRangeClip = true;
    Picked clipped = pick(options, QPoint(6, 4));
    const std::vector<PixelHistoryRow> rows = fragmentRows(*clipped.inspector);
    QCOMPARE(rows.size(), std::size_t(1));
    QVERIFY(rows[0].verdict == FragmentVerdict::OutsideDepthRange);
    QCOMPARE(rows[0].depthText, QStringLiteral("1.5 outside [0, 1]"));
    QCOMPARE(rows[0].resultText, QStringLiteral("discarded: depth outside [0, 1]"));
    QCOMPARE(clipped.inspector->verdictText(),
             QStringLiteral("The only fragment was rejected: the pixel keeps the background."));
}

void TestScanlineInspector::flags() {
    // Triangle 4 (index 3) is wound the other way: its normal faces away and is turned.
    Picked flipped = pick({}, QPoint(5, 0));
    QVERIFY(flipped.inspector->breakdown());
    QVERIFY(flipped.inspector->breakdown()->has(LightingFlag::Flipped));
    QVERIFY(!flipped.inspector->breakdown()->has(LightingFlag::LightBehind));
    RL_COMPARE_VEC(flipped.inspector->breakdown()->event.sample.n, vec3(0, 0, -1), 1e-6);

    // The light behind everything: N.L < 0, no diffuse, no specular.
    HandOptions behind;
    behind.light = dvec3(0.0, 0.0, 10.0);
    Picked back = pick(behind, QPoint(2, 2));
    const auto& b = back.inspector->breakdown();
    QVERIFY(b->has(LightingFlag::LightBehind));
    QVERIFY(!b->has(LightingFlag::NoSpecular));
    QVERIFY(b->flagTexts.contains(
        QStringLiteral("N.L < 0: the light is behind the surface; no diffuse, no specular.")));
    QVERIFY(back.inspector->formulaText().contains(
        QStringLiteral("R = 10 × 1 + 0 = 10 + 0 + 0 = 10 → 10")));

    // A light grazing from the viewer's side: N.L > 0 barely, the reflection points away.
    HandOptions grazing;
    grazing.light = dvec3(-100.0, 0.75, 0.99);
    Picked graze = pick(grazing, QPoint(1, 1));
    QVERIFY(graze.inspector->breakdown()->has(LightingFlag::NoSpecular));
    QVERIFY(graze.inspector->breakdown()->event.sample.nDotL > 0.0f);
    QVERIFY(graze.inspector->breakdown()->event.sample.rDotV < 0.0f);
    RL_COMPARE_VEC(graze.inspector->breakdown()->specular, vec3(0.0f), 0.0);

    // Too bright: every channel above 255.
    HandOptions bright;
    bright.intensity = vec3(1000.0f);
    Picked clamped = pick(bright, QPoint(2, 2));
    QVERIFY(clamped.inspector->breakdown()->has(LightingFlag::Clamped));
    QCOMPARE(clamped.inspector->breakdown()->bytes, rgb(255, 255, 255));
    QVERIFY(clamped.inspector->formulaText().contains(QStringLiteral("→ 255 (clamped)")));

    // Vertex normals (0,0,-1), (0,0,1), (0,0,-1): at (2, 0), beta = 1/2 and gamma = 0, they
    // cancel. Ambient only.
    HandOptions cancel;
    cancel.fileNormals = true;
    Picked zero = pick(cancel, QPoint(2, 0));
    QVERIFY(zero.inspector->breakdown()->has(LightingFlag::ZeroNormal));
    RL_COMPARE_VEC(zero.inspector->breakdown()->colour, vec3(10.0f), 0.0);

    // The light on the point itself: P' of (2, 2) is view (-0.25, 0.25, 0.5).
    HandOptions onPoint;
    onPoint.light = dvec3(0.25, 0.25, 0.5);
    Picked at = pick(onPoint, QPoint(2, 2));
    QVERIFY(at.inspector->breakdown()->has(LightingFlag::LightAtPoint));
    RL_COMPARE_VEC(at.inspector->breakdown()->diffuse, vec3(0.0f), 0.0);
}

void TestScanlineInspector::gouraudAndFlat() {
    // Gouraud: (2, 2) is triangle 3's first vertex, alpha = 1: its colour is that vertex's,
    // lit as in phongTermsByHand, (143.33, 176.67, 39.17).
    HandOptions gouraud;
    gouraud.model = ShadingModel::Gouraud;
    Picked g = pick(gouraud, QPoint(2, 2));
    const auto& b = g.inspector->breakdown();
    QVERIFY(b && b->event.model == ShadingModel::Gouraud);
    QCOMPARE(b->weights, (std::array<float, 3>{1.0f, 0.0f, 0.0f}));
    RL_COMPARE_VEC(b->vertexColours[0], vec3(430.0f / 3.0f, 530.0f / 3.0f, 117.5f / 3.0f), 1e-3);
    const QStringList lines = b->formula;
    QCOMPARE(lines.value(0), QStringLiteral("C = α C1 + β C2 + γ C3"));
    QCOMPARE(lines.value(1), QStringLiteral("α = 1, β = 0, γ = 0"));
    QVERIFY2(lines.value(3).startsWith(QStringLiteral("R = 1 × 143.3 + 0 × ")) &&
                 lines.value(3).endsWith(QStringLiteral(" = 143.333 → 143")),
             qPrintable(lines.value(3)));
    QCOMPARE(b->bytes, rgb(143, 176, 39));
    // Flat: one evaluation at the barycentre of triangle 3, P = (-1/12, 1/12, 1/2), with its
    // normal (0, 0, -1): L = (-1/6, 1/6, -3/2) / 1.51841, N.L = 1.5 / 1.51841 = 0.98788.
    HandOptions flat;
    flat.model = ShadingModel::Flat;
    Picked f = pick(flat, QPoint(3, 3));
    QVERIFY(f.inspector->breakdown());
    RL_COMPARE_NEAR(f.inspector->breakdown()->event.sample.nDotL,
                    1.5 / std::sqrt(2.25 + 2.0 / 36.0), 1e-6);
    QVERIFY(f.inspector->formulaText().startsWith(
        QStringLiteral("Flat shading: evaluated once, at the triangle's barycentre")));
}

void TestScanlineInspector::blackExplained() {
    HandOptions dark;
    dark.light = dvec3(0.0, 0.0, 10.0);
    dark.ambient = 0.0f;
    Picked p = pick(dark, QPoint(1, 1));
    QCOMPARE(p.inspector->history().back().after, std::optional(rgb(0, 0, 0)));
    QCOMPARE(p.inspector->verdictText(),
             QStringLiteral("Written by triangle 1; 1 fragment rejected; black: N.L < 0 and no "
                            "ambient."));
}

void TestScanlineInspector::fallbackWithoutReplay() {
    // No replay: the frame traced again for the pixel. The same fragments, the colours of
    // the overwritten write not kept, the final shading the same numbers.
    Picked p = pick({}, QPoint(2, 2), false);
    QVERIFY(p.inspector->traced());
    const std::vector<PixelHistoryRow> rows = fragmentRows(*p.inspector);
    QCOMPARE(rows.size(), std::size_t(3));
    QCOMPARE(rows[0].depthText, QStringLiteral("1 < +inf"));
    QCOMPARE(rows[1].depthText, QStringLiteral("2 >= 1"));
    QCOMPARE(rows[2].depthText, QStringLiteral("0.5 < 1"));
    QCOMPARE(*rows[0].before, rgb(0, 0, 0));
    QVERIFY(!rows[0].after);
    QVERIFY(!rows[2].before);
    QCOMPARE(*rows[2].after, rgb(143, 176, 39));
    QVERIFY(rows[2].atCursor);
    QCOMPARE(p.inspector->verdictText(),
             QStringLiteral("Written by triangle 3, over 1 earlier write; 1 fragment rejected."));
    QVERIFY(p.inspector->breakdown());
    QCOMPARE(p.inspector->breakdown()->bytes, rgb(143, 176, 39));
    QVERIFY(p.inspector->formulaText().contains(
        QStringLiteral("= 10 + 100 + 33.3333 = 143.333 → 143")));
    // An earlier fragment's lighting is not recorded without a replay.
    p.inspector->selectRow(1);
    QVERIFY(!p.inspector->breakdown());
    // While the replay is being built (no error yet), the history waits for it.
    Inspection waiting;
    PixelInspector inspector(&waiting);
    inspector.show();
    const auto frame = render(handScene());
    waiting.setFrame(frame, QImage(8, 8, QImage::Format_RGBA8888));
    waiting.pickPixel(QPoint(2, 2));
    QVERIFY(inspector.history().empty());
    QVERIFY(!inspector.traced());
    waiting.setReplay(replayOf(frame));
    QCOMPARE(fragmentRows(inspector).size(), std::size_t(3));
}

void TestScanlineInspector::screenshots() {
    // The views on the default scene and on calice2, saved when RASTERLAB_SCREENSHOTS names
    // a folder (to look at them).
    const QString dir = qEnvironmentVariable("RASTERLAB_SCREENSHOTS");
    std::vector<std::pair<QString, std::shared_ptr<const Scene>>> scenes{
        {QStringLiteral("hand"), handScene()},
        {QStringLiteral("trefoil"),
         testing::defaultCourseScene(ShadingModel::Phong, RuleSet::Course, 800, 600)},
        {QStringLiteral("trefoil-gpu-gouraud"),
         testing::defaultCourseScene(ShadingModel::Gouraud, RuleSet::Gpu, 800, 600)}};
    const QString samples = testing::samplesDir();
    if (!samples.isEmpty()) {
        Diagnostics hw2Diagnostics;
        auto hw2 = rasterlab::loadCommandFile(samples + QStringLiteral("/hw2/hw2sun1g.txt"),
                                              hw2Diagnostics);
        QVERIFY(hw2);
        scenes.emplace_back(QStringLiteral("hw2sun1g"),
                            std::make_shared<const Scene>(hw2->images.at(0).scene));
        scenes.emplace_back(QStringLiteral("calice2"), testing::calice2Scene());
    }
    for (const auto& [name, scene] : scenes) {
        Inspection inspection;
        ScanlineView scan(&inspection);
        PixelInspector pixel(&inspection);
        scan.resize(520, 720);
        pixel.resize(600, 760);
        scan.show();
        pixel.show();
        show(inspection, render(scene));
        const FrameReplay& replay = *inspection.replay();
        // A fragment written in the middle of the frame, and its pixel.
        auto middle = static_cast<std::uint32_t>(replay.fragments().size() / 2);
        while (replay.fragments()[middle].verdict != FragmentVerdict::Written) ++middle;
        inspection.seek(replay.atFragment(middle + 1));
        const ReplayFragment& f = replay.fragments()[middle];
        inspection.pickPixel(QPoint(f.x, f.y));
        QVERIFY(scan.model() && scan.model()->row);
        QCOMPARE(scan.model()->currentPixel, std::optional<int>(f.x));
        // The triangle's box and a pixel around it, or a window no finer than 6 pixels a square.
        const QRect window = scan.drawnWindow();
        QVERIFY(window.contains(QPoint(f.x, f.y)));
        QVERIFY(
            window.width() <=
            std::max(9, scan.findChild<QWidget*>(QStringLiteral("scanlineCanvas"))->width() / 6));
        QVERIFY(pixel.breakdown());
        QCOMPARE(pixel.history()[static_cast<std::size_t>(pixel.selectedRow())].fragment, middle);
        if (!dir.isEmpty()) {
            QCoreApplication::processEvents();  // the layouts, for the new contents
            scan.grab().save(dir + QStringLiteral("/scanline-%1.png").arg(name));
            pixel.grab().save(dir + QStringLiteral("/pixel-%1.png").arg(name));
            inspection.setPresentation(true);
            QCoreApplication::processEvents();
            scan.grab().save(dir + QStringLiteral("/scanline-%1-presenting.png").arg(name));
            pixel.grab().save(dir + QStringLiteral("/pixel-%1-presenting.png").arg(name));
        }
    }
}

// In presentation mode (12-point numbers) the numbers keep a space between them, the row
// numbers stay off the legend, and the crossings' values are whole inside the canvas (not cut
// at the grid's edge) and meet nothing: on a triangle about 20 pixels wide and 540 tall
// (small cells) and on one 600 wide, on its first, middle and last scanline, at three sizes.
void TestScanlineInspector::labelsStayApartAndWhole_data() {
    QTest::addColumn<QList<rl::dvec3>>("corners");
    QTest::addColumn<int>("row");  // 0 first, 1 middle, 2 last covered row
    // The axis camera at 800x600: screen x = (1 - x/z) 400, y = (1 - y/z) 300.
    const QList<rl::dvec3> tall = {{0.0, 0.9, 1.0}, {0.03, -0.9, 1.0}, {-0.02, 0.5, 1.0}};
    const QList<rl::dvec3> wide = {{0.75, 0.6, 1.0}, {-0.75, 0.5, 1.0}, {0.0, -0.7, 1.0}};
    for (int row = 0; row < 3; ++row) {
        const char* where = row == 0 ? "first" : row == 1 ? "middle" : "last";
        QTest::addRow("tall, %s row", where) << tall << row;
        QTest::addRow("wide, %s row", where) << wide << row;
    }
}

void TestScanlineInspector::labelsStayApartAndWhole() {
    QFETCH(QList<rl::dvec3>, corners);
    QFETCH(int, row);
    rl::Scene scene = testing::makeScene(
        testing::axisCamera(), testing::makeMesh({corners[0], corners[1], corners[2]}, {{0, 1, 2}}),
        800, 600);
    Inspection inspection;
    inspection.setPresentation(true);
    ScanlineView view(&inspection);
    view.show();
    const auto frame = render(std::make_shared<const rl::Scene>(std::move(scene)));
    show(inspection, frame);
    // The covered rows, and the middle pixel of the one asked.
    const rl::Image<std::uint32_t>& ids = frame->depth->triangle;
    std::vector<int> rows;
    for (int y = 0; y < ids.height(); ++y)
        for (int x = 0; x < ids.width(); ++x)
            if (ids.at(x, y) != rl::kNoTriangle) {
                rows.push_back(y);
                break;
            }
    QVERIFY(rows.size() > 100);
    const int y = row == 0 ? rows.front() : row == 1 ? rows[rows.size() / 2] : rows.back();
    std::vector<int> xs;
    for (int x = 0; x < ids.width(); ++x)
        if (ids.at(x, y) != rl::kNoTriangle) xs.push_back(x);
    inspection.pickPixel(QPoint(xs[xs.size() / 2], y));
    auto* canvas = view.findChild<QWidget*>(QStringLiteral("scanlineCanvas"));
    auto* labels = dynamic_cast<const rasterlab::PaintedLabels*>(canvas);
    QVERIFY(canvas && labels);
    for (const QSize size : {QSize(360, 420), QSize(520, 640), QSize(700, 500)}) {
        view.resize(size);
        QVERIFY(view.model() && view.model()->row);
        QCOMPARE(view.model()->row->y, y);
        canvas->grab();  // paints it
        const QList<QRect> rects = labels->labelRects();
        // Row and column numbers, both crossings and the three legend entries.
        QVERIFY2(rects.size() >= 7, qPrintable(QString::number(rects.size())));
        const int space = canvas->fontMetrics().horizontalAdvance(u' ');
        const QString at = QStringLiteral("%1x%2").arg(size.width()).arg(size.height());
        for (qsizetype i = 0; i < rects.size(); ++i) {
            QVERIFY2(canvas->rect().contains(rects[i]),
                     qPrintable(QStringLiteral("%1: label %2 leaves the canvas").arg(at).arg(i)));
            for (qsizetype j = i + 1; j < rects.size(); ++j)
                QVERIFY2(
                    !rects[i].adjusted(-space / 2, 0, space / 2, 0).intersects(rects[j]),
                    qPrintable(QStringLiteral("%1: labels %2 and %3 meet").arg(at).arg(i).arg(j)));
        }
    }
}

QTEST_MAIN(TestScanlineInspector)
#include "tst_scanline_inspector.moc"
