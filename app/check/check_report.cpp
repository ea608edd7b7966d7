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

std::string percent(double share) {
    return rl::formatFixed(100.0 * share, 1) + "%";
}

// A finding in one line: its cause, the elements it explains and its share.
std::string findingLine(const StageFinding& f) {
    std::string s = f.cause + " (explains " + std::to_string(f.explained) +
                    (f.spoiled ? ", spoils " + std::to_string(f.spoiled) : std::string()) + ", " +
                    percent(f.share) + " of the difference";
    if (!f.examples.empty()) s += "; e.g. " + f.examples.front();
    return s + ")";
}

std::vector<std::string> details(const StageResult& r) {
    std::vector<std::string> lines;
    if (r.first)
        lines.push_back("first: " + r.first->element + ": theirs " + r.first->theirs + ", ours " +
                        r.first->ours);
    if (r.first && !r.first->formula.empty()) lines.push_back(r.first->formula);
    for (const StageFinding& f : r.findings) lines.push_back("finding: " + findingLine(f));
    if (r.verdict == Verdict::Failed) {
        if (r.findings.empty())
            lines.push_back("no known mistake of this stage gives their answer");
        if (r.unexplained)
            lines.push_back("unexplained: " + std::to_string(r.unexplained) + " of the " +
                            std::to_string(r.differing) + " differing elements");
        else if (!r.findings.empty())
            lines.push_back("unexplained: nothing");
    }
    for (const std::string& d : r.description) lines.push_back("in numbers: " + d);
    if (r.carried)
        lines.push_back("carried from the earlier stages: " + std::to_string(*r.carried) +
                        " elements of the lecture's answer change with what was sent");
    for (const std::string& e : r.standardError) lines.push_back("stderr| " + e);
    if (!r.hint.empty()) lines.push_back("hint: " + r.hint);
    return lines;
}

std::string header(const CheckReport& r) {
    std::string s = "Check of `" + r.command + "` in " + r.folder;
    s += r.version ? " (stage protocol " + std::to_string(r.version) + ")" : "";
    if (r.chained) s += ", chained: each stage given the program's own earlier answers";
    return s;
}

// What "theirs" and "ours" are, said once at the top of every report.
std::string legend(const CheckReport& r) {
    return std::string("theirs: the program's answer; ours: the lecture's stage (RasterLab's) "
                       "applied to ") +
           (r.chained ? "exactly what the request sent (the program's own earlier answers)"
                      : "the same request (RasterLab's own inputs)");
}

// "basis 6 passed; scan 2 passed, 4 broken": each stage's verdicts over the scenes.
std::string stageCountsLine(const CheckReport& r, const char* separator) {
    std::string out;
    for (Stage stage : kStages) {
        const auto counts = r.stageCounts(stage);
        if (counts.empty()) continue;
        if (!out.empty()) out += separator;
        out += std::string(stageName(stage)) + " ";
        bool first = true;
        for (Verdict v : {Verdict::Passed, Verdict::Failed, Verdict::Broken, Verdict::Unsupported})
            if (const auto it = counts.find(v); it != counts.end()) {
                out += (first ? "" : ", ") + std::to_string(it->second) + " " +
                       std::string(verdictName(v));
                first = false;
            }
    }
    return out;
}

std::vector<std::string> failureLines(const CheckReport& r) {
    std::vector<std::string> lines;
    if (r.failure.empty()) return lines;
    lines.push_back(r.failure);
    for (const std::string& e : r.failureError) lines.push_back("stderr| " + e);
    if (!r.failureHint.empty()) lines.push_back("hint: " + r.failureHint);
    return lines;
}

std::string text(const CheckReport& r) {
    std::string out = header(r) + "\n" + legend(r) + "\n";
    for (const std::string& p : r.protections) out += "  limit: " + p + "\n";
    for (const std::string& p : r.missing) out += "  not applied: " + p + "\n";
    if (!r.failure.empty()) out += "\n";
    for (const std::string& line : failureLines(r)) out += line + "\n";
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
    out += "\nstages: " + stageCountsLine(r, "; ") + '\n';
    out += r.passed() ? "every stage passed" : "not every stage passed";
    if (r.restarts)
        out += "; the program was started again " + std::to_string(r.restarts) + " times";
    if (r.cancelled) out += "; cancelled";
    out += " (" + rl::formatNumber(r.seconds) + " s)\n";
    return out;
}

// The findings as a Markdown table: each one's share, then what stays unexplained.
std::string findingsTable(const StageResult& st) {
    std::string out = "\n| finding | explains | spoils | share |\n|---|---|---|---|\n";
    for (const StageFinding& f : st.findings)
        out += "| " + markdownCell(f.cause) + " | " + std::to_string(f.explained) + " | " +
               std::to_string(f.spoiled) + " | " + percent(f.share) + " |\n";
    const double left = st.differing ? double(st.unexplained) / double(st.differing) : 0.0;
    out += "| unexplained | " + std::to_string(st.unexplained) + " of " +
           std::to_string(st.differing) + " | | " + percent(left) + " |\n";
    out += "\nLargest error: " + rl::formatNumber(st.largestError) + " (tolerance " +
           st.tolerance + ").\n";
    return out;
}

std::string markdown(const CheckReport& r) {
    std::string out = "# " + header(r) + "\n\n" + legend(r) + ".\n\n";
    for (const std::string& p : r.protections) out += "- limit: " + p + "\n";
    for (const std::string& p : r.missing) out += "- not applied: " + p + "\n";
    if (!r.failure.empty()) {
        out += "\n**" + r.failure + "**\n";
        const std::vector<std::string> lines = failureLines(r);
        for (std::size_t i = 1; i < lines.size(); ++i) out += "\n    " + lines[i];
        out += "\n";
    }
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
    out += "\nPer stage: " + stageCountsLine(r, "; ") + ".\n";
    for (const SceneReport& s : r.scenes)
        for (const StageResult& st : s.stages) {
            // A stage that passed is said only when it has something to say (a rule its
            // values follow within the tolerance).
            if (st.verdict == Verdict::Passed && st.findings.empty() && st.description.empty())
                continue;
            out += "\n## " + s.name + ": " + std::string(stageName(st.stage)) + "\n\n" +
                   summary(st) + "\n";
            if (!st.findings.empty() || st.verdict == Verdict::Failed)
                out += findingsTable(st);
            for (const std::string& d : details(st))
                if (d.rfind("finding: ", 0) != 0 && d.rfind("unexplained: ", 0) != 0)
                    out += "\n    " + d;
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
    QJsonArray findings, description, standardError;
    for (const StageFinding& f : st.findings) {
        QJsonObject fo;
        fo[QStringLiteral("id")] = q(f.id);
        fo[QStringLiteral("cause")] = q(f.cause);
        fo[QStringLiteral("explained")] = qint64(f.explained);
        fo[QStringLiteral("spoiled")] = qint64(f.spoiled);
        fo[QStringLiteral("share")] = f.share;
        QJsonArray examples;
        for (const std::string& e : f.examples) examples.append(q(e));
        fo[QStringLiteral("examples")] = examples;
        findings.append(fo);
    }
    o[QStringLiteral("findings")] = findings;
    o[QStringLiteral("unexplained")] = qint64(st.unexplained);
    o[QStringLiteral("unexplainedShare")] =
        st.differing ? double(st.unexplained) / double(st.differing) : 0.0;
    for (const std::string& d : st.description) description.append(q(d));
    o[QStringLiteral("description")] = description;
    if (st.carried) o[QStringLiteral("carried")] = qint64(*st.carried);
    if (!st.problem.empty()) o[QStringLiteral("problem")] = q(st.problem);
    for (const std::string& e : st.standardError) standardError.append(q(e));
    if (!st.standardError.empty()) o[QStringLiteral("standardError")] = standardError;
    if (!st.hint.empty()) o[QStringLiteral("hint")] = q(st.hint);
    return o;
}

std::string json(const CheckReport& r) {
    QJsonObject o;
    o[QStringLiteral("command")] = q(r.command);
    o[QStringLiteral("folder")] = q(r.folder);
    o[QStringLiteral("protocolVersion")] = r.version;
    o[QStringLiteral("chained")] = r.chained;
    o[QStringLiteral("legend")] = q(legend(r));
    QJsonArray protections, missing, scenes;
    for (const std::string& p : r.protections) protections.append(q(p));
    for (const std::string& p : r.missing) missing.append(q(p));
    o[QStringLiteral("protections")] = protections;
    o[QStringLiteral("notApplied")] = missing;
    if (!r.failure.empty()) {
        o[QStringLiteral("failure")] = q(r.failure);
        QJsonArray lines;
        for (const std::string& e : r.failureError) lines.append(q(e));
        o[QStringLiteral("failureStandardError")] = lines;
        if (!r.failureHint.empty()) o[QStringLiteral("failureHint")] = q(r.failureHint);
    }
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
    QJsonObject verdicts, counts;
    for (Stage stage : kStages) {
        verdicts[q(std::string(stageName(stage)))] =
            q(std::string(verdictName(r.stageVerdict(stage))));
        QJsonObject c;
        for (const auto& [verdict, n] : r.stageCounts(stage))
            c[q(std::string(verdictName(verdict)))] = n;
        counts[q(std::string(stageName(stage)))] = c;
    }
    o[QStringLiteral("stageVerdicts")] = verdicts;
    o[QStringLiteral("stageCounts")] = counts;
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
