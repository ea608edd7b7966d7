#include "depth_test.h"

#include "probe.h"

namespace rl {

std::size_t DepthTest::coveredPixels() const {
    std::size_t n = 0;
    for (std::uint32_t t : triangle.pixels()) n += t != kNoTriangle ? 1 : 0;
    return n;
}

template <typename Probe>
DepthTest DepthTestStage::run(const Scene& scene, const Projection& projection,
                              const ScanConversion& scan, Probe& probe) const {
    DepthTest out;
    const Conventions& conv = scene.conventions;
    out.depth = Image<float>(scene.width, scene.height, conv.depthClear);
    out.triangle = Image<std::uint32_t>(scene.width, scene.height, kNoTriangle);
    out.barycentric = Image<vec2>(scene.width, scene.height, vec2(0.0f));
    const double offset = scene.rules.sampleOffset;
    const bool winsOnTie = conv.depthWinsOnTie;
    const bool rangeClip = conv.depthRangeClip;

    for (std::size_t t = 0; t < projection.triangles.size(); ++t) {
        const std::uint32_t first = scan.spanStart[t];
        const std::uint32_t last = scan.spanStart[t + 1];
        if (first == last) continue;
        const ScreenTriangle& tri = projection.triangles[t];
        const DrawProjection& draw = projection.draws[tri.draw];
        const std::array<dvec2, 3> p = screenVertices(projection, tri);
        const float z0 = draw.depth[tri.v[0]];
        const float dz1 = draw.depth[tri.v[1]] - z0;
        const float dz2 = draw.depth[tri.v[2]] - z0;

        // Barycentrics of a sample s: s = P1 + beta (P2 - P1) + gamma (P3 - P1), so
        // beta = (s - P1) x (P3 - P1) / A and gamma = (P2 - P1) x (s - P1) / A, where
        // A = (P2 - P1) x (P3 - P1). Both are linear in x along a scanline.
        const dvec2 e1 = p[1] - p[0];
        const dvec2 e2 = p[2] - p[0];
        const double area = e1.x * e2.y - e1.y * e2.x;
        const double betaDx = e2.y / area;
        const double gammaDx = -e1.y / area;

        for (std::uint32_t k = first; k < last; ++k) {
            const Span& span = scan.spans[k];
            // The sample of pixel (x, y) is the point (x + offset, y + offset).
            const dvec2 s0 = dvec2(span.xBegin + offset, span.y + offset) - p[0];
            const double beta0 = (s0.x * e2.y - s0.y * e2.x) / area;
            const double gamma0 = (e1.x * s0.y - e1.y * s0.x) / area;
            float* depthRow = out.depth.row(span.y);
            std::uint32_t* idRow = out.triangle.row(span.y);
            vec2* baryRow = out.barycentric.row(span.y);
            for (std::int32_t x = span.xBegin; x < span.xEnd; ++x) {
                const double i = x - span.xBegin;
                const auto beta = static_cast<float>(beta0 + i * betaDx);
                const auto gamma = static_cast<float>(gamma0 + i * gammaDx);
                const float z = z0 + beta * dz1 + gamma * dz2;
                if (rangeClip && !(z >= 0.0f && z <= 1.0f)) {  // per-pixel clipping (seed 001)
                    ++out.outsideDepthRange;
                    if constexpr (Probe::enabled) {
                        probe.onDepthTest({static_cast<std::uint32_t>(t), x, span.y,
                                           1.0f - beta - gamma, beta, gamma, z, depthRow[x], false,
                                           true});
                    }
                    continue;
                }
                const float stored = depthRow[x];
                const bool pass = z < stored || (winsOnTie && z == stored);
                if constexpr (Probe::enabled) {
                    probe.onDepthTest({static_cast<std::uint32_t>(t), x, span.y,
                                       1.0f - beta - gamma, beta, gamma, z, stored, pass});
                }
                if (pass) {
                    depthRow[x] = z;
                    idRow[x] = static_cast<std::uint32_t>(t);
                    baryRow[x] = vec2(beta, gamma);
                }
                out.passed += pass ? 1 : 0;
            }
            out.fragments += static_cast<std::size_t>(span.xEnd - span.xBegin);
        }
    }
    out.rejected = out.fragments - out.passed - out.outsideDepthRange;
    return out;
}

DepthTest DepthTestStage::run(const Scene& scene, const Projection& projection,
                              const ScanConversion& scan) const {
    NullProbe probe;
    return run(scene, projection, scan, probe);
}

template DepthTest DepthTestStage::run<NullProbe>(const Scene&, const Projection&,
                                                  const ScanConversion&, NullProbe&) const;
template DepthTest DepthTestStage::run<RecordingProbe>(const Scene&, const Projection&,
                                                       const ScanConversion&,
                                                       RecordingProbe&) const;

}  // namespace rl
