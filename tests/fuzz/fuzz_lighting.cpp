// libFuzzer target: the lighting reader in every layout (detected, UFPE, UFPE with several
// lights, UFRPE, key = value), and a small render with each lighting it accepts.
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    for (rl::LightingLayout layout : rl::kLightingLayouts) {
        rl::Diagnostics diagnostics;
        auto lighting = rl::readLightingFile(rl::fuzz::textOf(data, size), "fuzz.txt",
                                             diagnostics, layout);
        if (!lighting) continue;
        rl::fuzz::renderSmall({rl::fuzz::fixedCamera(), *lighting, rl::fuzz::fixedObject()});
    }
    return 0;
}
