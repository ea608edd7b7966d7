// Editing latency, as a teacher dragging a light sees it: the real window (offscreen) at its
// default size with its docks, a scene open, then N changes of the first light's x in the Edit
// dock, each timed from the spin box's new value to the new image painted (the widgets the
// change made dirty, painted at once as the event loop would; a move whose image view was not
// painted is an error). The next change comes as soon as the last one is painted, so the
// replay of each frame is still being built behind it, as in a drag. Prints the median, the 90th
// percentile and the worst, and how long the docks and the replay take to catch up once the
// changes stop.
//
//   bench_editing [--lesson NAME | --torus TRIANGLES] [--changes 50] [--docks all|image]
// Build in Release (scripts/bench-editing.sh).
#include <QApplication>
#include <QCommandLineParser>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "app/window/edit_panel.h"
#include "app/window/main_window.h"
#include "app/window/replay_builder.h"
#include "pipeline/core/frame_memory.h"
#include "tests/bench_support.h"
#include "tests/offscreen_screens.h"
#include "views/frame_image_view.h"

using namespace rasterlab;

namespace {

// Runs the event loop until `done` holds; false after `limitMs`. The loop sleeps until an
// event comes (a frame, a replay, the 2 ms tick) instead of spinning, which would take a core
// from the render's threads.
template <typename Done>
bool waitFor(Done done, qint64 limitMs) {
    QElapsedTimer wait;
    wait.start();
    QTimer tick;
    tick.start(2);
    while (!done()) {
        QCoreApplication::processEvents(QEventLoop::AllEvents | QEventLoop::WaitForMoreEvents);
        if (wait.elapsed() > limitMs) return false;
    }
    return true;
}

// Counts a widget's paint events.
class PaintCounter : public QObject {
public:
    int count = 0;
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() == QEvent::Paint) ++count;
        return QObject::eventFilter(watched, event);
    }
};

}  // namespace

int main(int argc, char* argv[]) {
    rl::keepFrameMemory();
    // Offscreen, a 1920x1080 screen, so that the window opens at its default size.
    QTemporaryDir screens;
    if (!useOffscreenScreens(screens, {QSize(1920, 1080)})) return 1;
    QApplication app(argc, argv);
    QCommandLineParser parser;
    parser.addOptions(
        {{QStringLiteral("lesson"), QStringLiteral("a shipped lesson"), QStringLiteral("NAME"),
          QStringLiteral("goblet")},
         {QStringLiteral("torus"), QStringLiteral("a generated torus of about N triangles"),
          QStringLiteral("N")},
         {QStringLiteral("changes"), QStringLiteral("changes to time"), QStringLiteral("N"),
          QStringLiteral("50")},
         {QStringLiteral("docks"), QStringLiteral("all: the window's docks; image: none"),
          QStringLiteral("D"), QStringLiteral("all")}});
    parser.process(app);

    MainWindow window;
    window.show();
    if (parser.value(QStringLiteral("docks")) == QLatin1String("image"))
        for (QDockWidget* dock : window.findChildren<QDockWidget*>())
            if (dock->objectName() != QLatin1String("editDock")) dock->hide();
    QTemporaryDir dir;
    QString what;
    if (parser.isSet(QStringLiteral("torus"))) {
        QString paths[3];
        if (!bench::writeTorus(dir.path(), parser.value(QStringLiteral("torus")).toInt(), paths))
            return 1;
        for (const QString& path : paths)
            if (!window.openPath(path)) return 1;
        what = QStringLiteral("torus");
    } else {
        what = parser.value(QStringLiteral("lesson"));
        if (!window.openExample(what)) {
            std::fprintf(stderr, "no lesson %s\n", qPrintable(what));
            return 1;
        }
    }
    if (!waitFor([&] { return window.isReadyToStep(); }, 120000)) {
        std::fprintf(stderr, "no replay within 120 s\n");
        return 1;
    }
    auto* edit = window.findChild<EditPanel*>();
    QDoubleSpinBox* x = edit ? edit->spinBox(EditPanel::Field::LightPosition, 0) : nullptr;
    if (!x) return 1;

    PaintCounter painted;
    window.imageView()->installEventFilter(&painted);
    const int changes = parser.value(QStringLiteral("changes")).toInt();
    std::vector<double> ms, arrived, render;  // to painted; to the frame's arrival; its render
    int behind = 0;  // changes made while the last frame's replay was still being built
    for (int i = 0; i < changes; ++i) {
        const auto before = window.shownFrame();
        const int paintsBefore = painted.count;
        behind += window.replayBuilder()->isBusy();
        // Right, then back: the light moves by one step of the spin box at a time.
        const double step = (i / 10) % 2 == 0 ? x->singleStep() : -x->singleStep();
        QElapsedTimer t;
        t.start();
        x->setValue(x->value() + step);
        if (!waitFor([&] { return window.shownFrame() != before; }, 60000)) {
            std::fprintf(stderr, "no new frame within 60 s\n");
            return 1;
        }
        arrived.push_back(double(t.nsecsElapsed()) / 1e6);
        render.push_back(window.shownFrame()->totalMilliseconds);
        // What the change left to paint (the image view, the time label ...), painted now, as
        // the event loop would: the posted update requests, sent at once.
        QCoreApplication::sendPostedEvents(nullptr, QEvent::UpdateRequest);
        ms.push_back(double(t.nsecsElapsed()) / 1e6);
        if (painted.count == paintsBefore) {
            std::fprintf(stderr, "move %d: the new image was not painted\n", i);
            return 1;
        }
    }
    // The drag stops: the docks take the last frame and its replay is finished.
    QElapsedTimer settle;
    settle.start();
    if (!waitFor([&] { return window.isReadyToStep(); }, 120000)) return 1;
    const double settleMs = double(settle.nsecsElapsed()) / 1e6;
    const auto frame = window.currentFrame();
    std::printf("scene: %s, %zu triangles, %dx%d image, window %dx%d; docks: %s\n",
                qPrintable(what), frame->scene->triangleCount(), frame->scene->width,
                frame->scene->height, window.width(), window.height(),
                qPrintable(parser.value(QStringLiteral("docks"))));
    std::printf("%zu light moves (%d with the replay still building): change to painted median "
                "%.1f ms, p90 %.1f ms, worst %.1f ms\n",
                ms.size(), behind, bench::percentile(ms, 0.5), bench::percentile(ms, 0.9),
                *std::max_element(ms.begin(), ms.end()));
    std::printf(
        "of which the new frame arrived after median %.1f ms, p90 %.1f ms (its render "
        "median %.1f ms)\n",
        bench::percentile(arrived, 0.5), bench::percentile(arrived, 0.9),
        bench::percentile(render, 0.5));
    std::printf("after the last move, the docks and the replay were ready %.1f ms later\n",
                settleMs);
    return 0;
}
