#include "view_transform.h"

#include <cmath>

#include "pipeline/scene/animation_matrix.h"

namespace rl {

ViewTransform ViewTransformStage::run(const Scene& scene, const CameraBasis& basis) const {
    ViewTransform out;
    out.worldFromModel.reserve(scene.draws.size());
    out.pivot.assign(scene.draws.size(), AnimationPivot{});
    out.viewFromModel.reserve(scene.draws.size());
    out.pView.reserve(scene.draws.size());
    for (std::size_t d = 0; d < scene.draws.size(); ++d) {
        const Draw& draw = scene.draws[d];
        const dmat4 worldFromModel = animatedWorldFromModel(scene, draw, &out.pivot[d]);
        out.worldFromModel.push_back(worldFromModel);
        const dmat4 viewFromModel = basis.viewFromWorld * worldFromModel;
        out.viewFromModel.push_back(viewFromModel);
        std::vector<dvec4> pView;
        if (draw.mesh) {
            pView.reserve(draw.mesh->positions.size());
            for (const dvec4& pModel : draw.mesh->positions) {
                const dvec4 p = viewFromModel * pModel;
                (p.z > 0.0 ? out.verticesInFront : out.verticesBehind) += 1;
                pView.push_back(p);
            }
        }
        out.pView.push_back(std::move(pView));
    }
    for (const Light& light : scene.lights) {
        ViewLight v;
        v.pView = basis.viewFromWorld * light.pWorld;
        v.intensity = light.intensity;
        v.attenuation = light.attenuation;
        v.attenuated = light.attenuated();
        v.spot = light.spot();
        if (v.spot) {
            // A direction: rotated, not moved (w = 0).
            const dvec3 d = dvec3(basis.viewFromWorld * dvec4(light.spotDirection, 0.0));
            const double length = glm::length(d);
            v.spotDirection = length > 0.0 ? vec3(d / length) : vec3(0.0f);
            v.spotCosCutoff = static_cast<float>(std::cos(glm::radians(double(light.spotCutoff))));
            v.spotExponent = light.spotExponent;
        }
        out.lights.push_back(v);
    }
    return out;
}

}  // namespace rl
