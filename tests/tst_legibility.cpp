// Legible on every screen: the main window at 1280x720, 1366x768 and 1920x1080, in English
// and Brazilian Portuguese, normal and in presentation mode, with every dock raised in turn.
// It fails, naming the dock, the widget and the text, where
//   - a label, button, check box, group box title, combo box, dock title, tab or header
//     section is too small for its text (elided text passes when a tooltip holds it all);
//   - a table cell's text does not fit its column, or a table or scroll area must scroll
//     sideways to show its columns;
//   - two sibling widgets overlap, or a toolbar hides items behind its extension button;
//   - two labels a custom-painted view drew (PaintedLabels) meet, or one leaves the view;
//   - the window cannot shrink to the screen, or opens larger than it.
// The window then fills itself with one dock and gives the layout back (View > Fill the
// Window).
//
// The offscreen platform gets three screens, one of each size, so that presentation mode
// (full screen) takes the size checked.
#include <QtTest>

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLayout>
#include <QPushButton>
#include <QRadioButton>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QStatusBar>
#include <QStyleOption>
#include <QTabBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QTextEdit>
#include <QToolBar>
#include <QToolButton>

#include "app/image_io.h"
#include "app/window/main_window.h"
#include "app/window/render_controller.h"
#include "app/window/translators.h"
#include "pipeline/analysis/mistakes.h"
#include "tests/offscreen_screens.h"
#include "views/frame_image_view.h"
#include "views/inspection.h"
#include "views/painted_labels.h"

using rasterlab::MainWindow;

namespace {

constexpr int kTimeoutMs = 20000;
constexpr int kSlack = 1;  // pixels of rounding allowed

// "QLabel pixelVerdict", with the chain of named parents up to the dock.
QString nameOf(const QWidget* w) {
    QString name = QString::fromLatin1(w->metaObject()->className());
    if (!w->objectName().isEmpty()) name += QLatin1Char(' ') + w->objectName();
    QStringList parents;
    for (const QWidget* p = w->parentWidget(); p && !qobject_cast<const QDockWidget*>(p) &&
                                               !qobject_cast<const QMainWindow*>(p);
         p = p->parentWidget())
        if (!p->objectName().isEmpty() && !p->objectName().startsWith(QLatin1String("qt_")))
            parents.prepend(p->objectName());
    if (!parents.isEmpty()) name += QStringLiteral(" in ") + parents.join(QLatin1Char('/'));
    return name;
}

QString withoutMnemonic(QString text) {
    text.replace(QStringLiteral("&&"), QStringLiteral("\x01"));
    text.remove(QLatin1Char('&'));
    text.replace(QLatin1Char('\x01'), QLatin1Char('&'));
    return text;
}

// Elided text ("…") passes when the tooltip holds every part of it.
bool elidedWithTooltip(const QString& text, const QString& tooltip) {
    if (!text.contains(QChar(0x2026)) || tooltip.isEmpty()) return false;
    for (const QString& part : text.split(QChar(0x2026), Qt::SkipEmptyParts))
        if (!tooltip.contains(part.trimmed())) return false;
    return true;
}

class Checker {
public:
    explicit Checker(QString where) : m_where(std::move(where)) {}
    const QStringList& findings() const { return m_findings; }
    void setWhere(const QString& where) { m_where = where; }

    // Every visible widget under root, root included.
    void tree(QWidget* root) {
        QList<QWidget*> all = root->findChildren<QWidget*>();
        all.prepend(root);
        for (QWidget* w : all) {
            if (!w->isVisible() || (w->isWindow() && w != root->window())) continue;
            if (w != root && w->window() != root->window()) continue;
            widget(w);
            siblings(w);
        }
    }

    void widget(QWidget* w) {
        if (auto* label = qobject_cast<QLabel*>(w)) this->label(label);
        if (auto* button = qobject_cast<QAbstractButton*>(w)) this->button(button);
        if (auto* box = qobject_cast<QGroupBox*>(w)) groupBox(box);
        if (auto* combo = qobject_cast<QComboBox*>(w)) comboBox(combo);
        if (auto* bar = qobject_cast<QTabBar*>(w)) tabBar(bar, false);
        if (auto* header = qobject_cast<QHeaderView*>(w)) this->header(header);
        if (auto* table = qobject_cast<QTableView*>(w)) cells(table);
        if (auto* scroll = qobject_cast<QScrollArea*>(w)) sideways(scroll);
        if (auto* text = qobject_cast<QTextEdit*>(w)) sideways(text);
        if (auto* painted = dynamic_cast<const rasterlab::PaintedLabels*>(w)) labels(w, *painted);
        if (auto* toolBar = qobject_cast<QToolBar*>(w)) extension(toolBar);
    }

    void fail(const QWidget* w, const QString& what) {
        m_findings << QStringLiteral("%1: %2: %3").arg(m_where, nameOf(w), what);
    }

    void label(const QLabel* label) {
        const QString text = label->text();
        if (text.isEmpty() || label->width() <= 0) return;
        const QString shown = QStringLiteral("\"%1\"").arg(text.left(80));
        if (elidedWithTooltip(text, label->toolTip())) return;
        if (label->wordWrap()) {
            // QLabel's own measure: the height at this width, and the longest word.
            const int need = label->heightForWidth(label->width());
            if (need > label->height() + kSlack)
                fail(label, QStringLiteral("%1 needs %2 px of height, has %3")
                                .arg(shown)
                                .arg(need)
                                .arg(label->height()));
            if (label->minimumSizeHint().width() > label->width() + kSlack)
                fail(label, QStringLiteral("%1 has a word wider than its %2 px")
                                .arg(shown)
                                .arg(label->width()));
            return;
        }
        const QSize need = label->sizeHint();
        if (need.width() > label->width() + kSlack || need.height() > label->height() + kSlack)
            fail(label, QStringLiteral("%1 needs %2x%3 px, has %4x%5")
                            .arg(shown)
                            .arg(need.width())
                            .arg(need.height())
                            .arg(label->width())
                            .arg(label->height()));
    }

    void button(const QAbstractButton* button) {
        const QString text = withoutMnemonic(button->text());
        if (text.isEmpty()) return;
        const auto* tool = qobject_cast<const QToolButton*>(button);
        if (tool && tool->toolButtonStyle() == Qt::ToolButtonIconOnly && !tool->icon().isNull())
            return;
        if (elidedWithTooltip(text, button->toolTip())) return;
        if (button->hasHeightForWidth()) {  // text that wraps (WrappingCheckBox)
            const int need = button->heightForWidth(button->width());
            if (need > button->height() + kSlack)
                fail(button, QStringLiteral("\"%1\" needs %2 px of height, has %3")
                                 .arg(text)
                                 .arg(need)
                                 .arg(button->height()));
            if (button->minimumSizeHint().width() > button->width() + kSlack)
                fail(button, QStringLiteral("\"%1\" has a word wider than its %2 px")
                                 .arg(text)
                                 .arg(button->width()));
            return;
        }
        int need = 0;
        if (qobject_cast<const QPushButton*>(button)) {
            // Fusion makes push buttons 80 px wide at least: measure the text and margins.
            const QStyle* style = button->style();
            need = button->fontMetrics().horizontalAdvance(text) +
                   style->pixelMetric(QStyle::PM_ButtonMargin, nullptr, button) +
                   2 * style->pixelMetric(QStyle::PM_DefaultFrameWidth, nullptr, button);
            if (!button->icon().isNull()) need += button->iconSize().width() + 4;
        } else {
            need = button->sizeHint().width();
        }
        if (need > button->width() + kSlack)
            fail(button, QStringLiteral("\"%1\" needs %2 px, has %3")
                             .arg(text)
                             .arg(need)
                             .arg(button->width()));
        if (button->fontMetrics().height() > button->height() + kSlack)
            fail(button, QStringLiteral("\"%1\" is %2 px high, its text %3")
                             .arg(text)
                             .arg(button->height())
                             .arg(button->fontMetrics().height()));
    }

    void groupBox(const QGroupBox* box) {
        if (box->title().isEmpty()) return;
        QStyleOptionGroupBox opt;
        opt.initFrom(box);
        opt.text = box->title();
        opt.lineWidth = 1;
        opt.textAlignment = box->alignment();
        opt.subControls = QStyle::SC_GroupBoxFrame | QStyle::SC_GroupBoxLabel;
        if (box->isCheckable()) opt.subControls |= QStyle::SC_GroupBoxCheckBox;
        const QRect title =
            box->style()->subControlRect(QStyle::CC_GroupBox, &opt, QStyle::SC_GroupBoxLabel, box);
        if (!box->rect().adjusted(0, 0, kSlack, 0).contains(title))
            fail(box, QStringLiteral("title \"%1\" needs %2 px, the box is %3")
                          .arg(box->title())
                          .arg(title.right() + 1)
                          .arg(box->width()));
    }

    void comboBox(const QComboBox* combo) {
        const QString text = combo->currentText();
        if (text.isEmpty() || combo->isEditable()) return;
        QStyleOptionComboBox opt;
        opt.initFrom(combo);
        opt.currentText = text;
        opt.subControls = QStyle::SC_All;
        const QRect field = combo->style()->subControlRect(QStyle::CC_ComboBox, &opt,
                                                           QStyle::SC_ComboBoxEditField, combo);
        int need = combo->fontMetrics().horizontalAdvance(text) + 2;
        if (!combo->itemIcon(combo->currentIndex()).isNull()) need += combo->iconSize().width() + 4;
        if (need > field.width() + kSlack && !elidedWithTooltip(text, combo->toolTip()))
            fail(combo, QStringLiteral("\"%1\" needs %2 px, its field has %3")
                            .arg(text)
                            .arg(need)
                            .arg(field.width()));
    }

    // Each tab shows its whole text inside the bar (no elision, no scrolling); a dock's tab
    // also has a tooltip (the dock's full title).
    void tabBar(const QTabBar* bar, bool docks) {
        const int space = bar->style()->pixelMetric(QStyle::PM_TabBarTabHSpace, nullptr, bar);
        for (int i = 0; i < bar->count(); ++i) {
            if (!bar->isTabVisible(i)) continue;
            const QString text = withoutMnemonic(bar->tabText(i));
            const QRect r = bar->tabRect(i);
            int need = bar->fontMetrics().size(Qt::TextShowMnemonic, text).width() + space;
            if (!bar->tabIcon(i).isNull()) need += bar->iconSize().width() + 4;
            if (need > r.width() + kSlack)
                fail(bar, QStringLiteral("tab \"%1\" needs %2 px, has %3")
                              .arg(text)
                              .arg(need)
                              .arg(r.width()));
            if (!bar->rect().contains(r))
                fail(bar, QStringLiteral("tab \"%1\" (%2, %3, %4x%5) leaves the bar of %6x%7 px")
                              .arg(text)
                              .arg(r.x())
                              .arg(r.y())
                              .arg(r.width())
                              .arg(r.height())
                              .arg(bar->width())
                              .arg(bar->height()));
            if (docks && bar->tabToolTip(i).isEmpty())
                fail(bar, QStringLiteral("tab \"%1\" has no tooltip").arg(text));
        }
    }

    void header(const QHeaderView* header) {
        const QAbstractItemModel* model = header->model();
        if (!model) return;
        const int margin = header->style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, header);
        QFont bold = header->font();
        bold.setBold(true);
        for (int i = 0; i < header->count(); ++i) {
            if (header->isSectionHidden(i)) continue;
            const QString text = model->headerData(i, header->orientation()).toString();
            if (text.isEmpty()) continue;
            // A section over a selected cell draws its title bold (highlightSections).
            bool highlighted = false;
            if (header->highlightSections() && header->selectionModel())
                for (const QModelIndex& index : header->selectionModel()->selectedIndexes())
                    highlighted = highlighted ||
                                  (header->orientation() == Qt::Horizontal ? index.column() == i
                                                                           : index.row() == i);
            const QFontMetrics metrics(highlighted ? bold : header->font());
            // A title on several lines (the pixel history's, in a narrow dock): each line across
            // its section, all of them down the header.
            const QSize lines = metrics.size(0, text);
            const int need = header->orientation() == Qt::Horizontal ? lines.width() + 2 * margin
                                                                     : lines.height();
            if (need > header->sectionSize(i) + kSlack)
                fail(header, QStringLiteral("section \"%1\" needs %2 px, has %3")
                                 .arg(text)
                                 .arg(need)
                                 .arg(header->sectionSize(i)));
            if (header->orientation() == Qt::Horizontal && lines.height() > header->height())
                fail(header, QStringLiteral("section \"%1\" needs %2 px of height, has %3")
                                 .arg(text)
                                 .arg(lines.height())
                                 .arg(header->height()));
        }
    }

    // The cells of the rows in view: their text in their column (a cell with its text in a
    // tooltip may elide it); the columns without sideways scrolling.
    void cells(const QTableView* table) {
        const QAbstractItemModel* model = table->model();
        if (!model) return;
        const QStyle* style = table->style();
        const int margin = 2 * (style->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, table) + 1);
        int failed = 0;  // two cells are enough to tell what is wrong
        for (int row = 0; row < std::min(model->rowCount(), 60) && failed < 2; ++row) {
            if (table->isRowHidden(row)) continue;
            for (int column = 0; column < model->columnCount(); ++column) {
                if (table->isColumnHidden(column)) continue;
                const QModelIndex index = model->index(row, column);
                const QString text = index.data().toString();
                if (text.isEmpty()) continue;
                QFont font = table->font();
                if (const QVariant f = index.data(Qt::FontRole); f.isValid())
                    font = f.value<QFont>();
                const QFontMetrics metrics(font);
                int width = table->columnWidth(column) - margin;
                if (!index.data(Qt::DecorationRole).isNull()) width -= table->iconSize().width() + 4;
                // Without wrapping, the text's own lines (a table may write a vector's
                // components one a line): the widest, and their height.
                const QStringList lines = text.split(QLatin1Char('\n'));
                int widest = 0;
                for (const QString& line : lines)
                    widest = std::max(widest, metrics.horizontalAdvance(line));
                const QRect need =
                    table->wordWrap()
                        ? metrics.boundingRect(QRect(0, 0, width, 100000), Qt::TextWordWrap, text)
                        : QRect(0, 0, widest,
                                metrics.height() + int(lines.size() - 1) * metrics.lineSpacing());
                const QString tip = index.data(Qt::ToolTipRole).toString();
                if ((need.width() > width + kSlack || need.height() > table->rowHeight(row)) &&
                    !tip.contains(text) && ++failed <= 2)
                    fail(table, QStringLiteral("cell (%1, %2) \"%3\" needs %4x%5 px, has %6x%7")
                                    .arg(row)
                                    .arg(column)
                                    .arg(text)
                                    .arg(need.width())
                                    .arg(need.height())
                                    .arg(width)
                                    .arg(table->rowHeight(row)));
            }
        }
        sideways(table);
    }

    void sideways(const QAbstractScrollArea* area) {
        // A table with more columns than a dock holds says so (the vertex table).
        if (area->property("scrollsSideways").toBool()) return;
        // An item view's scroll bar counts columns: its header tells the pixels.
        const auto* table = qobject_cast<const QTableView*>(area);
        const int wider = table ? table->horizontalHeader()->length() - area->viewport()->width()
                                : area->horizontalScrollBar()->maximum();
        if (wider > 0)
            fail(area, QStringLiteral("scrolls sideways: its content is %1 px wider than its "
                                      "%2 px")
                           .arg(wider)
                           .arg(area->viewport()->width()));
    }

    void labels(QWidget* view, const rasterlab::PaintedLabels& painted) {
        view->repaint();  // the labels of a paint at the current size
        const QList<QRect> rects = painted.labelRects();
        for (qsizetype i = 0; i < rects.size(); ++i) {
            if (!view->rect().adjusted(-kSlack, -kSlack, kSlack, kSlack).contains(rects[i]))
                fail(view, QStringLiteral("painted label %1 at (%2, %3, %4x%5) leaves the %6x%7 view")
                               .arg(i)
                               .arg(rects[i].x())
                               .arg(rects[i].y())
                               .arg(rects[i].width())
                               .arg(rects[i].height())
                               .arg(view->width())
                               .arg(view->height()));
            for (qsizetype j = i + 1; j < rects.size(); ++j)
                if (rects[i].intersects(rects[j]))
                    fail(view, QStringLiteral("painted labels %1 (%2, %3, %4x%5) and %6 (%7, %8, "
                                              "%9x%10) meet")
                                   .arg(i)
                                   .arg(rects[i].x())
                                   .arg(rects[i].y())
                                   .arg(rects[i].width())
                                   .arg(rects[i].height())
                                   .arg(j)
                                   .arg(rects[j].x())
                                   .arg(rects[j].y())
                                   .arg(rects[j].width())
                                   .arg(rects[j].height()));
        }
    }

    void extension(const QToolBar* bar) {
        for (const QWidget* child : bar->findChildren<QWidget*>(Qt::FindDirectChildrenOnly))
            if (child->isVisible() &&
                child->objectName() == QLatin1String("qt_toolbar_ext_button"))
                fail(bar, QStringLiteral("hides items behind its extension button"));
    }

    // Visible children of w that overlap one another, or stick out of it.
    void siblings(const QWidget* w) {
        QList<const QWidget*> shown;
        for (const QObject* o : w->children()) {
            const auto* child = qobject_cast<const QWidget*>(o);
            // Behind a tab, a dock is moved out of sight rather than hidden.
            if (child && child->isVisible() && !child->isWindow() &&
                child->geometry().intersects(w->rect()))
                shown << child;
        }
        const bool scrolled = w->objectName() == QLatin1String("qt_scrollarea_viewport");
        for (qsizetype i = 0; i < shown.size(); ++i) {
            const QRect a = shown[i]->geometry();
            if (!scrolled && !w->rect().contains(a) && !qobject_cast<const QTabBar*>(w))
                fail(shown[i], QStringLiteral("(%1, %2, %3x%4) sticks out of its parent %5 "
                                              "(%6x%7)")
                                   .arg(a.x())
                                   .arg(a.y())
                                   .arg(a.width())
                                   .arg(a.height())
                                   .arg(nameOf(w))
                                   .arg(w->width())
                                   .arg(w->height()));
            for (qsizetype j = i + 1; j < shown.size(); ++j)
                if (const QRect b = shown[j]->geometry(); a.intersects(b))
                    fail(shown[i], QStringLiteral("(%1, %2, %3x%4) overlaps %5 (%6, %7, %8x%9)")
                                       .arg(a.x())
                                       .arg(a.y())
                                       .arg(a.width())
                                       .arg(a.height())
                                       .arg(nameOf(shown[j]))
                                       .arg(b.x())
                                       .arg(b.y())
                                       .arg(b.width())
                                       .arg(b.height()));
        }
    }

    // A dock's title in its title bar, between its edge and its buttons.
    void dockTitle(const QDockWidget* dock) {
        if (dock->titleBarWidget()) return;
        QStyleOptionDockWidget opt;
        opt.initFrom(dock);
        opt.title = dock->windowTitle();
        opt.closable = dock->features() & QDockWidget::DockWidgetClosable;
        opt.movable = dock->features() & QDockWidget::DockWidgetMovable;
        opt.floatable = dock->features() & QDockWidget::DockWidgetFloatable;
        opt.rect = QRect(0, 0, dock->width(), dock->fontMetrics().height() + 6);
        const QRect text =
            dock->style()->subElementRect(QStyle::SE_DockWidgetTitleBarText, &opt, dock);
        const int need = dock->fontMetrics().horizontalAdvance(opt.title);
        if (need > text.width() + kSlack)
            fail(dock, QStringLiteral("title \"%1\" needs %2 px, has %3")
                           .arg(opt.title)
                           .arg(need)
                           .arg(text.width()));
    }

private:
    QString m_where;
    QStringList m_findings;
};

// The screens of the sizes checked, by size.
QScreen* screenOf(QSize size) {
    for (QScreen* screen : QGuiApplication::screens())
        if (screen->geometry().size() == size) return screen;
    return nullptr;
}

// The sizes checked: many projectors', small laptops' and full HD.
const QSize kScreenSizes[] = {QSize(1280, 720), QSize(1366, 768), QSize(1920, 1080)};

// The window shown on the screen of that size, filling it.
bool showOnScreen(MainWindow& window, QSize size) {
    QScreen* screen = screenOf(size);
    if (!screen) return false;
    window.setScreen(screen);
    window.move(screen->geometry().topLeft());
    window.resize(size);
    window.show();
    return QTest::qWaitForWindowExposed(&window);
}

bool waitForReplay(MainWindow& window) {
    return QTest::qWaitFor([&] { return window.isReadyToStep(); }, kTimeoutMs);
}

// The pixel on the knot's lower band picked, stepped by scanline to past the middle of the
// frame, and the frame compared with itself with the ambient times Od (the Compare dock,
// hidden until then): every view has something to show.
bool giveViewsContent(MainWindow& window, const QString& theirs) {
    if (!window.compareWithImage(theirs)) return false;
    rasterlab::Inspection* inspection = window.inspection();
    inspection->pickPixel(QPoint(400, 350));
    inspection->setGranularity(rl::StepGranularity::Scanline);
    const rl::FrameReplay* replay = inspection->replay();
    inspection->seek(replay->next(
        replay->atFragment(static_cast<std::uint32_t>(replay->fragments().size() * 6 / 10)),
        rl::StepGranularity::Scanline));
    return true;
}

void settle() {
    for (int k = 0; k < 4; ++k) {
        QCoreApplication::processEvents();
        QTest::qWait(10);
    }
}

// The docks the layout shows (raised or behind a tab).
QList<QDockWidget*> shownDocks(const MainWindow& window) {
    QList<QDockWidget*> docks;
    for (QDockWidget* dock : window.findChildren<QDockWidget*>())
        if (dock->toggleViewAction()->isChecked()) docks << dock;
    return docks;
}

// The docks' names, sorted: the order of the window's children changes as docks are shown.
QStringList names(const QList<QDockWidget*>& docks) {
    QStringList list;
    for (const QDockWidget* dock : docks) list << dock->objectName();
    list.sort();
    return list;
}

}  // namespace

class TestLegibility : public QObject {
    Q_OBJECT

private slots:
    void everyDock_data();
    void everyDock();
    void opensInsideTheScreen();
    void presentationLeavesTheImageRoom();
    void fillWindowWithDock();

private:
    rasterlab::Translators m_translators;
};

void TestLegibility::everyDock_data() {
    QTest::addColumn<QSize>("size");
    QTest::addColumn<QString>("language");
    QTest::addColumn<bool>("presenting");
    for (const QSize size : kScreenSizes)
        for (const char* language : {"en", "pt_BR"})
            for (const bool presenting : {false, true})
                QTest::addRow("%dx%d %s %s", size.width(), size.height(), language,
                              presenting ? "presenting" : "normal")
                    << size << QString::fromLatin1(language) << presenting;
}

void TestLegibility::everyDock() {
    QFETCH(QSize, size);
    QFETCH(QString, language);
    QFETCH(bool, presenting);
    m_translators.install(language);
    MainWindow window;
    QVERIFY2(showOnScreen(window, size),
             "no screen of that size (the offscreen platform's configuration), or not shown");
    QVERIFY2(waitForReplay(window), "the default scene was not ready to step through");
    // Presentation mode changes the application's font and palette: put back whatever
    // happens.
    const auto leave = qScopeGuard([&] { window.setPresentationMode(false); });
    // A pixel picked once presenting: the docks were fitted before it had a history.
    if (presenting) {
        window.setPresentationMode(true);
        settle();
    }
    const QTemporaryDir dir;
    const QString theirs = dir.filePath(QStringLiteral("theirs.png"));
    {
        auto ours = rl::renderOurFrame(window.currentFrame()->scene);
        QVERIFY(ours);
        auto image = rl::imageWithMistake(ours.value(), rl::Mistake::AmbientTimesOd);
        QVERIFY(image && image->has_value());
        QVERIFY(rasterlab::savePng(rasterlab::toQImage(**image), theirs, nullptr));
    }
    QVERIFY(giveViewsContent(window, theirs));
    settle();
    QVERIFY(
        shownDocks(window).contains(window.findChild<QDockWidget*>(QStringLiteral("compareDock"))));

    Checker check(QStringLiteral("window"));
    // The window's least size, not only the size it took: a window manager may not shrink it.
    if (const QSize least = window.minimumSizeHint();
        least.width() > size.width() || least.height() > size.height())
        check.fail(
            &window,
            QStringLiteral("cannot be smaller than %1x%2").arg(least.width()).arg(least.height()));
    if (window.size() != size) {
        QStringList minima;
        for (const QWidget* w : window.findChildren<QWidget*>(Qt::FindDirectChildrenOnly))
            if (w->isVisible() && !w->isWindow())
                minima << QStringLiteral("%1 %2x%3")
                              .arg(w->objectName())
                              .arg(w->minimumSizeHint().width())
                              .arg(w->minimumSizeHint().height());
        check.fail(&window, QStringLiteral("is %1x%2 on a screen of %3x%4: its parts' minimum "
                                           "sizes do not fit: %5")
                                .arg(window.width())
                                .arg(window.height())
                                .arg(size.width())
                                .arg(size.height())
                                .arg(minima.join(QStringLiteral(", "))));
    }
    for (QToolBar* bar : window.findChildren<QToolBar*>())
        if (bar->isVisible()) check.tree(bar);
    check.tree(window.statusBar());
    check.siblings(&window);
    for (QDockWidget* dock : shownDocks(window)) {
        dock->raise();
        settle();
        check.setWhere(dock->objectName() + QStringLiteral(" \"") + dock->windowTitle() +
                       QLatin1Char('"'));
        check.dockTitle(dock);
        check.tree(dock);
        check.setWhere(QStringLiteral("window"));
        // The window moves a tab bar it does not use out of sight.
        for (QTabBar* bar : window.findChildren<QTabBar*>(Qt::FindDirectChildrenOnly))
            if (bar->isVisible() && bar->geometry().intersects(window.rect()))
                check.tabBar(bar, true);
    }
    QStringList findings = check.findings();
    findings.removeDuplicates();
    for (const QString& finding : findings) qInfo().noquote() << finding;
    QVERIFY2(findings.isEmpty(), qPrintable(QStringLiteral("%1 problems, listed above")
                                                .arg(findings.size())));
}

void TestLegibility::opensInsideTheScreen() {
    // The size the window opens at (1560x960 at most), inside each screen's free area, with
    // room for a frame: a window manager does not always shrink a window to its screen.
    m_translators.install(QStringLiteral("en"));
    for (const QSize size : kScreenSizes) {
        QScreen* screen = screenOf(size);
        QVERIFY(screen);
        MainWindow window;
        window.setScreen(screen);
        window.fitToScreen(screen);
        const QRect free = screen->availableGeometry();
        QVERIFY2(free.contains(window.geometry()),
                 qPrintable(QStringLiteral("%1x%2 at (%3, %4) on a screen of %5x%6")
                                .arg(window.width())
                                .arg(window.height())
                                .arg(window.x())
                                .arg(window.y())
                                .arg(free.width())
                                .arg(free.height())));
        QVERIFY(window.width() <= 1560 && window.height() <= 960);
        // Large screens: the default size whole.
        if (size.width() >= 1920) QCOMPARE(window.size(), QSize(1560, 960));
    }
}

void TestLegibility::presentationLeavesTheImageRoom() {
    // In the teacher's own presentation layout (F7), below 1600 pixels wide, the pixel
    // inspector joins the scan view's tabs while presenting,
    // so that the image has at least half the width; it comes back to the left afterwards.
    m_translators.install(QStringLiteral("en"));
    for (const QSize size : kScreenSizes) {
        MainWindow window;
        QVERIFY(showOnScreen(window, size));
        settle();
        auto* inspector = window.findChild<QDockWidget*>(QStringLiteral("pixelInspectorDock"));
        auto* scan = window.findChild<QDockWidget*>(QStringLiteral("scanlineDock"));
        QVERIFY(inspector && scan);
        const auto leave = qScopeGuard([&] { window.setPresentationMode(false); });
        window.setLectureLayout(false);  // the teacher's own layout (the lecture's: tst_lecture)
        window.setPresentationMode(true);
        settle();
        const QString where = QStringLiteral("%1x%2").arg(size.width()).arg(size.height());
        const bool narrow = size.width() < MainWindow::kSidesBesideImageWidth;
        QCOMPARE(window.dockWidgetArea(inspector),
                 narrow ? Qt::RightDockWidgetArea : Qt::LeftDockWidgetArea);
        QCOMPARE(window.tabifiedDockWidgets(scan).contains(inspector), narrow);
        QVERIFY2(!scan->visibleRegion().isEmpty(), qPrintable(where));  // still in front
        const int image = window.centralWidget()->width();
        if (narrow)
            QVERIFY2(image >= window.width() / 2,
                     qPrintable(QStringLiteral("%1: the image %2 px wide").arg(where).arg(image)));
        window.setPresentationMode(false);
        settle();
        QCOMPARE(window.dockWidgetArea(inspector), Qt::LeftDockWidgetArea);
        QVERIFY(!window.tabifiedDockWidgets(scan).contains(inspector));
        QVERIFY(inspector->isVisible() && !inspector->visibleRegion().isEmpty());
    }
}

void TestLegibility::fillWindowWithDock() {
    // F11 (View > Fill the Window) and a double-click on a dock's title: the dock alone over
    // the whole window; again, the docks and the image as they were.
    m_translators.install(QStringLiteral("en"));
    MainWindow window;
    QVERIFY(showOnScreen(window, QSize(1280, 720)));
    settle();
    auto* action = window.findChild<QAction*>(QStringLiteral("fillWindowAction"));
    QVERIFY(action);
    QCOMPARE(action->shortcut(), QKeySequence(Qt::Key_F11));
    const QList<QDockWidget*> before = shownDocks(window);
    const auto visibleDocks = [&] {
        QList<QDockWidget*> docks;
        for (QDockWidget* dock : before)
            if (dock->isVisible()) docks << dock;
        return docks;
    };
    const auto checkFilled = [&](QDockWidget* dock) {
        QVERIFY(window.isFilled());
        QCOMPARE(window.filledDock(), dock);
        QVERIFY(action->isChecked());
        QVERIFY(dock->isVisible());
        QVERIFY(!window.centralWidget()->isVisible());
        QCOMPARE(names(visibleDocks()), QStringList{dock->objectName()});
        // The window's width and nearly all its height (the menu, toolbars and status bar
        // stay).
        QVERIFY2(dock->width() >= window.width() - 10,
                 qPrintable(QStringLiteral("%1 of %2").arg(dock->width()).arg(window.width())));
        QVERIFY(dock->height() >= window.height() / 2);
    };
    const auto checkGivenBack = [&](const QList<QDockWidget*>& visible) {
        QVERIFY(!window.isFilled());
        QVERIFY(!action->isChecked());
        QVERIFY(window.centralWidget()->isVisible());
        QCOMPARE(names(visibleDocks()), names(visible));
        QCOMPARE(names(shownDocks(window)), names(before));
    };

    QDockWidget* normals = window.findChild<QDockWidget*>(QStringLiteral("normalsDock"));
    QVERIFY(normals);
    normals->raise();
    settle();
    const QList<QDockWidget*> raised = visibleDocks();
    normals->widget()->setFocus();
    action->trigger();  // the dock holding the focus
    settle();
    checkFilled(normals);
    action->trigger();
    settle();
    checkGivenBack(raised);

    // A double-click on a title bar, not on the dock's content.
    QDockWidget* inspector = window.findChild<QDockWidget*>(QStringLiteral("pixelInspectorDock"));
    QVERIFY(inspector);
    QTest::mouseDClick(inspector->widget(), Qt::LeftButton, {}, QPoint(10, 10));
    settle();
    QVERIFY(!window.isFilled());
    const QPoint title(inspector->width() / 3, inspector->widget()->geometry().top() / 2);
    QTest::mouseDClick(inspector, Qt::LeftButton, {}, title);
    settle();
    checkFilled(inspector);
    QVERIFY(!inspector->isFloating());
    QTest::mouseDClick(inspector, Qt::LeftButton, {}, title);
    settle();
    checkGivenBack(raised);
}

int main(int argc, char* argv[]) {
    // The three screens of the sizes checked, side by side.
    QTemporaryDir dir;
    qputenv("QT_QPA_PLATFORM", "offscreen");
    if (!useOffscreenScreens(dir, {QSize(1280, 720), QSize(1366, 768), QSize(1920, 1080)}))
        return 1;
    QApplication app(argc, argv);
    TestLegibility test;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&test, argc, argv);
}

#include "tst_legibility.moc"
