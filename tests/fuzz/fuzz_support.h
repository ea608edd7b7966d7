// What the fuzz targets share: a small scene to render what a reader accepted, so that the
// stages meet whatever numbers the reader lets through (NaN and Inf are refused by the
// readers; huge, tiny, zero and negative values are not).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <string_view>

#include "course_readers.h"
#include "course_scene.h"
#include "probe.h"
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

template <typename T>
bool sameBits(const Image<T>& a, const Image<T>& b) {
    return a.width() == b.width() && a.height() == b.height() &&
           std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size() * sizeof(T)) == 0;
}

// The lecture's stages (traceFrame) and the fast paths (renderFrame: one and two threads,
// keeping every buffer and keeping only the image) must give the same bits, as tst_fast_paths
// holds them on chosen scenes. A difference aborts, so that libFuzzer keeps the input.
inline void renderBothWays(const std::shared_ptr<const Scene>& scene) {
    RenderOptions options;
    auto probe = RecordingProbe::forPixel(-1, -1);
    const auto plain = traceFrame(scene, options, probe);
    for (int threads : {1, 2}) {
        for (bool keep : {true, false}) {
            options.threads = threads;
            options.keepDepth = options.keepFragments = options.keepForViews = keep;
            const auto fast = renderFrame(scene, options);
            bool same = plain.ok() == fast.ok();
            if (same && plain.ok())
                same = sameBits(plain->shading->colour, fast->shading->colour) &&
                       (!keep || sameBits(plain->depth->depth, fast->depth->depth));
            if (!same) {
                std::fprintf(stderr, "fast path (%d thread(s), %s) differs from the lecture's\n",
                             threads, keep ? "every buffer" : "image only");
                std::abort();
            }
        }
    }
}

// Renders the parts small, in each shading model, both ways (renderBothWays).
inline void renderSmall(const CourseSceneParts& parts) {
    for (ShadingModel shading : {ShadingModel::Phong, ShadingModel::Gouraud, ShadingModel::Flat}) {
        CourseSceneSettings settings;
        settings.width = 32;
        settings.height = 24;
        settings.shading = shading;
        renderBothWays(std::make_shared<const Scene>(makeCourseScene(parts, settings)));
    }
}

}  // namespace rl::fuzz
