#include "projection.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "format.h"
#include "painters_algorithm.h"
#include "parallel.h"

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

// A screen coordinate on the rules' sub-pixel grid.
// grid = 2^subpixelBits and cell = 1 / grid, worked out once by the caller: both are powers
// of two, so multiplying by cell gives the very bits dividing by grid would, without a
// division.
double snap(double coordinate, const RasterRules& rules, double grid, double cell) {
    switch (rules.snap) {
        case RasterRules::VertexSnap::Truncate:
            return std::trunc(coordinate * grid) * cell;
        case RasterRules::VertexSnap::Nearest:
            return std::floor(coordinate * grid + 0.5) * cell;
    }
    return coordinate;
}

bool finite2(const dvec2& p) {
    return isFinite(p.x) && isFinite(p.y);
}

// Whether a triangle of a closed surface faces away from the camera (projection.h, step 6):
// n . P' > 0 in view space, with n by the right-hand rule turned by the surface's winding.
bool facesAway(const DrawProjection& proj, const std::array<std::uint32_t, 3>& tri, int winding) {
    const dvec3 a(proj.pView[tri[0]]), b(proj.pView[tri[1]]), c(proj.pView[tri[2]]);
    return double(winding) * glm::dot(glm::cross(b - a, c - a), a) > 0.0;
}

// Twice the signed area in pixels (y down): negative when the triangle is counter-clockwise
// as it appears on the screen.
double screenArea(const dvec2& a, const dvec2& b, const dvec2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The counter of a projection that counts the triangles of a fate.
std::size_t& tally(Projection& out, TriangleFate fate) {
    switch (fate) {
        case TriangleFate::Inside:
            return out.inside;
        case TriangleFate::Clipped:
            return out.clipped;
        case TriangleFate::Behind:
            return out.behind;
        case TriangleFate::ClippedAway:
            return out.clippedAway;
        case TriangleFate::Culled:
            return out.culled;
        case TriangleFate::BackFace:
            return out.backFaces;
        case TriangleFate::BeyondGuardBand:
            return out.beyondGuardBand;
        case TriangleFate::NonFinite:
            break;
    }
    return out.nonFinite;
}

}  // namespace

std::size_t trianglesBehindEye(const Projection& projection, const Scene& scene) {
    std::size_t count = 0;
    for (std::size_t d = 0; d < scene.draws.size() && d < projection.draws.size(); ++d) {
        const Draw& draw = scene.draws[d];
        const DrawProjection& proj = projection.draws[d];
        if (!draw.mesh) continue;
        for (const auto& tri : draw.mesh->triangles)
            count += proj.pClip[tri[0]].w < 0.0 && proj.pClip[tri[1]].w < 0.0 &&
                             proj.pClip[tri[2]].w < 0.0
                         ? 1
                         : 0;
    }
    return count;
}

Projection ProjectionStage::run(const Scene& scene, const ViewTransform& view,
                                Diagnostics& diagnostics, int threads, bool keepExact) const {
    Projection out;
    out.mode = scene.nearPlane.mode;
    const bool clipNear = out.mode == NearPlane::Mode::Clip;
    const double width = scene.width;
    const double height = scene.height;
    const Conventions& conv = scene.conventions;
    const double grid = std::ldexp(1.0, scene.rules.subpixelBits);
    const double cell = std::ldexp(1.0, -scene.rules.subpixelBits);

    // Every vertex to clip space first: the near plane is a plane of clip space, w = near.
    out.draws.resize(scene.draws.size());
    double wMax = 0.0;
    for (std::size_t d = 0; d < scene.draws.size(); ++d) {
        DrawProjection& proj = out.draws[d];
        proj.clipFromView = clipFromViewOf(scene, scene.draws[d]);
        const std::vector<dvec4>& pView = view.pView[d];
        proj.originalVertexCount = static_cast<std::uint32_t>(pView.size());
        const std::size_t count = pView.size();
        // Both written whole below, shared out between the threads (Buffer: not zeroed first).
        proj.pView.resize(count);
        proj.pClip.resize(count);
        const int parts = count < 4096 ? 1 : std::max(1, threads);
        std::vector<double> partMax(static_cast<std::size_t>(parts), 0.0);
        runParts(parts, [&](int part) {
            double most = 0.0;  // on the thread's stack, not beside the other threads'
            for (std::size_t i = rangeBegin(count, part, parts),
                             end = rangeBegin(count, part + 1, parts);
                 i < end; ++i) {
                proj.pView[i] = pView[i];
                proj.pClip[i] = proj.clipFromView * pView[i];
                const double w = proj.pClip[i].w;
                if (w > most && isFinite(w)) most = w;
            }
            partMax[static_cast<std::size_t>(part)] = most;
        });
        for (double most : partMax) wMax = std::max(wMax, most);
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

        // The plain divide (which does not clip a triangle whose w differ in sign) may pull a
        // vertex in to the guard band: 1 when it was, 2 once a drawn triangle counted it.
        std::vector<std::uint8_t> pulledIn;
        // One vertex to NDC and to pixels: pNdc = pClip.xy / pClip.w, then the seed's
        // x = (int)((pNdc.x + 1) width/2), y = (int)((1 - pNdc.y) height/2).
        auto project = [&](std::uint32_t i) {
            const dvec4& pClip = proj.pClip[i];
            const dvec2 pNdc = dvec2(pClip) / pClip.w;
            const dvec2 exact = screenFromNdc(pNdc, width, height, conv.ndcYUp);
            if (keepExact) {
                proj.pNdc[i] = pNdc;
                proj.pScreenExact[i] = exact;
            }
            dvec2 snapped(snap(exact.x, scene.rules, grid, cell),
                          snap(exact.y, scene.rules, grid, cell));
            // An infinite coordinate (w = 0 under the naive projection) stays infinite, so the
            // triangle is dropped as NonFinite instead of being pulled in to the guard band.
            // Clipping keeps drawn vertices inside the guard band; only the naive projection
            // (which does not clip) can bring one from beyond it, pulled in and counted.
            if (finite2(snapped) &&
                (std::abs(snapped.x) > kGuardBand || std::abs(snapped.y) > kGuardBand)) {
                snapped = glm::clamp(snapped, dvec2(-kGuardBand), dvec2(kGuardBand));
                if (out.mode == NearPlane::Mode::Naive) pulledIn[i] = 1;
            }
            proj.pScreen[i] = snapped;
            proj.depth[i] = static_cast<float>(
                conv.depth == DepthSource::ViewZ ? proj.pView[i].z : pClip.z / pClip.w);
            proj.inFront[i] = 1;
        };
        // The per-vertex arrays to n vertices, the new ones unset (Buffer): each is then
        // projected or marked as not projected.
        auto resizeVertices = [&](std::size_t n) {
            if (out.mode == NearPlane::Mode::Naive) pulledIn.resize(n, 0);
            if (keepExact) {
                proj.pNdc.resize(n, dvec2(0.0));
                proj.pScreenExact.resize(n, dvec2(0.0));
            }
            proj.pScreen.resize(n);
            proj.depth.resize(n);
            proj.inFront.resize(n);
        };
        // Vertex i projected when it is in front of the near plane (or nothing is clipped);
        // otherwise zeros, not in front.
        auto projectIfInFront = [&](std::uint32_t i) {
            if (!clipNear || proj.pClip[i].w >= out.nearW) {
                project(i);
                return;
            }
            proj.pScreen[i] = dvec2(0.0);
            proj.depth[i] = 0.0f;
            proj.inFront[i] = 0;
        };
        resizeVertices(proj.pView.size());
        // Vertices are independent: contiguous ranges on several threads (the naive
        // projection counts vertices pulled in, so it runs on one).
        const std::uint32_t vertexCount = proj.originalVertexCount;
        const int vertexParts =
            out.mode == NearPlane::Mode::Naive || vertexCount < 4096 ? 1 : std::max(1, threads);
        runParts(vertexParts, [&](int part) {
            const auto first =
                static_cast<std::uint32_t>(rangeBegin(vertexCount, part, vertexParts));
            const auto last =
                static_cast<std::uint32_t>(rangeBegin(vertexCount, part + 1, vertexParts));
            for (std::uint32_t i = first; i < last; ++i) projectIfInFront(i);
        });

        // The planes a triangle is clipped against, each as a signed distance (inside >= 0):
        // the draw's clip planes (view space); the near plane w = near (clip space; with
        // SameSide only for a triangle whose w differ in sign); and the guard band, four
        // planes |x| <= gx |w|, |y| <= gy |w| that keep every vertex within 2^28 pixels of
        // the image without bending an edge (side is the sign of the triangle's w).
        const std::size_t userPlanes = draw.clipPlanes.size();
        const std::size_t nearPlane = userPlanes;
        const std::size_t firstGuard = userPlanes + 1;
        const double gx = kGuardBand / width, gy = kGuardBand / height;
        bool nearActive = clipNear;
        double side = 1.0;
        auto distance = [&](std::size_t plane, std::uint32_t v) {
            if (plane < userPlanes) return glm::dot(draw.clipPlanes[plane], proj.pView[v]);
            const dvec4& c = proj.pClip[v];
            switch (plane - nearPlane) {
                case 0:
                    return c.w - out.nearW;
                case 1:
                    return side * gx * c.w - c.x;
                case 2:
                    return side * gx * c.w + c.x;
                case 3:
                    return side * gy * c.w - c.y;
                default:
                    return side * gy * c.w + c.y;
            }
        };
        // The guard band applies to a triangle whose w all have one sign; the plain divide
        // leaves a triangle across w = 0 unclipped.
        bool guardActive = true;
        // The planes that apply to the current triangle, in order.
        std::vector<std::size_t> planes;
        auto choosePlanes = [&] {
            planes.clear();
            for (std::size_t k = 0; k < userPlanes; ++k) planes.push_back(k);
            if (nearActive) planes.push_back(nearPlane);
            if (guardActive)
                for (std::size_t k = 0; k < 4; ++k) planes.push_back(firstGuard + k);
        };
        // A vertex where the edge from a (inside) to b (outside) crosses a plane. Always
        // computed from the inside vertex, so two triangles sharing the edge get the same
        // point, bit for bit.
        auto addClipVertex = [&](std::size_t plane, std::uint32_t a, std::uint32_t b) {
            const double t = crossingFraction(distance(plane, a), distance(plane, b));
            const auto index = static_cast<std::uint32_t>(proj.pView.size());
            const dvec4 pView = glm::mix(proj.pView[a], proj.pView[b], t);
            dvec4 pClip = glm::mix(proj.pClip[a], proj.pClip[b], t);
            if (plane == nearPlane) pClip.w = out.nearW;  // exactly on it
            proj.pView.push_back(pView);
            proj.pClip.push_back(pClip);
            proj.generated.push_back({a, b, t});
            resizeVertices(proj.pView.size());
            projectIfInFront(index);
            return index;
        };

        // Hidden back faces (step 6): the winding of the surface as seen in view space (a
        // mirroring transform turns it over), or 0 when nothing is left out.
        int hiddenWinding = 0;
        if (scene.cullHiddenBackFaces && draw.mesh->closedWinding != 0 && !draw.clipFromView &&
            scene.camera && draw.clipPlanes.empty()) {
            bool beyondNear = true;
            for (std::uint32_t i = 0; i < proj.originalVertexCount && beyondNear; ++i)
                beyondNear = proj.pClip[i].w > out.nearW && proj.pView[i].w == 1.0;
            const double det = glm::determinant(dmat3(view.viewFromModel[d]));
            if (beyondNear && det != 0.0)
                hiddenWinding = det > 0.0 ? draw.mesh->closedWinding : -draw.mesh->closedWinding;
        }

        // With the near plane always clipped, every triangle meets the same planes: each
        // vertex's side of each is worked out once (bit k set: outside planes[k]), and a
        // triangle wholly inside them all costs three loads instead of clipping work.
        // The verdicts (and the back-face test) are independent per triangle: worked out on
        // several threads; then the triangles are emitted and clipped in order on one, or,
        // when no triangle needs clipping, emitted on several too.
        const bool outcodes = out.mode == NearPlane::Mode::Clip && userPlanes + 5 <= 31;
        const auto& triangles = draw.mesh->triangles;
        // Per triangle, 1 when a plane cuts it: the clipping pass's work (every other triangle
        // gets its fate in the verdict pass).
        std::vector<std::uint8_t> toClip;
        const std::size_t triangleCount = triangles.size();
        const int triangleParts = triangleCount < 4096 ? 1 : std::max(1, threads);

        // Whether cull drops a triangle: not counter-clockwise on the screen.
        auto culled = [&](const std::array<std::uint32_t, 3>& v) {
            return draw.cull &&
                   !(screenArea(proj.pScreen[v[0]], proj.pScreen[v[1]], proj.pScreen[v[2]]) < 0.0);
        };
        // What becomes of a triangle that is drawn as is (or of a piece of a clipped one):
        // not drawn when a coordinate is not finite or cull drops it.
        auto screenFate = [&](const std::array<std::uint32_t, 3>& v) {
            for (std::uint32_t i : v)
                if (!finite2(proj.pScreen[i]) || !std::isfinite(proj.depth[i]))
                    return TriangleFate::NonFinite;
            return culled(v) ? TriangleFate::Culled : TriangleFate::Inside;
        };
        // A triangle wholly outside one of the planes.
        auto outsideFate = [&](std::size_t plane) {
            return plane == nearPlane   ? TriangleFate::Behind
                   : plane < userPlanes ? TriangleFate::ClippedAway
                                        : TriangleFate::BeyondGuardBand;  // far off the image
        };

        // With outcodes, each triangle that needs no clipping gets its fate in the same pass
        // (a vertex's bit kNotFinite: its screen position or depth is not finite, what
        // screenFate asks), counted per part on the thread's stack.
        constexpr std::uint32_t kNotFinite = 1u << 31;
        constexpr std::size_t kFates = std::size_t(TriangleFate::NonFinite) + 1;
        std::vector<std::array<std::size_t, kFates>> fateCounts;
        bool anyCut = false;
        if (outcodes) {
            choosePlanes();
            Buffer<std::uint32_t> outcode(proj.originalVertexCount);  // each written below
            toClip.assign(triangleCount, 0);
            proj.fate.resize(triangleCount);
            const int parts = triangleParts;
            std::vector<std::uint8_t> cutInPart(static_cast<std::size_t>(parts), 0);
            fateCounts.resize(static_cast<std::size_t>(parts));
            runParts(parts, [&](int part) {
                for (std::size_t v = rangeBegin(vertexCount, part, parts),
                                 end = rangeBegin(vertexCount, part + 1, parts);
                     v < end; ++v) {
                    std::uint32_t bits = 0;
                    for (std::size_t k = 0; k < planes.size(); ++k)
                        bits |= distance(planes[k], static_cast<std::uint32_t>(v)) >= 0.0 ? 0u
                                                                                          : 1u << k;
                    if (!finite2(proj.pScreen[v]) || !std::isfinite(proj.depth[v]))
                        bits |= kNotFinite;
                    outcode[v] = bits;
                }
            });
            runParts(parts, [&](int part) {
                bool cut = false;
                std::array<std::size_t, kFates> mine{};  // per TriangleFate
                const auto settle = [&](std::size_t t, TriangleFate fate) {
                    proj.fate[t] = fate;
                    ++mine[static_cast<std::size_t>(fate)];
                };
                for (std::size_t t = rangeBegin(triangleCount, part, parts),
                                 end = rangeBegin(triangleCount, part + 1, parts);
                     t < end; ++t) {
                    const auto& tri = triangles[t];
                    if (hiddenWinding != 0 && facesAway(proj, tri, hiddenWinding)) {
                        settle(t, TriangleFate::BackFace);
                        continue;
                    }
                    const std::uint32_t a = outcode[tri[0]], b = outcode[tri[1]],
                                        c = outcode[tri[2]];
                    const std::uint32_t all = a & b & c & ~kNotFinite;
                    const std::uint32_t any = a | b | c;
                    if (all != 0) {
                        const auto plane = static_cast<std::size_t>(std::countr_zero(all));
                        settle(t, outsideFate(planes[plane]));
                    } else if ((any & ~kNotFinite) != 0) {
                        toClip[t] = 1;
                        cut = true;
                    } else {
                        settle(t, (any & kNotFinite) != 0 ? TriangleFate::NonFinite
                                  : culled(tri)           ? TriangleFate::Culled
                                                          : TriangleFate::Inside);
                    }
                }
                cutInPart[static_cast<std::size_t>(part)] = cut ? 1 : 0;
                fateCounts[static_cast<std::size_t>(part)] = mine;
            });
            anyCut = std::find(cutInPart.begin(), cutInPart.end(), 1) != cutInPart.end();
        }

        // With outcodes every triangle but those to clip has its fate: counted here, once.
        for (const auto& counts : fateCounts)
            for (std::size_t fate = 0; fate < kFates; ++fate)
                tally(out, static_cast<TriangleFate>(fate)) += counts[fate];

        const auto drawIndex = static_cast<std::uint32_t>(d);
        if (outcodes && !anyCut) {
            // Nothing to clip: each thread writes the triangles it kept at its place in the
            // list, so the list is in triangle order as one thread would make it (1M sphere,
            // 2 threads: this loop was 6 ms on one).
            const auto parts = static_cast<std::size_t>(triangleParts);
            std::vector<std::size_t> at(parts);
            std::size_t kept = out.triangles.size();
            for (std::size_t part = 0; part < parts; ++part) {
                at[part] = kept;
                kept += fateCounts[part][static_cast<std::size_t>(TriangleFate::Inside)];
            }
            out.triangles.resize(kept);
            runParts(triangleParts, [&](int part) {
                std::size_t next = at[static_cast<std::size_t>(part)];
                for (std::size_t t = rangeBegin(triangleCount, part, triangleParts),
                                 end = rangeBegin(triangleCount, part + 1, triangleParts);
                     t < end; ++t)
                    if (proj.fate[t] == TriangleFate::Inside)
                        out.triangles[next++] = {drawIndex, static_cast<std::uint32_t>(t),
                                                 triangles[t]};
            });
            continue;
        }

        // Triangle by triangle in order, clipping those that need it. With outcodes the others
        // have their fates and counts from the verdict pass: only the kept ones are listed.
        if (!outcodes) proj.fate.assign(triangleCount, TriangleFate::Inside);
        std::vector<std::uint32_t> polygon, clipped;
        for (std::size_t t = 0; t < triangleCount; ++t) {
            const auto& tri = triangles[t];
            const auto source = static_cast<std::uint32_t>(t);
            if (outcodes && toClip[t] == 0) {
                if (proj.fate[t] == TriangleFate::Inside)
                    out.triangles.push_back({drawIndex, source, tri});
                continue;
            }
            if (!outcodes && hiddenWinding != 0 && facesAway(proj, tri, hiddenWinding)) {
                proj.fate[t] = TriangleFate::BackFace;
                ++out.backFaces;
                continue;
            }
            // Emits one screen triangle, unless a coordinate is not finite or cull drops it.
            auto emit = [&](const std::array<std::uint32_t, 3>& v) {
                const TriangleFate fate = screenFate(v);
                if (fate != TriangleFate::Inside) {
                    proj.fate[t] = fate;
                    return false;
                }
                out.triangles.push_back({drawIndex, source, v});
                for (std::uint32_t i : v)
                    if (!pulledIn.empty() && pulledIn[i] == 1) {
                        pulledIn[i] = 2;
                        ++out.outsideGuardBand;
                    }
                return true;
            };
            if (out.mode == NearPlane::Mode::Naive) {
                int behind = 0;
                for (std::uint32_t v : tri) behind += proj.pClip[v].w < 0.0 ? 1 : 0;
                const bool across =
                    behind < 3 && std::any_of(tri.begin(), tri.end(), [&](std::uint32_t v) {
                        return !(proj.pClip[v].w > 0.0);
                    });
                out.behindEye += behind == 3 ? 1 : 0;
                out.acrossEye += across ? 1 : 0;
                guardActive = !across;
                side = behind == 3 ? -1.0 : 1.0;
            } else if (out.mode == NearPlane::Mode::SameSide) {
                // Divided by w as they are when all w have one sign; a triangle across w = 0
                // keeps its part in front of the near plane.
                const auto positive = [&](std::uint32_t v) { return proj.pClip[v].w > 0.0; };
                const auto negative = [&](std::uint32_t v) { return proj.pClip[v].w < 0.0; };
                const bool allNegative = std::all_of(tri.begin(), tri.end(), negative);
                nearActive = !allNegative && !std::all_of(tri.begin(), tri.end(), positive);
                side = allNegative ? -1.0 : 1.0;
                out.acrossInfinity += nearActive ? 1 : 0;
            }
            // Which planes cut the triangle, and is it wholly outside one of them (the first
            // such plane)?
            bool cut = outcodes;  // the verdict pass leaves only triangles to clip
            std::size_t outsidePlane = SIZE_MAX;
            if (!outcodes) {
                choosePlanes();
                for (std::size_t plane : planes) {
                    int inside = 0;
                    for (std::uint32_t v : tri) inside += distance(plane, v) >= 0.0 ? 1 : 0;
                    if (inside == 0) {
                        outsidePlane = plane;
                        break;
                    }
                    cut = cut || inside < 3;
                }
            }
            if (outsidePlane != SIZE_MAX) {
                proj.fate[t] = outsideFate(outsidePlane);
                ++tally(out, proj.fate[t]);
                continue;
            }
            if (!cut) {
                if (emit(tri))
                    ++out.inside;
                else
                    ++tally(out, proj.fate[t]);
                continue;
            }
            // Sutherland-Hodgman, one plane after the other: walk the polygon's edges, keep
            // the vertices inside and add one where an edge crosses the plane. Winding is
            // preserved; the polygon left is cut into a fan.
            polygon.assign(tri.begin(), tri.end());
            for (std::size_t plane : planes) {
                if (polygon.size() < 3) break;
                clipped.clear();
                clipPolygonAgainstPlane(
                    polygon, clipped, [&](std::uint32_t v) { return distance(plane, v) >= 0.0; },
                    [&](std::uint32_t in, std::uint32_t outside) {
                        return addClipVertex(plane, in, outside);
                    });
                polygon.swap(clipped);
            }
            proj.fate[t] = TriangleFate::Clipped;
            bool any = false;
            for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
                any = emit({polygon[0], polygon[k], polygon[k + 1]}) || any;
            if (any) proj.fate[t] = TriangleFate::Clipped;
            if (polygon.size() < 3) {
                proj.fate[t] = TriangleFate::ClippedAway;  // only an edge or a point was left
                ++out.clippedAway;
            } else if (any) {
                ++out.clipped;
            } else {
                ++tally(out, proj.fate[t]);
            }
        }
    }

    // Tell the user what was clipped, dropped, culled or drawn naively.
    const SourceLocation where{scene.name, 0, 0};
    const std::size_t total = scene.triangleCount();
    if (everyTriangleBehind(out, scene)) {
        std::string text =
            "every triangle is behind the camera (is N pointing away from the object?): the "
            "image is empty";
        if (const std::size_t mirrored = trianglesBehindEye(out, scene); mirrored > 0)
            text += std::string(
                        ". The plain divide of seed 000, x/z and y/z with z < 0, would "
                        "draw ") +
                    (total == 1          ? std::string("it")
                     : mirrored == total ? "all " + std::to_string(mirrored) + " of them"
                                         : std::to_string(mirrored) + " of them") +
                    ": the object's point reflection through the eye (turned half a turn on "
                    "the screen), where the z-buffer, keeping the smallest z, keeps the side "
                    "farthest from the camera";
        diagnostics.warn(where, text);
    } else if (out.behind + out.clipped + out.clippedAway > 0) {
        bool planes = false;
        for (const Draw& draw : scene.draws) planes = planes || !draw.clipPlanes.empty();
        std::string text =
            countOf(out.clipped, "triangle was", "triangles were") + " clipped against ";
        if (clipNear) {
            text += "the near plane z = " + formatNumber(out.nearW) +
                    (planes ? " and the clip planes" : "") + "; " +
                    countOf(out.behind, "lies", "lie") + " wholly behind the near plane";
            if (out.clippedAway > 0)
                text += " and " + std::to_string(out.clippedAway) + " wholly outside a clip plane";
        } else {
            text += std::string(planes ? "the clip planes or " : "") +
                    "the guard band 2^28 pixels around the image; " +
                    std::to_string(out.clippedAway) + " lie wholly outside a clip plane";
        }
        diagnostics.note(where, text + ", not drawn");
    }
    if (out.backFaces > 0)
        diagnostics.note(where, countOf(out.backFaces, "triangle faces", "triangles face") +
                                    " away from the camera on a closed surface seen from "
                                    "outside: hidden, so not drawn (back-face culling)");
    if (out.culled > 0)
        diagnostics.note(where, countOf(out.culled, "triangle is", "triangles are") +
                                    " clockwise on screen and culled");
    if (out.acrossInfinity > 0) {
        diagnostics.note(where, countOf(out.acrossInfinity, "triangle reaches", "triangles reach") +
                                    " from in front of the eye to at or behind it (w of "
                                    "different signs): only the part with w >= " +
                                    formatNumber(out.nearW) + " is drawn");
    }
    if (out.behindEye > 0)
        diagnostics.note(
            where, "plain divide: " + countOf(out.behindEye, "triangle lies", "triangles lie") +
                       " wholly behind the eye (w < 0), drawn without clipping as "
                       "the point reflection through the eye");
    if (out.acrossEye > 0)
        diagnostics.warn(where, "plain divide: " +
                                    countOf(out.acrossEye, "triangle reaches", "triangles reach") +
                                    " from in front of the eye to at or behind it (w of "
                                    "different signs, or 0): divided by w without clipping, it "
                                    "wraps through infinity and is drawn wrong (clipping at the "
                                    "near plane draws its front part)");
    if (out.outsideGuardBand > 0) {
        diagnostics.warn(where, std::to_string(out.outsideGuardBand) +
                                    " vertices project more than 2^28 pixels from the image and "
                                    "were pulled in to that distance: triangles through them "
                                    "may be distorted on screen");
    }
    if (out.nonFinite > 0) {
        diagnostics.warn(where, std::to_string(out.nonFinite) +
                                    " triangles project to infinite or undefined coordinates "
                                    "and were not drawn");
    }
    if (paintersAlgorithm(scene)) sortFarToNear(scene, out);  // seed 004 (painter.h)
    return out;
}

}  // namespace rl
