// RL_MULTIVERSION: a hot kernel built three times, for the baseline x86-64, x86-64-v3 (AVX2)
// and x86-64-v4 (AVX-512), the best one picked when the program starts (GCC's target_clones,
// an ifunc; Clang 14 builds the three but always picks the baseline). Under ThreadSanitizer
// the picking function would run, instrumented, before the sanitizer is set up, and crash:
// there the kernel is built once, for the baseline.
#pragma once

#if defined(__SANITIZE_THREAD__)
#define RL_THREAD_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define RL_THREAD_SANITIZER 1
#endif
#endif

#if defined(RL_THREAD_SANITIZER) || !defined(__x86_64__)
#define RL_MULTIVERSION
#elif defined(RL_NO_AVX512_KERNELS)
// Built with RASTERLAB_AVX512_KERNELS=OFF: an AVX-512 machine runs the AVX2 kernels, so that
// it can time what an AVX2 machine runs.
#define RL_MULTIVERSION __attribute__((target_clones("default", "arch=x86-64-v3")))
#else
#define RL_MULTIVERSION \
    __attribute__((target_clones("default", "arch=x86-64-v3", "arch=x86-64-v4")))
#endif

namespace rl {

// The kernels this processor runs, as RL_MULTIVERSION picks them: "x86-64-v4 (AVX-512)",
// "x86-64-v3 (AVX2)" or "x86-64" (always "x86-64" when built by Clang 14, whose resolver picks
// the default; "baseline" where the kernels are built once). The bench prints it, so that
// figures from two machines say which kernels they timed.
const char* kernelLevel();

// How many pixels the kernels take at a time: eight where the kernel level has 32-byte
// registers (AVX2, AVX-512), four with the baseline's 16-byte ones, where GCC would build
// each shuffle of eight lanes one lane at a time, through the stack. Every clone holds both
// widths, which give the same bits; setKernelLanes lets the tests run the other one.
extern int g_kernelLanes;
inline int kernelLanes() {
    return g_kernelLanes;
}
// 4 or 8; anything else: the kernel level's own.
void setKernelLanes(int lanes);

}  // namespace rl
