#include "scene.h"

namespace rl {

const char* shadingModelName(ShadingModel model) {
    switch (model) {
        case ShadingModel::Flat:
            return "flat";
        case ShadingModel::Gouraud:
            return "gouraud";
        case ShadingModel::Phong:
            return "phong";
    }
    return "phong";
}

std::optional<ShadingModel> shadingModelFromName(std::string_view name) {
    if (name == "flat") return ShadingModel::Flat;
    if (name == "gouraud") return ShadingModel::Gouraud;
    if (name == "phong") return ShadingModel::Phong;
    return std::nullopt;
}

RasterRules RasterRules::course() {
    return RasterRules{};
}

RasterRules RasterRules::hw2() {
    RasterRules rules;
    rules.subpixelBits = 16;
    rules.sampleOffset = 0.0;
    rules.snap = VertexSnap::Nearest;
    rules.fill = FillRule::TopLeft;
    rules.interpolation = Interpolation::PerspectiveCorrect;
    return rules;
}

Conventions Conventions::course() {
    return Conventions{};
}

Conventions Conventions::hw2() {
    Conventions c;
    c.ndcYUp = false;  // (-1, -1) is the top-left corner
    c.depth = DepthSource::NdcZ;
    c.depthClear = 1.0f;
    c.depthWinsOnTie = true;
    c.depthRangeClip = true;
    c.flipNormalsTowardViewer = false;
    c.colourScale = 1.0f;
    c.rounding = ByteRounding::Truncate;
    c.background = vec4(0.0f);  // untouched pixels are transparent black
    return c;
}

std::size_t Scene::triangleCount() const {
    std::size_t n = 0;
    for (const auto& draw : draws) n += draw.mesh ? draw.mesh->triangles.size() : 0;
    return n;
}

std::size_t Scene::vertexCount() const {
    std::size_t n = 0;
    for (const auto& draw : draws) n += draw.mesh ? draw.mesh->positions.size() : 0;
    return n;
}

}  // namespace rl
