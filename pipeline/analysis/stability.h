// Numerical stability: a scene is made stiffer step by step along one axis (moved away from
// the origin, scaled, brought close to the eye, cut into slivers, given a sharp highlight,
// looked at with V nearly along N, lit from a light on its surface), and at each step every
// mode is measured against the exact reference (accuracy.h), in float and in double, under
// the course and gpu rules, with its run time.
//
// Where the stiffer scene shows the same picture as the original (moving, scaling, the camera
// basis: "invariant" axes), the reference is the original scene's, so that an error of the
// geometry stages themselves shows; the depths are scaled with the scene. Elsewhere the
// reference is the stiff scene's own.
#pragma once

#include <atomic>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/analysis/accuracy.h"
#include "pipeline/core/diagnostics.h"
#include "pipeline/scene/scene.h"

namespace rl {

enum class StiffnessAxis : std::uint8_t {
    Offset,          // scene, camera and lights moved by value along (1, 1, 1)/sqrt 3
    Scale,           // everything scaled by value about the origin (d, hx, hy too)
    Distance,        // everything scaled by value about the eye: the object value times nearer
    Sliver,          // each triangle cut in three around a sliver whose smallest angle is value°
    Shininess,       // every material's n set to value
    Grazing,         // the camera's V at value° from N (the same basis, in exact arithmetic)
    LightOnSurface,  // the first light value x the scene's size above a visible surface point
};

struct StiffnessAxisInfo {
    StiffnessAxis axis;
    const char* name;            // "offset", as the command line and the tables write it
    const char* unit;            // of the value: "units", "x", "degrees" ...
    std::vector<double> values;  // the default sweep, from the mildest to the stiffest
    bool invariant;              // the stiff scene shows the original's picture
};

const std::vector<StiffnessAxisInfo>& stiffnessAxes();
const StiffnessAxisInfo& axisInfo(StiffnessAxis axis);
std::optional<StiffnessAxis> stiffnessAxisFromName(std::string_view name);

// The scene made stiff along the axis, and how its view-space depths compare with the
// original's (depthScale). An error when the axis needs what the scene lacks (a course
// camera, a light, a visible surface).
struct StiffScene {
    Scene scene;
    double depthScale = 1.0;
};
Result<StiffScene> stiffenScene(const Scene& scene, StiffnessAxis axis, double value);

struct StabilityPoint {
    StiffnessAxis axis = StiffnessAxis::Offset;
    double value = 0.0;
    AccuracyRow row;  // its mode (shading, rules), precision, time and errors
    // On a float row with its double row: the largest and the mean channel difference between
    // the two (0..1) over the pixels both cover, the error of float arithmetic alone (the
    // same frame, its shading done again in double). NaN otherwise.
    double floatDoubleMax = std::numeric_limits<double>::quiet_NaN();
    double floatDoubleMean = std::numeric_limits<double>::quiet_NaN();
    // When the stiff scene cannot be made or rendered: why (the row's metrics are then empty).
    std::optional<Error> error;
};

struct StabilityReport {
    std::vector<StabilityPoint> points;
    double milliseconds = 0.0;  // the whole sweep
};

struct StabilityOptions {
    std::vector<StiffnessAxis> axes;  // empty: every axis
    std::vector<double> values;       // empty: each axis's own sweep (StiffnessAxisInfo)
    std::vector<RuleSet> rules = {RuleSet::Course, RuleSet::Gpu};
    ShadingModel shading = ShadingModel::Phong;
    bool withDouble = true;
    int repeats = 3;  // timed frames per point (the median is reported)
    int threads = 0;
    const std::atomic<bool>* cancel = nullptr;          // checked between points
    std::function<void(int done, int total)> progress;  // after each point
};

Result<StabilityReport> measureStability(const Scene& scene, const StabilityOptions& options);

}  // namespace rl
