// Error against run time: each mode of the renderer (a shading model under a rule set,
// optionally supersampled) is rendered and timed, and compared with the exact reference
// (reference.h) of the same shading model.
//
// Colours are compared as displayed: each channel clamped to [0, colour scale] and divided by
// it, so 1/255 is one step of a byte. A supersampled mode renders k x k times the pixels and
// averages the clamped colours of each k x k block; its reference averages k x k rays at the
// same sample points.
//
//   rmse               square root of the mean squared channel difference, over the pixels
//                      both cover
//   max_error          the largest channel difference there
//   psnr               20 log10(1 / rmse) dB (infinite when rmse = 0)
//   coverage_mismatch  pixels whose number of covered samples differs, over the pixels either
//                      covers
//   within_1_255       the share of the commonly covered pixels whose three channels are all
//                      within 1/255 of the reference
//   depth error        |z - z_ref| / z_ref of view z, over the commonly covered pixels (k = 1)
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/analysis/reference.h"
#include "pipeline/core/diagnostics.h"
#include "pipeline/core/image.h"
#include "pipeline/scene/scene.h"

namespace rl {

struct AccuracyMode {
    ShadingModel shading = ShadingModel::Phong;
    RuleSet rules = RuleSet::Course;
    int supersample = 1;  // samples per axis
    bool operator==(const AccuracyMode&) const = default;
};

std::string accuracyModeName(const AccuracyMode& mode);  // "phong/gpu", "flat/course x2"

struct AccuracyMetrics {
    std::size_t bothCovered = 0;  // pixels covered by the render and the reference
    std::size_t eitherCovered = 0;
    std::size_t coverageMismatch = 0;  // pixels whose covered-sample counts differ
    double rmse = 0.0;
    double maxError = 0.0;
    double psnr = 0.0;  // +infinity when rmse = 0
    double within1Of255 = 1.0;
    double depthMeanRelative = 0.0, depthMaxRelative = 0.0;  // NaN when not measured
    int worstX = -1, worstY = -1;                            // a pixel with the largest error

    double coverageMismatchShare() const {
        return eitherCovered ? double(coverageMismatch) / double(eitherCovered) : 0.0;
    }
};

// A render brought to the reference's terms: colours clamped and scaled to 0..1 and averaged
// over k x k blocks, covered samples counted, depth (view z, k = 1 only).
struct SampledImage {
    int samplesPerAxis = 1;
    Image<dvec3> colour;
    Image<std::uint16_t> hits;
    Image<double> depth;  // NaN where not measured
};

struct FrameTrace;
SampledImage sampleFrame(const FrameTrace& trace, int samplesPerAxis);

// The "double" precision of a mode: the frame's coverage and winning triangles as rendered,
// then every covered pixel's barycentrics, perspective weights, depth and lighting worked out
// again in double (the renderer's float shading stage, in double: the same interpolation of
// the same rules, the formula of referencePhong). Returns the frame in the reference's terms,
// and the time it took in shadingMilliseconds.
SampledImage shadeFrameInDouble(const FrameTrace& trace, int samplesPerAxis,
                                double& shadingMilliseconds);
AccuracyMetrics compareWithReference(const SampledImage& image, const ReferenceImage& reference);

// The per-pixel error (largest channel difference, 0..1) for a heat map; -1 where exactly one
// of the two covers the pixel, NaN where neither does.
Image<float> errorMap(const SampledImage& image, const ReferenceImage& reference);

struct AccuracyRow {
    AccuracyMode mode;
    // "float": the renderer as it is. "double": its frame with the shading stage (attributes,
    // depth, lighting) in double; the time is the float frame's with the float shading stage
    // replaced by the double one.
    std::string precision = "float";
    double milliseconds = 0.0;  // median time per frame (render, plus the k x k averaging)
    AccuracyMetrics metrics;
    Image<float> errorMap;  // with AccuracyOptions::keepErrorMaps
    // With AccuracyOptions::keepImages: the mode's frame and its reference, in the same terms
    // (for picking a pixel and reading both values).
    std::shared_ptr<const SampledImage> image;
    std::shared_ptr<const ReferenceImage> reference;
};

struct AccuracyReport {
    std::vector<AccuracyRow> rows;
    // The reference's own cost, per shading model measured (k = 1): build and cast, ms.
    double referenceMilliseconds = 0.0;
    std::size_t referenceRays = 0;
};

struct AccuracyOptions {
    std::vector<AccuracyMode> modes;  // empty: every shading model under every rule set, k = 1
    bool withDouble = true;           // a "double" row after each mode's "float" one
    int repeats = 5;                  // frames timed per mode (the median is reported)
    int threads = 0;
    bool keepErrorMaps = false;
    bool keepImages = false;
    // Checked between modes: when it becomes true, measureAccuracy stops with a Usage error
    // ("measurement cancelled").
    const std::atomic<bool>* cancel = nullptr;
};

std::vector<AccuracyMode> defaultAccuracyModes(const std::vector<ShadingModel>& shadings,
                                               const std::vector<RuleSet>& rules,
                                               const std::vector<int>& supersample);

// The steps of measureAccuracy, for sweeps that bring their own reference (stability.h).
// The scene with the mode's rules and shading, at k times the size.
std::shared_ptr<const Scene> sceneForMode(const Scene& scene, const AccuracyMode& mode);

struct TimedFrame {
    std::shared_ptr<const FrameTrace> trace;  // the last frame rendered
    SampledImage sampled;                     // in the reference's terms
    double milliseconds = 0.0;                // median per frame, with the k x k averaging
    double shadingMilliseconds = 0.0;         // median of the shading stage alone
};
// Renders warmup untimed frames, then repeats timed ones.
Result<TimedFrame> renderTimed(const std::shared_ptr<const Scene>& modeScene, int supersample,
                               int repeats, int warmup, int threads);
// The exact reference of the frame's scene, from its view-space geometry.
Result<ReferenceImage> referenceForFrame(const Scene& modeScene, const TimedFrame& frame,
                                         int supersample, int threads);
// The frame as rendered (float), and re-shaded in double, against the reference.
AccuracyRow floatRow(const AccuracyMode& mode, const TimedFrame& frame,
                     const std::shared_ptr<const ReferenceImage>& reference,
                     const AccuracyOptions& options);
AccuracyRow doubleRow(const AccuracyMode& mode, const TimedFrame& frame,
                      const std::shared_ptr<const ReferenceImage>& reference,
                      const AccuracyOptions& options);

// Renders every mode of the scene (its own shading and rules are replaced by the mode's) and
// compares each with the reference.
Result<AccuracyReport> measureAccuracy(const Scene& scene, const AccuracyOptions& options);

}  // namespace rl
