#include "main_window.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QFrame>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QTextBrowser>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

#include "app/documents/examples.h"
#include "app/image_io.h"
#include "app/install_paths.h"
#include "app/window/accuracy_panel.h"
#include "app/window/animation_panel.h"
#include "app/window/compare_panel.h"
#include "app/window/edit_panel.h"
#include "app/window/replay_builder.h"
#include "pipeline/stages/camera_basis.h"
#include "views/breakpoints_view.h"
#include "views/camera_basis_view.h"
#include "views/frame_image_view.h"
#include "views/messages/pipeline_messages.h"
#include "views/near_clip_view.h"
#include "views/normals_view.h"
#include "views/on_screen.h"
#include "views/painter_view.h"
#include "views/pixel_inspector.h"
#include "views/projection_view.h"
#include "views/scanline_view.h"
#include "views/stage_strip.h"
#include "views/stepping_bar.h"
#include "views/trapezoid_view.h"
#include "views/vertex_table.h"
#include "views/zbuffer_view.h"

namespace rasterlab {

namespace {

// How long after the last edit frames still count as part of a drag (onFrameReady).
constexpr int kEditPauseMs = 150;

QString partTitle(SceneDocument::Part part) {
    switch (part) {
        case SceneDocument::Part::Camera:
            return MainWindow::tr("Open Camera");
        case SceneDocument::Part::Lighting:
            return MainWindow::tr("Open Lighting");
        case SceneDocument::Part::Object:
            return MainWindow::tr("Open Object");
    }
    return {};
}

QString partFilter(SceneDocument::Part part) {
    switch (part) {
        case SceneDocument::Part::Camera:
            return MainWindow::tr("Camera files (*.cfg *.txt);;All files (*)");
        case SceneDocument::Part::Lighting:
            return MainWindow::tr("Lighting files (*.txt *.lux);;All files (*)");
        case SceneDocument::Part::Object:
            return MainWindow::tr("Objects (*.byu *.txt);;All files (*)");
    }
    return {};
}

// A shading model's name as people read it, translated.
QString shadingLabel(rl::ShadingModel model) {
    switch (model) {
        case rl::ShadingModel::Flat:
            return MainWindow::tr("flat");
        case rl::ShadingModel::Gouraud:
            return MainWindow::tr("Gouraud");
        case rl::ShadingModel::Phong:
            return MainWindow::tr("Phong");
        case rl::ShadingModel::Painter:
            return MainWindow::tr("painter's-algorithm flat");  // "..., %5 shading"
    }
    return {};
}

QString displayName(const QString& source) {
    if (const std::optional<QString> example = exampleOfPath(source))
        return MainWindow::tr("%1 (the %2 example)").arg(QFileInfo(source).fileName(), *example);
    if (source.startsWith(QStringLiteral(":/")))
        return MainWindow::tr("%1 (built in)").arg(QFileInfo(source).fileName());
    return QFileInfo(source).fileName();
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setObjectName(QStringLiteral("MainWindow"));
    setWindowTitle(tr("RasterLab"));
    setAcceptDrops(true);
    m_normalFont = QApplication::font();
    m_normalPalette = QApplication::palette();
    m_inspection = new Inspection(this);
    m_inspection->setWindowScalesText(true);  // setPresentationMode enlarges every text
    // The image, below a bar that shows only when clipping has left nothing to draw.
    auto* central = new QWidget(this);
    auto* centralLayout = new QVBoxLayout(central);
    centralLayout->setContentsMargins(0, 0, 0, 0);
    centralLayout->setSpacing(0);
    m_behindBanner = new QFrame(central);
    m_behindBanner->setObjectName(QStringLiteral("behindBanner"));
    m_behindBanner->setAutoFillBackground(true);
    QPalette bannerPalette = m_behindBanner->palette();
    bannerPalette.setColor(QPalette::Window, QColor(255, 243, 205));
    bannerPalette.setColor(QPalette::WindowText, QColor(60, 45, 0));
    m_behindBanner->setPalette(bannerPalette);
    auto* bannerLayout = new QHBoxLayout(m_behindBanner);
    m_behindText = new QLabel(m_behindBanner);
    m_behindText->setWordWrap(true);
    m_behindButton = new QPushButton(tr("Draw with the Plain Divide"), m_behindBanner);
    m_behindButton->setObjectName(QStringLiteral("plainDivideButton"));
    connect(m_behindButton, &QPushButton::clicked, this,
            [this] { setProjection(rl::NearPlane::Mode::Naive); });
    bannerLayout->addWidget(m_behindText, 1);
    bannerLayout->addWidget(m_behindButton);
    m_behindBanner->setVisible(false);
    m_view = new FrameImageView(central);
    m_view->setObjectName(QStringLiteral("imageView"));
    centralLayout->addWidget(m_behindBanner);
    centralLayout->addWidget(m_view, 1);
    setCentralWidget(central);
    m_controller = new RenderController(this);
    m_replayBuilder = new ReplayBuilder(this);
    connect(m_controller, &RenderController::frameReady, this, &MainWindow::onFrameReady);
    connect(m_controller, &RenderController::failed, this, &MainWindow::onRenderFailed);
    connect(m_controller, &RenderController::busyChanged, this, &MainWindow::updateTimeLabel);
    connect(m_controller, &RenderController::busyChanged, this, &MainWindow::updateBusy);
    connect(m_replayBuilder, &ReplayBuilder::busyChanged, this, &MainWindow::updateBusy);
    connect(m_replayBuilder, &ReplayBuilder::built, this, &MainWindow::onReplayBuilt);
    connect(m_replayBuilder, &ReplayBuilder::failed, this,
            [this](std::shared_ptr<const rl::FrameTrace> frame, const QString& message) {
                if (frame == m_inspection->frame()) m_inspection->setReplayError(message);
            });
    connect(m_view, &FrameImageView::pixelHovered, this, &MainWindow::onPixelHovered);
    connect(m_view, &FrameImageView::pixelPicked, m_inspection, &Inspection::pickPixel);
    connect(m_inspection, &Inspection::cursorChanged, this, &MainWindow::onCursorChanged);
    connect(m_inspection, &Inspection::selectionChanged, this, &MainWindow::updateOverlay);
    connect(m_inspection, &Inspection::pixelPicked, this, &MainWindow::updateOverlay);
    connect(m_inspection, &Inspection::presentationChanged, this, &MainWindow::updateOverlay);
    connect(m_inspection, &Inspection::stageChanged, this, &MainWindow::showStageView);
    connect(m_inspection, &Inspection::stageChanged, this, &MainWindow::updateOverlay);
    connect(m_inspection, &Inspection::replayChanged, this, &MainWindow::updateBusy);
    connect(m_inspection, &Inspection::breakpointHit, this, [this] {
        statusBar()->showMessage(
            tr("Stopped at a breakpoint: %1").arg(m_inspection->positionText()), 8000);
    });

    createDocks();
    createActions();
    keepKeysFromNumberBoxes();
    // The lecture layout follows the stepping cursor from stage to stage.
    connect(m_inspection, &Inspection::stageChanged, this, &MainWindow::scheduleLectureLayout);
    connect(m_inspection, &Inspection::cursorChanged, this, &MainWindow::scheduleLectureLayout);
    connect(m_inspection, &Inspection::frameChanged, this, &MainWindow::scheduleLectureLayout);
    connect(m_inspection, &Inspection::selectionChanged, this, &MainWindow::scheduleLectureLayout);
    m_adoptTimer.setSingleShot(true);
    m_adoptTimer.setInterval(kEditPauseMs);
    connect(&m_adoptTimer, &QTimer::timeout, this, [this] {
        if (m_waitingFrame) adoptFrame(*m_waitingFrame);
    });
    connect(m_edit, &EditPanel::sceneEdited, this, [this] {
        m_lastEdit.start();
        for (QAction* action : m_shadingGroup->actions())
            action->setChecked(action->data().toInt() ==
                               static_cast<int>(m_document.settings().shading));
        requestRender();
    });
    connect(m_edit, &EditPanel::modifiedChanged, this, &QWidget::setWindowModified);
    connect(m_edit, &EditPanel::saved, this, [this] {
        refreshMessages();
        refreshSceneSummary();
        watchSources();
    });
    m_pixelLabel = new QLabel(this);
    m_pixelLabel->setObjectName(QStringLiteral("pixelLabel"));
    m_timeLabel = new QLabel(this);
    m_busyBar = new QProgressBar(this);
    m_busyBar->setRange(0, 0);  // busy, with no known end
    m_busyBar->setMaximumWidth(120);
    m_busyBar->setMaximumHeight(14);
    m_busyBar->setVisible(false);
    m_cancelButton = new QToolButton(this);
    m_cancelButton->setObjectName(QStringLiteral("cancelButton"));
    m_cancelButton->setText(tr("Cancel"));
    m_cancelButton->setToolTip(tr("Stop preparing the stepping of this frame"));
    m_cancelButton->setVisible(false);
    connect(m_cancelButton, &QToolButton::clicked, this, [this] {
        m_replayBuilder->cancel();
        m_inspection->setReplayError(tr("cancelled"));
        updateBusy();
    });
    // The pixel readout is permanent: temporary messages take the left of the bar.
    statusBar()->addPermanentWidget(m_pixelLabel);
    statusBar()->addPermanentWidget(m_busyBar);
    statusBar()->addPermanentWidget(m_cancelButton);
    statusBar()->addPermanentWidget(m_timeLabel);
    fitToScreen(screen());
    m_defaultLayout = saveState(kLayoutVersion);
    restoreLayout();

    m_reloadTimer.setSingleShot(true);
    m_reloadTimer.setInterval(300);
    connect(&m_watcher, &QFileSystemWatcher::fileChanged, this, &MainWindow::onWatchedFileChanged);
    connect(&m_reloadTimer, &QTimer::timeout, this, &MainWindow::reloadChangedFiles);

    if (auto status = m_document.loadDefault(); !status) showError(translated(status.error()));
    documentChanged();
}

QDockWidget* MainWindow::addDock(const QString& title, const QString& name, QWidget* widget,
                                 Qt::DockWidgetArea area, bool scrolls, const QString& fullTitle) {
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(name);
    // A short title for its tab; the full one in the tab's and the title bar's tooltip.
    m_fullTitles.insert(dock, fullTitle.isEmpty() ? title : fullTitle);
    dock->installEventFilter(this);
    if (!scrolls) {
        dock->setWidget(widget);
    } else {
        // A long column of text and tables scrolls, rather than making the window taller than
        // the screen (large text in presentation mode).
        auto* scroll = new QScrollArea(dock);
        scroll->setObjectName(name + QStringLiteral("Scroll"));
        scroll->setFrameShape(QFrame::NoFrame);
        scroll->setWidgetResizable(true);
        scroll->setWidget(widget);
        dock->setWidget(scroll);
        widget->installEventFilter(this);  // its minimum width may widen the side (fitDocks)
    }
    // A tab brought to the front: its view refreshes if it left a step out while covered.
    connect(dock, &QDockWidget::visibilityChanged, widget, [widget](bool visible) {
        if (!visible) return;
        QEvent raised(kRaisedEvent);
        QCoreApplication::sendEvent(widget, &raised);
    });
    addDockWidget(area, dock);
    return dock;
}

void MainWindow::createDocks() {
    auto* stageBar = new QToolBar(tr("Stages"), this);
    stageBar->setObjectName(QStringLiteral("stageToolBar"));
    m_stageStrip = new StageStrip(m_inspection, stageBar);
    stageBar->addWidget(m_stageStrip);
    addToolBar(Qt::TopToolBarArea, stageBar);
    addToolBarBreak(Qt::TopToolBarArea);
    auto* stepBar = new QToolBar(tr("Stepping"), this);
    stepBar->setObjectName(QStringLiteral("steppingToolBar"));
    m_steppingBar = new SteppingBar(m_inspection, stepBar);
    stepBar->addWidget(m_steppingBar);
    addToolBar(Qt::TopToolBarArea, stepBar);

    m_messages = new QListWidget;
    m_messages->setObjectName(QStringLiteral("messagesList"));
    m_messages->setWordWrap(true);
    QDockWidget* messagesDock = addDock(tr("Messages"), QStringLiteral("messagesDock"), m_messages,
                                        Qt::BottomDockWidgetArea);

    m_summary = new QTextBrowser;
    m_summary->setObjectName(QStringLiteral("sceneSummary"));
    QDockWidget* sceneDock = addDock(tr("Scene"), QStringLiteral("sceneDock"), m_summary,
                                     Qt::BottomDockWidgetArea);
    tabifyDockWidget(messagesDock, sceneDock);
    messagesDock->raise();

    // On the left, what the scene's numbers are and what they make of a pixel: the panels
    // tabbed above the pixel inspector. (A dock is split from another before either is
    // tabbed: split from a tabbed dock, it would join its tabs.)
    m_edit = new EditPanel(&m_document);
    QDockWidget* editDock =
        addDock(tr("Edit"), QStringLiteral("editDock"), m_edit, Qt::LeftDockWidgetArea, true);
    m_inspector = new PixelInspector(m_inspection);
    QDockWidget* inspectorDock =
        addDock(tr("7 Pixel inspector"), QStringLiteral("pixelInspectorDock"), m_inspector,
                Qt::LeftDockWidgetArea, true, tr("7 Pixel inspector (lighting)"));
    splitDockWidget(editDock, inspectorDock, Qt::Vertical);
    m_breakpoints = new BreakpointsView(m_inspection);
    tabifyDockWidget(editDock, addDock(tr("Breakpoints"), QStringLiteral("breakpointsDock"),
                                       m_breakpoints, Qt::LeftDockWidgetArea));
    m_accuracy = new AccuracyPanel;
    tabifyDockWidget(editDock, addDock(tr("Accuracy"), QStringLiteral("accuracyDock"), m_accuracy,
                                       Qt::LeftDockWidgetArea, true));
    m_animation = new AnimationPanel;
    tabifyDockWidget(editDock, addDock(tr("Animation"), QStringLiteral("animationDock"),
                                       m_animation, Qt::LeftDockWidgetArea, true));
    connect(m_animation, &AnimationPanel::changed, this, [this] {
        m_document.setAnimation(m_animation->settings());
        requestRender();
    });
    connect(m_animation, &AnimationPanel::playingChanged, this, &MainWindow::onAnimationPlaying);
    editDock->raise();

    // On the right, the stage views in the lecture's order: the geometry above (stages 1 to
    // 4, and seed 002's clipping), the pixels below (5 and 6, seed 002's trapezoids and seed
    // 004's painter's algorithm). Two tab bars short enough to read on a small screen; each
    // view scrolls when the screen is too low for it.
    const auto stageDock = [this](const QString& title, const char* name, QWidget* view,
                                  const QString& fullTitle = {}) {
        return addDock(title, QLatin1String(name), view, Qt::RightDockWidgetArea, true, fullTitle);
    };
    m_cameraBasis = new CameraBasisView(m_inspection);
    QDockWidget* cameraDock =
        stageDock(tr("1 Camera"), "cameraBasisDock", m_cameraBasis, tr("1 Camera basis"));
    m_scanline = new ScanlineView(m_inspection);
    QDockWidget* scanlineDock =
        stageDock(tr("5 Scan"), "scanlineDock", m_scanline, tr("5 Scan conversion"));
    splitDockWidget(cameraDock, scanlineDock, Qt::Vertical);
    m_vertexTable = new VertexTableView(m_inspection);
    tabifyDockWidget(cameraDock, stageDock(tr("2 View"), "vertexTableDock", m_vertexTable,
                                           tr("2 View coordinates (vertices)")));
    m_normals = new NormalsView(m_inspection);
    tabifyDockWidget(cameraDock, stageDock(tr("3 Normals"), "normalsDock", m_normals));
    m_projection = new ProjectionView(m_inspection);
    tabifyDockWidget(cameraDock, stageDock(tr("4 Projection"), "projectionDock", m_projection));
    // Seed 002's presentations of stages 4 and 5: clipping one triangle step by step, and
    // the scan as trapezoids.
    tabifyDockWidget(cameraDock, stageDock(tr("4b Clipping"), "nearClipDock",
                                           new NearClipView(m_inspection),
                                           tr("4b Near-plane clipping (seed 002)")));
    tabifyDockWidget(scanlineDock, stageDock(tr("5b Trapezoids"), "trapezoidDock",
                                             new TrapezoidView(m_inspection),
                                             tr("5b Trapezoids: the scan of seed 002")));
    m_zbuffer = new ZBufferView;
    tabifyDockWidget(scanlineDock, stageDock(tr("6 Z-buffer"), "zbufferDock", m_zbuffer));
    // Seed 004's painter's algorithm beside the z-buffer (renders only while shown).
    m_painter = new PainterView(m_inspection);
    tabifyDockWidget(scanlineDock, stageDock(tr("Painter"), "painterDock", m_painter,
                                             tr("Painter's algorithm (seed 004)")));
    // A student's image against ours (File > Compare with Image...): hidden until then, and
    // beside the geometry views, the taller of the two groups on the right.
    m_compare = new ComparePanel(m_inspection);
    connect(m_compare, &ComparePanel::useFittedLighting, this,
            [this](const std::vector<ComparePanel::FittedSetting>& fitted) {
                std::vector<EditPanel::Setting> settings;
                for (const auto& f : fitted) settings.push_back({f.field, f.light, f.value});
                m_edit->setValues(settings, tr("Use the Fitted Lighting"));
            });
    m_compare->setCommandFileSource([this] {
        return m_document.showsCommandFile()
                   ? std::pair(m_document.commandFilePath(), m_document.imageIndex())
                   : std::pair(QString(), 0);
    });
    m_compareDock =
        stageDock(tr("Compare"), "compareDock", m_compare, tr("Compare with their image"));
    tabifyDockWidget(cameraDock, m_compareDock);
    m_compareDock->hide();
    setUpCheckDock(editDock);
    cameraDock->raise();
    scanlineDock->raise();
    resizeDocks({messagesDock}, {110}, Qt::Vertical);
}

void MainWindow::updateClickerKeys() {
    const bool presenting = m_inspection->presentation();
    for (QAction* a : m_clickerActions) {
        // Not presenting: the keys step only while the image has the focus (arrows elsewhere
        // move through tables and fields); presenting, they step wherever the focus is.
        removeAction(a);
        m_view->removeAction(a);
        a->setShortcutContext(presenting ? Qt::WindowShortcut : Qt::WidgetWithChildrenShortcut);
        if (presenting)
            addAction(a);
        else
            m_view->addAction(a);
    }
    m_view->setArrowsMovePick(!presenting);
}

double presentationTextScale(int screenHeight) {
    return std::clamp(1.5 * screenHeight / 1080.0, 1.25, 1.5);
}

// The status bar's hint on entering presentation mode.
static QString presentationHint() {
    return MainWindow::tr("Presentation mode: F5 or Esc to leave; Page Down, Right and "
                          "Space step and play");
}

void MainWindow::setPresentationMode(bool on) {
    if (on == m_inspection->presentation()) return;
    restoreFill();  // the layout saved and given back is the whole one
    {
        const QSignalBlocker block(m_presentationAction);
        m_presentationAction->setChecked(on);
    }
    if (on) {
        m_fitDocksBeforePresentation = m_fitDocks;
        m_fitDocks = true;  // the docks sized again for the larger text and the whole screen
        m_wasFullScreen = isFullScreen();
        enterPresentationLayout();
        showFullScreen();
    } else {
        if (!m_wasFullScreen) showNormal();
        leavePresentationLayout();
        m_fitDocks = m_fitDocksBeforePresentation;
    }
    if (on) {
        QFont big = m_normalFont;
        const QScreen* shown = screen();
        big.setPointSizeF(m_normalFont.pointSizeF() *
                          presentationTextScale(shown ? shown->size().height() : 1080));
        QApplication::setFont(big);
        // High contrast: white on black, yellow selection.
        QPalette p;
        p.setColor(QPalette::Window, Qt::black);
        p.setColor(QPalette::WindowText, Qt::white);
        p.setColor(QPalette::Base, QColor(16, 16, 16));
        p.setColor(QPalette::AlternateBase, QColor(40, 40, 40));
        p.setColor(QPalette::Text, Qt::white);
        p.setColor(QPalette::Button, QColor(30, 30, 30));
        p.setColor(QPalette::ButtonText, Qt::white);
        p.setColor(QPalette::Highlight, QColor(255, 220, 0));
        p.setColor(QPalette::HighlightedText, Qt::black);
        p.setColor(QPalette::ToolTipBase, Qt::black);
        p.setColor(QPalette::ToolTipText, Qt::white);
        QApplication::setPalette(p);
        statusBar()->showMessage(presentationHint(), 8000);
    } else {
        // The hint is about presentation mode: it leaves with it.
        if (statusBar()->currentMessage() == presentationHint()) statusBar()->clearMessage();
        QApplication::setFont(m_normalFont);
        QApplication::setPalette(m_normalPalette);
    }
    m_inspection->setPresentation(on);
    applyTextZoom();  // on top of the window's new text size
    updateClickerKeys();
    if (on && lectureLayoutShown()) {
        m_lectureShown = {};
        applyLectureLayout();
    } else if (on) {
        QMetaObject::invokeMethod(this, &MainWindow::fitDocks, Qt::QueuedConnection);
    }
}

void MainWindow::enterPresentationLayout() {
    // In front of a class: the whole screen, the image and the stage views only (the
    // animation's controls too: above the pixel inspector, each had half the height, too
    // little for either in large text).
    static const char* const kSideDocks[] = {"messagesDock",    "editDock",     "sceneDock",
                                             "breakpointsDock", "accuracyDock", "animationDock"};
    m_layoutBeforePresentation = saveState(kLayoutVersion);
    m_hiddenByPresentation.clear();
    for (const char* name : kSideDocks)
        if (auto* dock = findChild<QDockWidget*>(QLatin1String(name)); dock && !dock->isHidden()) {
            m_hiddenByPresentation << dock->objectName();
            dock->hide();
        }
    if (const QScreen* shown = screen(); shown && shown->size().width() < kSidesBesideImageWidth)
        movePixelInspectorRight();
    // Live edits keep the Edit dock on screen.
    if (m_liveEdits)
        if (auto* edit = findChild<QDockWidget*>(QStringLiteral("editDock"))) edit->show();
    keepOwnLayout();
}

void MainWindow::leavePresentationLayout() {
    showLectureCaption(nullptr);
    centralWidget()->show();  // the lecture layout may have given its room to a dock
    restoreState(m_layoutBeforePresentation, kLayoutVersion);
    m_hiddenByPresentation.clear();
    m_lectureShown = {};
}

void MainWindow::movePixelInspectorRight() {
    auto* inspectorDock = findChild<QDockWidget*>(QStringLiteral("pixelInspectorDock"));
    auto* scanDock = findChild<QDockWidget*>(QStringLiteral("scanlineDock"));
    // Only from its own place: a lesson's or a teacher's other arrangement stays.
    if (!inspectorDock || !scanDock || inspectorDock->isFloating() || scanDock->isFloating() ||
        dockWidgetArea(inspectorDock) != Qt::LeftDockWidgetArea ||
        dockWidgetArea(scanDock) != Qt::RightDockWidgetArea)
        return;
    // The tab in front stays in front.
    QDockWidget* front = scanDock;
    for (QDockWidget* dock : tabifiedDockWidgets(scanDock))
        if (!dock->visibleRegion().isEmpty()) front = dock;
    tabifyDockWidget(scanDock, inspectorDock);
    front->raise();
}

void MainWindow::fitToScreen(const QScreen* screen) {
    // Without the bound, a window larger than a 1280x720 screen runs off its edge (a window
    // manager does not always shrink it).
    QSize size(1560, 960);
    if (screen) {
        const QRect free = screen->availableGeometry();
        size = size.boundedTo(free.size() - QSize(16, 48)).expandedTo(minimumSizeHint());
        QRect placed(QPoint(), size);
        placed.moveCenter(free.center());
        move(std::max(placed.left(), free.left()), std::max(placed.top(), free.top()));
    }
    resize(size);
}

void MainWindow::resetLayout() {
    if (isFilled()) {
        centralWidget()->show();
        m_layoutBeforeFill.clear();
        m_filledDock = nullptr;
        m_fillAction->setChecked(false);
    }
    restoreState(m_defaultLayout, kLayoutVersion);
    m_fitDocks = true;
    fitDocks();
}

void MainWindow::saveLayout() const {
    if (QCoreApplication::organizationName().isEmpty()) return;
    QSettings settings;
    settings.setValue(QStringLiteral("layout/version"), kLayoutVersion);
    settings.setValue(QStringLiteral("layout/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("layout/state"), saveState(kLayoutVersion));
}

void MainWindow::restoreLayout() {
    if (QCoreApplication::organizationName().isEmpty()) return;
    const QSettings settings;
    if (settings.value(QStringLiteral("layout/version")).toInt() != kLayoutVersion) return;
    restoreGeometry(settings.value(QStringLiteral("layout/geometry")).toByteArray());
    // The user's layout: kept as it was, not fitted to the window.
    m_fitDocks = !restoreState(settings.value(QStringLiteral("layout/state")).toByteArray(),
                               kLayoutVersion);
}

void MainWindow::adoptDocument(const SceneDocument& document) {
    m_document = document;
    m_animation->setSettings(m_document.animation());
    m_lastError.clear();
    for (QAction* action : m_shadingGroup->actions())
        action->setChecked(action->data().toInt() ==
                           static_cast<int>(m_document.settings().shading));
    const std::optional<rl::RuleSet> rules = rl::ruleSetOf(m_document.settings().rules);
    for (QAction* action : m_rulesGroup->actions())
        action->setChecked(rules && action->data().toInt() == static_cast<int>(*rules));
    documentChanged();
}

bool MainWindow::handOver() {
    m_handingOver = true;
    const bool closed = close();
    m_handingOver = false;
    return closed;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    // Handing the document to a new window (another language): its edits go with it.
    if (!m_handingOver && !m_edit->maybeSave(this)) {
        event->ignore();
        return;
    }
    m_steppingBar->setPlaying(false);
    m_animation->setPlaying(false);
    if (m_inspection->presentation()) setPresentationMode(false);
    restoreFill();  // the layout kept is the one a dock filled
    saveLayout();
    QMainWindow::closeEvent(event);
}

bool MainWindow::mayReplace(SceneDocument::Part part) {
    return part == SceneDocument::Part::Object || m_edit->maybeSave(this, part);
}

bool MainWindow::openPart(SceneDocument::Part part, const QString& path) {
    if (!mayReplace(part)) return false;
    auto status = m_document.open(part, path);
    if (!status) {
        showError(translated(status.error()));
        return false;
    }
    if (part == SceneDocument::Part::Object || m_document.showsCommandFile()) leaveLesson();
    m_lastError.clear();
    addRecentFile(path);
    documentChanged();
    return true;
}

bool MainWindow::setCameraLayout(rl::CameraLayout layout) {
    if (!mayReplace(SceneDocument::Part::Camera)) return false;
    auto status = m_document.setCameraLayout(layout);
    if (!status) {
        showError(translated(status.error()));
        return false;
    }
    m_lastError.clear();
    documentChanged();
    return true;
}

bool MainWindow::setLightingLayout(rl::LightingLayout layout) {
    if (!mayReplace(SceneDocument::Part::Lighting)) return false;
    auto status = m_document.setLightingLayout(layout);
    if (!status) {
        showError(translated(status.error()));
        return false;
    }
    m_lastError.clear();
    documentChanged();
    return true;
}

bool MainWindow::openCommandFile(const QString& path) {
    if (!m_edit->maybeSave(this)) return false;
    auto status = m_document.openCommandFile(path);
    if (!status) {
        showError(translated(status.error()));
        return false;
    }
    leaveLesson();
    m_lastError.clear();
    addRecentFile(path);
    documentChanged();
    return true;
}

void MainWindow::documentChanged() {
    // The shading models and rules act on course scenes; a command file's draws bring their
    // own. The projection applies to both.
    for (QAction* action : m_shadingGroup->actions())
        action->setEnabled(!m_document.showsCommandFile());
    m_rulesMenu->setEnabled(!m_document.showsCommandFile());
    for (QAction* action : m_projectionGroup->actions())
        action->setChecked(action->data().toInt() == static_cast<int>(m_document.projection()));
    m_imageMenu->clear();
    const QStringList images = m_document.imageNames();
    m_imageMenu->setEnabled(images.size() > 1);
    auto* group = new QActionGroup(m_imageMenu);
    for (int i = 0; i < images.size(); ++i) {
        QAction* action = m_imageMenu->addAction(images[i]);
        action->setCheckable(true);
        action->setChecked(i == m_document.imageIndex());
        group->addAction(action);
        connect(action, &QAction::triggered, this, [this, i] {
            m_document.setImageIndex(i);
            requestRender();
        });
    }
    const QString shown = m_document.showsCommandFile()
                              ? QFileInfo(m_document.commandFilePath()).fileName()
                              : displayName(m_document.source(SceneDocument::Part::Object));
    setWindowTitle(tr("%1[*] - RasterLab").arg(shown));
    m_edit->refresh();
    setWindowModified(m_edit->isModified());
    watchSources();
    refreshMessages();
    requestRender();
}

void MainWindow::setShading(rl::ShadingModel model) {
    m_document.setShading(model);
    m_edit->refresh();
    for (QAction* action : m_shadingGroup->actions())
        action->setChecked(action->data().toInt() == static_cast<int>(model));
    requestRender();
}

bool MainWindow::exportImage(const QString& path) {
    return writePng(m_frame.image, path, tr("%1: cannot export the image: %2"));
}

void MainWindow::setRules(rl::RuleSet rules) {
    m_document.setRules(rules);
    for (QAction* action : m_rulesGroup->actions())
        action->setChecked(action->data().toInt() == static_cast<int>(rules));
    requestRender();
}

void MainWindow::setProjection(rl::NearPlane::Mode mode) {
    m_document.setProjection(mode);
    for (QAction* action : m_projectionGroup->actions())
        action->setChecked(action->data().toInt() == static_cast<int>(mode));
    requestRender();
}

void MainWindow::updateBehindBanner() {
    // Clipping left nothing: say what seed 000's formula would draw, and offer it.
    const auto& trace = m_frame.trace;
    const std::size_t mirrored = trace && rl::everyTriangleBehind(*trace->projection, *trace->scene)
                                     ? rl::trianglesBehindEye(*trace->projection, *trace->scene)
                                     : 0;
    m_behindBanner->setVisible(mirrored > 0);
    if (mirrored == 0) return;
    m_behindText->setText(
        tr("Every triangle is behind the camera (is N pointing away from the object?), so "
           "clipping at the near plane leaves nothing to draw. Seed 000's formula divides by z "
           "anyway: it would draw %1 of the %2 triangles as the object's point reflection "
           "through the eye, turned half a turn on the screen, and the z-buffer (keeping the "
           "smallest z) would keep the side farthest from the camera. The projection view's "
           "side view shows the eye, N and the object.")
            .arg(mirrored)
            .arg(trace->scene->triangleCount()));
}

void MainWindow::requestRender() {
    if (!m_document.isLoaded()) return;
    const std::shared_ptr<const rl::Scene> scene = m_document.scene();
    m_accuracy->setScene(scene);
    m_controller->request(scene);
}

bool MainWindow::isReadyToStep() const {
    return m_inspection->canStep() && !m_controller->isBusy() && !m_replayBuilder->isBusy() &&
           !m_waitingFrame;
}

void MainWindow::updateTimeLabel() {
    // The last frame's time, and whether a newer frame is still on its way.
    QString text;
    if (m_frame.trace) text = tr("%1 ms").arg(m_frame.trace->totalMilliseconds, 0, 'f', 1);
    if (m_controller->isBusy())
        text = text.isEmpty() ? tr("rendering...") : tr("%1, rendering...").arg(text);
    m_timeLabel->setText(text);
}

void MainWindow::updateBusy() {
    const bool preparing = m_replayBuilder->isBusy();
    m_busyBar->setVisible(m_controller->isBusy() || preparing);
    m_cancelButton->setVisible(preparing);
    m_busyBar->setToolTip(preparing ? tr("Preparing the stepping of this frame") : tr("Rendering"));
}

void MainWindow::onFrameReady(const RenderedFrame& frame) {
    const bool dragging = m_lastEdit.isValid() && m_lastEdit.elapsed() < kEditPauseMs &&
                          m_frame.trace && !m_animation->isPlaying();
    if (!dragging) {
        adoptFrame(frame);
        return;
    }
    // The image now; its replay behind it; the docks when the edits pause.
    m_waitingFrame = frame;
    m_waitingReplay.reset();
    m_view->setImage(frame.image);
    m_replayBuilder->build(frame.trace);
    m_adoptTimer.start();
    updateTimeLabel();
}

void MainWindow::adoptFrame(const RenderedFrame& frame) {
    const bool waited = m_waitingFrame && m_waitingFrame->trace == frame.trace;
    std::shared_ptr<const rl::FrameReplay> built = waited ? m_waitingReplay : nullptr;
    m_adoptTimer.stop();
    m_waitingFrame.reset();
    m_waitingReplay.reset();
    // A new frame of the scene being stepped through: stepping goes on at the same place.
    m_cursorToRestore.reset();
    if (m_inspection->canStep() && !m_inspection->atEnd())
        m_cursorToRestore = m_inspection->cursor();
    m_frame = frame;
    m_zbuffer->setFrame(frame.trace);
    m_inspection->setFrame(frame.trace, frame.image);
    applyPendingView(frame);
    m_animation->showFrame(*frame.trace);
    // While the animation plays, a frame is replaced before anyone could step through it: its
    // replay is built once paused (onAnimationPlaying).
    if (m_animation->isPlaying()) {
        m_replayBuilder->cancel();
    } else if (built) {
        onReplayBuilt(std::move(built));
    } else if (!(waited && m_replayBuilder->isBusy())) {
        m_replayBuilder->build(frame.trace);  // a waited frame's replay may still be on its way
    }
    updateTimeLabel();
    refreshMessages();
    refreshSceneSummary();
    updateBehindBanner();
}

void MainWindow::onReplayBuilt(std::shared_ptr<const rl::FrameReplay> replay) {
    if (m_waitingFrame && replay->tracePtr() == m_waitingFrame->trace) {
        m_waitingReplay = std::move(replay);  // the docks take it with the frame
        return;
    }
    std::optional<rl::ReplayCursor> at;
    if (m_cursorToRestore) {
        // Stepping goes on where it was (the same fragment, for a new frame of the same
        // geometry: a light or material being edited).
        at = replay->valid(*m_cursorToRestore) ? *m_cursorToRestore
                                               : replay->atFragment(m_cursorToRestore->fragments);
    }
    m_inspection->setReplay(std::move(replay), at);
}

void MainWindow::onAnimationPlaying(bool playing) {
    if (playing) {
        m_cursorToRestore.reset();
        return;
    }
    // Paused: the frame shown can be stepped through. A frame still being rendered builds its
    // own replay when it arrives.
    if (m_frame.trace && !m_controller->isBusy() && !m_inspection->replay())
        m_replayBuilder->build(m_frame.trace);
}

void MainWindow::onRenderFailed(const QString& message) {
    // The last good image stays on screen, with the message beside it; a camera without a
    // basis (an edit made N parallel to V, say) is also shown in the camera basis view.
    showError(message);
    if (m_document.isLoaded()) {
        rl::Diagnostics ignored;
        if (!rl::CameraBasisStage().run(*m_document.scene(), ignored))
            m_cameraBasis->setError(message);
    }
    updateTimeLabel();
}

void MainWindow::onCursorChanged() {
    m_view->setImage(m_inspection->image());
    if (const rl::FrameReplay* replay = m_inspection->replay()) {
        const std::uint32_t tested = m_inspection->cursor().fragments;
        m_zbuffer->setBuffers(m_inspection->sharedBuffers(), tested, replay->writtenBefore(tested));
    }
    updateOverlay();
}

void MainWindow::updateOverlay() {
    ImageOverlay o;
    o.lineWidth = m_inspection->lineWidth();
    o.pickedPixel = m_inspection->pickedPixel();
    const auto& frame = m_inspection->frame();
    if (!frame) {
        m_view->setOverlay(o);
        return;
    }
    o.sampleOffset = frame->scene->rules.sampleOffset;
    const rl::Projection& projection = *frame->projection;
    auto screenTriangle = [&](std::uint32_t t) {
        const std::array<rl::dvec2, 3> p = rl::screenVertices(projection, projection.triangles[t]);
        return std::array<QPointF, 3>{QPointF(p[0].x, p[0].y), QPointF(p[1].x, p[1].y),
                                      QPointF(p[2].x, p[2].y)};
    };
    const rl::FrameReplay* replay = m_inspection->replay();
    if (const rl::ReplayRow* row = m_inspection->currentRow(); row && !m_inspection->atEnd()) {
        o.currentTriangle = screenTriangle(row->triangle);
        o.scanline = row->y;
        o.spanBegin = row->xBegin;
        o.spanEnd = row->xEnd;
        o.crossings = std::make_pair(row->xLeft, row->xRight);
        // The current triangle's pixels tested so far: the last 40,000 at most, nearest the
        // cursor.
        const std::uint32_t end = m_inspection->cursor().fragments;
        const std::uint32_t first = replay->rows()[replay->firstRow(row->triangle)].fragmentBegin;
        const std::uint32_t from = end - std::min<std::uint32_t>(end - first, 40000);
        for (std::uint32_t i = from; i < end; ++i)
            o.coveredPixels.emplace_back(replay->fragments()[i].x, replay->fragments()[i].y);
        if (const std::optional<std::uint32_t> f = m_inspection->currentFragment())
            o.currentPixel = QPoint(replay->fragments()[*f].x, replay->fragments()[*f].y);
    }
    if (const std::optional<std::uint32_t> t = m_inspection->selectedTriangle();
        t && *t < projection.triangles.size())
        o.selectedTriangle = screenTriangle(*t);
    for (const VertexRef& v : m_inspection->selectedVertices()) {
        if (v.draw >= projection.draws.size()) continue;
        const rl::DrawProjection& d = projection.draws[v.draw];
        if (v.vertex < d.pScreen.size() && d.inFront[v.vertex])
            o.vertices.emplace_back(d.pScreen[v.vertex].x, d.pScreen[v.vertex].y);
    }
    // Scan conversion seen as a stage: every span of the frame, before any depth test.
    if (m_inspection->stage() == rl::StageId::ScanConversion &&
        m_inspection->granularity() == rl::StepGranularity::Stage && frame->scan) {
        // Made once per frame (the overlay is redrawn on every selection and pick).
        if (m_coverageFrame.lock() != frame) {
            m_coverage = QImage(frame->scene->width, frame->scene->height, QImage::Format_ARGB32);
            m_coverage.fill(Qt::transparent);
            const QRgb tint = qRgba(40, 200, 90, 110);
            for (const rl::Span& s : frame->scan->spans) {
                auto* line = reinterpret_cast<QRgb*>(m_coverage.scanLine(s.y));
                std::fill(line + s.xBegin, line + s.xEnd, tint);
            }
            m_coverageFrame = frame;
        }
        o.coverage = m_coverage;
    }
    m_view->setOverlay(std::move(o));
}

void MainWindow::showStageView(rl::StageId stage) {
    auto* dock = findChild<QDockWidget*>(stageDockName(stage));
    if (!dock) return;
    dock->show();
    dock->raise();
}

void MainWindow::showError(const QString& message) {
    m_lastError = message;
    refreshMessages();
    statusBar()->showMessage(message, 10000);
}

void MainWindow::refreshMessages() {
    m_messages->clear();
    if (!m_lastError.isEmpty()) {
        auto* item = new QListWidgetItem(tr("Error: %1").arg(m_lastError), m_messages);
        item->setForeground(QColor(200, 30, 30));
    }
    for (const QString& problem : m_lessonProblems) {
        auto* item = new QListWidgetItem(problem, m_messages);
        item->setForeground(QColor(170, 110, 0));
    }
    rl::Diagnostics all = m_document.diagnostics();
    if (m_frame.trace) all.append(m_frame.trace->diagnostics);
    for (const auto& d : all.items()) {
        auto* item = new QListWidgetItem(translated(d), m_messages);
        if (d.severity == rl::Severity::Warning) item->setForeground(QColor(170, 110, 0));
    }
}

void MainWindow::refreshSceneSummary() {
    if (!m_frame.trace) return;
    const rl::FrameTrace& t = *m_frame.trace;
    const rl::Scene& scene = *t.scene;
    QString html;
    if (!m_lessonTitle.isEmpty() || !m_lessonNotes.isEmpty())
        html += QStringLiteral("<h3>%1</h3><p>%2</p>")
                    .arg(tr("Lesson: %1").arg(m_lessonTitle.toHtmlEscaped()),
                         m_lessonNotes.toHtmlEscaped());
    html += QStringLiteral("<h3>%1</h3>").arg(tr("Files"));
    if (m_document.showsCommandFile()) {
        html += QStringLiteral("<p>%1: %2<br>%3: %4</p>")
                    .arg(tr("Command file"), QFileInfo(m_document.commandFilePath()).fileName(),
                         tr("Image"), QString::fromStdString(scene.name));
        html += QStringLiteral("<p>%1</p>")
                    .arg(tr("%1 vertices, %2 triangles in %3 draws; %4 x %5 pixels; %6 lights")
                             .arg(scene.vertexCount())
                             .arg(scene.triangleCount())
                             .arg(scene.draws.size())
                             .arg(scene.width)
                             .arg(scene.height)
                             .arg(scene.lights.size()));
    } else {
        html +=
            QStringLiteral("<p>%1: %2<br>%3: %4<br>%5: %6</p>")
                .arg(tr("Camera"), displayName(m_document.source(SceneDocument::Part::Camera)),
                     tr("Lighting"), displayName(m_document.source(SceneDocument::Part::Lighting)),
                     tr("Object"), displayName(m_document.source(SceneDocument::Part::Object)));
        html += QStringLiteral("<p>%1</p>")
                    .arg(tr("%1 vertices, %2 triangles; %3 x %4 pixels, %5 shading")
                             .arg(scene.vertexCount())
                             .arg(scene.triangleCount())
                             .arg(scene.width)
                             .arg(scene.height)
                             .arg(shadingLabel(m_document.settings().shading)));
    }
    html += QStringLiteral("<h3>%1</h3><table>").arg(tr("Stages"));
    for (rl::StageId stage : rl::kAllStages) {
        const auto i = static_cast<std::size_t>(stage);
        const QString skip = StageStrip::skipReason(t, stage);
        html += QStringLiteral("<tr><td>%1</td><td align='right'>%2</td></tr>")
                    .arg(StageStrip::stageName(stage),
                         skip.isEmpty() ? tr("%1 ms").arg(t.stageMilliseconds[i], 0, 'f', 2)
                                        : tr("skipped: %1").arg(skip));
    }
    html += QStringLiteral("</table>");
    html += QStringLiteral("<h3>%1</h3><p>").arg(tr("Counts"));
    html += tr("Triangles clipped at the near plane: %1; behind the camera: %2<br>")
                .arg(t.projection->clipped)
                .arg(t.projection->behind);
    html += tr("Zero-area triangles: %1 in view space, %2 on screen<br>")
                .arg(t.normals->degenerateTriangles)
                .arg(t.scan->degenerate);
    html += tr("Fragments tested: %1; written: %2; rejected: %3<br>")
                .arg(t.depth->fragments)
                .arg(t.depth->passed)
                .arg(t.depth->rejected);
    html += tr("Pixels shaded: %1; normals turned toward the viewer: %2; N.L &lt; 0: %3; "
               "R.V &lt; 0: %4; clamped at 255: %5")
                .arg(t.shading->shadedPixels)
                .arg(t.shading->flipped)
                .arg(t.shading->lightBehind)
                .arg(t.shading->noSpecular)
                .arg(t.shading->clampedPixels);
    html += QStringLiteral("</p>");
    m_summary->setHtml(html);
}

void MainWindow::onPixelHovered(QPoint pixel) {
    const rl::DepthTest* buffers = m_inspection->buffers();
    if (pixel.x() < 0 || !buffers) {
        m_pixelLabel->clear();
        return;
    }
    // The values at the cursor: what the image shows now.
    const QColor c = m_view->image().pixelColor(pixel);
    // The window's frames keep their z-buffer (RenderOptions::keepDepth); checked all the same.
    const bool kept = buffers->depth.contains(pixel.x(), pixel.y());
    const float z = kept ? buffers->depth.at(pixel.x(), pixel.y()) : 0.0f;
    const QString depth = !kept              ? tr("not kept")
                          : std::isfinite(z) ? QString::number(z, 'g', 7)
                                             : tr("empty (+inf)");
    m_pixelLabel->setText(tr("x %1, y %2   RGB (%3, %4, %5)   depth %6")
                              .arg(pixel.x())
                              .arg(pixel.y())
                              .arg(c.red())
                              .arg(c.green())
                              .arg(c.blue())
                              .arg(depth));
}

void MainWindow::openPartDialog(SceneDocument::Part part) {
    const QString path =
        QFileDialog::getOpenFileName(this, partTitle(part), QString(), partFilter(part));
    if (!path.isEmpty()) openPart(part, path);
}

void MainWindow::openCommandFileDialog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Command File"), QString(),
                                                      tr("Command files (*.txt);;All files (*)"));
    if (!path.isEmpty()) openCommandFile(path);
}

void MainWindow::openDialog() {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open"), QString(), tr("Scene files (*.byu *.cfg *.txt *.lux);;All files (*)"));
    if (!path.isEmpty()) openPath(path);
}

void MainWindow::exportDialog() {
    // A command file names its images; a course scene's image is named after its object.
    QString name = QStringLiteral("rasterlab.png");
    if (m_frame.trace && m_document.showsCommandFile())
        name = QString::fromStdString(m_frame.trace->scene->name);
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export PNG"), name, tr("PNG images (*.png)"));
    if (!path.isEmpty()) exportImage(path);
}

void MainWindow::compareDialog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Compare with Image"), QString(),
                                                      tr("PNG images (*.png);;All files (*)"));
    if (!path.isEmpty()) compareWithImage(path);
}

bool MainWindow::compareWithImage(const QString& path) {
    const QString problem = m_compare->compare(path);
    if (!problem.isEmpty() && m_compare->wasCancelled()) {
        statusBar()->showMessage(problem, 5000);
        return false;
    }
    if (!problem.isEmpty()) {
        showError(problem);
        return false;
    }
    // The first time, a window of its own over this one, large enough for two images and the
    // diagnosis (the right-hand group is too small for them); it can be docked like the others.
    if (!m_compareShown) {
        m_compareShown = true;
        if (m_compareDock->isHidden()) {
            m_compareDock->setFloating(true);
            const QRect area = geometry();
            const QSize size(std::min(1000, area.width() * 3 / 4),
                             std::min(860, area.height() * 9 / 10));
            m_compareDock->setGeometry(
                QRect(area.center() - QPoint(size.width(), size.height()) / 2, size));
        }
    }
    m_compareDock->show();
    m_compareDock->raise();
    statusBar()->showMessage(tr("Compared %1 with our render: %n pixel(s) differ", "",
                                int(m_compare->comparison()->differing))
                                 .arg(QFileInfo(path).fileName()),
                             8000);
    return true;
}

void MainWindow::about() {
    QMessageBox::about(this, tr("About RasterLab"), aboutText());
}

QString MainWindow::aboutText() {
    const QString copyright = QDir(docDir()).filePath(QStringLiteral("copyright"));
    const QString licence = QFileInfo(copyright).isFile()
                                ? tr("Released under the MIT License, whose text is in %1.")
                                      .arg(QDir::toNativeSeparators(copyright).toHtmlEscaped())
                                : tr("Released under the MIT License.");
    return tr("<h3>RasterLab %1</h3><p>The classic software rasterization pipeline, "
              "stage by stage: camera basis, view transform, normals, projection, "
              "scan conversion, depth test and shading.</p>")
               .arg(QStringLiteral(RASTERLAB_VERSION)) +
           tr("<p>It follows the courses it was made for: the computer graphics course "
              "projects of UFPE and UFRPE (Phong shading with a z-buffer, and its flat-shading "
              "variant with the painter's algorithm), the assignment “HW2: 3D "
              "Rasterizer”, the per-frame rendering pipeline of an animation course, and "
              "Prof. Jonh Edson R. de Carvalho's lecture slides on illumination models "
              "(“Modelos de Iluminação”).</p>") +
           QStringLiteral("<p>Copyright © 2026 The RasterLab developers. %1</p>").arg(licence);
}

QString MainWindow::shortcutsText() {
    // Two columns of key and meaning, so that the table fits a 720-pixel screen in
    // presentation mode's large text.
    QList<std::pair<QString, QString>> rows;
    const auto row = [&](const QString& keys, const QString& what) { rows.append({keys, what}); };
    row(QStringLiteral("F10, Page Down"), tr("step forward"));
    row(QStringLiteral("Shift+F10, Page Up"), tr("step back"));
    row(QStringLiteral("\u2192 \u2193, \u2190 \u2191"),
        tr("step forward, back (on the image, or anywhere in presentation mode)"));
    row(QStringLiteral("F6"), tr("play / pause"));
    row(tr("Space"), tr("play / pause (on the image, or anywhere in presentation mode)"));
    row(QStringLiteral("Ctrl+Home, Ctrl+End"), tr("jump to the start / the end of the frame"));
    row(QStringLiteral("F8"), tr("continue to the next breakpoint"));
    row(QStringLiteral("Ctrl+Shift+1 ... 5"), tr("step by stage, triangle, scanline, span, pixel"));
    row(QStringLiteral("Alt+1 ... 7"), tr("show a stage's view"));
    row(tr("Click, arrows"), tr("pick a pixel, move it by one"));
    row(QStringLiteral("Esc"), tr("let go of the picked pixel (on the image)"));
    row(QStringLiteral("F5, Esc"), tr("presentation mode on / off"));
    row(QStringLiteral("F7"),
        tr("presentation mode: the lecture layout (the stage being stepped fills the screen) "
           "or your own layout"));
    row(QStringLiteral("F9"), tr("presentation mode: the Edit panel on screen (live edits)"));
    row(tr("F11, double-click on a panel's title"),
        tr("fill the window with the panel under the pointer (in the lecture layout, the "
           "stage's), and back"));
    row(QStringLiteral("Ctrl+O, Ctrl+E, Ctrl+Shift+E"),
        tr("open, export the image, export it as displayed"));
    row(QStringLiteral("Ctrl+S, Ctrl+Z, Ctrl+Shift+Z"), tr("save, undo, redo"));
    row(QStringLiteral("Ctrl++, Ctrl+-, Ctrl+0"),
        tr("the panels' text larger, smaller, its normal size"));
    row(QStringLiteral("Ctrl+Alt++, Ctrl+Alt+-, Ctrl+Alt+0, Ctrl+1"),
        tr("the image: zoom in, zoom out, fit, actual size (and the wheel)"));
    const int half = int(rows.size() + 1) / 2;
    QString html = QStringLiteral("<table cellspacing='4'>");
    for (int i = 0; i < half; ++i) {
        html += QStringLiteral("<tr>");
        for (int j : {i, i + half}) {
            if (j >= rows.size()) break;
            html += QStringLiteral("<td width='14%'><b>%1</b></td><td width='36%'>%2</td>")
                        .arg(rows[j].first, rows[j].second);
        }
        html += QStringLiteral("</tr>");
    }
    html += QStringLiteral("</table><p>%1</p>")
                .arg(tr("These keys act wherever the focus is, a number box included (it keeps "
                        "its digits and its up and down arrows)."));
    return html;
}

void MainWindow::showShortcuts() {
    QDialog dialog(this);
    dialog.setObjectName(QStringLiteral("shortcutsDialog"));
    dialog.setWindowTitle(tr("Keyboard Shortcuts"));
    auto* layout = new QVBoxLayout(&dialog);
    auto* text = new QLabel(shortcutsText());
    text->setObjectName(QStringLiteral("shortcutsText"));
    text->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    text->setTextFormat(Qt::RichText);
    text->setWordWrap(true);
    // Scrolls rather than running off a small screen in large text.
    auto* scroll = new QScrollArea(&dialog);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidget(text);
    layout->addWidget(scroll);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, &dialog);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    layout->addWidget(buttons);
    const QRect free = screen() ? screen()->availableGeometry() : QRect(0, 0, 1280, 720);
    const int width = std::min(free.width() - 40, 1100);
    text->setFixedWidth(width - 60);
    const int wanted = text->heightForWidth(width - 60) + buttons->sizeHint().height() + 60;
    dialog.resize(width, std::min(wanted, free.height() - 60));
    dialog.exec();
}

}  // namespace rasterlab
