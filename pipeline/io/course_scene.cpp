#include "course_scene.h"

#include <filesystem>

#include "pipeline/scene/mesh_topology.h"

namespace rl {

Result<CourseObject> parseCourseObject(std::string_view text, const std::string& fileName,
                                       Diagnostics& diagnostics) {
    auto mesh = readByuMesh(text, fileName, diagnostics);
    if (!mesh) return mesh.error();
    CourseObject object;
    object.name = std::filesystem::path(fileName).filename().string();
    mesh->closedWinding = closedSurfaceWinding(*mesh);
    object.mesh = std::make_shared<const Mesh>(std::move(mesh).value());
    return object;
}

Scene makeCourseScene(const CourseSceneParts& parts, const CourseSceneSettings& settings) {
    Scene scene;
    scene.name = parts.object.name;
    scene.width = settings.width;
    scene.height = settings.height;
    scene.camera = parts.camera;
    scene.lights = parts.lighting.lights;
    scene.ambientIntensity = parts.lighting.ambientIntensity;
    scene.nearPlane = settings.nearPlane;
    scene.cullHiddenBackFaces = settings.cullHiddenBackFaces;
    scene.rules = settings.rules;
    scene.conventions = Conventions::course();
    scene.conventions.flipNormalsTowardViewer = parts.lighting.twoSided;

    Draw draw;
    draw.name = parts.object.name;
    draw.mesh = parts.object.mesh;
    draw.material = parts.lighting.material;
    draw.shading = settings.shading;
    draw.specular = parts.lighting.specular;
    scene.draws.push_back(std::move(draw));
    return scene;
}

}  // namespace rl
