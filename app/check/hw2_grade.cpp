#include "app/check/hw2_grade.h"

#include <QString>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "app/check/student_program.h"
#include "app/compare/compare_image.h"
#include "app/documents/command_file.h"
#include "pipeline/render/renderer.h"

namespace rasterlab::check {

namespace {

// A path as one word for /bin/sh.
std::string shellWord(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string cell(const Hw2Verdict& v) {
    if (!v.problem.empty()) return "not compared";
    char text[48];
    std::snprintf(text, sizeof text, "%s (%.2f%% off)", v.passed ? "passed" : "failed",
                  v.pixels ? 100.0 * double(v.offByMore) / double(v.pixels) : 0.0);
    return text;
}

}  // namespace

rl::Result<Hw2Case> loadHw2Case(const std::string& path) {
    rl::Diagnostics diagnostics;
    auto file = loadCommandFile(QString::fromStdString(path), diagnostics);
    if (!file) return file.error();
    Hw2Case c;
    c.path = path;
    c.name = std::filesystem::path(path).filename().string();
    for (const rl::Hw2Image& image : file->images) {
        auto scene = std::make_shared<const rl::Scene>(image.scene);
        rl::RenderOptions options;
        options.keepForViews = false;
        auto trace = rl::renderFrame(scene, options);
        if (!trace) return trace.error();
        c.images.emplace_back(image.fileName,
                              rl::colourImage(*trace->shading, *trace->depth, scene->conventions));
    }
    return c;
}

std::vector<Hw2Verdict> gradeHw2(const Submission& submission, const std::vector<Hw2Case>& cases,
                                 const Limits& limits) {
    std::vector<Hw2Verdict> out;
    for (const Hw2Case& c : cases) {
        std::vector<Hw2Verdict> verdicts;
        for (const auto& image : c.images) {
            Hw2Verdict v;
            v.commandFile = c.name;
            v.image = image.first;
            verdicts.push_back(std::move(v));
        }
        const auto fail = [&](const std::string& problem) {
            for (Hw2Verdict& v : verdicts) v.problem = problem;
            out.insert(out.end(), verdicts.begin(), verdicts.end());
        };
        if (!submission.problem.empty()) {
            fail(submission.problem);
            continue;
        }
        // The command file goes beside the program, in the copy it runs in.
        StudentProgram program(submission.command + " " + shellWord(c.name), submission.folder,
                               limits, true);
        const std::string work = program.temporaryFolder() + "/work";
        std::error_code ec;
        std::filesystem::copy_file(c.path, work + "/" + c.name,
                                   std::filesystem::copy_options::overwrite_existing, ec);
        if (!program.waitForExit()) {
            fail("the program broke on " + c.name + ": " + program.error());
            continue;
        }
        for (std::size_t i = 0; i < verdicts.size(); ++i) {
            Hw2Verdict& v = verdicts[i];
            const rl::Rgba8Image& ours = c.images[i].second;
            rl::Rgba8Image theirs;
            const QString path = QString::fromStdString(work + "/" + v.image);
            if (const QString problem = CompareImage::read(path, theirs); !problem.isEmpty()) {
                v.problem = "their " + v.image + ": " + problem.toStdString();
                continue;
            }
            if (theirs.width != ours.width || theirs.height != ours.height) {
                v.problem = "their " + v.image + " is " + std::to_string(theirs.width) + "x" +
                            std::to_string(theirs.height) + ", ours " + std::to_string(ours.width) +
                            "x" + std::to_string(ours.height);
                continue;
            }
            v.pixels = std::size_t(ours.width) * std::size_t(ours.height);
            for (std::size_t p = 0; p < v.pixels; ++p) {
                int worst = 0;
                for (int k = 0; k < 3; ++k)
                    worst = std::max(
                        worst, std::abs(int(ours.rgba[4 * p + k]) - int(theirs.rgba[4 * p + k])));
                v.largest = std::max(v.largest, worst);
                if (worst > 1) ++v.offByMore;
            }
            v.passed = double(v.offByMore) <= kHw2Share * double(v.pixels);
        }
        out.insert(out.end(), verdicts.begin(), verdicts.end());
    }
    return out;
}

std::string hw2Table(const std::vector<Submission>& submissions,
                     const std::vector<std::vector<Hw2Verdict>>& verdicts,
                     const std::string& format) {
    const bool csv = format == "csv";
    const char* separator = csv ? "," : " | ";
    std::string out = csv ? "submission" : "| submission";
    std::string rule = "|---|";
    if (!verdicts.empty())
        for (const Hw2Verdict& v : verdicts.front()) {
            out += separator;
            out += v.image;
            rule += "---|";
        }
    out += csv ? ",passed,note\n" : " | passed | note |\n";
    if (!csv) out += rule + "---|---|\n";
    for (std::size_t s = 0; s < submissions.size(); ++s) {
        bool all = true;
        std::string note;
        if (!csv) out += "| ";
        out += csv ? csvCell(submissions[s].name) : markdownCell(submissions[s].name);
        for (const Hw2Verdict& v : verdicts[s]) {
            out += separator;
            out += cell(v);
            all = all && v.passed;
            if (note.empty()) note = v.problem;
        }
        out += separator;
        out += all ? "yes" : "no";
        out += separator;
        out += csv ? csvCell(note) : markdownCell(note);
        out += csv ? "\n" : " |\n";
    }
    return out;
}

}  // namespace rasterlab::check
