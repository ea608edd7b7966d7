// The check's report as text, Markdown and JSON (check_session.h).
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>

#include <cstdio>

#include "app/check/check_session.h"
#include "pipeline/core/format.h"

namespace rasterlab::check {

namespace {

QString q(const std::string& s) {
    return QString::fromStdString(s);
}

// "passed (3 elements)", "failed: 2 of 9 elements differ ...", in one line.
std::string summary(const StageResult& r) {
    switch (r.verdict) {
        case Verdict::Passed:
            return "passed (" + std::to_string(r.elements) + " elements, largest error " +
                   rl::formatNumber(r.largestError) + "; tolerance " + r.tolerance + ")";
        case Verdict::Unsupported:
            return "unsupported (the program answered 'unsupported')";
        case Verdict::Broken:
            return "broken: " + r.problem;
        case Verdict::Failed:
            return "failed: " + std::to_string(r.differing) + " of " + std::to_string(r.elements) +
                   " elements differ, largest error " + rl::formatNumber(r.largestError) +
                   " (tolerance " + r.tolerance + ")";
    }
    return {};
}

std::vector<std::string> details(const StageResult& r) {
    std::vector<std::string> lines;
    if (r.first)
        lines.push_back("first: " + r.first->element + ": theirs " + r.first->theirs + ", ours " +
                        r.first->ours);
    if (r.first && !r.first->formula.empty()) lines.push_back(r.first->formula);
    if (!r.likelyCause.empty())
        lines.push_back("likely cause: " + r.likelyCause);
    else if (r.verdict == Verdict::Failed)
        lines.push_back("no known mistake of this stage gives their answer");
    return lines;
}

std::string header(const CheckReport& r) {
    std::string s = "Check of `" + r.command + "` in " + r.folder;
    s += r.version ? " (stage protocol " + std::to_string(r.version) + ")" : "";
    if (r.chained) s += ", chained: each stage given the program's own earlier answers";
    return s;
}

std::string text(const CheckReport& r) {
    std::string out = header(r) + "\n";
    for (const std::string& p : r.protections) out += "  limit: " + p + "\n";
    for (const std::string& p : r.missing) out += "  not applied: " + p + "\n";
    if (!r.failure.empty()) out += "\n" + r.failure + "\n";
    for (const SceneReport& s : r.scenes) {
        out +=
            "\n" + s.name + " (" + std::to_string(s.width) + "x" + std::to_string(s.height) + ")\n";
        if (!s.error.empty()) out += "  not checked: " + s.error + "\n";
        for (const StageResult& st : s.stages) {
            char name[16];
            std::snprintf(name, sizeof name, "%-11s", std::string(stageName(st.stage)).c_str());
            out += "  " + std::string(name) + summary(st) + "\n";
            for (const std::string& d : details(st)) out += "             " + d + "\n";
        }
    }
    out += "\nstages: ";
    bool firstStage = true;
    for (Stage stage : kStages) {
        bool ran = false;
        for (const SceneReport& s : r.scenes)
            for (const StageResult& st : s.stages) ran = ran || st.stage == stage;
        if (!ran) continue;
        if (!firstStage) out += ", ";
        out += stageName(stage);
        out += ' ';
        out += verdictName(r.stageVerdict(stage));
        firstStage = false;
    }
    out += '\n';
    out += r.passed() ? "every stage passed" : "not every stage passed";
    if (r.restarts)
        out += "; the program was started again " + std::to_string(r.restarts) + " times";
    if (r.cancelled) out += "; cancelled";
    out += " (" + rl::formatNumber(r.seconds) + " s)\n";
    return out;
}

std::string markdown(const CheckReport& r) {
    std::string out = "# " + header(r) + "\n\n";
    for (const std::string& p : r.protections) out += "- limit: " + p + "\n";
    for (const std::string& p : r.missing) out += "- not applied: " + p + "\n";
    if (!r.failure.empty()) out += "\n**" + r.failure + "**\n";
    out += "\n| scene |";
    std::string rule = "|---|";
    for (Stage stage : kStages) {
        out += ' ';
        out += stageName(stage);
        out += " |";
        rule += "---|";
    }
    out += "\n" + rule + "\n";
    for (const SceneReport& s : r.scenes) {
        out += "| " + markdownCell(s.name) + " |";
        for (Stage stage : kStages) {
            std::string cell = s.error.empty() ? "" : "not checked";
            for (const StageResult& st : s.stages)
                if (st.stage == stage) cell = std::string(verdictName(st.verdict));
            out += " " + cell + " |";
        }
        out += "\n";
    }
    for (const SceneReport& s : r.scenes)
        for (const StageResult& st : s.stages) {
            if (st.verdict == Verdict::Passed) continue;
            out += "\n## " + s.name + ": " + std::string(stageName(st.stage)) + "\n\n" +
                   summary(st) + "\n";
            for (const std::string& d : details(st)) out += "\n    " + d;
            out += "\n";
        }
    out += '\n';
    out += r.passed() ? "Every stage passed" : "Not every stage passed";
    out += " (" + rl::formatNumber(r.seconds) + " s).\n";
    return out;
}

QJsonObject stageJson(const StageResult& st) {
    QJsonObject o;
    o[QStringLiteral("stage")] = q(std::string(stageName(st.stage)));
    o[QStringLiteral("verdict")] = q(std::string(verdictName(st.verdict)));
    o[QStringLiteral("elements")] = qint64(st.elements);
    o[QStringLiteral("differing")] = qint64(st.differing);
    o[QStringLiteral("largestError")] = st.largestError;
    o[QStringLiteral("tolerance")] = q(st.tolerance);
    if (st.first) {
        QJsonObject f;
        f[QStringLiteral("element")] = q(st.first->element);
        f[QStringLiteral("theirs")] = q(st.first->theirs);
        f[QStringLiteral("ours")] = q(st.first->ours);
        f[QStringLiteral("formula")] = q(st.first->formula);
        o[QStringLiteral("first")] = f;
    }
    if (!st.likelyCause.empty()) o[QStringLiteral("likelyCause")] = q(st.likelyCause);
    if (!st.problem.empty()) o[QStringLiteral("problem")] = q(st.problem);
    return o;
}

std::string json(const CheckReport& r) {
    QJsonObject o;
    o[QStringLiteral("command")] = q(r.command);
    o[QStringLiteral("folder")] = q(r.folder);
    o[QStringLiteral("protocolVersion")] = r.version;
    o[QStringLiteral("chained")] = r.chained;
    QJsonArray protections, missing, scenes;
    for (const std::string& p : r.protections) protections.append(q(p));
    for (const std::string& p : r.missing) missing.append(q(p));
    o[QStringLiteral("protections")] = protections;
    o[QStringLiteral("notApplied")] = missing;
    if (!r.failure.empty()) o[QStringLiteral("failure")] = q(r.failure);
    for (const SceneReport& s : r.scenes) {
        QJsonObject so;
        so[QStringLiteral("scene")] = q(s.name);
        so[QStringLiteral("width")] = s.width;
        so[QStringLiteral("height")] = s.height;
        if (!s.error.empty()) so[QStringLiteral("error")] = q(s.error);
        QJsonArray stages;
        for (const StageResult& st : s.stages) stages.append(stageJson(st));
        so[QStringLiteral("stages")] = stages;
        scenes.append(so);
    }
    o[QStringLiteral("scenes")] = scenes;
    QJsonObject verdicts;
    for (Stage stage : kStages)
        verdicts[q(std::string(stageName(stage)))] =
            q(std::string(verdictName(r.stageVerdict(stage))));
    o[QStringLiteral("stageVerdicts")] = verdicts;
    o[QStringLiteral("passed")] = r.passed();
    o[QStringLiteral("restarts")] = r.restarts;
    o[QStringLiteral("cancelled")] = r.cancelled;
    o[QStringLiteral("seconds")] = r.seconds;
    return QJsonDocument(o).toJson(QJsonDocument::Indented).toStdString();
}

}  // namespace

std::string csvCell(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) {
        if (c == '"')
            out += "\"\"";
        else
            out += c == '\n' ? ' ' : c;
    }
    return out + "\"";
}

std::string markdownCell(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '|')
            out += "\\|";
        else
            out += c == '\n' ? ' ' : c;
    }
    return out;
}

std::string formatReport(const CheckReport& report, const std::string& format) {
    if (format == "json") return json(report);
    if (format == "md") return markdown(report);
    return text(report);
}

}  // namespace rasterlab::check
