// rasterlab-cli: see cli.h.
#include <QCoreApplication>
#include <QTextStream>

#include <cstdio>

#include "frame_memory.h"

#include "cli.h"

int main(int argc, char* argv[]) {
    rl::keepFrameMemory();
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("rasterlab-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(RASTERLAB_VERSION));
    QTextStream out(stdout);
    QTextStream err(stderr);
    return rasterlab::runCli(QCoreApplication::arguments(), out, err);
}
