// Their image for a comparison (rasterlab-cli compare, File > Compare with Image...): read as
// RGBA bytes, and the messages for a file that is not a PNG of our size. The command line and
// the window say the same (the window in the user's language).
#pragma once

#include <QCoreApplication>
#include <QString>

#include "pipeline/render/output_image.h"

namespace rasterlab {

struct CompareImage {
    Q_DECLARE_TR_FUNCTIONS(rasterlab::CompareImage)

public:
    // Reads their PNG into `image`: an empty string, or "PATH: why not" (no such file, a
    // folder, empty, not a PNG, cut short, unreadable).
    static QString read(const QString& path, rl::Rgba8Image& image);
    // Empty when the sizes agree; else "PATH: the image is 640x480, ours is 800x600", and
    // where it holds ours when it does (a screenshot with a window border), `embedded` then
    // set.
    static QString sizeMismatch(const QString& path, const rl::Rgba8Image& theirs,
                                const rl::Rgba8Image& ours, bool& embedded);
};

}  // namespace rasterlab
