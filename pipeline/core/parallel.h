// Running a stage on several threads: the image's rows are dealt out in chunks of 8, chunk
// k to thread k mod n, so that every thread gets a share of the busy middle rows and the
// empty ones alike. Each pixel belongs to one thread, which handles it exactly as a single
// thread would, in the same triangle order: the image is the same, bit for bit, for any
// number of threads.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string_view>
#include <thread>

namespace rl {

inline constexpr int kMaxThreads = 256;

// 0 means one thread per core; at most kMaxThreads.
inline int resolveThreads(int requested) {
    if (requested > 0) return std::min(requested, kMaxThreads);
    const unsigned cores = std::thread::hardware_concurrency();
    return cores > 0 ? std::min(static_cast<int>(cores), kMaxThreads) : 1;
}

inline constexpr int kRowChunk = 8;

// The rows of the bands a chunk is tested and shaded in (fast::depthTestInBands) for a
// request of `requested`: 1 to kRowChunk, and kRowChunk for 0 or less.
inline int bandRowsFor(int requested) {
    return requested > 0 ? std::min(requested, kRowChunk) : kRowChunk;
}

// The bytes of L2 cache each of `threads` threads has, at worst: the first processor's L2
// (from sysfs), divided by the threads that can share it, min(threads, the processors that
// share it). A virtual machine may not say that its processors share one core. 0 when not
// known.
std::size_t l2CachePerThread(int threads);
// What sysfs says of a cache, read: the processors in a list such as "0-1,4" (0 when it is
// not one), and a size such as "512K" in bytes (0 when it is not one).
int processorsInList(std::string_view list);
std::size_t cacheBytes(std::string_view size);

// Whether row y belongs to thread `part` of `parts`.
inline bool ownsRow(int y, int part, int parts) {
    return (y / kRowChunk) % parts == part;
}

// Runs fn(context, part) for part = 1 .. parts - 1 on other threads while the caller runs
// part 0 (fn(context, 0)), and returns when every part has. The other threads are kept from
// call to call (parallel.cpp): starting threads for each stage of each frame cost more than
// some stages themselves, and a thread that has just finished waits a little, awake, for
// the next stage before it sleeps. Calls from several threads at once are allowed: one
// that finds the kept threads busy starts threads of its own.
void runPartsOnWorkers(int parts, void (*fn)(const void* context, int part), const void* context);

// Runs body(part) for part = 0 .. parts - 1, part 0 on the calling thread.
template <typename Body>
void runParts(int parts, const Body& body) {
    if (parts <= 1) {
        body(0);
        return;
    }
    runPartsOnWorkers(
        parts, [](const void* context, int part) { (*static_cast<const Body*>(context))(part); },
        &body);
}

// Splits [0, count) into `parts` contiguous ranges; range k is [begin(k), begin(k + 1)).
inline std::size_t rangeBegin(std::size_t count, int part, int parts) {
    return count * static_cast<std::size_t>(part) / static_cast<std::size_t>(parts);
}

}  // namespace rl
