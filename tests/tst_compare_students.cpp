// rasterlab-cli compare on images no RasterLab code made: examples/student/python's
// rasterizer, written from the seed alone, with one, two or three of its mistakes switched
// on. Each switched-on mistake must be found (the dominant one first when there is one), and
// what stays unexplained must be small; an unlit image is compared as coverage; an image
// no mistake of the catalogue made (their light elsewhere) is said to be mostly unexplained.
#include <QtTest>

#include <QJsonArray>
#include <QJsonDocument>
#include <QFile>
#include <QJsonObject>
#include <QProcess>
#include <QRandomGenerator>
#include <QTemporaryDir>

#include <algorithm>

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

void TestCompareStudents::unknownMistakeIsUnexplained() {
    // Their light somewhere else: a value, not a mistake of the catalogue. Whatever the search
    // finds, most of the differing pixels stay, and compare says so.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    CourseScene theirScene = lesson(QStringLiteral("goblet"));
    QFile lighting(theirScene.lighting);
    QVERIFY(lighting.open(QIODevice::ReadOnly));
    QStringList lines = QString::fromUtf8(lighting.readAll()).split(QLatin1Char('\n'));
    lines[0] = QStringLiteral("-300 -100 50");  // Pl
    theirScene.lighting = dir.filePath(QStringLiteral("moved.txt"));
    QFile moved(theirScene.lighting);
    QVERIFY(moved.open(QIODevice::WriteOnly));
    moved.write(lines.join(QLatin1Char('\n')).toUtf8());
    moved.close();
    QString problem;
    const QString image = studentImage(dir, theirScene, {}, problem);
    QVERIFY2(!image.isEmpty(), qPrintable(problem));
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

QTEST_GUILESS_MAIN(TestCompareStudents)
#include "tst_compare_students.moc"
