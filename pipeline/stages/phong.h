// The lighting models, for one point P' with normal N in view coordinates.
//
// The course's (seed 000), phong():
//     V = -P',  L = Pl - P',  N, V, L normalised (multiplied by 1/length);
//     if V.N < 0, N := -N                       (turn the normal toward the viewer)
//     if N.L < 0: no diffuse and no specular     (the light is behind the surface)
//     else R = 2 (N.L) N - L (a unit vector, as N and L are); if R.V < 0: no specular
//     I = Ia ka + Il Od kd (N.L) + Il ks (R.V)^n, per colour channel, summed over lights.
// With the lecture slides' lighting (seed 003, OpenGL's): a light's two terms are multiplied
// by its attenuation 1 / (kc + kl d + kq d^2) and its spot factor (lightFactor), the
// highlight may be Blinn-Phong's Il ks (N.H)^n, and the material's emission Ke is added:
//     I = Ke + Ia ka + sum over lights of  att spot (Il Od kd (N.L) + Il ks (R.V)^n).
// The command files' (seed 001), hw2Lighting():
//     I = sum over lights with N.L >= 0 of  Il O (N.L)  +  Il (H.N)^s  (the second only
//     when the shininess s > 0; H = (L + E)/|L + E| with E = -P'/|P'|, Blinn-Phong).
// Clamping to the colour scale happens once, when the image becomes bytes. Every term and
// every special case is returned, so the pixel inspector can show them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "pipeline/core/fast_pow.h"
#include "pipeline/core/math.h"
#include "pipeline/scene/scene.h"
#include "pipeline/stages/view_transform.h"

namespace rl {

// Above this n, (R.V)^n is worked out in double (specularPower): float's rounding of R.V,
// about 6e-8, is multiplied by n in the power and would pass a tenth of a byte step.
inline constexpr float kPreciseShininess = 1000.0f;

// (R.V)^n, with 0^0 = 1 as in C's pow. Up to kPreciseShininess from the float R.V
// (fast_pow.h); above it from the cosine of R and V in double.
inline float specularPower(const vec3& r, const vec3& v, float rDotV, float n) {
    if (!(n > kPreciseShininess)) return fastPow(rDotV, n);
    const dvec3 rd(r), vd(v);
    const double lengths = glm::length(rd) * glm::length(vd);
    const double cosine = lengths > 0.0 ? std::clamp(glm::dot(rd, vd) / lengths, 0.0, 1.0) : 0.0;
    return static_cast<float>(std::pow(cosine, double(n)));
}

struct PhongSample {
    vec3 ambient = vec3(0.0f);   // Ia ka
    vec3 diffuse = vec3(0.0f);   // sum of Il Od kd (N.L)
    vec3 specular = vec3(0.0f);  // sum of Il ks (R.V)^n, or Il (H.N)^s
    vec3 unlit = vec3(0.0f);     // the object colour itself, for a draw that is not lit
    vec3 emission = vec3(0.0f);  // Ke, the material's own light
    vec3 n = vec3(0.0f);         // unit normal actually used (after the flip)
    vec3 l = vec3(0.0f);         // unit vector toward the (first) light
    vec3 v = vec3(0.0f);         // unit vector toward the viewer
    vec3 r = vec3(0.0f);         // reflection of L about N (course), or the half vector H
    float nDotL = 0.0f;
    float rDotV = 0.0f;         // R.V (course) or H.N (Blinn-Phong)
    bool flipped = false;       // V.N < 0: N was turned toward the viewer
    bool lightBehind = false;   // N.L < 0: no diffuse, no specular
    bool noSpecular = false;    // R.V < 0: no specular
    bool noNormal = false;      // N is zero (a vertex of degenerate triangles only): ambient only
    bool lightAtPoint = false;  // L = 0: the light sits on the point, ambient only
    bool outsideCone = false;   // the point is outside the (first) light's spot cone

    // Emission last: zero for the course's files, so their sums keep their bits.
    vec3 colour() const { return ambient + diffuse + specular + unlit + emission; }
};

// The unit vector from pView toward a light, or zero when the light sits on the point. A
// light so far that the square of its distance overflows float is first brought nearer
// along the same line (divided by its largest coordinate), rather than taken for one at the
// point.
inline vec3 towardLight(const ViewLight& light, const vec3& pView) {
    vec3 toLight = light.pView.w == 0.0 ? vec3(light.pView) : vec3(light.pView) - pView;
    float length = glm::length(toLight);
    if (length == std::numeric_limits<float>::infinity()) {
        const float largest =
            std::max(std::max(std::abs(toLight.x), std::abs(toLight.y)), std::abs(toLight.z));
        toLight = toLight * (1.0f / largest);
        length = glm::length(toLight);
    }
    return length > 0.0f ? toLight * (1.0f / length) : vec3(0.0f);
}

// The normal to light with: normalised, and turned toward the viewer when asked and V.N < 0.
// False when the normal is zero.
inline bool orientNormal(PhongSample& s, const vec3& pView, const vec3& nView, bool flip) {
    const float vLength = glm::length(pView);
    s.v = vLength > 0.0f ? -pView * (1.0f / vLength) : vec3(0.0f);
    const float nLength = glm::length(nView);
    if (!(nLength > 0.0f)) {
        s.noNormal = true;
        return false;
    }
    s.n = nView * (1.0f / nLength);
    if (flip && glm::dot(s.v, s.n) < 0.0f) {
        s.n = -s.n;
        s.flipped = true;
    }
    return true;
}

// What one light gives a point under the course's model: the pixel inspector's breakdown
// per light and per term (phong's perLight), from the very code the render runs.
struct LightTerms {
    vec3 diffuse = vec3(0.0f);   // factor Il Od kd (N.L)
    vec3 specular = vec3(0.0f);  // factor Il ks (R.V)^n, or (N.H)^n
    vec3 l = vec3(0.0f);         // unit vector toward the light
    vec3 r = vec3(0.0f);         // R, or H under Blinn-Phong
    float nDotL = 0.0f;
    float rDotV = 0.0f;        // R.V, or N.H under Blinn-Phong
    float distance = 0.0f;     // to a positional light (0 for a directional one)
    float attenuation = 1.0f;  // 1 / (kc + kl d + kq d^2)
    float spotCos = 1.0f;      // -L.D, the cosine of the angle off the spot's axis
    float spot = 1.0f;         // (-L.D)^exponent inside the cone, 0 outside, 1 if not a spot
    bool atPoint = false;      // L = 0: the light sits on the point
    bool behind = false;       // N.L < 0
    bool noSpecular = false;   // R.V < 0 (N.H < 0)
    bool outsideCone = false;  // beyond the spot's cutoff: no light from it
};

// The factor a light's diffuse and specular terms are multiplied by at a point: attenuation
// with distance (positional lights) times the spot's, and whether the point is outside the
// spot's cone.
struct LightFactor {
    float value = 1.0f;
    bool outsideCone = false;
};

// The factor at pView, l the unit vector toward the light; terms, when given, receives its
// parts (distance, attenuation, the spot's cosine and factor).
inline LightFactor lightFactor(const ViewLight& light, const vec3& pView, const vec3& l,
                               LightTerms* terms) {
    LightFactor f;
    if (light.attenuated) {
        const float d = glm::length(vec3(light.pView) - pView);
        const vec3& k = light.attenuation;
        const float denominator = k.x + k.y * d + k.z * d * d;
        // kc + kl d + kq d^2 <= 0 (coefficients outside OpenGL's range) would divide by zero
        // or make light negative: the light is left out there instead.
        const float attenuation = denominator > 0.0f ? 1.0f / denominator : 0.0f;
        f.value *= attenuation;
        if (terms) {
            terms->distance = d;
            terms->attenuation = attenuation;
        }
    } else if (terms && light.pView.w != 0.0) {
        terms->distance = glm::length(vec3(light.pView) - pView);
    }
    if (light.spot) {
        const float spotCos = -glm::dot(l, light.spotDirection);
        f.outsideCone = spotCos < light.spotCosCutoff;
        // 0^0 = 1: on the cone's edge at 90 degrees with exponent 0 the light is whole.
        const float spot = !(spotCos >= light.spotCosCutoff) ? 0.0f
                           : light.spotExponent == 0.0f
                               ? 1.0f
                               : std::pow(std::max(spotCos, 0.0f), light.spotExponent);
        f.value *= spot;
        if (terms) {
            terms->spotCos = spotCos;
            terms->spot = spot;
            terms->outsideCone = f.outsideCone;
        }
    }
    return f;
}

// What one light gives the point pView under the course's model: n is the normal (unit, and
// turned toward the viewer, except in the mistakes of mistakes.h), v the unit vector toward
// the viewer.
inline LightTerms lightTerms(const Material& m, const vec3& od, const ViewLight& light,
                             const vec3& pView, const vec3& n, const vec3& v,
                             SpecularModel specularModel = SpecularModel::Phong) {
    LightTerms t;
    t.l = towardLight(light, pView);
    if (t.l == vec3(0.0f)) {
        t.atPoint = true;
        return t;
    }
    // The course's own lights are neither attenuated nor spots: their factor is 1.
    const LightFactor f = light.plain() ? LightFactor{} : lightFactor(light, pView, t.l, &t);
    t.nDotL = glm::dot(n, t.l);
    t.behind = t.nDotL < 0.0f;
    if (!(t.nDotL >= 0.0f)) return t;  // behind (or NaN): no diffuse, no specular
    if (specularModel == SpecularModel::BlinnPhong) {
        // H = (L + V) times 1/|L + V|, normalised the course's way (not hw2Lighting()'s
        // division); zero when the light is straight behind the viewer's line.
        const vec3 sum = t.l + v;
        const float length = glm::length(sum);
        if (length > 0.0f) t.r = sum * (1.0f / length);
        t.rDotV = glm::dot(n, t.r);
    } else {
        // |R| = 1, since N and L are unit vectors: not normalised again.
        t.r = 2.0f * t.nDotL * n - t.l;
        t.rDotV = glm::dot(t.r, v);
    }
    t.noSpecular = t.rDotV < 0.0f;
    const vec3 il = light.intensity * f.value;
    t.diffuse = il * od * m.kd * t.nDotL;
    if (t.rDotV >= 0.0f && m.ks != 0.0f) {  // not when R.V is NaN either
        // (R.V)^n, or (N.H)^n. A negative n (outside the course's range, and warned about
        // when read) is not a highlight: its huge or infinite values are left out rather
        // than turned into NaN.
        const float power = specularModel == SpecularModel::BlinnPhong
                                ? specularPower(n, t.r, t.rDotV, m.shininess)
                                : specularPower(t.r, v, t.rDotV, m.shininess);
        if (std::isfinite(power)) t.specular = il * m.ks * power;
    }
    return t;
}

// One light's terms added to sample; the first light's vectors are kept for display.
inline void addLight(const LightTerms& t, bool first, PhongSample& sample) {
    if (!t.atPoint && t.nDotL >= 0.0f) {
        sample.diffuse += t.diffuse;
        if (t.specular != vec3(0.0f)) sample.specular += t.specular;
    }
    if (!first) return;
    if (t.atPoint) {
        sample.lightAtPoint = true;
        return;
    }
    sample.l = t.l;
    sample.r = t.r;
    sample.nDotL = t.nDotL;
    sample.rDotV = t.rDotV;
    sample.lightBehind = t.behind;
    sample.noSpecular = t.noSpecular;
    sample.outsideCone = t.outsideCone && !t.behind;
}

// The course's model; od is the object colour (the material's Od, or a per-vertex one).
// perLight, when given, receives each light's terms (lightCount entries).
inline PhongSample phong(const Material& m, const vec3& od, const vec3& ambientIntensity,
                         const ViewLight* lights, std::size_t lightCount, const vec3& pView,
                         const vec3& nView, bool flipTowardViewer,
                         SpecularModel specularModel = SpecularModel::Phong,
                         LightTerms* perLight = nullptr) {
    PhongSample s;
    s.ambient = ambientIntensity * m.ka;
    s.emission = m.emission;
    if (!orientNormal(s, pView, nView, flipTowardViewer)) return s;
    for (std::size_t i = 0; i < lightCount; ++i) {
        const LightTerms t = lightTerms(m, od, lights[i], pView, s.n, s.v, specularModel);
        addLight(t, i == 0, s);
        if (perLight) perLight[i] = t;
    }
    return s;
}

// The command files' model: Lambert for each light in front of the surface, plus
// Blinn-Phong highlights when the shininess is positive. The object colour does not tint
// the highlight.
inline PhongSample hw2Lighting(const vec3& objectColour, float shininess, const ViewLight* lights,
                               std::size_t lightCount, const vec3& pView, const vec3& nView,
                               bool flipTowardViewer) {
    PhongSample s;
    if (!orientNormal(s, pView, nView, flipTowardViewer)) return s;
    for (std::size_t i = 0; i < lightCount; ++i) {
        const vec3 l = towardLight(lights[i], pView);
        const float nDotL = glm::dot(s.n, l);
        float hDotN = 0.0f;
        vec3 h(0.0f);
        if (nDotL >= 0.0f && l != vec3(0.0f)) {
            s.diffuse += lights[i].intensity * objectColour * nDotL;
            if (shininess > 0.0f) {
                const vec3 sum = l + s.v;
                const float length = glm::length(sum);
                if (length > 0.0f) {
                    h = sum / length;
                    hDotN = std::max(glm::dot(h, s.n), 0.0f);
                    s.specular += lights[i].intensity * specularPower(h, s.n, hDotN, shininess);
                }
            }
        }
        if (i == 0) {
            s.l = l;
            s.r = h;
            s.nDotL = nDotL;
            s.rDotV = hDotN;
            s.lightBehind = nDotL < 0.0f;
            s.lightAtPoint = l == vec3(0.0f);
        }
    }
    return s;
}

}  // namespace rl
