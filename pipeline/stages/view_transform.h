// Stage 2, view transform (seed 000): every vertex and every light from world to view
// coordinates, pView = viewFromWorld * worldFromModel * pModel, where viewFromWorld comes
// from the camera basis ([U; V; N] (P - C) for a course camera). In view space the camera
// is at the origin and looks along +z: a point is in front when z > 0. A draw with an
// animation is first moved by its M at the scene's time (animation.h, seed 002).
#pragma once

#include <vector>

#include "pipeline/core/math.h"
#include "pipeline/scene/animation_matrix.h"
#include "pipeline/scene/scene.h"
#include "pipeline/stages/camera_basis.h"

namespace rl {

struct ViewLight {
    dvec4 pView = dvec4(0.0, 0.0, 0.0, 1.0);  // w = 0: a direction toward the light
    vec3 intensity = vec3(0.0f);
    // Light's attenuation and spot (scene.h), the spot direction in view space, unit length.
    vec3 attenuation = vec3(1.0f, 0.0f, 0.0f);
    bool attenuated = false;  // a positional light with attenuation other than (1, 0, 0)
    bool spot = false;        // cutoff other than 180 degrees
    vec3 spotDirection = vec3(0.0f, 0.0f, 1.0f);
    float spotCosCutoff = -1.0f;  // cos of the cutoff angle
    float spotExponent = 0.0f;
    // Neither attenuated nor a spot: the light of the course's own files.
    bool plain() const { return !attenuated && !spot; }
};

struct ViewTransform {
    // Per draw: M(t) * worldFromModel (animation.h; worldFromModel itself without an animation)
    std::vector<dmat4> worldFromModel;
    std::vector<AnimationPivot> pivot;      // per draw: where M turns (zero without an animation)
    std::vector<dmat4> viewFromModel;       // per draw
    std::vector<std::vector<dvec4>> pView;  // per draw, per vertex
    std::vector<ViewLight> lights;
    std::size_t verticesInFront = 0;  // z > 0
    std::size_t verticesBehind = 0;   // z <= 0: at or behind the camera's plane
};

class ViewTransformStage {
public:
    ViewTransform run(const Scene& scene, const CameraBasis& basis) const;
};

}  // namespace rl
