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

#include "app/check/stage_check_data.h"
#include "pipeline/core/format.h"
#include "pipeline/stages/phong.h"

namespace rasterlab::check {

using rl::dvec3;
using rl::vec3;

namespace {

constexpr std::size_t kMostSamples = 400;  // vertices lit by the lighting request, each twice

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
    if (d.mesh && d.mesh->triangles.size() >= (std::size_t(1) << 22))
        return "the protocol carries at most 4,194,303 triangles";
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

// A unit N with N.L = nl and N.V = nv (L and V unit), or none when there is none.
std::optional<dvec3> withDots(const dvec3& l, const dvec3& v, double nl, double nv) {
    const dvec3 w0 = v - glm::dot(v, l) * l;
    if (glm::length(w0) < 1e-3) return std::nullopt;
    const dvec3 w = glm::normalize(w0);
    const double beta = (nv - nl * glm::dot(l, v)) / glm::dot(w, v);
    const double rest = 1.0 - nl * nl - beta * beta;
    if (rest < 0.0) return std::nullopt;
    return nl * l + beta * w + std::sqrt(rest) * glm::cross(l, w);
}

// The small values the special cases' samples put each dot product at: they tell a comparison
// with 0 from one with a small epsilon, and bracket the epsilon.
constexpr double kGrazing[] = {1e-5, 3e-5, 1e-4, 3e-4, 7e-4, 1.5e-3, 3e-3, 7e-3, 1.5e-2, 3e-2, 7e-2};

// Samples made for the special cases, at the first vertex: V.N, N.L and R.V each just on the
// lit side of 0 at every grazing value; and one with N.L < 0 and R.V > 0 (the specular term
// the N.L test leaves out), halfway to the light.
void addDesignedSamples(StageCheck::Data& data) {
    if (data.view.pView[0].empty()) return;
    const dvec3 p = rl::cartesian(data.view.pView[0][0]);
    const dvec3 v = glm::normalize(-p);
    const dvec3 l = glm::normalize(dvec3(data.view.lights[0].pView) - p);
    const auto add = [&](const dvec3& n) {
        data.ours.samples.push_back({vec3(p), vec3(n), std::nullopt, false});
    };
    dvec3 n;
    for (double e : kGrazing) {
        if (leaning(v, l, e, n)) add(n);
        if (leaning(l, v, e, n)) add(n);
        // R.V = 2 (N.L)(N.V) - L.V = e with N.L = c: N.V = (e + L.V) / 2c, clear of 0.
        for (double c : {0.5, 0.8, 0.3, 0.95}) {
            const double nv = (e + glm::dot(l, v)) / (2.0 * c);
            if (nv < 0.1) continue;
            if (const auto found = withDots(l, v, c, nv)) {
                add(*found);
                break;
            }
        }
    }
    // Halfway between the eye and the light, L = -V: a normal with N.V = 0.3 has N.L = -0.3
    // and R.V = 1 - 2 (0.3)^2 = 0.82.
    const dvec3 light(data.view.lights[0].pView);
    if (glm::length(light) > 1e-6) {
        const dvec3 half = 0.5 * light;
        const dvec3 toEye = glm::normalize(-half);
        dvec3 side = glm::cross(toEye, dvec3(0.0, 1.0, 0.0));
        if (glm::length(side) < 1e-3) side = glm::cross(toEye, dvec3(1.0, 0.0, 0.0));
        const dvec3 grazing = 0.3 * toEye + std::sqrt(1.0 - 0.09) * glm::normalize(side);
        data.ours.samples.push_back({vec3(half), vec3(grazing), std::nullopt, false});
    }
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
    addDesignedSamples(data);
    const rl::Material& m = data.draw->material;
    for (const Sample& s : data.ours.samples) {
        const rl::PhongSample p = rl::phong(m, m.od, data.scene->ambientIntensity,
                                            data.view.lights.data(), 1, s.p, s.n, true);
        const vec3 c = glm::min(p.colour(), vec3(255.0f));
        data.colours.push_back(rowOf(c));
    }
}

// Two frames alike to a byte on all but 0.1% of their pixels.
bool framesAgree(const rl::Rgba8Image& a, const rl::Rgba8Image& b) {
    std::size_t apart = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int k = 0; k < 3; ++k)
                if (std::abs(int(a.pixel(x, y)[k]) - int(b.pixel(x, y)[k])) > 1) {
                    ++apart;
                    break;
                }
    return apart * 1000 <= std::size_t(a.width) * std::size_t(a.height);
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
    // The protocol's frame is seed 000's, Phong at every pixel, whatever a lesson shows.
    if (scene->draws[0].shading != rl::ShadingModel::Phong) {
        auto phong = std::make_shared<rl::Scene>(*scene);
        phong->draws[0].shading = rl::ShadingModel::Phong;
        scene = phong;
    }
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
    data->stagesFrameTrusted = framesAgree(modelFrame(data->frameScene(), {}), data->frame.image);
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
    const double width = double(scene.width), height = double(scene.height);
    for (Row s : spans) {
        // Spans that are not whole pixels are theirs to explain (the scan stage's judge does);
        // no fragment is made of them, nor of a pixel off the screen (the protocol sends none).
        if (!whole(s[0], 0, double(projection.triangles.size()) - 1) ||
            !whole(s[1], 0, height - 1) || !whole(s[2], -kFarthest, kFarthest) ||
            !whole(s[3], -kFarthest, kFarthest))
            continue;
        s[2] = std::max(s[2], 0.0);
        s[3] = std::min(s[3], width - 1);
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

std::shared_ptr<const StageCheck::Inputs> StageCheck::chainedInputs(const Answers& theirs) const {
    const Data& d = *m_data;
    auto made = std::make_shared<Inputs>(d.ours);
    Inputs& in = *made;
    const auto answer = [&](Stage stage) -> const std::vector<Record>* {
        const auto it = theirs.find(stage);
        if (it == theirs.end()) return nullptr;
        in.chained = true;
        return &it->second;
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
    return made;
}

Request StageCheck::request(Stage stage) const {
    return request(stage, m_data->ours);
}

Request StageCheck::chainedRequest(Stage stage, const Inputs& in) const {
    return request(stage, in);
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
            r.addList("triangles", d.screenTriangles(in.screen));
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

std::vector<Row> StageCheck::Data::screenTriangles(const std::vector<Row>& screen) const {
    std::vector<Row> rows;
    for (const rl::ScreenTriangle& t : projection.triangles) {
        const Row &a = screen[t.v[0]], &b = screen[t.v[1]], &c = screen[t.v[2]];
        rows.push_back({a[0], a[1], b[0], b[1], c[0], c[1]});
    }
    return rows;
}

std::string StageResult::causes() const {
    std::string out;
    for (const StageFinding& f : findings) {
        if (!out.empty()) out += "; then ";
        out += f.cause;
    }
    return out;
}

StageResult StageCheck::judge(Stage stage, const std::vector<Record>& answer,
                              const std::vector<StageResult>& earlier) const {
    return judge(stage, answer, m_data->ours, earlier);
}

StageResult StageCheck::judgeChained(Stage stage, const std::vector<Record>& answer,
                                     const Inputs& in,
                                     const std::vector<StageResult>& earlier) const {
    return judge(stage, answer, in, earlier);
}

StageResult StageCheck::judge(Stage stage, const std::vector<Record>& answer, const Inputs& in,
                              const std::vector<StageResult>& earlier) const {
    switch (stage) {
        case Stage::Basis:
            return judgeBasis(answer);
        case Stage::View:
            return judgeView(answer, in);
        case Stage::Normals:
            return judgeNormals(answer, in);
        case Stage::Projection:
            return judgeProjection(answer, in);
        case Stage::Scan:
            return judgeScan(answer, in);
        case Stage::ZBuffer:
            return judgeZBuffer(answer, in);
        case Stage::Lighting:
            return judgeLighting(answer, in);
        case Stage::Frame:
            return judgeFrame(answer, earlier);
    }
    StageResult r;
    r.stage = stage;
    r.verdict = Verdict::Broken;
    r.problem = "unknown stage";
    return r;
}

}  // namespace rasterlab::check
