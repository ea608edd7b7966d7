// Screenshots the program makes of itself for the user guide (docs/guide.en.md,
// docs/guide.pt_BR.md), in one language, each named <shot>-<language>.png:
//
//   window            the window on calice2, stepped by scanline past the middle of the frame
//   toolbars          the stage strip and the stepping bar, mid-frame
//   menu-file, menu-export, menu-step   the File menu, File > Export More, the Step menu
//   <dock name>       each stage view (cameraBasisDock ... pixelInspectorDock, nearClipDock,
//                     trapezoidDock) and the Scene
//   image-stepping    the image zoomed to the pixel grid, stepping pixel by pixel
//   breakpoints       the Breakpoints dock after a breakpoint stopped the replay
//   messages-error    the Messages dock after a bad object file (the scene kept)
//   edit              the Edit dock after ka was set to 0
//   inspector-black   the pixel inspector explaining a black pixel (N.L < 0, no ambient)
//   image-black       the image zoomed around that pixel, picked
//   presentation      presentation mode
//   strip-command-file  the stage strip of a command file (skipped stages)
//   animation         the default trefoil's turntable paused mid-turn, stepped by scanline
//   normals-wrong     the Normals dock under a scale (1, 0.5, 1): right and wrong normals
//   window-lighting, inspector-lighting, edit-lights   calice2 under the lecture slides'
//                     lighting (an attenuated spot, a directional light, Blinn-Phong): the
//                     window, the pixel inspector light by light, the Edit dock's lights
//   painter           the Painter's algorithm dock on that scene (seed 004)
//
//   screenshot_tour --out DIR [--language en|pt_BR] [--samples DIR]
// (scripts/screenshots.sh runs it in both languages.) The settings are kept in a temporary
// folder, so no earlier run (recent files, layout, language) changes what is shown.
#include <QApplication>
#include <QCheckBox>
#include <QCommandLineParser>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QPolygonF>
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

#include "animation_panel.h"
#include "breakpoints_view.h"
#include "edit_panel.h"
#include "frame_image_view.h"
#include "inspection.h"
#include "main_window.h"
#include "normals_view.h"
#include "painter_view.h"
#include "pixel_inspector.h"
#include "replay_builder.h"
#include "stepping_bar.h"
#include "translators.h"
#include "vertex_table.h"

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

// The widget (or the part `area` of it) as a PNG, compressed as much as PNG allows.
bool save(QWidget* widget, const QString& path, const QRect& area = QRect()) {
    QCoreApplication::processEvents();
    const bool ok = widget->grab(area.isNull() ? QRect(QPoint(0, 0), QSize(-1, -1)) : area)
                        .save(path, "PNG", 0);
    std::printf("%s %s\n", ok ? "wrote" : "FAILED", qPrintable(path));
    return ok;
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

}  // namespace

int main(int argc, char* argv[]) {
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
                       {QStringLiteral("samples"), QStringLiteral("course samples"),
                        QStringLiteral("DIR"), QStringLiteral("../shared/samples")}});
    parser.process(app);
    const QDir out(parser.value(QStringLiteral("out")));
    QDir().mkpath(out.path());
    const QString language = parser.value(QStringLiteral("language"));
    Translators translators;
    translators.install(language);
    const QString samples = parser.value(QStringLiteral("samples"));
    const QString suffix = QStringLiteral("-") + language + QStringLiteral(".png");
    auto file = [&](const QString& name) { return out.filePath(name + suffix); };
    int failures = 0;
    const auto check = [&](bool ok) { failures += ok ? 0 : 1; };

    MainWindow window;
    window.resize(1500, 940);
    window.show();
    const QString ufpe = samples + QStringLiteral("/course/ufpe/");
    for (const char* name : {"calice2.cfg", "iluminacao.txt", "calice2.byu"})
        if (!window.openPath(ufpe + QLatin1String(name))) return 1;
    if (!waitForReplay(window)) return 1;
    Inspection* inspection = window.inspection();
    const rl::FrameReplay* replay = inspection->replay();

    // The window: the brightest pixel of the image (the highlight) picked, stepped by
    // scanline to past the middle of the frame.
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
    // The pixels the object covers.
    QRect objectBox;
    {
        const rl::Image<std::uint32_t>& holder = inspection->frame()->depth->triangle;
        for (int y = 0; y < holder.height(); ++y)
            for (int x = 0; x < holder.width(); ++x)
                if (holder.at(x, y) != rl::kNoTriangle) objectBox |= QRect(x, y, 1, 1);
    }
    inspection->pickPixel(brightest);
    inspection->setGranularity(rl::StepGranularity::Scanline);
    inspection->seek(replay->next(
        replay->atFragment(static_cast<std::uint32_t>(replay->fragments().size() * 6 / 10)),
        rl::StepGranularity::Scanline));
    {
        // The object as large as the view allows.
        FrameImageView* view = window.imageView();
        zoomTo(view, QRectF(objectBox), QSizeF(view->size()) * 0.92, 0.1);
    }
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
    check(saveMenu(window, window.findChild<QMenu*>(QStringLiteral("exportMenu")),
                   file(QStringLiteral("menu-export"))));
    check(saveMenu(window, window.findChild<QMenu*>(QStringLiteral("stepMenu")),
                   file(QStringLiteral("menu-step"))));
    const std::pair<const char*, QSize> docks[] = {
        {"cameraBasisDock", {560, 640}},    {"vertexTableDock", {640, 560}},
        {"normalsDock", {560, 660}},        {"projectionDock", {560, 660}},
        {"scanlineDock", {560, 720}},       {"zbufferDock", {520, 760}},
        {"pixelInspectorDock", {700, 600}}, {"sceneDock", {380, 450}},
        {"nearClipDock", {620, 700}},       {"trapezoidDock", {560, 760}}};
    window.vertexTableView()->setOnlySelectedTriangle(true);
    for (const auto& [name, size] : docks)
        check(saveDock(dock(window, name), file(QLatin1String(name)), size));
    window.vertexTableView()->setOnlySelectedTriangle(false);
    window.resetLayout();

    // The image zoomed to the pixel grid, stepping pixel by pixel through the middle of a
    // triangle drawn early (on the empty background) and not a sliver: the triangle, its
    // scanline, span, edge crossings and samples drawn over.
    {
        std::uint32_t chosen = 0, most = 0;
        const std::size_t early = std::max<std::size_t>(1, replay->triangleCount() / 10);
        for (std::uint32_t t = 0; t < early; ++t) {
            std::uint32_t fragments = 0, rows = 0, widest = 0;
            for (std::uint32_t r = replay->firstRow(t); r < replay->endRow(t); ++r) {
                const rl::ReplayRow& row = replay->rows()[r];
                if (row.empty()) continue;
                ++rows;
                fragments += row.fragmentEnd - row.fragmentBegin;
                widest = std::max<std::uint32_t>(widest, row.xEnd - row.xBegin);
            }
            const bool fat = rows >= 5 && widest >= 5 && fragments * 2 >= rows * widest;
            if (fat && fragments > most) {
                most = fragments;
                chosen = t;
            }
        }
        const std::uint32_t first = replay->rows()[replay->firstRow(chosen)].fragmentBegin;
        const std::uint32_t middle = first + most / 2;
        inspection->setGranularity(rl::StepGranularity::Pixel);
        inspection->seek(replay->atFragment(middle + 1));
        // A pixel of this triangle tested two rows before, picked.
        for (std::uint32_t i = middle; i > first; --i) {
            const rl::ReplayFragment& f = replay->fragments()[i];
            if (f.y + 2 <= replay->fragments()[middle].y) {
                inspection->pickPixel(QPoint(f.x, f.y));
                break;
            }
        }
        FrameImageView* view = window.imageView();
        QRectF box;
        if (const auto& t = view->overlay().currentTriangle)
            box = QPolygonF(QList<QPointF>(t->begin(), t->end())).boundingRect();
        box.adjust(-1.0, -1.0, 1.0, 1.0);
        const QSize crop(620, 420);
        check(saveZoomed(view, box, QSizeF(crop) * 0.85, 10.0, crop,
                         file(QStringLiteral("image-stepping"))));
    }

    // A breakpoint: the first depth rejection at a pixel where a fragment is rejected.
    inspection->setGranularity(rl::StepGranularity::Scanline);
    for (const rl::ReplayFragment& f : replay->fragments())
        if (f.verdict == rl::FragmentVerdict::Rejected) {
            inspection->pickPixel(QPoint(f.x, f.y));
            break;
        }
    window.breakpointsView()->add(rl::Breakpoint::Kind::Triangle, 2000);
    window.breakpointsView()->add(rl::Breakpoint::Kind::DepthRejection, 0);
    inspection->toStart();
    inspection->continueToBreakpoint();
    check(saveDock(dock(window, "breakpointsDock"), file(QStringLiteral("breakpoints")),
                   QSize(380, 300)));
    window.breakpointsView()->clear();
    inspection->toEnd();

    // A bad object file: the message names the place; the scene stays.
    {
        const QDir dir(QDir::temp().filePath(QStringLiteral("rasterlab-guide")));
        dir.mkpath(QStringLiteral("."));
        QFile original(ufpe + QStringLiteral("calice2.byu"));
        QFile bad(dir.filePath(QStringLiteral("calice2.byu")));
        if (!original.open(QIODevice::ReadOnly) || !bad.open(QIODevice::WriteOnly)) return 1;
        QList<QByteArray> lines = original.readAll().split('\n');
        if (lines.size() > 3) lines[3].replace(QByteArray("409.537"), QByteArray("4l09.537"));
        bad.write(lines.join('\n'));
        bad.close();
        window.openPath(bad.fileName());
        bad.remove();
        QDir(dir).removeRecursively();
        check(saveDock(dock(window, "messagesDock"), file(QStringLiteral("messages-error")),
                       QSize(1240, 110)));
    }

    // Live editing: ka = 0 takes the ambient term away; the pixels the light does not reach
    // turn black. The pixel inspector says why.
    std::shared_ptr<const rl::FrameTrace> before = inspection->frame();
    window.editPanel()->spinBox(SceneDocument::Field::Ka)->setValue(0.0);
    if (!waitForNewFrame(window, before)) return 1;
    replay = inspection->replay();
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

    // In front of a class: ka back to 1 (Undo), the highlight picked, stepped by scanline to
    // the middle of the frame.
    before = inspection->frame();
    window.editPanel()->undoStack()->undo();
    if (!waitForNewFrame(window, before)) return 1;
    replay = inspection->replay();
    window.resetLayout();
    inspection->pickPixel(brightest);
    inspection->setGranularity(rl::StepGranularity::Scanline);
    inspection->seek(
        replay->next(replay->atFragment(static_cast<std::uint32_t>(replay->fragments().size() / 2)),
                     rl::StepGranularity::Scanline));
    window.setPresentationMode(true);
    QTest::qWait(50);
    zoomTo(window.imageView(), QRectF(objectBox), QSizeF(window.imageView()->size()) * 0.92, 0.1);
    {
        QEvent leave(QEvent::Leave);  // the mouse gone: no pixel read out in the status bar
        QCoreApplication::sendEvent(window.imageView(), &leave);
    }
    check(save(&window, file(QStringLiteral("presentation"))));
    window.setPresentationMode(false);

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

    // The lecture slides' lighting on calice2: an attenuated spot on the foot and a dim red
    // directional light; Blinn-Phong highlights. The brightest pixel (in the spot) picked.
    {
        QTemporaryDir lights;
        const QString path = lights.filePath(QStringLiteral("spot.txt"));
        QFile text(path);
        if (!text.open(QIODevice::WriteOnly)) return 1;
        text.write(
            "Iamb = 30 30 30\nKa = 0.5\nKd = 1 1 1\nOd = 0 0.8 0\nKs = 0.5\neta = 8\n"
            "Il = 255 255 255\nPl = 0 250 800\natten = 1 0.0005 0\nspot_dir = 60 130 -800\n"
            "spot_cutoff = 6\nspot_exp = 8\nPl2 = -1 0 0.3 0\nIl2 = 120 40 40\nblinn = 1\n");
        text.close();
        before = inspection->frame();
        if (!window.openPath(path) || !waitForNewFrame(window, before)) return 1;
        if (!waitForReplay(window)) return 1;
        const QImage lit = window.currentImage();
        QPoint spot(0, 0);
        for (int y = 0, most = -1; y < lit.height(); ++y)
            for (int x = 0; x < lit.width(); ++x) {
                const QColor c = lit.pixelColor(x, y);
                if (c.green() > most) {
                    most = c.green();
                    spot = QPoint(x, y);
                }
            }
        inspection->pickPixel(spot);
        inspection->seek(window.inspection()->replay()->end());
        zoomTo(window.imageView(), QRectF(objectBox), QSizeF(window.imageView()->size()) * 0.92,
               0.1);
        check(save(&window, file(QStringLiteral("window-lighting"))));
        check(saveDock(dock(window, "pixelInspectorDock"),
                       file(QStringLiteral("inspector-lighting")), QSize(760, 900)));
        check(saveDock(dock(window, "editDock"), file(QStringLiteral("edit-lights")),
                       QSize(380, 1100)));

        // Seed 004's painter's algorithm on the same scene, beside the z-buffer.
        before = inspection->frame();
        window.setShading(rl::ShadingModel::Painter);
        if (!waitForNewFrame(window, before)) return 1;
        {
            auto* painter = window.findChild<PainterView*>();
            dock(window, "painterDock")->raise();
            QTest::qWait(50);
            for (FrameImageView* view : {painter->painterImageView(), painter->zBufferImageView()})
                zoomTo(view, QRectF(objectBox), QSizeF(view->size()) * 0.95, 0.1);
        }
        check(saveDock(dock(window, "painterDock"), file(QStringLiteral("painter")),
                       QSize(1200, 620)));
        before = inspection->frame();
        window.setShading(rl::ShadingModel::Phong);
        if (!waitForNewFrame(window, before)) return 1;
    }

    // A command file: no course camera, nothing lit; three stages skipped.
    if (!window.openPath(samples + QStringLiteral("/hw2/hw2depth.txt"))) return 1;
    if (!waitForReplay(window)) return 1;
    {
        const QRect strip = window.findChild<QToolBar*>(QStringLiteral("stageToolBar"))->geometry();
        check(save(&window, file(QStringLiteral("strip-command-file")),
                   QRect(0, strip.top(), std::min(window.width(), 1100), strip.height())));
    }
    return failures == 0 ? 0 : 1;
}
