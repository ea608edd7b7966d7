#include "scan_conversion_fast.h"

#include <algorithm>

#include "pipeline/core/parallel.h"
#include "pipeline/stages/probe.h"

namespace rl::fast {

ScanConversion scanConversion(const ScanConversionInput& in, int threads) {
    const std::size_t count = in.projection.triangles.size();
    const int parts = count < 1024 ? 1 : std::max(1, threads);
    if (parts == 1) return ScanConversionStage().run(in);
    std::vector<ScanConversion> partial(static_cast<std::size_t>(parts));
    runParts(parts, [&](int part) {
        // Filled on the thread's own stack and moved out at the end, so that the counters and
        // the vectors' ends, updated for every triangle, share no cache line with the other
        // threads'.
        NullProbe none;
        ScanConversion mine;
        scanTriangles(in, rangeBegin(count, part, parts), rangeBegin(count, part + 1, parts), mine,
                      none);
        partial[static_cast<std::size_t>(part)] = std::move(mine);
    });
    ScanConversion out;
    std::size_t spans = 0;
    for (const ScanConversion& p : partial) spans += p.spans.size();
    out.spans.reserve(spans);
    if (in.scene.rules.scan == RasterRules::Scan::Dda) out.ddaSpans.reserve(spans);
    out.spanStart.reserve(count + 1);
    for (const ScanConversion& p : partial) {
        const auto offset = static_cast<std::uint32_t>(out.spans.size());
        for (std::uint32_t start : p.spanStart) out.spanStart.push_back(start + offset);
        out.spans.insert(out.spans.end(), p.spans.begin(), p.spans.end());
        out.ddaSpans.insert(out.ddaSpans.end(), p.ddaSpans.begin(), p.ddaSpans.end());
        out.degenerate += p.degenerate;
        out.offscreen += p.offscreen;
        out.pixels += p.pixels;
    }
    out.spanStart.push_back(static_cast<std::uint32_t>(out.spans.size()));
    return out;
}

}  // namespace rl::fast
