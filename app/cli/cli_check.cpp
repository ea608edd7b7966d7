// rasterlab-cli check: a student's program asked for each stage of the pipeline over the stage
// protocol (docs/stage-protocol.md), each answer held to the lecture's stage; and
// rasterlab-cli grade: every submission of a class through the same check.
#include "app/cli/cli_common.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include "app/check/check_session.h"

namespace rasterlab::cli {

namespace {

// Exit status of check beyond cli.h's: a stage failed or was unsupported; the program broke.
constexpr int ExitStageFailed = 3;
constexpr int ExitProgramBroke = 4;

struct LimitOptions {
    QCommandLineOption requestSeconds{lit("request-timeout"),
                                      lit("Seconds the program has for one answer (default 20)."),
                                      lit("S"), lit("20")};
    QCommandLineOption totalSeconds{
        lit("timeout"), lit("Seconds the program has in all (default 120)."), lit("S"), lit("120")};
    QCommandLineOption memory{lit("memory"),
                              lit("Megabytes of address space the program may use (default "
                                  "2048)."),
                              lit("MB"), lit("2048")};
    QCommandLineOption noSandbox{
        lit("no-sandbox"),
        lit("Run the program without bubblewrap even where it is installed (the other limits "
            "stay).")};

    void addTo(QCommandLineParser& parser) const {
        parser.addOptions({requestSeconds, totalSeconds, memory, noSandbox});
    }

    std::optional<int> read(const QCommandLineParser& parser, check::Limits& limits,
                            QTextStream& err) const {
        const auto positive = [&](const QCommandLineOption& option, double high,
                                  double& value) -> bool {
            bool ok = false;
            value = parser.value(option).toDouble(&ok);
            return ok && value > 0.0 && value <= high;
        };
        double v = 0.0;
        if (!positive(requestSeconds, 3600.0, v))
            return usageError(err,
                              lit("--request-timeout expects seconds from 0 to 3600, found '%1'")
                                  .arg(parser.value(requestSeconds)));
        limits.requestSeconds = v;
        if (!positive(totalSeconds, 86400.0, v))
            return usageError(err, lit("--timeout expects seconds from 0 to 86400, found '%1'")
                                       .arg(parser.value(totalSeconds)));
        limits.totalSeconds = v;
        limits.cpuSeconds = int(std::ceil(v));
        if (!positive(memory, 1 << 20, v) || v < 16)
            return usageError(
                err,
                lit("--memory expects megabytes from 16, found '%1'").arg(parser.value(memory)));
        limits.memoryBytes = static_cast<long long>(v) << 20;
        limits.sandbox = !parser.isSet(noSandbox);
        return std::nullopt;
    }
};

std::optional<int> readStages(const QString& text, std::vector<check::Stage>& stages,
                              QTextStream& err) {
    stages.clear();
    for (const QString& name : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const auto stage = check::stageNamed(name.trimmed().toStdString());
        if (!stage)
            return usageError(err, lit("--stages expects names among basis, view, normals, "
                                       "projection, scan, zbuffer, lighting, frame; found '%1'")
                                       .arg(name));
        stages.push_back(*stage);
    }
    if (stages.empty()) return usageError(err, lit("--stages names no stage"));
    return std::nullopt;
}

int exitCodeOf(const check::CheckReport& report) {
    if (report.passed()) return ExitOk;
    return report.anyBroken() ? ExitProgramBroke : ExitStageFailed;
}

}  // namespace

int runCheck(const QStringList& arguments, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        lit("Check your rasterizer stage by stage: your program answers each stage's request "
            "over the stage protocol (docs/stage-protocol.md) and every answer is held to the "
            "lecture's stage. Without scene options: the shipped lessons and the default scene "
            "at 160x120. Exit status 0 when every stage passes, 3 when a stage fails or is "
            "unsupported, 4 when the program breaks (a bad answer, a timeout, a crash)."));
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({lit("h"), lit("help")}, lit("Show this help."));
    const QCommandLineOption program(lit("program"),
                                     lit("The command that starts your program (run with "
                                         "/bin/sh in --folder); required."),
                                     lit("CMD"));
    const QCommandLineOption folder(lit("folder"),
                                    lit("The folder the program runs in (default: the current "
                                        "one)."),
                                    lit("DIR"));
    const QCommandLineOption format(lit("format"), lit("text (default), md or json."),
                                    lit("FORMAT"), lit("text"));
    const QCommandLineOption stagesOption(lit("stages"),
                                          lit("Only these stages, comma-separated (default: "
                                              "all eight)."),
                                          lit("LIST"));
    const SceneOptions sceneOptions;
    const LimitOptions limitOptions;
    const QCommandLineOption sceneName = SceneOptions::generatedSceneOption();
    parser.addOption(help);
    sceneOptions.addTo(parser);
    limitOptions.addTo(parser);
    parser.addOptions({sceneName, program, folder, format, stagesOption});
    rl::CourseSceneSettings settings;
    if (auto code = parseSceneCommand(parser, arguments, help, lit("check"), sceneOptions,
                                      sceneName, settings, out, err))
        return *code;
    if (!parser.isSet(program) || parser.value(program).trimmed().isEmpty())
        return usageError(err, lit("check needs --program CMD"));
    const QString formatName = parser.value(format);
    if (formatName != lit("text") && formatName != lit("md") && formatName != lit("json"))
        return usageError(err,
                          lit("--format expects text, md or json, found '%1'").arg(formatName));
    check::CheckOptions options;
    if (auto code = limitOptions.read(parser, options.limits, err)) return *code;
    if (parser.isSet(stagesOption))
        if (auto code = readStages(parser.value(stagesOption), options.stages, err)) return *code;
    const QString dir = parser.isSet(folder) ? parser.value(folder) : QDir::currentPath();
    if (!QFileInfo(dir).isDir())
        return usageError(err, lit("--folder: '%1' is not a folder").arg(dir));

    std::vector<check::CheckScene> scenes;
    if (sceneOptions.anyFile(parser) || parser.isSet(sceneName)) {
        rl::Diagnostics diagnostics;
        std::shared_ptr<const rl::Scene> scene;
        QString label;
        if (int code =
                sceneOptions.loadAny(parser, sceneName, settings, err, diagnostics, scene, label);
            code != ExitOk)
            return code;
        printDiagnostics(diagnostics, err);
        // The seed draws every triangle: the generated scenes' saving is left out.
        auto drawn = std::make_shared<rl::Scene>(*scene);
        drawn->cullHiddenBackFaces = false;
        scenes.push_back({label.toStdString(), drawn});
    } else {
        scenes = check::defaultCheckScenes();
    }
    const check::CheckReport report =
        check::runCheck(parser.value(program).toStdString(),
                        QFileInfo(dir).absoluteFilePath().toStdString(), scenes, options);
    out << QString::fromStdString(check::formatReport(report, formatName.toStdString()));
    return exitCodeOf(report);
}

}  // namespace rasterlab::cli
