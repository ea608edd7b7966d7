// RasterLab's main window: the rendered image in the centre, a Messages dock with every
// warning and error (file:line:col), a Scene dock with what was loaded and what each
// stage did, an Accuracy dock (each mode against an exact reference), and menus to open each
// course file on its own, pick the shading model and the rasterization rules, and export the
// image. A file that fails to load leaves the previous scene on screen.
#pragma once

#include <QActionGroup>
#include <QMainWindow>

#include <memory>

#include "render_controller.h"
#include "scene_document.h"

class QLabel;
class QMenu;
class QListWidget;
class QTextBrowser;

namespace rasterlab {

class AccuracyPanel;
class FrameImageView;
class ZBufferView;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);

    // Replaces one part of the scene from a file; returns false (and shows the error,
    // keeping the scene) when the file is bad.
    bool openPart(SceneDocument::Part part, const QString& path);
    // Reads course cameras / lighting in a layout from now on (Auto: detected), re-reading
    // the current file; false (the error shown, the scene kept) when it does not fit.
    bool setCameraLayout(rl::CameraLayout layout);
    bool setLightingLayout(rl::LightingLayout layout);
    // Shows a command file (seed 001); false (the error shown, the scene kept) when bad.
    bool openCommandFile(const QString& path);
    void setShading(rl::ShadingModel model);
    void setRules(rl::RuleSet rules);
    bool exportImage(const QString& path);

    const SceneDocument& document() const { return m_document; }
    std::shared_ptr<const rl::FrameTrace> currentFrame() const { return m_frame.trace; }
    const QImage& currentImage() const { return m_frame.image; }
    FrameImageView* imageView() const { return m_view; }
    QListWidget* messages() const { return m_messages; }
    RenderController* controller() const { return m_controller; }
    AccuracyPanel* accuracyPanel() const { return m_accuracy; }
    ZBufferView* zbufferView() const { return m_zbuffer; }
    // The docks as they are when the window opens (View > Reset Layout).
    void resetLayout();

    // The layout (geometry, docks) is kept in QSettings under layout/, with this version: a
    // layout saved by another version is not restored. Only when the application has an
    // organization name (the program sets one; tests choose theirs).
    static constexpr int kLayoutVersion = 1;

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void saveLayout() const;
    void restoreLayout();
    void createActions();
    void createDocks();
    void requestRender();
    void updateTimeLabel();
    void onFrameReady(const RenderedFrame& frame);
    void onRenderFailed(const QString& message);
    void showError(const QString& message);
    void refreshMessages();
    void refreshSceneSummary();
    void onPixelHovered(QPoint pixel);
    void openPartDialog(SceneDocument::Part part);
    void openCommandFileDialog();
    void documentChanged();  // menus, title, messages, and a new render
    void exportDialog();
    void about();

    SceneDocument m_document;
    RenderController* m_controller = nullptr;
    RenderedFrame m_frame;
    QString m_lastError;

    FrameImageView* m_view = nullptr;
    QListWidget* m_messages = nullptr;
    QTextBrowser* m_summary = nullptr;
    QLabel* m_pixelLabel = nullptr;
    QLabel* m_timeLabel = nullptr;  // the last frame's time; "rendering..." while busy
    QActionGroup* m_shadingGroup = nullptr;
    QActionGroup* m_rulesGroup = nullptr;
    AccuracyPanel* m_accuracy = nullptr;
    ZBufferView* m_zbuffer = nullptr;
    QByteArray m_defaultLayout;
    QMenu* m_shadingMenu = nullptr;
    QMenu* m_imageMenu = nullptr;
};

}  // namespace rasterlab
