#include "multiversion.h"

namespace rl {

#if defined(RL_THREAD_SANITIZER) || !defined(__x86_64__)
const char* kernelLevel() {
    return "baseline";
}
namespace {
// Built once: for x86-64's baseline under ThreadSanitizer; elsewhere eight, as before (not
// measured on other processors).
int lanesOfLevel() {
#if defined(__x86_64__)
    return 4;
#else
    return 8;
#endif
}
}  // namespace
#elif defined(__clang__)
// Clang 14 builds the x86-64-v3 and v4 clones, but its resolver does not know those names
// and always picks the default.
const char* kernelLevel() {
    return "x86-64";
}
namespace {
int lanesOfLevel() {
    return 4;  // the baseline's
}
}  // namespace
#else
namespace {
// Versions of one function, picked by the same resolver as RL_MULTIVERSION's clones.
__attribute__((target("default"))) const char* level() {
    return "x86-64";
}
__attribute__((target("default"))) int lanesOfLevel() {
    return 4;
}
__attribute__((target("arch=x86-64-v3"))) int lanesOfLevel() {
    return 8;
}
__attribute__((target("arch=x86-64-v3"))) const char* level() {
    return "x86-64-v3 (AVX2)";
}
#if !defined(RL_NO_AVX512_KERNELS)
__attribute__((target("arch=x86-64-v4"))) const char* level() {
    return "x86-64-v4 (AVX-512)";
}
__attribute__((target("arch=x86-64-v4"))) int lanesOfLevel() {
    return 8;
}
#endif
}  // namespace

const char* kernelLevel() {
    return level();
}
#endif

int g_kernelLanes = lanesOfLevel();

void setKernelLanes(int lanes) {
    g_kernelLanes = lanes == 4 || lanes == 8 ? lanes : lanesOfLevel();
}

}  // namespace rl
