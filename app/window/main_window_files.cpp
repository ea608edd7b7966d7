// The main window's files: opening any file or a folder (the kind told from the file),
// recent files, drag and drop, and reading a file again when it changes on disk.
#include <QCoreApplication>
#include <QDir>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QFileInfo>
#include <QMenu>
#include <QMimeData>
#include <QRegularExpression>
#include <QSettings>
#include <QStatusBar>

#include <set>

#include "app/window/main_window.h"
#include "pipeline/io/course_readers.h"
#include "pipeline/io/hw2_reader.h"

namespace rasterlab {

namespace {

// The keys of a key = value file, lower-case.
std::set<QString> keysOf(const QString& text) {
    std::set<QString> keys;
    static const QRegularExpression line(QStringLiteral("^\\s*([A-Za-z]+)\\s*="),
                                         QRegularExpression::MultilineOption);
    for (auto it = line.globalMatch(text); it.hasNext();)
        keys.insert(it.next().captured(1).toLower());
    return keys;
}

bool hasAny(const std::set<QString>& keys, std::initializer_list<const char*> names) {
    for (const char* name : names)
        if (keys.count(QLatin1String(name))) return true;
    return false;
}

}  // namespace

FileKind detectFileKind(const QString& path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("byu")) return FileKind::Object;
    if (suffix == QLatin1String("cfg")) return FileKind::Camera;
    if (suffix == QLatin1String("lux")) return FileKind::Lighting;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return FileKind::Unknown;
    const QByteArray head = file.read(1 << 16);
    const std::string_view text(head.constData(), static_cast<std::size_t>(head.size()));
    if (rl::looksLikeHw2(text)) return FileKind::CommandFile;
    if (head.contains('=')) {
        const std::set<QString> keys = keysOf(QString::fromUtf8(head));
        const bool camera = hasAny(keys, {"c", "n", "v", "d", "hx", "hy"});
        const bool lighting = hasAny(keys, {"iamb", "ka", "il", "pl", "kd", "od", "ks", "eta"});
        if (camera && lighting) return FileKind::CameraAndLighting;
        if (camera) return FileKind::Camera;
        if (lighting) return FileKind::Lighting;
        return FileKind::Unknown;
    }
    if (rl::detectCameraLayout(text)) return FileKind::Camera;
    if (rl::detectLightingLayout(text)) return FileKind::Lighting;
    // An object starts with two whole numbers: vertices and triangles.
    static const QRegularExpression counts(QStringLiteral("^\\s*\\d+\\s+\\d+\\s*$"));
    for (const QByteArray& line : head.split('\n')) {
        const QString trimmed = QString::fromUtf8(line).trimmed();
        if (trimmed.isEmpty()) continue;
        return counts.match(trimmed).hasMatch() ? FileKind::Object : FileKind::Unknown;
    }
    return FileKind::Unknown;
}

bool MainWindow::openPath(const QString& path) {
    const QFileInfo info(path);
    if (info.suffix().compare(QLatin1String("rasterlab"), Qt::CaseInsensitive) == 0)
        return openLesson(path);
    if (info.isDir()) {
        // A folder: the course files it holds (the first of each kind, by name).
        std::optional<QString> found[3];
        QString commandFile;
        const QDir dir(path);
        for (const QString& name : dir.entryList(QDir::Files, QDir::Name)) {
            const QString file = dir.filePath(name);
            switch (detectFileKind(file)) {
                case FileKind::Camera:
                    if (!found[0]) found[0] = file;
                    break;
                case FileKind::Lighting:
                    if (!found[1]) found[1] = file;
                    break;
                case FileKind::CameraAndLighting:
                    if (!found[0]) found[0] = file;
                    if (!found[1]) found[1] = file;
                    break;
                case FileKind::Object:
                    if (!found[2]) found[2] = file;
                    break;
                case FileKind::CommandFile:
                    if (commandFile.isEmpty()) commandFile = file;
                    break;
                case FileKind::Unknown:
                    break;
            }
        }
        const SceneDocument::Part parts[] = {SceneDocument::Part::Camera,
                                             SceneDocument::Part::Lighting,
                                             SceneDocument::Part::Object};
        bool any = false;
        for (int k = 0; k < 3; ++k) {
            if (!found[k]) continue;
            any = true;
            if (!openPart(parts[k], *found[k])) return false;
        }
        if (any) return true;
        if (!commandFile.isEmpty()) return openCommandFile(commandFile);
        showError(
            tr("%1: no course camera, lighting, object or command file in this folder").arg(path));
        return false;
    }
    if (!info.exists()) {
        showError(tr("%1: no such file").arg(path));
        return false;
    }
    switch (detectFileKind(path)) {
        case FileKind::Camera:
            return openPart(SceneDocument::Part::Camera, path);
        case FileKind::Lighting:
            return openPart(SceneDocument::Part::Lighting, path);
        case FileKind::CameraAndLighting:
            return openPart(SceneDocument::Part::Camera, path) &&
                   openPart(SceneDocument::Part::Lighting, path);
        case FileKind::Object:
            return openPart(SceneDocument::Part::Object, path);
        case FileKind::CommandFile:
            return openCommandFile(path);
        case FileKind::Unknown:
            break;
    }
    showError(tr("%1: not a course camera, lighting or object file, nor a command file "
                 "(expected a .byu object, a camera or lighting in one of the course layouts, "
                 "or png/xyz/tri commands)")
                  .arg(path));
    return false;
}

QStringList MainWindow::recentFiles() const {
    if (QCoreApplication::organizationName().isEmpty()) return {};
    return QSettings().value(QStringLiteral("recentFiles")).toStringList();
}

void MainWindow::addRecentFile(const QString& path) {
    if (QCoreApplication::organizationName().isEmpty() || path.startsWith(QStringLiteral(":/")))
        return;
    QStringList files = recentFiles();
    const QString absolute = QFileInfo(path).absoluteFilePath();
    files.removeAll(absolute);
    files.prepend(absolute);
    while (files.size() > kMaxRecentFiles) files.removeLast();
    QSettings().setValue(QStringLiteral("recentFiles"), files);
    refreshRecentMenu();
}

void MainWindow::refreshRecentMenu() {
    m_recentMenu->clear();
    const QStringList files = recentFiles();
    int n = 1;
    for (const QString& file : files) {
        const QString label = n < 10
                                  ? QStringLiteral("&%1 %2").arg(n).arg(QFileInfo(file).fileName())
                                  : QFileInfo(file).fileName();
        QAction* action = m_recentMenu->addAction(label, this, [this, file] { openPath(file); });
        action->setToolTip(file);
        action->setStatusTip(file);
        ++n;
    }
    m_recentMenu->setEnabled(!files.isEmpty());
    if (!files.isEmpty()) {
        m_recentMenu->addSeparator();
        m_recentMenu->addAction(tr("&Clear the List"), this, [this] {
            QSettings().remove(QStringLiteral("recentFiles"));
            refreshRecentMenu();
        });
    }
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (!event->mimeData()->hasUrls()) return;
    for (const QUrl& url : event->mimeData()->urls())
        if (!url.isLocalFile()) return;
    event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    const QList<QUrl> urls = event->mimeData()->urls();
    event->acceptProposedAction();
    for (const QUrl& url : urls)
        if (!openPath(url.toLocalFile())) break;  // the error is shown; the scene stays
}

QStringList MainWindow::shownFiles() const {
    QStringList files;
    if (m_document.showsCommandFile()) {
        files << m_document.commandFilePath();
    } else {
        for (SceneDocument::Part part : kCourseParts) {
            const QString source = m_document.source(part);
            if (!source.isEmpty() && !source.startsWith(QStringLiteral(":/"))) files << source;
        }
    }
    return files;
}

void MainWindow::watchSources() {
    const QStringList wanted = shownFiles();
    const QStringList watched = m_watcher.files();
    for (const QString& file : watched)
        if (!wanted.contains(file)) m_watcher.removePath(file);
    for (const QString& file : wanted)
        if (!watched.contains(file) && QFileInfo::exists(file)) m_watcher.addPath(file);
}

void MainWindow::onWatchedFileChanged(const QString& path) {
    // An editor that saves by writing a new file and renaming it over the old one ends the
    // watch on the old file: the path is watched again once the new file is there.
    if (!m_changedFiles.contains(path)) m_changedFiles << path;
    m_reloadAttempts = 0;
    m_reloadTimer.start(300);
}

void MainWindow::reloadChangedFiles() {
    QStringList waiting;
    for (const QString& path : m_changedFiles) {
        if (!QFileInfo::exists(path)) {
            waiting << path;  // renamed away, the new one not there yet
            continue;
        }
        if (!m_watcher.files().contains(path)) m_watcher.addPath(path);
        bool reloaded = false;
        if (m_document.showsCommandFile() && m_document.commandFilePath() == path) {
            reloaded = openCommandFile(path);
        } else {
            for (SceneDocument::Part part : kCourseParts) {
                // Our own save is not a change to read back (it would clear the undo history).
                if (m_document.source(part) != path || m_document.fileHoldsLastSave(part)) continue;
                reloaded = openPart(part, path) || reloaded;
            }
        }
        if (reloaded)
            statusBar()->showMessage(
                tr("%1 changed on disk: read again").arg(QFileInfo(path).fileName()), 5000);
    }
    // A file gone for good (about 10 s) is no longer waited for.
    m_reloadAttempts = waiting.isEmpty() ? 0 : m_reloadAttempts + 1;
    m_changedFiles = m_reloadAttempts > 20 ? QStringList() : waiting;
    if (!m_changedFiles.isEmpty()) m_reloadTimer.start(500);
}

}  // namespace rasterlab
