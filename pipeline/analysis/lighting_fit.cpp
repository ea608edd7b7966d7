#include "lighting_fit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>

#include "pipeline/stages/camera_basis.h"
#include "pipeline/stages/shading.h"
#include "pipeline/stages/view_transform.h"

namespace rl {

namespace {

// One sampled pixel: where it is, its normal turned toward the viewer, and their colour in
// byte units (a truncated byte b stands for b + 0.5).
struct Sample {
    dvec3 p, n, v;
    std::array<double, 3> theirs{};
};

// The parameters searched: the light's view position and log n.
using Point = std::array<double, 4>;

// A, D and S per channel for the light and n given, and the sum of squared residuals.
struct Solved {
    std::array<dvec3, 3> ads{};  // per channel: (A, D, S)
    double sse = 0.0;
};

void factors(const Sample& s, const dvec3& light, double n, double& diffuse, double& specular) {
    const dvec3 l = glm::normalize(light - s.p);
    const double nDotL = glm::dot(s.n, l);
    diffuse = specular = 0.0;
    if (!(nDotL >= 0.0)) return;
    diffuse = nDotL;
    const double rDotV = glm::dot(2.0 * nDotL * s.n - l, s.v);
    if (rDotV > 0.0) specular = std::pow(rDotV, n);
}

Solved solve(const std::vector<Sample>& samples, const Point& x) {
    const dvec3 light(x[0], x[1], x[2]);
    const double n = std::exp(x[3]);
    // Normal equations of [1 f1 f2] (A D S) = t, shared by the channels.
    dmat3 m(0.0);
    std::array<dvec3, 3> rhs{};
    std::vector<std::pair<double, double>> f(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) {
        factors(samples[i], light, n, f[i].first, f[i].second);
        const dvec3 row(1.0, f[i].first, f[i].second);
        m += glm::outerProduct(row, row);
        for (int c = 0; c < 3; ++c) rhs[std::size_t(c)] += row * samples[i].theirs[std::size_t(c)];
    }
    Solved out;
    // A nearly singular system (no highlight in view, say): S is left at 0.
    const bool specular = std::abs(glm::determinant(m)) > 1e-9 * (m[0][0] * m[1][1] * m[2][2] + 1e-30);
    for (int c = 0; c < 3; ++c) {
        if (specular) {
            out.ads[std::size_t(c)] = glm::inverse(m) * rhs[std::size_t(c)];
        } else {
            const glm::dmat2 m2(m[0][0], m[0][1], m[1][0], m[1][1]);
            const dvec2 ad = std::abs(glm::determinant(m2)) > 0.0
                                 ? glm::inverse(m2) * dvec2(rhs[std::size_t(c)])
                                 : dvec2(0.0);
            out.ads[std::size_t(c)] = dvec3(ad, 0.0);
        }
    }
    for (std::size_t i = 0; i < samples.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const dvec3& k = out.ads[std::size_t(c)];
            const double r = k.x + k.y * f[i].first + k.z * f[i].second -
                             samples[i].theirs[std::size_t(c)];
            out.sse += r * r;
        }
    return out;
}

// Nelder-Mead from start, with the first steps `step`.
Point minimise(const std::function<double(const Point&)>& cost, const Point& start,
               const Point& step, int iterations) {
    std::array<Point, 5> simplex;
    std::array<double, 5> value{};
    for (std::size_t k = 0; k < 5; ++k) {
        simplex[k] = start;
        if (k > 0) simplex[k][k - 1] += step[k - 1];
        value[k] = cost(simplex[k]);
    }
    for (int it = 0; it < iterations; ++it) {
        std::array<std::size_t, 5> order{0, 1, 2, 3, 4};
        std::sort(order.begin(), order.end(), [&](auto a, auto b) { return value[a] < value[b]; });
        const std::size_t worst = order[4];
        Point centre{};
        for (std::size_t k = 0; k < 4; ++k)
            for (std::size_t d = 0; d < 4; ++d) centre[d] += simplex[order[k]][d] / 4.0;
        const auto along = [&](double t) {
            Point p;
            for (std::size_t d = 0; d < 4; ++d) p[d] = centre[d] + t * (simplex[worst][d] - centre[d]);
            return p;
        };
        const Point reflected = along(-1.0);
        const double r = cost(reflected);
        if (r < value[order[0]]) {
            const Point expanded = along(-2.0);
            const double e = cost(expanded);
            simplex[worst] = e < r ? expanded : reflected;
            value[worst] = std::min(e, r);
        } else if (r < value[order[3]]) {
            simplex[worst] = reflected;
            value[worst] = r;
        } else {
            const Point contracted = along(0.5);
            const double c = cost(contracted);
            if (c < value[worst]) {
                simplex[worst] = contracted;
                value[worst] = c;
            } else {
                for (std::size_t k = 1; k < 5; ++k) {
                    for (std::size_t d = 0; d < 4; ++d)
                        simplex[order[k]][d] =
                            simplex[order[0]][d] + 0.5 * (simplex[order[k]][d] - simplex[order[0]][d]);
                    value[order[k]] = cost(simplex[order[k]]);
                }
            }
        }
    }
    const auto best = std::min_element(value.begin(), value.end()) - value.begin();
    return simplex[std::size_t(best)];
}

}  // namespace

namespace {

bool litByCourse(const Draw& d) { return d.lighting == LightingModel::CoursePhong; }

// The material of the draws the fit applies to; none, with the reason, when the scene has no
// course camera and one positional light, or its lit draws are not all Phong-shaded in one
// material.
const Material* fittableMaterial(const FrameTrace& frame, Message& reason) {
    const Scene& scene = *frame.scene;
    const auto firstLit = std::find_if(scene.draws.begin(), scene.draws.end(), litByCourse);
    if (scene.lights.size() != 1 || scene.lights[0].pWorld.w == 0.0 ||
        firstLit == scene.draws.end() || !frame.cameraBasis || frame.cameraBasis->skipped ||
        frame.normals->skipped) {
        reason = "the lighting is fitted for a course camera and one positional light of the "
                 "course's model"_msg;
        return nullptr;
    }
    const Material& m = firstLit->material;
    for (const Draw& d : scene.draws)
        if (litByCourse(d) && (d.material.od != m.od || d.material.kd != m.kd ||
                               d.material.ka != m.ka || d.material.ks != m.ks ||
                               d.material.shininess != m.shininess ||
                               d.colour != ColourSource::Material ||
                               d.shading != ShadingModel::Phong)) {
            reason = "the lighting is fitted for Phong-shaded draws of one material"_msg;
            return nullptr;
        }
    return &m;
}

// A grid of about 3,000 of our covered pixels inside a triangle (its four neighbours on the
// same one) of a course-lit draw, where none of their channels is clamped.
std::vector<Sample> samplesOf(const OurFrame& ours, const Rgba8Image& theirs) {
    const FrameTrace& frame = *ours.trace;
    const Scene& scene = *frame.scene;
    const FrameLighting lighting(scene, *frame.view, *frame.normals, *frame.projection);
    const DepthTest& depth = *frame.depth;
    const bool truncated = scene.conventions.rounding == ByteRounding::Truncate;
    std::size_t covered = 0;
    for (int y = 0; y < theirs.height; ++y)
        for (int x = 0; x < theirs.width; ++x) covered += ours.covered(x, y) ? 1 : 0;
    const int stride = std::max(1, int(std::sqrt(double(covered) / 3000.0)));
    std::vector<Sample> samples;
    if (!depth.barycentricsKept) return samples;
    for (int y = 1; y + 1 < theirs.height; y += stride) {
        for (int x = 1; x + 1 < theirs.width; x += stride) {
            const std::uint32_t t = depth.triangle.at(x, y);
            if (t == kNoTriangle || depth.triangle.at(x - 1, y) != t ||
                depth.triangle.at(x + 1, y) != t || depth.triangle.at(x, y - 1) != t ||
                depth.triangle.at(x, y + 1) != t)
                continue;
            const ScreenTriangle& tri = frame.projection->triangles[t];
            if (!litByCourse(scene.draws[tri.draw])) continue;
            const std::uint8_t* b = theirs.pixel(x, y);
            if (std::any_of(b, b + 3, [](std::uint8_t v) { return v == 0 || v == 255; })) continue;
            const vec2 w = depth.barycentric.at(x, y);
            float beta = w.x, gamma = w.y;
            lighting.attributeWeights(tri, beta, gamma);
            Sample s;
            s.p = dvec3(interpolate(lighting.vertices(tri.draw).pView, tri.v, beta, gamma));
            const dvec3 n = dvec3(lighting.normalAt(tri, beta, gamma));
            if (!(glm::length(n) > 0.0) || !(glm::length(s.p) > 0.0)) continue;
            s.v = -glm::normalize(s.p);
            s.n = glm::normalize(n);
            if (scene.conventions.flipNormalsTowardViewer && glm::dot(s.v, s.n) < 0.0) s.n = -s.n;
            for (int c = 0; c < 3; ++c) s.theirs[std::size_t(c)] = b[c] + (truncated ? 0.5 : 0.0);
            samples.push_back(s);
        }
    }
    return samples;
}

// The squared difference of a sample's three channels from the model with this light, n and
// (A, D, S) per channel; clamped to the bytes' range when asked (our own parameters).
double squaredError(const Sample& s, const dvec3& light, double n,
                    const std::array<dvec3, 3>& ads, bool clamped) {
    double f1, f2, sum = 0.0;
    factors(s, light, n, f1, f2);
    for (std::size_t c = 0; c < 3; ++c) {
        const double model = ads[c].x + ads[c].y * f1 + ads[c].z * f2;
        const double e = (clamped ? std::clamp(model, 0.0, 255.0) : model) - s.theirs[c];
        sum += e * e;
    }
    return sum;
}

// The best light and log n from each start; then the worst tenth of the samples left out of
// `used`, and the fit again from there.
Point fitBest(std::vector<Sample>& used, const std::vector<dvec3>& starts, double logN,
              const Point& step) {
    const auto cost = [&](const Point& x) { return solve(used, x).sse; };
    Point best{};
    double bestCost = std::numeric_limits<double>::infinity();
    for (const dvec3& s : starts) {
        const Point x = minimise(cost, {s.x, s.y, s.z, logN}, step, 150);
        const double c = cost(x);
        if (c < bestCost) bestCost = c, best = x;
    }
    const Solved solved = solve(used, best);
    std::vector<std::pair<double, std::size_t>> residual;
    for (std::size_t i = 0; i < used.size(); ++i)
        residual.push_back({squaredError(used[i], dvec3(best[0], best[1], best[2]),
                                         std::exp(best[3]), solved.ads, false),
                            i});
    std::sort(residual.begin(), residual.end());
    std::vector<Sample> kept;
    for (std::size_t k = 0; k < residual.size() * 9 / 10; ++k)
        kept.push_back(used[residual[k].second]);
    used = std::move(kept);
    return minimise(cost, best, step, 150);
}

// Each value, ours and theirs, with the spread of four fits on halves of the samples as its
// uncertainty.
void addValues(LightingFit& out, const std::vector<Sample>& used, const Point& best,
               const Point& step, const Solved& fitted, const std::array<dvec3, 3>& oursAds,
               double oursN, double scale, double toByte) {
    std::array<Point, 4> halves{};
    std::array<Solved, 4> halfSolved{};
    for (std::size_t h = 0; h < 4; ++h) {
        std::vector<Sample> half;
        for (std::size_t i = 0; i < used.size(); ++i)
            if (h < 2 ? i % 2 == h : (i < used.size() / 2) == (h == 2)) half.push_back(used[i]);
        const auto halfCost = [&](const Point& x) { return solve(half, x).sse; };
        halves[h] = minimise(halfCost, best, step, 100);
        halfSolved[h] = solve(half, halves[h]);
    }
    const auto spread = [&](const std::function<double(std::size_t)>& of) {
        double mean = 0.0, square = 0.0;
        for (std::size_t h = 0; h < 4; ++h) mean += of(h) / 4.0;
        for (std::size_t h = 0; h < 4; ++h) square += (of(h) - mean) * (of(h) - mean) / 3.0;
        return std::sqrt(square);
    };
    const auto add = [&](std::string name, double o, double t, double sd, double least) {
        const bool apart = std::abs(t - o) > least;
        out.values.push_back({std::move(name), o, t, sd, apart, apart && std::abs(t - o) > 3.0 * sd});
    };
    const char* axes = "xyz";
    for (std::size_t k = 0; k < 3; ++k)
        add(std::string("light ") + axes[k] + " (view)", out.lightOurs[int(k)], best[k],
            spread([&](std::size_t h) { return halves[h][k]; }), 0.02 * scale);
    add("n", oursN, std::exp(best[3]),
        spread([&](std::size_t h) { return std::exp(halves[h][3]); }), 0.05 * oursN);
    const char* channels = "RGB";
    const char* terms[] = {"ambient Ia*ka", "diffuse Il*Od*kd", "specular Il*ks"};
    for (int term = 0; term < 3; ++term)
        for (std::size_t c = 0; c < 3; ++c)
            add(std::string(terms[term]) + ' ' + channels[c], oursAds[c][term] / toByte,
                fitted.ads[c][term] / toByte,
                spread([&](std::size_t h) { return halfSolved[h].ads[c][term] / toByte; }),
                2.0 / toByte);
}

// The pairs of coordinates a light read in the wrong order may have swapped.
constexpr std::array<std::pair<int, int>, 3> kSwaps{{{0, 1}, {0, 2}, {1, 2}}};

// What the fitted light and n match: the light at its world position, at [I] Pl, ours with a
// coordinate negated or two swapped; n halved.
void nameMatches(LightingFit& out, const dvec3& inWorld, const dvec3& withoutC, double scale) {
    const double near = std::max(3.0 * out.values[0].uncertainty, 0.05 * scale);
    if (glm::distance(out.lightTheirs, out.lightOurs) > near) {
        if (glm::distance(out.lightTheirs, inWorld) <= near) {
            out.matches = Mistake::LightInWorld;
            out.findings.push_back("the fitted light is at the light's world position: it was "
                                   "not taken to view coordinates"_msg);
        } else if (glm::distance(out.lightTheirs, withoutC) <= near) {
            out.matches = Mistake::LightWithoutC;
            out.findings.push_back("the fitted light is at [I] Pl: C was not subtracted"_msg);
        } else {
            for (int k = 0; k < 3; ++k) {
                dvec3 negated = out.lightOurs;
                negated[k] = -negated[k];
                if (glm::distance(out.lightTheirs, negated) <= near)
                    out.findings.push_back("the fitted light is ours with %1 negated"_msg(
                        std::string(1, "xyz"[k])));
            }
            for (const auto& [a, b] : kSwaps) {
                dvec3 swapped = out.lightOurs;
                std::swap(swapped[a], swapped[b]);
                if (glm::distance(out.lightTheirs, swapped) <= near)
                    out.findings.push_back("the fitted light is ours with %1 and %2 swapped"_msg(
                        std::string(1, "xyz"[a]), std::string(1, "xyz"[b])));
            }
        }
    }
    const FittedValue& n = out.values[3];
    if (n.differs && std::abs(n.theirs - 0.5 * n.ours) <= std::max(3.0 * n.uncertainty, 0.05 * n.ours))
        out.findings.push_back("the fitted n is half of ours: n halved"_msg);
}

}  // namespace

LightingFit fitLighting(const OurFrame& ours, const Rgba8Image& theirs) {
    LightingFit out;
    const FrameTrace& frame = *ours.trace;
    const Scene& scene = *frame.scene;
    const Material* material = fittableMaterial(frame, out.reason);
    if (!material) return out;
    std::vector<Sample> used = samplesOf(ours, theirs);
    if (used.size() < 50) {
        out.reason = "too few unclamped pixels inside triangles to fit the lighting"_msg;
        return out;
    }
    // The starts: our light, where the transform mistakes put it, each coordinate of ours
    // negated.
    const dvec3 world = dvec3(scene.lights[0].pWorld) / scene.lights[0].pWorld.w;
    out.lightOurs = dvec3(frame.view->lights[0].pView);
    const dvec3 withoutC = dvec3(frame.cameraBasis->viewFromWorld * dvec4(world, 0.0));
    std::vector<dvec3> starts = {out.lightOurs, world, withoutC};
    for (int k = 0; k < 3; ++k) {
        dvec3 negated = out.lightOurs;
        negated[k] = -negated[k];
        starts.push_back(negated);
    }
    const double scale = std::max(1.0, glm::length(out.lightOurs));
    const Point step = {0.1 * scale, 0.1 * scale, 0.1 * scale, 0.3};
    const Point best =
        fitBest(used, starts, std::log(std::max(1.0f, material->shininess)), step);
    const Solved fitted = solve(used, best);
    out.fitted = true;
    out.samples = used.size();
    out.lightTheirs = dvec3(best[0], best[1], best[2]);
    out.rmsFitted = std::sqrt(fitted.sse / (3.0 * double(used.size())));
    // Our own parameters, in byte units, on the same samples.
    const double toByte = 255.0 / scene.conventions.colourScale;
    std::array<dvec3, 3> oursAds{};
    for (int c = 0; c < 3; ++c) {
        const double il = scene.lights[0].intensity[c];
        oursAds[std::size_t(c)] = dvec3(scene.ambientIntensity[c] * material->ka,
                                        il * material->od[c] * material->kd[c],
                                        il * material->ks) *
                                  toByte;
    }
    double sse = 0.0;
    for (const Sample& s : used)
        sse += squaredError(s, out.lightOurs, material->shininess, oursAds, true);
    out.rmsOurs = std::sqrt(sse / (3.0 * double(used.size())));
    addValues(out, used, best, step, fitted, oursAds, material->shininess, scale, toByte);
    nameMatches(out, world, withoutC, scale);
    return out;
}

std::shared_ptr<const Scene> sceneWithFit(const Scene& scene, const CameraBasis& basis,
                                          const LightingFit& fit) {
    auto out = std::make_shared<Scene>(scene);
    out->lights[0].pWorld = glm::inverse(basis.viewFromWorld) * dvec4(fit.lightTheirs, 1.0);
    const auto value = [&](std::size_t i) { return float(fit.values[i].theirs); };
    const Material& ours = std::find_if(scene.draws.begin(), scene.draws.end(), [](const Draw& d) {
                               return d.lighting == LightingModel::CoursePhong;
                           })->material;
    Material m = ours;
    m.shininess = value(3);
    vec3& il = out->lights[0].intensity;
    const bool highlight = value(10) > 1e-6f && value(11) > 1e-6f && value(12) > 1e-6f;
    m.ks = highlight ? (ours.ks > 0.0f ? ours.ks : 1.0f) : 0.0f;
    for (int c = 0; c < 3; ++c) {
        // A = Ia ka (or the emission when ka is 0), S = Il ks, D = Il Od kd.
        if (ours.ka > 0.0f)
            out->ambientIntensity[c] = value(4 + std::size_t(c)) / ours.ka;
        else
            m.emission[c] = value(4 + std::size_t(c));
        if (highlight) il[c] = value(10 + std::size_t(c)) / m.ks;
        const float lit = il[c] * ours.od[c];
        m.kd[c] = lit != 0.0f ? value(7 + std::size_t(c)) / lit : 0.0f;
    }
    for (Draw& d : out->draws)
        if (d.lighting == LightingModel::CoursePhong) d.material = m;
    return out;
}

Result<ImageComparison> withFittedLighting(ImageComparison base, const OurFrame& ours,
                                           const Rgba8Image& theirs, const CompareOptions& options,
                                           const LightingFit& fit) {
    if (!fit.explainsBetter() || fit.matches || base.differing == 0 || base.unlit) return base;
    const double whole = double(base.difference);
    // The catalogue explains all but what a finding must remove at least: nothing to gain.
    if (base.unexplained * whole <= kLeastShare * whole) return base;
    auto frame = renderOurFrame(sceneWithFit(*ours.trace->scene, *ours.trace->cameraBasis, fit));
    if (!frame) return frame.error();
    auto onIt = compareWithOurs(frame.value(), theirs, options);
    if (!onIt) return onIt.error();
    const double left = onIt->unexplained * double(onIt->difference);
    if (left + kLeastShare * whole >= base.unexplained * whole) return base;
    // The title: each value apart from ours, theirs (with its uncertainty) and ours.
    std::string values;
    for (const FittedValue& v : fit.values) {
        if (!v.apart) continue;
        char text[160];
        std::snprintf(text, sizeof text, "%s%s %.4g +- %.2g (ours %.4g)", values.empty() ? "" : ", ",
                      v.name.c_str(), v.theirs, v.uncertainty, v.ours);
        values += text;
    }
    Finding f;
    f.mistake = f.slip.mistake = Mistake::FittedLighting;
    f.title = "their lighting, fitted to their colours: %1"_msg(values);
    f.advice = "compare the light's position, the intensities and the coefficients your "
               "program uses with the fitted ones"_msg;
    return firstFinding(std::move(base), ours, frame->image, std::move(f), std::move(onIt.value()),
                        theirs);
}

}  // namespace rl
