// Their image for a comparison (rasterlab-cli compare, File > Compare with Image...): read as
// RGBA bytes from what student renderers write (PNG, PPM P3 and P6, BMP, TGA, JPEG), and the
// messages for a file that is none of them or not of our size. The command line and the
// window say the same (the window in the user's language).
#pragma once

#include <QCoreApplication>
#include <QString>

#include <atomic>
#include <optional>

#include "pipeline/analysis/lighting_fit.h"
#include "pipeline/analysis/mistakes.h"
#include "pipeline/core/math.h"
#include "pipeline/render/output_image.h"

namespace rasterlab {

struct CompareImage {
    Q_DECLARE_TR_FUNCTIONS(rasterlab::CompareImage)

public:
    struct Format {
        QByteArray name;    // "png", "ppm", "bmp", "tga", "jpeg" ...
        bool alpha = true;  // false: a format or file without alpha (PPM, JPEG, a 24-bit BMP)
        // A lossy format (JPEG) changes every pixel a little: the largest difference per
        // channel that still counts as the same, 0 for the others.
        int tolerance() const;
        QString describe() const;  // "a JPEG image, compared with a tolerance of 8 ..."
    };
    // Reads their image into `image`, and what it was into `format` when given: an empty
    // string, or "PATH: why not" (no such file, a folder, empty, not an image of those
    // formats, a PNG cut short, unreadable).
    static QString read(const QString& path, rl::Rgba8Image& image, Format* format = nullptr);
    // Their image without alpha takes ours, so that only the colours are compared.
    static void takeAlpha(const rl::Rgba8Image& ours, rl::Rgba8Image& theirs);
    // Empty when the sizes agree; else "PATH: the image is 640x480, ours is 800x600".
    static QString sizeMismatch(const QString& path, const rl::Rgba8Image& theirs,
                                const rl::Rgba8Image& ours);
    // A screenshot with a window border or a cursor: when their larger image holds ours, it is
    // cropped to that frame, and where it was is returned.
    static std::optional<rl::ivec2> cropToFrame(const rl::Rgba8Image& ours, rl::Rgba8Image& theirs);

    // The whole diagnosis of their image (our size, alpha taken where theirs has none): for a
    // command file (its path and the index of the image shown, else an empty path), the
    // command misread first when one is; the lighting fitted to their colours, and ours
    // rendered with it first when that explains more.
    struct Diagnosis {
        rl::ImageComparison comparison;
        rl::LightingFit fit;
    };
    // `cancel`, set from another thread, stops it with the error "comparison cancelled".
    static rl::Result<Diagnosis> diagnose(const rl::OurFrame& ours, const rl::Rgba8Image& theirs,
                                          const Format& format, const QString& commandFile,
                                          std::size_t imageIndex,
                                          const std::atomic<bool>* cancel = nullptr);
};

}  // namespace rasterlab
