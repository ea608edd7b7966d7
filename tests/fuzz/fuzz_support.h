// What the fuzz targets share: a small scene to render what a reader accepted, so that the
// stages meet whatever numbers the reader lets through (NaN and Inf are refused by the
// readers; huge, tiny, zero and negative values are not).
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <string_view>

#include "pipeline/io/course_readers.h"
#include "pipeline/io/course_scene.h"
#include "pipeline/render/renderer.h"
#include "pipeline/stages/probe.h"

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

inline bool sameValue(float a, float b) {
    return a == b || (std::isnan(a) && std::isnan(b));
}
inline bool sameValue(const vec3& a, const vec3& b) {
    return sameValue(a.x, b.x) && sameValue(a.y, b.y) && sameValue(a.z, b.z);
}
// Equal pixel by pixel as tst_fast_paths compares them (0 = -0), a NaN equal to any NaN.
template <typename T>
bool sameValues(const Image<T>& a, const Image<T>& b) {
    if (a.width() != b.width() || a.height() != b.height()) return false;
    for (std::size_t i = 0; i < a.pixels().size(); ++i)
        if (!sameValue(a.pixels()[i], b.pixels()[i])) return false;
    return true;
}

// What a fast frame must share with the lecture's: the colours and the depth test's counts;
// keeping every buffer, also the z-buffer, the winners and the shading's counts (in bands,
// flat and Gouraud light every triangle with a fragment first, so their counts may be
// larger).
inline bool sameFrame(const FrameTrace& plain, const FrameTrace& fast, bool keep) {
    const DepthTest& p = *plain.depth;
    const DepthTest& q = *fast.depth;
    const Shading& x = *plain.shading;
    const Shading& y = *fast.shading;
    if (!sameValues(x.colour, y.colour) || p.fragments != q.fragments || p.passed != q.passed ||
        p.outsideDepthRange != q.outsideDepthRange ||
        plain.projection->triangles.size() != fast.projection->triangles.size() ||
        plain.scan->pixels != fast.scan->pixels)
        return false;
    if (!keep) return true;
    return sameValues(p.depth, q.depth) && p.triangle == q.triangle &&
           x.shadedPixels == y.shadedPixels && x.phongEvaluations == y.phongEvaluations &&
           x.flipped == y.flipped && x.lightBehind == y.lightBehind &&
           x.noSpecular == y.noSpecular && x.noNormal == y.noNormal &&
           x.clampedPixels == y.clampedPixels;
}

// The lecture's stages (traceFrame) and the fast paths (renderFrame: one and two threads,
// keeping every buffer and keeping only the image, on two threads in bands of 3 rows, a
// chunk of 8 in three) must give the same frame (sameFrame), as
// tst_fast_paths holds them on chosen scenes. A difference aborts, so that libFuzzer keeps
// the input. (Built by Clang, the fuzzers run the baseline kernels: multiversion.h.)
inline void renderBothWays(const std::shared_ptr<const Scene>& scene) {
    RenderOptions options;
    auto probe = RecordingProbe::forPixel(-1, -1);
    const auto plain = traceFrame(scene, options, probe);
    for (int threads : {1, 2}) {
        for (bool keep : {true, false}) {
            options.threads = threads;
            options.keepDepth = options.keepFragments = options.keepForViews = keep;
            options.bandRows = threads == 2 ? 3 : 0;
            const auto fast = renderFrame(scene, options);
            const bool same = plain.ok() ? fast.ok() && sameFrame(*plain, *fast, keep)
                                         : !fast.ok() && plain.error().code == fast.error().code;
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
