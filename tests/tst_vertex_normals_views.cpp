// The vertex table and the normals view: rows and their texts worked out by hand on small
// scenes seen by the axis camera (view = (-x, y, z)), vertices made by clipping, the table's
// selection linked both ways with the Inspection, triangle normals, back faces and
// inconsistent winding counted by hand, the hairs projected, and the normal map equal to the
// renderer's own normal buffer (ShadingOptions::keepNormals) pixel for pixel, at every point
// of the stepping cursor it is asked at.
#include <QtTest>

#include <QCheckBox>
#include <QItemSelectionModel>
#include <QSignalSpy>
#include <QTableView>

#include <cmath>

#include "app/image_io.h"
#include "pipeline/render/output_image.h"
#include "pipeline/render/renderer.h"
#include "pipeline/render/replay.h"
#include "pipeline/scene/mesh_topology.h"
#include "tests/course_scenes.h"
#include "tests/test_support.h"
#include "views/frame_image_view.h"
#include "views/inspection.h"
#include "views/normals_view.h"
#include "views/vertex_table.h"

using rasterlab::Inspection;
using rasterlab::NormalsView;
using rasterlab::VertexRef;
using rasterlab::VertexTableModel;
using rasterlab::VertexTableView;
using namespace rl;

namespace {

std::shared_ptr<const FrameTrace> render(std::shared_ptr<const Scene> scene,
                                         bool keepNormals = false) {
    RenderOptions options;
    options.threads = 2;
    options.shading.keepNormals = keepNormals;
    return testing::renderTrace(std::move(scene), options);
}

// testing::handScene's four triangles. In view space triangle 0 is (-1,1,1) (0,1,1) (-1,0,1):
// (P2 - P1) x (P3 - P1) = (1,0,0) x (0,-1,0) = (0,0,-1), toward the camera; 1 and 2 likewise.
// Triangle 3, (0.25,1,1) (0.5,0.25,1) (0.75,0.25,1): (0.25,-0.75,0) x (0.5,-0.75,0) =
// (0,0,0.1875), away from the camera: a back face.
std::shared_ptr<const Scene> handScene(ShadingModel model = ShadingModel::Phong) {
    return std::make_shared<const Scene>(testing::handScene(model));
}

// The table's scene: the axis camera with d = 2, hx = 2, hy = 1, so pNdc = (x/z, 2 y/z), on
// 8x8 pixels: pScreen = ((x_ndc + 1) 4, (1 - y_ndc) 4). The near plane is at z = 0.5.
//   vertex 1, world (0.375, 0.125, 1): view (-0.375, 0.125, 1), pNdc (-0.375, 0.25),
//             screen (2.5, 3), truncated (2, 3);
//   vertex 2, world (-0.5, 0.25, 1): view (0.5, 0.25, 1), pNdc (0.5, 0.5), screen (6, 2);
//   vertex 3, world (0.5, -0.25, 2): view (-0.5, -0.25, 2), pNdc (-0.25, -0.25), screen (3, 5).
//   Triangle 1 = (1, 2, 3): (0.875, 0.125, 0) x (-0.125, -0.375, 1) = (0.125, -0.875, -0.3125),
//   of length 0.9375: n = (2/15, -14/15, -1/3).
//   Triangle 2 = (4, 5, 6) with vertex 4 behind the camera (view (0, -1, -1)) and 5, 6 at view
//   (-1, 0, 1) and (1, 0, 1): clipped at z = 0.5 a quarter of the way from 5 and from 6 toward
//   4: made vertices at view (-0.75, -0.25, 0.5) (world (0.75, -0.25, 0.5)), pNdc (-1.5, -1),
//   screen (-2, 8), and view (0.75, -0.25, 0.5), pNdc (1.5, -1), screen (10, 8).
std::shared_ptr<const Scene> tableScene() {
    auto mesh = testing::makeMesh(
        {{0.375, 0.125, 1}, {-0.5, 0.25, 1}, {0.5, -0.25, 2}, {0, -1, -1}, {1, 0, 1}, {-1, 0, 1}},
        {{0, 1, 2}, {3, 4, 5}});
    CourseCamera camera = testing::axisCamera();
    camera.d = 2.0;
    camera.hx = 2.0;
    camera.hy = 1.0;
    Scene scene = testing::makeScene(camera, mesh, 8, 8);
    scene.nearPlane.fixedW = 0.5;
    return std::make_shared<const Scene>(std::move(scene));
}

// An octahedron around (0, 0, 5) in view space, every face wound counter-clockwise seen from
// outside (the right-hand rule gives outward normals in view space; world = (-x, y, z)).
// View vertices: 1 (1,0,5), 2 (-1,0,5), 3 (0,1,5), 4 (0,-1,5), 5 (0,0,4) near, 6 (0,0,6) far.
// The four faces around the near apex have n ~ (+-1, +-1, -1): n . P1 = +-1 - 5 < 0, front;
// the four around the far apex n ~ (+-1, +-1, 1): n . P1 = +-1 + 5 > 0, back faces.
// flipOne: the face (1, 3, 6) wound the other way, (1, 6, 3): its normal turns inward (a
// front face now), and each of its three edges, 1->6, 6->3 and 3->1, is run the same way by a
// neighbour ((4, 1, 6), (3, 2, 6), (1, 5, 3)): 3 edges, 4 triangles inconsistent.
std::shared_ptr<const Mesh> octahedron(bool flipOne) {
    std::vector<std::array<std::uint32_t, 3>> faces{{0, 4, 2}, {2, 4, 1}, {1, 4, 3}, {3, 4, 0},
                                                    {0, 2, 5}, {2, 1, 5}, {1, 3, 5}, {3, 0, 5}};
    if (flipOne) faces[4] = {0, 5, 2};
    return testing::makeMesh({{-1, 0, 5}, {1, 0, 5}, {0, 1, 5}, {0, -1, 5}, {0, 0, 4}, {0, 0, 6}},
                             faces);
}

std::shared_ptr<const Scene> octahedronScene(bool flipOne) {
    CourseCamera camera = testing::axisCamera();
    camera.d = 4.0;  // pNdc = (4 x/z, 4 y/z): the octahedron fills most of the 64x64 image
    Scene scene = testing::makeScene(camera, octahedron(flipOne), 64, 64);
    scene.lights.push_back({dvec4(0.0, 0.0, -10.0, 1.0), vec3(200.0f), {}});
    return std::make_shared<const Scene>(std::move(scene));
}

// Gives the inspection a frame with its picture, as the main window does.
void setFrame(Inspection& inspection, const std::shared_ptr<const FrameTrace>& frame) {
    inspection.setFrame(frame, rasterlab::toQImage(colourImage(*frame->shading, *frame->depth,
                                                               frame->scene->conventions)));
}

// Pixels of `image` whose channels differ from the renderer's normal image by more than 1.
int normalMapMismatches(const QImage& image, const FrameTrace& frame) {
    const Rgba8Image expected = normalImage(frame.shading->normal, *frame.depth);
    if (image.width() != expected.width || image.height() != expected.height) return -1;
    int bad = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QRgb got = image.pixel(x, y);
            const std::uint8_t* e = expected.pixel(x, y);
            if (std::abs(qRed(got) - e[0]) > 1 || std::abs(qGreen(got) - e[1]) > 1 ||
                std::abs(qBlue(got) - e[2]) > 1)
                ++bad;
        }
    }
    return bad;
}

int colouredPixels(const QImage& image, QRgb colour, int tolerance) {
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QRgb c = image.pixel(x, y);
            if (std::abs(qRed(c) - qRed(colour)) <= tolerance &&
                std::abs(qGreen(c) - qGreen(colour)) <= tolerance &&
                std::abs(qBlue(c) - qBlue(colour)) <= tolerance)
                ++n;
        }
    return n;
}

QString cell(const VertexTableModel& model, int row, int column, int role = Qt::DisplayRole) {
    return model.data(model.index(row, column), role).toString();
}

// Saves a widget's picture where RASTERLAB_SCREENSHOTS points (to look at), if it is set.
void keep(QWidget& widget, const QString& name) {
    const QString dir = qEnvironmentVariable("RASTERLAB_SCREENSHOTS");
    QCoreApplication::processEvents();  // the layouts settle before the picture is taken
    if (!dir.isEmpty()) widget.grab().save(dir + QLatin1Char('/') + name + QStringLiteral(".png"));
}

}  // namespace

class TestVertexNormalsViews : public QObject {
    Q_OBJECT
private slots:
    void tableRowsAndTexts();
    void rowsAndVerticesBothWays();
    void tableSelectionGoesToTheInspection();
    void pickedPixelSelectsRows();
    void filterToTheSelectedTriangle();
    void vertexExplanation();
    void triangleNormalsAndBackFaces();
    void inconsistentWinding();
    void octahedronFaces();
    void hairsProjected();
    void selectedTriangleExplained();
    void normalMapOfTheHandScene();
    void normalMapFollowsTheCursor();
    void normalMapMatchesTheRenderer_data();
    void normalMapMatchesTheRenderer();
    void normalMapOfCalice2();
    void largeScenes();
};

void TestVertexNormalsViews::tableRowsAndTexts() {
    const auto frame = render(tableScene());
    VertexTableModel model;
    model.setFrame(frame);
    // 6 vertices of the mesh and 2 made by clipping.
    QCOMPARE(frame->projection->draws[0].generated.size(), std::size_t(2));
    QCOMPARE(model.rowCount(), 8);
    QCOMPARE(model.columnCount(), 7);

    QCOMPARE(cell(model, 0, VertexTableModel::Draw), QStringLiteral("1"));
    QCOMPARE(cell(model, 0, VertexTableModel::Vertex), QStringLiteral("1"));
    QCOMPARE(cell(model, 0, VertexTableModel::World), QStringLiteral("(0.375, 0.125, 1)"));
    QCOMPARE(cell(model, 0, VertexTableModel::View), QStringLiteral("(-0.375, 0.125, 1)"));
    QCOMPARE(cell(model, 0, VertexTableModel::Ndc), QStringLiteral("(-0.3750, 0.2500)"));
    QCOMPARE(cell(model, 0, VertexTableModel::Screen), QStringLiteral("(2, 3)"));
    QCOMPARE(cell(model, 0, VertexTableModel::Screen, Qt::ToolTipRole),
             QStringLiteral("Exact: (2.5, 3)"));
    QCOMPARE(cell(model, 0, VertexTableModel::Normal),
             QStringLiteral("(0.1333, -0.9333, -0.3333)"));
    QCOMPARE(cell(model, 1, VertexTableModel::Ndc), QStringLiteral("(0.5000, 0.5000)"));
    QCOMPARE(cell(model, 1, VertexTableModel::Screen), QStringLiteral("(6, 2)"));
    QCOMPARE(cell(model, 2, VertexTableModel::Screen), QStringLiteral("(3, 5)"));

    // Vertex 4 is behind the camera: not projected.
    QCOMPARE(cell(model, 3, VertexTableModel::View), QStringLiteral("(0, -1, -1)"));
    QCOMPARE(cell(model, 3, VertexTableModel::Ndc), QStringLiteral("behind"));
    QCOMPARE(cell(model, 3, VertexTableModel::Screen), QStringLiteral("behind"));

    // The two made by clipping, a quarter of the way from 5 and 6 toward 4 (which one comes
    // first is the clipper's order: edge 4-5 is met before 6-4 going round the triangle).
    QCOMPARE(cell(model, 6, VertexTableModel::Vertex),
             QStringLiteral("7 made by clipping (edge 5-4, t = 0.25)"));
    QCOMPARE(cell(model, 6, VertexTableModel::View), QStringLiteral("(-0.75, -0.25, 0.5)"));
    QCOMPARE(cell(model, 6, VertexTableModel::World), QStringLiteral("(0.75, -0.25, 0.5)"));
    QCOMPARE(cell(model, 6, VertexTableModel::Ndc), QStringLiteral("(-1.5000, -1.0000)"));
    QCOMPARE(cell(model, 6, VertexTableModel::Screen), QStringLiteral("(-2, 8)"));
    QCOMPARE(cell(model, 7, VertexTableModel::Vertex),
             QStringLiteral("8 made by clipping (edge 6-4, t = 0.25)"));
    QCOMPARE(cell(model, 7, VertexTableModel::View), QStringLiteral("(0.75, -0.25, 0.5)"));
    QCOMPARE(cell(model, 7, VertexTableModel::World), QStringLiteral("(-0.75, -0.25, 0.5)"));
    QCOMPARE(cell(model, 7, VertexTableModel::Screen), QStringLiteral("(10, 8)"));

    // Every column says its formula.
    for (int c = 0; c < model.columnCount(); ++c)
        QVERIFY(!model.headerData(c, Qt::Horizontal, Qt::ToolTipRole).toString().isEmpty());
    QVERIFY(model.headerData(VertexTableModel::Ndc, Qt::Horizontal, Qt::ToolTipRole)
                .toString()
                .contains(QStringLiteral("(d/hx) x/z")));

    // An unlit scene has no normals stage: "-".
    auto unlit = std::make_shared<Scene>(*tableScene());
    unlit->ambientIntensity = vec3(0.0f);
    model.setFrame(render(unlit));
    QVERIFY(model.frame()->normals->skipped);
    QCOMPARE(cell(model, 0, VertexTableModel::Normal), QStringLiteral("-"));
    QVERIFY(!model.normalOf({0, 0}));
}

void TestVertexNormalsViews::rowsAndVerticesBothWays() {
    // Two draws of the hand mesh: rows 0..11 the first draw's, 12..23 the second's.
    auto scene = std::make_shared<Scene>(*handScene());
    scene->draws.push_back(scene->draws[0]);
    VertexTableModel model;
    model.setFrame(render(scene));
    QCOMPARE(model.rowCount(), 24);
    QCOMPARE(model.rowOf({1, 3}), 15);
    QCOMPARE(model.vertexAt(15), (VertexRef{1, 3}));
    QCOMPARE(model.vertexAt(11), (VertexRef{0, 11}));
    QCOMPARE(model.vertexAt(12), (VertexRef{1, 0}));
    QCOMPARE(model.rowOf({0, 12}), -1);  // the first draw has 12
    QCOMPARE(model.rowOf({2, 0}), -1);   // no third draw
    for (int row = 0; row < model.rowCount(); ++row)
        QCOMPARE(model.rowOf(model.vertexAt(row)), row);
    QCOMPARE(cell(model, 15, VertexTableModel::Draw), QStringLiteral("2"));
    QCOMPARE(cell(model, 15, VertexTableModel::Vertex), QStringLiteral("4"));
}

void TestVertexNormalsViews::tableSelectionGoesToTheInspection() {
    Inspection inspection;
    VertexTableView view(&inspection);
    QCOMPARE(view.objectName(), QStringLiteral("vertexTableView"));
    view.resize(900, 500);
    view.show();
    const auto frame = render(tableScene());
    setFrame(inspection, frame);
    QCOMPARE(view.model()->rowCount(), 8);

    QSignalSpy spy(&inspection, &Inspection::selectionChanged);
    QTableView* table = view.table();
    table->selectionModel()->select(
        table->model()->index(1, 0),
        QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    QCOMPARE(inspection.selectedVertices(), (std::vector<VertexRef>{{0, 1}}));
    QCOMPARE(spy.count(), 1);  // once: the table does not echo the Inspection's answer
    QCOMPARE(view.selectedRows(), (std::vector<int>{1}));

    table->selectionModel()->select(table->model()->index(6, 0),
                                    QItemSelectionModel::Select | QItemSelectionModel::Rows);
    QCOMPARE(inspection.selectedVertices(), (std::vector<VertexRef>{{0, 1}, {0, 6}}));
    QCOMPARE(spy.count(), 2);
}

void TestVertexNormalsViews::pickedPixelSelectsRows() {
    Inspection inspection;
    VertexTableView view(&inspection);
    view.resize(900, 500);
    view.show();
    const auto frame = render(tableScene());
    setFrame(inspection, frame);
    // Row 3 of triangle 1 runs from its edge (2,3)-(6,2) at x = 2 to its edge (6,2)-(3,5) at
    // x = 5; the clipped triangle is below row 4.
    QCOMPARE(inspection.triangleAt(QPoint(4, 3)), 0u);
    inspection.pickPixel(QPoint(4, 3));
    QCOMPARE(view.selectedRows(), (std::vector<int>{0, 1, 2}));
    QCOMPARE(view.table()->currentIndex().row(), 0);
    QCOMPARE(view.explainedVertex(), std::optional<VertexRef>(VertexRef{0, 0}));
    // An empty pixel selects nothing.
    QCOMPARE(inspection.triangleAt(QPoint(7, 0)), kNoTriangle);
    inspection.pickPixel(QPoint(7, 0));
    QVERIFY(view.selectedRows().empty());
    // A triangle of the clipped quad: three of its rows, made ones included.
    const std::uint32_t t = inspection.triangleAt(QPoint(4, 6));
    QVERIFY(t != kNoTriangle && t > 0);
    inspection.pickPixel(QPoint(4, 6));
    std::vector<int> expected;
    for (std::uint32_t v : frame->projection->triangles[t].v) expected.push_back(int(v));
    std::sort(expected.begin(), expected.end());
    QCOMPARE(view.selectedRows(), expected);
    QVERIFY(expected.back() >= 6);  // a made vertex
    keep(view, QStringLiteral("vertex_table_small"));
    // Presentation mode: larger text in the table.
    const double before = view.table()->font().pointSizeF();
    inspection.setPresentation(true);
    QVERIFY(view.table()->font().pointSizeF() > before * 1.3);
    inspection.setPresentation(false);
    QCOMPARE(view.table()->font().pointSizeF(), before);
}

void TestVertexNormalsViews::filterToTheSelectedTriangle() {
    Inspection inspection;
    VertexTableView view(&inspection);
    view.show();
    const auto frame = render(tableScene());
    setFrame(inspection, frame);
    QCOMPARE(view.visibleRowCount(), 8);
    view.setOnlySelectedTriangle(true);
    QVERIFY(view.findChild<QCheckBox*>(QStringLiteral("vertexTableOnlyTriangle"))->isChecked());
    QCOMPARE(view.visibleRowCount(), 0);  // no triangle selected yet
    inspection.pickPixel(QPoint(4, 3));
    QCOMPARE(view.visibleRowCount(), 3);
    QCOMPARE(view.selectedRows(), (std::vector<int>{0, 1, 2}));
    // Selecting one of the three rows keeps the three shown.
    QTableView* table = view.table();
    table->selectionModel()->select(
        table->model()->index(2, 0),
        QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    QCOMPARE(inspection.selectedVertices(), (std::vector<VertexRef>{{0, 2}}));
    QCOMPARE(view.visibleRowCount(), 3);
    view.setOnlySelectedTriangle(false);
    QCOMPARE(view.visibleRowCount(), 8);
    QCOMPARE(view.selectedRows(), (std::vector<int>{2}));
}

void TestVertexNormalsViews::vertexExplanation() {
    Inspection inspection;
    VertexTableView view(&inspection);
    view.show();
    const auto frame = render(tableScene());
    setFrame(inspection, frame);
    inspection.selectVertices({{0, 0}});
    const QString text = view.explanationText();
    // [U; V; N](P - C) with the axis camera: U = (-1, 0, 0), V = (0, 1, 0), N = (0, 0, 1).
    QVERIFY2(text.contains(QStringLiteral("x = U · (P − C) = (-1, 0, 0) · (0.375, 0.125, 1) = "
                                          "-0.375")),
             qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("pNdc = ((d/hx) x/z, (d/hy) y/z) = ((2/2) · (-0.375)/1, "
                                          "(2/1) · 0.125/1) = (-0.375, 0.25)")),
             qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("((-0.375 + 1) · 4, (1 − 0.25) · 4) = (2.5, 3), "
                                          "truncated, as C's (int) does: (2, 3)")),
             qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("the 1 triangles around it: nView = "
                                          "(0.1333, -0.9333, -0.3333)")),
             qPrintable(text));
    // A vertex behind the camera, and one made by clipping.
    inspection.selectVertices({{0, 3}});
    QVERIFY2(view.explanationText().contains(QStringLiteral("z = -1 is not beyond the near plane "
                                                            "(w = 0.5)")),
             qPrintable(view.explanationText()));
    inspection.selectVertices({{0, 6}});
    QVERIFY2(view.explanationText().contains(
                 QStringLiteral("= (-1, 0, 1) + 0.25 ((0, -1, -1) − (-1, 0, 1)) = (-0.75, "
                                "-0.25, 0.5)")),
             qPrintable(view.explanationText()));
}

void TestVertexNormalsViews::triangleNormalsAndBackFaces() {
    const auto frame = render(handScene());
    const DrawNormals& normals = frame->normals->draws[0];
    RL_COMPARE_VEC(normals.triangle[0], vec3(0.0f, 0.0f, -1.0f), 1e-7);
    RL_COMPARE_VEC(normals.triangle[3], vec3(0.0f, 0.0f, 1.0f), 1e-7);
    const auto back =
        rasterlab::backFaces(frame->projection->draws[0].pView, *frame->scene->draws[0].mesh);
    QCOMPARE(back, (std::vector<std::uint8_t>{0, 0, 0, 1}));

    Inspection inspection;
    NormalsView view(&inspection);
    QCOMPARE(view.objectName(), QStringLiteral("normalsView"));
    view.resize(700, 600);
    view.show();
    setFrame(inspection, frame);
    QCOMPARE(view.picture().meshTriangles, std::size_t(4));
    QCOMPARE(view.picture().backFaces, std::size_t(1));
    QCOMPARE(view.picture().inconsistentTriangles, std::size_t(0));
    QCOMPARE(view.picture().triangles.size(), std::size_t(4));
    QVERIFY(view.picture().triangles[3].face == rasterlab::NormalsPicture::Face::Back);
    QVERIFY(view.picture().triangles[0].face == rasterlab::NormalsPicture::Face::Front);
    QCOMPARE(view.picture().triangles[0].p[1], QPointF(4, 0));
    QVERIFY2(view.legendText().contains(QStringLiteral("back faces (n · pView &gt; 0) 1")),
             qPrintable(view.legendText()));
}

void TestVertexNormalsViews::inconsistentWinding() {
    // Two triangles sharing the edge 2-3 (1-based), both running it from 2 to 3.
    const auto bad =
        testing::makeMesh({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}}, {{0, 1, 2}, {1, 2, 3}});
    const auto report = rasterlab::inconsistentWinding(*bad);
    QCOMPARE(report.edges, std::size_t(1));
    QCOMPARE(report.triangles, std::size_t(2));
    QCOMPARE(report.inconsistent, (std::vector<std::uint8_t>{1, 1}));
    // The second wound the other way, (3, 2, 4): the edge is run once each way.
    const auto good =
        testing::makeMesh({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}}, {{0, 1, 2}, {2, 1, 3}});
    QCOMPARE(rasterlab::inconsistentWinding(*good).edges, std::size_t(0));
    QCOMPARE(rasterlab::inconsistentWinding(*good).triangles, std::size_t(0));
}

void TestVertexNormalsViews::octahedronFaces() {
    const auto good = rasterlab::inconsistentWinding(*octahedron(false));
    QCOMPARE(good.edges, std::size_t(0));
    const auto flipped = rasterlab::inconsistentWinding(*octahedron(true));
    QCOMPARE(flipped.edges, std::size_t(3));
    QCOMPARE(flipped.triangles, std::size_t(4));
    // (1, 6, 3) itself and (4, 1, 6), (3, 2, 6), (1, 5, 3): faces 5, 8, 6 and 1.
    QCOMPARE(flipped.inconsistent, (std::vector<std::uint8_t>{1, 0, 0, 0, 1, 1, 0, 1}));

    Inspection inspection;
    NormalsView view(&inspection);
    view.resize(700, 700);
    view.show();
    auto frame = render(octahedronScene(false));
    QCOMPARE(rasterlab::backFaces(frame->projection->draws[0].pView, *octahedron(false)),
             (std::vector<std::uint8_t>{0, 0, 0, 0, 1, 1, 1, 1}));
    setFrame(inspection, frame);
    QCOMPARE(view.picture().backFaces, std::size_t(4));
    QCOMPARE(view.picture().inconsistentEdges, std::size_t(0));
    // Wound outward in view space: in world space (x mirrored) the other way round, and the
    // axis camera's [U; V; N] mirrors it back (det -1). Only front faces are seen.
    QCOMPARE(closedSurfaceWinding(*octahedron(false)), -1);
    QCOMPARE(view.picture().viewWinding, (std::vector<int>{1}));
    QVERIFY(view.picture().coveredPixels > 100);
    QCOMPARE(view.picture().backFacePixels, std::size_t(0));
    QVERIFY(!view.legendText().contains(QStringLiteral("point inward")));
    QCOMPARE(view.picture().culledBack, std::size_t(0));

    // With hidden back faces left out (the surface closed, the camera outside), the four far
    // faces are not drawn, and the legend counts them where they belong.
    {
        auto mesh = std::make_shared<Mesh>(*octahedron(false));
        mesh->closedWinding = closedSurfaceWinding(*mesh);
        auto culled = std::make_shared<Scene>(*octahedronScene(false));
        culled->draws[0].mesh = mesh;
        culled->cullHiddenBackFaces = true;
        const auto culledFrame = render(culled);
        QCOMPARE(culledFrame->projection->backFaces, std::size_t(4));
        setFrame(inspection, culledFrame);
        QCOMPARE(view.picture().triangles.size(), std::size_t(4));
        QCOMPARE(view.picture().culledBack, std::size_t(4));
        QCOMPARE(view.picture().culledFront, std::size_t(0));
        QVERIFY2(view.legendText().contains(QStringLiteral("back faces (n · pView &gt; 0) 4 (4 "
                                                           "hidden, left out by culling)")),
                 qPrintable(view.legendText()));
        setFrame(inspection, frame);
    }
    view.setTriangleHairs(false);
    view.setVertexHairs(false);
    QImage picture = view.canvas()->grab().toImage();
    QVERIFY(colouredPixels(picture, qRgb(235, 60, 235), 60) == 0);  // no magenta

    frame = render(octahedronScene(true));
    setFrame(inspection, frame);
    QCOMPARE(view.picture().backFaces, std::size_t(3));  // the flipped far face looks front
    QCOMPARE(view.picture().inconsistentEdges, std::size_t(3));
    QCOMPARE(view.picture().inconsistentTriangles, std::size_t(4));
    QCOMPARE(view.picture().viewWinding, (std::vector<int>{0}));  // not a consistent surface
    QVERIFY(view.picture().triangles[4].face == rasterlab::NormalsPicture::Face::Inconsistent);
    QVERIFY(view.picture().triangles[6].face == rasterlab::NormalsPicture::Face::Back);
    QVERIFY2(view.legendText().contains(QStringLiteral("inconsistent winding: 4 triangles, 3 "
                                                       "edges")),
             qPrintable(view.legendText()));
    picture = view.canvas()->grab().toImage();
    QVERIFY(colouredPixels(picture, qRgb(235, 60, 235), 60) > 100);  // the magenta faces
    view.setTriangleHairs(true);
    view.setVertexHairs(true);
    keep(view, QStringLiteral("normals_octahedron"));
}

void TestVertexNormalsViews::hairsProjected() {
    Inspection inspection;
    NormalsView view(&inspection);
    view.show();
    const auto frame = render(handScene());
    setFrame(inspection, frame);
    // By default only the triangles seen carry hairs: triangle 2 of the file is hidden behind
    // triangle 1 everywhere.
    QVERIFY(view.onlyVisibleHairs());
    QCOMPARE(view.picture().hairTriangles, std::size_t(3));
    QCOMPARE(view.picture().triangleHairs.size(), std::size_t(3));
    QCOMPARE(view.picture().vertexHairs.size(), std::size_t(9));
    view.setOnlyVisibleHairs(false);
    const auto& picture = view.picture();
    // Four triangles: every hair drawn. Triangle 1's centroid (-2/3, 2/3, 1) in view space is
    // at pNdc (-2/3, 2/3): screen (4/3, 4/3). Its normal (0, 0, -1) comes toward the camera:
    // the tip, at z = 1 - L, lands farther from the image's centre (4, 4):
    // 4 - 4 (2/3) / (1 - L) on both axes.
    QCOMPARE(picture.triangleHairStep, 1);
    QCOMPARE(picture.triangleHairs.size(), std::size_t(4));
    QCOMPARE(picture.vertexHairs.size(), std::size_t(12));
    const double length = picture.hairLength;
    // L = 0.3 / sqrt(4 triangles) of the diagonal of the view-space box, x from -2 to 0.75,
    // y from -0.25 to 2, z from 0.5 to 2: 0.15 sqrt(2.75^2 + 2.25^2 + 1.5^2) = 0.5914; but at
    // most half the nearest depth, 0.5 / 2, or triangle 3's hair would reach the camera.
    RL_COMPARE_NEAR(length, 0.25, 1e-12);
    const QLineF hair = picture.triangleHairs[0];
    RL_COMPARE_NEAR(hair.p1().x(), 4.0 / 3.0, 1e-9);
    RL_COMPARE_NEAR(hair.p1().y(), 4.0 / 3.0, 1e-9);
    RL_COMPARE_NEAR(hair.p2().x(), 4.0 - 4.0 * (2.0 / 3.0) / (1.0 - length), 1e-9);
    RL_COMPARE_NEAR(hair.p2().y(), 4.0 - 4.0 * (2.0 / 3.0) / (1.0 - length), 1e-9);
    // Vertex 1, view (-1, 1, 1), screen (0, 0): its hair runs off to (-4 L/(1-L), same).
    const QLineF vertexHair = picture.vertexHairs[0];
    QCOMPARE(vertexHair.p1(), QPointF(0, 0));
    RL_COMPARE_NEAR(vertexHair.p2().x(), 4.0 - 4.0 / (1.0 - length), 1e-9);

    // Without lights nothing computes normals: no hairs, and the legend says why.
    auto unlit = std::make_shared<Scene>(*handScene());
    unlit->lights.clear();
    unlit->ambientIntensity = vec3(0.0f);
    const auto dark = render(unlit);
    setFrame(inspection, dark);
    QVERIFY(view.picture().normalsSkipped);
    QVERIFY(view.picture().triangleHairs.empty());
    QCOMPARE(view.picture().backFaces, std::size_t(1));  // found from pView all the same
    QVERIFY(view.legendText().contains(QStringLiteral("nothing reads the normals")));
}

void TestVertexNormalsViews::selectedTriangleExplained() {
    Inspection inspection;
    NormalsView view(&inspection);
    view.show();
    const auto frame = render(handScene());
    setFrame(inspection, frame);
    inspection.pickPixel(QPoint(0, 0));  // triangle 1 of the file (projected triangle 0)
    QCOMPARE(inspection.selectedTriangle(), std::optional<std::uint32_t>(0u));
    QVERIFY(view.picture().selected.has_value());
    QCOMPARE((*view.picture().selected)[2], QPointF(0, 4));
    QCOMPARE(view.picture().selectedTriangleHairs.size(), std::size_t(1));
    QCOMPARE(view.picture().selectedVertexHairs.size(), std::size_t(3));
    const QString text = view.explanationText();
    QVERIFY2(text.contains(QStringLiteral("P1 = (-1, 1, 1), P2 = (0, 1, 1), P3 = (-1, 0, 1)")),
             qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("(P2 − P1) × (P3 − P1) = (1, 0, 0) × (0, -1, 0) = "
                                          "(0, 0, -1), length 1")),
             qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("n = (0.0000, 0.0000, -1.0000); n · P1 = -1: a front "
                                          "face")),
             qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("N1 = (0.0000, 0.0000, -1.0000)")), qPrintable(text));
    // The pixel: the vertex normals are all (0, 0, -1): colour ((0+1)/2, (0+1)/2, (-1+1)/2).
    QVERIFY2(text.contains(QStringLiteral("Colour (N + 1) / 2 = (128, 128, 0)")), qPrintable(text));

    // Triangle 4 of the file faces away; at its pixel (5, 0) shading turns its normal.
    inspection.pickPixel(QPoint(5, 0));
    QCOMPARE(inspection.selectedTriangle(), std::optional<std::uint32_t>(3u));
    const QString back = view.explanationText();
    QVERIFY2(back.contains(QStringLiteral("n · P1 = 1: a back face")), qPrintable(back));
    QVERIFY2(back.contains(QStringLiteral("turned toward the viewer: (0.0000, 0.0000, -1.0000)")),
             qPrintable(back));

    // A pixel picked while the view is hidden, on the same frame: shown when it is shown.
    view.hide();
    inspection.pickPixel(QPoint(0, 0));
    view.show();
    QVERIFY(view.picture().selected.has_value());
    QCOMPARE((*view.picture().selected)[2], QPointF(0, 4));
    QVERIFY2(view.explanationText().contains(QStringLiteral("n · P1 = -1: a front face")),
             qPrintable(view.explanationText()));
}

void TestVertexNormalsViews::normalMapOfTheHandScene() {
    const auto frame = render(handScene(), true);
    Inspection inspection;
    NormalsView view(&inspection);
    view.show();
    view.showNormalMap(true);
    setFrame(inspection, frame);
    const QImage& map = view.normalMap();
    QCOMPARE(map.size(), QSize(8, 8));
    // Every normal is (0, 0, -1) toward the camera (triangle 4's turned): (128, 128, 0).
    QCOMPARE(map.pixel(0, 0), qRgb(128, 128, 0));
    QCOMPARE(map.pixel(5, 0), qRgb(128, 128, 0));
    QCOMPARE(map.pixel(7, 7), qRgb(0, 0, 0));  // no triangle
    QCOMPARE(normalMapMismatches(map, *frame), 0);
    QCOMPARE(view.normalMapView()->image().pixel(0, 0), qRgb(128, 128, 0));
}

void TestVertexNormalsViews::normalMapFollowsTheCursor() {
    const auto frame = render(handScene(), true);
    auto replay = FrameReplay::build(frame);
    QVERIFY(replay.ok());
    Inspection inspection;
    NormalsView view(&inspection);
    view.show();
    view.showNormalMap(true);
    setFrame(inspection, frame);
    inspection.setReplay(replay.value());
    QCOMPARE(normalMapMismatches(view.normalMap(), *frame), 0);  // at the end
    inspection.seek(replay.value()->start());
    QCOMPARE(colouredPixels(view.normalMapView()->image(), qRgb(0, 0, 0), 0), 64);  // nothing yet
    // After triangle 1 of the file (15 fragments): its pixels, not triangle 4's.
    inspection.seek(replay.value()->atFragment(15));
    const QImage& map = view.normalMapView()->image();
    QCOMPARE(map.pixel(0, 0), qRgb(128, 128, 0));
    QCOMPARE(map.pixel(0, 4), qRgb(128, 128, 0));
    QCOMPARE(map.pixel(5, 0), qRgb(0, 0, 0));
    QCOMPARE(colouredPixels(map, qRgb(128, 128, 0), 0), 15);
    inspection.seek(replay.value()->end());
    QCOMPARE(normalMapMismatches(view.normalMapView()->image(), *frame), 0);
}

void TestVertexNormalsViews::normalMapMatchesTheRenderer_data() {
    QTest::addColumn<int>("model");
    QTest::addColumn<int>("rules");
    QTest::newRow("phong course") << int(ShadingModel::Phong) << int(RuleSet::Course);
    QTest::newRow("gouraud course") << int(ShadingModel::Gouraud) << int(RuleSet::Course);
    QTest::newRow("flat course") << int(ShadingModel::Flat) << int(RuleSet::Course);
    QTest::newRow("phong gpu") << int(ShadingModel::Phong) << int(RuleSet::Gpu);
}

void TestVertexNormalsViews::normalMapMatchesTheRenderer() {
    QFETCH(int, model);
    QFETCH(int, rules);
    const auto frame =
        render(testing::defaultCourseScene(ShadingModel(model), RuleSet(rules), 400, 300), true);
    rasterlab::PixelNormals normals(frame);
    const QImage map = normals.image(*frame->depth);
    QCOMPARE(normalMapMismatches(map, *frame), 0);
    QVERIFY(frame->depth->coveredPixels() > 10000);
    // Flat normals on a Phong draw: the triangle's, per pixel.
    if (ShadingModel(model) == ShadingModel::Phong && RuleSet(rules) == RuleSet::Course) {
        auto scene = std::make_shared<Scene>(*frame->scene);
        scene->draws[0].flatNormals = true;
        const auto flat = render(scene, true);
        QCOMPARE(normalMapMismatches(rasterlab::PixelNormals(flat).image(*flat->depth), *flat), 0);
    }
}

void TestVertexNormalsViews::normalMapOfCalice2() {
    const auto scene = testing::calice2Scene();
    if (!scene) QSKIP("course samples not found: set RASTERLAB_SAMPLES to the samples folder");
    const auto frame = render(scene, true);
    Inspection inspection;
    NormalsView view(&inspection);
    view.showNormalMap(true);
    view.show();
    setFrame(inspection, frame);
    QCOMPARE(normalMapMismatches(view.normalMap(), *frame), 0);
}

void TestVertexNormalsViews::largeScenes() {
    // The default trefoil (7,776 triangles) and calice2 in both views: hairs subsampled, the
    // table's rows one per vertex.
    const auto trefoil =
        render(testing::defaultCourseScene(ShadingModel::Phong, RuleSet::Course, 800, 600), true);
    Inspection inspection;
    NormalsView normals(&inspection);
    normals.resize(900, 800);
    normals.show();
    VertexTableView table(&inspection);
    table.resize(1000, 600);
    table.show();
    setFrame(inspection, trefoil);
    QCOMPARE(table.model()->rowCount(), int(trefoil->scene->draws[0].mesh->positions.size()));
    QCOMPARE(normals.picture().meshTriangles, std::size_t(7776));
    // The default scene's file is wound so that its normals point outward in the course's
    // view space: what is seen is front faces (but for a few at the silhouettes).
    QCOMPARE(normals.picture().viewWinding, (std::vector<int>{1}));
    QVERIFY(normals.picture().backFacePixels * 100 < normals.picture().coveredPixels);
    QVERIFY(normals.picture().triangleHairStep > 1);
    QVERIFY(normals.picture().triangleHairs.size() <= 600);
    QVERIFY(normals.legendText().contains(QStringLiteral("Large mesh")));
    inspection.pickPixel(QPoint(400, 350));
    QVERIFY(inspection.selectedTriangle().has_value());
    QCOMPARE(table.selectedRows().size(), std::size_t(3));
    keep(normals, QStringLiteral("normals_trefoil"));
    keep(table, QStringLiteral("vertex_table_trefoil"));
    normals.showNormalMap(true);
    QCOMPARE(normalMapMismatches(normals.normalMap(), *trefoil), 0);
    keep(normals, QStringLiteral("normal_map_trefoil"));

    const auto scene = testing::calice2Scene();
    if (!scene) QSKIP("course samples not found: set RASTERLAB_SAMPLES to the samples folder");
    const auto calice = render(scene, true);
    normals.showNormalMap(false);
    setFrame(inspection, calice);
    QCOMPARE(table.model()->rowCount(), 1062);
    QCOMPARE(normals.picture().meshTriangles, std::size_t(2120));
    // calice2 is wound the other way: nearly every pixel seen is a "back face", and the legend
    // says why.
    QCOMPARE(normals.picture().viewWinding, (std::vector<int>{-1}));
    QVERIFY(normals.picture().backFacePixels * 10 > normals.picture().coveredPixels * 9);
    QVERIFY2(normals.legendText().contains(QStringLiteral("normals point inward in view space")),
             qPrintable(normals.legendText()));
    QVERIFY(inspection.triangleAt(QPoint(430, 420)) != kNoTriangle);  // in the cup
    inspection.pickPixel(QPoint(430, 420));
    QCOMPARE(table.selectedRows().size(), std::size_t(3));
    keep(normals, QStringLiteral("normals_calice2"));
    keep(table, QStringLiteral("vertex_table_calice2"));
    normals.showNormalMap(true);
    keep(normals, QStringLiteral("normal_map_calice2"));
}

QTEST_MAIN(TestVertexNormalsViews)
#include "tst_vertex_normals_views.moc"
