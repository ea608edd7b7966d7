#include "install_paths.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace rasterlab {

namespace {

QString existingDir(const QString& appDir, const char* relative) {
    const QString base = appDir.isEmpty() ? QCoreApplication::applicationDirPath() : appDir;
    const QFileInfo info(QDir(base).filePath(QString::fromUtf8(relative)));
    return info.isDir() ? QDir::cleanPath(info.absoluteFilePath()) : QString();
}

}  // namespace

QString dataDir(const QString& appDir) {
    return existingDir(appDir, RASTERLAB_DATADIR_FROM_BINDIR);
}

QString docDir(const QString& appDir) {
    return existingDir(appDir, RASTERLAB_DOCDIR_FROM_BINDIR);
}

QString userGuide(const QString& language, const QString& appDir) {
    const QString docs = docDir(appDir);
    if (docs.isEmpty()) return {};
    // "pt_BR.UTF-8" and "pt-BR" name the pt_BR guide; any other Portuguese too, as the closest.
    QString name = language.section(QLatin1Char('.'), 0, 0);
    name.replace(QLatin1Char('-'), QLatin1Char('_'));
    if (name.startsWith(QLatin1String("pt"))) name = QStringLiteral("pt_BR");
    for (const QString& candidate : {name, QStringLiteral("en")}) {
        if (candidate.isEmpty()) continue;
        const QString file = QDir(docs).filePath(QStringLiteral("guide.%1.md").arg(candidate));
        if (QFileInfo(file).isFile()) return file;
    }
    return {};
}

QString translationsDir(const QString& appDir) {
    const QString data = dataDir(appDir);
    const QString installed = data.isEmpty() ? QString() : data + QStringLiteral("/translations");
    if (!installed.isEmpty() && QFileInfo(installed).isDir()) return installed;
    return QStringLiteral(":/i18n");
}

}  // namespace rasterlab
