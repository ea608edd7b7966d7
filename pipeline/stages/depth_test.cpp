#include "depth_test.h"

#include "pipeline/stages/probe.h"

namespace rl {

std::size_t DepthTest::coveredPixels() const {
    if (!fragmentsKept) return covered;
    std::size_t n = 0;
    for (std::uint32_t t : triangle.pixels()) n += t != kNoTriangle ? 1 : 0;
    return n;
}

FragmentDepth ddaFragment(const DdaValues& v, bool reciprocal) {
    return {static_cast<float>(v.beta), static_cast<float>(v.gamma),
            static_cast<float>(reciprocal ? 1.0 / v.z : v.z)};
}

FragmentDepth fragmentDepth(const Scene& scene, const Projection& projection, std::uint32_t t,
                            std::int32_t y, std::int32_t xBegin, std::int32_t x) {
    if (scene.rules.scan == RasterRules::Scan::Dda) {
        DdaSpan dda = ddaSpanAt(scene, projection, t, y, xBegin);
        for (std::int32_t i = xBegin; i < x; ++i) dda.next();
        return ddaFragment(dda.values, perspectiveDepth(scene));
    }
    const TrianglePlane plane(projection, t, perspectiveDepth(scene));
    double beta0 = 0.0, gamma0 = 0.0;
    plane.spanStart(xBegin, y, scene.rules.sampleOffset, beta0, gamma0);
    return plane.fragment(beta0, gamma0, x - xBegin);
}

namespace {

// The test of the fragments of one span, pixel by pixel, each from fragmentAt(i) for the
// span's i-th pixel in order.
template <typename Probe, typename Fragments>
void testFragments(const Scene& scene, Fragments&& fragmentAt, std::uint32_t id, const Span& span,
                   const DepthRows& rows, bool painted, DepthCounts& counts, Probe& probe) {
    const bool winsOnTie = scene.conventions.depthWinsOnTie;
    const bool rangeClip = scene.conventions.depthRangeClip;
    counts.fragments += static_cast<std::size_t>(span.xEnd - span.xBegin);
    for (std::int32_t x = span.xBegin; x < span.xEnd; ++x) {
        const FragmentDepth f = fragmentAt(x - span.xBegin);
        const float alpha = 1.0f - f.beta - f.gamma;
        if (rangeClip && !(f.depth >= 0.0f && f.depth <= 1.0f)) {  // per-pixel clipping (seed 001)
            ++counts.outsideDepthRange;
            RL_PROBE_HOOK(probe.onDepthTest(
                {id, x, span.y, alpha, f.beta, f.gamma, f.depth, rows.depth[x], false, true}));
            continue;
        }
        // The nearer fragment wins (on a tie, the one drawn first, unless the convention says
        // otherwise); the painter's algorithm writes every fragment.
        const float stored = rows.depth[x];
        const bool pass = painted || f.depth < stored || (winsOnTie && f.depth == stored);
        RL_PROBE_HOOK(
            probe.onDepthTest({id, x, span.y, alpha, f.beta, f.gamma, f.depth, stored, pass}));
        if (pass) {
            rows.depth[x] = f.depth;
            rows.ids[x] = id;
            if (rows.bary) rows.bary[x] = vec2(f.beta, f.gamma);
        }
        counts.passed += pass ? 1 : 0;
    }
}

}  // namespace

template <typename Probe>
void testSpanPixels(const Scene& scene, const TrianglePlane& plane, std::uint32_t id,
                    const Span& span, const DepthRows& rows, bool painted, DepthCounts& counts,
                    Probe& probe) {
    double beta0 = 0.0, gamma0 = 0.0;
    plane.spanStart(span.xBegin, span.y, scene.rules.sampleOffset, beta0, gamma0);
    testFragments(
        scene, [&](std::int32_t i) { return plane.fragment(beta0, gamma0, i); }, id, span, rows,
        painted, counts, probe);
}

template <typename Probe>
void testDdaSpanPixels(const Scene& scene, const DdaSpan& dda, std::uint32_t id, const Span& span,
                       const DepthRows& rows, bool painted, DepthCounts& counts, Probe& probe) {
    DdaSpan stepped = dda;
    const bool reciprocal = perspectiveDepth(scene);
    testFragments(
        scene, [&](std::int32_t) { return ddaFragment(stepped.next(), reciprocal); }, id, span,
        rows, painted, counts, probe);
}

template <typename Probe>
DepthTest DepthTestStage::run(const DepthTestInput& in, Probe& probe) const {
    const Scene& scene = in.scene;
    DepthTest out;
    out.clearedTo = scene.conventions.depthClear;
    out.painted = paintersAlgorithm(scene);
    out.depth.reset(scene.width, scene.height, scene.conventions.depthClear);
    out.triangle.reset(scene.width, scene.height, kNoTriangle);
    out.barycentric.reset(scene.width, scene.height, vec2(0.0f));
    // Every span in triangle order.
    DepthCounts counts;
    const bool reciprocal = perspectiveDepth(scene);
    for (std::size_t t = 0; t < in.projection.triangles.size(); ++t) {
        const std::uint32_t first = in.scan.spanStart[t], last = in.scan.spanStart[t + 1];
        if (first == last) continue;
        const auto id = static_cast<std::uint32_t>(t);
        if (scene.rules.scan == RasterRules::Scan::Dda) {  // seed 001's DDA stepped them
            for (std::uint32_t k = first; k < last; ++k) {
                const std::int32_t y = in.scan.spans[k].y;
                testDdaSpanPixels(
                    scene, in.scan.ddaSpans[k], id, in.scan.spans[k],
                    DepthRows{out.depth.row(y), out.triangle.row(y), out.barycentric.row(y)},
                    out.painted, counts, probe);
            }
            continue;
        }
        const TrianglePlane plane(in.projection, t, reciprocal);
        for (std::uint32_t k = first; k < last; ++k) {
            const std::int32_t y = in.scan.spans[k].y;
            testSpanPixels(scene, plane, id, in.scan.spans[k],
                           DepthRows{out.depth.row(y), out.triangle.row(y), out.barycentric.row(y)},
                           out.painted, counts, probe);
        }
    }
    out.fragments = counts.fragments;
    out.passed = counts.passed;
    out.outsideDepthRange = counts.outsideDepthRange;
    out.rejected = out.fragments - out.passed - out.outsideDepthRange;
    return out;
}

DepthTest DepthTestStage::run(const DepthTestInput& in) const {
    NullProbe probe;
    return run(in, probe);
}

template DepthTest DepthTestStage::run<NullProbe>(const DepthTestInput&, NullProbe&) const;
template DepthTest DepthTestStage::run<RecordingProbe>(const DepthTestInput&,
                                                       RecordingProbe&) const;
template DepthTest DepthTestStage::run<ReplayProbe>(const DepthTestInput&, ReplayProbe&) const;
template void testSpanPixels<NullProbe>(const Scene&, const TrianglePlane&, std::uint32_t,
                                        const Span&, const DepthRows&, bool, DepthCounts&,
                                        NullProbe&);
template void testDdaSpanPixels<NullProbe>(const Scene&, const DdaSpan&, std::uint32_t, const Span&,
                                           const DepthRows&, bool, DepthCounts&, NullProbe&);

}  // namespace rl
