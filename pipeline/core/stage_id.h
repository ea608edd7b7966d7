// The seven stages of the pipeline, in lecture order.
#pragma once

#include <array>
#include <cstdint>

namespace rl {

enum class StageId : std::uint8_t {
    CameraBasis,
    ViewTransform,
    Normals,
    Projection,
    ScanConversion,
    DepthTest,
    Shading,
};

inline constexpr int kStageCount = 7;

inline constexpr std::array<StageId, kStageCount> kAllStages = {
    StageId::CameraBasis,    StageId::ViewTransform, StageId::Normals, StageId::Projection,
    StageId::ScanConversion, StageId::DepthTest,     StageId::Shading,
};

// The lecture's name of a stage, in English ("camera basis").
const char* stageName(StageId stage);

}  // namespace rl
