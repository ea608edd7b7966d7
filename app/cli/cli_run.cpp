// rasterlab-cli run: a command file (seed 001) and the PNG images it names.
#include "app/cli/cli_common.h"

#include <QDir>

#include <optional>

#include "app/documents/command_file.h"
#include "pipeline/render/explain.h"
#include "pipeline/render/renderer.h"

namespace rasterlab::cli {

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
    qint64 pixelLimit = 0;
    if (int code = readMaxPixels(parser, maxPixels, err, pixelLimit); code != ExitOk) return code;

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
        if (int code = checkPixelLimit(image, pixelLimit, err); code != ExitOk) return code;
        const bool explainHere =
            parser.isSet(explain) && explainX < scene.width && explainY < scene.height;
        std::optional<rl::RecordingProbe> probe;
        if (explainHere) probe = rl::RecordingProbe::forPixel(explainX, explainY);
        auto shared = std::make_shared<const rl::Scene>(scene);
        // The image alone is written: no z-buffer, ids or barycentrics are kept, and each
        // draw gets only the normals its shading reads (the recording probe keeps them all).
        rl::RenderOptions options;
        options.keepDepth = false;
        options.keepFragments = false;
        options.keepForViews = false;
        auto trace = probe ? rl::traceFrame(shared, {}, *probe) : rl::renderFrame(shared, options);
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

}  // namespace rasterlab::cli
