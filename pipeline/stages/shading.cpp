#include "shading.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <optional>

#include "multiversion.h"
#include "parallel.h"
#include "phong.h"
#include "phong_kernel.h"
#include "probe.h"

namespace rl {

namespace {

// What shading reads about one draw's projected vertices, in float: one entry per vertex,
// the draw's own and then those made by clipping (interpolated along the edge they came
// from). Only what the draw's lighting and colour source read is filled.
struct DrawVertices {
    std::vector<vec3> pView;     // positions (x, y, z) / w
    std::vector<vec3> nView;     // vertex normals (zero where a vertex has none)
    std::vector<vec3> colour;    // object colours per vertex
    std::vector<vec2> texcoord;  // texture coordinates
    std::vector<double> invW;    // 1 / clip w, for perspective-correct weights (double: a
                                 // float 1/w would overflow for |w| < 3e-39)
};

DrawVertices drawVertices(const Draw& draw, const DrawProjection& proj, const DrawNormals* normals,
                          bool perspective) {
    DrawVertices out;
    const bool lit = draw.lighting != LightingModel::Unlit;
    if (lit) {
        out.pView.reserve(proj.pView.size());
        for (const dvec4& p : proj.pView) out.pView.emplace_back(cartesian(p));
        if (normals && !normals->vertex.empty()) {
            out.nView = normals->vertex;
            extendByClipping(out.nView, proj);
        } else if (!normals) {  // the scene is not lit
            out.nView.assign(proj.pView.size(), vec3(0.0f));
        }  // else left out by the normals stage (NormalsScope::Read): nothing reads them
    }
    const bool vertexColours = draw.colour == ColourSource::Vertex ||
                               (draw.colour == ColourSource::Texture && draw.decals);
    if (vertexColours && !draw.mesh->colours.empty()) {
        out.colour = draw.mesh->colours;
        extendByClipping(out.colour, proj);
    }
    if (draw.colour == ColourSource::Texture && !draw.mesh->texcoords.empty()) {
        out.texcoord = draw.mesh->texcoords;
        extendByClipping(out.texcoord, proj);
    }
    if (perspective) {
        out.invW.reserve(proj.pClip.size());
        for (const dvec4& p : proj.pClip) out.invW.push_back(1.0 / p.w);
    }
    return out;
}

void count(Shading& out, const PhongSample& s) {
    ++out.phongEvaluations;
    out.flipped += s.flipped ? 1 : 0;
    out.lightBehind += s.lightBehind ? 1 : 0;
    out.noSpecular += s.noSpecular ? 1 : 0;
    out.noNormal += s.noNormal ? 1 : 0;
}

}  // namespace

void attributeWeights(const RasterRules& rules, const DrawProjection& proj,
                      const std::array<std::uint32_t, 3>& v, float& beta, float& gamma) {
    if (rules.interpolation != RasterRules::Interpolation::PerspectiveCorrect) return;
    perspectiveWeights(beta, gamma, 1.0 / proj.pClip[v[0]].w, 1.0 / proj.pClip[v[1]].w,
                       1.0 / proj.pClip[v[2]].w);
}

ivec2 texelIndex(const Texture& texture, const vec2& st, RasterRules::TexelRounding rule) {
    const auto pick = [rule](float u, int size) {
        if (rule == RasterRules::TexelRounding::Truncate) {
            // (int)(u size + 0.5) mod size; a coordinate too large for an int wraps as 0.
            const float scaled = u * float(size) + 0.5f;
            const auto whole =
                std::abs(scaled) < 2e9f ? static_cast<long long>(scaled) : 0LL;  // toward 0
            const auto i = static_cast<int>(whole % size);
            return i < 0 ? i + size : i;
        }
        const float f = u - std::floor(u);  // -1.3, -0.3, 0.7, 1.7 all give 0.7
        const int i = static_cast<int>(std::floor(f * float(size) + 0.5f)) % size;
        return std::clamp(i, 0, size - 1);
    };
    return {pick(st.x, texture.width), pick(st.y, texture.height)};
}

vec4 sampleTexture(const Texture& texture, const vec2& st, RasterRules::TexelRounding rule) {
    if (texture.width <= 0 || texture.height <= 0) return vec4(0.0f);
    const ivec2 texel = texelIndex(texture, st, rule);
    return texture.at(texel.x, texel.y);
}

std::optional<TexelLookup> texelLookup(const Scene& scene, const DrawProjection& proj,
                                       const std::array<std::uint32_t, 3>& v, std::uint32_t draw,
                                       float beta, float gamma) {
    const Draw& d = scene.draws[draw];
    if (d.colour != ColourSource::Texture || !d.texture || !d.mesh || d.mesh->texcoords.empty() ||
        d.texture->width <= 0 || d.texture->height <= 0)
        return std::nullopt;
    attributeWeights(scene.rules, proj, v, beta, gamma);
    TexelLookup out;
    out.st = interpolate(ProjectedValues<vec2>{d.mesh->texcoords, proj}, v, beta, gamma);
    out.used = texelIndex(*d.texture, out.st, scene.rules.texel);
    out.nearest = texelIndex(*d.texture, out.st, RasterRules::TexelRounding::Nearest);
    out.truncated = texelIndex(*d.texture, out.st, RasterRules::TexelRounding::Truncate);
    return out;
}

namespace {

// The depth test run together with shading (ShadingStage::runWithDepthTest): its input, and
// what it gives back.
struct InBands {
    const ScanConversion& scan;
    DepthTest depth;
    double depthShare = 0.0;  // of the threads' time, spent testing (the rest shading)
};

// The shading stage. depth: the frame's depth test, with its ids and barycentrics; or null
// with bands, when each chunk of rows is shaded as the depth test hands it over.
template <typename Probe>
Shading shade(const Scene& scene, const ViewTransform& view, const Normals& normals,
              const Projection& projection, const DepthTest* depth, InBands* bands,
              const ShadingOptions& options, Probe& probe, int threads, Shading* recycled) {
    Shading out;
    const Conventions& conv = scene.conventions;
    const vec3 background = vec3(conv.background) * conv.colourScale;
    // Columns to work on: only those the depth test touched, and those the recycled colour
    // buffer holds something other than the background in (when both are known).
    const int chunks = (scene.height + kRowChunk - 1) / kRowChunk;
    const bool tracked = !Probe::enabled && !options.keepNormals &&
                         (bands || depth->touched.size() == static_cast<std::size_t>(chunks));
    std::vector<ColumnRange> previous;
    if (recycled) {
        if (tracked && recycled->colour.width() == scene.width &&
            recycled->colour.height() == scene.height && recycled->background == background &&
            recycled->touched.size() == static_cast<std::size_t>(chunks) &&
            (!bands || recycled->covered.width() == scene.width))
            previous = std::move(recycled->touched);
        out.colour = std::move(recycled->colour);
        out.normal = std::move(recycled->normal);
        if (bands) out.covered = std::move(recycled->covered);
    }
    out.background = background;
    if (tracked && !bands) out.touched = depth->touched;
    // Every pixel is written below (the background where no triangle won).
    out.colour.resize(scene.width, scene.height);
    if (bands) out.covered.resize(scene.width, scene.height);
    if (options.keepNormals)
        out.normal.resize(scene.width, scene.height);
    else
        out.normal = Image<vec3>();
    const bool flip = conv.flipNormalsTowardViewer;
    const bool perspective =
        scene.rules.interpolation == RasterRules::Interpolation::PerspectiveCorrect;

    std::vector<DrawVertices> vertices;
    vertices.reserve(projection.draws.size());
    for (std::size_t d = 0; d < projection.draws.size(); ++d)
        vertices.push_back(drawVertices(scene.draws[d], projection.draws[d],
                                        normals.skipped ? nullptr : &normals.draws[d],
                                        perspective));

    // The light at a point of a draw, by its lighting model.
    auto light = [&](const Draw& draw, const vec3& objectColour, const vec3& p, const vec3& n) {
        const std::size_t lightCount = std::min(draw.lightCount, view.lights.size());
        switch (draw.lighting) {
            case LightingModel::CoursePhong:
                return phong(draw.material, objectColour, scene.ambientIntensity,
                             view.lights.data(), lightCount, p, n, flip, draw.specular);
            case LightingModel::Lambert:
                return lambert(objectColour, draw.material.shininess, view.lights.data(),
                               lightCount, p, n, flip);
            case LightingModel::Unlit:
                break;
        }
        PhongSample s;
        s.unlit = objectColour;
        return s;
    };
    // The object colour of a draw at the weights (beta, gamma) of a screen triangle.
    auto colourAt = [&](const Draw& draw, const DrawVertices& dv, const ScreenTriangle& tri,
                        float beta, float gamma) {
        return objectColour(draw, scene.rules.texel, dv.colour, dv.texcoord, tri.v, beta, gamma);
    };
    // The normal to light a point with: the triangle's (flat normals) or interpolated. None
    // for an unlit draw (HW2 geometry before the first light, in a lit scene): nothing reads
    // it, and drawVertices gives such a draw no vertex normals.
    auto normalAt = [&](const Draw& draw, const DrawVertices& dv, const ScreenTriangle& tri,
                        float beta, float gamma) -> vec3 {
        if (normals.skipped || draw.lighting == LightingModel::Unlit) return vec3(0.0f);
        if (draw.flatNormals) return normals.draws[tri.draw].triangle[tri.source];
        return interpolate(dv.nView, tri.v, beta, gamma);
    };

    // Seed 004: one evaluation at the barycentre of the (unclipped) triangle, with the
    // triangle's normal; the point and normal lit are given back when asked (a probe's).
    auto flatSample = [&](const ScreenTriangle& tri, vec3* point = nullptr,
                          vec3* normal = nullptr) {
        const Draw& draw = scene.draws[tri.draw];
        const auto& corners = draw.mesh->triangles[tri.source];
        const DrawVertices& dv = vertices[tri.draw];
        const ScreenTriangle whole{tri.draw, tri.source, corners};
        const float third = 1.0f / 3.0f;
        const vec3 barycentre =
            dv.pView.empty() ? vec3(0.0f) : interpolate(dv.pView, whole.v, third, third);
        const vec3 n = normals.skipped ? vec3(0.0f) : normals.draws[tri.draw].triangle[tri.source];
        if (point) *point = barycentre;
        if (normal) *normal = n;
        return light(draw, colourAt(draw, dv, whole, third, third), barycentre, n);
    };

    // Per draw, whether its lighting is what the many-point kernels know (phong_kernel.h):
    // the course's common case, the course's Phong with the material's colour, one plain
    // light, R.V highlights and no emission. Its pixels go through the kernel when it is
    // Phong shaded with interpolated normals, screen-affine; its vertices when Gouraud, its
    // triangles' barycentres when flat.
    // kernelRuns[d] holds the draw's constants for the kernels (its material under the one
    // light), worked out once per frame.
    std::vector<std::uint8_t> kernelDraw(scene.draws.size(), 0);
    std::vector<std::uint8_t> kernelPoints(scene.draws.size(), 0);
    std::vector<CoursePhongRun> kernelRuns(scene.draws.size());
    for (std::size_t d = 0; d < scene.draws.size(); ++d) {
        const Draw& draw = scene.draws[d];
        const bool kernelLighting =
            draw.lighting == LightingModel::CoursePhong && draw.colour == ColourSource::Material &&
            !normals.skipped && std::min(draw.lightCount, view.lights.size()) == 1 &&
            view.lights[0].plain() && draw.specular == SpecularModel::Phong &&
            draw.material.emission == vec3(0.0f);
        if (!kernelLighting) continue;
        kernelDraw[d] = draw.shading == ShadingModel::Phong && !draw.flatNormals && !perspective;
        kernelPoints[d] = draw.shading == ShadingModel::Gouraud || litPerTriangle(draw.shading);
        const Material& m = draw.material;
        const ViewLight& l = view.lights[0];
        CoursePhongRun& run = kernelRuns[d];
        run.ambient = scene.ambientIntensity * m.ka;
        run.diffuse = l.intensity * m.od * m.kd;
        run.specular = l.intensity * m.ks;
        run.light = vec3(l.pView);
        run.directional = l.pView.w == 0.0;
        run.shininess = m.shininess;
        run.flip = flip;
        run.withSpecular = m.ks != 0.0f;
    }
    // What a kernel counted, for `evaluations` points.
    auto addKernelCounts = [](Shading& counts, const CoursePhongCounts& c,
                              std::size_t evaluations) {
        counts.phongEvaluations += evaluations;
        counts.flipped += c.flipped;
        counts.lightBehind += c.lightBehind;
        counts.noSpecular += c.noSpecular;
        counts.noNormal += c.noNormal;
    };

    // Flat and Gouraud colours are evaluated first, for the visible triangles and their
    // vertices only, so that the pixel loop (on several threads) only reads them.
    struct DrawTables {
        std::vector<vec3> flatColour, flatNormal;  // per mesh triangle
        std::vector<vec3> vertexColour;            // per projected vertex (Gouraud)
        std::vector<std::uint8_t> done;
    };
    std::vector<DrawTables> tables(projection.draws.size());
    bool anyPerTriangle = false;
    for (const Draw& draw : scene.draws)
        anyPerTriangle = anyPerTriangle || draw.shading != ShadingModel::Phong;
    if (anyPerTriangle) {
        // The triangles that kept a pixel: from the depth test when it worked them out,
        // otherwise found here. In bands, before the depth test: those with a fragment.
        std::vector<std::uint8_t> found;
        const bool known = !bands && depth->visible.size() == projection.triangles.size();
        if (!known) found.assign(projection.triangles.size(), 0);
        const std::vector<std::uint8_t>& visible = known ? depth->visible : found;
        if (bands) {
            for (std::size_t t = 0; t < found.size(); ++t)
                found[t] = bands->scan.spanStart[t] < bands->scan.spanStart[t + 1] ? 1 : 0;
        } else if (!known) {
            const bool touchedKnown = depth->touched.size() == static_cast<std::size_t>(chunks);
            for (int y = 0; y < scene.height; ++y) {
                const ColumnRange columns =
                    touchedKnown ? depth->touched[static_cast<std::size_t>(y / kRowChunk)]
                                 : ColumnRange{0, scene.width};
                const std::uint32_t* idRow = depth->triangle.row(y);
                // A run of one triangle's pixels at a time.
                for (int x = columns.begin; x < columns.end;) {
                    const std::uint32_t t = idRow[x];
                    if (t != kNoTriangle) found[t] = 1;
                    x = runEnd(idRow, x + 1, columns.end, t);
                }
            }
        }
        // Which flat triangles and Gouraud vertices are needed (done = kNeeded), then their
        // colours, the independent ones shared out between the threads, then the vertices
        // made by clipping, from the colours of their edge's ends.
        constexpr std::uint8_t kNeeded = 1, kDone = 2;
        for (std::size_t t = 0; t < projection.triangles.size(); ++t) {
            if (!visible[t]) continue;
            const ScreenTriangle& tri = projection.triangles[t];
            const Draw& draw = scene.draws[tri.draw];
            DrawTables& table = tables[tri.draw];
            if (litPerTriangle(draw.shading)) {
                if (table.done.empty()) {
                    table.flatColour.resize(draw.mesh->triangles.size());
                    table.flatNormal.resize(draw.mesh->triangles.size());
                    table.done.assign(draw.mesh->triangles.size(), 0);
                }
                table.done[tri.source] = kNeeded;
            } else if (draw.shading == ShadingModel::Gouraud) {
                if (table.done.empty()) {
                    const std::size_t n = projection.draws[tri.draw].pView.size();
                    table.vertexColour.resize(n);
                    table.done.assign(n, 0);
                }
                for (std::uint32_t v : tri.v) table.done[v] = kNeeded;
            }
        }
        const auto evaluate = [&](std::size_t d, std::size_t i, Shading& counts) {
            const Draw& draw = scene.draws[d];
            DrawTables& table = tables[d];
            if (litPerTriangle(draw.shading)) {
                const ScreenTriangle tri{static_cast<std::uint32_t>(d),
                                         static_cast<std::uint32_t>(i), draw.mesh->triangles[i]};
                const PhongSample sample = flatSample(tri);
                count(counts, sample);
                table.flatColour[i] = sample.colour();
                table.flatNormal[i] = sample.n;
            } else {
                const auto v = static_cast<std::uint32_t>(i);
                const DrawVertices& dv = vertices[d];
                const ScreenTriangle at{static_cast<std::uint32_t>(d), 0, {v, v, v}};
                const PhongSample sample = light(draw, colourAt(draw, dv, at, 0.0f, 0.0f),
                                                 dv.pView.empty() ? vec3(0.0f) : dv.pView[v],
                                                 dv.nView.empty() ? vec3(0.0f) : dv.nView[v]);
                count(counts, sample);
                table.vertexColour[v] = sample.colour();
            }
            table.done[i] = kDone;
        };
        for (std::size_t d = 0; d < tables.size(); ++d) {
            DrawTables& table = tables[d];
            if (table.done.empty()) continue;
            // Flat: every triangle; Gouraud: the vertices the projection did not make.
            const std::size_t independent = litPerTriangle(scene.draws[d].shading)
                                                ? table.done.size()
                                                : projection.draws[d].originalVertexCount;
            const int parts = Probe::enabled || independent < 4096 ? 1 : std::max(1, threads);
            std::vector<Shading> partCounts(static_cast<std::size_t>(parts));
            runParts(parts, [&](int part) {
                Shading counts;  // on the thread's stack
                const std::size_t first = rangeBegin(independent, part, parts);
                const std::size_t last = rangeBegin(independent, part + 1, parts);
                const Draw& draw = scene.draws[d];
                if (!Probe::enabled && kernelPoints[d]) {
                    // Eight at a time: Gouraud's vertices (1M sphere: ~250,000 of them), or
                    // flat's triangles, each lit at its barycentre with its normal as
                    // flatSample lights it.
                    std::vector<std::uint32_t> needed;
                    for (std::size_t i = first; i < last; ++i)
                        if (table.done[i] == kNeeded) {
                            needed.push_back(static_cast<std::uint32_t>(i));
                            table.done[i] = kDone;
                        }
                    const DrawVertices& dv = vertices[d];
                    CoursePhongCounts c;
                    if (draw.shading == ShadingModel::Gouraud) {
                        shadeCoursePhongPoints(kernelRuns[d], dv.pView.data(), dv.nView.data(),
                                               needed.data(), needed.size(),
                                               table.vertexColour.data(), nullptr, c);
                    } else {
                        const std::vector<vec3>& triangleNormals = normals.draws[d].triangle;
                        std::vector<vec3> points, pointNormals;
                        points.reserve(needed.size());
                        pointNormals.reserve(needed.size());
                        const float third = 1.0f / 3.0f;
                        for (std::uint32_t i : needed) {
                            points.push_back(
                                interpolate(dv.pView, draw.mesh->triangles[i], third, third));
                            pointNormals.push_back(triangleNormals[i]);
                        }
                        std::vector<vec3> colours(needed.size()), used(needed.size());
                        shadeCoursePhongPoints(kernelRuns[d], points.data(), pointNormals.data(),
                                               nullptr, needed.size(), colours.data(), used.data(),
                                               c);
                        for (std::size_t k = 0; k < needed.size(); ++k) {
                            table.flatColour[needed[k]] = colours[k];
                            table.flatNormal[needed[k]] = used[k];
                        }
                    }
                    addKernelCounts(counts, c, needed.size());
                } else {
                    for (std::size_t i = first; i < last; ++i)
                        if (table.done[i] == kNeeded) evaluate(d, i, counts);
                }
                partCounts[static_cast<std::size_t>(part)] = std::move(counts);
            });
            for (const Shading& c : partCounts) {
                out.phongEvaluations += c.phongEvaluations;
                out.flipped += c.flipped;
                out.lightBehind += c.lightBehind;
                out.noSpecular += c.noSpecular;
                out.noNormal += c.noNormal;
            }
        }
        // Gouraud, a vertex made by clipping: the colour interpolated along its edge, as if
        // clipping had happened after vertex lighting (the ends may be made by clipping too).
        const auto clippedColour = [&](std::size_t d, std::uint32_t v, const auto& self) -> vec3 {
            DrawTables& table = tables[d];
            if (table.done[v] == kDone) return table.vertexColour[v];
            const DrawProjection& proj = projection.draws[d];
            vec3 colour;
            if (v >= proj.originalVertexCount) {
                const ClipVertex& g = proj.generated[v - proj.originalVertexCount];
                colour = glm::mix(self(d, g.a, self), self(d, g.b, self), static_cast<float>(g.t));
            } else {
                evaluate(d, v, out);  // an end no visible triangle uses
                return table.vertexColour[v];
            }
            table.vertexColour[v] = colour;
            table.done[v] = kDone;
            return colour;
        };
        for (std::size_t d = 0; d < tables.size(); ++d) {
            DrawTables& table = tables[d];
            if (table.done.empty() || scene.draws[d].shading != ShadingModel::Gouraud) continue;
            for (std::size_t v = projection.draws[d].originalVertexCount; v < table.done.size();
                 ++v)
                if (table.done[v] == kNeeded)
                    clippedColour(d, static_cast<std::uint32_t>(v), clippedColour);
        }
    }

    // One row's pixels: idRow and baryRow (null when no draw reads barycentrics) hold what won
    // them; columns, those to shade (the rest is the background). When tracked, the
    // background missing outside them is written too. coveredRow: 1 where a triangle won, 0
    // elsewhere (only in bands, whose ids are not kept).
    const float scale = conv.colourScale;
    auto shadeRow = [&](int y, const std::uint32_t* idRow, const vec2* baryRow, ColumnRange columns,
                        Shading& counts) {
        vec3* colourRow = out.colour.row(y);
        vec3* normalRow = options.keepNormals ? out.normal.row(y) : nullptr;
        std::uint8_t* coveredRow = bands ? out.covered.row(y) : nullptr;
        if (tracked) {
            const ColumnRange stale = previous.empty()
                                          ? ColumnRange{0, scene.width}
                                          : previous[static_cast<std::size_t>(y / kRowChunk)];
            const auto clear = [&](int from, int to) {
                std::fill(colourRow + from, colourRow + to, background);
                if (coveredRow)
                    std::memset(coveredRow + from, 0, static_cast<std::size_t>(to - from));
            };
            if (columns.begin >= columns.end) {
                if (stale.begin < stale.end) clear(stale.begin, stale.end);
            } else {
                if (stale.begin < columns.begin)
                    clear(stale.begin, std::min(stale.end, columns.begin));
                if (stale.end > columns.end) clear(std::max(stale.begin, columns.end), stale.end);
            }
        }
        int x = columns.begin;
        while (x < columns.end) {
            const std::uint32_t t = idRow[x];
            // A run of pixels won by one triangle (or by none): its set-up is done once.
            const int end = runEnd(idRow, x + 1, columns.end, t);
            if (t == kNoTriangle) {
                fillColourRun(background, end - x, colourRow + x);
                if (normalRow) std::fill(normalRow + x, normalRow + end, vec3(0.0f));
                if (coveredRow) std::memset(coveredRow + x, 0, static_cast<std::size_t>(end - x));
                x = end;
                continue;
            }
            if (coveredRow) std::memset(coveredRow + x, 1, static_cast<std::size_t>(end - x));
            const ScreenTriangle& tri = projection.triangles[t];
            const Draw& draw = scene.draws[tri.draw];
            const DrawVertices& dv = vertices[tri.draw];
            const DrawTables& table = tables[tri.draw];
            if constexpr (!Probe::enabled) {
                if (kernelDraw[tri.draw]) {
                    // Many pixels at once, the same bits as phong() (phong_kernel.h).
                    const vec3& a = dv.pView[tri.v[0]];
                    const vec3& na = dv.nView[tri.v[0]];
                    CoursePhongRun run = kernelRuns[tri.draw];
                    run.p0 = a;
                    run.dp1 = dv.pView[tri.v[1]] - a;
                    run.dp2 = dv.pView[tri.v[2]] - a;
                    run.n0 = na;
                    run.dn1 = dv.nView[tri.v[1]] - na;
                    run.dn2 = dv.nView[tri.v[2]] - na;
                    CoursePhongCounts c;
                    shadeCoursePhongRun(run, baryRow + x, end - x, colourRow + x,
                                        normalRow ? normalRow + x : nullptr, scale, c);
                    const std::size_t shaded = static_cast<std::size_t>(end - x);
                    counts.shadedPixels += shaded;
                    addKernelCounts(counts, c, shaded);
                    counts.clampedPixels += c.clamped;
                    x = end;
                    continue;
                }
                if (litPerTriangle(draw.shading) && !normalRow) {
                    // One colour for the whole run.
                    const vec3 colour = table.flatColour[tri.source];
                    fillColourRun(colour, end - x, colourRow + x);
                    const auto n = static_cast<std::size_t>(end - x);
                    counts.shadedPixels += n;
                    if (colour.r > scale || colour.g > scale || colour.b > scale)
                        counts.clampedPixels += n;
                    x = end;
                    continue;
                }
                if (draw.shading == ShadingModel::Gouraud && !normalRow && !perspective) {
                    // c0 + beta (c1 - c0) + gamma (c2 - c0), as interpolate() writes it.
                    const vec3 c0 = table.vertexColour[tri.v[0]];
                    const vec3 d1 = table.vertexColour[tri.v[1]] - c0;
                    const vec3 d2 = table.vertexColour[tri.v[2]] - c0;
                    counts.clampedPixels +=
                        shadeGouraudRun(c0, d1, d2, baryRow + x, end - x, colourRow + x, scale);
                    counts.shadedPixels += static_cast<std::size_t>(end - x);
                    x = end;
                    continue;
                }
            }
            for (; x < end; ++x) {
                float beta = baryRow ? baryRow[x].x : 0.0f;
                float gamma = baryRow ? baryRow[x].y : 0.0f;
                vec3 colour(0.0f);
                vec3 usedNormal(0.0f);
                [[maybe_unused]] ShadeEvent event;
                if (perspective)
                    perspectiveWeights(beta, gamma, dv.invW[tri.v[0]], dv.invW[tri.v[1]],
                                       dv.invW[tri.v[2]]);
                switch (draw.shading) {
                    case ShadingModel::Phong: {
                        const vec3 p = dv.pView.empty() ? vec3(0.0f)
                                                        : interpolate(dv.pView, tri.v, beta, gamma);
                        const vec3 n = normalAt(draw, dv, tri, beta, gamma);
                        const PhongSample s =
                            light(draw, colourAt(draw, dv, tri, beta, gamma), p, n);
                        if (draw.lighting != LightingModel::Unlit) count(counts, s);
                        colour = s.colour();
                        usedNormal = s.n;
                        RL_PROBE_HOOK(event.pView = p; event.nInterpolated = n; event.sample = s);
                        break;
                    }
                    case ShadingModel::Flat:
                    case ShadingModel::Painter: {
                        colour = table.flatColour[tri.source];
                        usedNormal = table.flatNormal[tri.source];
                        RL_PROBE_HOOK(event.sample =
                                          flatSample(tri, &event.pView, &event.nInterpolated));
                        break;
                    }
                    case ShadingModel::Gouraud: {
                        const vec3 c0 = table.vertexColour[tri.v[0]];
                        const vec3 c1 = table.vertexColour[tri.v[1]];
                        const vec3 c2 = table.vertexColour[tri.v[2]];
                        colour = c0 + beta * (c1 - c0) + gamma * (c2 - c0);
                        if (normalRow && !dv.pView.empty()) {
                            // The normal Phong would use here: interpolated,
                            // normalised, turned toward the viewer, so that the
                            // normals image means the same in every shading model.
                            const vec3 p = interpolate(dv.pView, tri.v, beta, gamma);
                            usedNormal =
                                orientedNormal(normalAt(draw, dv, tri, beta, gamma), p, flip);
                        }
                        RL_PROBE_HOOK(event.vertexColours = {c0, c1, c2});
                        break;
                    }
                }
                colourRow[x] = colour;
                ++counts.shadedPixels;
                counts.clampedPixels +=
                    (colour.r > scale || colour.g > scale || colour.b > scale) ? 1 : 0;
                if (normalRow) normalRow[x] = usedNormal;
                RL_PROBE_HOOK(event.triangle = t; event.x = x; event.y = y;
                              event.model = draw.shading; event.colour = colour;
                              probe.onShade(event));
            }
        }
    };

    const int parts = Probe::enabled ? 1 : std::max(1, std::min(threads, scene.height));
    std::vector<Shading> partCounts(static_cast<std::size_t>(parts));
    if (bands) {
        // Each chunk as soon as the thread that tested it hands it over, from its band (in
        // that thread's cache); the time each thread spends testing and shading is summed.
        // Each thread's counts and times on cache lines of their own.
        using Clock = std::chrono::steady_clock;
        struct alignas(64) PartTime {
            Clock::time_point last;
            Clock::duration testing{}, shading{};
            Shading counts;
        };
        std::vector<PartTime> times(static_cast<std::size_t>(parts));
        for (PartTime& t : times) t.last = Clock::now();
        bands->depth = DepthTestStage().runBands(
            scene, projection, bands->scan, parts, [&](const TestedBand& band) {
                const auto part = static_cast<std::size_t>(band.part);
                const Clock::time_point start = Clock::now();
                times[part].testing += start - times[part].last;
                for (int y = band.y0; y < band.y1; ++y) {
                    const auto row = static_cast<std::size_t>(y - band.y0) * band.stride;
                    shadeRow(y, band.ids + row, band.bary ? band.bary + row : nullptr, band.columns,
                             times[part].counts);
                }
                times[part].last = Clock::now();
                times[part].shading += times[part].last - start;
            });
        out.touched = bands->depth.touched;
        Clock::duration testing{}, shading{};
        for (std::size_t part = 0; part < times.size(); ++part) {
            testing += times[part].testing;
            shading += times[part].shading;
            partCounts[part] = std::move(times[part].counts);
        }
        const double sum = std::chrono::duration<double>(testing + shading).count();
        bands->depthShare = sum > 0.0 ? std::chrono::duration<double>(testing).count() / sum : 0.5;
    } else {
        // The rows shared out between the threads (one thread when a probe records).
        runParts(parts, [&](int part) {
            Shading counts;  // on the thread's stack, not beside the other threads' counters
            for (int y = 0; y < scene.height; ++y) {
                if (parts > 1 && !ownsRow(y, part, parts)) continue;
                const ColumnRange columns =
                    tracked ? depth->touched[static_cast<std::size_t>(y / kRowChunk)]
                            : ColumnRange{0, scene.width};
                shadeRow(y, depth->triangle.row(y), depth->barycentric.row(y), columns, counts);
            }
            partCounts[static_cast<std::size_t>(part)] = std::move(counts);
        });
    }
    for (const Shading& c : partCounts) {
        out.shadedPixels += c.shadedPixels;
        out.phongEvaluations += c.phongEvaluations;
        out.flipped += c.flipped;
        out.lightBehind += c.lightBehind;
        out.noSpecular += c.noSpecular;
        out.noNormal += c.noNormal;
        out.clampedPixels += c.clampedPixels;
    }
    if (bands) bands->depth.covered = out.shadedPixels;
    return out;
}

}  // namespace

template <typename Probe>
Shading ShadingStage::run(const Scene& scene, const ViewTransform& view, const Normals& normals,
                          const Projection& projection, const DepthTest& depth,
                          const ShadingOptions& options, Probe& probe, int threads,
                          Shading* recycled) const {
    return shade(scene, view, normals, projection, &depth, nullptr, options, probe, threads,
                 recycled);
}

bool shadeInBands(const Scene& scene, const Projection& projection, const ScanConversion& scan) {
    // What lighting the triangles with a fragment costs, in points lit, against the fragments
    // to test (scan conversion's count). Phong lights nothing ahead. A flat draw lights each
    // of its triangles with a fragment; a Gouraud draw each vertex of them, at most all its
    // vertices (on a closed mesh about half as many as its triangles). The triangles with a
    // fragment are those neither degenerate nor off the screen (scan conversion counts them),
    // an upper bound for each draw's.
    const std::size_t withFragments =
        scan.triangleCount() - std::min(scan.triangleCount(), scan.degenerate + scan.offscreen);
    std::size_t flatPoints = 0, gouraudVertices = 0;
    for (std::size_t d = 0; d < scene.draws.size(); ++d) {
        const ShadingModel model = scene.draws[d].shading;
        if (litPerTriangle(model)) flatPoints = withFragments;
        if (model == ShadingModel::Gouraud && d < projection.draws.size())
            gouraudVertices += projection.draws[d].pView.size();
    }
    const std::size_t points = flatPoints + std::min(gouraudVertices, 3 * withFragments);
    return points * kBandsFragmentsPerPoint <= scan.pixels;
}

std::pair<DepthTest, Shading> ShadingStage::runWithDepthTest(
    const Scene& scene, const ViewTransform& view, const Normals& normals,
    const Projection& projection, const ScanConversion& scan, int threads, Shading* recycled,
    double& depthShare) const {
    NullProbe probe;
    InBands bands{scan, DepthTest{}, 0.0};
    Shading shading = shade(scene, view, normals, projection, nullptr, &bands, ShadingOptions{},
                            probe, threads, recycled);
    depthShare = bands.depthShare;
    return {std::move(bands.depth), std::move(shading)};
}

Shading ShadingStage::run(const Scene& scene, const ViewTransform& view, const Normals& normals,
                          const Projection& projection, const DepthTest& depth,
                          const ShadingOptions& options, int threads, Shading* recycled) const {
    NullProbe probe;
    return run(scene, view, normals, projection, depth, options, probe, threads, recycled);
}

template Shading ShadingStage::run<NullProbe>(const Scene&, const ViewTransform&, const Normals&,
                                              const Projection&, const DepthTest&,
                                              const ShadingOptions&, NullProbe&, int,
                                              Shading*) const;
template Shading ShadingStage::run<RecordingProbe>(const Scene&, const ViewTransform&,
                                                   const Normals&, const Projection&,
                                                   const DepthTest&, const ShadingOptions&,
                                                   RecordingProbe&, int, Shading*) const;

}  // namespace rl
