// rasterlab-cli stability: a scene made stiffer along each axis, and at each step the error
// of float and double under the course and gpu rules against the exact reference, with time.
#include "app/cli/cli_common.h"

#include <QFileInfo>
#include <QGuiApplication>

#include <cmath>

#include "app/image_io.h"
#include "app/plots/stability_plot.h"
#include "pipeline/analysis/stability.h"
#include "pipeline/core/parallel.h"

namespace rasterlab::cli {

namespace {

QString scientific(double v) {
    return QString::number(v, 'g', 3);
}

QString errorText(const rl::StabilityPoint& point) {
    return point.error ? QString::fromStdString(point.error->message) : QString();
}

void printJson(const rl::StabilityReport& report, QTextStream& out) {
    out << "[";
    bool first = true;
    for (const rl::StabilityPoint& p : report.points) {
        const rl::AccuracyMetrics& m = p.row.metrics;
        out << (first ? "\n" : ",\n") << "  {\"axis\": \"" << rl::axisInfo(p.axis).name
            << "\", \"value\": " << scientific(p.value) << ", \"rules\": \""
            << rl::ruleSetName(p.row.mode.rules) << "\", \"precision\": \""
            << QString::fromStdString(p.row.precision) << "\"";
        if (p.error) {
            QString message = errorText(p);
            message.replace(QLatin1Char('\\'), lit("\\\\")).replace(QLatin1Char('"'), lit("\\\""));
            out << ", \"error\": \"" << message << "\"}";
        } else {
            out << ", \"ms\": " << jsonNumber(p.row.milliseconds, 3)
                << ", \"rmse\": " << jsonNumber(m.rmse, 9)
                << ", \"max_error\": " << jsonNumber(m.maxError, 9)
                << ", \"coverage_mismatch\": " << jsonNumber(m.coverageMismatchShare(), 6)
                << ", \"depth_error_mean\": " << jsonNumber(m.depthMeanRelative, 12)
                << ", \"depth_error_max\": " << jsonNumber(m.depthMaxRelative, 12)
                << ", \"float_vs_double_max\": " << jsonNumber(p.floatDoubleMax, 9)
                << ", \"float_vs_double_mean\": " << jsonNumber(p.floatDoubleMean, 12) << "}";
        }
        first = false;
    }
    out << "\n]\n";
}

void printCsv(const rl::StabilityReport& report, QTextStream& out) {
    out << "axis,value,rules,precision,ms,rmse,max_error,coverage_mismatch,depth_error_mean,"
           "depth_error_max,float_vs_double_max,float_vs_double_mean,error\n";
    for (const rl::StabilityPoint& p : report.points) {
        const rl::AccuracyMetrics& m = p.row.metrics;
        out << rl::axisInfo(p.axis).name << "," << scientific(p.value) << ","
            << rl::ruleSetName(p.row.mode.rules) << "," << QString::fromStdString(p.row.precision);
        if (p.error) {
            out << ",,,,,,,,,\"" << errorText(p).replace(QLatin1Char('"'), lit("\"\"")) << "\"\n";
            continue;
        }
        out << "," << jsonNumber(p.row.milliseconds, 3) << "," << jsonNumber(m.rmse, 9) << ","
            << jsonNumber(m.maxError, 9) << "," << jsonNumber(m.coverageMismatchShare(), 6) << ","
            << scientific(m.depthMeanRelative) << "," << scientific(m.depthMaxRelative) << ","
            << scientific(p.floatDoubleMax) << "," << scientific(p.floatDoubleMean) << ",\n";
    }
}

void printTable(const rl::StabilityReport& report, const rl::Scene& scene,
                const QString& sceneLabel, QTextStream& out) {
    out << "Stability of " << sceneLabel << " at " << scene.width << "x" << scene.height << " ("
        << scene.triangleCount() << " triangles), " << jsonNumber(report.milliseconds / 1000.0, 1)
        << " s. Colour errors in byte steps (1/255) against the exact reference; time is the "
           "median per frame.\n";
    std::optional<rl::StiffnessAxis> axis;
    for (const rl::StabilityPoint& p : report.points) {
        if (p.axis != axis) {
            axis = p.axis;
            const rl::StiffnessAxisInfo& info = rl::axisInfo(p.axis);
            out << "\n## " << info.name << " (" << info.unit << ")\n\n"
                << "| value | rules | precision | ms | RMSE | max error | coverage mismatch | "
                   "depth error max | float - double max / mean |\n"
                   "|---|---|---|---|---|---|---|---|---|\n";
        }
        out << "| " << scientific(p.value) << " | " << rl::ruleSetName(p.row.mode.rules) << " | "
            << QString::fromStdString(p.row.precision) << " | ";
        if (p.error) {
            out << errorText(p) << " | | | | | |\n";
            continue;
        }
        const rl::AccuracyMetrics& m = p.row.metrics;
        out << jsonNumber(p.row.milliseconds, 2) << " | " << scientific(m.rmse * 255.0) << " | "
            << scientific(m.maxError * 255.0) << " | "
            << jsonNumber(100.0 * m.coverageMismatchShare(), 3) << " % | "
            << (std::isnan(m.depthMaxRelative) ? lit("-") : scientific(m.depthMaxRelative)) << " | "
            << (std::isnan(p.floatDoubleMax) ? lit("-")
                                             : scientific(p.floatDoubleMax * 255.0) + lit(" / ") +
                                                   scientific(p.floatDoubleMean * 255.0))
            << " |\n";
    }
}

bool parseAxes(const QString& text, std::vector<rl::StiffnessAxis>& axes) {
    for (const QString& part : text.split(QLatin1Char(','))) {
        const auto axis = rl::stiffnessAxisFromName(part.trimmed().toStdString());
        if (!axis) return false;
        axes.push_back(*axis);
    }
    return true;
}

QString axisNames() {
    QStringList names;
    for (const rl::StiffnessAxisInfo& info : rl::stiffnessAxes())
        names << QString::fromLatin1(info.name);
    return names.join(lit(", "));
}

}  // namespace

int runStability(const QStringList& arguments, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        lit("Make a course scene stiffer step by step along each axis and measure, at each step, "
            "the error against the exact reference (colour RMSE and largest error in byte "
            "steps, coverage mismatch, depth error) in float and in double, under the course "
            "and gpu rules (or --rules), with the time per frame. Axes: offset (the scene and "
            "camera moved 1 to 1e12 units from the origin), scale (1e-6 to 1e6), distance (the "
            "scene brought 1 to 1e-9 times nearer the eye), sliver (triangles cut around "
            "slivers of 1e-1 to 1e-12 degrees), shininess (1 to 1e6), grazing (the camera's V "
            "1e-1 to 1e-12 degrees from N) and light (a light 1e-1 to 1e-9 times the scene's "
            "size above its surface). The shading model is Phong unless --shading says."));
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({lit("h"), lit("help")}, lit("Show this help."));
    const SceneOptions sceneOptions;
    const QCommandLineOption sceneName = SceneOptions::generatedSceneOption();
    const QCommandLineOption axesOption(lit("axes"),
                                        lit("The axes to sweep, separated by commas (default: "
                                            "all): %1.")
                                            .arg(axisNames()),
                                        lit("LIST"));
    const QCommandLineOption format(lit("format"), lit("md (default), csv or json."), lit("FORMAT"),
                                    lit("md"));
    const QCommandLineOption plot(lit("plot"),
                                  lit("Also draw error against stiffness, one panel per axis, "
                                      "and error against time, to a PNG."),
                                  lit("FILE.png"));
    const QCommandLineOption repeats(lit("repeats"),
                                     lit("Frames timed per point; the median is reported "
                                         "(default 3)."),
                                     lit("N"), lit("3"));
    const QCommandLineOption threads(
        lit("threads"), lit("Threads to render with (default: every core)."), lit("N"));
    parser.addOption(help);
    sceneOptions.addTo(parser);
    parser.addOptions({sceneName, axesOption, format, plot, repeats, threads});
    rl::CourseSceneSettings settings;
    if (auto code = parseSceneCommand(parser, arguments, help, lit("stability"), sceneOptions,
                                      sceneName, settings, out, err))
        return *code;
    const QString outputFormat = parser.value(format);
    if (auto code = checkTableFormat(outputFormat, err)) return *code;
    rl::StabilityOptions options;
    if (parser.isSet(axesOption) && !parseAxes(parser.value(axesOption), options.axes))
        return usageError(err, lit("--axes expects names among %1, separated by commas, found '%2'")
                                   .arg(axisNames(), parser.value(axesOption)));
    bool ok = false;
    options.repeats = parser.value(repeats).toInt(&ok);
    if (!ok || options.repeats < 1 || options.repeats > 1000)
        return usageError(err, lit("--repeats expects a whole number from 1 to 1000, found '%1'")
                                   .arg(parser.value(repeats)));
    if (auto code = readThreads(parser, threads, options.threads, err)) return *code;
    if (parser.isSet(plot) && !qobject_cast<QGuiApplication*>(QCoreApplication::instance()))
        return usageError(err, lit("--plot needs the program's own start-up (run rasterlab-cli)"));
    if (parser.isSet(sceneOptions.shading)) options.shading = settings.shading;
    if (parser.isSet(sceneOptions.rules)) options.rules = {*rl::ruleSetOf(settings.rules)};

    rl::Diagnostics diagnostics;
    std::shared_ptr<const rl::Scene> scene;
    QString sceneLabel;
    if (int code =
            sceneOptions.loadAny(parser, sceneName, settings, err, diagnostics, scene, sceneLabel);
        code != ExitOk)
        return code;
    printDiagnostics(diagnostics, err);
    auto report = rl::measureStability(*scene, options);
    if (!report) return inputError(err, report.error());
    if (outputFormat == lit("json"))
        printJson(*report, out);
    else if (outputFormat == lit("csv"))
        printCsv(*report, out);
    else
        printTable(*report, *scene, sceneLabel, out);
    if (parser.isSet(plot)) {
        const QString title = lit("Error against stiffness: %1, %2x%3, %4 triangles")
                                  .arg(sceneLabel)
                                  .arg(scene->width)
                                  .arg(scene->height)
                                  .arg(scene->triangleCount());
        QString error;
        if (!savePng(stabilityPlot(*report, title), parser.value(plot), &error)) {
            err << parser.value(plot) << ": cannot write the plot: " << error << "\n";
            return ExitBadInput;
        }
        out << "wrote " << QFileInfo(parser.value(plot)).absoluteFilePath() << " (plot)\n";
    }
    out.flush();
    return ExitOk;
}

}  // namespace rasterlab::cli
