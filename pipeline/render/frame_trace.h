// Everything one frame computed: each stage's output, kept so that every view can draw
// its stage, plus the diagnostics and the time each stage took. Immutable once returned;
// shared with the UI through shared_ptr<const ...>.
#pragma once

#include <array>
#include <memory>

#include "pipeline/core/diagnostics.h"
#include "pipeline/core/stage_id.h"
#include "pipeline/scene/scene.h"
#include "pipeline/stages/camera_basis.h"
#include "pipeline/stages/depth_test.h"
#include "pipeline/stages/normals.h"
#include "pipeline/stages/projection.h"
#include "pipeline/stages/scan_conversion.h"
#include "pipeline/stages/shading.h"
#include "pipeline/stages/view_transform.h"

namespace rl {

struct FrameTrace {
    std::shared_ptr<const Scene> scene;
    std::shared_ptr<const CameraBasis> cameraBasis;
    std::shared_ptr<const ViewTransform> view;
    std::shared_ptr<const Normals> normals;
    std::shared_ptr<const Projection> projection;
    std::shared_ptr<const ScanConversion> scan;
    std::shared_ptr<const DepthTest> depth;
    std::shared_ptr<const Shading> shading;

    Diagnostics diagnostics;  // what the stages noted and warned
    std::array<double, kStageCount> stageMilliseconds{};
    double totalMilliseconds = 0.0;
    int threads = 1;  // the stages that share out their work ran on this many threads
    // The rows of each band when the depth test and shading ran together band by band
    // (fast::depthTestAndShading), 0 when they ran one after the other.
    int bandRows = 0;

    // Whether a stage did nothing for this scene, and why ("" when it ran).
    std::string skipReason(StageId stage) const;
};

}  // namespace rl
