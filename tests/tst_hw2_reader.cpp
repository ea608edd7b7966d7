// The command-file reader (seed 001) without rendering: what each command does to the
// Scene it builds (image, vertices and their attributes, draws with their matrices, clip
// planes, cull, textures, lights), how draws are shared, what is skipped with a note, and
// the exact file:line:col message of each malformed command.
#include <QtTest>

#include <QDirIterator>

#include <functional>

#include "pipeline/io/hw2_reader.h"
#include "tests/test_support.h"

using namespace rl;

namespace {

using Rows = QList<double>;

const char* const kFile = "cmd.txt";

// A 2x1 texture, as the fake loader returns it.
std::shared_ptr<const Texture> smallTexture() {
    auto texture = std::make_shared<Texture>();
    texture->width = 2;
    texture->height = 1;
    texture->texels = {vec4(1, 0, 0, 1), vec4(0, 0, 1, 0.5f)};
    texture->name = "small.png";
    return texture;
}

// Records every texture the reader asks for and answers with one texture.
struct FakeLoader {
    std::vector<std::pair<std::string, SourceLocation>> calls;
    std::shared_ptr<const Texture> texture = smallTexture();
    TextureLoader loader() {
        return [this](const std::string& name,
                      const SourceLocation& where) -> Result<std::shared_ptr<const Texture>> {
            calls.emplace_back(name, where);
            return texture;
        };
    }
};

Result<Hw2File> read(const QByteArray& text, Diagnostics& diagnostics,
                     const TextureLoader& loader) {
    return readHw2(std::string_view(text.constData(), std::size_t(text.size())), kFile, loader,
                   diagnostics);
}

Result<Hw2File> read(const QByteArray& text, Diagnostics& diagnostics) {
    FakeLoader fake;
    return read(text, diagnostics, fake.loader());
}

QString errorOf(const Result<Hw2File>& file) {
    return file ? QStringLiteral("(no error)") : QString::fromStdString(file.error().toString());
}

QStringList linesOf(const Diagnostics& diagnostics) {
    QStringList lines;
    for (const auto& d : diagnostics.items()) lines << QString::fromStdString(d.toString());
    return lines;
}

// "" when `m` equals the 16 values of `rows` (row by row) within `tolerance`.
QString differs(const dmat4& m, const Rows& rows, double tolerance) {
    if (rows.size() != 16) return QStringLiteral("expected 16 values, found %1").arg(rows.size());
    QString actual;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) actual += QStringLiteral(" %1").arg(m[c][r], 0, 'g', 10);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            if (!(std::abs(m[c][r] - rows[r * 4 + c]) <= tolerance))
                return QStringLiteral("row %1 column %2 is %3, expected %4; rows:%5")
                    .arg(r + 1)
                    .arg(c + 1)
                    .arg(m[c][r], 0, 'g', 15)
                    .arg(rows[r * 4 + c], 0, 'g', 15)
                    .arg(actual);
    return {};
}

#define RL_COMPARE_MATRIX(actual, rows, tolerance)                       \
    do {                                                                 \
        const QString problem_ = differs((actual), (rows), (tolerance)); \
        QVERIFY2(problem_.isEmpty(), qPrintable(problem_));              \
    } while (false)

const Rows kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

// A unit triangle after `commands`, drawn with negative indices so that the commands may
// define vertices of their own.
QByteArray withTriangle(const QByteArray& commands, const QByteArray& draw = "trif") {
    return "png 4 4 a.png\n" + commands + "\nxyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\n" + draw +
           " -3 -2 -1\n";
}

}  // namespace

class TestHw2Reader : public QObject {
    Q_OBJECT

private slots:
    void png();
    void pngStartsNewImage();
    void vertexAttributes();
    void fills_data();
    void fills();
    void indices_data();
    void indices();
    void negativeIndexCountsFromNow();
    void modelView_data();
    void modelView();
    void projection_data();
    void projection();
    void clipPlanes();
    void cull();
    void texture();
    void textureLoaderError();
    void decalsActOnWholeFile_data();
    void decalsActOnWholeFile();
    void flatNormals_data();
    void flatNormals();
    void sunlight_data();
    void sunlight();
    void bulb_data();
    void bulb();
    void lightsSeenByDraws();
    void shininess_data();
    void shininess();
    void bezierPatches_data();
    void bezierPatches();
    void drawSharing_data();
    void drawSharing();
    void unknownKeywordsSkipped();
    void blankLinesSkipped();
    void extraValuesWarned_data();
    void extraValuesWarned();
    void errors_data();
    void errors();
    void looksLikeHw2_data();
    void looksLikeHw2();
    void looksLikeHw2OnSamples();
};

void TestHw2Reader::png() {
    Diagnostics diagnostics;
    auto file = read("\n  png 120 60 out.png\n", diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    QCOMPARE(file->images.size(), std::size_t(1));
    const Hw2Image& image = file->images[0];
    QCOMPARE(image.fileName, std::string("out.png"));
    QCOMPARE(QString::fromStdString(image.where.toString()), QStringLiteral("cmd.txt:2:3"));
    const Scene& scene = image.scene;
    QCOMPARE(scene.name, std::string("out.png"));
    QCOMPARE(scene.width, 120);
    QCOMPARE(scene.height, 60);
    QVERIFY(scene.draws.empty());
    QVERIFY(scene.lights.empty());
    QVERIFY(!scene.camera);
    // Conventions of seed 001: (-1, -1) top left, NDC z depth cleared to 1, z <= wins,
    // depths outside [0, 1] dropped, colours 0..1 truncated to bytes, transparent black.
    const Conventions& c = scene.conventions;
    QCOMPARE(c.ndcYUp, false);
    QCOMPARE(c.viewport, ViewportFormula::ScaleThenShift);
    QCOMPARE(c.depth, DepthSource::NdcZ);
    QCOMPARE(c.depthClear, 1.0f);
    QCOMPARE(c.depthWinsOnTie, true);
    QCOMPARE(c.depthRangeClip, true);
    QCOMPARE(c.flipNormalsTowardViewer, false);
    QCOMPARE(c.colourScale, 1.0f);
    QCOMPARE(c.rounding, ByteRounding::Truncate);
    QCOMPARE(c.background, vec4(0.0f));
    // Rules: seed 001's DDA on unsnapped vertices, integer sample points, half-open rows and
    // spans, perspective-correct.
    const RasterRules& r = scene.rules;
    QCOMPARE(r.subpixelBits, 16);
    QCOMPARE(r.sampleOffset, 0.0);
    QCOMPARE(r.snap, RasterRules::VertexSnap::None);
    QCOMPARE(r.scan, RasterRules::Scan::Dda);
    QCOMPARE(r.fill, RasterRules::FillRule::TopLeft);
    QCOMPARE(r.interpolation, RasterRules::Interpolation::PerspectiveCorrect);
    QCOMPARE(r.texel, RasterRules::TexelRounding::Truncate);
    // No clipping against w before the divide (seed 001: "we won't add it").
    QCOMPARE(scene.nearPlane.mode, NearPlane::Mode::Naive);
    QVERIFY(diagnostics.empty());
}

void TestHw2Reader::pngStartsNewImage() {
    Diagnostics diagnostics;
    auto file = read(
        "png 4 4 a.png\nxyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\ntrif 1 2 3\ntrif 1 2 3\n"
        "png 8 2 b.png\ntrif 3 2 1\n",
        diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    QCOMPARE(file->images.size(), std::size_t(2));
    QCOMPARE(file->images[0].fileName, std::string("a.png"));
    QCOMPARE(file->images[0].scene.triangleCount(), std::size_t(2));
    QCOMPARE(file->images[1].fileName, std::string("b.png"));
    QCOMPARE(file->images[1].scene.width, 8);
    QCOMPARE(file->images[1].scene.height, 2);
    QCOMPARE(file->images[1].scene.triangleCount(), std::size_t(1));
    // The vertex list carries on into the second image.
    QCOMPARE(file->images[1].scene.draws[0].mesh->positions[0], dvec4(0, 1, 0, 1));
}

void TestHw2Reader::vertexAttributes() {
    // Each vertex keeps the colour, normal and texture coordinate current when it was made;
    // before any of those commands: white, no normal, (0, 0).
    Diagnostics diagnostics;
    auto file = read(
        "png 4 4 a.png\n"
        "xyz 1 2 3\n"
        "color 0.5 0.25 1\n"
        "normal 0 0 2\n"
        "texcoord 0.5 -1\n"
        "xyzw 2 4 6 2\n"
        "color 0 1 0\n"
        "texcoord 3 0.25\n"
        "xyz -1 -2 -3\n"
        "trig 1 2 3\n",
        diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    const Scene& scene = file->images[0].scene;
    QCOMPARE(scene.draws.size(), std::size_t(1));
    const Mesh& mesh = *scene.draws[0].mesh;
    QCOMPARE(mesh.positions, (std::vector<dvec4>{{1, 2, 3, 1}, {2, 4, 6, 2}, {-1, -2, -3, 1}}));
    QCOMPARE(mesh.colours, (std::vector<vec3>{{1, 1, 1}, {0.5f, 0.25f, 1}, {0, 1, 0}}));
    QCOMPARE(mesh.normals, (std::vector<vec3>{{0, 0, 0}, {0, 0, 2}, {0, 0, 2}}));
    QCOMPARE(mesh.texcoords, (std::vector<vec2>{{0, 0}, {0.5f, -1}, {3, 0.25f}}));
    QCOMPARE(mesh.triangles, (std::vector<std::array<std::uint32_t, 3>>{{0, 1, 2}}));
    QCOMPARE(mesh.triangleLines, std::vector<int>{10});
    QVERIFY(diagnostics.empty());
}

void TestHw2Reader::fills_data() {
    QTest::addColumn<QByteArray>("command");
    QTest::addColumn<int>("colourSource");  // ColourSource
    QTest::addColumn<bool>("vertexColours");
    QTest::newRow("trif: flat in the colour current at the trif")
        << QByteArray("trif") << int(ColourSource::Vertex) << false;
    QTest::newRow("trig: each vertex its own colour")
        << QByteArray("trig") << int(ColourSource::Vertex) << true;
    QTest::newRow("trit: the texture") << QByteArray("trit") << int(ColourSource::Texture) << true;
}

void TestHw2Reader::fills() {
    QFETCH(QByteArray, command);
    QFETCH(int, colourSource);
    QFETCH(bool, vertexColours);
    FakeLoader fake;
    Diagnostics diagnostics;
    auto file = read(
        "png 4 4 a.png\ntexture t.png\n"
        "color 1 0 0\ntexcoord 0.25 0.5\nxyz 0 0 0\n"
        "color 0 1 0\ntexcoord 1 2\nxyz 1 0 0\n"
        "color 0 0 1\ntexcoord -1 3\nxyz 0 1 0\n"
        "color 0.5 0.5 0.5\n" +
            command + " 1 2 3\n",
        diagnostics, fake.loader());
    QVERIFY2(file, qPrintable(errorOf(file)));
    const Draw& draw = file->images[0].scene.draws.at(0);
    const Mesh& mesh = *draw.mesh;
    QCOMPARE(int(draw.colour), colourSource);
    QCOMPARE(draw.lighting, LightingModel::Unlit);
    QCOMPARE(draw.decals, false);
    if (vertexColours)
        QCOMPARE(mesh.colours, (std::vector<vec3>{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}));
    else
        QCOMPARE(mesh.colours, std::vector<vec3>(3, vec3(0.5f)));
    QCOMPARE(mesh.texcoords, (std::vector<vec2>{{0.25f, 0.5f}, {1, 2}, {-1, 3}}));
    if (colourSource == int(ColourSource::Texture))
        QCOMPARE(draw.texture, fake.texture);
    else
        QVERIFY(!draw.texture);
}

void TestHw2Reader::indices_data() {
    QTest::addColumn<QByteArray>("indices");
    QTest::addColumn<QList<int>>("xs");  // the x of the vertices drawn: vertex k has x = k
    QTest::newRow("1-based") << QByteArray("1 2 3") << QList<int>{1, 2, 3};
    QTest::newRow("last three") << QByteArray("4 3 2") << QList<int>{4, 3, 2};
    QTest::newRow("-1 is the last") << QByteArray("-1 -2 -3") << QList<int>{4, 3, 2};
    QTest::newRow("-4 is the first") << QByteArray("-4 2 -1") << QList<int>{1, 2, 4};
    QTest::newRow("explicit plus sign") << QByteArray("+1 +3 -2") << QList<int>{1, 3, 3};
}

void TestHw2Reader::indices() {
    QFETCH(QByteArray, indices);
    QFETCH(QList<int>, xs);
    Diagnostics diagnostics;
    auto file =
        read("png 4 4 a.png\nxyz 1 0 0\nxyz 2 1 0\nxyz 3 0 1\nxyz 4 1 1\ntrif " + indices + "\n",
             diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    const Mesh& mesh = *file->images[0].scene.draws.at(0).mesh;
    QCOMPARE(mesh.positions.size(), std::size_t(3));
    for (int k = 0; k < 3; ++k) QCOMPARE(mesh.positions[std::size_t(k)].x, double(xs[k]));
}

void TestHw2Reader::negativeIndexCountsFromNow() {
    // -1 is the last vertex defined before the command, not the last of the file.
    Diagnostics diagnostics;
    auto file = read(
        "png 4 4 a.png\nxyz 1 0 0\nxyz 2 0 0\nxyz 3 0 0\ntrif -1 -2 -3\nxyz 4 0 0\n"
        "trif -1 -2 -3\n",
        diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    const Mesh& mesh = *file->images[0].scene.draws.at(0).mesh;
    std::vector<double> xs;
    for (const dvec4& p : mesh.positions) xs.push_back(p.x);
    QCOMPARE(xs, (std::vector<double>{3, 2, 1, 4, 3, 2}));
}

void TestHw2Reader::modelView_data() {
    QTest::addColumn<QByteArray>("commands");
    QTest::addColumn<Rows>("rows");  // the draw's worldFromModel (model/view)
    const double h = std::sqrt(0.5);
    QTest::newRow("none") << QByteArray() << kIdentity;
    QTest::newRow("translate") << QByteArray("translate 1 2 3")
                               << Rows{1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1};
    QTest::newRow("rotatex 90") << QByteArray("rotatex 90")
                                << Rows{1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1};
    QTest::newRow("rotatey 90") << QByteArray("rotatey 90")
                                << Rows{0, 0, 1, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 0, 1};
    QTest::newRow("rotatez 45") << QByteArray("rotatez 45")
                                << Rows{h, -h, 0, 0, h, h, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    QTest::newRow("rotate 90 about (0, 0, 2)")
        << QByteArray("rotate 90 0 0 2") << Rows{0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    // (1, 2, 2)/3 at 90 degrees: [1 -4 8; 8 4 1; -4 7 4] / 9 (glRotate's matrix).
    QTest::newRow("rotate 90 about (1, 2, 2)")
        << QByteArray("rotate 90 1 2 2")
        << Rows{1.0 / 9,  -4.0 / 9, 8.0 / 9, 0, 8.0 / 9, 4.0 / 9, 1.0 / 9, 0,
                -4.0 / 9, 7.0 / 9,  4.0 / 9, 0, 0,       0,       0,       1};
    QTest::newRow("scale") << QByteArray("scale 2 3 4")
                           << Rows{2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 4, 0, 0, 0, 0, 1};
    // Each command multiplies on the right: the last one given is applied to points first.
    QTest::newRow("translate then scale: T S")
        << QByteArray("translate 1 0 0\nscale 2 2 2")
        << Rows{2, 0, 0, 1, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1};
    QTest::newRow("scale then translate: S T")
        << QByteArray("scale 2 2 2\ntranslate 1 0 0")
        << Rows{2, 0, 0, 2, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1};
    QTest::newRow("rotatez 90 then translate: Rz T")
        << QByteArray("rotatez 90\ntranslate 1 0 0")
        << Rows{0, -1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 1};
    QTest::newRow("multmv alone") << QByteArray("multmv 1 2 3 4  5 6 7 8  9 10 11 12  0 0 0 1")
                                  << Rows{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 0, 0, 0, 1};
    QTest::newRow("translate then multmv: T M")
        << QByteArray("translate 0 0 -5\nmultmv 2 0 0 0  0 1 0 1  0 0 1 0  0 0 0 1")
        << Rows{2, 0, 0, 0, 0, 1, 0, 1, 0, 0, 1, -5, 0, 0, 0, 1};
    QTest::newRow("loadmv replaces")
        << QByteArray(
               "translate 5 5 5\nrotatex 30\nloadmv 0.7 0.1 0.2 0.1  -0.1 0.6 0.1 -0.1  "
               "0 0 1 -0.3  0 0 0 1")
        << Rows{0.7, 0.1, 0.2, 0.1, -0.1, 0.6, 0.1, -0.1, 0, 0, 1, -0.3, 0, 0, 0, 1};
    QTest::newRow("loadmv then translate: M T")
        << QByteArray("loadmv 2 0 0 0  0 2 0 0  0 0 2 0  0 0 0 1\ntranslate 1 1 1")
        << Rows{2, 0, 0, 2, 0, 2, 0, 2, 0, 0, 2, 2, 0, 0, 0, 1};
    // gluLookAt from (3, 0, 0) toward the origin, y up: rows s = (0, 0, -1), u = (0, 1, 0),
    // -f = (1, 0, 0), last column -(s.eye, u.eye, -f.eye).
    QTest::newRow("lookat replaces")
        << QByteArray("translate 9 9 9\nxyz 3 0 0\nxyz 0 0 0\nlookat 1 2 0 1 0")
        << Rows{0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, -3, 0, 0, 0, 1};
    QTest::newRow("lookat with negative indices and xyzw")
        << QByteArray("xyzw 6 0 0 2\nxyz 0 0 0\nlookat -2 -1 0 1 0")
        << Rows{0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, -3, 0, 0, 0, 1};
    QTest::newRow("lookat then translate: L T")
        << QByteArray("xyz 3 0 0\nxyz 0 0 0\nlookat 1 2 0 1 0\ntranslate 0 0 1")
        << Rows{0, 0, -1, -1, 0, 1, 0, 0, 1, 0, 0, -3, 0, 0, 0, 1};
    QTest::newRow("projection commands leave it alone")
        << QByteArray(
               "translate 1 2 3\nfrustum -1 1 -1 1 1 10\northo -1 1 -1 1 1 10\n"
               "loadp 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1")
        << Rows{1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1};
}

void TestHw2Reader::modelView() {
    QFETCH(QByteArray, commands);
    QFETCH(Rows, rows);
    Diagnostics diagnostics;
    auto file = read(withTriangle(commands), diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    const Scene& scene = file->images[0].scene;
    QCOMPARE(scene.draws.size(), std::size_t(1));
    RL_COMPARE_MATRIX(scene.draws[0].worldFromModel, rows, 1e-12);
    // The positions stay as given: the matrix is applied by the pipeline.
    QCOMPARE(scene.draws[0].mesh->positions[1], dvec4(1, 0, 0, 1));
    QVERIFY2(diagnostics.empty(), qPrintable(linesOf(diagnostics).join('\n')));
}

void TestHw2Reader::projection_data() {
    QTest::addColumn<QByteArray>("commands");
    QTest::addColumn<Rows>("rows");  // the draw's clipFromView
    QTest::newRow("none") << QByteArray() << kIdentity;
    QTest::newRow("loadp, row by row")
        << QByteArray("loadp 1 2 3 4  5 6 7 8  9 10 11 12  13 14 15 16")
        << Rows{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
    // glFrustum(-1, 1, -1, 1, 1, 10): -(f+n)/(f-n) = -11/9, -2fn/(f-n) = -20/9.
    QTest::newRow("frustum") << QByteArray("frustum -1 1 -1 1 1 10")
                             << Rows{1, 0, 0,         0,         0, 1, 0,  0,
                                     0, 0, -11.0 / 9, -20.0 / 9, 0, 0, -1, 0};
    // glOrtho with near 2n - f = -1: -2/(f-N) = -0.5, -(f+N)/(f-N) = -0.5.
    QTest::newRow("ortho") << QByteArray("ortho -2 2 -1 1 1 3")
                           << Rows{0.5, 0, 0, 0, 0, 1, 0, 0, 0, 0, -0.5, -0.5, 0, 0, 0, 1};
    QTest::newRow("frustum replaces loadp")
        << QByteArray("loadp 1 2 3 4  5 6 7 8  9 10 11 12  13 14 15 16\nfrustum -1 1 -1 1 1 10")
        << Rows{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -11.0 / 9, -20.0 / 9, 0, 0, -1, 0};
    QTest::newRow("loadp replaces ortho")
        << QByteArray("ortho -2 2 -1 1 1 3\nloadp 2 0 0 0  0 2 0 0  0 0 2 0  0 0 0 1")
        << Rows{2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1};
    QTest::newRow("model/view commands leave it alone")
        << QByteArray(
               "ortho -2 2 -1 1 1 3\ntranslate 1 2 3\nloadmv 2 0 0 0  0 2 0 0  0 0 2 0  0 0 "
               "0 1\nscale 3 3 3")
        << Rows{0.5, 0, 0, 0, 0, 1, 0, 0, 0, 0, -0.5, -0.5, 0, 0, 0, 1};
}

void TestHw2Reader::projection() {
    QFETCH(QByteArray, commands);
    QFETCH(Rows, rows);
    Diagnostics diagnostics;
    auto file = read(withTriangle(commands), diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    const Draw& draw = file->images[0].scene.draws.at(0);
    QVERIFY(draw.clipFromView.has_value());
    RL_COMPARE_MATRIX(*draw.clipFromView, rows, 1e-12);
}

void TestHw2Reader::clipPlanes() {
    // A plane is kept as given, in eye coordinates (after the model/view), whatever the
    // model/view is; planes add up; triangles drawn before a plane do not see it.
    Diagnostics diagnostics;
    auto file = read(
        "png 4 4 a.png\nxyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\n"
        "trif 1 2 3\n"
        "translate 0.5 0 0\nscale 2 2 2\n"
        "clipplane 1 0 0 0.5\n"
        "trif 1 2 3\n"
        "clipplane -0.1 -0.2 0.1 0.03\n"
        "trif 1 2 3\n",
        diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    const auto& draws = file->images[0].scene.draws;
    QCOMPARE(draws.size(), std::size_t(3));
    QVERIFY(draws[0].clipPlanes.empty());
    QCOMPARE(draws[1].clipPlanes, (std::vector<dvec4>{{1, 0, 0, 0.5}}));
    QCOMPARE(draws[2].clipPlanes, (std::vector<dvec4>{{1, 0, 0, 0.5}, {-0.1, -0.2, 0.1, 0.03}}));
}

void TestHw2Reader::cull() {
    Diagnostics diagnostics;
    auto file =
        read("png 4 4 a.png\nxyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\ntrif 1 2 3\ncull\ntrif 1 2 3\n",
             diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    const auto& draws = file->images[0].scene.draws;
    QCOMPARE(draws.size(), std::size_t(2));
    QCOMPARE(draws[0].cull, false);
    QCOMPARE(draws[1].cull, true);
    QVERIFY(diagnostics.empty());
}

void TestHw2Reader::texture() {
    FakeLoader fake;
    Diagnostics diagnostics;
    auto file =
        read("png 4 4 a.png\n  texture   splat2.png\nxyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\ntrit 1 2 3\n",
             diagnostics, fake.loader());
    QVERIFY2(file, qPrintable(errorOf(file)));
    QCOMPARE(fake.calls.size(), std::size_t(1));
    QCOMPARE(fake.calls[0].first, std::string("splat2.png"));
    // The location of the file name, for the loader's messages.
    QCOMPARE(QString::fromStdString(fake.calls[0].second.toString()),
             QStringLiteral("cmd.txt:2:13"));
    const Draw& draw = file->images[0].scene.draws.at(0);
    QCOMPARE(draw.colour, ColourSource::Texture);
    QCOMPARE(draw.texture, fake.texture);
    QCOMPARE(draw.texture->width, 2);
    QVERIFY(diagnostics.empty());

    // No texture command: the loader is never asked.
    FakeLoader unused;
    auto plain = read("png 4 4 a.png\nxyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\ntrif 1 2 3\n", diagnostics,
                      unused.loader());
    QVERIFY(plain);
    QVERIFY(unused.calls.empty());
}

void TestHw2Reader::textureLoaderError() {
    const TextureLoader failing =
        [](const std::string& name,
           const SourceLocation& where) -> Result<std::shared_ptr<const Texture>> {
        return makeError(ErrorCode::Io, where, "cannot read the texture " + name + ": not found");
    };
    Diagnostics diagnostics;
    auto file = read("png 4 4 a.png\nxyz 0 0 0\ntexture missing.png\n", diagnostics, failing);
    QVERIFY(!file);
    QCOMPARE(errorOf(file),
             QStringLiteral("cmd.txt:3:9: cannot read the texture missing.png: not found"));
    QCOMPARE(file.error().code, ErrorCode::Io);
}

void TestHw2Reader::decalsActOnWholeFile_data() {
    QTest::addColumn<QByteArray>("before");
    QTest::addColumn<QByteArray>("after");
    QTest::addColumn<bool>("decals");
    QTest::newRow("no decals") << QByteArray() << QByteArray() << false;
    QTest::newRow("decals first") << QByteArray("decals\n") << QByteArray() << true;
    QTest::newRow("decals after the trit") << QByteArray() << QByteArray("decals\n") << true;
    QTest::newRow("decals after the last png")
        << QByteArray() << QByteArray("png 2 2 b.png\ndecals\n") << true;
}

void TestHw2Reader::decalsActOnWholeFile() {
    QFETCH(QByteArray, before);
    QFETCH(QByteArray, after);
    QFETCH(bool, decals);
    Diagnostics diagnostics;
    auto file = read("png 4 4 a.png\n" + before +
                         "texture t.png\nxyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\ntrit 1 2 3\n"
                         "trig 1 2 3\n" +
                         after,
                     diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    const auto& draws = file->images[0].scene.draws;
    QCOMPARE(draws.size(), std::size_t(2));
    QCOMPARE(draws[0].colour, ColourSource::Texture);
    QCOMPARE(draws[0].decals, decals);
    QCOMPARE(draws[1].decals, false);  // only textured triangles blend
    QVERIFY(diagnostics.empty());
}

void TestHw2Reader::flatNormals_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<bool>("flatNormals");
    QTest::addColumn<int>("lighting");  // LightingModel
    const QByteArray lit = "png 4 4 a.png\nsunlight 0 0 -1\nnormal 0 0 -1\n";
    const QByteArray triangle = "xyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\n";
    QTest::newRow("trif with normals") << lit + triangle + "trif 1 2 3\n"
                                       << false << int(LightingModel::Lambert);
    QTest::newRow("trif, flatnormals after it") << lit + triangle + "trif 1 2 3\nflatnormals\n"
                                                << true << int(LightingModel::Lambert);
    QTest::newRow("trif, flatnormals first") << "flatnormals\n" + lit + triangle + "trif 1 2 3\n"
                                             << true << int(LightingModel::Lambert);
    QTest::newRow("trig ignores flatnormals") << lit + triangle + "trig 1 2 3\nflatnormals\n"
                                              << false << int(LightingModel::Lambert);
    QTest::newRow("trif without normals lights with its own")
        << "png 4 4 a.png\nsunlight 0 0 -1\n" + triangle + "trif 1 2 3\n"
        << true << int(LightingModel::Lambert);
    QTest::newRow("unlit: no normals needed")
        << "png 4 4 a.png\n" + triangle + "trif 1 2 3\nflatnormals\n"
        << false << int(LightingModel::Unlit);
}

void TestHw2Reader::flatNormals() {
    QFETCH(QByteArray, text);
    QFETCH(bool, flatNormals);
    QFETCH(int, lighting);
    Diagnostics diagnostics;
    auto file = read(text, diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    const Draw& draw = file->images[0].scene.draws.at(0);
    QCOMPARE(draw.flatNormals, flatNormals);
    QCOMPARE(int(draw.lighting), lighting);
}

void TestHw2Reader::sunlight_data() {
    QTest::addColumn<QByteArray>("commands");
    QTest::addColumn<Rows>("direction");  // the unit eye-space direction stored
    QTest::newRow("made unit length") << QByteArray("sunlight 0 3 -4") << Rows{0, 0.6, -0.8};
    QTest::newRow("rotatez 90 turns it")
        << QByteArray("rotatez 90\nsunlight 1 0 0") << Rows{0, 1, 0};
    QTest::newRow("translations ignored")
        << QByteArray("translate 5 6 7\nsunlight 0 0 2") << Rows{0, 0, 1};
    // Scaling applies inversely: (1, 1, 0) under scale 2 1 1 is (1/2, 1, 0), i.e. (1, 2, 0)/sqrt5.
    const double r5 = std::sqrt(5.0);
    QTest::newRow("scale applies inversely")
        << QByteArray("scale 2 1 1\nsunlight 1 1 0") << Rows{1 / r5, 2 / r5, 0};
    QTest::newRow("later model/view does not move it")
        << QByteArray("sunlight 0 0 -1\nrotatex 90") << Rows{0, 0, -1};
}

void TestHw2Reader::sunlight() {
    QFETCH(QByteArray, commands);
    QFETCH(Rows, direction);
    Diagnostics diagnostics;
    auto file =
        read("png 4 4 a.png\ncolor 1 0.5 0.25\n" + commands + "\ncolor 0 1 0\n", diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    const Scene& scene = file->images[0].scene;
    QCOMPARE(scene.lights.size(), std::size_t(1));
    const Light& light = scene.lights[0];
    RL_COMPARE_VEC(light.pWorld, dvec4(direction[0], direction[1], direction[2], 0.0), 1e-12);
    QCOMPARE(light.intensity, vec3(1, 0.5f, 0.25f));  // the colour current at the command
}

void TestHw2Reader::bulb_data() {
    QTest::addColumn<QByteArray>("commands");
    QTest::addColumn<Rows>("position");  // eye space
    QTest::newRow("no model/view") << QByteArray("xyz 1 2 3\nbulb 1") << Rows{1, 2, 3};
    QTest::newRow("-1, the last vertex")
        << QByteArray("xyz 9 9 9\nxyz 1 2 3\nbulb -1") << Rows{1, 2, 3};
    QTest::newRow("translated") << QByteArray("translate 1 1 1\nxyz 1 2 3\nbulb 1")
                                << Rows{2, 3, 4};
    QTest::newRow("rotated: (1, 2, 3) about z by 90")
        << QByteArray("rotatez 90\nxyz 1 2 3\nbulb 1") << Rows{-2, 1, 3};
    QTest::newRow("xyzw divided") << QByteArray("xyzw 2 4 6 2\nbulb 1") << Rows{1, 2, 3};
    QTest::newRow("projection not applied")
        << QByteArray("frustum -1 1 -1 1 1 10\nxyz 1 2 -3\nbulb 1") << Rows{1, 2, -3};
}

void TestHw2Reader::bulb() {
    QFETCH(QByteArray, commands);
    QFETCH(Rows, position);
    Diagnostics diagnostics;
    auto file = read("png 4 4 a.png\ncolor 2 -1 0.5\n" + commands + "\n", diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    const Scene& scene = file->images[0].scene;
    QCOMPARE(scene.lights.size(), std::size_t(1));
    RL_COMPARE_VEC(scene.lights[0].pWorld, dvec4(position[0], position[1], position[2], 1.0),
                   1e-12);
    // Brighter than 1 and negative values are kept as they are.
    QCOMPARE(scene.lights[0].intensity, vec3(2, -1, 0.5f));
}

void TestHw2Reader::lightsSeenByDraws() {
    // A draw is lit by the lights given before it; lights after do not change it.
    Diagnostics diagnostics;
    auto file = read(
        "png 4 4 a.png\nxyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\ntrif 1 2 3\n"
        "sunlight 0 0 -1\ntrif 1 2 3\nbulb 1\ntrif 1 2 3\nsunlight 1 0 0\n",
        diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    const Scene& scene = file->images[0].scene;
    QCOMPARE(scene.lights.size(), std::size_t(3));
    QCOMPARE(scene.lights[0].pWorld.w, 0.0);
    QCOMPARE(scene.lights[1].pWorld, dvec4(0, 0, 0, 1));
    QCOMPARE(QString::fromStdString(scene.lights[1].where.toString()),
             QStringLiteral("cmd.txt:8:1"));
    QCOMPARE(scene.draws.size(), std::size_t(3));
    QCOMPARE(scene.draws[0].lighting, LightingModel::Unlit);
    QCOMPARE(scene.draws[0].lightCount, std::size_t(0));
    QCOMPARE(scene.draws[1].lighting, LightingModel::Lambert);
    QCOMPARE(scene.draws[1].lightCount, std::size_t(1));
    QCOMPARE(scene.draws[2].lightCount, std::size_t(2));
    QCOMPARE(scene.draws[2].material.od, vec3(1.0f));
}

void TestHw2Reader::shininess_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<float>("shininess");
    const QByteArray triangle = "xyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\n";
    QTest::newRow("lit") << "png 4 4 a.png\nsunlight 0 0 -1\nshininess 8\n" + triangle +
                                "trif 1 2 3\n"
                         << 8.0f;
    QTest::newRow("the most recent one")
        << "png 4 4 a.png\nsunlight 0 0 -1\nshininess 8\nshininess 2.5\n" + triangle +
               "trif 1 2 3\n"
        << 2.5f;
    QTest::newRow("none given") << "png 4 4 a.png\nsunlight 0 0 -1\n" + triangle + "trif 1 2 3\n"
                                << 0.0f;
    QTest::newRow("negative kept (no highlight)")
        << "png 4 4 a.png\nbulb 1\nshininess -3\n" + triangle + "trif 1 2 3\n"
        << -3.0f;
    QTest::newRow("unlit: no highlight")
        << "png 4 4 a.png\nshininess 8\n" + triangle + "trif 1 2 3\n"
        << 0.0f;
}

void TestHw2Reader::shininess() {
    QFETCH(QByteArray, text);
    QFETCH(float, shininess);
    Diagnostics diagnostics;
    // "bulb 1" before any vertex would be an error: give one first where needed.
    if (text.contains("bulb 1")) text.replace("png 4 4 a.png\n", "png 4 4 a.png\nxyz 0 0 0\n");
    auto file = read(text, diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    QCOMPARE(file->images[0].scene.draws.at(0).material.shininess, shininess);
}

void TestHw2Reader::bezierPatches_data() {
    QTest::addColumn<QByteArray>("command");
    QTest::addColumn<int>("vertices");
    QTest::addColumn<int>("triangles");
    QTest::addColumn<bool>("flat");
    QTest::newRow("rectbezf 1") << QByteArray("rectbezf 1 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16")
                                << 9 << 8 << true;
    QTest::newRow("rectbezg 2") << QByteArray("rectbezg 2 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16")
                                << 25 << 32 << false;
    // Rows of 4, 3, 2, 1 points of the grid: (0..3, 0), (0..2, 1), (0..1, 2), (0, 3).
    QTest::newRow("tribezf 1") << QByteArray("tribezf 1 1 2 3 4 5 6 7 9 10 13") << 6 << 4 << true;
    QTest::newRow("tribezg 3 (negative indices)")
        << QByteArray("tribezg 3 -16 -15 -14 -13 -12 -11 -10 -8 -7 -4") << 45 << 64 << false;
}

void TestHw2Reader::bezierPatches() {
    QFETCH(QByteArray, command);
    QFETCH(int, vertices);
    QFETCH(int, triangles);
    QFETCH(bool, flat);
    // 16 control points on a grid, coloured by column: red, then green, blue, white.
    QByteArray text = "png 4 4 a.png\n";
    const char* colours[4] = {"1 0 0", "0 1 0", "0 0 1", "1 1 1"};
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i)
            text += QByteArray("color ") + colours[i] + "\nxyz " + QByteArray::number(i) + " " +
                    QByteArray::number(j) + " 0\n";
    text += "color 0.5 0.25 0.125\n" + command + "\n";
    Diagnostics diagnostics;
    auto file = read(text, diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    const Scene& scene = file->images[0].scene;
    QCOMPARE(scene.draws.size(), std::size_t(1));
    const Mesh& mesh = *scene.draws[0].mesh;
    QCOMPARE(int(mesh.positions.size()), vertices);
    QCOMPARE(int(mesh.triangles.size()), triangles);
    QCOMPARE(int(mesh.triangleLines.size()), triangles);
    QCOMPARE(mesh.triangleLines.front(), 35);
    // The first patch vertex is the first control point (s = t = 0, or u = 1).
    QCOMPARE(mesh.positions.front(), dvec4(0, 0, 0, 1));
    if (flat)
        QCOMPARE(mesh.colours, std::vector<vec3>(mesh.positions.size(), vec3(0.5f, 0.25f, 0.125f)));
    else
        QCOMPARE(mesh.colours.front(), vec3(1, 0, 0));
    // Patch normals (of the interpolated shape): the grid lies in z = 0.
    RL_COMPARE_VEC(mesh.normals[std::size_t(vertices / 2)], vec3(0, 0, 1), 1e-6);
}

void TestHw2Reader::drawSharing_data() {
    QTest::addColumn<QByteArray>("between");  // between two triangles
    QTest::addColumn<QByteArray>("second");   // the second drawing command
    QTest::addColumn<int>("draws");
    QTest::newRow("nothing") << QByteArray() << QByteArray("trif") << 1;
    QTest::newRow("a colour") << QByteArray("color 1 0 0") << QByteArray("trif") << 1;
    QTest::newRow("a vertex") << QByteArray("xyz 5 5 5") << QByteArray("trif") << 1;
    QTest::newRow("a translation by zero")
        << QByteArray("translate 0 0 0") << QByteArray("trif") << 1;
    QTest::newRow("unknown command") << QByteArray("bogus 1 2") << QByteArray("trif") << 1;
    QTest::newRow("a translation") << QByteArray("translate 0 0 0.5") << QByteArray("trif") << 2;
    QTest::newRow("loadmv") << QByteArray("loadmv 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 2")
                            << QByteArray("trif") << 2;
    QTest::newRow("a projection") << QByteArray("frustum -1 1 -1 1 1 10") << QByteArray("trif")
                                  << 2;
    QTest::newRow("a clip plane") << QByteArray("clipplane 0 0 1 0") << QByteArray("trif") << 2;
    QTest::newRow("cull") << QByteArray("cull") << QByteArray("trif") << 2;
    QTest::newRow("a light") << QByteArray("sunlight 0 0 -1") << QByteArray("trif") << 2;
    QTest::newRow("trif then trig") << QByteArray() << QByteArray("trig") << 2;
    QTest::newRow("trif then trit") << QByteArray("texture t.png") << QByteArray("trit") << 2;
}

void TestHw2Reader::drawSharing() {
    QFETCH(QByteArray, between);
    QFETCH(QByteArray, second);
    QFETCH(int, draws);
    Diagnostics diagnostics;
    auto file = read("png 4 4 a.png\nxyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\ntrif 1 2 3\n" + between +
                         "\n" + second + " 1 2 3\n",
                     diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    const Scene& scene = file->images[0].scene;
    QCOMPARE(int(scene.draws.size()), draws);
    QCOMPARE(scene.triangleCount(), std::size_t(2));
    if (draws == 1) QCOMPARE(scene.draws[0].mesh->triangleLines, (std::vector<int>{5, 7}));
    for (const Draw& draw : scene.draws) QVERIFY(draw.mesh && !draw.mesh->triangles.empty());
}

void TestHw2Reader::unknownKeywordsSkipped() {
    // Skipped, counted per keyword, and noted once at the first place each appears (the
    // notes in the keywords' alphabetical order).
    Diagnostics diagnostics;
    auto file = read(
        "png 4 4 a.png\nfoo 1 2\nxyz 0 0 0\n  bar\nfoo\nxyz 1 0 0\nxyz 0 1 0\nPNG 2 2 x.png\n"
        "trif 1 2 3\n",
        diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    QCOMPARE(file->images.size(), std::size_t(1));
    QCOMPARE(file->images[0].scene.triangleCount(), std::size_t(1));
    QCOMPARE(linesOf(diagnostics),
             (QStringList{"cmd.txt:8:1: note: skipped 1 line with the unknown command 'PNG'",
                          "cmd.txt:4:3: note: skipped 1 line with the unknown command 'bar'",
                          "cmd.txt:2:1: note: skipped 2 lines with the unknown command 'foo'"}));
}

void TestHw2Reader::blankLinesSkipped() {
    // Blank and whitespace-only lines, CRLF endings and tabs change nothing but the line
    // numbers, which stay those of the file.
    Diagnostics diagnostics;
    auto file = read(
        "\r\npng 4 4 a.png\r\n\r\n \t \r\nxyz 0 0 0\r\n\txyz\t1 0 0\r\n\r\nxyz 0 1 0\r\n"
        "trif 1 2 3",
        diagnostics);
    QVERIFY2(file, qPrintable(errorOf(file)));
    const Mesh& mesh = *file->images[0].scene.draws.at(0).mesh;
    QCOMPARE(mesh.positions[1], dvec4(1, 0, 0, 1));
    QCOMPARE(mesh.triangleLines, std::vector<int>{9});
    QVERIFY(diagnostics.empty());

    auto bad = read("png 4 4 a.png\n\n\n   \n\txyz 0 x 0\n", diagnostics);
    QCOMPARE(errorOf(bad),
             QStringLiteral("cmd.txt:5:8: expected a number in 'xyz' (x y z), found 'x'"));
}

void TestHw2Reader::extraValuesWarned_data() {
    QTest::addColumn<QByteArray>("line");  // line 5, after png and three vertices
    QTest::addColumn<QStringList>("diagnostics");
    QTest::newRow("xyz with four numbers")
        << QByteArray("xyz 1 2 3 4")
        << QStringList{"cmd.txt:5:11: warning: ignored 1 value after 'xyz'"};
    QTest::newRow("trif with four indices")
        << QByteArray("trif 1 2 3 1 2")
        << QStringList{"cmd.txt:5:12: warning: ignored 2 values after 'trif'"};
    QTest::newRow("cull with a value")
        << QByteArray("cull 1")
        << QStringList{"cmd.txt:5:6: warning: ignored 1 value after 'cull'"};
    QTest::newRow("lookat, complete") << QByteArray("lookat 1 2 0 1 0") << QStringList();
    QTest::newRow("lookat with an extra value")
        << QByteArray("lookat 1 2 0 1 0 7")
        << QStringList{"cmd.txt:5:18: warning: ignored 1 value after 'lookat'"};
    QTest::newRow("bulb with an extra value")
        << QByteArray("bulb 1 2")
        << QStringList{"cmd.txt:5:8: warning: ignored 1 value after 'bulb'"};
    QTest::newRow("rectbezf, complete")
        << QByteArray("rectbezf 1 1 2 3 1 2 3 1 2 3 1 2 3 1 2 3 1") << QStringList();
    // Image names stay in the output folder; a name used twice is said.
    QTest::newRow("png name with folders")
        << QByteArray("png 4 4 ../../etc/b.png")
        << QStringList{
               "cmd.txt:5:9: warning: the image name '../../etc/b.png' reaches into "
               "folders: it is written as 'b.png' in the output folder"};
    QTest::newRow("png name used twice")
        << QByteArray("png 4 4 a.png")
        << QStringList{
               "cmd.txt:5:9: warning: an earlier png command (line 1) names 'a.png' "
               "too: this image replaces it"};
}

void TestHw2Reader::extraValuesWarned() {
    QFETCH(QByteArray, line);
    QFETCH(QStringList, diagnostics);
    Diagnostics found;
    auto file = read("png 4 4 a.png\nxyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\n" + line + "\n", found);
    QVERIFY2(file, qPrintable(errorOf(file)));
    QCOMPARE(linesOf(found), diagnostics);
}

void TestHw2Reader::errors_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("message");  // file:line:col: message
    const QByteArray head = "png 4 4 a.png\nxyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\n";  // line 5 next

    // "xyz 1 b 3": the b is at column 7.
    QTest::newRow("letter for a number")
        << QByteArray("png 4 4 a.png\nxyz 1 b 3\n")
        << "cmd.txt:2:7: expected a number in 'xyz' (x y z), found 'b'";
    QTest::newRow("decimal comma")
        << QByteArray("png 4 4 a.png\ncolor 1,5 0 0\n")
        << "cmd.txt:2:7: expected a number in 'color' (r g b), found '1,5'";
    QTest::newRow("nan") << QByteArray("png 4 4 a.png\nxyzw 0 0 0 nan\n")
                         << "cmd.txt:2:12: expected a number in 'xyzw' (x y z w), found 'nan'";
    // "color 1 0.5" ends at column 11: the place after it is column 12.
    QTest::newRow("too few numbers") << QByteArray("png 4 4 a.png\ncolor 1 0.5\n")
                                     << "cmd.txt:2:12: expected 3 numbers after 'color' (r g b), "
                                        "found 2";
    QTest::newRow("loadmv with 15 numbers")
        << QByteArray("png 4 4 a.png\nloadmv 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0\n")
        << "cmd.txt:2:37: expected 16 numbers after 'loadmv' (a11 a12 ... a44, row by row), "
           "found 15";
    QTest::newRow("texcoord alone") << QByteArray("texcoord\n")
                                    << "cmd.txt:1:9: expected 2 numbers after 'texcoord' (s t), "
                                       "found 0";
    // "trif 1 0 2": the 0 is at column 8.
    QTest::newRow("index 0") << head + "trif 1 0 2\n"
                             << "cmd.txt:5:8: 'trif' refers to vertex 0, but indices start at 1 "
                                "(or count back from -1, the last)";
    QTest::newRow("index out of range")
        << head + "trig 1 2 4\n"
        << "cmd.txt:5:10: 'trig' refers to vertex 4, but only 3 vertices are defined so far";
    // "trif -1 -2 -4": the -4 is at column 12.
    QTest::newRow("negative index beyond the first")
        << head + "trif -1 -2 -4\n"
        << "cmd.txt:5:12: 'trif' refers to vertex -4, but only 3 vertices are defined so far";
    QTest::newRow("one vertex so far")
        << QByteArray("png 4 4 a.png\nxyz 0 0 0\nbulb 2\n")
        << "cmd.txt:3:6: 'bulb' refers to vertex 2, but only 1 vertex is defined so far";
    QTest::newRow("index not a whole number")
        << head + "trif 1 2 3.0\n"
        << "cmd.txt:5:10: expected a vertex index in 'trif', found '3.0'";
    QTest::newRow("too few indices")
        << head + "trif 1 2\n"
        << "cmd.txt:5:9: expected 3 vertex indices in 'trif' (i1 i2 i3), found 2";
    QTest::newRow("rectbezf with three indices")
        << head + "rectbezf 2 1 2 3\n"
        << "cmd.txt:5:17: expected 16 vertex indices in 'rectbezf' (subd i1 ... i16), found 3";
    QTest::newRow("drawing before png")
        << QByteArray("xyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\n  trif 1 2 3\npng 4 4 a.png\n")
        << "cmd.txt:4:3: expected a 'png width height file' command before 'trif'";
    QTest::newRow("sunlight before png")
        << QByteArray("sunlight 1 0 0\n")
        << "cmd.txt:1:1: expected a 'png width height file' command before 'sunlight'";
    QTest::newRow("no png at all") << QByteArray("xyz 0 0 0\ncolor 1 1 1\n")
                                   << "cmd.txt:3:1: expected a 'png width height file' command, "
                                      "found none";
    QTest::newRow("trit without a texture")
        << head + "trit 1 2 3\n"
        << "cmd.txt:5:1: 'trit' needs a texture: expected a 'texture file.png' command before it";
    QTest::newRow("png width 0") << QByteArray("png 0 10 a.png\n")
                                 << "cmd.txt:1:5: expected the image width (a whole number from 1 "
                                    "to 65536), found '0'";
    QTest::newRow("png height 1.5") << QByteArray("png 10 1.5 a.png\n")
                                    << "cmd.txt:1:8: expected the image height (a whole number "
                                       "from 1 to 65536), found '1.5'";
    QTest::newRow("png width too large") << QByteArray("png 65537 2 a.png\n")
                                         << "cmd.txt:1:5: expected the image width (a whole "
                                            "number from 1 to 65536), found '65537'";
    QTest::newRow("png without a name")
        << QByteArray("png 10 10\n")
        << "cmd.txt:1:10: expected 'png width height file', found 2 "
           "arguments";
    // "rectbezf 0 ...": the 0 is at column 10.
    QTest::newRow("subdivisions 0")
        << head + "rectbezf 0 1 2 3 1 2 3 1 2 3 1 2 3 1 2 3 1\n"
        << "cmd.txt:5:10: expected the number of subdivisions (a whole number from 1 to 10) after "
           "'rectbezf', found '0'";
    QTest::newRow("subdivisions 11")
        << head + "tribezg 11 1 2 3 1 2 3 1 2 3 1\n"
        << "cmd.txt:5:9: expected the number of subdivisions (a whole number from 1 to 10) after "
           "'tribezg', found '11'";
    QTest::newRow("subdivisions missing")
        << head + "tribezf\n"
        << "cmd.txt:5:8: expected the number of subdivisions after 'tribezf', found the end of "
           "the line";
    QTest::newRow("frustum l == r")
        << QByteArray("png 4 4 a.png\n frustum 1 1 -1 1 1 10\n")
        << "cmd.txt:2:2: 'frustum' needs l != r, b != t and n != f, found 1 1 -1 1 1 10";
    QTest::newRow("ortho n == f")
        << QByteArray("png 4 4 a.png\northo -1 1 -1 1 0.5 0.5\n")
        << "cmd.txt:2:1: 'ortho' needs l != r, b != t and n != f, found -1 1 -1 1 0.5 0.5";
    // "rotate 30 0 0 0": the axis starts at column 11.
    QTest::newRow("rotate about the zero axis")
        << QByteArray("png 4 4 a.png\nrotate 30 0 0 0\n")
        << "cmd.txt:2:11: 'rotate' needs an axis, found the zero vector";
    QTest::newRow("sunlight from nowhere")
        << QByteArray("png 4 4 a.png\nsunlight 0 0 0\n")
        << "cmd.txt:2:10: 'sunlight' needs a direction, found the zero vector";
    QTest::newRow("lookat with eye == center")
        << head + "xyz 0 0 0\nlookat 1 4 0 1 0\n"
        << "cmd.txt:6:1: 'lookat' needs an eye apart from the center and an up that is not along "
           "the line of sight";
    QTest::newRow("lookat with up along the sight")
        << head + "lookat 1 2 -3 0 0\n"
        << "cmd.txt:5:1: 'lookat' needs an eye apart from the center and an up that is not along "
           "the line of sight";
    QTest::newRow("lookat without up")
        << head + "lookat 1 2 0 1\n"
        << "cmd.txt:5:15: expected 'lookat eye center upx upy upz', found 4 arguments";
    QTest::newRow("lookat with a letter in up")
        << head + "lookat 1 2 0 y 0\n"
        << "cmd.txt:5:14: expected a number in 'lookat' (eye center upx upy upz), found 'y'";
    QTest::newRow("texture without a name")
        << QByteArray("png 4 4 a.png\ntexture\n")
        << "cmd.txt:2:8: expected a file name after 'texture', found the end of the line";
    QTest::newRow("png name that is only folders")
        << QByteArray("png 4 4 out/..\n")
        << "cmd.txt:1:9: expected an image file name after 'png width height', found 'out/..'";
    // Five subdivision-10 patches: 10,485,760 triangles, over the limit of 2^23.
    QByteArray patches = head;
    for (int i = 0; i < 5; ++i) patches += "rectbezf 10 1 2 3 1 2 3 1 2 3 1 2 3 1 2 3 1\n";
    QTest::newRow("too many triangles")
        << patches
        << "cmd.txt:9:1: this command would bring the file to 10485760 triangles, more than "
           "the limit of 8388608 a command file may draw";
}

void TestHw2Reader::errors() {
    QFETCH(QByteArray, text);
    QFETCH(QString, message);
    Diagnostics diagnostics;
    auto file = read(text, diagnostics);
    QVERIFY2(!file, "the file was accepted");
    QCOMPARE(errorOf(file), message);
}

void TestHw2Reader::looksLikeHw2_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<bool>("hw2");
    QTest::newRow("command file") << QByteArray("png 120 120 a.png\nxyz 0 0 0\n") << true;
    QTest::newRow("blank lines, then xyz") << QByteArray("\n\n  xyz 1 2 3\n") << true;
    QTest::newRow("unknown keyword, then png")
        << QByteArray("hello there\npng 4 4 a.png\n") << true;
    QTest::newRow("course camera")
        << QByteArray("-200 -50 300\n0.667 0.172 -1\n0 3 0\n65 0.5 0.6\n") << false;
    QTest::newRow("course lighting")
        << QByteArray("-200 -50 300\n1\n2 2 2\n1\n1 1 1\n0.5\n0 255 0\n2\n") << false;
    QTest::newRow("byu object") << QByteArray("3 1\n50.0000 0.0000 0.000\n0 50 0\n0 0 50\n1 2 3\n")
                                << false;
    QTest::newRow("key = value camera")
        << QByteArray("C = 0 -500 500\nN = 0 1 -1\nV = 0 -1 -1\nd = 5\nhx = 2\nhy = 2\n") << false;
    QTest::newRow("key = value lighting")
        << QByteArray("Iamb = 100 100 100\nKa = 0.2\nIl = 127 213 254\n") << false;
    QTest::newRow("empty") << QByteArray() << false;
}

void TestHw2Reader::looksLikeHw2() {
    QFETCH(QByteArray, text);
    QFETCH(bool, hw2);
    QCOMPARE(rl::looksLikeHw2(std::string_view(text.constData(), std::size_t(text.size()))), hw2);
}

void TestHw2Reader::looksLikeHw2OnSamples() {
    const QString samples = testing::samplesDir();
    if (samples.isEmpty())
        QSKIP("the course samples are absent (set RASTERLAB_SAMPLES or RASTERLAB_SAMPLES_DIR)");
    int checked = 0;
    const auto check = [&](const QString& folder, const QStringList& patterns, bool expected) {
        QDirIterator it(samples + folder, patterns, QDir::Files, QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString path = it.next();
            const QByteArray text = testing::readFile(path);
            if (rl::looksLikeHw2(std::string_view(text.constData(), std::size_t(text.size()))) !=
                expected)
                return path;
            ++checked;
        }
        return QString();
    };
    QString wrong = check(QStringLiteral("/hw2"), {QStringLiteral("*.txt")}, true);
    QVERIFY2(wrong.isEmpty(),
             qPrintable(wrong + QStringLiteral(" is not taken for a command file")));
    const int commandFiles = checked;
    wrong = check(QStringLiteral("/course"),
                  {QStringLiteral("*.cfg"), QStringLiteral("*.byu"), QStringLiteral("*.lux"),
                   QStringLiteral("camera*.txt"), QStringLiteral("*iluminacao.txt")},
                  false);
    QVERIFY2(wrong.isEmpty(), qPrintable(wrong + QStringLiteral(" is taken for a command file")));
    if (commandFiles == 0 || checked == commandFiles) QSKIP("no sample files found to classify");
}

QTEST_GUILESS_MAIN(TestHw2Reader)
#include "tst_hw2_reader.moc"
