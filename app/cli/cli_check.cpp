// rasterlab-cli check: a student's program asked for each stage of the pipeline over the stage
// protocol (docs/stage-protocol.md), each answer held to the lecture's stage; and
// rasterlab-cli grade: every submission of a class through the same check.
#include "app/cli/cli_common.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include "app/check/check_session.h"
#include "app/check/grade.h"
#include "app/check/hw2_grade.h"

namespace rasterlab::cli {

namespace {

// Exit status of check beyond cli.h's: a stage failed or was unsupported; the program broke.
constexpr int ExitStageFailed = 3;
constexpr int ExitProgramBroke = 4;

// What check and grade share: the stages asked, and the limits the program runs under.
struct CheckOptionSet {
    QCommandLineOption stages{lit("stages"),
                              lit("Only these stages, comma-separated (default: all eight)."),
                              lit("LIST")};
    QCommandLineOption requestSeconds{lit("request-timeout"),
                                      lit("Seconds the program has for one answer (default 20)."),
                                      lit("S"), lit("20")};
    QCommandLineOption totalSeconds{
        lit("timeout"), lit("Seconds the program has in all (default 120)."), lit("S"), lit("120")};
    QCommandLineOption memory{lit("memory"),
                              lit("Megabytes of memory (data, not address space) the program "
                                  "may use (default 2048; 0: no limit, for a program built "
                                  "with AddressSanitizer)."),
                              lit("MB"), lit("2048")};
    QCommandLineOption noSandbox{
        lit("no-sandbox"),
        lit("Run the program without bubblewrap even where it is installed (the other limits "
            "stay).")};

    void addTo(QCommandLineParser& parser) const {
        parser.addOptions({requestSeconds, totalSeconds, memory, noSandbox, stages});
    }

    std::optional<int> read(const QCommandLineParser& parser, check::CheckOptions& options,
                            QTextStream& err) const;
    std::optional<int> readLimits(const QCommandLineParser& parser, check::Limits& limits,
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
        bool whole = false;
        const long long megabytes = parser.value(memory).toLongLong(&whole);
        if (!whole || (megabytes != 0 && (megabytes < 16 || megabytes > (1 << 20))))
            return usageError(err,
                              lit("--memory expects megabytes from 16 (or 0: no limit), found '%1'")
                                  .arg(parser.value(memory)));
        limits.memoryBytes = megabytes << 20;
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

std::optional<int> CheckOptionSet::read(const QCommandLineParser& parser,
                                        check::CheckOptions& options, QTextStream& err) const {
    if (auto code = readLimits(parser, options.limits, err)) return code;
    if (parser.isSet(stages)) return readStages(parser.value(stages), options.stages, err);
    return std::nullopt;
}

int exitCodeOf(const check::CheckReport& report) {
    if (report.passed()) return ExitOk;
    return report.anyBroken() ? ExitProgramBroke : ExitStageFailed;
}

// The scene the options name, or the default scenes when they name none.
int chooseScenes(const QCommandLineParser& parser, const SceneOptions& sceneOptions,
                 const QCommandLineOption& sceneName, const rl::CourseSceneSettings& settings,
                 QTextStream& err, std::vector<check::CheckScene>& scenes) {
    if (!sceneOptions.anyFile(parser) && !parser.isSet(sceneName)) {
        scenes = check::defaultCheckScenes();
        return ExitOk;
    }
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
    return ExitOk;
}

bool writeText(const QString& path, const std::string& text, QTextStream& err);

// A grade table as grades.csv and grades.md in dir.
bool writeTables(const QDir& dir, const std::string& csv, const std::string& md, QTextStream& err) {
    return writeText(dir.filePath(lit("grades.csv")), csv, err) &&
           writeText(dir.filePath(lit("grades.md")), md, err);
}

bool writeText(const QString& path, const std::string& text, QTextStream& err) {
    QFile file(path);
    if (file.open(QIODevice::WriteOnly | QIODevice::Truncate) &&
        file.write(text.data(), qint64(text.size())) == qint64(text.size()))
        return true;
    err << "rasterlab-cli: cannot write " << path << ": " << file.errorString() << '\n';
    return false;
}

// grade --hw2: every submission's program run on each command file.
int gradeHw2(const QCommandLineParser& parser, const QCommandLineOption& hw2,
             const QCommandLineOption& output, const QString& format, int jobs,
             const check::CheckOptions& options, const std::vector<check::Submission>& submissions,
             QTextStream& out, QTextStream& err) {
    std::vector<check::Hw2Case> cases;
    for (const QString& path : parser.values(hw2)) {
        auto c = check::loadHw2Case(path.toStdString());
        if (!c) return inputError(err, c.error());
        cases.push_back(std::move(c.value()));
    }
    std::vector<std::vector<check::Hw2Verdict>> verdicts(submissions.size());
    check::forEachInParallel(
        submissions.size(), jobs,
        [&](std::size_t i) {
            verdicts[i] = check::gradeHw2(submissions[i], cases, options.limits);
        },
        [&](std::size_t i, int done) {
            err << "graded " << done << "/" << submissions.size() << ": "
                << QString::fromStdString(submissions[i].name) << '\n';
            err.flush();
        });
    out << QString::fromStdString(check::hw2Table(submissions, verdicts, format.toStdString()));
    if (!parser.isSet(output)) return ExitOk;
    const QDir dir(parser.value(output));
    if (!dir.mkpath(lit(".")))
        return usageError(err, lit("--output: cannot make the folder '%1'").arg(dir.path()));
    return writeTables(dir, check::hw2Table(submissions, verdicts, "csv"),
                       check::hw2Table(submissions, verdicts, "md"), err)
               ? ExitOk
               : ExitBadInput;
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
    const QCommandLineOption chain(lit("chain"),
                                   lit("Give each stage the program's own earlier answers as "
                                       "its input, to see how errors add up (by default each "
                                       "stage gets RasterLab's, so no mistake hides another)."));
    const SceneOptions sceneOptions;
    const CheckOptionSet checkOptions;
    const QCommandLineOption sceneName = SceneOptions::generatedSceneOption();
    parser.addOption(help);
    sceneOptions.addTo(parser);
    checkOptions.addTo(parser);
    parser.addOptions({sceneName, program, folder, format, chain});
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
    if (auto code = checkOptions.read(parser, options, err)) return *code;
    options.chain = parser.isSet(chain);
    const QString dir = parser.isSet(folder) ? parser.value(folder) : QDir::currentPath();
    if (!QFileInfo(dir).isDir())
        return usageError(err, lit("--folder: '%1' is not a folder").arg(dir));

    std::vector<check::CheckScene> scenes;
    if (int code = chooseScenes(parser, sceneOptions, sceneName, settings, err, scenes);
        code != ExitOk)
        return code;
    const check::CheckReport report =
        check::runCheck(parser.value(program).toStdString(),
                        QFileInfo(dir).absoluteFilePath().toStdString(), scenes, options);
    out << QString::fromStdString(check::formatReport(report, formatName.toStdString()));
    return exitCodeOf(report);
}

int runGrade(const QStringList& arguments, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        lit("Grade a class: every subfolder of --submissions holding a one-line 'run' file (the "
            "command that starts its program, run in that folder) goes through check, two at a "
            "time. Prints the table of submissions x stages; --output also writes it as CSV and "
            "Markdown with each submission's report. Exit status 0 once every submission has "
            "its row."));
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({lit("h"), lit("help")}, lit("Show this help."));
    const QCommandLineOption submissions(lit("submissions"),
                                         lit("The folder of submissions (required)."), lit("DIR"));
    const QCommandLineOption output(lit("output"),
                                    lit("Write grades.csv, grades.md and reports/NAME.md and "
                                        ".json into this folder (made if missing)."),
                                    lit("DIR"));
    const QCommandLineOption format(lit("format"), lit("The table printed: md (default) or csv."),
                                    lit("FORMAT"), lit("md"));
    const QCommandLineOption jobs(
        lit("jobs"), lit("Submissions checked at once (default 2; 1 to 16)."), lit("N"), lit("2"));
    const SceneOptions sceneOptions;
    const CheckOptionSet checkOptions;
    const QCommandLineOption sceneName = SceneOptions::generatedSceneOption();
    parser.addOption(help);
    sceneOptions.addTo(parser);
    checkOptions.addTo(parser);
    const QCommandLineOption hw2(lit("hw2"),
                                 lit("HW2 submissions: run each program on this command file (the "
                                     "file's name after its command, in a copy of its folder) and "
                                     "compare the PNGs it names with ours; repeat for each file."),
                                 lit("FILE"));
    parser.addOptions({sceneName, submissions, output, format, jobs, hw2});
    rl::CourseSceneSettings settings;
    if (auto code = parseSceneCommand(parser, arguments, help, lit("grade"), sceneOptions,
                                      sceneName, settings, out, err))
        return *code;
    if (!parser.isSet(submissions)) return usageError(err, lit("grade needs --submissions DIR"));
    const QString formatName = parser.value(format);
    if (formatName != lit("md") && formatName != lit("csv"))
        return usageError(err, lit("--format expects md or csv, found '%1'").arg(formatName));
    bool ok = false;
    const int jobCount = parser.value(jobs).toInt(&ok);
    if (!ok || jobCount < 1 || jobCount > 16)
        return usageError(
            err,
            lit("--jobs expects a whole number from 1 to 16, found '%1'").arg(parser.value(jobs)));
    check::CheckOptions options;
    if (auto code = checkOptions.read(parser, options, err)) return *code;
    const auto found = check::findSubmissions(parser.value(submissions).toStdString());
    if (!found) return inputError(err, found.error());
    if (found->empty())
        return usageError(
            err, lit("--submissions: '%1' holds no folder").arg(parser.value(submissions)));
    if (parser.isSet(hw2))
        return gradeHw2(parser, hw2, output, formatName, jobCount, options, found.value(), out,
                        err);
    std::vector<check::CheckScene> scenes;
    if (int code = chooseScenes(parser, sceneOptions, sceneName, settings, err, scenes);
        code != ExitOk)
        return code;

    const auto rows = check::gradeSubmissions(found.value(), scenes, options, jobCount,
                                              [&err](int done, int total, const std::string& name) {
                                                  err << "graded " << done << "/" << total << ": "
                                                      << QString::fromStdString(name) << '\n';
                                                  err.flush();
                                              });
    out << QString::fromStdString(check::gradeTable(rows, formatName.toStdString()));
    if (!parser.isSet(output)) return ExitOk;
    const QDir dir(parser.value(output));
    if (!dir.mkpath(lit("reports")))
        return usageError(err, lit("--output: cannot make the folder '%1'").arg(dir.path()));
    bool written =
        writeTables(dir, check::gradeTable(rows, "csv"), check::gradeTable(rows, "md"), err);
    for (const check::GradeRow& row : rows) {
        const QString base =
            dir.filePath(lit("reports/") + QString::fromStdString(row.submission.name));
        const std::string text =
            row.submission.problem.empty()
                ? check::formatReport(row.report, "md")
                : "# " + row.submission.name + "\n\n" + row.submission.problem + "\n";
        written = written && writeText(base + lit(".md"), text, err);
        if (row.submission.problem.empty())
            written = written &&
                      writeText(base + lit(".json"), check::formatReport(row.report, "json"), err);
    }
    return written ? ExitOk : ExitBadInput;
}

}  // namespace rasterlab::cli
