#include "image_io.h"

#include <QSaveFile>

namespace rasterlab {

QImage viewOf(const rl::Rgba8Image& image) {
    return QImage(image.rgba.data(), image.width, image.height, image.width * 4,
                  QImage::Format_RGBA8888);
}

QImage toQImage(const rl::Rgba8Image& image) {
    return viewOf(image).copy();
}

bool savePng(const QImage& image, const QString& path, QString* error) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        if (error) *error = file.errorString();
        return false;
    }
    if (!image.save(&file, "PNG")) {
        file.cancelWriting();
        if (error) *error = QStringLiteral("the PNG encoder failed");
        return false;
    }
    if (!file.commit()) {
        if (error) *error = file.errorString();
        return false;
    }
    return true;
}

}  // namespace rasterlab
