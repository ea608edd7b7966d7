#include "app/check/stage_description.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "pipeline/core/format.h"

namespace rasterlab::check {

using rl::dvec3;
using rl::formatNumber;

namespace {

std::string plural(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

// "on 12 rows 1 pixel right, on 3 rows 1 pixel left": the most common non-zero offsets of a
// histogram, largest first; `unit` and `units` name what is counted.
std::string offsets(const std::map<long long, std::size_t>& histogram, const char* unit,
                    const char* units) {
    std::vector<std::pair<std::size_t, long long>> order;
    for (const auto& [offset, count] : histogram)
        if (offset != 0) order.push_back({count, offset});
    std::sort(order.rbegin(), order.rend());
    std::string out;
    for (std::size_t i = 0; i < order.size() && i < 3; ++i) {
        const long long k = order[i].second;
        if (i) out += ", ";
        out += "on " + plural(order[i].first, unit, units) + " " +
               std::to_string(std::abs(k)) + (std::abs(k) == 1 ? " pixel " : " pixels ") +
               (k < 0 ? "left" : "right");
    }
    return out;
}

double pearson(const std::vector<double>& a, const std::vector<double>& b) {
    const std::size_t n = a.size();
    if (n < 3) return 0.0;
    double ma = 0, mb = 0;
    for (std::size_t i = 0; i < n; ++i) ma += a[i], mb += b[i];
    ma /= double(n);
    mb /= double(n);
    double sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < n; ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

}  // namespace

std::vector<std::string> describeVectors(const std::vector<Row>& theirs,
                                         const std::vector<Row>& best, const ElementKeys& left,
                                         const std::vector<std::string>& names) {
    std::vector<std::string> out;
    if (left.empty()) return out;
    std::vector<std::string> named;
    for (std::uint64_t k : left)
        if (k < names.size()) named.push_back(names[k]);
    dvec3 first(0.0);
    bool constant = true, sameDirection = true, opposite = true;
    double shortest = 1e300, longest = 0.0, leastAngle = 180.0, mostAngle = 0.0;
    for (std::size_t i = 0; i < left.size(); ++i) {
        const dvec3 a = vecOf(theirs[left[i]]), b = vecOf(best[left[i]]);
        const dvec3 d = a - b;
        if (i == 0) first = d;
        constant = constant && glm::length(d - first) <= 1e-6 * std::max(1.0, glm::length(b));
        const double la = glm::length(a), lb = glm::length(b);
        if (la == 0.0 || lb == 0.0) {
            sameDirection = opposite = false;
            continue;
        }
        const double cosine = std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0);
        sameDirection = sameDirection && cosine > 1.0 - 1e-9;
        opposite = opposite && cosine < -1.0 + 1e-9;
        shortest = std::min(shortest, la / lb);
        longest = std::max(longest, la / lb);
        const double angle = std::acos(cosine) * 180.0 / 3.141592653589793;
        leastAngle = std::min(leastAngle, angle);
        mostAngle = std::max(mostAngle, angle);
    }
    const std::string where = plural(left.size(), "element", "elements") + " left" +
                              (named.empty() ? std::string() : " (among them " + named[0] + ")");
    if (constant)
        out.push_back(where + ": theirs are ours plus " + rl::formatVector(first) +
                      ", a constant offset");
    else if (sameDirection)
        out.push_back(where + ": theirs point as ours do, " + formatNumber(shortest) + " to " +
                      formatNumber(longest) + " times as long");
    else if (opposite)
        out.push_back(where + ": theirs point the other way, " + formatNumber(shortest) + " to " +
                      formatNumber(longest) + " times as long");
    else
        out.push_back(where + ": theirs are turned " + formatNumber(leastAngle) + " to " +
                      formatNumber(mostAngle) + " degrees from ours, " + formatNumber(shortest) +
                      " to " + formatNumber(longest) + " times as long");
    return out;
}

std::vector<std::string> describeScreen(const std::vector<Row>& theirs,
                                        const std::vector<Row>& best, const ElementKeys& left) {
    std::vector<std::string> out;
    std::size_t fractional = 0;
    std::map<long long, std::size_t> dx, dy;
    double sumX = 0, sumY = 0;
    for (std::uint64_t k : left) {
        const Row &a = theirs[k], &b = best[k];
        if (a[0] != std::floor(a[0]) || a[1] != std::floor(a[1])) ++fractional;
        ++dx[std::llround(a[0] - b[0])];
        ++dy[std::llround(a[1] - b[1])];
        sumX += a[0] - b[0];
        sumY += a[1] - b[1];
    }
    const std::size_t n = left.size();
    if (fractional)
        out.push_back("their coordinates are fractional on " +
                      plural(fractional, "vertex", "vertices") + " of the " +
                      std::to_string(n) + " left: not made whole");
    else
        out.push_back("their coordinates are whole on all " + plural(n, "vertex", "vertices") +
                      " left");
    const std::string x = offsets(dx, "vertex", "vertices"), y = offsets(dy, "vertex", "vertices");
    if (!x.empty()) out.push_back("x: " + x);
    if (!y.empty()) {
        std::string line = "y: " + y;
        for (const char* a : {" left", " right"}) {
            for (std::size_t at; (at = line.find(a)) != std::string::npos;)
                line.replace(at, std::string(a).size(), a[1] == 'l' ? " up" : " down");
        }
        out.push_back(line);
    }
    if (dx.size() == 1 && dy.size() == 1)
        out.push_back("a constant offset of (" + formatNumber(sumX / double(n)) + ", " +
                      formatNumber(sumY / double(n)) + ") pixels");
    return out;
}

std::vector<std::string> describeColours(const std::vector<Row>& theirs,
                                         const std::vector<Row>& best, const ElementKeys& left,
                                         const Lighting& lighting,
                                         const std::vector<Sample>& samples) {
    std::vector<std::string> out;
    if (left.empty()) return out;
    dvec3 sum(0.0), low(1e300), high(-1e300);
    std::vector<double> bias, nl, rv;
    std::size_t behind = 0, away = 0;
    for (std::uint64_t k : left) {
        const dvec3 d = vecOf(theirs[k]) - vecOf(best[k]);
        sum += d;
        low = glm::min(low, d);
        high = glm::max(high, d);
        const PhongTerms t = phongTerms(lighting, samples[k]);
        bias.push_back(d.x + d.y + d.z);
        nl.push_back(t.nDotL);
        rv.push_back(t.rDotV);
        behind += t.nDotL < 0.0 ? 1 : 0;
        away += t.nDotL >= 0.0 && t.rDotV < 0.0 ? 1 : 0;
    }
    const double n = double(left.size());
    out.push_back(plural(left.size(), "sample", "samples") + " left: theirs minus ours is " +
                  rl::formatVector(sum / n) + " on average per channel (r g b), from " +
                  rl::formatVector(low) + " to " + rl::formatVector(high));
    const double withNl = pearson(bias, nl), withRv = pearson(bias, rv);
    if (std::abs(withNl) >= 0.9 && std::abs(withNl) >= std::abs(withRv))
        out.push_back("the difference follows N.L (correlation " + formatNumber(withNl) + ")");
    else if (std::abs(withRv) >= 0.9)
        out.push_back("the difference follows R.V (correlation " + formatNumber(withRv) + ")");
    else
        out.push_back("the difference follows neither N.L (correlation " + formatNumber(withNl) +
                      ") nor R.V (" + formatNumber(withRv) + ")");
    if (behind || away)
        out.push_back("of them " + plural(behind, "sample has", "samples have") +
                      " N.L < 0 and " + plural(away, "has", "have") + " R.V < 0");
    return out;
}

std::vector<std::string> describeSpans(const std::vector<Row>& theirs,
                                       const std::vector<Row>& best) {
    using Key = std::pair<double, double>;  // triangle, row
    const auto ends = [](const std::vector<Row>& spans) {
        std::map<Key, std::pair<double, double>> out;
        for (const Row& s : spans) {
            auto [it, fresh] = out.try_emplace({s[0], s[1]}, s[2], s[3]);
            if (!fresh) {
                it->second.first = std::min(it->second.first, s[2]);
                it->second.second = std::max(it->second.second, s[3]);
            }
        }
        return out;
    };
    const auto a = ends(theirs), b = ends(best);
    std::map<long long, std::size_t> starts, finishes;
    std::size_t onlyTheirs = 0, onlyOurs = 0;
    for (const auto& [key, span] : a) {
        const auto it = b.find(key);
        if (it == b.end()) {
            ++onlyTheirs;
            continue;
        }
        ++starts[std::llround(span.first - it->second.first)];
        ++finishes[std::llround(span.second - it->second.second)];
    }
    for (const auto& [key, span] : b) onlyOurs += a.count(key) ? 0 : 1;
    std::vector<std::string> out;
    const std::string s = offsets(starts, "row", "rows"), f = offsets(finishes, "row", "rows");
    if (!s.empty()) out.push_back("their spans start " + s + " of ours");
    if (!f.empty()) out.push_back("their spans end " + f + " of ours");
    if (onlyTheirs)
        out.push_back(plural(onlyTheirs, "row", "rows") + " of a triangle only they cover");
    if (onlyOurs) out.push_back(plural(onlyOurs, "row", "rows") + " of a triangle only we cover");
    return out;
}

std::vector<double> epsilonsOf(const Lighting& lighting, const std::vector<Sample>& samples) {
    std::set<double> dots;
    for (const Sample& s : samples) {
        const PhongTerms t = phongTerms(lighting, s);
        for (double d : {t.vDotN, t.nDotL, t.rDotV})
            if (d > 0.0 && d < 0.1) dots.insert(d);
    }
    std::vector<double> out;
    std::set<std::size_t> gaps;  // how many dots each epsilon is above
    for (int e = -6; e <= -1; ++e)
        for (double m : {1.0, 2.0, 5.0}) {
            const double eps = m * std::pow(10.0, e);
            const auto below = std::size_t(std::distance(dots.begin(), dots.lower_bound(eps)));
            if (below > 0 && gaps.insert(below).second) out.push_back(eps);
        }
    return out;
}

}  // namespace rasterlab::check
