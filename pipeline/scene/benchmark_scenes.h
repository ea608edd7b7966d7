// Procedural scenes for benchmarks: UV spheres and tori of about 1k, 100k and 1M
// triangles, framed by a course camera that fits the object's bounding sphere in the
// view, lit by one white light up and to the left of the camera, with a Phong material.
// Also a sphere seen from inside its own radius, so that it fills the whole image.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/scene/scene.h"

namespace rl {

// A UV sphere of radius 1 around the origin, y through the poles: nu segments around,
// nv bands from pole to pole; 2 nu (nv - 1) triangles, wound counter-clockwise seen from
// outside.
std::shared_ptr<Mesh> uvSphere(int nu, int nv);
// A torus around the y axis (radius R to the tube's centre, r of the tube): nu segments
// around the axis, nv around the tube; 2 nu nv triangles, counter-clockwise from outside.
std::shared_ptr<Mesh> torusMesh(int nu, int nv, double R = 1.0, double r = 0.35);

struct BenchmarkScene {
    std::string name;         // "sphere-100k"
    std::string description;  // "UV sphere, 250 x 201, 100,000 triangles"
};

// The names benchmark scenes are known by: sphere-1k, sphere-100k, sphere-1m, torus-1k,
// torus-100k, torus-1m, and full-screen (a 1k sphere around the camera's view).
const std::vector<BenchmarkScene>& benchmarkScenes();

// The scene with that name at the given size and shading, or nullopt for an unknown name.
std::optional<Scene> makeBenchmarkScene(std::string_view name, int width, int height,
                                        ShadingModel shading);

// A course camera that looks along `direction` at the mesh's bounding-sphere centre from
// just far enough for the sphere to fit the narrower field of view (40 degrees vertically),
// and a light up and to the left of it: the framing the benchmark scenes use.
struct Framing {
    CourseCamera camera;
    dvec3 light;
};
Framing frameMesh(const Mesh& mesh, int width, int height, dvec3 direction = {0.3, -0.6, 1.0});

}  // namespace rl
