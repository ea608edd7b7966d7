// rasterlab-cli compare: "their" image is ours with one deliberate mistake (made by the
// what-if machinery of pipeline/analysis/mistakes.h, or independently here: a mirrored
// QImage, a scene with other rules or conventions, bytes made another way), and the
// diagnosis must rank that mistake first with at least the share the row states. Bad inputs
// give one exact line and exit 1 or 2.
#include <QtTest>

#include <QCommandLineParser>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <cmath>
#include <cstring>
#include <functional>
#include <utility>

#include "app/cli/cli_common.h"
#include "app/documents/command_file.h"
#include "app/image_io.h"
#include "pipeline/analysis/mistakes.h"
#include "pipeline/render/output_image.h"
#include "pipeline/render/renderer.h"
#include "pipeline/scene/transforms.h"
#include "tests/test_support.h"

using testing::CliRun;
using testing::runCli;

namespace {

#define RUN_CLI(run, arguments, workDir) \
    QVERIFY2(runCli((arguments), (workDir), (run)), qPrintable((run).problem))

// The scene `rasterlab-cli compare ARGS` renders, through the CLI's own option code.
std::shared_ptr<const rl::Scene> sceneOfOptions(const QStringList& arguments) {
    using namespace rasterlab::cli;
    QCommandLineParser parser;
    const SceneOptions options;
    const QCommandLineOption sceneName = SceneOptions::generatedSceneOption();
    options.addTo(parser);
    parser.addOption(sceneName);
    if (!parser.parse(QStringList{QStringLiteral("compare")} + arguments)) return nullptr;
    QString errors;
    QTextStream err(&errors);
    rl::CourseSceneSettings settings;
    if (options.settings(parser, err, settings) != 0) return nullptr;
    options.lessonSettings(parser, sceneName, settings);
    rl::Diagnostics diagnostics;
    std::shared_ptr<const rl::Scene> scene;
    QString label;
    if (options.loadAny(parser, sceneName, settings, err, diagnostics, scene, label) != 0)
        return nullptr;
    return scene;
}

std::shared_ptr<const rl::Scene> commandFileScene(const QString& path) {
    rl::Diagnostics diagnostics;
    auto file = rasterlab::loadCommandFile(path, diagnostics);
    if (!file || file->images.empty()) return nullptr;
    return std::make_shared<const rl::Scene>(file->images.front().scene);
}

rl::Rgba8Image imageOf(std::shared_ptr<const rl::Scene> scene) {
    auto trace = rl::renderFrame(scene);
    if (!trace) return {};
    return rl::colourImage(*trace->shading, *trace->depth, scene->conventions);
}

// A scene changed by `change`, rendered: the mistake made independently of mistakes.cpp.
rl::Rgba8Image changed(const rl::Scene& scene, const std::function<void(rl::Scene&)>& change) {
    auto copy = std::make_shared<rl::Scene>(scene);
    change(*copy);
    return imageOf(copy);
}

// Our image with each pixel's bytes made by `bytes` from the float colour (covered pixels).
rl::Rgba8Image rebyted(const rl::OurFrame& ours,
                       const std::function<std::array<std::uint8_t, 4>(rl::vec3)>& bytes) {
    rl::Rgba8Image out = ours.image;
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x)
            if (ours.covered(x, y)) {
                const auto b = bytes(ours.trace->shading->colour.at(x, y));
                std::copy(b.begin(), b.end(),
                          out.rgba.begin() + (std::ptrdiff_t(y) * out.width + x) * 4);
            }
    return out;
}

rl::Rgba8Image fromQImage(const QImage& image) {
    const QImage rgba = image.convertToFormat(QImage::Format_RGBA8888);
    rl::Rgba8Image out;
    out.width = rgba.width();
    out.height = rgba.height();
    for (int y = 0; y < rgba.height(); ++y)
        out.rgba.insert(out.rgba.end(), rgba.constScanLine(y),
                        rgba.constScanLine(y) + 4 * out.width);
    return out;
}

// How a test makes their image from our frame.
using Maker = std::function<rl::Rgba8Image(const rl::OurFrame&)>;

Maker whatIf(rl::Mistake mistake) {
    return [mistake](const rl::OurFrame& ours) {
        auto image = rl::imageWithMistake(ours, mistake);
        return image && image.value() ? *image.value() : rl::Rgba8Image{};
    };
}

Maker sceneChange(std::function<void(rl::Scene&)> change) {
    return [change](const rl::OurFrame& ours) { return changed(*ours.trace->scene, change); };
}

Maker qimage(std::function<QImage(const QImage&)> transform) {
    return [transform](const rl::OurFrame& ours) {
        return fromQImage(transform(rasterlab::toQImage(ours.image)));
    };
}

QJsonObject compareJson(const QTemporaryDir& dir, const QStringList& arguments, CliRun& run) {
    if (!runCli(QStringList{QStringLiteral("compare")} + arguments +
                    QStringList{QStringLiteral("--format"), QStringLiteral("json")},
                dir.path(), run))
        return {};
    return QJsonDocument::fromJson(run.out.toUtf8()).object();
}

}  // namespace

Q_DECLARE_METATYPE(Maker)

class TestCompare : public QObject {
    Q_OBJECT

private slots:
    void ranksTheMistakeFirst_data();
    void ranksTheMistakeFirst();
    void sameImageHasNoDiagnosis();
    void textOutputAndDifferenceImage();
    void badInputs_data();
    void badInputs();
    void screenshotWithBorder();
    void theirSizeByDefault();
    void theirFormats_data();
    void theirFormats();
    void findsTheMisreadCommand_data();
    void findsTheMisreadCommand();
};

void TestCompare::ranksTheMistakeFirst_data() {
    QTest::addColumn<QStringList>("scene");  // compare's scene options, or a command file
    QTest::addColumn<Maker>("make");
    QTest::addColumn<QString>("expected");
    QTest::addColumn<double>("threshold");
    const QStringList goblet = {"--scene", "goblet"};
    const QStringList defaults = {};
    using rl::Mistake;
    // Shading mistakes, by the what-if shading and, where a scene can say it, independently.
    QTest::newRow("goblet ambient Ia ka Od, by the scene's Ia times Od")
        << goblet
        << sceneChange([](rl::Scene& s) { s.ambientIntensity *= s.draws.front().material.od; })
        << "ambient-times-od" << 0.99;
    QTest::newRow("goblet ambient Ia ka Od, what-if")
        << goblet << whatIf(Mistake::AmbientTimesOd) << "ambient-times-od" << 0.99;
    QTest::newRow("default scene ambient Ia ka Od")
        << defaults << whatIf(Mistake::AmbientTimesOd) << "ambient-times-od" << 0.99;
    QTest::newRow("goblet normal not flipped, by the conventions")
        << goblet
        << sceneChange([](rl::Scene& s) { s.conventions.flipNormalsTowardViewer = false; })
        << "normal-not-flipped" << 0.99;
    QTest::newRow("goblet specular where R.V < 0")
        << goblet << whatIf(Mistake::SpecularWhereRvNegative) << "specular-where-rv-negative"
        << 0.99;
    QTest::newRow("goblet diffuse and specular where N.L < 0")
        << goblet << whatIf(Mistake::LightBehindNotSkipped) << "light-behind-not-skipped" << 0.99;
    QTest::newRow("goblet normal not normalised")
        << goblet << whatIf(Mistake::NormalNotNormalised) << "normal-not-normalised" << 0.99;
    QTest::newRow("goblet gouraud, by the scene") << goblet << sceneChange([](rl::Scene& s) {
        for (auto& d : s.draws) d.shading = rl::ShadingModel::Gouraud;
    }) << "gouraud" << 0.99;
    QTest::newRow("goblet flat, by the scene") << goblet << sceneChange([](rl::Scene& s) {
        for (auto& d : s.draws) d.shading = rl::ShadingModel::Flat;
    }) << "flat" << 0.99;
    QTest::newRow("default scene painter's order")
        << defaults << whatIf(Mistake::PainterOrder) << "painter-order" << 0.95;
    QTest::newRow("goblet painter's order, lit per pixel")
        << goblet << whatIf(Mistake::PainterOrder) << "painter-order" << 0.95;
    QTest::newRow("sphere lesson phong where flat was asked")
        << QStringList{"--scene", "sphere"} << sceneChange([](rl::Scene& s) {
               for (auto& d : s.draws) d.shading = rl::ShadingModel::Phong;
           })
        << "phong" << 0.99;
    QTest::newRow("goblet alpha 128 on covered pixels")
        << goblet << Maker([](const rl::OurFrame& ours) {
               rl::Rgba8Image out = ours.image;
               for (int y = 0; y < out.height; ++y)
                   for (int x = 0; x < out.width; ++x)
                       if (ours.covered(x, y))
                           out.rgba[(std::size_t(y) * out.width + x) * 4 + 3] = 128;
               return out;
           })
        << "alpha" << 0.99;
    // Image mistakes, made here with QImage.
    QTest::newRow("goblet mirrored left-right")
        << goblet << qimage([](const QImage& i) { return i.mirrored(true, false); })
        << "mirrored-left-right" << 0.99;
    QTest::newRow("goblet upside down")
        << goblet << qimage([](const QImage& i) { return i.mirrored(false, true); })
        << "upside-down" << 0.99;
    QTest::newRow("default scene shifted one pixel right")
        << defaults << qimage([](const QImage& i) {
               QImage out(i.size(), i.format());
               out.fill(Qt::black);
               for (int y = 0; y < i.height(); ++y)
                   for (int x = 1; x < i.width(); ++x) out.setPixel(x, y, i.pixel(x - 1, y));
               return out;
           })
        << "shifted" << 0.99;
    // Rules, by the scene.
    QTest::newRow("goblet sampled at pixel centres")
        << goblet << sceneChange([](rl::Scene& s) { s.rules.sampleOffset = 0.5; })
        << "sample-offset" << 0.9;
    QTest::newRow("goblet vertices rounded") << goblet << sceneChange([](rl::Scene& s) {
        s.rules.snap = rl::RasterRules::VertexSnap::Nearest;
    }) << "vertex-snap" << 0.9;
    QTest::newRow("default scene top-left fill rule") << defaults << sceneChange([](rl::Scene& s) {
        s.rules.fill = rl::RasterRules::FillRule::TopLeft;
    }) << "fill-rule" << 0.9;
    // Bytes, made here from the float colours.
    QTest::newRow("goblet bytes rounded") << goblet << Maker([](const rl::OurFrame& ours) {
        return rebyted(ours, [](rl::vec3 c) {
            const auto b = [](float v) {
                return std::uint8_t(std::clamp(std::floor(v + 0.5f), 0.0f, 255.0f));
            };
            return std::array<std::uint8_t, 4>{b(c.r), b(c.g), b(c.b), 255};
        });
    }) << "byte-rounding" << 0.99;
    QTest::newRow("goblet colours wrap") << goblet << Maker([](const rl::OurFrame& ours) {
        return rebyted(ours, [](rl::vec3 c) {
            const auto b = [](float v) { return std::uint8_t(int(v) & 0xFF); };
            return std::array<std::uint8_t, 4>{b(c.r), b(c.g), b(c.b), 255};
        });
    }) << "colour-wrap" << 0.99;
    QTest::newRow("goblet grey background") << goblet << Maker([](const rl::OurFrame& ours) {
        rl::Rgba8Image out = ours.image;
        for (int y = 0; y < out.height; ++y)
            for (int x = 0; x < out.width; ++x)
                if (!ours.covered(x, y))
                    for (int c = 0; c < 3; ++c)
                        out.rgba[(std::size_t(y) * out.width + x) * 4 + c] = 40;
        return out;
    }) << "background" << 0.99;
    // Command files (seed 001).
    const QString hw2 = testing::samplesDir() + QStringLiteral("/hw2/");
    QTest::newRow("hw2depth depth ties")
        << QStringList{hw2 + "hw2depth.txt"} << sceneChange([](rl::Scene& s) {
               s.conventions.depthWinsOnTie = !s.conventions.depthWinsOnTie;
           })
        << "depth-ties" << 0.9;
    QTest::newRow("hw2trif upside down")
        << QStringList{hw2 + "hw2trif.txt"}
        << qimage([](const QImage& i) { return i.mirrored(false, true); }) << "upside-down" << 0.99;
    QTest::newRow("hw2sun1g opaque background")
        << QStringList{hw2 + "hw2sun1g.txt"} << Maker([](const rl::OurFrame& ours) {
               rl::Rgba8Image out = ours.image;
               for (int y = 0; y < out.height; ++y)
                   for (int x = 0; x < out.width; ++x)
                       if (!ours.covered(x, y))
                           out.rgba[(std::size_t(y) * out.width + x) * 4 + 3] = 255;
               return out;
           })
        << "background" << 0.99;
    QTest::newRow("hw2sun1g bytes rounded")
        << QStringList{hw2 + "hw2sun1g.txt"} << Maker([](const rl::OurFrame& ours) {
               const float scale = ours.trace->scene->conventions.colourScale;
               return rebyted(ours, [scale](rl::vec3 c) {
                   const auto b = [scale](float v) {
                       return std::uint8_t(
                           std::clamp(std::floor(v * 255.0f / scale + 0.5f), 0.0f, 255.0f));
                   };
                   return std::array<std::uint8_t, 4>{b(c.r), b(c.g), b(c.b), 255};
               });
           })
        << "byte-rounding" << 0.99;
}

void TestCompare::ranksTheMistakeFirst() {
    QFETCH(QStringList, scene);
    QFETCH(Maker, make);
    QFETCH(QString, expected);
    QFETCH(double, threshold);
    const bool commandFile = scene.size() == 1 && scene.first().endsWith(QLatin1String(".txt"));
    if (commandFile && testing::samplesDir().isEmpty()) QSKIP("no course samples");
    const auto sceneObject = commandFile ? commandFileScene(scene.first()) : sceneOfOptions(scene);
    QVERIFY(sceneObject);
    auto ours = rl::renderOurFrame(sceneObject);
    QVERIFY(ours);
    const rl::Rgba8Image theirs = make(ours.value());
    QCOMPARE(theirs.width, ours->image.width);
    QVERIFY2(theirs != ours->image, "the mistake changes nothing in this scene");
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("theirs.png"));
    QVERIFY(rasterlab::savePng(rasterlab::toQImage(theirs), path, nullptr));

    CliRun run;
    const QJsonObject result =
        compareJson(dir, scene + QStringList{QStringLiteral("--image"), path}, run);
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    const QJsonArray diagnosis = result[QStringLiteral("diagnosis")].toArray();
    QVERIFY2(!diagnosis.isEmpty(), qPrintable(run.out));
    QString ranking;
    for (const auto& d : diagnosis)
        ranking += QStringLiteral("%1 %2; ")
                       .arg(d[QStringLiteral("mistake")].toString())
                       .arg(d[QStringLiteral("share")].toDouble(), 0, 'f', 4);
    qInfo("%s: %lld differing; %s", QTest::currentDataTag(),
          result[QStringLiteral("differing")].toInteger(), qPrintable(ranking));
    const QJsonObject first = diagnosis.first().toObject();
    QCOMPARE(first[QStringLiteral("mistake")].toString(), expected);
    QVERIFY2(first[QStringLiteral("share")].toDouble() >= threshold, qPrintable(ranking));
    QVERIFY(!first[QStringLiteral("examples")].toArray().isEmpty());
}

void TestCompare::sameImageHasNoDiagnosis() {
    QTemporaryDir dir;
    CliRun run;
    RUN_CLI(run, (QStringList{"render", "--scene", "goblet", "--output", "ours.png"}), dir.path());
    QCOMPARE(run.exitCode, 0);
    RUN_CLI(run, (QStringList{"compare", "--scene", "goblet", "--image", "ours.png"}), dir.path());
    QCOMPARE(run.exitCode, 0);
    QVERIFY2(run.out.contains(QStringLiteral("480000 pixels compared, 0 differ (0.0%)\n  the "
                                             "images are the same\n")),
             qPrintable(run.out));
}

void TestCompare::textOutputAndDifferenceImage() {
    const auto scene = sceneOfOptions({"--scene", "goblet"});
    QVERIFY(scene);
    auto ours = rl::renderOurFrame(scene);
    QVERIFY(ours);
    auto theirs = rl::imageWithMistake(ours.value(), rl::Mistake::AmbientTimesOd);
    QVERIFY(theirs && theirs.value());
    QTemporaryDir dir;
    QVERIFY(rasterlab::savePng(rasterlab::toQImage(*theirs.value()),
                               dir.filePath(QStringLiteral("theirs.png")), nullptr));
    CliRun run;
    RUN_CLI(run,
            (QStringList{"compare", "--scene", "goblet", "--image", "theirs.png", "--diff-output",
                         "diff.png"}),
            dir.path());
    QCOMPARE(run.exitCode, 0);
    const QStringList lines = run.out.split(QLatin1Char('\n'));
    QCOMPARE(lines.value(0),
             QStringLiteral("comparing theirs.png with our render of goblet (800x600, the scene's "
                            "size)"));
    QCOMPARE(lines.value(1), QStringLiteral("  your image: a PNG image"));
    QVERIFY2(lines.value(6).startsWith(QStringLiteral("  total difference: ")), qPrintable(run.out));
    QCOMPARE(lines.value(7),
             QStringLiteral("diagnosis, each mistake applied before the next is ranked:"));
    QCOMPARE(lines.value(8), QStringLiteral("  1. the ambient term multiplied by the object "
                                            "colour: Ia*ka*Od instead of Ia*ka"));
    QVERIFY2(lines.value(9).startsWith(QStringLiteral("     removes 100.0% of the difference; ")),
             qPrintable(run.out));
    QVERIFY2(run.out.contains(QStringLiteral(
                 "unexplained: 0.0% of the difference; pixels that still differ with every "
                 "mistake above applied: 0\n")),
             qPrintable(run.out));
    QVERIFY2(run.out.contains(QStringLiteral("(difference, 800x600)")), qPrintable(run.out));
    // The difference image: differing pixels bright (red channel 255), the others darkened.
    const QImage diff(dir.filePath(QStringLiteral("diff.png")));
    QCOMPARE(diff.size(), QSize(800, 600));
    const rl::Rgba8Image& our = ours->image;
    int bright = 0;
    for (int y = 0; y < 600; ++y)
        for (int x = 0; x < 800; ++x) {
            const bool differs = std::memcmp(our.pixel(x, y), theirs.value()->pixel(x, y), 4) != 0;
            const int red = qRed(diff.pixel(x, y));
            if (differs) {
                QCOMPARE(red, 255);
                ++bright;
            } else {
                QVERIFY(red <= 85);
            }
        }
    QVERIFY(bright > 1000);
}

void TestCompare::badInputs_data() {
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("message");
    const QStringList goblet = {"compare", "--scene", "goblet", "--image"};
    QTest::newRow("other size than --size")
        << (goblet + QStringList{"small.png", "--size", "800x600"}) << 1
        << "small.png: the image is 640x480, ours is 800x600 (no frame of ours found inside it "
           "at --size 800x600)";
    QTest::newRow("not an image") << (goblet + QStringList{"notes.png"}) << 1
                                  << "notes.png: not an image RasterLab reads (PNG, PPM, BMP, "
                                     "TGA or JPEG)";
    QTest::newRow("a GIF") << (goblet + QStringList{"anim.gif"}) << 1
                           << "anim.gif: not an image RasterLab reads (PNG, PPM, BMP, TGA or "
                              "JPEG): a gif image";
    QTest::newRow("TGA cut short") << (goblet + QStringList{"cut.tga"}) << 1
                                   << "cut.tga: the TGA image is cut short";
    QTest::newRow("colour-mapped TGA")
        << (goblet + QStringList{"mapped.tga"}) << 1
        << "mapped.tga: a TGA image of a kind RasterLab does not read (only 8-bit grey and 24- or "
           "32-bit colour, plain or run-length encoded)";
    QTest::newRow("empty file") << (goblet + QStringList{"empty.png"}) << 1
                                << "empty.png: the file is empty";
    QTest::newRow("missing file") << (goblet + QStringList{"missing.png"}) << 1
                                  << "missing.png: no such file";
    QTest::newRow("truncated PNG")
        << (goblet + QStringList{"cut.png"}) << 1
        << "cut.png: the PNG is cut short (it does not end with its IEND chunk)";
    QTest::newRow("no image") << QStringList{"compare", "--scene", "goblet"} << 2
                              << "rasterlab-cli: compare needs --image THEIRS.png";
    QTest::newRow("bad format") << (goblet + QStringList{"small.png", "--format", "xml"}) << 2
                                << "rasterlab-cli: --format expects text or json, found 'xml'";
    QTest::newRow("command file and scene")
        << QStringList{"compare", "scene.txt", "--scene", "goblet", "--image", "small.png"} << 2
        << "rasterlab-cli: --scene does not apply to a command file, which sets its own scene";
    QTest::newRow("command file with other size")
        << QStringList{"compare", "scene.txt", "--image", "small.png"} << 1
        << "small.png: the image is 640x480, ours is 32x24 (its png command sets the size)";
}

void TestCompare::badInputs() {
    QFETCH(QStringList, arguments);
    QFETCH(int, exitCode);
    QFETCH(QString, message);
    QTemporaryDir dir;
    QImage small(640, 480, QImage::Format_RGBA8888);
    small.fill(Qt::black);
    QVERIFY(small.save(dir.filePath(QStringLiteral("small.png"))));
    // A TGA header for 320x240 pixels of 24 bits, followed by ten bytes; one colour-mapped.
    for (const auto& [name, type] :
         {std::pair{QStringLiteral("cut.tga"), 2}, std::pair{QStringLiteral("mapped.tga"), 1}}) {
        QByteArray tga = QByteArray::fromHex("0000020000000000000000004001f0001820");
        tga[2] = char(type);
        if (type == 1) tga[1] = 1;
        QFile file(dir.filePath(name));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(tga + QByteArray(10, 'x'));
    }
    QFile gif(dir.filePath(QStringLiteral("anim.gif")));  // one white pixel
    QVERIFY(gif.open(QIODevice::WriteOnly));
    gif.write(QByteArray::fromHex("47494638396101000100800000ffffff00000021f90401000000002c00000000"
                                  "010001000002024401003b"));
    gif.close();
    QFile notes(dir.filePath(QStringLiteral("notes.png")));
    QVERIFY(notes.open(QIODevice::WriteOnly));
    notes.write("not an image\n");
    notes.close();
    QFile empty(dir.filePath(QStringLiteral("empty.png")));
    QVERIFY(empty.open(QIODevice::WriteOnly));
    empty.close();
    QFile full(dir.filePath(QStringLiteral("small.png")));
    QVERIFY(full.open(QIODevice::ReadOnly));
    const QByteArray png = full.readAll();
    QFile cut(dir.filePath(QStringLiteral("cut.png")));
    QVERIFY(cut.open(QIODevice::WriteOnly));
    cut.write(png.left(png.size() / 2));
    cut.close();
    QFile commands(dir.filePath(QStringLiteral("scene.txt")));
    QVERIFY(commands.open(QIODevice::WriteOnly));
    commands.write("png 32 24 out.png\nxyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\ntrif 1 2 3\n");
    commands.close();
    CliRun run;
    RUN_CLI(run, arguments, dir.path());
    QCOMPARE(run.exitCode, exitCode);
    QCOMPARE(run.err.split(QLatin1Char('\n')).first(), message);
    QCOMPARE(run.out, QString());
}

void TestCompare::screenshotWithBorder() {
    QTemporaryDir dir;
    CliRun run;
    RUN_CLI(run, (QStringList{"render", "--scene", "goblet", "--output", "ours.png"}), dir.path());
    QCOMPARE(run.exitCode, 0);
    const QImage ours(dir.filePath(QStringLiteral("ours.png")));
    QImage shot(820, 640, QImage::Format_RGBA8888);
    shot.fill(QColor(200, 200, 200));
    for (int y = 0; y < ours.height(); ++y)
        for (int x = 0; x < ours.width(); ++x) shot.setPixel(x + 7, y + 31, ours.pixel(x, y));
    QVERIFY(shot.save(dir.filePath(QStringLiteral("shot.png"))));
    RUN_CLI(run, (QStringList{"compare", "--scene", "goblet", "--image", "shot.png"}), dir.path());
    QCOMPARE(run.exitCode, 0);
    const QStringList lines = run.out.split(QLatin1Char('\n'));
    QCOMPARE(lines.value(0),
             QStringLiteral("comparing shot.png with our render of goblet (800x600, the scene's "
                            "size)"));
    QCOMPARE(lines.value(2), QStringLiteral("  cropped to 800x600 at (7, 31) from 820x640, the "
                                            "frame found inside your image"));
    QVERIFY2(run.out.contains(QStringLiteral("the images are the same")), qPrintable(run.out));
}

// Without --size, ours is rendered at their image's size, and the summary says so.
void TestCompare::theirSizeByDefault() {
    QTemporaryDir dir;
    CliRun run;
    RUN_CLI(run, (QStringList{"render", "--scene", "goblet", "--size", "600x600", "--output",
                              "theirs.png"}),
            dir.path());
    QCOMPARE(run.exitCode, 0);
    RUN_CLI(run, (QStringList{"compare", "--scene", "goblet", "--image", "theirs.png"}),
            dir.path());
    QCOMPARE(run.exitCode, 0);
    QCOMPARE(run.out.split(QLatin1Char('\n')).value(0),
             QStringLiteral("comparing theirs.png with our render of goblet (600x600, your "
                            "image's size; --size overrides)"));
    QVERIFY2(run.out.contains(QStringLiteral("360000 pixels compared, 0 differ")),
             qPrintable(run.out));
    RUN_CLI(run, (QStringList{"compare", "--scene", "goblet", "--image", "theirs.png", "--size",
                              "800x600"}),
            dir.path());
    QCOMPARE(run.exitCode, 1);
}

// The formats student renderers write: the same pixels as PNG, PPM (P3 and P6), BMP and TGA
// compare equal; a JPEG, with the tolerance the summary states.
void TestCompare::theirFormats_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("described");
    QTest::addColumn<int>("tolerance");
    const QString noAlpha = QStringLiteral(", without alpha: colours compared, alpha taken as ours");
    QTest::newRow("PNG") << "theirs.png" << "a PNG image" << 0;
    QTest::newRow("PPM P6") << "theirs.ppm" << QStringLiteral("a PPM image") + noAlpha << 0;
    QTest::newRow("PPM P3") << "plain.ppm" << QStringLiteral("a PPM image") + noAlpha << 0;
    QTest::newRow("BMP") << "theirs.bmp" << QStringLiteral("a BMP image") + noAlpha << 0;
    QTest::newRow("TGA") << "theirs.tga" << QStringLiteral("a TGA image") + noAlpha << 0;
    QTest::newRow("JPEG") << "theirs.jpg"
                          << QStringLiteral("a JPEG image, lossy: compared with a tolerance of 8 "
                                            "per channel") + noAlpha
                          << 8;
}

void TestCompare::theirFormats() {
    QFETCH(QString, file);
    QFETCH(QString, described);
    QFETCH(int, tolerance);
    QTemporaryDir dir;
    CliRun run;
    RUN_CLI(run, (QStringList{"render", "--scene", "goblet", "--size", "320x240", "--output",
                              "theirs.png"}),
            dir.path());
    QCOMPARE(run.exitCode, 0);
    const QImage png(dir.filePath(QStringLiteral("theirs.png")));
    const QImage rgb = png.convertToFormat(QImage::Format_RGB888);
    QVERIFY(rgb.save(dir.filePath(QStringLiteral("theirs.ppm")), "PPM"));
    QVERIFY(rgb.save(dir.filePath(QStringLiteral("theirs.bmp")), "BMP"));
    QVERIFY(rgb.save(dir.filePath(QStringLiteral("theirs.jpg")), "JPEG", 95));
    // P3 and TGA written byte by byte, as a student's program would.
    QByteArray plain = "P3\n# a comment\n320 240\n255\n";
    QByteArray tga(18, '\0');
    tga[2] = 2;  // uncompressed true colour
    tga[12] = char(320 & 0xff);
    tga[13] = char(320 >> 8);
    tga[14] = char(240 & 0xff);
    tga[15] = char(240 >> 8);
    tga[16] = 24;
    tga[17] = 0x20;  // the top row first
    for (int y = 0; y < 240; ++y)
        for (int x = 0; x < 320; ++x) {
            const QRgb p = rgb.pixel(x, y);
            plain += QByteArray::number(qRed(p)) + ' ' + QByteArray::number(qGreen(p)) + ' ' +
                     QByteArray::number(qBlue(p)) + '\n';
            tga += char(qBlue(p));
            tga += char(qGreen(p));
            tga += char(qRed(p));
        }
    for (const auto& [name, bytes] :
         {std::pair{QStringLiteral("plain.ppm"), plain}, std::pair{QStringLiteral("theirs.tga"), tga}}) {
        QFile out(dir.filePath(name));
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(bytes);
    }
    RUN_CLI(run, (QStringList{"compare", "--scene", "goblet", "--size", "320x240", "--image", file,
                              "--format", "json"}),
            dir.path());
    QCOMPARE(run.exitCode, 0);
    const QJsonObject o = QJsonDocument::fromJson(run.out.toUtf8()).object();
    QCOMPARE(o.value(QStringLiteral("imageFormat")).toString(), described);
    QCOMPARE(o.value(QStringLiteral("tolerance")).toInt(), tolerance);
    const int differing = o.value(QStringLiteral("differing")).toInt();
    if (tolerance == 0) {
        QCOMPARE(differing, 0);
    } else {
        // JPEG at quality 95: only edge pixels stay beyond the tolerance.
        QVERIFY2(differing < 320 * 240 / 50, qPrintable(QString::number(differing)));
    }
}


namespace {

// A small command file whose transforms each matter: lookat (line 8, |f x up| = 2), rotatez
// (line 9) and translate (line 10).
const QString kTransforms = QStringLiteral(
    "png 64 64 mine.png\n"
    "xyz -0.5 -0.4 0\nxyz 0.5 -0.4 0\nxyz 0.1 0.5 0\nxyz 0 0 3\nxyz 0 0 0\n"
    "frustum -0.3 0.3 -0.3 0.3 1 10\n"
    "lookat 4 5 0 2 0\n"
    "rotatez 20\n"
    "translate 0.3 0 0\n"
    "color 1 0.5 0\n"
    "trif 1 2 3\n");

// Lines 8 to 10 replaced by one loadmv of m, written row by row.
QString withModelView(const rl::dmat4& m) {
    QStringList lines = kTransforms.split(QLatin1Char('\n'));
    QString rows = QStringLiteral("loadmv");
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) rows += QLatin1Char(' ') + QString::number(m[c][r], 'g', 17);
    lines[7] = rows;
    lines[8] = lines[9] = QString();
    return lines.join(QLatin1Char('\n'));
}

rl::dmat4 lookAtOfTransforms() {
    return rl::lookAtMatrix(rl::dvec3(0, 0, 3), rl::dvec3(0, 0, 0), rl::dvec3(0, 2, 0));
}

}  // namespace

void TestCompare::findsTheMisreadCommand_data() {
    QTest::addColumn<QString>("ours");    // the command file as given
    QTest::addColumn<QString>("theirs");  // the command file their program in effect ran
    QTest::addColumn<int>("line");
    QTest::addColumn<QString>("variant");
    const rl::dmat4 rz = rl::rotationMatrix(20.0, rl::dvec3(0, 0, 1));
    const rl::dmat4 t = rl::translationMatrix(rl::dvec3(0.3, 0, 0));
    QString radians = kTransforms;
    radians.replace(QStringLiteral("rotatez 20"), QStringLiteral("rotatez 1145.9155902616465"));
    QTest::newRow("rotatez in radians") << kTransforms << radians << 9 << "radians";
    QString ignored = kTransforms;
    ignored.replace(QStringLiteral("translate 0.3 0 0"), QString());
    QTest::newRow("translate ignored") << kTransforms << ignored << 10 << "ignored";
    QTest::newRow("translate on the left")
        << kTransforms << withModelView(t * lookAtOfTransforms() * rz) << 10 << "other-side";
    // s = f x up = (0, 0, -1) x (0, 2, 0) = (2, 0, 0) left at length 2: x doubled.
    QTest::newRow("lookat's s not normalised")
        << kTransforms
        << withModelView(rl::scaleMatrix(rl::dvec3(2, 1, 1)) * lookAtOfTransforms() * rz * t) << 8
        << "unnormalised-side";
    const QString samples = testing::samplesDir();
    if (samples.isEmpty()) return;
    const auto sample = [&](const char* name) {
        QFile file(samples + QStringLiteral("/hw2/") + QLatin1String(name));
        return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
    };
    // The shared samples: the translate of hw2clipplane left out, hw2loadmv's matrix
    // transposed (the sixteen numbers written column by column).
    const QString clip = sample("hw2clipplane.txt");
    QString clipIgnored = clip;
    clipIgnored.replace(QStringLiteral("translate -0.25 0.1 -0.2"), QString());
    QTest::newRow("hw2clipplane translate ignored") << clip << clipIgnored << 8 << "ignored";
    const QString loadmv = sample("hw2loadmv.txt");
    QStringList lines = loadmv.split(QLatin1Char('\n'));
    const QStringList numbers = lines[6].split(QLatin1Char(' '), Qt::SkipEmptyParts).mid(1);
    QStringList transposed{QStringLiteral("loadmv")};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) transposed += numbers.value(c * 4 + r);
    lines[6] = transposed.join(QLatin1Char(' '));
    QTest::newRow("hw2loadmv transposed") << loadmv << lines.join(QLatin1Char('\n')) << 7
                                          << "transposed";
}

// Their image made by our renderer from the command file their program in effect ran (its
// text edited here); compare with the file as given names the line and the misreading, and
// leaves nothing unexplained.
void TestCompare::findsTheMisreadCommand() {
    QFETCH(QString, ours);
    QFETCH(QString, theirs);
    QFETCH(int, line);
    QFETCH(QString, variant);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const auto write = [&](const QString& name, const QString& text) {
        QFile file(dir.filePath(name));
        return file.open(QIODevice::WriteOnly) && file.write(text.toUtf8()) == text.toUtf8().size();
    };
    QVERIFY(write(QStringLiteral("ours.txt"), ours) && write(QStringLiteral("theirs.txt"), theirs));
    CliRun made;
    RUN_CLI(made, (QStringList{"run", "theirs.txt"}), dir.path());
    QCOMPARE(made.exitCode, 0);
    const QString png = ours.section(QLatin1Char('\n'), 0, 0).section(QLatin1Char(' '), 3, 3);
    CliRun run;
    const QJsonObject result = compareJson(dir, {QStringLiteral("ours.txt"), "--image", png}, run);
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    const QJsonArray diagnosis = result[QStringLiteral("diagnosis")].toArray();
    QVERIFY2(!diagnosis.isEmpty(), qPrintable(run.out));
    const QJsonObject first = diagnosis.first().toObject();
    QCOMPARE(first[QStringLiteral("mistake")].toString(), QStringLiteral("command-misread"));
    QCOMPARE(first[QStringLiteral("line")].toInt(), line);
    QCOMPARE(first[QStringLiteral("variant")].toString(), variant);
    QVERIFY2(result[QStringLiteral("unexplained")][QStringLiteral("share")].toDouble() <= 0.01,
             qPrintable(run.out));
}

QTEST_GUILESS_MAIN(TestCompare)
#include "tst_compare.moc"
