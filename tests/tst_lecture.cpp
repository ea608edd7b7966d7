// Teaching from a projector at 1280x720 (issue 48): the lecture layout following the stepping
// cursor from stage to stage, the window's keys acting with the focus in a number box, the
// text zoom kept in a lesson file, and a language switch retranslating the open lesson.
#include <QtTest>

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QScrollArea>
#include <QScrollBar>
#include <QSpinBox>
#include <QTemporaryDir>

#include "app/documents/examples.h"
#include "app/documents/lesson_file.h"
#include "app/window/main_window.h"
#include "app/window/translators.h"
#include "tests/offscreen_screens.h"
#include "pipeline/render/frame_trace.h"
#include "pipeline/stages/depth_test.h"
#include "pipeline/stages/scan_conversion.h"
#include "views/frame_image_view.h"
#include "views/inspection.h"
#include "views/stepping_bar.h"

using rasterlab::Lesson;
using rasterlab::MainWindow;

namespace {

constexpr int kTimeoutMs = 20000;

QScreen* screenOf(QSize size) {
    for (QScreen* screen : QGuiApplication::screens())
        if (screen->size() == size) return screen;
    return nullptr;
}

bool showAt1280x720(MainWindow& window) {
    QScreen* screen = screenOf(QSize(1280, 720));
    if (!screen) return false;
    window.setScreen(screen);
    window.move(screen->geometry().topLeft());
    window.resize(1280, 720);
    window.show();
    QApplication::setActiveWindow(&window);
    return QTest::qWaitForWindowExposed(&window) && QTest::qWaitForWindowActive(&window);
}

bool waitUntilReady(const MainWindow& window) {
    return QTest::qWaitFor(
        [&] { return !window.lessonViewPending() && window.isReadyToStep(); }, kTimeoutMs);
}

void settle() {
    for (int k = 0; k < 5; ++k) {
        QCoreApplication::processEvents();
        QTest::qWait(20);
    }
}

// The docks on screen, by name, sorted.
QStringList shownDocks(const MainWindow& window) {
    QStringList names;
    for (const QDockWidget* dock : window.findChildren<QDockWidget*>())
        if (dock->isVisible()) names << dock->objectName();
    names.sort();
    return names;
}

QAction* action(const MainWindow& window, const char* name) {
    return window.findChild<QAction*>(QLatin1String(name));
}

}  // namespace

class TestLecture : public QObject {
    Q_OBJECT

private slots:
    void lectureFollowsTheCursor_data();
    void lectureFollowsTheCursor();
    void ownLayoutAndBack();
    void liveEditsStayInTheLecture();
    void keysActFromANumberBox_data();
    void keysActFromANumberBox();
    void numberBoxKeepsItsOwnKeys();
    void textZoomKeptInALesson();
    void languageSwitchRetranslatesTheLesson();
    void lessonsChooseTheStageDock_data();
    void lessonsChooseTheStageDock();
    void fillFollowsThePointerAndTheLecture();
    void shortcutsDialogFitsTheScreen_data();
    void shortcutsDialogFitsTheScreen();

private:
    rasterlab::Translators m_translators;
};

void TestLecture::lectureFollowsTheCursor_data() {
    QTest::addColumn<QString>("language");
    QTest::newRow("en") << QStringLiteral("en");
    QTest::newRow("pt_BR") << QStringLiteral("pt_BR");
}

void TestLecture::lectureFollowsTheCursor() {
    // The goblet stepped by stage from the start: each stage's dock alone on screen; the
    // image gives its room while nothing is drawn (stages 1 to 4), and stands beside the
    // dock from the scan on.
    QFETCH(QString, language);
    m_translators.install(language);
    const auto english = qScopeGuard([&] { m_translators.install(QStringLiteral("en")); });
    MainWindow window;
    QVERIFY(showAt1280x720(window));
    QVERIFY(window.openExample(QStringLiteral("goblet")));
    QVERIFY(waitUntilReady(window));
    const auto leave = qScopeGuard([&] { window.setPresentationMode(false); });
    QVERIFY(window.lectureLayout());  // the presentation's own layout, unless chosen off
    window.setPresentationMode(true);
    rasterlab::Inspection* inspection = window.inspection();
    inspection->setGranularity(rl::StepGranularity::Stage);
    inspection->toStart();
    settle();
    QVERIFY(window.lectureLayoutShown());
    for (rl::StageId stage : rl::kAllStages) {
        const QString where = QStringLiteral("stage %1").arg(int(stage) + 1);
        QCOMPARE(inspection->stage(), stage);
        settle();
        const QString name = MainWindow::stageDockName(stage);
        QCOMPARE(shownDocks(window), QStringList{name});
        auto* dock = window.findChild<QDockWidget*>(name);
        QCOMPARE(window.lectureDock(), dock);
        const bool drawn = stage >= rl::StageId::ScanConversion;
        QCOMPARE(window.lectureShowsImage(), drawn);
        QCOMPARE(window.centralWidget()->isVisible(), drawn);
        const double share = double(dock->width()) / window.width();
        if (drawn) {
            // Most of the window, the image the rest: never half the screen for the image.
            const double own = stage == rl::StageId::Shading ? MainWindow::kLectureLightingShare
                                                             : MainWindow::kLectureStageShare;
            QVERIFY2(std::abs(share - own) < 0.02, qPrintable(QStringLiteral("%1: %2 of the width")
                                                                  .arg(where).arg(share)));
            QVERIFY2(window.centralWidget()->width() >= 0.22 * window.width(), qPrintable(where));
        } else {
            QVERIFY2(share > 0.97, qPrintable(QStringLiteral("%1: %2 of the width")
                                                  .arg(where).arg(share)));
        }
        QVERIFY2(dock->height() > 0.7 * window.height(), qPrintable(where));
        // Its title: the stage's key numbers in large print.
        auto* caption = qobject_cast<QLabel*>(dock->titleBarWidget());
        QVERIFY2(caption && caption->isVisible(), qPrintable(where));
        QVERIFY(caption->font().pointSizeF() > QApplication::font().pointSizeF() * 1.2);
        const auto& frame = *window.currentFrame();
        // Written in either language with the numbers as the views write them.
        const bool en = language == QLatin1String("en");
        if (stage == rl::StageId::DepthTest)
            QVERIFY2(caption->text().contains(
                         (en ? QStringLiteral("%1 fragments tested, %2 written, %3 rejected")
                             : QStringLiteral("%1 fragmentos testados, %2 escritos, %3 rejeitados"))
                             .arg(frame.depth->fragments)
                             .arg(frame.depth->passed)
                             .arg(frame.depth->rejected)),
                     qPrintable(caption->text()));
        if (stage == rl::StageId::ScanConversion)
            QVERIFY2(caption->text().contains(
                         (en ? QStringLiteral("%1 pixels covered") : QStringLiteral("%1 pixels cobertos"))
                             .arg(frame.scan->pixels)),
                     qPrintable(caption->text()));
        if (stage == rl::StageId::Shading) {
            // The lit pixel's history and its formula's last line on screen, unscrolled.
            auto* scroll = dock->findChild<QScrollArea*>();
            auto* formula = dock->findChild<QLabel*>(QStringLiteral("pixelFormula"));
            QVERIFY(scroll && formula && formula->isVisible());
            QVERIFY(!formula->text().isEmpty());
            QVERIFY(!scroll->verticalScrollBar()->isVisible());
            QVERIFY(!scroll->horizontalScrollBar()->isVisible());
            const QRect shown(formula->mapTo(scroll->viewport(), QPoint(0, 0)), formula->size());
            QVERIFY2(scroll->viewport()->rect().contains(shown),
                     qPrintable(QStringLiteral("formula at %1,%2 %3x%4")
                                    .arg(shown.x()).arg(shown.y()).arg(shown.width())
                                    .arg(shown.height())));
        }
        if (stage != rl::StageId::Shading) window.steppingBar()->stepForwardAction()->trigger();
    }
    // Back a stage (Page Up): the z-buffer's dock again, and the pixel inspector's own title.
    window.steppingBar()->stepBackAction()->trigger();
    settle();
    QCOMPARE(shownDocks(window), QStringList{QStringLiteral("zbufferDock")});
    QVERIFY(!window.findChild<QDockWidget*>(QStringLiteral("pixelInspectorDock"))->titleBarWidget());
    // Leaving gives back the docks as they were before presenting.
    window.setPresentationMode(false);
    settle();
    QVERIFY(window.centralWidget()->isVisible());
    QVERIFY(shownDocks(window).size() > 3);
    QVERIFY(!window.findChild<QDockWidget*>(QStringLiteral("zbufferDock"))->titleBarWidget());
}

void TestLecture::ownLayoutAndBack() {
    // F7: the teacher's own presentation layout (the image and the stage views), and again the
    // lecture layout.
    m_translators.install(QStringLiteral("en"));
    MainWindow window;
    QVERIFY(showAt1280x720(window));
    QVERIFY(waitUntilReady(window));
    const auto leave = qScopeGuard([&] { window.setPresentationMode(false); });
    QCOMPARE(action(window, "lectureLayoutAction")->shortcut(), QKeySequence(Qt::Key_F7));
    window.setPresentationMode(true);
    window.inspection()->setGranularity(rl::StepGranularity::Stage);
    window.inspection()->setStage(rl::StageId::Normals);
    settle();
    QCOMPARE(shownDocks(window), QStringList{QStringLiteral("normalsDock")});
    QTest::keyClick(&window, Qt::Key_F7);
    settle();
    QVERIFY(!window.lectureLayoutShown());
    QVERIFY(window.centralWidget()->isVisible());
    const QStringList own = shownDocks(window);
    QVERIFY2(own.contains(QStringLiteral("normalsDock")) && own.size() >= 2,
             qPrintable(own.join(QLatin1Char(' '))));
    QVERIFY(!own.contains(QStringLiteral("editDock")));  // put away while presenting
    QTest::keyClick(&window, Qt::Key_F7);
    settle();
    QVERIFY(window.lectureLayoutShown());
    QCOMPARE(shownDocks(window), QStringList{QStringLiteral("normalsDock")});
}

void TestLecture::liveEditsStayInTheLecture() {
    // F9: the Edit dock on the left of the lecture layout; an edit there renders at once.
    m_translators.install(QStringLiteral("en"));
    MainWindow window;
    QVERIFY(showAt1280x720(window));
    QVERIFY(waitUntilReady(window));
    const auto leave = qScopeGuard([&] {
        window.setLiveEdits(false);
        window.setPresentationMode(false);
    });
    window.setPresentationMode(true);
    window.inspection()->setGranularity(rl::StepGranularity::Stage);
    window.inspection()->setStage(rl::StageId::Shading);
    settle();
    QTest::keyClick(&window, Qt::Key_F9);
    settle();
    QVERIFY(window.liveEdits());
    auto* edit = window.findChild<QDockWidget*>(QStringLiteral("editDock"));
    QVERIFY(edit->isVisible());
    QCOMPARE(window.dockWidgetArea(edit), Qt::LeftDockWidgetArea);
    QCOMPARE(shownDocks(window),
             (QStringList{QStringLiteral("editDock"), QStringLiteral("pixelInspectorDock")}));
    const double share = double(edit->width()) / window.width();
    QVERIFY2(share > 0.26 && share < 0.34, qPrintable(QString::number(share)));
    // The stage keeps the most of the rest, the image a fifth of the window.
    auto* inspector = window.findChild<QDockWidget*>(QStringLiteral("pixelInspectorDock"));
    QVERIFY2(inspector->width() > 0.45 * window.width(), qPrintable(QString::number(inspector->width())));
    QVERIFY(window.centralWidget()->width() > 0.15 * window.width());
    // Still presenting, and the Edit dock's number boxes are there to change the scene.
    QVERIFY(window.presentationMode());
    QVERIFY(!edit->findChildren<QDoubleSpinBox*>().isEmpty());
    QTest::keyClick(&window, Qt::Key_F9);
    settle();
    QVERIFY(!edit->isVisible());
}

void TestLecture::keysActFromANumberBox_data() {
    QTest::addColumn<QString>("actionName");
    QTest::addColumn<QKeySequence>("key");
    QTest::addColumn<bool>("presenting");
    const auto row = [](const char* name, QKeySequence key, bool presenting = false) {
        QTest::addRow("%s %s%s", name, qPrintable(key.toString()),
                      presenting ? " presenting" : "")
            << QString::fromLatin1(name) << key << presenting;
    };
    row("stepForwardAction", QKeySequence(Qt::Key_PageDown));
    row("stepForwardAction", QKeySequence(Qt::Key_F10));
    row("stepBackAction", QKeySequence(Qt::Key_PageUp));
    row("stepBackAction", QKeySequence(Qt::SHIFT | Qt::Key_F10));
    row("playAction", QKeySequence(Qt::Key_F6));
    row("toStartAction", QKeySequence(Qt::CTRL | Qt::Key_Home));
    row("toEndAction", QKeySequence(Qt::CTRL | Qt::Key_End));
    row("continueAction", QKeySequence(Qt::Key_F8));
    row("exportAction", QKeySequence(Qt::CTRL | Qt::Key_E));
    row("fillWindowAction", QKeySequence(Qt::Key_F11));
    row("presentationAction", QKeySequence(Qt::Key_F5));
    row("lectureLayoutAction", QKeySequence(Qt::Key_F7));
    row("liveEditsAction", QKeySequence(Qt::Key_F9));
    row("textLargerAction", QKeySequence(Qt::CTRL | Qt::Key_Plus));
    row("textLargerAction", QKeySequence(Qt::CTRL | Qt::Key_Equal));
    row("textSmallerAction", QKeySequence(Qt::CTRL | Qt::Key_Minus));
    row("textNormalAction", QKeySequence(Qt::CTRL | Qt::Key_0));
    row("imageFitAction", QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_0));
    row("imageZoomInAction", QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_Equal));
    row("imageZoomOutAction", QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_Minus));
    // A clicker's keys, while presenting.
    row("stepForwardAction", QKeySequence(Qt::Key_Right), true);
    row("stepBackAction", QKeySequence(Qt::Key_Left), true);
    row("playAction", QKeySequence(Qt::Key_Space), true);
    row("stepForwardAction", QKeySequence(Qt::Key_PageDown), true);
    row("exportAction", QKeySequence(Qt::CTRL | Qt::Key_E), true);
}

void TestLecture::keysActFromANumberBox() {
    // The focus in a number box (the stepping bar's speed, the Edit dock's values): each of
    // the window's keys still triggers its action, once.
    QFETCH(QString, actionName);
    QFETCH(QKeySequence, key);
    QFETCH(bool, presenting);
    m_translators.install(QStringLiteral("en"));
    MainWindow window;
    QVERIFY(showAt1280x720(window));
    QVERIFY(waitUntilReady(window));
    const auto leave = qScopeGuard([&] {
        window.setLiveEdits(false);
        window.setPresentationMode(false);
    });
    if (presenting) {
        window.setLiveEdits(true);  // the Edit dock's boxes on screen while presenting
        window.setPresentationMode(true);
        settle();
    }
    QAction* target = window.findChild<QAction*>(actionName);
    QVERIFY2(target, qPrintable(actionName));
    // Dialogs the action opens (Export) are closed as they come.
    QTimer closer;
    connect(&closer, &QTimer::timeout, [] {
        if (QWidget* modal = QApplication::activeModalWidget()) modal->close();
    });
    closer.start(50);
    // The speed box, and a value of the Edit dock (shown unless presenting without it).
    QList<QAbstractSpinBox*> boxes{window.findChild<QSpinBox*>(QStringLiteral("speedBox"))};
    auto* edit = window.findChild<QDockWidget*>(QStringLiteral("editDock"));
    if (edit->isVisible()) boxes << edit->findChildren<QDoubleSpinBox*>().first();
    for (QAbstractSpinBox* box : boxes) {
        QVERIFY(box);
        QApplication::setActiveWindow(&window);  // a dialog closed may have left it inactive
        box->setFocus();
        QTRY_VERIFY(box->hasFocus());
        const QString text = box->text();
        QSignalSpy triggered(target, &QAction::triggered);
        const QKeyCombination combination = key[0];
        QTest::keyClick(box, combination.key(), combination.keyboardModifiers());
        QTRY_COMPARE_WITH_TIMEOUT(triggered.count(), 1, 2000);
        // Undone, where it changed the window.
        if (actionName == QLatin1String("presentationAction") ||
            actionName == QLatin1String("fillWindowAction") ||
            actionName == QLatin1String("lectureLayoutAction") ||
            actionName == QLatin1String("liveEditsAction") ||
            actionName == QLatin1String("playAction"))
            target->trigger();
        settle();
        if (box->isVisible()) QCOMPARE(box->text(), text);  // the box did not take the key
    }
}

void TestLecture::numberBoxKeepsItsOwnKeys() {
    // Up and digits change the number box, and step nothing; presenting, too.
    m_translators.install(QStringLiteral("en"));
    MainWindow window;
    QVERIFY(showAt1280x720(window));
    QVERIFY(waitUntilReady(window));
    const auto leave = qScopeGuard([&] { window.setPresentationMode(false); });
    auto* speed = window.findChild<QSpinBox*>(QStringLiteral("speedBox"));
    for (const bool presenting : {false, true}) {
        window.setPresentationMode(presenting);
        settle();
        speed->setValue(10);
        speed->setFocus();
        QTRY_VERIFY(speed->hasFocus());
        const rl::ReplayCursor before = window.inspection()->cursor();
        QTest::keyClick(speed, Qt::Key_Up);
        QCOMPARE(speed->value(), 11);
        speed->selectAll();
        QTest::keyClicks(speed, QStringLiteral("25"));
        QCOMPARE(speed->value(), 25);
        QTest::keyClick(speed, Qt::Key_Backspace);
        QCOMPARE(speed->text().remove(speed->suffix()), QStringLiteral("2"));
        QCOMPARE(window.inspection()->cursor(), before);
    }
}

void TestLecture::textZoomKeptInALesson() {
    // Ctrl++ twice: the docks' text 1.3 times the window's; saved in a lesson, read back
    // from its text, and restored in another window.
    m_translators.install(QStringLiteral("en"));
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("zoomed.rasterlab"));
    const auto content = [](const MainWindow& w) {
        return w.findChild<QDockWidget*>(QStringLiteral("vertexTableDock"))->widget();
    };
    {
        MainWindow window;
        QVERIFY(showAt1280x720(window));
        QVERIFY(waitUntilReady(window));
        const double normal = content(window)->font().pointSizeF();
        QCOMPARE(normal, QApplication::font().pointSizeF());
        QTest::keyClick(&window, Qt::Key_Plus, Qt::ControlModifier);
        QTest::keyClick(&window, Qt::Key_Equal, Qt::ControlModifier);
        QCOMPARE(window.textZoom(), 1.3);
        QCOMPARE(content(window)->font().pointSizeF(), normal * 1.3);
        // Presentation mode's larger text, and the zoom on top of it.
        window.setPresentationMode(true);
        QCOMPARE(content(window)->font().pointSizeF(), QApplication::font().pointSizeF() * 1.3);
        window.setPresentationMode(false);
        QCOMPARE(content(window)->font().pointSizeF(), normal * 1.3);
        QVERIFY(window.saveLesson(path));
        QTest::keyClick(&window, Qt::Key_0, Qt::ControlModifier);
        QCOMPARE(window.textZoom(), 1.0);
        QCOMPARE(content(window)->font().pointSizeF(), normal);
        QTest::keyClick(&window, Qt::Key_Minus, Qt::ControlModifier);
        QCOMPARE(window.textZoom(), 0.9);
    }
    rl::Diagnostics diagnostics;
    const auto lesson = rasterlab::readLesson(path, diagnostics);
    QVERIFY(bool(lesson));
    QCOMPARE(lesson->textZoom, std::optional<double>(1.3));
    QVERIFY(rasterlab::lessonJson(*lesson).contains("\"text_zoom\": 1.3"));
    const auto again = rasterlab::parseLesson(rasterlab::lessonJson(*lesson), path, diagnostics);
    QVERIFY(bool(again));
    QCOMPARE(*again, *lesson);
    MainWindow window;
    QVERIFY(showAt1280x720(window));
    QVERIFY(window.openLesson(path));
    QVERIFY(waitUntilReady(window));
    QCOMPARE(window.textZoom(), 1.3);
    QCOMPARE(content(window)->font().pointSizeF(), QApplication::font().pointSizeF() * 1.3);
}

void TestLecture::languageSwitchRetranslatesTheLesson() {
    // View > Language while a shipped lesson is open: the program installs the new language,
    // takes the window's view as a lesson, and builds the window again with it (gui_main.cpp).
    // The lesson's title and notes are then the new language's.
    m_translators.install(QStringLiteral("en"));
    const auto back = qScopeGuard([&] { m_translators.install(QStringLiteral("en")); });
    Lesson view;
    {
        MainWindow window;
        QVERIFY(showAt1280x720(window));
        QVERIFY(window.openExample(QStringLiteral("triangle")));
        QVERIFY(waitUntilReady(window));
        QCOMPARE(window.lessonTitle(), QStringLiteral("One triangle"));
        m_translators.install(QStringLiteral("pt_BR"));
        view = window.currentLesson(QDir());
        QVERIFY(window.handOver());
    }
    QCOMPARE(view.example, QStringLiteral("triangle"));
    QVERIFY2(view.title.isEmpty(), qPrintable(view.title));  // the program's, not kept
    QVERIFY(view.notes.isEmpty());
    MainWindow window;
    QVERIFY(showAt1280x720(window));
    window.restoreView(view);
    QCOMPARE(window.lessonTitle(), QStringLiteral("Um triângulo"));
    QCOMPARE(window.lessonNotes(), rasterlab::exampleNotes(QStringLiteral("triangle")));
    QVERIFY(window.lessonNotes().startsWith(QStringLiteral("Um único triângulo")));
}

void TestLecture::lessonsChooseTheStageDock_data() {
    QTest::addColumn<QString>("lesson");
    QTest::addColumn<int>("stage");
    QTest::addColumn<QString>("dock");
    QTest::addColumn<bool>("presentingFirst");
    for (const bool first : {false, true}) {
        const char* when = first ? "opened presenting" : "then presenting";
        QTest::addRow("near-plane %s", when) << QStringLiteral("near-plane")
                                              << int(rl::StageId::Projection)
                                              << QStringLiteral("nearClipDock") << first;
        QTest::addRow("painter-cycle %s", when) << QStringLiteral("painter-cycle")
                                                 << int(rl::StageId::DepthTest)
                                                 << QStringLiteral("painterDock") << first;
        QTest::addRow("goblet %s", when) << QStringLiteral("goblet")
                                          << int(rl::StageId::Projection)
                                          << QStringLiteral("projectionDock") << first;
    }
}

void TestLecture::lessonsChooseTheStageDock() {
    // The near-plane lesson raises the clipping dock, the painter's the painter's: the lecture
    // shows those for their stages.
    QFETCH(QString, lesson);
    QFETCH(int, stage);
    QFETCH(QString, dock);
    QFETCH(bool, presentingFirst);
    m_translators.install(QStringLiteral("en"));
    MainWindow window;
    QVERIFY(showAt1280x720(window));
    const auto leave = qScopeGuard([&] { window.setPresentationMode(false); });
    if (presentingFirst) window.setPresentationMode(true);
    QVERIFY(window.openExample(lesson));
    QVERIFY(waitUntilReady(window));
    window.setPresentationMode(true);
    window.inspection()->setGranularity(rl::StepGranularity::Stage);
    window.inspection()->setStage(rl::StageId(stage));
    settle();
    QCOMPARE(shownDocks(window), QStringList{dock});
}

void TestLecture::fillFollowsThePointerAndTheLecture() {
    // F11 with the image holding the focus and the pointer over the z-buffer dock: the dock
    // fills the window (it was the image). In the lecture layout: the stage's dock, and F11
    // again gives the lecture layout back.
    m_translators.install(QStringLiteral("en"));
    MainWindow window;
    QVERIFY(showAt1280x720(window));
    QVERIFY(waitUntilReady(window));
    auto* zbuffer = window.findChild<QDockWidget*>(QStringLiteral("zbufferDock"));
    zbuffer->show();
    zbuffer->raise();
    settle();
    window.imageView()->setFocus();
    QTRY_VERIFY(window.imageView()->hasFocus());
    QCursor::setPos(zbuffer->mapToGlobal(zbuffer->rect().center()));
    QTRY_COMPARE(QApplication::widgetAt(QCursor::pos()) &&
                     zbuffer->isAncestorOf(QApplication::widgetAt(QCursor::pos())),
                 true);
    QTest::keyClick(window.imageView(), Qt::Key_F11);
    QVERIFY(window.isFilled());
    QCOMPARE(window.filledDock(), zbuffer);
    QTest::keyClick(&window, Qt::Key_F11);
    QVERIFY(!window.isFilled());
    // Presenting, at the z-buffer: F11 fills with the stage's dock, the pointer on the image.
    const auto leave = qScopeGuard([&] { window.setPresentationMode(false); });
    window.setPresentationMode(true);
    window.inspection()->setGranularity(rl::StepGranularity::Stage);
    window.inspection()->setStage(rl::StageId::DepthTest);
    settle();
    QCOMPARE(shownDocks(window), QStringList{QStringLiteral("zbufferDock")});
    QVERIFY(window.centralWidget()->isVisible());
    QCursor::setPos(window.centralWidget()->mapToGlobal(window.centralWidget()->rect().center()));
    QTest::keyClick(&window, Qt::Key_F11);
    QCOMPARE(window.filledDock(), zbuffer);
    QVERIFY(!window.centralWidget()->isVisible());
    QTest::keyClick(&window, Qt::Key_F11);
    settle();
    QVERIFY(!window.isFilled());
    QVERIFY(window.lectureLayoutShown());
    QCOMPARE(shownDocks(window), QStringList{QStringLiteral("zbufferDock")});
    QVERIFY(window.centralWidget()->isVisible());
    const double share = double(zbuffer->width()) / window.width();
    QVERIFY2(share > 0.68 && share < 0.76, qPrintable(QString::number(share)));
}

void TestLecture::shortcutsDialogFitsTheScreen_data() {
    QTest::addColumn<QString>("language");
    QTest::newRow("en") << QStringLiteral("en");
    QTest::newRow("pt_BR") << QStringLiteral("pt_BR");
}

void TestLecture::shortcutsDialogFitsTheScreen() {
    // F1 in presentation mode's large text at 1280x720: the dialog, its Close button
    // included, inside the screen (it was 810 px tall).
    QFETCH(QString, language);
    m_translators.install(language);
    const auto back = qScopeGuard([&] { m_translators.install(QStringLiteral("en")); });
    MainWindow window;
    QVERIFY(showAt1280x720(window));
    const auto leave = qScopeGuard([&] { window.setPresentationMode(false); });
    window.setPresentationMode(true);
    settle();
    QRect shown;
    bool closeInside = false;
    QTimer::singleShot(300, [&] {
        QWidget* dialog = QApplication::activeModalWidget();
        if (!dialog) return;
        shown = dialog->frameGeometry();
        if (auto* close = dialog->findChild<QAbstractButton*>())
            closeInside = dialog->rect().contains(QRect(close->mapTo(dialog, QPoint()), close->size()));
        dialog->close();
    });
    QTest::keyClick(&window, Qt::Key_F1);
    QVERIFY(shown.isValid());
    QVERIFY2(shown.height() <= 720 && shown.top() >= 0 && shown.bottom() < 720,
             qPrintable(QStringLiteral("%1,%2 %3x%4").arg(shown.x()).arg(shown.y())
                            .arg(shown.width()).arg(shown.height())));
    QVERIFY(shown.width() <= 1280);
    QVERIFY(closeInside);
    // Every key the window has for a lecture is listed.
    const QString text = MainWindow::shortcutsText();
    for (const char* key : {"F7", "F9", "F11", "Ctrl++", "Ctrl+Alt+0"})
        QVERIFY2(text.contains(QLatin1String(key)), key);
}

int main(int argc, char* argv[]) {
    // A 1280x720 screen: the projector's.
    QTemporaryDir dir;
    if (!useOffscreenScreens(dir, {QSize(1280, 720)})) return 1;
    QApplication app(argc, argv);
    TestLecture test;
    return QTest::qExec(&test, argc, argv);
}

#include "tst_lecture.moc"
