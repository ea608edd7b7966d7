// `rasterlab-cli check` and Check My Renderer...: a student's program asked for every stage
// of each scene over the stage protocol, each answer judged (stage_check.h), and the report
// as text, Markdown or JSON. The program runs under the limits of student_program.h; when it
// breaks in a stage (a bad answer, a timeout, a crash) that stage says so, with what was read
// last and the end of its standard error, and the program is started again for the next one:
// a crash costs one stage of one scene.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "app/check/stage_check.h"
#include "app/check/stage_mistakes.h"
#include "app/check/student_program.h"

namespace rasterlab::check {

struct CheckScene {
    std::string name;  // "triangle", "calice2.byu"
    std::shared_ptr<const rl::Scene> scene;
};

struct SceneReport {
    std::string name;
    int width = 0, height = 0;
    std::string error;  // the protocol cannot carry this scene: why (no stages then)
    std::vector<StageResult> stages;
    rl::Rgba8Image theirFrame;    // the frame stage's answer, when it gave one that reads
    std::vector<Row> theirSpans;  // the scan stage's answer (t y first last), likewise
};

struct CheckReport {
    std::string command;
    std::string folder;
    int version = 0;  // the version the program speaks (0: it never said)
    std::vector<std::string> protections, missing;
    std::vector<SceneReport> scenes;
    bool chained = false;
    std::string failure;  // why the program could not be checked at all, or empty
    std::vector<std::string> failureError;  // then, the last lines of its standard error
    std::string failureHint;                // and a runtime's memory message explained
    bool cancelled = false;
    double seconds = 0.0;
    int restarts = 0;

    // Every stage of every scene passed (or unsupported: then not passed).
    bool passed() const;
    // The worst verdict of a stage over the scenes (Passed when it never ran).
    Verdict stageVerdict(Stage stage) const;
    // How many scenes gave a stage each verdict.
    std::map<Verdict, int> stageCounts(Stage stage) const;
    bool anyBroken() const;
    // A stage's result in the first scene checked (the window checks one), or null.
    const StageResult* result(Stage stage) const;
};

// Progress: the number of requests answered, of all, and what is being asked; false cancels.
using CheckProgress = std::function<bool(int done, int total, const std::string& what)>;

struct CheckOptions {
    std::vector<Stage> stages{kStages.begin(), kStages.end()};
    // Chained: each stage is given the program's own earlier answers as its input (where it
    // gave them), to show how errors add up; otherwise RasterLab's, so none hides another.
    bool chain = false;
    Limits limits;
};

CheckReport runCheck(const std::string& command, const std::string& folder,
                     const std::vector<CheckScene>& scenes, const CheckOptions& options,
                     const CheckProgress& progress = {});

// The default scenes: the shipped lessons the protocol carries (not near-plane, whose vertices
// lie behind the camera, nor lights and gouraud, lit by more than one light), and the default
// scene, each at 160x120 so that a student's check takes seconds.
std::vector<CheckScene> defaultCheckScenes();

// A table's cell: quoted as CSV needs it, or with Markdown's '|' escaped; a line end a space.
std::string csvCell(const std::string& s);
std::string markdownCell(const std::string& s);

// The report, as the command line prints it (format "text", "md" or "json").
std::string formatReport(const CheckReport& report, const std::string& format);

}  // namespace rasterlab::check
