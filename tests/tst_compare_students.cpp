// rasterlab-cli compare on images no RasterLab code made: examples/student/python's
// rasterizer, written from the seed alone, with one, two or three of its mistakes switched
// on. Each switched-on mistake must be found (the dominant one first when there is one), and
// what stays unexplained must be small; an unlit image is compared as coverage; their light
// elsewhere is found by fitting the lighting to their colours; an image no mistake of the
// catalogue made (gamma-encoded bytes) is said to be mostly unexplained.
#include <QtTest>

#include <QJsonArray>
#include <QJsonDocument>
#include <QFile>
#include <QImage>
#include <QJsonObject>
#include <QMap>
#include <QProcess>
#include <QRandomGenerator>
#include <QTemporaryDir>

#include <algorithm>
#include <cmath>

#include "pipeline/analysis/screen_map.h"
#include "tests/test_support.h"

using testing::CliRun;
using testing::runCli;

namespace {

// A shipped scene in the course's files, which the student's program reads.
struct CourseScene {
    QString camera, lighting, object;
    QStringList options() const {
        return {QStringLiteral("--camera"), camera, QStringLiteral("--lighting"), lighting,
                QStringLiteral("--object"), object};
    }
};

CourseScene lesson(const QString& name) {
    const QString root = testing::sourceDir() + QStringLiteral("/resources/");
    if (name == QLatin1String("default"))
        return {root + "default-scene/camera.cfg", root + "default-scene/lighting.txt",
                root + "default-scene/trefoil.byu"};
    const QString dir = root + QStringLiteral("lessons/") + name + QLatin1Char('/');
    return {dir + "camera.cfg", dir + "lighting.txt", dir + name + ".byu"};
}

// The student's program draws the scene at 240x180 with the switches, into dir.
QString studentImage(const QTemporaryDir& dir, const CourseScene& scene, const QStringList& switches,
                     QString& problem) {
    const QString out = dir.filePath(QStringLiteral("theirs.png"));
    QProcess python;
    python.setWorkingDirectory(dir.path());
    python.start(QStringLiteral(RASTERLAB_PYTHON),
                 QStringList{testing::sourceDir() + "/examples/student/python/rasterizer.py"} +
                     scene.options() +
                     QStringList{QStringLiteral("--size"), QStringLiteral("240x180"),
                                 QStringLiteral("--output"), out} +
                     switches);
    if (!python.waitForFinished(120000) || python.exitCode() != 0) {
        problem = QStringLiteral("the student's program failed: %1")
                      .arg(QString::fromUtf8(python.readAllStandardError()));
        return {};
    }
    return out;
}

// compare without --size: their image's size is ours.
QJsonObject compareJson(const QTemporaryDir& dir, const CourseScene& scene, const QString& image,
                        CliRun& run) {
    const QStringList arguments = QStringList{QStringLiteral("compare")} + scene.options() +
                                  QStringList{QStringLiteral("--image"), image,
                                              QStringLiteral("--format"), QStringLiteral("json")};
    if (!runCli(arguments, dir.path(), run)) return {};
    return QJsonDocument::fromJson(run.out.toUtf8()).object();
}

// The student's image of the scene with the switches, compared: compare's JSON.
#define COMPARE_STUDENT(result, scene, switches)                                       \
    QTemporaryDir dir;                                                                 \
    QVERIFY(dir.isValid());                                                            \
    QString problem;                                                                   \
    const CourseScene course = lesson(scene);                                          \
    const QString image = studentImage(dir, course, switches, problem);                \
    QVERIFY2(!image.isEmpty(), qPrintable(problem));                                   \
    CliRun run;                                                                        \
    const QJsonObject result = compareJson(dir, course, image, run);                   \
    QVERIFY2(run.exitCode == 0, qPrintable(run.err))

// examples/student/hw2's program run in dir on a command file's text with the switches, and
// its image compared with ours: compare's JSON (empty, with the problem in run, on a failure).
QJsonObject hw2StudentCompared(const QTemporaryDir& dir, const QString& text,
                               const QStringList& switches, CliRun& run) {
    const QString hw2 = testing::sourceDir() + QStringLiteral("/examples/student/hw2/");
    QFile file(dir.filePath(QStringLiteral("scene.txt")));
    if (!file.open(QIODevice::WriteOnly)) return {};
    file.write(text.toUtf8());
    file.close();
    QProcess python;
    python.setWorkingDirectory(dir.path());
    python.start(QStringLiteral(RASTERLAB_PYTHON),
                 QStringList{hw2 + QStringLiteral("rasterizer.py"), QStringLiteral("scene.txt")} +
                     switches);
    if (!python.waitForFinished(120000) || python.exitCode() != 0) {
        run.problem = QString::fromUtf8(python.readAllStandardError());
        return {};
    }
    if (!runCli({"compare", "scene.txt", "--image", "scene.png", "--format", "json"}, dir.path(),
                run))
        return {};
    return QJsonDocument::fromJson(run.out.toUtf8()).object();
}

QString hw2SceneText() {
    return QString::fromUtf8(
        testing::readFile(testing::sourceDir() + QStringLiteral("/examples/student/hw2/scene.txt")));
}

QString ranking(const QJsonObject& result) {
    QString text;
    for (const auto& d : result[QStringLiteral("diagnosis")].toArray())
        text += QStringLiteral("%1 %2; ")
                    .arg(d[QStringLiteral("mistake")].toString())
                    .arg(d[QStringLiteral("share")].toDouble(), 0, 'f', 3);
    return text + QStringLiteral("unexplained %1")
                      .arg(result[QStringLiteral("unexplained")][QStringLiteral("share")].toDouble(),
                           0, 'f', 3);
}

// The student's switches and the mistake compare must name for each.
struct Switch {
    QStringList arguments;
    QString mistake;
};

const QList<Switch>& pool() {
    static const QList<Switch> switches = {
        {{"--light-in-world"}, "light-in-world"},
        {{"--light-no-minus-c"}, "light-without-c"},
        {{"--depth-reversed"}, "depth-reversed"},
        {{"--round-vertices"}, "vertex-snap"},
        {{"--flip-y"}, "upside-down"},
        {{"--mirror-x"}, "mirrored-left-right"},
        {{"--no-flip-normal"}, "normal-not-flipped"},
        {{"--ambient-times-od"}, "ambient-times-od"},
        {{"--gouraud"}, "gouraud"},
        {{"--color-offset", "-4"}, "colour-offset"},
        {{"--color-scale", "0.85"}, "colour-scale"},
    };
    return switches;
}

// Pairs the student's program makes one image of, or that are one image in effect: the
// world light overrides the light without C; a reversed depth test with unturned normals
// draws the far faces lit from behind, which is the near faces with V reversed; an offset and
// a scale of the same bytes trade against each other.
bool together(const QString& a, const QString& b) {
    const auto pair = [&](const char* x, const char* y) {
        return (a == QLatin1String(x) && b == QLatin1String(y)) ||
               (a == QLatin1String(y) && b == QLatin1String(x));
    };
    return !pair("light-in-world", "light-without-c") &&
           !pair("depth-reversed", "normal-not-flipped") &&
           !pair("colour-offset", "colour-scale");
}

}  // namespace

class TestCompareStudents : public QObject {
    Q_OBJECT

private slots:
    void oneMistake_data();
    void oneMistake();
    void severalMistakes_data();
    void severalMistakes();
    void unlitImageComparesCoverage();
    void unknownMistakeIsUnexplained();
    void fittedLightingComposes();
    void fitsWhatTheirLightingUsed();
    void namesAColourScaledBy255();
    void fitsTheScreenMap_data();
    void fitsTheScreenMap();
    void fitsATurnedCoverage();
    void normalsSharedByPosition();
    void commandFileOfAnIndependentRenderer_data();
    void commandFileOfAnIndependentRenderer();
    void commandNeverImplemented();
    void coveredPixelsAfterTheBackground();
};

void TestCompareStudents::oneMistake_data() {
    QTest::addColumn<QString>("scene");
    QTest::addColumn<QStringList>("switches");
    QTest::addColumn<QString>("expected");
    for (const Switch& s : pool())
        QTest::newRow(qPrintable("goblet " + s.arguments.join(' ')))
            << "goblet" << s.arguments << s.mistake;
    // The goblet's ka is not 1, so Ia alone shows.
    QTest::newRow("goblet --ambient-ia-only") << "goblet" << QStringList{"--ambient-ia-only"}
                                              << "ambient-ia-only";
    QTest::newRow("goblet --v-equals-p") << "goblet" << QStringList{"--v-equals-p"}
                                         << "view-vector-reversed";
    QTest::newRow("goblet --l-reversed") << "goblet" << QStringList{"--l-reversed"}
                                         << "view-vector-reversed";
    // x and y swapped in the pixel's index: the screen map, the whole of it.
    QTest::newRow("goblet --pixels-transposed") << "goblet" << QStringList{"--pixels-transposed"}
                                                << "screen-map";
    // The camera basis and the normals stage, rendered as the student's stages make them.
    QTest::newRow("goblet --u-v-cross-n") << "goblet" << QStringList{"--u-v-cross-n"}
                                          << "basis-u-reversed";
    QTest::newRow("goblet --no-normalize-n-before-gram-schmidt")
        << "goblet" << QStringList{"--no-normalize-n-before-gram-schmidt"}
        << "basis-n-not-normalised";
    QTest::newRow("sphere --no-normalize-n-before-gram-schmidt")
        << "sphere" << QStringList{"--no-normalize-n-before-gram-schmidt"}
        << "basis-n-not-normalised";
    QTest::newRow("goblet --vertex-normals-unnormalized")
        << "goblet" << QStringList{"--vertex-normals-unnormalized"} << "vertex-normals-unnormalised";
    QTest::newRow("sphere --vertex-normals-unnormalized")
        << "sphere" << QStringList{"--vertex-normals-unnormalized"} << "vertex-normals-unnormalised";
    QTest::newRow("goblet --sum-unnormalized-triangle-normals")
        << "goblet" << QStringList{"--sum-unnormalized-triangle-normals"}
        << "area-weighted-normals";
    QTest::newRow("default --sum-unnormalized-triangle-normals")
        << "default" << QStringList{"--sum-unnormalized-triangle-normals"}
        << "area-weighted-normals";
    QTest::newRow("goblet --no-clamp") << "goblet" << QStringList{"--no-clamp"} << "colour-wrap";
    // Every byte one lower: an offset, not a normal left unnormalised.
    QTest::newRow("default --color-offset -1") << "default" << QStringList{"--color-offset", "-1"}
                                               << "colour-offset";
    QTest::newRow("default --light-in-world") << "default" << QStringList{"--light-in-world"}
                                              << "light-in-world";
    QTest::newRow("default --depth-reversed") << "default" << QStringList{"--depth-reversed"}
                                              << "depth-reversed";
    QTest::newRow("default --truncate-terms") << "default" << QStringList{"--truncate-terms"}
                                              << "terms-truncated";
}

void TestCompareStudents::oneMistake() {
    QFETCH(QString, scene);
    QFETCH(QStringList, switches);
    QFETCH(QString, expected);
    COMPARE_STUDENT(result, scene, switches);
    qInfo("%s: %lld differing; %s", QTest::currentDataTag(),
          result[QStringLiteral("differing")].toInteger(), qPrintable(ranking(result)));
    const QJsonArray diagnosis = result[QStringLiteral("diagnosis")].toArray();
    QVERIFY2(!diagnosis.isEmpty(), qPrintable(run.out));
    QCOMPARE(diagnosis.first()[QStringLiteral("mistake")].toString(), expected);
    QVERIFY2(diagnosis.first()[QStringLiteral("share")].toDouble() >= 0.9, qPrintable(ranking(result)));
    QVERIFY2(result[QStringLiteral("unexplained")][QStringLiteral("share")].toDouble() <= 0.02,
             qPrintable(ranking(result)));
    QCOMPARE(result[QStringLiteral("width")].toInt(), 240);  // ours drawn at their size
    // A constant's evidence is the histogram of theirs - ours.
    const QString evidence = diagnosis.first()[QStringLiteral("evidence")].toString();
    if (expected == QLatin1String("colour-offset"))
        QVERIFY2(evidence.startsWith(QStringLiteral("theirs - ours is %1 in ")
                                         .arg(switches.value(1).toInt())),
                 qPrintable(evidence));
    if (expected == QLatin1String("colour-scale"))
        QVERIFY2(evidence.startsWith(QStringLiteral("theirs is within 2 of 0.85 times ours in ")),
                 qPrintable(evidence));
}

void TestCompareStudents::severalMistakes_data() {
    QTest::addColumn<QString>("scene");
    QTest::addColumn<QStringList>("switches");
    QTest::addColumn<QStringList>("expected");
    // Pairs and triples drawn from the pool with a fixed seed, so that a failure repeats.
    QRandomGenerator random(20261128);
    const QStringList scenes = {"goblet", "default"};
    for (int k = 0; k < 10; ++k) {
        const int count = k < 6 ? 2 : 3;
        QList<Switch> chosen;
        while (chosen.size() < count) {
            const Switch& s = pool()[int(random.bounded(quint32(pool().size())))];
            if (std::all_of(chosen.begin(), chosen.end(), [&](const Switch& c) {
                    return c.mistake != s.mistake && together(c.mistake, s.mistake);
                }))
                chosen.push_back(s);
        }
        QStringList switches, expected;
        for (const Switch& s : chosen) {
            switches += s.arguments;
            expected += s.mistake;
        }
        const QString scene = scenes[k % 2];
        QTest::newRow(qPrintable(scene + ' ' + switches.join(' ')))
            << scene << switches << expected;
    }
}

void TestCompareStudents::severalMistakes() {
    QFETCH(QString, scene);
    QFETCH(QStringList, switches);
    QFETCH(QStringList, expected);
    COMPARE_STUDENT(result, scene, switches);
    qInfo("%s: %s", QTest::currentDataTag(), qPrintable(ranking(result)));
    QStringList found;
    for (const auto& d : result[QStringLiteral("diagnosis")].toArray())
        found += d[QStringLiteral("mistake")].toString();
    // Every mistake switched on is found, and nothing else.
    QStringList sortedFound = found, sortedExpected = expected;
    sortedFound.sort();
    sortedExpected.sort();
    QVERIFY2(sortedFound == sortedExpected, qPrintable(ranking(result)));
    QVERIFY2(result[QStringLiteral("unexplained")][QStringLiteral("share")].toDouble() <= 0.02,
             qPrintable(ranking(result)));
}

void TestCompareStudents::unlitImageComparesCoverage() {
    const QStringList switches = {"--flat-color", "0,200,0", "--round-vertices"};
    COMPARE_STUDENT(result, QStringLiteral("goblet"), switches);
    const QJsonObject unlit = result[QStringLiteral("unlit")].toObject();
    QCOMPARE(unlit[QStringLiteral("comparedAs")].toString(), QStringLiteral("coverage"));
    QCOMPARE(unlit[QStringLiteral("colour")].toArray(), (QJsonArray{0, 200, 0, 255}));
    // Only the rounded vertices' coverage differs, and it is found.
    const QJsonArray diagnosis = result[QStringLiteral("diagnosis")].toArray();
    QCOMPARE(diagnosis.size(), 1);
    QCOMPARE(diagnosis.first()[QStringLiteral("mistake")].toString(), QStringLiteral("vertex-snap"));
    QCOMPARE(result[QStringLiteral("unexplained")][QStringLiteral("pixels")].toInt(), 0);
    QCOMPARE(result[QStringLiteral("differing")].toInteger(),
             result[QStringLiteral("onlyOurs")].toInteger() +
                 result[QStringLiteral("onlyTheirs")].toInteger());
}

namespace {

// Their goblet with its light somewhere else, written in the course's lighting file.
QString movedLightImage(const QTemporaryDir& dir, const QStringList& switches, QString& problem) {
    CourseScene theirScene = lesson(QStringLiteral("goblet"));
    QFile lighting(theirScene.lighting);
    if (!lighting.open(QIODevice::ReadOnly)) return {};
    QStringList lines = QString::fromUtf8(lighting.readAll()).split(QLatin1Char('\n'));
    lines[0] = QStringLiteral("-300 -100 50");  // Pl, world
    theirScene.lighting = dir.filePath(QStringLiteral("moved.txt"));
    QFile moved(theirScene.lighting);
    if (!moved.open(QIODevice::WriteOnly)) return {};
    moved.write(lines.join(QLatin1Char('\n')).toUtf8());
    moved.close();
    return studentImage(dir, theirScene, switches, problem);
}

}  // namespace

void TestCompareStudents::unknownMistakeIsUnexplained() {
    // Their bytes gamma-encoded (255 (c / 255)^(1 / 2.2)): no mistake of the catalogue, and
    // no lighting, makes that curve. Whatever the search finds, most of the differing pixels
    // stay, and compare says so.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QString problem;
    const QString image = studentImage(dir, lesson("goblet"), {}, problem);
    QVERIFY2(!image.isEmpty(), qPrintable(problem));
    QImage encoded(image);
    QVERIFY(!encoded.isNull());
    encoded = encoded.convertToFormat(QImage::Format_RGB32);
    const auto gamma = [](int c) { return int(std::lround(255.0 * std::pow(c / 255.0, 1.0 / 2.2))); };
    for (int y = 0; y < encoded.height(); ++y)
        for (int x = 0; x < encoded.width(); ++x) {
            const QRgb p = encoded.pixel(x, y);
            encoded.setPixel(x, y, qRgb(gamma(qRed(p)), gamma(qGreen(p)), gamma(qBlue(p))));
        }
    QVERIFY(encoded.save(image));
    CliRun run;
    QVERIFY2(runCli(QStringList{QStringLiteral("compare")} + lesson("goblet").options() +
                        QStringList{QStringLiteral("--image"), image},
                    dir.path(), run),
             qPrintable(run.problem));
    QCOMPARE(run.exitCode, 0);
    const QStringList out = run.out.split(QLatin1Char('\n'));
    QVERIFY2(out.contains(
                 QStringLiteral("  none of the known mistakes explains most of this difference")),
             qPrintable(run.out));
    CliRun json;
    const QJsonObject result = compareJson(dir, lesson("goblet"), image, json);
    const QJsonObject unexplained = result[QStringLiteral("unexplained")].toObject();
    QVERIFY(unexplained[QStringLiteral("most")].toBool());
    QVERIFY2(unexplained[QStringLiteral("pixels")].toInteger() * 2 >
                 result[QStringLiteral("differing")].toInteger(),
             qPrintable(ranking(result)));
}

// Their light elsewhere (a value, not a catalogued mistake) and their vertices rounded: ours
// rendered with the lighting fitted to their colours comes first, the rounding after it. The
// moved light is far (view (-300, -113.29, -0.73)), so its distance is loosely fitted, and
// its direction closely: within 5 degrees.
void TestCompareStudents::fittedLightingComposes() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QString problem;
    const QString image = movedLightImage(dir, {"--round-vertices"}, problem);
    QVERIFY2(!image.isEmpty(), qPrintable(problem));
    CliRun run;
    const QJsonObject result = compareJson(dir, lesson("goblet"), image, run);
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    QStringList found;
    for (const auto& d : result[QStringLiteral("diagnosis")].toArray())
        found += d[QStringLiteral("mistake")].toString();
    QCOMPARE(found.value(0), QStringLiteral("fitted-lighting"));
    QVERIFY2(found.contains(QStringLiteral("vertex-snap")), qPrintable(ranking(result)));
    QVERIFY2(result[QStringLiteral("unexplained")][QStringLiteral("share")].toDouble() <= 0.03,
             qPrintable(ranking(result)));
    const double expected[] = {-300.0, -113.29, -0.73};
    const QJsonArray values = result[QStringLiteral("lightingFit")][QStringLiteral("values")].toArray();
    double dot = 0.0, fitted = 0.0, moved = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double v = values[k][QStringLiteral("theirs")].toDouble();
        dot += v * expected[k];
        fitted += v * v;
        moved += expected[k] * expected[k];
    }
    const double degrees = std::acos(std::min(1.0, dot / std::sqrt(fitted * moved))) * 180.0 / M_PI;
    QVERIFY2(degrees < 5.0, qPrintable(QString::number(degrees)));
}

// The lighting fitted to their colours: where their light effectively was, and their ambient
// term, against what the student's program was given.
void TestCompareStudents::namesAColourScaledBy255() {
    // Divided by 255, the goblet's colours truncate to 0 or 1: black where it covers, too far
    // off for the least-squares scale, which leaves out the channels either side clamps.
    {
        COMPARE_STUDENT(result, QStringLiteral("goblet"),
                        (QStringList{QStringLiteral("--color-scale"),
                                     QString::number(1.0 / 255.0, 'g', 17)}));
        qInfo("divided by 255: %s", qPrintable(ranking(result)));
        const QJsonArray diagnosis = result[QStringLiteral("diagnosis")].toArray();
        QVERIFY2(!diagnosis.isEmpty(), qPrintable(run.out));
        QCOMPARE(diagnosis.first()[QStringLiteral("mistake")].toString(),
                 QStringLiteral("colour-scale"));
        QCOMPARE(diagnosis.first()[QStringLiteral("title")].toString(),
                 QStringLiteral("every colour divided by 255: a colour scaled to 0..1 where the "
                                "scene's are 0..255"));
        QVERIFY2(diagnosis.first()[QStringLiteral("share")].toDouble() >= 0.99,
                 qPrintable(ranking(result)));
        QVERIFY2(result[QStringLiteral("unexplained")][QStringLiteral("share")].toDouble() <= 0.01,
                 qPrintable(ranking(result)));
    }
    // Multiplied by 255, every covered channel saturates: one colour, white, which is also
    // what an unlit program draws, so the summary says both.
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QString problem;
        const CourseScene course = lesson(QStringLiteral("goblet"));
        const QString image = studentImage(
            dir, course, {QStringLiteral("--color-scale"), QStringLiteral("255")}, problem);
        QVERIFY2(!image.isEmpty(), qPrintable(problem));
        CliRun run;
        QVERIFY(runCli(QStringList{QStringLiteral("compare")} + course.options() +
                           QStringList{QStringLiteral("--image"), image},
                       dir.path(), run));
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains(QStringLiteral("your image is unlit: one colour (255, 255, 255, "
                                                 "255) wherever it covers")),
                 qPrintable(run.out));
        QVERIFY2(run.out.contains(QStringLiteral(
                     "  white wherever it covers is also what a lit image becomes with every "
                     "colour multiplied by 255 (a colour scaled by 255 where it was already "
                     "0..255)\n")),
                 qPrintable(run.out));
    }
}

void TestCompareStudents::fitsWhatTheirLightingUsed() {
    const auto fitOf = [](const QJsonObject& result) {
        QMap<QString, QJsonObject> values;
        for (const auto& v : result[QStringLiteral("lightingFit")][QStringLiteral("values")].toArray())
            values[v[QStringLiteral("name")].toString()] = v.toObject();
        return values;
    };
    {
        // The light left in world coordinates: fitted at the world position (-6, 9, 8).
        COMPARE_STUDENT(result, QStringLiteral("goblet"), QStringList{"--light-in-world"});
        const QJsonObject fit = result[QStringLiteral("lightingFit")].toObject();
        QVERIFY2(fit[QStringLiteral("fitted")].toBool(), qPrintable(run.out));
        QCOMPARE(fit[QStringLiteral("matches")].toString(), QStringLiteral("light-in-world"));
        const auto values = fitOf(result);
        QVERIFY(std::abs(values["light x (view)"]["theirs"].toDouble() - -6.0) < 0.1);
        QVERIFY(std::abs(values["light y (view)"]["theirs"].toDouble() - 9.0) < 0.1);
        QVERIFY(std::abs(values["light z (view)"]["theirs"].toDouble() - 8.0) < 0.1);
        QVERIFY(fit[QStringLiteral("rmsFitted")].toDouble() < 1.0);
        QVERIFY(fit[QStringLiteral("rmsOurs")].toDouble() > 10.0);
    }
    {
        // Ia ka Od: the fitted ambient is (14, 14, 16) times Od (0.85, 0.65, 0.25), and the
        // light is where ours is.
        COMPARE_STUDENT(result, QStringLiteral("goblet"), QStringList{"--ambient-times-od"});
        const auto values = fitOf(result);
        const double expected[] = {14 * 0.85, 14 * 0.65, 16 * 0.25};
        const char* names[] = {"ambient Ia*ka R", "ambient Ia*ka G", "ambient Ia*ka B"};
        for (int c = 0; c < 3; ++c) {
            const QJsonObject v = values[QString::fromLatin1(names[c])];
            QVERIFY2(std::abs(v["theirs"].toDouble() - expected[c]) < 0.6, names[c]);
            QVERIFY(v["differs"].toBool());
        }
        QVERIFY(!values["light x (view)"]["differs"].toBool());
        QVERIFY(!values["n"]["differs"].toBool());
    }
    {
        // Their light's view x and y swapped: fitted at (3.508, -6, ...), ours (-6, 3.508).
        COMPARE_STUDENT(result, QStringLiteral("goblet"), QStringList{"--light-swap-xy"});
        const QJsonObject fit = result[QStringLiteral("lightingFit")].toObject();
        QVERIFY2(fit[QStringLiteral("fitted")].toBool(), qPrintable(run.out));
        QVERIFY(fit[QStringLiteral("matches")].isUndefined() ||
                fit[QStringLiteral("matches")].isNull());
        QVERIFY2(fit[QStringLiteral("findings")].toArray().contains(
                     QStringLiteral("the fitted light is ours with x and y swapped")),
                 qPrintable(run.out));
        const auto values = fitOf(result);
        QVERIFY(std::abs(values["light x (view)"]["theirs"].toDouble() -
                         values["light y (view)"]["ours"].toDouble()) < 0.1);
        QVERIFY(std::abs(values["light y (view)"]["theirs"].toDouble() -
                         values["light x (view)"]["ours"].toDouble()) < 0.1);
        const QJsonArray diagnosis = result[QStringLiteral("diagnosis")].toArray();
        QVERIFY(!diagnosis.isEmpty());
        QCOMPARE(diagnosis.first()[QStringLiteral("mistake")].toString(),
                 QStringLiteral("fitted-lighting"));
        QVERIFY(result[QStringLiteral("unexplained")][QStringLiteral("share")].toDouble() < 0.01);
    }
    {
        // Their own image (one pixel one unit off, where double and float round apart): the
        // fit finds every value as ours.
        COMPARE_STUDENT(result, QStringLiteral("goblet"), QStringList{});
        QCOMPARE(result[QStringLiteral("differing")].toInteger(), 1);
        QCOMPARE(fitOf(result).size(), 13);  // the light's x, y, z, n, and A, D, S per channel
        for (const QJsonObject& v : fitOf(result))
            QVERIFY2(!v["differs"].toBool(), qPrintable(v["name"].toString()));
    }
}

// An HW2 command file drawn by examples/student/hw2's rasterizer, written from seed 001
// alone: as written, it is our image to the byte; with multmv ignored, compare names the line
// and the misreading, and leaves nothing unexplained.
void TestCompareStudents::fitsTheScreenMap_data() {
    QTest::addColumn<QString>("scene");
    QTest::addColumn<QStringList>("switches");
    QTest::addColumn<QStringList>("expected");  // in the order found
    QTest::addColumn<QList<double>>("map");     // xx, xy, yx, yy
    QTest::addColumn<double>("unexplained");    // at most
    // y scaled by the width (240 / 180): the warp of ours samples the surface at the nearest
    // pixel where theirs is drawn anew, so a few percent stay along the edges and the shading.
    const QList<double> tall = {1.0, 0.0, 0.0, 4.0 / 3.0}, swapped = {0.0, 1.0, 1.0, 0.0};
    QTest::newRow("goblet --width-for-height")
        << "goblet" << QStringList{"--width-for-height"} << QStringList{"screen-map"} << tall
        << 0.04;
    QTest::newRow("default --width-for-height --ambient-times-od")
        << "default" << QStringList{"--width-for-height", "--ambient-times-od"}
        << QStringList{"screen-map", "ambient-times-od"} << tall << 0.04;
    QTest::newRow("goblet --pixels-transposed --light-in-world")
        << "goblet" << QStringList{"--pixels-transposed", "--light-in-world"}
        << QStringList{"screen-map", "light-in-world"} << swapped << 0.01;
    QTest::newRow("goblet unlit --width-for-height")
        << "goblet" << QStringList{"--flat-color", "0,200,0", "--width-for-height"}
        << QStringList{"screen-map"} << tall << 0.03;
}

// Their projection or pixel writing maps the screen another way: the map fitted to the
// coverage is the one their program used (the numbers, and the words), ranked with the
// other mistakes by what each removes.
void TestCompareStudents::fitsTheScreenMap() {
    QFETCH(QString, scene);
    QFETCH(QStringList, switches);
    QFETCH(QStringList, expected);
    QFETCH(QList<double>, map);
    QFETCH(double, unexplained);
    COMPARE_STUDENT(result, scene, switches);
    qInfo("%s: %s", QTest::currentDataTag(), qPrintable(ranking(result)));
    const QJsonArray diagnosis = result[QStringLiteral("diagnosis")].toArray();
    QStringList found;
    for (const auto& d : diagnosis) found += d[QStringLiteral("mistake")].toString();
    QCOMPARE(found, expected);
    QVERIFY2(result[QStringLiteral("unexplained")][QStringLiteral("share")].toDouble() <= unexplained,
             qPrintable(ranking(result)));
    const QJsonObject fitted = diagnosis.first()[QStringLiteral("map")].toObject();
    const char* const names[] = {"xx", "xy", "yx", "yy"};
    for (int k = 0; k < 4; ++k)
        QVERIFY2(std::abs(fitted[QLatin1String(names[k])].toDouble() - map[k]) < 1e-9,
                 qPrintable(QStringLiteral("%1 = %2").arg(QLatin1String(names[k])).arg(
                     fitted[QLatin1String(names[k])].toDouble())));
    // Scaled from the top edge (y = (1 - y_ndc) * width / 2) or swapped about the corner:
    // no shift but the nearest pixel's.
    QVERIFY(std::abs(fitted[QStringLiteral("tx")].toDouble()) < 0.5);
    QVERIFY(std::abs(fitted[QStringLiteral("ty")].toDouble()) < 0.5);
    const QString title = diagnosis.first()[QStringLiteral("title")].toString();
    if (map == QList<double>{1.0, 0.0, 0.0, 4.0 / 3.0})
        QVERIFY2(title.contains(QStringLiteral("stretched 1.333 times up and down, the ratio of "
                                               "the image's sides (one size used for both axes)")),
                 qPrintable(title));
    else
        QVERIFY2(title.contains(QStringLiteral("x and y swapped (transposed)")), qPrintable(title));
}

// No student program here turns its image, so the fit is checked on coverage turned by hand:
// an L shape (no symmetry to confuse it) turned 30 degrees, scaled by 0.8 and moved. The fit
// finds the map within a hundredth and a pixel, and leaves almost nothing apart.
void TestCompareStudents::fitsATurnedCoverage() {
    const int w = 200, h = 150;
    rl::Coverage ours(w, h), theirs(w, h);
    const auto inL = [](double x, double y) {
        return (x >= 40 && x < 70 && y >= 30 && y < 120) || (x >= 40 && x < 130 && y >= 90 && y < 120);
    };
    const double c = std::cos(M_PI / 6.0) * 0.8, s = std::sin(M_PI / 6.0) * 0.8;
    const rl::ScreenMap turned{c, -s, s, c, 60.0, -20.0};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            ours.at(x, y) = inL(x + 0.5, y + 0.5) ? 1 : 0;
            const rl::dvec2 q = turned.ourPoint({x + 0.5, y + 0.5});
            theirs.at(x, y) = inL(q.x, q.y) ? 1 : 0;
        }
    const auto fit = rl::fitScreenMap(ours, theirs);
    QVERIFY(fit);
    const rl::ScreenMap& m = fit->map;
    qInfo("fitted %.4f %.4f %.2f / %.4f %.4f %.2f; apart %zu before, %zu after", m.xx, m.xy,
          m.tx, m.yx, m.yy, m.ty, fit->apartBefore, fit->apartAfter);
    QVERIFY(std::abs(m.xx - c) < 0.01 && std::abs(m.xy + s) < 0.01);
    QVERIFY(std::abs(m.yx - s) < 0.01 && std::abs(m.yy - c) < 0.01);
    // Where the L's corner goes.
    QVERIFY(glm::length(m.theirPoint({40.0, 120.0}) - turned.theirPoint({40.0, 120.0})) < 1.0);
    QVERIFY(fit->apartAfter * 20 < fit->apartBefore);
    QVERIFY(!rl::isPlainMove(m, w, h));
}

// The goblet faceted: each triangle with three vertices of its own, at the positions it
// shares with its neighbours (as some course files are written). A normals stage that sums
// over every vertex at one position draws it smooth where ours is faceted: found first, and
// nearly all of the difference.
void TestCompareStudents::normalsSharedByPosition() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    CourseScene scene = lesson(QStringLiteral("goblet"));
    QFile shipped(scene.object);
    QVERIFY(shipped.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(shipped.readAll()).split(u'\n', Qt::SkipEmptyParts);
    const QStringList counts = lines[0].split(u' ', Qt::SkipEmptyParts);
    const int vertices = counts[0].toInt(), triangles = counts[1].toInt();
    QStringList faceted{QStringLiteral("%1 %2").arg(3 * triangles).arg(triangles)};
    for (int t = 0; t < triangles; ++t)
        for (const QString& index : lines[1 + vertices + t].split(u' ', Qt::SkipEmptyParts))
            faceted << lines[std::abs(index.toInt())];
    for (int t = 0; t < triangles; ++t)
        faceted << QStringLiteral("%1 %2 %3").arg(3 * t + 1).arg(3 * t + 2).arg(3 * t + 3);
    scene.object = dir.filePath(QStringLiteral("faceted.byu"));
    QFile out(scene.object);
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(faceted.join(u'\n').toUtf8() + '\n');
    out.close();
    QString problem;
    const QString image = studentImage(dir, scene, {"--normals-shared-by-position"}, problem);
    QVERIFY2(!image.isEmpty(), qPrintable(problem));
    CliRun run;
    const QJsonObject result = compareJson(dir, scene, image, run);
    QVERIFY2(run.exitCode == 0, qPrintable(run.err));
    qInfo("faceted goblet --normals-shared-by-position: %lld differing; %s",
          result[QStringLiteral("differing")].toInteger(), qPrintable(ranking(result)));
    const QJsonArray diagnosis = result[QStringLiteral("diagnosis")].toArray();
    QVERIFY2(!diagnosis.isEmpty(), qPrintable(run.out));
    QCOMPARE(diagnosis.first()[QStringLiteral("mistake")].toString(),
             QStringLiteral("normals-shared-by-position"));
    QVERIFY2(diagnosis.first()[QStringLiteral("share")].toDouble() >= 0.9, qPrintable(ranking(result)));
    QVERIFY2(result[QStringLiteral("unexplained")][QStringLiteral("share")].toDouble() <= 0.02,
             qPrintable(ranking(result)));
}

void TestCompareStudents::commandFileOfAnIndependentRenderer_data() {
    QTest::addColumn<QStringList>("switches");
    QTest::addColumn<int>("differing");
    QTest::addColumn<QString>("mistake");
    QTest::newRow("as written") << QStringList{} << 0 << QString();
    QTest::newRow("--ignore-multmv") << QStringList{QStringLiteral("--ignore-multmv")} << 2368
                                     << QStringLiteral("command-misread");
    // The DDA steps the depth as it scans (hw2 rules): the farther-wins frame must scan the
    // flipped depths, not reuse our spans.
    QTest::newRow("--depth-reversed") << QStringList{QStringLiteral("--depth-reversed")} << 1179
                                      << QStringLiteral("depth-reversed");
}

void TestCompareStudents::commandFileOfAnIndependentRenderer() {
    QFETCH(QStringList, switches);
    QFETCH(int, differing);
    QFETCH(QString, mistake);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    CliRun run;
    const QJsonObject result = hw2StudentCompared(dir, hw2SceneText(), switches, run);
    QVERIFY2(run.exitCode == 0, qPrintable(run.problem + run.err));
    QCOMPARE(result[QStringLiteral("differing")].toInt(), differing);
    const QJsonArray diagnosis = result[QStringLiteral("diagnosis")].toArray();
    if (differing == 0) {
        QVERIFY(diagnosis.isEmpty());
        return;
    }
    QVERIFY2(!diagnosis.isEmpty(), qPrintable(run.out));
    const QJsonObject first = diagnosis.first().toObject();
    QCOMPARE(first[QStringLiteral("mistake")].toString(), mistake);
    if (mistake == QLatin1String("command-misread")) {
        QCOMPARE(first[QStringLiteral("line")].toInt(), 17);
        QCOMPARE(first[QStringLiteral("variant")].toString(), QStringLiteral("ignored"));
    }
    QCOMPARE(result[QStringLiteral("unexplained")][QStringLiteral("share")].toDouble(), 0.0);
}

// A program that never implemented multmv ignores every one of them: one finding names the
// command, all its occurrences, and nothing stays unexplained.
void TestCompareStudents::commandNeverImplemented() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QString text = hw2SceneText();
    text.replace(QStringLiteral("scale 1.2 1 1\n"),
                 QStringLiteral("scale 1.2 1 1\nmultmv 1 0 0 0  0 0.9 -0.3 0  0 0.3 0.9 0  0 0 0 1\n"));
    CliRun run;
    const QJsonObject result =
        hw2StudentCompared(dir, text, {QStringLiteral("--ignore-multmv")}, run);
    QVERIFY2(run.exitCode == 0, qPrintable(run.problem + run.err));
    const QJsonArray diagnosis = result[QStringLiteral("diagnosis")].toArray();
    QVERIFY2(!diagnosis.isEmpty(), qPrintable(run.out));
    const QJsonObject first = diagnosis.first().toObject();
    QCOMPARE(first[QStringLiteral("mistake")].toString(), QStringLiteral("command-misread"));
    QCOMPARE(first[QStringLiteral("variant")].toString(), QStringLiteral("ignored"));
    QCOMPARE(first[QStringLiteral("occurrences")].toInt(), 2);
    QCOMPARE(first[QStringLiteral("title")].toString(),
             QStringLiteral("every 'multmv' ignored (2 of them, from line 17): the command never "
                            "implemented"));
    QVERIFY2(result[QStringLiteral("unexplained")][QStringLiteral("share")].toDouble() < 0.01,
             qPrintable(ranking(result)));
}

// A window's grey background is almost all of the difference; the covered pixels that still
// differ are ranked on what is left, so Gouraud shading is named after the background.
void TestCompareStudents::coveredPixelsAfterTheBackground() {
    COMPARE_STUDENT(plain, "goblet", QStringList{"--gouraud"});
    QImage grey(image);
    QVERIFY(!grey.isNull());
    for (int y = 0; y < grey.height(); ++y)
        for (int x = 0; x < grey.width(); ++x)
            if (grey.pixelColor(x, y) == QColor(0, 0, 0)) grey.setPixelColor(x, y, QColor(238, 238, 238));
    const QString windowed = dir.filePath(QStringLiteral("window.png"));
    QVERIFY(grey.save(windowed));
    CliRun again;
    const QJsonObject result = compareJson(dir, course, windowed, again);
    QVERIFY2(again.exitCode == 0, qPrintable(again.err));
    const QJsonArray diagnosis = result[QStringLiteral("diagnosis")].toArray();
    qInfo("%s", qPrintable(ranking(result)));
    QVERIFY2(diagnosis.size() >= 2, qPrintable(ranking(result)));
    QCOMPARE(diagnosis[0][QStringLiteral("mistake")].toString(), QStringLiteral("background"));
    QVERIFY2(diagnosis[0][QStringLiteral("share")].toDouble() > 0.95, qPrintable(ranking(result)));
    bool gouraud = false;
    for (const auto& d : diagnosis)
        gouraud = gouraud || d[QStringLiteral("mistake")].toString() == QLatin1String("gouraud");
    QVERIFY2(gouraud, qPrintable(ranking(result)));
    QVERIFY2(result[QStringLiteral("unexplained")][QStringLiteral("share")].toDouble() < 0.005,
             qPrintable(ranking(result)));
    (void)plain;
}

QTEST_GUILESS_MAIN(TestCompareStudents)
#include "tst_compare_students.moc"
