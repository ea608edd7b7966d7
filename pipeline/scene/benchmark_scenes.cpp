#include "benchmark_scenes.h"

#include "pipeline/scene/mesh_topology.h"

#include <algorithm>
#include <cmath>

namespace rl {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

std::shared_ptr<Mesh> uvSphere(int nu, int nv) {
    auto mesh = std::make_shared<Mesh>();
    mesh->positions.push_back({0.0, 1.0, 0.0, 1.0});  // north pole
    for (int i = 1; i < nv; ++i) {
        const double theta = kPi * i / nv;
        for (int j = 0; j < nu; ++j) {
            const double phi = 2.0 * kPi * j / nu;
            mesh->positions.push_back({std::sin(theta) * std::cos(phi), std::cos(theta),
                                       std::sin(theta) * std::sin(phi), 1.0});
        }
    }
    mesh->positions.push_back({0.0, -1.0, 0.0, 1.0});  // south pole
    const auto south = static_cast<std::uint32_t>(mesh->positions.size() - 1);
    const auto ring = [nu](int i, int j) {  // vertex j of band i (1 .. nv - 1)
        return static_cast<std::uint32_t>(1 + (i - 1) * nu + (j % nu));
    };
    auto& t = mesh->triangles;
    for (int j = 0; j < nu; ++j) t.push_back({0, ring(1, j + 1), ring(1, j)});
    for (int i = 1; i + 1 < nv; ++i)
        for (int j = 0; j < nu; ++j) {
            t.push_back({ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)});
            t.push_back({ring(i, j), ring(i, j + 1), ring(i + 1, j + 1)});
        }
    for (int j = 0; j < nu; ++j) t.push_back({ring(nv - 1, j), ring(nv - 1, j + 1), south});
    mesh->source = {"<sphere>", 0, 0};
    mesh->closedWinding = closedSurfaceWinding(*mesh);
    return mesh;
}

std::shared_ptr<Mesh> torusMesh(int nu, int nv, double R, double r) {
    auto mesh = std::make_shared<Mesh>();
    for (int j = 0; j < nu; ++j) {
        const double phi = 2.0 * kPi * j / nu;
        for (int i = 0; i < nv; ++i) {
            const double theta = 2.0 * kPi * i / nv;
            const double radius = R + r * std::cos(theta);
            mesh->positions.push_back(
                {radius * std::cos(phi), r * std::sin(theta), radius * std::sin(phi), 1.0});
        }
    }
    const auto id = [nu, nv](int j, int i) {
        return static_cast<std::uint32_t>((j % nu) * nv + (i % nv));
    };
    for (int j = 0; j < nu; ++j)
        for (int i = 0; i < nv; ++i) {
            mesh->triangles.push_back({id(j, i), id(j, i + 1), id(j + 1, i + 1)});
            mesh->triangles.push_back({id(j, i), id(j + 1, i + 1), id(j + 1, i)});
        }
    mesh->source = {"<torus>", 0, 0};
    mesh->closedWinding = closedSurfaceWinding(*mesh);
    return mesh;
}

const std::vector<BenchmarkScene>& benchmarkScenes() {
    static const std::vector<BenchmarkScene> scenes = {
        {"sphere-1k", "UV sphere, 25 x 21, 1,000 triangles"},
        {"sphere-100k", "UV sphere, 250 x 201, 100,000 triangles"},
        {"sphere-1m", "UV sphere, 1000 x 501, 1,000,000 triangles"},
        {"torus-1k", "torus, 25 x 20, 1,000 triangles"},
        {"torus-100k", "torus, 250 x 200, 100,000 triangles"},
        {"torus-1m", "torus, 1000 x 500, 1,000,000 triangles"},
        {"full-screen", "the 1k sphere around the view: every pixel lit per pixel"},
    };
    return scenes;
}

Framing frameMesh(const Mesh& mesh, int width, int height, dvec3 direction) {
    dvec3 lo(1e300), hi(-1e300);
    for (const dvec4& p : mesh.positions) {
        lo = glm::min(lo, dvec3(p));
        hi = glm::max(hi, dvec3(p));
    }
    const dvec3 centre = (lo + hi) / 2.0;
    const double radius = glm::length(hi - lo) / 2.0;
    Framing f;
    CourseCamera& c = f.camera;
    c.d = 1.0;
    c.hy = std::tan(20.0 * kPi / 180.0);
    c.hx = c.hy * width / height;
    c.n = glm::normalize(direction);
    c.v = dvec3(0.0, 1.0, 0.0);
    // Far enough for the bounding sphere to fit the narrower half-angle, with 2% to spare.
    const double halfAngle = std::atan(std::min(c.hx, c.hy) / c.d);
    const double distance = radius / std::sin(halfAngle) * 1.02;
    c.c = centre - c.n * distance;
    const dvec3 up = glm::normalize(c.v - glm::dot(c.v, c.n) * c.n);
    const dvec3 right = glm::cross(c.n, up);
    f.light = c.c + (up - right) * (0.5 * distance);
    return f;
}

std::optional<Scene> makeBenchmarkScene(std::string_view name, int width, int height,
                                        ShadingModel shading) {
    std::shared_ptr<Mesh> mesh;
    if (name == "sphere-1k" || name == "full-screen")
        mesh = uvSphere(25, 21);
    else if (name == "sphere-100k")
        mesh = uvSphere(250, 201);
    else if (name == "sphere-1m")
        mesh = uvSphere(1000, 501);
    else if (name == "torus-1k")
        mesh = torusMesh(25, 20);
    else if (name == "torus-100k")
        mesh = torusMesh(250, 200);
    else if (name == "torus-1m")
        mesh = torusMesh(1000, 500);
    else
        return std::nullopt;

    Framing framing = frameMesh(*mesh, width, height);
    if (name == "full-screen") {
        // From (0, 0, -1.5) toward the centre: the unit sphere covers the whole view.
        framing.camera.c = dvec3(0.0, 0.0, -1.5);
        framing.camera.n = dvec3(0.0, 0.0, 1.0);
        framing.light = dvec3(0.75, 0.75, -1.5);
    }
    Scene scene;
    scene.name = std::string(name);
    scene.width = width;
    scene.height = height;
    scene.camera = framing.camera;
    scene.conventions = Conventions::course();
    scene.rules = RasterRules::course();
    scene.ambientIntensity = vec3(255.0f);
    scene.lights.push_back({dvec4(framing.light, 1.0), vec3(255.0f), {}});
    scene.cullHiddenBackFaces = true;  // no course semantics to keep: hidden faces left out
    Draw draw;
    draw.name = std::string(name);
    draw.mesh = mesh;
    draw.material.ka = 0.15f;
    draw.material.kd = vec3(0.75f);
    draw.material.od = vec3(0.9f, 0.6f, 0.3f);
    draw.material.ks = 0.5f;
    draw.material.shininess = 32.0f;
    draw.shading = shading;
    scene.draws.push_back(std::move(draw));
    return scene;
}

}  // namespace rl
