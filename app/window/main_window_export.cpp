// The main window's exports: the image as displayed (at the cursor, with its overlays), the
// raw buffers, any dock's view as displayed, the frame in three shading models side by side, a
// stepping sequence and the animation's frames as numbered PNGs.
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QPainter>
#include <QProgressDialog>
#include <QStatusBar>

#include "app/image_io.h"
#include "app/window/animation_panel.h"
#include "app/window/main_window.h"
#include "pipeline/render/animation.h"
#include "pipeline/render/output_image.h"
#include "pipeline/render/renderer.h"
#include "views/frame_image_view.h"
#include "views/messages/pipeline_messages.h"

namespace rasterlab {

bool MainWindow::writePng(const QImage& image, const QString& path, const QString& failure) {
    QString error;
    if (image.isNull() || !savePng(image, path, &error)) {
        showError(failure.arg(path, error.isEmpty() ? tr("nothing has been rendered yet") : error));
        return false;
    }
    statusBar()->showMessage(tr("Exported %1").arg(QFileInfo(path).absoluteFilePath()), 5000);
    return true;
}

bool MainWindow::exportDisplayed(const QString& path) {
    return writePng(m_view->grab().toImage(), path, tr("%1: cannot export the image: %2"));
}

bool MainWindow::exportDepthBuffer(const QString& path) {
    const rl::DepthTest* buffers = m_inspection->buffers();
    QImage image;
    if (buffers) image = toQImage(rl::depthImage(buffers->depth, rl::depthRange(buffers->depth)));
    return writePng(image, path, tr("%1: cannot export the depth buffer: %2"));
}

bool MainWindow::exportNormalBuffer(const QString& path) {
    // The frame again, keeping the normal each pixel was lit with.
    const QString failure = tr("%1: cannot export the normal buffer: %2");
    QImage image;
    if (m_frame.trace) {
        rl::RenderOptions options;
        options.shading.keepNormals = true;
        auto frame = rl::renderFrame(m_frame.trace->scene, options);
        if (!frame) {
            showError(failure.arg(path, translated(frame.error())));
            return false;
        }
        image = toQImage(rl::normalImage(frame->shading->normal, *frame->depth));
    }
    return writePng(image, path, failure);
}

bool MainWindow::exportShadingSideBySide(const QString& path) {
    const QString failure = tr("%1: cannot export the shadings side by side: %2");
    if (!m_frame.trace || m_document.showsCommandFile()) {
        showError(failure.arg(path, tr("it needs a course scene")));
        return false;
    }
    const rl::ShadingModel models[] = {rl::ShadingModel::Flat, rl::ShadingModel::Gouraud,
                                       rl::ShadingModel::Phong};
    const QString names[] = {tr("Flat"), tr("Gouraud"), tr("Phong")};
    const rl::Scene& shown = *m_frame.trace->scene;
    // Small images (a lesson's 32 x 24) are enlarged, pixel by pixel, to be read on a slide.
    const int scale = std::max(1, 480 / std::max(shown.width, 1));
    const int w = shown.width * scale, h = shown.height * scale, gap = 12;
    const int caption = std::max(28, w / 14);
    QImage sheet(3 * w + 2 * gap, h + caption, QImage::Format_RGB32);
    sheet.fill(Qt::white);
    QPainter painter(&sheet);
    QFont font = painter.font();
    font.setPixelSize(caption * 3 / 5);
    painter.setFont(font);
    painter.setPen(Qt::black);
    for (int i = 0; i < 3; ++i) {
        auto scene = std::make_shared<rl::Scene>(shown);
        for (rl::Draw& draw : scene->draws) draw.shading = models[i];
        const auto frame = rl::renderFrame(scene);
        if (!frame) {
            showError(failure.arg(path, translated(frame.error())));
            return false;
        }
        const QImage image =
            toQImage(rl::colourImage(*frame->shading, *frame->depth, scene->conventions));
        const QRect where(i * (w + gap), 0, w, h);
        painter.drawImage(where, image);
        painter.drawText(QRect(where.left(), h, w, caption), Qt::AlignCenter, names[i]);
    }
    painter.end();
    return writePng(sheet, path, failure);
}

bool MainWindow::exportDock(const QString& dockName, const QString& path) {
    auto* dock = findChild<QDockWidget*>(dockName);
    if (!dock || !dock->widget()) {
        showError(tr("%1: cannot export the view: there is no view %2").arg(path, dockName));
        return false;
    }
    return writePng(dock->widget()->grab().toImage(), path, tr("%1: cannot export the view: %2"));
}

int MainWindow::exportSequence(const QString& folder, int maxImages) {
    if (!m_inspection->canStep() && m_inspection->granularity() != rl::StepGranularity::Stage) {
        showError(
            tr("%1: cannot export the steps: the frame cannot be stepped through yet").arg(folder));
        return 0;
    }
    if (!QDir().mkpath(folder)) {
        showError(tr("%1: cannot create the folder").arg(folder));
        return 0;
    }
    const rl::ReplayCursor saved = m_inspection->cursor();
    const rl::StageId savedStage = m_inspection->stage();
    QProgressDialog progress(tr("Exporting the steps..."), tr("Cancel"), 0, maxImages, this);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(500);
    m_inspection->toStart();
    int written = 0;
    const QDir dir(folder);
    while (written < maxImages) {
        const QString path =
            dir.filePath(QStringLiteral("step-%1.png").arg(written, 5, 10, QLatin1Char('0')));
        QString error;
        if (!savePng(m_view->grab().toImage(), path, &error)) {
            showError(tr("%1: cannot export the image: %2").arg(path, error));
            break;
        }
        ++written;
        progress.setValue(written);
        if (progress.wasCanceled()) break;
        if (!m_inspection->stepForward()) break;
    }
    if (m_inspection->granularity() == rl::StepGranularity::Stage)
        m_inspection->setStage(savedStage);
    m_inspection->seek(saved);
    statusBar()->showMessage(tr("Exported %1 images to %2").arg(written).arg(folder), 8000);
    return written;
}

int MainWindow::exportAnimationFrames(const QString& folder) {
    if (!m_document.isLoaded()) return 0;
    if (!QDir().mkpath(folder)) {
        showError(tr("%1: cannot create the folder").arg(folder));
        return 0;
    }
    // The document's scene with the animation on, rendered here at each frame's time, one
    // after the other; the window's own frame is left as it is.
    auto scene = std::make_shared<rl::Scene>(*m_document.scene());
    rl::animateEveryDraw(*scene, m_animation->settings().motion, 0.0);
    const int frames = m_animation->frameCount();
    QProgressDialog progress(tr("Exporting the animation's frames..."), tr("Cancel"), 0, frames,
                             this);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(500);
    const QDir dir(folder);
    const auto path = [&](int k) {
        return dir.filePath(QString::fromStdString(rl::animationFrameFileName(k)));
    };
    int written = 0;
    const rl::Status rendered = rl::renderAnimationFrames(
        *scene, frames, m_animation->framesPerSecond(),
        [&](int k, double, const rl::FrameTrace& frame) {
            QString error;
            if (!savePng(toQImage(rl::colourImage(*frame.shading, *frame.depth,
                                                  frame.scene->conventions)),
                         path(k), &error)) {
                showError(tr("%1: cannot export the image: %2").arg(path(k), error));
                return false;
            }
            ++written;
            progress.setValue(written);
            return !progress.wasCanceled();
        });
    if (!rendered)  // every frame before it was written
        showError(
            tr("%1: cannot render the frame: %2").arg(path(written), translated(rendered.error())));
    statusBar()->showMessage(tr("Exported %1 frames to %2").arg(written).arg(folder), 8000);
    return written;
}

void MainWindow::exportAnimationDialog() {
    const QString folder =
        QFileDialog::getExistingDirectory(this, tr("Folder for the Animation's Frames"));
    if (!folder.isEmpty()) exportAnimationFrames(folder);
}

void MainWindow::exportDisplayedDialog() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export the Image as Displayed"),
                                                      QStringLiteral("rasterlab-view.png"),
                                                      tr("PNG images (*.png)"));
    if (!path.isEmpty()) exportDisplayed(path);
}

void MainWindow::exportBufferDialog(int which) {
    const QString names[] = {QStringLiteral("colour.png"), QStringLiteral("depth.png"),
                             QStringLiteral("normals.png")};
    const QString path = QFileDialog::getSaveFileName(this, tr("Export a Buffer"), names[which],
                                                      tr("PNG images (*.png)"));
    if (path.isEmpty()) return;
    if (which == 0) {
        writePng(m_inspection->image(), path, tr("%1: cannot export the image: %2"));
    } else if (which == 1) {
        exportDepthBuffer(path);
    } else {
        exportNormalBuffer(path);
    }
}

void MainWindow::exportSequenceDialog() {
    const QString folder =
        QFileDialog::getExistingDirectory(this, tr("Folder for the Numbered Images"));
    if (folder.isEmpty()) return;
    bool ok = false;
    const int count = QInputDialog::getInt(
        this, tr("Stepping Sequence"),
        tr("At most how many images (one per step, at the current granularity)?"), 200, 1, 100000,
        1, &ok);
    if (ok) exportSequence(folder, count);
}

}  // namespace rasterlab
