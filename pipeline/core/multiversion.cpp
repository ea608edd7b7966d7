#include "multiversion.h"

namespace rl {

#if defined(RL_KERNELS_BUILT_ONCE)
const char* kernelLevel() {
    return "baseline";
}
namespace {
int lanesOfLevel() {
#if defined(__x86_64__)
    return 4;  // the baseline's
#else
    return 8;  // as before (not measured)
#endif
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
#if !defined(RL_KERNELS_UP_TO_V3)
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

std::atomic<int> g_kernelLanes{lanesOfLevel()};

void setKernelLanes(int lanes) {
    g_kernelLanes.store(lanes == 4 || lanes == 8 ? lanes : lanesOfLevel(),
                        std::memory_order_relaxed);
}

}  // namespace rl
