#include "input_file.h"

#include <QFile>

#include <algorithm>
#include <string>

namespace rasterlab {

using rl::operator""_msg;  // message templates, translated in the window (pipeline_messages.h)

rl::Result<QByteArray> readInputFile(const QString& path, qint64 maxBytes) {
    const rl::SourceLocation where{path.toStdString(), 0, 0};
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return rl::makeError(rl::ErrorCode::Io, where,
                             "cannot open: %1"_msg(file.errorString().toStdString()));
    const auto mib = [](qint64 bytes) { return std::to_string((bytes + (1 << 20) - 1) >> 20); };
    // A sequential file (a pipe, a device) has no size to check: it is read up to the limit.
    if (!file.isSequential() && file.size() > maxBytes)
        return rl::makeError(rl::ErrorCode::Range, where,
                             "the file has %1 MiB, more than the %2 MiB an input file may have"_msg(
                                 mib(file.size()), mib(maxBytes)));
    // Read in chunks: asking read() for the whole limit would reserve all of it at once.
    QByteArray bytes;
    if (!file.isSequential()) bytes.reserve(file.size());
    constexpr qint64 kChunk = qint64(1) << 20;
    while (bytes.size() <= maxBytes) {
        const QByteArray chunk = file.read(std::min(kChunk, maxBytes + 1 - bytes.size()));
        if (chunk.isEmpty()) break;
        bytes += chunk;
    }
    if (bytes.size() > maxBytes)
        return rl::makeError(
            rl::ErrorCode::Range, where,
            "the file has more than the %1 MiB an input file may have"_msg(mib(maxBytes)));
    return bytes;
}

}  // namespace rasterlab
