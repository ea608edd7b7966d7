// rasterlab: the teaching application. Opens on the embedded default scene, or on the files
// or folder given on the command line.
#include <QApplication>
#include <QCommandLineParser>
#include <QSettings>

#include <functional>
#include <memory>

#include "frame_memory.h"
#include "main_window.h"
#include "translators.h"

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

    rasterlab::Translators translators;
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
