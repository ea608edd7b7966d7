#include "view_transform.h"

#include "animation.h"

namespace rl {

ViewTransform ViewTransformStage::run(const Scene& scene, const CameraBasis& basis) const {
    ViewTransform out;
    out.worldFromModel.reserve(scene.draws.size());
    out.viewFromModel.reserve(scene.draws.size());
    out.pView.reserve(scene.draws.size());
    for (const Draw& draw : scene.draws) {
        const dmat4 worldFromModel = animatedWorldFromModel(scene, draw);
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
    for (const Light& light : scene.lights)
        out.lights.push_back({basis.viewFromWorld * light.pWorld, light.intensity});
    return out;
}

}  // namespace rl
