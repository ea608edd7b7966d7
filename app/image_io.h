// Writing pipeline images as PNG files (8-bit RGBA), atomically: a failed write leaves
// any previous file untouched.
#pragma once

#include <QImage>
#include <QString>

#include "pipeline/render/output_image.h"

namespace rasterlab {

// The image as a QImage (Format_RGBA8888): a read-only view of its bytes, valid while it
// lives, or a deep copy.
QImage viewOf(const rl::Rgba8Image& image);
QImage toQImage(const rl::Rgba8Image& image);
bool savePng(const QImage& image, const QString& path, QString* error);

}  // namespace rasterlab
