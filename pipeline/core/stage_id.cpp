#include "stage_id.h"

namespace rl {

const char* stageName(StageId stage) {
    switch (stage) {
        case StageId::CameraBasis:
            return "camera basis";
        case StageId::ViewTransform:
            return "view transform";
        case StageId::Normals:
            return "normals";
        case StageId::Projection:
            return "projection";
        case StageId::ScanConversion:
            return "scan conversion";
        case StageId::DepthTest:
            return "depth test";
        case StageId::Shading:
            return "shading";
    }
    return "";
}

}  // namespace rl
