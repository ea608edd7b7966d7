// rasterlab: the teaching application. Opens on the embedded default scene, or on the files
// or folder given on the command line.
#include <QApplication>
#include <QCommandLineParser>
#include <QLibraryInfo>
#include <QLocale>
#include <QPointer>
#include <QSettings>
#include <QTranslator>

#include <functional>
#include <memory>

#include "frame_memory.h"
#include "main_window.h"

namespace {

// Our strings and Qt's own (its dialogs) in one language: "" for the system's, "en" or
// "pt_BR". Installed again when the user picks another language from the View menu.
class Translators {
public:
    void install(const QString& language) {
        QCoreApplication::removeTranslator(&m_qt);
        QCoreApplication::removeTranslator(&m_ours);
        const QLocale locale = language.isEmpty() ? QLocale() : QLocale(language);
        QLocale::setDefault(locale);
        if (m_qt.load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                      QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
            QCoreApplication::installTranslator(&m_qt);
        if (m_ours.load(locale, QStringLiteral("rasterlab"), QStringLiteral("_"),
                        QStringLiteral(":/i18n")))
            QCoreApplication::installTranslator(&m_ours);
    }

private:
    QTranslator m_qt;
    QTranslator m_ours;
};

}  // namespace

int main(int argc, char* argv[]) {
    rl::keepFrameMemory();
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("RasterLab"));
    QCoreApplication::setApplicationName(QStringLiteral("RasterLab"));
    QCoreApplication::setApplicationVersion(QStringLiteral(RASTERLAB_VERSION));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("The classic software rasterization pipeline, stage by stage."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(
        QStringLiteral("files"),
        QStringLiteral("Course camera, lighting or object files, command files, or a folder."));
    parser.process(app);

    Translators translators;
    translators.install(QSettings().value(QStringLiteral("language")).toString());

    // A new language builds the window again (every string is set when a widget is made); the
    // new window takes the old one's document, with its unsaved edits.
    std::unique_ptr<rasterlab::MainWindow> window;
    std::function<void(const rasterlab::SceneDocument*)> build =
        [&](const rasterlab::SceneDocument* document) {
            auto fresh = std::make_unique<rasterlab::MainWindow>();
            if (document) fresh->adoptDocument(*document);
            QObject::connect(fresh.get(), &rasterlab::MainWindow::languageChangeRequested,
                             [&](const QString& language) {
                                 translators.install(language);
                                 QMetaObject::invokeMethod(
                                     &app,
                                     [&] {
                                         const rasterlab::SceneDocument kept = window->document();
                                         const QByteArray geometry = window->saveGeometry();
                                         if (!window->handOver()) return;
                                         build(&kept);
                                         window->restoreGeometry(geometry);
                                     },
                                     Qt::QueuedConnection);
                             });
            fresh->show();
            window = std::move(fresh);
        };
    build(nullptr);
    for (const QString& file : parser.positionalArguments())
        if (!window->openPath(file)) break;
    return app.exec();
}
