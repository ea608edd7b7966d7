#include "cli.h"

#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSaveFile>

#include "default_scene.h"
#include "default_scene_resource.h"
#include "explain.h"
#include "image_io.h"
#include "output_image.h"
#include "renderer.h"

namespace rasterlab {

namespace {

constexpr int kMaxImageSide = 16384;

QString lit(const char* s) { return QString::fromUtf8(s); }

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

bool writePng(const rl::Rgba8Image& image, const QString& path, QTextStream& out,
              QTextStream& err, const QString& what) {
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
    const QCommandLineOption camera(lit("camera"), lit("Camera file (C; N; V; d hx hy)."),
                                    lit("FILE"));
    const QCommandLineOption lighting(lit("lighting"),
                                      lit("Lighting file (Pl; ka; Ia; kd; Od; ks; Il; n)."),
                                      lit("FILE"));
    const QCommandLineOption object(lit("object"), lit("Object file (.byu)."), lit("FILE"));
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
    const QCommandLineOption explain(lit("explain-pixel"),
                                     lit("Print the story of one pixel: the triangles that "
                                         "covered it, each depth test, and its Phong terms."),
                                     lit("X,Y"));
    parser.addOptions({help, camera, lighting, object, size, shading, output, depthOutput,
                       normalsOutput, near, naive, explain});
    if (!parser.parse(arguments)) return usageError(err, parser.errorText());
    if (parser.isSet(help)) {
        out << commandHelp(parser, lit("render"));
        return ExitOk;
    }
    if (!parser.positionalArguments().isEmpty())
        return usageError(err, lit("unexpected argument '%1'").arg(parser.positionalArguments().first()));

    rl::CourseSceneSettings settings;
    if (!parseSize(parser.value(size), settings.width, settings.height) || settings.width < 1 ||
        settings.height < 1)
        return usageError(err, lit("--size expects WIDTHxHEIGHT such as 800x600, found '%1'")
                                   .arg(parser.value(size)));
    if (settings.width > kMaxImageSide || settings.height > kMaxImageSide)
        return usageError(err, lit("--size %1 is larger than the limit of %2 pixels a side")
                                   .arg(parser.value(size))
                                   .arg(kMaxImageSide));
    const auto model = rl::shadingModelFromName(parser.value(shading).toStdString());
    if (!model)
        return usageError(err, lit("--shading expects phong, flat or gouraud, found '%1'")
                                   .arg(parser.value(shading)));
    settings.shading = *model;
    if (parser.isSet(near)) {
        bool ok = false;
        const double z = parser.value(near).toDouble(&ok);
        if (!ok || !(z > 0.0))
            return usageError(err, lit("--near expects a positive number, found '%1'")
                                       .arg(parser.value(near)));
        settings.nearPlane.fixedZ = z;
    }
    settings.nearPlane.naive = parser.isSet(naive);
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

    // Each file replaces its part of the default scene.
    rl::Diagnostics diagnostics;
    auto parts = loadDefaultCourseScene(diagnostics);
    if (!parts) return inputError(err, parts.error());
    if (parser.isSet(camera)) {
        auto c = loadCamera(parser.value(camera), diagnostics);
        if (!c) return inputError(err, c.error());
        parts->camera = c.value();
    }
    if (parser.isSet(lighting)) {
        auto l = loadLighting(parser.value(lighting), diagnostics);
        if (!l) return inputError(err, l.error());
        parts->lighting = l.value();
    }
    if (parser.isSet(object)) {
        auto o = loadObject(parser.value(object), diagnostics);
        if (!o) return inputError(err, o.error());
        parts->object = o.value();
    }
    if (!parser.isSet(camera) && !parser.isSet(lighting) && !parser.isSet(object))
        out << "rendering the embedded default scene\n";

    auto scene = std::make_shared<const rl::Scene>(rl::makeCourseScene(parts.value(), settings));
    rl::RenderOptions options;
    options.shading.keepNormals = parser.isSet(normalsOutput);
    auto trace = rl::renderFrame(scene, options);
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
        << rl::shadingModelName(settings.shading) << " shading, "
        << trace->depth->coveredPixels() << " pixels covered, "
        << QString::number(trace->totalMilliseconds, 'f', 1) << " ms\n";

    if (parser.isSet(explain)) {
        auto probe = rl::RecordingProbe::forPixel(explainX, explainY);
        auto traced = rl::traceFrame(scene, options, probe);
        if (traced) out << QString::fromStdString(rl::explainPixel(traced.value(), probe));
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
    if (command == lit("render"))
        code = runRender(rest, out, err);
    else if (command == lit("generate-default-scene"))
        code = runGenerateDefaultScene(rest, out, err);
    else
        code = usageError(err, lit("unknown command '%1' (commands: render, "
                                   "generate-default-scene)")
                                   .arg(command));
    out.flush();
    err.flush();
    return code;
}

}  // namespace rasterlab
