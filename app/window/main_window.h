// RasterLab's main window: the image at the stepping cursor in the centre, with overlays for
// the triangle, scanline, span and pixel being drawn; the stage strip (the seven stages in
// the lecture's order) and the stepping bar above it; a dock per stage view (camera basis,
// vertex table, normals, projection, scanline, z-buffer, pixel inspector), the breakpoints,
// the live editing panel, the scene summary, the accuracy report and the messages. Every dock
// has an objectName, so the layout is saved and restored (View > Reset Layout puts it back).
//
// Files: Open (a course camera, lighting or object, each replacing its part alone, or a
// command file; the kind is told from the file), recent files, drag and drop of files or a
// folder, and a watch on the files shown: a file changed on disk (also when an editor saves
// by renaming) is read again. A file that fails to load leaves the previous scene on screen,
// with its file:line:col message in the Messages dock.
#pragma once

#include <QActionGroup>
#include <QFileSystemWatcher>
#include <QHash>
#include <QMainWindow>
#include <QElapsedTimer>
#include <QPointer>
#include <QTemporaryDir>
#include <QTimer>

#include <memory>

#include "app/documents/lesson_file.h"
#include "app/documents/scene_document.h"
#include "app/window/render_controller.h"
#include "views/inspection.h"

class QDir;
class QDockWidget;
class QKeyEvent;
class QLabel;
class QMenu;
class QListWidget;
class QProgressBar;
class QPushButton;
class QScreen;
class QTextBrowser;
class QToolButton;

namespace rasterlab {

class AccuracyPanel;
class AnimationPanel;
class BreakpointsView;
class CameraBasisView;
class ComparePanel;
class CheckPanel;
class EditPanel;
class NormalsView;
class PixelInspector;
class ProjectionView;
class ScanlineView;
class VertexTableView;
class FrameImageView;
class ReplayBuilder;
class StageStrip;
class SteppingBar;
class ZBufferView;
class PainterView;

// What a file holds, told from its name and its text.
// CameraAndLighting: one key = value file holding both (the UFRPE courses' habit).
enum class FileKind { Camera, Lighting, CameraAndLighting, Object, CommandFile, Unknown };
FileKind detectFileKind(const QString& path);

// Presentation mode's text scale on a screen this many pixels tall: 1.5 from 1080 up, less
// below, to no less than 1.25 (a projector shows a 720-pixel screen as large as a 1080-pixel
// one, so its text is already half as large again on the wall).
double presentationTextScale(int screenHeight);

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);

    // Replaces one part of the scene from a file; returns false (and shows the error,
    // keeping the scene) when the file is bad.
    bool openPart(SceneDocument::Part part, const QString& path);
    // Opens any file: a course part or a command file, told from the file; a folder opens
    // the course files it holds. False (the error shown, the scene kept) when it fails.
    bool openPath(const QString& path);
    // Reads course cameras / lighting in a layout from now on (Auto: detected), re-reading
    // the current file; false (the error shown, the scene kept) when it does not fit.
    bool setCameraLayout(rl::CameraLayout layout);
    bool setLightingLayout(rl::LightingLayout layout);
    // Shows a command file (seed 001); false (the error shown, the scene kept) when bad.
    bool openCommandFile(const QString& path);
    void setShading(rl::ShadingModel model);
    void setRules(rl::RuleSet rules);
    // What happens to triangles at or behind the eye (Shading > Projection), kept with the
    // scene: clipping at the near plane, the plain divide of seeds 000 and 001, same side.
    void setProjection(rl::NearPlane::Mode mode);
    // The bar above the image offering the plain divide when clipping left every triangle
    // behind the camera (hidden otherwise), and its button.
    QWidget* behindBanner() const { return m_behindBanner; }
    QPushButton* behindBannerButton() const { return m_behindButton; }
    // The final image of the frame shown.
    bool exportImage(const QString& path);
    // The image as displayed (at the cursor, with its overlays), the raw buffers at the cursor,
    // a dock's view as displayed, and the frame stepped at the current granularity to numbered
    // PNGs (at most maxImages); false with the error shown when a file cannot be written.
    bool exportDisplayed(const QString& path);
    bool exportDepthBuffer(const QString& path);
    bool exportNormalBuffer(const QString& path);
    bool exportDock(const QString& dockName, const QString& path);
    int exportSequence(const QString& folder, int maxImages);
    // The frame shown rendered in flat, Gouraud and Phong shading, side by side with their
    // names under them, as one PNG (a course scene's; small images enlarged pixel by pixel).
    bool exportShadingSideBySide(const QString& path);
    // The animation's frames (the animation panel's count, at its frames a second, from
    // frame 0) as frame_0000.png ... in folder, with a progress dialog that can cancel; the
    // number written (0 with the error shown when a file cannot be written).
    int exportAnimationFrames(const QString& folder);
    // File > Compare with Image...: their PNG against our render of the frame shown, in the
    // Compare dock (shown and raised); false with the error shown (as the command line words
    // it) and the dock as it was when the image cannot be compared.
    bool compareWithImage(const QString& path);
    // File > Check My Renderer...: the Check dock shown and raised, its command field focused.
    void showCheckDock();

    const SceneDocument& document() const { return m_document; }
    std::shared_ptr<const rl::FrameTrace> currentFrame() const { return m_frame.trace; }
    // The frame whose image is on screen: during a drag in the Edit dock, a newer one than
    // currentFrame(), whose image is shown before the docks take it (adoptFrame).
    std::shared_ptr<const rl::FrameTrace> shownFrame() const {
        return m_waitingFrame ? m_waitingFrame->trace : m_frame.trace;
    }
    const QImage& currentImage() const { return m_frame.image; }  // the frame's final image
    FrameImageView* imageView() const { return m_view; }
    QListWidget* messages() const { return m_messages; }
    RenderController* controller() const { return m_controller; }
    ReplayBuilder* replayBuilder() const { return m_replayBuilder; }
    Inspection* inspection() const { return m_inspection; }
    // The newest frame is shown and its replay built: nothing is on its way.
    bool isReadyToStep() const;
    AccuracyPanel* accuracyPanel() const { return m_accuracy; }
    ZBufferView* zbufferView() const { return m_zbuffer; }
    ProjectionView* projectionView() const { return m_projection; }
    PainterView* painterView() const { return m_painter; }
    StageStrip* stageStrip() const { return m_stageStrip; }
    SteppingBar* steppingBar() const { return m_steppingBar; }
    BreakpointsView* breakpointsView() const { return m_breakpoints; }
    VertexTableView* vertexTableView() const { return m_vertexTable; }
    PixelInspector* pixelInspector() const { return m_inspector; }
    EditPanel* editPanel() const { return m_edit; }
    AnimationPanel* animationPanel() const { return m_animation; }
    ComparePanel* comparePanel() const { return m_compare; }
    CheckPanel* checkPanel() const { return m_check; }
    QStringList recentFiles() const;
    QStringList watchedFiles() const { return m_watcher.files(); }
    // The files the scene shown was read from (built-in parts left out).
    QStringList shownFiles() const;
    bool presentationMode() const { return m_inspection->presentation(); }
    // Presentation mode; on a screen narrower than kSidesBesideImageWidth the pixel
    // inspector joins the pixel views' tabs on the right, so that the image is not left a
    // strip between the two sides (it goes back to the left afterwards).
    void setPresentationMode(bool on);
    static constexpr int kSidesBesideImageWidth = 1600;
    // The document of another window (its files, values edited and not saved, shading, rules
    // and layouts), shown here.
    void adoptDocument(const SceneDocument& document);
    // Closes the window without asking about unsaved edits (a new window has the document);
    // false when the close did not happen.
    bool handOver();
    // The docks as they are when the window opens (View > Reset Layout).
    void resetLayout();
    // The window's opening size, 1560x960 or less, inside the screen's free area (room left
    // for the title bar and frame) and centred on it.
    void fitToScreen(const QScreen* screen);
    // View > Fill the Window (F11, or a double-click on a dock's title bar): one dock over the
    // whole window, the others and the image hidden (for a projector); with no dock, the
    // image alone. Again, the layout as it was. Without a dock given, the dock holding the
    // focus or under the mouse.
    void toggleFill(QDockWidget* dock = nullptr);
    bool isFilled() const;
    QDockWidget* filledDock() const;
    // The docks' widths and heights for the window's size (the default layout, presentation
    // mode): each side as wide as its tab bars need (the left one, its docks' contents too),
    // the image the rest.
    void fitDocks();

    // ---- Teaching from a projector (main_window_lecture.cpp) ------------------------------
    // The lecture layout, presentation mode's own (View > Lecture Layout, F7): the dock of the
    // stage the stepping cursor is in takes the screen and changes as the cursor crosses into
    // the next stage; the image is beside it (kLectureStageShare of the width to the dock)
    // once it has something drawn, and gives its room to the dock while it is black (stages
    // 1 to 4 at stage granularity). Every other dock is put away. Off, the teacher's own
    // presentation layout, as it was left. The choice holds outside presentation mode too.
    bool lectureLayout() const { return m_lectureLayout; }
    void setLectureLayout(bool on);
    // Presentation mode in the lecture layout.
    bool lectureLayoutShown() const;
    // The dock of the stage the cursor is in (seed 002's clipping or trapezoids, seed 004's
    // painter when one was in front of its tabs on entering, or the painter's shading), and
    // whether the image has something to show.
    QDockWidget* lectureDock() const;
    bool lectureShowsImage() const;
    static QString stageDockName(rl::StageId stage);
    static constexpr double kLectureStageShare = 0.72;
    // The lighting's: the lit pixel's history and its formula side by side need the room.
    static constexpr double kLectureLightingShare = 0.76;
    static constexpr double kLectureEditShare = 0.3;
    // The stage dock's title in the lecture layout: the stage and its key numbers for the
    // frame (fragments tested, pixels shaded ...), this much larger than the window's text.
    QString lectureCaption(rl::StageId stage) const;
    static constexpr double kLectureCaptionScale = 1.3;
    // Live edits (F9): the Edit dock kept on screen in presentation mode (on the left of the
    // lecture layout), so that the light and the material change in front of the class.
    bool liveEdits() const { return m_liveEdits; }
    void setLiveEdits(bool on);
    // The text zoom of every dock's contents (View > Text Size: Ctrl++, Ctrl+-, Ctrl+0), on
    // top of presentation mode's larger text; kept in lesson files.
    double textZoom() const;
    void setTextZoom(double zoom);
    void zoomText(int steps);  // so many steps larger (negative: smaller)
    // For the application's event filter: the window's keys refused to a number box with
    // the focus (a ShortcutOverride), so that they act wherever the focus is.
    bool filterNumberBoxKey(QObject* watched, QEvent* event);

    // ---- Lessons (main_window_lessons.cpp) -----------------------------------------------
    // Opens a lesson file (lesson_file.h): its scene, settings, stepping and window. A part
    // of the scene that cannot be read keeps the part shown, and the Messages dock says what
    // was not restored. False, with the error shown and nothing changed, when the lesson
    // file itself is bad.
    bool openLesson(const QString& path);
    // A shipped lesson (File > Examples); false for an unknown name.
    bool openExample(const QString& name);
    // The About box's text: the version, the courses followed, the licence.
    static QString aboutText();
    // Help > Keyboard Shortcuts (F1): the keys, in two columns, in a dialog that fits the
    // screen (it scrolls when the text is too large for it).
    static QString shortcutsText();
    // The setup on screen as a lesson file; false with the error shown when it cannot be
    // written.
    bool saveLesson(const QString& path);
    // The setup on screen, with file paths relative to `base`.
    Lesson currentLesson(const QDir& base) const;
    // Restores a lesson's stepping, picked pixel, breakpoints, zoom, docks and presentation
    // mode, not its scene (the cursor, pixel and zoom once the next frame is shown): what a
    // window built again in another language keeps.
    void restoreView(const Lesson& lesson);
    QStringList recentLessons() const;
    // Whether a lesson's cursor, pixel or zoom still waits for the first frame of its scene.
    bool lessonViewPending() const { return m_pendingView.has_value(); }
    // What opening the last lesson could not restore (shown in the Messages dock).
    QStringList lessonProblems() const { return m_lessonProblems; }
    // What the lesson shown says about itself (a shipped lesson's in the language shown).
    QString lessonTitle() const { return m_lessonTitle; }
    QString lessonNotes() const { return m_lessonNotes; }

    // The layout (geometry, docks) is kept in QSettings under layout/, with this version: a
    // layout saved by another version is not restored. Only when the application has an
    // organization name (the program sets one; tests choose theirs).
    static constexpr int kLayoutVersion = 3;
    static constexpr int kMaxRecentFiles = 10;
    static constexpr int kMaxRecentLessons = 10;

signals:
    // The user chose another language ("", "en" or "pt_BR"): the program builds the window
    // again in it.
    void languageChangeRequested(const QString& language);

protected:
    bool event(QEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;
    void showEvent(QShowEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    // Presentation mode's docks: the layout kept to come back to, the side docks put away,
    // and on a narrow screen the pixel inspector among the scan view's tabs; and back. The
    // font, palette and full screen are setPresentationMode's.
    void enterPresentationLayout();
    void leavePresentationLayout();
    // The pixel inspector from the left side into the tabs of the scan view (presentation
    // mode on a narrow screen), when both are where the window put them.
    void movePixelInspectorRight();
    void saveLayout() const;
    void restoreLayout();
    // The menus, one function each (main_window_actions.cpp), and their submenus.
    void createActions();
    void createFileMenu();
    void addLayoutMenus(QMenu* file);
    void addExportMenu(QMenu* file);
    void createEditMenu();
    void createViewMenu();
    void addLanguageMenu(QMenu* view);
    void createStepMenu();
    void addClickerKeys();
    void createShadingMenu();
    void addRulesMenu(QMenu* shading);
    void addProjectionMenu(QMenu* shading);
    void createHelpMenu();
    void addLessonMenus(QMenu* file);
    void refreshRecentLessons();
    void openLessonDialog();
    void saveLessonDialog();
    // The lesson's scene, settings and edits in a copy of the document; `problems` gets what
    // could not be restored.
    SceneDocument lessonDocument(const Lesson& lesson, const QDir& base, QStringList& problems);
    void applyPendingView(const RenderedFrame& frame);
    // Another object, command file or the default scene replaces a lesson's: its text goes,
    // and its image size and near plane give way to 800 x 600 and the automatic near plane.
    void leaveLesson();
    void createDocks();
    QDockWidget* addDock(const QString& title, const QString& name, QWidget* widget,
                         Qt::DockWidgetArea area, bool scrolls = false,
                         const QString& fullTitle = {});
    // Dock layout (main_window_docks.cpp).
    void updateDockTabTips();
    QList<QDockWidget*> shownDocks(Qt::DockWidgetArea area) const;
    int tabBarWidth(const QList<QDockWidget*>& docks) const;
    int contentWidth(const QList<QDockWidget*>& docks) const;
    void restoreFill();
    QDockWidget* fillTarget() const;
    void requestRender();
    void updateTimeLabel();
    void updateBusy();
    void onFrameReady(const RenderedFrame& frame);
    // Gives the frame to the inspection and every dock, and builds its replay.
    void adoptFrame(const RenderedFrame& frame);
    void onReplayBuilt(std::shared_ptr<const rl::FrameReplay> replay);
    void onRenderFailed(const QString& message);
    void onCursorChanged();
    void updateOverlay();
    void showStageView(rl::StageId stage);
    void showError(const QString& message);
    void refreshMessages();
    void refreshSceneSummary();
    void onPixelHovered(QPoint pixel);
    void openDialog();
    void openPartDialog(SceneDocument::Part part);
    void openCommandFileDialog();
    void documentChanged();  // menus, title, messages, watched files, and a new render
    void updateBehindBanner();
    // Asks about unsaved edits of a part about to be replaced: false to stop.
    bool mayReplace(SceneDocument::Part part);
    void addRecentFile(const QString& path);
    void refreshRecentMenu();
    void watchSources();
    void onWatchedFileChanged(const QString& path);
    void reloadChangedFiles();
    // Writes a picture; false with `failure` (%1 the path, %2 why) shown when it cannot.
    bool writePng(const QImage& image, const QString& path, const QString& failure);
    void exportDialog();
    void exportDisplayedDialog();
    void exportBufferDialog(int which);
    void exportSequenceDialog();
    void exportAnimationDialog();
    void compareDialog();
    // The Check dock, hidden until File > Check My Renderer..., beside `beside`.
    void setUpCheckDock(QDockWidget* beside);
    void showCheckMarks();
    void onAnimationPlaying(bool playing);
    void about();
    void showShortcuts();
    void updateClickerKeys();
    // The lecture layout (main_window_lecture.cpp): made for the cursor's stage now, or once
    // the events in hand are handled; the docks' widths for the window.
    void applyLectureLayout();
    void scheduleLectureLayout();
    void fitLectureDocks();
    void rememberLectureChoices();  // which dock shows a stage with two (m_lectureChoices)
    // The teacher's own presentation layout kept (F7 gives it back), and the stages' views
    // the lecture will show.
    void keepOwnLayout();
    void applyTextZoom();
    void showLectureCaption(QDockWidget* dock);  // null: the caption taken away
    bool keyForWindow(const QKeyEvent* key) const;
    void addTeachingActions(QMenu* view);
    void keepKeysFromNumberBoxes();  // installs the application's filter (filterNumberBoxKey)

    SceneDocument m_document;
    std::unique_ptr<QObject> m_numberBoxKeys;  // the application's filter, gone first
    RenderController* m_controller = nullptr;
    ReplayBuilder* m_replayBuilder = nullptr;
    Inspection* m_inspection = nullptr;
    RenderedFrame m_frame;
    QString m_lastError;
    std::optional<rl::ReplayCursor> m_cursorToRestore;
    // While a value is being dragged in the Edit dock, each new frame's image is shown at once
    // and the docks take the newest frame when the edits pause (m_adoptTimer): the image
    // follows the drag without waiting for every dock to recompute.
    QElapsedTimer m_lastEdit;
    QTimer m_adoptTimer;
    std::optional<RenderedFrame> m_waitingFrame;
    std::shared_ptr<const rl::FrameReplay> m_waitingReplay;  // the waiting frame's, if built
    QImage m_coverage;  // the frame's spans, tinted (scan conversion seen as a stage)
    std::weak_ptr<const rl::FrameTrace> m_coverageFrame;

    FrameImageView* m_view = nullptr;
    StageStrip* m_stageStrip = nullptr;
    SteppingBar* m_steppingBar = nullptr;
    BreakpointsView* m_breakpoints = nullptr;
    CameraBasisView* m_cameraBasis = nullptr;
    VertexTableView* m_vertexTable = nullptr;
    NormalsView* m_normals = nullptr;
    ProjectionView* m_projection = nullptr;
    ScanlineView* m_scanline = nullptr;
    PixelInspector* m_inspector = nullptr;
    EditPanel* m_edit = nullptr;
    AnimationPanel* m_animation = nullptr;
    ComparePanel* m_compare = nullptr;
    QDockWidget* m_compareDock = nullptr;
    bool m_compareShown = false;  // the Compare dock was shown once (floated the first time)
    CheckPanel* m_check = nullptr;
    QDockWidget* m_checkDock = nullptr;
    bool m_checkShown = false;  // the Check dock was shown once (floated the first time)
    QTemporaryDir m_checkFrames;  // their frame, written for the Compare dock
    QListWidget* m_messages = nullptr;
    QTextBrowser* m_summary = nullptr;
    QLabel* m_pixelLabel = nullptr;
    QLabel* m_timeLabel = nullptr;  // the last frame's time; "rendering..." while busy
    QProgressBar* m_busyBar = nullptr;
    QToolButton* m_cancelButton = nullptr;
    QActionGroup* m_shadingGroup = nullptr;
    QActionGroup* m_rulesGroup = nullptr;
    QActionGroup* m_projectionGroup = nullptr;
    QMenu* m_rulesMenu = nullptr;
    QWidget* m_behindBanner = nullptr;
    QLabel* m_behindText = nullptr;
    QPushButton* m_behindButton = nullptr;
    AccuracyPanel* m_accuracy = nullptr;
    ZBufferView* m_zbuffer = nullptr;
    PainterView* m_painter = nullptr;
    QByteArray m_defaultLayout;
    QMenu* m_shadingMenu = nullptr;
    QMenu* m_imageMenu = nullptr;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_recentLessonsMenu = nullptr;
    // The lesson shown (its title and text), and what opening it could not restore.
    QString m_lessonTitle, m_lessonNotes, m_lessonExample;
    bool m_lessonTitleIsExample = false, m_lessonNotesAreExample = false;  // the program's own
    QStringList m_lessonProblems;
    // A lesson's cursor, pixel and zoom, waiting for the first frame of its scene.
    struct PendingView {
        quint64 generation = 0;  // RenderController's request the lesson's scene went in
        std::optional<rl::ReplayCursor> cursor;
        std::optional<QPoint> pixel;
        std::optional<double> zoom;
        std::optional<QPointF> centre;
    };
    std::optional<PendingView> m_pendingView;
    QMenu* m_exportViewMenu = nullptr;
    QList<QAction*> m_clickerActions;  // arrows and space: stepping in front of a class
    QAction* m_presentationAction = nullptr;
    QByteArray m_layoutBeforePresentation;
    QStringList m_hiddenByPresentation;               // the side docks it put away, to come back
    QHash<const QDockWidget*, QString> m_fullTitles;  // for the tooltips of short titles
    bool m_fitDocks = true;  // the layout is the program's, not the user's: fit it to the window
    bool m_fitDocksBeforePresentation = true;
    QByteArray m_layoutBeforeFill;  // empty unless a dock fills the window
    QPointer<QDockWidget> m_filledDock;
    QAction* m_fillAction = nullptr;
    bool m_wasFullScreen = false;
    // The lecture layout: chosen, what it shows now (laid out again only when that changes),
    // and the teacher's own presentation layout to give back.
    bool m_lectureLayout = true;
    bool m_lectureQueued = false;
    struct LectureShown {
        QDockWidget* stage = nullptr;
        QDockWidget* edit = nullptr;
        bool image = false;
        QSize window;
        bool operator==(const LectureShown&) const = default;
    };
    LectureShown m_lectureShown;
    QByteArray m_presentationOwnLayout;
    QHash<int, QString> m_lectureChoices;  // stage: its other dock in front, when one was
    QLabel* m_lectureCaption = nullptr;
    QPointer<QDockWidget> m_captionDock;
    struct CaptionKey {  // what the caption was made for
        quint64 frame = ~quint64(0);
        rl::StageId stage = rl::StageId::CameraBasis;
        qint64 triangle = -1;  // the selected one
        bool operator==(const CaptionKey&) const = default;
    };
    CaptionKey m_captionKey;
    QAction* m_lectureAction = nullptr;
    bool m_liveEdits = false;
    QAction* m_liveEditsAction = nullptr;
    double m_textZoom = 1.0;
    // The window's keys that act wherever the focus is, even in a number box.
    QList<QAction*> m_alwaysActions;
    bool m_handingOver = false;
    QFont m_normalFont;
    QPalette m_normalPalette;

    QFileSystemWatcher m_watcher;
    QTimer m_reloadTimer;  // editors write in several steps: read once they are done
    QStringList m_changedFiles;
    int m_reloadAttempts = 0;
};

}  // namespace rasterlab
