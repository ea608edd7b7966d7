// The lighting model of seed 000, for one point P' with normal N in view coordinates:
//     V = -P',  L = Pl - P',  N, V, L normalised;
//     if V.N < 0, N := -N                       (turn the normal toward the viewer)
//     if N.L < 0: no diffuse and no specular     (the light is behind the surface)
//     else R = 2 (N.L) N - L, normalised; if R.V < 0: no specular
//     I = Ia ka + Il Od kd (N.L) + Il ks (R.V)^n, per colour channel, summed over lights.
// Clamping to the colour scale (255) happens once, when the image becomes bytes.
// Every term and every special case is returned, so the pixel inspector can show them.
#pragma once

#include <cmath>
#include <cstddef>

#include "math.h"
#include "scene.h"
#include "view_transform.h"

namespace rl {

struct PhongSample {
    vec3 ambient = vec3(0.0f);   // Ia ka
    vec3 diffuse = vec3(0.0f);   // sum of Il Od kd (N.L)
    vec3 specular = vec3(0.0f);  // sum of Il ks (R.V)^n
    vec3 n = vec3(0.0f);         // unit normal actually used (after the flip)
    vec3 l = vec3(0.0f);         // unit vector toward the (first) light
    vec3 v = vec3(0.0f);         // unit vector toward the viewer
    vec3 r = vec3(0.0f);         // reflection of L about N
    float nDotL = 0.0f;
    float rDotV = 0.0f;
    bool flipped = false;       // V.N < 0: N was turned toward the viewer
    bool lightBehind = false;   // N.L < 0: no diffuse, no specular
    bool noSpecular = false;    // R.V < 0: no specular
    bool noNormal = false;      // N is zero (a vertex of degenerate triangles only): ambient only
    bool lightAtPoint = false;  // L = 0: the light sits on the point, ambient only

    vec3 colour() const { return ambient + diffuse + specular; }
};

// For one light; `sample` receives the light's terms added to its diffuse and specular,
// and the vectors of the first light are kept for display.
inline void addLight(const Material& m, const ViewLight& light, const vec3& pView,
                     const vec3& nUnit, const vec3& vUnit, bool first, PhongSample& sample) {
    vec3 toLight = light.pView.w == 0.0 ? vec3(light.pView) : vec3(light.pView) - pView;
    const float lLength = glm::length(toLight);
    if (!(lLength > 0.0f)) {
        if (first) sample.lightAtPoint = true;
        return;
    }
    const vec3 l = toLight / lLength;
    const float nDotL = glm::dot(nUnit, l);
    vec3 r(0.0f);
    float rDotV = 0.0f;
    if (nDotL >= 0.0f) {
        r = 2.0f * nDotL * nUnit - l;
        const float rLength = glm::length(r);
        if (rLength > 0.0f) r /= rLength;
        rDotV = glm::dot(r, vUnit);
        sample.diffuse += light.intensity * m.od * m.kd * nDotL;
        if (rDotV >= 0.0f && m.ks != 0.0f) {
            // (R.V)^n, with 0^0 = 1 as in C's pow. A negative n (outside the course's range,
            // and warned about when read) makes 0^n infinite: that term is left out rather
            // than turned into NaN.
            const float power = std::pow(rDotV, m.shininess);
            if (std::isfinite(power)) sample.specular += light.intensity * m.ks * power;
        }
    }
    if (first) {
        sample.l = l;
        sample.r = r;
        sample.nDotL = nDotL;
        sample.rDotV = rDotV;
        sample.lightBehind = nDotL < 0.0f;
        sample.noSpecular = nDotL >= 0.0f && rDotV < 0.0f;
    }
}

inline PhongSample phong(const Material& m, const vec3& ambientIntensity, const ViewLight* lights,
                         std::size_t lightCount, const vec3& pView, const vec3& nView,
                         bool flipTowardViewer) {
    PhongSample s;
    s.ambient = ambientIntensity * m.ka;
    const float vLength = glm::length(pView);
    s.v = vLength > 0.0f ? -pView / vLength : vec3(0.0f);
    const float nLength = glm::length(nView);
    if (!(nLength > 0.0f)) {
        s.noNormal = true;
        return s;
    }
    s.n = nView / nLength;
    if (flipTowardViewer && glm::dot(s.v, s.n) < 0.0f) {
        s.n = -s.n;
        s.flipped = true;
    }
    for (std::size_t i = 0; i < lightCount; ++i) addLight(m, lights[i], pView, s.n, s.v, i == 0, s);
    return s;
}

}  // namespace rl
