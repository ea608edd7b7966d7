#include "compare_image.h"

#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QImageReader>

#include <cstring>

#include "pipeline/analysis/mistakes.h"

namespace rasterlab {

namespace {

QString sizeText(int width, int height) {
    return QStringLiteral("%1x%2").arg(width).arg(height);
}

}  // namespace

QString CompareImage::read(const QString& path, rl::Rgba8Image& image) {
    const QFileInfo info(path);
    QString problem;
    if (!info.exists())
        problem = tr("no such file");
    else if (info.isDir())
        problem = tr("a folder, not a PNG image");
    else if (info.size() == 0)
        problem = tr("the file is empty");
    if (problem.isEmpty()) {
        QImageReader reader(path);
        reader.setDecideFormatFromContent(true);
        const QByteArray format = reader.format();
        // A PNG ends with its IEND chunk; libpng would complain of a cut one on stderr.
        QFile file(path);
        const bool complete = file.open(QIODevice::ReadOnly) && file.seek(file.size() - 8) &&
                              file.read(8) == QByteArray("IEND\xAE\x42\x60\x82", 8);
        if (format != "png") {
            problem = format.isEmpty()
                          ? tr("not a PNG image")
                          : tr("not a PNG image (a %1 image)").arg(QString::fromLatin1(format));
        } else if (!complete) {
            problem = tr("the PNG is cut short (it does not end with its IEND chunk)");
        } else {
            const QImage read = reader.read();
            if (read.isNull() || read.width() == 0 || read.height() == 0) {
                problem = tr("cannot read the PNG: %1").arg(reader.errorString());
            } else {
                const QImage rgba = read.convertToFormat(QImage::Format_RGBA8888);
                image.width = rgba.width();
                image.height = rgba.height();
                image.rgba.resize(std::size_t(image.width) * image.height * 4);
                for (int y = 0; y < image.height; ++y)
                    std::memcpy(image.rgba.data() + std::size_t(y) * image.width * 4,
                                rgba.constScanLine(y), std::size_t(image.width) * 4);
            }
        }
    }
    return problem.isEmpty() ? QString() : path + QStringLiteral(": ") + problem;
}

QString CompareImage::sizeMismatch(const QString& path, const rl::Rgba8Image& theirs,
                                   const rl::Rgba8Image& ours, bool& embedded) {
    embedded = false;
    if (theirs.width == ours.width && theirs.height == ours.height) return {};
    QString text =
        path + QStringLiteral(": ") +
        tr("the image is %1, ours is %2")
            .arg(sizeText(theirs.width, theirs.height), sizeText(ours.width, ours.height));
    if (const auto at = rl::findEmbedded(ours, theirs)) {
        embedded = true;
        text += tr("; it holds ours at (%1, %2), as a screenshot with a window border would: "
                   "crop it to %3 from there")
                    .arg(at->x)
                    .arg(at->y)
                    .arg(sizeText(ours.width, ours.height));
    }
    return text;
}

}  // namespace rasterlab
