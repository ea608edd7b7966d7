#include "compare_image.h"

#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QImageReader>

#include <algorithm>
#include <cstring>
#include <utility>

#include "app/documents/command_file.h"
#include "pipeline/analysis/mistakes.h"

namespace rasterlab {

namespace {

QString sizeText(int width, int height) {
    return QStringLiteral("%1x%2").arg(width).arg(height);
}

// A TGA file as simple programs write it: true colour (24 or 32 bits) or grey (8 bits),
// plain or run-length encoded, without the TGA 2.0 footer that Qt's reader insists on.
// A null image, with `why` set, when it is not such a file; `alpha` says if it has 32 bits.
QImage readTga(const QByteArray& data, QString& why, bool& alpha) {
    const auto byte = [&](qsizetype i) { return static_cast<unsigned char>(data[i]); };
    if (data.size() < 18) {
        why = CompareImage::tr("the TGA header is cut short");
        return {};
    }
    const int type = byte(2), depth = byte(16), descriptor = byte(17);
    const int width = byte(12) | byte(13) << 8, height = byte(14) | byte(15) << 8;
    const bool grey = type == 3 || type == 11, rle = type == 10 || type == 11;
    if (byte(1) != 0 || !(type == 2 || type == 3 || type == 10 || type == 11) ||
        (grey ? depth != 8 : depth != 24 && depth != 32) || width == 0 || height == 0) {
        why = CompareImage::tr("a TGA image of a kind RasterLab does not read (only 8-bit grey "
                               "and 24- or 32-bit colour, plain or run-length encoded)");
        return {};
    }
    const int bytes = depth / 8;
    alpha = bytes == 4;
    const qsizetype count = qsizetype(width) * height;
    qsizetype at = 18 + byte(0);
    // Never more pixels than the file can hold (a run-length packet gives at most 128), nor
    // than Qt would allocate for an image of its own (its 256 MB limit).
    const qsizetype available = std::max<qsizetype>(0, data.size() - at);
    if ((rle ? available * 128 : available) < count * bytes) {
        why = CompareImage::tr("the TGA image is cut short");
        return {};
    }
    if (count * 4 > qsizetype(256) << 20) {
        why = CompareImage::tr("the TGA image is %1x%2, larger than RasterLab reads")
                  .arg(width)
                  .arg(height);
        return {};
    }
    QByteArray pixels;
    pixels.reserve(count * bytes);
    while (pixels.size() < count * bytes) {
        qsizetype run = 1;
        bool repeat = false;
        if (rle) {
            if (at >= data.size()) break;
            repeat = byte(at) & 0x80;
            run = (byte(at) & 0x7f) + 1;
            ++at;
        }
        const qsizetype take = repeat ? bytes : run * bytes;
        if (at + take > data.size()) break;
        for (qsizetype i = 0; i < (repeat ? run : 1); ++i) pixels.append(data.mid(at, take));
        at += take;
    }
    if (pixels.size() < count * bytes) {
        why = CompareImage::tr("the TGA image is cut short");
        return {};
    }
    QImage image(width, height, QImage::Format_RGBA8888);
    const bool topFirst = descriptor & 0x20, rightFirst = descriptor & 0x10;
    for (int row = 0; row < height; ++row)
        for (int column = 0; column < width; ++column) {
            const auto* p = reinterpret_cast<const unsigned char*>(pixels.constData()) +
                            (qsizetype(row) * width + column) * bytes;
            const int x = rightFirst ? width - 1 - column : column;
            const int y = topFirst ? row : height - 1 - row;
            const QColor colour = grey ? QColor(p[0], p[0], p[0])
                                       : QColor(p[2], p[1], p[0], bytes == 4 ? p[3] : 255);
            image.setPixelColor(x, y, colour);
        }
    return image;
}

}  // namespace

QString CompareImage::read(const QString& path, rl::Rgba8Image& image, Format* format) {
    // The formats students' renderers write: Qt reads PBM/PGM/PPM (plain and raw), BMP, PNG and
    // JPEG; TGA is read here.
    static const QList<QByteArray> readable = {"png", "ppm", "pgm", "pbm", "bmp", "tga", "jpeg"};
    const QFileInfo info(path);
    QString problem;
    if (!info.exists())
        problem = tr("no such file");
    else if (info.isDir())
        problem = tr("a folder, not an image");
    else if (info.size() == 0)
        problem = tr("the file is empty");
    if (problem.isEmpty()) {
        // A TGA file has no signature to recognise it by (its header can pass for an icon's):
        // its name says what it is. The others are known by their content.
        QByteArray found = "tga";
        if (info.suffix().compare(QStringLiteral("tga"), Qt::CaseInsensitive) != 0) {
            QImageReader probe(path);
            probe.setDecideFormatFromContent(true);
            found = probe.format();
        }
        QImageReader reader(path, found);
        if (format) *format = Format{found, true};
        // A PNG ends with its IEND chunk; libpng would complain of a cut one on stderr.
        QFile file(path);
        const bool complete = found != "png" ||
                              (file.open(QIODevice::ReadOnly) && file.seek(file.size() - 8) &&
                               file.read(8) == QByteArray("IEND\xAE\x42\x60\x82", 8));
        if (!readable.contains(found)) {
            problem = found.isEmpty()
                          ? tr("not an image RasterLab reads (PNG, PPM, BMP, TGA or JPEG)")
                          : tr("not an image RasterLab reads (PNG, PPM, BMP, TGA or JPEG): a %1 "
                               "image")
                                .arg(QString::fromLatin1(found));
        } else if (!complete) {
            problem = tr("the PNG is cut short (it does not end with its IEND chunk)");
        } else {
            QString why;
            QImage read;
            bool tgaAlpha = false;
            if (found == "tga") {
                if (file.open(QIODevice::ReadOnly)) read = readTga(file.readAll(), why, tgaAlpha);
                if (why.isEmpty() && read.isNull()) why = file.errorString();
            } else {
                read = reader.read();
                why = reader.errorString();
            }
            if (read.isNull() || read.width() == 0 || read.height() == 0) {
                problem = found == "tga" ? why
                                         : tr("cannot read the %1 image: %2")
                                               .arg(QString::fromLatin1(found.toUpper()), why);
            } else {
                // A PNG's alpha is always compared (an opaque background where the reference's
                // is transparent is a finding); the other formats' only when they have one.
                if (format)
                    format->alpha = found == "png" ||
                                    (found == "tga" ? tgaAlpha : read.hasAlphaChannel());
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

int CompareImage::Format::tolerance() const {
    // JPEG at the usual qualities (75-95) moves a flat colour by a few units and an edge by
    // more: 8 per channel keeps flat areas the same without hiding a whole shading term.
    return name == "jpeg" ? 8 : 0;
}

QString CompareImage::Format::describe() const {
    QString text = tr("a %1 image").arg(QString::fromLatin1(name.toUpper()));
    if (tolerance() > 0)
        text += tr(", lossy: compared with a tolerance of %1 per channel").arg(tolerance());
    if (!alpha) text += tr(", without alpha: colours compared, alpha taken as ours");
    return text;
}

std::optional<rl::ivec2> CompareImage::cropToFrame(const rl::Rgba8Image& ours,
                                                   rl::Rgba8Image& theirs) {
    if (theirs.width == ours.width && theirs.height == ours.height) return std::nullopt;
    const auto at = rl::findEmbedded(ours, theirs);
    if (!at) return std::nullopt;
    rl::Rgba8Image frame;
    frame.width = ours.width;
    frame.height = ours.height;
    frame.rgba.resize(std::size_t(frame.width) * frame.height * 4);
    for (int row = 0; row < frame.height; ++row)
        std::memcpy(frame.rgba.data() + std::size_t(row) * frame.width * 4,
                    theirs.rgba.data() + (std::size_t(at->y + row) * theirs.width + at->x) * 4,
                    std::size_t(frame.width) * 4);
    theirs = std::move(frame);
    return at;
}

void CompareImage::takeAlpha(const rl::Rgba8Image& ours, rl::Rgba8Image& theirs) {
    if (ours.width != theirs.width || ours.height != theirs.height) return;
    for (std::size_t i = 3; i < theirs.rgba.size(); i += 4) theirs.rgba[i] = ours.rgba[i];
}

QString CompareImage::sizeMismatch(const QString& path, const rl::Rgba8Image& theirs,
                                   const rl::Rgba8Image& ours) {
    if (theirs.width == ours.width && theirs.height == ours.height) return {};
    return path + QStringLiteral(": ") +
           tr("the image is %1, ours is %2")
               .arg(sizeText(theirs.width, theirs.height), sizeText(ours.width, ours.height));
}

rl::Result<CompareImage::Diagnosis> CompareImage::diagnose(const rl::OurFrame& ours,
                                                          const rl::Rgba8Image& theirs,
                                                          const Format& format,
                                                          const QString& commandFile,
                                                          std::size_t imageIndex,
                                                          const std::atomic<bool>* cancel) {
    std::optional<CommandFileText> text;
    if (!commandFile.isEmpty()) {
        auto read = readCommandFileText(commandFile);
        if (!read) return read.error();
        text = std::move(read.value());
    }
    rl::CompareOptions options;
    options.tolerance = format.tolerance();
    options.cancel = cancel;
    auto comparison = text ? rl::compareCommandFile(ours, theirs, options, text->text(),
                                                    text->fileName, text->loader, imageIndex,
                                                    !format.alpha)
                           : rl::compareWithOurs(ours, theirs, options);
    if (!comparison) return comparison.error();
    Diagnosis out;
    if (comparison->differing > 0 && !comparison->unlit) {
        // Their image moved (mirrored, shifted, mapped another way) first of all: its colours
        // are fitted where they belong, carried back onto ours.
        const auto move = rl::dominantMove(comparison.value());
        out.fit = rl::fitLighting(ours, move ? rl::carriedBack(theirs, *move) : theirs);
        out.fit.carriedBack = move.has_value();
    }
    if (options.cancelled()) return rl::makeError(rl::ErrorCode::Usage, {}, "comparison cancelled");
    auto withFit = rl::withFittedLighting(std::move(comparison.value()), ours, theirs, options,
                                          out.fit);
    if (!withFit) return withFit.error();
    out.comparison = std::move(withFit.value());
    return out;
}

}  // namespace rasterlab
