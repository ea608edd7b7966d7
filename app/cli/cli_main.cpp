// rasterlab-cli: see cli.h.
#include <QCoreApplication>
#include <QDir>
#include <QGuiApplication>

#include <sys/stat.h>
#include <unistd.h>

#include <QTextStream>
#include <cerrno>

#include <cstdio>
#include <cstring>
#include <memory>

#include "pipeline/core/frame_memory.h"

#include "app/cli/cli.h"

int main(int argc, char* argv[]) {
    rl::keepFrameMemory();
    // `accuracy` and `stability` draw their plots and heat maps with text, which needs a GUI
    // application: on the offscreen platform unless one is asked for, so that no display is needed.
    std::unique_ptr<QCoreApplication> app;
    if (argc > 1 &&
        (std::strcmp(argv[1], "accuracy") == 0 || std::strcmp(argv[1], "stability") == 0)) {
        if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
            qputenv("QT_QPA_PLATFORM", QByteArrayLiteral("offscreen"));
        // Without a session (a terminal over ssh, CI) Qt would warn that it has no runtime
        // folder and make one itself: make it quietly, private as Qt requires.
        if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
            const QByteArray dir = QDir::tempPath().toLocal8Bit() + "/rasterlab-runtime-" +
                                   QByteArray::number(getuid());
            if (mkdir(dir.constData(), 0700) == 0 || errno == EEXIST) {
                struct stat info {};
                if (stat(dir.constData(), &info) == 0 && info.st_uid == getuid() &&
                    (info.st_mode & 0777) == 0700)
                    qputenv("XDG_RUNTIME_DIR", dir);
            }
        }
        app = std::make_unique<QGuiApplication>(argc, argv);
    } else {
        app = std::make_unique<QCoreApplication>(argc, argv);
    }
    QCoreApplication::setApplicationName(QStringLiteral("rasterlab-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(RASTERLAB_VERSION));
    QTextStream out(stdout);
    QTextStream err(stderr);
    return rasterlab::runCli(QCoreApplication::arguments(), out, err);
}
