// The judges of the stages whose answers are rows in the request's order (basis, view,
// normals, projection, lighting): each row held to the lecture's answer to what was sent, the
// mistakes that explain the rows that differ, and what stays unexplained in numbers.
#include <algorithm>
#include <cmath>
#include <functional>

#include "app/check/stage_check_data.h"
#include "app/check/stage_description.h"
#include "pipeline/core/format.h"

namespace rasterlab::check {

using rl::dvec3;
using rl::formatNumber;
using rl::vec3;

namespace {

// A number of the request as it was sent, every digit.
std::string sent(double v) {
    return protocolNumber(v);
}

std::string sentVector(const dvec3& v) {
    return "(" + sent(v.x) + ", " + sent(v.y) + ", " + sent(v.z) + ")";
}

std::string rowShown(const Row& r) {
    if (r.size() == 3) return rl::formatVector(vecOf(r));
    std::string s;
    for (std::size_t i = 0; i < r.size(); ++i) {
        if (i) s += ' ';
        s += formatNumber(r[i]);
    }
    return s;
}

using Equal = std::function<bool(std::size_t, const Row&, const Row&, double&)>;

// How a stage of rows is judged: the lecture's answer to what was sent (and, in a chained run,
// to RasterLab's own inputs), each element's name and formula, when two rows count as equal,
// the catalogue of mistakes and the answer with any of them, and what says the rest in numbers.
struct RowsJudge {
    Stage stage;
    std::vector<Row> ours;
    std::optional<std::vector<Row>> fromScratch;
    std::function<std::string(std::size_t)> element;
    std::function<std::string(std::size_t)> formula;
    Equal equal;
    std::string tolerance;
    Mistakes catalogue;
    std::function<std::vector<Row>(const Mistakes&)> answer;
    // Where an element that departs is on the screen, when it is (the projection's vertices).
    std::function<Departure(std::size_t, const Row& theirs)> departure;
    std::function<std::vector<std::string>(const std::vector<Row>& theirs,
                                           const std::vector<Row>& best, const ElementKeys& left)>
        describe;
    // Where the tolerance lets through values the lecture does not give (the projection's
    // ties): equality to the digit, to name the rule their values follow even when they pass.
    Equal exact;
};

ElementKeys differingRows(const Equal& equal, const std::vector<Row>& theirs,
                          const std::vector<Row>& rows) {
    ElementKeys keys;
    for (std::size_t i = 0; i < theirs.size(); ++i) {
        double error = 0.0;
        if (!equal(i, theirs[i], rows[i], error)) keys.push_back(i);
    }
    return keys;
}

StageResult judgeRows(const RowsJudge& j, const std::vector<Row>& theirs) {
    StageResult result;
    result.stage = j.stage;
    result.tolerance = j.tolerance;
    result.elements = j.ours.size();
    ElementKeys differing;
    for (std::size_t i = 0; i < j.ours.size(); ++i) {
        double error = 0.0;
        const bool same = j.equal(i, theirs[i], j.ours[i], error);
        result.largestError = std::max(result.largestError, error);
        if (same) continue;
        differing.push_back(i);
        if (j.departure && result.departures.size() < kMostDepartures)
            result.departures.push_back(j.departure(i, theirs[i]));
        if (result.differing++ == 0)
            result.first =
                Divergence{j.element(i), rowShown(theirs[i]), rowShown(j.ours[i]), j.formula(i)};
    }
    if (j.fromScratch) result.carried = differingRows(j.equal, *j.fromScratch, j.ours).size();
    // Passed, but not to the digit: which rule their values follow, said without failing.
    const bool byTolerance = result.differing == 0 && j.exact;
    if (byTolerance) differing = differingRows(j.exact, theirs, j.ours);
    if (differing.empty()) return result;
    if (!byTolerance) result.verdict = Verdict::Failed;
    const Equal& equal = byTolerance ? j.exact : j.equal;
    const Explanation e = explainStage(
        j.catalogue, differing,
        [&](const Mistakes& applied) -> std::optional<ElementKeys> {
            const std::vector<Row> rows = j.answer(applied);
            if (rows.size() != theirs.size()) return std::nullopt;
            return differingRows(equal, theirs, rows);
        },
        [&](std::uint64_t key) { return j.element(std::size_t(key)); });
    if (byTolerance) {
        if (e.findings.empty()) return result;
        result.description.push_back(
            "passed by the tolerance; to the digit, " + std::to_string(differing.size()) +
            (differing.size() == 1 ? " element differs" : " elements differ") +
            ", as this finding gives: it may show in the frame");
        result.findings = e.findings;
        result.applied = e.applied;
        return result;
    }
    takeExplanation(result, e);
    if (!e.unexplained.empty() && j.describe)
        result.description =
            j.describe(theirs, e.applied.empty() ? j.ours : j.answer(e.applied), e.unexplained);
    return result;
}

// A value that is not a number (a mistake's pow of a negative base, an overflow) equals
// nothing.
Equal absoluteWithin(double tolerance) {
    return [tolerance](std::size_t, const Row& a, const Row& b, double& error) {
        error = 0.0;
        bool same = true;
        for (std::size_t k = 0; k < a.size(); ++k) {
            const double d = std::abs(a[k] - b[k]);
            same = same && d <= tolerance;
            if (!std::isnan(d)) error = std::max(error, d);
        }
        return same;
    };
}

// Relative to the size of the coordinate (at least 1).
bool relativelyEqual(std::size_t, const Row& a, const Row& b, double& error) {
    error = 0.0;
    bool same = true;
    for (std::size_t k = 0; k < a.size(); ++k) {
        const double d = std::abs(a[k] - b[k]) / std::max(1.0, std::abs(b[k]));
        same = same && d <= 1e-6;
        if (!std::isnan(d)) error = std::max(error, d);
    }
    return same;
}

StageResult broken(Stage stage, std::string problem) {
    StageResult r;
    r.stage = stage;
    r.verdict = Verdict::Broken;
    r.problem = std::move(problem);
    return r;
}

// The list a record holds must have as many rows as the request's.
std::optional<StageResult> countMismatch(Stage stage, const Record& record, std::size_t wanted,
                                         const char* what) {
    if (record.rows.size() == wanted) return std::nullopt;
    return broken(stage, "their answer has " + std::to_string(record.rows.size()) + " rows of '" +
                             record.name + "', the request had " + std::to_string(wanted) + " " +
                             what);
}

std::vector<Row> numbersOf(const std::vector<Record>& records, std::size_t first, std::size_t end) {
    std::vector<Row> rows;
    for (std::size_t i = first; i < end; ++i) rows.push_back(records[i].numbers);
    return rows;
}

std::vector<Row> worldPositions(const rl::Mesh& mesh) {
    std::vector<Row> world;
    for (const rl::dvec4& p : mesh.positions) world.push_back(rowOf(dvec3(p)));
    return world;
}

}  // namespace

StageResult StageCheck::judgeBasis(const std::vector<Record>& answer) const {
    const rl::CameraBasis& b = m_data->basis;
    RowsJudge j;
    j.stage = Stage::Basis;
    j.ours = {rowOf(b.u), rowOf(b.v), rowOf(b.n)};
    j.element = [](std::size_t i) { return std::string(i == 0 ? "U" : i == 1 ? "V" : "N"); };
    j.formula = [&b](std::size_t i) {
        using rl::formatVector;
        if (i == 0)
            return "U = N x V = " + formatVector(b.n) + " x " + formatVector(b.v) + " = " +
                   formatVector(b.u);
        if (i == 1)
            return "V = (V - (V.N) N) / |V - (V.N) N| = (" + sentVector(b.vGiven) + " - " +
                   formatNumber(b.vDotN) + " " + formatVector(b.n) + ") / " +
                   formatNumber(b.vOrthogonalLength) + " = " + formatVector(b.v);
        return "N = N / |N| = " + sentVector(b.nGiven) + " / " + formatNumber(b.nLength) + " = " +
               formatVector(b.n);
    };
    j.equal = absoluteWithin(1e-6);
    j.tolerance = "1e-6 in each coordinate";
    j.catalogue = basisCatalogue();
    j.answer = [&b](const Mistakes& a) { return basisAnswer(b.nGiven, b.vGiven, a); };
    j.describe = [](const auto& theirs, const auto& best, const ElementKeys& left) {
        return describeVectors(theirs, best, left, {"U", "V", "N"});
    };
    return judgeRows(j, numbersOf(answer, 0, 3));
}

StageResult StageCheck::judgeView(const std::vector<Record>& answer, const Inputs& in) const {
    const Data& d = *m_data;
    if (auto bad = countMismatch(Stage::View, answer[1], d.mesh().positions.size(), "vertices"))
        return *bad;
    const dvec3 c = d.basis.c;
    const std::array<dvec3, 3> uvn = in.uvn;
    const dvec3 lightWorld(d.scene->lights[0].pWorld);
    const std::vector<Row> world = worldPositions(d.mesh());
    RowsJudge j;
    j.stage = Stage::View;
    std::vector<Row> lecture{rowOf(dvec3(d.view.lights[0].pView))};
    for (const rl::dvec4& p : d.view.pView[0]) lecture.push_back(rowOf(dvec3(p)));
    if (in.chained) {
        j.ours = viewAnswer(c, uvn, lightWorld, world, {});
        j.fromScratch = lecture;
    } else {
        j.ours = lecture;
    }
    j.element = [](std::size_t i) {
        return i == 0 ? std::string("the light") : "vertex " + std::to_string(i - 1);
    };
    j.formula = [=](std::size_t i) {
        const dvec3 p = i == 0 ? lightWorld : vecOf(world[i - 1]);
        const dvec3 q = p - c;
        return std::string(i == 0 ? "Pl' = [U; V; N] (Pl - C)" : "P' = [U; V; N] (P - C)") +
               " with U = " + sentVector(uvn[0]) + ", V = " + sentVector(uvn[1]) +
               ", N = " + sentVector(uvn[2]) + ": (U.q, V.q, N.q) with q = " + sentVector(p) +
               " - " + sentVector(c) + " = " + rl::formatVector(q) + ": " +
               rl::formatVector(dvec3(glm::dot(uvn[0], q), glm::dot(uvn[1], q),
                                      glm::dot(uvn[2], q)));
    };
    j.equal = relativelyEqual;
    j.tolerance = "1e-6 times the coordinate's size (at least 1e-6)";
    j.catalogue = viewCatalogue();
    j.answer = [=](const Mistakes& a) { return viewAnswer(c, uvn, lightWorld, world, a); };
    j.describe = [](const auto& theirs, const auto& best, const ElementKeys& left) {
        return describeVectors(theirs, best, left, {"the light"});
    };
    std::vector<Row> theirs{answer[0].numbers};
    theirs.insert(theirs.end(), answer[1].rows.begin(), answer[1].rows.end());
    return judgeRows(j, theirs);
}

StageResult StageCheck::judgeNormals(const std::vector<Record>& answer, const Inputs& in) const {
    const Data& d = *m_data;
    const auto& triangles = d.triangles();
    const std::size_t vertices = d.view.pView[0].size();
    if (auto bad = countMismatch(Stage::Normals, answer[0], triangles.size(), "triangles"))
        return *bad;
    if (auto bad = countMismatch(Stage::Normals, answer[1], vertices, "vertices")) return *bad;
    const std::vector<Row> view = in.view, screen = in.screen;
    RowsJudge j;
    j.stage = Stage::Normals;
    std::vector<Row> lecture;
    for (const vec3& n : d.normals.triangle) lecture.push_back(rowOf(n));
    for (const vec3& n : d.normals.vertex) lecture.push_back(rowOf(n));
    if (in.chained) {
        j.ours = normalsAnswer(view, triangles, screen, {});
        j.fromScratch = lecture;
    } else {
        j.ours = lecture;
    }
    const std::size_t m = triangles.size();
    j.element = [m](std::size_t i) {
        return i < m ? "triangle " + std::to_string(i) : "vertex " + std::to_string(i - m);
    };
    j.formula = [&triangles, view, m](std::size_t i) {
        if (i < m) {
            const auto& t = triangles[i];
            const dvec3 a = vecOf(view[t[0]]);
            const dvec3 e1 = vecOf(view[t[1]]) - a, e2 = vecOf(view[t[2]]) - a;
            const dvec3 c = glm::cross(e1, e2);
            return "n = (P" + std::to_string(t[1]) + " - P" + std::to_string(t[0]) + ") x (P" +
                   std::to_string(t[2]) + " - P" + std::to_string(t[0]) + ") / |...| with P" +
                   std::to_string(t[0]) + " = " + sentVector(a) + ", P" + std::to_string(t[1]) +
                   " = " + sentVector(vecOf(view[t[1]])) + ", P" + std::to_string(t[2]) + " = " +
                   sentVector(vecOf(view[t[2]])) + ": " + rl::formatVector(e1) + " x " +
                   rl::formatVector(e2) + " / " + formatNumber(glm::length(c)) + " = " +
                   rl::formatVector(glm::length(c) > 0.0 ? c / glm::length(c) : dvec3(0.0));
        }
        const std::size_t v = i - m;
        std::string around;
        int count = 0;
        for (std::size_t t = 0; t < m; ++t)
            if (triangles[t][0] == v || triangles[t][1] == v || triangles[t][2] == v) {
                if (count++) around += ", ";
                around += std::to_string(t);
            }
        return "N = the sum of the unit normals of triangles " + around + ", normalised";
    };
    j.equal = absoluteWithin(1e-5);
    j.tolerance = "1e-5 in each coordinate (the lecture's normals are floats)";
    j.catalogue = normalsCatalogue(screen, triangles);
    j.answer = [view, screen, &triangles](const Mistakes& a) {
        return normalsAnswer(view, triangles, screen, a);
    };
    j.describe = [](const auto& theirs, const auto& best, const ElementKeys& left) {
        return describeVectors(theirs, best, left, {});
    };
    std::vector<Row> theirs = answer[0].rows;
    theirs.insert(theirs.end(), answer[1].rows.begin(), answer[1].rows.end());
    return judgeRows(j, theirs);
}

StageResult StageCheck::judgeProjection(const std::vector<Record>& answer, const Inputs& in) const {
    const Data& d = *m_data;
    if (auto bad = countMismatch(Stage::Projection, answer[0], d.projected.size(), "vertices"))
        return *bad;
    const rl::CourseCamera& cam = d.camera();
    const int w = d.scene->width, h = d.scene->height;
    std::vector<Row> view, lecture;
    for (std::uint32_t i : d.projected) {
        view.push_back(in.view[i]);
        const rl::dvec2 s = d.projection.draws[0].pScreen[i];
        lecture.push_back({s.x, s.y});
    }
    RowsJudge j;
    j.stage = Stage::Projection;
    if (in.chained) {
        j.ours = projectionAnswer(cam.d, cam.hx, cam.hy, w, h, view, {});
        j.fromScratch = lecture;
    } else {
        j.ours = lecture;
    }
    const auto projected = d.projected;
    j.element = [projected](std::size_t i) { return "vertex " + std::to_string(projected[i]); };
    j.formula = [cam, w, h, view](std::size_t i) {
        const Row& p = view[i];
        const auto e = projectionExact(cam.d, cam.hx, cam.hy, w, h, p);
        return "x = (int)((d/hx * x/z + 1) * width/2) = (int)((" + sent(cam.d) + "/" +
               sent(cam.hx) + " * " + sent(p[0]) + "/" + sent(p[2]) + " + 1) * " +
               std::to_string(w) + "/2) = (int)(" + formatNumber(e[0]) +
               ") = " + formatNumber(std::trunc(e[0])) +
               "; y = (int)((1 - d/hy * y/z) * height/2) = (int)((1 - " + sent(cam.d) + "/" +
               sent(cam.hy) + " * " + sent(p[1]) + "/" + sent(p[2]) + ") * " + std::to_string(h) +
               "/2) = (int)(" + formatNumber(e[1]) + ") = " + formatNumber(std::trunc(e[1]));
    };
    // Whole pixels: equal, or the other side of a whole number the exact value all but
    // reaches; a fractional value (a mistake's) within 1e-6 of its size.
    j.equal = [cam, w, h, view](std::size_t i, const Row& a, const Row& b, double& error) {
        const auto e = projectionExact(cam.d, cam.hx, cam.hy, w, h, view[i]);
        error = 0.0;
        bool same = true;
        for (std::size_t k = 0; k < 2; ++k) {
            const double diff = std::abs(a[k] - b[k]);
            error = std::max(error, diff);
            const bool tie =
                std::abs(e[k] - std::round(e[k])) <= 1e-9 * std::max(1.0, std::abs(e[k]));
            const bool fractional = b[k] != std::floor(b[k]);
            same = same && (diff == 0.0 || (tie && diff <= 1.0) ||
                            (fractional && diff <= 1e-6 * std::max(1.0, std::abs(b[k]))));
        }
        return same;
    };
    j.tolerance = "exact whole pixels (either side where x or y is within 1e-9 of a whole number)";
    j.exact = [](std::size_t, const Row& a, const Row& b, double& error) {
        error = 0.0;
        bool same = true;
        for (std::size_t k = 0; k < 2; ++k) {
            const double apart = std::abs(a[k] - b[k]);
            error = std::max(error, apart);
            same = same && (apart == 0.0 || (b[k] != std::floor(b[k]) &&
                                             apart <= 1e-6 * std::max(1.0, std::abs(b[k]))));
        }
        return same;
    };
    j.catalogue = projectionCatalogue();
    j.answer = [cam, w, h, view](const Mistakes& a) {
        return projectionAnswer(cam.d, cam.hx, cam.hy, w, h, view, a);
    };
    j.departure = [ours = j.ours](std::size_t i, const Row& theirs) {
        return Departure{
            Departure::Kind::Vertex, {ours[i][0], ours[i][1]}, {theirs[0], theirs[1]}};
    };
    j.describe = [](const auto& theirs, const auto& best, const ElementKeys& left) {
        return describeScreen(theirs, best, left);
    };
    return judgeRows(j, answer[0].rows);
}

StageResult StageCheck::judgeLighting(const std::vector<Record>& answer, const Inputs& in) const {
    const Data& d = *m_data;
    if (auto bad = countMismatch(Stage::Lighting, answer[0], in.samples.size(), "samples"))
        return *bad;
    Lighting lighting = d.lighting;
    lighting.light = in.light;
    const std::vector<Sample> samples = in.samples;
    RowsJudge j;
    j.stage = Stage::Lighting;
    if (in.chained) {
        j.ours = lightingAnswer(lighting, samples, {});
        j.fromScratch = d.colours;
    } else {
        j.ours = d.colours;
    }
    j.element = [](std::size_t i) { return "sample " + std::to_string(i); };
    j.formula = [lighting, samples](std::size_t i) {
        const Sample& s = samples[i];
        const PhongTerms p = phongTerms(lighting, s);
        std::string text = "at P' = " + sentVector(dvec3(s.p)) + ", N = " +
                           sentVector(dvec3(s.n)) + ", Pl = " + sentVector(lighting.light) +
                           ": I = Ia ka + Il Od kd (N.L) + Il ks (R.V)^n = " +
                           rl::formatVector(p.ambient) + " + " + rl::formatVector(p.diffuse) +
                           " + " + rl::formatVector(p.specular) + " with N.L = " +
                           formatNumber(p.nDotL) + ", R.V = " + formatNumber(p.rDotV);
        if (glm::dot(dvec3(s.n), -dvec3(s.p)) < 0.0) text += "; V.N < 0: N turned toward the viewer";
        if (p.nDotL < 0.0)
            text += "; N.L < 0: no diffuse, no specular";
        else if (p.rDotV < 0.0)
            text += "; R.V < 0: no specular";
        return text + "; each channel min(I, 255)";
    };
    j.equal = absoluteWithin(0.01);
    j.tolerance = "0.01 in each channel (0..255)";
    j.catalogue = lightingCatalogue(epsilonsOf(lighting, samples));
    j.answer = [lighting, samples](const Mistakes& a) {
        return lightingAnswer(lighting, samples, a);
    };
    j.describe = [lighting, samples](const auto& theirs, const auto& best, const ElementKeys& left) {
        return describeColours(theirs, best, left, lighting, samples);
    };
    return judgeRows(j, answer[0].rows);
}

}  // namespace rasterlab::check
