// libFuzzer target: the camera reader in every layout (detected, UFPE, UFRPE six and five
// lines, key = value), and a small render with each camera it accepts.
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    for (rl::CameraLayout layout : rl::kCameraLayouts) {
        rl::Diagnostics diagnostics;
        auto camera = rl::readCameraFile(rl::fuzz::textOf(data, size), "fuzz.cfg", diagnostics,
                                         layout);
        if (!camera) continue;
        rl::fuzz::renderSmall({*camera, rl::fuzz::fixedLighting(), rl::fuzz::fixedObject()});
    }
    return 0;
}
