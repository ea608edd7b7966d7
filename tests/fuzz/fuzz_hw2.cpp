// libFuzzer target: the command-file reader (seed 001's language), and a render of each image
// it names when the image is small (up to 64 x 64 here; the reader's own limits apply to the
// rest), by the lecture's stages and by the fast paths, which must agree bit for bit.
#include "pipeline/io/hw2_reader.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // Every texture is a 2 x 2 checker, whatever its name.
    const rl::TextureLoader texture = [](const std::string&, const rl::SourceLocation&)
        -> rl::Result<std::shared_ptr<const rl::Texture>> {
        auto t = std::make_shared<rl::Texture>();
        t->width = 2;
        t->height = 2;
        t->texels = {rl::vec4(1.0f), rl::vec4(0.0f, 0.0f, 0.0f, 1.0f), rl::vec4(0.0f, 0.0f, 0.0f, 1.0f),
                     rl::vec4(1.0f)};
        return std::shared_ptr<const rl::Texture>(t);
    };
    rl::Diagnostics diagnostics;
    auto file = rl::readHw2(rl::fuzz::textOf(data, size), "fuzz.txt", texture, diagnostics);
    if (!file) return 0;
    for (const rl::Hw2Image& image : file->images) {
        if (image.scene.width > 64 || image.scene.height > 64) continue;
        if (image.scene.triangleCount() > 20000) continue;
        rl::fuzz::renderBothWays(std::make_shared<const rl::Scene>(image.scene));
    }
    return 0;
}
