// Writing pipeline images as PNG files (8-bit RGBA), atomically: a failed write leaves
// any previous file untouched.
#pragma once

#include <QImage>
#include <QString>

#include "output_image.h"

namespace rasterlab {

QImage toQImage(const rl::Rgba8Image& image);  // a deep copy, Format_RGBA8888
bool savePng(const QImage& image, const QString& path, QString* error);

}  // namespace rasterlab
