#include "explain.h"

#include <cstdio>

#include "pipeline/core/format.h"
#include "pipeline/render/output_image.h"
#include "pipeline/stages/shading.h"

namespace rl {

namespace {

std::string f3(const vec3& v) {
    return formatVector(dvec3(v));
}

std::string triangleName(const FrameTrace& trace, std::uint32_t t) {
    const ScreenTriangle& tri = trace.projection->triangles[t];
    const Draw& draw = trace.scene->draws[tri.draw];
    std::string s = "triangle " + std::to_string(tri.source + 1) + " of " + draw.name;
    if (draw.mesh && tri.source < draw.mesh->triangleLines.size())
        s += " (line " + std::to_string(draw.mesh->triangleLines[tri.source]) + ")";
    if (trace.projection->draws[tri.draw].fate[tri.source] == TriangleFate::Clipped)
        s += ", its part in front of the near plane";
    return s;
}

std::string depthText(float z) {
    if (std::isinf(z)) return z > 0 ? "+infinity" : "-infinity";
    return formatNumber(z);
}

// "< stored 12: written", ">= stored 3: rejected, not nearer", or the range discard.
std::string depthVerdict(const DepthTestEvent& test, bool winsOnTie, bool painted) {
    if (test.outsideDepthRange) return ": discarded, outside the depth range [0, 1]";
    const std::string stored = "stored " + depthText(test.stored);
    if (painted) return ", over " + stored + ": painted, no depth test (painter's algorithm)";
    if (test.passed) return std::string(winsOnTie ? " <= " : " < ") + stored + ": written";
    return std::string(winsOnTie ? " > " : " >= ") + stored + ": rejected, not nearer";
}

void describeSample(std::string& out, const PhongSample& s, const Draw& draw) {
    if (draw.lighting == LightingModel::Unlit) {
        out += "    not lit: the colour is the object colour " + f3(s.unlit) + "\n";
        return;
    }
    out += "    N = " + f3(s.n) + (s.flipped ? "  (turned toward the viewer: V.N was < 0)" : "") +
           "\n";
    if (s.noNormal) {
        out +=
            "    the normal is zero (only degenerate triangles meet here): no light reaches it\n";
        return;
    }
    if (s.lightAtPoint) {
        out += "    the light is at the point itself (L = 0): it adds nothing\n";
        if (draw.lighting == LightingModel::CoursePhong) return;
    }
    const bool course = draw.lighting == LightingModel::CoursePhong;
    out += "    L = " + f3(s.l) + "   V = " + f3(s.v) + (course ? "   R = " : "   H = ") + f3(s.r) +
           (course ? "" : "   (the first light)") + "\n";
    out += "    N.L = " + formatNumber(s.nDotL) + (course ? "   R.V = " : "   H.N = ") +
           formatNumber(s.rDotV) + "\n";
    if (s.lightBehind)
        out += "    N.L < 0: the light is behind the surface, no diffuse, no specular\n";
    if (s.noSpecular)
        out += "    R.V < 0: the reflection points away from the viewer, no specular\n";
    if (course) {
        out += "    ambient  Ia*ka          = " + f3(s.ambient) + "\n";
        out += "    diffuse  Il*Od*kd*(N.L) = " + f3(s.diffuse) + "\n";
        out += "    specular Il*ks*(R.V)^n  = " + f3(s.specular) +
               "   (n = " + formatNumber(draw.material.shininess) + ")\n";
    } else {
        out += "    diffuse  sum of Il*O*(N.L)  = " + f3(s.diffuse) + "\n";
        out += "    specular sum of Il*(H.N)^s  = " + f3(s.specular) +
               "   (s = " + formatNumber(draw.material.shininess) + ")\n";
    }
}

std::string texelText(const ivec2& texel) {
    std::string text(1, '(');
    text += std::to_string(texel.x) + ", " + std::to_string(texel.y) + ")";
    return text;
}

// The texel a fragment read; where seed 001's text and the HW2 reference images pick
// different texels, both, and which one the rules follow.
void describeTexel(std::string& out, const TexelLookup& lookup, RasterRules::TexelRounding used) {
    out += "    texture at (s, t) = (" + formatNumber(lookup.st.x) + ", " +
           formatNumber(lookup.st.y) + "): texel " + texelText(lookup.used) + "\n";
    if (!lookup.rulesDisagree()) return;
    const bool images = used == RasterRules::TexelRounding::Truncate;
    out +=
        "    here seed 001's text and its reference images disagree: the texel nearest to "
        "(s w, t h) once the coordinates wrap is " +
        texelText(lookup.nearest) + ", the images' (int)(s w + 0.5) mod w gives " +
        texelText(lookup.truncated) + "; these rules follow the " + (images ? "images" : "text") +
        "\n";
}

}  // namespace

std::string explainPixel(const FrameTrace& trace, const RecordingProbe& probe) {
    std::string out;
    if (!probe.pixel()) return out;
    const ivec2 px = *probe.pixel();
    out += "pixel (" + std::to_string(px.x) + ", " + std::to_string(px.y) + ")\n";
    // Scan conversion: which triangles' spans reach the pixel.
    int spans = 0;
    for (const ProbeEvent& event : probe.events()) {
        if (const auto* span = std::get_if<SpanEvent>(&event)) {
            if (spans++ == 0) out += "  scan conversion: spans covering the pixel\n";
            out += "    " + triangleName(trace, span->triangle) + ": row " +
                   std::to_string(span->span.y) + ", x = " + std::to_string(span->span.xBegin) +
                   ".." + std::to_string(span->span.xEnd - 1) +
                   " (edges at x = " + formatNumber(span->xLeft) + " and " +
                   formatNumber(span->xRight) + ")\n";
        }
    }
    bool anyFragment = false;
    int fragment = 0;
    const DepthTestEvent* written = nullptr;  // the last fragment that passed
    for (const ProbeEvent& event : probe.events()) {
        if (const auto* test = std::get_if<DepthTestEvent>(&event)) {
            if (test->passed) written = test;
            if (!anyFragment) out += "  depth test, in drawing order:\n";
            anyFragment = true;
            out +=
                "    " + std::to_string(++fragment) + ". " + triangleName(trace, test->triangle) +
                ": barycentrics alpha = " + formatNumber(test->alpha) +
                ", beta = " + formatNumber(test->beta) + ", gamma = " + formatNumber(test->gamma) +
                "; z = " + depthText(test->depth) +
                depthVerdict(*test, trace.scene->conventions.depthWinsOnTie, trace.depth->painted) +
                "\n";
        } else if (const auto* shade = std::get_if<ShadeEvent>(&event)) {
            const Draw& draw =
                trace.scene->draws[trace.projection->triangles[shade->triangle].draw];
            out += "  shading (" + std::string(shadingModelName(shade->model)) +
                   ") of the winner, " + triangleName(trace, shade->triangle) + ":\n";
            switch (shade->model) {
                case ShadingModel::Phong:
                    out += "    P' = " + f3(shade->pView) +
                           "   N interpolated = " + f3(shade->nInterpolated) + "\n";
                    describeSample(out, shade->sample, draw);
                    break;
                case ShadingModel::Flat:
                case ShadingModel::Painter:
                    out += "    one evaluation at the triangle's barycentre, with its normal\n";
                    describeSample(out, shade->sample, draw);
                    break;
                case ShadingModel::Gouraud:
                    out += "    vertex colours " + f3(shade->vertexColours[0]) + ", " +
                           f3(shade->vertexColours[1]) + ", " + f3(shade->vertexColours[2]) +
                           ", interpolated with the barycentrics\n";
                    break;
            }
            const Conventions& conv = trace.scene->conventions;
            const vec3 c = shade->colour;
            const bool clamped =
                c.r > conv.colourScale || c.g > conv.colourScale || c.b > conv.colourScale;
            out += "    colour = " + f3(c) + " -> bytes (" + std::to_string(toByte(c.r, conv)) +
                   ", " + std::to_string(toByte(c.g, conv)) + ", " +
                   std::to_string(toByte(c.b, conv)) + ")" +
                   (clamped ? "  (clamped at " + formatNumber(conv.colourScale) + ")" : "") + "\n";
            const ScreenTriangle& tri = trace.projection->triangles[shade->triangle];
            if (written && written->triangle == shade->triangle)
                if (const auto lookup = texelLookup(*trace.scene, trace.projection->draws[tri.draw],
                                                    tri.v, tri.draw, written->beta, written->gamma))
                    describeTexel(out, *lookup, trace.scene->rules.texel);
        }
    }
    if (!anyFragment) out += "  no triangle covers this pixel: it keeps the background colour\n";
    return out;
}

}  // namespace rl
