// rasterlab-cli generate-default-scene: the default scene's three course files.
#include "cli_common.h"

#include <QDir>
#include <QFileInfo>
#include <QSaveFile>

#include "default_scene.h"

namespace rasterlab::cli {

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

}  // namespace rasterlab::cli
