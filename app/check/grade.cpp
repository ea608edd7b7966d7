#include "app/check/grade.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

namespace rasterlab::check {

namespace {

namespace fs = std::filesystem;

constexpr std::uintmax_t kLargestRunFile = 4096;

// The `run` file's command: its first line that is not empty, or why there is none.
std::string readRun(const fs::path& folder, std::string& problem) {
    const fs::path run = folder / "run";
    std::error_code ec;
    if (!fs::is_regular_file(run, ec)) {
        problem = "no 'run' file";
        return {};
    }
    if (fs::file_size(run, ec) > kLargestRunFile) {
        problem = "the 'run' file is longer than " + std::to_string(kLargestRunFile) + " bytes";
        return {};
    }
    std::ifstream in(run);
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find_first_not_of(" \t") != std::string::npos) return line;
    }
    problem = "the 'run' file is empty";
    return {};
}

// The row's last column: what went wrong for the whole submission, or how it went.
std::string note(const GradeRow& row) {
    if (!row.submission.problem.empty()) return row.submission.problem;
    const CheckReport& r = row.report;
    if (!r.failure.empty()) return r.failure;
    std::string s = r.passed() ? "every stage passed" : "";
    if (r.restarts)
        s += (s.empty() ? "" : "; ") + std::string("started again ") + std::to_string(r.restarts) +
             " times";
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.1f s", r.seconds);
    return s + (s.empty() ? "" : "; ") + seconds;
}

}  // namespace

rl::Result<std::vector<Submission>> findSubmissions(const std::string& dir) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        return rl::makeError(rl::ErrorCode::Io, {dir, 0, 0}, "not a folder of submissions");
    std::vector<Submission> out;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        if (!entry.is_directory(ec)) continue;
        Submission s;
        s.name = entry.path().filename().string();
        if (s.name.empty() || s.name.front() == '.') continue;
        s.folder = fs::absolute(entry.path(), ec).string();
        s.command = readRun(entry.path(), s.problem);
        out.push_back(std::move(s));
    }
    std::sort(out.begin(), out.end(),
              [](const Submission& a, const Submission& b) { return a.name < b.name; });
    return out;
}

void forEachInParallel(std::size_t count, int jobs, const std::function<void(std::size_t)>& work,
                       const std::function<void(std::size_t, int)>& done) {
    std::atomic<std::size_t> next{0};
    std::atomic<int> finished{0};
    std::mutex doneLock;
    const auto run = [&] {
        for (std::size_t i = next++; i < count; i = next++) {
            work(i);
            const int n = ++finished;
            if (done) {
                const std::lock_guard<std::mutex> lock(doneLock);
                done(i, n);
            }
        }
    };
    std::vector<std::thread> threads;
    for (int t = 1; t < std::max(1, jobs); ++t) threads.emplace_back(run);
    run();
    for (std::thread& t : threads) t.join();
}

std::vector<GradeRow> gradeSubmissions(
    const std::vector<Submission>& submissions, const std::vector<CheckScene>& scenes,
    const CheckOptions& options, int jobs,
    const std::function<void(int, int, const std::string&)>& progress) {
    std::vector<GradeRow> rows(submissions.size());
    forEachInParallel(
        submissions.size(), jobs,
        [&](std::size_t i) {
            rows[i].submission = submissions[i];
            if (submissions[i].problem.empty())
                rows[i].report =
                    runCheck(submissions[i].command, submissions[i].folder, scenes, options);
        },
        [&](std::size_t i, int finished) {
            if (progress) progress(finished, int(submissions.size()), submissions[i].name);
        });
    return rows;
}

std::string gradeTable(const std::vector<GradeRow>& rows, const std::string& format) {
    const bool csv = format == "csv";
    std::string out = csv ? "submission" : "| submission |";
    std::string rule = "|---|";
    for (Stage stage : kStages) {
        out += csv ? "," : " ";
        out += stageName(stage);
        out += csv ? "" : " |";
        rule += "---|";
    }
    out += csv ? ",passed,note\n" : " passed | note |\n" + rule + "---|---|\n";
    for (const GradeRow& row : rows) {
        const CheckReport& r = row.report;
        const bool ran = row.submission.problem.empty() && r.failure.empty();
        out += csv ? csvCell(row.submission.name) : "| " + markdownCell(row.submission.name) + " |";
        for (Stage stage : kStages) {
            std::string cell = ran ? std::string(verdictName(r.stageVerdict(stage))) : "not run";
            bool asked = false;
            for (const SceneReport& s : r.scenes)
                for (const StageResult& st : s.stages) asked = asked || st.stage == stage;
            if (ran && !asked) cell = "not asked";
            out += csv ? "," + cell : " " + cell + " |";
        }
        const std::string passed = ran && r.passed() ? "yes" : "no";
        out += csv ? "," + passed + "," + csvCell(note(row)) + "\n"
                   : " " + passed + " | " + markdownCell(note(row)) + " |\n";
    }
    return out;
}

}  // namespace rasterlab::check
