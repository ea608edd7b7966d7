// Opens a lesson file in a new window, waits until its cursor, pixel and zoom are restored and
// its frame can be stepped through, then saves the lesson on screen to another file: what
// tst_lessons compares with the lesson it saved, to show that a lesson reopens in a new
// process exactly as it was saved.
//   lesson_reopen IN.rasterlab OUT.rasterlab
#include <QApplication>
#include <QElapsedTimer>
#include <QFileInfo>

#include <cstdio>

#include "app/window/main_window.h"

int main(int argc, char* argv[]) {
    QApplication app(argc, argv);
    const QStringList args = QCoreApplication::arguments();
    if (args.size() != 3) {
        std::fprintf(stderr, "usage: lesson_reopen IN.rasterlab OUT.rasterlab\n");
        return 2;
    }
    rasterlab::MainWindow window;
    window.resize(1600, 1000);
    window.show();
    if (!window.openLesson(args[1])) return 1;
    QElapsedTimer timer;
    timer.start();
    while (window.lessonViewPending() || !window.isReadyToStep()) {
        if (timer.elapsed() > 60000) {
            std::fprintf(stderr, "lesson_reopen: the lesson's frame was not ready within 60 s\n");
            return 1;
        }
        QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    }
    return window.saveLesson(args[2]) ? 0 : 1;
}
