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
        case ShadingModel::Painter:
            return "painter";
    }
    return "phong";
}

std::optional<ShadingModel> shadingModelFromName(std::string_view name) {
    if (name == "flat") return ShadingModel::Flat;
    if (name == "gouraud") return ShadingModel::Gouraud;
    if (name == "phong") return ShadingModel::Phong;
    if (name == "painter") return ShadingModel::Painter;
    return std::nullopt;
}

bool paintersAlgorithm(const Scene& scene) {
    for (const Draw& draw : scene.draws)
        if (draw.shading == ShadingModel::Painter) return true;
    return false;
}

RasterRules RasterRules::course() {
    return RasterRules{};
}

RasterRules RasterRules::hw2() {
    RasterRules rules;
    rules.subpixelBits = 16;  // only the grid the views show the edges on
    rules.sampleOffset = 0.0;
    rules.snap = VertexSnap::None;
    rules.fill = FillRule::TopLeft;
    rules.scan = Scan::Dda;
    rules.interpolation = Interpolation::PerspectiveCorrect;
    rules.texel = TexelRounding::Truncate;
    return rules;
}

RasterRules RasterRules::gpu() {
    RasterRules rules;
    rules.subpixelBits = 8;
    rules.sampleOffset = 0.5;
    rules.snap = VertexSnap::Nearest;
    rules.fill = FillRule::TopLeft;
    rules.interpolation = Interpolation::PerspectiveCorrect;
    return rules;
}

const char* ruleSetName(RuleSet set) {
    switch (set) {
        case RuleSet::Course:
            return "course";
        case RuleSet::Gpu:
            return "gpu";
        case RuleSet::Hw2:
            return "hw2";
    }
    return "course";
}

std::optional<RuleSet> ruleSetFromName(std::string_view name) {
    if (name == "course") return RuleSet::Course;
    if (name == "gpu") return RuleSet::Gpu;
    if (name == "hw2") return RuleSet::Hw2;
    return std::nullopt;
}

RasterRules rulesOf(RuleSet set) {
    switch (set) {
        case RuleSet::Course:
            return RasterRules::course();
        case RuleSet::Gpu:
            return RasterRules::gpu();
        case RuleSet::Hw2:
            return RasterRules::hw2();
    }
    return RasterRules::course();
}

std::optional<RuleSet> ruleSetOf(const RasterRules& rules) {
    for (RuleSet set : {RuleSet::Course, RuleSet::Gpu, RuleSet::Hw2})
        if (rulesOf(set) == rules) return set;
    return std::nullopt;
}

Conventions Conventions::course() {
    return Conventions{};
}

Conventions Conventions::hw2() {
    Conventions c;
    c.ndcYUp = false;  // (-1, -1) is the top-left corner
    c.viewport = ViewportFormula::ScaleThenShift;
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
