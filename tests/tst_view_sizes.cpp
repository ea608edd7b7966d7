// Every stage view laid out for the space it gets, on the goblet lesson: docked (a dock of
// the 1280x720 window), filled to the window (F11) and in the lecture layout (most of a
// 1280x720 window). Each view sits in a scroll area that resizes it, as the window's docks
// hold them, and the same views are looked at in the window itself at 1280x720, docked
// and filled: the z-buffer image and the normals drawing whole inside their widgets, and
// those inside what the dock shows.
#include <QtTest>

#include <QDockWidget>
#include <QHeaderView>
#include <QScrollArea>
#include <QScrollBar>
#include <QTableView>
#include <QTextBrowser>
#include <QTemporaryDir>
#include <QWheelEvent>

#include "app/window/main_window.h"
#include "tests/offscreen_screens.h"
#include "views/camera_basis_view.h"
#include "views/frame_image_view.h"
#include "views/inspection.h"
#include "views/key_figures.h"
#include "views/near_clip_view.h"
#include "views/normals_canvas.h"
#include "views/normals_view.h"
#include "views/painted_labels.h"
#include "views/painter_view.h"
#include "views/pixel_inspector.h"
#include "views/projection_view.h"
#include "views/scanline_view.h"
#include "views/trapezoid_view.h"
#include "views/vertex_table.h"
#include "views/zbuffer_view.h"

using rasterlab::Inspection;
using rasterlab::MainWindow;

namespace {

constexpr int kTimeoutMs = 20000;

// Docked in the 1280x720 window (short and tall docks), the window filled by one dock, and
// the lecture layout's range.
const QSize kSizes[] = {{420, 190}, {420, 300}, {1264, 600}, {900, 560}, {1260, 600}};

// A view in a scroll area that resizes it, the way the window's docks hold the stage views.
struct Docked {
    Docked(QWidget* view, QSize size) {
        scroll.setWidgetResizable(true);
        scroll.setFrameShape(QFrame::NoFrame);
        scroll.setWidget(view);
        scroll.resize(size);
        scroll.show();
    }
    QScrollArea scroll;
};

void settle() {
    for (int k = 0; k < 6; ++k) {
        QCoreApplication::processEvents();
        QTest::qWait(10);
    }
}

QString text(const QRectF& r) {
    return QStringLiteral("(%1, %2) %3 x %4").arg(r.x()).arg(r.y()).arg(r.width()).arg(r.height());
}

// The part of a widget its scroll area shows, in the widget's coordinates.
QRect shownPart(const QWidget* w, const QScrollArea& scroll) {
    const QPoint at = w->mapTo(scroll.viewport(), QPoint(0, 0));
    return scroll.viewport()->rect().translated(-at).intersected(w->rect());
}

// The image's rectangle in its view: inside the view, and fitted (as wide or as high as the
// view, within a pixel).
void checkImageFitted(const rasterlab::FrameImageView* view, const QString& where) {
    QVERIFY2(!view->image().isNull(), qPrintable(where));
    const QRectF image(view->widgetPoint({0, 0}),
                       view->widgetPoint(QPointF(view->image().width(), view->image().height())));
    const QRectF inside = QRectF(view->rect()).adjusted(-0.5, -0.5, 0.5, 0.5);
    QVERIFY2(inside.contains(image), qPrintable(QStringLiteral("%1: the image at %2 in %3")
                                                    .arg(where, text(image), text(view->rect()))));
    const bool fitted = image.width() >= view->width() - 1.0 || image.height() >= view->height() - 1.0;
    QVERIFY2(fitted, qPrintable(QStringLiteral("%1: the image at %2 does not fill %3")
                                    .arg(where, text(image), text(view->rect()))));
}

// The drawing's pixels (neither of the canvas's two backgrounds): their bounding box.
QRect drawnBox(QWidget* canvas) {
    const QImage image = canvas->grab().toImage().convertToFormat(QImage::Format_RGB32);
    const QRgb outside = qRgb(40, 40, 44), screen = qRgb(22, 22, 26);
    QRect box;
    for (int y = 0; y < image.height(); ++y) {
        const auto* line = reinterpret_cast<const QRgb*>(image.constScanLine(y));
        for (int x = 0; x < image.width(); ++x)
            if (line[x] != outside && line[x] != screen) box |= QRect(x, y, 1, 1);
    }
    return box;
}

// The normals drawing: inside the canvas with none of it on the canvas's edge (cut off),
// using the canvas's width or height (the mesh's box fitted with 8 % on each side), and the canvas wholly
// in what the scroll area shows.
void checkNormalsDrawing(rasterlab::NormalsCanvas* canvas, const QString& where) {
    const QRect box = drawnBox(canvas);
    QVERIFY2(!box.isEmpty(), qPrintable(where + QStringLiteral(": nothing drawn")));
    QVERIFY2(canvas->rect().adjusted(1, 1, -1, -1).contains(box),
             qPrintable(QStringLiteral("%1: drawn over %2 in %3")
                            .arg(where, text(box), text(canvas->rect()))));
    QVERIFY2(box.width() >= canvas->width() * 0.8 || box.height() >= canvas->height() * 0.8,
             qPrintable(QStringLiteral("%1: drawn over %2 of %3")
                            .arg(where, text(box), text(canvas->rect()))));
}

}  // namespace

class TestViewSizes : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void zbufferImageWhole_data();
    void zbufferImageWhole();
    void normalsUseTheHeight_data();
    void normalsUseTheHeight();
    void vertexTableColumnsInView_data();
    void vertexTableColumnsInView();
    void gramSchmidtStepsInView_data();
    void gramSchmidtStepsInView();
    void phongBarsLabelled();
    void inspectorFormulaInView_data();
    void inspectorFormulaInView();
    void textFollowsTheDocksFont_data();
    void textFollowsTheDocksFont();
    void keyFiguresLarge();
    void inTheWindow();

private:
    std::unique_ptr<MainWindow> m_window;
};

void TestViewSizes::initTestCase() {
    m_window = std::make_unique<MainWindow>();
    QVERIFY(m_window->openExample(QStringLiteral("goblet")));
    QVERIFY(QTest::qWaitFor([&] { return m_window->isReadyToStep(); }, kTimeoutMs));
    m_window->inspection()->pickPixel(QPoint(353, 157));
}

void TestViewSizes::zbufferImageWhole_data() {
    QTest::addColumn<QSize>("size");
    for (const QSize size : kSizes) QTest::addRow("%dx%d", size.width(), size.height()) << size;
}

void TestViewSizes::zbufferImageWhole() {
    // The 800 x 600 depth image fitted whole, the view no taller than the dock: nothing to
    // scroll to see it, and the image as large as the view's share allows.
    QFETCH(QSize, size);
    auto* view = new rasterlab::ZBufferView;
    Docked docked(view, size);
    view->setFrame(m_window->currentFrame());
    settle();
    const QString where = QStringLiteral("%1x%2").arg(size.width()).arg(size.height());
    QCOMPARE(docked.scroll.verticalScrollBar()->maximum(), 0);
    const rasterlab::FrameImageView* image = view->imageView();
    QCOMPARE(image->image().size(), QSize(800, 600));
    QCOMPARE(shownPart(image, docked.scroll), image->rect());
    checkImageFitted(image, where);
    // Beside the words in every one of these (wider than tall): at least half the width.
    QVERIFY2(image->width() >= size.width() / 2,
             qPrintable(QStringLiteral("%1: the image view %2 px wide").arg(where).arg(image->width())));
    // The wheel still zooms, and the zoomed image is no longer fitted.
    const double fitted = image->zoom();
    QWheelEvent wheel(QPointF(image->rect().center()), image->mapToGlobal(image->rect().center()),
                      QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase,
                      false);
    QCoreApplication::sendEvent(const_cast<rasterlab::FrameImageView*>(image), &wheel);
    QCOMPARE(image->zoom(), fitted * 1.25);
}

void TestViewSizes::normalsUseTheHeight_data() {
    zbufferImageWhole_data();
}

void TestViewSizes::normalsUseTheHeight() {
    QFETCH(QSize, size);
    auto* view = new rasterlab::NormalsView(m_window->inspection());
    Docked docked(view, size);
    settle();
    const QString where = QStringLiteral("%1x%2").arg(size.width()).arg(size.height());
    QCOMPARE(docked.scroll.verticalScrollBar()->maximum(), 0);
    rasterlab::NormalsCanvas* canvas = view->canvas();
    QCOMPARE(shownPart(canvas, docked.scroll), canvas->rect());
    // The words beside the drawing: the canvas has the height less the tab bar and the
    // switches (two rows), and three fifths of the width.
    QVERIFY2(canvas->height() >= size.height() * 0.55,
             qPrintable(QStringLiteral("%1: the canvas %2 px high").arg(where).arg(canvas->height())));
    QVERIFY2(canvas->width() >= size.width() / 2,
             qPrintable(QStringLiteral("%1: the canvas %2 px wide").arg(where).arg(canvas->width())));
    checkNormalsDrawing(canvas, where);
}

void TestViewSizes::vertexTableColumnsInView_data() {
    zbufferImageWhole_data();
}

void TestViewSizes::vertexTableColumnsInView() {
    // Every column across the table without scrolling sideways, each as wide as its title and
    // its values: on one line when they fit (900 px and more), else each vector's
    // components on three lines and the titles on two (a dock). The goblet has one draw:
    // its column is left out.
    QFETCH(QSize, size);
    auto* view = new rasterlab::VertexTableView(m_window->inspection());
    Docked docked(view, size);
    settle();
    const QString where = QStringLiteral("%1x%2").arg(size.width()).arg(size.height());
    QTableView* table = view->table();
    QCOMPARE(table->horizontalScrollBar()->maximum(), 0);
    QVERIFY(table->isColumnHidden(rasterlab::VertexTableModel::Draw));
    QCOMPARE(view->model()->stacked(), size.width() < 900);
    const QHeaderView* header = table->horizontalHeader();
    for (int c = rasterlab::VertexTableModel::Vertex; c < rasterlab::VertexTableModel::ColumnCount;
         ++c) {
        const QString title = table->model()->headerData(c, Qt::Horizontal).toString();
        const int right = header->sectionViewportPosition(c) + header->sectionSize(c);
        QVERIFY2(right <= table->viewport()->width(),
                 qPrintable(QStringLiteral("%1: \"%2\" ends at %3 of %4")
                                .arg(where, title)
                                .arg(right)
                                .arg(table->viewport()->width())));
        int values = 0;  // the widest of the first 100 rows' values
        for (int r = 0; r < std::min(100, table->model()->rowCount()); ++r)
            values = std::max(values,
                              table->sizeHintForIndex(table->model()->index(r, c)).width());
        QVERIFY2(header->sectionSize(c) >= values,
                 qPrintable(QStringLiteral("%1: \"%2\" %3 px for values of %4")
                                .arg(where, title)
                                .arg(header->sectionSize(c))
                                .arg(values)));
        QVERIFY2(header->sectionSize(c) >= header->sectionSizeHint(c),
                 qPrintable(QStringLiteral("%1: \"%2\" %3 px for a title of %4")
                                .arg(where, title)
                                .arg(header->sectionSize(c))
                                .arg(header->sectionSizeHint(c))));
    }
    // Vertex 494 of the highlight's triangle, its view coordinates on three lines or one.
    const QModelIndex view494 = table->model()->index(493, rasterlab::VertexTableModel::View);
    QCOMPARE(table->model()->data(view494).toString(),
             size.width() < 900 ? QStringLiteral("-0.478976\n1.08283\n8.6901")
                                : QStringLiteral("(-0.478976, 1.08283, 8.6901)"));
}

void TestViewSizes::gramSchmidtStepsInView_data() {
    zbufferImageWhole_data();
}

void TestViewSizes::gramSchmidtStepsInView() {
    // The steps beside the drawing: 34 characters a line, or half the width when that is
    // less (a dock); with the lecture layout's room, the four steps in view without
    // scrolling.
    QFETCH(QSize, size);
    auto* view = new rasterlab::CameraBasisView(m_window->inspection());
    Docked docked(view, size);
    settle();
    view->setStep(4);
    settle();
    const QString where = QStringLiteral("%1x%2").arg(size.width()).arg(size.height());
    auto* text = view->findChild<QTextBrowser*>(QStringLiteral("cameraBasisText"));
    QVERIFY(text);
    QCOMPARE(shownPart(text, docked.scroll), text->rect());
    const int least = std::min(size.width() / 2, view->fontMetrics().averageCharWidth() * 34);
    QVERIFY2(text->width() >= least - 12,  // less the splitter's handle and the margins
             qPrintable(QStringLiteral("%1: the steps %2 px wide").arg(where).arg(text->width())));
    QTextCursor last = text->document()->find(QStringLiteral("4. U := N"));
    QVERIFY(!last.isNull());
    if (size.height() >= 500) {
        QCOMPARE(text->verticalScrollBar()->value(), 0);
        const QRect at = text->cursorRect(last);
        QVERIFY2(text->viewport()->rect().contains(at),
                 qPrintable(QStringLiteral("%1: step 4 at %2").arg(where, ::text(at))));
    }
}

void TestViewSizes::phongBarsLabelled() {
    // The goblet's highlight (docs/guide.en.md, section 5): red is 70 x 0.2 + 255 x 0.85 x
    // 0.7 x 0.930058 + 255 x 0.7 x 0.999819^30 = 14 + 141.113 + 177.534 = 332.648; green
    // 14 + 105.794 + 174.053 = 293.848; blue 16 + 39.0624 + 167.091 = 222.154 (six
    // significant digits, as the formula writes them; the guide rounds 39.062). Each term's
    // value is written under its part of its channel's bar, in the bar's row, left to right.
    auto* inspector = new rasterlab::PixelInspector(m_window->inspection());
    Docked docked(inspector, QSize(420, 600));
    QTRY_VERIFY_WITH_TIMEOUT(inspector->breakdown().has_value(), kTimeoutMs);
    settle();
    auto* bars = inspector->findChild<QWidget*>(QStringLiteral("pixelTermBars"));
    const auto* labels = dynamic_cast<const rasterlab::PaintedLabels*>(bars);
    QVERIFY(bars && labels);
    bars->grab();  // a paint, which records the labels
    const QStringList texts = labels->labelTexts();
    const QList<QRect> rects = labels->labelRects();
    const QStringList expected[3] = {{QStringLiteral("14"), QStringLiteral("141.113"),
                                      QStringLiteral("177.534"), QStringLiteral("332.6")},
                                     {QStringLiteral("14"), QStringLiteral("105.794"),
                                      QStringLiteral("174.053"), QStringLiteral("293.8")},
                                     {QStringLiteral("16"), QStringLiteral("39.0624"),
                                      QStringLiteral("167.091"), QStringLiteral("222.2")}};
    // The channels' names, R, G and B, head the rows: each row's labels lie between its name's
    // top and the next name's.
    QList<int> rowTops;
    for (const QString& name : {QStringLiteral("R"), QStringLiteral("G"), QStringLiteral("B")}) {
        const qsizetype i = texts.indexOf(name);
        QVERIFY2(i >= 0, qPrintable(texts.join(QStringLiteral(" | "))));
        rowTops << rects[i].top();
    }
    rowTops << bars->height();
    for (int c = 0; c < 3; ++c) {
        QStringList row;
        QList<int> lefts;
        for (qsizetype i = 0; i < texts.size(); ++i)
            if (rects[i].top() >= rowTops[c] && rects[i].bottom() < rowTops[c + 1] &&
                texts[i].front().isDigit()) {
                row << texts[i];
                lefts << rects[i].left();
            }
        // The terms in order, then the total at the bar's end (four significant digits).
        QCOMPARE(row.mid(0, 4), expected[c]);
        QVERIFY(std::is_sorted(lefts.begin(), lefts.begin() + 3));
        for (int k = 0; k < 3; ++k)
            QVERIFY2(bars->rect().contains(rects[texts.indexOf(expected[c][k], 0)]),
                     qPrintable(expected[c][k]));
    }
    // And the formula with the same numbers.
    QVERIFY2(inspector->formulaText().contains(QStringLiteral("14 + 141.113 + 177.534 = 332.648")),
             qPrintable(inspector->formulaText()));
}

void TestViewSizes::inspectorFormulaInView_data() {
    QTest::addColumn<QSize>("size");
    for (const QSize size : {QSize(900, 560), QSize(1260, 600), QSize(1264, 600)})
        QTest::addRow("%dx%d", size.width(), size.height()) << size;
}

void TestViewSizes::inspectorFormulaInView() {
    // With the lecture layout's room, the history beside the lighting: the bars and the
    // formula's lines in view without scrolling.
    QFETCH(QSize, size);
    auto* inspector = new rasterlab::PixelInspector(m_window->inspection());
    Docked docked(inspector, size);
    QTRY_VERIFY_WITH_TIMEOUT(inspector->breakdown().has_value(), kTimeoutMs);
    settle();
    const QString where = QStringLiteral("%1x%2").arg(size.width()).arg(size.height());
    for (const char* name : {"pixelFormula", "pixelTermBars", "pixelVectors", "pixelHistory"}) {
        auto* w = inspector->findChild<QWidget*>(QLatin1String(name));
        QVERIFY2(w, name);
        QVERIFY2(w->isVisible(), name);
        QVERIFY2(shownPart(w, docked.scroll) == w->rect(),
                 qPrintable(QStringLiteral("%1: %2 at %3, shown %4")
                                .arg(where, QLatin1String(name), text(w->geometry()),
                                     text(shownPart(w, docked.scroll)))));
    }
    QVERIFY(inspector->formulaText().contains(QStringLiteral("332.648")));
}

void TestViewSizes::textFollowsTheDocksFont_data() {
    QTest::addColumn<QString>("name");
    for (const char* name : {"camera", "vertices", "normals", "projection", "clipping", "scan",
                             "trapezoids", "zbuffer", "painter", "inspector"})
        QTest::newRow(name) << QString::fromLatin1(name);
}

void TestViewSizes::textFollowsTheDocksFont() {
    // The window sets a font on a dock's contents (presentation mode, the text zoom): every
    // part of every view takes it, twice as large here, and the text a view paints itself
    // (PaintedLabels) grows with it.
    QFETCH(QString, name);
    Inspection* inspection = m_window->inspection();
    QWidget* view = nullptr;
    if (name == QLatin1String("camera")) view = new rasterlab::CameraBasisView(inspection);
    if (name == QLatin1String("vertices")) view = new rasterlab::VertexTableView(inspection);
    if (name == QLatin1String("normals")) view = new rasterlab::NormalsView(inspection);
    if (name == QLatin1String("projection")) view = new rasterlab::ProjectionView(inspection);
    if (name == QLatin1String("clipping")) view = new rasterlab::NearClipView(inspection);
    if (name == QLatin1String("scan")) view = new rasterlab::ScanlineView(inspection);
    if (name == QLatin1String("trapezoids")) view = new rasterlab::TrapezoidView(inspection);
    if (name == QLatin1String("painter")) view = new rasterlab::PainterView(inspection);
    if (name == QLatin1String("inspector")) view = new rasterlab::PixelInspector(inspection);
    if (name == QLatin1String("zbuffer")) {
        auto* z = new rasterlab::ZBufferView;
        z->setFrame(m_window->currentFrame());
        view = z;
    }
    QVERIFY(view);
    Docked docked(view, QSize(900, 560));
    settle();
    const auto paintedHeight = [&] {
        int tallest = 0;
        for (QWidget* w : view->findChildren<QWidget*>())
            if (const auto* painted = dynamic_cast<const rasterlab::PaintedLabels*>(w);
                painted && w->isVisible()) {
                w->grab();
                // Text labels only (a view records a button's place too, without text).
                const QList<QRect> rects = painted->labelRects();
                const QStringList texts = painted->labelTexts();
                for (qsizetype i = 0; i < rects.size(); ++i)
                    if (!texts[i].isEmpty()) tallest = std::max(tallest, rects[i].height());
            }
        return tallest;
    };
    const int paintedBefore = paintedHeight();
    const double size = docked.scroll.font().pointSizeF();
    QFont large = docked.scroll.font();
    large.setPointSizeF(2 * size);
    docked.scroll.setFont(large);
    settle();
    QList<QWidget*> parts = view->findChildren<QWidget*>();
    parts.prepend(view);
    for (const QWidget* w : parts) {
        if (w->objectName().startsWith(QLatin1String("qt_"))) continue;  // Qt's own parts
        // The key figures, half as large again as the rest.
        const double expected =
            w->objectName() == QLatin1String("keyFigures") ? 3 * size : 2 * size;
        QVERIFY2(std::abs(w->font().pointSizeF() - expected) < 0.01,
                 qPrintable(QStringLiteral("%1 %2: %3 pt, the dock's %4")
                                .arg(QLatin1String(w->metaObject()->className()), w->objectName())
                                .arg(w->font().pointSizeF())
                                .arg(expected)));
    }
    const int paintedAfter = paintedHeight();
    if (paintedBefore > 0)
        QVERIFY2(paintedAfter >= 1.6 * paintedBefore,
                 qPrintable(QStringLiteral("painted labels %1 px high, then %2")
                                .arg(paintedBefore)
                                .arg(paintedAfter)));
}

void TestViewSizes::keyFiguresLarge() {
    // Each stage's key numbers, half as large again as the view's text and bold, with the
    // lecture layout's room; a short dock (190 px) leaves them out for its drawing.
    Inspection* inspection = m_window->inspection();
    auto* camera = new rasterlab::CameraBasisView(inspection);
    auto* normals = new rasterlab::NormalsView(inspection);
    auto* projection = new rasterlab::ProjectionView(inspection);
    auto* zbuffer = new rasterlab::ZBufferView;
    zbuffer->setFrame(m_window->currentFrame());
    const std::pair<QWidget*, QString> views[] = {
        {camera, QStringLiteral("U = (1, 0, 0)  V = (0, 0.937862, -0.347009)  "
                                "N = (0, -0.347009, -0.937862)")},
        {normals, QStringLiteral("n = (0.3819, 0.2616, 0.8864)  n · P1 = 7.803")},
        {projection, QStringLiteral("1520 inside · 0 clipped · 0 culled · 0 behind")},
        {zbuffer, QStringLiteral("241332 tested · 140068 written · 101264 rejected\n"
                                 "z 8.38824 – 12.8632")}};
    for (const auto& [view, expected] : views) {
        Docked docked(view, QSize(900, 560));
        settle();
        const auto* figures = view->findChild<rasterlab::KeyFigures*>();
        QVERIFY(figures);
        QCOMPARE(figures->text(), expected);
        QVERIFY2(figures->isVisible(), qPrintable(expected));
        QCOMPARE(shownPart(figures, docked.scroll), figures->rect());
        QCOMPARE(figures->font().pointSizeF(), 1.5 * view->font().pointSizeF());
        QVERIFY(figures->font().bold());
        docked.scroll.resize(420, 190);
        settle();
        QVERIFY2(!figures->isVisible(), qPrintable(expected));
        docked.scroll.takeWidget();
        delete view;
    }
}

void TestViewSizes::inTheWindow() {
    // The window on a 1280x720 screen: the z-buffer and normals docks raised in turn, then each
    // filling the window.
    MainWindow window;
    QScreen* screen = nullptr;
    for (QScreen* s : QGuiApplication::screens())
        if (s->geometry().size() == QSize(1280, 720)) screen = s;
    QVERIFY2(screen, "no 1280x720 screen (tests/offscreen_screens.h)");
    window.setScreen(screen);
    window.move(screen->geometry().topLeft());
    window.resize(1280, 720);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(window.openExample(QStringLiteral("goblet")));
    QVERIFY(QTest::qWaitFor([&] { return window.isReadyToStep(); }, kTimeoutMs));
    for (const bool filled : {false, true}) {
        for (const char* name : {"zbufferDock", "normalsDock"}) {
            auto* dock = window.findChild<QDockWidget*>(QLatin1String(name));
            QVERIFY(dock);
            dock->raise();
            settle();
            if (filled) window.toggleFill(dock);
            settle();
            const QString where =
                QStringLiteral("%1 %2").arg(QLatin1String(name), filled ? "filled" : "docked");
            auto* scroll = qobject_cast<QScrollArea*>(dock->widget());
            QVERIFY(scroll);
            if (QLatin1String(name) == QLatin1String("zbufferDock")) {
                rasterlab::FrameImageView* image = window.zbufferView()->imageView();
                QCOMPARE(shownPart(image, *scroll), image->rect());
                checkImageFitted(image, where);
            } else {
                auto* canvas = window.findChild<rasterlab::NormalsCanvas*>();
                QVERIFY(canvas);
                QCOMPARE(shownPart(canvas, *scroll), canvas->rect());
                checkNormalsDrawing(canvas, where);
            }
            if (filled) window.toggleFill(dock);
        }
    }
}

int main(int argc, char** argv) {
    const QTemporaryDir dir;
    if (!useOffscreenScreens(dir, {QSize(1280, 720)})) return 1;
    QApplication app(argc, argv);
    TestViewSizes test;
    return QTest::qExec(&test, argc, argv);
}

#include "tst_view_sizes.moc"
