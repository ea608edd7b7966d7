#include "main_window.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QTextBrowser>

#include <cmath>

#include "accuracy_panel.h"
#include "frame_image_view.h"
#include "image_io.h"
#include "zbuffer_view.h"

namespace rasterlab {

namespace {

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

// A layout's description as a menu label ("detected" is translated; the layouts' own
// names, such as "UFRPE (N; V; d; hx; hy; C)", are file formats and stay as they are).
QString layoutLabel(const char* description) {
    const QString text = QString::fromUtf8(description);
    return text.startsWith(QStringLiteral("detected")) ? MainWindow::tr("Detect from the file")
                                                       : text;
}

QString displayName(const QString& source) {
    if (source.startsWith(QStringLiteral(":/")))
        return MainWindow::tr("%1 (built in)").arg(QFileInfo(source).fileName());
    return QFileInfo(source).fileName();
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setObjectName(QStringLiteral("MainWindow"));
    setWindowTitle(tr("RasterLab"));
    m_view = new FrameImageView(this);
    m_view->setObjectName(QStringLiteral("imageView"));
    setCentralWidget(m_view);
    m_controller = new RenderController(this);
    connect(m_controller, &RenderController::frameReady, this, &MainWindow::onFrameReady);
    connect(m_controller, &RenderController::failed, this, &MainWindow::onRenderFailed);
    connect(m_controller, &RenderController::busyChanged, this, &MainWindow::updateTimeLabel);
    connect(m_view, &FrameImageView::pixelHovered, this, &MainWindow::onPixelHovered);

    createDocks();
    createActions();
    m_pixelLabel = new QLabel(this);
    m_timeLabel = new QLabel(this);
    statusBar()->addWidget(m_pixelLabel, 1);
    statusBar()->addPermanentWidget(m_timeLabel);
    resize(1280, 860);
    m_defaultLayout = saveState(kLayoutVersion);
    restoreLayout();

    if (auto status = m_document.loadDefault(); !status)
        showError(QString::fromStdString(status.error().toString()));
    documentChanged();
}

void MainWindow::createActions() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* openObject = file->addAction(tr("Open &Object..."), this,
                                          [this] { openPartDialog(SceneDocument::Part::Object); });
    openObject->setShortcut(QKeySequence::Open);
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
    file->addAction(tr("&Default Scene"), this, [this] {
        if (auto status = m_document.loadDefault(); !status)
            showError(QString::fromStdString(status.error().toString()));
        else
            m_lastError.clear();
        documentChanged();
    });
    // The layouts course files are read in: detected, or one chosen by hand.
    QMenu* formats = file->addMenu(tr("Course File &Layouts"));
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
    file->addSeparator();
    QAction* exportAction = file->addAction(tr("&Export PNG..."), this, &MainWindow::exportDialog);
    exportAction->setShortcut(QKeySequence(tr("Ctrl+E")));
    exportAction->setObjectName(QStringLiteral("exportAction"));
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    QAction* fit = view->addAction(tr("&Fit to Window"), m_view, &FrameImageView::fitToWindow);
    fit->setShortcut(QKeySequence(tr("Ctrl+0")));
    QAction* actual =
        view->addAction(tr("&Actual Size"), m_view, &FrameImageView::zoomToActualSize);
    actual->setShortcut(QKeySequence(tr("Ctrl+1")));
    QAction* zoomIn = view->addAction(tr("Zoom &In"), m_view, &FrameImageView::zoomIn);
    zoomIn->setShortcut(QKeySequence::ZoomIn);
    QAction* zoomOut = view->addAction(tr("Zoom &Out"), m_view, &FrameImageView::zoomOut);
    zoomOut->setShortcut(QKeySequence::ZoomOut);
    view->addSeparator();
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        view->addAction(dock->toggleViewAction());
    QAction* reset = view->addAction(tr("Reset &Layout"), this, &MainWindow::resetLayout);
    reset->setObjectName(QStringLiteral("resetLayoutAction"));
    view->addSeparator();
    // The images a command file names (its png commands): one is shown at a time.
    m_imageMenu = view->addMenu(tr("&Image"));
    m_imageMenu->setObjectName(QStringLiteral("imageMenu"));

    QMenu* shading = menuBar()->addMenu(tr("&Shading"));
    m_shadingMenu = shading;
    m_shadingGroup = new QActionGroup(this);
    const std::pair<rl::ShadingModel, QString> models[] = {
        {rl::ShadingModel::Phong, tr("&Phong (per pixel)")},
        {rl::ShadingModel::Gouraud, tr("&Gouraud (per vertex)")},
        {rl::ShadingModel::Flat, tr("&Flat (per triangle)")},
    };
    int key = 1;
    for (const auto& [model, label] : models) {
        QAction* action = shading->addAction(label);
        action->setCheckable(true);
        action->setChecked(model == m_document.settings().shading);
        action->setShortcut(QKeySequence(tr("Alt+%1").arg(key++)));
        action->setData(static_cast<int>(model));
        m_shadingGroup->addAction(action);
        connect(action, &QAction::triggered, this, [this, model = model] { setShading(model); });
    }

    shading->addSeparator();
    QMenu* rules = shading->addMenu(tr("&Rasterization Rules"));
    rules->setObjectName(QStringLiteral("rulesMenu"));
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

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About RasterLab"), this, &MainWindow::about);
}

void MainWindow::createDocks() {
    auto* messagesDock = new QDockWidget(tr("Messages"), this);
    messagesDock->setObjectName(QStringLiteral("messagesDock"));
    m_messages = new QListWidget(messagesDock);
    m_messages->setObjectName(QStringLiteral("messagesList"));
    m_messages->setWordWrap(true);
    messagesDock->setWidget(m_messages);
    addDockWidget(Qt::BottomDockWidgetArea, messagesDock);

    auto* sceneDock = new QDockWidget(tr("Scene"), this);
    sceneDock->setObjectName(QStringLiteral("sceneDock"));
    m_summary = new QTextBrowser(sceneDock);
    m_summary->setObjectName(QStringLiteral("sceneSummary"));
    sceneDock->setWidget(m_summary);
    addDockWidget(Qt::RightDockWidgetArea, sceneDock);
    auto* accuracyDock = new QDockWidget(tr("Accuracy"), this);
    accuracyDock->setObjectName(QStringLiteral("accuracyDock"));
    m_accuracy = new AccuracyPanel(accuracyDock);
    accuracyDock->setWidget(m_accuracy);
    addDockWidget(Qt::RightDockWidgetArea, accuracyDock);
    tabifyDockWidget(sceneDock, accuracyDock);
    auto* zbufferDock = new QDockWidget(tr("Z-buffer"), this);
    zbufferDock->setObjectName(QStringLiteral("zbufferDock"));
    m_zbuffer = new ZBufferView(zbufferDock);
    zbufferDock->setWidget(m_zbuffer);
    addDockWidget(Qt::RightDockWidgetArea, zbufferDock);
    tabifyDockWidget(sceneDock, zbufferDock);
    sceneDock->raise();
    resizeDocks({sceneDock}, {330}, Qt::Horizontal);
    resizeDocks({messagesDock}, {130}, Qt::Vertical);
}

void MainWindow::resetLayout() {
    restoreState(m_defaultLayout, kLayoutVersion);
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
    restoreState(settings.value(QStringLiteral("layout/state")).toByteArray(), kLayoutVersion);
}

void MainWindow::closeEvent(QCloseEvent* event) {
    saveLayout();
    QMainWindow::closeEvent(event);
}

bool MainWindow::openPart(SceneDocument::Part part, const QString& path) {
    auto status = m_document.open(part, path);
    if (!status) {
        showError(QString::fromStdString(status.error().toString()));
        return false;
    }
    m_lastError.clear();
    documentChanged();
    return true;
}

bool MainWindow::setCameraLayout(rl::CameraLayout layout) {
    auto status = m_document.setCameraLayout(layout);
    if (!status) {
        showError(QString::fromStdString(status.error().toString()));
        return false;
    }
    m_lastError.clear();
    documentChanged();
    return true;
}

bool MainWindow::setLightingLayout(rl::LightingLayout layout) {
    auto status = m_document.setLightingLayout(layout);
    if (!status) {
        showError(QString::fromStdString(status.error().toString()));
        return false;
    }
    m_lastError.clear();
    documentChanged();
    return true;
}

bool MainWindow::openCommandFile(const QString& path) {
    auto status = m_document.openCommandFile(path);
    if (!status) {
        showError(QString::fromStdString(status.error().toString()));
        return false;
    }
    m_lastError.clear();
    documentChanged();
    return true;
}

void MainWindow::documentChanged() {
    // The shading menu acts on course scenes; a command file's draws bring their own.
    m_shadingMenu->setEnabled(!m_document.showsCommandFile());  // the rules submenu too
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
    setWindowTitle(tr("%1 - RasterLab").arg(shown));
    refreshMessages();
    requestRender();
}

void MainWindow::setShading(rl::ShadingModel model) {
    m_document.setShading(model);
    for (QAction* action : m_shadingGroup->actions())
        action->setChecked(action->data().toInt() == static_cast<int>(model));
    requestRender();
}

bool MainWindow::exportImage(const QString& path) {
    QString error;
    if (m_frame.image.isNull() || !savePng(m_frame.image, path, &error)) {
        showError(tr("%1: cannot export the image: %2")
                      .arg(path, error.isEmpty() ? tr("nothing has been rendered yet") : error));
        return false;
    }
    statusBar()->showMessage(tr("Exported %1").arg(QFileInfo(path).absoluteFilePath()), 5000);
    return true;
}

void MainWindow::setRules(rl::RuleSet rules) {
    m_document.setRules(rules);
    for (QAction* action : m_rulesGroup->actions())
        action->setChecked(action->data().toInt() == static_cast<int>(rules));
    requestRender();
}

void MainWindow::requestRender() {
    if (!m_document.isLoaded()) return;
    const std::shared_ptr<const rl::Scene> scene = m_document.scene();
    m_accuracy->setScene(scene);
    m_controller->request(scene);
}

void MainWindow::updateTimeLabel() {
    // The last frame's time, and whether a newer frame is still on its way.
    QString text;
    if (m_frame.trace) text = tr("%1 ms").arg(m_frame.trace->totalMilliseconds, 0, 'f', 1);
    if (m_controller->isBusy())
        text = text.isEmpty() ? tr("rendering...") : tr("%1, rendering...").arg(text);
    m_timeLabel->setText(text);
}

void MainWindow::onFrameReady(const RenderedFrame& frame) {
    m_frame = frame;
    m_view->setImage(frame.image);
    m_zbuffer->setFrame(frame.trace);
    updateTimeLabel();
    refreshMessages();
    refreshSceneSummary();
}

void MainWindow::onRenderFailed(const QString& message) {
    // The last good image stays on screen, with the message beside it.
    showError(message);
    updateTimeLabel();
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
    rl::Diagnostics all = m_document.diagnostics();
    if (m_frame.trace) all.append(m_frame.trace->diagnostics);
    for (const auto& d : all.items()) {
        auto* item = new QListWidgetItem(QString::fromStdString(d.toString()), m_messages);
        if (d.severity == rl::Severity::Warning) item->setForeground(QColor(170, 110, 0));
    }
}

void MainWindow::refreshSceneSummary() {
    if (!m_frame.trace) return;
    const rl::FrameTrace& t = *m_frame.trace;
    const rl::Scene& scene = *t.scene;
    QString html;
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
                             .arg(QString::fromUtf8(
                                 rl::shadingModelName(m_document.settings().shading))));
    }
    html += QStringLiteral("<h3>%1</h3><table>").arg(tr("Stages"));
    const QString stageNames[] = {tr("Camera basis"), tr("View transform"),  tr("Normals"),
                                  tr("Projection"),   tr("Scan conversion"), tr("Depth test"),
                                  tr("Shading")};
    for (rl::StageId stage : rl::kAllStages) {
        const auto i = static_cast<std::size_t>(stage);
        const std::string skip = t.skipReason(stage);
        html += QStringLiteral("<tr><td>%1</td><td align='right'>%2</td></tr>")
                    .arg(stageNames[i], skip.empty()
                                            ? tr("%1 ms").arg(t.stageMilliseconds[i], 0, 'f', 2)
                                            : tr("skipped: %1").arg(QString::fromStdString(skip)));
    }
    html += QStringLiteral("</table>");
    const auto& b = *t.cameraBasis;
    if (!b.skipped) {
        html += QStringLiteral("<h3>%1</h3>").arg(tr("Camera basis"));
        auto vec = [](const rl::dvec3& v) {
            return QStringLiteral("(%1, %2, %3)")
                .arg(v.x, 0, 'f', 4)
                .arg(v.y, 0, 'f', 4)
                .arg(v.z, 0, 'f', 4);
        };
        html += QStringLiteral("<p>U = %1<br>V = %2<br>N = %3<br>%4</p>")
                    .arg(vec(b.u), vec(b.v), vec(b.n),
                         tr("largest orthonormality residual: %1").arg(b.maxResidual(), 0, 'g', 3));
    }
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
    if (pixel.x() < 0 || !m_frame.trace) {
        m_pixelLabel->clear();
        return;
    }
    const QColor c = m_frame.image.pixelColor(pixel);
    const float z = m_frame.trace->depth->depth.at(pixel.x(), pixel.y());
    const QString depth = std::isfinite(z) ? QString::number(z, 'g', 6) : tr("empty (+inf)");
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

void MainWindow::exportDialog() {
    // A command file names its images; a course scene's image is named after its object.
    QString name = QStringLiteral("rasterlab.png");
    if (m_frame.trace && m_document.showsCommandFile())
        name = QString::fromStdString(m_frame.trace->scene->name);
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export PNG"), name, tr("PNG images (*.png)"));
    if (!path.isEmpty()) exportImage(path);
}

void MainWindow::about() {
    QMessageBox::about(this, tr("About RasterLab"),
                       tr("<h3>RasterLab %1</h3><p>The classic software rasterization pipeline, "
                          "stage by stage: camera basis, view transform, normals, projection, "
                          "scan conversion, depth test and shading.</p>")
                           .arg(QStringLiteral(RASTERLAB_VERSION)));
}

}  // namespace rasterlab
