// Stage 2, view transform (seed 000): every vertex and every light from world to view
// coordinates, pView = viewFromWorld * worldFromModel * pModel, where viewFromWorld comes
// from the camera basis ([U; V; N] (P - C) for a course camera). In view space the camera
// is at the origin and looks along +z: a point is in front when z > 0. A draw with an
// animation is first moved by its M at the scene's time (animation.h, seed 002).
#pragma once

#include <vector>

#include "animation_matrix.h"
#include "camera_basis.h"
#include "math.h"
#include "scene.h"

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

// Float keeps a view-space point to about 1.2e-7 of its distance from the eye, so the shading
// cannot tell on which side of a surface a light nearer to it than about that lies. Below
// kLightSurfaceRatio times the light's distance from the eye, the sweep of docs/accuracy.md
// measures float and double apart by a byte step or more, and the renderer warns.
inline constexpr double kLightSurfaceRatio = 1e-5;

struct LightOnSurface {
    std::size_t light = 0;  // in ViewTransform::lights
    std::size_t draw = 0, triangle = 0;
    double height = 0.0;  // from the triangle's plane, above the triangle itself
    double limit = 0.0;   // kLightSurfaceRatio times the light's distance from the eye
};
// Each positional light within its limit of a triangle it lies above, with the nearest such.
std::vector<LightOnSurface> lightsOnSurfaces(const Scene& scene, const ViewTransform& view);

class ViewTransformStage {
public:
    ViewTransform run(const Scene& scene, const CameraBasis& basis) const;
};

}  // namespace rl
