// Command files rendered through the whole pipeline: small files of our own, written to a
// scratch folder, with pixels worked out by hand (coverage under the top-left rule, colours
// truncated to bytes, the depth test, perspective-correct interpolation, clip planes, cull,
// textures, decals, the lighting of seed 001, Bezier patches); then the ten reference
// images of the course, compared pixel by pixel.
//
// Screen geometry used throughout: an 8x8 image maps NDC x = -1 + k/4 to pixel column k
// (and likewise y, -1 at the top); pixel (x, y) is sampled at the point (x, y).
#include <QtTest>

#include <QDir>
#include <QFile>
#include <QImage>
#include <QTemporaryDir>

#include <cmath>
#include <optional>

#include "app/documents/command_file.h"
#include "pipeline/render/output_image.h"
#include "pipeline/render/renderer.h"
#include "tests/test_support.h"

using namespace rl;

namespace {

struct Frame {
    QString problem;  // why the file could not be rendered
    Diagnostics diagnostics;
    std::shared_ptr<const Scene> scene;
    std::optional<FrameTrace> trace;
    Rgba8Image image;
};

struct Fixture {
    QString name;
    QImage image;
};

// Writes `text` as a command file (and `images` beside it) in a scratch folder, reads it
// with loadCommandFile and renders its one image.
Frame render(const QByteArray& text, const QList<Fixture>& images = {}) {
    Frame frame;
    QTemporaryDir dir;
    if (!dir.isValid()) {
        frame.problem = QStringLiteral("cannot make a scratch folder");
        return frame;
    }
    for (const Fixture& f : images) {
        if (!f.image.save(dir.filePath(f.name), "PNG")) {
            frame.problem = QStringLiteral("cannot write ") + f.name;
            return frame;
        }
    }
    const QString path = dir.filePath(QStringLiteral("scene.txt"));
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(text) != text.size()) {
        frame.problem = QStringLiteral("cannot write ") + path;
        return frame;
    }
    file.close();
    auto hw2 = rasterlab::loadCommandFile(path, frame.diagnostics);
    if (!hw2) {
        frame.problem = QString::fromStdString(hw2.error().toString());
        return frame;
    }
    if (hw2->images.size() != 1) {
        frame.problem = QStringLiteral("expected one image, found %1").arg(hw2->images.size());
        return frame;
    }
    frame.scene = std::make_shared<const Scene>(hw2->images[0].scene);
    auto trace = renderFrame(frame.scene);
    if (!trace) {
        frame.problem = QString::fromStdString(trace.error().toString());
        return frame;
    }
    frame.image = colourImage(*trace->shading, *trace->depth, frame.scene->conventions);
    frame.trace = std::move(trace).value();
    return frame;
}

#define RENDER(frame, ...)                   \
    const Frame frame = render(__VA_ARGS__); \
    QVERIFY2(frame.problem.isEmpty(), qPrintable(frame.problem))

QString rgba(const std::uint8_t* p) {
    return QStringLiteral("(%1, %2, %3, %4)").arg(p[0]).arg(p[1]).arg(p[2]).arg(p[3]);
}

// A pixel as "(r, g, b, a)".
QString pixel(const Frame& frame, int x, int y) {
    return rgba(frame.image.pixel(x, y));
}
QString pixel(const Frame& frame, const QPoint& p) {
    return pixel(frame, p.x(), p.y());
}

const QString kTransparent = QStringLiteral("(0, 0, 0, 0)");
const QString kWhite = QStringLiteral("(255, 255, 255, 255)");
const QString kRed = QStringLiteral("(255, 0, 0, 255)");
const QString kGreen = QStringLiteral("(0, 255, 0, 255)");
const QString kBlack = QStringLiteral("(0, 0, 0, 255)");

// How many pixels have the colour "(r, g, b, a)".
int count(const Frame& frame, const QString& colour) {
    int n = 0;
    for (int y = 0; y < frame.image.height; ++y)
        for (int x = 0; x < frame.image.width; ++x) n += pixel(frame, x, y) == colour ? 1 : 0;
    return n;
}

int covered(const Frame& frame) {
    return frame.image.width * frame.image.height - count(frame, kTransparent);
}

// A quad over the whole image at depth z, as two triangles, with the vertices given last.
QByteArray screenQuad(const QByteArray& z, const QByteArray& command = "trif") {
    return "xyz -1 -1 " + z + "\nxyz 1 -1 " + z + "\nxyz 1 1 " + z + "\nxyz -1 1 " + z + "\n" +
           command + " -4 -3 -2\n" + command + " -4 -2 -1\n";
}

// A texture of w x h texels, texel (i, j) = (40 + 50 i, 40 + 50 j, 200), opaque.
QImage gridTexture(int w, int h) {
    QImage image(w, h, QImage::Format_RGBA8888);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            image.setPixelColor(i, j, QColor(40 + 50 * i, 40 + 50 * j, 200));
    return image;
}
QString gridTexel(int i, int j) {
    return QStringLiteral("(%1, %2, 200, 255)").arg(40 + 50 * i).arg(40 + 50 * j);
}

// --- The reference samples ---

// The error of a failed result, or "" (QVERIFY2 evaluates its message even when it passes).
template <typename T>
QString errorText(const Result<T>& result) {
    return result ? QString() : QString::fromStdString(result.error().toString());
}

struct Comparison {
    int width = 0;
    int height = 0;
    int differing = 0;
    int largest = 0;        // the largest channel difference among the differing pixels
    int coverage = 0;       // differing pixels covered by one image only (alpha 0 and 255)
    int largestColour = 0;  // the largest channel difference where both images cover
    QList<QPoint> where;    // the differing pixels
    QImage reference;       // RGBA8888
};

Comparison compare(const Rgba8Image& ours, const QImage& referenceImage) {
    Comparison c;
    c.reference = referenceImage.convertToFormat(QImage::Format_RGBA8888);
    c.width = c.reference.width();
    c.height = c.reference.height();
    for (int y = 0; y < c.height; ++y) {
        const uchar* row = c.reference.constScanLine(y);
        for (int x = 0; x < c.width; ++x) {
            const std::uint8_t* a = ours.pixel(x, y);
            const uchar* b = row + 4 * x;
            int diff = 0;
            for (int k = 0; k < 4; ++k) diff = std::max(diff, std::abs(int(a[k]) - int(b[k])));
            if (diff == 0) continue;
            if (a[3] != b[3])
                ++c.coverage;
            else
                c.largestColour = std::max(c.largestColour, diff);
            ++c.differing;
            c.largest = std::max(c.largest, diff);
            c.where.append(QPoint(x, y));
        }
    }
    return c;
}

// The texture coordinates at a pixel as shading interpolates them: the winning fragment's
// screen barycentrics, weighted by 1/w of each vertex (perspective-correct).
std::optional<vec2> texcoordAt(const FrameTrace& trace, int x, int y) {
    const std::uint32_t t = trace.depth->triangle.at(x, y);
    if (t == kNoTriangle) return std::nullopt;
    const ScreenTriangle& tri = trace.projection->triangles[t];
    const DrawProjection& proj = trace.projection->draws[tri.draw];
    const Mesh& mesh = *trace.scene->draws[tri.draw].mesh;
    for (std::uint32_t v : tri.v)
        if (v >= mesh.texcoords.size()) return std::nullopt;  // made by clipping: not here
    const vec2 b = trace.depth->barycentric.at(x, y);
    const double weights[3] = {(1.0 - b.x - b.y) / proj.pClip[tri.v[0]].w,
                               b.x / proj.pClip[tri.v[1]].w, b.y / proj.pClip[tri.v[2]].w};
    const double sum = weights[0] + weights[1] + weights[2];
    dvec2 st(0.0);
    for (int k = 0; k < 3; ++k)
        st += weights[k] / sum * dvec2(mesh.texcoords[tri.v[std::size_t(k)]]);
    return vec2(st);
}

}  // namespace

class TestHw2Render : public QObject {
    Q_OBJECT

private slots:
    void coverage_data();
    void coverage();
    void sharedEdgesDrawnOnce();
    void flatColour_data();
    void flatColour();
    void gouraudColour_data();
    void gouraudColour();
    void depthTest_data();
    void depthTest();
    void depthRangeClipsPerPixel();
    void perspectiveCorrect();
    void xyzwDivide_data();
    void xyzwDivide();
    void clipPlane_data();
    void clipPlane();
    void clippedColoursUnchanged();
    void cull_data();
    void cull();
    void textureNearestTexel_data();
    void textureNearestTexel();
    void texelRules_data();
    void texelRules();
    void textureInterpolatedNegativeS();
    void decals_data();
    void decals();
    void lighting_data();
    void lighting();
    void flatNormals_data();
    void flatNormals();
    void flatNormalOfXyzwTriangle();
    void unlitBeforeTheFirstLight_data();
    void unlitBeforeTheFirstLight();
    void bezierCoverage_data();
    void bezierCoverage();
    void bezierColours();

    void guardBandKeepsEdgesStraight();
    void nearTheEyePlane();
    void acrossTheEyePlane();
    void tinyWGivesNoNaN();

    void viewportAsTheSeedWritesIt();
    void orthoGridLineRows();
    void referenceSamples_data();
    void referenceSamples();
    void referenceTexture();
};

void TestHw2Render::coverage_data() {
    QTest::addColumn<QByteArray>("vertices");  // three "x y" in NDC, at z = 0.5
    QTest::addColumn<int>("pixels");
    QTest::addColumn<QList<QPoint>>("inside");
    QTest::addColumn<QList<QPoint>>("outside");
    // Screen (0, 0), (8, 0), (0, 8): row y covers 0 <= x < 8 - y; the samples on the
    // hypotenuse x + y = 8 lie on a right edge and are left out: 8 + 7 + ... + 1 = 36.
    QTest::newRow("lower-left half")
        << QByteArray("-1 -1  1 -1  -1 1") << 36 << QList<QPoint>{{0, 0}, {7, 0}, {0, 7}, {3, 4}}
        << QList<QPoint>{{4, 4}, {7, 1}, {1, 7}, {7, 7}};
    // Screen (8, 0), (8, 8), (0, 8): the hypotenuse is its left edge, included; the right
    // column x = 8 and the bottom row y = 8 are off the image anyway: 0 + 1 + ... + 7 = 28.
    QTest::newRow("upper-right half")
        << QByteArray("1 -1  1 1  -1 1") << 28 << QList<QPoint>{{4, 4}, {7, 1}, {1, 7}, {7, 7}}
        << QList<QPoint>{{0, 0}, {3, 4}, {7, 0}, {0, 7}};
    // Screen (0.5, 0.5), (7.5, 0.5), (0.5, 7.5): samples at integer points, so column 0 and
    // row 0 are out although the triangle covers a quarter of pixel (0, 0); row y covers
    // 1 <= x < 8 - y: 6 + 5 + 4 + 3 + 2 + 1 = 21.
    QTest::newRow("half-pixel corners")
        << QByteArray("-0.875 -0.875  0.875 -0.875  -0.875 0.875") << 21
        << QList<QPoint>{{1, 1}, {6, 1}, {1, 6}}
        << QList<QPoint>{{0, 0}, {1, 0}, {0, 1}, {7, 1}, {6, 2}, {1, 7}};
    // Screen (0, 2), (8, 2), (0, 6): the top row 2 is in, the bottom vertex's row 6 out;
    // rows 2..5 cover 8, 6, 4, 2 pixels.
    QTest::newRow("top row in, bottom row out")
        << QByteArray("-1 -0.5  1 -0.5  -1 0.5") << 20 << QList<QPoint>{{0, 2}, {7, 2}, {1, 5}}
        << QList<QPoint>{{0, 1}, {0, 6}, {2, 5}};
    // A gargantuan triangle: efficient screen clipping fills just the 64 pixels.
    QTest::newRow("gargantuan") << QByteArray("-1e6 -1e6  3e6 -1e6  -1e6 3e6") << 64
                                << QList<QPoint>{{0, 0}, {7, 7}} << QList<QPoint>{};
    QTest::newRow("off screen") << QByteArray("2 2  3 2  2 3") << 0 << QList<QPoint>{}
                                << QList<QPoint>{{7, 7}};
}

void TestHw2Render::coverage() {
    QFETCH(QByteArray, vertices);
    QFETCH(int, pixels);
    QFETCH(QList<QPoint>, inside);
    QFETCH(QList<QPoint>, outside);
    const QList<QByteArray> v = vertices.simplified().split(' ');
    QCOMPARE(v.size(), 6);
    RENDER(frame, "png 8 8 t.png\nxyz " + v[0] + " " + v[1] + " 0.5\nxyz " + v[2] + " " + v[3] +
                      " 0.5\nxyz " + v[4] + " " + v[5] + " 0.5\ntrif 1 2 3\n");
    QCOMPARE(covered(frame), pixels);
    QCOMPARE(count(frame, kWhite), pixels);  // white when no colour was given
    QCOMPARE(int(frame.trace->depth->fragments), pixels);
    for (const QPoint& p : inside) QCOMPARE(pixel(frame, p), kWhite);
    for (const QPoint& p : outside) QCOMPARE(pixel(frame, p), kTransparent);
}

void TestHw2Render::sharedEdgesDrawnOnce() {
    // The two halves of the square: every pixel exactly once, the diagonal's samples going
    // to the triangle whose left edge it is.
    {
        RENDER(frame,
               "png 8 8 t.png\nxyz -1 -1 0.5\nxyz 1 -1 0.5\nxyz -1 1 0.5\nxyz 1 1 0.5\n"
               "color 1 0 0\ntrif 1 2 3\ncolor 0 1 0\ntrif 2 4 3\n");
        QCOMPARE(count(frame, kRed), 36);
        QCOMPARE(count(frame, kGreen), 28);
        QCOMPARE(int(frame.trace->depth->fragments), 64);
        QCOMPARE(pixel(frame, 4, 4), kGreen);
        QCOMPARE(pixel(frame, 3, 4), kRed);
    }
    // Four triangles around the centre (4, 4), a fan: still 64 fragments for 64 pixels.
    {
        RENDER(frame,
               "png 8 8 t.png\nxyz -1 -1 0.5\nxyz 1 -1 0.5\nxyz 1 1 0.5\nxyz -1 1 0.5\n"
               "xyz 0 0 0.5\ntrif 1 2 5\ntrif 2 3 5\ntrif 3 4 5\ntrif 4 1 5\n");
        QCOMPARE(covered(frame), 64);
        QCOMPARE(int(frame.trace->depth->fragments), 64);
    }
}

void TestHw2Render::flatColour_data() {
    QTest::addColumn<QByteArray>("colour");
    QTest::addColumn<QString>("expected");
    // Bytes are truncated: 0.5 * 255 = 127.5 -> 127, 0.25 * 255 = 63.75 -> 63.
    QTest::newRow("1 0.5 0.25") << QByteArray("1 0.5 0.25") << "(255, 127, 63, 255)";
    QTest::newRow("0.999 0.001 0.3") << QByteArray("0.999 0.001 0.3") << "(254, 0, 76, 255)";
    QTest::newRow("clamped") << QByteArray("2 -1 1.5") << "(255, 0, 255, 255)";
    QTest::newRow("no colour: white") << QByteArray() << "(255, 255, 255, 255)";
}

void TestHw2Render::flatColour() {
    // trif uses the colour current at the trif, not the vertices' colours.
    QFETCH(QByteArray, colour);
    QFETCH(QString, expected);
    RENDER(frame, "png 8 8 t.png\ncolor 0 0 1\nxyz -1 -1 0.5\nxyz 1 -1 0.5\nxyz -1 1 0.5\n" +
                      (colour.isEmpty() ? QByteArray("color 1 1 1") : "color " + colour) +
                      "\ntrif 1 2 3\n");
    QCOMPARE(pixel(frame, 0, 0), expected);
    QCOMPARE(pixel(frame, 2, 3), expected);
    QCOMPARE(count(frame, expected), 36);
}

void TestHw2Render::gouraudColour_data() {
    QTest::addColumn<QPoint>("at");
    QTest::addColumn<QString>("expected");
    // Red at (0, 0), green at (8, 0), blue at (0, 8): at pixel (x, y) the weights are
    // (1 - x/8 - y/8, x/8, y/8).
    QTest::newRow("red corner") << QPoint(0, 0) << "(255, 0, 0, 255)";
    // (0.25, 0.25, 0.5) -> 63.75, 63.75, 127.5.
    QTest::newRow("(2, 4)") << QPoint(2, 4) << "(63, 63, 127, 255)";
    // (0.25, 0.5, 0.25).
    QTest::newRow("(4, 2)") << QPoint(4, 2) << "(63, 127, 63, 255)";
    // (0.625, 0.125, 0.25) -> 159.375, 31.875, 63.75.
    QTest::newRow("(1, 2)") << QPoint(1, 2) << "(159, 31, 63, 255)";
}

void TestHw2Render::gouraudColour() {
    QFETCH(QPoint, at);
    QFETCH(QString, expected);
    RENDER(frame,
           "png 8 8 t.png\ncolor 1 0 0\nxyz -1 -1 0.5\ncolor 0 1 0\nxyz 1 -1 0.5\n"
           "color 0 0 1\nxyz -1 1 0.5\ncolor 1 1 1\ntrig 1 2 3\n");
    QCOMPARE(pixel(frame, at), expected);
}

void TestHw2Render::depthTest_data() {
    QTest::addColumn<QByteArray>("first");   // z of the red quad, drawn first
    QTest::addColumn<QByteArray>("second");  // z of the green quad, drawn second
    QTest::addColumn<QString>("expected");
    QTest::newRow("second nearer") << QByteArray("0.6") << QByteArray("0.3") << kGreen;
    QTest::newRow("first nearer") << QByteArray("0.3") << QByteArray("0.6") << kRed;
    QTest::newRow("tie: z <= stored, the later wins")
        << QByteArray("0.5") << QByteArray("0.5") << kGreen;
    QTest::newRow("z = 0 is drawn") << QByteArray("0.5") << QByteArray("0") << kGreen;
    QTest::newRow("z = 1 is drawn (the clear value)")
        << QByteArray("1") << QByteArray("1") << kGreen;
    QTest::newRow("z < 0 is discarded, however near")
        << QByteArray("0.5") << QByteArray("-0.25") << kRed;
    QTest::newRow("z > 1 is discarded") << QByteArray("1.25") << QByteArray("0.9") << kGreen;
    QTest::newRow("both outside [0, 1]") << QByteArray("-0.5") << QByteArray("1.5") << kTransparent;
}

void TestHw2Render::depthTest() {
    QFETCH(QByteArray, first);
    QFETCH(QByteArray, second);
    QFETCH(QString, expected);
    RENDER(frame, "png 8 8 t.png\ncolor 1 0 0\n" + screenQuad(first) + "color 0 1 0\n" +
                      screenQuad(second));
    QCOMPARE(count(frame, expected), 64);
}

void TestHw2Render::depthRangeClipsPerPixel() {
    // A quad whose z runs from -1 at the left edge to 1 at the right: at column x the depth
    // is x/4 - 1, at least 0 from column 4 on. Four columns of eight pixels survive.
    RENDER(frame,
           "png 8 8 t.png\nxyz -1 -1 -1\nxyz 1 -1 1\nxyz 1 1 1\nxyz -1 1 -1\n"
           "trif 1 2 3\ntrif 1 3 4\n");
    QCOMPARE(covered(frame), 32);
    for (int y = 0; y < 8; ++y) {
        QCOMPARE(pixel(frame, 3, y), kTransparent);
        QCOMPARE(pixel(frame, 4, y), kWhite);
    }
    QCOMPARE(int(frame.trace->depth->outsideDepthRange), 32);
    RL_COMPARE_NEAR(frame.trace->depth->depth.at(6, 3), 0.5, 1e-6);
}

void TestHw2Render::perspectiveCorrect() {
    // frustum -1 1 -1 1 1 10: x_ndc = x / -z, z_ndc = 11/9 + 20/(9 z). The eye-space vertices
    // A (-2, -2, -2), B (4, -4, -4), C (-2, 2, -2) land on the screen at (0, 0), (8, 0) and
    // (0, 8) with w = 2, 4, 2 and depths 1/9, 6/9, 1/9.
    // At pixel (2, 2) the screen weights are (0.5, 0.25, 0.25). Screen-affine, red A and C
    // with green B would give (0.75, 0.25, 0) -> (191, 63, 0). Perspective-correct, each
    // weight over its w: (0.25, 0.0625, 0.125) / 0.4375 = (4/7, 1/7, 2/7), so
    // (6/7, 1/7, 0) -> (218.57, 36.43, 0) -> (218, 36, 0).
    RENDER(frame,
           "png 8 8 t.png\nfrustum -1 1 -1 1 1 10\n"
           "color 1 0 0\nxyz -2 -2 -2\ncolor 0 1 0\nxyz 4 -4 -4\ncolor 1 0 0\nxyz -2 2 -2\n"
           "trig 1 2 3\n");
    QCOMPARE(covered(frame), 36);
    QCOMPARE(pixel(frame, 2, 2), QStringLiteral("(218, 36, 0, 255)"));
    QVERIFY(pixel(frame, 2, 2) != QStringLiteral("(191, 63, 0, 255)"));
    // Depth is NDC z, linear on the screen: 1/9 + 0.25 (6/9 - 1/9) = 1/4.
    RL_COMPARE_NEAR(frame.trace->depth->depth.at(2, 2), 0.25, 1e-6);
    // At the corners the colours are the vertices' own.
    QCOMPARE(pixel(frame, 0, 0), kRed);
}

void TestHw2Render::xyzwDivide_data() {
    QTest::addColumn<QByteArray>("b");  // the second vertex; (1, -1, 0.5) in NDC
    QTest::addColumn<QString>("at22");  // pixel (2, 2): red A and C, green B
    // With w = 1 everywhere the weights at (2, 2) are (0.5, 0.25, 0.25): (0.75, 0.25, 0).
    QTest::newRow("xyz") << QByteArray("xyz 1 -1 0.5") << "(191, 63, 0, 255)";
    // B with w = 2: the same point on the screen, but its weight is halved by the
    // perspective-correct interpolation: (0.5, 0.125, 0.25)/0.875 -> (6/7, 1/7, 0).
    QTest::newRow("xyzw, w = 2") << QByteArray("xyzw 2 -2 1 2") << "(218, 36, 0, 255)";
    // w = 0.25 quadruples it: (0.5, 1, 0.25)/1.75 -> (3/7, 4/7, 0) -> (109.29, 145.71, 0).
    QTest::newRow("xyzw, w = 0.25")
        << QByteArray("xyzw 0.25 -0.25 0.125 0.25") << "(109, 145, 0, 255)";
}

void TestHw2Render::xyzwDivide() {
    QFETCH(QByteArray, b);
    QFETCH(QString, at22);
    RENDER(frame, "png 8 8 t.png\ncolor 1 0 0\nxyz -1 -1 0.5\ncolor 0 1 0\n" + b +
                      "\ncolor 1 0 0\nxyz -1 1 0.5\ntrig 1 2 3\n");
    // Divided by w, B lands on the same pixel: the same 36 pixels are covered.
    QCOMPARE(covered(frame), 36);
    QCOMPARE(pixel(frame, 4, 4), kTransparent);
    QCOMPARE(pixel(frame, 0, 7), kRed);  // on the edge A C: B's weight is 0
    QCOMPARE(pixel(frame, 2, 2), at22);
}

void TestHw2Render::clipPlane_data() {
    QTest::addColumn<QByteArray>("commands");
    QTest::addColumn<int>("screenTriangles");
    QTest::addColumn<int>("pixels");
    QTest::addColumn<QList<QPoint>>("inside");
    QTest::addColumn<QList<QPoint>>("outside");
    // The triangle at screen (0, 0), (8, 0), (0, 8), 36 pixels, cut by eye x = 0 (column 4).
    // Kept x >= 0: the corner (4, 0), (8, 0), (4, 4), one triangle; column 4 is its left
    // edge: 4 + 3 + 2 + 1 = 10 pixels.
    QTest::newRow("keep x >= 0") << QByteArray("clipplane 1 0 0 0") << 1 << 10
                                 << QList<QPoint>{{4, 0}, {7, 0}, {4, 3}}
                                 << QList<QPoint>{{3, 0}, {4, 4}, {0, 0}};
    // Kept x <= 0: the quadrilateral (0, 0), (4, 0), (4, 4), (0, 8), two triangles; column 4
    // is its right edge: 4 rows of 4, then 4 + 3 + 2 + 1: 26 pixels. 26 + 10 = 36.
    QTest::newRow("keep x <= 0") << QByteArray("clipplane -1 0 0 0") << 2 << 26
                                 << QList<QPoint>{{0, 0}, {3, 0}, {3, 4}, {0, 7}}
                                 << QList<QPoint>{{4, 0}, {4, 3}, {7, 0}};
    // Kept y <= 0 (the top half): (0, 0), (8, 0), (4, 4), (0, 4): rows 0..3, 8 + 7 + 6 + 5.
    QTest::newRow("keep y <= 0") << QByteArray("clipplane 0 -1 0 0") << 2 << 26
                                 << QList<QPoint>{{0, 3}, {7, 0}, {4, 3}}
                                 << QList<QPoint>{{0, 4}, {3, 4}};
    QTest::newRow("wholly inside") << QByteArray("clipplane 1 0 0 2") << 1 << 36
                                   << QList<QPoint>{{0, 0}, {0, 7}} << QList<QPoint>{};
    QTest::newRow("wholly outside") << QByteArray("clipplane 1 0 0 -2") << 0 << 0 << QList<QPoint>{}
                                    << QList<QPoint>{{0, 0}, {4, 0}};
    QTest::newRow("two planes: x >= 0 and y <= 0")
        << QByteArray("clipplane 1 0 0 0\nclipplane 0 -1 0 0") << 1 << 10
        << QList<QPoint>{{4, 0}, {4, 3}} << QList<QPoint>{{3, 0}, {4, 4}};
    // The plane is in eye coordinates, as given: after translate 0.5 0 0 the triangle is at
    // (2, 0), (10, 0), (2, 8) and eye x >= 0 still means column 4 on: columns 4..7 cover
    // 6 + 5 + 4 + 3 = 18 pixels (a plane carried through the model/view would start at
    // column 6 and cover 7).
    QTest::newRow("eye space, after a translation")
        << QByteArray("translate 0.5 0 0\nclipplane 1 0 0 0") << 1 << 18
        << QList<QPoint>{{4, 0}, {4, 5}, {5, 4}, {7, 2}} << QList<QPoint>{{3, 0}, {4, 6}};
}

void TestHw2Render::clipPlane() {
    QFETCH(QByteArray, commands);
    QFETCH(int, screenTriangles);
    QFETCH(int, pixels);
    QFETCH(QList<QPoint>, inside);
    QFETCH(QList<QPoint>, outside);
    RENDER(frame, "png 8 8 t.png\n" + commands +
                      "\nxyz -1 -1 0.5\nxyz 1 -1 0.5\nxyz -1 1 0.5\ntrif 1 2 3\n");
    QCOMPARE(int(frame.trace->projection->triangles.size()), screenTriangles);
    QCOMPARE(covered(frame), pixels);
    QCOMPARE(int(frame.trace->depth->fragments), pixels);  // the pieces do not overlap
    for (const QPoint& p : inside) QCOMPARE(pixel(frame, p), kWhite);
    for (const QPoint& p : outside) QCOMPARE(pixel(frame, p), kTransparent);
}

void TestHw2Render::clippedColoursUnchanged() {
    // Clipping makes new vertices with colours interpolated along the cut edges: the part
    // left shows the colours the whole triangle has there (red, green, blue corners).
    const QByteArray triangle =
        "color 1 0 0\nxyz -1 -1 0.5\ncolor 0 1 0\nxyz 1 -1 0.5\ncolor 0 0 1\nxyz -1 1 0.5\n"
        "trig 1 2 3\n";
    RENDER(whole, "png 8 8 t.png\n" + triangle);
    RENDER(clipped, "png 8 8 t.png\nclipplane 1 -1 0 0\n" + triangle);
    int compared = 0;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            if (pixel(clipped, x, y) == kTransparent) continue;
            QCOMPARE(pixel(clipped, x, y), pixel(whole, x, y));
            ++compared;
        }
    // Kept x >= y: rows 0..3 from column y to 7 - y: 8 + 6 + 4 + 2.
    QCOMPARE(compared, 20);
    QCOMPARE(pixel(clipped, 4, 2), QStringLiteral("(63, 127, 63, 255)"));
}

void TestHw2Render::cull_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<int>("red");
    QTest::addColumn<int>("green");
    QTest::addColumn<int>("culled");
    // Red: screen (0, 0), (0, 8), (8, 0): down, then up to the right: counter-clockwise as
    // it appears on the screen. Green: (8, 0), (8, 8), (0, 8): down, then left: clockwise.
    const QByteArray vertices =
        "png 8 8 t.png\nxyz -1 -1 0.5\nxyz -1 1 0.5\nxyz 1 -1 0.5\nxyz 1 1 0.5\n";
    const QByteArray red = "color 1 0 0\ntrif 1 2 3\n";
    const QByteArray green = "color 0 1 0\ntrif 3 4 2\n";
    QTest::newRow("no cull: both") << vertices + red + green << 36 << 28 << 0;
    QTest::newRow("cull: the clockwise one dropped")
        << vertices + "cull\n" + red + green << 36 << 0 << 1;
    QTest::newRow("cull after the triangles: nothing dropped") << vertices + red + green + "cull\n"
                                                               << 36 << 28 << 0;
    QTest::newRow("cull, windings reversed")
        << vertices + "cull\ncolor 1 0 0\ntrif 1 3 2\ncolor 0 1 0\ntrif 3 2 4\n"
        << 0 << 28 << 1;
}

void TestHw2Render::cull() {
    QFETCH(QByteArray, text);
    QFETCH(int, red);
    QFETCH(int, green);
    QFETCH(int, culled);
    RENDER(frame, text);
    QCOMPARE(count(frame, kRed), red);
    QCOMPARE(count(frame, kGreen), green);
    QCOMPARE(int(frame.trace->projection->culled), culled);
}

void TestHw2Render::textureNearestTexel_data() {
    QTest::addColumn<QByteArray>("st");  // the same at all three vertices
    QTest::addColumn<int>("i");          // the texel expected, of a 4x4 texture
    QTest::addColumn<int>("j");
    // The hw2 rules pick the texel the reference images do, (int)(4s + 0.5) mod 4 with (int)
    // toward zero; the seed's text (the texel nearest to 4s once s wraps) agrees wherever
    // 4s + 0.5 >= 0, and the rows marked "images" are where it does not (texelRules).
    QTest::newRow("0 0") << QByteArray("0 0") << 0 << 0;
    QTest::newRow("0.3 0.55: (1.7, 2.7)") << QByteArray("0.3 0.55") << 1 << 2;
    QTest::newRow("0.7: 3.3 -> 3") << QByteArray("0.7 0") << 3 << 0;
    QTest::newRow("1.7: 7.3 -> 7 mod 4") << QByteArray("1.7 0") << 3 << 0;
    QTest::newRow("0.9: 4.1 -> 4 mod 4") << QByteArray("0.9 0") << 0 << 0;
    QTest::newRow("-0.1: 0.1 -> 0") << QByteArray("-0.1 0") << 0 << 0;
    QTest::newRow("images: -0.3, -0.7 -> 0") << QByteArray("-0.3 0") << 0 << 0;
    QTest::newRow("images: -0.2, -0.3 -> 0") << QByteArray("-0.2 0") << 0 << 0;
    QTest::newRow("images: -1.3, -4.7 -> -4 mod 4") << QByteArray("-1.3 0") << 0 << 0;
    QTest::newRow("images: t = -0.75, -2.5 -> -2 mod 4") << QByteArray("0 -0.75") << 0 << 2;
    QTest::newRow("t = 0.6: 2.9 -> 2, row 0 on top") << QByteArray("0.26 0.6") << 1 << 2;
}

void TestHw2Render::texelRules_data() {
    QTest::addColumn<float>("s");
    QTest::addColumn<int>("nearest");    // seed 001's text: wrap, then the nearest of 4s
    QTest::addColumn<int>("truncated");  // the reference images: (int)(4s + 0.5) mod 4
    QTest::newRow("0.3") << 0.3f << 1 << 1;
    QTest::newRow("0.9") << 0.9f << 0 << 0;
    QTest::newRow("1.7") << 1.7f << 3 << 3;
    QTest::newRow("-0.1: 0.1 either way") << -0.1f << 0 << 0;
    QTest::newRow("-0.2: 0.8 wrapped, 3.2") << -0.2f << 3 << 0;
    QTest::newRow("-0.3: 0.7 wrapped, 2.8") << -0.3f << 3 << 0;
    QTest::newRow("-0.6: 0.4 wrapped, 1.6") << -0.6f << 2 << 3;
    QTest::newRow("-1.3: 0.7 wrapped, 2.8") << -1.3f << 3 << 0;
    QTest::newRow("-2: 0 wrapped, -7.5 -> -7 mod 4") << -2.0f << 0 << 1;
}

void TestHw2Render::texelRules() {
    QFETCH(float, s);
    QFETCH(int, nearest);
    QFETCH(int, truncated);
    Texture texture;
    texture.width = 4;
    texture.height = 4;
    texture.texels.assign(16, vec4(0.0f));
    using R = RasterRules::TexelRounding;
    QCOMPARE(texelIndex(texture, vec2(s, 0.0f), R::Nearest), ivec2(nearest, 0));
    QCOMPARE(texelIndex(texture, vec2(s, 0.0f), R::Truncate), ivec2(truncated, 0));
    // t picks the row the same way.
    QCOMPARE(texelIndex(texture, vec2(0.0f, s), R::Nearest), ivec2(0, nearest));
    QCOMPARE(texelIndex(texture, vec2(0.0f, s), R::Truncate), ivec2(0, truncated));
    QCOMPARE(RasterRules::hw2().texel, R::Truncate);
    QCOMPARE(RasterRules::gpu().texel, R::Nearest);
    QCOMPARE(RasterRules::course().texel, R::Nearest);
}

void TestHw2Render::textureNearestTexel() {
    QFETCH(QByteArray, st);
    QFETCH(int, i);
    QFETCH(int, j);
    RENDER(frame,
           "png 8 8 t.png\ntexture grid.png\ntexcoord " + st +
               "\nxyz -1 -1 0.5\nxyz 1 -1 0.5\nxyz -1 1 0.5\ncolor 1 0 1\ntrit 1 2 3\n",
           {{QStringLiteral("grid.png"), gridTexture(4, 4)}});
    QCOMPARE(pixel(frame, 2, 2), gridTexel(i, j));
    QCOMPARE(count(frame, gridTexel(i, j)), 36);
}

void TestHw2Render::textureInterpolatedNegativeS() {
    // s runs from -1 at screen x = 0 to 0 at x = 8 (t = 0), on a 3x1 texture: at column x,
    // s = x/8 - 1 and 3s + 0.5 = 3x/8 - 2.5 is truncated toward zero, mod 3 (the reference
    // images' rule): columns 0..7 give -2.5, -2.125, -1.75, -1.375, (-1), -0.625, -0.25,
    // 0.125 -> -2, -2, -1, -1, (-1), 0, 0, 0 -> texels 1, 1, 2, 2, (2), 0, 0, 0. Column 4
    // sits exactly on -1 and is not checked. (Seed 001's text, wrapping s first, would give
    // 0, 0, 1, 1, (2), 2, 2, 0.)
    RENDER(frame,
           "png 8 8 t.png\ntexture grid.png\ntexcoord -1 0\nxyz -1 -1 0.5\ntexcoord 0 0\n"
           "xyz 1 -1 0.5\ntexcoord -1 0\nxyz -1 1 0.5\ntrit 1 2 3\n",
           {{QStringLiteral("grid.png"), gridTexture(3, 1)}});
    const int texels[8] = {1, 1, 2, 2, -1, 0, 0, 0};
    for (int x = 0; x < 8; ++x) {
        if (texels[x] < 0) continue;
        QVERIFY2(pixel(frame, x, 0) == gridTexel(texels[x], 0),
                 qPrintable(QStringLiteral("column %1: %2, expected %3")
                                .arg(x)
                                .arg(pixel(frame, x, 0), gridTexel(texels[x], 0))));
    }
    // Perspective-correct texture coordinates: w = 2 at the second vertex (as xyzw) moves
    // column 2 (weights 0.75, 0.25 on the top edge) to s = -1 + (0.25/2)/(0.75 + 0.125) =
    // -6/7: 3s + 0.5 = -2.07 -> -2 -> texel 1 instead of 2.
    RENDER(weighted,
           "png 8 8 t.png\ntexture grid.png\ntexcoord -1 0\nxyz -1 -1 0.5\ntexcoord 0 0\n"
           "xyzw 2 -2 1 2\ntexcoord -1 0\nxyz -1 1 0.5\ntrit 1 2 3\n",
           {{QStringLiteral("grid.png"), gridTexture(3, 1)}});
    QCOMPARE(pixel(weighted, 2, 0), gridTexel(1, 0));
}

void TestHw2Render::decals_data() {
    QTest::addColumn<bool>("decals");
    QTest::addColumn<QByteArray>("s");
    QTest::addColumn<QString>("expected");
    // Texels: (200, 0, 0) with alpha 128, (0, 0, 255) with alpha 0, (10, 20, 30) opaque.
    // The object colour (trig-style, from the vertices) is (0, 0.7, 0.5).
    // Decals: object (1 - a) + texel a, a = 128/255: (0.7843 a, 0.7 (1 - a), 0.5 (1 - a)) =
    // (0.3937, 0.3486, 0.2490) -> (100.39, 88.90, 63.50) -> (100, 88, 63).
    QTest::newRow("decals, half transparent") << true << QByteArray("0") << "(100, 88, 63, 255)";
    QTest::newRow("decals, transparent: the object")
        << true << QByteArray("0.34") << "(0, 178, 127, 255)";
    QTest::newRow("decals, opaque: the texel") << true << QByteArray("0.67") << "(10, 20, 30, 255)";
    // Without decals the texel's RGB, its alpha ignored.
    QTest::newRow("no decals, half transparent") << false << QByteArray("0") << "(200, 0, 0, 255)";
    QTest::newRow("no decals, transparent") << false << QByteArray("0.34") << "(0, 0, 255, 255)";
}

void TestHw2Render::decals() {
    QFETCH(bool, decals);
    QFETCH(QByteArray, s);
    QFETCH(QString, expected);
    QImage texture(3, 1, QImage::Format_RGBA8888);
    texture.setPixelColor(0, 0, QColor(200, 0, 0, 128));
    texture.setPixelColor(1, 0, QColor(0, 0, 255, 0));
    texture.setPixelColor(2, 0, QColor(10, 20, 30, 255));
    RENDER(frame,
           "png 8 8 t.png\ntexture decal.png\ncolor 0 0.7 0.5\ntexcoord " + s +
               " 0\nxyz -1 -1 0.5\nxyz 1 -1 0.5\nxyz -1 1 0.5\ncolor 1 1 1\ntrit 1 2 3\n" +
               (decals ? "decals\n" : ""),
           {{QStringLiteral("decal.png"), texture}});
    QCOMPARE(pixel(frame, 2, 2), expected);
    QCOMPARE(count(frame, expected), 36);
}

void TestHw2Render::lighting_data() {
    QTest::addColumn<QByteArray>("lights");
    QTest::addColumn<QByteArray>("object");  // the object's colour
    QTest::addColumn<QPoint>("at");
    QTest::addColumn<QString>("expected");
    // A quad over the image at z = 0.5 with the normal (0, 0, -1), toward the eye at the
    // origin; pixel (x, y) is the eye-space point (x/4 - 1, y/4 - 1, 0.5).
    // sunlight 0 3 -4 is stored as (0, 0.6, -0.8): N.L = 0.8.
    const QByteArray sun = "color 1 1 1\nsunlight 0 3 -4\n";
    // (0.3, 0.6, 0.9) 0.8 = (0.24, 0.48, 0.72) -> (61.2, 122.4, 183.6).
    QTest::newRow("sunlight, Lambert")
        << sun << QByteArray("0.3 0.6 0.9") << QPoint(1, 6) << "(61, 122, 183, 255)";
    // The light's colour multiplies: (0.3, 0.6 * 0.5, 0.9 * 0.25) -> (76.5, 76.5, 57.4).
    QTest::newRow("coloured sunlight")
        << QByteArray("color 1 0.5 0.25\nsunlight 0 0 -1\n") << QByteArray("0.3 0.6 0.9")
        << QPoint(6, 1) << "(76, 76, 57, 255)";
    // Two lights summed: 0.8 (1 + 0.5) = 1.2 times the object: (0.36, 0.72, 1.08).
    QTest::newRow("two lights summed")
        << sun + "color 0.5 0.5 0.5\nsunlight 0 -3 -4\n"
        << QByteArray("0.3 0.6 0.9") << QPoint(3, 3) << "(91, 183, 255, 255)";
    // A darkness light: 0.8 (1 - 0.5) = 0.4 times the object: (0.12, 0.24, 0.36).
    QTest::newRow("darkness light")
        << sun + "color -0.5 -0.5 -0.5\nsunlight 0 -3 -4\n"
        << QByteArray("0.3 0.6 0.9") << QPoint(3, 3) << "(30, 61, 91, 255)";
    // Lights are summed before clamping: 0.8 (2 - 1.5) = 0.4 again (clamping the bright
    // light to 1 first would give 0.8 (1 - 1.5) < 0, black).
    QTest::newRow("bright light, clamped only at the end")
        << QByteArray("color 2 2 2\nsunlight 0 3 -4\ncolor -1.5 -1.5 -1.5\nsunlight 0 -3 -4\n")
        << QByteArray("0.3 0.6 0.9") << QPoint(3, 3) << "(30, 61, 91, 255)";
    // 1.6 times the object: (0.48, 0.96, 1.44).
    QTest::newRow("bright light alone")
        << QByteArray("color 2 2 2\nsunlight 0 3 -4\n") << QByteArray("0.3 0.6 0.9") << QPoint(3, 3)
        << "(122, 244, 255, 255)";
    // A light behind the surface (N.L < 0) is left out, darkness or not.
    QTest::newRow("light behind left out")
        << sun + "color -1 -1 -1\nsunlight 0 0 1\n"
        << QByteArray("0.3 0.6 0.9") << QPoint(3, 3) << "(61, 122, 183, 255)";
    QTest::newRow("only a light behind") << QByteArray("color 1 1 1\nsunlight 0 0 1\n")
                                         << QByteArray("0.3 0.6 0.9") << QPoint(3, 3) << kBlack;
    // A bulb at the eye: at pixel (4, 4), the point (0, 0, 0.5), N.L = 1:
    // (0.3, 0.7, 0.9) -> (76.5, 178.5, 229.5).
    const QByteArray bulb = "color 1 1 1\nxyz 0 0 0\nbulb -1\n";
    QTest::newRow("bulb, straight ahead")
        << bulb << QByteArray("0.3 0.7 0.9") << QPoint(4, 4) << "(76, 178, 229, 255)";
    // At pixel (2, 4), the point (-0.5, 0, 0.5): L = (0.5, 0, -0.5)/0.7071, N.L = 0.7071:
    // (0.2121, 0.4950, 0.6364) -> (54.09, 126.22, 162.28).
    QTest::newRow("bulb, at an angle")
        << bulb << QByteArray("0.3 0.7 0.9") << QPoint(2, 4) << "(54, 126, 162, 255)";
    // The bulb's vertex goes through the model/view: xyz 0 0 -0.5 translated by (0, 0, 0.5)
    // is the eye again.
    QTest::newRow("bulb through the model/view")
        << QByteArray(
               "color 1 1 1\nxyz 0 0 -0.5\ntranslate 0 0 0.5\nbulb -1\nloadmv 1 0 0 0 0 1 "
               "0 0 0 0 1 0 0 0 0 1\n")
        << QByteArray("0.3 0.7 0.9") << QPoint(2, 4) << "(54, 126, 162, 255)";
    // Blinn-Phong with shininess 4 at pixel (4, 4), the point (0, 0, 0.5): the eye
    // direction is E = (0, 0, -1), H = (L + E)/|L + E| = (0, 0.6, -1.8)/sqrt(3.6), H.N =
    // 0.9487, (H.N)^4 = 0.81, added white, untinted: (0.08, 0.16, 0.04) + 0.81 =
    // (0.89, 0.97, 0.85) -> (226.95, 247.35, 216.75). (Phong's (R.V)^4 would be 0.8^4.)
    const QByteArray shiny = sun + "shininess 4\n";
    QTest::newRow("shininess, Blinn-Phong")
        << shiny << QByteArray("0.1 0.2 0.05") << QPoint(4, 4) << "(226, 247, 216, 255)";
    // At pixel (4, 0), the point (0, -1, 0.5): E = (0, 2, -1)/sqrt5, H = (0, 0.7678,
    // -0.6407), (H.N)^4 = 0.1686: (0.2486, 0.3286, 0.2086) -> (63.4, 83.8, 53.2).
    QTest::newRow("shininess, eye direction from the point")
        << shiny << QByteArray("0.1 0.2 0.05") << QPoint(4, 0) << "(63, 83, 53, 255)";
    QTest::newRow("shininess of a black object")
        << shiny << QByteArray("0 0 0") << QPoint(4, 4) << "(206, 206, 206, 255)";
    // (0.08, 0.16, 0.04) -> (20.4, 40.8, 10.2).
    QTest::newRow("shininess 0: no highlight")
        << sun + "shininess 0\n"
        << QByteArray("0.1 0.2 0.05") << QPoint(4, 4) << "(20, 40, 10, 255)";
    QTest::newRow("negative shininess: no highlight")
        << sun + "shininess -2\n"
        << QByteArray("0.1 0.2 0.05") << QPoint(4, 4) << "(20, 40, 10, 255)";
    QTest::newRow("no highlight from behind")
        << QByteArray("color 1 1 1\nsunlight 0 0 1\nshininess 4\n") << QByteArray("0.1 0.2 0.05")
        << QPoint(4, 4) << kBlack;
}

void TestHw2Render::lighting() {
    QFETCH(QByteArray, lights);
    QFETCH(QByteArray, object);
    QFETCH(QPoint, at);
    QFETCH(QString, expected);
    RENDER(frame, "png 8 8 lit.png\n" + lights + "color " + object + "\nnormal 0 0 -1\n" +
                      screenQuad("0.5"));
    QCOMPARE(pixel(frame, at), expected);
    QCOMPARE(covered(frame), 64);
}

void TestHw2Render::flatNormals_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("expected");
    // The triangle A (-1, -1), B (-1, 1), C (1, -1) at z = 0.5 has (B - A) x (C - A) =
    // (0, 2, 0) x (2, 0, 0) = (0, 0, -4): toward the eye. Its vertices' normal (0, 0, 1)
    // points away. Lit by sunlight 0 3 -4 (N.L = 0.8 when N faces the eye).
    const QByteArray head =
        "png 8 8 t.png\ncolor 1 1 1\nsunlight 0 3 -4\ncolor 0.3 0.6 0.9\nnormal 0 0 1\n"
        "xyz -1 -1 0.5\nxyz -1 1 0.5\nxyz 1 -1 0.5\n";
    QTest::newRow("vertex normals, facing away") << head + "trif 1 2 3\n" << kBlack;
    QTest::newRow("flatnormals: the triangle's own") << head + "trif 1 2 3\nflatnormals\n"
                                                     << "(61, 122, 183, 255)";
    QTest::newRow("flatnormals, wound the other way: facing away")
        << head + "trif 1 3 2\nflatnormals\n"
        << kBlack;
    QTest::newRow("flatnormals leave trig alone") << head + "trig 1 2 3\nflatnormals\n" << kBlack;
    QTest::newRow("no normals: the triangle's own")
        << QByteArray(
               "png 8 8 t.png\ncolor 1 1 1\nsunlight 0 3 -4\ncolor 0.3 0.6 0.9\n"
               "xyz -1 -1 0.5\nxyz -1 1 0.5\nxyz 1 -1 0.5\ntrif 1 2 3\n")
        << "(61, 122, 183, 255)";
}

void TestHw2Render::unlitBeforeTheFirstLight_data() {
    QTest::addColumn<QByteArray>("command");
    QTest::newRow("trif") << QByteArray("trif");
    QTest::newRow("trig") << QByteArray("trig");
}

void TestHw2Render::unlitBeforeTheFirstLight() {
    // Geometry given before the file's first light is drawn unlit, in its colour, although
    // the scene is lit (it used to index the vertex normals such a draw is not given and
    // crash), and so is it with the normals kept and with a pixel's events recorded.
    QFETCH(QByteArray, command);
    RENDER(frame,
           "png 8 8 u.png\ncolor 1 0.5 0.5\n" + screenQuad("0.5", command) + "sunlight 0 0 -1\n");
    QCOMPARE(frame.scene->draws[0].lighting, LightingModel::Unlit);
    QVERIFY(frame.scene->lit());
    QCOMPARE(pixel(frame, 3, 4), QStringLiteral("(255, 127, 127, 255)"));
    QCOMPARE(count(frame, QStringLiteral("(255, 127, 127, 255)")), 64);
    RenderOptions options;
    options.shading.keepNormals = true;
    auto withNormals = renderFrame(frame.scene, options);
    QVERIFY(withNormals.ok());
    QVERIFY(withNormals->shading->colour == frame.trace->shading->colour);
    QCOMPARE(withNormals->shading->normal.at(3, 4), vec3(0.0f));
    auto probe = RecordingProbe::forPixel(3, 4);
    auto traced = traceFrame(frame.scene, RenderOptions{}, probe);
    QVERIFY(traced.ok());
    QVERIFY(traced->shading->colour == frame.trace->shading->colour);
}

void TestHw2Render::flatNormalOfXyzwTriangle() {
    // The same triangle with B given as xyzw -2 2 1 2, i.e. (-1, 1, 0.5) once divided by w:
    // its normal is that of the points, (0, 0, -1), N.L = 0.8 -> (61, 122, 183). Taking the
    // cross product of the undivided coordinates would give (0, 1, -6)/sqrt37 instead, N.L =
    // 0.888 -> (67, 135, 203).
    RENDER(frame,
           "png 8 8 t.png\ncolor 1 1 1\nsunlight 0 3 -4\ncolor 0.3 0.6 0.9\n"
           "xyz -1 -1 0.5\nxyzw -2 2 1 2\nxyz 1 -1 0.5\ntrif 1 2 3\n");
    QCOMPARE(covered(frame), 36);
    QCOMPARE(pixel(frame, 2, 2), QStringLiteral("(61, 122, 183, 255)"));
}

void TestHw2Render::flatNormals() {
    QFETCH(QByteArray, text);
    QFETCH(QString, expected);
    RENDER(frame, text);
    QCOMPARE(pixel(frame, 2, 2), expected);
    QCOMPARE(count(frame, expected), 36);
}

void TestHw2Render::bezierCoverage_data() {
    QTest::addColumn<QByteArray>("command");
    QTest::addColumn<int>("triangles");
    QTest::addColumn<int>("pixels");
    // A flat, regular control grid over NDC [-0.75, 0.75]^2: the square of screen
    // [2, 14]^2 on a 16x16 image, 12 x 12 = 144 pixels, each once.
    const QByteArray all = " 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16";
    QTest::newRow("rectbezf 1") << "rectbezf 1" + all << 8 << 144;
    QTest::newRow("rectbezf 3") << "rectbezf 3" + all << 128 << 144;
    QTest::newRow("rectbezg 2") << "rectbezg 2" + all << 32 << 144;
    // The triangular net of the grid's points (0..3, 0), (0..2, 1), (0..1, 2), (0, 3): the
    // triangle (2, 2), (14, 2), (2, 14); row y covers 2 <= x < 16 - y: 12 + 11 + ... + 1.
    QTest::newRow("tribezf 2") << QByteArray("tribezf 2 1 2 3 4 5 6 7 9 10 13") << 16 << 78;
    QTest::newRow("tribezg 1") << QByteArray("tribezg 1 1 2 3 4 5 6 7 9 10 13") << 4 << 78;
}

void TestHw2Render::bezierCoverage() {
    QFETCH(QByteArray, command);
    QFETCH(int, triangles);
    QFETCH(int, pixels);
    QByteArray text = "png 16 16 bez.png\ncolor 0.5 0.25 1\n";
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i)
            text += "xyz " + QByteArray::number(-0.75 + 0.5 * i) + " " +
                    QByteArray::number(-0.75 + 0.5 * j) + " 0.5\n";
    RENDER(frame, text + command + "\n");
    QCOMPARE(int(frame.scene->triangleCount()), triangles);
    QCOMPARE(covered(frame), pixels);
    QCOMPARE(int(frame.trace->depth->fragments), pixels);
    QCOMPARE(pixel(frame, 2, 2), QStringLiteral("(127, 63, 255, 255)"));
    QCOMPARE(pixel(frame, 1, 2), kTransparent);
    QCOMPARE(pixel(frame, 2, 1), kTransparent);
    if (command.startsWith("rect")) {
        QCOMPARE(pixel(frame, 13, 13), QStringLiteral("(127, 63, 255, 255)"));
        QCOMPARE(pixel(frame, 14, 13), kTransparent);
        QCOMPARE(pixel(frame, 13, 14), kTransparent);
    } else {
        QCOMPARE(pixel(frame, 2, 13), QStringLiteral("(127, 63, 255, 255)"));
        QCOMPARE(pixel(frame, 8, 8), kTransparent);  // on the hypotenuse, a right edge
    }
}

void TestHw2Render::bezierColours() {
    // rectbezg: control points coloured by column, red = i/3; Bernstein polynomials keep
    // a linear function linear, so on the screen red = s = (x - 2)/12: 0.25 at column 5,
    // 0.75 at column 11 -> 63.75, 191.25. rectbezf uses the current colour instead.
    QByteArray text = "png 16 16 bez.png\n";
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i)
            text += "color " + QByteArray::number(i / 3.0, 'g', 17) + " 0 1\nxyz " +
                    QByteArray::number(-0.75 + 0.5 * i) + " " +
                    QByteArray::number(-0.75 + 0.5 * j) + " 0.5\n";
    text += "color 0 1 0\n";
    {
        RENDER(frame, text + "rectbezg 2 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16\n");
        QCOMPARE(pixel(frame, 5, 8), QStringLiteral("(63, 0, 255, 255)"));
        QCOMPARE(pixel(frame, 11, 3), QStringLiteral("(191, 0, 255, 255)"));
        QCOMPARE(pixel(frame, 2, 13), QStringLiteral("(0, 0, 255, 255)"));
    }
    {
        RENDER(frame, text + "rectbezf 2 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16\n");
        QCOMPARE(count(frame, kGreen), 144);
    }
}

void TestHw2Render::viewportAsTheSeedWritesIt() {
    // Seed 001's viewport, y = y_ndc H/2 + H/2: y_ndc = -0.7 on 120 rows gives -42 + 60 = 18
    // exactly, where (y_ndc + 1) H/2 gives 0.30000000000000004 * 60 = 18.000000000000004. The
    // triangle's flat top then lies on row 18, and the DDA starts there (ceil(18) = 18).
    RENDER(frame,
           "png 120 120 top.png\nxyz -0.5 -0.7 0\nxyz 0.5 -0.7 0\nxyz 0 0.5 0\n"
           "trif 1 2 3\n");
    QVERIFY((-0.7 + 1.0) * 120.0 / 2.0 > 18.0);  // the other formula's y
    const dvec2 top = frame.trace->projection->draws.at(0).pScreen.at(0);
    QCOMPARE(top.y, 18.0);
    QCOMPARE(top.x, 30.0);
    int onRow18 = 0;
    for (int x = 0; x < 120; ++x) onRow18 += pixel(frame, x, 18) == kWhite ? 1 : 0;
    QCOMPARE(onRow18, 60);  // 30 <= x < 90
    QCOMPARE(pixel(frame, 60, 17), kTransparent);
}

void TestHw2Render::orthoGridLineRows() {
    // The ortho checkerboard of the held-out check: a 7x8 grid of unit squares, (i, j) drawn
    // when i + j is even, tilted by the model-view and mirrored by l > r. Its grid lines j =
    // -1 and j = 0 are horizontal on the screen and lie, in exact arithmetic, on rows 16 and
    // 64; in double they land a hair below them (y = 16.000000000000036 and
    // 64.00000000000001). The DDA (seed 001: rows ceil(y_top) <= y < y_bottom, in double)
    // gives both rows to the squares above the line; the exact walk on snapped vertices gave
    // them to the squares below.
    QByteArray text =
        "png 120 120 ortho.png\ncolor 0 0.5 0\n"
        "loadmv 1 0.1 0 0  0 0.6 0.8 -1.2  0 0.8 -0.6 4.5  0 0 0 1\n"
        "ortho 2 -2.5 -2 -0.5 -5.5 -2.5\n";
    for (int j = -4; j <= 3; ++j)
        for (int i = -3; i <= 3; ++i)
            text += "xyz " + QByteArray::number(i) + " " + QByteArray::number(j) + " 0\n";
    const auto index = [](int i, int j) { return QByteArray::number((j + 4) * 7 + (i + 3) + 1); };
    const auto drawn = [](int i, int j) {
        return i >= -3 && i < 3 && j >= -4 && j < 3 && (i + j) % 2 == 0;
    };
    for (int j = -4; j < 3; ++j)
        for (int i = -3; i < 3; ++i)
            if (drawn(i, j))
                text += "trif " + index(i, j) + " " + index(i + 1, j) + " " + index(i + 1, j + 1) +
                        "\ntrif " + index(i, j) + " " + index(i + 1, j + 1) + " " +
                        index(i, j + 1) + "\n";
    RENDER(frame, text);
    // The premise, worked out here as the lecture does it: v_eye = MV v, v_clip = P v_eye,
    // y_ndc = y_clip / w, y = y_ndc H/2 + H/2 (P's row for y: 2/(t - b), -(t + b)/(t - b)).
    const double t = -0.5, b = -2.0;
    for (const auto& [j, row] : {std::pair{-1, 16}, std::pair{0, 64}}) {
        const double yEye = 0.6 * j + (-1.2);
        const double yNdc = 2.0 / (t - b) * yEye + (-(t + b) / (t - b));
        const double y = yNdc * 60.0 + 60.0;
        QVERIFY2(y > double(row) && y < double(row) + 1e-12,
                 qPrintable(QString::number(y, 'g', 17)));
    }
    // Row 16 belongs to the squares j = -2 (above the line j = -1), row 64 to j = -1. Along
    // the row, pixel x lies in the square i = floor(x_eye - 0.1 j) of the line's j, with
    // x_eye = ((r - l) x_ndc + (r + l)) / 2, x_ndc = x/60 - 1 (exactly, as l, r are given).
    const double l = 2.0, r = -2.5;
    int checked = 0;
    for (const auto& [lineJ, row] : {std::pair{-1, 16}, std::pair{0, 64}}) {
        for (int x = 0; x < 120; ++x) {
            const double xNdc = x / 60.0 - 1.0;
            const double iReal = ((r - l) * xNdc + (r + l)) / 2.0 - 0.1 * lineJ;
            if (std::abs(iReal - std::round(iReal)) < 1e-6) continue;  // on a line of i
            const int i = int(std::floor(iReal));
            const bool above = drawn(i, lineJ - 1), below = drawn(i, lineJ);
            const bool covered = frame.trace->depth->triangle.at(x, row) != kNoTriangle;
            QVERIFY2(covered == above,
                     qPrintable(QStringLiteral("pixel (%1, %2): square (%3, %4) above is %5, the "
                                               "one below %6, the pixel %7")
                                    .arg(x)
                                    .arg(row)
                                    .arg(i)
                                    .arg(lineJ - 1)
                                    .arg(above ? "drawn" : "empty", below ? "drawn" : "empty",
                                         covered ? "covered" : "empty")));
            ++checked;
        }
    }
    QVERIFY2(checked > 230, qPrintable(QString::number(checked)));
    // The exact walk on the vertices snapped to 1/65536 pixel (the hw2 rules before seed
    // 001's DDA) hands both rows to the squares below: every pixel of them differs.
    Scene snapped = *frame.scene;
    snapped.rules.snap = RasterRules::VertexSnap::Nearest;
    snapped.rules.scan = RasterRules::Scan::ExactWalk;
    auto walk = renderFrame(std::make_shared<const Scene>(snapped));
    QVERIFY(walk);
    for (int row : {16, 64}) {
        int differing = 0;
        for (int x = 0; x < 120; ++x)
            differing += (walk->depth->triangle.at(x, row) != kNoTriangle) !=
                                 (frame.trace->depth->triangle.at(x, row) != kNoTriangle)
                             ? 1
                             : 0;
        QVERIFY2(differing >= 119,
                 qPrintable(QStringLiteral("row %1: %2").arg(row).arg(differing)));
    }
}

void TestHw2Render::referenceSamples_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<bool>("exact");         // every pixel equal
    QTest::addColumn<int>("mostDiffering");  // pixels that may differ (seed 001's DDA)
    // With seed 001's DDA and viewport (hw2 rules) these match pixel for pixel.
    for (const char* name : {"hw2trif", "hw2color", "hw2depth", "hw2loadmv", "hw2frustum",
                             "hw2clipplane", "hw2texture"})
        QTest::newRow(name) << QString::fromLatin1(name) << true << 0;
    // trig: eight colours one byte step off; sun1g: two pixels covered by one image only.
    QTest::newRow("hw2trig") << QStringLiteral("hw2trig") << false << 8;
    QTest::newRow("hw2sun1g") << QStringLiteral("hw2sun1g") << false << 2;
    // The patch leaves the depth range [0, 1] inside its quads: its outline there follows the
    // diagonal each quad is cut along, the reference's only with (i + 1, j)-(i, j + 1).
    QTest::newRow("hw2rectbezf") << QStringLiteral("hw2rectbezf") << true << 0;
}

void TestHw2Render::referenceSamples() {
    // The ten samples: at most 0.5 % of the pixels may differ.
    QFETCH(QString, name);
    const QString samples = testing::samplesDir();
    const QDir dir(samples + QStringLiteral("/hw2"));
    if (samples.isEmpty() || !dir.exists(name + QStringLiteral(".txt")) ||
        !dir.exists(name + QStringLiteral(".png")))
        QSKIP(qPrintable(QStringLiteral("%1.txt and %1.png are absent from the samples (set "
                                        "RASTERLAB_SAMPLES or RASTERLAB_SAMPLES_DIR)")
                             .arg(name)));
    Diagnostics diagnostics;
    auto file =
        rasterlab::loadCommandFile(dir.filePath(name + QStringLiteral(".txt")), diagnostics);
    QVERIFY2(file, qPrintable(errorText(file)));
    QCOMPARE(file->images.size(), std::size_t(1));
    QCOMPARE(QString::fromStdString(file->images[0].fileName), name + QStringLiteral(".png"));
    auto scene = std::make_shared<const Scene>(file->images[0].scene);
    auto trace = renderFrame(scene);
    QVERIFY2(trace, qPrintable(errorText(trace)));
    const Rgba8Image ours = colourImage(*trace->shading, *trace->depth, scene->conventions);
    const QImage reference(dir.filePath(name + QStringLiteral(".png")));
    QVERIFY(!reference.isNull());
    QCOMPARE(reference.size(), QSize(ours.width, ours.height));
    const Comparison c = compare(ours, reference);
    const int total = c.width * c.height;
    qInfo(
        "%s: %d of %d pixels differ (%.3f %%), largest channel difference %d; %d of them "
        "covered by one image only, largest difference where both cover %d",
        qPrintable(name), c.differing, total, 100.0 * c.differing / total, c.largest, c.coverage,
        c.largestColour);
    QVERIFY2(c.differing * 200 <= total,
             qPrintable(QStringLiteral("%1 pixels differ, more than 0.5 %").arg(c.differing)));
    QFETCH(bool, exact);
    if (exact) QCOMPARE(c.differing, 0);
    QFETCH(int, mostDiffering);
    QVERIFY2(c.differing <= mostDiffering, qPrintable(QString::number(c.differing)));
}

void TestHw2Render::referenceTexture() {
    // hw2texture, where seed 001's text and its reference image disagree. The text says
    // texture coordinates wrap and the texel is the one nearest to (s w, t h), i.e.
    // floor(s w + 0.5) mod w; the image used (int)(s w + 0.5) mod w, truncating toward zero:
    // the two differ where s w + 0.5 < 0. The hw2 rules follow the image. Checked at every
    // pixel both images cover, at the texture coordinates interpolated here independently:
    // RasterLab and the reference show the truncating rule's texel, and the sample does
    // reach the pixels where the rules disagree.
    const QString samples = testing::samplesDir();
    const QDir dir(samples + QStringLiteral("/hw2"));
    for (const char* needed : {"hw2texture.txt", "hw2texture.png", "splat2.png"})
        if (samples.isEmpty() || !dir.exists(QLatin1String(needed)))
            QSKIP(qPrintable(QStringLiteral("%1 is absent from the samples (set RASTERLAB_SAMPLES "
                                            "or RASTERLAB_SAMPLES_DIR)")
                                 .arg(QLatin1String(needed))));
    Diagnostics diagnostics;
    auto file =
        rasterlab::loadCommandFile(dir.filePath(QStringLiteral("hw2texture.txt")), diagnostics);
    QVERIFY2(file, qPrintable(errorText(file)));
    auto scene = std::make_shared<const Scene>(file->images.at(0).scene);
    auto trace = renderFrame(scene);
    QVERIFY2(trace, qPrintable(errorText(trace)));
    const Rgba8Image ours = colourImage(*trace->shading, *trace->depth, scene->conventions);
    const QImage reference(dir.filePath(QStringLiteral("hw2texture.png")));
    QCOMPARE(reference.size(), QSize(ours.width, ours.height));
    const Comparison c = compare(ours, reference);

    const Texture& texture = *scene->draws.at(0).texture;
    const int w = texture.width, h = texture.height;
    const auto positive = [](long long i, int n) { return int(((i % n) + n) % n); };
    const auto texel = [&](int i, int j) {
        const vec4 t = texture.at(i, j);
        const std::uint8_t bytes[4] = {std::uint8_t(std::lround(t.r * 255.0f)),
                                       std::uint8_t(std::lround(t.g * 255.0f)),
                                       std::uint8_t(std::lround(t.b * 255.0f)), 255};
        return rgba(bytes);
    };
    int bothCovered = 0, rulesDisagree = 0;
    for (int y = 0; y < c.height; ++y) {
        for (int x = 0; x < c.width; ++x) {
            const std::uint8_t* a = ours.pixel(x, y);
            const uchar* b = c.reference.constScanLine(y) + 4 * x;
            if (a[3] != b[3] || a[3] == 0) continue;
            ++bothCovered;
            const auto st = texcoordAt(*trace, x, y);
            QVERIFY(st.has_value());
            const double sw = double(st->x) * w + 0.5, th = double(st->y) * h + 0.5;
            const int i = positive((long long)std::trunc(sw), w);
            const int j = positive((long long)std::trunc(th), h);
            rulesDisagree += i != positive((long long)std::floor(sw), w) ||
                                     j != positive((long long)std::floor(th), h)
                                 ? 1
                                 : 0;
            const QString where = QStringLiteral("pixel (%1, %2), s = %3, t = %4")
                                      .arg(x)
                                      .arg(y)
                                      .arg(double(st->x))
                                      .arg(double(st->y));
            QVERIFY2(rgba(a) == texel(i, j),
                     qPrintable(where + QStringLiteral(": RasterLab shows %1, the truncating "
                                                       "rule's texel (%2, %3) is %4")
                                            .arg(rgba(a))
                                            .arg(i)
                                            .arg(j)
                                            .arg(texel(i, j))));
            QVERIFY2(rgba(b) == texel(i, j),
                     qPrintable(where + QStringLiteral(": the reference shows %1, the "
                                                       "truncating rule's texel (%2, %3) is %4")
                                            .arg(rgba(b))
                                            .arg(i)
                                            .arg(j)
                                            .arg(texel(i, j))));
        }
    }
    qInfo(
        "hw2texture: %d pixels differ, %d covered by one image only; of the %d covered by "
        "both, the seed's text and the images pick different texels at %d",
        c.differing, c.coverage, bothCovered, rulesDisagree);
    QVERIFY2(rulesDisagree > 500, qPrintable(QString::number(rulesDisagree)));
    QVERIFY2(c.differing * 200 <= c.width * c.height, qPrintable(QString::number(c.differing)));
}

QTEST_GUILESS_MAIN(TestHw2Render)
// A vertex far off the image is clipped by the guard band, not pulled in: the edges through
// it keep their direction, so the covered pixels do not depend on how far it is.
void TestHw2Render::guardBandKeepsEdgesStraight() {
    int first = -1;
    // Along a direction whose slope passes no sample exactly (a sample exactly on an edge
    // may fall either way once the far vertex is clipped to the band).
    for (const char* far : {"1e6 314159.2653589793", "1e8 31415926.53589793",
                            "1e12 314159265358.9793", "1e15 314159265358979.3"}) {
        RENDER(frame, QByteArray("png 100 100 g.png\nxyz -1 -1 0.5\nxyz -1 1 0.5\nxyz ") + far +
                          " 0.5\ntrif 1 2 3\n");
        if (first < 0) first = covered(frame);
        QCOMPARE(covered(frame), first);
        QVERIFY(!frame.trace->diagnostics.contains("pulled in"));
    }
    QVERIFY(first > 8000);
}

// A vertex closing in on the eye plane (z -> 0 under a frustum): the visible part of the
// triangle, on screen, barely changes.
void TestHw2Render::nearTheEyePlane() {
    std::vector<int> pixels;
    for (const char* z : {"-1e-4", "-1e-6", "-1e-7", "-1e-8", "-1e-12"}) {
        RENDER(frame, QByteArray("png 100 100 f.png\nfrustum -1 1 -1 1 1 10\nxyz -1 -1 -2\n"
                                 "xyz 1 -1 -2\nxyz 0 0.5 ") +
                          z + "\ntrif 1 2 3\n");
        pixels.push_back(covered(frame));
    }
    for (int n : pixels) QCOMPARE(n, pixels.front());
    QVERIFY(pixels.front() > 50);
}

// Seed 001's xyzw: (0.5, 0, 0), (1, 2, 1, 2) and (1, 1, -0.5, -1), the last behind the eye.
// "Frustum clipping happens here in OpenGL, but we won't add it": the hw2 rules divide each
// vertex by its w, NDC (0.5, 0), (0.5, 1), (-1, -1), and scan convert the triangle where it
// lands, (90, 60), (90, 120), (0, 0) on 120x120 (z 0, 0.5, 0.5, all in [0, 1]). Clipping at
// the near plane (the course and gpu rules) draws instead the part with w > 0, which lies
// beyond x = 90 (the edges from the vertices in front run away from (0, 0)).
void TestHw2Render::acrossTheEyePlane() {
    const QByteArray file =
        "png 120 120 xyzw.png\nxyz 0.5 0 0\nxyzw 1 2 1 2\nxyzw 1 1 -0.5 -1\ncolor 0 0 0\n"
        "trif 1 2 3\n";
    RENDER(frame, file);
    QCOMPARE(frame.trace->projection->mode, NearPlane::Mode::Naive);
    QCOMPARE(frame.trace->projection->acrossEye, std::size_t(1));
    QVERIFY(frame.trace->diagnostics.contains(
        "plain divide: 1 triangle reaches from in front of the eye to at or behind it"));
    // Twice the signed areas against each edge of (90, 60), (90, 120), (0, 0), in integers.
    const auto edges = [](int x, int y) {
        return std::array<int, 3>{(90 - 90) * (y - 60) - (120 - 60) * (x - 90),
                                  (0 - 90) * (y - 120) - (0 - 120) * (x - 90),
                                  (90 - 0) * (y - 0) - (60 - 0) * (x - 0)};
    };
    int inside = 0;
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 120; ++x) {
            const auto e = edges(x, y);
            const bool in =
                (e[0] < 0 && e[1] < 0 && e[2] < 0) || (e[0] > 0 && e[1] > 0 && e[2] > 0);
            const bool out =
                (e[0] < 0 || e[1] < 0 || e[2] < 0) && (e[0] > 0 || e[1] > 0 || e[2] > 0);
            const bool drawn = pixel(frame, x, y) == kBlack;
            if (in) ++inside;
            QVERIFY2(!(in && !drawn) && !(out && drawn),
                     qPrintable(QStringLiteral("pixel (%1, %2): %3")
                                    .arg(x)
                                    .arg(y)
                                    .arg(drawn ? QStringLiteral("drawn outside")
                                               : QStringLiteral("missed"))));
        }
    QVERIFY2(inside > 2500, qPrintable(QString::number(inside)));

    // The same file with near-plane clipping: the front part, right of x = 90 only.
    Scene clipped = *frame.scene;
    clipped.nearPlane.mode = NearPlane::Mode::Clip;
    auto trace = renderFrame(std::make_shared<const Scene>(clipped));
    QVERIFY2(trace, qPrintable(errorText(trace)));
    const Rgba8Image image = colourImage(*trace->shading, *trace->depth, clipped.conventions);
    int right = 0;
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 120; ++x) {
            if (image.pixel(x, y)[3] == 0) continue;
            QVERIFY2(x >= 90, qPrintable(QStringLiteral("(%1, %2)").arg(x).arg(y)));
            ++right;
        }
    QVERIFY2(right > 400, qPrintable(QString::number(right)));
    QCOMPARE(trace->projection->clipped, std::size_t(1));
}

// w so small that 1/w overflows a float: the perspective weights stay finite.
void TestHw2Render::tinyWGivesNoNaN() {
    RENDER(frame,
           "png 16 16 w.png\ncolor 1 0 0\nxyzw -1e-39 -1e-39 0 1e-39\n"
           "xyzw 1e-39 -1e-39 0 1e-39\nxyz 0 1 0\ntrig 1 2 3\n");
    for (const vec3& c : frame.trace->shading->colour.pixels())
        QVERIFY(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b));
    QVERIFY(covered(frame) > 0);
    QCOMPARE(pixel(frame, 8, 12), kRed);
}

#include "tst_hw2_render.moc"
