#include "multiversion.h"

namespace rl {

#if defined(RL_THREAD_SANITIZER) || !defined(__x86_64__)
const char* kernelLevel() {
    return "baseline";
}
#elif defined(__clang__)
// Clang 14 builds the x86-64-v3 and v4 clones, but its resolver does not know those names
// and always picks the default.
const char* kernelLevel() {
    return "x86-64";
}
#else
namespace {
// Versions of one function, picked by the same resolver as RL_MULTIVERSION's clones.
__attribute__((target("default"))) const char* level() {
    return "x86-64";
}
__attribute__((target("arch=x86-64-v3"))) const char* level() {
    return "x86-64-v3 (AVX2)";
}
#if !defined(RL_NO_AVX512_KERNELS)
__attribute__((target("arch=x86-64-v4"))) const char* level() {
    return "x86-64-v4 (AVX-512)";
}
#endif
}  // namespace

const char* kernelLevel() {
    return level();
}
#endif

}  // namespace rl
