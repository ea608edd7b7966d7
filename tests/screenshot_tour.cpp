// Screenshots the program makes of itself for the user guide (docs/guide.en.md,
// docs/guide.pt_BR.md), in one language, each named <shot>-<language>.png, all on the lessons
// the program ships (File > Examples) and the repository's docs/examples, so that whoever
// clones RasterLab can make every picture of the guide again:
//
//   window            the goblet lesson stepped by scanline past the middle of the frame
//   toolbars          the stage strip and the stepping bar, mid-frame
//   menu-file, menu-examples, menu-export, menu-step   the File menu, File > Examples,
//                     File > Export More, the Step menu
//   <dock name>       each stage view: cameraBasisDock ... pixelInspectorDock and the Scene
//                     on the goblet, scanlineDock and trapezoidDock on the triangle lesson,
//                     zbufferDock on the zbuffer lesson, nearClipDock on the near-plane lesson
//   image-stepping    the triangle lesson zoomed to the pixel grid, stepping pixel by pixel
//   breakpoints       the zbuffer lesson's Breakpoints dock after its breakpoint stopped it
//   messages-error    the Messages dock after a bad object file (the scene kept)
//   edit              the Edit dock after ka was set to 0 on the goblet
//   inspector-black   the pixel inspector explaining a black pixel (N.L < 0, no ambient)
//   image-black       the image zoomed around that pixel, picked
//   presentation      presentation mode on the goblet, in the teacher's own layout (F7)
//   lecture-1 ... lecture-7   the lecture layout at 1280x720 on the goblet, stepped by stage
//                     from the start: each stage's dock over the screen, the image beside it
//                     from the scan on
//   fill              View > Fill the Window: the z-buffer dock over the whole window
//   window-lighting, inspector-lighting, edit-lights   the lights lesson: the window, the
//                     pixel inspector light by light, the Edit dock's lights
//   painter           the Painter's algorithm dock on the painter-cycle lesson
//   shading-side-by-side   File > Export More > Shading Side by Side on the sphere lesson
//   strip-command-file  the stage strip of docs/examples/crossing.txt (skipped stages)
//   animation         the default trefoil's turntable paused mid-turn, stepped by scanline
//   normals-wrong     the Normals dock under a scale (1, 0.5, 1): right and wrong normals
//
// With --images DIR it also makes the pictures of the README and docs/accuracy.md:
// zbuffer-dock.png (in Portuguese, the run with --language pt_BR), accuracy-dock.png and
// stability-dock.png (the run with --language en).
//
// Every shot is checked: no visible text (labels, buttons, list and table cells, the window
// title, the status bar) may show a path of the machine it was made on (/tmp/, /home/,
// /work/, /root/, the temporary folder), and no shot outside presentation mode may show
// presentation mode's text. A shot that does is reported on stderr and the tour exits 1.
//
//   screenshot_tour --out DIR [--language en|pt_BR] [--docs DIR] [--images DIR]
// (scripts/screenshots.sh runs it in both languages from the repository's root; --docs is
// the repository's docs folder, default "docs".) The settings are kept in a temporary
// folder, so no earlier run (recent files, layout, language) changes what is shown.
#include <functional>

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QApplication>
#include <QComboBox>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QStatusBar>
#include <QTabBar>
#include <QTextEdit>
#include <QTimer>
#include <QCheckBox>
#include <QCommandLineParser>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QPolygonF>
#include <QProgressDialog>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QSplitter>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>
#include <QUndoStack>
#include <QWheelEvent>

#include <climits>
#include <cstdio>
#include <vector>

#include "app/image_io.h"
#include "app/window/accuracy_panel.h"
#include "app/window/animation_panel.h"
#include "app/window/compare_panel.h"
#include "app/window/edit_panel.h"
#include "app/window/main_window.h"
#include "app/window/replay_builder.h"
#include "app/window/translators.h"
#include "pipeline/analysis/mistakes.h"
#include "tests/offscreen_screens.h"
#include "views/breakpoints_view.h"
#include "views/frame_image_view.h"
#include "views/inspection.h"
#include "views/normals_view.h"
#include "views/painter_view.h"
#include "views/pixel_inspector.h"
#include "views/stepping_bar.h"
#include "views/vertex_table.h"
#include "views/zbuffer_view.h"

using namespace rasterlab;

namespace {

constexpr int kTimeoutMs = 60000;

bool waitForReplay(MainWindow& window) {
    const bool ready = QTest::qWaitFor([&] { return window.isReadyToStep(); }, kTimeoutMs);
    if (!ready) std::printf("FAILED: the frame was not ready to step through in 60 s\n");
    return ready;
}

// After a change of the scene: waits for a frame other than `old`, ready to step through.
bool waitForNewFrame(MainWindow& window, const std::shared_ptr<const rl::FrameTrace>& old) {
    (void)QTest::qWaitFor([&] { return window.inspection()->frame() != old; }, kTimeoutMs);
    return waitForReplay(window);
}

// What a shot must not show: the machine's paths, and presentation mode's text outside it.
struct ShotRules {
    QStringList paths;         // machine paths, e.g. "/tmp/"
    QString presentationText;  // the status bar's text on entering presentation mode
};
ShotRules g_rules;

void addText(QStringList& texts, const QString& text) {
    if (!text.isEmpty()) texts << text;
}

// The cells of a model (every role shown: display, and tooltips are not visible), children
// of tree rows too, up to a limit that no view of the tour reaches.
void addModelTexts(QStringList& texts, const QAbstractItemModel* model, const QModelIndex& parent,
                   int& budget) {
    if (!model) return;
    for (int row = 0; row < model->rowCount(parent) && budget > 0; ++row)
        for (int column = 0; column < model->columnCount(parent) && budget > 0; ++column) {
            const QModelIndex index = model->index(row, column, parent);
            addText(texts, model->data(index, Qt::DisplayRole).toString());
            --budget;
            if (column == 0 && model->hasChildren(index))
                addModelTexts(texts, model, index, budget);
        }
    for (int section = 0; section < model->columnCount(parent); ++section)
        addText(texts, model->headerData(section, Qt::Horizontal).toString());
}

// The texts a widget shows: its own, and those of its descendants visible with it, the
// window's title and status bar.
QStringList visibleTexts(QWidget* root) {
    QStringList texts;
    QWidget* top = root->window();
    addText(texts, top->windowTitle());
    if (auto* main = qobject_cast<QMainWindow*>(top); main && main == root)
        addText(texts, main->statusBar()->currentMessage());
    QList<QWidget*> widgets = root->findChildren<QWidget*>();
    widgets.prepend(root);
    for (QWidget* w : widgets) {
        if (w != root && !w->isVisibleTo(root)) continue;
        if (auto* label = qobject_cast<QLabel*>(w)) addText(texts, label->text());
        if (auto* button = qobject_cast<QAbstractButton*>(w)) addText(texts, button->text());
        if (auto* line = qobject_cast<QLineEdit*>(w)) addText(texts, line->text());
        if (auto* edit = qobject_cast<QTextEdit*>(w)) addText(texts, edit->toPlainText());
        if (auto* plain = qobject_cast<QPlainTextEdit*>(w)) addText(texts, plain->toPlainText());
        if (auto* group = qobject_cast<QGroupBox*>(w)) addText(texts, group->title());
        if (auto* combo = qobject_cast<QComboBox*>(w)) addText(texts, combo->currentText());
        if (auto* dockWidget = qobject_cast<QDockWidget*>(w)) addText(texts, dockWidget->windowTitle());
        if (auto* bar = qobject_cast<QStatusBar*>(w)) addText(texts, bar->currentMessage());
        if (auto* tabs = qobject_cast<QTabBar*>(w))
            for (int i = 0; i < tabs->count(); ++i) addText(texts, tabs->tabText(i));
        if (auto* menu = qobject_cast<QMenu*>(w))
            for (const QAction* action : menu->actions()) addText(texts, action->text());
        if (auto* view = qobject_cast<QAbstractItemView*>(w)) {
            int budget = 200000;
            addModelTexts(texts, view->model(), view->rootIndex(), budget);
        }
    }
    texts.removeDuplicates();
    return texts;
}

// The reasons the shot of `widget` must not be published (empty: none).
QStringList shotProblems(QWidget* widget) {
    QStringList problems;
    const auto* main = qobject_cast<const MainWindow*>(widget->window());
    const bool presenting = main && main->presentationMode();
    for (const QString& text : visibleTexts(widget)) {
        for (const QString& path : g_rules.paths)
            if (text.contains(path))
                problems << QStringLiteral("shows the machine path '%1' in '%2'").arg(path, text);
        if (!presenting && !g_rules.presentationText.isEmpty() &&
            text.contains(g_rules.presentationText))
            problems << QStringLiteral("shows presentation mode's text outside it: '%1'").arg(text);
    }
    return problems;
}

// The widget (or the part `area` of it) as a PNG, compressed as much as PNG allows; false,
// with the reason on stderr, when it cannot be written or shows what it must not.
bool save(QWidget* widget, const QString& path, const QRect& area = QRect()) {
    QCoreApplication::processEvents();
    const QStringList problems = shotProblems(widget);
    for (const QString& problem : problems)
        std::fprintf(stderr, "FAILED: %s %s\n", qPrintable(path), qPrintable(problem));
    const bool ok = widget->grab(area.isNull() ? QRect(QPoint(0, 0), QSize(-1, -1)) : area)
                        .save(path, "PNG", 0);
    if (!ok) std::fprintf(stderr, "FAILED: %s could not be written\n", qPrintable(path));
    else std::printf("wrote %s\n", qPrintable(path));
    return ok && problems.isEmpty();
}

QDockWidget* dock(MainWindow& window, const char* name) {
    return window.findChild<QDockWidget*>(QLatin1String(name));
}

// A menu as it looks open (a hidden menu has no layout to grab).
bool saveMenu(MainWindow& window, QMenu* menu, const QString& path) {
    if (!menu) return false;
    menu->popup(window.mapToGlobal(QPoint(20, 40)));
    QTest::qWait(50);
    const bool ok = save(menu, path);
    menu->hide();
    return ok;
}

void wheel(QWidget* widget, QPointF at, int notches) {
    QWheelEvent event(at, widget->mapToGlobal(at), QPoint(), QPoint(0, 120 * notches), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(widget, &event);
}

// Drags the image so that widget point `from` lands on `to` (a drag of more than a few
// pixels pans; a shorter one would pick a pixel, so it is not made).
void drag(QWidget* widget, QPointF from, QPointF to) {
    if ((to - from).manhattanLength() <= 4.0) return;
    const auto send = [&](QEvent::Type type, QPointF at, Qt::MouseButtons buttons) {
        QMouseEvent event(type, at, widget->mapToGlobal(at), Qt::LeftButton, buttons,
                          Qt::NoModifier);
        QCoreApplication::sendEvent(widget, &event);
    };
    send(QEvent::MouseButtonPress, from, Qt::LeftButton);
    send(QEvent::MouseMove, (from + to) / 2.0, Qt::LeftButton);
    send(QEvent::MouseMove, to, Qt::LeftButton);
    send(QEvent::MouseButtonRelease, to, Qt::NoButton);
}

// The rectangle around the widget point `centre`, of the given size, kept inside `bounds`.
QRect around(QPointF centre, QSize size, const QRect& bounds) {
    QRect r(QPoint(0, 0), size.boundedTo(bounds.size()));
    r.moveCenter(centre.toPoint());
    if (r.left() < bounds.left()) r.moveLeft(bounds.left());
    if (r.top() < bounds.top()) r.moveTop(bounds.top());
    if (r.right() > bounds.right()) r.moveRight(bounds.right());
    if (r.bottom() > bounds.bottom()) r.moveBottom(bounds.bottom());
    return r;
}

// A dock's view on its own, laid out at a chosen size (at least its minimum): what the dock
// shows when it is that large. A view in a scroll area is taken out of its control for the
// grab (a resizable scroll area lays its view out at the view's preferred height for the
// width, however large the dock).
bool saveDock(QDockWidget* dock, const QString& path, QSize size) {
    dock->show();
    dock->raise();
    QTest::qWait(50);
    QWidget* view = dock->widget();
    auto* scroll = qobject_cast<QScrollArea*>(view);
    if (scroll && scroll->widget()) {
        view = scroll->widget();
        scroll->setWidgetResizable(false);
    }
    const QSize old = view->size();
    view->resize(size.expandedTo(view->minimumSizeHint()));
    const bool ok = save(view, path);
    view->resize(old);
    if (scroll) scroll->setWidgetResizable(true);
    return ok;
}

// Shows the image rectangle `area` (pixels) in the middle of the view, as large as fits in
// `room` (widget pixels; at least `minZoom`), with the mouse wheel and a drag as by hand.
void zoomTo(FrameImageView* view, const QRectF& area, QSizeF room, double minZoom) {
    view->fitToWindow();
    QCoreApplication::processEvents();
    const QPointF centre(view->width() / 2.0, view->height() / 2.0);
    drag(view, view->widgetPoint(area.center()), centre);
    const double wanted =
        std::max(minZoom, std::min(room.width() / area.width(), room.height() / area.height()));
    while (view->zoom() * 1.25 <= wanted) wheel(view, centre, 1);
    // Centre again (the wheel keeps the point under the mouse, up to rounding).
    drag(view, view->widgetPoint(area.center()), centre);
}

// The image zoomed onto `area` (zoomTo, in `room`), the part `crop` of the view around its
// middle saved; then the whole image in the view again.
bool saveZoomed(FrameImageView* view, const QRectF& area, QSizeF room, double minZoom, QSize crop,
                const QString& path) {
    zoomTo(view, area, room, minZoom);
    const bool ok = save(
        view, path, around(QPointF(view->width() / 2.0, view->height() / 2.0), crop, view->rect()));
    view->fitToWindow();
    return ok;
}

// Opens a shipped lesson and waits for its frame, ready to step, with its view restored.
bool openExample(MainWindow& window, const char* name) {
    const auto old = window.inspection()->frame();
    if (!window.openExample(QLatin1String(name))) {
        std::fprintf(stderr, "FAILED: no lesson '%s'\n", name);
        return false;
    }
    const bool ready = QTest::qWaitFor(
        [&] {
            return window.inspection()->frame() != old && !window.lessonViewPending() &&
                   window.isReadyToStep();
        },
        kTimeoutMs);
    if (!ready) std::fprintf(stderr, "FAILED: the lesson '%s' was not ready in 60 s\n", name);
    // The status bar may still tell of the lesson before ("Stopped at a breakpoint ...").
    window.statusBar()->clearMessage();
    QTest::qWait(50);
    return ready;
}

// The stepping bar's text: where the cursor is (quoted by the guide).
QString position(MainWindow& window) {
    return window.steppingBar()->positionLabel()->fullText();
}

// The steps of `granularity` from `from` to `to` (as many presses of Step Forward).
int stepsBetween(const rl::FrameReplay* replay, rl::ReplayCursor from, rl::ReplayCursor to,
                 rl::StepGranularity granularity) {
    int steps = 0;
    while (from < to) {
        const rl::ReplayCursor next = replay->next(from, granularity);
        if (!(from < next)) break;
        from = next;
        ++steps;
    }
    return steps;
}

// The pixels an object covers at the end of the frame.
QRect coveredBox(Inspection* inspection) {
    QRect box;
    const rl::Image<std::uint32_t>& holder = inspection->frame()->depth->triangle;
    for (int y = 0; y < holder.height(); ++y)
        for (int x = 0; x < holder.width(); ++x)
            if (holder.at(x, y) != rl::kNoTriangle) box |= QRect(x, y, 1, 1);
    return box;
}

}  // namespace

// The Compare dock on the goblet lesson: "their" image is ours with the ambient times Od
// (the guide's worked example), their pixel (435, 140) picked; the dock closed again.
bool saveCompare(MainWindow& window, const QString& path) {
    QTemporaryDir theirDir;
    const QString theirs = theirDir.filePath(QStringLiteral("theirs.png"));
    auto ours = rl::renderOurFrame(window.currentFrame()->scene);
    if (!ours) return false;
    auto mistake = rl::imageWithMistake(ours.value(), rl::Mistake::AmbientTimesOd);
    if (!mistake || !mistake->has_value() ||
        !rasterlab::savePng(rasterlab::toQImage(**mistake), theirs, nullptr) ||
        !window.compareWithImage(theirs)) {
        std::fprintf(stderr, "FAILED: %s: the comparison could not be made\n", qPrintable(path));
        return false;
    }
    window.inspection()->pickPixel(QPoint(435, 140));
    QTest::qWait(50);
    QDockWidget* compare = dock(window, "compareDock");
    const bool ok = saveDock(compare, path, QSize(900, 700));
    compare->close();
    return ok;
}

// The Compare dock on the goblet stretched a third down (their y scaled by the width, the
// fitted screen map), and the dialog that says a compare runs, grabbed while it does; the
// comparison is then cancelled and the dock closed.
bool saveCompareScreenMap(MainWindow& window, const QString& path, const QString& progressPath) {
    QTemporaryDir theirDir;
    auto ours = rl::renderOurFrame(window.currentFrame()->scene);
    if (!ours) return false;
    rl::Slip tall;
    tall.mistake = rl::Mistake::ScreenMap;
    tall.map = rl::ScreenMap{1.0, 0.0, 0.0, 4.0 / 3.0, 0.0, 0.0};
    rl::Slip light;
    light.mistake = rl::Mistake::LightInWorld;
    auto stretched = rl::imageWithMistakes(ours.value(), {tall});
    auto longer = rl::imageWithMistakes(ours.value(), {tall, light});
    const QString first = theirDir.filePath(QStringLiteral("tall.png")),
                  second = theirDir.filePath(QStringLiteral("longer.png"));
    if (!stretched || !stretched->has_value() || !longer || !longer->has_value() ||
        !rasterlab::savePng(rasterlab::toQImage(**stretched), first, nullptr) ||
        !rasterlab::savePng(rasterlab::toQImage(**longer), second, nullptr) ||
        !window.compareWithImage(first)) {
        std::fprintf(stderr, "FAILED: %s: the comparison could not be made\n", qPrintable(path));
        return false;
    }
    QDockWidget* compare = dock(window, "compareDock");
    bool ok = saveDock(compare, path, QSize(900, 700));
    bool grabbed = false;
    QTimer::singleShot(rasterlab::ComparePanel::kProgressAfterMs + 200, &window, [&] {
        auto* progress = window.findChild<QProgressDialog*>(QStringLiteral("compareProgress"));
        if (!progress || !progress->isVisible()) return;
        grabbed = progress->grab().save(progressPath);
        if (auto* button = progress->findChild<QPushButton*>()) button->click();
    });
    window.compareWithImage(second);
    if (!grabbed) std::fprintf(stderr, "FAILED: %s: no dialog\n", qPrintable(progressPath));
    compare->close();
    return ok && grabbed;
}

// The lecture layout on a 1280x720 projector: the goblet in presentation mode, stepped by
// stage from the start (Ctrl+Home, then Page Down), a shot per stage.
bool saveLecture(const std::function<QString(const QString&)>& file) {
    QScreen* projector = nullptr;
    for (QScreen* screen : QGuiApplication::screens())
        if (screen->size() == QSize(1280, 720)) projector = screen;
    if (!projector) {
        std::fprintf(stderr, "FAILED: no 1280x720 screen\n");
        return false;
    }
    MainWindow window;
    window.setScreen(projector);
    window.move(projector->geometry().topLeft());
    window.resize(1280, 720);
    window.show();
    if (!waitForReplay(window) || !openExample(window, "goblet")) return false;
    window.setPresentationMode(true);
    Inspection* inspection = window.inspection();
    inspection->setGranularity(rl::StepGranularity::Stage);
    window.steppingBar()->toStartAction()->trigger();
    bool ok = true;
    for (int stage = 1; stage <= rl::kStageCount; ++stage) {
        if (stage > 1) window.steppingBar()->stepForwardAction()->trigger();
        QTest::qWait(150);
        window.statusBar()->clearMessage();  // the hint on entering: the same in every shot
        ok = save(&window, file(QStringLiteral("lecture-%1").arg(stage))) && ok;
    }
    window.setPresentationMode(false);
    return ok;
}

int main(int argc, char* argv[]) {
    // Offscreen, a projector's 1600x1000 screen: presentation mode sizes its text and places
    // its docks by the screen, and the window fits itself to it; and a 1280x720 one, the
    // lecture layout's.
    QTemporaryDir screens;
    if (!useOffscreenScreens(screens, {QSize(1600, 1000), QSize(1280, 720)})) return 1;
    QApplication app(argc, argv);
    // Settings of this run only: no recent files, layout or language of an earlier one.
    QTemporaryDir settingsDir;
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir.path());
    QCoreApplication::setOrganizationName(QStringLiteral("RasterLabTour"));
    QCommandLineParser parser;
    parser.addOptions({{QStringLiteral("out"), QStringLiteral("folder"), QStringLiteral("DIR")},
                       {QStringLiteral("language"), QStringLiteral("en or pt_BR"),
                        QStringLiteral("L"), QStringLiteral("en")},
                       {QStringLiteral("docs"), QStringLiteral("the repository's docs folder"),
                        QStringLiteral("DIR"), QStringLiteral("docs")},
                       {QStringLiteral("images"),
                        QStringLiteral("where to write the README's and accuracy.md's pictures"),
                        QStringLiteral("DIR")}});
    parser.process(app);
    // Absolute: the bad file's shot is made from another current folder.
    const QDir out(QFileInfo(parser.value(QStringLiteral("out"))).absoluteFilePath());
    QDir().mkpath(out.path());
    const QString language = parser.value(QStringLiteral("language"));
    Translators translators;
    translators.install(language);
    const QDir docs(QFileInfo(parser.value(QStringLiteral("docs"))).absoluteFilePath());
    const QString images = parser.value(QStringLiteral("images")).isEmpty()
                               ? QString()
                               : QFileInfo(parser.value(QStringLiteral("images"))).absoluteFilePath();
    const QString suffix = QStringLiteral("-") + language + QStringLiteral(".png");
    auto file = [&](const QString& name) { return out.filePath(name + suffix); };
    int failures = 0;
    const auto check = [&](bool ok) { failures += ok ? 0 : 1; };

    g_rules.paths = {QStringLiteral("/tmp/"), QStringLiteral("/home/"), QStringLiteral("/work/"),
                     QStringLiteral("/root/"), QDir::tempPath(), settingsDir.path(),
                     QDir::currentPath(), QDir::homePath() + QLatin1Char('/')};
    g_rules.paths.removeDuplicates();
    g_rules.paths.removeAll(QStringLiteral("/"));
    g_rules.presentationText = QCoreApplication::translate(
        "rasterlab::MainWindow",
        "Presentation mode: F5 or Esc to leave; Page Down, Right and Space step and play");

    MainWindow window;
    window.resize(1500, 940);
    window.show();
    if (!waitForReplay(window)) return 1;
    if (!openExample(window, "goblet")) return 1;
    Inspection* inspection = window.inspection();
    const rl::FrameReplay* replay = inspection->replay();
    const QPoint highlight(353, 157);  // the highlight on the bowl (clamped to 255)
    const QRect gobletBox = coveredBox(inspection);

    // The window: the goblet, its highlight picked, stepped by scanline to past the middle.
    inspection->setGranularity(rl::StepGranularity::Scanline);
    inspection->seek(replay->next(
        replay->atFragment(static_cast<std::uint32_t>(replay->fragments().size() * 6 / 10)),
        rl::StepGranularity::Scanline));
    {
        FrameImageView* view = window.imageView();
        zoomTo(view, QRectF(gobletBox), QSizeF(view->size()) * 0.92, 0.1);
    }
    std::printf("window: %s\n", qPrintable(position(window)));
    check(save(&window, file(QStringLiteral("window"))));
    {
        const QRect strip = window.findChild<QToolBar*>(QStringLiteral("stageToolBar"))->geometry();
        const QRect bar =
            window.findChild<QToolBar*>(QStringLiteral("steppingToolBar"))->geometry();
        const QRect both = strip.united(bar);
        check(save(&window, file(QStringLiteral("toolbars")),
                   QRect(0, both.top(), window.width(), both.height())));
    }
    QMenu* fileMenu =
        window.menuBar()->actions().value(0) ? window.menuBar()->actions()[0]->menu() : nullptr;
    check(saveMenu(window, fileMenu, file(QStringLiteral("menu-file"))));
    check(saveMenu(window, window.findChild<QMenu*>(QStringLiteral("examplesMenu")),
                   file(QStringLiteral("menu-examples"))));
    check(saveMenu(window, window.findChild<QMenu*>(QStringLiteral("exportMenu")),
                   file(QStringLiteral("menu-export"))));
    check(saveMenu(window, window.findChild<QMenu*>(QStringLiteral("stepMenu")),
                   file(QStringLiteral("menu-step"))));

    // The goblet's stage views at the end of the frame, its highlight picked.
    inspection->toEnd();
    inspection->pickPixel(highlight);
    {
        const std::pair<const char*, QSize> docks[] = {
            {"cameraBasisDock", {560, 640}},    {"vertexTableDock", {640, 560}},
            {"normalsDock", {560, 660}},        {"projectionDock", {560, 660}},
            {"pixelInspectorDock", {700, 600}}, {"sceneDock", {380, 560}}};
        window.vertexTableView()->setOnlySelectedTriangle(true);
        for (const auto& [name, size] : docks)
            check(saveDock(dock(window, name), file(QLatin1String(name)), size));
        window.vertexTableView()->setOnlySelectedTriangle(false);
        window.resetLayout();
    }

    // Live editing: ka = 0 takes the ambient term away; the pixels the light does not reach
    // turn black. The pixel inspector says why.
    std::shared_ptr<const rl::FrameTrace> before = inspection->frame();
    window.editPanel()->spinBox(SceneDocument::Field::Ka)->setValue(0.0);
    if (!waitForNewFrame(window, before)) return 1;
    replay = inspection->replay();
    dock(window, "editDock")->raise();
    check(saveDock(dock(window, "editDock"), file(QStringLiteral("edit")), QSize(380, 700)));
    {
        const QImage image = window.currentImage();
        const rl::DepthTest* buffers = inspection->buffers();
        // A black pixel in the middle of a black patch of the surface (where a student would
        // click), the light farthest behind its surface among them (the clearest drawing).
        const auto blackSurface = [&](int x, int y) {
            if (!buffers->triangle.contains(x, y) || buffers->triangle.at(x, y) == rl::kNoTriangle)
                return false;
            const QColor c = image.pixelColor(x, y);
            return c.red() + c.green() + c.blue() == 0;
        };
        std::vector<std::pair<int, QPoint>> candidates;
        int most = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                if (!blackSurface(x, y)) continue;
                int around = 0;
                for (int dy = -4; dy <= 4; ++dy)
                    for (int dx = -4; dx <= 4; ++dx) around += blackSurface(x + dx, y + dy);
                most = std::max(most, around);
                candidates.emplace_back(around, QPoint(x, y));
            }
        QPoint black(-1, -1);
        float lowest = 0.0f;
        for (const auto& [around, p] : candidates) {
            if (around < most) continue;
            inspection->pickPixel(p);
            const auto& b = window.pixelInspector()->breakdown();
            if (b && b->has(LightingFlag::LightBehind) && b->event.sample.nDotL < lowest) {
                lowest = b->event.sample.nDotL;
                black = p;
            }
        }
        std::printf("black pixel (%d, %d), N.L = %g\n", black.x(), black.y(), double(lowest));
        inspection->pickPixel(black);
        check(saveDock(dock(window, "pixelInspectorDock"), file(QStringLiteral("inspector-black")),
                       QSize(700, 600)));
        // Where it is: black on black, next to the background.
        const QSize crop(520, 320);
        check(saveZoomed(window.imageView(), QRectF(black.x() - 20, black.y() - 12, 41, 25),
                         QSizeF(crop), 4.0, crop, file(QStringLiteral("image-black"))));
    }

    // ka back (Undo).
    before = inspection->frame();
    window.editPanel()->undoStack()->undo();
    if (!waitForNewFrame(window, before)) return 1;
    replay = inspection->replay();
    window.resetLayout();
    // The README's and accuracy.md's pictures: the window filled (F11) by the z-buffer dock in
    // false colour (in Portuguese), or by the Accuracy dock's measurement (in English).
    if (!images.isEmpty()) {
        QDir().mkpath(images);
        inspection->toEnd();
        window.imageView()->fitToWindow();
        if (language == QLatin1String("pt_BR")) {
            window.zbufferView()->setPalette(DepthPalette::FalseColour);
            dock(window, "zbufferDock")->raise();
            window.toggleFill(dock(window, "zbufferDock"));
            QTest::qWait(100);
            check(save(&window, QDir(images).filePath(QStringLiteral("zbuffer-dock.png"))));
            window.toggleFill();
            window.zbufferView()->setPalette(DepthPalette::Grey);
        } else if (language == QLatin1String("en")) {
            dock(window, "accuracyDock")->raise();
            AccuracyPanel* accuracy = window.accuracyPanel();
            accuracy->measure();
            const bool measured = QTest::qWaitFor(
                [&] { return !accuracy->isMeasuring() && accuracy->report(); }, 5 * kTimeoutMs);
            if (!measured) std::fprintf(stderr, "FAILED: the accuracy measurement did not end\n");
            check(measured);
            window.toggleFill(dock(window, "accuracyDock"));
            QTest::qWait(100);
            check(save(&window, QDir(images).filePath(QStringLiteral("accuracy-dock.png"))));
            window.toggleFill();
            // The stability sweep of the same scene along every axis, its plot and summary.
            accuracy->setSweepAxis(std::nullopt);
            accuracy->sweep();
            const bool swept = QTest::qWaitFor(
                [&] { return !accuracy->isSweeping() && accuracy->stabilityReport(); },
                10 * kTimeoutMs);
            if (!swept) std::fprintf(stderr, "FAILED: the stability sweep did not end\n");
            check(swept);
            window.toggleFill(dock(window, "accuracyDock"));
            QTest::qWait(100);
            check(save(&window, QDir(images).filePath(QStringLiteral("stability-dock.png"))));
            window.toggleFill();
        }
        window.resetLayout();
    }

    // View > Fill the Window: the z-buffer dock alone, for a projector.
    inspection->toEnd();
    dock(window, "zbufferDock")->raise();
    window.toggleFill(dock(window, "zbufferDock"));
    QTest::qWait(100);
    check(save(&window, file(QStringLiteral("fill"))));
    window.toggleFill();
    QTest::qWait(50);
    window.resetLayout();

    // In front of a class: the highlight picked, stepped by scanline to the middle of the
    // frame, in presentation mode.
    inspection->pickPixel(highlight);
    inspection->setGranularity(rl::StepGranularity::Scanline);
    inspection->seek(
        replay->next(replay->atFragment(static_cast<std::uint32_t>(replay->fragments().size() / 2)),
                     rl::StepGranularity::Scanline));
    window.setLectureLayout(false);  // the teacher's own layout; the lecture's shots follow
    window.setPresentationMode(true);  // full screen: the projector's 1600x1000
    QTest::qWait(50);
    window.fitDocks();
    QTest::qWait(50);
    zoomTo(window.imageView(), QRectF(gobletBox), QSizeF(window.imageView()->size()) * 0.92, 0.1);
    {
        QEvent leave(QEvent::Leave);  // the mouse gone: no pixel read out in the status bar
        QCoreApplication::sendEvent(window.imageView(), &leave);
    }
    check(save(&window, file(QStringLiteral("presentation"))));
    window.setPresentationMode(false);
    window.setLectureLayout(true);
    window.resize(1500, 940);
    QTest::qWait(50);

    // A bad object file: the message names the place; the scene stays. The goblet's files
    // copied to a folder (as a reader copies resources/lessons/goblet), opened from there by
    // their names, then line 4 of the object broken: the letter O typed for a zero.
    {
        QTemporaryDir copy;
        const QString home = QDir::currentPath();
        for (const char* name : {"camera.cfg", "lighting.txt", "goblet.byu"})
            QFile::copy(QStringLiteral(":/lessons/goblet/") + QLatin1String(name),
                        copy.filePath(QLatin1String(name)));
        QDir::setCurrent(copy.path());
        for (const char* name : {"camera.cfg", "lighting.txt", "goblet.byu"})
            QFile(QLatin1String(name)).setPermissions(QFile::ReadOwner | QFile::WriteOwner);
        before = inspection->frame();
        if (!window.openPath(QStringLiteral(".")) || !waitForNewFrame(window, before)) return 1;
        QFile object(QStringLiteral("goblet.byu"));
        if (!object.open(QIODevice::ReadOnly)) return 1;
        QList<QByteArray> lines = object.readAll().split('\n');
        object.close();
        if (lines.size() > 3) lines[3].replace(QByteArray("1.5803"), QByteArray("1.58O3"));
        QFile bad(QStringLiteral("goblet.byu"));
        if (!bad.open(QIODevice::WriteOnly)) return 1;
        bad.write(lines.join('\n'));
        bad.close();
        window.openPath(QStringLiteral("goblet.byu"));
        QTest::qWait(100);
        check(saveDock(dock(window, "messagesDock"), file(QStringLiteral("messages-error")),
                       QSize(1240, 110)));
        QDir::setCurrent(home);
    }

    // The triangle lesson: stepped pixel by pixel to the middle of its middle row.
    if (!openExample(window, "triangle")) return 1;
    replay = inspection->replay();
    {
        const QPoint picked(14, 12);  // the lesson's picked pixel
        std::uint32_t target = 0;
        for (std::uint32_t i = 0; i < replay->fragments().size(); ++i) {
            const rl::ReplayFragment& f = replay->fragments()[i];
            if (f.y == picked.y() && int(f.x) == picked.x() + 3) target = i;
        }
        const rl::ReplayCursor cursor = replay->atFragment(target + 1);
        std::printf("triangle: %d pixel steps to '", stepsBetween(replay, replay->start(), cursor,
                                                                rl::StepGranularity::Pixel));
        inspection->seek(cursor);
        std::printf("%s'\n", qPrintable(position(window)));
        FrameImageView* view = window.imageView();
        const QRectF box(QPointF(0, 0), QSizeF(window.currentImage().size()));
        const QSize crop(700, 520);
        check(saveZoomed(view, box, QSizeF(crop) * 0.95, 10.0, crop,
                         file(QStringLiteral("image-stepping"))));
        check(saveDock(dock(window, "scanlineDock"), file(QStringLiteral("scanlineDock")),
                       QSize(560, 760)));
        check(saveDock(dock(window, "trapezoidDock"), file(QStringLiteral("trapezoidDock")),
                       QSize(560, 760)));
    }

    // The zbuffer lesson: Continue to Breakpoint stops at the second triangle; then stepped by
    // scanline half-way through it.
    if (!openExample(window, "zbuffer")) return 1;
    replay = inspection->replay();
    inspection->continueToBreakpoint();
    std::printf("zbuffer: stopped at '%s'\n", qPrintable(position(window)));
    check(saveDock(dock(window, "breakpointsDock"), file(QStringLiteral("breakpoints")),
                  QSize(380, 300)));
    {
        const rl::ReplayCursor stop = inspection->cursor();
        const std::uint32_t second = 1;  // 0-based
        const std::uint32_t rows = replay->endRow(second) - replay->firstRow(second);
        rl::ReplayCursor c = stop;
        for (std::uint32_t i = 0; i < rows / 2; ++i)
            c = replay->next(c, rl::StepGranularity::Scanline);
        inspection->seek(c);
        std::printf("zbuffer: %d scanline steps more to '%s'\n",
                    stepsBetween(replay, stop, c, rl::StepGranularity::Scanline),
                    qPrintable(position(window)));
        check(saveDock(dock(window, "zbufferDock"), file(QStringLiteral("zbufferDock")),
                       QSize(520, 760)));
    }

    // The near-plane lesson: the clipping dock on its one clipped triangle.
    if (!openExample(window, "near-plane")) return 1;
    check(saveDock(dock(window, "nearClipDock"), file(QStringLiteral("nearClipDock")),
                   QSize(620, 760)));

    // The lights lesson: a spot, a directional and an attenuated light; its pixel picked.
    if (!openExample(window, "lights")) return 1;
    window.resetLayout();
    inspection->toEnd();
    inspection->pickPixel(QPoint(330, 340));  // inside the spot's disc (the lesson's is outside)
    QTest::qWait(50);
    check(save(&window, file(QStringLiteral("window-lighting"))));
    check(saveDock(dock(window, "pixelInspectorDock"), file(QStringLiteral("inspector-lighting")),
                   QSize(760, 1000)));
    check(saveDock(dock(window, "editDock"), file(QStringLiteral("edit-lights")),
                   QSize(380, 1100)));

    // The painter-cycle lesson: the painter against the z-buffer.
    if (!openExample(window, "painter-cycle")) return 1;
    inspection->toEnd();
    {
        auto* painter = window.findChild<PainterView*>();
        dock(window, "painterDock")->raise();
        QTest::qWait(50);
        for (FrameImageView* view : {painter->painterImageView(), painter->zBufferImageView()})
            view->fitToWindow();
    }
    check(saveDock(dock(window, "painterDock"), file(QStringLiteral("painter")),
                   QSize(1200, 620)));

    // The sphere lesson: flat, Gouraud and Phong side by side, as exported.
    if (!openExample(window, "sphere")) return 1;
    {
        const QString path = file(QStringLiteral("shading-side-by-side"));
        const bool ok = window.exportShadingSideBySide(path);
        std::printf("%s %s\n", ok ? "wrote" : "FAILED", qPrintable(path));
        check(ok);
        window.statusBar()->clearMessage();  // "Exported <the path on this machine>"
    }

    // Compare with Image on the goblet (the guide's worked example).
    if (!openExample(window, "goblet")) return 1;
    check(saveCompare(window, file(QStringLiteral("compare"))));
    check(saveCompareScreenMap(window, file(QStringLiteral("compare-screenmap")),
                               file(QStringLiteral("compare-progress"))));

    // A command file of the repository: no course camera, nothing lit; three stages skipped.
    if (!window.openPath(docs.filePath(QStringLiteral("examples/crossing.txt")))) return 1;
    if (!waitForReplay(window)) return 1;
    {
        const QRect strip = window.findChild<QToolBar*>(QStringLiteral("stageToolBar"))->geometry();
        check(save(&window, file(QStringLiteral("strip-command-file")),
                   QRect(0, strip.top(), std::min(window.width(), 1100), strip.height())));
        // Stepped by scanline past the middle: the scan dock shows seed 001's DDA, its sums of
        // x and of the depth in double.
        Inspection* in = window.inspection();
        const rl::FrameReplay* r = in->replay();
        in->setGranularity(rl::StepGranularity::Scanline);
        rl::ReplayCursor row = r->atFragment(static_cast<std::uint32_t>(r->fragments().size() / 2));
        for (int k = 0; k < 12; ++k) row = r->next(row, rl::StepGranularity::Scanline);
        in->seek(row);
        check(saveDock(dock(window, "scanlineDock"), file(QStringLiteral("scanlineDock-dda")),
                       QSize(560, 1500)));
    }

    // Seed 002's animation on the default trefoil: paused at frame 30 (t = 1.25 s, 45
    // degrees), a pixel picked, stepped by scanline to the middle of the frame.
    {
        MainWindow moving;
        moving.resize(1500, 940);
        moving.show();
        if (!waitForReplay(moving)) return 1;
        AnimationPanel* panel = moving.animationPanel();
        dock(moving, "animationDock")->raise();
        panel->findChild<QCheckBox*>(QStringLiteral("animationEnabled"))->setChecked(true);
        before = moving.inspection()->frame();
        panel->setFrame(30);
        if (!waitForNewFrame(moving, before)) return 1;
        Inspection* in = moving.inspection();
        const rl::FrameReplay* r = in->replay();
        // The covered pixel nearest the middle of the image.
        const rl::Image<std::uint32_t>& holder = in->frame()->depth->triangle;
        QPoint middle(holder.width() / 2, holder.height() / 2), picked = middle;
        for (int nearest = INT_MAX, y = 0; y < holder.height(); ++y)
            for (int x = 0; x < holder.width(); ++x)
                if (holder.at(x, y) != rl::kNoTriangle &&
                    (QPoint(x, y) - middle).manhattanLength() < nearest) {
                    nearest = (QPoint(x, y) - middle).manhattanLength();
                    picked = QPoint(x, y);
                }
        in->pickPixel(picked);
        in->setGranularity(rl::StepGranularity::Scanline);
        in->seek(r->next(r->atFragment(static_cast<std::uint32_t>(r->fragments().size() / 2)),
                         rl::StepGranularity::Scanline));
        check(save(&moving, file(QStringLiteral("animation"))));

        // The same frame squashed by (1, 0.5, 1): the normals by M leave the surface.
        before = moving.inspection()->frame();
        panel->findChild<QDoubleSpinBox*>(QStringLiteral("animationScale1"))->setValue(0.5);
        if (!waitForNewFrame(moving, before)) return 1;
        auto* normals = moving.findChild<NormalsView*>(QStringLiteral("normalsView"));
        normals->setWrongNormals(true);
        dock(moving, "normalsDock")->raise();
        moving.inspection()->pickPixel(picked);
        // Room for the explanation: the two normals of the picked triangle in numbers.
        if (auto* split = normals->findChild<QSplitter*>()) split->setSizes({560, 620});
        check(saveDock(dock(moving, "normalsDock"), file(QStringLiteral("normals-wrong")),
                       QSize(640, 1180)));
    }
    check(saveLecture(file));
    if (failures > 0)
        std::fprintf(stderr, "FAILED: %d shots could not be made or show what they must not\n",
                     failures);
    return failures == 0 ? 0 : 1;
}
