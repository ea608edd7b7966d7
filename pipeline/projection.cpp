#include "projection.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "format.h"

namespace rl {

dmat4 courseClipFromView(const CourseCamera& camera) {
    dmat4 m(0.0);
    m[0][0] = camera.d / camera.hx;
    m[1][1] = camera.d / camera.hy;
    m[2][2] = 1.0;
    m[2][3] = 1.0;  // w = z
    return m;
}

dmat4 clipFromViewOf(const Scene& scene, const Draw& draw) {
    if (draw.clipFromView) return *draw.clipFromView;
    if (scene.camera) return courseClipFromView(*scene.camera);
    return dmat4(1.0);
}

namespace {

double snap(double coordinate, RasterRules::VertexSnap rule) {
    switch (rule) {
        case RasterRules::VertexSnap::Truncate:
            return std::trunc(coordinate);  // C's (int)
    }
    return coordinate;
}

bool finite2(const dvec2& p) {
    return isFinite(p.x) && isFinite(p.y);
}

}  // namespace

Projection ProjectionStage::run(const Scene& scene, const ViewTransform& view,
                                Diagnostics& diagnostics) const {
    Projection out;
    out.naive = scene.nearPlane.naive;
    const double width = scene.width;
    const double height = scene.height;
    const Conventions& conv = scene.conventions;

    // Every vertex to clip space first: the near plane is a plane of clip space, w = near.
    out.draws.resize(scene.draws.size());
    double wMax = 0.0;
    for (std::size_t d = 0; d < scene.draws.size(); ++d) {
        DrawProjection& proj = out.draws[d];
        proj.clipFromView = clipFromViewOf(scene, scene.draws[d]);
        proj.pView = view.pView[d];
        proj.originalVertexCount = static_cast<std::uint32_t>(proj.pView.size());
        proj.pClip.reserve(proj.pView.size());
        for (const dvec4& p : proj.pView) {
            proj.pClip.push_back(proj.clipFromView * p);
            const double w = proj.pClip.back().w;
            if (w > wMax && isFinite(w)) wMax = w;
        }
    }
    // The near plane must lie strictly in front of the camera, or a vertex at w = 0 would
    // be divided by 0.
    const double requested =
        scene.nearPlane.fixedW ? *scene.nearPlane.fixedW : scene.nearPlane.autoFraction * wMax;
    out.nearW = std::max(requested, std::numeric_limits<double>::min());

    for (std::size_t d = 0; d < scene.draws.size(); ++d) {
        const Draw& draw = scene.draws[d];
        DrawProjection& proj = out.draws[d];
        if (!draw.mesh) continue;

        // One vertex to NDC and to pixels: pNdc = pClip.xy / pClip.w, then the seed's
        // x = (int)((pNdc.x + 1) width/2), y = (int)((1 - pNdc.y) height/2).
        auto project = [&](std::uint32_t i) {
            const dvec4& pClip = proj.pClip[i];
            const dvec2 pNdc = dvec2(pClip) / pClip.w;
            const double yFromTop = conv.ndcYUp ? 1.0 - pNdc.y : pNdc.y + 1.0;
            const dvec2 exact((pNdc.x + 1.0) * width / 2.0, yFromTop * height / 2.0);
            proj.pNdc[i] = pNdc;
            proj.pScreenExact[i] = exact;
            dvec2 snapped(snap(exact.x, scene.rules.snap), snap(exact.y, scene.rules.snap));
            // An infinite coordinate (w = 0 under the naive projection) stays infinite, so the
            // triangle is dropped as NonFinite instead of being pulled in to the guard band.
            if (finite2(snapped) &&
                (std::abs(snapped.x) > kGuardBand || std::abs(snapped.y) > kGuardBand)) {
                snapped = glm::clamp(snapped, dvec2(-kGuardBand), dvec2(kGuardBand));
                ++out.outsideGuardBand;
            }
            proj.pScreen[i] = snapped;
            proj.depth[i] = static_cast<float>(proj.pView[i].z);
            proj.inFront[i] = 1;
        };
        auto resizeVertices = [&](std::size_t n) {
            proj.pNdc.resize(n, dvec2(0.0));
            proj.pScreenExact.resize(n, dvec2(0.0));
            proj.pScreen.resize(n, dvec2(0.0));
            proj.depth.resize(n, 0.0f);
            proj.inFront.resize(n, 0);
        };
        resizeVertices(proj.pView.size());
        const auto inFront = [&](std::uint32_t i) { return proj.pClip[i].w >= out.nearW; };
        for (std::uint32_t i = 0; i < proj.originalVertexCount; ++i)
            if (out.naive || inFront(i)) project(i);

        // A vertex on the edge from a (in front) to b (behind), on the near plane. Always
        // computed from the vertex in front, so that two triangles sharing the edge get the
        // same point, bit for bit.
        auto addClipVertex = [&](std::uint32_t a, std::uint32_t b) {
            const double wa = proj.pClip[a].w;
            const double wb = proj.pClip[b].w;
            const double t = (out.nearW - wa) / (wb - wa);
            const auto index = static_cast<std::uint32_t>(proj.pView.size());
            const dvec4 pView = glm::mix(proj.pView[a], proj.pView[b], t);
            dvec4 pClip = glm::mix(proj.pClip[a], proj.pClip[b], t);
            pClip.w = out.nearW;
            proj.pView.push_back(pView);
            proj.pClip.push_back(pClip);
            proj.generated.push_back({a, b, t});
            resizeVertices(proj.pView.size());
            project(index);
            return index;
        };

        const auto& triangles = draw.mesh->triangles;
        proj.fate.resize(triangles.size(), TriangleFate::Inside);
        for (std::size_t t = 0; t < triangles.size(); ++t) {
            const auto& tri = triangles[t];
            const auto source = static_cast<std::uint32_t>(t);
            const auto drawIndex = static_cast<std::uint32_t>(d);
            // A triangle drawn as it is, unless a coordinate is not finite.
            auto projectWhole = [&] {
                for (std::uint32_t v : tri) {
                    if (!finite2(proj.pScreen[v]) || !std::isfinite(proj.depth[v])) {
                        proj.fate[t] = TriangleFate::NonFinite;
                        ++out.nonFinite;
                        return;
                    }
                }
                out.triangles.push_back({drawIndex, source, tri});
                ++out.inside;
            };
            if (out.naive) {
                bool throughZero = false;
                for (std::uint32_t v : tri) throughZero = throughZero || proj.pClip[v].w <= 0.0;
                out.throughZeroOrBehind += throughZero ? 1 : 0;
                projectWhole();
                continue;
            }
            int frontCount = 0;
            for (std::uint32_t v : tri) frontCount += inFront(v) ? 1 : 0;
            if (frontCount == 3) {
                projectWhole();
                continue;
            }
            if (frontCount == 0) {
                proj.fate[t] = TriangleFate::Behind;
                ++out.behind;
                continue;
            }
            // Sutherland-Hodgman against w >= near: walk the edges, keep the vertices in
            // front and add one where an edge crosses the plane. Winding is preserved.
            std::array<std::uint32_t, 4> polygon{};
            int count = 0;
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t a = tri[static_cast<std::size_t>(k)];
                const std::uint32_t b = tri[static_cast<std::size_t>((k + 1) % 3)];
                const bool aFront = inFront(a);
                const bool bFront = inFront(b);
                if (aFront) polygon[static_cast<std::size_t>(count++)] = a;
                if (aFront != bFront)
                    polygon[static_cast<std::size_t>(count++)] =
                        aFront ? addClipVertex(a, b) : addClipVertex(b, a);
            }
            proj.fate[t] = TriangleFate::Clipped;
            ++out.clipped;
            out.triangles.push_back({drawIndex, source, {polygon[0], polygon[1], polygon[2]}});
            if (count == 4)  // a quad: split into two triangles
                out.triangles.push_back({drawIndex, source, {polygon[0], polygon[2], polygon[3]}});
        }
    }

    // Tell the user what was clipped, dropped or drawn naively.
    const SourceLocation where{scene.name, 0, 0};
    const std::size_t total = scene.triangleCount();
    if (total > 0 && out.behind == total) {
        diagnostics.warn(where,
                         "every triangle is behind the camera (is N pointing away from "
                         "the object?): the image is empty");
    } else if (out.behind + out.clipped > 0) {
        diagnostics.note(
            where, std::to_string(out.clipped) + " triangles cross the near plane z = " +
                       formatNumber(out.nearW) + " and were clipped; " +
                       std::to_string(out.behind) + " are wholly behind it and were not drawn");
    }
    if (out.naive && out.throughZeroOrBehind > 0) {
        diagnostics.warn(where, "naive projection: " + std::to_string(out.throughZeroOrBehind) +
                                    " triangles have a vertex at or behind the camera and were "
                                    "divided by its z <= 0 anyway");
    }
    if (out.outsideGuardBand > 0) {
        diagnostics.warn(where, std::to_string(out.outsideGuardBand) +
                                    " vertices project more than 2^29 pixels from the image and "
                                    "were pulled in to that distance: triangles through them "
                                    "may be distorted on screen");
    }
    if (out.nonFinite > 0) {
        diagnostics.warn(where, std::to_string(out.nonFinite) +
                                    " triangles project to infinite or undefined coordinates "
                                    "and were not drawn");
    }
    return out;
}

}  // namespace rl
