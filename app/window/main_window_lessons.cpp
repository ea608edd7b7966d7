// The main window's lessons: File > Examples (the shipped lessons), lesson files opened and
// saved (lesson_file.h), recent lessons, and the view state a lesson restores once its first
// frame is shown.
#include <QAction>
#include <QActionGroup>
#include <QCoreApplication>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QSaveFile>
#include <QSettings>
#include <QStatusBar>

#include "app/documents/examples.h"
#include "app/window/animation_panel.h"
#include "app/window/edit_panel.h"
#include "app/window/check_panel.h"
#include "app/window/main_window.h"
#include "views/breakpoints_view.h"
#include "views/frame_image_view.h"
#include "views/messages/pipeline_messages.h"

namespace rasterlab {

namespace {

using Field = SceneDocument::Field;

constexpr Field kCameraFields[] = {Field::C, Field::N, Field::V, Field::D, Field::Hx, Field::Hy};
constexpr Field kLightingFields[] = {Field::Ambient,   Field::Ka,       Field::Kd,
                                     Field::Od,        Field::Ks,       Field::Shininess,
                                     Field::Emission,  Field::TwoSided, Field::BlinnPhong};
constexpr Field kLightFields[] = {Field::LightPosition,      Field::LightDirectional,
                                  Field::LightIntensity,     Field::LightAttenuation,
                                  Field::LightSpotDirection, Field::LightSpotCutoff,
                                  Field::LightSpotExponent};

// The values of the parts edited and not saved: every field of such a part.
void captureEdits(const SceneDocument& document, Lesson& lesson) {
    if (document.showsCommandFile()) return;
    if (document.isModified(SceneDocument::Part::Camera))
        for (Field f : kCameraFields) lesson.edits.push_back({f, 0, document.value(f)});
    if (!document.isModified(SceneDocument::Part::Lighting)) return;
    for (Field f : kLightingFields) lesson.edits.push_back({f, 0, document.value(f)});
    const std::size_t lights = document.parts().lighting.lights.size();
    lesson.lightCount = lights;
    for (std::size_t i = 0; i < lights; ++i)
        for (Field f : kLightFields) lesson.edits.push_back({f, i, document.value(f, i)});
}

void applyEdits(SceneDocument& document, const Lesson& lesson) {
    if (lesson.lightCount) {
        const std::size_t want = *lesson.lightCount;
        while (document.parts().lighting.lights.size() < want) {
            const std::size_t n = document.parts().lighting.lights.size();
            document.insertLight(n, document.parts().lighting.lights.back());
        }
        while (document.parts().lighting.lights.size() > want)
            document.takeLight(document.parts().lighting.lights.size() - 1);
    }
    for (const Lesson::Edit& edit : lesson.edits) document.setValue(edit.field, edit.value, edit.light);
}

// A path as a lesson file holds it: relative to the lesson's folder (embedded files as they are).
QString relativePath(const QDir& base, const QString& path) {
    if (path.isEmpty() || path.startsWith(QStringLiteral(":/"))) return path;
    return base.relativeFilePath(QFileInfo(path).absoluteFilePath());
}

QString resolvedPath(const QDir& base, const QString& path) {
    if (path.startsWith(QStringLiteral(":/")) || QDir::isAbsolutePath(path)) return path;
    return QDir::cleanPath(base.absoluteFilePath(path));
}

}  // namespace

void MainWindow::addLessonMenus(QMenu* file) {
    QMenu* examples = file->addMenu(tr("E&xamples"));
    examples->setObjectName(QStringLiteral("examplesMenu"));
    for (const QString& name : exampleNames()) {
        QAction* action =
            examples->addAction(exampleTitle(name), this, [this, name] { openExample(name); });
        action->setObjectName(QStringLiteral("example_") + name);
        action->setToolTip(exampleNotes(name));
        action->setStatusTip(exampleNotes(name));
    }
    examples->setToolTipsVisible(true);
    QAction* open = file->addAction(tr("Open Lesso&n..."), this, &MainWindow::openLessonDialog);
    open->setShortcut(QKeySequence(tr("Ctrl+Alt+O")));
    open->setObjectName(QStringLiteral("openLessonAction"));
    open->setToolTip(tr("A lesson file (.rasterlab): a scene with its stepping, picked pixel, "
                        "breakpoints, zoom and docks"));
    QAction* save = file->addAction(tr("Save Lesson &As..."), this, &MainWindow::saveLessonDialog);
    save->setShortcut(QKeySequence(tr("Ctrl+Alt+S")));
    save->setObjectName(QStringLiteral("saveLessonAction"));
    m_recentLessonsMenu = file->addMenu(tr("Recent Lesso&ns"));
    m_recentLessonsMenu->setObjectName(QStringLiteral("recentLessonsMenu"));
    refreshRecentLessons();
}

QStringList MainWindow::recentLessons() const {
    if (QCoreApplication::organizationName().isEmpty()) return {};
    return QSettings().value(QStringLiteral("recentLessons")).toStringList();
}

void MainWindow::refreshRecentLessons() {
    m_recentLessonsMenu->clear();
    const QStringList lessons = recentLessons();
    for (int i = 0; i < lessons.size(); ++i) {
        const QString file = lessons[i];
        const QString name = QFileInfo(file).fileName();
        QAction* action = m_recentLessonsMenu->addAction(
            i < 9 ? QStringLiteral("&%1 %2").arg(i + 1).arg(name) : name, this,
            [this, file] { openLesson(file); });
        action->setToolTip(file);
        action->setStatusTip(file);
    }
    m_recentLessonsMenu->setEnabled(!lessons.isEmpty());
}

void MainWindow::openLessonDialog() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Lesson"), QString(),
                                                      tr("Lessons (*.rasterlab);;All files (*)"));
    if (!path.isEmpty()) openLesson(path);
}

void MainWindow::saveLessonDialog() {
    QString path = QFileDialog::getSaveFileName(this, tr("Save Lesson"), QString(),
                                                tr("Lessons (*.rasterlab)"));
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".rasterlab");
    if (saveLesson(path)) statusBar()->showMessage(tr("Saved the lesson to %1").arg(path), 5000);
}

bool MainWindow::openExample(const QString& name) {
    if (!isExample(name)) {
        showError(tr("there is no example named '%1' (examples: %2)")
                      .arg(name, exampleNames().join(QStringLiteral(", "))));
        return false;
    }
    return openLesson(exampleLessonPath(name));
}

SceneDocument MainWindow::lessonDocument(const Lesson& lesson, const QDir& base,
                                         QStringList& problems) {
    SceneDocument document = m_document;
    QString camera = lesson.camera, lighting = lesson.lighting, object = lesson.object;
    if (!lesson.example.isEmpty()) {
        if (!isExample(lesson.example)) {
            problems << tr("there is no example named '%1' (examples: %2)")
                            .arg(lesson.example, exampleNames().join(QStringLiteral(", ")));
        } else {
            const QString folder = exampleFolder(lesson.example) + QLatin1Char('/');
            camera = folder + QStringLiteral("camera.cfg");
            lighting = folder + QStringLiteral("lighting.txt");
            object = folder + lesson.example + QStringLiteral(".byu");
        }
    }
    // The layouts first: they say how the files below are read.
    (void)document.setCameraLayout(lesson.cameraLayout);
    (void)document.setLightingLayout(lesson.lightingLayout);
    const auto open = [&](SceneDocument::Part part, const QString& path, const QString& what) {
        if (path.isEmpty()) return;
        if (auto status = document.open(part, resolvedPath(base, path)); !status)
            problems << tr("the %1 was not restored, the one shown stays: %2")
                            .arg(what, translated(status.error()));
    };
    open(SceneDocument::Part::Camera, camera, tr("camera"));
    open(SceneDocument::Part::Lighting, lighting, tr("lighting"));
    open(SceneDocument::Part::Object, object, tr("object"));
    if (!lesson.commandFile.isEmpty()) {
        if (auto status = document.openCommandFile(resolvedPath(base, lesson.commandFile)); !status)
            problems << tr("the command file was not restored, the scene shown stays: %1")
                            .arg(translated(status.error()));
        else
            document.setImageIndex(lesson.commandImage);
    }
    applyEdits(document, lesson);
    if (lesson.shading) document.setShading(*lesson.shading);
    if (lesson.rules) document.setRules(*lesson.rules);
    if (lesson.projection) document.setProjection(*lesson.projection);
    document.setNearW(lesson.nearW);
    const QSize size = lesson.imageSize.value_or(QSize(800, 600));
    document.setSize(size.width(), size.height());
    document.setAnimation(lesson.animation.value_or(SceneDocument::Animation{}));
    return document;
}

bool MainWindow::openLesson(const QString& path) {
    rl::Diagnostics warnings;
    auto lesson = readLesson(path, warnings);
    if (!lesson) {
        showError(translated(lesson.error()));
        return false;
    }
    if (!m_edit->maybeSave(this)) return false;
    const QDir base = QFileInfo(path).absoluteDir();
    QStringList problems;
    for (const rl::Diagnostic& d : warnings.items()) problems << translated(d);
    SceneDocument document = lessonDocument(*lesson, base, problems);
    for (QString& problem : problems)
        if (!problem.startsWith(path)) problem = QStringLiteral("%1: %2").arg(path, problem);
    if (!exampleOfPath(path)) {
        const QString absolute = QFileInfo(path).absoluteFilePath();
        if (!QCoreApplication::organizationName().isEmpty()) {
            QStringList recent = recentLessons();
            recent.removeAll(absolute);
            recent.prepend(absolute);
            while (recent.size() > kMaxRecentLessons) recent.removeLast();
            QSettings().setValue(QStringLiteral("recentLessons"), recent);
            refreshRecentLessons();
        }
    }
    adoptDocument(document);
    m_lastError.clear();
    statusBar()->clearMessage();  // the last lesson's ("Stopped at a breakpoint ...")
    m_lessonProblems = problems;
    restoreView(*lesson);
    refreshMessages();
    refreshSceneSummary();
    if (!problems.isEmpty())
        statusBar()->showMessage(tr("The lesson opened, but not all of it: see the Messages dock"),
                                 10000);
    return true;
}

void MainWindow::restoreView(const Lesson& lesson) {
    // A shipped lesson's title and text are the program's, in the language shown.
    m_lessonExample = lesson.example;
    const bool example = isExample(lesson.example);
    m_lessonTitleIsExample = example && lesson.title.isEmpty();
    m_lessonNotesAreExample = example && lesson.notes.isEmpty();
    m_lessonTitle = m_lessonTitleIsExample ? exampleTitle(lesson.example) : lesson.title;
    m_lessonNotes = m_lessonNotesAreExample ? exampleNotes(lesson.example) : lesson.notes;
    if (!lesson.checkCommand.isEmpty() || !lesson.checkFolder.isEmpty()) {
        m_check->setCommand(lesson.checkCommand);
        m_check->setFolder(lesson.checkFolder);
    }
    // The lesson's layout is the one outside presentation mode. While presenting, it takes
    // the place of the layout presentation mode gives back, and its side docks are put away
    // again (else leaving would put the window's earlier layout back over the lesson's).
    const bool wasPresenting = m_inspection->presentation();
    restoreFill();
    if (wasPresenting) leavePresentationLayout();
    if (!lesson.dockState.isEmpty()) restoreState(lesson.dockState, kLayoutVersion);
    const QList<QDockWidget*> docks = findChildren<QDockWidget*>();
    if (!lesson.docksShown.isEmpty())
        for (QDockWidget* dock : docks) dock->setVisible(lesson.docksShown.contains(dock->objectName()));
    for (QDockWidget* dock : docks)
        if (lesson.docksRaised.contains(dock->objectName())) dock->show();
    if (wasPresenting) enterPresentationLayout();
    setPresentationMode(lesson.presentation.value_or(wasPresenting));
    setTextZoom(lesson.textZoom.value_or(1.0));
    // Raised last: entering presentation mode may move the pixel inspector among the tabs.
    for (QDockWidget* dock : docks)
        if (lesson.docksRaised.contains(dock->objectName()) && !dock->isHidden()) dock->raise();
    if (lectureLayoutShown()) {
        // The lesson's raised docks choose the lecture's (its clipping dock, say); the teacher's
        // own layout is the lesson's.
        keepOwnLayout();
        scheduleLectureLayout();
    }
    if (lesson.granularity) m_inspection->setGranularity(*lesson.granularity);
    if (lesson.breakpoints) m_breakpoints->setEntries(*lesson.breakpoints);
    if (lesson.stage) m_inspection->setStage(*lesson.stage);
    PendingView pending;
    pending.generation = m_controller->lastRequest();
    pending.cursor = lesson.cursor;
    pending.pixel = lesson.pixel;
    pending.zoom = lesson.zoom;
    pending.centre = lesson.centre;
    if (!lesson.zoom) m_view->fitToWindow();
    m_pendingView = pending;
}

// The lesson's pixel, zoom and cursor, once the first frame of its scene is shown.
void MainWindow::applyPendingView(const RenderedFrame& frame) {
    if (!m_pendingView || frame.generation < m_pendingView->generation) return;
    const PendingView pending = *m_pendingView;
    m_pendingView.reset();
    m_cursorToRestore = pending.cursor;
    m_inspection->pickPixel(pending.pixel.value_or(QPoint(-1, -1)));
    if (pending.zoom)
        m_view->showAt(*pending.zoom,
                       pending.centre.value_or(QPointF(frame.image.width(), frame.image.height()) / 2.0));
}

Lesson MainWindow::currentLesson(const QDir& base) const {
    Lesson lesson;
    lesson.title = m_lessonTitle;
    lesson.notes = m_lessonNotes;
    const SceneDocument& d = m_document;
    if (d.showsCommandFile()) {
        lesson.commandFile = relativePath(base, d.commandFilePath());
        lesson.commandImage = d.imageIndex();
    } else {
        lesson.camera = relativePath(base, d.source(SceneDocument::Part::Camera));
        lesson.lighting = relativePath(base, d.source(SceneDocument::Part::Lighting));
        lesson.object = relativePath(base, d.source(SceneDocument::Part::Object));
        const std::optional<QString> example = exampleOfPath(lesson.object);
        if (example && exampleOfPath(lesson.camera) == example &&
            exampleOfPath(lesson.lighting) == example) {
            lesson.example = *example;
            lesson.camera.clear();
            lesson.lighting.clear();
            lesson.object.clear();
            // A shipped lesson's title and text come from the program, in the reader's
            // language: left out when they are the program's (in the language they were
            // shown in, which may no longer be the one installed: a language switch).
            if (m_lessonTitleIsExample || lesson.title == exampleTitle(*example))
                lesson.title.clear();
            if (m_lessonNotesAreExample || lesson.notes == exampleNotes(*example))
                lesson.notes.clear();
        }
    }
    lesson.cameraLayout = d.cameraLayout();
    lesson.lightingLayout = d.lightingLayout();
    captureEdits(d, lesson);
    const rl::CourseSceneSettings settings = d.settings();
    lesson.shading = settings.shading;
    lesson.rules = rl::ruleSetOf(settings.rules);
    lesson.projection = d.projection();
    lesson.nearW = settings.nearPlane.fixedW;
    lesson.imageSize = QSize(settings.width, settings.height);
    if (d.animation() != SceneDocument::Animation{}) lesson.animation = d.animation();
    lesson.granularity = m_inspection->granularity();
    lesson.stage = m_inspection->stage();
    if (m_inspection->canStep() && !m_inspection->atEnd()) lesson.cursor = m_inspection->cursor();
    if (m_inspection->pickedPixel().x() >= 0) lesson.pixel = m_inspection->pickedPixel();
    lesson.breakpoints = m_breakpoints->entries();
    if (!m_view->fitsWindow()) {
        lesson.zoom = m_view->zoom();
        lesson.centre = m_view->centrePoint();
    }
    for (QDockWidget* dock : findChildren<QDockWidget*>()) {
        if (dock->isHidden()) continue;
        lesson.docksShown << dock->objectName();
        if (!tabifiedDockWidgets(dock).isEmpty() && !dock->visibleRegion().isEmpty())
            lesson.docksRaised << dock->objectName();
    }
    // Presenting: the layout to come back to when presentation mode is left, with the docks
    // it put away (it puts them away again when the lesson opens).
    const bool presenting = m_inspection->presentation();
    if (presenting) lesson.docksShown << m_hiddenByPresentation;
    lesson.docksShown.sort();
    lesson.docksShown.removeDuplicates();
    lesson.docksRaised.sort();
    lesson.dockState = presenting ? m_layoutBeforePresentation : saveState(kLayoutVersion);
    lesson.presentation = presenting;
    if (m_textZoom != 1.0) lesson.textZoom = m_textZoom;
    lesson.checkCommand = m_check->command();
    lesson.checkFolder = m_check->folder();
    return lesson;
}

void MainWindow::leaveLesson() {
    m_lessonExample.clear();
    m_lessonTitle.clear();
    m_lessonNotes.clear();
    m_lessonTitleIsExample = m_lessonNotesAreExample = false;
    m_lessonProblems.clear();
    m_pendingView.reset();
    m_document.setSize(800, 600);
    m_document.setNearW(std::nullopt);
}

bool MainWindow::saveLesson(const QString& path) {
    const QDir base = QFileInfo(path).absoluteDir();
    const QByteArray bytes = lessonJson(currentLesson(base));
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
        showError(tr("%1: cannot save the lesson: %2").arg(path, file.errorString()));
        return false;
    }
    return true;
}

}  // namespace rasterlab
