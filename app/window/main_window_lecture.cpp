// Teaching from a projector: the lecture layout (presentation mode's screen given to the
// stage being stepped, the image beside it once it has something drawn), the text zoom of
// the docks' contents, live edits in presentation mode, and the window's keys kept from the
// number boxes that would swallow them.
#include <QAbstractSpinBox>
#include <QDoubleSpinBox>
#include <QApplication>
#include <QDockWidget>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QScrollArea>
#include <QScrollBar>
#include <QStatusBar>
#include <QTimer>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "app/window/main_window.h"
#include "app/window/edit_panel.h"
#include "pipeline/render/frame_trace.h"
#include "pipeline/stages/camera_basis.h"
#include "pipeline/stages/depth_test.h"
#include "pipeline/stages/projection.h"
#include "pipeline/stages/scan_conversion.h"
#include "pipeline/stages/shading.h"
#include "pipeline/stages/view_transform.h"
#include "views/normals_model.h"
#include "views/stage_strip.h"
#include "views/frame_image_view.h"
#include "views/stepping_bar.h"
#include "views/zbuffer_view.h"

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

// The application's filter that hands the window's keys back from number boxes. The window
// owns it outside Qt's children, so it is gone before the window's widgets are taken down.
class NumberBoxKeys : public QObject {
public:
    explicit NumberBoxKeys(MainWindow* window) : m_window(window) {}
    bool eventFilter(QObject* watched, QEvent* event) override {
        return event->type() == QEvent::ShortcutOverride &&
               m_window->filterNumberBoxKey(watched, event);
    }

private:
    MainWindow* m_window;
};

// The caption over the lecture's dock: the dock gives its title bar the height of the hint,
// which for wrapped text would be that of a narrow label; the hint is the height it is given.
class CaptionLabel : public QLabel {
public:
    using QLabel::QLabel;
    QSize sizeHint() const override {
        const QSize hint = QLabel::sizeHint();
        return {hint.width(), minimumHeight() > 0 ? minimumHeight() : hint.height()};
    }
};

}  // namespace

void MainWindow::keepKeysFromNumberBoxes() {
    m_numberBoxKeys = std::make_unique<NumberBoxKeys>(this);
    qApp->installEventFilter(m_numberBoxKeys.get());
}

QString MainWindow::stageDockName(rl::StageId stage) {
    return QLatin1String(kStageDocks[static_cast<std::size_t>(stage)]);
}

bool MainWindow::lectureLayoutShown() const {
    return m_inspection->presentation() && m_lectureLayout;
}

// Seed 002's and 004's presentations of a stage, tabbed with its own view.
constexpr std::pair<rl::StageId, const char*> kOtherStageDocks[] = {
    {rl::StageId::Projection, "nearClipDock"},
    {rl::StageId::ScanConversion, "trapezoidDock"},
    {rl::StageId::DepthTest, "painterDock"}};

QDockWidget* MainWindow::lectureDock() const {
    const rl::StageId stage = m_inspection->stage();
    if (const QString other = m_lectureChoices.value(int(stage)); !other.isEmpty())
        if (auto* dock = findChild<QDockWidget*>(other)) return dock;
    return findChild<QDockWidget*>(stageDockName(stage));
}

void MainWindow::keepOwnLayout() {
    rememberLectureChoices();
    m_presentationOwnLayout = saveState(kLayoutVersion);  // the teacher's own, for F7
    m_lectureShown = {};  // the lecture's docks are placed again
}

void MainWindow::rememberLectureChoices() {
    // A stage's other presentation in front of its tab group (a lesson's: the near-plane
    // lesson raises the clipping dock, the painter's lesson the painter's) is the one the
    // lecture shows for that stage; the painter's algorithm shades without a z-buffer.
    m_lectureChoices.clear();
    for (const auto& [stage, name] : kOtherStageDocks) {
        auto* dock = findChild<QDockWidget*>(QLatin1String(name));
        if (dock && !dock->isHidden() && !dock->visibleRegion().isEmpty())
            m_lectureChoices.insert(int(stage), QLatin1String(name));
    }
    if (m_document.settings().shading == rl::ShadingModel::Painter)
        m_lectureChoices.insert(int(rl::StageId::DepthTest), QStringLiteral("painterDock"));
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
        keepOwnLayout();
        m_lectureLayout = true;
        applyLectureLayout();
    } else {
        m_lectureLayout = false;
        showLectureCaption(nullptr);
        centralWidget()->show();
        restoreState(m_presentationOwnLayout, kLayoutVersion);
        if (m_liveEdits)
            if (auto* edit = findChild<QDockWidget*>(QStringLiteral("editDock"))) edit->show();
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
    // The light first in view (the camera's values above it are seldom changed in class),
    // the material below it.
    if (on)
        if (auto* scroll = qobject_cast<QScrollArea*>(edit->widget()))
            if (QWidget* light = m_edit->spinBox(SceneDocument::Field::LightPosition))
                // Once the dock has its new size (laid out after the events in hand).
                QTimer::singleShot(150, scroll, [scroll, light] {
                    const int top = light->mapTo(scroll->widget(), QPoint()).y();
                    scroll->verticalScrollBar()->setValue(top - 3 * light->height());
                });
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
    showLectureCaption(stage);  // the frame's numbers change with each new frame
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
        // With the edits beside it, the stage gives up their width, and the image keeps a
        // fifth of the window.
        const double own = m_inspection->stage() == rl::StageId::Shading ? kLectureLightingShare
                                                                          : kLectureStageShare;
        const double image = centralWidget()->isVisible() ? 1.0 - own : 0.0;
        const double share =
            widths.isEmpty() ? 1.0 - image : 1.0 - kLectureEditShare - std::min(image, 0.2);
        docks << stage;
        widths << int(share * w);
    }
    if (!docks.isEmpty()) resizeDocks(docks, widths, Qt::Horizontal);
    // The caption as tall as its lines at the dock's width (a wrapped label's own size hint
    // guesses a narrower width, and so more lines).
    if (m_lectureCaption && stage && stage->titleBarWidget() == m_lectureCaption) {
        const int width = stage->isFloating() || docks.isEmpty() ? stage->width() : widths.last();
        m_lectureCaption->setFixedHeight(m_lectureCaption->heightForWidth(std::max(width, 100)));
    }
}

QString MainWindow::lectureCaption(rl::StageId stage) const {
    // The stage's name and its key numbers for the whole frame, in the language shown.
    const QString name = QStringLiteral("%1 %2").arg(int(stage) + 1).arg(StageStrip::stageName(stage));
    const rl::FrameTrace* t = m_frame.trace.get();
    if (!t || !t->skipReason(stage).empty()) return name;
    // Written as the views write them (a point for decimals, no thousands separator), so
    // that the caption's numbers read as the dock's.
    const auto n = [](std::size_t count) { return QString::number(qulonglong(count)); };
    const auto x = [](double v) { return QString::number(v, 'g', 4); };
    const auto vec = [&](const rl::dvec3& v) {
        return QStringLiteral("(%1, %2, %3)").arg(x(v.x), x(v.y), x(v.z));
    };
    QString numbers;
    switch (stage) {
        case rl::StageId::CameraBasis:
            numbers = tr("|N| = %1 · U = %2 · V = %3 · N = %4")
                          .arg(x(t->cameraBasis->nLength), vec(t->cameraBasis->u),
                               vec(t->cameraBasis->v), vec(t->cameraBasis->n));
            break;
        case rl::StageId::ViewTransform:
            numbers = tr("%1 vertices: %2 in front of the camera, %3 behind")
                          .arg(n(t->scene->vertexCount()), n(t->view->verticesInFront),
                               n(t->view->verticesBehind));
            break;
        case rl::StageId::Normals: {
            std::size_t back = 0;  // facing away from the camera: n · pView > 0
            for (std::size_t d = 0; d < t->scene->draws.size(); ++d)
                if (const auto& mesh = t->scene->draws[d].mesh; mesh && d < t->projection->draws.size())
                    for (std::uint8_t b : backFaces(t->projection->draws[d].pView, *mesh)) back += b;
            numbers = tr("%1 triangle normals: %2 front faces, %3 back faces · %4 vertex normals")
                          .arg(n(t->scene->triangleCount()), n(t->scene->triangleCount() - back),
                               n(back), n(t->scene->vertexCount()));
            // The selected triangle's (the picked pixel's), the one the view draws.
            if (const auto s = m_inspection->selectedTriangle();
                s && *s < t->projection->triangles.size()) {
                const rl::ScreenTriangle& st = t->projection->triangles[*s];
                const auto& normals = t->normals->draws.at(st.draw).triangle;
                if (st.source < normals.size())
                    numbers += tr(" · triangle %1: n = %2")
                                   .arg(n(st.source + 1), vec(rl::dvec3(normals[st.source])));
            }
            break;
        }
        case rl::StageId::Projection:
            numbers = tr("%1 triangles: %2 inside, %3 clipped, %4 behind · near plane w = %5")
                          .arg(n(t->scene->triangleCount()), n(t->projection->inside),
                               n(t->projection->clipped), n(t->projection->behind),
                               x(t->projection->nearW));
            break;
        case rl::StageId::ScanConversion:
            numbers = tr("%1 triangles → %2 spans, %3 pixels covered")
                          .arg(n(t->scan->triangleCount()), n(t->scan->spans.size()),
                               n(t->scan->pixels));
            break;
        case rl::StageId::DepthTest: {
            numbers = tr("%1 fragments tested, %2 written, %3 rejected")
                          .arg(n(t->depth->fragments), n(t->depth->passed), n(t->depth->rejected));
            // The depths kept, nearest and farthest, as the z-buffer view finds them.
            if (const DepthRange kept = coveredDepthRange(*t->depth); kept.valid)
                numbers += tr(" · z kept from %1 to %2").arg(x(kept.nearest), x(kept.farthest));
            break;
        }
        case rl::StageId::Shading:
            numbers = tr("%1 pixels shaded · N·L < 0: %2 · R·V < 0: %3 · clamped at 255: %4")
                          .arg(n(t->shading->shadedPixels), n(t->shading->lightBehind),
                               n(t->shading->noSpecular), n(t->shading->clampedPixels));
            break;
    }
    return QStringLiteral("<b>%1</b> &nbsp; %2").arg(name.toHtmlEscaped(), numbers.toHtmlEscaped());
}

void MainWindow::showLectureCaption(QDockWidget* dock) {
    // The dock's title bar, in the lecture layout: its stage's numbers in large print. This
    // runs at every step: the label changes only for another dock, frame, stage, selection
    // or text size.
    if (m_captionDock && m_captionDock != dock) m_captionDock->setTitleBarWidget(nullptr);
    m_captionDock = dock;
    if (!dock) return;
    bool changed = false;
    if (!m_lectureCaption) {
        m_lectureCaption = new CaptionLabel(this);
        m_lectureCaption->setObjectName(QStringLiteral("lectureCaption"));
        m_lectureCaption->setWordWrap(true);
        m_lectureCaption->setTextFormat(Qt::RichText);
        m_lectureCaption->setContentsMargins(8, 4, 8, 4);
        m_lectureCaption->setAutoFillBackground(true);
        QPalette palette = m_lectureCaption->palette();
        palette.setColor(QPalette::Window, QColor(40, 40, 40));
        palette.setColor(QPalette::WindowText, QColor(255, 220, 0));
        m_lectureCaption->setPalette(palette);
    }
    const double size = QApplication::font().pointSizeF() * kLectureCaptionScale * m_textZoom;
    if (m_lectureCaption->font().pointSizeF() != size) {
        QFont font;
        font.setPointSizeF(size);
        m_lectureCaption->setFont(font);
        changed = true;
    }
    const auto selected = m_inspection->selectedTriangle();
    const CaptionKey key{m_frame.generation, m_inspection->stage(),
                         selected ? qint64(*selected) : qint64(-1)};
    if (key != m_captionKey) {
        m_captionKey = key;
        m_lectureCaption->setText(lectureCaption(key.stage));
        changed = true;
    }
    if (dock->titleBarWidget() != m_lectureCaption) {
        dock->setTitleBarWidget(m_lectureCaption);
        changed = true;
    }
    m_lectureCaption->show();
    if (changed) fitLectureDocks();  // its height for the new text and font
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
    if (m_captionDock) showLectureCaption(m_captionDock);
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
