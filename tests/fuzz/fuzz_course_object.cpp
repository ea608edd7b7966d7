// libFuzzer target: the .byu object reader (triangle mesh, course Bezier surface, Movie.BYU),
// and a small render of what it accepts.
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    rl::Diagnostics diagnostics;
    auto mesh = rl::readByuObject(rl::fuzz::textOf(data, size), "fuzz.byu", diagnostics);
    if (!mesh || mesh->triangles.size() > 20000) return 0;
    rl::CourseSceneParts parts{rl::fuzz::fixedCamera(), rl::fuzz::fixedLighting(),
                               {"fuzz.byu", std::make_shared<const rl::Mesh>(std::move(*mesh))}};
    rl::fuzz::renderSmall(parts);
    return 0;
}
