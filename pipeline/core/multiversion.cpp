#include "multiversion.h"

namespace rl {

namespace {

// A kernel level's name and its width (kernelLanes).
struct Level {
    const char* name;
    int lanes;
};

#if defined(RL_KERNELS_BUILT_ONCE)
Level level() {
#if defined(__x86_64__)
    return {"baseline", 4};
#else
    return {"baseline", 8};  // as before (not measured)
#endif
}
#else
// Versions of one function, picked by the same resolver as RL_MULTIVERSION's clones.
__attribute__((target("default"))) Level level() {
    return {"x86-64", 4};
}
__attribute__((target("arch=x86-64-v3"))) Level level() {
    return {"x86-64-v3 (AVX2)", 8};
}
#if !defined(RL_KERNELS_UP_TO_V3)
__attribute__((target("arch=x86-64-v4"))) Level level() {
    return {"x86-64-v4 (AVX-512)", 8};
}
#endif
#endif

}  // namespace

const char* kernelLevel() {
    return level().name;
}

std::atomic<int> g_kernelLanes{level().lanes};

void setKernelLanes(int lanes) {
    g_kernelLanes.store(lanes == 4 || lanes == 8 ? lanes : level().lanes,
                        std::memory_order_relaxed);
}

}  // namespace rl
