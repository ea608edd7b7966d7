#include "app/check/stage_findings.h"

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <set>
#include <tuple>

#include "pipeline/core/format.h"

namespace rasterlab::check {

namespace {

constexpr std::size_t kExamples = 3;

// A set of mistakes in the order they were applied, and the elements that differ with them.
struct Hypothesis {
    std::vector<StageMistake> applied;
    ElementKeys differing;
    std::size_t spoiled = 0;  // by its last mistake
};

std::string keyOf(std::vector<StageMistake> applied) {
    std::sort(applied.begin(), applied.end(), [](const auto& a, const auto& b) {
        return std::tie(a.code, a.value) < std::tie(b.code, b.value);
    });
    std::string key;
    for (const StageMistake& m : applied) {
        char text[48];
        std::snprintf(text, sizeof text, "%d:%.17g;", m.code, m.value);
        key += text;
    }
    return key;
}

// The hypotheses one mistake more than `parent` makes, each making at least one element
// match net of those it spoils.
void grow(const std::vector<StageMistake>& catalogue, const Hypothesis& parent,
          const DifferingWith& differingWith, std::set<std::string>& seen,
          std::vector<Hypothesis>& out) {
    for (const StageMistake& m : catalogue) {
        const bool excluded = std::any_of(parent.applied.begin(), parent.applied.end(),
                                          [&](const auto& a) {
                                              return a.code == m.code || (a.groups & m.groups) != 0;
                                          });
        if (excluded) continue;
        std::vector<double> values = m.values;
        if (values.empty()) values.push_back(m.value);
        for (double v : values) {
            Hypothesis h{parent.applied, {}, 0};
            h.applied.push_back(m);
            h.applied.back().value = v;
            if (!seen.insert(keyOf(h.applied)).second) continue;
            auto differing = differingWith(h.applied);
            if (!differing) continue;
            h.spoiled = without(*differing, parent.differing).size();
            const std::size_t made = without(parent.differing, *differing).size();
            if (made <= h.spoiled) continue;
            h.differing = std::move(*differing);
            out.push_back(std::move(h));
        }
    }
}

// The search: a beam of the kStageBeam best hypotheses each round, as compare's, so that a
// mistake that imitates part of two others does not hide the pair; the hypothesis that leaves
// fewest elements differing wins, the one with fewer mistakes on a tie.
Hypothesis search(const std::vector<StageMistake>& catalogue, const ElementKeys& differing,
                  const DifferingWith& differingWith) {
    Hypothesis best{{}, differing, 0};
    std::vector<Hypothesis> beam{best};
    std::set<std::string> seen;
    for (std::size_t round = 0; round < kMostStageFindings && !beam.empty(); ++round) {
        std::vector<Hypothesis> next;
        for (const Hypothesis& parent : beam) grow(catalogue, parent, differingWith, seen, next);
        std::stable_sort(next.begin(), next.end(), [](const Hypothesis& a, const Hypothesis& b) {
            return std::pair(a.differing.size(), a.spoiled) <
                   std::pair(b.differing.size(), b.spoiled);
        });
        if (next.size() > kStageBeam) next.resize(kStageBeam);
        if (!next.empty() && next.front().differing.size() < best.differing.size())
            best = next.front();
        if (best.differing.empty()) break;
        beam = std::move(next);
    }
    return best;
}

}  // namespace

ElementKeys without(const ElementKeys& a, const ElementKeys& b) {
    ElementKeys out;
    std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
    return out;
}

std::string causeWithValue(const StageMistake& mistake) {
    std::string cause = mistake.cause;
    const std::size_t at = cause.find("%v");
    if (at != std::string::npos) cause.replace(at, 2, rl::formatNumber(mistake.value));
    return cause;
}

Explanation explainStage(const std::vector<StageMistake>& catalogue, const ElementKeys& differing,
                         const DifferingWith& differingWith,
                         const std::function<std::string(std::uint64_t)>& elementName) {
    const Hypothesis best = search(catalogue, differing, differingWith);
    // The findings in the order the winning hypothesis applied them, each given those above.
    Explanation out;
    out.unexplained = differing;
    const double first = double(differing.size());
    for (const StageMistake& m : best.applied) {
        out.applied.push_back(m);
        const ElementKeys now = differingWith(out.applied).value_or(out.unexplained);
        StageFinding f;
        f.id = m.id;
        f.cause = causeWithValue(m);
        const ElementKeys made = without(out.unexplained, now);
        f.explained = made.size();
        f.spoiled = without(now, out.unexplained).size();
        f.share = first > 0 ? (double(f.explained) - double(f.spoiled)) / first : 0.0;
        f.value = m.value;
        for (std::size_t i = 0; i < made.size() && i < kExamples; ++i)
            f.examples.push_back(elementName(made[i]));
        out.findings.push_back(std::move(f));
        out.unexplained = now;
    }
    return out;
}

}  // namespace rasterlab::check
