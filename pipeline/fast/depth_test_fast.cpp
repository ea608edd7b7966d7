#include "depth_test_fast.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <memory>
#include <optional>

#include "pipeline/core/multiversion.h"
#include "pipeline/core/parallel.h"
#include "pipeline/fast/lanes.h"
#include "pipeline/stages/probe.h"

namespace rl::fast {

namespace {

using namespace lanes;

// (beta, gamma) pairs of the first and the second half of the lanes, and each lane's pass
// mask twice, for the same pairs.
RL_LANES void pairs(const LaneTypes<8>::Floats& beta, const LaneTypes<8>::Floats& gamma,
                    LaneTypes<8>::Floats& first, LaneTypes<8>::Floats& second) {
    first = __builtin_shufflevector(beta, gamma, 0, 8, 1, 9, 2, 10, 3, 11);
    second = __builtin_shufflevector(beta, gamma, 4, 12, 5, 13, 6, 14, 7, 15);
}
RL_LANES void pairs(const LaneTypes<4>::Floats& beta, const LaneTypes<4>::Floats& gamma,
                    LaneTypes<4>::Floats& first, LaneTypes<4>::Floats& second) {
    first = __builtin_shufflevector(beta, gamma, 0, 4, 1, 5);
    second = __builtin_shufflevector(beta, gamma, 2, 6, 3, 7);
}
RL_LANES void pairMasks(const LaneTypes<8>::Ints& pass, LaneTypes<8>::Ints& first,
                        LaneTypes<8>::Ints& second) {
    first = __builtin_shufflevector(pass, pass, 0, 0, 1, 1, 2, 2, 3, 3);
    second = __builtin_shufflevector(pass, pass, 4, 4, 5, 5, 6, 6, 7, 7);
}
RL_LANES void pairMasks(const LaneTypes<4>::Ints& pass, LaneTypes<4>::Ints& first,
                        LaneTypes<4>::Ints& second) {
    first = __builtin_shufflevector(pass, pass, 0, 0, 1, 1);
    second = __builtin_shufflevector(pass, pass, 2, 2, 3, 3);
}

// testSpanPixels (stages/depth_test.h) for a span when no depth range clips, N pixels at a
// time (kernelLanes: eight or four) with the compiler's vector extensions (GCC and Clang). A
// group that passes whole is written without reading what was stored (barycentrics only when
// baryRow is given), one that fails whole is not written, and a mixed one is blended lane by
// lane and stored back whole. The operations are TrianglePlane::fragment's, lane by lane, so
// the bits are the same. Built for each of RL_MULTIVERSION's machines, the best one chosen
// when the program starts. Returns the number of fragments that passed.
template <int N>
RL_LANES std::size_t spanLanes(float* depthRow, std::uint32_t* idRow, float* baryRow,
                               std::int32_t n, const TrianglePlane& plane, double beta0,
                               double gamma0, std::uint32_t id, bool winsOnTie, bool painted) {
    using Doubles = typename LaneTypes<N>::Doubles;
    using Floats = typename LaneTypes<N>::Floats;
    using Ints = typename LaneTypes<N>::Ints;
    const double betaDx = plane.betaDx, gammaDx = plane.gammaDx;
    const float z0 = plane.z0, dz1 = plane.dz1, dz2 = plane.dz2;
    const bool reciprocal = plane.reciprocal;
    std::int32_t i = 0;
    const Ints tie = winsOnTie ? Ints{} - 1 : Ints{};
    const Ints always = painted ? Ints{} - 1 : Ints{};  // the painter's: no depth test
    const auto ids = static_cast<std::int32_t>(id);
    Doubles step;
    for (int lane = 0; lane < N; ++lane) step[lane] = lane;
    Ints passes = {};  // minus the number of passes, per lane
    for (; i + N <= n; i += N) {
        const Doubles index = double(i) + step;
        const Floats beta = __builtin_convertvector(beta0 + index * betaDx, Floats);
        const Floats gamma = __builtin_convertvector(gamma0 + index * gammaDx, Floats);
        Floats z = (z0 + beta * dz1) + gamma * dz2;
        if (reciprocal) z = 1.0f / z;
        Floats stored;
        std::memcpy(&stored, depthRow + i, sizeof stored);
        const Ints pass = (z < stored) | (tie & (z == stored)) | always;
        passes += pass;
        Floats interleaved0, interleaved1;
        pairs(beta, gamma, interleaved0, interleaved1);
        Words2 both, either;
        foldMask(pass, both, either);
        if ((both[0] & both[1]) == ~std::uint64_t{0}) {
            // Every lane passes (no overdraw here): the stored values are not needed.
            const Ints triangle = Ints{} + ids;
            std::memcpy(depthRow + i, &z, sizeof z);
            std::memcpy(idRow + i, &triangle, sizeof triangle);
            if (baryRow) {
                std::memcpy(baryRow + 2 * i, &interleaved0, sizeof interleaved0);
                std::memcpy(baryRow + 2 * i + N, &interleaved1, sizeof interleaved1);
            }
            continue;
        }
        if ((either[0] | either[1]) == 0) continue;  // nothing to write
        Ints storedId;
        std::memcpy(&storedId, idRow + i, sizeof storedId);
        const Floats depth = select(pass, z, stored);
        const Ints triangle = (pass & ids) | (~pass & storedId);
        std::memcpy(depthRow + i, &depth, sizeof depth);
        std::memcpy(idRow + i, &triangle, sizeof triangle);
        if (!baryRow) continue;
        Floats stored0, stored1;
        std::memcpy(&stored0, baryRow + 2 * i, sizeof stored0);
        std::memcpy(&stored1, baryRow + 2 * i + N, sizeof stored1);
        Ints mask0, mask1;
        pairMasks(pass, mask0, mask1);
        const Floats bary0 = select(mask0, interleaved0, stored0);
        const Floats bary1 = select(mask1, interleaved1, stored1);
        std::memcpy(baryRow + 2 * i, &bary0, sizeof bary0);
        std::memcpy(baryRow + 2 * i + N, &bary1, sizeof bary1);
    }
    std::size_t passed = 0;
    for (int lane = 0; lane < N; ++lane) passed += static_cast<std::size_t>(-passes[lane]);
    for (; i < n; ++i) {  // the last pixels, one at a time as the stage tests them
        const FragmentDepth f = plane.fragment(beta0, gamma0, i);
        if (painted || f.depth < depthRow[i] || (winsOnTie && f.depth == depthRow[i])) {
            depthRow[i] = f.depth;
            idRow[i] = id;
            if (baryRow) {
                baryRow[2 * i] = f.beta;
                baryRow[2 * i + 1] = f.gamma;
            }
            ++passed;
        }
    }
    return passed;
}

RL_MULTIVERSION std::size_t spanKernel(float* depthRow, std::uint32_t* idRow, float* baryRow,
                                       std::int32_t n, const TrianglePlane& plane, double beta0,
                                       double gamma0, std::uint32_t id, bool winsOnTie,
                                       bool painted) {
    if (kernelLanes() == 8)
        return spanLanes<8>(depthRow, idRow, baryRow, n, plane, beta0, gamma0, id, winsOnTie,
                            painted);
    return spanLanes<4>(depthRow, idRow, baryRow, n, plane, beta0, gamma0, id, winsOnTie, painted);
}

// n copies of value from row on: the clear of a row's depths, with the widest stores the
// machine has (std::fill_n is built for the baseline's 16-byte ones).
RL_MULTIVERSION void fillFloats(float* row, std::size_t n, float value) {
    for (std::size_t i = 0; i < n; ++i) row[i] = value;
}

// The depth test of one span: the vector kernel, or the stage's own loop where the depth
// range clips (seed 001's per-pixel clipping, which the kernel does not do).
void testSpanOnLanes(const Scene& scene, const TrianglePlane& plane, std::uint32_t id,
                  const Span& span, const DepthRows& rows, bool painted, DepthCounts& counts) {
    if (scene.conventions.depthRangeClip) {
        NullProbe none;
        testSpanPixels(scene, plane, id, span, rows, painted, counts, none);
        return;
    }
    double beta0 = 0.0, gamma0 = 0.0;
    plane.spanStart(span.xBegin, span.y, scene.rules.sampleOffset, beta0, gamma0);
    const std::int32_t n = span.xEnd - span.xBegin;
    counts.fragments += static_cast<std::size_t>(n);
    counts.passed += spanKernel(rows.depth + span.xBegin, rows.ids + span.xBegin,
                              rows.bary ? &rows.bary[span.xBegin].x : nullptr, n, plane, beta0,
                              gamma0, id, scene.conventions.depthWinsOnTie, painted);
}

// Every span, sorted by chunk of rows (parallel.h) and within a chunk in triangle order: the
// spans of chunk c are entries[first[c] .. first[c + 1]).
struct Entry {
    std::uint32_t triangle;
    Span span;  // a copy: the chunk's spans are then read in order, not gathered
};
struct SpansByChunk {
    std::vector<Entry> entries;
    std::vector<std::uint32_t> first;
};

// A counting sort shared out between the threads: each takes a contiguous range of
// triangles, counts its spans per chunk, and writes them where the ranges before its own
// end, so that triangle order is kept within every chunk.
SpansByChunk sortByChunk(const ScanConversion& scan, int chunks, int threads) {
    const std::size_t triangles = scan.triangleCount();
    // Below some thousands of spans, starting threads costs more than it saves.
    const int parts = scan.spans.size() < 32768 ? 1 : std::max(1, threads);
    const auto chunkCount = static_cast<std::size_t>(chunks);
    std::vector<std::vector<std::uint32_t>> next(static_cast<std::size_t>(parts));
    runParts(parts, [&](int part) {
        std::vector<std::uint32_t> counts(chunkCount, 0);  // on the thread's own
        const std::uint32_t begin = scan.spanStart[rangeBegin(triangles, part, parts)];
        const std::uint32_t end = scan.spanStart[rangeBegin(triangles, part + 1, parts)];
        for (std::uint32_t k = begin; k < end; ++k)
            ++counts[static_cast<std::size_t>(scan.spans[k].y / kRowChunk)];
        next[static_cast<std::size_t>(part)] = std::move(counts);
    });
    SpansByChunk out;
    out.first.assign(chunkCount + 1, 0);
    std::uint32_t at = 0;
    for (std::size_t c = 0; c < chunkCount; ++c) {
        out.first[c] = at;
        for (auto& counts : next) {  // counts become where each range's spans go
            const std::uint32_t n = counts[c];
            counts[c] = at;
            at += n;
        }
    }
    out.first[chunkCount] = at;
    out.entries.resize(at);
    runParts(parts, [&](int part) {
        std::vector<std::uint32_t>& where = next[static_cast<std::size_t>(part)];
        for (std::size_t t = rangeBegin(triangles, part, parts),
                         last = rangeBegin(triangles, part + 1, parts);
             t < last; ++t) {
            for (std::uint32_t k = scan.spanStart[t]; k < scan.spanStart[t + 1]; ++k) {
                const Span& span = scan.spans[k];
                const auto c = static_cast<std::size_t>(span.y / kRowChunk);
                out.entries[where[c]++] = {static_cast<std::uint32_t>(t), span};
            }
        }
    });
    return out;
}

// Row dy of the rows from `first` on, width apart.
DepthRows rowOf(const DepthRows& first, int dy, std::size_t width) {
    const std::size_t offset = static_cast<std::size_t>(dy) * width;
    return DepthRows{first.depth + offset, first.ids + offset,
                     first.bary ? first.bary + offset : nullptr};
}

// Clears `rows` rows from `first` on: depths to `clear` in depthDirty's columns, ids to none
// in idDirty's (and barycentrics to 0 there when zeroBary).
void clearRows(const DepthRows& first, int rows, std::size_t width, ColumnRange depthDirty,
               ColumnRange idDirty, float clear, bool zeroBary) {
    for (int dy = 0; dy < rows; ++dy) {
        const DepthRows row = rowOf(first, dy, width);
        if (depthDirty.begin < depthDirty.end)
            fillFloats(row.depth + depthDirty.begin,
                       static_cast<std::size_t>(depthDirty.end - depthDirty.begin), clear);
        if (idDirty.begin >= idDirty.end) continue;
        const auto n = static_cast<std::size_t>(idDirty.end - idDirty.begin);
        static_assert(kNoTriangle == ~std::uint32_t{0}, "cleared byte by byte");
        std::memset(row.ids + idDirty.begin, 0xff, n * sizeof(std::uint32_t));
        // Barycentrics are read only where a triangle won, so any value does; but zeroing
        // the frame's brings their lines into the cache ahead of the spans' stores.
        if (zeroBary)
            std::memset(static_cast<void*>(row.bary + idDirty.begin), 0, n * sizeof(vec2));
    }
}

// The DDA's attributes of triangle t's span on row y (its spans run down the rows, one a row).
const DdaSpan& ddaSpanOfRow(const ScanConversion& scan, std::uint32_t t, std::int32_t y) {
    const Span* first = scan.spans.data() + scan.spanStart[t];
    const Span* last = scan.spans.data() + scan.spanStart[t + 1];
    const Span* span =
        std::lower_bound(first, last, y, [](const Span& s, std::int32_t row) { return s.y < row; });
    return scan.ddaSpans[static_cast<std::size_t>(span - scan.spans.data())];
}

// The spans among [begin, end) (a chunk's, in triangle order) whose row is in [y0, y1),
// tested into the rows from `first` (row y0) on. The DDA's spans (hw2 rules) take the
// stage's own loop: their attributes are stepped one addition a pixel.
void testRows(const Scene& scene, const DepthTestInput& in, const Entry* begin, const Entry* end,
              int y0, int y1, const DepthRows& first, std::size_t width, bool painted,
              DepthCounts& counts) {
    std::uint32_t current = kNoTriangle;
    std::optional<TrianglePlane> plane;
    const bool dda = scene.rules.scan == RasterRules::Scan::Dda;
    for (const Entry* entry = begin; entry != end; ++entry) {
        const int y = entry->span.y;
        if (y < y0 || y >= y1) continue;
        const DepthRows rows = rowOf(first, y - y0, width);
        if (dda) {
            NullProbe none;
            testDdaSpanPixels(scene, ddaSpanOfRow(in.scan, entry->triangle, y), entry->triangle,
                              entry->span, rows, painted, counts, none);
            continue;
        }
        if (entry->triangle != current) {
            current = entry->triangle;
            plane.emplace(in.projection, current, perspectiveDepth(scene));
        }
        testSpanOnLanes(scene, *plane, current, entry->span, rows, painted, counts);
    }
}

// Marks the triangles that kept a pixel of rows [y0, y1), a run of one id at a time. Two
// threads may mark the same triangle: relaxed atomic stores of the same value.
void markVisible(DepthTest& out, int y0, int y1, ColumnRange touched) {
    for (int y = y0; y < y1; ++y) {
        const std::uint32_t* ids = out.triangle.row(y);
        for (int x = touched.begin; x < touched.end;) {
            const std::uint32_t t = ids[x];
            if (t != kNoTriangle)
                std::atomic_ref<std::uint8_t>(out.visible[t]).store(1, std::memory_order_relaxed);
            x = runEnd(ids, x + 1, touched.end, t);
        }
    }
}

// The rows one thread owns, chunk by chunk (parallel.h): the chunk's buffers are cleared,
// then its spans tested in triangle order, so that each chunk's pixels stay in the cache
// while its triangles are drawn. Every pixel sees the same fragments in the same order as
// in the stage, so the buffers are the same bits. When the z-buffer is not kept
// (DepthTest::depthKept), the depths are in a band of the thread's own, cleared where the
// chunk's spans fall: kRowChunk rows (61 KB at 1920 pixels wide), in L2. With a sink
// (depthTestInBands) the ids and barycentrics are in the band too, of bandRows rows: each
// chunk is tested a band at a time, each band handed to the sink once tested, before the
// next one overwrites it.
DepthCounts testChunks(const Scene& scene, const DepthTestInput& in, const SpansByChunk& sorted,
                       DepthTest& out, int part, int parts,
                       const std::vector<ColumnRange>& previous, const BandSink* sink, int bandRows,
                       std::atomic<int>& nextChunk) {
    DepthCounts counts;
    const int chunks = (scene.height + kRowChunk - 1) / kRowChunk;
    const Entry* entries = sorted.entries.data();
    const std::vector<std::uint32_t>& start = sorted.first;
    const auto width = static_cast<std::size_t>(scene.width);
    const int rows = sink ? bandRows : kRowChunk;
    const std::size_t bandPixels = static_cast<std::size_t>(rows) * width;
    // The thread's band, cleared below where it is used.
    std::unique_ptr<float[]> depthBand;
    std::unique_ptr<std::uint32_t[]> idBand;
    std::unique_ptr<vec2[]> baryBand;
    if (!out.depthKept) depthBand = std::make_unique_for_overwrite<float[]>(bandPixels);
    if (sink) {
        idBand = std::make_unique_for_overwrite<std::uint32_t[]>(bandPixels);
        if (out.barycentricsKept) baryBand = std::make_unique_for_overwrite<vec2[]>(bandPixels);
    }
    // The first of the rows from y0 on, in each buffer; the rows follow it, width apart.
    const auto firstRow = [&](int y0) {
        DepthRows first;
        first.depth = out.depthKept ? out.depth.row(y0) : depthBand.get();
        first.ids = sink ? idBand.get() : out.triangle.row(y0);
        first.bary = !out.barycentricsKept ? nullptr
                     : sink                ? baryBand.get()
                                           : out.barycentric.row(y0);
        return first;
    };
    // In bands, each chunk goes to the next thread free to take it (nextChunk): a thread that
    // starts late (a virtual machine's core can take milliseconds to wake) holds nothing up,
    // the others take its share. Tested and shaded by one thread, a chunk is the same bits
    // whichever thread that is. Otherwise chunk c is thread c mod parts's, as in shading.
    const auto nextOf = [&](int c) {
        return sink ? nextChunk.fetch_add(1, std::memory_order_relaxed) : c + parts;
    };
    for (int c = sink ? nextOf(0) : part; c < chunks; c = nextOf(c)) {
        const int y0 = c * kRowChunk;
        const int y1 = std::min(scene.height, y0 + kRowChunk);
        ColumnRange touched{scene.width, 0};
        for (std::uint32_t e = start[c]; e < start[c + 1]; ++e) {
            touched.begin = std::min(touched.begin, entries[e].span.xBegin);
            touched.end = std::max(touched.end, entries[e].span.xEnd);
        }
        if (touched.begin >= touched.end) touched = ColumnRange{};
        out.touched[static_cast<std::size_t>(c)] = touched;
        // Clear what the previous frame wrote (everything when that is not known); a band,
        // where this chunk's spans fall.
        const ColumnRange dirty =
            previous.empty() ? ColumnRange{0, scene.width} : previous[static_cast<std::size_t>(c)];
        const ColumnRange depthDirty = out.depthKept ? dirty : touched;
        const ColumnRange idDirty = sink ? touched : dirty;
        for (int b0 = y0; b0 < y1; b0 += rows) {
            const int b1 = std::min(y1, b0 + rows);
            const DepthRows first = firstRow(b0);
            clearRows(first, b1 - b0, width, depthDirty, idDirty, scene.conventions.depthClear,
                      first.bary && !sink);
            testRows(scene, in, entries + start[c], entries + start[c + 1], b0, b1, first,
                     width, out.painted, counts);
            if (sink) (*sink)(TestedBand{part, b0, b1, touched, first.ids, first.bary, width});
        }
        if (!sink && !out.visible.empty()) markVisible(out, y0, y1, touched);
    }
    return counts;
}

}  // namespace

// Sixteen ids at a time (their differences from t ORed together, in four vectors of four:
// GCC's AVX2 and baseline kernels took one vector of sixteen through the stack), then one at
// a time within the first sixteen that differ.
RL_MULTIVERSION int runEnd(const std::uint32_t* ids, int from, int limit, std::uint32_t t) {
    typedef std::uint32_t Ids __attribute__((vector_size(16)));
    const Ids same = Ids{} + t;
    int end = from;
    while (end + 16 <= limit) {
        Ids v[4];
        std::memcpy(v, ids + end, sizeof v);
        const Words2 differ = reinterpret_cast<Words2>(((v[0] ^ same) | (v[1] ^ same)) |
                                                       ((v[2] ^ same) | (v[3] ^ same)));
        if (differ[0] | differ[1]) break;
        end += 16;
    }
    while (end < limit && ids[end] == t) ++end;
    return end;
}

namespace {

// The depth test chunk by chunk on `threads` threads (testChunks); when a sink is given,
// each band of bandRowsFor(bandRows) rows is handed to it.
DepthTest test(const DepthTestInput& in, int threads, DepthTest* recycled, bool keepDepth,
               const BandSink* sink, int bandRows) {
    const Scene& scene = in.scene;
    DepthTest out;
    const float clear = scene.conventions.depthClear;
    const int chunks = (scene.height + kRowChunk - 1) / kRowChunk;
    out.depthKept = keepDepth && !sink;
    out.fragmentsKept = !sink;
    std::vector<ColumnRange> previous;  // what the recycled buffers hold besides the clear value
    if (recycled && out.fragmentsKept) {
        // When this frame keeps its z-buffer and the recycled one did not, nothing in it is
        // known: everything is cleared.
        if (recycled->triangle.width() == scene.width &&
            recycled->triangle.height() == scene.height && recycled->clearedTo == clear &&
            (recycled->depthKept || !out.depthKept) &&
            recycled->touched.size() == static_cast<std::size_t>(chunks))
            previous = std::move(recycled->touched);
        if (out.depthKept) out.depth = std::move(recycled->depth);
        out.triangle = std::move(recycled->triangle);
        out.barycentric = std::move(recycled->barycentric);
        out.visible = std::move(recycled->visible);
    }
    out.clearedTo = clear;
    out.painted = paintersAlgorithm(scene);
    // Flat shading reads no barycentrics (one colour per triangle): when every draw is flat
    // they are not written.
    out.barycentricsKept = scene.draws.empty();
    bool perTriangle = false;
    for (const Draw& draw : scene.draws) {
        out.barycentricsKept = out.barycentricsKept || !litPerTriangle(draw.shading);
        perTriangle = perTriangle || draw.shading != ShadingModel::Phong;
    }
    // Each thread clears its own rows (testChunks).
    if (out.depthKept) out.depth.resize(scene.width, scene.height);
    if (out.fragmentsKept) {
        out.triangle.resize(scene.width, scene.height);
        out.barycentric.resize(scene.width, scene.height);
    }
    out.touched.assign(static_cast<std::size_t>(chunks), ColumnRange{});
    if (perTriangle && !sink)
        out.visible.assign(in.projection.triangles.size(), 0);
    else
        out.visible.clear();
    const int parts = std::max(1, std::min(threads, scene.height));
    std::vector<DepthCounts> counts(static_cast<std::size_t>(parts));
    const SpansByChunk sorted = sortByChunk(in.scan, chunks, threads);
    std::atomic<int> nextChunk{0};
    runParts(parts, [&](int part) {
        counts[static_cast<std::size_t>(part)] =
            testChunks(scene, in, sorted, out, part, parts, previous, sink,
                       bandRowsFor(bandRows), nextChunk);
    });
    for (const DepthCounts& c : counts) {
        out.fragments += c.fragments;
        out.passed += c.passed;
        out.outsideDepthRange += c.outsideDepthRange;
    }
    out.rejected = out.fragments - out.passed - out.outsideDepthRange;
    return out;
}

}  // namespace

void testSpan(const Scene& scene, const TrianglePlane& plane, std::uint32_t id, const Span& span,
              const DepthRows& rows, bool painted, DepthCounts& counts) {
    testSpanOnLanes(scene, plane, id, span, rows, painted, counts);
}

DepthTest depthTest(const DepthTestInput& in, int threads, DepthTest* recycled, bool keepDepth) {
    return test(in, threads, recycled, keepDepth, nullptr, kRowChunk);
}

DepthTest depthTestInBands(const DepthTestInput& in, int threads, int bandRows,
                           const BandSink& sink) {
    return test(in, threads, nullptr, false, &sink, bandRows);
}

}  // namespace rl::fast
