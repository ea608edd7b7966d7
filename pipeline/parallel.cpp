#include "parallel.h"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace rl {

namespace {

using Clock = std::chrono::steady_clock;

// How long a thread that has nothing to do keeps looking for work before it sleeps. A frame's
// stages follow each other within microseconds; a sleeping core of a virtual machine can take
// longer than a whole small stage to wake.
constexpr auto kAwake = std::chrono::microseconds(500);

// Spins that only pause before the waiting thread starts giving its core away.
constexpr int kPauseSpins = 64;

inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_pause();
#else
    std::this_thread::yield();
#endif
}

// Waits until value differs from old: looks for kAwake, then sleeps until notified. After a
// few spins the look gives the core away (yield) between looks: when the thread it waits for
// shares its core (the machine is busy, or a virtual machine's other core is stalled), that
// thread runs at once instead of when the waiter's time slice ends. On a busy core the pause
// alone made two threads slower than one: 5.3 ms a frame against 3.2 with the yield
// (full-screen Gouraud, both threads held to one core).
template <typename T>
T waitWhileEqual(const std::atomic<T>& value, T old) {
    const auto deadline = Clock::now() + kAwake;
    for (int spins = 0;; ++spins) {
        const T now = value.load(std::memory_order_acquire);
        if (now != old) return now;
        if ((spins & 63) == 63 && Clock::now() > deadline) break;
        if (spins < kPauseSpins)
            relax();
        else
            std::this_thread::yield();
    }
    for (;;) {
        value.wait(old, std::memory_order_acquire);
        const T now = value.load(std::memory_order_acquire);
        if (now != old) return now;
    }
}

// The kept threads. A job is published by bumping the generation; every kept thread (needed
// or not) acknowledges it by counting `remaining` down, so none can still be reading one
// job's description when the next is written.
class Workers {
public:
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
        m_remaining.store(static_cast<int>(m_threads.size()), std::memory_order_relaxed);
        m_generation.fetch_add(1, std::memory_order_release);
        m_generation.notify_all();
        fn(context, 0);
        for (int left = m_remaining.load(std::memory_order_acquire); left != 0;
             left = m_remaining.load(std::memory_order_acquire))
            waitWhileEqual(m_remaining, left);
        m_busy.store(false, std::memory_order_release);
        return true;
    }

private:
    void work(int part, std::uint64_t seen) {
        for (;;) {
            seen = waitWhileEqual(m_generation, seen);
            if (part < m_parts) m_fn(m_context, part);
            if (m_remaining.fetch_sub(1, std::memory_order_acq_rel) == 1) m_remaining.notify_one();
        }
    }

    std::atomic<bool> m_busy{false};
    std::atomic<std::uint64_t> m_generation{0};
    std::atomic<int> m_remaining{0};
    // The job, written before the generation is bumped and read after it is seen.
    void (*m_fn)(const void*, int) = nullptr;
    const void* m_context = nullptr;
    int m_parts = 0;
    // Never joined: the threads live as long as the program (the object is never destroyed).
    std::vector<std::thread> m_threads;
};

}  // namespace

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
