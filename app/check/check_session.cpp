#include "app/check/check_session.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>

#include <algorithm>
#include <cstdio>

#include "pipeline/io/course_readers.h"
#include "pipeline/io/course_scene.h"
#include "pipeline/scene/default_scene.h"
#include "pipeline/scene/lessons.h"

namespace rasterlab::check {

namespace {

constexpr int kCheckWidth = 160, kCheckHeight = 120;

std::shared_ptr<const rl::Scene> sceneOf(const rl::CourseSceneTexts& texts,
                                         const std::string& objectName) {
    rl::Diagnostics diagnostics;
    auto camera = rl::readCourseCamera(texts.camera, "camera.cfg", diagnostics);
    auto lighting = rl::readCourseLighting(texts.lighting, "lighting.txt", diagnostics);
    auto object = rl::parseCourseObject(texts.object, objectName, diagnostics);
    if (!camera || !lighting || !object) return nullptr;
    rl::CourseSceneSettings settings;
    settings.width = kCheckWidth;
    settings.height = kCheckHeight;
    auto scene = std::make_shared<rl::Scene>(
        rl::makeCourseScene({camera.value(), lighting.value(), object.value()}, settings));
    scene->name = objectName;
    return scene;
}

// One program's run: started (again after it breaks), and asked request by request.
class Session {
public:
    Session(const std::string& command, const std::string& folder, const CheckOptions& options,
            CheckReport& report)
        : m_command(command), m_folder(folder), m_options(options), m_report(report) {}

    // A started program that has said which version it speaks, or null (report.failure
    // says why when it never could). After a break it is started again for every request,
    // while the run's time lasts.
    StudentProgram* program() {
        if (m_program) return m_program.get();
        if (m_dead) return nullptr;
        Limits limits = m_options.limits;
        limits.totalSeconds = std::max(0.1, m_options.limits.totalSeconds - m_spent);
        m_program = std::make_unique<StudentProgram>(m_command, m_folder, limits);
        if (m_started++ > 0) ++m_report.restarts;
        if (m_report.protections.empty()) {
            m_report.protections = m_program->protections();
            m_report.missing = m_program->missingProtections();
        }
        m_firstLines.clear();
        if (handshake()) return m_program.get();
        std::vector<std::string> lines = m_program->errorLines();
        if (lines.empty()) lines = m_firstLines;  // a runtime may say why on its output
        if (m_started > 1) {
            // Started again after a break, it did not answer this time: this request breaks,
            // and the next starts it again.
            m_restartError = "started again, the program did not start the protocol: " +
                             m_handshakeError;
            m_restartLines = lines;
            finish();
            return nullptr;
        }
        // A program that cannot even say its version the first time is not started again.
        m_report.failure = "the program did not start the protocol: " + m_handshakeError;
        m_report.failureError = lines;
        m_report.failureHint = memoryHintOf(lines, m_options.limits.memoryBytes);
        m_dead = true;
        m_deadReason = "not asked: the program did not start the protocol";
        finish();
        return nullptr;
    }

    // Asks one stage; the answer's lines (without "end"), or nullopt with `problem` set
    // ("unsupported" comes back as the single line "unsupported").
    std::optional<std::vector<std::string>> ask(const Request& request, StageResult& problem) {
        StudentProgram* p = program();
        if (!p) {
            problem.problem = m_dead ? m_deadReason : m_restartError;
            if (!m_dead) {
                problem.standardError = m_restartLines;
                problem.hint = memoryHintOf(m_restartLines, m_options.limits.memoryBytes);
            }
            return std::nullopt;
        }
        p->beginRequest();
        std::vector<std::string> lines;
        if (p->send(request.text())) {
            while (auto line = p->readLine()) {
                const std::string trimmed = trim(*line);
                if (trimmed == "end") return lines;
                if (lines.empty() && trimmed == "unsupported")
                    return std::vector<std::string>{"unsupported"};
                lines.push_back(std::move(*line));
            }
        }
        problem.problem = "the program broke while answering '" +
                          std::string(stageName(request.stage())) + "': " + p->error();
        problem.standardError = p->errorLines();
        problem.hint = p->memoryHint();
        finish();
        return std::nullopt;
    }

    void close() {
        if (!m_program) return;
        m_program->send("bye\n");
        m_program->stop();
        finish();
    }

    bool outOfTime() const { return m_spent >= m_options.limits.totalSeconds; }

private:
    static std::string trim(const std::string& s) {
        const std::size_t a = s.find_first_not_of(" \t\r");
        if (a == std::string::npos) return {};
        return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
    }

    bool handshake() {
        StudentProgram& p = *m_program;
        p.beginRequest();
        if (!p.send("rasterlab " + std::to_string(kProtocolVersion) + "\n")) {
            m_handshakeError = p.error();
            return false;
        }
        const auto line = p.readLine();
        if (!line) {
            m_handshakeError = p.error();
            return false;
        }
        const std::string t = trim(*line);
        if (t.rfind("speaks ", 0) != 0) {
            m_handshakeError =
                "expected 'speaks 1' as its first line, found '" + t.substr(0, 120) + "'";
            // A runtime that cannot start may say why on its standard output (a JVM does):
            // what it wrote before it was stopped, a few lines.
            m_firstLines.push_back(t.substr(0, std::size_t(kErrorLineBytes)));
            p.stop();
            p.beginRequest();
            for (int i = 1; i < kErrorLines; ++i) {
                const auto more = p.readLine();
                if (!more) break;
                m_firstLines.push_back(more->substr(0, std::size_t(kErrorLineBytes)));
            }
            return false;
        }
        const std::string version = trim(t.substr(7));
        if (version != std::to_string(kProtocolVersion)) {
            m_handshakeError = "it speaks version " + version.substr(0, 20) +
                               "; RasterLab speaks " + std::to_string(kProtocolVersion);
            return false;
        }
        m_report.version = kProtocolVersion;
        return true;
    }

    void finish() {
        if (!m_program) return;
        m_spent += m_program->secondsUsed();
        m_program.reset();
        if (outOfTime() && !m_dead) {
            m_dead = true;
            m_deadReason = "not asked: the time for the whole run had passed";
        }
    }

    std::string m_command, m_folder;
    const CheckOptions& m_options;
    CheckReport& m_report;
    std::unique_ptr<StudentProgram> m_program;
    int m_started = 0;
    bool m_dead = false;
    std::string m_deadReason, m_handshakeError, m_restartError;
    std::vector<std::string> m_firstLines, m_restartLines;
    double m_spent = 0.0;
};

}  // namespace

bool CheckReport::passed() const {
    if (!failure.empty() || cancelled) return false;
    for (const SceneReport& s : scenes) {
        if (!s.error.empty()) return false;
        for (const StageResult& r : s.stages)
            if (r.verdict != Verdict::Passed) return false;
    }
    return true;
}

Verdict CheckReport::stageVerdict(Stage stage) const {
    Verdict worst = Verdict::Passed;
    const auto rank = [](Verdict v) {
        return v == Verdict::Passed        ? 0
               : v == Verdict::Unsupported ? 1
               : v == Verdict::Failed      ? 2
                                           : 3;
    };
    for (const SceneReport& s : scenes)
        for (const StageResult& r : s.stages)
            if (r.stage == stage && rank(r.verdict) > rank(worst)) worst = r.verdict;
    return worst;
}

std::map<Verdict, int> CheckReport::stageCounts(Stage stage) const {
    std::map<Verdict, int> counts;
    for (const SceneReport& s : scenes)
        for (const StageResult& r : s.stages)
            if (r.stage == stage) ++counts[r.verdict];
    return counts;
}

bool CheckReport::anyBroken() const {
    if (!failure.empty()) return true;
    for (const SceneReport& s : scenes)
        for (const StageResult& r : s.stages)
            if (r.verdict == Verdict::Broken) return true;
    return false;
}

const StageResult* CheckReport::result(Stage stage) const {
    if (scenes.empty()) return nullptr;
    for (const StageResult& r : scenes.front().stages)
        if (r.stage == stage) return &r;
    return nullptr;
}

CheckReport runCheck(const std::string& command, const std::string& folder,
                     const std::vector<CheckScene>& scenes, const CheckOptions& options,
                     const CheckProgress& progress) {
    CheckReport report;
    report.command = command;
    report.folder = folder;
    report.chained = options.chain;
    const auto started = std::chrono::steady_clock::now();
    Session session(command, folder, options, report);
    const int total = int(scenes.size() * options.stages.size());
    int done = 0;
    for (const CheckScene& scene : scenes) {
        SceneReport& sr = report.scenes.emplace_back();
        sr.name = scene.name;
        sr.width = scene.scene->width;
        sr.height = scene.scene->height;
        auto check = StageCheck::make(scene.scene);
        if (!check) {
            sr.error = check.error().message;
            done += int(options.stages.size());
            continue;
        }
        StageCheck::Answers answers;  // theirs, for a chained run's next requests
        for (Stage stage : options.stages) {
            const auto stopped = [&] {
                return options.limits.cancel && options.limits.cancel->load();
            };
            if (stopped() ||
                (progress &&
                 !progress(done, total, scene.name + ": " + std::string(stageName(stage))))) {
                report.cancelled = true;
                break;
            }
            ++done;
            StageResult result;
            result.stage = stage;
            const auto chained = options.chain ? (*check)->chainedInputs(answers) : nullptr;
            const auto lines = session.ask(
                chained ? (*check)->chainedRequest(stage, *chained) : (*check)->request(stage),
                result);
            if (stopped()) {
                report.cancelled = true;
                break;
            }
            if (!lines) {
                result.verdict = Verdict::Broken;
            } else if (lines->size() == 1 && lines->front() == "unsupported") {
                result.verdict = Verdict::Unsupported;
            } else {
                auto records =
                    parseAnswer(stage, *lines, "their answer to " + std::string(stageName(stage)));
                if (!records) {
                    result.verdict = Verdict::Broken;
                    result.problem = records.error().toString();
                } else {
                    result = options.chain
                                 ? (*check)->judgeChained(stage, records.value(), *chained,
                                                          sr.stages)
                                 : (*check)->judge(stage, records.value(), sr.stages);
                    if (stage == Stage::Frame && result.verdict != Verdict::Broken)
                        sr.theirFrame = StageCheck::theirImage(records.value());
                    if (stage == Stage::Scan && result.verdict != Verdict::Broken)
                        sr.theirSpans = records.value()[0].rows;
                    // An answer the judge could not read as one is not sent on.
                    if (result.verdict != Verdict::Broken)
                        answers[stage] = std::move(records.value());
                }
            }
            sr.stages.push_back(std::move(result));
        }
        if (report.cancelled) break;
    }
    session.close();
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (progress) progress(total, total, "done");
    return report;
}

std::vector<CheckScene> defaultCheckScenes() {
    std::vector<CheckScene> scenes;
    for (const std::string& name : rl::lessonNames()) {
        if (name == "near-plane" || name == "lights" || name == "gouraud") continue;
        const auto lesson = rl::generateLesson(name);
        if (!lesson) continue;
        if (auto scene = sceneOf(lesson->texts, lesson->objectFile))
            scenes.push_back({name, scene});
    }
    if (auto scene = sceneOf(rl::generateDefaultScene(), rl::kDefaultObjectFile))
        scenes.push_back({"default scene", scene});
    return scenes;
}

}  // namespace rasterlab::check
