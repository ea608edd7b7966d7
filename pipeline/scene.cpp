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
