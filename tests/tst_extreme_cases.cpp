// Stiff and extreme cases, each with its stated behaviour. Every case goes through the
// readers (so their messages count) and, when they accept it, the seven stages at 64x48 in
// Phong, Gouraud and flat. For every case that renders:
//   - no NaN or Inf reaches a pixel: every colour is finite, and every depth is finite or
//     the empty buffer's +infinity exactly where nothing was drawn;
//   - the number of covered pixels is the one stated;
//   - the warnings a student can act on are those stated (substrings of the messages).
// A case the readers refuse gives its exact file:line:col message and renders nothing.
#include <QtTest>

#include <cmath>

#include "pipeline/io/course_readers.h"
#include "pipeline/io/course_scene.h"
#include "pipeline/io/hw2_reader.h"
#include "pipeline/render/renderer.h"
#include "tests/test_support.h"

using namespace rl;

namespace {

// The usual parts: a camera at (0, 0, -5) looking along +z with a 90 degree view, the light
// at the camera, and a square of side 2 in the plane z = 0 (it covers 140 pixels at 64x48).
const char* const kCamera = "0 0 -5\n0 0 1\n0 1 0\n1 1 1\n";
const char* const kLighting = "0 0 -5\n0.2\n100 100 100\n0.5\n1 0.5 0.25\n0.5\n255 255 255\n8\n";
const char* const kSquare = "4 2\n-1 -1 0\n1 -1 0\n1 1 0\n-1 1 0\n1 2 3\n1 3 4\n";

QString lines(std::initializer_list<const char*> parts) {
    QString text;
    for (const char* p : parts) text += QLatin1String(p) + QLatin1Char('\n');
    return text;
}

struct Outcome {
    QString error;         // the first reader's error, or ""
    QStringList messages;  // warnings and notes, readers and stages
    std::size_t covered = 0;
    bool finite = true;  // no NaN or Inf in a pixel
    QString why;         // where it was not
};

Outcome run(const QString& camera, const QString& lighting, const QString& object) {
    Outcome out;
    Diagnostics diagnostics;
    const QByteArray c = camera.toUtf8(), l = lighting.toUtf8(), o = object.toUtf8();
    auto cam = readCameraFile({c.constData(), size_t(c.size())}, "cam.cfg", diagnostics);
    if (!cam) {
        out.error = QString::fromStdString(cam.error().toString());
        return out;
    }
    auto lit = readLightingFile({l.constData(), size_t(l.size())}, "lit.txt", diagnostics);
    if (!lit) {
        out.error = QString::fromStdString(lit.error().toString());
        return out;
    }
    auto obj = parseCourseObject({o.constData(), size_t(o.size())}, "obj.byu", diagnostics);
    if (!obj) {
        out.error = QString::fromStdString(obj.error().toString());
        return out;
    }
    for (const auto& d : diagnostics.items())
        if (d.toString().find(": note: read as") == std::string::npos)
            out.messages << QString::fromStdString(d.toString());
    std::size_t covered = 0;
    bool first = true;
    for (ShadingModel shading : {ShadingModel::Phong, ShadingModel::Gouraud, ShadingModel::Flat}) {
        CourseSceneSettings settings;
        settings.width = 64;
        settings.height = 48;
        settings.shading = shading;
        auto scene = std::make_shared<const Scene>(
            makeCourseScene({cam.value(), lit.value(), obj.value()}, settings));
        auto frame = renderFrame(scene);
        if (!frame) {
            out.error = QString::fromStdString(frame.error().toString());
            return out;
        }
        if (first)
            for (const auto& d : frame->diagnostics.items())
                out.messages << QString::fromStdString(d.toString());
        first = false;
        const DepthTest& depth = *frame->depth;
        const Shading& shade = *frame->shading;
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 64; ++x) {
                const vec3 colour = shade.colour.at(x, y);
                const float z = depth.depth.at(x, y);
                const bool drawn = depth.triangle.at(x, y) != kNoTriangle;
                const bool ok = std::isfinite(colour.r) && std::isfinite(colour.g) &&
                                std::isfinite(colour.b) &&
                                (drawn ? std::isfinite(z) : z == depth.clearedTo);
                if (!ok && out.finite) {
                    out.finite = false;
                    out.why = QStringLiteral("%1: pixel (%2, %3)")
                                  .arg(QLatin1String(shadingModelName(shading)))
                                  .arg(x)
                                  .arg(y);
                }
            }
        // Coverage does not depend on the shading model.
        if (covered && depth.coveredPixels() != covered) out.why = QStringLiteral("coverage moved");
        covered = depth.coveredPixels();
    }
    out.covered = covered;
    return out;
}

}  // namespace

class TestExtremeCases : public QObject {
    Q_OBJECT

private slots:
    void renders_data() {
        QTest::addColumn<QString>("camera");
        QTest::addColumn<QString>("lighting");
        QTest::addColumn<QString>("object");
        QTest::addColumn<int>("covered");
        QTest::addColumn<QStringList>("warnings");  // substrings, one message each

        const QString cam = QLatin1String(kCamera), lit = QLatin1String(kLighting),
                      square = QLatin1String(kSquare);
        QTest::newRow("the usual square") << cam << lit << square << 140 << QStringList();
        // A sliver: its smallest angle is 1e-11 degrees. Truncated to whole pixels, it
        // becomes the 8 pixels its edges run through; lit like any other triangle.
        QTest::newRow("sliver below 1e-4 degrees")
            << cam << lit << lines({"3 1", "0 0 0", "1 0 0", "1000000 0.0000001 0", "1 2 3"}) << 8
            << QStringList();
        // Collinear in space: no area and no normal (noted); integer vertices on the screen
        // make a thin triangle of 4 pixels, lit by the ambient term only.
        QTest::newRow("collinear")
            << cam << lit << lines({"3 1", "0 0 0", "1 1 1", "2 2 2", "1 2 3"}) << 4
            << QStringList({"obj.byu: note: 1 triangles have zero area and no normal"});
        // A repeated vertex: zero area, nothing drawn; the unused vertex is named.
        QTest::newRow("repeated vertex")
            << cam << lit << lines({"3 1", "0 0 0", "1 0 0", "0 1 0", "1 1 2"}) << 0
            << QStringList({"obj.byu: warning: 1 vertex of 3 is not used by any triangle",
                            "obj.byu: note: 1 triangles have zero area and no normal"});
        // Coordinates of 1e8 around the camera: clipped at the near plane, the whole image.
        QTest::newRow("coordinates of 1e8")
            << cam << lit << lines({"3 1", "-1e8 -1e8 0", "1e8 -1e8 0", "0 1e8 0", "1 2 3"})
            << 64 * 48 << QStringList({"1 triangle was clipped against the near plane"});
        // Coordinates of 1e-8: far below a pixel, but truncated vertices still make one
        // pixel-sized triangle (the course's (int)): 3 pixels.
        QTest::newRow("coordinates of 1e-8")
            << cam << lit << lines({"3 1", "-1e-8 -1e-8 0", "1e-8 -1e-8 0", "0 1e-8 0", "1 2 3"})
            << 3 << QStringList();
        // hx = hy = 0.001: the square projects to a thousand times the screen; every pixel.
        QTest::newRow("projection 1000 times the screen")
            << lines({"0 0 -5", "0 0 1", "0 1 0", "1 0.001 0.001"}) << lit << square << 64 * 48
            << QStringList();
        // A vertex at the camera: clipped against the near plane, what is in front drawn.
        QTest::newRow("camera at a vertex")
            << cam << lit << lines({"3 1", "0 0 -5", "1 0 0", "0 1 0", "1 2 3"}) << 0
            << QStringList({"1 triangle was clipped against the near plane"});
        // A vertex exactly on the near plane (z = 1 in view; the near plane is 0.001 of the
        // farthest z, here 1e-3 * 1000): nothing to clip, the wedge from the centre to
        // x = 0.9 drawn whole (about 0.5 * 43.2 * 28.8 = 622 pixels, 647 with its edges).
        // Just behind it (z = 0.999): clipped, the part in front drawn, one pixel fewer.
        QTest::newRow("vertex on the near plane")
            << cam << lit << lines({"3 1", "0 0 -4", "900 -900 995", "900 900 995", "1 2 3"}) << 647
            << QStringList();
        QTest::newRow("vertex just behind the near plane")
            << cam << lit << lines({"3 1", "0 0 -4.001", "900 -900 995", "900 900 995", "1 2 3"})
            << 646 << QStringList({"1 triangle was clipped against the near plane"});
        // The camera inside a closed box: every face is drawn from inside, nothing culled.
        QTest::newRow("camera inside the object")
            << lines({"0 0 0", "0 0 1", "0 1 0", "1 1 1"}) << lit
            << lines({"8 12",  "-2 -2 -2", "2 -2 -2", "2 2 -2", "-2 2 -2", "-2 -2 2", "2 -2 2",
                      "2 2 2", "-2 2 2",   "1 2 3",   "1 3 4",  "5 7 6",   "5 8 7",   "1 5 6",
                      "1 6 2", "2 6 7",    "2 7 3",   "3 7 8",  "3 8 4",   "4 8 5",   "4 5 1"})
            << 64 * 48 << QStringList();
        QTest::newRow("every vertex behind the camera")
            << cam << lit << lines({"3 1", "0 0 -6", "1 0 -6", "0 1 -6", "1 2 3"}) << 0
            << QStringList({"obj.byu: warning: every triangle is behind the camera"});
        // The camera in the plane of the square: seen edge-on, at the camera's plane.
        QTest::newRow("camera in the object's plane")
            << lines({"0 0 0", "0 0 1", "0 1 0", "1 1 1"}) << lit << square << 0
            << QStringList({"obj.byu: warning: every triangle is behind the camera"});
        QTest::newRow("hx negative")
            << lines({"0 0 -5", "0 0 1", "0 1 0", "1 -1 1"}) << lit << square << 140
            << QStringList({"cam.cfg:4:3: warning: hx is negative: the image is mirrored left "
                            "to right"});
        // The light on the surface (L = 0 at the centre): ambient only there, no NaN, and a
        // warning that float cannot tell the light's side there.
        QTest::newRow("light at the shaded point")
            << cam
            << lines(
                   {"0 0 0", "0.2", "100 100 100", "0.5", "1 0.5 0.25", "0.5", "255 255 255", "8"})
            << square << 140
            << QStringList({"lit.txt:1:1: warning: light 1 is 0 above triangle 1 of obj.byu, "
                            "nearer than float can resolve points there (5e-05)"});
        // The light in the square's plane: N.L = 0 exactly, no diffuse, no NaN.
        QTest::newRow("N.L exactly 0") << cam
                                       << lines({"0 5 0", "0.2", "100 100 100", "0.5", "1 0.5 0.25",
                                                 "0.5", "255 255 255", "8"})
                                       << square << 140 << QStringList();
        QTest::newRow("n = 0") << cam
                               << lines({"0 0 -5", "0.2", "100 100 100", "0.5", "1 0.5 0.25", "0.5",
                                         "255 255 255", "0"})
                               << square << 140
                               << QStringList({"lit.txt:8:1: warning: n = 0 is not positive"});
        QTest::newRow("n = 1e6") << cam
                                 << lines({"0 0 -5", "0.2", "100 100 100", "0.5", "1 0.5 0.25",
                                           "0.5", "255 255 255", "1e6"})
                                 << square << 140 << QStringList();
        QTest::newRow("ka, kd, ks outside [0, 1]")
            << cam
            << lines({"0 0 -5", "-0.5", "100 100 100", "2", "1 0.5 0.25", "7", "255 255 255", "8"})
            << square << 140
            << QStringList({"lit.txt:2:1: warning: ka = -0.5 is outside [0, 1]",
                            "lit.txt:4:1: warning: kd = 2 is outside [0, 1]",
                            "lit.txt:6:1: warning: ks = 7 is outside [0, 1]"});
        // Colours far above 255 are kept unclamped through the stages, clamped in the image.
        QTest::newRow("colours far above 255")
            << cam
            << lines(
                   {"0 0 -5", "0.2", "1e6 100 100", "0.5", "1 0.5 0.25", "0.5", "1e9 255 255", "8"})
            << square << 140
            << QStringList({"lit.txt:3:1: warning: Ia.r = 1e+06 is outside [0, 255]",
                            "lit.txt:7:1: warning: Il.r = 1e+09 is outside [0, 255]"});
        // Two coplanar triangles over each other: the depth test keeps the first drawn on a
        // tie (z < stored), so the result is the same on every run and every thread count.
        QTest::newRow("coplanar overlapping (z-fighting)")
            << cam << lit
            << lines({"6 2", "-1 -1 0", "1 -1 0", "1 1 0", "-1 -1 0", "1 -1 0", "-1 1 0", "1 2 3",
                      "4 5 6"})
            << 104 << QStringList();
    }

    void renders() {
        QFETCH(QString, camera);
        QFETCH(QString, lighting);
        QFETCH(QString, object);
        QFETCH(int, covered);
        QFETCH(QStringList, warnings);
        const Outcome out = run(camera, lighting, object);
        QVERIFY2(out.error.isEmpty(), qPrintable(out.error));
        QVERIFY2(out.finite, qPrintable(QStringLiteral("not finite at ") + out.why));
        QVERIFY2(out.why.isEmpty(), qPrintable(out.why));
        QCOMPARE(int(out.covered), covered);
        for (const QString& w : warnings) {
            bool found = false;
            for (const QString& m : out.messages) found = found || m.contains(w);
            QVERIFY2(found, qPrintable(w + QStringLiteral(" not in: ") +
                                       out.messages.join(QStringLiteral(" | "))));
        }
        // No warning beyond those stated (notes about what the stages did are allowed).
        for (const QString& m : out.messages) {
            if (!m.contains(QStringLiteral(": warning: "))) continue;
            bool stated = false;
            for (const QString& w : warnings) stated = stated || m.contains(w);
            QVERIFY2(stated, qPrintable(QStringLiteral("unexpected: ") + m));
        }
    }

    void refused_data() {
        QTest::addColumn<QString>("camera");
        QTest::addColumn<QString>("lighting");
        QTest::addColumn<QString>("object");
        QTest::addColumn<QString>("message");
        const QString cam = QLatin1String(kCamera), lit = QLatin1String(kLighting),
                      square = QLatin1String(kSquare);
        const auto camera = [](const char* n, const char* v, const char* dhh) {
            return lines({"0 0 -5", n, v, dhh});
        };
        QTest::newRow("N parallel to V")
            << camera("0 1 0", "0 1 0", "1 1 1") << lit << square
            << "cam.cfg:3:1: V (0, 1, 0) is parallel to N (0, 1, 0): Gram-Schmidt leaves "
               "nothing of V, so 'up' is undefined; choose a V that is not along N";
        QTest::newRow("V = 0") << camera("0 0 1", "0 0 0", "1 1 1") << lit << square
                               << "cam.cfg:3:1: V, the up vector, is the zero vector: it must "
                                  "say which way is up";
        QTest::newRow("N = 0") << camera("0 0 0", "0 1 0", "1 1 1") << lit << square
                               << "cam.cfg:2:1: N, the view direction, is the zero vector: it "
                                  "must point from the camera toward the scene";
        QTest::newRow("d = 0") << camera("0 0 1", "0 1 0", "0 1 1") << lit << square
                               << "cam.cfg:4:1: d, the distance to the projection plane, is 0: "
                                  "the projection (d/hx) x/z would squash every point to the "
                                  "centre";
        QTest::newRow("hx = 0") << camera("0 0 1", "0 1 0", "1 0 1") << lit << square
                                << "cam.cfg:4:3: hx, the horizontal half-size of the window, is "
                                   "0: the projection (d/hx) x/z divides by it";
        QTest::newRow("NaN in a vertex")
            << cam << lit << lines({"3 1", "nan 0 0", "1 0 0", "0 1 0", "1 2 3"})
            << "obj.byu:2:1: expected a number for the x coordinate of vertex 1 of 3, found "
               "'nan', which is not a finite number";
        QTest::newRow("Inf in a vertex")
            << cam << lit << lines({"3 1", "0 -inf 0", "1 0 0", "0 1 0", "1 2 3"})
            << "obj.byu:2:3: expected a number for the y coordinate of vertex 1 of 3, found "
               "'-inf', which is not a finite number";
        QTest::newRow("1e400 in a vertex")
            << cam << lit << lines({"3 1", "0 0 1e400", "1 0 0", "0 1 0", "1 2 3"})
            << "obj.byu:2:5: expected a number for the z coordinate of vertex 1 of 3, found "
               "'1e400', which is out of range";
        QTest::newRow("NaN in the lighting")
            << cam
            << lines(
                   {"0 0 -5", "0.2", "nan 100 100", "0.5", "1 0.5 0.25", "0.5", "255 255 255", "8"})
            << square
            << "lit.txt:3:1: expected a number for Ia, found 'nan', which is not a "
               "finite number";
        QTest::newRow("Inf in the camera")
            << lines({"0 0 -5", "0 0 1", "0 1 0", "inf 1 1"}) << lit << square
            << "cam.cfg:4:1: expected a number for d hx hy, found 'inf', which is not a finite "
               "number";
    }

    void refused() {
        QFETCH(QString, camera);
        QFETCH(QString, lighting);
        QFETCH(QString, object);
        QFETCH(QString, message);
        const Outcome out = run(camera, lighting, object);
        QCOMPARE(out.error, message);
    }
    // HW2's stiff orthographic projection: l > r (the image mirrored left to right), near
    // and far both negative (the visible box at positive eye z), a model/view that tilts a
    // 7x8 grid of unit squares, painted as a checkerboard of pairs of triangles. Every pixel
    // whose sample lies inside a square (by more than 1e-6 of a pixel) is drawn and every one
    // outside all of them is not: one continuous checkerboard, without a seam where one path
    // hands over to another (screen edges, the mirrored x, clipping).
    void stiffOrthographicCheckerboard() {
        QByteArray text =
            "png 120 120 ortho.png\ncolor 0 0.5 0\n"
            "loadmv 1 0.1 0 0  0 0.6 0.8 -1.2  0 0.8 -0.6 4.5  0 0 0 1\n"
            "ortho 2 -2.5 -2 -0.5 -5.5 -2.5\n";
        const auto index = [](int i, int j) { return (j + 4) * 7 + (i + 3) + 1; };
        for (int j = -4; j <= 3; ++j)
            for (int i = -3; i <= 3; ++i)
                text += "xyz " + QByteArray::number(i) + " " + QByteArray::number(j) + " 0\n";
        std::vector<std::array<dvec2, 3>> expected;  // each triangle on the screen
        // The seed's ortho matrix, with near = 2n - f, worked out here on its own.
        const double l = 2, r = -2.5, b = -2, t = -0.5;
        const auto screen = [&](int i, int j) {
            const double xEye = i + 0.1 * j, yEye = 0.6 * j - 1.2;
            const double xNdc = 2 / (r - l) * xEye - (r + l) / (r - l);
            const double yNdc = 2 / (t - b) * yEye - (t + b) / (t - b);
            return dvec2((xNdc + 1) * 60, (yNdc + 1) * 60);
        };
        for (int j = -4; j < 3; ++j)
            for (int i = -3; i < 3; ++i) {
                if ((i + j) % 2 != 0) continue;
                const int a = index(i, j), bb = index(i + 1, j), c = index(i + 1, j + 1),
                          d = index(i, j + 1);
                text += "trif " + QByteArray::number(a) + " " + QByteArray::number(bb) + " " +
                        QByteArray::number(c) + "\ntrif " + QByteArray::number(a) + " " +
                        QByteArray::number(c) + " " + QByteArray::number(d) + "\n";
                expected.push_back({screen(i, j), screen(i + 1, j), screen(i + 1, j + 1)});
                expected.push_back({screen(i, j), screen(i + 1, j + 1), screen(i, j + 1)});
            }
        Diagnostics diagnostics;
        const TextureLoader noTextures =
            [](const std::string&,
               const SourceLocation& where) -> Result<std::shared_ptr<const Texture>> {
            return makeError(ErrorCode::Io, where, "no textures here");
        };
        auto file = readHw2({text.constData(), std::size_t(text.size())}, "ortho.txt", noTextures,
                            diagnostics);
        QVERIFY2(file, file ? "" : file.error().toString().c_str());
        auto scene = std::make_shared<const Scene>(file->images.at(0).scene);
        auto frame = renderFrame(scene);
        QVERIFY(frame);
        // Twice the signed area of (from, to, p): which side of from -> to the point p lies on.
        const auto side = [](const dvec2& from, const dvec2& to, const dvec2& p) {
            return (to.x - from.x) * (p.y - from.y) - (to.y - from.y) * (p.x - from.x);
        };
        int inside = 0;
        for (int y = 0; y < 120; ++y)
            for (int x = 0; x < 120; ++x) {
                const dvec2 p(x, y);
                // The sample's least signed distance to the edges of each triangle, in pixels
                // (positive inside): inside by 1e-6 of a pixel, or outside every one by as much.
                bool in = false, near = false;
                for (const auto& tri : expected) {
                    const double area = side(tri[0], tri[1], tri[2]);
                    double least = 1e300;
                    for (int k = 0; k < 3; ++k) {
                        const dvec2& a = tri[std::size_t(k)];
                        const dvec2& bEnd = tri[std::size_t((k + 1) % 3)];
                        least = std::min(
                            least, side(a, bEnd, p) * (area > 0 ? 1 : -1) / glm::length(bEnd - a));
                    }
                    in = in || least > 1e-6;
                    near = near || std::abs(least) <= 1e-6;
                }
                const bool drawn = frame->depth->triangle.at(x, y) != kNoTriangle;
                inside += in ? 1 : 0;
                if (near && !in) continue;  // a sample on an edge: the fill rule decides
                QVERIFY2(drawn == in, qPrintable(QStringLiteral("pixel (%1, %2) %3")
                                                     .arg(x)
                                                     .arg(y)
                                                     .arg(drawn ? "drawn outside the squares"
                                                                : "missed inside a square")));
            }
        // About half the image: a checkerboard that fills it.
        QVERIFY2(inside > 6000 && inside < 8400, qPrintable(QString::number(inside)));
    }
};

QTEST_GUILESS_MAIN(TestExtremeCases)
#include "tst_extreme_cases.moc"
