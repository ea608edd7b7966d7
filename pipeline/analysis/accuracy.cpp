#include "accuracy.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "pipeline/core/stage_id.h"
#include "pipeline/render/frame_trace.h"
#include "pipeline/render/renderer.h"
#include "pipeline/stages/scan_conversion.h"

namespace rl {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2.0;
}

}  // namespace

std::string accuracyModeName(const AccuracyMode& mode) {
    std::string name = std::string(shadingModelName(mode.shading)) + "/" + ruleSetName(mode.rules);
    if (mode.supersample > 1) name += " x" + std::to_string(mode.supersample * mode.supersample);
    return name;
}

namespace {

// A frame's image at k x k samples a pixel, averaged: each sample's colour (colourAt(x, y),
// in the scene's scale) clamped to [0, 1], the samples a triangle covers counted, and at one
// sample a pixel the depth of a covered one (depthAt(x, y), NaN when there is none).
template <typename ColourAt, typename Covered, typename DepthAt>
SampledImage downsample(int sampleWidth, int sampleHeight, int samplesPerAxis, double scale,
                        ColourAt colourAt, Covered covered, DepthAt depthAt) {
    const int k = std::max(1, samplesPerAxis);
    const int width = sampleWidth / k, height = sampleHeight / k;
    SampledImage out;
    out.samplesPerAxis = k;
    out.colour.reset(width, height, dvec3(0.0));
    out.hits.reset(width, height, 0);
    out.depth.reset(width, height, std::numeric_limits<double>::quiet_NaN());
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            dvec3 sum(0.0);
            int hits = 0;
            for (int j = 0; j < k; ++j) {
                for (int i = 0; i < k; ++i) {
                    const int sx = x * k + i, sy = y * k + j;
                    sum += glm::clamp(colourAt(sx, sy) / scale, dvec3(0.0), dvec3(1.0));
                    hits += covered(sx, sy) ? 1 : 0;
                }
            }
            out.colour.at(x, y) = sum / double(k * k);
            out.hits.at(x, y) = static_cast<std::uint16_t>(hits);
            if (k == 1 && hits > 0) out.depth.at(x, y) = depthAt(x, y);
        }
    }
    return out;
}

// Per projected vertex of a draw, in double: view-space point, normal (a vertex made by
// clipping takes them along its edge), 1/w, depth; and Gouraud's vertex colours.
struct DoubleVertices {
    std::vector<dvec3> p, n, colour;
    std::vector<double> invW, depth;
};

DoubleVertices doubleVertices(const FrameTrace& trace, std::size_t d) {
    const Scene& scene = *trace.scene;
    const DrawProjection& proj = trace.projection->draws[d];
    const Draw& draw = scene.draws[d];
    const Normals& normals = *trace.normals;
    DoubleVertices v;
    const std::size_t count = proj.pView.size();
    v.p.resize(count);
    v.n.assign(count, dvec3(0.0));
    v.invW.resize(count);
    v.depth.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const dvec4& p = proj.pView[i];
        v.p[i] = p.w != 0.0 && p.w != 1.0 ? dvec3(p) / p.w : dvec3(p);
        v.invW[i] = 1.0 / proj.pClip[i].w;
        v.depth[i] = scene.conventions.depth == DepthSource::ViewZ
                         ? proj.pView[i].z
                         : proj.pClip[i].z / proj.pClip[i].w;
        if (i < proj.originalVertexCount && !normals.skipped)
            v.n[i] = dvec3(normals.draws[d].vertex[i]);
    }
    for (std::size_t i = 0; i < proj.generated.size(); ++i) {
        const ClipVertex& g = proj.generated[i];
        v.n[proj.originalVertexCount + i] = glm::mix(v.n[g.a], v.n[g.b], g.t);
    }
    if (draw.shading == ShadingModel::Gouraud) {
        v.colour.resize(count);
        for (std::size_t i = 0; i < proj.originalVertexCount; ++i)
            v.colour[i] = referencePhong(scene, draw, trace.view->lights, v.p[i], v.n[i]);
        for (std::size_t i = 0; i < proj.generated.size(); ++i) {
            const ClipVertex& g = proj.generated[i];
            v.colour[proj.originalVertexCount + i] = glm::mix(v.colour[g.a], v.colour[g.b], g.t);
        }
    }
    return v;
}

// The colour of screen triangle t at the sample of pixel (x, y), in double, and its depth.
dvec3 shadeSampleInDouble(const FrameTrace& trace, const std::vector<DoubleVertices>& vertices,
                          std::uint32_t t, int x, int y, double& depth) {
    const Scene& scene = *trace.scene;
    const ScreenTriangle& tri = trace.projection->triangles[t];
    const Draw& draw = scene.draws[tri.draw];
    const DoubleVertices& v = vertices[tri.draw];
    // Screen barycentrics of the sample, as the depth test writes them, unrounded.
    const double offset = scene.rules.sampleOffset;
    const std::array<dvec2, 3> p = screenVertices(*trace.projection, tri);
    const dvec2 s = dvec2(x + offset, y + offset) - p[0];
    const dvec2 e1 = p[1] - p[0], e2 = p[2] - p[0];
    const double area = e1.x * e2.y - e1.y * e2.x;
    const double sb = (s.x * e2.y - s.y * e2.x) / area;
    const double sg = (e1.x * s.y - e1.y * s.x) / area;
    const double sa = 1.0 - sb - sg;
    const bool perspective =
        scene.rules.interpolation == RasterRules::Interpolation::PerspectiveCorrect;
    const auto& z = v.depth;
    if (perspective && scene.conventions.depth == DepthSource::ViewZ)
        depth = 1.0 / (sa / z[tri.v[0]] + sb / z[tri.v[1]] + sg / z[tri.v[2]]);
    else
        depth = sa * z[tri.v[0]] + sb * z[tri.v[1]] + sg * z[tri.v[2]];
    double a = sa, b = sb, g = sg;
    if (perspective) {
        const double w0 = sa * v.invW[tri.v[0]], w1 = sb * v.invW[tri.v[1]],
                     w2 = sg * v.invW[tri.v[2]];
        const double sum = w0 + w1 + w2;
        if (sum != 0.0 && std::isfinite(sum)) a = w0 / sum, b = w1 / sum, g = w2 / sum;
    }
    const auto mixed = [&](const std::vector<dvec3>& values) {
        return a * values[tri.v[0]] + b * values[tri.v[1]] + g * values[tri.v[2]];
    };
    const std::vector<ViewLight>& lights = trace.view->lights;
    switch (draw.shading) {
        case ShadingModel::Flat:
        case ShadingModel::Painter: {
            const auto& corners = draw.mesh->triangles[tri.source];
            const dvec3 centre = (v.p[corners[0]] + v.p[corners[1]] + v.p[corners[2]]) / 3.0;
            const Normals& normals = *trace.normals;
            const dvec3 n = normals.skipped
                                ? dvec3(0.0)
                                : dvec3(normals.draws[tri.draw].triangle[tri.source]);
            return referencePhong(scene, draw, lights, centre, n);
        }
        case ShadingModel::Gouraud:
            return mixed(v.colour);
        case ShadingModel::Phong:
            break;
    }
    return referencePhong(scene, draw, lights, mixed(v.p), mixed(v.n));
}

}  // namespace

SampledImage sampleFrame(const FrameTrace& trace, int samplesPerAxis) {
    const Image<vec3>& colour = trace.shading->colour;
    const DepthTest& depth = *trace.depth;
    return downsample(
        colour.width(), colour.height(), samplesPerAxis, trace.scene->conventions.colourScale,
        [&](int x, int y) { return dvec3(colour.at(x, y)); },
        [&](int x, int y) { return depth.triangle.at(x, y) != kNoTriangle; },
        [&](int x, int y) {
            return depth.depthKept ? double(depth.depth.at(x, y))
                                   : std::numeric_limits<double>::quiet_NaN();
        });
}

SampledImage shadeFrameInDouble(const FrameTrace& trace, int samplesPerAxis,
                                double& shadingMilliseconds) {
    const auto started = Clock::now();
    const Scene& scene = *trace.scene;
    const DepthTest& depth = *trace.depth;
    std::vector<DoubleVertices> vertices;
    for (std::size_t d = 0; d < trace.projection->draws.size(); ++d)
        vertices.push_back(doubleVertices(trace, d));
    const double scale = scene.conventions.colourScale;
    Image<dvec3> colour(scene.width, scene.height,
                        dvec3(vec3(scene.conventions.background)) * scale);
    Image<double> depthImage(scene.width, scene.height, 0.0);
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x)
            if (const std::uint32_t t = depth.triangle.at(x, y); t != kNoTriangle)
                colour.at(x, y) =
                    shadeSampleInDouble(trace, vertices, t, x, y, depthImage.at(x, y));
    shadingMilliseconds = millisecondsSince(started);
    return downsample(
        scene.width, scene.height, samplesPerAxis, scale,
        [&](int x, int y) { return colour.at(x, y); },
        [&](int x, int y) { return depth.triangle.at(x, y) != kNoTriangle; },
        [&](int x, int y) { return depthImage.at(x, y); });
}

AccuracyMetrics compareWithReference(const SampledImage& image, const ReferenceImage& reference) {
    AccuracyMetrics m;
    double squares = 0.0, depthSum = 0.0;
    std::size_t within = 0, depthCount = 0;
    const int width = std::min(image.colour.width(), reference.colour.width());
    const int height = std::min(image.colour.height(), reference.colour.height());
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const int ours = image.hits.at(x, y), theirs = reference.hits.at(x, y);
            if (ours == 0 && theirs == 0) continue;
            ++m.eitherCovered;
            if (ours != theirs) ++m.coverageMismatch;
            if (ours == 0 || theirs == 0) continue;
            ++m.bothCovered;
            const dvec3 difference = glm::abs(image.colour.at(x, y) - reference.colour.at(x, y));
            squares += glm::dot(difference, difference);
            const double worst = std::max({difference.x, difference.y, difference.z});
            if (worst > m.maxError || m.worstX < 0) {
                m.maxError = std::max(m.maxError, worst);
                m.worstX = x;
                m.worstY = y;
            }
            // One byte step, with room for the rounding of a value stored as a float.
            if (worst <= 1.0 / 255.0 + 1e-9) ++within;
            const double z = image.depth.at(x, y), zRef = reference.depth.at(x, y);
            if (!std::isnan(z) && std::isfinite(zRef) && zRef != 0.0) {
                const double relative = std::abs(z - zRef) / std::abs(zRef);
                depthSum += relative;
                m.depthMaxRelative = std::max(m.depthMaxRelative, relative);
                ++depthCount;
            }
        }
    }
    m.rmse = m.bothCovered ? std::sqrt(squares / (3.0 * double(m.bothCovered))) : 0.0;
    m.psnr =
        m.rmse > 0.0 ? 20.0 * std::log10(1.0 / m.rmse) : std::numeric_limits<double>::infinity();
    m.within1Of255 = m.bothCovered ? double(within) / double(m.bothCovered) : 1.0;
    if (depthCount) {
        m.depthMeanRelative = depthSum / double(depthCount);
    } else {
        m.depthMeanRelative = m.depthMaxRelative = std::numeric_limits<double>::quiet_NaN();
    }
    return m;
}

Image<float> errorMap(const SampledImage& image, const ReferenceImage& reference) {
    const int width = std::min(image.colour.width(), reference.colour.width());
    const int height = std::min(image.colour.height(), reference.colour.height());
    Image<float> out(width, height, std::numeric_limits<float>::quiet_NaN());
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const int ours = image.hits.at(x, y), theirs = reference.hits.at(x, y);
            if (ours == 0 && theirs == 0) continue;
            if ((ours == 0) != (theirs == 0)) {
                out.at(x, y) = -1.0f;
                continue;
            }
            const dvec3 d = glm::abs(image.colour.at(x, y) - reference.colour.at(x, y));
            out.at(x, y) = static_cast<float>(std::max({d.x, d.y, d.z}));
        }
    }
    return out;
}

std::vector<AccuracyMode> defaultAccuracyModes(const std::vector<ShadingModel>& shadings,
                                               const std::vector<RuleSet>& rules,
                                               const std::vector<int>& supersample) {
    std::vector<AccuracyMode> modes;
    for (int k : supersample)
        for (ShadingModel s : shadings)
            for (RuleSet r : rules) modes.push_back({s, r, k});
    return modes;
}

std::shared_ptr<const Scene> sceneForMode(const Scene& scene, const AccuracyMode& mode) {
    auto modeScene = std::make_shared<Scene>(scene);
    modeScene->rules = rulesOf(mode.rules);
    modeScene->width = scene.width * mode.supersample;
    modeScene->height = scene.height * mode.supersample;
    for (Draw& draw : modeScene->draws) draw.shading = mode.shading;
    return modeScene;
}

Result<TimedFrame> renderTimed(const std::shared_ptr<const Scene>& modeScene, int supersample,
                               int repeats, int warmup, int threads) {
    RenderOptions renderOptions;
    renderOptions.threads = threads;
    RenderContext context;
    std::vector<double> times, shadingTimes;
    std::optional<FrameTrace> last;
    TimedFrame timed;
    for (int r = 0; r < std::max(1, repeats) + warmup; ++r) {
        last.reset();  // so that the context's buffers are free to be reused
        const auto started = Clock::now();
        auto trace = renderFrame(modeScene, renderOptions, &context);
        if (!trace) return trace.error();
        if (supersample > 1) timed.sampled = sampleFrame(trace.value(), supersample);
        const double ms = millisecondsSince(started);
        if (r >= warmup) {
            times.push_back(ms);
            shadingTimes.push_back(
                trace->stageMilliseconds[static_cast<std::size_t>(StageId::Shading)]);
        }
        last = std::move(trace.value());
    }
    if (supersample == 1) timed.sampled = sampleFrame(*last, 1);
    timed.trace = std::make_shared<const FrameTrace>(std::move(*last));
    timed.milliseconds = median(times);
    timed.shadingMilliseconds = median(shadingTimes);
    return timed;
}

Result<ReferenceImage> referenceForFrame(const Scene& modeScene, const TimedFrame& frame,
                                         int supersample, int threads) {
    // The reference sees the scene at the output size, with the mode's shading.
    Scene referenceScene = modeScene;
    referenceScene.width = modeScene.width / supersample;
    referenceScene.height = modeScene.height / supersample;
    ReferenceOptions options;
    options.samplesPerAxis = supersample;
    options.threads = threads;
    options.nearZ = frame.trace->projection->nearW;
    return renderReference(referenceScene, *frame.trace->view, *frame.trace->normals, options);
}

AccuracyRow floatRow(const AccuracyMode& mode, const TimedFrame& frame,
                     const std::shared_ptr<const ReferenceImage>& reference,
                     const AccuracyOptions& options) {
    AccuracyRow row;
    row.mode = mode;
    row.milliseconds = frame.milliseconds;
    row.metrics = compareWithReference(frame.sampled, *reference);
    if (options.keepErrorMaps) row.errorMap = errorMap(frame.sampled, *reference);
    if (options.keepImages) {
        row.image = std::make_shared<const SampledImage>(frame.sampled);
        row.reference = reference;
    }
    return row;
}

AccuracyRow doubleRow(const AccuracyMode& mode, const TimedFrame& frame,
                      const std::shared_ptr<const ReferenceImage>& reference,
                      const AccuracyOptions& options) {
    // The float frame's time with its shading stage swapped for the double one (the median of
    // as many runs).
    std::vector<double> shadingTimes;
    SampledImage inDouble;
    for (int r = 0; r < std::max(1, options.repeats); ++r) {
        double ms = 0.0;
        inDouble = shadeFrameInDouble(*frame.trace, mode.supersample, ms);
        shadingTimes.push_back(ms);
    }
    AccuracyRow row;
    row.mode = mode;
    row.precision = "double";
    row.milliseconds =
        std::max(0.0, frame.milliseconds - frame.shadingMilliseconds) + median(shadingTimes);
    row.metrics = compareWithReference(inDouble, *reference);
    if (options.keepErrorMaps) row.errorMap = errorMap(inDouble, *reference);
    if (options.keepImages) {
        row.image = std::make_shared<const SampledImage>(std::move(inDouble));
        row.reference = reference;
    }
    return row;
}

Result<AccuracyReport> measureAccuracy(const Scene& scene, const AccuracyOptions& options) {
    std::vector<AccuracyMode> modes = options.modes;
    if (modes.empty())
        modes =
            defaultAccuracyModes({ShadingModel::Flat, ShadingModel::Gouraud, ShadingModel::Phong},
                                 {RuleSet::Course, RuleSet::Gpu, RuleSet::Hw2}, {1});
    AccuracyReport report;
    // The references, one per shading model and sample count, made when first needed.
    struct Cached {
        ShadingModel shading;
        int k;
        std::shared_ptr<const ReferenceImage> image;
    };
    std::vector<Cached> references;
    for (const AccuracyMode& mode : modes) {
        if (options.cancel && options.cancel->load())
            return makeError(ErrorCode::Usage, {}, "measurement cancelled"_msg);
        if (mode.supersample < 1 || mode.supersample > 16)
            return makeError(ErrorCode::Usage, {},
                             "supersampling must be 1 to 16 samples per axis"_msg);
        const auto modeScene = sceneForMode(scene, mode);
        // Untimed frames first: one per mode for its buffers, a few more for the first mode,
        // whose frames also wake the threads and the caches up.
        const int warmup = &mode == &modes.front() ? 4 : 1;
        auto frame =
            renderTimed(modeScene, mode.supersample, options.repeats, warmup, options.threads);
        if (!frame) return frame.error();

        std::shared_ptr<const ReferenceImage> reference;
        for (const Cached& c : references)
            if (c.shading == mode.shading && c.k == mode.supersample) reference = c.image;
        if (!reference) {
            auto made = referenceForFrame(*modeScene, *frame, mode.supersample, options.threads);
            if (!made) return made.error();
            if (mode.supersample == 1) {
                report.referenceMilliseconds += made->buildMilliseconds + made->castMilliseconds;
                report.referenceRays += made->rays;
            }
            reference = std::make_shared<const ReferenceImage>(std::move(made.value()));
            references.push_back({mode.shading, mode.supersample, reference});
        }
        report.rows.push_back(floatRow(mode, *frame, reference, options));
        if (options.withDouble) report.rows.push_back(doubleRow(mode, *frame, reference, options));
    }
    return report;
}

}  // namespace rl
