// Stepping speed, as a teacher sees it: the real window (offscreen), a scene opened from
// course files, its replay built, then N steps forward at a granularity, each followed by a
// synchronous repaint of the whole window (the image with its overlays and every visible dock).
// Prints the replay's build time and the replay-and-repaint time per step (median, 90th
// percentile, worst) and the steps a second that makes.
//
//   bench_stepping [--object F --camera F --lighting F | --torus TRIANGLES]
//                  [--granularity scanline] [--steps 300] [--docks all|image]
// Build in Release (scripts/bench-stepping.sh).
#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QTemporaryDir>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "app/window/main_window.h"
#include "app/window/replay_builder.h"
#include "pipeline/core/frame_memory.h"
#include "tests/bench_support.h"
#include "views/inspection.h"

using namespace rasterlab;

using bench::percentile;

int main(int argc, char* argv[]) {
    rl::keepFrameMemory();
    QApplication app(argc, argv);
    QCommandLineParser parser;
    parser.addOptions(
        {{QStringLiteral("object"), QStringLiteral("object file"), QStringLiteral("F")},
         {QStringLiteral("camera"), QStringLiteral("camera file"), QStringLiteral("F")},
         {QStringLiteral("lighting"), QStringLiteral("lighting file"), QStringLiteral("F")},
         {QStringLiteral("torus"), QStringLiteral("a generated torus of about N triangles"),
          QStringLiteral("N")},
         {QStringLiteral("granularity"), QStringLiteral("triangle|scanline|span|pixel"),
          QStringLiteral("G"), QStringLiteral("scanline")},
         {QStringLiteral("steps"), QStringLiteral("steps to time"), QStringLiteral("N"),
          QStringLiteral("300")},
         {QStringLiteral("docks"), QStringLiteral("all: every dock shown; image: none"),
          QStringLiteral("D"), QStringLiteral("all")}});
    parser.process(app);

    QTemporaryDir dir;
    QStringList files;
    if (parser.isSet(QStringLiteral("torus"))) {
        QString paths[3];
        if (!bench::writeTorus(dir.path(), parser.value(QStringLiteral("torus")).toInt(), paths)) return 1;
        files = {paths[0], paths[1], paths[2]};
    } else {
        for (const char* name : {"camera", "lighting", "object"})
            if (parser.isSet(QLatin1String(name))) files << parser.value(QLatin1String(name));
    }

    MainWindow window;
    window.resize(1600, 1000);
    window.show();
    if (parser.value(QStringLiteral("docks")) == QLatin1String("image"))
        for (QDockWidget* dock : window.findChildren<QDockWidget*>()) dock->hide();
    for (const QString& file : files)
        if (!window.openPath(file)) {
            std::fprintf(stderr, "cannot open %s\n", qPrintable(file));
            return 1;
        }
    // The frame, then its replay.
    QElapsedTimer wait;
    wait.start();
    QElapsedTimer buildTimer;
    bool building = false;
    double buildMs = 0.0;
    QObject::connect(window.replayBuilder(), &ReplayBuilder::busyChanged, [&](bool busy) {
        if (busy) {
            buildTimer.start();
            building = true;
        } else if (building) {
            buildMs = double(buildTimer.nsecsElapsed()) / 1e6;
            building = false;
        }
    });
    while (!window.isReadyToStep()) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        if (wait.elapsed() > 120000) {
            std::fprintf(stderr, "no replay within 120 s\n");
            return 1;
        }
    }
    Inspection* inspection = window.inspection();
    const QString g = parser.value(QStringLiteral("granularity"));
    inspection->setGranularity(g == QLatin1String("triangle") ? rl::StepGranularity::Triangle
                               : g == QLatin1String("span")   ? rl::StepGranularity::Span
                               : g == QLatin1String("pixel")  ? rl::StepGranularity::Pixel
                                                              : rl::StepGranularity::Scanline);
    const auto frame = window.currentFrame();
    const rl::FrameReplay* replay = inspection->replay();
    // Start in the middle of the frame, where the most has been drawn.
    inspection->seek(
        replay->atFragment(static_cast<std::uint32_t>(replay->fragments().size() / 3)));
    window.repaint();
    QCoreApplication::processEvents();
    const int steps = parser.value(QStringLiteral("steps")).toInt();
    std::vector<double> ms;
    ms.reserve(static_cast<std::size_t>(steps));
    for (int i = 0; i < steps && !inspection->atEnd(); ++i) {
        QElapsedTimer t;
        t.start();
        inspection->stepForward();
        window.repaint();  // synchronous: every visible widget paints now
        ms.push_back(double(t.nsecsElapsed()) / 1e6);
    }
    if (ms.empty()) return 1;
    const double median = percentile(ms, 0.5);
    std::printf("scene: %zu triangles, %dx%d, %zu fragments, %zu rows; docks: %s\n",
                frame->scene->triangleCount(), frame->scene->width, frame->scene->height,
                replay->fragments().size(), replay->rows().size(),
                qPrintable(parser.value(QStringLiteral("docks"))));
    std::printf("frame: %.1f ms; replay built in %.1f ms\n", frame->totalMilliseconds, buildMs);
    std::printf(
        "%zu %s steps: replay and repaint per step median %.2f ms, p90 %.2f ms, worst "
        "%.2f ms: %.0f steps/s\n",
        ms.size(), qPrintable(g), median, percentile(ms, 0.9),
        *std::max_element(ms.begin(), ms.end()), 1000.0 / median);
    return 0;
}
