// The main window's menus and their actions: File, Edit, View, Step, Shading and Help, and
// the keys a presentation clicker sends.
#include <QActionGroup>
#include <QCoreApplication>
#include <QDesktopServices>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QMenuBar>
#include <QSettings>
#include <QToolBar>
#include <QUrl>

#include "app/install_paths.h"
#include "app/window/edit_panel.h"
#include "app/window/main_window.h"
#include "pipeline/io/course_readers.h"
#include "views/frame_image_view.h"
#include "views/messages/pipeline_messages.h"
#include "views/stage_strip.h"
#include "views/stepping_bar.h"

namespace rasterlab {

namespace {

// A layout's description as a menu label ("detected" is translated; the layouts' own
// names, such as "UFRPE (N; V; d; hx; hy; C)", are file formats and stay as they are).
QString layoutLabel(const char* description) {
    const QString text = QString::fromUtf8(description);
    return text.startsWith(QStringLiteral("detected")) ? MainWindow::tr("Detect from the file")
                                                       : text;
}

}  // namespace

void MainWindow::createActions() {
    createFileMenu();
    createEditMenu();
    createViewMenu();
    createStepMenu();
    createShadingMenu();
    createHelpMenu();
    refreshRecentMenu();
}

void MainWindow::createFileMenu() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open = file->addAction(tr("&Open..."), this, &MainWindow::openDialog);
    open->setShortcut(QKeySequence::Open);
    open->setObjectName(QStringLiteral("openAction"));
    open->setToolTip(tr("A course camera, lighting or object file, or a command file"));
    QAction* openObject = file->addAction(tr("Open O&bject..."), this,
                                          [this] { openPartDialog(SceneDocument::Part::Object); });
    openObject->setShortcut(QKeySequence(tr("Ctrl+Shift+B")));
    openObject->setObjectName(QStringLiteral("openObjectAction"));
    QAction* openCamera = file->addAction(tr("Open &Camera..."), this,
                                          [this] { openPartDialog(SceneDocument::Part::Camera); });
    openCamera->setShortcut(QKeySequence(tr("Ctrl+Shift+C")));
    QAction* openLighting = file->addAction(
        tr("Open &Lighting..."), this, [this] { openPartDialog(SceneDocument::Part::Lighting); });
    openLighting->setShortcut(QKeySequence(tr("Ctrl+Shift+L")));
    QAction* openCommands =
        file->addAction(tr("Open Command &File..."), this, &MainWindow::openCommandFileDialog);
    openCommands->setShortcut(QKeySequence(tr("Ctrl+Shift+O")));
    openCommands->setObjectName(QStringLiteral("openCommandFileAction"));
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    m_recentMenu->setObjectName(QStringLiteral("recentMenu"));
    file->addAction(tr("&Default Scene"), this, [this] {
        if (!m_edit->maybeSave(this)) return;
        if (auto status = m_document.loadDefault(); !status) {
            showError(translated(status.error()));
        } else {
            leaveLesson();
            m_lastError.clear();
        }
        documentChanged();
    });
    file->addSeparator();
    addLessonMenus(file);
    file->addSeparator();
    addLayoutMenus(file);
    file->addSeparator();
    file->addAction(m_edit->saveAction());
    file->addAction(m_edit->saveAsAction());
    file->addSeparator();
    addExportMenu(file);
    QAction* compare =
        file->addAction(tr("Compare with &Image..."), this, &MainWindow::compareDialog);
    compare->setObjectName(QStringLiteral("compareImageAction"));
    compare->setToolTip(
        tr("A PNG of your own renderer against this scene's render, with the "
           "likely mistakes"));
    QAction* check = file->addAction(tr("Check My &Renderer..."), this, &MainWindow::showCheckDock);
    check->setObjectName(QStringLiteral("checkRendererAction"));
    check->setToolTip(tr("Your own renderer's stages, each held to the lecture's over the "
                         "stage protocol"));
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);
}

// The layouts course files are read in: detected, or one chosen by hand.
void MainWindow::addLayoutMenus(QMenu* file) {
    QMenu* formats = file->addMenu(tr("Course File La&youts"));
    formats->setObjectName(QStringLiteral("layoutMenu"));
    QMenu* cameraFormats = formats->addMenu(tr("&Camera"));
    auto* cameraGroup = new QActionGroup(cameraFormats);
    for (rl::CameraLayout layout : rl::kCameraLayouts) {
        QAction* action =
            cameraFormats->addAction(layoutLabel(rl::cameraLayoutDescription(layout)));
        action->setCheckable(true);
        action->setChecked(layout == m_document.cameraLayout());
        action->setObjectName(QStringLiteral("cameraLayout_") +
                              QString::fromUtf8(rl::cameraLayoutName(layout)));
        cameraGroup->addAction(action);
        connect(action, &QAction::triggered, this, [this, layout] { setCameraLayout(layout); });
    }
    QMenu* lightingFormats = formats->addMenu(tr("&Lighting"));
    auto* lightingGroup = new QActionGroup(lightingFormats);
    for (rl::LightingLayout layout : rl::kLightingLayouts) {
        QAction* action =
            lightingFormats->addAction(layoutLabel(rl::lightingLayoutDescription(layout)));
        action->setCheckable(true);
        action->setChecked(layout == m_document.lightingLayout());
        action->setObjectName(QStringLiteral("lightingLayout_") +
                              QString::fromUtf8(rl::lightingLayoutName(layout)));
        lightingGroup->addAction(action);
        connect(action, &QAction::triggered, this, [this, layout] { setLightingLayout(layout); });
    }
}

// Export PNG, and the other exports in a submenu.
void MainWindow::addExportMenu(QMenu* file) {
    QAction* exportAction = file->addAction(tr("&Export PNG..."), this, &MainWindow::exportDialog);
    exportAction->setShortcut(QKeySequence(tr("Ctrl+E")));
    exportAction->setObjectName(QStringLiteral("exportAction"));
    QMenu* exports = file->addMenu(tr("Export &More"));
    exports->setObjectName(QStringLiteral("exportMenu"));
    QAction* exportShown =
        exports->addAction(tr("Image as &Displayed..."), this, &MainWindow::exportDisplayedDialog);
    exportShown->setShortcut(QKeySequence(tr("Ctrl+Shift+E")));
    m_alwaysActions << exportAction << exportShown;
    exports->addAction(tr("&Colour Buffer at the Cursor..."), this,
                       [this] { exportBufferDialog(0); });
    exports->addAction(tr("D&epth Buffer at the Cursor..."), this,
                       [this] { exportBufferDialog(1); });
    exports->addAction(tr("&Normal Buffer..."), this, [this] { exportBufferDialog(2); });
    m_exportViewMenu = exports->addMenu(tr("A &View as Displayed"));
    for (QDockWidget* dock : findChildren<QDockWidget*>()) {
        m_exportViewMenu->addAction(dock->windowTitle(), this, [this, dock] {
            const QString path = QFileDialog::getSaveFileName(
                this, tr("Export View"), dock->objectName() + QStringLiteral(".png"),
                tr("PNG images (*.png)"));
            if (!path.isEmpty()) exportDock(dock->objectName(), path);
        });
    }
    QAction* sideBySide = exports->addAction(tr("Shading Side &by Side..."), this, [this] {
        const QString path = QFileDialog::getSaveFileName(
            this, tr("Export Shading Side by Side"), QStringLiteral("shading.png"),
            tr("PNG images (*.png)"));
        if (!path.isEmpty()) exportShadingSideBySide(path);
    });
    sideBySide->setObjectName(QStringLiteral("exportShadingAction"));
    exports->addAction(tr("&Stepping Sequence..."), this, &MainWindow::exportSequenceDialog);
    QAction* exportFrames =
        exports->addAction(tr("&Animation Frames..."), this, &MainWindow::exportAnimationDialog);
    exportFrames->setObjectName(QStringLiteral("exportAnimationAction"));
}

void MainWindow::createEditMenu() {
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(m_edit->undoAction());
    edit->addAction(m_edit->redoAction());
}

void MainWindow::createViewMenu() {
    QMenu* view = menuBar()->addMenu(tr("&View"));
    // The image's zoom (the wheel zooms it too); Ctrl++, Ctrl+- and Ctrl+0 are the text's.
    QMenu* image = view->addMenu(tr("Image &Zoom"));
    image->setObjectName(QStringLiteral("imageZoomMenu"));
    QAction* fit = image->addAction(tr("&Fit to Window"), m_view, &FrameImageView::fitToWindow);
    fit->setShortcut(QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_0));
    fit->setObjectName(QStringLiteral("imageFitAction"));
    QAction* actual =
        image->addAction(tr("&Actual Size"), m_view, &FrameImageView::zoomToActualSize);
    actual->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_1));
    QAction* zoomIn = image->addAction(tr("Zoom &In"), m_view, &FrameImageView::zoomIn);
    zoomIn->setShortcuts({QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_Plus),
                          QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_Equal)});
    zoomIn->setObjectName(QStringLiteral("imageZoomInAction"));
    QAction* zoomOut = image->addAction(tr("Zoom &Out"), m_view, &FrameImageView::zoomOut);
    zoomOut->setShortcut(QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_Minus));
    zoomOut->setObjectName(QStringLiteral("imageZoomOutAction"));
    m_alwaysActions << fit << actual << zoomIn << zoomOut;
    addTeachingActions(view);
    view->addSeparator();
    QMenu* panels = view->addMenu(tr("Pa&nels"));
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        panels->addAction(dock->toggleViewAction());
    for (QToolBar* bar : findChildren<QToolBar*>()) panels->addAction(bar->toggleViewAction());
    QAction* reset = view->addAction(tr("Reset &Layout"), this, &MainWindow::resetLayout);
    reset->setObjectName(QStringLiteral("resetLayoutAction"));
    m_fillAction = view->addAction(tr("Fill the &Window with a Panel"));
    m_fillAction->setObjectName(QStringLiteral("fillWindowAction"));
    m_fillAction->setCheckable(true);
    m_fillAction->setShortcut(QKeySequence(Qt::Key_F11));
    m_fillAction->setToolTip(tr("The panel with the focus or under the mouse (the image, from the "
                                "image) over the whole window; again, the layout back"));
    connect(m_fillAction, &QAction::triggered, this, [this] { toggleFill(); });
    view->addSeparator();
    // The images a command file names (its png commands): one is shown at a time.
    m_imageMenu = view->addMenu(tr("I&mage"));
    m_imageMenu->setObjectName(QStringLiteral("imageMenu"));
    view->addSeparator();
    m_presentationAction = view->addAction(tr("&Presentation Mode"));
    m_presentationAction->setObjectName(QStringLiteral("presentationAction"));
    m_presentationAction->setCheckable(true);
    m_presentationAction->setShortcut(QKeySequence(Qt::Key_F5));
    m_presentationAction->setToolTip(
        tr("Larger text, thicker overlays, high contrast; the clicker's keys step (F5 or Esc)"));
    connect(m_presentationAction, &QAction::toggled, this, &MainWindow::setPresentationMode);
    m_lectureAction = view->addAction(tr("&Lecture Layout"));
    m_lectureAction->setObjectName(QStringLiteral("lectureLayoutAction"));
    m_lectureAction->setCheckable(true);
    m_lectureAction->setChecked(m_lectureLayout);
    m_lectureAction->setShortcut(QKeySequence(Qt::Key_F7));
    m_lectureAction->setToolTip(
        tr("In presentation mode, the stage being stepped fills the screen, the image beside "
           "it once something is drawn; off, your own layout (F7)"));
    connect(m_lectureAction, &QAction::toggled, this, &MainWindow::setLectureLayout);
    m_liveEditsAction = view->addAction(tr("Live &Edits in Presentation"));
    m_liveEditsAction->setObjectName(QStringLiteral("liveEditsAction"));
    m_liveEditsAction->setCheckable(true);
    m_liveEditsAction->setShortcut(QKeySequence(Qt::Key_F9));
    m_liveEditsAction->setToolTip(
        tr("The Edit panel stays on screen in presentation mode: the light and the material "
           "change in front of the class (F9)"));
    connect(m_liveEditsAction, &QAction::toggled, this, &MainWindow::setLiveEdits);
    m_alwaysActions << m_fillAction << m_presentationAction << m_lectureAction
                    << m_liveEditsAction;
    auto* leave = new QAction(this);
    leave->setShortcut(QKeySequence(Qt::Key_Escape));
    connect(leave, &QAction::triggered, this, [this] { setPresentationMode(false); });
    addAction(leave);
    addLanguageMenu(view);
}

// View > Text Size: the docks' text and numbers, larger for the back of the room.
void MainWindow::addTeachingActions(QMenu* view) {
    QMenu* text = view->addMenu(tr("&Text Size"));
    text->setObjectName(QStringLiteral("textSizeMenu"));
    QAction* larger = text->addAction(tr("&Larger"), this, [this] { zoomText(1); });
    larger->setShortcuts({QKeySequence::ZoomIn, QKeySequence(Qt::CTRL | Qt::Key_Equal)});
    larger->setObjectName(QStringLiteral("textLargerAction"));
    QAction* smaller = text->addAction(tr("&Smaller"), this, [this] { zoomText(-1); });
    smaller->setShortcut(QKeySequence::ZoomOut);
    smaller->setObjectName(QStringLiteral("textSmallerAction"));
    QAction* normal = text->addAction(tr("&Normal Size"), this, [this] { setTextZoom(1.0); });
    normal->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_0));
    normal->setObjectName(QStringLiteral("textNormalAction"));
    m_alwaysActions << larger << smaller << normal;
}

void MainWindow::addLanguageMenu(QMenu* view) {
    QMenu* language = view->addMenu(tr("Lan&guage"));
    language->setObjectName(QStringLiteral("languageMenu"));
    auto* languages = new QActionGroup(language);
    const QString current = QSettings().value(QStringLiteral("language"), QString()).toString();
    const std::pair<QString, QString> choices[] = {
        {QString(), tr("The System's")},
        {QStringLiteral("en"), QStringLiteral("English")},
        {QStringLiteral("pt_BR"), QStringLiteral("Portugu\u00eas (Brasil)")}};
    for (const auto& [code, label] : choices) {
        QAction* action = language->addAction(label);
        action->setCheckable(true);
        action->setChecked(code == current);
        action->setObjectName(QStringLiteral("language_") +
                              (code.isEmpty() ? QStringLiteral("system") : code));
        languages->addAction(action);
        connect(action, &QAction::triggered, this, [this, code = code] {
            if (!QCoreApplication::organizationName().isEmpty())
                QSettings().setValue(QStringLiteral("language"), code);
            emit languageChangeRequested(code);
        });
    }
}

void MainWindow::createStepMenu() {
    QMenu* step = menuBar()->addMenu(tr("S&tep"));
    step->setObjectName(QStringLiteral("stepMenu"));
    step->addAction(m_steppingBar->toStartAction());
    step->addAction(m_steppingBar->stepBackAction());
    step->addAction(m_steppingBar->playAction());
    step->addAction(m_steppingBar->stepForwardAction());
    step->addAction(m_steppingBar->toEndAction());
    step->addAction(m_steppingBar->continueAction());
    step->addSeparator();
    QMenu* granularity = step->addMenu(tr("Step B&y"));
    for (QAction* a : m_steppingBar->granularityActions()) granularity->addAction(a);
    QMenu* stages = step->addMenu(tr("S&tage"));
    for (rl::StageId stage : rl::kAllStages) {
        const int n = static_cast<int>(stage) + 1;
        QAction* a =
            stages->addAction(QStringLiteral("&%1 %2").arg(n).arg(StageStrip::stageName(stage)));
        a->setShortcut(QKeySequence(Qt::ALT | (Qt::Key_0 + n)));
        connect(a, &QAction::triggered, this, [this, stage] { m_inspection->setStage(stage); });
    }
    addClickerKeys();
    for (QAction* a : {m_steppingBar->toStartAction(), m_steppingBar->stepBackAction(),
                       m_steppingBar->playAction(), m_steppingBar->stepForwardAction(),
                       m_steppingBar->toEndAction(), m_steppingBar->continueAction()})
        m_alwaysActions << a;
    QAction* goTo = step->addAction(tr("Pick the Pixel Under the &Mouse"));
    goTo->setShortcut(QKeySequence(tr("Ctrl+G")));
    connect(goTo, &QAction::triggered, this, [this] {
        const QPoint p = m_view->pixelAt(m_view->mapFromGlobal(QCursor::pos()));
        if (p.x() >= 0) m_inspection->pickPixel(p);
    });
}

// The keys a presentation clicker sends (arrows, space): on the image, or everywhere in
// presentation mode (updateClickerKeys).
void MainWindow::addClickerKeys() {
    const std::pair<QKeySequence, QAction*> clicker[] = {
        {QKeySequence(Qt::Key_Right), m_steppingBar->stepForwardAction()},
        {QKeySequence(Qt::Key_Down), m_steppingBar->stepForwardAction()},
        {QKeySequence(Qt::Key_Left), m_steppingBar->stepBackAction()},
        {QKeySequence(Qt::Key_Up), m_steppingBar->stepBackAction()},
        {QKeySequence(Qt::Key_Space), m_steppingBar->playAction()},
        {QKeySequence(Qt::Key_Home), m_steppingBar->toStartAction()},
        {QKeySequence(Qt::Key_End), m_steppingBar->toEndAction()},
    };
    for (const auto& [key, target] : clicker) {
        auto* a = new QAction(this);
        a->setShortcut(key);
        connect(a, &QAction::triggered, target, &QAction::trigger);
        m_clickerActions.append(a);
    }
    updateClickerKeys();
}

void MainWindow::createShadingMenu() {
    QMenu* shading = menuBar()->addMenu(tr("&Shading"));
    m_shadingMenu = shading;
    m_shadingGroup = new QActionGroup(this);
    const std::pair<rl::ShadingModel, QString> models[] = {
        {rl::ShadingModel::Phong, tr("&Phong (per pixel)")},
        {rl::ShadingModel::Gouraud, tr("&Gouraud (per vertex)")},
        {rl::ShadingModel::Flat, tr("&Flat (per triangle)")},
        {rl::ShadingModel::Painter, tr("P&ainter's algorithm (flat, far to near, no depth test)")},
    };
    int key = 1;
    for (const auto& [model, label] : models) {
        QAction* action = shading->addAction(label);
        action->setCheckable(true);
        action->setChecked(model == m_document.settings().shading);
        action->setShortcut(QKeySequence(Qt::ALT | Qt::SHIFT | (Qt::Key_0 + key++)));
        action->setData(static_cast<int>(model));
        m_shadingGroup->addAction(action);
        connect(action, &QAction::triggered, this, [this, model = model] { setShading(model); });
    }
    shading->addSeparator();
    addRulesMenu(shading);
    addProjectionMenu(shading);
}

void MainWindow::addRulesMenu(QMenu* shading) {
    QMenu* rules = shading->addMenu(tr("&Rasterization Rules"));
    rules->setObjectName(QStringLiteral("rulesMenu"));
    m_rulesMenu = rules;
    m_rulesGroup = new QActionGroup(this);
    const std::pair<rl::RuleSet, QString> ruleSets[] = {
        {rl::RuleSet::Course, tr("&Course (seed 000: whole-pixel vertices, screen-space "
                                 "interpolation)")},
        {rl::RuleSet::Gpu, tr("&GPU-like (1/256-pixel vertices, pixel centres, top-left rule, "
                              "perspective-correct)")},
        {rl::RuleSet::Hw2, tr("&HW2 (seed 001's reference images)")},
    };
    for (const auto& [set, label] : ruleSets) {
        QAction* action = rules->addAction(label);
        action->setCheckable(true);
        action->setChecked(rl::ruleSetOf(m_document.settings().rules) == set);
        action->setData(static_cast<int>(set));
        action->setObjectName(QStringLiteral("rules_%1").arg(QLatin1String(rl::ruleSetName(set))));
        m_rulesGroup->addAction(action);
        connect(action, &QAction::triggered, this, [this, set = set] { setRules(set); });
    }
}

void MainWindow::addProjectionMenu(QMenu* shading) {
    QMenu* projection = shading->addMenu(tr("Pro&jection"));
    projection->setObjectName(QStringLiteral("projectionMenu"));
    m_projectionGroup = new QActionGroup(this);
    const std::pair<rl::NearPlane::Mode, QString> modes[] = {
        {rl::NearPlane::Mode::Clip,
         tr("&Clip at the Near Plane (nothing behind the eye is divided)")},
        {rl::NearPlane::Mode::Naive,
         tr("&Plain Divide, No Clipping (seed 000 as written; seed 001's HW2)")},
        {rl::NearPlane::Mode::SameSide,
         tr("&Same Side (clip only triangles that cross the eye plane)")},
    };
    for (const auto& [mode, label] : modes) {
        QAction* action = projection->addAction(label);
        action->setCheckable(true);
        action->setChecked(m_document.projection() == mode);
        action->setData(static_cast<int>(mode));
        action->setObjectName(QStringLiteral("projection_%1").arg(static_cast<int>(mode)));
        m_projectionGroup->addAction(action);
        connect(action, &QAction::triggered, this, [this, mode = mode] { setProjection(mode); });
    }
}

void MainWindow::createHelpMenu() {
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* keys = help->addAction(tr("&Keyboard Shortcuts"), this, &MainWindow::showShortcuts);
    keys->setShortcut(QKeySequence::HelpContents);
    // The user guide in the interface's language, where the program's files are
    // (install_paths.h): disabled, saying why, when it is not there.
    const QString guide = userGuide(QLocale().name());
    QAction* guideAction = help->addAction(tr("&User Guide"), this, [guide] {
        QDesktopServices::openUrl(QUrl::fromLocalFile(guide));
    });
    guideAction->setObjectName(QStringLiteral("userGuideAction"));
    guideAction->setData(guide);
    guideAction->setEnabled(!guide.isEmpty());
    guideAction->setStatusTip(guide.isEmpty() ? tr("The user guide is not installed")
                                              : QDir::toNativeSeparators(guide));
    help->addAction(tr("&About RasterLab"), this, &MainWindow::about);
}

}  // namespace rasterlab
