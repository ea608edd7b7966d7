// Screenshots the program makes of itself, for the user guide and for looking at every view:
// the window on a course scene stepped to the middle of the frame with a pixel picked, each
// dock on its own, presentation mode, and a command file (skipped stages), in one language.
//
//   screenshot_tour --out DIR [--language en|pt_BR] [--samples DIR]
// (scripts/screenshots.sh runs it in both languages.)
#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QLibraryInfo>
#include <QTabBar>
#include <QTest>
#include <QTranslator>

#include <cstdio>

#include "breakpoints_view.h"
#include "frame_image_view.h"
#include "inspection.h"
#include "main_window.h"
#include "replay_builder.h"
#include "stepping_bar.h"

using namespace rasterlab;

namespace {

bool waitForReplay(MainWindow& window) {
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < 60000) {
        if (window.inspection()->canStep() && !window.controller()->isBusy() &&
            !window.replayBuilder()->isBusy())
            return true;
        QTest::qWait(20);
    }
    return false;
}

bool save(QWidget* widget, const QString& path) {
    QCoreApplication::processEvents();
    const bool ok = widget->grab().save(path);
    std::printf("%s %s\n", ok ? "wrote" : "FAILED", qPrintable(path));
    return ok;
}

}  // namespace

int main(int argc, char* argv[]) {
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("RasterLabTour"));  // no user settings
    QCommandLineParser parser;
    parser.addOptions({{QStringLiteral("out"), QStringLiteral("folder"), QStringLiteral("DIR")},
                       {QStringLiteral("language"), QStringLiteral("en or pt_BR"),
                        QStringLiteral("L"), QStringLiteral("en")},
                       {QStringLiteral("samples"), QStringLiteral("course samples"),
                        QStringLiteral("DIR"), QStringLiteral("../shared/samples")}});
    parser.process(app);
    const QDir out(parser.value(QStringLiteral("out")));
    QDir().mkpath(out.path());
    const QString language = parser.value(QStringLiteral("language"));
    QTranslator qt, ours;
    const QLocale locale(language);
    QLocale::setDefault(locale);
    if (qt.load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(&qt);
    if (ours.load(locale, QStringLiteral("rasterlab"), QStringLiteral("_"),
                  QStringLiteral(":/i18n")))
        QCoreApplication::installTranslator(&ours);
    const QString samples = parser.value(QStringLiteral("samples"));
    const QString suffix = QStringLiteral("-") + language + QStringLiteral(".png");
    auto file = [&](const QString& name) { return out.filePath(name + suffix); };

    MainWindow window;
    window.resize(1600, 1000);
    window.show();
    const QString ufpe = samples + QStringLiteral("/course/ufpe/");
    for (const char* name : {"calice2.cfg", "iluminacao.txt", "calice2.byu"})
        if (!window.openPath(ufpe + QLatin1String(name))) return 1;
    if (!waitForReplay(window)) return 1;
    Inspection* inspection = window.inspection();
    // The brightest pixel of the image (the highlight), stepped to a scanline past the middle.
    const QImage final = window.currentImage();
    QPoint brightest(0, 0);
    int best = -1;
    for (int y = 0; y < final.height(); ++y)
        for (int x = 0; x < final.width(); ++x) {
            const QColor c = final.pixelColor(x, y);
            if (c.red() + c.green() + c.blue() > best) {
                best = c.red() + c.green() + c.blue();
                brightest = QPoint(x, y);
            }
        }
    inspection->pickPixel(brightest);
    inspection->setGranularity(rl::StepGranularity::Scanline);
    const rl::FrameReplay* replay = inspection->replay();
    inspection->seek(replay->next(
        replay->atFragment(static_cast<std::uint32_t>(replay->fragments().size() * 6 / 10)),
        rl::StepGranularity::Scanline));
    window.imageView()->zoomIn();
    save(&window, file(QStringLiteral("main-window")));
    for (QDockWidget* dock : window.findChildren<QDockWidget*>()) {
        dock->show();
        dock->raise();
        QCoreApplication::processEvents();
        save(dock, file(dock->objectName()));
    }
    window.breakpointsView()->add(rl::Breakpoint::Kind::DepthRejection, 0);
    window.breakpointsView()->add(rl::Breakpoint::Kind::Scanline, 300);
    window.findChild<QDockWidget*>(QStringLiteral("breakpointsDock"))->raise();
    save(window.findChild<QDockWidget*>(QStringLiteral("breakpointsDock")),
         file(QStringLiteral("breakpointsDock")));
    // In front of a class.
    window.setPresentationMode(true);
    QCoreApplication::processEvents();
    save(&window, file(QStringLiteral("presentation")));
    window.setPresentationMode(false);
    // A command file: no course camera; its lighting is the command language's.
    if (!window.openPath(samples + QStringLiteral("/hw2/hw2sun1g.txt"))) return 1;
    if (!waitForReplay(window)) return 1;
    inspection->pickPixel(QPoint(100, 100));
    window.findChild<QDockWidget*>(QStringLiteral("cameraBasisDock"))->raise();
    save(&window, file(QStringLiteral("command-file")));
    return 0;
}
