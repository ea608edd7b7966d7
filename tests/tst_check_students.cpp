// check on students' programs RasterLab did not write: examples/student/java and
// examples/student/c, each written by a helper from docs/stage-protocol.md and the seeds
// alone, with real students' mistakes behind switches. Each mistake is named at its stage,
// several at once are each named with what they explain, the frame's diagnosis starts from
// the stages' findings and names no cause a passed stage rules out, a crash costs one stage
// of one scene, a chained run judges each stage on what it was sent, and the JVM starts with
// no flags under the default limits.
#include <QtTest>

#include <map>
#include <set>

#include "app/check/check_session.h"
#include "tests/test_support.h"

using namespace rasterlab::check;

namespace {

const std::vector<CheckScene>& scenes() {
    static const std::vector<CheckScene> all = defaultCheckScenes();
    return all;
}

// Without a JDK (scripts/setup.sh installs one) the Java program was not built.
#define NEEDS_JAVA(student)                                                                   \
    if ((student) == QLatin1String("java") && QStringLiteral(STUDENT_JAVA).isEmpty())        \
    QSKIP("no JDK 17 when this was built: scripts/setup.sh installs default-jdk-headless")

QString javaCommand(const QString& switches) {
    return QStringLiteral("'%1' -cp '%2' Stages %3")
        .arg(QStringLiteral(STUDENT_JAVA), QStringLiteral(STUDENT_JAVA_CLASSES), switches);
}

QString cCommand(const QString& switches) {
    return QStringLiteral("'%1' --stages %2").arg(QStringLiteral(STUDENT_C), switches);
}

CheckReport check(const QString& command, std::vector<Stage> stages = {}, bool chain = false) {
    CheckOptions options;
    if (!stages.empty()) options.stages = std::move(stages);
    options.chain = chain;
#if defined(__SANITIZE_ADDRESS__)
    options.limits.totalSeconds = 600.0;  // RasterLab's judging is slower under ASan
    options.limits.requestSeconds = 120.0;
#endif
    return runCheck(command.toStdString(), QDir::tempPath().toStdString(), scenes(), options);
}

std::string text(const CheckReport& r) {
    return formatReport(r, "text");
}

// The ids of a stage result's findings.
std::set<std::string> ids(const StageResult& r) {
    std::set<std::string> out;
    for (const StageFinding& f : r.findings) out.insert(f.id);
    return out;
}

// What a mistake does in a check: the stage it fails, the finding that names it there, in how
// many of the six scenes at least, and the frame's finding it starts from ("" when the frame
// passes everywhere).
struct Expected {
    Stage stage;
    std::string finding;
    int scenes;
};

// Every scene where `stage` failed names `finding` with nothing left unexplained; returns how
// many scenes it failed in.
int namedIn(const CheckReport& r, const Expected& e) {
    int named = 0;
    for (const SceneReport& s : r.scenes)
        for (const StageResult& st : s.stages) {
            if (st.stage != e.stage || st.verdict == Verdict::Passed) continue;
            if (st.verdict != Verdict::Failed || !ids(st).count(e.finding)) return -1;
            if (st.unexplained != 0) return -1;
            ++named;
        }
    return named;
}

// The frame names no compare mistake a stage that passed (exactly) rules out, and where the
// named stage failed, the frame's first finding is that stage's.
bool frameConsistent(const CheckReport& r, Stage stage, std::string* why) {
    static const std::map<Stage, std::set<std::string>> shown = {
        {Stage::Basis, {"basis-u-reversed", "basis-n-not-normalised"}},
        {Stage::View, {"light-in-world", "light-without-c"}},
        {Stage::Normals, {"vertex-normals-unnormalised", "area-weighted-normals"}},
        {Stage::Projection, {"screen-map"}},
        {Stage::Scan, {"fill-rule", "sample-offset"}},
        {Stage::ZBuffer, {"depth-reversed", "depth-ties", "painter-order"}},
        {Stage::Lighting,
         {"normal-not-flipped", "view-vector-reversed", "light-behind-not-skipped",
          "specular-where-rv-negative", "ambient-times-od", "ambient-ia-only", "terms-truncated",
          "epsilon-special-cases", "colour-wrap", "colour-scale"}},
    };
    for (const SceneReport& s : r.scenes) {
        const StageResult* frame = nullptr;
        bool failed = false;
        std::set<std::string> ruledOut;
        for (const StageResult& st : s.stages) {
            if (st.stage == Stage::Frame) frame = &st;
            if (st.stage == stage && st.verdict == Verdict::Failed) failed = true;
            if (st.verdict == Verdict::Passed && shown.count(st.stage))
                ruledOut.insert(shown.at(st.stage).begin(), shown.at(st.stage).end());
        }
        if (!frame || frame->verdict != Verdict::Failed) continue;
        for (const StageFinding& f : frame->findings)
            if (ruledOut.count(f.id)) {
                *why = s.name + ": the frame names " + f.id + ", which a passed stage rules out";
                return false;
            }
        const std::string first = "stage-" + std::string(stageName(stage));
        if (failed && !frame->findings.empty() && frame->findings.front().id != first &&
            frame->findings.front().id.rfind("stage-", 0) == 0) {
            *why = s.name + ": the frame starts from " + frame->findings.front().id;
            return false;
        }
    }
    return true;
}

void addRows(const char* student, const std::vector<std::pair<const char*, Expected>>& rows) {
    for (const auto& [switches, e] : rows)
        QTest::newRow((std::string(student) + " " + switches).c_str())
            << QString(student) << QString(switches) << int(e.stage)
            << QString::fromStdString(e.finding) << e.scenes;
}

}  // namespace

class TestCheckStudents : public QObject {
    Q_OBJECT

private slots:
    // Both pass every stage of every default scene, plain and chained; the JVM starts with
    // plain `java` under the default limits (2048 MiB of data).
    void rightProgramsPassEveryStage_data() {
        QTest::addColumn<QString>("student");
        QTest::addColumn<QString>("command");
        QTest::addColumn<bool>("chain");
        QTest::newRow("java") << "java" << javaCommand({}) << false;
        QTest::newRow("java chained") << "java" << javaCommand({}) << true;
        QTest::newRow("c") << "c" << cCommand({}) << false;
        QTest::newRow("c chained") << "c" << cCommand({}) << true;
    }

    void rightProgramsPassEveryStage() {
        QFETCH(QString, student);
        QFETCH(QString, command);
        QFETCH(bool, chain);
        NEEDS_JAVA(student);
        const CheckReport r = check(command, {}, chain);
        QVERIFY2(r.passed(), text(r).c_str());
        QCOMPARE(r.scenes.size(), std::size_t(6));
        bool memory = false;
        for (const std::string& p : r.protections)
            memory = memory || p.rfind("memory: 2048 MiB of data", 0) == 0;
        QVERIFY(memory);
        qInfo("%s%s: %.2f s", qPrintable(command), chain ? " (chained)" : "", r.seconds);
    }

    // Each mistake alone: failed at its stage, named there in every scene it fails in (at
    // least `scenes` of the six) with nothing unexplained, and the frame consistent with it.
    void eachMistakeIsNamedAtItsStage_data() {
        QTest::addColumn<QString>("student");
        QTest::addColumn<QString>("switches");
        QTest::addColumn<int>("stage");
        QTest::addColumn<QString>("finding");
        QTest::addColumn<int>("scenes");
        addRows("java", {
                            {"--no-int-cast", {Stage::Projection, "screen-fractional", 5}},
                            {"--ceil-screen", {Stage::Projection, "screen-ceil", 5}},
                            {"--specular-without-nl-test",
                             {Stage::Lighting, "specular-without-nl-test", 6}},
                            {"--edges-y-ax-b", {Stage::Scan, "edges-y-ax-b", 5}},
                            {"--light-in-place", {Stage::View, "light-in-place-on-p", 2}},
                            {"--n-not-normalised=never",
                             {Stage::Basis, "basis-n-not-normalised", 6}},
                            {"--n-not-normalised=after",
                             {Stage::Basis, "basis-n-normalised-after", 2}},
                            {"--vertex-normals-front-only",
                             {Stage::Normals, "vertex-normals-front-faces", 6}},
                        });
        addRows("c", {
                         {"--light-in-world", {Stage::View, "light-in-world", 6}},
                         {"--round-screen", {Stage::Projection, "vertex-snap", 5}},
                         {"--normals-crossed", {Stage::Normals, "normals-crossed", 6}},
                         {"--span-unit-steps", {Stage::Scan, "span-unit-steps-from-left-x", 6}},
                         {"--span-start-round", {Stage::Scan, "span-start-rounded", 6}},
                         {"--span-start-trunc", {Stage::Scan, "span-start-truncated", 6}},
                         {"--span-open-end", {Stage::Scan, "span-end-open", 6}},
                         {"--span-open-start", {Stage::Scan, "span-start-open", 6}},
                         {"--truncate-terms", {Stage::Lighting, "terms-truncated", 6}},
                         {"--epsilon 0.001", {Stage::Lighting, "epsilon-special-cases", 6}},
                         {"--n-not-normalised-for-u",
                          {Stage::Basis, "basis-n-not-normalised-in-u", 6}},
                     });
    }

    void eachMistakeIsNamedAtItsStage() {
        QFETCH(QString, student);
        QFETCH(QString, switches);
        QFETCH(int, stage);
        QFETCH(QString, finding);
        QFETCH(int, scenes);
        NEEDS_JAVA(student);
        // The stage and the frame, which starts from that stage's findings.
        const CheckReport r = check(student == "java" ? javaCommand(switches) : cCommand(switches),
                                    {Stage(stage), Stage::Frame});
        const Expected e{Stage(stage), finding.toStdString(), scenes};
        const int named = namedIn(r, e);
        QVERIFY2(named >= scenes, text(r).c_str());
        std::string why;
        QVERIFY2(frameConsistent(r, Stage(stage), &why), (why + "\n" + text(r)).c_str());
        qInfo("%s %s: %s named in %d scenes (%.2f s)", qPrintable(student), qPrintable(switches),
              qPrintable(finding), named, r.seconds);
    }

    // The real C program's six departures at once: each stage names its own, the scan and the
    // lighting in every scene, and the frame starts from the stages' findings.
    void theCProgramsMistakesTogether() {
        const CheckReport r = check(cCommand(
            "--light-in-world --round-screen --normals-crossed --span-unit-steps "
            "--truncate-terms --epsilon 0.001"));
        for (const auto& e : {Expected{Stage::View, "light-in-world", 6},
                              Expected{Stage::Projection, "vertex-snap", 5},
                              Expected{Stage::Normals, "normals-crossed", 6},
                              Expected{Stage::Scan, "span-unit-steps-from-left-x", 6},
                              Expected{Stage::Lighting, "terms-truncated", 6},
                              Expected{Stage::Lighting, "epsilon-special-cases", 6}})
            QVERIFY2(namedIn(r, e) >= e.scenes, (e.finding + "\n" + text(r)).c_str());
        std::string why;
        QVERIFY2(frameConsistent(r, Stage::View, &why), (why + "\n" + text(r)).c_str());
        for (const SceneReport& s : r.scenes) {
            const StageResult& frame = s.stages.back();
            QCOMPARE(int(frame.stage), int(Stage::Frame));
            QVERIFY2(frame.unexplained * 20 < frame.differing, (s.name + "\n" + text(r)).c_str());
        }
        qInfo("the C program's mistakes together: %.2f s", r.seconds);
    }

    // The Java program's scan throws ArrayIndexOutOfBoundsException in some scenes: that
    // stage and the frame break there, with the exception and its first frame quoted; every
    // other stage of every scene is still asked, and the summary counts per stage.
    void aCrashCostsOneStageOfOneScene() {
        NEEDS_JAVA(QStringLiteral("java"));
        const CheckReport r = check(javaCommand("--scan-index-bug --no-int-cast"));
        const auto counts = r.stageCounts(Stage::Scan);
        QVERIFY2(counts.count(Verdict::Broken) && counts.count(Verdict::Passed), text(r).c_str());
        const int broken = counts.at(Verdict::Broken);
        QCOMPARE(r.stageCounts(Stage::Basis), (std::map<Verdict, int>{{Verdict::Passed, 6}}));
        QCOMPARE(r.stageCounts(Stage::Lighting), (std::map<Verdict, int>{{Verdict::Passed, 6}}));
        QCOMPARE(r.stageCounts(Stage::Frame).at(Verdict::Broken), broken);
        // Started again after each break but one that ends the run.
        QVERIFY2(r.restarts >= 2 * broken - 1 && r.restarts <= 2 * broken, text(r).c_str());
        for (const SceneReport& s : r.scenes)
            for (const StageResult& st : s.stages) {
                if (st.verdict != Verdict::Broken) continue;
                QVERIFY2(st.problem.find("ArrayIndexOutOfBoundsException") != std::string::npos &&
                             st.problem.find("at Pipeline.scanTriangle(Pipeline.java:") !=
                                 std::string::npos,
                         st.problem.c_str());
                bool quoted = false;
                for (const std::string& line : st.standardError)
                    quoted = quoted || line.rfind("Exception in thread \"main\" "
                                                  "java.lang.ArrayIndexOutOfBoundsException",
                                                  0) == 0;
                QVERIFY(quoted);
            }
        const std::string report = text(r);
        QVERIFY2(report.find("scan " + std::to_string(6 - broken) + " passed, " +
                             std::to_string(broken) + " broken") != std::string::npos,
                 report.c_str());
    }

    // Chained, both students' z-buffers are judged on the fragments of their own spans: they
    // pass, with the spans' error carried beside the verdict.
    void chainedZBuffersPass_data() {
        QTest::addColumn<QString>("student");
        QTest::addColumn<QString>("command");
        QTest::newRow("java") << "java" << javaCommand("--no-int-cast --edges-y-ax-b");
        QTest::newRow("c") << "c" << cCommand("--round-screen --span-unit-steps");
    }

    void chainedZBuffersPass() {
        QFETCH(QString, student);
        QFETCH(QString, command);
        NEEDS_JAVA(student);
        const CheckReport r =
            check(command, {Stage::Basis, Stage::View, Stage::Normals, Stage::Projection,
                            Stage::Scan, Stage::ZBuffer},
                  true);
        QCOMPARE(r.stageCounts(Stage::ZBuffer), (std::map<Verdict, int>{{Verdict::Passed, 6}}));
        int carried = 0;
        for (const SceneReport& s : r.scenes)
            for (const StageResult& st : s.stages)
                if (st.stage == Stage::ZBuffer && st.carried) carried += int(*st.carried > 0);
        QVERIFY2(carried >= 5, text(r).c_str());
    }
};

QTEST_GUILESS_MAIN(TestCheckStudents)
#include "tst_check_students.moc"
