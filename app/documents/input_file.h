// Reading an input file (course file, command file) whole, within a size limit: a file larger
// than any scene RasterLab can hold (a gigabyte of garbage, a device) fails at once, before a
// byte is read, with a message naming its size; the program's memory stays bounded.
#pragma once

#include <QByteArray>
#include <QString>

#include "pipeline/core/diagnostics.h"

namespace rasterlab {

// 512 MiB: ten times the text of a million-triangle .byu.
inline constexpr qint64 kMaxInputFileBytes = qint64(512) << 20;

rl::Result<QByteArray> readInputFile(const QString& path, qint64 maxBytes = kMaxInputFileBytes);

}  // namespace rasterlab
