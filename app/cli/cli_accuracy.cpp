// rasterlab-cli accuracy: each mode's error against its run time, measured against an exact
// reference, as a table, a plot and heat maps.
#include "app/cli/cli_common.h"

#include <QDir>
#include <QFileInfo>
#include <QGuiApplication>

#include <algorithm>
#include <cmath>

#include "app/image_io.h"
#include "app/plots/accuracy_plot.h"
#include "pipeline/analysis/accuracy.h"
#include "pipeline/core/parallel.h"

namespace rasterlab::cli {

namespace {

// A list of whole numbers such as "1,2,4", each from least to most.
bool parseList(const QString& text, int least, int most, std::vector<int>& values) {
    values.clear();
    for (const QString& part : text.split(QLatin1Char(','))) {
        bool ok = false;
        const int v = part.trimmed().toInt(&ok);
        if (!ok || v < least || v > most) return false;
        if (std::find(values.begin(), values.end(), v) == values.end()) values.push_back(v);
    }
    return !values.empty();
}

// The report in the format --format names: JSON, CSV, or a Markdown table (md) under a line
// about the scene and the reference.
void printJson(const rl::AccuracyReport& report, QTextStream& out) {
    out << "[";
    bool first = true;
    for (const rl::AccuracyRow& row : report.rows) {
        const rl::AccuracyMetrics& m = row.metrics;
        out << (first ? "\n" : ",\n") << "  {\"mode\": \"" << rl::shadingModelName(row.mode.shading)
            << "\", \"rules\": \"" << rl::ruleSetName(row.mode.rules) << "\", \"precision\": \""
            << QString::fromStdString(row.precision)
            << "\", \"supersample\": " << row.mode.supersample * row.mode.supersample
            << ", \"ms\": " << number(row.milliseconds, 3)
            << ", \"rmse\": " << jsonNumber(m.rmse, 7)
            << ", \"max_error\": " << jsonNumber(m.maxError, 7)
            << ", \"psnr\": " << jsonNumber(m.psnr, 2)
            << ", \"coverage_mismatch\": " << jsonNumber(m.coverageMismatchShare(), 6)
            << ", \"within_1_255\": " << jsonNumber(m.within1Of255, 6)
            << ", \"depth_error_mean\": " << jsonNumber(m.depthMeanRelative, 9)
            << ", \"depth_error_max\": " << jsonNumber(m.depthMaxRelative, 9)
            << ", \"worst_x\": " << m.worstX << ", \"worst_y\": " << m.worstY
            << ", \"both_covered\": " << m.bothCovered
            << ", \"either_covered\": " << m.eitherCovered
            << ", \"coverage_mismatch_pixels\": " << m.coverageMismatch << "}";
        first = false;
    }
    out << "\n]\n";
}

void printCsv(const rl::AccuracyReport& report, QTextStream& out) {
    out << "mode,rules,precision,supersample,ms,rmse,max_error,psnr,coverage_mismatch,"
           "within_1_255,depth_error_mean,depth_error_max\n";
    for (const rl::AccuracyRow& row : report.rows) {
        const rl::AccuracyMetrics& m = row.metrics;
        out << rl::shadingModelName(row.mode.shading) << "," << rl::ruleSetName(row.mode.rules)
            << "," << QString::fromStdString(row.precision) << ","
            << row.mode.supersample * row.mode.supersample << "," << number(row.milliseconds, 3)
            << "," << number(m.rmse, 7) << "," << number(m.maxError, 7) << ","
            << (std::isfinite(m.psnr) ? number(m.psnr, 2) : lit("inf")) << ","
            << number(m.coverageMismatchShare(), 6) << "," << number(m.within1Of255, 6) << ","
            << number(m.depthMeanRelative, 9) << "," << number(m.depthMaxRelative, 9) << "\n";
    }
}

void printTable(const rl::AccuracyReport& report, const rl::Scene& scene, const QString& sceneLabel,
                QTextStream& out) {
    out << "Accuracy of " << sceneLabel << " at " << scene.width << "x" << scene.height << " ("
        << scene.triangleCount() << " triangles) against the exact reference ("
        << report.referenceRays << " rays, " << number(report.referenceMilliseconds, 0)
        << " ms). Colour errors in byte steps (1/255) over the pixels both cover; time is "
           "the median per frame.\n\n"
        << "| mode | rules | precision | samples | ms | RMSE | max error | PSNR dB | "
           "coverage mismatch | within 1/255 | depth error mean / max |\n"
        << "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const rl::AccuracyRow& row : report.rows) {
        const rl::AccuracyMetrics& m = row.metrics;
        out << "| " << rl::shadingModelName(row.mode.shading) << " | "
            << rl::ruleSetName(row.mode.rules) << " | " << QString::fromStdString(row.precision)
            << " | " << row.mode.supersample * row.mode.supersample << " | "
            << number(row.milliseconds, 2) << " | " << number(m.rmse * 255.0, 4) << " | "
            << number(m.maxError * 255.0, 3)
            << (m.worstX >= 0 ? lit(" at (%1, %2)").arg(m.worstX).arg(m.worstY) : QString())
            << " | " << (std::isfinite(m.psnr) ? number(m.psnr, 1) : lit("inf")) << " | "
            << number(100.0 * m.coverageMismatchShare(), 3) << " % (" << m.coverageMismatch
            << " px) | " << number(100.0 * m.within1Of255, 3) << " % | "
            << (std::isnan(m.depthMeanRelative)
                    ? lit("-")
                    : QString::number(m.depthMeanRelative, 'g', 2) + lit(" / ") +
                          QString::number(m.depthMaxRelative, 'g', 2))
            << " |\n";
    }
}

// --plot: error against run time. ExitOk, or ExitBadInput when the file cannot be written.
int writePlot(const rl::AccuracyReport& report, const rl::Scene& scene, const QString& sceneLabel,
              const QString& path, QTextStream& out, QTextStream& err) {
    const QString title = lit("Error against run time: %1, %2x%3, %4 triangles")
                              .arg(sceneLabel)
                              .arg(scene.width)
                              .arg(scene.height)
                              .arg(scene.triangleCount());
    QString error;
    if (!savePng(accuracyPlot(report, title), path, &error)) {
        err << path << ": cannot write the plot: " << error << "\n";
        return ExitBadInput;
    }
    out << "wrote " << QFileInfo(path).absoluteFilePath() << " (plot)\n";
    return ExitOk;
}

// --heatmaps: each mode's error heat map in the folder. ExitOk, or ExitBadInput when the
// folder or a file cannot be written.
int writeHeatMaps(const rl::AccuracyReport& report, const QString& folderPath, QTextStream& out,
                  QTextStream& err) {
    const QDir folder(folderPath);
    if (!QDir().mkpath(folder.path())) {
        err << folder.path() << ": cannot create the folder\n";
        return ExitBadInput;
    }
    for (const rl::AccuracyRow& row : report.rows) {
        QString name = QString::fromStdString(rl::accuracyModeName(row.mode));
        name.replace(QLatin1Char('/'), QLatin1Char('-')).replace(lit(" "), QString());
        const QString path = folder.filePath(lit("error-%1.png").arg(name));
        // One scale for every mode: 0 to 8 byte steps, larger errors white.
        QString error;
        if (!savePng(errorHeatMap(row.errorMap, 8.0f / 255.0f), path, &error)) {
            err << path << ": cannot write the heat map: " << error << "\n";
            return ExitBadInput;
        }
        out << "wrote " << QFileInfo(path).absoluteFilePath() << " (heat map)\n";
    }
    return ExitOk;
}

}  // namespace

int runAccuracy(const QStringList& arguments, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        lit("Render a scene in each mode (flat, Gouraud and Phong under the course, gpu and hw2 "
            "rules, optionally supersampled), time each (median of --repeats frames) and compare "
            "it with an exact reference: a ray cast per sample in double precision, exact "
            "barycentrics, perspective-correct attributes, the same lighting formula. Colours "
            "are compared as displayed, clamped and scaled to 0..1: RMSE, largest error and PSNR "
            "over the pixels both cover, the share of pixels whose coverage differs, the share "
            "within 1/255, and the relative error of the depth. --shading and --rules, when given, "
            "keep only that shading model or rule set."));
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({lit("h"), lit("help")}, lit("Show this help."));
    const SceneOptions sceneOptions;
    const QCommandLineOption sceneName = SceneOptions::generatedSceneOption();
    const QCommandLineOption format(lit("format"), lit("md (default), csv or json."), lit("FORMAT"),
                                    lit("md"));
    const QCommandLineOption plot(lit("plot"), lit("Also draw error against time to a PNG."),
                                  lit("FILE.png"));
    const QCommandLineOption heatmaps(
        lit("heatmaps"),
        lit("Also write each mode's error heat map to DIR (error-<mode>.png: 0 to 8 byte "
            "steps, dark blue to white; magenta where only one of the two covers a pixel)."),
        lit("DIR"));
    const QCommandLineOption repeats(lit("repeats"),
                                     lit("Frames timed per mode; the median is reported "
                                         "(default 5)."),
                                     lit("N"), lit("5"));
    const QCommandLineOption supersample(
        lit("supersample"),
        lit("Samples per pixel axis to measure, a list such as 1,2,4 (default 1): 2 is 2x2 "
            "samples averaged, for the render and the reference alike."),
        lit("LIST"), lit("1"));
    const QCommandLineOption threads(
        lit("threads"), lit("Threads to render with (default: every core)."), lit("N"));
    parser.addOption(help);
    sceneOptions.addTo(parser);
    parser.addOptions({sceneName, format, plot, heatmaps, repeats, supersample, threads});
    rl::CourseSceneSettings settings;
    if (auto code = parseSceneCommand(parser, arguments, help, lit("accuracy"), sceneOptions,
                                      sceneName, settings, out, err))
        return *code;
    const QString outputFormat = parser.value(format);
    if (auto code = checkTableFormat(outputFormat, err)) return *code;
    std::vector<int> repeatList, samples;
    if (!parseList(parser.value(repeats), 1, 1000, repeatList) || repeatList.size() != 1)
        return usageError(err, lit("--repeats expects a whole number from 1 to 1000, found '%1'")
                                   .arg(parser.value(repeats)));
    if (!parseList(parser.value(supersample), 1, 8, samples))
        return usageError(err, lit("--supersample expects whole numbers from 1 to 8 separated "
                                   "by commas, such as 1,2,4, found '%1'")
                                   .arg(parser.value(supersample)));
    int threadCount = 0;
    if (auto code = readThreads(parser, threads, threadCount, err)) return *code;
    if (parser.isSet(plot) && !qobject_cast<QGuiApplication*>(QCoreApplication::instance()))
        return usageError(err, lit("--plot needs the program's own start-up (run rasterlab-cli)"));

    rl::Diagnostics diagnostics;
    std::shared_ptr<const rl::Scene> scene;
    QString sceneLabel;
    if (int code =
            sceneOptions.loadAny(parser, sceneName, settings, err, diagnostics, scene, sceneLabel);
        code != ExitOk)
        return code;
    printDiagnostics(diagnostics, err);

    std::vector<rl::ShadingModel> shadings = {rl::ShadingModel::Flat, rl::ShadingModel::Gouraud,
                                              rl::ShadingModel::Phong};
    if (parser.isSet(sceneOptions.shading)) shadings = {settings.shading};
    std::vector<rl::RuleSet> ruleSets = {rl::RuleSet::Course, rl::RuleSet::Gpu, rl::RuleSet::Hw2};
    if (parser.isSet(sceneOptions.rules)) ruleSets = {*rl::ruleSetOf(settings.rules)};
    rl::AccuracyOptions options;
    options.modes = rl::defaultAccuracyModes(shadings, ruleSets, samples);
    options.repeats = repeatList.front();
    options.threads = threadCount;
    options.keepErrorMaps = parser.isSet(heatmaps);
    auto report = rl::measureAccuracy(*scene, options);
    if (!report) return inputError(err, report.error());

    if (outputFormat == lit("json"))
        printJson(*report, out);
    else if (outputFormat == lit("csv"))
        printCsv(*report, out);
    else
        printTable(*report, *scene, sceneLabel, out);
    if (parser.isSet(plot)) {
        if (int code = writePlot(*report, *scene, sceneLabel, parser.value(plot), out, err);
            code != ExitOk)
            return code;
    }
    if (parser.isSet(heatmaps)) {
        if (int code = writeHeatMaps(*report, parser.value(heatmaps), out, err); code != ExitOk)
            return code;
    }
    out.flush();
    return ExitOk;
}

}  // namespace rasterlab::cli
