// rasterlab-cli compare: a student's image against ours, of a course scene (render's options)
// or of a command file's png, with a summary, a difference image and a diagnosis: the
// mistakes (pipeline/analysis/mistakes.h) composed greedily by the difference each removes,
// and what stays unexplained.
#include "app/cli/cli_common.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <optional>

#include "app/compare/compare_image.h"
#include "app/documents/command_file.h"
#include "pipeline/analysis/lighting_fit.h"
#include "pipeline/analysis/mistakes.h"

namespace rasterlab::cli {

namespace {

QString sizeText(int width, int height) {
    return lit("%1x%2").arg(width).arg(height);
}

QJsonArray bytesJson(const std::array<std::uint8_t, 4>& b) {
    return {int(b[0]), int(b[1]), int(b[2]), int(b[3])};
}

QString bytesText(const std::array<std::uint8_t, 4>& b) {
    return lit("(%1, %2, %3, %4)").arg(b[0]).arg(b[1]).arg(b[2]).arg(b[3]);
}

QString channels(const std::array<int, 4>& v) {
    return lit("R %1, G %2, B %3, A %4").arg(v[0]).arg(v[1]).arg(v[2]).arg(v[3]);
}

QString channels(const std::array<double, 4>& v) {
    return lit("R %1, G %2, B %3, A %4")
        .arg(v[0], 0, 'f', 1)
        .arg(v[1], 0, 'f', 1)
        .arg(v[2], 0, 'f', 1)
        .arg(v[3], 0, 'f', 1);
}

// What their image was, where our size came from, and what was cropped.
struct Provenance {
    QString format;    // "a PPM image, without alpha: ..."
    QString sizeFrom;  // "your image's size; --size overrides", "--size" ...
    QString cropped;   // empty, or "cropped to 800x600 at (10, 30) from 820x640 ..."
};

QString percent(double share) {
    return QString::number(100.0 * share, 'f', 1) + QLatin1Char('%');
}

void printFit(const rl::LightingFit& fit, QTextStream& out) {
    if (!fit.fitted) return;
    out << "lighting fitted to their colours"
        << (fit.carriedBack ? ", carried back onto ours by the move above" : "") << " ("
        << fit.samples << " pixels inside triangles): "
        << "rms " << QString::number(fit.rmsOurs, 'f', 1) << " with ours, "
        << QString::number(fit.rmsFitted, 'f', 1) << " fitted\n";
    for (const rl::FittedValue& v : fit.values)
        if (v.apart)
            out << "  " << QString::fromStdString(v.name) << ": theirs "
                << QString::number(v.theirs, 'g', 4) << " +- "
                << QString::number(v.uncertainty, 'g', 2) << ", ours "
                << QString::number(v.ours, 'g', 4) << '\n';
    for (const rl::Message& m : fit.findings)
        out << "  " << QString::fromStdString(m.english()) << '\n';
}

QJsonObject fitJson(const rl::LightingFit& fit) {
    QJsonObject o;
    o[lit("fitted")] = fit.fitted;
    if (!fit.fitted) {
        o[lit("reason")] = QString::fromStdString(fit.reason.english());
        return o;
    }
    o[lit("samples")] = qint64(fit.samples);
    o[lit("carried_back")] = fit.carriedBack;
    o[lit("rmsOurs")] = fit.rmsOurs;
    o[lit("rmsFitted")] = fit.rmsFitted;
    QJsonArray values;
    for (const rl::FittedValue& v : fit.values)
        values.append(QJsonObject{{lit("name"), QString::fromStdString(v.name)},
                                  {lit("ours"), v.ours},
                                  {lit("theirs"), v.theirs},
                                  {lit("uncertainty"), v.uncertainty},
                                  {lit("apart"), v.apart},
                                  {lit("differs"), v.differs}});
    o[lit("values")] = values;
    if (fit.matches) o[lit("matches")] = QString::fromLatin1(rl::mistakeId(*fit.matches));
    QJsonArray findings;
    for (const rl::Message& m : fit.findings) findings.append(QString::fromStdString(m.english()));
    o[lit("findings")] = findings;
    return o;
}

void printText(const rl::ImageComparison& c, const QString& image, const QString& label,
               const Provenance& p, QTextStream& out) {
    out << "comparing " << image << " with our render of " << label << " ("
        << sizeText(c.width, c.height) << ", " << p.sizeFrom << ")\n";
    out << "  your image: " << p.format << '\n';
    if (!p.cropped.isEmpty()) out << "  " << p.cropped << '\n';
    if (c.unlit)
        out << "  your image is unlit: one colour " << bytesText(c.unlitColour)
            << " wherever it covers; only coverage is compared (our covered pixels in that "
               "colour), and only projection and scan conversion mistakes are tried\n";
    if (c.unlitWhite())
        out << "  white wherever it covers is also what a lit image becomes with every colour "
               "multiplied by 255 (a colour scaled by 255 where it was already 0..255)\n";
    out << "  " << c.compared << " pixels compared, " << c.differing << " differ ("
        << QString::number(100.0 * double(c.differing) / double(c.compared), 'f', 1) << "%)\n";
    if (c.differing == 0) {
        out << "  the images are the same\n";
        return;
    }
    out << "  largest difference per channel: " << channels(c.largest) << '\n';
    out << "  mean difference per channel, over the differing pixels: " << channels(c.mean) << '\n';
    out << "  pixels covered: " << c.coveredByBoth << " by both, " << c.onlyOurs
        << " only by ours (our depth buffer), " << c.onlyTheirs
        << " only by theirs (not the background)\n";
    out << "  total difference: " << c.difference
        << " (the sum over pixels and channels of |ours - theirs|)\n";
    if (c.diagnosis.empty()) {
        out << "diagnosis: none of the mistakes RasterLab knows explains these differences\n";
    } else {
        out << "diagnosis, each mistake applied before the next is ranked:\n";
        int rank = 0;
        for (const rl::Finding& f : c.diagnosis) {
            out << "  " << ++rank << ". " << QString::fromStdString(f.title.english()) << '\n';
            out << "     removes " << percent(f.share) << " of the difference; makes " << f.explained
                << " differing pixels match\n";
            out << "     evidence: " << QString::fromStdString(f.evidence.english()) << '\n';
            out << "     check: " << QString::fromStdString(f.advice.english()) << '\n';
            for (const rl::PixelExample& e : f.examples)
                out << "     at (" << e.x << ", " << e.y << ") ours " << bytesText(e.ours)
                    << ", theirs " << bytesText(e.theirs) << '\n';
        }
    }
    out << "unexplained: " << percent(c.unexplained) << " of the difference; "
        << "pixels that still differ with every mistake above applied: " << c.unexplainedPixels << "\n";
    if (c.mostlyUnexplained())
        out << "  none of the known mistakes explains most of this difference\n";
}

QJsonObject toJson(const rl::ImageComparison& c, const QString& image, const QString& label,
                   const Provenance& p) {
    QJsonObject o;
    o[lit("image")] = image;
    o[lit("scene")] = label;
    o[lit("width")] = c.width;
    o[lit("height")] = c.height;
    o[lit("sizeFrom")] = p.sizeFrom;
    o[lit("imageFormat")] = p.format;
    o[lit("tolerance")] = c.tolerance;
    if (!p.cropped.isEmpty()) o[lit("cropped")] = p.cropped;
    o[lit("compared")] = qint64(c.compared);
    o[lit("differing")] = qint64(c.differing);
    o[lit("largestDifference")] =
        QJsonArray{c.largest[0], c.largest[1], c.largest[2], c.largest[3]};
    o[lit("meanDifference")] = QJsonArray{c.mean[0], c.mean[1], c.mean[2], c.mean[3]};
    o[lit("onlyOurs")] = qint64(c.onlyOurs);
    o[lit("onlyTheirs")] = qint64(c.onlyTheirs);
    o[lit("coveredByBoth")] = qint64(c.coveredByBoth);
    o[lit("totalDifference")] = qint64(c.difference);
    if (c.unlit)
        o[lit("unlit")] = QJsonObject{{lit("colour"), bytesJson(c.unlitColour)},
                                      {lit("comparedAs"), lit("coverage")}};
    QJsonArray diagnosis;
    for (const rl::Finding& f : c.diagnosis) {
        QJsonObject d;
        d[lit("mistake")] = QString::fromLatin1(rl::mistakeId(f.mistake));
        d[lit("title")] = QString::fromStdString(f.title.english());
        d[lit("evidence")] = QString::fromStdString(f.evidence.english());
        d[lit("advice")] = QString::fromStdString(f.advice.english());
        d[lit("explained")] = qint64(f.explained);
        d[lit("share")] = f.share;
        d[lit("removed")] = qint64(f.removed);
        d[lit("spoiled")] = qint64(f.spoiled);
        if (f.mistake == rl::Mistake::Shifted)
            d[lit("shift")] = QJsonArray{f.slip.shift.x, f.slip.shift.y};
        if (f.mistake == rl::Mistake::ScreenMap) {
            const rl::ScreenMap& m = f.slip.map;  // x' = xx x + xy y + tx, y' = yx x + yy y + ty
            d[lit("map")] = QJsonObject{{lit("xx"), m.xx}, {lit("xy"), m.xy}, {lit("tx"), m.tx},
                                        {lit("yx"), m.yx}, {lit("yy"), m.yy}, {lit("ty"), m.ty}};
        }
        if (f.mistake == rl::Mistake::ColourOffset || f.mistake == rl::Mistake::ColourScale)
            d[lit("amount")] = f.slip.amount;
        if (f.mistake == rl::Mistake::CommandMisread) {
            static const char* const kinds[] = {"ignored", "other-side", "transposed", "radians",
                                                "unnormalised-side"};
            d[lit("line")] = f.command.line;
            d[lit("command")] = QString::fromStdString(f.command.keyword);
            d[lit("variant")] = QString::fromLatin1(kinds[int(f.command.kind)]);
            if (f.command.everywhere) d[lit("occurrences")] = f.command.count;
        }
        QJsonArray examples;
        for (const rl::PixelExample& e : f.examples)
            examples.append(QJsonObject{{lit("x"), e.x},
                                        {lit("y"), e.y},
                                        {lit("ours"), bytesJson(e.ours)},
                                        {lit("theirs"), bytesJson(e.theirs)}});
        d[lit("examples")] = examples;
        diagnosis.append(d);
    }
    o[lit("diagnosis")] = diagnosis;
    o[lit("unexplained")] = QJsonObject{{lit("share"), c.unexplained},
                                        {lit("pixels"), qint64(c.unexplainedPixels)},
                                        {lit("most"), c.mostlyUnexplained()}};
    return o;
}

// What the comparison needs, loaded from the command line: the scene (a course scene or a
// command file's image), their image, and our frame when it was rendered on the way.
struct CompareInputs {
    std::shared_ptr<const rl::Scene> scene;
    std::size_t imageIndex = 0;  // of a command file's images
    QString sceneLabel;
    QString sizeFrom;  // where our size came from: the options, the lesson, the file, theirs
    QString imagePath;
    rl::Rgba8Image theirs;
    CompareImage::Format theirFormat;
    int theirWidth = 0, theirHeight = 0;  // before any crop
    std::optional<rl::OurFrame> ours;
    std::optional<rl::ivec2> croppedAt;  // where their screenshot held our frame
};

struct CompareOptionSet {
    const SceneOptions scene;
    const QCommandLineOption sceneName = SceneOptions::generatedSceneOption();
    const QCommandLineOption image{
        lit("image"),
        lit("Your image (required): PNG, PPM (P3 or P6), BMP, TGA or JPEG (compared with a "
            "tolerance). Without --size, ours is rendered at its size; a screenshot that holds "
            "our frame is cropped to it."),
        lit("THEIRS.png")};
    const QCommandLineOption diffOutput{
        lit("diff-output"),
        lit("Write the difference image: ours darkened, differing pixels from yellow (off by "
            "little) to red (by 64 or more), magenta where only we cover a pixel, cyan where "
            "only you do."),
        lit("FILE.png")};
    const QCommandLineOption format{lit("format"), lit("text (default) or json."), lit("FORMAT"),
                                    lit("text")};
};

bool readTheirImage(CompareInputs& in, QTextStream& err) {
    const QString problem = CompareImage::read(in.imagePath, in.theirs, &in.theirFormat);
    if (!problem.isEmpty()) {
        err << problem << '\n';
        err.flush();
        return false;
    }
    in.theirWidth = in.theirs.width;
    in.theirHeight = in.theirs.height;
    return true;
}

// A command file's scene: the png named like their image, else the first.
int loadCommandFileScene(const QCommandLineParser& parser, const CompareOptionSet& o,
                         const QString& path, rl::Diagnostics& diagnostics, CompareInputs& in,
                         QTextStream& err) {
    const SceneOptions& so = o.scene;
    for (const QCommandLineOption* option :
         {&so.camera, &so.lighting, &so.object, &o.sceneName, &so.size, &so.shading, &so.rules,
          &so.near, &so.naive, &so.backFaces})
        if (parser.isSet(*option))
            return usageError(err, lit("--%1 does not apply to a command file, which sets "
                                       "its own scene")
                                       .arg(option->names().first()));
    qint64 pixelLimit = 0;
    if (int code = readMaxPixels(parser, so.maxPixels, err, pixelLimit); code != ExitOk)
        return code;
    auto file = loadCommandFile(path, diagnostics);
    if (!file) {
        printDiagnostics(diagnostics, err);
        return inputError(err, file.error());
    }
    if (file->images.empty()) {
        err << path << ": the command file has no png command\n";
        return ExitBadInput;
    }
    const std::string theirName = QFileInfo(in.imagePath).fileName().toStdString();
    const rl::Hw2Image* chosen = &file->images.front();
    for (const rl::Hw2Image& i : file->images)
        if (i.fileName == theirName) chosen = &i;
    if (file->images.size() > 1 && chosen->fileName != theirName)
        err << "note: " << path << " names " << file->images.size()
            << " images; comparing the first, " << QString::fromStdString(chosen->fileName)
            << '\n';
    if (int code = checkPixelLimit(*chosen, pixelLimit, err); code != ExitOk) return code;
    in.imageIndex = static_cast<std::size_t>(chosen - file->images.data());
    in.scene = std::make_shared<const rl::Scene>(chosen->scene);
    in.sceneLabel = QString::fromStdString(chosen->fileName);
    in.sizeFrom = lit("the command file's png command");
    return ExitOk;
}

// A course scene, their image read first: without --size, ours is rendered at its size, or
// at the scene's own when their image is a screenshot that holds our frame.
int loadCourseScene(const QCommandLineParser& parser, const CompareOptionSet& o,
                    rl::Diagnostics& diagnostics, CompareInputs& in, QTextStream& err) {
    const SceneOptions& so = o.scene;
    in.sizeFrom = parser.isSet(so.size) ? lit("--size") : lit("the scene's size");
    if (!readTheirImage(in, err)) return ExitBadInput;
    rl::CourseSceneSettings settings;
    if (int code = so.settings(parser, err, settings); code != ExitOk) return code;
    so.lessonSettings(parser, o.sceneName, settings);
    if (int code = so.loadAny(parser, o.sceneName, settings, err, diagnostics, in.scene,
                              in.sceneLabel);
        code != ExitOk)
        return code;
    if (parser.isSet(so.size) ||
        (in.theirs.width == settings.width && in.theirs.height == settings.height))
        return ExitOk;
    auto atOwnSize = rl::renderOurFrame(in.scene);
    if (!atOwnSize) return inputError(err, atOwnSize.error());
    in.croppedAt = CompareImage::cropToFrame(atOwnSize->image, in.theirs);
    if (in.croppedAt) {
        in.ours = std::move(atOwnSize.value());
        return ExitOk;
    }
    qint64 pixelLimit = 0;
    if (int code = readMaxPixels(parser, so.maxPixels, err, pixelLimit); code != ExitOk)
        return code;
    if (qint64(in.theirs.width) * in.theirs.height > pixelLimit) {
        err << in.imagePath << ": the image is " << sizeText(in.theirs.width, in.theirs.height)
            << ", more pixels than the limit of " << pixelLimit << " (raise it with --max-pixels)\n";
        err.flush();
        return ExitBadInput;
    }
    settings.width = in.theirs.width;
    settings.height = in.theirs.height;
    diagnostics = {};
    if (int code = so.loadAny(parser, o.sceneName, settings, err, diagnostics, in.scene,
                              in.sceneLabel);
        code != ExitOk)
        return code;
    in.sizeFrom = lit("your image's size; --size overrides");
    return ExitOk;
}

// Our frame, rendered unless it was on the way, and their image of its size (cropped from a
// screenshot that holds it), or a bad input.
int matchOurFrame(bool commandFile, CompareInputs& in, Provenance& provenance, QTextStream& err) {
    if (!in.ours) {
        auto rendered = rl::renderOurFrame(in.scene);
        if (!rendered) return inputError(err, rendered.error());
        in.ours = std::move(rendered.value());
    }
    printDiagnostics(in.ours->trace->diagnostics, err);
    const rl::Rgba8Image& ourImage = in.ours->image;
    if (!in.croppedAt) in.croppedAt = CompareImage::cropToFrame(ourImage, in.theirs);
    if (const QString mismatch = CompareImage::sizeMismatch(in.imagePath, in.theirs, ourImage);
        !mismatch.isEmpty()) {
        err << mismatch << " ("
            << (commandFile ? lit("its png command sets the size")
                            : lit("no frame of ours found inside it at --size %1")
                                  .arg(sizeText(ourImage.width, ourImage.height)))
            << ")\n";
        err.flush();
        return ExitBadInput;
    }
    QString cropped;
    if (in.croppedAt)
        cropped = lit("cropped to %1 at (%2, %3) from %4, the frame found inside your image")
                      .arg(sizeText(ourImage.width, ourImage.height))
                      .arg(in.croppedAt->x)
                      .arg(in.croppedAt->y)
                      .arg(sizeText(in.theirWidth, in.theirHeight));
    if (!in.theirFormat.alpha) CompareImage::takeAlpha(ourImage, in.theirs);
    provenance = Provenance{in.theirFormat.describe(), in.sizeFrom, cropped};
    return ExitOk;
}

// The diagnosis as text or JSON, and the difference image where asked.
int printComparison(const CompareImage::Diagnosis& diagnosis, const CompareInputs& in,
                    const Provenance& provenance, bool json, const QString& diffPath,
                    QTextStream& out, QTextStream& err) {
    const rl::ImageComparison& comparison = diagnosis.comparison;
    QString sink;
    QTextStream quiet(&sink);  // JSON keeps stdout to itself
    const auto writeDiff = [&](QTextStream& to) {
        return diffPath.isEmpty() ||
               writePng(comparison.differenceImage, diffPath, to, err, lit("difference"));
    };
    if (json) {
        if (!writeDiff(quiet)) return ExitBadInput;
        QJsonObject o = toJson(comparison, in.imagePath, in.sceneLabel, provenance);
        if (comparison.differing > 0 && !comparison.unlit) o[lit("lightingFit")] = fitJson(diagnosis.fit);
        if (!diffPath.isEmpty()) o[lit("differenceImage")] = QFileInfo(diffPath).absoluteFilePath();
        out << QJsonDocument(o).toJson(QJsonDocument::Indented);
    } else {
        printText(comparison, in.imagePath, in.sceneLabel, provenance, out);
        printFit(diagnosis.fit, out);
        if (!writeDiff(out)) return ExitBadInput;
    }
    out.flush();
    return ExitOk;
}

}  // namespace

int runCompare(const QStringList& arguments, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        lit("Compare an image of your own rasterizer with RasterLab's render of the same scene "
            "(render's scene options, or a command file): a summary, a difference image, and "
            "the likely mistakes, each applied before the next is ranked by the difference it removes, "
            "and what stays unexplained."));
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({lit("h"), lit("help")}, lit("Show this help."));
    const CompareOptionSet o;
    parser.addOption(help);
    o.scene.addTo(parser);
    parser.addOptions({o.sceneName, o.image, o.diffOutput, o.format});
    parser.addPositionalArgument(
        lit("FILE"), lit("A command file: its png image is compared (optional)."), lit("[FILE]"));
    if (!parser.parse(arguments)) return usageError(err, parser.errorText());
    if (parser.isSet(help)) {
        out << commandHelp(parser, lit("compare"));
        return ExitOk;
    }
    const QStringList files = parser.positionalArguments();
    if (files.size() > 1)
        return usageError(err, lit("compare takes one command file, found %1").arg(files.size()));
    if (!parser.isSet(o.image)) return usageError(err, lit("compare needs --image THEIRS.png"));
    const bool json = parser.value(o.format) == lit("json");
    if (!json && parser.value(o.format) != lit("text"))
        return usageError(
            err, lit("--format expects text or json, found '%1'").arg(parser.value(o.format)));

    rl::Diagnostics diagnostics;
    CompareInputs in;
    in.imagePath = parser.value(o.image);
    const bool commandFile = !files.isEmpty();
    if (int code = commandFile ? loadCommandFileScene(parser, o, files.first(), diagnostics, in, err)
                               : loadCourseScene(parser, o, diagnostics, in, err);
        code != ExitOk)
        return code;
    printDiagnostics(diagnostics, err);
    if (commandFile && !readTheirImage(in, err)) return ExitBadInput;
    Provenance provenance;
    if (int code = matchOurFrame(commandFile, in, provenance, err); code != ExitOk) return code;

    // A command file's misread command, the catalogue, the lighting fitted to their colours.
    auto diagnosis = CompareImage::diagnose(*in.ours, in.theirs, in.theirFormat,
                                            commandFile ? files.first() : QString(), in.imageIndex);
    if (!diagnosis) return inputError(err, diagnosis.error());
    return printComparison(diagnosis.value(), in, provenance, json,
                           parser.isSet(o.diffOutput) ? parser.value(o.diffOutput) : QString(),
                           out, err);
}

}  // namespace rasterlab::cli
