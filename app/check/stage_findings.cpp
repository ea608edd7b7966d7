#include "app/check/stage_findings.h"

#include <algorithm>
#include <iterator>

#include "pipeline/core/format.h"

namespace rasterlab::check {

namespace {

constexpr std::size_t kExamples = 3;

ElementKeys without(const ElementKeys& a, const ElementKeys& b) {
    ElementKeys out;
    std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
    return out;
}

struct Trial {
    StageMistake mistake;
    ElementKeys differing;
    long long net = 0;  // elements made to match, less those spoiled
    std::size_t spoiled = 0;
};

// The best next mistake given those applied, or none when no mistake makes an element match
// net of those it spoils.
std::optional<Trial> bestNext(const std::vector<StageMistake>& catalogue,
                              const std::vector<StageMistake>& applied, const ElementKeys& now,
                              const DifferingWith& differingWith) {
    std::optional<Trial> best;
    for (const StageMistake& m : catalogue) {
        const bool excluded = std::any_of(applied.begin(), applied.end(), [&](const auto& a) {
            return a.code == m.code || (a.groups & m.groups) != 0;
        });
        if (excluded) continue;
        std::vector<double> values = m.values;
        if (values.empty()) values.push_back(m.value);
        for (double v : values) {
            std::vector<StageMistake> trial = applied;
            trial.push_back(m);
            trial.back().value = v;
            const auto differing = differingWith(trial);
            if (!differing) continue;
            const std::size_t spoiled = without(*differing, now).size();
            const long long net =
                (long long)without(now, *differing).size() - (long long)spoiled;
            if (net <= 0) continue;
            if (!best || net > best->net || (net == best->net && spoiled < best->spoiled))
                best = Trial{trial.back(), *differing, net, spoiled};
        }
    }
    return best;
}

}  // namespace

std::string causeWithValue(const StageMistake& mistake) {
    std::string cause = mistake.cause;
    const std::size_t at = cause.find("%v");
    if (at != std::string::npos) cause.replace(at, 2, rl::formatNumber(mistake.value));
    return cause;
}

Explanation explainStage(const std::vector<StageMistake>& catalogue, const ElementKeys& differing,
                         const DifferingWith& differingWith,
                         const std::function<std::string(std::uint64_t)>& elementName) {
    Explanation out;
    out.unexplained = differing;
    const double first = double(differing.size());
    while (!out.unexplained.empty() && out.applied.size() < kMostStageFindings) {
        const auto next = bestNext(catalogue, out.applied, out.unexplained, differingWith);
        if (!next) break;
        StageFinding f;
        f.id = next->mistake.id;
        f.cause = causeWithValue(next->mistake);
        const ElementKeys made = without(out.unexplained, next->differing);
        f.explained = made.size();
        f.spoiled = next->spoiled;
        f.share = first > 0 ? double(next->net) / first : 0.0;
        f.value = next->mistake.value;
        for (std::size_t i = 0; i < made.size() && i < kExamples; ++i)
            f.examples.push_back(elementName(made[i]));
        out.findings.push_back(std::move(f));
        out.applied.push_back(next->mistake);
        out.unexplained = next->differing;
    }
    return out;
}

}  // namespace rasterlab::check
