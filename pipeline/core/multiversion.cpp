#include "multiversion.h"

namespace rl {

const char* kernelLevel() {
#if defined(RL_THREAD_SANITIZER) || !defined(__x86_64__)
    return "baseline";
#else
    __builtin_cpu_init();
#if defined(__clang__)
    // Clang 14 names the features, not the levels: those that set each level apart.
    const bool v4 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
                    __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512dq") &&
                    __builtin_cpu_supports("avx512vl");
    const bool v3 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
                    __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2");
#else
    const bool v4 = __builtin_cpu_supports("x86-64-v4");
    const bool v3 = __builtin_cpu_supports("x86-64-v3");
#endif
    return v4 ? "x86-64-v4 (AVX-512)" : v3 ? "x86-64-v3 (AVX2)" : "x86-64";
#endif
}

}  // namespace rl
