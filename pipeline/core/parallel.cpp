#include "parallel.h"

#include <array>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cstdint>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif
#if defined(__linux__)
#include <sched.h>
#include <unistd.h>
#endif

namespace rl {

namespace {

using Clock = std::chrono::steady_clock;

// How long a thread that has nothing to do keeps looking for work before it sleeps. A frame's
// stages follow each other within microseconds; a sleeping core of a virtual machine can take
// longer than a whole small stage to wake.
constexpr auto kAwake = std::chrono::microseconds(500);
// How long a caller waiting for the parts of a job it handed out keeps looking before it
// sleeps: longer, as the parts are on their way. A caller that slept while a kept thread moved
// to another core (leaveCore) would be woken on that thread's new core, and the two would take
// turns on it again (docs/performance.md).
constexpr auto kAwakeForParts = std::chrono::milliseconds(20);

// The core the calling thread runs on, or -1 where that is not known.
int currentCore() {
#if defined(__linux__)
    return sched_getcpu();
#else
    return -1;
#endif
}

inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#else
    std::this_thread::yield();
#endif
}

// Whether the calling thread runs on one of the cores in cores[0 .. count) (-1: not known).
bool onCoreOf(const std::atomic<int>* cores, int count) {
    const int core = currentCore();
    if (core < 0) return false;
    for (int k = 0; k < count; ++k)
        if (cores[k].load(std::memory_order_relaxed) == core) return true;
    return false;
}

// Waits until value differs from old: looks for `awake`, then sleeps until notified. While
// it looks, it gives its core away (yield) between looks only when a thread it waits for was
// last seen on the same core (cores[0 .. count), checked every 64 looks): that thread then
// runs at once instead of when the waiter's time slice ends. On a core of its own it only
// pauses: yielding there let the scheduler keep it from the next job (docs/performance.md).
template <typename T>
T waitWhileEqual(const std::atomic<T>& value, T old, Clock::duration awake,
                 const std::atomic<int>* cores, int count) {
    const auto deadline = Clock::now() + awake;
    bool shared = false;
    for (int spins = 0;; ++spins) {
        const T now = value.load(std::memory_order_acquire);
        if (now != old) return now;
        if ((spins & 63) == 63) {
            if (Clock::now() > deadline) break;
            shared = onCoreOf(cores, count);
        }
        if (shared)
            std::this_thread::yield();
        else
            relax();
    }
    for (;;) {
        value.wait(old, std::memory_order_acquire);
        const T now = value.load(std::memory_order_acquire);
        if (now != old) return now;
    }
}

// Moves the calling thread off `core` onto an allowed core none of `taken` runs on, if there
// is one, and leaves it free to be moved again: held to the one core for a moment, then given
// back the cores it was allowed. A virtual machine's idle core can look busy to the scheduler
// (its virtual processor stopped), so a kept thread woken by the caller often wakes on the
// caller's own core and stays there for many frames: the two threads then take turns on one
// core (docs/performance.md).
void leaveCore([[maybe_unused]] int core, [[maybe_unused]] const std::atomic<int>* taken,
               [[maybe_unused]] int takenCount) {
#if defined(__linux__)
    cpu_set_t allowed;
    if (sched_getaffinity(0, sizeof allowed, &allowed) != 0) return;
    for (int c = 0; c < CPU_SETSIZE; ++c) {
        if (c == core || !CPU_ISSET(c, &allowed)) continue;
        bool free = true;
        for (int k = 0; k < takenCount && free; ++k)
            free = taken[k].load(std::memory_order_relaxed) != c;
        if (!free) continue;
        cpu_set_t one;
        CPU_ZERO(&one);
        CPU_SET(c, &one);
        if (sched_setaffinity(0, sizeof one, &one) == 0)  // moves this thread to c now
            sched_setaffinity(0, sizeof allowed, &allowed);
        return;
    }
#endif
}

// The kept threads. A job is published by bumping the generation; every kept thread (needed
// or not) acknowledges it by counting `remaining` down, so none can still be reading one
// job's description when the next is written.
class Workers {
public:
    Workers() {
        for (auto& core : m_cores) core.store(-1, std::memory_order_relaxed);
    }

    // Runs the job on the kept threads; false when another caller is using them.
    bool run(int parts, void (*fn)(const void*, int), const void* context) {
        if (m_busy.exchange(true, std::memory_order_acquire)) return false;
        while (static_cast<int>(m_threads.size()) < parts - 1) {
            const int part = static_cast<int>(m_threads.size()) + 1;
            const std::uint64_t seen = m_generation.load(std::memory_order_relaxed);
            m_threads.emplace_back([this, part, seen] { work(part, seen); });
        }
        m_fn = fn;
        m_context = context;
        m_parts = parts;
        m_cores[0].store(currentCore(), std::memory_order_relaxed);
        m_remaining.store(static_cast<int>(m_threads.size()), std::memory_order_relaxed);
        m_generation.fetch_add(1, std::memory_order_release);
        m_generation.notify_all();
        fn(context, 0);
        for (int left = m_remaining.load(std::memory_order_acquire); left != 0;
             left = m_remaining.load(std::memory_order_acquire))
            waitWhileEqual(m_remaining, left, kAwakeForParts, m_cores.data() + 1, parts - 1);
        m_busy.store(false, std::memory_order_release);
        return true;
    }

private:
    void work(int part, std::uint64_t seen) {
        for (;;) {
            seen = waitWhileEqual(m_generation, seen, kAwake, m_cores.data(), 1);
            const int parts = m_parts;  // read before the job is acknowledged
            if (part < parts) {
                m_cores[part].store(currentCore(), std::memory_order_relaxed);
                m_fn(m_context, part);
            }
            if (m_remaining.fetch_sub(1, std::memory_order_acq_rel) == 1) m_remaining.notify_one();
            // After acknowledging: the caller does not wait while this thread moves.
            if (part < parts) spread(part, parts);
        }
    }

    // A kept thread that finds itself on the core of the caller or of a kept thread before it
    // moves to a core none of them is on (leaveCore).
    void spread(int part, int parts) {
        const int core = currentCore();
        if (core < 0) return;
        m_cores[part].store(core, std::memory_order_relaxed);
        for (int k = 0; k < part; ++k) {
            if (m_cores[k].load(std::memory_order_relaxed) != core) continue;
            leaveCore(core, m_cores.data(), parts);
            m_cores[part].store(currentCore(), std::memory_order_relaxed);
            return;
        }
    }

    std::atomic<bool> m_busy{false};
    std::atomic<std::uint64_t> m_generation{0};
    std::atomic<int> m_remaining{0};
    // The job, written before the generation is bumped and read after it is seen.
    void (*m_fn)(const void*, int) = nullptr;
    const void* m_context = nullptr;
    int m_parts = 0;
    // The core each kept thread was on when it started its last part and after it, and
    // m_cores[0] the caller's when it published the job; -1 where not known.
    std::array<std::atomic<int>, kMaxThreads> m_cores{};
    // Never joined: the threads live as long as the program (the object is never destroyed).
    std::vector<std::thread> m_threads;
};

// The first line of a file, empty when it cannot be read.
std::string firstLine(const std::string& path) {
    std::ifstream file(path);
    std::string line;
    std::getline(file, line);
    return line;
}

// The first processor's L2 cache: its size in bytes (0 when not known) and how many
// processors share it.
struct L2Cache {
    std::size_t bytes = 0;
    int sharedBy = 1;
};

L2Cache firstL2() {
    L2Cache l2;
#if defined(__linux__)
    const std::string base = "/sys/devices/system/cpu/cpu0/cache/index";
    for (int k = 0; k < 8; ++k) {
        const std::string dir = base + std::to_string(k) + "/";
        if (firstLine(dir + "level") != "2" || firstLine(dir + "type") == "Instruction") continue;
        l2.bytes = cacheBytes(firstLine(dir + "size"));
        l2.sharedBy = std::max(1, processorsInList(firstLine(dir + "shared_cpu_list")));
        break;
    }
#if defined(_SC_LEVEL2_CACHE_SIZE)
    if (l2.bytes == 0)
        l2.bytes = static_cast<std::size_t>(std::max(0L, sysconf(_SC_LEVEL2_CACHE_SIZE)));
#endif
#endif
    return l2;
}

}  // namespace

int processorsInList(std::string_view list) {
    // Ranges "a" or "a-b" (a <= b), separated by commas.
    long count = 0;
    const char* at = list.data();
    const char* const end = list.data() + list.size();
    while (at < end) {
        long first = 0, last = 0;
        std::from_chars_result read = std::from_chars(at, end, first);
        if (read.ec != std::errc() || first < 0) return 0;
        last = first;
        if (read.ptr < end && *read.ptr == '-') {
            read = std::from_chars(read.ptr + 1, end, last);
            if (read.ec != std::errc() || last < first) return 0;
        }
        count += last - first + 1;
        if (count > 1 << 20) return 0;
        if (read.ptr == end) break;
        if (*read.ptr != ',' || read.ptr + 1 == end) return 0;
        at = read.ptr + 1;
    }
    return static_cast<int>(count);
}

std::size_t cacheBytes(std::string_view size) {
    // A whole number, then K, M or nothing.
    std::size_t bytes = 0;
    const char* const end = size.data() + size.size();
    const auto [next, error] = std::from_chars(size.data(), end, bytes);
    if (error != std::errc()) return 0;
    const std::string_view unit(next, static_cast<std::size_t>(end - next));
    const std::size_t scale = unit.empty() ? 1 : unit == "K" ? 1024 : unit == "M" ? 1 << 20 : 0;
    if (scale == 0 || bytes > (std::size_t(1) << 40) / scale) return 0;
    return bytes * scale;
}

std::size_t l2CachePerThread(int threads) {
    static const L2Cache l2 = firstL2();
    return l2.bytes / static_cast<std::size_t>(std::clamp(threads, 1, l2.sharedBy));
}

void runPartsOnWorkers(int parts, void (*fn)(const void* context, int part), const void* context) {
    static Workers* const workers = new Workers;  // kept for the program's life
    if (workers->run(parts, fn, context)) return;
    // The kept threads are busy (another render, or a part that runs parts of its own).
    std::vector<std::thread> threads;
    threads.reserve(static_cast<std::size_t>(parts - 1));
    for (int part = 1; part < parts; ++part)
        threads.emplace_back([fn, context, part] { fn(context, part); });
    fn(context, 0);
    for (auto& thread : threads) thread.join();
}

}  // namespace rl
