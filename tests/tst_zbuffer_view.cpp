// The z-buffer view: the range found from the drawn pixels, the grey and false-colour
// mappings worked out by hand, the checkerboard where no triangle is, the histogram with
// the pixels outside a manual range, the value under the cursor, the explanation's formula
// under each rule set, and the window's dock.
#include <QtTest>

#include <QDockWidget>
#include <QSignalSpy>

#include <cmath>
#include <limits>

#include "app/window/main_window.h"
#include "app/window/render_controller.h"
#include "views/zbuffer_view.h"

using rasterlab::DepthPalette;
using rasterlab::DepthRange;
using rasterlab::ZBufferView;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// 4 x 2 pixels: depths 2, 4, (none), 6 / 3, (none), 5, 8, held by triangles 0, 1, -, 2 /
// 3, -, 4, 5.
std::shared_ptr<rl::DepthTest> handMadeDepth() {
    auto depth = std::make_shared<rl::DepthTest>();
    depth->depth.reset(4, 2, kInf);
    depth->triangle.reset(4, 2, rl::kNoTriangle);
    const float z[2][4] = {{2, 4, kInf, 6}, {3, kInf, 5, 8}};
    const std::uint32_t t[2][4] = {{0, 1, rl::kNoTriangle, 2}, {3, rl::kNoTriangle, 4, 5}};
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 4; ++x) {
            depth->depth.at(x, y) = z[y][x];
            depth->triangle.at(x, y) = t[y][x];
        }
    }
    return depth;
}

std::shared_ptr<const rl::FrameTrace> traceWith(std::shared_ptr<rl::DepthTest> depth) {
    auto trace = std::make_shared<rl::FrameTrace>();
    trace->depth = std::move(depth);
    return trace;
}

QRgb grey(int level) {
    return qRgb(level, level, level);
}

}  // namespace

class TestZBufferView : public QObject {
    Q_OBJECT
private slots:
    void rangeOfDrawnPixels();
    void greyMapping();
    void falseColourMapping();
    void emptyPixelsAreChequered();
    void histogram();
    void viewRanges();
    void valueUnderCursor();
    void explanation();
    void windowDock();
};

void TestZBufferView::rangeOfDrawnPixels() {
    const DepthRange range = rasterlab::coveredDepthRange(*handMadeDepth());
    QVERIFY(range.valid);
    QCOMPARE(range.nearest, 2.0f);  // the clear value (+inf) of empty pixels is not a depth
    QCOMPARE(range.farthest, 8.0f);
    rl::DepthTest empty;
    empty.depth.reset(3, 3, kInf);
    empty.triangle.reset(3, 3, rl::kNoTriangle);
    QVERIFY(!rasterlab::coveredDepthRange(empty).valid);
}

void TestZBufferView::greyMapping() {
    const DepthRange range{2.0f, 8.0f, true};
    // 255 - 239 t with t = (z - 2) / 6, rounded.
    QCOMPARE(rasterlab::depthColour(2.0f, range, DepthPalette::Grey), grey(255));
    QCOMPARE(rasterlab::depthColour(8.0f, range, DepthPalette::Grey), grey(16));
    QCOMPARE(rasterlab::depthColour(5.0f, range, DepthPalette::Grey), grey(136));  // 135.5
    QCOMPARE(rasterlab::depthColour(3.0f, range, DepthPalette::Grey), grey(215));  // 215.17
    // Outside the range: clamped to its ends.
    QCOMPARE(rasterlab::depthColour(-100.0f, range, DepthPalette::Grey), grey(255));
    QCOMPARE(rasterlab::depthColour(100.0f, range, DepthPalette::Grey), grey(16));
    // A range of one value shows every pixel as the nearest.
    QCOMPARE(rasterlab::depthColour(4.0f, DepthRange{4.0f, 4.0f, true}, DepthPalette::Grey),
             grey(255));
}

void TestZBufferView::falseColourMapping() {
    const DepthRange range{2.0f, 8.0f, true};
    QCOMPARE(rasterlab::depthColour(2.0f, range, DepthPalette::FalseColour), qRgb(122, 4, 3));
    QCOMPARE(rasterlab::depthColour(8.0f, range, DepthPalette::FalseColour), qRgb(48, 18, 59));
    // t = 1/2 falls halfway between the third and fourth stops, (225, 220, 55) and
    // (100, 253, 106): (162.5, 236.5, 80.5), rounded away from zero.
    QCOMPARE(rasterlab::depthColour(5.0f, range, DepthPalette::FalseColour), qRgb(163, 237, 81));
}

void TestZBufferView::emptyPixelsAreChequered() {
    const auto depth = handMadeDepth();
    const DepthRange range{2.0f, 8.0f, true};
    const QImage image = rasterlab::depthImage(*depth, range, DepthPalette::Grey);
    QCOMPARE(image.size(), QSize(4, 2));
    QCOMPARE(image.pixel(0, 0), grey(255));
    QCOMPARE(image.pixel(3, 1), grey(16));
    QCOMPARE(image.pixel(2, 0), qRgb(58, 60, 70));  // no triangle: the checkerboard
    QCOMPARE(image.pixel(1, 1), qRgb(58, 60, 70));
    QCOMPARE(rasterlab::emptyPixelColour(8, 0), qRgb(78, 80, 92));
    QCOMPARE(rasterlab::emptyPixelColour(8, 8), qRgb(58, 60, 70));
}

void TestZBufferView::histogram() {
    const auto depth = handMadeDepth();
    // Three bins over [2, 8]: {2, 3}, {4, 5}, {6, 8} (the farthest falls in the last).
    const auto whole = rasterlab::depthHistogram(*depth, DepthRange{2.0f, 8.0f, true}, 3);
    QCOMPARE(whole.counts, (std::vector<int>{2, 2, 2}));
    QCOMPARE(whole.below, 0);
    QCOMPARE(whole.above, 0);
    // Over [3, 6]: 2 is nearer, 8 farther; {3}, {4}, {5, 6}.
    const auto part = rasterlab::depthHistogram(*depth, DepthRange{3.0f, 6.0f, true}, 3);
    QCOMPARE(part.counts, (std::vector<int>{1, 1, 2}));
    QCOMPARE(part.below, 1);
    QCOMPARE(part.above, 1);
}

void TestZBufferView::viewRanges() {
    ZBufferView view;
    view.show();  // a hidden view waits until it is shown
    view.setFrame(traceWith(handMadeDepth()));
    QVERIFY(view.automaticRange());
    QCOMPARE(view.range().nearest, 2.0f);
    QCOMPARE(view.range().farthest, 8.0f);
    QCOMPARE(view.image().pixel(0, 1), grey(215));  // z = 3
    QCOMPARE(view.histogram().counts.size(), std::size_t(64));

    view.setManualRange(3.0f, 6.0f);
    QVERIFY(!view.automaticRange());
    QCOMPARE(view.range().nearest, 3.0f);
    QCOMPARE(view.range().farthest, 6.0f);
    QCOMPARE(view.image().pixel(0, 1), grey(255));  // z = 3 is now the nearest
    QCOMPARE(view.image().pixel(3, 1), grey(16));   // z = 8 beyond the range: clamped
    QCOMPARE(view.image().pixel(1, 0), grey(175));  // z = 4: 255 - 239/3 = 175.33
    QCOMPARE(view.histogram().below, 1);
    QCOMPARE(view.histogram().above, 1);
    // A range given the wrong way round is put in order.
    view.setManualRange(6.0f, 3.0f);
    QCOMPARE(view.range().nearest, 3.0f);

    view.setPalette(DepthPalette::FalseColour);
    QCOMPARE(view.image().pixel(0, 1), qRgb(122, 4, 3));
    view.setAutomaticRange(true);
    QCOMPARE(view.range().farthest, 8.0f);
    QCOMPARE(view.image().pixel(3, 1), qRgb(48, 18, 59));
}

void TestZBufferView::valueUnderCursor() {
    ZBufferView view;
    QCOMPARE(view.valueText(QPoint(0, 0)), QString());  // no frame yet
    view.setFrame(traceWith(handMadeDepth()));
    QCOMPARE(view.valueText(QPoint(0, 0)), QStringLiteral("x 0, y 0: depth 2, triangle 0"));
    QCOMPARE(view.valueText(QPoint(2, 1)), QStringLiteral("x 2, y 1: depth 5, triangle 4"));
    QCOMPARE(view.valueText(QPoint(2, 0)),
             QStringLiteral("x 2, y 0: no triangle; the depth stays at the clear value +inf"));
    QCOMPARE(view.valueText(QPoint(4, 0)), QString());  // outside the image
}

void TestZBufferView::explanation() {
    // 9 fragments tested, 6 written. The course interpolates view z on the screen; under the
    // GPU's perspective-correct rules 1/z is.
    auto depth = handMadeDepth();
    depth->fragments = 9;
    depth->passed = 6;
    auto scene = std::make_shared<rl::Scene>();
    auto trace = std::make_shared<rl::FrameTrace>();
    trace->scene = scene;
    trace->depth = depth;
    ZBufferView view;
    view.setFrame(trace);
    const QString course = view.explanation();
    QVERIFY2(course.contains(QStringLiteral("Every pixel starts at +&infin;. Each fragment's depth "
                                            "z = &alpha;z<sub>1</sub> + &beta;z<sub>2</sub> + "
                                            "&gamma;z<sub>3</sub> (the view-space z of P')")),
             qPrintable(course));
    QVERIFY(course.contains(QStringLiteral("only when z &lt; z<sub>stored</sub>")));
    QVERIFY(course.contains(QStringLiteral("So far: 9 fragments tested, 6 written, 3 rejected.")));
    scene->rules = rl::RasterRules::gpu();
    view.setFrame(trace);
    QVERIFY(view.explanation().contains(
        QStringLiteral("1/z = &alpha;/z<sub>1</sub> + &beta;/z<sub>2</sub> + &gamma;/z<sub>3</sub> "
                       "(the view-space z of P')")));
}

void TestZBufferView::windowDock() {
    rasterlab::MainWindow window;
    QSignalSpy spy(window.controller(), &rasterlab::RenderController::frameReady);
    auto* dock = window.findChild<QDockWidget*>(QStringLiteral("zbufferDock"));
    QVERIFY(dock);
    // The view draws while it is shown: its dock in front.
    window.show();
    dock->show();
    dock->raise();
    QVERIFY2(spy.count() > 0 || spy.wait(10000), "no frame within 10 s");
    QVERIFY(dock->isAncestorOf(window.zbufferView()));
    const ZBufferView* view = window.zbufferView();
    const auto frame = window.currentFrame();
    QCOMPARE(view->image().size(), QSize(800, 600));
    const DepthRange drawn = rasterlab::coveredDepthRange(*frame->depth);
    QVERIFY(drawn.valid && drawn.nearest < drawn.farthest);
    QCOMPARE(view->range().nearest, drawn.nearest);
    QCOMPARE(view->range().farthest, drawn.farthest);
    // The default scene's corner is empty; the knot's lower band at (400, 350) is drawn.
    QCOMPARE(view->image().pixel(0, 0), rasterlab::emptyPixelColour(0, 0));
    const float z = frame->depth->depth.at(400, 350);
    QVERIFY(std::isfinite(z));
    QCOMPARE(view->image().pixel(400, 350), rasterlab::depthColour(z, drawn, DepthPalette::Grey));
}

QTEST_MAIN(TestZBufferView)
#include "tst_zbuffer_view.moc"
