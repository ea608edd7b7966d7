// The judges of the stages whose answers are pixels (scan, z-buffer, frame): the pixels each
// side covers, keeps or colours, held to the lecture's answer to what was sent, the mistakes
// that explain the pixels that differ, and the frame handed to compare's diagnosis, starting
// from what the stages before it found.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <set>
#include <tuple>

#include "app/check/stage_check_data.h"
#include "app/check/stage_description.h"
#include "app/check/stage_frame.h"
#include "pipeline/core/format.h"

namespace rasterlab::check {

using rl::formatNumber;

namespace {

using Pixel = std::tuple<std::uint32_t, std::int32_t, std::int32_t>;  // triangle, y, x

std::uint64_t keyOf(const Pixel& p) {
    const auto& [t, y, x] = p;
    return (std::uint64_t(t) << 42) | (std::uint64_t(y + (1 << 20)) << 21) |
           std::uint64_t(x + (1 << 20));
}

Pixel pixelOf(std::uint64_t key) {
    return {std::uint32_t(key >> 42), std::int32_t((key >> 21) & 0x1fffff) - (1 << 20),
            std::int32_t(key & 0x1fffff) - (1 << 20)};
}

std::string rowText(const Row& r) {
    std::string s;
    for (std::size_t i = 0; i < r.size(); ++i) {
        if (i) s += ' ';
        s += protocolNumber(r[i]);
    }
    return s;
}

// The pixels of spans t y first last, as sorted keys; an error names the first span that is
// not one, or says that they list more pixels than `most`.
std::optional<std::string> pixelsOf(const std::vector<Row>& spans, std::size_t triangles, int width,
                                    std::size_t most, ElementKeys& pixels) {
    for (std::size_t k = 0; k < spans.size(); ++k) {
        const Row& s = spans[k];
        if (!whole(s[0], 0, double(triangles) - 1) || !whole(s[1], -kFarthest, kFarthest) ||
            !whole(s[2], -kFarthest, kFarthest) || !whole(s[3], -kFarthest, kFarthest))
            return "span " + std::to_string(k) + " (" + rowText(s) +
                   ") is not 't y first last' with whole numbers within 1000000 pixels of the "
                   "screen and t one of the " +
                   std::to_string(triangles) + " triangles";
        if (s[3] - s[2] >= double(width))
            return "span " + std::to_string(k) + " (" + rowText(s) + ") is wider than the screen";
        if (pixels.size() + std::size_t(std::max(0.0, s[3] - s[2] + 1)) > most)
            return "their spans list more than " + std::to_string(most) +
                   " pixels, 64 times the screen";
        for (double x = s[2]; x <= s[3]; ++x)
            pixels.push_back(keyOf({std::uint32_t(s[0]), std::int32_t(s[1]), std::int32_t(x)}));
    }
    std::sort(pixels.begin(), pixels.end());
    const auto twice = std::adjacent_find(pixels.begin(), pixels.end());
    if (twice != pixels.end()) {
        const auto [t, y, x] = pixelOf(*twice);
        return "their spans list pixel (" + std::to_string(x) + ", " + std::to_string(y) +
               ") of triangle " + std::to_string(t) + " a second time";
    }
    return std::nullopt;
}

ElementKeys symmetricDifference(const ElementKeys& a, const ElementKeys& b) {
    ElementKeys out;
    std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
    return out;
}

// The pixels of spans the lecture or a mistake of its catalogue makes: whole, on the screen,
// each once.
ElementKeys spanPixels(const std::vector<Row>& spans) {
    ElementKeys out;
    for (const Row& s : spans)
        for (double x = s[2]; x <= s[3]; ++x)
            out.push_back(keyOf({std::uint32_t(s[0]), std::int32_t(s[1]), std::int32_t(x)}));
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::vector<Row> lectureSpans(const rl::ScanConversion& scan) {
    std::vector<Row> rows;
    for (std::uint32_t t = 0; t < scan.triangleCount(); ++t)
        for (std::uint32_t s = scan.spanStart[t]; s < scan.spanStart[t + 1]; ++s)
            rows.push_back({double(t), double(scan.spans[s].y), double(scan.spans[s].xBegin),
                            double(scan.spans[s].xEnd - 1)});
    return rows;
}

std::string pixelName(std::uint64_t key) {
    const auto [t, y, x] = pixelOf(key);
    return "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") of triangle " +
           std::to_string(t);
}

}  // namespace

StageResult StageCheck::judgeScan(const std::vector<Record>& answer, const Inputs& in) const {
    const Data& d = *m_data;
    const int w = d.scene->width, h = d.scene->height;
    const std::vector<Row> triangles = d.screenTriangles(in.screen);
    ElementKeys theirs;
    StageResult result;
    result.stage = Stage::Scan;
    if (auto bad = pixelsOf(answer[0].rows, triangles.size(), w,
                            64 * std::size_t(w) * std::size_t(h), theirs)) {
        result.verdict = Verdict::Broken;
        result.problem = *bad;
        return result;
    }
    const std::vector<Row> lecture = lectureSpans(d.scan);
    const std::vector<Row> oursRows = in.chained ? scanAnswer(triangles, w, h, {}) : lecture;
    const ElementKeys ours = spanPixels(oursRows);
    if (in.chained) result.carried = symmetricDifference(ours, spanPixels(lecture)).size();
    result.tolerance = "exact: the same pixels";
    ElementKeys all;
    std::set_union(theirs.begin(), theirs.end(), ours.begin(), ours.end(), std::back_inserter(all));
    const ElementKeys differ = symmetricDifference(theirs, ours);
    result.elements = all.size();
    result.differing = differ.size();
    if (differ.empty()) return result;
    result.verdict = Verdict::Failed;
    for (std::uint64_t k : differ) {
        if (result.departures.size() >= kMostDepartures) break;
        const auto [t, y, x] = pixelOf(k);
        const rl::dvec2 at(x, y);
        const bool covered = std::binary_search(ours.begin(), ours.end(), k);
        result.departures.push_back(
            {covered ? Departure::Kind::OnlyOurs : Departure::Kind::OnlyTheirs, at, at});
    }
    const auto [t, y, x] = pixelOf(differ.front());
    const Row& r = triangles[t];
    const double area = (r[2] - r[0]) * (r[5] - r[1]) - (r[3] - r[1]) * (r[4] - r[0]);
    std::string edges;
    for (int k = 0; k < 3; ++k) {
        const int j = (k + 1) % 3;
        const double e = (area > 0 ? 1 : -1) * ((r[2 * j] - r[2 * k]) * (y - r[2 * k + 1]) -
                                                (r[2 * j + 1] - r[2 * k + 1]) * (x - r[2 * k]));
        if (k) edges += ", ";
        edges += "e" + std::to_string(k) + std::to_string(j) + " = " + formatNumber(e);
    }
    const bool covered = std::binary_search(ours.begin(), ours.end(), differ.front());
    result.first = Divergence{
        "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") of triangle " +
            std::to_string(t),
        covered ? "not covered" : "covered", covered ? "covered" : "not covered",
        "the sample (" + std::to_string(x) + ", " + std::to_string(y) + ") against the edges of (" +
            rowText(r) + "): " + edges + "; inside when all three are >= 0"};
    const Explanation e = explainStage(
        scanCatalogue(), differ,
        [&](const Mistakes& applied) -> std::optional<ElementKeys> {
            return symmetricDifference(theirs, spanPixels(scanAnswer(triangles, w, h, applied)));
        },
        pixelName);
    takeExplanation(result, e);
    if (!e.unexplained.empty())
        result.description = describeSpans(
            answer[0].rows, e.applied.empty() ? oursRows : scanAnswer(triangles, w, h, e.applied));
    return result;
}

namespace {

using Winner = std::pair<std::uint32_t, double>;  // triangle, z
using Winners = std::map<std::uint64_t, Winner>;  // by pixel key (y, x)

std::uint64_t pixelKey(double x, double y) {
    return keyOf({0, std::int32_t(y), std::int32_t(x)});
}

std::optional<std::string> winnersOf(const std::vector<Row>& rows, Winners& out) {
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const Row& r = rows[k];
        if (!whole(r[0], -kFarthest, kFarthest) || !whole(r[1], -kFarthest, kFarthest) ||
            !whole(r[2], 0, 4e9))
            return "pixel " + std::to_string(k) + " (" + rowText(r) +
                   ") is not 'x y t z' with whole x, y (within 1000000 pixels of the screen) and t";
        if (!out.emplace(pixelKey(r[0], r[1]), Winner(std::uint32_t(r[2]), r[3])).second)
            return "pixel (" + formatNumber(r[0]) + ", " + formatNumber(r[1]) + ") is listed twice";
    }
    return std::nullopt;
}

bool sameWinner(const Winner& a, const Winner& b, double& error) {
    error = std::abs(a.second - b.second);
    return a.first == b.first && error <= 1e-6 * std::max(1.0, std::abs(b.second));
}

// The pixels whose winner differs (or that one side alone has), and the largest error of z
// where both keep the same triangle.
ElementKeys differingWinners(const Winners& theirs, const Winners& ours, double* largest = nullptr) {
    ElementKeys out;
    auto a = theirs.begin(), b = ours.begin();
    while (a != theirs.end() || b != ours.end()) {
        if (b == ours.end() || (a != theirs.end() && a->first < b->first)) {
            out.push_back((a++)->first);
        } else if (a == theirs.end() || b->first < a->first) {
            out.push_back((b++)->first);
        } else {
            double error = 0.0;
            if (sameWinner(a->second, b->second, error)) {
                if (largest) *largest = std::max(*largest, error);
            } else {
                out.push_back(a->first);
            }
            ++a, ++b;
        }
    }
    return out;
}

Winners winnersFrom(const std::vector<Row>& rows) {
    Winners w;
    winnersOf(rows, w);
    return w;
}

std::string pixelOnly(std::uint64_t key) {
    const auto [t, y, x] = pixelOf(key);
    return "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")";
}

std::vector<std::string> describeWinners(const Winners& theirs, const Winners& best,
                                         const ElementKeys& left) {
    std::size_t farther = 0, nearer = 0, onlyTheirs = 0, onlyOurs = 0, otherZ = 0;
    for (std::uint64_t k : left) {
        const auto a = theirs.find(k), b = best.find(k);
        if (a == theirs.end()) {
            ++onlyOurs;
        } else if (b == best.end()) {
            ++onlyTheirs;
        } else if (a->second.first == b->second.first) {
            ++otherZ;
        } else {
            (a->second.second > b->second.second ? farther : nearer) += 1;
        }
    }
    std::vector<std::string> out;
    const auto say = [&](std::size_t n, const std::string& what) {
        if (n) out.push_back("on " + std::to_string(n) + (n == 1 ? " pixel " : " pixels ") + what);
    };
    say(farther, "they keep a farther fragment than the nearest");
    say(nearer, "they keep another fragment, nearer than the one the lecture keeps");
    say(otherZ, "they keep the same triangle with another z");
    say(onlyTheirs, "they keep a fragment where no fragment reached");
    say(onlyOurs, "they keep no fragment where one reached");
    return out;
}

}  // namespace

StageResult StageCheck::judgeZBuffer(const std::vector<Record>& answer, const Inputs& in) const {
    const Data& d = *m_data;
    Winners theirs, lecture;
    StageResult result;
    result.stage = Stage::ZBuffer;
    if (auto bad = winnersOf(answer[0].rows, theirs)) {
        result.verdict = Verdict::Broken;
        result.problem = *bad;
        return result;
    }
    for (std::int32_t y = 0; y < d.scene->height; ++y)
        for (std::int32_t x = 0; x < d.scene->width; ++x)
            if (const std::uint32_t t = d.depth.triangle.at(x, y); t != rl::kNoTriangle)
                lecture[pixelKey(x, y)] = {t, double(d.depth.depth.at(x, y))};
    const Winners ours = in.chained ? winnersFrom(zbufferAnswer(in.fragments, {})) : lecture;
    if (in.chained) result.carried = differingWinners(ours, lecture).size();
    result.tolerance = "the same triangle, its z within 1e-6 times its size (at least 1e-6)";
    std::set<std::uint64_t> keys;
    for (const auto& [k, v] : ours) keys.insert(k);
    for (const auto& [k, v] : theirs) keys.insert(k);
    result.elements = keys.size();
    const ElementKeys differ = differingWinners(theirs, ours, &result.largestError);
    result.differing = differ.size();
    if (differ.empty()) return result;
    result.verdict = Verdict::Failed;
    const auto show = [](const Winners& w, std::uint64_t k) {
        const auto it = w.find(k);
        return it == w.end() ? std::string("no fragment kept")
                             : "triangle " + std::to_string(it->second.first) +
                                   ", z = " + protocolNumber(it->second.second);
    };
    for (std::uint64_t k : differ) {
        if (result.departures.size() >= kMostDepartures) break;
        const auto [t, y, x] = pixelOf(k);
        const rl::dvec2 at(x, y);
        const auto kind = !theirs.count(k) ? Departure::Kind::OnlyOurs
                          : !ours.count(k) ? Departure::Kind::OnlyTheirs
                                           : Departure::Kind::Different;
        result.departures.push_back({kind, at, at});
    }
    const auto [t0, y0, x0] = pixelOf(differ.front());
    std::string order;
    for (const Fragment& f : in.fragments)
        if (f.x == x0 && f.y == y0) {
            if (!order.empty()) order += ", ";
            order += "triangle " + std::to_string(f.t) + " z = " + protocolNumber(f.z);
        }
    result.first = Divergence{pixelOnly(differ.front()), show(theirs, differ.front()),
                              show(ours, differ.front()),
                              "its fragments in drawing order, as sent: " + order +
                                  "; the least z is kept, the earlier on a tie"};
    const Explanation e = explainStage(
        zbufferCatalogue(), differ,
        [&](const Mistakes& applied) -> std::optional<ElementKeys> {
            return differingWinners(theirs, winnersFrom(zbufferAnswer(in.fragments, applied)));
        },
        pixelOnly);
    takeExplanation(result, e);
    if (!e.unexplained.empty())
        result.description = describeWinners(
            theirs, e.applied.empty() ? ours : winnersFrom(zbufferAnswer(in.fragments, e.applied)),
            e.unexplained);
    return result;
}

rl::Rgba8Image StageCheck::theirImage(const std::vector<Record>& answer) {
    rl::Rgba8Image image;
    image.width = int(answer[0].numbers[0]);
    image.height = int(answer[0].numbers[1]);
    image.rgba.assign(std::size_t(image.width) * std::size_t(image.height) * 4, 255);
    for (std::size_t y = 0; y < answer[0].rows.size(); ++y)
        for (std::size_t i = 0; i < answer[0].rows[y].size(); ++i)
            image.rgba[(y * std::size_t(image.width) + i / 3) * 4 + i % 3] =
                std::uint8_t(std::clamp(answer[0].rows[y][i], 0.0, 255.0));
    return image;
}

namespace {

// The frame mistakes each stage's findings are (applied first), and those a stage that passed
// or whose findings explain it whole rules out.
struct FrameMistakes {
    std::vector<rl::Slip> given;
    std::vector<rl::Mistake> excluded;
};

std::optional<rl::Mistake> frameMistakeOf(const std::string& id) {
    static const std::map<std::string, rl::Mistake> kMap = {
        {"basis-u-reversed", rl::Mistake::BasisUReversed},
        {"basis-n-not-normalised", rl::Mistake::BasisNNotNormalised},
        {"light-in-world", rl::Mistake::LightInWorld},
        {"light-without-c", rl::Mistake::LightWithoutC},
        {"vertex-normals-not-normalised", rl::Mistake::VertexNormalsUnnormalised},
        {"area-weighted-normals", rl::Mistake::AreaWeightedNormals},
        {"vertex-snap", rl::Mistake::VertexSnap},
        {"screen-fractional", rl::Mistake::VertexSnap},
        {"upside-down", rl::Mistake::UpsideDown},
        {"depth-reversed", rl::Mistake::DepthReversed},
        {"depth-ties-later", rl::Mistake::DepthTies},
        {"normal-not-flipped", rl::Mistake::NormalNotFlipped},
        {"view-vector-reversed", rl::Mistake::ViewVectorReversed},
        {"light-behind-not-skipped", rl::Mistake::LightBehindNotSkipped},
        {"specular-where-rv-negative", rl::Mistake::SpecularWhereRvNegative},
        {"ambient-times-od", rl::Mistake::AmbientTimesOd},
        {"ambient-ia-only", rl::Mistake::AmbientIaOnly},
        {"terms-truncated", rl::Mistake::TermsTruncated},
        {"epsilon-special-cases", rl::Mistake::EpsilonSpecialCases},
        {"no-clamp", rl::Mistake::ColourWrap},
    };
    const auto it = kMap.find(id);
    return it == kMap.end() ? std::nullopt : std::optional(it->second);
}

// The frame mistakes that would show in a stage's answer: ruled out when the stage passed.
std::vector<rl::Mistake> shownBy(Stage stage) {
    using M = rl::Mistake;
    switch (stage) {
        case Stage::Basis:
            return {M::BasisUReversed, M::BasisNNotNormalised};
        case Stage::View:
            return {M::LightInWorld, M::LightWithoutC};
        case Stage::Normals:
            return {M::VertexNormalsUnnormalised, M::AreaWeightedNormals,
                    M::NormalsSharedByPosition};
        case Stage::Projection:
            return {M::VertexSnap, M::ScreenMap};
        case Stage::Scan:
            return {M::FillRule, M::SampleOffset};
        case Stage::ZBuffer:
            return {M::DepthReversed, M::DepthTies, M::PainterOrder};
        case Stage::Lighting:
            return {M::NormalNotFlipped,      M::ViewVectorReversed,      M::LightBehindNotSkipped,
                    M::SpecularWhereRvNegative, M::AmbientTimesOd,       M::AmbientIaOnly,
                    M::TermsTruncated,        M::EpsilonSpecialCases,     M::ColourWrap,
                    M::ColourScale};
        case Stage::Frame:
            break;
    }
    return {};
}

FrameMistakes frameMistakes(const std::vector<StageResult>& earlier) {
    FrameMistakes out;
    for (const StageResult& r : earlier) {
        std::vector<rl::Mistake> given;
        for (const StageFinding& f : r.findings) {
            if (const auto m = frameMistakeOf(f.id)) {
                const double amount = f.id == "screen-fractional" ? rl::kKeptFractional : f.value;
                out.given.push_back({*m, rl::ivec2(1, 0), {}, amount, {}});
                given.push_back(*m);
            }
        }
        // Truncated terms leave every byte a little low: not a constant offset, nor bytes
        // rounded another way.
        if (std::find(given.begin(), given.end(), rl::Mistake::TermsTruncated) != given.end())
            out.excluded.insert(out.excluded.end(),
                                {rl::Mistake::ColourOffset, rl::Mistake::ByteRounding});
        // A projection that passed only by the tie rule (a coordinate all but whole, made whole
        // the other way) does not rule out another way of making it whole.
        const bool ties = r.stage == Stage::Projection && r.largestError > 0.0;
        const bool whole = (r.verdict == Verdict::Passed && !ties) ||
                           (r.verdict == Verdict::Failed && r.unexplained == 0);
        if (!whole) continue;
        for (rl::Mistake m : shownBy(r.stage))
            if (std::find(given.begin(), given.end(), m) == given.end()) out.excluded.push_back(m);
    }
    return out;
}

}  // namespace

namespace {

// The pixels (keys y * width + x) where two images differ by more than 1 in a channel.
ElementKeys differingPixels(const rl::Rgba8Image& a, const rl::Rgba8Image& b) {
    ElementKeys out;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const std::uint8_t *p = a.pixel(x, y), *q = b.pixel(x, y);
            for (int k = 0; k < 3; ++k)
                if (std::abs(int(p[k]) - int(q[k])) > 1) {
                    out.push_back(std::uint64_t(y) * std::uint64_t(a.width) + std::uint64_t(x));
                    break;
                }
        }
    return out;
}

// The findings of these stages rendered into the frame in the pipeline's order, each with the
// pixels it makes match given those before it; what stays differing in `left`.
std::vector<StageFinding> renderedInOrder(const FrameScene& scene,
                                          const std::vector<const StageResult*>& stages,
                                          const rl::Rgba8Image& theirs, ElementKeys& left) {
    std::vector<StageFinding> out;
    const double first = double(left.size());
    std::map<Stage, Mistakes> applied;
    for (const StageResult* r : stages) {
        applied[r->stage] = r->applied;
        const ElementKeys now = differingPixels(theirs, modelFrame(scene, applied));
        StageFinding f;
        f.id = "stage-" + std::string(stageName(r->stage));
        f.cause = "the " + std::string(stageName(r->stage)) + " stage's findings: " + r->causes();
        f.explained = without(left, now).size();
        f.spoiled = without(now, left).size();
        f.share = first > 0 ? (double(f.explained) - double(f.spoiled)) / first : 0.0;
        left = now;
        out.push_back(std::move(f));
    }
    return out;
}

// Each earlier stage's findings rendered into the frame, as renderedInOrder; a stage whose
// findings make no pixel match net (a truncated term within the frame's byte of tolerance)
// is left out when the frame without it leaves no more pixels differing (two stages' findings
// may match pixels only together: a rounding and the spans walked from it).
std::vector<StageFinding> stagesInFrame(const FrameScene& scene,
                                        const std::vector<StageResult>& earlier,
                                        const rl::Rgba8Image& theirs, ElementKeys& left) {
    std::vector<const StageResult*> stages;
    for (const StageResult& r : earlier)
        if (!r.applied.empty()) stages.push_back(&r);
    const ElementKeys start = left;
    std::vector<StageFinding> out = renderedInOrder(scene, stages, theirs, left);
    for (std::size_t i = out.size(); i-- > 0;) {
        if (out[i].explained > out[i].spoiled) continue;
        std::vector<const StageResult*> fewer = stages;
        fewer.erase(fewer.begin() + std::ptrdiff_t(i));
        ElementKeys fewerLeft = start;
        std::vector<StageFinding> without = renderedInOrder(scene, fewer, theirs, fewerLeft);
        if (fewerLeft.size() > left.size()) continue;
        stages = std::move(fewer);
        out = std::move(without);
        left = std::move(fewerLeft);
    }
    return out;
}

}  // namespace

FrameScene StageCheck::Data::frameScene() const {
    FrameScene s;
    s.width = scene->width;
    s.height = scene->height;
    s.c = camera().c;
    s.n = camera().n;
    s.v = camera().v;
    s.d = camera().d;
    s.hx = camera().hx;
    s.hy = camera().hy;
    s.lightWorld = rl::dvec3(scene->lights[0].pWorld);
    s.lighting = lighting;
    for (const rl::dvec4& p : mesh().positions) s.world.push_back({p.x, p.y, p.z});
    s.triangles = triangles();
    return s;
}

rl::Rgba8Image StageCheck::stagesFrame(const std::map<Stage, Mistakes>& applied) const {
    return modelFrame(m_data->frameScene(), applied);
}

namespace {

// Their frame answer as an image, or why it is not one of our size.
std::optional<std::string> frameProblem(const Record& image, const rl::Rgba8Image& ours) {
    if (image.numbers[0] != ours.width || image.numbers[1] != ours.height)
        return "their image is " + formatNumber(image.numbers[0]) + "x" +
               formatNumber(image.numbers[1]) + ", the request asked for " +
               std::to_string(ours.width) + "x" + std::to_string(ours.height);
    for (std::size_t y = 0; y < image.rows.size(); ++y)
        for (std::size_t i = 0; i < image.rows[y].size(); ++i)
            if (!whole(image.rows[y][i], 0, 255))
                return "row " + std::to_string(y) + " of their image holds " +
                       formatNumber(image.rows[y][i]) + " (number " + std::to_string(i + 1) +
                       "), not a whole 0..255";
    return std::nullopt;
}

// The largest difference in a channel, the pixels that differ as departures, and the first.
void framePixels(const rl::Rgba8Image& theirs, const rl::Rgba8Image& ours,
                 const ElementKeys& differing, StageResult& result) {
    for (int y = 0; y < ours.height; ++y)
        for (int x = 0; x < ours.width; ++x)
            for (int k = 0; k < 3; ++k)
                result.largestError =
                    std::max(result.largestError,
                             double(std::abs(int(theirs.pixel(x, y)[k]) - int(ours.pixel(x, y)[k]))));
    const auto at = [&](std::uint64_t key) {
        return rl::dvec2(double(key % std::uint64_t(ours.width)),
                         double(key / std::uint64_t(ours.width)));
    };
    for (std::uint64_t k : differing) {
        if (result.departures.size() >= kMostDepartures) break;
        result.departures.push_back({Departure::Kind::Different, at(k), at(k)});
    }
    if (differing.empty()) return;
    const rl::dvec2 p = at(differing.front());
    const auto rgb = [&](const rl::Rgba8Image& image) {
        const std::uint8_t* c = image.pixel(int(p.x), int(p.y));
        return std::to_string(c[0]) + " " + std::to_string(c[1]) + " " + std::to_string(c[2]);
    };
    result.first = Divergence{"pixel (" + formatNumber(p.x) + ", " + formatNumber(p.y) + ")",
                              rgb(theirs), rgb(ours), "the lecture's render of the whole frame"};
}

}  // namespace

// compare's diagnosis of their frame, starting from the stages' findings it can render and
// never naming a mistake a stage rules out: taken when it leaves fewer pixels unexplained.
bool StageCheck::compareFrame(const rl::Rgba8Image& theirs, const std::vector<StageResult>& earlier,
                              StageResult& result) const {
    const FrameMistakes stages = frameMistakes(earlier);
    rl::CompareOptions options;
    options.tolerance = 1;
    options.given = stages.given;
    options.excluded = stages.excluded;
    auto comparison = rl::compareWithOurs(m_data->frame, theirs, options);
    if (!comparison || comparison->unexplainedPixels >= result.unexplained) return false;
    result.findings.clear();
    for (const rl::Finding& f : comparison->diagnosis)
        result.findings.push_back({rl::mistakeId(f.mistake),
                                   f.title.english() + (f.given ? " (found by the stages)" : ""),
                                   f.explained, f.spoiled, f.share, {}, f.slip.amount});
    result.unexplained = comparison->unexplainedPixels;
    if (!result.findings.empty() && comparison->mostlyUnexplained())
        result.description.push_back("most of the difference stays unexplained (" +
                                     formatNumber(100.0 * comparison->unexplained) + "%)");
    return true;
}

StageResult StageCheck::judgeFrame(const std::vector<Record>& answer,
                                   const std::vector<StageResult>& earlier) const {
    const rl::Rgba8Image& ours = m_data->frame.image;
    StageResult result;
    result.stage = Stage::Frame;
    if (auto problem = frameProblem(answer[0], ours)) {
        result.verdict = Verdict::Broken;
        result.problem = *problem;
        return result;
    }
    const rl::Rgba8Image theirs = theirImage(answer);
    result.tolerance =
        "1 in each channel (the lecture's colours are floats: a byte may fall the other side of a "
        "whole number)";
    result.elements = std::size_t(ours.width) * std::size_t(ours.height);
    const ElementKeys differing = differingPixels(theirs, ours);
    framePixels(theirs, ours, differing, result);
    result.differing = differing.size();
    if (differing.empty()) return result;
    result.verdict = Verdict::Failed;
    // The stages' own findings first, rendered into the frame by their answers' formulas;
    // then, when they leave much unexplained, compare's diagnosis.
    ElementKeys left = differing;
    if (m_data->stagesFrameTrusted)
        result.findings = stagesInFrame(m_data->frameScene(), earlier, theirs, left);
    result.unexplained = left.size();
    if ((result.findings.empty() || result.unexplained * 5 > result.differing) &&
        compareFrame(theirs, earlier, result))
        left = result.unexplained ? differing : ElementKeys();
    std::size_t black = 0;
    for (std::uint64_t k : left) {
        const int x = int(k % std::uint64_t(ours.width)), y = int(k / std::uint64_t(ours.width));
        const std::uint8_t* a = theirs.pixel(x, y);
        black += a[0] == 0 && a[1] == 0 && a[2] == 0 && m_data->frame.covered(x, y) ? 1 : 0;
    }
    if (black)
        result.description.push_back(
            std::to_string(black) + (black == 1 ? " pixel" : " pixels") +
            " we light are black in theirs: not covered by their triangles, or lit with a colour "
            "that is not a number (NaN), which becomes 0 when made a byte");
    return result;
}

}  // namespace rasterlab::check
