// rasterlab: the teaching application. Opens on the embedded default scene.
#include <QApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

#include "frame_memory.h"
#include "main_window.h"

int main(int argc, char* argv[]) {
    rl::keepFrameMemory();
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("RasterLab"));
    QCoreApplication::setApplicationName(QStringLiteral("RasterLab"));
    QCoreApplication::setApplicationVersion(QStringLiteral(RASTERLAB_VERSION));

    // Our strings in the system's language (pt_BR or English), and Qt's own dialogs too.
    QTranslator qtTranslator;
    if (qtTranslator.load(QLocale(), QStringLiteral("qtbase"), QStringLiteral("_"),
                          QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(&qtTranslator);
    QTranslator translator;
    if (translator.load(QLocale(), QStringLiteral("rasterlab"), QStringLiteral("_"),
                        QStringLiteral(":/i18n")))
        QCoreApplication::installTranslator(&translator);

    rasterlab::MainWindow window;
    window.show();
    return app.exec();
}
