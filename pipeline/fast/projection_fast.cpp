#include "projection_fast.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "pipeline/core/buffer.h"
#include "pipeline/core/parallel.h"
#include "pipeline/stages/painters_algorithm.h"

namespace rl::fast {

namespace {

constexpr std::size_t kFates = std::size_t(TriangleFate::NonFinite) + 1;
using FateCounts = std::array<std::size_t, kFates>;

// Step 1 on several threads: the same values as toClipSpace over the whole draw.
double toClipSpaceOnThreads(const ProjectionInput& in, std::size_t d, DrawProjection& proj,
                            int threads) {
    const std::size_t count = proj.originalVertexCount;
    const int parts = count < 4096 ? 1 : std::max(1, threads);
    std::vector<double> partMax(static_cast<std::size_t>(parts), 0.0);
    runParts(parts, [&](int part) {
        partMax[static_cast<std::size_t>(part)] = toClipSpace(
            in, d, proj, rangeBegin(count, part, parts), rangeBegin(count, part + 1, parts));
    });
    return *std::max_element(partMax.begin(), partMax.end());
}

// The fates of a draw whose planes are the same for every triangle (the near plane always
// clipped): each vertex's side of each plane is worked out once (bit k set: outside planes[k];
// bit kNotFinite: its screen position or depth is not finite), so that a triangle wholly
// inside costs three loads. The fate of every triangle that needs no clipping is settled
// (and counted per part); toClip marks the others. Returns whether any needs clipping.
constexpr std::uint32_t kNotFinite = 1u << 31;

bool settleFates(const DrawProjector& draw, const Mesh& mesh, DrawProjection& proj,
                 std::vector<std::uint8_t>& toClip, std::vector<FateCounts>& counts, int parts) {
    const std::vector<std::size_t>& planes = draw.planes();
    const std::size_t vertexCount = proj.originalVertexCount;
    Buffer<std::uint32_t> outcode(vertexCount);  // each written below
    runParts(parts, [&](int part) {
        for (std::size_t v = rangeBegin(vertexCount, part, parts),
                         end = rangeBegin(vertexCount, part + 1, parts);
             v < end; ++v) {
            const auto vertex = static_cast<std::uint32_t>(v);
            std::uint32_t bits = draw.finite(vertex) ? 0u : kNotFinite;
            for (std::size_t k = 0; k < planes.size(); ++k)
                bits |= draw.distance(planes[k], vertex) >= 0.0 ? 0u : 1u << k;
            outcode[v] = bits;
        }
    });
    const std::size_t triangleCount = mesh.triangles.size();
    std::vector<std::uint8_t> cutInPart(static_cast<std::size_t>(parts), 0);
    counts.assign(static_cast<std::size_t>(parts), FateCounts{});
    runParts(parts, [&](int part) {
        bool cut = false;
        FateCounts mine{};  // on the thread's stack
        const auto settle = [&](std::size_t t, TriangleFate fate) {
            proj.fate[t] = fate;
            ++mine[static_cast<std::size_t>(fate)];
        };
        for (std::size_t t = rangeBegin(triangleCount, part, parts),
                         end = rangeBegin(triangleCount, part + 1, parts);
             t < end; ++t) {
            const auto& tri = mesh.triangles[t];
            if (draw.hiddenWinding() != 0 && draw.facesAway(tri)) {
                settle(t, TriangleFate::BackFace);
                continue;
            }
            const std::uint32_t a = outcode[tri[0]], b = outcode[tri[1]], c = outcode[tri[2]];
            const std::uint32_t all = a & b & c & ~kNotFinite;
            const std::uint32_t any = a | b | c;
            if (all != 0) {
                settle(t, draw.outsideFate(planes[std::size_t(std::countr_zero(all))]));
            } else if ((any & ~kNotFinite) != 0) {
                toClip[t] = 1;
                cut = true;
            } else {
                settle(t, (any & kNotFinite) != 0 ? TriangleFate::NonFinite
                          : draw.culled(tri)      ? TriangleFate::Culled
                                                  : TriangleFate::Inside);
            }
        }
        cutInPart[static_cast<std::size_t>(part)] = cut ? 1 : 0;
        counts[static_cast<std::size_t>(part)] = mine;
    });
    return std::find(cutInPart.begin(), cutInPart.end(), 1) != cutInPart.end();
}

// Nothing to clip: each thread writes the triangles it kept at its place in the list, so the
// list is in triangle order as one thread would make it.
void emitOnThreads(std::uint32_t d, const Mesh& mesh, const DrawProjection& proj,
                   const std::vector<FateCounts>& counts, Projection& out) {
    const auto parts = static_cast<int>(counts.size());
    std::vector<std::size_t> at(counts.size());
    std::size_t kept = out.triangles.size();
    for (std::size_t part = 0; part < counts.size(); ++part) {
        at[part] = kept;
        kept += counts[part][static_cast<std::size_t>(TriangleFate::Inside)];
    }
    out.triangles.resize(kept);
    const std::size_t triangleCount = mesh.triangles.size();
    runParts(parts, [&](int part) {
        std::size_t next = at[static_cast<std::size_t>(part)];
        for (std::size_t t = rangeBegin(triangleCount, part, parts),
                         end = rangeBegin(triangleCount, part + 1, parts);
             t < end; ++t)
            if (proj.fate[t] == TriangleFate::Inside)
                out.triangles[next++] = {d, static_cast<std::uint32_t>(t), mesh.triangles[t]};
    });
}

// Steps 2 to 6 of one draw.
void projectDraw(const ProjectionInput& in, std::size_t d, Projection& out, int threads,
                 bool keepExact) {
    const Mesh& mesh = *in.scene.draws[d].mesh;
    DrawProjection& proj = out.draws[d];
    DrawProjector draw(in, d, out, keepExact);
    // Vertices are independent: contiguous ranges on several threads (the plain divide
    // counts the vertices it pulls in to the guard band, so it runs on one).
    const std::uint32_t vertexCount = proj.originalVertexCount;
    const int vertexParts =
        out.mode == NearPlane::Mode::Naive || vertexCount < 4096 ? 1 : std::max(1, threads);
    runParts(vertexParts, [&](int part) {
        const auto first = static_cast<std::uint32_t>(rangeBegin(vertexCount, part, vertexParts));
        const auto last =
            static_cast<std::uint32_t>(rangeBegin(vertexCount, part + 1, vertexParts));
        for (std::uint32_t i = first; i < last; ++i) draw.projectIfInFront(i);
    });
    const std::size_t triangleCount = mesh.triangles.size();
    // Only when the near plane is always clipped do all triangles meet the same planes; with
    // at most 26 clip planes their bits fit beside the near plane's, the guard band's and
    // kNotFinite.
    if (out.mode != NearPlane::Mode::Clip || in.scene.draws[d].clipPlanes.size() + 5 > 31) {
        proj.fate.assign(triangleCount, TriangleFate::Inside);
        for (std::size_t t = 0; t < triangleCount; ++t) draw.projectTriangle(t);
        return;
    }
    proj.fate.resize(triangleCount);
    std::vector<std::uint8_t> toClip(triangleCount, 0);
    std::vector<FateCounts> counts;
    const int parts = triangleCount < 4096 ? 1 : std::max(1, threads);
    const bool anyCut = settleFates(draw, mesh, proj, toClip, counts, parts);
    for (const FateCounts& c : counts)
        for (std::size_t fate = 0; fate < kFates; ++fate)
            tally(out, static_cast<TriangleFate>(fate)) += c[fate];
    if (!anyCut) {
        emitOnThreads(static_cast<std::uint32_t>(d), mesh, proj, counts, out);
        return;
    }
    // In order: the settled triangles kept as they are, the others clipped by the stage.
    for (std::size_t t = 0; t < triangleCount; ++t) {
        if (toClip[t])
            draw.projectTriangle(t);
        else if (proj.fate[t] == TriangleFate::Inside)
            out.triangles.push_back(
                {static_cast<std::uint32_t>(d), static_cast<std::uint32_t>(t), mesh.triangles[t]});
    }
}

}  // namespace

Projection projection(const ProjectionInput& in, Diagnostics& diagnostics, int threads,
                      bool keepExact) {
    const Scene& scene = in.scene;
    // pView and pClip are written whole, shared out between the threads (Buffer: the sizing
    // does not zero them first).
    Projection out = projectionOf(in);
    double wMax = 0.0;
    for (std::size_t d = 0; d < scene.draws.size(); ++d)
        wMax = std::max(wMax, toClipSpaceOnThreads(in, d, out.draws[d], threads));
    out.nearW = nearPlaneW(scene, wMax);
    for (std::size_t d = 0; d < scene.draws.size(); ++d)
        if (scene.draws[d].mesh) projectDraw(in, d, out, threads, keepExact);
    reportProjection(scene, out, diagnostics);
    if (paintersAlgorithm(scene)) sortFarToNear(scene, out);
    return out;
}

}  // namespace rl::fast
