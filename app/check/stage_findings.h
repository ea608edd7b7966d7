// The mistakes that together explain a stage's answer, found as compare finds an image's: the
// known mistake that makes most of their differing elements match is applied first, the rest
// ranked again on what remains, and what no mistake explains is counted. Each stage's catalogue
// (stage_mistakes.h) says how its answer is made with any set of its mistakes at once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rasterlab::check {

// A mistake of a stage's catalogue. Mistakes that share a bit of `groups` exclude each other
// (two ways of rounding, two starts of a span). A mistake with `values` has a number fitted to
// their answer (an epsilon, an area): each value is tried, the best kept.
struct StageMistake {
    int code = 0;  // the catalogue's own
    std::string id;     // "light-in-world"
    std::string cause;  // words; "%v" stands for the fitted value
    unsigned groups = 0;
    std::vector<double> values;
    double value = 0.0;  // the one tried or fitted
};

// One mistake as found: applied after those above it, the elements it makes match and those
// it spoils, and its share of the elements that differed at first.
struct StageFinding {
    std::string id;
    std::string cause;  // with the fitted value written in
    std::size_t explained = 0;
    std::size_t spoiled = 0;
    double share = 0.0;  // (explained - spoiled) / the elements that differed at first
    std::vector<std::string> examples;  // the first few elements it explains
    double value = 0.0;                 // the fitted value, for a mistake that has one
};

// The differing elements of an answer, each a key the stage makes (an index, a pixel), sorted.
using ElementKeys = std::vector<std::uint64_t>;

// The keys of a that are not in b (both sorted).
ElementKeys without(const ElementKeys& a, const ElementKeys& b);

struct Explanation {
    std::vector<StageFinding> findings;
    std::vector<StageMistake> applied;  // the same, as the catalogue's mistakes
    ElementKeys unexplained;            // still differing with every finding applied
};

// How a stage's answer made with some mistakes differs from theirs: the differing elements,
// or none when these mistakes cannot go together in this scene.
using DifferingWith = std::function<std::optional<ElementKeys>(const std::vector<StageMistake>&)>;

// At most this many mistakes are composed, and this many hypotheses kept at each step.
inline constexpr std::size_t kMostStageFindings = 6;
inline constexpr std::size_t kStageBeam = 3;

// The search: `differing` the elements that differ from the lecture's answer, the catalogue's
// mistakes tried one more at a time, each making at least one element match net of those it
// spoils; the kStageBeam hypotheses that leave fewest elements differing are kept each round,
// the catalogue's order breaking ties, and the best of all is said as findings in the order
// it applied them.
Explanation explainStage(const std::vector<StageMistake>& catalogue, const ElementKeys& differing,
                         const DifferingWith& differingWith,
                         const std::function<std::string(std::uint64_t)>& elementName);

// The cause's words with its fitted value written in.
std::string causeWithValue(const StageMistake& mistake);

}  // namespace rasterlab::check
