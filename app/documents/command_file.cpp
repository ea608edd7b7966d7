#include "command_file.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QImageReader>

#include "app/documents/input_file.h"

namespace rasterlab {

using rl::operator""_msg;  // message templates, translated in the window (pipeline_messages.h)

rl::Result<std::shared_ptr<const rl::Texture>> loadTexture(const QString& path,
                                                           const rl::SourceLocation& where) {
    QImageReader reader(path);
    const QImage read = reader.read();
    if (read.isNull())
        return rl::makeError(rl::ErrorCode::Io, where,
                             "cannot read the texture %1: %2"_msg(
                                 path.toStdString(), reader.errorString().toStdString()));
    const QImage image = read.convertToFormat(QImage::Format_RGBA8888);
    auto texture = std::make_shared<rl::Texture>();
    texture->width = image.width();
    texture->height = image.height();
    texture->name = QFileInfo(path).fileName().toStdString();
    texture->texels.reserve(static_cast<std::size_t>(image.width()) *
                            static_cast<std::size_t>(image.height()));
    for (int y = 0; y < image.height(); ++y) {
        const uchar* row = image.constScanLine(y);
        for (int x = 0; x < image.width(); ++x) {
            const uchar* p = row + 4 * x;
            texture->texels.emplace_back(p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f,
                                         p[3] / 255.0f);
        }
    }
    return std::shared_ptr<const rl::Texture>(std::move(texture));
}

rl::Result<CommandFileText> readCommandFileText(const QString& path) {
    auto read = readInputFile(path);
    if (!read) return read.error();
    const QDir folder = QFileInfo(path).absoluteDir();
    CommandFileText out;
    out.bytes = std::move(read.value());
    out.fileName = path.toStdString();
    out.loader = [folder](const std::string& name, const rl::SourceLocation& where) {
        return loadTexture(folder.filePath(QString::fromStdString(name)), where);
    };
    return out;
}

rl::Result<rl::Hw2File> loadCommandFile(const QString& path, rl::Diagnostics& diagnostics) {
    auto file = readCommandFileText(path);
    if (!file) return file.error();
    return rl::readHw2(file->text(), file->fileName, file->loader, diagnostics);
}

}  // namespace rasterlab
