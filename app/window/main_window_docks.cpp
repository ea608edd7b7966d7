// The docks' layout on screens of every size: short tab titles with the full title in a
// tooltip, dock widths that let each tab bar show its tabs whole, and View > Fill the Window:
// one dock (or the image) over the whole window, for a projector, and the layout given back.
#include <QApplication>
#include <QDockWidget>
#include <QEvent>
#include <QHelpEvent>
#include <QMouseEvent>
#include <QScrollArea>
#include <QScrollBar>
#include <QStatusBar>
#include <QStyle>
#include <QTabBar>
#include <QTimer>
#include <QToolTip>

#include <algorithm>

#include "app/window/main_window.h"
#include "views/frame_image_view.h"

namespace rasterlab {

namespace {

// Whether a point of a dock (its own coordinates) is on its title bar.
bool onTitleBar(const QDockWidget* dock, QPoint pos) {
    const QWidget* content = dock->widget();
    return content && pos.y() >= 0 && pos.y() < content->geometry().top();
}

}  // namespace

bool MainWindow::event(QEvent* event) {
    // A press on the window itself is on a separator between docks: the user sizes them now.
    if (event->type() == QEvent::MouseButtonPress) m_fitDocks = false;
    const bool done = QMainWindow::event(event);
    // The layout puts each dock's title on its tab, as its tooltip too: the full title
    // instead.
    if (event->type() == QEvent::LayoutRequest) updateDockTabTips();
    return done;
}

void MainWindow::showEvent(QShowEvent* event) {
    QMainWindow::showEvent(event);
    if (m_fitDocks) QMetaObject::invokeMethod(this, &MainWindow::fitDocks, Qt::QueuedConnection);
}

void MainWindow::resizeEvent(QResizeEvent* event) {
    QMainWindow::resizeEvent(event);
    if (lectureLayoutShown()) {
        QMetaObject::invokeMethod(this, &MainWindow::fitLectureDocks, Qt::QueuedConnection);
        return;
    }
    if (m_fitDocks && isVisible())
        QMetaObject::invokeMethod(this, &MainWindow::fitDocks, Qt::QueuedConnection);
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event) {
    // A left dock's content grown wider than the dock (a pixel picked in large text): the
    // side widened again, while the window fits its docks.
    if (event->type() == QEvent::LayoutRequest && m_fitDocks && isVisible() && !isFilled() &&
        !qobject_cast<QDockWidget*>(watched)) {
        for (QObject* o = watched->parent(); o && o != this; o = o->parent()) {
            auto* dock = qobject_cast<QDockWidget*>(o);
            if (!dock) continue;
            if (!dock->isFloating() && dockWidgetArea(dock) == Qt::LeftDockWidgetArea &&
                dock->width() < int(0.45 * width()) && contentWidth({dock}) > dock->width())
                QMetaObject::invokeMethod(this, &MainWindow::fitDocks, Qt::QueuedConnection);
            break;
        }
        return QMainWindow::eventFilter(watched, event);
    }
    auto* dock = qobject_cast<QDockWidget*>(watched);
    if (!dock || dock->isFloating()) return QMainWindow::eventFilter(watched, event);
    if (event->type() == QEvent::ToolTip) {
        const auto* help = static_cast<QHelpEvent*>(event);
        if (onTitleBar(dock, help->pos())) {
            QToolTip::showText(help->globalPos(), m_fullTitles.value(dock), dock);
            return true;
        }
    } else if (event->type() == QEvent::MouseButtonDblClick) {
        // Not floating the dock (QDockWidget's own double-click): filling the window.
        const auto* mouse = static_cast<QMouseEvent*>(event);
        if (mouse->button() == Qt::LeftButton && onTitleBar(dock, mouse->position().toPoint())) {
            toggleFill(dock);
            return true;
        }
    }
    return QMainWindow::eventFilter(watched, event);
}

void MainWindow::updateDockTabTips() {
    for (QTabBar* bar : findChildren<QTabBar*>(Qt::FindDirectChildrenOnly)) {
        for (int i = 0; i < bar->count(); ++i) {
            for (auto it = m_fullTitles.cbegin(); it != m_fullTitles.cend(); ++it)
                if (it.key()->windowTitle() == bar->tabText(i) && bar->tabToolTip(i) != *it)
                    bar->setTabToolTip(i, *it);
        }
    }
}

QList<QDockWidget*> MainWindow::shownDocks(Qt::DockWidgetArea area) const {
    QList<QDockWidget*> docks;
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        if (dock->toggleViewAction()->isChecked() && !dock->isFloating() &&
            dockWidgetArea(dock) == area)
            docks << dock;
    return docks;
}

int MainWindow::tabBarWidth(const QList<QDockWidget*>& docks) const {
    // The widest group of tabbed docks, each tab its title and the style's margins.
    const QFontMetrics metrics(QApplication::font("QTabBar"));
    const int space = style()->pixelMetric(QStyle::PM_TabBarTabHSpace);
    int widest = 0;
    for (QDockWidget* dock : docks) {
        QList<QDockWidget*> group = tabifiedDockWidgets(dock);
        group << dock;
        int width = 0;
        for (QDockWidget* tab : group)
            if (docks.contains(tab)) width += metrics.horizontalAdvance(tab->windowTitle()) + space;
        if (group.size() > 1) widest = std::max(widest, width);
    }
    return widest;
}

int MainWindow::contentWidth(const QList<QDockWidget*>& docks) const {
    // The widest minimum of a dock's scrolled content, with the dock's frame and a vertical
    // scroll bar beside it.
    int widest = 0;
    for (QDockWidget* dock : docks) {
        const auto* scroll = qobject_cast<const QScrollArea*>(dock->widget());
        if (!scroll || !scroll->widget()) continue;
        const QScrollBar* bar = scroll->verticalScrollBar();
        const int frame = dock->width() - scroll->viewport()->width() +
                          (bar->isVisible() ? 0 : bar->sizeHint().width());
        widest = std::max(widest,
                          scroll->widget()->minimumSizeHint().width() + std::clamp(frame, 0, 60));
    }
    return widest;
}

void MainWindow::fitDocks() {
    // Each side as wide as its tabs need, and at least 30% (left: room for the pixel
    // inspector's table) and a third (right) of the window; the image takes the rest. The
    // left side also as wide as its docks' contents need, up to 45% (the pixel inspector's
    // table in presentation mode's large text); the stage views on the right scale their
    // pictures instead. Each side's docks share its height. The lecture layout has its own.
    if (isFilled() || lectureLayoutShown()) return;
    constexpr int kFrame = 20;  // the dock area's frame and margins around its tab bar
    struct Side {
        Qt::DockWidgetArea area;
        double share;
        bool fitsContent;
    };
    const Side sides[] = {{Qt::LeftDockWidgetArea, 0.3, true},
                          {Qt::RightDockWidgetArea, 0.32, false}};
    for (const auto& [area, share, fitsContent] : sides) {
        const QList<QDockWidget*> docks = shownDocks(area);
        if (docks.isEmpty()) continue;
        int width = std::max(int(share * this->width()), tabBarWidth(docks) + kFrame);
        if (fitsContent)
            width = std::max(width, std::min(contentWidth(docks), int(0.45 * this->width())));
        resizeDocks({docks.front()}, {width}, Qt::Horizontal);
        // One dock per row: the first of each tab group.
        QList<QDockWidget*> rows;
        for (QDockWidget* dock : docks) {
            bool tabbed = false;
            for (QDockWidget* row : rows) tabbed = tabbed || tabifiedDockWidgets(row).contains(dock);
            if (!tabbed) rows << dock;
        }
        if (rows.size() > 1) resizeDocks(rows, QList<int>(rows.size(), height()), Qt::Vertical);
    }
}

QDockWidget* MainWindow::filledDock() const {
    return m_filledDock;
}

bool MainWindow::isFilled() const {
    return !m_layoutBeforeFill.isEmpty();
}

void MainWindow::toggleFill(QDockWidget* dock) {
    if (isFilled()) {
        restoreFill();
        return;
    }
    // In the lecture layout, the stage being stepped (else the panel under the pointer).
    if (!dock && lectureLayoutShown()) dock = lectureDock();
    if (!dock) dock = fillTarget();
    m_layoutBeforeFill = saveState(kLayoutVersion);
    m_filledDock = dock;
    // The other docks hidden; for a dock, the image too, so that the dock takes its place.
    for (QDockWidget* other : findChildren<QDockWidget*>())
        if (other != dock && !other->isFloating()) other->hide();
    if (dock) {
        centralWidget()->hide();
        dock->show();
        dock->raise();
    }
    m_fillAction->setChecked(true);
    statusBar()->showMessage(
        tr("%1 fills the window: F11 or a double-click on its title gives the layout back")
            .arg(dock ? dock->windowTitle() : tr("The image")),
        8000);
}

void MainWindow::restoreFill() {
    if (!isFilled()) return;
    centralWidget()->show();
    restoreState(m_layoutBeforeFill, kLayoutVersion);
    m_layoutBeforeFill.clear();
    m_filledDock = nullptr;
    const QSignalBlocker block(m_fillAction);
    m_fillAction->setChecked(false);
    if (lectureLayoutShown()) {
        m_lectureShown = {};
        scheduleLectureLayout();  // the cursor may have moved on while the dock filled
    }
}

QDockWidget* MainWindow::fillTarget() const {
    // The panel under the pointer (what the teacher points at), else the one holding the
    // focus; none (the image) when the pointer is on the image, or nothing else says.
    const auto dockOf = [this](QWidget* w) -> QDockWidget* {
        for (; w && w != this; w = w->parentWidget())
            if (auto* dock = qobject_cast<QDockWidget*>(w)) return dock;
        return nullptr;
    };
    QWidget* under = QApplication::widgetAt(QCursor::pos());
    if (under && under->window() == this) {
        if (under == m_view || m_view->isAncestorOf(under)) return nullptr;
        if (QDockWidget* dock = dockOf(under)) return dock;
    }
    QWidget* focus = QApplication::focusWidget();
    if (focus && (focus == m_view || m_view->isAncestorOf(focus))) return nullptr;
    return dockOf(focus);
}

}  // namespace rasterlab
