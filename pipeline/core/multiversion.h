// RL_MULTIVERSION: a hot kernel built three times, for the baseline x86-64, x86-64-v3 (AVX2)
// and x86-64-v4 (AVX-512), the best one picked when the program starts (GCC's target_clones,
// an ifunc). The CMake option RASTERLAB_KERNELS lowers the highest level built, so that one
// machine can time the kernels another runs. Built once, for the baseline
// (RL_KERNELS_BUILT_ONCE): by Clang 14, which does not dispatch; under ThreadSanitizer, where
// the picking function would run, instrumented, before the sanitizer is set up, and crash; off
// x86-64; and with RASTERLAB_KERNELS=x86-64.
#pragma once

#if defined(__SANITIZE_THREAD__)
#define RL_THREAD_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define RL_THREAD_SANITIZER 1
#endif
#endif

#if defined(RL_THREAD_SANITIZER) || !defined(__x86_64__) || defined(__clang__) || \
    defined(RL_KERNELS_BASELINE)
#define RL_KERNELS_BUILT_ONCE 1
#define RL_MULTIVERSION
#elif defined(RL_KERNELS_UP_TO_V3)
#define RL_MULTIVERSION __attribute__((target_clones("default", "arch=x86-64-v3")))
#else
#define RL_MULTIVERSION \
    __attribute__((target_clones("default", "arch=x86-64-v3", "arch=x86-64-v4")))
#endif

#include <atomic>

namespace rl {

// The kernels this processor runs, as RL_MULTIVERSION picks them: "x86-64-v4 (AVX-512)",
// "x86-64-v3 (AVX2)" or "x86-64" ("baseline" where the kernels are built once). The bench
// prints it, so that figures from two machines say which kernels they timed.
const char* kernelLevel();

// How many pixels the kernels take at a time: eight where the kernel level has 32-byte
// registers (AVX2, AVX-512), four with the baseline's 16-byte ones, where GCC would build
// each shuffle of eight lanes one lane at a time, through the stack (eight off x86-64, not
// measured). Every clone holds both widths, which give the same bits; setKernelLanes lets the
// tests run the other one, while no kernel runs.
extern std::atomic<int> g_kernelLanes;
inline int kernelLanes() {
    return g_kernelLanes.load(std::memory_order_relaxed);
}
// 4 or 8; anything else: the kernel level's own.
void setKernelLanes(int lanes);

}  // namespace rl
