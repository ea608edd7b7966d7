// HW2 submissions (seed 001's command files): each submission's program run on each command
// file, under the same limits as check, in a copy of its folder, with the command file's name
// after its command; every image the file's `png` commands name is read from where the
// program wrote it and held to ours: it passes with at most 0.5 % of its pixels more than one
// step off in some channel (the measure of the instructor's reference images).
#pragma once

#include <string>
#include <vector>

#include "app/check/grade.h"
#include "pipeline/render/output_image.h"

namespace rasterlab::check {

// A command file and our images of it.
struct Hw2Case {
    std::string name;  // the command file's name
    std::string path;
    std::vector<std::pair<std::string, rl::Rgba8Image>> images;  // png name, ours
};
rl::Result<Hw2Case> loadHw2Case(const std::string& path);

struct Hw2Verdict {
    std::string commandFile, image;  // the command file's name, the png it names
    bool passed = false;
    std::size_t pixels = 0, offByMore = 0;  // more than one step off in some channel
    int largest = 0;
    std::string problem;  // why there is no image to compare (the program broke, no file ...)
};
inline constexpr double kHw2Share = 0.005;  // at most this share of pixels off by more than 1

// The submission's program run on every case, one run a command file.
std::vector<Hw2Verdict> gradeHw2(const Submission& submission, const std::vector<Hw2Case>& cases,
                                 const Limits& limits);

// The table of submissions x images ("md" or "csv").
std::string hw2Table(const std::vector<Submission>& submissions,
                     const std::vector<std::vector<Hw2Verdict>>& verdicts,
                     const std::string& format);

}  // namespace rasterlab::check
