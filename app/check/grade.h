// `rasterlab-cli grade`: every submission of a class through the check. A submission is a
// folder holding a one-line `run` file, the command that starts its program in that folder.
// Submissions are checked two at a time (one per core), each under its own limits, so one
// that hangs or floods costs its time limit and nothing more; the result is a table of
// submissions x stages and each submission's own report.
#pragma once

#include <string>
#include <vector>

#include "app/check/check_session.h"

namespace rasterlab::check {

struct Submission {
    std::string name;     // the folder's name
    std::string folder;   // its absolute path
    std::string command;  // the `run` file's line
    std::string problem;  // why it cannot be run (no `run` file, an empty one ...), or empty
};

// The submissions in `dir`: its subfolders, by name. An error when dir is not a folder.
rl::Result<std::vector<Submission>> findSubmissions(const std::string& dir);

struct GradeRow {
    Submission submission;
    CheckReport report;
};

// Runs work(i) for i = 0 .. count - 1, `jobs` at a time (the calling thread one of them);
// done(finished) after each, one at a time.
void forEachInParallel(std::size_t count, int jobs, const std::function<void(std::size_t)>& work,
                       const std::function<void(std::size_t, int)>& done = {});

// Checks every submission over the scenes, `jobs` at a time; progress hears of each
// submission as it ends (how many have, of all, and its name).
std::vector<GradeRow> gradeSubmissions(
    const std::vector<Submission>& submissions, const std::vector<CheckScene>& scenes,
    const CheckOptions& options, int jobs,
    const std::function<void(int, int, const std::string&)>& progress = {});

// The table of submissions x stages: "csv" or "md". A cell is the stage's worst verdict over
// the scenes; a submission that could not run says why in its last column.
std::string gradeTable(const std::vector<GradeRow>& rows, const std::string& format);

}  // namespace rasterlab::check
