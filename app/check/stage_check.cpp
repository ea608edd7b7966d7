#include "app/check/stage_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <tuple>

#include "app/check/stage_mistakes.h"
#include "pipeline/analysis/mistakes.h"
#include "pipeline/core/format.h"
#include "pipeline/stages/camera_basis.h"
#include "pipeline/stages/depth_test.h"
#include "pipeline/stages/normals.h"
#include "pipeline/stages/phong.h"
#include "pipeline/stages/projection.h"
#include "pipeline/stages/scan_conversion.h"
#include "pipeline/stages/view_transform.h"

namespace rasterlab::check {

using rl::dvec3;
using rl::vec3;

// The inputs the requests carry: ours, or in a chained run the student's own earlier answers
// wherever they gave one of the right size.
struct StageCheck::Inputs {
    std::array<dvec3, 3> uvn;
    dvec3 light;              // in view coordinates
    std::vector<Row> view;    // every vertex, in view coordinates
    std::vector<Row> screen;  // every projected vertex of the draw, in pixels (x, y)
    std::vector<Fragment> fragments;
    std::vector<Sample> samples;
};

struct StageCheck::Data {
    std::shared_ptr<const rl::Scene> scene;
    const rl::Draw* draw = nullptr;
    rl::CameraBasis basis;
    rl::ViewTransform view;
    rl::DrawNormals normals;
    rl::Projection projection;
    rl::ScanConversion scan;
    rl::DepthTest depth;
    std::vector<std::uint32_t> projected;  // the projection request's vertex k is this vertex
    // Our inputs of every request, made once: the z-buffer's fragments in drawing order, the
    // lighting's samples, the basis, view coordinates and screen vertices.
    Inputs ours;
    std::vector<Row> colours;  // ours for the samples, clamped
    rl::OurFrame frame;        // our render, for the frame stage and compare
    Lighting lighting;         // the scene's, in view coordinates

    const rl::Mesh& mesh() const { return *draw->mesh; }
    const rl::CourseCamera& camera() const { return *scene->camera; }
};

namespace {

constexpr std::size_t kMostSamples = 400;  // vertices lit by the lighting request, each twice

// The project's number and vector texts, '.' as the decimal point whatever the locale.
using rl::formatNumber;

std::string vector3(const Row& r) {
    return rl::formatVector(dvec3(r[0], r[1], r[2]));
}

std::string vector3(const dvec3& v) {
    return rl::formatVector(v);
}

Row rowOf(const dvec3& v) {
    return {v.x, v.y, v.z};
}

Row rowOf(const vec3& v) {
    return {double(v.x), double(v.y), double(v.z)};
}

std::string rowText(const Row& r) {
    std::string s;
    for (std::size_t i = 0; i < r.size(); ++i) {
        if (i) s += ' ';
        s += formatNumber(r[i]);
    }
    return s;
}

// Why the protocol cannot carry a scene, or nothing.
std::optional<std::string> notCarried(const rl::Scene& scene) {
    if (!scene.camera) return "the scene has no course camera (C, N, V, d, hx, hy)";
    if (scene.draws.size() != 1)
        return "the protocol carries one object, the scene has " +
               std::to_string(scene.draws.size());
    if (scene.lights.size() != 1)
        return "the protocol carries one light, the scene has " +
               std::to_string(scene.lights.size());
    const rl::Light& light = scene.lights[0];
    if (light.pWorld.w == 0.0 || light.attenuated() || light.spot())
        return "the protocol carries the course's light: a point light, neither attenuated nor a "
               "spot";
    const rl::Material& m = scene.draws[0].material;
    if (m.kd.x != m.kd.y || m.kd.y != m.kd.z)
        return "the protocol carries a single kd, the scene's differs per channel";
    if (m.emission != vec3(0.0f)) return "the protocol has no emission (Ke)";
    if (!(scene.rules == rl::RasterRules::course()))
        return "the protocol is seed 000's: use the course's rules (--rules course)";
    const rl::Draw& d = scene.draws[0];
    if (d.worldFromModel != rl::dmat4(1.0) || d.animation || !d.clipPlanes.empty() || d.cull ||
        !d.mesh->normals.empty() || !d.mesh->colours.empty())
        return "the object has more than seed 000's file gives (a transform, normals, colours, "
               "clip planes)";
    return std::nullopt;
}

void computeFragments(StageCheck::Data& data) {
    const rl::Scene& scene = *data.scene;
    for (std::uint32_t t = 0; t < data.scan.triangleCount(); ++t)
        for (std::uint32_t s = data.scan.spanStart[t]; s < data.scan.spanStart[t + 1]; ++s) {
            const rl::Span& span = data.scan.spans[s];
            for (std::int32_t x = span.xBegin; x < span.xEnd; ++x)
                data.ours.fragments.push_back(
                    {t, x, span.y,
                     rl::fragmentDepth(scene, data.projection, t, span.y, span.xBegin, x).depth});
        }
}

// A unit vector at angle asin(e) from the plane normal to `axis`, leaning toward `toward`:
// its dot product with axis is e. False when toward lies along axis.
bool leaning(const dvec3& axis, const dvec3& toward, double e, dvec3& out) {
    const dvec3 t = toward - glm::dot(toward, axis) * axis;
    if (glm::length(t) < 1e-3) return false;
    out = std::sqrt(1.0 - e * e) * glm::normalize(t) + e * axis;
    return true;
}

// Samples just on the lit side of the special cases, V.N = 5e-4 and N.L = 5e-4, at the
// first vertex: they tell a comparison with 0 from one with a small epsilon.
void addGrazingSamples(StageCheck::Data& data) {
    if (data.view.pView[0].empty()) return;
    const dvec3 p = rl::cartesian(data.view.pView[0][0]);
    const dvec3 v = glm::normalize(-p);
    const dvec3 l = glm::normalize(dvec3(data.view.lights[0].pView) - p);
    constexpr double e = 5e-4;
    dvec3 n;
    if (leaning(v, l, e, n)) data.ours.samples.push_back({vec3(p), vec3(n), std::nullopt, false});
    if (leaning(l, v, e, n)) data.ours.samples.push_back({vec3(p), vec3(n), std::nullopt, false});
}

void computeSamples(StageCheck::Data& data) {
    const auto& pView = data.view.pView[0];
    const std::size_t count = pView.size();
    const std::size_t step = std::max<std::size_t>(1, count / kMostSamples);
    for (std::size_t i = 0; i < count; i += step) {
        const vec3 n = data.normals.vertex[i];
        if (n == vec3(0.0f)) continue;
        data.ours.samples.push_back({vec3(rl::cartesian(pView[i])), n, std::uint32_t(i), false});
        data.ours.samples.push_back({vec3(rl::cartesian(pView[i])), -n, std::uint32_t(i), true});
    }
    addGrazingSamples(data);
    const rl::Material& m = data.draw->material;
    for (const Sample& s : data.ours.samples) {
        const rl::PhongSample p = rl::phong(m, m.od, data.scene->ambientIntensity,
                                            data.view.lights.data(), 1, s.p, s.n, true);
        const vec3 c = glm::min(p.colour(), vec3(255.0f));
        data.colours.push_back(rowOf(c));
    }
}

// The basis, view coordinates and screen vertices of our inputs (the fragments and samples
// are made with them, by computeFragments and computeSamples).
void addOurGeometry(StageCheck::Data& d) {
    StageCheck::Inputs& in = d.ours;
    in.uvn = {d.basis.u, d.basis.v, d.basis.n};
    in.light = dvec3(d.view.lights[0].pView);
    for (const rl::dvec4& p : d.view.pView[0]) in.view.push_back(rowOf(dvec3(p)));
    for (const rl::dvec2& p : d.projection.draws[0].pScreen) in.screen.push_back({p.x, p.y});
}

}  // namespace

std::string_view verdictName(Verdict verdict) {
    switch (verdict) {
        case Verdict::Passed:
            return "passed";
        case Verdict::Failed:
            return "failed";
        case Verdict::Unsupported:
            return "unsupported";
        case Verdict::Broken:
            return "broken";
    }
    return "";
}

StageCheck::StageCheck(std::unique_ptr<Data> data) : m_data(std::move(data)) {}
StageCheck::~StageCheck() = default;

const rl::Rgba8Image& StageCheck::ourImage() const {
    return m_data->frame.image;
}

rl::Result<std::shared_ptr<const StageCheck>> StageCheck::make(
    std::shared_ptr<const rl::Scene> scene) {
    if (auto why = notCarried(*scene))
        return rl::makeError(rl::ErrorCode::Unsupported, {scene->name, 0, 0}, *why);
    auto data = std::make_unique<Data>();
    data->scene = scene;
    data->draw = &scene->draws[0];
    rl::Diagnostics diagnostics;
    auto basis = rl::CameraBasisStage().run(*scene, diagnostics);
    if (!basis) return basis.error();
    data->basis = basis.value();
    data->view = rl::ViewTransformStage().run(*scene, data->basis);
    rl::Normals normals = rl::NormalsStage().run({*scene, data->view});
    data->normals = normals.draws.at(0);
    data->projection = rl::ProjectionStage().run({*scene, data->view}, diagnostics);
    if (data->projection.clipped || data->projection.behind || data->projection.beyondGuardBand ||
        data->projection.backFaces)
        return rl::makeError(
            rl::ErrorCode::Unsupported, {scene->name, 0, 0},
            "a triangle is clipped, behind the camera or left out: the seed projects every vertex "
            "by dividing by its z and clips nothing, so the protocol carries only scenes wholly "
            "in front of the camera, every triangle drawn");
    data->scan = rl::ScanConversionStage().run({*scene, data->projection});
    data->depth = rl::DepthTestStage().run({*scene, data->projection, data->scan});
    const auto& pView = data->view.pView[0];
    for (std::uint32_t i = 0; i < pView.size(); ++i)
        if (pView[i].z > 0.0) data->projected.push_back(i);
    addOurGeometry(*data);
    computeFragments(*data);
    const rl::Material& m = data->draw->material;
    data->lighting = {dvec3(data->view.lights[0].pView),
                      data->scene->ambientIntensity,
                      data->view.lights[0].intensity,
                      m.ka,
                      m.kd.x,
                      m.od,
                      m.ks,
                      m.shininess};
    computeSamples(*data);
    auto frame = rl::renderOurFrame(scene);
    if (!frame) return frame.error();
    data->frame = std::move(frame.value());
    return std::shared_ptr<const StageCheck>(std::make_shared<StageCheck>(std::move(data)));
}

namespace {

// A student's number as a float: clamped to float's range (a double beyond it has no float).
float toFloat(double v) {
    constexpr double largest = std::numeric_limits<float>::max();
    return std::isnan(v) ? 0.0f : float(std::clamp(v, -largest, largest));
}

// The fragments of spans t y first last, in drawing order. A triangle whose screen vertices
// and view z are ours gets the lecture's own depths (depth_test.h's, bit for bit); another
// gets the view z of its vertices interpolated with the screen barycentrics of each sample.
std::vector<Fragment> fragmentsOfSpans(std::vector<Row> spans, const rl::Scene& scene,
                                       const rl::Projection& projection,
                                       const std::vector<Row>& screen, const std::vector<Row>& view,
                                       const std::vector<bool>& oursToo) {
    std::sort(spans.begin(), spans.end());
    std::vector<Fragment> out;
    for (const Row& s : spans) {
        // Spans that are not whole pixels on a screen of sensible size are theirs to explain
        // (the scan stage's judge does); no fragment is made of them.
        const auto whole = [](double v) { return v == std::floor(v) && std::abs(v) <= 1e9; };
        if (!(s[0] >= 0 && s[0] < double(projection.triangles.size())) || !whole(s[1]) ||
            !whole(s[2]) || !whole(s[3]) || s[3] - s[2] > 1e6)
            continue;
        const auto t = std::uint32_t(s[0]);
        const auto& v = projection.triangles[t].v;
        const Row &a = screen[v[0]], &b = screen[v[1]], &c = screen[v[2]];
        const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        if (area == 0.0) continue;
        for (double x = s[2]; x <= s[3]; ++x) {
            float z = 0.0f;
            if (oursToo[t]) {
                z = rl::fragmentDepth(scene, projection, t, std::int32_t(s[1]), std::int32_t(s[2]),
                                      std::int32_t(x))
                        .depth;
            } else {
                const double beta =
                    ((x - a[0]) * (c[1] - a[1]) - (s[1] - a[1]) * (c[0] - a[0])) / area;
                const double gamma =
                    ((b[0] - a[0]) * (s[1] - a[1]) - (b[1] - a[1]) * (x - a[0])) / area;
                z = toFloat((1.0 - beta - gamma) * view[v[0]][2] + beta * view[v[1]][2] +
                            gamma * view[v[2]][2]);
            }
            out.push_back({t, std::int32_t(x), std::int32_t(s[1]), z});
        }
    }
    return out;
}

}  // namespace

StageCheck::Inputs StageCheck::chainedInputs(const Answers& theirs) const {
    const Data& d = *m_data;
    Inputs in = d.ours;
    const auto answer = [&](Stage stage) -> const std::vector<Record>* {
        const auto it = theirs.find(stage);
        return it == theirs.end() ? nullptr : &it->second;
    };
    if (const auto* a = answer(Stage::Basis))
        for (std::size_t k = 0; k < 3; ++k)
            in.uvn[k] = dvec3((*a)[k].numbers[0], (*a)[k].numbers[1], (*a)[k].numbers[2]);
    if (const auto* a = answer(Stage::View); a && (*a)[1].rows.size() == in.view.size()) {
        in.light = dvec3((*a)[0].numbers[0], (*a)[0].numbers[1], (*a)[0].numbers[2]);
        in.view = (*a)[1].rows;
    }
    if (const auto* a = answer(Stage::Projection); a && (*a)[0].rows.size() == d.projected.size())
        for (std::size_t k = 0; k < d.projected.size(); ++k)
            in.screen[d.projected[k]] = (*a)[0].rows[k];
    if (const auto* a = answer(Stage::Scan)) {
        const Inputs& ours = d.ours;
        std::vector<bool> oursToo;
        for (const rl::ScreenTriangle& t : d.projection.triangles) {
            bool same = true;
            for (std::uint32_t v : t.v)
                same = same && in.screen[v] == ours.screen[v] &&
                       std::abs(in.view[v][2] - ours.view[v][2]) <=
                           1e-9 * std::max(1.0, std::abs(ours.view[v][2]));
            oursToo.push_back(same);
        }
        in.fragments =
            fragmentsOfSpans((*a)[0].rows, *d.scene, d.projection, in.screen, in.view, oursToo);
    }
    const auto* normals = answer(Stage::Normals);
    const bool theirNormals = normals && (*normals)[1].rows.size() == in.view.size();
    for (Sample& s : in.samples) {
        if (!s.vertex) continue;
        const Row& p = in.view[*s.vertex];
        s.p = vec3(toFloat(p[0]), toFloat(p[1]), toFloat(p[2]));
        if (theirNormals) {
            const Row& n = (*normals)[1].rows[*s.vertex];
            s.n = (s.reversed ? -1.0f : 1.0f) * vec3(toFloat(n[0]), toFloat(n[1]), toFloat(n[2]));
        }
    }
    return in;
}

Request StageCheck::request(Stage stage) const {
    return request(stage, m_data->ours);
}

Request StageCheck::chainedRequest(Stage stage, const Answers& theirs) const {
    return request(stage, chainedInputs(theirs));
}

Request StageCheck::request(Stage stage, const Inputs& in) const {
    const Data& d = *m_data;
    const rl::CourseCamera& camera = d.camera();
    const rl::Scene& scene = *d.scene;
    Request r(stage);
    const auto add3 = [&r](const char* name, const dvec3& v) { r.add(name, {v.x, v.y, v.z}); };
    const auto addLighting = [&](const dvec3& light) {
        const Lighting& l = d.lighting;
        add3("light", light);
        r.add("Ia", {l.ia.x, l.ia.y, l.ia.z});
        r.add("Il", {l.il.x, l.il.y, l.il.z});
        r.add("ka", {l.ka});
        r.add("kd", {l.kd});
        r.add("Od", {l.od.x, l.od.y, l.od.z});
        r.add("ks", {l.ks});
        r.add("n", {l.n});
    };
    const auto addTriangles = [&] {
        std::vector<Row> rows;
        for (const auto& t : d.mesh().triangles)
            rows.push_back({double(t[0]), double(t[1]), double(t[2])});
        r.addList("triangles", rows);
    };
    std::vector<Row> rows;
    switch (stage) {
        case Stage::Basis:
            add3("C", camera.c);
            add3("N", camera.n);
            add3("V", camera.v);
            break;
        case Stage::View:
            add3("C", camera.c);
            add3("U", in.uvn[0]);
            add3("V", in.uvn[1]);
            add3("N", in.uvn[2]);
            add3("light", dvec3(scene.lights[0].pWorld));
            for (const rl::dvec4& p : d.mesh().positions) rows.push_back(rowOf(dvec3(p)));
            r.addList("vertices", rows);
            break;
        case Stage::Normals:
            r.addList("vertices", in.view);
            addTriangles();
            break;
        case Stage::Projection:
            r.add("camera", {camera.d, camera.hx, camera.hy});
            r.add("size", {double(scene.width), double(scene.height)});
            for (std::uint32_t i : d.projected) rows.push_back(in.view[i]);
            r.addList("vertices", rows);
            break;
        case Stage::Scan:
            r.add("size", {double(scene.width), double(scene.height)});
            for (const rl::ScreenTriangle& t : d.projection.triangles) {
                const Row &a = in.screen[t.v[0]], &b = in.screen[t.v[1]], &c = in.screen[t.v[2]];
                rows.push_back({a[0], a[1], b[0], b[1], c[0], c[1]});
            }
            r.addList("triangles", rows);
            break;
        case Stage::ZBuffer:
            r.add("size", {double(scene.width), double(scene.height)});
            for (const Fragment& f : in.fragments)
                rows.push_back({double(f.t), double(f.x), double(f.y), double(f.z)});
            r.addList("fragments", rows);
            break;
        case Stage::Lighting:
            addLighting(in.light);
            for (const Sample& s : in.samples)
                rows.push_back({s.p.x, s.p.y, s.p.z, s.n.x, s.n.y, s.n.z});
            r.addList("samples", rows);
            break;
        case Stage::Frame:
            r.add("size", {double(scene.width), double(scene.height)});
            add3("C", camera.c);
            add3("N", camera.n);
            add3("V", camera.v);
            r.add("camera", {camera.d, camera.hx, camera.hy});
            addLighting(dvec3(scene.lights[0].pWorld));
            for (const rl::dvec4& p : d.mesh().positions) rows.push_back(rowOf(dvec3(p)));
            r.addList("vertices", rows);
            addTriangles();
            break;
    }
    return r;
}

}  // namespace rasterlab::check

namespace rasterlab::check {

namespace {

// How a stage of rows is judged: ours, each element's name and formula, when two rows count
// as equal (and the error between them), and the known mistakes.
struct RowsJudge {
    Stage stage;
    std::vector<Row> ours;
    std::function<std::string(std::size_t)> element;
    std::function<std::string(std::size_t)> formula;
    std::function<bool(std::size_t, const Row&, const Row&, double&)> equal;
    std::string tolerance;
    std::function<std::vector<Alternative>()> mistakes;
    // Where an element that departs is on the screen, when it is (the projection's vertices).
    std::function<Departure(std::size_t, const Row& theirs)> departure;
};

std::string rowShown(const Row& r) {
    return r.size() == 3 ? vector3(r) : rowText(r);
}

StageResult judgeRows(const RowsJudge& j, const std::vector<Row>& theirs) {
    StageResult result;
    result.stage = j.stage;
    result.tolerance = j.tolerance;
    result.elements = j.ours.size();
    for (std::size_t i = 0; i < j.ours.size(); ++i) {
        double error = 0.0;
        const bool same = j.equal(i, theirs[i], j.ours[i], error);
        result.largestError = std::max(result.largestError, error);
        if (same) continue;
        if (j.departure && result.departures.size() < kMostDepartures)
            result.departures.push_back(j.departure(i, theirs[i]));
        if (result.differing++ == 0)
            result.first =
                Divergence{j.element(i), rowShown(theirs[i]), rowShown(j.ours[i]), j.formula(i)};
    }
    if (result.differing == 0) return result;
    result.verdict = Verdict::Failed;
    for (const Alternative& a : j.mistakes()) {
        bool all = a.rows.size() == theirs.size();
        for (std::size_t i = 0; all && i < theirs.size(); ++i) {
            double error = 0.0;
            all = j.equal(i, theirs[i], a.rows[i], error);
        }
        if (all) {
            result.likelyCause = a.cause;
            break;
        }
    }
    return result;
}

std::function<bool(std::size_t, const Row&, const Row&, double&)> absoluteWithin(double tolerance) {
    return [tolerance](std::size_t, const Row& a, const Row& b, double& error) {
        error = 0.0;
        for (std::size_t k = 0; k < a.size(); ++k) error = std::max(error, std::abs(a[k] - b[k]));
        return error <= tolerance;
    };
}

// Relative to the size of the coordinate (at least 1).
bool relativelyEqual(std::size_t, const Row& a, const Row& b, double& error) {
    error = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k)
        error = std::max(error, std::abs(a[k] - b[k]) / std::max(1.0, std::abs(b[k])));
    return error <= 1e-6;
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

}  // namespace

StageResult StageCheck::judge(Stage stage, const std::vector<Record>& answer) const {
    switch (stage) {
        case Stage::Basis:
            return judgeBasis(answer);
        case Stage::View:
            return judgeView(answer);
        case Stage::Normals:
            return judgeNormals(answer);
        case Stage::Projection:
            return judgeProjection(answer);
        case Stage::Scan:
            return judgeScan(answer);
        case Stage::ZBuffer:
            return judgeZBuffer(answer);
        case Stage::Lighting:
            return judgeLighting(answer);
        case Stage::Frame:
            return judgeFrame(answer);
    }
    return broken(stage, "unknown stage");
}

StageResult StageCheck::judgeBasis(const std::vector<Record>& answer) const {
    const rl::CameraBasis& b = m_data->basis;
    RowsJudge j;
    j.stage = Stage::Basis;
    j.ours = {rowOf(b.u), rowOf(b.v), rowOf(b.n)};
    j.element = [](std::size_t i) { return std::string(i == 0 ? "U" : i == 1 ? "V" : "N"); };
    j.formula = [&b](std::size_t i) {
        if (i == 0)
            return "U = N x V = " + vector3(b.n) + " x " + vector3(b.v) + " = " + vector3(b.u);
        if (i == 1)
            return "V = (V - (V.N) N) / |V - (V.N) N| = (" + vector3(b.vGiven) + " - " +
                   formatNumber(b.vDotN) + " " + vector3(b.n) + ") / " +
                   formatNumber(b.vOrthogonalLength) + " = " + vector3(b.v);
        return "N = N / |N| = " + vector3(b.nGiven) + " / " + formatNumber(b.nLength) + " = " +
               vector3(b.n);
    };
    j.equal = absoluteWithin(1e-6);
    j.tolerance = "1e-6 in each coordinate";
    j.mistakes = [&b] { return basisMistakes(b.nGiven, b.vGiven); };
    return judgeRows(j, numbersOf(answer, 0, 3));
}

StageResult StageCheck::judgeView(const std::vector<Record>& answer) const {
    const Data& d = *m_data;
    if (auto bad = countMismatch(Stage::View, answer[1], d.mesh().positions.size(), "vertices"))
        return *bad;
    const rl::CameraBasis& b = d.basis;
    const dvec3 lightWorld(d.scene->lights[0].pWorld);
    std::vector<Row> world;
    for (const rl::dvec4& p : d.mesh().positions) world.push_back(rowOf(dvec3(p)));
    RowsJudge j;
    j.stage = Stage::View;
    j.ours.push_back(rowOf(dvec3(d.view.lights[0].pView)));
    for (const rl::dvec4& p : d.view.pView[0]) j.ours.push_back(rowOf(dvec3(p)));
    j.element = [](std::size_t i) {
        return i == 0 ? std::string("the light") : "vertex " + std::to_string(i - 1);
    };
    j.formula = [&, world](std::size_t i) {
        const dvec3 p =
            i == 0 ? lightWorld : dvec3(world[i - 1][0], world[i - 1][1], world[i - 1][2]);
        const dvec3 q = p - b.c;
        return std::string(i == 0 ? "Pl' = [U; V; N] (Pl - C)" : "P' = [U; V; N] (P - C)") +
               " = (U.q, V.q, N.q) with q = " + vector3(p) + " - " + vector3(b.c) + " = " +
               vector3(q) + ": " +
               vector3(dvec3(glm::dot(b.u, q), glm::dot(b.v, q), glm::dot(b.n, q)));
    };
    j.equal = relativelyEqual;
    j.tolerance = "1e-6 times the coordinate's size (at least 1e-6)";
    j.mistakes = [&b, lightWorld, world] {
        return viewMistakes(b.c, {b.u, b.v, b.n}, lightWorld, world);
    };
    std::vector<Row> theirs{answer[0].numbers};
    theirs.insert(theirs.end(), answer[1].rows.begin(), answer[1].rows.end());
    return judgeRows(j, theirs);
}

StageResult StageCheck::judgeNormals(const std::vector<Record>& answer) const {
    const Data& d = *m_data;
    const auto& triangles = d.mesh().triangles;
    const std::size_t vertices = d.view.pView[0].size();
    if (auto bad = countMismatch(Stage::Normals, answer[0], triangles.size(), "triangles"))
        return *bad;
    if (auto bad = countMismatch(Stage::Normals, answer[1], vertices, "vertices")) return *bad;
    std::vector<Row> view;
    for (const rl::dvec4& p : d.view.pView[0]) view.push_back(rowOf(dvec3(p)));
    RowsJudge j;
    j.stage = Stage::Normals;
    for (const vec3& n : d.normals.triangle) j.ours.push_back(rowOf(n));
    for (const vec3& n : d.normals.vertex) j.ours.push_back(rowOf(n));
    const std::size_t m = triangles.size();
    j.element = [m](std::size_t i) {
        return i < m ? "triangle " + std::to_string(i) : "vertex " + std::to_string(i - m);
    };
    j.formula = [&, view, m](std::size_t i) {
        if (i < m) {
            const auto& t = triangles[i];
            const dvec3 a(view[t[0]][0], view[t[0]][1], view[t[0]][2]);
            const dvec3 e1 = dvec3(view[t[1]][0], view[t[1]][1], view[t[1]][2]) - a;
            const dvec3 e2 = dvec3(view[t[2]][0], view[t[2]][1], view[t[2]][2]) - a;
            const dvec3 c = glm::cross(e1, e2);
            return "n = (P" + std::to_string(t[1]) + " - P" + std::to_string(t[0]) + ") x (P" +
                   std::to_string(t[2]) + " - P" + std::to_string(t[0]) +
                   ") / |...| = " + vector3(e1) + " x " + vector3(e2) + " / " +
                   formatNumber(glm::length(c)) + " = " +
                   vector3(glm::length(c) > 0.0 ? c / glm::length(c) : dvec3(0.0));
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
    j.mistakes = [view, &triangles] { return normalsMistakes(view, triangles); };
    std::vector<Row> theirs = answer[0].rows;
    theirs.insert(theirs.end(), answer[1].rows.begin(), answer[1].rows.end());
    return judgeRows(j, theirs);
}

StageResult StageCheck::judgeProjection(const std::vector<Record>& answer) const {
    const Data& d = *m_data;
    if (auto bad = countMismatch(Stage::Projection, answer[0], d.projected.size(), "vertices"))
        return *bad;
    const rl::CourseCamera& cam = d.camera();
    const int w = d.scene->width, h = d.scene->height;
    std::vector<Row> view;
    RowsJudge j;
    j.stage = Stage::Projection;
    for (std::uint32_t i : d.projected) {
        view.push_back(rowOf(dvec3(d.view.pView[0][i])));
        const rl::dvec2 s = d.projection.draws[0].pScreen[i];
        j.ours.push_back({s.x, s.y});
    }
    const auto projected = d.projected;
    j.element = [projected](std::size_t i) { return "vertex " + std::to_string(projected[i]); };
    j.formula = [cam, w, h, view](std::size_t i) {
        const Row& p = view[i];
        const auto e = projectionExact(cam.d, cam.hx, cam.hy, w, h, p);
        return "x = (int)((d/hx * x/z + 1) * width/2) = (int)((" + formatNumber(cam.d) + "/" +
               formatNumber(cam.hx) + " * " + formatNumber(p[0]) + "/" + formatNumber(p[2]) +
               " + 1) * " + std::to_string(w) + "/2) = (int)(" + formatNumber(e[0]) +
               ") = " + formatNumber(std::trunc(e[0])) +
               "; y = (int)((1 - d/hy * y/z) * height/2) = (int)((1 - " + formatNumber(cam.d) +
               "/" + formatNumber(cam.hy) + " * " + formatNumber(p[1]) + "/" + formatNumber(p[2]) +
               ") * " + std::to_string(h) + "/2) = (int)(" + formatNumber(e[1]) +
               ") = " + formatNumber(std::trunc(e[1]));
    };
    // Whole pixels: equal, or the other side of a whole number the exact value all but reaches.
    j.equal = [cam, w, h, view](std::size_t i, const Row& a, const Row& b, double& error) {
        const auto e = projectionExact(cam.d, cam.hx, cam.hy, w, h, view[i]);
        error = 0.0;
        bool same = true;
        for (int k = 0; k < 2; ++k) {
            const double diff = std::abs(a[std::size_t(k)] - b[std::size_t(k)]);
            error = std::max(error, diff);
            const bool tie = std::abs(e[std::size_t(k)] - std::round(e[std::size_t(k)])) <=
                             1e-9 * std::max(1.0, std::abs(e[std::size_t(k)]));
            same = same && (diff == 0.0 || (tie && diff <= 1.0));
        }
        return same;
    };
    j.tolerance = "exact whole pixels (either side where x or y is within 1e-9 of a whole number)";
    j.mistakes = [cam, w, h, view] {
        return projectionMistakes(cam.d, cam.hx, cam.hy, w, h, view);
    };
    j.departure = [&j](std::size_t i, const Row& theirs) {
        return Departure{
            Departure::Kind::Vertex, {j.ours[i][0], j.ours[i][1]}, {theirs[0], theirs[1]}};
    };
    return judgeRows(j, answer[0].rows);
}

StageResult StageCheck::judgeLighting(const std::vector<Record>& answer) const {
    const Data& d = *m_data;
    if (auto bad = countMismatch(Stage::Lighting, answer[0], d.ours.samples.size(), "samples"))
        return *bad;
    RowsJudge j;
    j.stage = Stage::Lighting;
    j.ours = d.colours;
    j.element = [](std::size_t i) { return "sample " + std::to_string(i); };
    j.formula = [&d](std::size_t i) {
        const Sample& s = d.ours.samples[i];
        const rl::Material& m = d.draw->material;
        const rl::PhongSample p =
            rl::phong(m, m.od, d.scene->ambientIntensity, d.view.lights.data(), 1, s.p, s.n, true);
        std::string text =
            "I = Ia ka + Il Od kd (N.L) + Il ks (R.V)^n = " + vector3(rowOf(p.ambient)) + " + " +
            vector3(rowOf(p.diffuse)) + " + " + vector3(rowOf(p.specular)) +
            " with N.L = " + formatNumber(p.nDotL) + ", R.V = " + formatNumber(p.rDotV);
        if (p.flipped) text += "; V.N < 0: N turned toward the viewer";
        if (p.lightBehind)
            text += "; N.L < 0: no diffuse, no specular";
        else if (p.noSpecular)
            text += "; R.V < 0: no specular";
        return text + "; each channel min(I, 255)";
    };
    j.equal = absoluteWithin(0.01);
    j.tolerance = "0.01 in each channel (0..255)";
    j.mistakes = [&d] { return lightingMistakes(d.lighting, d.ours.samples); };
    return judgeRows(j, answer[0].rows);
}

}  // namespace rasterlab::check

namespace rasterlab::check {

namespace {

using Pixel = std::tuple<std::uint32_t, std::int32_t, std::int32_t>;  // triangle, y, x

bool whole(double v, double low, double high) {
    return v == std::floor(v) && v >= low && v <= high;
}

// The pixels of spans t y first last; an error names the first span that is not one.
std::optional<std::string> pixelsOf(const std::vector<Row>& spans, std::size_t triangles, int width,
                                    int height, std::set<Pixel>& pixels) {
    for (std::size_t k = 0; k < spans.size(); ++k) {
        const Row& s = spans[k];
        if (!whole(s[0], 0, double(triangles) - 1) || !whole(s[1], -1e9, 1e9) ||
            !whole(s[2], -1e9, 1e9) || !whole(s[3], -1e9, 1e9))
            return "span " + std::to_string(k) + " (" + rowText(s) +
                   ") is not 't y first last' with whole numbers and t one of the " +
                   std::to_string(triangles) + " triangles";
        if (s[3] - s[2] > double(width))
            return "span " + std::to_string(k) + " (" + rowText(s) + ") is wider than the screen";
        for (double x = s[2]; x <= s[3]; ++x)
            if (!pixels.insert({std::uint32_t(s[0]), std::int32_t(s[1]), std::int32_t(x)}).second)
                return "span " + std::to_string(k) + " (" + rowText(s) + ") lists pixel (" +
                       formatNumber(x) + ", " + formatNumber(s[1]) + ") of triangle " +
                       formatNumber(s[0]) + " a second time";
    }
    (void)height;
    return std::nullopt;
}

using Winners = std::map<std::pair<std::int32_t, std::int32_t>, std::pair<std::uint32_t, double>>;

std::optional<std::string> winnersOf(const std::vector<Row>& rows, Winners& out) {
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const Row& r = rows[k];
        if (!whole(r[0], -1e9, 1e9) || !whole(r[1], -1e9, 1e9) || !whole(r[2], 0, 4e9))
            return "pixel " + std::to_string(k) + " (" + rowText(r) +
                   ") is not 'x y t z' with whole x, y and t";
        if (!out.emplace(std::make_pair(std::int32_t(r[1]), std::int32_t(r[0])),
                         std::make_pair(std::uint32_t(r[2]), r[3]))
                 .second)
            return "pixel (" + formatNumber(r[0]) + ", " + formatNumber(r[1]) + ") is listed twice";
    }
    return std::nullopt;
}

bool sameWinner(const std::pair<std::uint32_t, double>& a,
                const std::pair<std::uint32_t, double>& b, double& error) {
    error = std::abs(a.second - b.second);
    return a.first == b.first && error <= 1e-6 * std::max(1.0, std::abs(b.second));
}

}  // namespace

StageResult StageCheck::judgeScan(const std::vector<Record>& answer) const {
    const Data& d = *m_data;
    const int w = d.scene->width, h = d.scene->height;
    std::vector<Row> triangles;
    for (const rl::ScreenTriangle& t : d.projection.triangles) {
        const auto p = rl::screenVertices(d.projection, t);
        triangles.push_back({p[0].x, p[0].y, p[1].x, p[1].y, p[2].x, p[2].y});
    }
    std::set<Pixel> theirs, ours;
    if (auto bad = pixelsOf(answer[0].rows, triangles.size(), w, h, theirs))
        return broken(Stage::Scan, *bad);
    for (std::uint32_t t = 0; t < d.scan.triangleCount(); ++t)
        for (std::uint32_t s = d.scan.spanStart[t]; s < d.scan.spanStart[t + 1]; ++s)
            for (std::int32_t x = d.scan.spans[s].xBegin; x < d.scan.spans[s].xEnd; ++x)
                ours.insert({t, d.scan.spans[s].y, x});
    StageResult result;
    result.stage = Stage::Scan;
    result.tolerance = "exact: the same pixels";
    std::vector<Pixel> differ;
    std::set_symmetric_difference(theirs.begin(), theirs.end(), ours.begin(), ours.end(),
                                  std::back_inserter(differ));
    std::set<Pixel> all = ours;
    all.insert(theirs.begin(), theirs.end());
    result.elements = all.size();
    result.differing = differ.size();
    if (differ.empty()) return result;
    result.verdict = Verdict::Failed;
    for (const Pixel& p : differ) {
        if (result.departures.size() >= kMostDepartures) break;
        const rl::dvec2 at(std::get<2>(p), std::get<1>(p));
        result.departures.push_back(
            {ours.count(p) ? Departure::Kind::OnlyOurs : Departure::Kind::OnlyTheirs, at, at});
    }
    const auto [t, y, x] = differ.front();
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
    const bool covered = ours.count(differ.front()) > 0;
    result.first = Divergence{
        "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") of triangle " +
            std::to_string(t),
        covered ? "not covered" : "covered", covered ? "covered" : "not covered",
        "the sample (" + std::to_string(x) + ", " + std::to_string(y) + ") against the edges of (" +
            rowText(r) + "): " + edges + "; inside when all three are >= 0"};
    for (const Alternative& a : scanMistakes(triangles, w, h)) {
        std::set<Pixel> pixels;
        if (!pixelsOf(a.rows, triangles.size(), w, h, pixels) && pixels == theirs) {
            result.likelyCause = a.cause;
            break;
        }
    }
    return result;
}

StageResult StageCheck::judgeZBuffer(const std::vector<Record>& answer) const {
    const Data& d = *m_data;
    Winners theirs, ours;
    if (auto bad = winnersOf(answer[0].rows, theirs)) return broken(Stage::ZBuffer, *bad);
    for (std::int32_t y = 0; y < d.scene->height; ++y)
        for (std::int32_t x = 0; x < d.scene->width; ++x)
            if (const std::uint32_t t = d.depth.triangle.at(x, y); t != rl::kNoTriangle)
                ours[{y, x}] = {t, double(d.depth.depth.at(x, y))};
    StageResult result;
    result.stage = Stage::ZBuffer;
    result.tolerance = "the same triangle, its z within 1e-6 times its size (at least 1e-6)";
    std::set<std::pair<std::int32_t, std::int32_t>> keys;
    for (const auto& [k, v] : ours) keys.insert(k);
    for (const auto& [k, v] : theirs) keys.insert(k);
    result.elements = keys.size();
    const auto show = [](const Winners& w, const std::pair<std::int32_t, std::int32_t>& k) {
        const auto it = w.find(k);
        return it == w.end() ? std::string("no fragment kept")
                             : "triangle " + std::to_string(it->second.first) +
                                   ", z = " + formatNumber(it->second.second);
    };
    for (const auto& k : keys) {
        const auto a = theirs.find(k), b = ours.find(k);
        double error = 0.0;
        if (a != theirs.end() && b != ours.end() && sameWinner(a->second, b->second, error)) {
            result.largestError = std::max(result.largestError, error);
            continue;
        }
        if (result.departures.size() < kMostDepartures) {
            const rl::dvec2 at(k.second, k.first);
            const auto kind = a == theirs.end() ? Departure::Kind::OnlyOurs
                              : b == ours.end() ? Departure::Kind::OnlyTheirs
                                                : Departure::Kind::Different;
            result.departures.push_back({kind, at, at});
        }
        if (result.differing++ > 0) continue;
        std::string order;
        for (const Fragment& f : d.ours.fragments)
            if (f.x == k.second && f.y == k.first) {
                if (!order.empty()) order += ", ";
                order += "triangle " + std::to_string(f.t) + " z = " + formatNumber(f.z);
            }
        result.first =
            Divergence{"pixel (" + std::to_string(k.second) + ", " + std::to_string(k.first) + ")",
                       show(theirs, k), show(ours, k),
                       "its fragments in drawing order: " + order +
                           "; the least z is kept, the earlier on a tie"};
    }
    if (result.differing == 0) return result;
    result.verdict = Verdict::Failed;
    for (const Alternative& a : zbufferMistakes(d.ours.fragments)) {
        Winners w;
        if (winnersOf(a.rows, w) || w.size() != theirs.size()) continue;
        bool all = true;
        for (auto it = w.begin(), jt = theirs.begin(); all && it != w.end(); ++it, ++jt) {
            double error = 0.0;
            all = it->first == jt->first && sameWinner(jt->second, it->second, error);
        }
        if (all) {
            result.likelyCause = a.cause;
            break;
        }
    }
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

StageResult StageCheck::judgeFrame(const std::vector<Record>& answer) const {
    const rl::Rgba8Image& ours = m_data->frame.image;
    const Record& image = answer[0];
    if (image.numbers[0] != ours.width || image.numbers[1] != ours.height)
        return broken(Stage::Frame, "their image is " + formatNumber(image.numbers[0]) + "x" +
                                        formatNumber(image.numbers[1]) +
                                        ", the request asked for " + std::to_string(ours.width) +
                                        "x" + std::to_string(ours.height));
    for (std::size_t y = 0; y < image.rows.size(); ++y)
        for (std::size_t i = 0; i < image.rows[y].size(); ++i)
            if (!whole(image.rows[y][i], 0, 255))
                return broken(Stage::Frame, "row " + std::to_string(y) + " of their image holds " +
                                                formatNumber(image.rows[y][i]) + " (number " +
                                                std::to_string(i + 1) + "), not a whole 0..255");
    const rl::Rgba8Image theirs = theirImage(answer);
    StageResult result;
    result.stage = Stage::Frame;
    result.tolerance =
        "1 in each channel (the lecture's colours are floats: a byte may fall the other side of a "
        "whole number)";
    result.elements = std::size_t(ours.width) * std::size_t(ours.height);
    for (int y = 0; y < ours.height; ++y)
        for (int x = 0; x < ours.width; ++x) {
            const std::uint8_t* a = theirs.pixel(x, y);
            const std::uint8_t* b = ours.pixel(x, y);
            int error = 0;
            for (int k = 0; k < 3; ++k) error = std::max(error, std::abs(int(a[k]) - int(b[k])));
            result.largestError = std::max(result.largestError, double(error));
            if (error <= 1) continue;
            if (result.departures.size() < kMostDepartures)
                result.departures.push_back(
                    {Departure::Kind::Different, rl::dvec2(x, y), rl::dvec2(x, y)});
            if (result.differing++ > 0) continue;
            const auto rgb = [](const std::uint8_t* p) {
                return std::to_string(p[0]) + " " + std::to_string(p[1]) + " " +
                       std::to_string(p[2]);
            };
            result.first =
                Divergence{"pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")", rgb(a),
                           rgb(b), "the lecture's render of the whole frame"};
        }
    if (result.differing == 0) return result;
    result.verdict = Verdict::Failed;
    // Handed to compare: the mistakes that explain their image, in the order they apply.
    if (auto comparison = rl::compareWithOurs(m_data->frame, theirs, rl::CompareOptions{1})) {
        std::string causes;
        for (const rl::Finding& f : comparison->diagnosis) {
            if (!causes.empty()) causes += "; then ";
            causes += f.title.english();
        }
        if (!causes.empty() && comparison->mostlyUnexplained())
            causes += " (most of the difference stays unexplained)";
        if (!causes.empty()) result.likelyCause = "compare: " + causes;
    }
    return result;
}

}  // namespace rasterlab::check
