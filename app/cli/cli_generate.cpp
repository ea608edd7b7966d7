// rasterlab-cli generate-default-scene and generate-lessons: the course files RasterLab
// ships (resources/default-scene and resources/lessons are their output).
#include "app/cli/cli_common.h"

#include <QDir>
#include <QFileInfo>
#include <QSaveFile>

#include <string>
#include <vector>

#include "app/documents/examples.h"
#include "app/documents/lesson_file.h"
#include "pipeline/scene/default_scene.h"
#include "pipeline/scene/lessons.h"

namespace rasterlab::cli {

namespace {

struct OutputFile {
    QString name;
    QByteArray bytes;
};

QByteArray bytesOf(const std::string& text) {
    return QByteArray(text.data(), static_cast<qsizetype>(text.size()));
}

// Writes the files into folder (created if needed), each atomically; false with the error
// printed when one cannot be written.
bool writeFiles(const QDir& folder, const std::vector<OutputFile>& files, QTextStream& out,
                QTextStream& err) {
    if (!QDir().mkpath(folder.path())) {
        err << folder.path() << ": cannot create the folder\n";
        return false;
    }
    for (const OutputFile& f : files) {
        const QString path = folder.filePath(f.name);
        QSaveFile file(path);
        if (!file.open(QIODevice::WriteOnly) || file.write(f.bytes) != f.bytes.size() ||
            !file.commit()) {
            err << path << ": cannot write: " << file.errorString() << '\n';
            return false;
        }
        out << "wrote " << QFileInfo(path).absoluteFilePath() << '\n';
    }
    return true;
}

// Parses `--dir DIR` (and the options given); ExitOk with the folder, or the exit code.
int parseGenerate(QCommandLineParser& parser, const QStringList& arguments, const QString& command,
                  const QString& description, QTextStream& out, QTextStream& err, bool& helped) {
    parser.setApplicationDescription(description);
    const QCommandLineOption help({lit("h"), lit("help")}, lit("Show this help."));
    const QCommandLineOption dir(lit("dir"), lit("The folder to write into (created if needed)."),
                                 lit("DIR"));
    parser.addOptions({help, dir});
    helped = false;
    if (!parser.parse(arguments)) return usageError(err, parser.errorText());
    if (parser.isSet(help)) {
        out << commandHelp(parser, command);
        helped = true;
        return ExitOk;
    }
    if (!parser.isSet(dir)) return usageError(err, lit("%1 needs --dir DIR").arg(command));
    return ExitOk;
}

}  // namespace

int runGenerateDefaultScene(const QStringList& arguments, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    bool helped = false;
    if (int code = parseGenerate(parser, arguments, lit("generate-default-scene"),
                                 lit("Write the default scene's three course files."), out, err,
                                 helped);
        code != ExitOk || helped)
        return code;
    const rl::CourseSceneTexts texts = rl::generateDefaultScene();
    const std::vector<OutputFile> files = {
        {QString::fromUtf8(rl::kDefaultCameraFile), bytesOf(texts.camera)},
        {QString::fromUtf8(rl::kDefaultLightingFile), bytesOf(texts.lighting)},
        {QString::fromUtf8(rl::kDefaultObjectFile), bytesOf(texts.object)},
    };
    return writeFiles(QDir(parser.value(lit("dir"))), files, out, err) ? ExitOk : ExitBadInput;
}

int runGenerateLessons(const QStringList& arguments, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    bool helped = false;
    if (int code = parseGenerate(
            parser, arguments, lit("generate-lessons"),
            lit("Write the shipped lessons, each in a folder of its own: its three course files "
                "and its lesson file."),
            out, err, helped);
        code != ExitOk || helped)
        return code;
    const QDir root(parser.value(lit("dir")));
    for (const QString& name : exampleNames()) {
        const auto lesson = rl::generateLesson(name.toStdString());
        if (!lesson) continue;  // every example is one of the pipeline's lessons (tested)
        const std::vector<OutputFile> files = {
            {QString::fromUtf8(rl::kDefaultCameraFile), bytesOf(lesson->texts.camera)},
            {QString::fromUtf8(rl::kDefaultLightingFile), bytesOf(lesson->texts.lighting)},
            {QString::fromStdString(lesson->objectFile), bytesOf(lesson->texts.object)},
            {name + QStringLiteral(".rasterlab"), lessonJson(exampleLesson(name))},
        };
        if (!writeFiles(QDir(root.filePath(name)), files, out, err)) return ExitBadInput;
    }
    return ExitOk;
}

}  // namespace rasterlab::cli
