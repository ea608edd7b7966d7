// The painter's algorithm dock (views/painter_view.h) on the long-triangle-over-a-small-one
// scene of tst_painter (numbers worked out there): its table in painted order, the selection
// shared with Inspection both ways, the explanation's numbers, and that it renders only while
// shown. With RASTERLAB_SCREENSHOTS set to a folder, it also saves pictures of the view there.
#include <QtTest>

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QTableView>

#include "app/window/main_window.h"
#include "pipeline/render/output_image.h"
#include "tests/course_scenes.h"
#include "tests/test_support.h"
#include "views/frame_image_view.h"
#include "views/inspection.h"
#include "views/painter_view.h"

using namespace rl;
using rasterlab::Inspection;
using rasterlab::PainterView;

namespace {

// The painter's failure of tst_painter (numbers in test_support.h): L's barycentre is farther
// (sqrt(443)/3 = 7.01586 against sqrt(21.5) = 4.63681), but L is nearer at (0,0), (1,0) and
// (0,1). `size` scales the screen (the same story, larger).
std::shared_ptr<const Scene> failureScene(ShadingModel shading, int size = 8,
                                          bool colours = false) {
    Scene scene = testing::painterFailureScene(shading, size);
    if (colours) {
        // For the pictures: a light behind the camera, S green, L orange.
        scene.lights.push_back({dvec4(0.0, 0.0, -5.0, 1.0), vec3(255.0f), {}});
        scene.draws[0].material.od = vec3(0.2f, 0.9f, 0.3f);
        scene.draws[1].material.od = vec3(1.0f, 0.6f, 0.2f);
    }
    return std::make_shared<const Scene>(std::move(scene));
}

QString cell(const QTableView* table, int row, int column) {
    return table->model()->index(row, column).data().toString();
}

void saveShot(QWidget& widget, const char* name) {
    const QString dir = qEnvironmentVariable("RASTERLAB_SCREENSHOTS");
    if (dir.isEmpty()) return;
    QDir().mkpath(dir);
    QCoreApplication::processEvents();  // the layout follows the texts set
    QVERIFY(
        widget.grab().save(QDir(dir).filePath(QString::fromLatin1(name) + QStringLiteral(".png"))));
}

}  // namespace

class TestPainterView : public QObject {
    Q_OBJECT

private slots:
    void orderTableAndSelection() {
        Inspection inspection;
        PainterView view(&inspection);
        view.resize(1100, 600);
        inspection.setFrame(testing::renderTrace(failureScene(ShadingModel::Painter)), QImage());
        QVERIFY(!view.comparison());  // hidden: nothing rendered
        view.show();
        QVERIFY(view.comparison());
        QTableView* table = view.orderTable();
        QCOMPARE(table->model()->rowCount(), 2);
        // Painted first: L (draw "L"), then S.
        QCOMPARE(cell(table, 0, 0), QStringLiteral("1"));
        QCOMPARE(cell(table, 0, 1), QStringLiteral("L"));
        QCOMPARE(cell(table, 0, 2), QStringLiteral("1"));
        QCOMPARE(cell(table, 0, 3), QStringLiteral("7.01586"));
        QCOMPARE(cell(table, 0, 4), QStringLiteral("3"));  // hidden wrongly at 3 pixels
        QCOMPARE(cell(table, 1, 1), QStringLiteral("S"));
        QCOMPARE(cell(table, 1, 3), QStringLiteral("4.63681"));
        QCOMPARE(cell(table, 1, 4), QStringLiteral("0"));
        QVERIFY2(view.explanation().contains(QStringLiteral(", 3 pixels differ")),
                 qPrintable(view.explanation()));
        // The frame is painted: its triangles are numbered by rank. A row selects in
        // Inspection; Inspection's selection moves the row.
        table->selectionModel()->setCurrentIndex(
            table->model()->index(1, 0),
            QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
        QCOMPARE(inspection.selectedTriangle(), std::optional<std::uint32_t>(1));
        QVERIFY2(view.explanation().contains(QStringLiteral(
                     "Triangle 1 (S): b = (-2.5, 2.5, 3), |b| = 4.63681, painted 2 of "
                     "2. The z-buffer shows it at 3 pixels; a triangle painted "
                     "after it covers 0 of them though it is farther there; it "
                     "covers 3 pixels of nearer triangles painted before it.")),
                 qPrintable(view.explanation()));
        inspection.selectTriangle(0);
        QCOMPARE(table->currentIndex().row(), 0);
        // L: the z-buffer shows it at 43 - 3 = 40 pixels, 3 of them covered by S.
        QVERIFY2(view.explanation().contains(QStringLiteral("shows it at 40 pixels; a triangle "
                                                            "painted after it covers 3 of them")),
                 qPrintable(view.explanation()));

        // A z-buffer frame of the same scene numbers its triangles in draw order: S is 0.
        inspection.setFrame(testing::renderTrace(failureScene(ShadingModel::Phong)), QImage());
        QCOMPARE(view.rankOf(0), std::optional<std::uint32_t>(1));
        QCOMPARE(view.frameTriangleOf(0), std::optional<std::uint32_t>(1));
        inspection.selectTriangle(0);
        QCOMPARE(table->currentIndex().row(), 1);
        QVERIFY(view.explanation().contains(QStringLiteral("The frame shown uses the z-buffer")));
        QCOMPARE(view.painterImageView()->image().size(), QSize(8, 8));
    }

    void windowDock() {
        // The window in painter mode: its frame is painted, and the dock's painter render of
        // the same scene has the same bytes.
        rasterlab::MainWindow window;
        window.resize(1600, 1000);
        auto* dock = window.findChild<QDockWidget*>(QStringLiteral("painterDock"));
        QVERIFY(dock);
        window.show();
        dock->show();
        dock->raise();
        window.setShading(ShadingModel::Painter);
        QVERIFY2(QTest::qWaitFor(
                     [&] {
                         const auto frame = window.currentFrame();
                         return frame && frame->depth->painted;
                     },
                     10000),
                 "no painted frame within 10 s");
        QVERIFY(
            QTest::qWaitFor([&] { return window.painterView()->comparison() != nullptr; }, 10000));
        const auto frame = window.currentFrame();
        const auto* c = window.painterView()->comparison();
        QVERIFY(c->painter->scene != frame->scene);  // rendered again by the dock
        QVERIFY(colourImage(*c->painter->shading, *c->painter->depth, frame->scene->conventions) ==
                colourImage(*frame->shading, *frame->depth, frame->scene->conventions));
        QVERIFY(c->wrongOrder > 0);  // the trefoil passes in front of itself
        saveShot(window, "painter-window");
    }

    void screenshots() {
        if (qEnvironmentVariableIsEmpty("RASTERLAB_SCREENSHOTS"))
            QSKIP("set RASTERLAB_SCREENSHOTS to a folder to save the pictures");
        Inspection inspection;
        PainterView view(&inspection);
        view.resize(1200, 560);
        view.show();
        inspection.setFrame(testing::renderTrace(failureScene(ShadingModel::Painter, 64, true)),
                            QImage());
        inspection.selectTriangle(1);
        saveShot(view, "painter-failure");
        inspection.setFrame(testing::renderTrace(testing::defaultCourseScene(
                                ShadingModel::Painter, RuleSet::Course, 800, 600)),
                            QImage());
        const auto* c = view.comparison();
        QVERIFY(c);
        // Select the triangle hidden wrongly at the most pixels.
        std::uint32_t worst = 0;
        for (std::uint32_t r = 0; r < c->hiddenWrongly.size(); ++r)
            if (c->hiddenWrongly[r] > c->hiddenWrongly[worst]) worst = r;
        inspection.selectTriangle(worst);
        saveShot(view, "painter-trefoil");
        view.findChild<QCheckBox*>(QStringLiteral("painterMarksTies"))->setChecked(true);
        saveShot(view, "painter-trefoil-ties");
        view.findChild<QCheckBox*>(QStringLiteral("painterMarksTies"))->setChecked(false);
        view.setLeftImage(1);
        saveShot(view, "painter-trefoil-order");
        view.setLeftImage(0);
        view.painterImageView()->zoomIn();
        inspection.setPresentation(true);
        saveShot(view, "painter-trefoil-presentation");
    }
};

QTEST_MAIN(TestPainterView)
#include "tst_painter_view.moc"
