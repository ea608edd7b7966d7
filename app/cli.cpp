#include "cli.h"

#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSaveFile>

#include <new>
#include <optional>

#include "command_file.h"
#include "default_scene.h"
#include "default_scene_resource.h"
#include "explain.h"
#include "image_io.h"
#include "output_image.h"
#include "renderer.h"

namespace rasterlab {

namespace {

constexpr int kMaxImageSide = 16384;
// The buffers of one frame take about 40 bytes a pixel (depth, triangle ids, barycentrics,
// colour, the RGBA image): 40 million pixels, such as 7680x4320, need about 1.6 GB.
constexpr qint64 kDefaultMaxPixels = 40'000'000;

QString lit(const char* s) {
    return QString::fromUtf8(s);
}

void printDiagnostics(const rl::Diagnostics& diagnostics, QTextStream& err) {
    for (const auto& d : diagnostics.items()) err << QString::fromStdString(d.toString()) << '\n';
}

int usageError(QTextStream& err, const QString& message) {
    err << "rasterlab-cli: " << message << '\n'
        << "Try 'rasterlab-cli --help' for more information.\n";
    err.flush();
    return ExitUsage;
}

int inputError(QTextStream& err, const rl::Error& error) {
    err << QString::fromStdString(error.toString()) << '\n';
    err.flush();
    return ExitBadInput;
}

QString generalHelp() {
    return lit(
        "Usage: rasterlab-cli <command> [options]\n"
        "\n"
        "RasterLab's software rasterization pipeline, without a window.\n"
        "\n"
        "Commands:\n"
        "  render                   Render a course scene (camera, lighting, object) to PNG.\n"
        "                           Without scene files, renders the embedded default scene.\n"
        "  run FILE                 Run a command file (seed 001's png, xyz, trif ...) and\n"
        "                           write the PNGs it names.\n"
        "  generate-default-scene   Write the default scene's three course files.\n"
        "\n"
        "Run 'rasterlab-cli <command> --help' for a command's options.\n");
}

// A subcommand's help. QCommandLineParser names the running executable in its usage line
// (from QCoreApplication::arguments(), not from the list it parsed): name the command.
QString commandHelp(const QCommandLineParser& parser, const QString& command) {
    QString text = parser.helpText();
    const QString prefix = lit("Usage: ");
    const qsizetype end = text.indexOf(lit(" [options]"));
    const qsizetype lineEnd = text.indexOf(QLatin1Char('\n'));
    if (text.startsWith(prefix) && end > 0 && (lineEnd < 0 || end < lineEnd))
        text.replace(0, end, prefix + lit("rasterlab-cli ") + command);
    return text;
}

bool parseSize(const QString& text, int& width, int& height) {
    static const QRegularExpression pattern(lit("^(\\d{1,6})[xX](\\d{1,6})$"));
    const auto match = pattern.match(text);
    if (!match.hasMatch()) return false;
    width = match.captured(1).toInt();
    height = match.captured(2).toInt();
    return true;
}

bool parsePixel(const QString& text, int& x, int& y) {
    static const QRegularExpression pattern(lit("^(\\d{1,6}),(\\d{1,6})$"));
    const auto match = pattern.match(text);
    if (!match.hasMatch()) return false;
    x = match.captured(1).toInt();
    y = match.captured(2).toInt();
    return true;
}

bool writePng(const rl::Rgba8Image& image, const QString& path, QTextStream& out, QTextStream& err,
              const QString& what) {
    QString error;
    if (!savePng(toQImage(image), path, &error)) {
        err << path << ": cannot write the " << what << ": " << error << '\n';
        return false;
    }
    out << "wrote " << QFileInfo(path).absoluteFilePath() << " (" << what << ", " << image.width
        << "x" << image.height << ")\n";
    return true;
}

int runRender(const QStringList& arguments, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(lit("Render a course scene to PNG."));
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({lit("h"), lit("help")}, lit("Show this help."));
    const QCommandLineOption camera(
        lit("camera"), lit("Camera file, in a layout --camera-format names."), lit("FILE"));
    const QCommandLineOption cameraFormat(
        lit("camera-format"),
        lit("Layout of the camera file: auto (default: detected, and named in a note), ufpe "
            "(C; N; V; d hx hy), ufrpe6 (N; V; d; hx; hy; C), ufrpe5 (C; N; V; hx hy; d) or "
            "keyvalue (C = x y z, N, V, d, hx, hy in any order). Detection: key = value when a "
            "line contains '='; otherwise the layout whose lines hold as many numbers as the "
            "file's, or the one layout a single line away."),
        lit("FORMAT"), lit("auto"));
    const QCommandLineOption lighting(
        lit("lighting"), lit("Lighting file, in a layout --lighting-format names."), lit("FILE"));
    const QCommandLineOption lightingFormat(
        lit("lighting-format"),
        lit("Layout of the lighting file: auto (default: detected, and named in a note), ufpe "
            "(Pl; ka; Ia; kd; Od; ks; Il; n), multi (ka; Ia; kd; Od; ks; n; L; then L times Pl; "
            "Il), ufrpe (Iamb; Ka; Il; Pl; Kd; Od; Ks; n) or keyvalue (Iamb = r g b, Ka, Il, Pl, "
            "Kd, Od, Ks, eta in any order). One key = value file may hold both the camera and "
            "the lighting."),
        lit("FORMAT"), lit("auto"));
    const QCommandLineOption object(
        lit("object"),
        lit("Object file (.byu: a triangle mesh, a course Bezier surface or a Movie.BYU file)."),
        lit("FILE"));
    const QCommandLineOption size(lit("size"), lit("Image size, default 800x600."), lit("WxH"),
                                  lit("800x600"));
    const QCommandLineOption shading(lit("shading"), lit("phong (default), flat or gouraud."),
                                     lit("MODEL"), lit("phong"));
    const QCommandLineOption output(lit("output"), lit("The PNG to write (required)."),
                                    lit("FILE.png"));
    const QCommandLineOption depthOutput(lit("depth-output"),
                                         lit("Also write the z-buffer as a grey PNG "
                                             "(near white, far dark, empty black)."),
                                         lit("FILE.png"));
    const QCommandLineOption normalsOutput(lit("normals-output"),
                                           lit("Also write the normals as a PNG, (N + 1) / 2 "
                                               "per channel, in view coordinates."),
                                           lit("FILE.png"));
    const QCommandLineOption near(lit("near"),
                                  lit("View-space z of the near plane (default: 0.001 times "
                                      "the farthest vertex's z)."),
                                  lit("Z"));
    const QCommandLineOption naive(lit("naive-projection"),
                                   lit("Divide by z even at or behind the camera, without "
                                       "clipping (shows why clipping exists)."));
    const QCommandLineOption maxPixels(lit("max-pixels"),
                                       lit("Refuse images with more pixels than this "
                                           "(default 40000000, about 1.6 GB of buffers)."),
                                       lit("N"), QString::number(kDefaultMaxPixels));
    const QCommandLineOption explain(lit("explain-pixel"),
                                     lit("Print the story of one pixel: the triangles that "
                                         "covered it, each depth test, and its Phong terms."),
                                     lit("X,Y"));
    parser.addOptions({help, camera, cameraFormat, lighting, lightingFormat, object, size, shading,
                       output, depthOutput, normalsOutput, near, naive, maxPixels, explain});
    if (!parser.parse(arguments)) return usageError(err, parser.errorText());
    if (parser.isSet(help)) {
        out << commandHelp(parser, lit("render"));
        return ExitOk;
    }
    if (!parser.positionalArguments().isEmpty())
        return usageError(
            err, lit("unexpected argument '%1'").arg(parser.positionalArguments().first()));

    rl::CourseSceneSettings settings;
    if (!parseSize(parser.value(size), settings.width, settings.height) || settings.width < 1 ||
        settings.height < 1)
        return usageError(
            err,
            lit("--size expects WIDTHxHEIGHT such as 800x600, found '%1'").arg(parser.value(size)));
    if (settings.width > kMaxImageSide || settings.height > kMaxImageSide)
        return usageError(err, lit("--size %1 is larger than the limit of %2 pixels a side")
                                   .arg(parser.value(size))
                                   .arg(kMaxImageSide));
    bool maxOk = false;
    const qint64 pixelLimit = parser.value(maxPixels).toLongLong(&maxOk);
    if (!maxOk || pixelLimit < 1)
        return usageError(err, lit("--max-pixels expects a positive whole number, found '%1'")
                                   .arg(parser.value(maxPixels)));
    if (qint64(settings.width) * settings.height > pixelLimit)
        return usageError(err, lit("--size %1 has %2 pixels, more than the limit of %3 (raise it "
                                   "with --max-pixels if the memory is there)")
                                   .arg(parser.value(size))
                                   .arg(qint64(settings.width) * settings.height)
                                   .arg(pixelLimit));
    const auto model = rl::shadingModelFromName(parser.value(shading).toStdString());
    if (!model)
        return usageError(
            err,
            lit("--shading expects phong, flat or gouraud, found '%1'").arg(parser.value(shading)));
    settings.shading = *model;
    const auto cameraLayout = rl::cameraLayoutFromName(parser.value(cameraFormat).toStdString());
    if (!cameraLayout)
        return usageError(err, lit("--camera-format expects auto, ufpe, ufrpe6, ufrpe5 or "
                                   "keyvalue, found '%1'")
                                   .arg(parser.value(cameraFormat)));
    if (parser.isSet(cameraFormat) && !parser.isSet(camera))
        return usageError(err, lit("--camera-format applies to the file of --camera, which is "
                                   "not given"));
    const auto lightingLayout =
        rl::lightingLayoutFromName(parser.value(lightingFormat).toStdString());
    if (!lightingLayout)
        return usageError(err, lit("--lighting-format expects auto, ufpe, multi, ufrpe or "
                                   "keyvalue, found '%1'")
                                   .arg(parser.value(lightingFormat)));
    if (parser.isSet(lightingFormat) && !parser.isSet(lighting))
        return usageError(err, lit("--lighting-format applies to the file of --lighting, which "
                                   "is not given"));
    if (parser.isSet(near)) {
        bool ok = false;
        const double z = parser.value(near).toDouble(&ok);
        if (!ok || !(z > 0.0))
            return usageError(
                err, lit("--near expects a positive number, found '%1'").arg(parser.value(near)));
        settings.nearPlane.fixedW = z;
    }
    if (parser.isSet(naive)) settings.nearPlane.mode = rl::NearPlane::Mode::Naive;
    if (!parser.isSet(output)) return usageError(err, lit("render needs --output FILE.png"));
    int explainX = -1, explainY = -1;
    if (parser.isSet(explain)) {
        if (!parsePixel(parser.value(explain), explainX, explainY))
            return usageError(err, lit("--explain-pixel expects X,Y such as 400,300, found '%1'")
                                       .arg(parser.value(explain)));
        if (explainX >= settings.width || explainY >= settings.height)
            return usageError(err, lit("--explain-pixel %1 is outside the %2x%3 image")
                                       .arg(parser.value(explain))
                                       .arg(settings.width)
                                       .arg(settings.height));
    }

    // Each part from its file, or from the default scene where no file is given.
    rl::Diagnostics diagnostics;
    const auto source = [&](const QCommandLineOption& option, CoursePart part) {
        return parser.isSet(option) ? parser.value(option) : defaultScenePath(part);
    };
    auto c = loadCamera(source(camera, CoursePart::Camera), diagnostics, *cameraLayout);
    if (!c) return inputError(err, c.error());
    auto l = loadLighting(source(lighting, CoursePart::Lighting), diagnostics, *lightingLayout);
    if (!l) return inputError(err, l.error());
    auto o = loadObject(source(object, CoursePart::Object), diagnostics);
    if (!o) return inputError(err, o.error());
    if (!parser.isSet(camera) && !parser.isSet(lighting) && !parser.isSet(object))
        out << "rendering the embedded default scene\n";

    auto scene = std::make_shared<const rl::Scene>(
        rl::makeCourseScene({c.value(), l.value(), o.value()}, settings));
    rl::RenderOptions options;
    options.shading.keepNormals = parser.isSet(normalsOutput);
    // With --explain-pixel the one render records that pixel's events; the recording probe
    // leaves every buffer as the plain render would.
    std::optional<rl::RecordingProbe> probe;
    if (parser.isSet(explain)) probe = rl::RecordingProbe::forPixel(explainX, explainY);
    auto trace = probe ? rl::traceFrame(scene, options, *probe) : rl::renderFrame(scene, options);
    if (!trace) {
        printDiagnostics(diagnostics, err);
        return inputError(err, trace.error());
    }
    diagnostics.append(trace->diagnostics);
    printDiagnostics(diagnostics, err);

    const rl::Rgba8Image colour =
        rl::colourImage(*trace->shading, *trace->depth, scene->conventions);
    if (!writePng(colour, parser.value(output), out, err, lit("image"))) return ExitBadInput;
    if (parser.isSet(depthOutput)) {
        const rl::DepthRange range = rl::depthRange(trace->depth->depth);
        if (!writePng(rl::depthImage(trace->depth->depth, range), parser.value(depthOutput), out,
                      err, lit("z-buffer")))
            return ExitBadInput;
        if (!range.empty)
            out << "  z-buffer range: " << range.nearest << " (white) to " << range.farthest
                << " (dark grey)\n";
    }
    if (parser.isSet(normalsOutput) &&
        !writePng(rl::normalImage(trace->shading->normal, *trace->depth),
                  parser.value(normalsOutput), out, err, lit("normals")))
        return ExitBadInput;

    out << "  " << scene->triangleCount() << " triangles, "
        << rl::shadingModelName(settings.shading) << " shading, " << trace->depth->coveredPixels()
        << " pixels covered, " << QString::number(trace->totalMilliseconds, 'f', 1) << " ms\n";

    if (probe) out << QString::fromStdString(rl::explainPixel(trace.value(), *probe));
    out.flush();
    return ExitOk;
}

int runCommandFile(const QStringList& arguments, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        lit("Run a command file and write the PNG images it names (8-bit RGBA, untouched "
            "pixels transparent black)."));
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({lit("h"), lit("help")}, lit("Show this help."));
    const QCommandLineOption outdir(lit("outdir"),
                                    lit("The folder to write the images into (default: the "
                                        "current folder)."),
                                    lit("DIR"), lit("."));
    const QCommandLineOption maxPixels(lit("max-pixels"),
                                       lit("Refuse images with more pixels than this "
                                           "(default 40000000)."),
                                       lit("N"), QString::number(kDefaultMaxPixels));
    const QCommandLineOption explain(lit("explain-pixel"),
                                     lit("Print the story of one pixel of each image: the "
                                         "triangles that covered it, each depth test, and its "
                                         "lighting."),
                                     lit("X,Y"));
    parser.addOptions({help, outdir, maxPixels, explain});
    parser.addPositionalArgument(lit("FILE"), lit("The command file."));
    if (!parser.parse(arguments)) return usageError(err, parser.errorText());
    if (parser.isSet(help)) {
        out << commandHelp(parser, lit("run"));
        return ExitOk;
    }
    const QStringList files = parser.positionalArguments();
    if (files.size() != 1)
        return usageError(err, files.isEmpty()
                                   ? lit("run needs a command file")
                                   : lit("run takes one command file, found %1").arg(files.size()));
    bool maxOk = false;
    const qint64 pixelLimit = parser.value(maxPixels).toLongLong(&maxOk);
    if (!maxOk || pixelLimit < 1)
        return usageError(err, lit("--max-pixels expects a positive whole number, found '%1'")
                                   .arg(parser.value(maxPixels)));

    int explainX = -1, explainY = -1;
    if (parser.isSet(explain) && !parsePixel(parser.value(explain), explainX, explainY))
        return usageError(err, lit("--explain-pixel expects X,Y such as 400,300, found '%1'")
                                   .arg(parser.value(explain)));

    rl::Diagnostics diagnostics;
    auto file = loadCommandFile(files.first(), diagnostics);
    if (!file) {
        printDiagnostics(diagnostics, err);
        return inputError(err, file.error());
    }
    printDiagnostics(diagnostics, err);
    const QDir folder(parser.value(outdir));
    if (!QDir().mkpath(folder.path())) {
        err << folder.path() << ": cannot create the folder\n";
        return ExitBadInput;
    }
    for (const rl::Hw2Image& image : file->images) {
        const rl::Scene& scene = image.scene;
        if (qint64(scene.width) * scene.height > pixelLimit)
            return inputError(
                err, rl::makeError(
                         rl::ErrorCode::Range, image.where,
                         "the image " + std::to_string(scene.width) + "x" +
                             std::to_string(scene.height) + " has more pixels than the limit of " +
                             std::to_string(pixelLimit) + " (raise it with --max-pixels)"));
        const bool explainHere =
            parser.isSet(explain) && explainX < scene.width && explainY < scene.height;
        std::optional<rl::RecordingProbe> probe;
        if (explainHere) probe = rl::RecordingProbe::forPixel(explainX, explainY);
        auto shared = std::make_shared<const rl::Scene>(scene);
        auto trace = probe ? rl::traceFrame(shared, {}, *probe) : rl::renderFrame(shared);
        if (!trace) return inputError(err, trace.error());
        printDiagnostics(trace->diagnostics, err);
        const QString name = QString::fromStdString(image.fileName);
        if (!writePng(rl::colourImage(*trace->shading, *trace->depth, scene.conventions),
                      folder.filePath(name), out, err, lit("image")))
            return ExitBadInput;
        out << "  " << scene.triangleCount() << " triangles in " << scene.draws.size() << " draws, "
            << trace->depth->coveredPixels() << " pixels covered, "
            << QString::number(trace->totalMilliseconds, 'f', 1) << " ms\n";
        if (probe)
            out << QString::fromStdString(rl::explainPixel(trace.value(), *probe));
        else if (parser.isSet(explain))
            err << "rasterlab-cli: --explain-pixel " << parser.value(explain) << " is outside the "
                << scene.width << "x" << scene.height << " image " << name << '\n';
    }
    out.flush();
    return ExitOk;
}

int runGenerateDefaultScene(const QStringList& arguments, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(lit("Write the default scene's three course files."));
    const QCommandLineOption help({lit("h"), lit("help")}, lit("Show this help."));
    const QCommandLineOption dir(lit("dir"), lit("The folder to write into (created if needed)."),
                                 lit("DIR"));
    parser.addOptions({help, dir});
    if (!parser.parse(arguments)) return usageError(err, parser.errorText());
    if (parser.isSet(help)) {
        out << commandHelp(parser, lit("generate-default-scene"));
        return ExitOk;
    }
    if (!parser.isSet(dir)) return usageError(err, lit("generate-default-scene needs --dir DIR"));
    const QDir folder(parser.value(dir));
    if (!QDir().mkpath(folder.path())) {
        err << folder.path() << ": cannot create the folder\n";
        return ExitBadInput;
    }
    const rl::CourseSceneTexts texts = rl::generateDefaultScene();
    const std::pair<const char*, const std::string*> files[] = {
        {rl::kDefaultCameraFile, &texts.camera},
        {rl::kDefaultLightingFile, &texts.lighting},
        {rl::kDefaultObjectFile, &texts.object},
    };
    for (const auto& [name, text] : files) {
        const QString path = folder.filePath(QString::fromUtf8(name));
        QSaveFile file(path);
        if (!file.open(QIODevice::WriteOnly) ||
            file.write(text->data(), static_cast<qint64>(text->size())) !=
                static_cast<qint64>(text->size()) ||
            !file.commit()) {
            err << path << ": cannot write: " << file.errorString() << '\n';
            return ExitBadInput;
        }
        out << "wrote " << QFileInfo(path).absoluteFilePath() << '\n';
    }
    return ExitOk;
}

}  // namespace

int runCli(const QStringList& arguments, QTextStream& out, QTextStream& err) {
    const QString command = arguments.value(1);
    if (command.isEmpty() || command == lit("-h") || command == lit("--help") ||
        command == lit("help")) {
        out << generalHelp();
        out.flush();
        return command.isEmpty() ? ExitUsage : ExitOk;
    }
    if (command == lit("--version")) {
        out << "rasterlab-cli " << RASTERLAB_VERSION << '\n';
        return ExitOk;
    }
    QStringList rest = arguments.mid(2);
    rest.prepend(arguments.first() + QLatin1Char(' ') + command);
    int code = ExitUsage;
    try {
        if (command == lit("render"))
            code = runRender(rest, out, err);
        else if (command == lit("run"))
            code = runCommandFile(rest, out, err);
        else if (command == lit("generate-default-scene"))
            code = runGenerateDefaultScene(rest, out, err);
        else
            code = usageError(err, lit("unknown command '%1' (commands: render, run, "
                                       "generate-default-scene)")
                                       .arg(command));
    } catch (const std::bad_alloc&) {
        // The only exception the pipeline can meet: a frame larger than the memory.
        out.flush();
        err << "rasterlab-cli: not enough memory for this render (try a smaller --size)\n";
        code = ExitBadInput;
    }
    out.flush();
    err.flush();
    return code;
}

}  // namespace rasterlab
