#include "mesh_topology.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace rl {

namespace {

// Union-find over vertices, for the connected pieces.
struct Pieces {
    std::vector<std::uint32_t> parent;
    explicit Pieces(std::size_t n) : parent(n) {
        std::iota(parent.begin(), parent.end(), std::uint32_t{0});
    }
    std::uint32_t find(std::uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    }
    void join(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

}  // namespace

int closedSurfaceWinding(const Mesh& mesh) {
    const std::size_t vertices = mesh.positions.size();
    if (mesh.triangles.empty()) return 0;
    if (vertices >= (std::size_t{1} << 31)) return 0;  // beyond the edge keys below
    // Each edge a -> b as (min, max, forward): a closed, consistently wound surface has every
    // undirected edge exactly twice, once each way.
    std::vector<std::uint64_t> edges;
    edges.reserve(mesh.triangles.size() * 3);
    Pieces pieces(vertices);
    for (const auto& t : mesh.triangles) {
        if (t[0] >= vertices || t[1] >= vertices || t[2] >= vertices) return 0;
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return 0;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = t[k], b = t[(k + 1) % 3];
            const std::uint64_t low = std::min(a, b), high = std::max(a, b);
            edges.push_back(low << 33 | high << 1 | (a < b ? 1u : 0u));
            pieces.join(a, b);
        }
    }
    std::sort(edges.begin(), edges.end());
    for (std::size_t i = 0; i < edges.size(); i += 2) {
        if (i + 1 == edges.size() || edges[i] + 1 != edges[i + 1] || (edges[i] & 1) != 0)
            return 0;  // an open edge, or one run twice the same way
        if (i + 2 < edges.size() && edges[i + 2] >> 1 == edges[i] >> 1) return 0;  // 3+ triangles
    }
    // Six times the signed volume of each piece: the sum of a . (b x c) over its triangles.
    std::vector<double> volume(vertices, 0.0);
    std::vector<std::uint8_t> hasTriangles(vertices, 0);
    const auto point = [&](std::uint32_t v) {
        const dvec4& p = mesh.positions[v];
        return p.w != 0.0 && p.w != 1.0 ? dvec3(p) / p.w : dvec3(p);
    };
    for (const auto& t : mesh.triangles) {
        const std::uint32_t piece = pieces.find(t[0]);
        volume[piece] += glm::dot(point(t[0]), glm::cross(point(t[1]), point(t[2])));
        hasTriangles[piece] = 1;
    }
    int winding = 0;
    for (std::size_t v = 0; v < vertices; ++v) {
        if (!hasTriangles[v]) continue;  // not a piece's root, or a vertex no triangle uses
        const int sign = volume[v] > 0.0 ? 1 : (volume[v] < 0.0 ? -1 : 0);
        if (sign == 0 || (winding != 0 && sign != winding)) return 0;
        winding = sign;
    }
    return winding;
}

}  // namespace rl
