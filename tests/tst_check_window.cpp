// File > Check My Renderer... in the window (offscreen), on the shipped goblet lesson: the
// student's Python renderer with y not flipped fails the projection alone; the Check dock says
// where and why, draws their vertices beside ours, the stage strip marks each stage, and Stop
// at the First Departure selects the vertex. The window stays responsive while a program
// hangs, and Cancel ends the check; the command and folder are kept in lesson files.
#include <QtTest>

#include <QCheckBox>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QScreen>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QToolButton>
#include <QTreeWidget>

#include <algorithm>

#include "app/window/check_panel.h"
#include "app/window/compare_panel.h"
#include "app/window/main_window.h"
#include "app/window/translators.h"
#include "pipeline/render/frame_trace.h"
#include "pipeline/stages/scan_conversion.h"
#include "tests/test_support.h"
#include "views/frame_image_view.h"
#include "views/pixel_inspector.h"
#include "views/projection_view.h"
#include "views/scanline_view.h"
#include "views/stage_strip.h"
#include "views/zbuffer_view.h"

using rasterlab::CheckPanel;
using rasterlab::MainWindow;
using rasterlab::ScanlineView;
using rasterlab::StageStrip;
namespace check = rasterlab::check;

namespace {

constexpr int kTimeoutMs = 120000;

bool ready(const MainWindow& window) {
    return window.isReadyToStep() && !window.lessonViewPending();
}

QString pythonFolder() {
    return testing::sourceDir() + "/examples/student/python";
}

// Checks the example student's renderer with these switches in the panel, and waits for the
// check to end; false when it does not start or end.
bool checkWith(CheckPanel* panel, const char* switches) {
    panel->setCommand(QStringLiteral(RASTERLAB_PYTHON " stages.py ") + QLatin1String(switches));
    QSignalSpy finished(panel, &CheckPanel::finished);
    return panel->start().isEmpty() && finished.wait(kTimeoutMs);
}

}  // namespace

class TestCheckWindow : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        m_window.resize(1280, 720);
        m_window.show();
        QVERIFY(m_window.openExample(QStringLiteral("goblet")));
        QVERIFY(QTest::qWaitFor([&] { return ready(m_window); }, kTimeoutMs));
    }

    void checkShowsWhereTheStagesDepart() {
        m_window.showCheckDock();
        CheckPanel* panel = m_window.checkPanel();
        QVERIFY(panel->parentWidget()->isVisible() || panel->isVisibleTo(&m_window));
        panel->setCommand(QStringLiteral(RASTERLAB_PYTHON " stages.py --flip-y"));
        panel->setFolder(pythonFolder());
        QSignalSpy finished(panel, &CheckPanel::finished);
        QTest::mouseClick(panel->checkButton(), Qt::LeftButton);
        QVERIFY(!panel->checkButton()->isEnabled());
        QVERIFY(finished.wait(kTimeoutMs));
        QVERIFY(panel->report());
        QCOMPARE(panel->stageList()->topLevelItemCount(), 8);
        // The first stage that departs is the one selected.
        QCOMPARE(int(*panel->selectedStage()), int(check::Stage::Projection));
        const check::StageResult* r = panel->selectedResult();
        QVERIFY(r);
        QCOMPARE(int(r->verdict), int(check::Verdict::Failed));
        QVERIFY2(panel->detailsText().contains("Likely cause: y not flipped: (int)((d/hy * y/z + "
                                               "1) * height/2), y growing upward"),
                 qPrintable(panel->detailsText()));
        QVERIFY(panel->detailsText().contains("x = (int)((d/hx * x/z + 1) * width/2)"));
        // Their vertices beside ours, one departure a vertex.
        QVERIFY(!panel->canvas()->departures().empty());
        QCOMPARE(int(panel->canvas()->departures().front().kind),
                 int(check::Departure::Kind::Vertex));
        QCOMPARE(panel->canvas()->departures().size(), r->differing);
        // The projection view draws them too, each pair ours and theirs.
        const auto& pairs = m_window.projectionView()->canvas()->theirVertices();
        QCOMPARE(pairs.size(), r->differing);
        QCOMPARE(pairs.front().first,
                 QPointF(r->departures.front().ours.x, r->departures.front().ours.y));
        QCOMPARE(pairs.front().second,
                 QPointF(r->departures.front().theirs.x, r->departures.front().theirs.y));
        // The strip: the projection departs; the stages before it pass.
        StageStrip* strip = m_window.stageStrip();
        QCOMPARE(strip->checkMark(rl::StageId::Projection), StageStrip::CheckMark::Failed);
        QCOMPARE(strip->checkMark(rl::StageId::CameraBasis), StageStrip::CheckMark::Passed);
        QCOMPARE(strip->checkMark(rl::StageId::Normals), StageStrip::CheckMark::Passed);
        // Their lighting passes: the frame, which fails, is no stage's.
        QCOMPARE(strip->checkMark(rl::StageId::Shading), StageStrip::CheckMark::Passed);
        QVERIFY(strip->button(rl::StageId::Projection)->text().endsWith(QStringLiteral("\u2717")));
        // Stop at the First Departure: the projection's stage, its first vertex selected.
        QVERIFY(panel->stopButton()->isEnabled());
        QTest::mouseClick(panel->stopButton(), Qt::LeftButton);
        QCOMPARE(m_window.inspection()->stage(), rl::StageId::Projection);
        QCOMPARE(m_window.inspection()->selectedVertices().size(), std::size_t(1));
        QCOMPARE(
            QString::fromStdString(r->first->element),
            QStringLiteral("vertex %1").arg(m_window.inspection()->selectedVertices()[0].vertex));
    }

    // At 1280x720, after a check whose first departure is the lighting (the seventh of eight
    // rows): its row, its explanation and its overlay in view without scrolling, and the
    // progress text inside its bar.
    void firstDepartureInView() {
        m_window.showCheckDock();
        CheckPanel* panel = m_window.checkPanel();
        QVERIFY(checkWith(panel, "--ambient-times-od"));
        QTest::qWait(50);
        QTreeWidget* list = panel->stageList();
        QTreeWidgetItem* current = list->currentItem();
        QVERIFY(current);
        QVERIFY2(list->indexOfTopLevelItem(current) >= 6,
                 qPrintable(QString::number(list->indexOfTopLevelItem(current))));
        const QRect row = list->visualItemRect(current);
        QVERIFY2(list->viewport()->rect().contains(row),
                 qPrintable(QStringLiteral("row %1,%2 %3x%4 in a viewport %5 high")
                                .arg(row.x()).arg(row.y()).arg(row.width()).arg(row.height())
                                .arg(list->viewport()->height())));
        QVERIFY(!panel->detailsText().isEmpty());
        // The words: at least three lines' height shown; the picture: at least 150 px.
        const auto* scroll = panel->findChildren<QScrollArea*>().value(0);
        QVERIFY(scroll);
        QVERIFY2(scroll->viewport()->height() >= 3 * panel->fontMetrics().height(),
                 qPrintable(QString::number(scroll->viewport()->height())));
        QVERIFY2(panel->canvas()->height() >= 150,
                 qPrintable(QString::number(panel->canvas()->height())));
        QVERIFY(panel->canvas()->isVisible());
        // "goblet.byu: frame", the longest progress text, fits the bar.
        QProgressBar* bar = panel->progressBar();
        QVERIFY2(bar->fontMetrics().horizontalAdvance(QStringLiteral("goblet.byu: frame")) + 16 <
                     bar->width(),
                 qPrintable(QString::number(bar->width())));
        QVERIFY(panel->window()->height() <= 720);
    }

    // Their frame goes to the Compare dock, whose diagnosis names the mistake.
    void comparesTheirFrame() {
        CheckPanel* panel = m_window.checkPanel();
        QVERIFY(checkWith(panel, "--ambient-times-od"));
        // The pixel inspector gives their colour beside ours at the pixel picked, and the
        // Phong term that departs: the ambient term, times Od.
        const check::StageResult* frame = nullptr;
        for (const check::StageResult& st : panel->report()->scenes.front().stages)
            if (st.stage == check::Stage::Frame) frame = &st;
        QVERIFY(frame && !frame->departures.empty());
        const QPoint pixel(int(frame->departures.front().ours.x),
                           int(frame->departures.front().ours.y));
        m_window.inspection()->pickPixel(pixel);
        const QString their = m_window.pixelInspector()->theirColourText();
        QVERIFY2(
            their.startsWith(QStringLiteral("Your renderer's colour here: (")) &&
                their.contains(QStringLiteral("\nFor your colour, each term alone:\n• the ambient "
                                              "term Ia·ka would have to be ")) &&
                their.contains(QStringLiteral(": that is the term times Od (")),
            qPrintable(their));
        QVERIFY(panel->compareButton()->isEnabled());
        QTest::mouseClick(panel->compareButton(), Qt::LeftButton);
        const rl::ImageComparison* comparison = m_window.comparePanel()->comparison();
        QVERIFY(comparison);
        QVERIFY(!comparison->diagnosis.empty());
        QCOMPARE(comparison->diagnosis.front().mistake, rl::Mistake::AmbientTimesOd);
        // At 1280x720 the Compare dock shows the first mistake found, unscrolled, under the
        // images.
        QTest::qWait(50);
        auto* dock = m_window.findChild<QDockWidget*>(QStringLiteral("compareDock"));
        auto* diagnosis = dock->findChild<QLabel*>(QStringLiteral("compareDiagnosis"));
        auto* scroll = dock->findChild<QScrollArea*>();
        QVERIFY(dock->isVisible() && diagnosis && scroll);
        QVERIFY(diagnosis->text().contains(QStringLiteral("Ia*ka*Od")));
        QVERIFY(dock->frameGeometry().bottom() < 720);
        // The first finding's ten lines: the heading, its name, share, evidence (two lines),
        // the course's rule and three pixels.
        const QPoint top = diagnosis->mapTo(scroll->viewport(), QPoint(0, 0));
        const int finding = 10 * diagnosis->fontMetrics().height();
        QVERIFY2(top.y() >= 0 && top.y() + finding <= scroll->viewport()->height(),
                 qPrintable(QStringLiteral("the diagnosis at %1 in a viewport %2 high")
                                .arg(top.y()).arg(scroll->viewport()->height())));
    }

    // A departure at a pixel: the frame is stepped to the first fragment written there.
    void stopsAtThePixel() {
        CheckPanel* panel = m_window.checkPanel();
        QVERIFY(checkWith(panel, "--span-end-exclusive"));
        QCOMPARE(int(*panel->selectedStage()), int(check::Stage::Scan));
        const check::StageResult* r = panel->selectedResult();
        QVERIFY(r && !r->departures.empty());
        QVERIFY(panel->stopAtFirstDeparture());
        const QPoint pixel(int(r->departures.front().ours.x), int(r->departures.front().ours.y));
        QCOMPARE(m_window.inspection()->pickedPixel(), pixel);
        // The scan view, at the pixel's row, puts their span beside ours: one pixel shorter.
        ScanlineView* scan = m_window.findChild<ScanlineView*>();
        QVERIFY(scan && scan->model() && scan->model()->row);
        const auto& row = *scan->model()->row;
        const QString html =
            m_window.findChild<QTextBrowser*>(QStringLiteral("scanlineExplanation"))->toHtml();
        QVERIFY2(html.contains(QStringLiteral("Your renderer: pixels %1 to %2 (ours: %1 to %3).")
                                   .arg(row.xBegin)
                                   .arg(row.xEnd - 2)
                                   .arg(row.xEnd - 1)),
                 qPrintable(html));
        // Its grid outlines their span and crosses out the pixel only ours covers, on every
        // row of the triangle in the window.
        QVERIFY(scan->theirCoverage());
        const ScanlineView::TheirCoverage& theirs = *scan->theirCoverage();
        QCOMPARE(theirs.rowSpan, std::make_optional(std::make_pair(row.xBegin, row.xEnd - 2)));
        QVERIFY(theirs.onlyTheirs.empty());
        QVERIFY(std::find(theirs.onlyOurs.begin(), theirs.onlyOurs.end(),
                          QPoint(row.xEnd - 1, row.y)) != theirs.onlyOurs.end());
        const rl::ScanConversion& ours = *m_window.inspection()->frame()->scan;
        const std::uint32_t t = scan->model()->triangle;
        const QRect window = scan->drawnWindow();
        qsizetype rows = 0;
        for (std::uint32_t i = ours.spanStart[t]; i < ours.spanStart[t + 1]; ++i)
            rows += window.contains(ours.spans[i].xEnd - 1, ours.spans[i].y);
        QCOMPARE(theirs.onlyOurs.size(), rows);
        QVERIFY(!m_window.inspection()->atEnd());
        QVERIFY(m_window.inspection()->breakpoints().empty());  // the user's, put back
    }

    // Chained, the basis's mistake reaches every stage after it.
    void chainedFromTheWindow() {
        CheckPanel* panel = m_window.checkPanel();
        panel->chainBox()->setChecked(true);
        QVERIFY(checkWith(panel, "--u-v-cross-n"));
        panel->chainBox()->setChecked(false);
        QVERIFY(panel->report()->chained);
        // Each stage is judged on what it was sent: the basis fails, every later stage takes
        // the wrong basis's consequences right and passes, with an error carried.
        for (rl::StageId stage : rl::kAllStages)
            QCOMPARE(m_window.stageStrip()->checkMark(stage),
                     stage == rl::StageId::CameraBasis ? StageStrip::CheckMark::Failed
                                                       : StageStrip::CheckMark::Passed);
        const check::StageResult* view = panel->report()->result(check::Stage::View);
        QVERIFY(view && view->carried && *view->carried > 0);
    }

    // The z-buffer view marks the pixels whose winner differs.
    void zbufferViewMarksThePixels() {
        CheckPanel* panel = m_window.checkPanel();
        QVERIFY(checkWith(panel, "--depth-reversed"));
        QCOMPARE(int(*panel->selectedStage()), int(check::Stage::ZBuffer));
        const check::StageResult* r = panel->selectedResult();
        QVERIFY(r && r->differing > 100);
        QCOMPARE(m_window.zbufferView()->markedPixels(), r->departures.size());
        const QImage& mask = m_window.zbufferView()->imageView()->overlay().coverage;
        const check::Departure& d = r->departures.front();
        QCOMPARE(mask.pixelColor(int(d.ours.x), int(d.ours.y)).red(), 255);
        QCOMPARE(mask.pixelColor(0, 0).alpha(), 0);
    }

    // A program that hangs never blocks the window, and Cancel ends the check at once.
    void cancelEndsAHangingProgram() {
        CheckPanel* panel = m_window.checkPanel();
        panel->setCommand(QStringLiteral("sleep 100"));
        QSignalSpy finished(panel, &CheckPanel::finished);
        QVERIFY(panel->start().isEmpty());
        QVERIFY(panel->cancelButton()->isEnabled());
        QElapsedTimer clock;
        clock.start();
        QTest::qWait(300);  // the event loop runs: the window answers
        QTest::mouseClick(panel->cancelButton(), Qt::LeftButton);
        QVERIFY(finished.wait(5000));
        QVERIFY(clock.elapsed() < 5000);
        QVERIFY(panel->report()->cancelled);
        QCOMPARE(panel->progressBar()->format(), QStringLiteral("cancelled"));
    }

    void keptInLessonFiles() {
        CheckPanel* panel = m_window.checkPanel();
        panel->setCommand(QStringLiteral("python3 stages.py"));
        panel->setFolder(pythonFolder());
        QTemporaryDir dir;
        const QString path = dir.filePath("check.rasterlab");
        QVERIFY(m_window.saveLesson(path));
        const QByteArray text = testing::readFile(path);
        QVERIFY2(text.contains("\"check\""), text.constData());
        panel->setCommand(QString());
        panel->setFolder(QString());
        QVERIFY(m_window.openLesson(path));
        QVERIFY(QTest::qWaitFor([&] { return ready(m_window); }, kTimeoutMs));
        QCOMPARE(panel->command(), QStringLiteral("python3 stages.py"));
        QCOMPARE(panel->folder(), pythonFolder());
    }

    // The guides' pictures (docs/images/check-en.png, check-pt_BR.png): made when
    // RASTERLAB_SCREENSHOTS names a folder, under a real display (xvfb-run at 1280x720), since
    // the Check dock is a window of its own the first time.
    void screenshots() {
        const QString dir = qEnvironmentVariable("RASTERLAB_SCREENSHOTS");
        if (dir.isEmpty()) QSKIP("RASTERLAB_SCREENSHOTS names no folder");
        m_window.hide();
        for (const QString& language : {QStringLiteral("en"), QStringLiteral("pt_BR")}) {
            rasterlab::Translators translators;
            translators.install(language);
            MainWindow window;
            window.resize(1280, 720);
            window.show();
            QVERIFY(window.openExample(QStringLiteral("goblet")));
            QVERIFY(QTest::qWaitFor([&] { return ready(window); }, kTimeoutMs));
            window.showCheckDock();
            CheckPanel* panel = window.checkPanel();
            panel->setCommand(QStringLiteral("python3 stages.py --flip-y"));
            panel->setFolder(pythonFolder());
            QSignalSpy finished(panel, &CheckPanel::finished);
            QVERIFY(panel->start().isEmpty());
            QVERIFY(finished.wait(kTimeoutMs));
            QVERIFY(panel->stopAtFirstDeparture());
            QVERIFY(QTest::qWaitFor([&] { return ready(window); }, kTimeoutMs));
            QTest::qWait(1000);
            const QPixmap screen = QGuiApplication::primaryScreen()->grabWindow(0);
            QVERIFY(screen.save(QDir(dir).filePath("check-" + language + ".png")));
            // The scan view at a span that ends one pixel early.
            panel->setCommand(QStringLiteral("python3 stages.py --span-end-exclusive"));
            QVERIFY(panel->start().isEmpty());
            QVERIFY(finished.wait(kTimeoutMs));
            QVERIFY(panel->stopAtFirstDeparture());
            QVERIFY(QTest::qWaitFor([&] { return ready(window); }, kTimeoutMs));
            QTest::qWait(500);
            ScanlineView* scan = window.findChild<ScanlineView*>();
            QVERIFY(scan && scan->theirCoverage());
            QVERIFY(scan->grab().save(QDir(dir).filePath("check-scan-" + language + ".png")));
            translators.install(QStringLiteral("en"));
        }
        m_window.show();
    }

private:
    MainWindow m_window;
};

QTEST_MAIN(TestCheckWindow)
#include "tst_check_window.moc"
