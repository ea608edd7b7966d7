// Command files (seed 001) read from disk: the text through rl::readHw2, and the textures
// they name through QImage, relative to the command file's folder.
#pragma once

#include <QByteArray>
#include <QString>

#include <memory>
#include <string>
#include <string_view>

#include "pipeline/core/diagnostics.h"
#include "pipeline/io/hw2_reader.h"
#include "pipeline/scene/scene.h"

namespace rasterlab {

// A PNG (or any image Qt reads) as a texture: RGBA, 0..1, row 0 at the top.
rl::Result<std::shared_ptr<const rl::Texture>> loadTexture(const QString& path,
                                                           const rl::SourceLocation& where);

rl::Result<rl::Hw2File> loadCommandFile(const QString& path, rl::Diagnostics& diagnostics);

// What rl::readHw2 needs to read the command file at path again (compare's search for a
// misread command): its text, and the loader of the textures it names.
struct CommandFileText {
    QByteArray bytes;
    std::string fileName;
    rl::TextureLoader loader;
    std::string_view text() const {
        return std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size()));
    }
};
rl::Result<CommandFileText> readCommandFileText(const QString& path);

}  // namespace rasterlab
