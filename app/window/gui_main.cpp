// rasterlab: the teaching application. Opens on the embedded default scene, or on the files
// or folder given on the command line.
#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QSettings>
#include <QTimer>

#include <cstdio>
#include <cstring>

#include <functional>
#include <memory>

#include "app/documents/examples.h"
#include "app/window/main_window.h"
#include "app/window/translators.h"
#include "pipeline/core/frame_memory.h"

int main(int argc, char* argv[]) {
    rl::keepFrameMemory();
    // The version needs no display: answered before QApplication connects to one (as
    // QCommandLineParser's --version would print it).
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--version") == 0 || std::strcmp(argv[i], "-v") == 0) {
            printf("RasterLab %s\n", RASTERLAB_VERSION);
            return 0;
        }
    }
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
        QStringLiteral("Course camera, lighting or object files, command files, a folder, or "
                       "a lesson file (.rasterlab)."));
    const QCommandLineOption scene(
        QStringLiteral("scene"),
        QStringLiteral("Open a shipped lesson: %1.").arg(rasterlab::exampleNames().join(QStringLiteral(", "))),
        QStringLiteral("NAME"));
    parser.addOption(scene);
    // For scripts that check an installation (scripts/check-package.sh): open the files, then
    // close after MS milliseconds, with status 1 if one of them could not be opened.
    const QCommandLineOption quitAfter(
        QStringLiteral("quit-after"),
        QStringLiteral("Close the window MS milliseconds after opening the files; exit status 1 "
                       "if one of them could not be opened."),
        QStringLiteral("MS"));
    parser.addOption(quitAfter);
    // This session's language, not kept (View > Language keeps its choice).
    const QCommandLineOption languageOption(
        QStringLiteral("language"),
        QStringLiteral("The interface's language for this session: en or pt_BR (View > "
                       "Language chooses one for every session)."),
        QStringLiteral("LANG"));
    parser.addOption(languageOption);
    parser.process(app);
    const QString language = parser.value(languageOption);
    if (parser.isSet(languageOption) && language != QLatin1String("en") &&
        language != QLatin1String("pt_BR")) {
        fprintf(stderr, "rasterlab: --language expects en or pt_BR, found '%s'\n",
                qPrintable(language));
        return 2;
    }
    if (parser.isSet(scene) && !rasterlab::isExample(parser.value(scene))) {
        fprintf(stderr, "rasterlab: --scene expects one of %s, found '%s'\n",
                qPrintable(rasterlab::exampleNames().join(QStringLiteral(", "))),
                qPrintable(parser.value(scene)));
        return 2;
    }
    bool quitAfterIsNumber = false;
    const int quitAfterMs = parser.value(quitAfter).toInt(&quitAfterIsNumber);
    if (parser.isSet(quitAfter) && (!quitAfterIsNumber || quitAfterMs < 0)) {
        fprintf(stderr, "rasterlab: --quit-after expects milliseconds, found '%s'\n",
                qPrintable(parser.value(quitAfter)));
        return 2;
    }

    rasterlab::Translators translators;
    translators.install(parser.isSet(languageOption)
                            ? language
                            : QSettings().value(QStringLiteral("language")).toString());

    // A new language builds the window again (every string is set when a widget is made); the
    // new window takes the old one's document, with its unsaved edits, and its view: stepping,
    // picked pixel, breakpoints, zoom, docks (as a lesson file would keep them).
    std::unique_ptr<rasterlab::MainWindow> window;
    std::function<void(const rasterlab::SceneDocument*)> build =
        [&](const rasterlab::SceneDocument* document) {
            auto fresh = std::make_unique<rasterlab::MainWindow>();
            if (document) fresh->adoptDocument(*document);
            QObject::connect(fresh.get(), &rasterlab::MainWindow::languageChangeRequested,
                             [&](const QString& chosen) {
                                 translators.install(chosen);
                                 QMetaObject::invokeMethod(
                                     &app,
                                     [&] {
                                         const rasterlab::SceneDocument kept = window->document();
                                         const rasterlab::Lesson view = window->currentLesson(QDir());
                                         const QByteArray geometry = window->saveGeometry();
                                         if (!window->handOver()) return;
                                         build(&kept);
                                         window->restoreGeometry(geometry);
                                         window->restoreView(view);
                                     },
                                     Qt::QueuedConnection);
                             });
            fresh->show();
            window = std::move(fresh);
        };
    build(nullptr);
    bool opened = true;
    if (parser.isSet(scene)) opened = window->openExample(parser.value(scene));
    for (const QString& file : parser.positionalArguments()) {
        if (!window->openPath(file)) {
            opened = false;
            break;
        }
    }
    if (parser.isSet(quitAfter))
        QTimer::singleShot(quitAfterMs, &app, [&app, opened] { app.exit(opened ? 0 : 1); });
    return app.exec();
}
