// The course's Phong model (phong.h) for a run of pixels that one triangle won, written
// for several lanes at once: the hot loop of a course render. The same operations in the
// same order as phong(), so the colours are the same bits as the one-pixel path's (which a
// recording probe uses); built for the baseline x86-64, x86-64-v3 (AVX2) and x86-64-v4
// (AVX-512, unless RASTERLAB_KERNELS leaves it out), the best one chosen when the program
// starts (multiversion.h).
#pragma once

#include <cstddef>
#include <cstdint>

#include "pipeline/core/math.h"
#include "pipeline/scene/scene.h"
#include "pipeline/stages/view_transform.h"

namespace rl {

// What a run needs, worked out once: P' and N at weights (beta, gamma) are
// x0 + beta d1 + gamma d2, and one light's constant factors.
struct CoursePhongRun {
    vec3 p0, dp1, dp2;  // view-space position
    vec3 n0, dn1, dn2;  // vertex normal (not normalised)
    vec3 ambient;       // Ia ka
    vec3 diffuse;       // (Il Od) kd
    vec3 specular;      // Il ks
    vec3 light;         // view-space position, or direction toward the light
    bool directional = false;
    float shininess = 1.0f;
    bool flip = true;          // turn N toward the viewer
    bool withSpecular = true;  // ks != 0
};

// The run's constants for a material under one light (its position or direction in view
// space), as phong() multiplies them: Ia ka, (Il Od) kd, Il ks.
CoursePhongRun coursePhongRun(const Material& material, const ViewLight& light,
                              const vec3& ambientIntensity, bool flip);

struct CoursePhongCounts {
    std::size_t flipped = 0, lightBehind = 0, noSpecular = 0, noNormal = 0, clamped = 0;
};

// Shades `count` pixels with barycentrics bary[i] = (beta, gamma) into colour[i] (and the
// normal used into normal[i] when normal is not null); clampScale is the colour scale.
void shadeCoursePhongRun(const CoursePhongRun& run, const vec2* bary, int count, vec3* colour,
                         vec3* normal, float clampScale, CoursePhongCounts& counts);

// The same model at `count` points (Gouraud's vertices, flat's barycentres): point
// v = at[i] (v = i when at is null) is lit at P = p[v] with the normal n[v] (not normalised)
// as phong() lights it, its colour written to colour[v] and, when normal is not null, the
// normal used to normal[v]; counts.clamped is not counted.
void shadeCoursePhongPoints(const CoursePhongRun& run, const vec3* p, const vec3* n,
                            const std::uint32_t* at, std::size_t count, vec3* colour,
                            vec3* normal, CoursePhongCounts& counts);

// Gouraud's colours for a run of pixels, (c0 + beta d1) + gamma d2 with the barycentrics
// bary[i] = (beta, gamma), into colour[i] (the same bits as interpolate()); returns how many
// are above the colour scale.
std::size_t shadeGouraudRun(const vec3& c0, const vec3& d1, const vec3& d2, const vec2* bary,
                            int count, vec3* colour, float clampScale);

// out[i] = colour for i < count (a flat run, or the background), eight or four pixels a
// store (kernelLanes).
void fillColourRun(const vec3& colour, int count, vec3* out);

}  // namespace rl
