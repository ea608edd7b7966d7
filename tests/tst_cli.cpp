// rasterlab-cli run as its users run it: a separate process in a scratch folder. Checks the
// exit codes (0 done, 1 bad input, 2 bad command line), the exact stderr lines of usage
// errors, bad files and warnings, and the PNGs it writes, pixel by pixel where it matters;
// for `render` (course scenes) and `run` (command files of seed 001).
#include <QtTest>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>

#include "pipeline/analysis/painter.h"
#include "pipeline/core/multiversion.h"
#include "pipeline/core/parallel.h"
#include "tests/course_scenes.h"
#include "tests/test_support.h"

using testing::CliRun;
using testing::runCli;

namespace {

QStringList linesOf(const QString& text) {
    QStringList lines = text.split(QLatin1Char('\n'));
    if (!lines.isEmpty() && lines.last().isEmpty()) lines.removeLast();
    return lines;
}

#define RUN_CLI(run, arguments, workDir) \
    QVERIFY2(runCli((arguments), (workDir), (run)), qPrintable((run).problem))

// Writes `content` to `name` in `dir`; returns the absolute path, or "" on failure.
QString writeFixture(const QTemporaryDir& dir, const QString& name, const QByteArray& content) {
    const QString path = dir.filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(content) != content.size()) return {};
    return path;
}

// The absolute path the CLI prints for `name` written in `dir` (its working directory).
QString printedPath(const QTemporaryDir& dir, const QString& name) {
    return QDir(QFileInfo(dir.path()).canonicalFilePath()).absoluteFilePath(name);
}

bool isBlack(QRgb c) {
    return qRed(c) == 0 && qGreen(c) == 0 && qBlue(c) == 0;
}

// Which pixels are not black, row by row.
QVector<bool> coverage(const QImage& image) {
    QVector<bool> mask;
    mask.reserve(qsizetype(image.width()) * image.height());
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) mask.push_back(!isBlack(image.pixel(x, y)));
    return mask;
}

qsizetype countTrue(const QVector<bool>& mask) {
    return mask.count(true);
}

const char* const kTryHelp = "Try 'rasterlab-cli --help' for more information.";

// The note a camera file in the UFPE layout gets (%1: the file's path).
const QString kUfpeCameraNote = QStringLiteral(
    "%1: note: read as a UFPE camera, C; N; V; d hx hy (no line contains '=' and the 4 lines "
    "have 3, 3, 3, 3 numbers, as in that layout)");

}  // namespace

class TestCli : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();

    void renderDefaultScene();
    void shadingModelsDiffer();
    void painterCountsDifferences();
    void depthAndNormalsOutputs();
    void usageErrors_data();
    void usageErrors();
    void badInputFiles_data();
    void badInputFiles();
    void missingFile_data();
    void missingFile();
    void unwritableOutput();
    void warnings_data();
    void warnings();
    void cameraFacingAway();
    void courseVariants();
    void explainPixel_data();
    void explainPixel();
    void generateDefaultScene();
    void decimalCommaLocale();
    void outOfMemory();
    void help_data();
    void help();
    void courseSamples_data();
    void courseSamples();
    void runCommandFile();
    void runExplainsTexel();
    void runWritesEveryImage();
    void runBadCommandFile_data();
    void runBadCommandFile();
    void bench_data();
    void bench();
    void rulesChangeTheImage();
    void hugeFileFailsFast();
    void accuracyJson();
    void accuracyTablePlotAndHeatMaps();
};

void TestCli::initTestCase() {
    QVERIFY2(QFileInfo(testing::cliPath()).isExecutable(),
             qPrintable(testing::cliPath() + QStringLiteral(" is not an executable")));
}

void TestCli::renderDefaultScene() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    CliRun run;
    RUN_CLI(run, QStringList({"render", "--output", "out.png", "--size", "320x240"}), dir.path());
    QCOMPARE(run.err, QString());
    QCOMPARE(run.exitCode, 0);

    const QStringList out = linesOf(run.out);
    QCOMPARE(out.size(), 3);
    QCOMPARE(out[0], QStringLiteral("rendering the embedded default scene"));
    QCOMPARE(out[1], QStringLiteral("wrote %1 (image, 320x240)").arg(printedPath(dir, "out.png")));
    static const QRegularExpression summary(
        QStringLiteral("^  7776 triangles, phong shading, (\\d+) pixels covered, [0-9.]+ ms$"));
    const auto match = summary.match(out[2]);
    QVERIFY2(match.hasMatch(), qPrintable(out[2]));

    const QImage image(dir.filePath("out.png"));
    QVERIFY(!image.isNull());
    QCOMPARE(image.size(), QSize(320, 240));
    QCOMPARE(image.pixel(0, 0), qRgba(0, 0, 0, 255));  // background: opaque black
    QCOMPARE(image.pixel(319, 239), qRgba(0, 0, 0, 255));
    bool litNearCentre = false;
    for (int y = 100; y < 140 && !litNearCentre; ++y)
        for (int x = 140; x < 180 && !litNearCentre; ++x)
            litNearCentre = !isBlack(image.pixel(x, y)) && qAlpha(image.pixel(x, y)) == 255;
    QVERIFY2(litNearCentre, "no opaque lit pixel within 20 pixels of the centre");
    // The ambient term is not zero, so every covered pixel is lit: the count matches.
    QCOMPARE(countTrue(coverage(image)), match.captured(1).toLongLong());
}

void TestCli::shadingModelsDiffer() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QStringList models = {"phong", "flat", "gouraud"};
    QList<QImage> images;
    for (const QString& model : models) {
        const QString file = model + QStringLiteral(".png");
        CliRun run;
        RUN_CLI(run,
                QStringList({"render", "--shading", model, "--size", "400x300", "--output", file}),
                dir.path());
        QCOMPARE(run.err, QString());
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains(QStringLiteral("  7776 triangles, %1 shading, ").arg(model)),
                 qPrintable(run.out));
        const QImage image(dir.filePath(file));
        QVERIFY(!image.isNull());
        QCOMPARE(image.size(), QSize(400, 300));
        images.append(image.convertToFormat(QImage::Format_RGBA8888));
    }
    for (int i = 0; i < images.size(); ++i) {
        for (int j = i + 1; j < images.size(); ++j) {
            QVERIFY2(
                images[i] != images[j],
                qPrintable(
                    QStringLiteral("%1 and %2 give the same image").arg(models[i], models[j])));
            // The shading model changes colours, never which pixels are covered.
            QVERIFY2(
                coverage(images[i]) == coverage(images[j]),
                qPrintable(
                    QStringLiteral("%1 and %2 cover different pixels").arg(models[i], models[j])));
        }
    }
}

void TestCli::painterCountsDifferences() {
    // --shading painter prints how many pixels differ from the z-buffer's render, the same
    // count compareWithZBuffer gives in this process, and writes the difference image: red
    // where a farther triangle was painted last, yellow on ties, the rest darkened.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    CliRun run;
    RUN_CLI(run,
            QStringList({"render", "--shading", "painter", "--output", "painter.png",
                         "--painter-diff", "diff.png"}),
            dir.path());
    QCOMPARE(run.err, QString());
    QCOMPARE(run.exitCode, 0);
    const auto comparison = rl::compareWithZBuffer(
        testing::defaultCourseScene(rl::ShadingModel::Painter, rl::RuleSet::Course, 800, 600));
    QVERIFY(comparison.ok());
    // The trefoil passes in front of itself: at 800x600 a farther triangle is painted over a
    // nearer one at a few pixels (5, measured); most differences are ties on shared edges.
    QVERIFY(comparison->wrongOrder > 0);
    QVERIFY(comparison->ties > comparison->wrongOrder);
    const QString line = QStringLiteral(
                             "  painter: %1 pixels differ from the z-buffer render (%2 where a "
                             "farther triangle was painted last, %3 where two triangles are as "
                             "near)")
                             .arg(comparison->differing)
                             .arg(comparison->wrongOrder)
                             .arg(comparison->ties);
    QVERIFY2(linesOf(run.out).contains(line), qPrintable(run.out));
    QVERIFY2(run.out.contains(QStringLiteral("wrote %1 (painter difference, 800x600)")
                                  .arg(printedPath(dir, "diff.png"))),
             qPrintable(run.out));
    const QImage diff = QImage(dir.filePath("diff.png")).convertToFormat(QImage::Format_RGBA8888);
    QCOMPARE(diff.size(), QSize(800, 600));
    qsizetype red = 0, yellow = 0;
    for (int y = 0; y < diff.height(); ++y) {
        for (int x = 0; x < diff.width(); ++x) {
            const QRgb c = diff.pixel(x, y);
            const auto d = comparison->mask.at(x, y);
            // Farther by more than the tolerance (not float rounding along a shared edge): a
            // wrong order; within it, a tie.
            const float painted = comparison->painter->depth->depth.at(x, y);
            const float nearest = comparison->zBuffer->depth->depth.at(x, y);
            if (d != rl::PixelDifference::Same)
                QCOMPARE(d == rl::PixelDifference::WrongOrder,
                         painted - nearest > rl::kPainterDepthTolerance * std::abs(nearest));
            if (d == rl::PixelDifference::WrongOrder) {
                QCOMPARE(c, qRgba(255, 0, 0, 255));
                ++red;
            } else if (d == rl::PixelDifference::Tie) {
                QCOMPARE(c, qRgba(255, 220, 0, 255));
                ++yellow;
            }
        }
    }
    QCOMPARE(red, qsizetype(comparison->wrongOrder));
    QCOMPARE(yellow, qsizetype(comparison->ties));
}

void TestCli::depthAndNormalsOutputs() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    CliRun run;
    RUN_CLI(run,
            QStringList({"render", "--size", "320x240", "--output", "out.png", "--depth-output",
                         "depth.png", "--normals-output", "normals.png"}),
            dir.path());
    QCOMPARE(run.err, QString());
    QCOMPARE(run.exitCode, 0);
    const QStringList out = linesOf(run.out);
    QCOMPARE(out.size(), 6);
    QCOMPARE(out[1], QStringLiteral("wrote %1 (image, 320x240)").arg(printedPath(dir, "out.png")));
    QCOMPARE(out[2],
             QStringLiteral("wrote %1 (z-buffer, 320x240)").arg(printedPath(dir, "depth.png")));
    static const QRegularExpression range(
        QStringLiteral("^  z-buffer range: ([0-9.]+) \\(white\\) to ([0-9.]+) \\(dark grey\\)$"));
    const auto match = range.match(out[3]);
    QVERIFY2(match.hasMatch(), qPrintable(out[3]));
    QVERIFY(match.captured(1).toDouble() > 0.0);
    QVERIFY(match.captured(1).toDouble() < match.captured(2).toDouble());
    QCOMPARE(out[4],
             QStringLiteral("wrote %1 (normals, 320x240)").arg(printedPath(dir, "normals.png")));

    const QImage colour(dir.filePath("out.png"));
    const QImage depth(dir.filePath("depth.png"));
    const QImage normals(dir.filePath("normals.png"));
    QCOMPARE(colour.size(), QSize(320, 240));
    QCOMPARE(depth.size(), QSize(320, 240));
    QCOMPARE(normals.size(), QSize(320, 240));

    // The three images cover the same pixels; depth is grey from white (nearest) to 40.
    const QVector<bool> covered = coverage(colour);
    QVERIFY(countTrue(covered) > 0);
    QVERIFY(coverage(depth) == covered);
    QVERIFY(coverage(normals) == covered);
    int lightest = 0, darkest = 255;
    for (int y = 0; y < depth.height(); ++y) {
        for (int x = 0; x < depth.width(); ++x) {
            const QRgb d = depth.pixel(x, y);
            QVERIFY(qRed(d) == qGreen(d) && qGreen(d) == qBlue(d));
            QCOMPARE(qAlpha(d), 255);
            if (isBlack(d)) continue;
            lightest = std::max(lightest, qRed(d));
            darkest = std::min(darkest, qRed(d));
        }
    }
    QCOMPARE(lightest, 255);
    QCOMPARE(darkest, 40);

    // Without --depth-output the render keeps no z-buffer (each thread a band of depths):
    // the same image, byte for byte.
    CliRun plain;
    RUN_CLI(plain, QStringList({"render", "--size", "320x240", "--output", "plain.png"}),
            dir.path());
    QCOMPARE(plain.exitCode, 0);
    const QByteArray withDepth = testing::readFile(dir.filePath("out.png"));
    QVERIFY(!withDepth.isEmpty());
    QCOMPARE(testing::readFile(dir.filePath("plain.png")), withDepth);
}

void TestCli::usageErrors_data() {
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");

    const QStringList out = {"--output", "out.png"};
    QTest::newRow("painter diff without painter")
        << (QStringList({"render", "--painter-diff", "diff.png"}) + out)
        << "--painter-diff needs --shading painter";
    QTest::newRow("size without height")
        << (QStringList({"render", "--size", "800"}) + out)
        << "--size expects WIDTHxHEIGHT such as 800x600, found '800'";
    QTest::newRow("size zero") << (QStringList({"render", "--size", "0x10"}) + out)
                               << "--size expects WIDTHxHEIGHT such as 800x600, found '0x10'";
    QTest::newRow("size too large")
        << (QStringList({"render", "--size", "20000x10"}) + out)
        << "--size 20000x10 is larger than the limit of 16384 pixels a side";
    QTest::newRow("too many pixels")
        << (QStringList({"render", "--size", "8000x8000"}) + out)
        << "--size 8000x8000 has 64000000 pixels, more than the limit of 40000000 (raise it "
           "with --max-pixels if the memory is there)";
    QTest::newRow("lowered pixel limit")
        << (QStringList({"render", "--size", "320x240", "--max-pixels", "76799"}) + out)
        << "--size 320x240 has 76800 pixels, more than the limit of 76799 (raise it with "
           "--max-pixels if the memory is there)";
    QTest::newRow("pixel limit not a number")
        << (QStringList({"render", "--max-pixels", "lots"}) + out)
        << "--max-pixels expects a positive whole number, found 'lots'";
    QTest::newRow("unknown shading")
        << (QStringList({"render", "--shading", "toon"}) + out)
        << "--shading expects phong, flat, gouraud or painter, found 'toon'";
    QTest::newRow("negative near") << (QStringList({"render", "--near", "-1"}) + out)
                                   << "--near expects a positive number, found '-1'";
    QTest::newRow("zero near") << (QStringList({"render", "--near", "0"}) + out)
                               << "--near expects a positive number, found '0'";
    QTest::newRow("no output") << QStringList({"render", "--size", "320x240"})
                               << "render needs --output FILE.png";
    QTest::newRow("explain not a pixel")
        << (QStringList({"render", "--explain-pixel", "a,b"}) + out)
        << "--explain-pixel expects X,Y such as 400,300, found 'a,b'";
    QTest::newRow("explain outside")
        << (QStringList({"render", "--size", "320x240", "--explain-pixel", "100,240"}) + out)
        << "--explain-pixel 100,240 is outside the 320x240 image";
    QTest::newRow("explain outside default size")
        << (QStringList({"render", "--explain-pixel", "800,10"}) + out)
        << "--explain-pixel 800,10 is outside the 800x600 image";
    QTest::newRow("unknown command") << QStringList({"paint", "--output", "out.png"})
                                     << "unknown command 'paint' (commands: render, run, compare, check, grade, "
                                        "bench, accuracy, stability, generate-default-scene, "
                                        "generate-lessons)";
    QTest::newRow("unknown option")
        << (QStringList({"render", "--bogus"}) + out) << "Unknown option 'bogus'.";
    QTest::newRow("stray argument")
        << (QStringList({"render", "scene.cfg"}) + out) << "unexpected argument 'scene.cfg'";
    QTest::newRow("option without value")
        << QStringList({"render", "--output"}) << "Missing value after '--output'.";
    QTest::newRow("generate without dir")
        << QStringList({"generate-default-scene"}) << "generate-default-scene needs --dir DIR";
    QTest::newRow("unknown camera format")
        << (QStringList({"render", "--camera", "c.cfg", "--camera-format", "ufrpe7"}) + out)
        << "--camera-format expects auto, ufpe, ufrpe6, ufrpe5 or keyvalue, found 'ufrpe7'";
    QTest::newRow("camera format in capitals")
        << (QStringList({"render", "--camera", "c.cfg", "--camera-format", "UFPE"}) + out)
        << "--camera-format expects auto, ufpe, ufrpe6, ufrpe5 or keyvalue, found 'UFPE'";
    QTest::newRow("unknown lighting format")
        << (QStringList({"render", "--lighting", "l.txt", "--lighting-format", "multi2"}) + out)
        << "--lighting-format expects auto, ufpe, multi, ufrpe or keyvalue, found 'multi2'";
    QTest::newRow("camera format without a camera")
        << (QStringList({"render", "--camera-format", "keyvalue"}) + out)
        << "--camera-format applies to the file of --camera, which is not given";
    QTest::newRow("lighting format without lighting")
        << (QStringList({"render", "--camera", "c.cfg", "--lighting-format", "multi"}) + out)
        << "--lighting-format applies to the file of --lighting, which is not given";
    QTest::newRow("run without a file") << QStringList({"run"}) << "run needs a command file";
    QTest::newRow("run with two files")
        << QStringList({"run", "a.txt", "b.txt"}) << "run takes one command file, found 2";
    QTest::newRow("run, pixel limit zero")
        << QStringList({"run", "a.txt", "--max-pixels", "0"})
        << "--max-pixels expects a positive whole number, found '0'";
    QTest::newRow("run, outdir without value")
        << QStringList({"run", "a.txt", "--outdir"}) << "Missing value after '--outdir'.";
    QTest::newRow("back faces unknown") << (QStringList({"render", "--back-faces", "hide"}) + out)
                                        << "--back-faces expects draw or cull, found 'hide'";
    QTest::newRow("bench, no frames") << QStringList({"bench", "--frames", "0"})
                                      << "--frames expects a whole number of at least 1, found '0'";
    QTest::newRow("bench, negative warm-up")
        << QStringList({"bench", "--warmup", "-1"})
        << "--warmup expects a whole number of at least 0, found '-1'";
    QTest::newRow("bench, zero threads") << QStringList({"bench", "--threads", "0"})
                                         << "--threads expects a whole number from 1 to 256, "
                                            "found '0'";
    QTest::newRow("bench, too many threads")
        << QStringList({"bench", "--threads", "100000"})
        << "--threads expects a whole number from 1 to 256, found '100000'";
    QTest::newRow("bench, no band rows")
        << QStringList({"bench", "--band-rows", "0"})
        << "--band-rows expects a whole number from 1 to 8, found '0'";
    QTest::newRow("bench, bands taller than a chunk")
        << QStringList({"bench", "--band-rows", "9"})
        << "--band-rows expects a whole number from 1 to 8, found '9'";
    QTest::newRow("bench, unknown format")
        << QStringList({"bench", "--format", "csv"}) << "--format expects md or json, found 'csv'";
    QTest::newRow("bench, unknown scene")
        << QStringList({"bench", "--scene", "teapot"})
        << "--scene expects one of triangle, zbuffer, near-plane, goblet, sphere, lights, "
           "painter-cycle, gouraud, sphere-1k, sphere-100k, sphere-1m, torus-1k, torus-100k, "
           "torus-1m, full-screen, found 'teapot'";
    QTest::newRow("unknown rules") << (QStringList({"render", "--rules", "d3d"}) + out)
                                   << "--rules expects course, gpu or hw2, found 'd3d'";
    QTest::newRow("accuracy, unknown format") << QStringList({"accuracy", "--format", "xml"})
                                              << "--format expects md, csv or json, found 'xml'";
    QTest::newRow("accuracy, supersample zero")
        << QStringList({"accuracy", "--supersample", "1,0"})
        << "--supersample expects whole numbers from 1 to 8 separated by commas, such as 1,2,4, "
           "found '1,0'";
    QTest::newRow("accuracy, repeats not a number")
        << QStringList({"accuracy", "--repeats", "many"})
        << "--repeats expects a whole number from 1 to 1000, found 'many'";
    QTest::newRow("accuracy, unknown scene")
        << QStringList({"accuracy", "--scene", "teapot"})
        << "--scene expects one of triangle, zbuffer, near-plane, goblet, sphere, lights, "
           "painter-cycle, gouraud, sphere-1k, sphere-100k, sphere-1m, torus-1k, torus-100k, "
           "torus-1m, full-screen, found 'teapot'";
    QTest::newRow("bench, scene and files")
        << QStringList({"bench", "--scene", "sphere-1k", "--object", "a.byu"})
        << "--scene replaces --camera, --lighting and --object";
}

void TestCli::usageErrors() {
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    CliRun run;
    RUN_CLI(run, arguments, dir.path());
    const QStringList err = linesOf(run.err);
    QCOMPARE(err.size(), 2);
    QCOMPARE(err[0], QStringLiteral("rasterlab-cli: ") + message);
    QCOMPARE(err[1], QString::fromLatin1(kTryHelp));
    QCOMPARE(run.out, QString());
    QCOMPARE(run.exitCode, 2);
    QVERIFY(!QFile::exists(dir.filePath("out.png")));
}

void TestCli::badInputFiles_data() {
    QTest::addColumn<QString>("option");
    QTest::addColumn<QString>("fileName");
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("message");  // %1: the file's path; lines apart with '\n'

    // Line 3 is "1.0   a 0.0": the 'a' is at column 7.
    QTest::newRow("letter for a coordinate")
        << "--object"
        << "letter.byu" << QByteArray("3 1\n0 0 0\n1.0   a 0.0\n0 1 0\n1 2 3\n")
        << "%1:3:7: expected a number for the y coordinate of vertex 2 of 3, found 'a'";
    // Line 7 is "2  4 5": the 5 is at column 6.
    QTest::newRow("index out of range")
        << "--object"
        << "range.byu" << QByteArray("4 2\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n1 2 3\n2  4 5\n")
        << "%1:7:6: triangle 2 refers to vertex 5, but the file declares only 4 vertices";
    QTest::newRow("index zero")
        << "--object"
        << "zero.byu" << QByteArray("3 1\n0 0 0\n1 0 0\n0 1 0\n0 1 2\n")
        << "%1:5:1: triangle 1 refers to vertex 0, but indices are 1-based (1 to 3)";
    // A blank first line: N is on line 3; the error points at the start of its line. The
    // camera was read (its layout noted); the render refuses it.
    QTest::newRow("camera N zero")
        << "--camera"
        << "n-zero.cfg" << QByteArray("\n0 -380 330\n  0 0 0\n0 0 1\n1 0.4 0.3\n")
        << kUfpeCameraNote +
               "\n%1:3:1: N, the view direction, is the zero vector: it must point from the "
               "camera toward the scene";
    // Line 4 is "1   0 0.3": hx is at column 5.
    QTest::newRow("camera hx zero")
        << "--camera"
        << "hx-zero.cfg" << QByteArray("0 -380 330\n0 380 -330\n0 0 1\n1   0 0.3\n")
        << kUfpeCameraNote +
               "\n%1:4:5: hx, the horizontal half-size of the window, is 0: the projection "
               "(d/hx) x/z divides by it";
    // Five lines with 3, 3, 3, 1, 2 numbers: no camera layout fits, none is one line away.
    QTest::newRow("camera in no layout")
        << "--camera"
        << "swapped.cfg" << QByteArray("0 -380 330\n0 380 -330\n0 0 1\n1\n0.4 0.3\n")
        << "%1:1:1: expected a camera in one of the layouts UFPE (C; N; V; d hx hy), UFRPE (N; "
           "V; d; hx; hy; C), UFRPE (C; N; V; hx hy; d) or key = value, found 5 lines with 3, 3, "
           "3, 1, 2 numbers (if the layout is known, choose it by hand: --camera-format / "
           "--lighting-format, or File > Course File Layouts)";
    // kd (line 4) written with a decimal comma.
    QTest::newRow("lighting decimal comma")
        << "--lighting"
        << "comma.txt"
        << QByteArray(
               "-260 -420 520\n0.35\n60 60 72\n0,85\n0.88 0.42 0.18\n0.6\n255 248 235\n"
               "40\n")
        << "%1:4:1: expected a number for kd, found '0,85' (the decimal separator is '.')";
    // Seven lines of eight: the file ends at line 8, column 1.
    QTest::newRow("lighting too short")
        << "--lighting"
        << "short.txt"
        << QByteArray("-260 -420 520\n0.35\n60 60 72\n0.85\n0.88 0.42 0.18\n0.6\n255 248 235\n")
        << "%1:8:1: expected n, the specular exponent (1 number), found the end of the file";
}

void TestCli::badInputFiles() {
    QFETCH(QString, option);
    QFETCH(QString, fileName);
    QFETCH(QByteArray, content);
    QFETCH(QString, message);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = writeFixture(dir, fileName, content);
    QVERIFY(!path.isEmpty());
    CliRun run;
    RUN_CLI(run, QStringList({"render", option, path, "--output", "out.png"}), dir.path());
    QCOMPARE(linesOf(run.err), message.arg(path).split(QLatin1Char('\n')));
    QCOMPARE(run.exitCode, 1);
    QVERIFY(!QFile::exists(dir.filePath("out.png")));
}

void TestCli::missingFile_data() {
    QTest::addColumn<QString>("option");
    QTest::newRow("camera") << "--camera";
    QTest::newRow("lighting") << "--lighting";
    QTest::newRow("object") << "--object";
}

void TestCli::missingFile() {
    QFETCH(QString, option);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("absent.txt");
    CliRun run;
    RUN_CLI(run, QStringList({"render", option, path, "--output", "out.png"}), dir.path());
    const QStringList err = linesOf(run.err);
    QCOMPARE(err.size(), 1);
    // The reason after "cannot open: " is the system's, in the user's language.
    const QString prefix = path + QStringLiteral(": cannot open: ");
    QVERIFY2(err[0].startsWith(prefix) && err[0].size() > prefix.size(), qPrintable(err[0]));
    QCOMPARE(run.exitCode, 1);
    QVERIFY(!QFile::exists(dir.filePath("out.png")));
}

void TestCli::unwritableOutput() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    CliRun run;
    RUN_CLI(run, QStringList({"render", "--size", "64x48", "--output", "no-such-dir/out.png"}),
            dir.path());
    const QStringList err = linesOf(run.err);
    QCOMPARE(err.size(), 1);
    const QString prefix = QStringLiteral("no-such-dir/out.png: cannot write the image: ");
    QVERIFY2(err[0].startsWith(prefix) && err[0].size() > prefix.size(), qPrintable(err[0]));
    QCOMPARE(run.exitCode, 1);
    QVERIFY(!run.out.contains(QStringLiteral("wrote")));
}

void TestCli::warnings_data() {
    QTest::addColumn<QString>("option");
    QTest::addColumn<QString>("fileName");
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("warning");  // %1: the file's path; lines apart with '\n'

    QTest::newRow("unused vertex")
        << "--object"
        << "unused.byu" << QByteArray("4 1\n0 0 0\n100 0 0\n0 100 0\n5 5 5\n1 2 3\n")
        << "%1: warning: 1 vertex of 4 is not used by any triangle";
    // Line 4 is "1 -0.4 0.3": hx is at column 3.
    QTest::newRow("negative hx")
        << "--camera"
        << "mirror.cfg" << QByteArray("0 -380 330\n0 380 -330\n0 0 1\n1 -0.4 0.3\n")
        << kUfpeCameraNote +
               "\n%1:4:3: warning: hx is negative: the image is mirrored left to right";
    // Line 2 is "0 380 -330 7": the extra 7 is at column 12. 3, 4, 3, 3 numbers fit no layout,
    // but UFPE's but for line 2: read as UFPE, whose reader names the extra value.
    QTest::newRow("extra value after N")
        << "--camera"
        << "extra.cfg" << QByteArray("0 -380 330\n0 380 -330 7\n0 0 1\n1 0.4 0.3\n")
        << "%1: note: read as a UFPE camera, C; N; V; d hx hy (no line contains '=' and the 4 "
           "lines have 3, 4, 3, 3 numbers: no layout fits exactly, and this one is one line away "
           "(line 2 has 4 numbers where N needs 3 numbers))\n"
           "%1:2:12: warning: ignored 1 value after N";
}

void TestCli::warnings() {
    QFETCH(QString, option);
    QFETCH(QString, fileName);
    QFETCH(QByteArray, content);
    QFETCH(QString, warning);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = writeFixture(dir, fileName, content);
    QVERIFY(!path.isEmpty());
    CliRun run;
    RUN_CLI(run, QStringList({"render", option, path, "--size", "160x120", "--output", "out.png"}),
            dir.path());
    QCOMPARE(linesOf(run.err), warning.arg(path).split(QLatin1Char('\n')));
    QCOMPARE(run.exitCode, 0);
    QVERIFY(run.out.contains(
        QStringLiteral("wrote %1 (image, 160x120)").arg(printedPath(dir, "out.png"))));
    QCOMPARE(QImage(dir.filePath("out.png")).size(), QSize(160, 120));
}

void TestCli::cameraFacingAway() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    // The default camera with N negated: it looks away from the knot.
    const QString path =
        writeFixture(dir, "away.cfg", "0 -380 330\n0 -380 330\n0 0 1\n1 0.4 0.3\n");
    QVERIFY(!path.isEmpty());
    CliRun run;
    RUN_CLI(run,
            QStringList({"render", "--camera", path, "--size", "200x150", "--output", "out.png"}),
            dir.path());
    QCOMPARE(linesOf(run.err),
             QStringList({kUfpeCameraNote.arg(path),
                          "trefoil.byu: warning: every triangle is behind the camera (is N "
                          "pointing away from the object?): the image is empty. The plain "
                          "divide of seed 000, x/z and y/z with z < 0, would draw all 7776 of "
                          "them: the object's point reflection through the eye (turned half a "
                          "turn on the screen), where the z-buffer, keeping the smallest z, "
                          "keeps the side farthest from the camera",
                          "hint: --naive-projection draws the 7776 triangles behind the eye "
                          "with seed 000's plain divide"}));
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.contains(QStringLiteral("  7776 triangles, phong shading, 0 pixels covered")),
             qPrintable(run.out));
    const QImage image(dir.filePath("out.png"));
    QCOMPARE(image.size(), QSize(200, 150));
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (image.pixel(x, y) != qRgba(0, 0, 0, 255))
                QFAIL(qPrintable(
                    QStringLiteral("pixel (%1, %2) is not the background").arg(x).arg(y)));
}

// The course variants from the command line: a key = value file holding both the default
// scene's camera and its lighting renders the default image byte for byte, with a note for
// each part; a layout given with --camera-format is used as given, and a wrong one names the
// layout detection would choose; a Bezier surface object is evaluated.
void TestCli::courseVariants() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString scene = writeFixture(dir, "scene.txt",
                                       "C = 0 -380 330\nN = 0 380 -330\nV = 0 0 1\nU = 1 0 0\n"
                                       "d = 1\nhx = 0.4\nhy = 0.3\n"
                                       "Iamb = 60 60 72\nKa = 0.35\nIl = 255 248 235\n"
                                       "Pl = -260 -420 520\nKd = 0.85 0.85 0.85\n"
                                       "Od = 0.88 0.42 0.18\nKs = 0.6\neta = 40\n");
    QVERIFY(!scene.isEmpty());
    CliRun run;
    RUN_CLI(run, QStringList({"render", "--size", "200x150", "--output", "default.png"}),
            dir.path());
    QCOMPARE(run.exitCode, 0);
    RUN_CLI(run,
            QStringList({"render", "--camera", scene, "--lighting", scene, "--size", "200x150",
                         "--output", "keyvalue.png"}),
            dir.path());
    QCOMPARE(run.exitCode, 0);
    QCOMPARE(linesOf(run.err),
             QStringList({scene + ": note: read as a key = value camera (lines contain '=')",
                          scene + ":4:1: note: ignored U: the camera's axes come from N and V",
                          scene + ": note: read as a key = value lighting file (lines contain "
                                  "'=')"}));
    const QImage reference(dir.filePath("default.png"));
    const QImage keyValue(dir.filePath("keyvalue.png"));
    QVERIFY(!reference.isNull());
    QVERIFY(countTrue(coverage(reference)) > 1000);
    QVERIFY(keyValue == reference);

    // The default camera as six UFRPE lines, read with the layout given.
    const QString ufrpe6 =
        writeFixture(dir, "camera6.txt", "0 380 -330\n0 0 1\n1\n0.4\n0.3\n0 -380 330\n");
    RUN_CLI(run,
            QStringList({"render", "--camera", ufrpe6, "--camera-format", "ufrpe6", "--size",
                         "200x150", "--output", "ufrpe6.png"}),
            dir.path());
    QCOMPARE(run.exitCode, 0);
    QCOMPARE(linesOf(run.err),
             QStringList(ufrpe6 + ": note: read as a UFRPE camera, N; V; d; hx; hy; C (the "
                                  "layout was chosen, not detected)"));
    QVERIFY(QImage(dir.filePath("ufrpe6.png")) == reference);

    // The same file forced into the five-line layout: that layout's error, then the hint.
    RUN_CLI(run,
            QStringList({"render", "--camera", ufrpe6, "--camera-format", "ufrpe5", "--output",
                         "wrong.png"}),
            dir.path());
    QCOMPARE(run.exitCode, 1);
    QCOMPARE(
        linesOf(run.err),
        QStringList(ufrpe6 + ":3:2: expected 3 numbers for V, found 1; the layout was set to UFRPE "
                             "(C; N; V; hx hy; d), but the file looks like UFRPE (N; V; d; hx; hy; "
                             "C) (no line contains '=' and the 6 lines have 3, 3, 1, 1, 1, 3 "
                             "numbers, as in that layout)"));
    QVERIFY(!QFile::exists(dir.filePath("wrong.png")));

    // A course Bezier surface as the object.
    const QString surface = writeFixture(dir, "superficie.byu",
                                         "1 2\n4\n-150 -150 400\n-50 -150 200\n50 -150 -100\n"
                                         "-150 -50 100\n-50 -50 300\n50 -50 0\n");
    RUN_CLI(run,
            QStringList(
                {"render", "--object", surface, "--size", "200x150", "--output", "surface.png"}),
            dir.path());
    QCOMPARE(run.exitCode, 0);
    QCOMPARE(linesOf(run.err).value(0),
             surface +
                 ": note: read as a course Bezier surface (the header 'm n' is followed by "
                 "a line of one number, the evaluations per direction): degrees 1 x 2, "
                 "evaluated on a 4 x 4 grid into 16 vertices and 18 triangles");
    QVERIFY2(run.out.contains(QStringLiteral("  18 triangles, phong shading, ")),
             qPrintable(run.out));
}

void TestCli::explainPixel_data() {
    QTest::addColumn<QPoint>("pixel");
    QTest::addColumn<bool>("covered");
    QTest::newRow("on the knot") << QPoint(400, 350) << true;
    QTest::newRow("corner") << QPoint(0, 0) << false;
    QTest::newRow("hole of the knot") << QPoint(400, 300) << false;
}

void TestCli::explainPixel() {
    QFETCH(QPoint, pixel);
    QFETCH(bool, covered);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString xy = QStringLiteral("%1,%2").arg(pixel.x()).arg(pixel.y());
    CliRun run;
    RUN_CLI(run, QStringList({"render", "--output", "out.png", "--explain-pixel", xy}), dir.path());
    QCOMPARE(run.err, QString());
    QCOMPARE(run.exitCode, 0);
    const QStringList out = linesOf(run.out);
    const qsizetype start =
        out.indexOf(QStringLiteral("pixel (%1, %2)").arg(pixel.x()).arg(pixel.y()));
    QVERIFY2(start >= 0, qPrintable(run.out));
    const QStringList story = out.mid(start + 1);
    const QImage image(dir.filePath("out.png"));
    QCOMPARE(image.size(), QSize(800, 600));
    const QRgb colour = image.pixel(pixel);

    if (!covered) {
        QCOMPARE(story, QStringList("  no triangle covers this pixel: it keeps the background "
                                    "colour"));
        QCOMPARE(colour, qRgba(0, 0, 0, 255));
        return;
    }
    QVERIFY2(story.contains(QStringLiteral("  depth test, in drawing order:")),
             qPrintable(run.out));
    QCOMPARE(story
                 .filter(QRegularExpression(QStringLiteral("^  shading \\(phong\\) of the "
                                                           "winner, triangle \\d+ of "
                                                           "trefoil.byu")))
                 .size(),
             1);
    QCOMPARE(story.filter(QStringLiteral("    ambient  Ia*ka          = ")).size(), 1);
    // The default lighting: Ia = (60, 60, 72), ka = 0.35.
    QVERIFY(story.contains(QStringLiteral("    ambient  Ia*ka          = (21, 21, 25.2)")));
    // The bytes the story ends with are the pixel's colour in the image.
    static const QRegularExpression bytes(QStringLiteral("-> bytes \\((\\d+), (\\d+), (\\d+)\\)"));
    const QStringList colourLines = story.filter(bytes);
    QCOMPARE(colourLines.size(), 1);
    const auto match = bytes.match(colourLines.first());
    QCOMPARE(
        qRgba(match.captured(1).toInt(), match.captured(2).toInt(), match.captured(3).toInt(), 255),
        colour);
}

void TestCli::generateDefaultScene() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    CliRun run;
    RUN_CLI(run, QStringList({"generate-default-scene", "--dir", "scene/nested"}), dir.path());
    QCOMPARE(run.err, QString());
    QCOMPARE(run.exitCode, 0);
    const QStringList names = {"camera.cfg", "lighting.txt", "trefoil.byu"};
    QStringList expectedOut;
    for (const QString& name : names)
        expectedOut << QStringLiteral("wrote ") + printedPath(dir, "scene/nested/" + name);
    QCOMPARE(linesOf(run.out), expectedOut);

    // The committed default scene must be the generator's output, byte for byte.
    const QString committed = testing::sourceDir() + QStringLiteral("/resources/default-scene/");
    for (const QString& name : names) {
        const QByteArray generated = testing::readFile(dir.filePath("scene/nested/" + name));
        const QByteArray reference = testing::readFile(committed + name);
        QVERIFY2(!generated.isEmpty(), qPrintable(name));
        QVERIFY2(!reference.isEmpty(), qPrintable(committed + name));
        QVERIFY2(generated == reference,
                 qPrintable(QStringLiteral("%1 differs from the generator's output; run "
                                           "rasterlab-cli generate-default-scene --dir %2")
                                .arg(committed + name, committed)));
    }
}

// Under a locale whose decimal separator is a comma (pt_BR, the course's own), every
// number the CLI writes, in files and in messages, still uses '.'. The locale is compiled
// into a scratch folder with localedef, so the test does not depend on installed locales.
void TestCli::decimalCommaLocale() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QProcess localedef;
    localedef.start(QStringLiteral("localedef"),
                    {QStringLiteral("-i"), QStringLiteral("pt_BR"), QStringLiteral("-f"),
                     QStringLiteral("UTF-8"), dir.filePath(QStringLiteral("pt_BR.UTF-8"))});
    if (!localedef.waitForFinished(60000) || localedef.exitStatus() != QProcess::NormalExit ||
        !QFileInfo::exists(dir.filePath(QStringLiteral("pt_BR.UTF-8/LC_NUMERIC"))))
        QSKIP("localedef could not build pt_BR.UTF-8 (is the 'locales' package installed?)");
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert(QStringLiteral("LOCPATH"), dir.path());
    env.insert(QStringLiteral("LC_ALL"), QStringLiteral("pt_BR.UTF-8"));
    env.insert(QStringLiteral("LANG"), QStringLiteral("pt_BR.UTF-8"));
    QProcess locale;
    locale.setProcessEnvironment(env);
    locale.start(QStringLiteral("locale"), {QStringLiteral("decimal_point")});
    QVERIFY(locale.waitForFinished(10000));
    QCOMPARE(QString::fromUtf8(locale.readAllStandardOutput()).trimmed(), QStringLiteral(","));

    // The default scene's files, written under pt_BR, are still the committed ones.
    CliRun run;
    RUN_CLI(run, QStringList({"generate-default-scene", "--dir", "scene"}), dir.path());
    QCOMPARE(run.exitCode, 0);
    for (const char* name : {"camera.cfg", "lighting.txt", "trefoil.byu"}) {
        const QString file = QString::fromUtf8(name);
        QCOMPARE(testing::readFile(dir.filePath(QStringLiteral("scene/") + file)),
                 testing::readFile(testing::sourceDir() +
                                   QStringLiteral("/resources/default-scene/") + file));
    }
    // Messages: the numbers in an error keep their points.
    const QString camera = writeFixture(dir, QStringLiteral("parallel.cfg"),
                                        "0 0 0\n0.667 0.172 -1\n1.334 0.344 -2\n1 1 1\n");
    QVERIFY(runCli({"render", "--camera", camera, "--output", "x.png"}, dir.path(), run, env));
    QCOMPARE(run.exitCode, 1);
    QVERIFY2(run.err.contains(
                 QStringLiteral("V (1.334, 0.344, -2) is parallel to N (0.667, 0.172, -1)")),
             qPrintable(run.err));
    // The pixel explanation: no decimal commas anywhere.
    QVERIFY(runCli({"render", "--output", "y.png", "--explain-pixel", "460,355"}, dir.path(), run,
                   env));
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.contains(QStringLiteral("N.L = 0.")), qPrintable(run.out));
    QVERIFY2(!run.out.contains(QRegularExpression(QStringLiteral("\\d,\\d"))), qPrintable(run.out));
}

// A frame larger than the memory the process may use: a clear message and exit 1, not a
// crash. The address space is limited with the shell's ulimit.
void TestCli::outOfMemory() {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    QSKIP("sanitizers reserve more address space than the limit this test sets");
#endif
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QProcess process;
    process.setWorkingDirectory(dir.path());
    process.start(
        QStringLiteral("/bin/sh"),
        {QStringLiteral("-c"), QStringLiteral("ulimit -v 1500000 && exec \"$0\" \"$@\""),
         testing::cliPath(), QStringLiteral("render"), QStringLiteral("--size"),
         QStringLiteral("11000x11000"), QStringLiteral("--max-pixels"), QStringLiteral("150000000"),
         QStringLiteral("--output"), QStringLiteral("big.png")});
    QVERIFY(process.waitForFinished(120000));
    QCOMPARE(process.exitStatus(), QProcess::NormalExit);
    QCOMPARE(process.exitCode(), 1);
    QCOMPARE(linesOf(QString::fromUtf8(process.readAllStandardError())),
             QStringList(QStringLiteral("rasterlab-cli: not enough memory for this render (try a "
                                        "smaller --size)")));
    QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("big.png"))));
}

void TestCli::help_data() {
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("usage");  // the first line of stdout

    QTest::newRow("--help") << QStringList("--help") << 0
                            << "Usage: rasterlab-cli <command> [options]";
    QTest::newRow("help") << QStringList("help") << 0 << "Usage: rasterlab-cli <command> [options]";
    QTest::newRow("render --help")
        << QStringList({"render", "--help"}) << 0 << "Usage: rasterlab-cli render [options]";
    QTest::newRow("generate --help") << QStringList({"generate-default-scene", "--help"}) << 0
                                     << "Usage: rasterlab-cli generate-default-scene [options]";
    QTest::newRow("run --help") << QStringList({"run", "--help"}) << 0
                                << "Usage: rasterlab-cli run [options] FILE";
    QTest::newRow("no arguments") << QStringList() << 2
                                  << "Usage: rasterlab-cli <command> [options]";
}

void TestCli::help() {
    QFETCH(QStringList, arguments);
    QFETCH(int, exitCode);
    QFETCH(QString, usage);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    CliRun run;
    RUN_CLI(run, arguments, dir.path());
    QCOMPARE(run.exitCode, exitCode);
    QCOMPARE(run.err, QString());
    const QStringList out = linesOf(run.out);
    QVERIFY(out.size() > 2);
    QCOMPARE(out.first(), usage);
    if (arguments.value(0) == QStringLiteral("render"))
        for (const char* option : {"--output", "--size", "--shading", "--explain-pixel",
                                   "--camera-format", "--lighting-format"})
            QVERIFY2(run.out.contains(QLatin1String(option)), option);
}

void TestCli::courseSamples_data() {
    QTest::addColumn<QString>("shading");
    QTest::newRow("phong") << "phong";
    QTest::newRow("flat") << "flat";
    QTest::newRow("gouraud") << "gouraud";
}

void TestCli::courseSamples() {
    QFETCH(QString, shading);
    const QString samples = testing::samplesDir();
    if (samples.isEmpty())
        QSKIP("the course samples are absent (set RASTERLAB_SAMPLES or RASTERLAB_SAMPLES_DIR)");
    const QDir ufpe(samples + QStringLiteral("/course/ufpe"));
    for (const char* name : {"calice2.byu", "calice2.cfg", "iluminacao.txt"})
        if (!ufpe.exists(QLatin1String(name)))
            QSKIP(qPrintable(ufpe.filePath(QLatin1String(name)) + QStringLiteral(" is absent")));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    CliRun run;
    RUN_CLI(run,
            QStringList({"render", "--camera", ufpe.filePath("calice2.cfg"), "--lighting",
                         ufpe.filePath("iluminacao.txt"), "--object", ufpe.filePath("calice2.byu"),
                         "--shading", shading, "--output", "calice.png"}),
            dir.path());
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.contains(QStringLiteral("  2120 triangles, %1 shading, ").arg(shading)),
             qPrintable(run.out));
    QVERIFY(!run.out.contains(QStringLiteral("rendering the embedded default scene")));
    const QImage image(dir.filePath("calice.png"));
    QCOMPARE(image.size(), QSize(800, 600));

    // White light, Od = (0, 0.8, 0), grey ambient: red and blue get only the ambient and
    // the white highlight, green also the diffuse term. Green may fall one unit short where
    // a pixel centre lies on an edge: a barycentric of -6e-8 turns 64 into 63.99999, which
    // the course's truncation makes 63 (seen in Gouraud on calice2).
    qsizetype lit = 0, green = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QRgb c = image.pixel(x, y);
            if (isBlack(c)) continue;
            ++lit;
            if (qGreen(c) + 1 < qRed(c) || qGreen(c) + 1 < qBlue(c))
                QFAIL(qPrintable(QStringLiteral("pixel (%1, %2) = (%3, %4, %5) is not green")
                                     .arg(x)
                                     .arg(y)
                                     .arg(qRed(c))
                                     .arg(qGreen(c))
                                     .arg(qBlue(c))));
            if (qGreen(c) > qRed(c) + 32 && qGreen(c) > qBlue(c) + 32) ++green;
        }
    }
    QVERIFY2(lit > 10000, qPrintable(QString::number(lit)));
    QVERIFY2(
        green * 10 > lit * 9,
        qPrintable(QStringLiteral("%1 of %2 lit pixels are clearly green").arg(green).arg(lit)));
}

// A command file: one triangle, screen (0, 0), (8, 0), (0, 4) of an 8x4 image, rows 0..3
// covering 8, 6, 4 and 2 pixels, in (1, 0.5, 0.25) -> bytes (255, 127, 63); then an unknown
// command, skipped with a note.
void TestCli::runExplainsTexel() {
    // s runs from -1 at x = 0 to 0 at x = 8 along row 0, on a 3x1 texture. At (6, 0),
    // s = -0.25: the seed's text wraps it to 0.75 and takes the texel nearest to 2.25, 2; the
    // reference images' (int)(3s + 0.5) = (int)(-0.25) = 0 gives texel 0, which the hw2 rules
    // read. --explain-pixel says both.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QImage texture(3, 1, QImage::Format_RGBA8888);
    for (int i = 0; i < 3; ++i) texture.setPixelColor(i, 0, QColor(40 + 50 * i, 40, 200));
    QVERIFY(texture.save(dir.filePath("grid.png")));
    const QString path = writeFixture(dir, "tex.txt",
                                      "png 8 8 tex.png\ntexture grid.png\ntexcoord -1 0\n"
                                      "xyz -1 -1 0.5\ntexcoord 0 0\nxyz 1 -1 0.5\ntexcoord -1 0\n"
                                      "xyz -1 1 0.5\ntrit 1 2 3\n");
    QVERIFY(!path.isEmpty());
    CliRun run;
    RUN_CLI(run, QStringList({"run", path, "--explain-pixel", "6,0"}), dir.path());
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.contains("    texture at (s, t) = (-0.25, 0): texel (0, 0)\n"
                              "    here seed 001's text and its reference images disagree: the "
                              "texel nearest to (s w, t h) once the coordinates wrap is (2, 0), "
                              "the images' (int)(s w + 0.5) mod w gives (0, 0); these rules "
                              "follow the images\n"),
             qPrintable(run.out));
    QCOMPARE(QImage(dir.filePath("tex.png")).pixelColor(6, 0), QColor(40, 40, 200));
}

void TestCli::runCommandFile() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = writeFixture(dir, "tri.txt",
                                      "png 8 4 tri.png\nxyz -1 -1 0.5\nxyz 1 -1 0.5\n"
                                      "xyz -1 1 0.5\ncolor 1 0.5 0.25\ntrif 1 2 3\nwobble 3\n");
    QVERIFY(!path.isEmpty());
    CliRun run;
    RUN_CLI(run, QStringList({"run", path, "--outdir", "images/out"}), dir.path());
    QCOMPARE(run.exitCode, 0);
    QCOMPARE(linesOf(run.err),
             QStringList(path + ":7:1: note: skipped 1 line with the unknown command 'wobble'"));
    const QStringList out = linesOf(run.out);
    QCOMPARE(out.size(), 2);
    QCOMPARE(out[0],
             QStringLiteral("wrote %1 (image, 8x4)").arg(printedPath(dir, "images/out/tri.png")));
    static const QRegularExpression summary(
        QStringLiteral("^  1 triangles in 1 draws, 20 pixels covered, [0-9.]+ ms$"));
    QVERIFY2(summary.match(out[1]).hasMatch(), qPrintable(out[1]));

    // 8-bit RGBA: covered pixels opaque, the others transparent black.
    const QImage image(dir.filePath("images/out/tri.png"));
    QVERIFY(!image.isNull());
    QCOMPARE(image.size(), QSize(8, 4));
    QVERIFY(image.hasAlphaChannel());
    int opaque = 0;
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 8; ++x) {
            const bool inside = x < 8 - 2 * y;
            const QRgb expected = inside ? qRgba(255, 127, 63, 255) : qRgba(0, 0, 0, 0);
            QVERIFY2(image.pixel(x, y) == expected,
                     qPrintable(QStringLiteral("pixel (%1, %2) is #%3, expected #%4")
                                    .arg(x)
                                    .arg(y)
                                    .arg(image.pixel(x, y), 8, 16, QLatin1Char('0'))
                                    .arg(expected, 8, 16, QLatin1Char('0'))));
            opaque += inside ? 1 : 0;
        }
    }
    QCOMPARE(opaque, 20);
    QVERIFY(!QFile::exists(dir.filePath("tri.png")));  // only into --outdir
}

void TestCli::runWritesEveryImage() {
    // Two png commands: two images, written into the current folder without --outdir.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkdir("files"));
    const QString path = writeFixture(dir, "files/two.txt",
                                      "png 4 4 first.png\nxyz -1 -1 0\nxyz 1 -1 0\nxyz -1 1 0\n"
                                      "trif 1 2 3\npng 6 2 second.png\ntrif 1 2 3\ntrif 3 2 1\n");
    QVERIFY(!path.isEmpty());
    CliRun run;
    RUN_CLI(run, QStringList({"run", "files/two.txt"}), dir.path());
    QCOMPARE(run.err, QString());
    QCOMPARE(run.exitCode, 0);
    const QStringList out = linesOf(run.out);
    QCOMPARE(out.size(), 4);
    QCOMPARE(out[0], QStringLiteral("wrote %1 (image, 4x4)").arg(printedPath(dir, "first.png")));
    // (0, 0), (4, 0), (0, 4): 4 + 3 + 2 + 1 pixels.
    QVERIFY2(out[1].startsWith(QStringLiteral("  1 triangles in 1 draws, 10 pixels covered, ")),
             qPrintable(out[1]));
    QCOMPARE(out[2], QStringLiteral("wrote %1 (image, 6x2)").arg(printedPath(dir, "second.png")));
    QVERIFY2(out[3].startsWith(QStringLiteral("  2 triangles in 1 draws, ")), qPrintable(out[3]));
    QCOMPARE(QImage(dir.filePath("first.png")).size(), QSize(4, 4));
    QCOMPARE(QImage(dir.filePath("second.png")).size(), QSize(6, 2));
    QVERIFY(!QFile::exists(dir.filePath("files/first.png")));
}

void TestCli::runBadCommandFile_data() {
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("message");  // after "<path>:"
    // "xyz 1 b 3": the b is at column 7.
    QTest::newRow("letter for a number") << QByteArray("png 8 8 out.png\nxyz 1 b 3\n")
                                         << "2:7: expected a number in 'xyz' (x y z), found 'b'";
    // "trif 1 2 4": the 4 is at column 10.
    QTest::newRow("index out of range")
        << QByteArray("png 8 8 out.png\nxyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\ntrif 1 2 4\n")
        << "5:10: 'trif' refers to vertex 4, but only 3 vertices are defined so far";
    QTest::newRow("drawing before png")
        << QByteArray("xyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\ntrif 1 2 3\npng 8 8 out.png\n")
        << "4:1: expected a 'png width height file' command before 'trif'";
    // "png 8 -8 out.png": the -8 is at column 7.
    QTest::newRow("bad png size") << QByteArray("png 8 -8 out.png\n")
                                  << "1:7: expected the image height (a whole number from 1 to "
                                     "65536), found '-8'";
    QTest::newRow("trit without a texture")
        << QByteArray("png 8 8 out.png\nxyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\ntrit 1 2 3\n")
        << "5:1: 'trit' needs a texture: expected a 'texture file.png' command before it";
    QTest::newRow("no png") << QByteArray("xyz 0 0 0\n")
                            << "2:1: expected a 'png width height file' command, found none";
}

void TestCli::runBadCommandFile() {
    QFETCH(QByteArray, content);
    QFETCH(QString, message);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = writeFixture(dir, "bad.txt", content);
    QVERIFY(!path.isEmpty());
    CliRun run;
    RUN_CLI(run, QStringList({"run", path, "--outdir", "out"}), dir.path());
    QCOMPARE(run.exitCode, 1);
    QCOMPARE(linesOf(run.err), QStringList(path + QLatin1Char(':') + message));
    QCOMPARE(run.out, QString());
    QVERIFY(!QFile::exists(dir.filePath("out/out.png")));
}

void TestCli::bench_data() {
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("triangles");
    QTest::addColumn<int>("threads");
    QTest::addColumn<bool>("zBufferKept");
    // Draws whose triangle normals and vertex normals are left out (nothing reads them).
    QTest::addColumn<int>("withoutTriangleNormals");
    QTest::addColumn<int>("withoutVertexNormals");
    QTest::newRow("default scene, 2 threads")
        << QStringList({"--size", "200x150", "--threads", "2"}) << 7776 << 2 << false << 1 << 0;
    QTest::newRow("sphere, gouraud, 1 thread")
        << QStringList({"--scene", "sphere-1k", "--size", "160x120", "--shading", "gouraud",
                        "--threads", "1"})
        << 1000 << 1 << false << 1 << 0;
    QTest::newRow("sphere, gouraud, 1 thread, z-buffer kept")
        << QStringList({"--scene", "sphere-1k", "--size", "160x120", "--shading", "gouraud",
                        "--threads", "1", "--keep-depth"})
        << 1000 << 1 << true << 1 << 0;
    QTest::newRow("sphere, gouraud, 2 threads, bands of 3 rows")
        << QStringList({"--scene", "sphere-1k", "--size", "160x120", "--shading", "gouraud",
                        "--threads", "2", "--band-rows", "3"})
        << 1000 << 2 << false << 1 << 0;
    QTest::newRow("torus, flat, 2 threads")
        << QStringList(
               {"--scene", "torus-1k", "--size", "160x120", "--shading", "flat", "--threads", "2"})
        << 1000 << 2 << false << 0 << 1;
}

void TestCli::bench() {
    QFETCH(QStringList, arguments);
    QFETCH(int, triangles);
    QFETCH(int, threads);
    QFETCH(bool, zBufferKept);
    QFETCH(int, withoutTriangleNormals);
    QFETCH(int, withoutVertexNormals);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    CliRun run;
    RUN_CLI(run, QStringList({"bench", "--frames", "5", "--format", "json"}) + arguments,
            dir.path());
    QCOMPARE(run.exitCode, 0);
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(run.out.toUtf8(), &error);
    QVERIFY2(doc.isObject(), qPrintable(error.errorString() + QStringLiteral(": ") + run.out));
    const QJsonObject o = doc.object();
    QCOMPARE(o.value(QStringLiteral("triangles")).toInt(), triangles);
    QCOMPARE(o.value(QStringLiteral("threads")).toInt(), threads);
    QCOMPARE(o.value(QStringLiteral("frames")).toInt(), 5);
    QCOMPARE(o.value(QStringLiteral("z_buffer_kept")).toBool(!zBufferKept), zBufferKept);
    QCOMPARE(o.value(QStringLiteral("draws_without_triangle_normals")).toInt(-1),
             withoutTriangleNormals);
    QCOMPARE(o.value(QStringLiteral("draws_without_vertex_normals")).toInt(-1),
             withoutVertexNormals);
    const QString size = arguments.at(arguments.indexOf(QStringLiteral("--size")) + 1);
    QCOMPARE(QStringLiteral("%1x%2")
                 .arg(o.value(QStringLiteral("width")).toInt())
                 .arg(o.value(QStringLiteral("height")).toInt()),
             size);
    const double median = o.value(QStringLiteral("median_ms")).toDouble();
    const double fastest = o.value(QStringLiteral("min_ms")).toDouble();
    const double slowest = o.value(QStringLiteral("max_ms")).toDouble();
    QVERIFY(fastest > 0.0 && fastest <= median && median <= slowest);
    QVERIFY(o.value(QStringLiteral("covered_pixels")).toInt() > 0);
    // Depth first: every covered pixel had at least one fragment, shaded once.
    QVERIFY(o.value(QStringLiteral("fragments")).toInt() >=
            o.value(QStringLiteral("covered_pixels")).toInt());
    QVERIFY(o.value(QStringLiteral("peak_rss_mib")).toDouble() > 1.0);
    const QJsonObject stages = o.value(QStringLiteral("stages_ms")).toObject();
    QCOMPARE(stages.size(), 7);
    double sum = 0.0;
    for (const QJsonValue& v : stages) sum += v.toDouble();
    QVERIFY(sum > 0.0);
    // The kernels this processor runs (multiversion.h), one of the three builds.
    const QString kernels = o.value(QStringLiteral("kernels")).toString();
    QVERIFY2(QStringList({"x86-64-v4 (AVX-512)", "x86-64-v3 (AVX2)", "x86-64", "baseline"})
                 .contains(kernels),
             qPrintable(kernels));
    QCOMPARE(kernels, QString::fromLatin1(rl::kernelLevel()));
    // Their width: eight lanes with AVX2 and AVX-512, four with the baseline clone.
    QCOMPARE(o.value(QStringLiteral("kernel_lanes")).toInt(), rl::kernelLanes());
    if (kernels.startsWith(QLatin1String("x86-64-v")))
        QCOMPARE(rl::kernelLanes(), 8);
    else if (kernels == QLatin1String("x86-64"))
        QCOMPARE(rl::kernelLanes(), 4);
    // The bands' rows: as asked, or a chunk's (8); and the L2 cache a thread has.
    const bool inBands = o.value(QStringLiteral("shaded_in_bands")).toBool();
    const qsizetype asked = arguments.indexOf(QStringLiteral("--band-rows"));
    const std::size_t l2 = rl::l2CachePerThread(threads);
    const int rows = !inBands ? 0 : asked >= 0 ? arguments.at(asked + 1).toInt() : rl::kRowChunk;
    QCOMPARE(inBands, !zBufferKept);
    QCOMPARE(o.value(QStringLiteral("band_rows")).toInt(-1), rows);
    // null where sysfs and sysconf do not say.
    QCOMPARE(o.value(QStringLiteral("l2_cache_per_thread_kib")).toInteger(-1),
             l2 >= 1024 ? qint64(l2 / 1024) : -1);
    // The Markdown table carries the same scene.
    CliRun md;
    RUN_CLI(md, QStringList({"bench", "--frames", "1"}) + arguments, dir.path());
    QCOMPARE(md.exitCode, 0);
    QVERIFY(md.out.startsWith(QStringLiteral("| scene | size | shading | threads |")));
    QVERIFY(md.out.contains(QStringLiteral("| ") + size + QStringLiteral(" |")));
    QVERIFY(md.out.contains(QStringLiteral("| scan conversion | ")));
    QVERIFY(md.out.contains(QStringLiteral("Memory: peak ")));
    QVERIFY(md.out.contains(QStringLiteral(" Kernels: %1, %2 pixels at a time.\n")
                                .arg(kernels)
                                .arg(rl::kernelLanes())));
    if (inBands)
        QVERIFY(md.out.contains(QStringLiteral("each band of %1 row(s) shaded by the thread that "
                                               "tested it")
                                    .arg(rows)) &&
                md.out.contains(l2 >= 1024
                                    ? QStringLiteral("L2 cache: %1 KiB a thread).").arg(l2 / 1024)
                                    : QStringLiteral("L2 cache: not known).")));
    QVERIFY(md.out.contains(QStringLiteral(" Normals: only those the shading reads (left out: "
                                           "the triangles' of %1 draw(s), the vertices' of %2).")
                                .arg(withoutTriangleNormals)
                                .arg(withoutVertexNormals)));
    if (zBufferKept) {
        // The same frame as without --keep-depth.
        CliRun band;
        RUN_CLI(band,
                QStringList({"bench", "--frames", "1", "--format", "json"}) +
                    arguments.mid(0, arguments.indexOf(QStringLiteral("--keep-depth"))),
                dir.path());
        QCOMPARE(band.exitCode, 0);
        const QJsonObject b = QJsonDocument::fromJson(band.out.toUtf8()).object();
        QCOMPARE(b.value(QStringLiteral("z_buffer_kept")).toBool(true), false);
        for (const char* key : {"covered_pixels", "fragments", "triangles"})
            QCOMPARE(b.value(QLatin1String(key)).toInt(-1), o.value(QLatin1String(key)).toInt());
    }
    QVERIFY(md.out.contains(zBufferKept
                                ? QStringLiteral("Z-buffer: kept whole (--keep-depth).")
                                : QStringLiteral("Z-buffer: a band of rows per thread, in the "
                                                 "cache.")));
}

void TestCli::hugeFileFailsFast() {
    // A gigabyte of garbage (a sparse file: no disk is used) is refused from its size,
    // before a byte is read: the process stays small and quick.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    for (const char* name : {"garbage.byu", "garbage.txt"}) {
        QFile file(dir.filePath(QLatin1String(name)));
        QVERIFY(file.open(QIODevice::WriteOnly));
        QVERIFY(file.resize(qint64(1) << 30));
    }
    CliRun run;
    RUN_CLI(run, QStringList({"render", "--object", "garbage.byu", "--output", "out.png"}),
            dir.path());
    QCOMPARE(run.exitCode, 1);
    QCOMPARE(linesOf(run.err),
             QStringList({"garbage.byu: the file has 1024 MiB, more than the 512 MiB an input "
                          "file may have"}));
    QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("out.png"))));
    CliRun command;
    RUN_CLI(command, QStringList({"run", "garbage.txt"}), dir.path());
    QCOMPARE(command.exitCode, 1);
    QCOMPARE(linesOf(command.err),
             QStringList({"garbage.txt: the file has 1024 MiB, more than the 512 MiB an input "
                          "file may have"}));
}

void TestCli::rulesChangeTheImage() {
    // The default scene under each rule set: the same picture, but not the same pixels (the
    // course samples pixel corners with whole-pixel vertices, gpu and hw2 do not).
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QMap<QString, QImage> images;
    for (const char* rules : {"course", "gpu", "hw2"}) {
        CliRun run;
        const QString name = QStringLiteral("%1.png").arg(QLatin1String(rules));
        RUN_CLI(run,
                QStringList({"render", "--size", "200x150", "--rules", QLatin1String(rules),
                             "--output", name}),
                dir.path());
        QCOMPARE(run.exitCode, 0);
        images[QLatin1String(rules)] = QImage(dir.filePath(name));
    }
    const auto differing = [](const QImage& a, const QImage& b) {
        int n = 0;
        for (int y = 0; y < a.height(); ++y)
            for (int x = 0; x < a.width(); ++x) n += a.pixel(x, y) != b.pixel(x, y) ? 1 : 0;
        return n;
    };
    const int covered = int(countTrue(coverage(images[QStringLiteral("gpu")])));
    QVERIFY(covered > 2000);
    const int courseVsGpu =
        differing(images[QStringLiteral("course")], images[QStringLiteral("gpu")]);
    QVERIFY2(courseVsGpu > covered / 10, qPrintable(QString::number(courseVsGpu)));
    QVERIFY(differing(images[QStringLiteral("gpu")], images[QStringLiteral("hw2")]) > 0);
}

void TestCli::accuracyJson() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    CliRun run;
    RUN_CLI(run,
            QStringList({"accuracy", "--scene", "sphere-1k", "--size", "160x120", "--repeats", "1",
                         "--format", "json", "--shading", "phong"}),
            dir.path());
    QCOMPARE(run.exitCode, 0);
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(run.out.toUtf8(), &error);
    QVERIFY2(doc.isArray(), qPrintable(error.errorString() + QStringLiteral(": ") + run.out));
    const QJsonArray rows = doc.array();
    QCOMPARE(rows.size(), 6);  // --shading keeps one model: three rule sets, float and double
    QStringList rules, precisions;
    for (const QJsonValue& v : rows) {
        const QJsonObject o = v.toObject();
        for (const char* key : {"mode", "rules", "precision", "ms", "rmse", "max_error", "psnr",
                                "coverage_mismatch", "within_1_255"})
            QVERIFY2(o.contains(QLatin1String(key)), key);
        QCOMPARE(o.value(QStringLiteral("mode")).toString(), QStringLiteral("phong"));
        precisions << o.value(QStringLiteral("precision")).toString();
        QVERIFY(o.value(QStringLiteral("ms")).toDouble() > 0.0);
        const double within = o.value(QStringLiteral("within_1_255")).toDouble();
        QVERIFY(within >= 0.0 && within <= 1.0);
        rules << o.value(QStringLiteral("rules")).toString();
        if (rules.last() == QStringLiteral("gpu")) {
            QVERIFY(within >= 0.999);
            QVERIFY(o.value(QStringLiteral("rmse")).toDouble() < 0.5 / 255.0);
        }
    }
    QCOMPARE(rules, QStringList({"course", "course", "gpu", "gpu", "hw2", "hw2"}));
    QCOMPARE(precisions, QStringList({"float", "double", "float", "double", "float", "double"}));
}

void TestCli::accuracyTablePlotAndHeatMaps() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    CliRun run;
    RUN_CLI(run,
            QStringList({"accuracy", "--scene", "sphere-1k", "--size", "120x90", "--repeats", "1",
                         "--rules", "gpu", "--supersample", "1,2", "--plot", "plot.png",
                         "--heatmaps", "maps"}),
            dir.path());
    QCOMPARE(run.exitCode, 0);
    QCOMPARE(run.err, QString());
    const QStringList lines = linesOf(run.out);
    QVERIFY(
        lines.value(0).startsWith(QStringLiteral("Accuracy of sphere-1k at 120x90 (1000 "
                                                 "triangles) against the exact reference")));
    QVERIFY(run.out.contains(QStringLiteral(
        "| mode | rules | precision | samples | ms | RMSE | max error | PSNR dB | coverage "
        "mismatch | within 1/255 | depth error mean / max |")));
    // Three shading models at 1 and at 2x2 samples, under the gpu rules, in float and double.
    for (const char* precision : {"float", "double"})
        QCOMPARE(
            lines
                .filter(QRegularExpression(QStringLiteral("^\\| \\w+ \\| gpu \\| %1 \\| [14] \\|")
                                               .arg(QLatin1String(precision))))
                .size(),
            6);
    QVERIFY(run.out.contains(QStringLiteral("wrote ") +
                             printedPath(dir, QStringLiteral("plot.png")) +
                             QStringLiteral(" (plot)")));
    const QImage plot(dir.filePath(QStringLiteral("plot.png")));
    QCOMPARE(plot.size(), QSize(960, 640));
    // Six markers: the plot is not blank white.
    int coloured = 0;
    for (int y = 0; y < plot.height(); ++y)
        for (int x = 0; x < plot.width(); ++x) {
            const QRgb c = plot.pixel(x, y);
            coloured += (qRed(c) != qGreen(c) || qGreen(c) != qBlue(c)) ? 1 : 0;
        }
    QVERIFY(coloured > 200);
    for (const char* mode : {"flat-gpu", "gouraud-gpu", "phong-gpu", "phong-gpux4"}) {
        const QImage map(
            dir.filePath(QStringLiteral("maps/error-%1.png").arg(QLatin1String(mode))));
        QVERIFY2(!map.isNull(), mode);
        QCOMPARE(map.height(), 160);       // at least room for the colour bar
        QCOMPARE(map.width(), 120 + 110);  // the image and the colour bar
        // A corner no triangle covers is black; the centre of the sphere is covered.
        QCOMPARE(map.pixel(0, 0), qRgb(0, 0, 0));
        QVERIFY(map.pixel(60, 45) != qRgb(0, 0, 0));
    }
}

QTEST_GUILESS_MAIN(TestCli)
#include "tst_cli.moc"
