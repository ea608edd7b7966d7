#include "stability.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include "pipeline/render/frame_trace.h"
#include "pipeline/stages/normals.h"

namespace rl {

namespace {

std::vector<double> decadesFrom(int firstExponent, int lastExponent) {
    std::vector<double> values;
    const int step = lastExponent >= firstExponent ? 1 : -1;
    for (int e = firstExponent;; e += step) {
        values.push_back(std::pow(10.0, e));
        if (e == lastExponent) break;
    }
    return values;
}

// Every point, length and plane of the scene through x -> s x + t (s > 0). The view-space
// picture stays the same; view-space lengths are multiplied by s.
void moveScene(Scene& scene, double s, const dvec3& t) {
    dmat4 m(s);
    m[3] = dvec4(t, 1.0);
    for (Draw& draw : scene.draws) {
        draw.worldFromModel = m * draw.worldFromModel;
        for (dvec4& plane : draw.clipPlanes) plane.w *= s;
    }
    for (Light& light : scene.lights) light.pWorld = m * light.pWorld;
    CourseCamera& camera = *scene.camera;
    camera.c = s * camera.c + t;
    camera.d *= s;
    camera.hx *= s;
    camera.hy *= s;
    if (scene.nearPlane.fixedW) *scene.nearPlane.fixedW *= s;
}

// The camera's up hint turned to `degrees` from N, in N's plane with the original V: the same
// basis in exact arithmetic, a harder Gram-Schmidt step in floating point.
void tiltUpHint(CourseCamera& camera, double degrees) {
    const dvec3 n = glm::normalize(camera.n);
    const dvec3 across = glm::normalize(camera.v - glm::dot(camera.v, n) * n);
    const double angle = glm::radians(degrees);
    camera.v = std::cos(angle) * n + std::sin(angle) * across;
}

template <glm::length_t L>
void appendBlend(std::vector<glm::vec<L, float>>& values, const std::array<std::uint32_t, 3>& abc,
                 const dvec3& weights) {
    if (values.empty()) return;
    using D = glm::vec<L, double>;
    const D blend = weights.x * D(values[abc[0]]) + weights.y * D(values[abc[1]]) +
                    weights.z * D(values[abc[2]]);
    values.push_back(glm::vec<L, float>(blend));
}

// Each triangle abc (bc its longest edge) cut in three around an inner point p at height
// tan(angle) |bc| / 2 above the middle of bc: abp, bcp and cap, in abc's winding. bcp is a
// sliver whose angles at b and c are about `degrees`; the surface and its closedness stay.
// Attributes at p are blended with p's barycentrics; the vertex normals are given (those of
// the uncut mesh) so that the cuts do not change the shading.
std::shared_ptr<Mesh> sliverMesh(const Mesh& mesh, double degrees) {
    auto cut = std::make_shared<Mesh>(mesh);
    // Model-space vertex normals as the normals stage makes them.
    if (cut->normals.empty()) cut->normals = drawNormals(mesh, mesh.positions, dmat3(1.0)).vertex;
    for (vec3& n : cut->normals) n = glm::length(n) > 0.0f ? glm::normalize(n) : n;
    cut->triangles.clear();
    cut->triangleLines.clear();
    const double slope = std::tan(glm::radians(degrees));
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        auto abc = mesh.triangles[i];
        const int line = mesh.triangleLines.empty() ? 0 : mesh.triangleLines[i];
        auto edge = [&](int k) {
            return glm::length(dvec3(mesh.positions[abc[(k + 2) % 3]]) -
                               dvec3(mesh.positions[abc[(k + 1) % 3]]));
        };
        // Rotate (keeping the winding) so that a is opposite the longest edge.
        int longest = 0;
        for (int k = 1; k < 3; ++k)
            if (edge(k) > edge(longest)) longest = k;
        std::rotate(abc.begin(), abc.begin() + longest, abc.end());
        const dvec3 a(mesh.positions[abc[0]]), b(mesh.positions[abc[1]]), c(mesh.positions[abc[2]]);
        const double base = glm::length(c - b);
        const double height = base > 0.0 ? glm::length(glm::cross(c - b, a - b)) / base : 0.0;
        const double weightA = height > 0.0 ? slope * base / 2.0 / height : 1.0;
        if (!(weightA < 0.5)) {  // too flat already, or degenerate: left whole
            cut->triangles.push_back(abc);
            if (!mesh.triangleLines.empty()) cut->triangleLines.push_back(line);
            continue;
        }
        const dvec3 weights(weightA, (1.0 - weightA) / 2.0, (1.0 - weightA) / 2.0);
        const auto p = static_cast<std::uint32_t>(cut->positions.size());
        cut->positions.push_back(weights.x * mesh.positions[abc[0]] +
                                 weights.y * mesh.positions[abc[1]] +
                                 weights.z * mesh.positions[abc[2]]);
        appendBlend(cut->colours, abc, weights);
        appendBlend(cut->normals, abc, weights);
        cut->normals.back() = glm::normalize(cut->normals.back());
        appendBlend(cut->texcoords, abc, weights);
        cut->triangles.push_back({abc[0], abc[1], p});
        cut->triangles.push_back({abc[1], abc[2], p});
        cut->triangles.push_back({abc[2], abc[0], p});
        if (!mesh.triangleLines.empty())
            cut->triangleLines.insert(cut->triangleLines.end(), 3, line);
    }
    return cut;
}

struct WorldTriangle {
    dvec3 a, b, c;
};

template <typename F>
void forEachWorldTriangle(const Scene& scene, F&& f) {
    for (const Draw& draw : scene.draws)
        for (const auto& t : draw.mesh->triangles) {
            auto world = [&](std::uint32_t v) {
                const dvec4 p = draw.worldFromModel * draw.mesh->positions[v];
                return dvec3(p) / p.w;
            };
            f(WorldTriangle{world(t[0]), world(t[1]), world(t[2])});
        }
}

// The first light moved to `height` x the scene's size above the middle of the triangle
// nearest the eye (in front of it), on the side the eye sees.
Result<Scene> withLightAboveSurface(Scene scene, double height) {
    if (scene.lights.empty())
        return makeError(ErrorCode::Unsupported, {}, "the scene has no light to move"_msg);
    const CourseCamera& camera = *scene.camera;
    const dvec3 forward = glm::normalize(camera.n);
    dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    double nearest = std::numeric_limits<double>::infinity();
    dvec3 foot(0.0), normal(0.0);
    forEachWorldTriangle(scene, [&](const WorldTriangle& t) {
        for (const dvec3& p : {t.a, t.b, t.c}) lo = glm::min(lo, p), hi = glm::max(hi, p);
        const dvec3 middle = (t.a + t.b + t.c) / 3.0;
        const dvec3 n = glm::cross(t.b - t.a, t.c - t.a);
        const double distance = glm::length(middle - camera.c);
        if (glm::dot(middle - camera.c, forward) <= 0.0 || glm::length(n) == 0.0 ||
            distance >= nearest)
            return;
        nearest = distance;
        foot = middle;
        normal = glm::normalize(n);
        if (glm::dot(normal, camera.c - middle) < 0.0) normal = -normal;
    });
    if (!std::isfinite(nearest))
        return makeError(ErrorCode::Unsupported, {}, "no triangle is in front of the camera"_msg);
    scene.lights.front().pWorld = dvec4(foot + height * glm::length(hi - lo) * normal, 1.0);
    return scene;
}

bool looksTheSameWhenMoved(const Scene& scene) {
    for (const Light& light : scene.lights)
        if (light.attenuated()) return false;
    for (const Draw& draw : scene.draws)
        if (draw.animation) return false;
    return true;
}

}  // namespace

const std::vector<StiffnessAxisInfo>& stiffnessAxes() {
    static const std::vector<StiffnessAxisInfo> axes = {
        {StiffnessAxis::Offset, "offset", "units", decadesFrom(0, 12), true},
        {StiffnessAxis::Scale, "scale", "x", decadesFrom(-6, 6), true},
        {StiffnessAxis::Distance, "distance", "x", decadesFrom(0, -9), true},
        {StiffnessAxis::Sliver, "sliver", "degrees", decadesFrom(-1, -12), false},
        {StiffnessAxis::Shininess, "shininess", "n", decadesFrom(0, 6), false},
        {StiffnessAxis::Grazing, "grazing", "degrees", decadesFrom(-1, -12), true},
        {StiffnessAxis::LightOnSurface, "light", "x size", decadesFrom(-1, -9), false},
    };
    return axes;
}

const StiffnessAxisInfo& axisInfo(StiffnessAxis axis) {
    return stiffnessAxes()[static_cast<std::size_t>(axis)];
}

std::optional<StiffnessAxis> stiffnessAxisFromName(std::string_view name) {
    for (const StiffnessAxisInfo& info : stiffnessAxes())
        if (name == info.name) return info.axis;
    return std::nullopt;
}

Result<StiffScene> stiffenScene(const Scene& scene, StiffnessAxis axis, double value) {
    if (!scene.camera)
        return makeError(ErrorCode::Unsupported, {}, "this scene has no course camera"_msg);
    StiffScene stiff{scene, 1.0};
    Scene& s = stiff.scene;
    switch (axis) {
        case StiffnessAxis::Offset:
            moveScene(s, 1.0, dvec3(value / std::sqrt(3.0)));
            break;
        case StiffnessAxis::Scale:
            moveScene(s, value, dvec3(0.0));
            stiff.depthScale = value;
            break;
        case StiffnessAxis::Distance:
            moveScene(s, value, (1.0 - value) * s.camera->c);
            stiff.depthScale = value;
            break;
        case StiffnessAxis::Sliver:
            for (Draw& draw : s.draws) draw.mesh = sliverMesh(*draw.mesh, value);
            break;
        case StiffnessAxis::Shininess:
            for (Draw& draw : s.draws) draw.material.shininess = static_cast<float>(value);
            break;
        case StiffnessAxis::Grazing:
            tiltUpHint(*s.camera, value);
            break;
        case StiffnessAxis::LightOnSurface: {
            auto lit = withLightAboveSurface(std::move(s), value);
            if (!lit) return lit.error();
            stiff.scene = std::move(lit.value());
            break;
        }
    }
    return stiff;
}

namespace {

const std::vector<double>& sweptValues(StiffnessAxis axis, const StabilityOptions& options) {
    return options.values.empty() ? axisInfo(axis).values : options.values;
}

struct PointContext {
    const StabilityOptions& options;
    const std::vector<std::shared_ptr<const ReferenceImage>>& original;  // per rule set
    StabilityReport& report;
};

std::shared_ptr<const ReferenceImage> scaledDepths(const std::shared_ptr<const ReferenceImage>& r,
                                                   double scale) {
    if (scale == 1.0) return r;
    auto scaled = std::make_shared<ReferenceImage>(*r);
    for (int y = 0; y < scaled->depth.height(); ++y)
        for (int x = 0; x < scaled->depth.width(); ++x) scaled->depth.at(x, y) *= scale;
    return scaled;
}

StabilityPoint pointAt(StiffnessAxis axis, double value, AccuracyRow row) {
    StabilityPoint point;
    point.axis = axis;
    point.value = value;
    point.row = std::move(row);
    return point;
}

void compareFloatWithDouble(StabilityPoint& point, const SampledImage& inFloat,
                            const SampledImage& inDouble) {
    double largest = 0.0, sum = 0.0;
    std::size_t count = 0;
    for (int y = 0; y < inFloat.colour.height(); ++y)
        for (int x = 0; x < inFloat.colour.width(); ++x) {
            if (!inFloat.hits.at(x, y) || !inDouble.hits.at(x, y)) continue;
            const dvec3 d = glm::abs(inFloat.colour.at(x, y) - inDouble.colour.at(x, y));
            const double worst = std::max({d.x, d.y, d.z});
            largest = std::max(largest, worst);
            sum += worst;
            ++count;
        }
    point.floatDoubleMax = largest;
    point.floatDoubleMean = count ? sum / double(count) : 0.0;
}

// One stiff scene under one rule set: its float row and its double row, or an error point.
void measurePoint(const PointContext& context, StiffnessAxis axis, double value,
                  const Result<StiffScene>& stiff, std::size_t ruleIndex, bool invariant) {
    const StabilityOptions& options = context.options;
    const AccuracyMode mode{options.shading, options.rules[ruleIndex], 1};
    auto failed = [&](const Error& error) {
        StabilityPoint point = pointAt(axis, value, AccuracyRow{});
        point.row.mode = mode;
        point.error = error;
        context.report.points.push_back(std::move(point));
    };
    if (!stiff) return failed(stiff.error());
    const auto modeScene = sceneForMode(stiff->scene, mode);
    auto frame = renderTimed(modeScene, 1, options.repeats, 1, options.threads);
    if (!frame) return failed(frame.error());
    std::shared_ptr<const ReferenceImage> reference;
    if (invariant) {
        reference = scaledDepths(context.original[ruleIndex], stiff->depthScale);
    } else {
        auto own = referenceForFrame(*modeScene, *frame, 1, options.threads);
        if (!own) return failed(own.error());
        reference = std::make_shared<const ReferenceImage>(std::move(own.value()));
    }
    AccuracyOptions rowOptions;
    rowOptions.repeats = options.repeats;
    StabilityPoint inFloat = pointAt(axis, value, floatRow(mode, *frame, reference, rowOptions));
    if (!options.withDouble) return context.report.points.push_back(std::move(inFloat));
    rowOptions.keepImages = true;  // the double image, to set beside the frame's own
    StabilityPoint inDouble = pointAt(axis, value, doubleRow(mode, *frame, reference, rowOptions));
    compareFloatWithDouble(inFloat, frame->sampled, *inDouble.row.image);
    inDouble.row.image.reset();
    inDouble.row.reference.reset();
    context.report.points.push_back(std::move(inFloat));
    context.report.points.push_back(std::move(inDouble));
}

}  // namespace

Result<StabilityReport> measureStability(const Scene& scene, const StabilityOptions& options) {
    const auto started = std::chrono::steady_clock::now();
    if (!scene.camera)
        return makeError(ErrorCode::Unsupported, {}, "this scene has no course camera"_msg);
    std::vector<StiffnessAxis> axes = options.axes;
    if (axes.empty())
        for (const StiffnessAxisInfo& info : stiffnessAxes()) axes.push_back(info.axis);
    // The original scene's references, one per rule set, for the axes that keep its picture
    // (made only when such an axis is swept).
    const bool movable = looksTheSameWhenMoved(scene);
    const bool keepsPicture =
        movable && std::any_of(axes.begin(), axes.end(),
                               [](StiffnessAxis axis) { return axisInfo(axis).invariant; });
    std::vector<std::shared_ptr<const ReferenceImage>> original;
    for (RuleSet rules : keepsPicture ? options.rules : std::vector<RuleSet>{}) {
        const auto modeScene = sceneForMode(scene, {options.shading, rules, 1});
        auto frame = renderTimed(modeScene, 1, 1, 0, options.threads);
        if (!frame) return frame.error();
        auto made = referenceForFrame(*modeScene, *frame, 1, options.threads);
        if (!made) return made.error();
        original.push_back(std::make_shared<const ReferenceImage>(std::move(made.value())));
    }
    int total = 0, done = 0;
    for (StiffnessAxis axis : axes)
        total += static_cast<int>(sweptValues(axis, options).size() * options.rules.size());
    StabilityReport report;
    const PointContext context{options, original, report};
    for (StiffnessAxis axis : axes) {
        const StiffnessAxisInfo& info = axisInfo(axis);
        for (double value : sweptValues(axis, options)) {
            const auto stiff = stiffenScene(scene, axis, value);
            for (std::size_t r = 0; r < options.rules.size(); ++r) {
                if (options.cancel && options.cancel->load())
                    return makeError(ErrorCode::Usage, {}, "measurement cancelled"_msg);
                measurePoint(context, axis, value, stiff, r, info.invariant && movable);
                if (options.progress) options.progress(++done, total);
            }
        }
    }
    report.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
            .count();
    return report;
}

}  // namespace rl
