// What the fuzz targets share: a small scene to render what a reader accepted, so that the
// stages meet whatever numbers the reader lets through (NaN and Inf are refused by the
// readers; huge, tiny, zero and negative values are not).
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "course_readers.h"
#include "course_scene.h"
#include "renderer.h"

namespace rl::fuzz {

inline std::string_view textOf(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

// A camera at (0, 0, -10) looking along +z, with 90 degrees of view.
inline CourseCamera fixedCamera() {
    CourseCamera c;
    c.c = dvec3(0.0, 0.0, -10.0);
    c.n = dvec3(0.0, 0.0, 1.0);
    c.v = dvec3(0.0, 1.0, 0.0);
    c.d = 1.0;
    c.hx = 1.0;
    c.hy = 1.0;
    return c;
}

inline CourseLighting fixedLighting() {
    CourseLighting l;
    l.material.ka = 0.2f;
    l.material.kd = vec3(0.5f);
    l.material.od = vec3(0.8f, 0.5f, 0.3f);
    l.material.ks = 0.5f;
    l.material.shininess = 8.0f;
    l.ambientIntensity = vec3(100.0f);
    l.lights.push_back({dvec4(-5.0, 5.0, -10.0, 1.0), vec3(255.0f), {}});
    return l;
}

// Two triangles of a square around the origin.
inline CourseObject fixedObject() {
    auto mesh = std::make_shared<Mesh>();
    mesh->positions = {dvec4(-1, -1, 0, 1), dvec4(1, -1, 0, 1), dvec4(1, 1, 0, 1),
                       dvec4(-1, 1, 0, 1)};
    mesh->triangles = {{0, 1, 2}, {0, 2, 3}};
    return {"square", mesh};
}

// Renders the parts small, in each shading model, on one thread; the result is not
// checked here (the sanitizers check the way there), only that a frame comes back or a
// value-error does.
inline void renderSmall(const CourseSceneParts& parts) {
    for (ShadingModel shading : {ShadingModel::Phong, ShadingModel::Gouraud, ShadingModel::Flat}) {
        CourseSceneSettings settings;
        settings.width = 32;
        settings.height = 24;
        settings.shading = shading;
        auto scene = std::make_shared<const Scene>(makeCourseScene(parts, settings));
        RenderOptions options;
        options.threads = 1;
        auto frame = renderFrame(scene, options);
        (void)frame;
    }
}

}  // namespace rl::fuzz
