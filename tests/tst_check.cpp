// rasterlab-cli check: the stage protocol's answers read with exact messages, the protocol
// document's own examples, the student's Python renderer (written without RasterLab's code)
// passing every stage, one mutant of it per known stage mistake caught at the right stage and
// element with its cause, and hostile programs stopped with a message.
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <signal.h>

#include <map>
#include <set>

#include "app/check/check_session.h"
#include "app/check/stage_description.h"
#include "app/check/stage_findings.h"
#include "app/check/stage_mistakes.h"
#include "app/check/student_program.h"
#include "pipeline/stages/camera_basis.h"
#include "pipeline/stages/projection.h"
#include "pipeline/stages/scan_conversion.h"
#include "pipeline/stages/view_transform.h"
#include "tests/test_support.h"

using namespace rasterlab::check;

namespace {

QString pythonFolder() {
    return testing::sourceDir() + "/examples/student/python";
}

QString python() {
    return QStringLiteral(RASTERLAB_PYTHON);
}

const std::vector<CheckScene>& scenes() {
    static const std::vector<CheckScene> all = defaultCheckScenes();
    return all;
}

CheckReport checkPython(const QStringList& switches, std::vector<Stage> stages = {}) {
    CheckOptions options;
    if (!stages.empty()) options.stages = std::move(stages);
    const QString command = python() + " stages.py " + switches.join(' ');
    return runCheck(command.toStdString(), pythonFolder().toStdString(), scenes(), options);
}

// The first stage of the pipeline that did not pass, in the first scene where it did not.
const StageResult* firstDeparture(const CheckReport& report, std::string* scene = nullptr) {
    const StageResult* first = nullptr;
    for (const SceneReport& s : report.scenes)
        for (const StageResult& r : s.stages)
            if (r.verdict != Verdict::Passed && (!first || int(r.stage) < int(first->stage))) {
                first = &r;
                if (scene) *scene = s.name;
            }
    return first;
}

// The fenced blocks of the protocol document that follow "```" + language.
QStringList fencedBlocks(const QString& language) {
    const QString text =
        QString::fromUtf8(testing::readFile(testing::sourceDir() + "/docs/stage-protocol.md"));
    QStringList blocks;
    const QRegularExpression fence("```" + language + "\\n(.*?)```",
                                   QRegularExpression::DotMatchesEverythingOption);
    for (auto it = fence.globalMatch(text); it.hasNext();) blocks << it.next().captured(1);
    return blocks;
}

}  // namespace

class TestCheck : public QObject {
    Q_OBJECT

private slots:
    void badAnswersGetExactMessages_data() {
        QTest::addColumn<int>("stage");
        QTest::addColumn<QStringList>("lines");
        QTest::addColumn<QString>("message");
        const int basis = int(Stage::Basis), view = int(Stage::View), frame = int(Stage::Frame);
        QTest::newRow("too few numbers")
            << basis << QStringList{"U 1 0 0", "V 0 1"}
            << "their answer:2:6: expected 3 numbers after 'V', found 2";
        QTest::newRow("too many numbers")
            << basis << QStringList{"U 1 0 0 4"}
            << "their answer:1:9: expected 3 numbers after 'U', found 4";
        QTest::newRow("not a number")
            << basis << QStringList{"U 1 0 x"}
            << "their answer:1:7: expected a finite number ('.' as the decimal point), found 'x'";
        QTest::newRow("nan") << basis << QStringList{"U nan 0 0"}
                             << "their answer:1:3: expected a finite number ('.' as the "
                                "decimal point), found 'nan'";
        QTest::newRow("decimal comma")
            << basis << QStringList{"U 1,5 0 0"}
            << "their answer:1:3: expected a finite number ('.' as the decimal point), found "
               "'1,5'";
        QTest::newRow("another record")
            << basis << QStringList{"X 1 0 0"} << "their answer:1:1: expected 'U', found 'X'";
        QTest::newRow("empty line")
            << basis << QStringList{""} << "their answer:1:1: expected 'U', found an empty line";
        QTest::newRow("nothing") << basis << QStringList{}
                                 << "their answer:1:1: expected 'U', the answer ended ('end')";
        QTest::newRow("a line after the last record")
            << basis << QStringList{"U 1 0 0", "V 0 1 0", "N 0 0 1", "extra"}
            << "their answer:4:1: expected 'end', found 'extra'";
        QTest::newRow("rows missing")
            << view << QStringList{"light 0 0 0", "vertices 3", "1 2 3"}
            << "their answer:2:10: expected 3 rows after 'vertices', the answer has 1 lines "
               "before 'end'";
        QTest::newRow("negative count")
            << view << QStringList{"light 0 0 0", "vertices -1"}
            << "their answer:2:10: expected a whole number of rows, not negative, after "
               "'vertices'";
        QTest::newRow("short image row")
            << frame << QStringList{"image 2 1", "1 2 3 4 5"}
            << "their answer:2:10: expected 6 numbers in a row of 'image', found 5";
    }

    void badAnswersGetExactMessages() {
        QFETCH(int, stage);
        QFETCH(QStringList, lines);
        QFETCH(QString, message);
        std::vector<std::string> text;
        for (const QString& line : lines) text.push_back(line.toStdString());
        const auto parsed = parseAnswer(Stage(stage), text, "their answer");
        QVERIFY(!parsed);
        QCOMPARE(QString::fromStdString(parsed.error().toString()), message);
    }

    // The session in the document: its answer reads, and is the lecture's basis of its camera.
    void documentSessionIsTheLecturesBasis() {
        const QStringList blocks = fencedBlocks("");
        QVERIFY(!blocks.isEmpty());
        std::vector<std::string> answer;
        rl::CourseCamera camera;
        for (const QString& line : blocks.first().split('\n', Qt::SkipEmptyParts)) {
            const QStringList f = line.mid(2).split(' ');
            if (line.startsWith(QStringLiteral("← ")) && f.first() != "speaks" &&
                f.first() != "end")
                answer.push_back(line.mid(2).toStdString());
            if (line.startsWith(QStringLiteral("→ ")) && f.size() == 4) {
                const rl::dvec3 v(f[1].toDouble(), f[2].toDouble(), f[3].toDouble());
                (f[0] == "C" ? camera.c : f[0] == "N" ? camera.n : camera.v) = v;
            }
        }
        const auto records = parseAnswer(Stage::Basis, answer, "the document");
        QVERIFY2(records, records ? "" : records.error().toString().c_str());
        rl::Scene scene;
        scene.camera = camera;
        rl::Diagnostics diagnostics;
        const auto basis = rl::CameraBasisStage().run(scene, diagnostics);
        QVERIFY(basis);
        const rl::dvec3 ours[3] = {basis->u, basis->v, basis->n};
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k)
                QVERIFY2(std::abs(records->at(std::size_t(i)).numbers[std::size_t(k)] -
                                  ours[i][k]) < 1e-15,
                         qPrintable(QStringLiteral("%1[%2]").arg(i).arg(k)));
    }

    // The document's whole program has the basis alone: it passes it, the rest unsupported.
    void documentProgramPassesTheBasis() {
        const QStringList programs = fencedBlocks("python");
        QCOMPARE(programs.size(), 1);
        QTemporaryDir dir;
        QFile file(dir.filePath("basis.py"));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(programs.first().toUtf8());
        file.close();
        const CheckReport report = runCheck((python() + " basis.py").toStdString(),
                                            dir.path().toStdString(), {scenes().front()}, {});
        QVERIFY2(report.failure.empty(), report.failure.c_str());
        QCOMPARE(report.scenes.front().stages.size(), kStages.size());
        for (const StageResult& r : report.scenes.front().stages)
            QCOMPARE(int(r.verdict),
                     int(r.stage == Stage::Basis ? Verdict::Passed : Verdict::Unsupported));
        QVERIFY(!report.passed());
    }

    // The spans of the scan's catalogue with no mistake (stage_mistakes.h: each row's crossings
    // with the edges, written apart from the lecture's edge walk) are the lecture's spans on
    // every default scene, so that a mistake's spans differ from the lecture's by that mistake
    // alone.
    void edgeFunctionsGiveTheLecturesSpans() {
        for (const CheckScene& s : scenes()) {
            rl::Diagnostics diagnostics;
            const auto basis = rl::CameraBasisStage().run(*s.scene, diagnostics);
            QVERIFY(basis);
            const auto view = rl::ViewTransformStage().run(*s.scene, basis.value());
            const auto projection = rl::ProjectionStage().run({*s.scene, view}, diagnostics);
            const auto scan = rl::ScanConversionStage().run({*s.scene, projection});
            std::vector<Row> triangles, ours;
            for (const rl::ScreenTriangle& t : projection.triangles) {
                const auto p = rl::screenVertices(projection, t);
                triangles.push_back({p[0].x, p[0].y, p[1].x, p[1].y, p[2].x, p[2].y});
            }
            for (std::uint32_t t = 0; t < scan.triangleCount(); ++t)
                for (std::uint32_t k = scan.spanStart[t]; k < scan.spanStart[t + 1]; ++k)
                    ours.push_back({double(t), double(scan.spans[k].y),
                                    double(scan.spans[k].xBegin), double(scan.spans[k].xEnd - 1)});
            std::vector<Row> brute = scanAnswer(triangles, s.scene->width, s.scene->height, {});
            std::sort(brute.begin(), brute.end());
            std::sort(ours.begin(), ours.end());
            QVERIFY2(brute == ours, s.name.c_str());
            QVERIFY(ours.size() > 20);
        }
    }

    void pythonExamplePassesEveryStage() {
        const CheckReport report = checkPython({});
        std::string scene;
        const StageResult* departure = firstDeparture(report, &scene);
        QVERIFY2(!departure,
                 departure ? (scene + ": " + formatReport(report, "text")).c_str() : "");
        QVERIFY(report.passed());
        QCOMPARE(report.scenes.size(), std::size_t(6));
        qInfo("the Python example's check over the default scenes: %.2f s", report.seconds);
    }

    // Chained, each stage given the program's own earlier answers: the example still passes.
    // Each stage is judged on exactly what it was sent, so one mistake in the basis or the
    // projection fails that stage and the frame alone; what it carries into the later stages
    // is counted beside their verdicts (0 before the mistake, more after it).
    void chainedStagesAreJudgedOnWhatTheyReceived() {
        const auto run = [&](const QString& switches, bool chain) {
            CheckOptions o;
            o.chain = chain;
            return runCheck((python() + " stages.py " + switches).toStdString(),
                            pythonFolder().toStdString(), {scenes()[2]}, o);
        };
        const CheckReport plain = run({}, true);
        QVERIFY2(plain.passed(), formatReport(plain, "text").c_str());
        QVERIFY(plain.chained);
        const auto failing = [](const CheckReport& r) {
            QStringList out;
            for (const StageResult& st : r.scenes.front().stages)
                if (st.verdict != Verdict::Passed)
                    out << QString::fromStdString(std::string(stageName(st.stage)));
            return out.join(',');
        };
        const auto carried = [](const CheckReport& r, Stage stage) {
            for (const StageResult& st : r.scenes.front().stages)
                if (st.stage == stage) return st.carried ? int(*st.carried) : -1;
            return -2;
        };
        const CheckReport apart = run("--u-v-cross-n", false);
        QCOMPARE(failing(apart), QStringLiteral("basis,frame"));
        QCOMPARE(carried(apart, Stage::View), -1);
        const CheckReport basis = run("--u-v-cross-n", true);
        QCOMPARE(failing(basis), QStringLiteral("basis,frame"));
        for (Stage s : {Stage::View, Stage::Normals, Stage::Projection, Stage::Scan,
                        Stage::ZBuffer, Stage::Lighting})
            QVERIFY2(carried(basis, s) > 0, stageName(s).data());
        const CheckReport rounded = run("--round-vertices", true);
        QCOMPARE(failing(rounded), QStringLiteral("projection,frame"));
        QCOMPARE(carried(rounded, Stage::View), 0);
        QCOMPARE(carried(rounded, Stage::Projection), 0);
        QVERIFY(carried(rounded, Stage::Scan) > 0);
        QVERIFY(carried(rounded, Stage::ZBuffer) > 0);
        const std::string text = formatReport(run("--flip-y", true), "text");
        QVERIFY(text.find(", chained: each stage given the program's own earlier answers") !=
                std::string::npos);
        QVERIFY(text.find("theirs: the program's answer; ours: the lecture's stage (RasterLab's) "
                          "applied to exactly what the request sent") != std::string::npos);
    }

    // The second student's renderer, in C++, written apart from RasterLab and from the Python
    // one: every stage passes too.
    void cppExamplePassesEveryStage() {
        CheckOptions options;
#if defined(__SANITIZE_ADDRESS__)
        // Built with AddressSanitizer too (scripts/sanitizers.sh), it reserves terabytes of
        // address space for its shadow memory: no limit on it would hold.
        options.limits.memoryBytes = 0;
#endif
        const CheckReport report = runCheck(
            STUDENT_CPP " --stages", (testing::sourceDir() + "/examples/student/cpp").toStdString(),
            scenes(), options);
        QVERIFY2(report.passed(), formatReport(report, "text").c_str());
        qInfo("the C++ example's check over the default scenes: %.2f s", report.seconds);
    }

    // Scenes the protocol cannot carry are reported as not checked, with the reason.
    void scenesBeyondTheSeedAreNotChecked() {
        testing::CliRun run;
        QVERIFY(
            testing::runCli({"check", "--program", python() + " stages.py", "--scene", "lights"},
                            pythonFolder(), run));
        QVERIFY2(run.out.contains("not checked: the protocol carries one light, the scene has 3"),
                 qPrintable(run.out));
        QCOMPARE(run.exitCode, 3);
        QVERIFY(testing::runCli(
            {"check", "--program", python() + " stages.py", "--scene", "near-plane"},
            pythonFolder(), run));
        QVERIFY2(run.out.contains("not checked: a triangle is clipped, behind the camera"),
                 qPrintable(run.out));
    }

    // The sphere lesson opens in flat shading; the protocol's frame is seed 000's Phong, so a
    // right program passes it whatever the lesson shows.
    void theFrameIsPhongWhateverTheLessonShows() {
        testing::CliRun run;
        QVERIFY(testing::runCli({"check", "--program", python() + " stages.py", "--scene",
                                 "sphere", "--size", "160x120", "--stages", "frame"},
                                pythonFolder(), run));
        QVERIFY2(run.exitCode == 0, qPrintable(run.out));
        QVERIFY2(run.out.contains("frame      passed (19200 elements"), qPrintable(run.out));
    }

    // One mutant of the Python example per known mistake: the stage and element where check
    // stops it, and the cause it names.
    void mutantsAreCaughtWhereTheyAre_data() {
        QTest::addColumn<QString>("switches");
        QTest::addColumn<int>("stage");
        QTest::addColumn<QString>("element");
        QTest::addColumn<QString>("cause");
        const auto row = [](const char* switches, Stage stage, const char* element,
                            const char* cause) {
            QTest::newRow(switches)
                << QString(switches) << int(stage) << QString(element) << QString(cause);
        };
        row("--u-v-cross-n", Stage::Basis, "U", "U = V x N: the cross product in the other order");
        row("--no-normalize-n-before-gram-schmidt", Stage::Basis, "U",
            "N not normalised before V - (V.N)N, nor after");
        row("--light-in-world", Stage::View, "the light", "the light left in world coordinates");
        row("--light-no-minus-c", Stage::View, "the light",
            "the light taken to view coordinates without subtracting C: [U; V; N] Pl");
        row("--triangle-normal-reversed", Stage::Normals, "triangle 0",
            "the cross product in the other order: (Pc - Pa) x (Pb - Pa)");
        row("--sum-unnormalized-triangle-normals", Stage::Normals, "triangle 0",
            "the triangle normals not normalised");
        row("--vertex-normals-unnormalized", Stage::Normals, "vertex 0",
            "the vertex normals not normalised: the sum left at its length");
        row("--round-vertices", Stage::Projection, "vertex 0",
            "rounded to the nearest pixel instead of truncated by (int)");
        row("--flip-y", Stage::Projection, "vertex 0",
            "y not flipped: (int)((d/hy * y/z + 1) * height/2), y growing upward");
        row("--span-end-exclusive", Stage::Scan, "pixel (72, 10) of triangle 0",
            "each span's last pixel left out (x < last instead of x <= last)");
        row("--depth-reversed", Stage::ZBuffer, "pixel (68, 25)",
            "the farther fragment wins (z > stored, the buffer starting at -infinity)");
        row("--zbuffer-ties-later", Stage::ZBuffer, "pixel (66, 17)",
            "on a tie the later fragment wins (z <= stored instead of z < stored)");
        row("--no-flip-normal", Stage::Lighting, "sample 0",
            "N not turned toward the viewer where V.N < 0");
        row("--v-equals-p", Stage::Lighting, "sample 0",
            "V = P' instead of -P' (or L = P' - Pl: the same colours)");
        row("--l-reversed", Stage::Lighting, "sample 0",
            "V = P' instead of -P' (or L = P' - Pl: the same colours)");
        row("--epsilon-special-cases", Stage::Lighting, "sample 6",
            "V.N, N.L and R.V compared with 0.001 instead of 0 (the special cases at a small "
            "epsilon)");
        row("--truncate-terms", Stage::Lighting, "sample 0",
            "each term truncated to a whole number before the sum");
        row("--ambient-ia-only", Stage::Lighting, "sample 0",
            "the ambient term Ia instead of Ia ka");
        row("--ambient-times-od", Stage::Lighting, "sample 0",
            "the ambient term Ia ka Od instead of Ia ka");
        row("--no-clamp", Stage::Lighting, "sample 0", "no clamp: channels above 255 kept");
        row("--gouraud", Stage::Frame, "pixel (72, 11)",
            "gouraud shading where phong was asked");
        row("--mirror-x", Stage::Frame, "pixel (72, 10)",
            "the image mirrored left-right (x runs the other way)");
    }

    void mutantsAreCaughtWhereTheyAre() {
        QFETCH(QString, switches);
        QFETCH(int, stage);
        QFETCH(QString, element);
        QFETCH(QString, cause);
        // The stages up to the one expected: an earlier departure would still show.
        std::vector<Stage> upTo;
        for (Stage s : kStages)
            if (int(s) <= stage) upTo.push_back(s);
        const CheckReport report = checkPython(switches.split(' '), upTo);
        QVERIFY2(report.failure.empty(), report.failure.c_str());
        std::string scene;
        const StageResult* r = firstDeparture(report, &scene);
        QVERIFY(r);
        qInfo("%s: %s, %s (%s)", qPrintable(switches), std::string(stageName(r->stage)).c_str(),
              r->first ? r->first->element.c_str() : "", scene.c_str());
        QCOMPARE(int(r->stage), stage);
        QCOMPARE(int(r->verdict), int(Verdict::Failed));
        QVERIFY(r->first);
        QCOMPARE(QString::fromStdString(r->first->element), element);
        QCOMPARE(QString::fromStdString(r->causes()), cause);
        QVERIFY(r->differing > 0 && r->differing <= r->elements);
    }

    // The search on a catalogue made by hand: ten elements; A makes 0..5 theirs, B makes 6..8
    // theirs, C imitates most of both (0..7 theirs, and spoils 9). Their answer is A and B with
    // element 9 matching: greedy would take C first (8 made, 1 spoiled, against A's 6) and then
    // B, leaving 9; the beam names A then B, each with what it explains, and nothing left.
    void findingsComposeByHand() {
        const auto mistake = [](int code, const char* id) {
            StageMistake m;
            m.code = code;
            m.id = id;
            m.cause = id;
            return m;
        };
        const std::vector<StageMistake> catalogue = {mistake(3, "C"), mistake(1, "A"),
                                                     mistake(2, "B")};
        const auto differingWith = [](const std::vector<StageMistake>& applied) {
            std::set<std::uint64_t> made;
            bool spoils = false;
            for (const StageMistake& m : applied) {
                const int first = m.code == 1 ? 0 : m.code == 2 ? 6 : 0;
                const int last = m.code == 1 ? 5 : m.code == 2 ? 8 : 7;
                for (int i = first; i <= last; ++i) made.insert(std::uint64_t(i));
                spoils = spoils || m.code == 3;
            }
            ElementKeys differing;
            for (std::uint64_t i = 0; i < 9; ++i)
                if (!made.count(i)) differing.push_back(i);
            if (spoils) differing.push_back(9);
            return std::optional<ElementKeys>(differing);
        };
        const Explanation e = explainStage(catalogue, {0, 1, 2, 3, 4, 5, 6, 7, 8}, differingWith,
                                           [](std::uint64_t k) { return std::to_string(k); });
        QCOMPARE(e.findings.size(), std::size_t(2));
        QCOMPARE(QString::fromStdString(e.findings[0].id), QStringLiteral("A"));
        QCOMPARE(e.findings[0].explained, std::size_t(6));
        QCOMPARE(e.findings[0].share, 6.0 / 9.0);
        QCOMPARE(QString::fromStdString(e.findings[1].id), QStringLiteral("B"));
        QCOMPARE(e.findings[1].explained, std::size_t(3));
        QCOMPARE(e.findings[1].examples, (std::vector<std::string>{"6", "7", "8"}));
        QVERIFY(e.unexplained.empty());
    }

    // The basis's forms of N not normalised, by hand: N = (0, 0, 2), V = (0, 1, 1). Used raw
    // in V.N and unit after it, V - 2 (0, 0, 1) = (0, 1, -1), normalised (0, 0.7071, -0.7071);
    // unit in V.N and raw after, V - 1 (0, 0, 2) = (0, 1, -1) likewise; the lecture's V is
    // (0, 1, 0). Raw in both: V - 2 (0, 0, 2) = (0, 1, -3), normalised.
    void basisFormsByHand() {
        const rl::dvec3 n(0, 0, 2), v(0, 1, 1);
        const auto formOf = [&](const char* id) {
            for (const StageMistake& m : basisCatalogue())
                if (m.id == id) return basisAnswer(n, v, {m});
            return std::vector<Row>{};
        };
        const double h = 1.0 / std::sqrt(2.0), t = 1.0 / std::sqrt(10.0);
        QCOMPARE(basisAnswer(n, v, {})[1], (Row{0, 1, 0}));
        QCOMPARE(formOf("basis-n-not-normalised-in-dot")[1], (Row{0, h, -h}));
        QCOMPARE(formOf("basis-n-not-normalised-in-scale")[1], (Row{0, h, -h}));
        QCOMPARE(formOf("basis-n-not-normalised")[1], (Row{0, t, -3 * t}));
        QCOMPARE(formOf("basis-n-not-normalised")[2], (Row{0, 0, 2}));
        QCOMPARE(formOf("basis-n-normalised-after")[2], (Row{0, 0, 1}));
        QCOMPARE(formOf("basis-n-answered-raw")[1], (Row{0, 1, 0}));
        QCOMPARE(formOf("basis-n-answered-raw")[2], (Row{0, 0, 2}));
    }

    // The scan's rules by hand, on the triangle (1, 0) (6, 0) (3, 4) of an 8x8 screen. Row 1's
    // edges cross at x = 1.5 and 5.25, row 2's at 2 and 4.5, row 0 runs from 1 to 6.
    void scanRulesByHand() {
        const std::vector<Row> triangle = {{1, 0, 6, 0, 3, 4}};
        const auto rowsOf = [&](const char* id) {
            Mistakes applied;
            for (const StageMistake& m : scanCatalogue())
                if (id && m.id == id) applied.push_back(m);
            std::map<double, std::pair<double, double>> rows;
            for (const Row& r : scanAnswer(triangle, 8, 8, applied)) rows[r[1]] = {r[2], r[3]};
            return rows;
        };
        using Span = std::pair<double, double>;
        const auto lecture = rowsOf(nullptr);
        QCOMPARE(lecture.at(0), Span(1, 6));
        QCOMPARE(lecture.at(1), Span(2, 5));
        QCOMPARE(lecture.at(2), Span(2, 4));
        QCOMPARE(lecture.at(4), Span(3, 3));
        // From floor(1.5) = 1, floor(5.25 - 1.5) + 1 = 4 pixels.
        QCOMPARE(rowsOf("span-unit-steps-from-left-x").at(1), Span(1, 4));
        QCOMPARE(rowsOf("span-start-truncated").at(1), Span(1, 5));
        QCOMPARE(rowsOf("span-start-rounded").at(1), Span(2, 5));
        QCOMPARE(rowsOf("span-start-open").at(2), Span(3, 4));
        QCOMPARE(rowsOf("span-start-open").at(1), Span(2, 5));
        QCOMPARE(rowsOf("span-end-open").at(0), Span(1, 5));
        QCOMPARE(rowsOf("span-end-dropped").at(1), Span(2, 4));
        QCOMPARE(rowsOf("last-row-out").count(4), std::size_t(0));
        QCOMPARE(rowsOf("edges-strict").count(0), std::size_t(0));  // the bottom edge is row 0
    }

    // The frame the stages' formulas make with no mistake is the lecture's, to within a byte on
    // all but a few pixels of each default scene (the lecture's colours are floats, the
    // stages' doubles), so that the frame's findings start from the lecture's image.
    void stagesFrameIsTheLecturesFrame() {
        for (const CheckScene& s : scenes()) {
            const auto check = StageCheck::make(s.scene);
            QVERIFY(check);
            const rl::Rgba8Image ours = (*check)->ourImage();
            const rl::Rgba8Image stages = (*check)->stagesFrame({});
            QCOMPARE(stages.width, ours.width);
            std::size_t apart = 0, covered = 0;
            for (int y = 0; y < ours.height; ++y)
                for (int x = 0; x < ours.width; ++x) {
                    int most = 0;
                    for (int k = 0; k < 3; ++k)
                        most = std::max(most, std::abs(int(ours.pixel(x, y)[k]) -
                                                       int(stages.pixel(x, y)[k])));
                    apart += most > 1 ? 1 : 0;
                    covered += ours.pixel(x, y)[0] + ours.pixel(x, y)[1] + ours.pixel(x, y)[2] > 0;
                }
            qInfo("%s: %zu of %zu covered pixels more than 1 apart", s.name.c_str(), apart, covered);
            QVERIFY(covered > 100);
            QVERIFY2(apart * 1000 <= covered, s.name.c_str());
        }
    }

    // What stays unexplained, in numbers, by hand: spans that start a pixel left on two rows;
    // screen coordinates a pixel right, a constant offset; colours off by 10 N.L in red.
    void descriptionsInNumbers() {
        const std::vector<std::string> spans =
            describeSpans({{0, 0, 1, 5}, {0, 1, 1, 4}, {0, 2, 3, 3}}, {{0, 0, 2, 5}, {0, 1, 2, 4}});
        QCOMPARE(spans, (std::vector<std::string>{
                            "their spans start on 2 rows 1 pixel left of ours",
                            "1 row of a triangle only they cover"}));
        const std::vector<Row> ours = {{10, 20}, {30, 40}, {50, 60}};
        const std::vector<Row> moved = {{11, 20}, {31, 40}, {51, 60}};
        QCOMPARE(describeScreen(moved, ours, {0, 1, 2}),
                 (std::vector<std::string>{"their coordinates are whole on all 3 vertices left",
                                           "x: on 3 vertices 1 pixel right",
                                           "a constant offset of (1, 0) pixels"}));
        Lighting lighting;
        lighting.light = rl::dvec3(0, 0, 0);
        std::vector<Sample> samples;
        std::vector<Row> best, theirs;
        ElementKeys left;
        for (int i = 0; i < 5; ++i) {
            // The light at the eye, P' on the axis: N.L = N.V = n_z for N = (s, 0, -c).
            const double c = 0.3 + 0.15 * i;
            const rl::vec3 n(float(std::sqrt(1.0 - c * c)), 0.0f, float(-c));
            samples.push_back({rl::vec3(0, 0, 5), n, std::nullopt, false});
            const PhongTerms t = phongTerms(lighting, samples.back());
            best.push_back({100, 100, 100});
            theirs.push_back({100 + 10 * t.nDotL, 100, 100});
            left.push_back(std::uint64_t(i));
        }
        const std::vector<std::string> colours =
            describeColours(theirs, best, left, lighting, samples);
        QCOMPARE(colours.size(), std::size_t(3));
        QVERIFY2(colours[0].rfind("5 samples left: theirs minus ours is (6, 0, 0) on average", 0) ==
                     0,
                 colours[0].c_str());
        QCOMPARE(colours[1], std::string("the difference follows N.L (correlation 1)"));
        // R.V = 2 (N.L)^2 - 1 with the light at the eye: below 0 for N.L of 0.3, 0.45, 0.6.
        QCOMPARE(colours[2], std::string("of them 0 samples have N.L < 0 and 3 have R.V < 0"));
    }

    // Several mistakes in one stage are each named, with what they explain; the Markdown and
    // JSON reports carry each finding's share, the unexplained remainder and the largest error,
    // and say what "theirs" and "ours" are.
    void reportsCarryTheFindings() {
        const CheckReport r = checkPython({"--truncate-terms", "--no-flip-normal"},
                                          {Stage::Lighting});
        const StageResult* lighting = r.result(Stage::Lighting);
        QVERIFY(lighting);
        std::set<std::string> ids;
        for (const StageFinding& f : lighting->findings) ids.insert(f.id);
        QCOMPARE(ids, (std::set<std::string>{"terms-truncated", "normal-not-flipped"}));
        QCOMPARE(lighting->unexplained, std::size_t(0));
        std::size_t explained = 0;
        for (const StageFinding& f : lighting->findings) explained += f.explained - f.spoiled;
        QCOMPARE(explained, lighting->differing);
        const std::string md = formatReport(r, "md");
        QVERIFY2(md.find("theirs: the program's answer; ours: the lecture's stage (RasterLab's) "
                         "applied to the same request") != std::string::npos,
                 md.c_str());
        QVERIFY2(md.find("| finding | explains | spoils | share |") != std::string::npos, md.c_str());
        QVERIFY2(md.find("| unexplained | 0 of " + std::to_string(lighting->differing) +
                         " | | 0.0% |") != std::string::npos,
                 md.c_str());
        QVERIFY2(md.find("Largest error: ") != std::string::npos, md.c_str());
        const QJsonObject json =
            QJsonDocument::fromJson(QByteArray::fromStdString(formatReport(r, "json"))).object();
        QVERIFY(json[QStringLiteral("legend")].toString().startsWith("theirs: the program's answer"));
        const QJsonObject stage = json[QStringLiteral("scenes")]
                                      .toArray()
                                      .first()[QStringLiteral("stages")]
                                      .toArray()
                                      .first()
                                      .toObject();
        QCOMPARE(stage[QStringLiteral("unexplained")].toInt(), 0);
        QVERIFY(stage[QStringLiteral("largestError")].toDouble() > 0.0);
        double shares = 0.0;
        for (const auto& f : stage[QStringLiteral("findings")].toArray())
            shares += f[QStringLiteral("share")].toDouble();
        QVERIFY2(std::abs(shares - 1.0) < 1e-9, qPrintable(QString::number(shares)));
        QCOMPARE(json[QStringLiteral("stageCounts")][QStringLiteral("lighting")]
                     [QStringLiteral("failed")]
                         .toInt(),
                 6);
    }

    // A program that runs out of memory breaks its stage with the last lines of its standard
    // error and a hint that names the limit; the next stage is asked of it again.
    void outOfMemoryGetsAHint() {
        QTemporaryDir dir;
        QFile file(dir.filePath("hog.py"));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("import sys\n"
                   "print('speaks 1', flush=True)\n"
                   "for line in sys.stdin:\n"
                   "    if line.strip() == 'basis':\n"
                   "        hoard = bytearray(1 << 30)\n"
                   "    if line.strip() == 'end':\n"
                   "        print('unsupported', flush=True)\n");
        file.close();
        CheckOptions options;
        options.limits.memoryBytes = 256LL << 20;
        options.stages = {Stage::Basis, Stage::View};
        const CheckReport r = runCheck((python() + " hog.py").toStdString(),
                                       dir.path().toStdString(), {scenes().front()}, options);
        const StageResult& basis = r.scenes.front().stages.front();
        QCOMPARE(int(basis.verdict), int(Verdict::Broken));
        QVERIFY2(!basis.standardError.empty() && basis.standardError.back() == "MemoryError",
                 formatReport(r, "text").c_str());
        QCOMPARE(basis.hint,
                 std::string("this is the runtime running out of memory: the program may use "
                             "256 MiB of data; --memory MB gives it more, and a smaller data set "
                             "or fewer copies need less"));
        QVERIFY2(basis.problem.find("its standard error says 'MemoryError'") != std::string::npos,
                 basis.problem.c_str());
        QCOMPARE(r.restarts, 1);  // asked the view again, after the basis broke
        QCOMPARE(int(r.scenes.front().stages.back().verdict), int(Verdict::Unsupported));
        QVERIFY(formatReport(r, "text").find("stderr| MemoryError") != std::string::npos);
    }

    // A program that starts the protocol once, crashes, and then no longer starts: each
    // stage after the crash breaks with the reason, and the run goes on to the end.
    void aRestartThatFailsCostsItsStageAlone() {
        QTemporaryDir dir;
        QFile file(dir.filePath("once.sh"));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("if [ -e started ]; then echo 'no, not again'; exit 1; fi\n"
                   "touch started; echo speaks 1; read line; read line; exit 3\n");
        file.close();
        CheckOptions options;
        options.limits.sandbox = false;  // it keeps a file in its folder
        options.stages = {Stage::Basis, Stage::View, Stage::Normals};
        const CheckReport r =
            runCheck("sh once.sh", dir.path().toStdString(), {scenes().front()}, options);
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        const auto& stages = r.scenes.front().stages;
        QCOMPARE(stages.size(), std::size_t(3));
        for (const StageResult& st : stages) QCOMPARE(int(st.verdict), int(Verdict::Broken));
        QVERIFY2(stages[0].problem.find("exit status 3") != std::string::npos,
                 stages[0].problem.c_str());
        for (std::size_t i = 1; i < 3; ++i) {
            QCOMPARE(stages[i].problem,
                     std::string("started again, the program did not start the protocol: "
                                 "expected 'speaks 1' as its first line, found 'no, not again'"));
            QCOMPARE(stages[i].standardError, std::vector<std::string>{"no, not again"});
        }
        QCOMPARE(r.restarts, 2);
    }

    // A class of three: the example, one that hangs and one that floods; each gets its row,
    // and the two that misbehave cost their time limit and nothing more.
    void gradeWritesARowForEachSubmission() {
        QTemporaryDir dir;
        const QDir root(dir.path());
        const auto submit = [&](const char* name, const QString& run) {
            QVERIFY(root.mkpath(QString("class/") + name));
            QFile file(root.filePath(QString("class/") + name + "/run"));
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write(run.toUtf8() + "\n");
        };
        submit("example", python() + " " + pythonFolder() + "/stages.py");
        submit("hangs", "sleep 1000");
        submit("floods", "yes");
        QVERIFY(root.mkpath("class/empty"));
        QElapsedTimer clock;
        clock.start();
        testing::CliRun run;
        QVERIFY2(
            testing::runCli({"grade", "--submissions", root.filePath("class"), "--output",
                             root.filePath("grades"), "--request-timeout", "3", "--timeout", "20"},
                            dir.path(), run),
            qPrintable(run.problem));
        qInfo("grade of four submissions: %.1f s", clock.elapsed() / 1000.0);
        QVERIFY(clock.elapsed() < 600000);
        QCOMPARE(run.exitCode, 0);
        const QStringList rows = run.out.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(rows.size(), 6);
        QCOMPARE(rows[0],
                 "| submission | basis | view | normals | projection | scan | zbuffer | lighting "
                 "| frame | passed | note |");
        QVERIFY2(
            rows[2].startsWith("| empty | not run |") && rows[2].endsWith("| no | no 'run' file |"),
            qPrintable(rows[2]));
        QVERIFY2(
            rows[3].startsWith("| example | passed | passed | passed | passed | passed | passed "
                               "| passed | passed | yes | every stage passed;"),
            qPrintable(rows[3]));
        QVERIFY2(rows[4].startsWith("| floods | not run |") &&
                     rows[4].contains("expected 'speaks 1' as its first line, found 'y'"),
                 qPrintable(rows[4]));
        QVERIFY2(rows[5].startsWith("| hangs | not run |") &&
                     rows[5].contains("no answer within 3 s (the limit per request)"),
                 qPrintable(rows[5]));
        const QString csv =
            QString::fromUtf8(testing::readFile(root.filePath("grades/grades.csv")));
        QVERIFY(csv.startsWith(
            "submission,basis,view,normals,projection,scan,zbuffer,lighting,frame,passed,note\n"));
        QVERIFY(
            csv.contains("\nexample,passed,passed,passed,passed,passed,passed,passed,passed,yes,"));
        QVERIFY(QFile::exists(root.filePath("grades/grades.md")));
        QVERIFY(testing::readFile(root.filePath("grades/reports/example.md"))
                    .contains("Every stage passed"));
        QVERIFY(QFile::exists(root.filePath("grades/reports/hangs.json")));
    }

    // HW2 submissions: each program run on a command file in a copy of its folder, the PNG
    // it names compared with ours. RasterLab's own `run` stands for a right program (this
    // tests the grading, not a diagnosis); one writes a black image, one hangs.
    void gradeRunsHw2Programs() {
        QTemporaryDir dir;
        const QDir root(dir.path());
        const auto write = [&](const QString& name, const QByteArray& text) {
            QVERIFY(root.mkpath(QFileInfo(root.filePath(name)).path()));
            QFile file(root.filePath(name));
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write(text);
        };
        write("mine.txt",
              "png 64 64 mine.png\nxyz -0.5 -0.4 0\nxyz 0.5 -0.4 0\nxyz 0.1 0.5 0\n"
              "frustum -0.3 0.3 -0.3 0.3 1 10\ntranslate 0 0 -3\ncolor 1 0.5 0\n"
              "trif 1 2 3\n");
        write("class/right/run", testing::cliPath().toUtf8() + " run\n");
        write("class/black/black.py",
              "import struct, zlib\n"
              "def chunk(k, d): return struct.pack('>I', len(d)) + k + d + "
              "struct.pack('>I', zlib.crc32(k + d))\n"
              "raw = b''.join(b'\\0' + b'\\0\\0\\0' * 64 for _ in range(64))\n"
              "open('mine.png', 'wb').write(b'\\x89PNG\\r\\n\\x1a\\n' + chunk(b'IHDR', "
              "struct.pack('>IIBBBBB', 64, 64, 8, 2, 0, 0, 0)) + chunk(b'IDAT', "
              "zlib.compress(raw)) + "
              "chunk(b'IEND', b''))\n");
        write("class/black/run", python().toUtf8() + " black.py\n");
        write("class/hangs/run", "sleep 1000; true\n");
        QElapsedTimer clock;
        clock.start();
        testing::CliRun run;
        QStringList arguments{"grade",
                              "--submissions",
                              root.filePath("class"),
                              "--hw2",
                              root.filePath("mine.txt"),
                              "--timeout",
                              "3",
                              "--format",
                              "csv"};
#if defined(__SANITIZE_ADDRESS__)
        // The right program is RasterLab's own, built with AddressSanitizer here: its shadow
        // memory needs more address space than any limit holds.
        arguments << "--memory"
                  << "0";
#endif
        QVERIFY2(testing::runCli(arguments, dir.path(), run), qPrintable(run.problem));
        QVERIFY(clock.elapsed() < 60000);
        QCOMPARE(run.exitCode, 0);
        const QStringList rows = run.out.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(rows.size(), 4);
        QCOMPARE(rows[0], QStringLiteral("submission,mine.png,passed,note"));
        QVERIFY2(rows[1].startsWith("black,failed (") && rows[1].endsWith(",no,"),
                 qPrintable(rows[1]));
        QVERIFY2(
            rows[2].startsWith("hangs,not compared,no,the program broke on mine.txt: it did not "
                               "end within 3 s (the limit for the whole run)"),
            qPrintable(rows[2]));
        QCOMPARE(rows[3], QStringLiteral("right,passed (0.00% off),yes,"));
    }

    // Programs that misbehave end within 120 s, with a status below 128 and a message that
    // names what happened.
    // HW2 grading on images no RasterLab code made: examples/student/hw2's rasterizer passes
    // as written, and fails with multmv ignored (2368 of 7680 pixels off).
    void gradeHw2WithAnIndependentRenderer() {
        QTemporaryDir dir;
        const QDir root(dir.path());
        const QString hw2 = testing::sourceDir() + "/examples/student/hw2/";
        const QByteArray run = python().toUtf8() + " '" + hw2.toUtf8() + "rasterizer.py'";
        for (const auto& [name, command] :
             {std::pair{QStringLiteral("as-written"), run},
              std::pair{QStringLiteral("forgets-multmv"), run + " --ignore-multmv"}}) {
            QVERIFY(root.mkpath("class/" + name));
            QFile file(root.filePath("class/" + name + "/run"));
            QVERIFY(file.open(QIODevice::WriteOnly));
            file.write(command + "\n");
        }
        testing::CliRun grade;
        QVERIFY2(testing::runCli({"grade", "--submissions", root.filePath("class"), "--hw2",
                                  hw2 + "scene.txt", "--format", "csv"},
                                 dir.path(), grade),
                 qPrintable(grade.problem));
        QCOMPARE(grade.exitCode, 0);
        QCOMPARE(
            grade.out.split('\n', Qt::SkipEmptyParts),
            QStringList({"submission,scene.png,passed,note", "as-written,passed (0.00% off),yes,",
                         "forgets-multmv,failed (30.83% off),no,"}));
    }

    // A program that forks as much as it can gets no more than its limit of processes, as
    // root too (a pids cgroup then), and what it started, even out of its process group, is
    // gone once the run ends.
    void processesAreBounded_data() {
        QTest::addColumn<bool>("sandbox");
        QTest::newRow("bubblewrap") << true;
        QTest::newRow("no sandbox") << false;
    }

    void processesAreBounded() {
        QFETCH(bool, sandbox);
        QTemporaryDir dir;
        QFile file(dir.filePath("forks.py"));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(
            "import os, time\n"
            "started = []\n"
            "for i in range(40):\n"
            "    try:\n"
            "        pid = os.fork()\n"
            "    except OSError:\n"
            "        break\n"
            "    if pid == 0:\n"
            "        os.setsid()\n"
            "        time.sleep(60)\n"
            "        os._exit(0)\n"
            "    started.append(pid)\n"
            "print(len(started), flush=True)\n"
            "print(os.getpid() if len(started) == 0 else started[0], flush=True)\n"
            "time.sleep(60)\n");
        file.close();
        Limits limits;
        limits.processes = 16;
        limits.sandbox = sandbox;
        pid_t escaped = 0;
        {
            StudentProgram program(python().toStdString() + " forks.py", dir.path().toStdString(),
                                   limits);
            bool bounded = false;
            for (const auto& p : program.protections())
                bounded = bounded || p.rfind("processes: 16", 0) == 0;
            if (!bounded)
                QSKIP(qPrintable(QString::fromStdString(program.missingProtections().back())));
            program.beginRequest();
            const auto count = program.readLine();
            QVERIFY2(count, program.error().c_str());
            qInfo("forks that succeeded: %s (limit 16 processes)", count->c_str());
            QVERIFY(std::stoi(*count) > 0);
            QVERIFY(std::stoi(*count) < 16);
            const auto first = program.readLine();
            QVERIFY2(first, program.error().c_str());
            escaped = pid_t(std::stol(*first));
        }
        if (sandbox) return;  // the first fork's pid is inside bubblewrap's own pid namespace
        QTRY_VERIFY_WITH_TIMEOUT(kill(escaped, 0) != 0, 2000);
    }

    void hostileProgramsAreStopped_data() {
        QTest::addColumn<QString>("command");
        QTest::addColumn<QString>("message");
        QTest::newRow("sleeps") << "sleep 100"
                                << "no answer within 2 s (the limit per request)";
        QTest::newRow("floods") << "yes"
                                << "expected 'speaks 1' as its first line, found 'y'";
        QTest::newRow("floods after the handshake") << "echo speaks 1; yes"
                                                    << "without its 'end' (the output limit)";
        QTest::newRow("exits at once")
            << "true"
            << "the program ended (exit status 0) before it finished answering";
        QTest::newRow("writes binary")
            << "printf 'speaks 1\\n\\001\\002\\n'"
            << "the answer is not text: byte 0x01 at column 1 of its line";
        QTest::newRow("never ends a line") << "echo speaks 1; yes | tr -d '\\n'"
                                           << "bytes without the end of a line";
        QTest::newRow("crashes") << "echo speaks 1; kill -SEGV $$"
                                 << "killed by signal 11 (Segmentation fault)";
        QTest::newRow("answers another stage")
            << "echo speaks 1; cat"
            << "their answer to view:1:1: expected 'light', found 'view'";
        QTest::newRow("not found") << "./no-such-program"
                                   << "exit status 127: the command was not found";
    }

    void hostileProgramsAreStopped() {
        QFETCH(QString, command);
        QFETCH(QString, message);
        // 2 s for the one that sleeps; the others get the time to be read to their limit
        // (four million lines of a flood take seconds under AddressSanitizer). Two stages: a
        // program that breaks is started again for the second, each costing it as much.
        const bool sleeps = command.startsWith("sleep");
        const QStringList arguments{"check",     "--program", command,
                                    "--scene",   "triangle",  "--stages",
                                    "basis,view", "--timeout", "30",
                                    "--request-timeout", sleeps ? "2" : "20"};
        QElapsedTimer clock;
        clock.start();
        testing::CliRun run;
        QVERIFY2(testing::runCli(arguments, QDir::tempPath(), run), qPrintable(run.problem));
        qInfo("%s: %.1f s", qPrintable(command), clock.elapsed() / 1000.0);
        QVERIFY(clock.elapsed() < 120000);
        QVERIFY2(run.out.contains(message), qPrintable(run.out));
        QVERIFY(run.exitCode > 0 && run.exitCode < 128);
        QCOMPARE(run.exitCode, 4);
    }
};

QTEST_GUILESS_MAIN(TestCheck)
#include "tst_check.moc"
