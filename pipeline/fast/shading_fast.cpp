#include "shading_fast.h"

#include <algorithm>
#include <chrono>
#include <cstring>

#include "pipeline/core/parallel.h"
#include "pipeline/fast/phong_kernel.h"
#include "pipeline/stages/probe.h"

namespace rl::fast {

namespace {

// Per draw, whether its lighting is what the many-point kernels know (phong_kernel.h): the
// course's common case, the course's Phong with the material's colour, one plain light, R.V
// highlights up to kPreciseShininess and no emission. Its pixels go through the kernel when it is
// Phong shaded with interpolated normals, screen-affine; its vertices when Gouraud, its triangles'
// barycentres when flat. runs[d] holds the draw's constants (its material under the one light).
struct Kernels {
    std::vector<std::uint8_t> pixels, points;
    std::vector<CoursePhongRun> runs;
};

Kernels kernelsFor(const FrameLighting& lighting) {
    const Scene& scene = lighting.scene();
    const ViewTransform& view = lighting.view();
    Kernels k;
    k.pixels.assign(scene.draws.size(), 0);
    k.points.assign(scene.draws.size(), 0);
    k.runs.resize(scene.draws.size());
    for (std::size_t d = 0; d < scene.draws.size(); ++d) {
        const Draw& draw = scene.draws[d];
        const bool kernelLighting =
            draw.lighting == LightingModel::CoursePhong && draw.colour == ColourSource::Material &&
            !lighting.normals().skipped && std::min(draw.lightCount, view.lights.size()) == 1 &&
            view.lights[0].plain() && draw.specular == SpecularModel::Phong &&
            draw.material.emission == vec3(0.0f) && !(draw.material.shininess > kPreciseShininess);
        if (!kernelLighting) continue;
        k.pixels[d] =
            draw.shading == ShadingModel::Phong && !draw.flatNormals && !lighting.perspective();
        k.points[d] = draw.shading == ShadingModel::Gouraud || litPerTriangle(draw.shading);
        k.runs[d] = coursePhongRun(draw.material, view.lights[0], scene.ambientIntensity,
                                   scene.conventions.flipNormalsTowardViewer);
    }
    return k;
}

// What a kernel counted, for `evaluations` points.
void addKernelCounts(Shading& counts, const CoursePhongCounts& c, std::size_t evaluations) {
    counts.phongEvaluations += evaluations;
    counts.flipped += c.flipped;
    counts.lightBehind += c.lightBehind;
    counts.noSpecular += c.noSpecular;
    counts.noNormal += c.noNormal;
}

// lightEntry for the entries [first, last) of draw d that are needed, eight or four at a time
// (kernelLanes) through the kernel: Gouraud's vertices, or flat's triangles, each lit at its
// barycentre with its normal as FrameLighting::flatSample lights it.
void lightEntriesByKernel(const FrameLighting& lighting, const CoursePhongRun& run,
                          ColourTables& tables, std::size_t d, std::size_t first, std::size_t last,
                          Shading& counts) {
    const Draw& draw = lighting.scene().draws[d];
    DrawColours& table = tables.draws[d];
    std::vector<std::uint32_t> needed;
    for (std::size_t i = first; i < last; ++i)
        if (table.state[i] == DrawColours::kNeeded) {
            needed.push_back(static_cast<std::uint32_t>(i));
            table.state[i] = DrawColours::kLit;
        }
    const DrawVertices& dv = lighting.vertices(d);
    CoursePhongCounts c;
    if (draw.shading == ShadingModel::Gouraud) {
        shadeCoursePhongPoints(run, dv.pView.data(), dv.nView.data(), needed.data(), needed.size(),
                               table.vertexColour.data(), nullptr, c);
    } else {
        const std::vector<vec3>& triangleNormals = lighting.normals().draws[d].triangle;
        std::vector<vec3> points, pointNormals;
        points.reserve(needed.size());
        pointNormals.reserve(needed.size());
        const float third = 1.0f / 3.0f;
        for (std::uint32_t i : needed) {
            points.push_back(interpolate(dv.pView, draw.mesh->triangles[i], third, third));
            pointNormals.push_back(triangleNormals[i]);
        }
        std::vector<vec3> colours(needed.size()), used(needed.size());
        shadeCoursePhongPoints(run, points.data(), pointNormals.data(), nullptr, needed.size(),
                               colours.data(), used.data(), c);
        for (std::size_t k = 0; k < needed.size(); ++k) {
            table.flatColour[needed[k]] = colours[k];
            table.flatNormal[needed[k]] = used[k];
        }
    }
    addKernelCounts(counts, c, needed.size());
}

// The stage's lightTrianglesAndVertices, the independent entries shared out between the
// threads (a flat draw's triangles, a Gouraud draw's own vertices), then the vertices made by
// clipping.
ColourTables lightTables(const FrameLighting& lighting, const Kernels& kernels,
                         const std::vector<std::uint8_t>& visible, int threads, Shading& out) {
    ColourTables tables = neededColours(lighting, visible);
    for (std::size_t d = 0; d < tables.draws.size(); ++d) {
        DrawColours& table = tables.draws[d];
        if (table.state.empty()) continue;
        const std::size_t independent = litPerTriangle(lighting.scene().draws[d].shading)
                                            ? table.state.size()
                                            : lighting.projection().draws[d].originalVertexCount;
        const int parts = independent < 4096 ? 1 : std::max(1, threads);
        std::vector<Shading> partCounts(static_cast<std::size_t>(parts));
        runParts(parts, [&](int part) {
            Shading counts;  // on the thread's stack
            const std::size_t first = rangeBegin(independent, part, parts);
            const std::size_t last = rangeBegin(independent, part + 1, parts);
            if (kernels.points[d]) {
                lightEntriesByKernel(lighting, kernels.runs[d], tables, d, first, last, counts);
            } else {
                for (std::size_t i = first; i < last; ++i)
                    if (table.state[i] == DrawColours::kNeeded)
                        lightEntry(lighting, tables, d, i, counts);
            }
            partCounts[static_cast<std::size_t>(part)] = std::move(counts);
        });
        for (const Shading& c : partCounts) addCounts(out, c);
    }
    colourClippedVertices(lighting, tables, out);
    return tables;
}

// The triangles that kept a pixel when the depth test did not work them out. In bands,
// before the depth test: those with a fragment.
std::vector<std::uint8_t> findVisible(const FrameLighting& lighting, const DepthTest* depth,
                                      const ScanConversion* bandsScan) {
    const Scene& scene = lighting.scene();
    const std::size_t count = lighting.projection().triangles.size();
    std::vector<std::uint8_t> found(count, 0);
    if (bandsScan) {
        for (std::size_t t = 0; t < count; ++t)
            found[t] = bandsScan->spanStart[t] < bandsScan->spanStart[t + 1] ? 1 : 0;
        return found;
    }
    const int chunks = (scene.height + kRowChunk - 1) / kRowChunk;
    const bool touchedKnown = depth->touched.size() == static_cast<std::size_t>(chunks);
    for (int y = 0; y < scene.height; ++y) {
        const ColumnRange columns = touchedKnown
                                        ? depth->touched[static_cast<std::size_t>(y / kRowChunk)]
                                        : ColumnRange{0, scene.width};
        const std::uint32_t* idRow = depth->triangle.row(y);
        for (int x = columns.begin; x < columns.end;) {  // a run of one triangle at a time
            const std::uint32_t t = idRow[x];
            if (t != kNoTriangle) found[t] = 1;
            x = runEnd(idRow, x + 1, columns.end, t);
        }
    }
    return found;
}

// Shades rows of the image, run of one triangle's pixels by run.
class RowShader {
public:
    RowShader(const FrameLighting& lighting, const ColourTables& tables, const Kernels& kernels,
              Shading& out, bool keepNormals, bool tracked, std::vector<ColumnRange> previous)
        : m_lighting(lighting),
          m_tables(tables),
          m_kernels(kernels),
          m_out(out),
          m_keepNormals(keepNormals),
          m_tracked(tracked),
          m_previous(std::move(previous)) {}

    // One row's pixels: idRow and baryRow (null when no draw reads barycentrics) hold what won
    // them; columns, those to shade (the rest is the background). When tracked, the
    // background missing outside them is written too. In bands the covered image says where
    // a triangle won (1) and where not (0).
    void row(int y, const std::uint32_t* idRow, const vec2* baryRow, ColumnRange columns,
             Shading& counts) const;

private:
    void clearStale(int y, ColumnRange columns) const;
    // The run [x, end) of triangle t: through a kernel, or pixel by pixel as the stage does.
    void run(int y, int x, int end, std::uint32_t t, const vec2* baryRow, Shading& counts) const;

    const FrameLighting& m_lighting;
    const ColourTables& m_tables;
    const Kernels& m_kernels;
    Shading& m_out;
    bool m_keepNormals, m_tracked;
    std::vector<ColumnRange> m_previous;
};

void RowShader::clearStale(int y, ColumnRange columns) const {
    const Scene& scene = m_lighting.scene();
    const ColumnRange stale = m_previous.empty()
                                  ? ColumnRange{0, scene.width}
                                  : m_previous[static_cast<std::size_t>(y / kRowChunk)];
    vec3* colourRow = m_out.colour.row(y);
    std::uint8_t* coveredRow = m_out.covered.empty() ? nullptr : m_out.covered.row(y);
    const auto clear = [&](int from, int to) {
        std::fill(colourRow + from, colourRow + to, m_out.background);
        if (coveredRow) std::memset(coveredRow + from, 0, static_cast<std::size_t>(to - from));
    };
    if (columns.begin >= columns.end) {
        if (stale.begin < stale.end) clear(stale.begin, stale.end);
        return;
    }
    if (stale.begin < columns.begin) clear(stale.begin, std::min(stale.end, columns.begin));
    if (stale.end > columns.end) clear(std::max(stale.begin, columns.end), stale.end);
}

void RowShader::row(int y, const std::uint32_t* idRow, const vec2* baryRow, ColumnRange columns,
                    Shading& counts) const {
    if (m_tracked) clearStale(y, columns);
    vec3* colourRow = m_out.colour.row(y);
    vec3* normalRow = m_keepNormals ? m_out.normal.row(y) : nullptr;
    std::uint8_t* coveredRow = m_out.covered.empty() ? nullptr : m_out.covered.row(y);
    for (int x = columns.begin; x < columns.end;) {
        const std::uint32_t t = idRow[x];
        // A run of pixels won by one triangle (or by none): its set-up is done once.
        const int end = runEnd(idRow, x + 1, columns.end, t);
        const auto n = static_cast<std::size_t>(end - x);
        if (coveredRow) std::memset(coveredRow + x, t == kNoTriangle ? 0 : 1, n);
        if (t == kNoTriangle) {
            fillColourRun(m_out.background, end - x, colourRow + x);
            if (normalRow) std::fill(normalRow + x, normalRow + end, vec3(0.0f));
        } else {
            run(y, x, end, t, baryRow, counts);
        }
        x = end;
    }
}

void RowShader::run(int y, int x, int end, std::uint32_t t, const vec2* baryRow,
                    Shading& counts) const {
    const ScreenTriangle& tri = m_lighting.projection().triangles[t];
    const Draw& draw = m_lighting.scene().draws[tri.draw];
    const DrawVertices& dv = m_lighting.vertices(tri.draw);
    const DrawColours& table = m_tables.draws[tri.draw];
    const float scale = m_lighting.scene().conventions.colourScale;
    vec3* colourRow = m_out.colour.row(y);
    vec3* normalRow = m_keepNormals ? m_out.normal.row(y) : nullptr;
    const auto n = static_cast<std::size_t>(end - x);
    if (m_kernels.pixels[tri.draw]) {
        // Many pixels at once, the same bits as phong() (phong_kernel.h).
        const vec3& a = dv.pView[tri.v[0]];
        const vec3& na = dv.nView[tri.v[0]];
        CoursePhongRun run = m_kernels.runs[tri.draw];
        run.p0 = a;
        run.dp1 = dv.pView[tri.v[1]] - a;
        run.dp2 = dv.pView[tri.v[2]] - a;
        run.n0 = na;
        run.dn1 = dv.nView[tri.v[1]] - na;
        run.dn2 = dv.nView[tri.v[2]] - na;
        CoursePhongCounts c;
        shadeCoursePhongRun(run, baryRow + x, end - x, colourRow + x,
                            normalRow ? normalRow + x : nullptr, scale, c);
        counts.shadedPixels += n;
        addKernelCounts(counts, c, n);
        counts.clampedPixels += c.clamped;
        return;
    }
    if (litPerTriangle(draw.shading) && !normalRow) {
        // One colour for the whole run.
        const vec3 colour = table.flatColour[tri.source];
        fillColourRun(colour, end - x, colourRow + x);
        counts.shadedPixels += n;
        if (colour.r > scale || colour.g > scale || colour.b > scale) counts.clampedPixels += n;
        return;
    }
    if (draw.shading == ShadingModel::Gouraud && !normalRow && !m_lighting.perspective()) {
        // c0 + beta (c1 - c0) + gamma (c2 - c0), as interpolate() writes it.
        const vec3 c0 = table.vertexColour[tri.v[0]];
        const vec3 d1 = table.vertexColour[tri.v[1]] - c0;
        const vec3 d2 = table.vertexColour[tri.v[2]] - c0;
        counts.clampedPixels +=
            shadeGouraudRun(c0, d1, d2, baryRow + x, end - x, colourRow + x, scale);
        counts.shadedPixels += n;
        return;
    }
    NullProbe none;
    for (; x < end; ++x) {
        const vec2 b = baryRow ? baryRow[x] : vec2(0.0f);
        colourRow[x] = shadeFragment(m_lighting, m_tables, t, x, y, b.x, b.y,
                                     normalRow ? normalRow + x : nullptr, counts, none);
    }
}

// The colour buffer (and covered, in bands) taken from an earlier frame, and the columns of
// it that may hold something other than the background (empty: unknown, all of them).
std::vector<ColumnRange> recycle(const Scene& scene, Shading& out, Shading* recycled, bool tracked,
                                 bool bands) {
    std::vector<ColumnRange> previous;
    if (!recycled) return previous;
    const int chunks = (scene.height + kRowChunk - 1) / kRowChunk;
    if (tracked && recycled->colour.width() == scene.width &&
        recycled->colour.height() == scene.height && recycled->background == out.background &&
        recycled->touched.size() == static_cast<std::size_t>(chunks) &&
        (!bands || recycled->covered.width() == scene.width))
        previous = std::move(recycled->touched);
    out.colour = std::move(recycled->colour);
    out.normal = std::move(recycled->normal);
    if (bands) out.covered = std::move(recycled->covered);
    return previous;
}

// The shading of a frame: after the depth test (depth), or band by band while it runs
// (bands given; the depth test is then returned in bands->depth).
struct InBands {
    const ScanConversion& scan;
    int rows = kRowChunk;  // of each band (depthTestInBands)
    DepthTest depth;
    double depthShare = 0.0;  // of the threads' time, spent testing (the rest shading)
};

Shading shade(const FrameLighting& lighting, const DepthTest* depth, InBands* bands,
              const ShadingExecution& execution);

// The rows shared out between the threads, from the frame's depth test.
void shadeRows(const RowShader& shader, const DepthTest& depth, const Scene& scene, bool tracked,
               int parts, std::vector<Shading>& partCounts) {
    runParts(parts, [&](int part) {
        Shading counts;  // on the thread's stack, not beside the other threads' counters
        for (int y = 0; y < scene.height; ++y) {
            if (parts > 1 && !ownsRow(y, part, parts)) continue;
            const ColumnRange columns = tracked
                                            ? depth.touched[static_cast<std::size_t>(y / kRowChunk)]
                                            : ColumnRange{0, scene.width};
            shader.row(y, depth.triangle.row(y), depth.barycentric.row(y), columns, counts);
        }
        partCounts[static_cast<std::size_t>(part)] = std::move(counts);
    });
}

// Each band as soon as the thread that tested it hands it over (in that thread's cache);
// the time each thread spends testing and shading is summed, each thread's counts and times
// on cache lines of their own.
void shadeBands(const RowShader& shader, const FrameLighting& lighting, InBands& bands, int parts,
                std::vector<Shading>& partCounts) {
    using Clock = std::chrono::steady_clock;
    struct alignas(64) PartTime {
        Clock::time_point last;
        Clock::duration testing{}, shading{};
        Shading counts;
    };
    std::vector<PartTime> times(static_cast<std::size_t>(parts));
    for (PartTime& t : times) t.last = Clock::now();
    bands.depth = depthTestInBands(
        {lighting.scene(), lighting.projection(), bands.scan}, parts, bands.rows,
        [&](const TestedBand& band) {
            const auto part = static_cast<std::size_t>(band.part);
            const Clock::time_point start = Clock::now();
            times[part].testing += start - times[part].last;
            for (int y = band.y0; y < band.y1; ++y) {
                const auto row = static_cast<std::size_t>(y - band.y0) * band.stride;
                shader.row(y, band.ids + row, band.bary ? band.bary + row : nullptr, band.columns,
                           times[part].counts);
            }
            times[part].last = Clock::now();
            times[part].shading += times[part].last - start;
        });
    Clock::duration testing{}, shading{};
    for (std::size_t part = 0; part < times.size(); ++part) {
        testing += times[part].testing;
        shading += times[part].shading;
        partCounts[part] = std::move(times[part].counts);
    }
    const double sum = std::chrono::duration<double>(testing + shading).count();
    bands.depthShare = sum > 0.0 ? std::chrono::duration<double>(testing).count() / sum : 0.5;
}

Shading shade(const FrameLighting& lighting, const DepthTest* depth, InBands* bands,
              const ShadingExecution& execution) {
    const Scene& scene = lighting.scene();
    const Conventions& conv = scene.conventions;
    Shading out;
    out.background = vec3(conv.background) * conv.colourScale;
    // Columns to work on: only those the depth test touched, and those the recycled colour
    // buffer holds something other than the background in (when both are known).
    const int chunks = (scene.height + kRowChunk - 1) / kRowChunk;
    const bool tracked = !execution.keepNormals &&
                         (bands || depth->touched.size() == static_cast<std::size_t>(chunks));
    std::vector<ColumnRange> previous =
        recycle(scene, out, execution.recycled, tracked, bands != nullptr);
    if (tracked && !bands) out.touched = depth->touched;
    // Every pixel is written below (the background where no triangle won).
    out.colour.resize(scene.width, scene.height);
    if (bands) out.covered.resize(scene.width, scene.height);
    if (execution.keepNormals)
        out.normal.resize(scene.width, scene.height);
    else
        out.normal = Image<vec3>();

    const Kernels kernels = kernelsFor(lighting);
    // Flat and Gouraud colours first, for the visible triangles and their vertices only, so
    // that the pixel loop (on several threads) only reads them.
    bool anyPerTriangle = false;
    for (const Draw& draw : scene.draws)
        anyPerTriangle = anyPerTriangle || draw.shading != ShadingModel::Phong;
    ColourTables tables;
    if (anyPerTriangle) {
        // The triangles that kept a pixel: from the depth test when it worked them out.
        std::vector<std::uint8_t> found;
        const bool known =
            !bands && depth->visible.size() == lighting.projection().triangles.size();
        if (!known) found = findVisible(lighting, depth, bands ? &bands->scan : nullptr);
        tables =
            lightTables(lighting, kernels, known ? depth->visible : found, execution.threads, out);
    }
    tables.draws.resize(lighting.projection().draws.size());

    const RowShader shader(lighting, tables, kernels, out, execution.keepNormals, tracked,
                           std::move(previous));
    const int parts = std::max(1, std::min(execution.threads, scene.height));
    std::vector<Shading> partCounts(static_cast<std::size_t>(parts));
    if (bands) {
        shadeBands(shader, lighting, *bands, parts, partCounts);
        out.touched = bands->depth.touched;
    } else {
        shadeRows(shader, *depth, scene, tracked, parts, partCounts);
    }
    for (const Shading& c : partCounts) addCounts(out, c);
    if (bands) bands->depth.covered = out.shadedPixels;
    return out;
}

}  // namespace

Shading shading(const ShadingInput& in, const ShadingExecution& execution) {
    const FrameLighting lighting(in.scene, in.view, in.normals, in.projection);
    return shade(lighting, &in.depth, nullptr, execution);
}

std::pair<DepthTest, Shading> depthTestAndShading(const FrameLighting& lighting,
                                                  const ScanConversion& scan, int threads,
                                                  int bandRows, Shading* recycled,
                                                  double& depthShare) {
    InBands bands{scan, bandRows, DepthTest{}, 0.0};
    Shading shading = shade(lighting, nullptr, &bands, {threads, false, recycled});
    depthShare = bands.depthShare;
    return {std::move(bands.depth), std::move(shading)};
}

bool shadeInBands(const Scene& scene, const Projection& projection, const ScanConversion& scan) {
    // What lighting the triangles with a fragment costs, in points lit, against the fragments
    // to test (scan conversion's count). Phong lights nothing ahead. A flat draw lights each
    // of its triangles with a fragment; a Gouraud draw each vertex of them, at most all its
    // vertices. The triangles with a fragment are those neither degenerate nor off the screen
    // (scan conversion counts them), an upper bound for each draw's.
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

}  // namespace rl::fast
