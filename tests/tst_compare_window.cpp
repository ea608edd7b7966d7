// File > Compare with Image... in the window (offscreen): on the shipped goblet lesson, "their"
// image is ours with the ambient multiplied by Od (pipeline/analysis/mistakes.h); the Compare
// dock must rank that mistake first, count the differing pixels as rasterlab-cli compare does,
// show their colour at the pixel picked and the Phong term that would have to change; flicker
// and the threshold work; and a bad image gives the command line's message and keeps the scene.
// Every mistake the diagnosis knows is ranked first in the dock, and in Portuguese the
// diagnosis is Portuguese.
#include <QtTest>

#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QListWidget>
#include <QProgressDialog>
#include <QPushButton>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>

#include "app/window/compare_panel.h"
#include "app/window/edit_panel.h"
#include "app/window/main_window.h"
#include "app/window/translators.h"
#include "pipeline/analysis/mistakes.h"
#include "tests/test_support.h"

using rasterlab::ComparePanel;
using rasterlab::MainWindow;

namespace {

constexpr int kTimeoutMs = 60000;

bool savePng(const rl::Rgba8Image& image, const QString& path) {
    return QImage(image.rgba.data(), image.width, image.height, image.width * 4,
                  QImage::Format_RGBA8888)
        .save(path, "PNG");
}

// Our render of the window's frame with these mistakes, saved as their image.
bool saveWithMistakes(const MainWindow& window, const std::vector<rl::Slip>& slips,
                      const QString& path) {
    auto ours = rl::renderOurFrame(window.currentFrame()->scene);
    if (!ours) return false;
    auto theirs = rl::imageWithMistakes(ours.value(), slips);
    return theirs && theirs->has_value() && savePng(**theirs, path);
}

bool ready(const MainWindow& window) {
    return window.isReadyToStep() && !window.lessonViewPending();
}

}  // namespace

class TestCompareWindow : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        QVERIFY(m_window.openExample(QStringLiteral("goblet")));
        QVERIFY(QTest::qWaitFor([&] { return ready(m_window); }, kTimeoutMs));
        auto ours = rl::renderOurFrame(m_window.currentFrame()->scene);
        QVERIFY(ours);
        m_ours = ours->image;
        auto theirs = rl::imageWithMistake(ours.value(), rl::Mistake::AmbientTimesOd);
        QVERIFY(theirs && theirs->has_value());
        m_theirs = **theirs;
        m_theirPath = m_dir.filePath(QStringLiteral("theirs.png"));
        QVERIFY(savePng(m_theirs, m_theirPath));
    }

    void ranksTheMistakeFirst();
    void windowGoesOnDuringACompare();
    void cancelKeepsTheComparisonBefore();
    void countsAsTheCommandLine();
    void thresholdAndFlicker();
    void pickedPixel();
    void pickedPixelFollowsTheMove();
    void badImages_data();
    void badImages();
    void compareAgainAfterAChange();
    void diagnosisInPortuguese();
    void everyMistakeInTheDock_data();
    void everyMistakeInTheDock();
    void commandFileFindsTheMisreadCommand();
    void renderOursWithTheFittedLighting();

private:
    ComparePanel* panel() const { return m_window.comparePanel(); }
    QString cliError(const QString& image);

    QTemporaryDir m_dir;
    MainWindow m_window;
    rl::Rgba8Image m_ours, m_theirs;
    QString m_theirPath;
};

void TestCompareWindow::ranksTheMistakeFirst() {
    QAction* action = m_window.findChild<QAction*>(QStringLiteral("compareImageAction"));
    QVERIFY(action);
    QVERIFY(m_window.compareWithImage(m_theirPath));
    auto* dock = m_window.findChild<QDockWidget*>(QStringLiteral("compareDock"));
    QVERIFY(dock && !dock->isHidden());
    const rl::ImageComparison* c = panel()->comparison();
    QVERIFY(c && !c->diagnosis.empty());
    QCOMPARE(c->diagnosis.front().mistake, rl::Mistake::AmbientTimesOd);
    // The dock lists it first, in the command line's words.
    const QString text = panel()->diagnosisText();
    const QString first =
        QStringLiteral("1. ") + QString::fromStdString(c->diagnosis.front().title.english());
    QVERIFY2(text.contains(first), qPrintable(text));
    QVERIFY(text.indexOf(first) < text.indexOf(QStringLiteral("2. ")) ||
            !text.contains(QStringLiteral("2. ")));
    QVERIFY2(panel()->summaryText().contains(QStringLiteral("%1 differ").arg(c->differing)),
             qPrintable(panel()->summaryText()));
}

// Our render and the diagnosis run on a worker: the window's events (its painting, its
// timers) go on while a compare runs.
void TestCompareWindow::windowGoesOnDuringACompare() {
    int ticks = 0;
    QTimer timer;
    timer.setInterval(5);
    connect(&timer, &QTimer::timeout, this, [&] { ++ticks; });
    timer.start();
    QElapsedTimer clock;
    clock.start();
    QVERIFY(m_window.compareWithImage(m_theirPath));
    timer.stop();
    qInfo("the compare took %lld ms; a 5 ms timer fired %d times meanwhile", clock.elapsed(),
          ticks);
    QVERIFY(ticks > 0);
    QVERIFY(panel()->comparison());
}

// A compare still running after a moment shows a dialog over the window; its Cancel stops
// the worker within a few seconds (it checks between hypotheses), says so in the status bar
// rather than as an error, and the comparison shown before stays. The next compare runs.
void TestCompareWindow::cancelKeepsTheComparisonBefore() {
    QVERIFY(m_window.compareWithImage(m_theirPath));
    const rl::ImageComparison* before = panel()->comparison();
    const std::size_t differing = before->differing;
    // A long diagnosis: their goblet squeezed, its ambient times Od and its light in world
    // coordinates, on a frame of the window's size.
    std::vector<rl::Slip> slips(3);
    slips[0].mistake = rl::Mistake::ScreenMap;
    slips[0].map = rl::ScreenMap{0.9, 0.0, 0.0, 1.0, 30.0, 0.0};
    slips[1].mistake = rl::Mistake::AmbientTimesOd;
    slips[2].mistake = rl::Mistake::LightInWorld;
    const QString path = m_dir.filePath(QStringLiteral("long.png"));
    QVERIFY(saveWithMistakes(m_window, slips, path));
    bool shown = false;
    QElapsedTimer clock;
    qint64 cancelledAt = -1;
    QTimer::singleShot(ComparePanel::kProgressAfterMs + 300, this, [&] {
        auto* progress = m_window.findChild<QProgressDialog*>(QStringLiteral("compareProgress"));
        shown = progress && progress->isVisible();
        auto* button = progress ? progress->findChild<QPushButton*>() : nullptr;
        if (button) {
            cancelledAt = clock.elapsed();
            button->click();
        }
    });
    clock.start();
    const bool compared = m_window.compareWithImage(path);
    const qint64 stopped = clock.elapsed() - cancelledAt;
    QVERIFY(!compared);
    qInfo("cancelled at %lld ms, stopped %lld ms later", cancelledAt, stopped);
    QVERIFY2(cancelledAt >= 0, "no progress dialog while the compare ran");
    QVERIFY(shown);
    QVERIFY(panel()->wasCancelled());
    QVERIFY2(stopped < 5000, qPrintable(QString::number(stopped)));
    QCOMPARE(panel()->comparison(), before);
    QCOMPARE(panel()->comparison()->differing, differing);
    QCOMPARE(panel()->imagePath(), m_theirPath);
    QVERIFY2(m_window.statusBar()->currentMessage().contains(QStringLiteral("cancelled")),
             qPrintable(m_window.statusBar()->currentMessage()));
    QVERIFY(m_window.compareWithImage(m_theirPath));
    QVERIFY(!panel()->wasCancelled());
}

void TestCompareWindow::countsAsTheCommandLine() {
    QVERIFY(panel()->comparison());
    testing::CliRun run;
    QVERIFY2(testing::runCli({QStringLiteral("compare"), QStringLiteral("--scene"),
                              QStringLiteral("goblet"), QStringLiteral("--image"), m_theirPath,
                              QStringLiteral("--format"), QStringLiteral("json")},
                             m_dir.path(), run),
             qPrintable(run.problem));
    QCOMPARE(run.exitCode, 0);
    const QJsonObject cli = QJsonDocument::fromJson(run.out.toUtf8()).object();
    panel()->setThreshold(0);
    QCOMPARE(qint64(panel()->differingAboveThreshold()),
             cli.value(QStringLiteral("differing")).toInteger());
    QVERIFY(panel()->differingAboveThreshold() > 0);
    QCOMPARE(cli.value(QStringLiteral("diagnosis"))[0][QStringLiteral("mistake")].toString(),
             QStringLiteral("ambient-times-od"));
}

void TestCompareWindow::thresholdAndFlicker() {
    QVERIFY(panel()->comparison());
    // Above a threshold, the pixels that differ by more are coloured, the others ours
    // darkened. Their blue differs by 12 wherever the goblet is (Ia·ka·Od = 4, not 16).
    panel()->setMode(ComparePanel::Mode::Difference);
    panel()->setThreshold(0);
    const std::size_t all = panel()->differingAboveThreshold();
    for (int threshold : {11, 12}) {
        panel()->setThreshold(threshold);
        std::size_t counted = 0;
        const QImage& difference = panel()->differenceImage();
        for (int y = 0; y < m_ours.height; ++y)
            for (int x = 0; x < m_ours.width; ++x) {
                const std::uint8_t* a = m_ours.pixel(x, y);
                const std::uint8_t* b = m_theirs.pixel(x, y);
                int d = 0;
                for (int k = 0; k < 4; ++k) d = std::max(d, std::abs(int(a[k]) - int(b[k])));
                const QRgb shown = difference.pixel(x, y);
                if (d > threshold) {
                    ++counted;
                    QCOMPARE(qRed(shown), 255);  // yellow to red
                } else {
                    QCOMPARE(qRed(shown), a[0] / 3);
                }
            }
        QCOMPARE(panel()->differingAboveThreshold(), counted);
        QCOMPARE(counted, threshold == 11 ? all : 0);
    }
    panel()->setThreshold(0);
    // Flicker: theirs, then ours half a second later.
    panel()->setMode(ComparePanel::Mode::Flicker);
    QVERIFY(panel()->flickerShowsTheirs());
    QVERIFY(QTest::qWaitFor([&] { return !panel()->flickerShowsTheirs(); }, 2000));
    QVERIFY(QTest::qWaitFor([&] { return panel()->flickerShowsTheirs(); }, 2000));
    panel()->setMode(ComparePanel::Mode::SideBySide);
}

void TestCompareWindow::pickedPixel() {
    const rl::ImageComparison* c = panel()->comparison();
    QVERIFY(c && !c->diagnosis.front().examples.empty());
    const rl::PixelExample& e = c->diagnosis.front().examples.front();
    m_window.inspection()->pickPixel(QPoint(e.x, e.y));
    QVERIFY(QTest::qWaitFor([&] { return ready(m_window); }, kTimeoutMs));
    const QString text = panel()->pixelText();
    const auto bytes = [](const std::array<std::uint8_t, 4>& b) {
        return QStringLiteral("(%1, %2, %3, %4)").arg(b[0]).arg(b[1]).arg(b[2]).arg(b[3]);
    };
    QVERIFY2(text.contains(QStringLiteral("Pixel (%1, %2): theirs %3, ours %4.")
                               .arg(e.x)
                               .arg(e.y)
                               .arg(bytes(e.theirs), bytes(e.ours))),
             qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("Their colour is ours minus ")), qPrintable(text));
    // The ambient term, times Od, gives their colour; the specular term cannot.
    QVERIFY2(text.contains(QRegularExpression(
                 QStringLiteral("the ambient term Ia·ka would have to be .* instead of "
                                "\\(14, 14, 16\\).*: that is the term times Od"))),
             qPrintable(text));
    QVERIFY2(!text.contains(QRegularExpression(
                 QStringLiteral("the specular term [^\n]*that is the term times Od"))),
             qPrintable(text));
}

QString TestCompareWindow::cliError(const QString& image) {
    testing::CliRun run;
    if (!testing::runCli({QStringLiteral("compare"), QStringLiteral("--scene"),
                          QStringLiteral("goblet"), QStringLiteral("--image"), image},
                         m_dir.path(), run))
        return run.problem;
    return run.err.trimmed();
}

// Their goblet with x and y swapped and its ambient times Od: the move comes first, and the
// picked pixel's colour is theirs at the point the move takes it to, where the ambient term
// times Od gives it again.
void TestCompareWindow::pickedPixelFollowsTheMove() {
    std::vector<rl::Slip> slips(2);
    slips[0].mistake = rl::Mistake::ScreenMap;
    slips[0].map = rl::ScreenMap{0.0, 1.0, 1.0, 0.0, 0.0, 0.0};
    slips[1].mistake = rl::Mistake::AmbientTimesOd;
    const QString path = m_dir.filePath(QStringLiteral("swapped.png"));
    QVERIFY(saveWithMistakes(m_window, slips, path));
    QVERIFY(m_window.compareWithImage(path));
    const std::vector<rl::Finding>& found = panel()->comparison()->diagnosis;
    QCOMPARE(found.size(), std::size_t(2));
    QCOMPARE(found.front().mistake, rl::Mistake::ScreenMap);
    QCOMPARE(found.back().mistake, rl::Mistake::AmbientTimesOd);
    QVERIFY(!found.back().examples.empty());
    // An example of the ambient finding is a pixel of theirs; ours at (y, x) is its point.
    const rl::PixelExample e = found.back().examples.front();
    m_window.inspection()->pickPixel(QPoint(e.y, e.x));
    QVERIFY(QTest::qWaitFor([&] { return ready(m_window); }, kTimeoutMs));
    const QString text = panel()->pixelText();
    QVERIFY2(text.contains(QStringLiteral("this pixel's point of the surface is their pixel "
                                          "(%1, %2).")
                               .arg(e.x)
                               .arg(e.y)),
             qPrintable(text));
    QVERIFY2(text.contains(QRegularExpression(
                 QStringLiteral("the ambient term Ia·ka would have to be .* instead of "
                                "\\(14, 14, 16\\).*: that is the term times Od"))),
             qPrintable(text));
    QVERIFY(m_window.compareWithImage(m_theirPath));
}

void TestCompareWindow::badImages_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("content");  // empty: a 640x480 PNG
    QTest::addColumn<QString>("message");     // empty: the command line's
    QTest::newRow("other size") << "small.png" << QByteArray()
                                << "small.png: the image is 640x480, ours is 800x600";
    QTest::newRow("not a PNG") << "notes.png" << QByteArray("my notes\n") << QString();
    QTest::newRow("empty file") << "empty.png" << QByteArray("") << QString();
}

void TestCompareWindow::badImages() {
    QFETCH(QString, name);
    QFETCH(QByteArray, content);
    QFETCH(QString, message);
    const QString path = m_dir.filePath(name);
    if (name == QLatin1String("small.png")) {
        QImage small(640, 480, QImage::Format_RGBA8888);
        small.fill(Qt::black);
        QVERIFY(small.save(path, "PNG"));
    } else {
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(content);
    }
    if (message.isEmpty()) message = cliError(name);
    QVERIFY(!message.isEmpty());
    const auto frame = m_window.currentFrame();
    const QString title = m_window.lessonTitle();
    const rl::ImageComparison* before = panel()->comparison();
    QVERIFY(!m_window.compareWithImage(path));
    QVERIFY(m_window.messages()->count() > 0);
    QCOMPARE(m_window.messages()->item(0)->text(),
             QStringLiteral("Error: ") + m_dir.filePath(message));
    // The scene, its frame and the comparison shown stay.
    QCOMPARE(m_window.currentFrame(), frame);
    QCOMPARE(m_window.lessonTitle(), title);
    QCOMPARE(panel()->comparison(), before);
    QCOMPARE(panel()->imagePath(), m_theirPath);
}

void TestCompareWindow::compareAgainAfterAChange() {
    // Another shading model: the comparison is of the scene before, until compared again.
    auto* again = panel()->findChild<QPushButton*>(QStringLiteral("compareAgainButton"));
    QVERIFY(again && again->isHidden());
    const auto before = m_window.currentFrame();
    m_window.setShading(rl::ShadingModel::Flat);
    QVERIFY(QTest::qWaitFor([&] { return m_window.currentFrame() != before && ready(m_window); },
                            kTimeoutMs));
    QVERIFY(panel()->isStale());
    QVERIFY(!again->isHidden());
    QVERIFY(panel()->summaryText().contains(QStringLiteral("The scene has changed")));
    again->click();
    QVERIFY(!panel()->isStale());
    QVERIFY(again->isHidden());
    // Flat shading against their Phong image differs by more than the ambient's 12 in blue.
    const std::array<int, 4>& largest = panel()->comparison()->largest;
    QVERIFY(*std::max_element(largest.begin(), largest.end()) > 12);
}

// In a Portuguese window the diagnosis is Portuguese: its titles, evidence and advice are
// message templates (pipeline/core/message.h), translated as the readers' errors are.
void TestCompareWindow::diagnosisInPortuguese() {
    rasterlab::Translators translators;
    translators.install(QStringLiteral("pt_BR"));
    const auto english = qScopeGuard([&] { translators.install(QStringLiteral("en")); });
    MainWindow window;
    QVERIFY(window.openExample(QStringLiteral("goblet")));
    QVERIFY(QTest::qWaitFor([&] { return ready(window); }, kTimeoutMs));
    QVERIFY(window.compareWithImage(m_theirPath));
    const QString text = window.comparePanel()->diagnosisText();
    QVERIFY2(text.contains(QStringLiteral("1. o termo ambiente multiplicado pela cor do objeto: "
                                          "Ia*ka*Od em vez de Ia*ka")),
             qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("nossos pixels iluminados de novo com essa fórmula")),
             qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("o termo ambiente da seed 000 é Ia*ka, sem a cor do "
                                          "objeto Od")),
             qPrintable(text));
    QVERIFY2(!text.contains(QStringLiteral("multiplied")), qPrintable(text));
}

void TestCompareWindow::everyMistakeInTheDock_data() {
    QTest::addColumn<int>("mistake");
    QTest::addColumn<QString>("lesson");
    for (std::size_t m = 0; m < rl::kMistakeCount; ++m) {
        const auto kind = static_cast<rl::Mistake>(m);
        // No lesson has two vertices at one position, where normals shared by position show:
        // tst_compare_students finds it on a faceted goblet.
        if (kind == rl::Mistake::NormalsSharedByPosition) continue;
        // The goblet is lit per pixel and has no two triangles at one depth: Phong and depth
        // ties show on the sphere lesson (flat shading, shared edges at equal depths).
        const bool sphere = kind == rl::Mistake::Phong || kind == rl::Mistake::DepthTies;
        const QString lesson = QString::fromLatin1(sphere ? "sphere" : "goblet");
        QTest::newRow(qPrintable(QStringLiteral("%1 on %2").arg(rl::mistakeId(kind), lesson)))
            << int(m) << lesson;
    }
}

// Each mistake the diagnosis knows, made by the diagnosis's own hypothesis on a shipped
// lesson (an offset of -3, a scale of 0.8, x and y swapped): the dock ranks it first,
// removing the whole difference, and lists it first in its text.
void TestCompareWindow::everyMistakeInTheDock() {
    QFETCH(int, mistake);
    QFETCH(QString, lesson);
    const auto kind = static_cast<rl::Mistake>(mistake);
    QVERIFY(m_window.openExample(lesson));
    QVERIFY(QTest::qWaitFor([&] { return ready(m_window); }, kTimeoutMs));
    auto ours = rl::renderOurFrame(m_window.currentFrame()->scene);
    QVERIFY(ours);
    const std::array<std::uint8_t, 4> value = kind == rl::Mistake::Alpha
                                                  ? std::array<std::uint8_t, 4>{0, 0, 0, 128}
                                                  : std::array<std::uint8_t, 4>{40, 40, 40, 255};
    const double amount = kind == rl::Mistake::ColourScale ? 0.8 : -3.0;
    // The screen map: x and y swapped, as a program that writes pixel (x, y) at (y, x) does.
    const rl::Slip slip{kind, rl::ivec2(0, 1), value, amount, rl::ScreenMap{0.0, 1.0, 1.0, 0.0, 0.0, 0.0}};
    auto theirs = rl::imageWithMistakes(ours.value(), {slip});
    QVERIFY(theirs);
    QVERIFY2(theirs->has_value() && **theirs != ours->image, "the mistake changes nothing");
    const QString path = m_dir.filePath(QStringLiteral("mistake.png"));
    QVERIFY(savePng(**theirs, path));
    QVERIFY(m_window.compareWithImage(path));
    const rl::ImageComparison* c = panel()->comparison();
    QVERIFY(c && !c->diagnosis.empty());
    QString ranking;
    for (const rl::Finding& f : c->diagnosis)
        ranking += QStringLiteral("%1 %2; ").arg(rl::mistakeId(f.mistake)).arg(f.share, 0, 'f', 4);
    QVERIFY2(c->diagnosis.front().mistake == kind, qPrintable(ranking));
    QCOMPARE(c->diagnosis.front().share, 1.0);
    const QString first =
        QStringLiteral("1. ") + QString::fromStdString(c->diagnosis.front().title.english());
    QVERIFY2(panel()->diagnosisText().contains(first), qPrintable(panel()->diagnosisText()));
}


// A command file shown: their image made from it with a translate left out (the text
// edited here, drawn by the command line) is diagnosed as that line ignored.
void TestCompareWindow::commandFileFindsTheMisreadCommand() {
    const QString ours = QStringLiteral(
        "png 64 64 mine.png\n"
        "xyz -0.5 -0.4 0\nxyz 0.5 -0.4 0\nxyz 0.1 0.5 0\n"
        "frustum -0.3 0.3 -0.3 0.3 1 10\n"
        "translate 0 0 -3\n"
        "translate 0.2 0 0\n"
        "color 1 0.5 0\n"
        "trif 1 2 3\n");
    QString theirs = ours;
    theirs.replace(QStringLiteral("translate 0.2 0 0"), QString());
    const auto write = [&](const QString& name, const QString& text) {
        QFile file(m_dir.filePath(name));
        return file.open(QIODevice::WriteOnly) && file.write(text.toUtf8()) == text.toUtf8().size();
    };
    QVERIFY(write(QStringLiteral("ours.txt"), ours) && write(QStringLiteral("theirs.txt"), theirs));
    testing::CliRun run;
    QVERIFY2(testing::runCli({QStringLiteral("run"), QStringLiteral("theirs.txt")}, m_dir.path(),
                             run),
             qPrintable(run.problem));
    QCOMPARE(run.exitCode, 0);
    QVERIFY(m_window.openCommandFile(m_dir.filePath(QStringLiteral("ours.txt"))));
    QVERIFY(QTest::qWaitFor([&] { return ready(m_window); }, kTimeoutMs));
    QVERIFY(m_window.compareWithImage(m_dir.filePath(QStringLiteral("mine.png"))));
    const rl::ImageComparison* c = panel()->comparison();
    QVERIFY(c && !c->diagnosis.empty());
    QCOMPARE(c->diagnosis.front().mistake, rl::Mistake::CommandMisread);
    QCOMPARE(c->diagnosis.front().command.line, 7);
    QVERIFY2(panel()->diagnosisText().contains(QStringLiteral("1. line 7: 'translate' ignored")),
             qPrintable(panel()->diagnosisText()));
}


// Their goblet lit from elsewhere (the scene's light moved here, before rendering theirs):
// the lighting fitted to their colours puts the light back where they had it, and Render
// Ours with the Fitted Lighting sets it in the scene as one undo step; compared again, the
// two images nearly agree: a tenth of the pixels differ at most, by at most 3.
void TestCompareWindow::renderOursWithTheFittedLighting() {
    QVERIFY(m_window.openExample(QStringLiteral("goblet")));
    QVERIFY(QTest::qWaitFor([&] { return ready(m_window); }, kTimeoutMs));
    const rl::dvec3 original = [&] {
        const auto v = m_window.document().value(rasterlab::SceneDocument::Field::LightPosition, 0);
        return rl::dvec3(v[0], v[1], v[2]);
    }();
    const rl::dvec3 moved = original + rl::dvec3(4.0, -3.0, 1.0);
    auto scene = std::make_shared<rl::Scene>(*m_window.currentFrame()->scene);
    scene->lights[0].pWorld = rl::dvec4(moved, 1.0);
    auto theirs = rl::renderOurFrame(scene);
    QVERIFY(theirs);
    const QString path = m_dir.filePath(QStringLiteral("moved-light.png"));
    QVERIFY(savePng(theirs->image, path));
    QVERIFY(m_window.compareWithImage(path));
    const std::size_t before = panel()->comparison()->differing;
    QPushButton* use = panel()->useFitButton();
    QVERIFY(!use->isHidden());
    QCOMPARE(panel()->comparison()->diagnosis.front().mistake, rl::Mistake::FittedLighting);
    const auto frame = m_window.currentFrame();
    use->click();
    QVERIFY(QTest::qWaitFor([&] { return m_window.currentFrame() != frame && ready(m_window); },
                            kTimeoutMs));
    const auto fitted = m_window.document().value(rasterlab::SceneDocument::Field::LightPosition, 0);
    for (int k = 0; k < 3; ++k)
        QVERIFY2(std::abs(fitted[std::size_t(k)] - moved[k]) < 0.05,
                 qPrintable(QStringLiteral("%1 against %2").arg(fitted[std::size_t(k)]).arg(moved[k])));
    QVERIFY(m_window.compareWithImage(path));
    // The fitted values, as the edit panel keeps them, leave bytes a unit or two apart.
    const rl::ImageComparison& again = *panel()->comparison();
    const int largest = *std::max_element(again.largest.begin(), again.largest.end());
    QVERIFY2(again.differing * 10 < before && largest <= 3,
             qPrintable(QStringLiteral("%1 then %2, largest %3")
                            .arg(before)
                            .arg(again.differing)
                            .arg(largest)));
    m_window.editPanel()->undoStack()->undo();  // one step puts every value back
    const auto undone = m_window.document().value(rasterlab::SceneDocument::Field::LightPosition, 0);
    QCOMPARE(rl::dvec3(undone[0], undone[1], undone[2]), original);
}

QTEST_MAIN(TestCompareWindow)
#include "tst_compare_window.moc"
