// Teaching from a projector: the lecture layout (presentation mode's screen given to the
// stage being stepped, the image beside it once it has something drawn), the text zoom of
// the docks' contents, live edits in presentation mode, and the window's keys kept from the
// number boxes that would swallow them.
#include <QAbstractSpinBox>
#include <QApplication>
#include <QDockWidget>
#include <QKeyEvent>
#include <QLineEdit>
#include <QStatusBar>

#include <algorithm>
#include <array>
#include <cmath>

#include "app/window/main_window.h"
#include "views/frame_image_view.h"
#include "views/stepping_bar.h"

namespace rasterlab {

namespace {

// The docks of the seven stages, in the lecture's order.
constexpr std::array<const char*, rl::kStageCount> kStageDocks = {
    "cameraBasisDock", "vertexTableDock", "normalsDock",       "projectionDock",
    "scanlineDock",    "zbufferDock",     "pixelInspectorDock"};

// The text zoom's steps, from small to large; 1 is the window's own size.
constexpr std::array<double, 9> kTextZooms = {0.8, 0.9, 1.0, 1.15, 1.3, 1.5, 1.75, 2.0, 2.5};

bool isNumberBox(const QWidget* w) {
    for (; w; w = w->parentWidget())
        if (qobject_cast<const QAbstractSpinBox*>(w)) return true;
    return false;
}

// The application's filter that hands the window's keys back from number boxes.
class NumberBoxKeys : public QObject {
public:
    explicit NumberBoxKeys(MainWindow* window) : QObject(window), m_window(window) {}
    bool eventFilter(QObject* watched, QEvent* event) override {
        return m_window->filterNumberBoxKey(watched, event);
    }

private:
    MainWindow* m_window;
};

}  // namespace

void MainWindow::keepKeysFromNumberBoxes() {
    qApp->installEventFilter(new NumberBoxKeys(this));
}

QString MainWindow::stageDockName(rl::StageId stage) {
    return QLatin1String(kStageDocks[static_cast<std::size_t>(stage)]);
}

bool MainWindow::lectureLayoutShown() const {
    return m_inspection->presentation() && m_lectureLayout;
}

QDockWidget* MainWindow::lectureDock() const {
    return findChild<QDockWidget*>(stageDockName(m_inspection->stage()));
}

bool MainWindow::lectureShowsImage() const {
    // Stages 1 to 4 draw nothing: the image is black until the scan (whose spans it tints),
    // or until a step at a finer granularity has tested a pixel.
    if (!m_inspection->frame()) return false;
    if (m_inspection->stage() >= rl::StageId::ScanConversion) return true;
    return m_inspection->canStep() && m_inspection->cursor().fragments > 0;
}

void MainWindow::setLectureLayout(bool on) {
    if (on == m_lectureLayout) return;
    {
        const QSignalBlocker block(m_lectureAction);
        m_lectureAction->setChecked(on);
    }
    if (!m_inspection->presentation()) {
        m_lectureLayout = on;  // the choice for the next presentation
        return;
    }
    restoreFill();
    if (on) {
        m_presentationOwnLayout = saveState(kLayoutVersion);  // the teacher's, to come back to
        m_lectureLayout = true;
        m_lectureShown = {};
        applyLectureLayout();
    } else {
        m_lectureLayout = false;
        centralWidget()->show();
        restoreState(m_presentationOwnLayout, kLayoutVersion);
        QMetaObject::invokeMethod(this, &MainWindow::fitDocks, Qt::QueuedConnection);
    }
    statusBar()->showMessage(on ? tr("Lecture layout: the stage being stepped fills the screen "
                                     "(F7: your own layout)")
                                : tr("Your own layout (F7: the lecture layout again)"),
                             6000);
}

void MainWindow::setLiveEdits(bool on) {
    {
        const QSignalBlocker block(m_liveEditsAction);
        m_liveEditsAction->setChecked(on);
    }
    m_liveEdits = on;
    auto* edit = findChild<QDockWidget*>(QStringLiteral("editDock"));
    if (!edit) return;
    if (lectureLayoutShown()) {
        applyLectureLayout();
    } else if (m_inspection->presentation()) {
        edit->setVisible(on);
        if (on) edit->raise();
    }
}

void MainWindow::scheduleLectureLayout() {
    if (!lectureLayoutShown() || m_lectureQueued) return;
    m_lectureQueued = true;
    QMetaObject::invokeMethod(
        this,
        [this] {
            m_lectureQueued = false;
            applyLectureLayout();
        },
        Qt::QueuedConnection);
}

void MainWindow::applyLectureLayout() {
    if (!lectureLayoutShown() || isFilled()) return;
    QDockWidget* stage = lectureDock();
    auto* edit = m_liveEdits ? findChild<QDockWidget*>(QStringLiteral("editDock")) : nullptr;
    const bool image = lectureShowsImage();
    const LectureShown shown{stage, edit, image, size()};
    if (shown == m_lectureShown) return;  // stepping within a stage changes nothing here
    m_lectureShown = shown;
    // The other docks put away (floating ones stay where the teacher put them).
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        if (dock != stage && dock != edit && !dock->isFloating() && !dock->isHidden())
            dock->hide();
    // The stage on the right of the image, the edits on its left: always the same places.
    if (stage) {
        if (!stage->isFloating() && dockWidgetArea(stage) != Qt::RightDockWidgetArea)
            addDockWidget(Qt::RightDockWidgetArea, stage);
        stage->show();
        stage->raise();
    }
    if (edit) {
        if (!edit->isFloating() && dockWidgetArea(edit) != Qt::LeftDockWidgetArea)
            addDockWidget(Qt::LeftDockWidgetArea, edit);
        edit->show();
    }
    centralWidget()->setVisible(image || !stage);
    fitLectureDocks();
    QMetaObject::invokeMethod(this, &MainWindow::fitLectureDocks, Qt::QueuedConnection);
}

void MainWindow::fitLectureDocks() {
    if (!lectureLayoutShown() || isFilled()) return;
    QDockWidget* stage = lectureDock();
    auto* edit = m_liveEdits ? findChild<QDockWidget*>(QStringLiteral("editDock")) : nullptr;
    QList<QDockWidget*> docks;
    QList<int> widths;
    const int w = width();
    if (edit && !edit->isFloating()) {
        docks << edit;
        widths << int(kLectureEditShare * w);
    }
    if (stage && !stage->isFloating()) {
        const double share = centralWidget()->isVisible() ? kLectureStageShare : 1.0;
        docks << stage;
        widths << int(share * w);
    }
    if (!docks.isEmpty()) resizeDocks(docks, widths, Qt::Horizontal);
}

double MainWindow::textZoom() const {
    return m_textZoom;
}

void MainWindow::setTextZoom(double zoom) {
    m_textZoom = std::clamp(zoom, kTextZooms.front(), kTextZooms.back());
    applyTextZoom();
}

void MainWindow::zoomText(int steps) {
    // The nearest step, then so many steps on.
    const auto nearest = std::min_element(kTextZooms.begin(), kTextZooms.end(),
                                          [this](double a, double b) {
                                              return std::abs(a - m_textZoom) <
                                                     std::abs(b - m_textZoom);
                                          });
    const auto at = std::clamp<std::ptrdiff_t>((nearest - kTextZooms.begin()) + steps, 0,
                                               std::ptrdiff_t(kTextZooms.size()) - 1);
    setTextZoom(kTextZooms[std::size_t(at)]);
    statusBar()->showMessage(tr("Text size %1 %").arg(std::lround(m_textZoom * 100)), 3000);
}

void MainWindow::applyTextZoom() {
    // Only the size is set, so the docks' contents follow the window's font in everything
    // else; at 1 they take the window's font again (presentation mode's, too).
    const double base = QApplication::font().pointSizeF();
    for (QDockWidget* dock : findChildren<QDockWidget*>()) {
        QWidget* content = dock->widget();
        if (!content) continue;
        if (m_textZoom == 1.0 || base <= 0) {
            content->setFont(QFont());
        } else {
            QFont font;
            font.setPointSizeF(base * m_textZoom);
            content->setFont(font);
        }
    }
}

bool MainWindow::keyForWindow(const QKeyEvent* key) const {
    // A number box keeps its digits, signs, arrows up and down, and editing keys; the
    // window's keys (stepping, export, fill, presentation, zoom) go to the window. In
    // presentation mode the clicker's keys (Right, Left, Space, Home, End) step too.
    const QKeyCombination pressed = key->keyCombination();
    const QKeySequence sequence(pressed);
    for (const QAction* action : m_alwaysActions)
        for (const QKeySequence& shortcut : action->shortcuts())
            if (shortcut == sequence) return true;
    if (m_inspection->presentation())
        for (const QAction* action : m_clickerActions)
            if (action->shortcut() == sequence) return true;
    return false;
}

bool MainWindow::filterNumberBoxKey(QObject* watched, QEvent* event) {
    // The override a line edit asks for keeps a shortcut from firing: refused for the
    // window's keys while a number box of this window has the focus.
    if (event->type() != QEvent::ShortcutOverride) return false;
    auto* widget = qobject_cast<QWidget*>(watched);
    if (!widget || widget->window() != this || !isNumberBox(widget)) return false;
    auto* key = static_cast<QKeyEvent*>(event);
    // Up and Down are the box's own, even where a clicker's arrows step.
    if (key->modifiers() == Qt::NoModifier &&
        (key->key() == Qt::Key_Up || key->key() == Qt::Key_Down)) {
        key->accept();
        return true;
    }
    if (!keyForWindow(key)) return false;
    key->ignore();
    return true;
}

}  // namespace rasterlab
