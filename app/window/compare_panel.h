// The Compare dock (File > Compare with Image...): a student's image and ours side by side,
// flickering one into the other, or their difference above a threshold; the summary and the
// ranked diagnosis of `rasterlab-cli compare` (the same functions: mistakes.h); and, for the
// pixel picked, their colour beside ours and which Phong term of ours (ambient, diffuse,
// specular) would have to change, and by how much, to give theirs.
#pragma once

#include <QImage>
#include <QTimer>
#include <QWidget>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/documents/scene_document.h"
#include "pipeline/analysis/lighting_fit.h"
#include "pipeline/analysis/mistakes.h"

class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace rasterlab {

class Inspection;
class CompareCanvas;

class ComparePanel : public QWidget {
    Q_OBJECT
public:
    enum class Mode { SideBySide, Flicker, Difference };
    static constexpr int kFlickerMs = 500;  // each image half a second: two changes a second

    explicit ComparePanel(Inspection* inspection, QWidget* parent = nullptr);

    // The command file shown and the index of its image, or an empty path for course files:
    // a command file's comparison also looks for a misread command (mistakes.h).
    using CommandFileSource = std::function<std::pair<QString, int>()>;
    void setCommandFileSource(CommandFileSource source) { m_commandFile = std::move(source); }

    // Compares the PNG at `path` with our render of the frame shown: an empty string, or the
    // message saying why it cannot be (the panel then keeps what it showed). A compare still
    // running after kProgressAfterMs shows a dialog whose Cancel stops it.
    QString compare(const QString& path);
    static constexpr int kProgressAfterMs = 400;
    // The last compare was cancelled by the user (its message says so; not an error).
    bool wasCancelled() const { return m_cancelled; }
    const rl::ImageComparison* comparison() const { return m_comparison.get(); }
    QString imagePath() const { return m_path; }
    // The scene shown is no longer the one compared (a file or value changed since).
    bool isStale() const;

    Mode mode() const;
    void setMode(Mode mode);
    bool flickerShowsTheirs() const { return m_flickerTheirs; }
    int threshold() const;
    void setThreshold(int threshold);
    // The pixels that differ by more than the threshold in some channel (RGBA), and the
    // difference view: theirs against ours from yellow (a little) to red, magenta where only
    // we cover a pixel, cyan where only they do, the other pixels ours darkened.
    std::size_t differingAboveThreshold() const { return m_aboveThreshold; }
    const QImage& differenceImage() const { return m_difference; }
    const QImage& theirImage() const { return m_theirImage; }
    const QImage& ourImage() const { return m_ourImage; }

    QString summaryText() const;
    QString diagnosisText() const;  // plain text
    QString pixelText() const;

    // The scene's values that give the fitted lighting (the Render Ours with the Fitted
    // Lighting button's): the first light's position and Il, Ia, kd, ks, n and Ke.
    struct FittedSetting {
        SceneDocument::Field field;
        std::size_t light = 0;
        SceneDocument::Numbers value{};
    };
    std::vector<FittedSetting> fittedSettings() const;
    QPushButton* useFitButton() const { return m_useFit; }
    // A fitted value's name (lighting_fit.h's), translated.
    static QString fittedName(const std::string& name);

signals:
    void compared();
    // Render Ours with the Fitted Lighting: set these values in the scene, as one edit.
    void useFittedLighting(const std::vector<ComparePanel::FittedSetting>& settings);

private:
    // Where their image holds our pixel's point of the surface: moved by the diagnosis's first
    // finding when that is a move removing most of the difference (rl::dominantMove), else the
    // same pixel; and the other way.
    QPoint theirPixelOf(QPoint ours) const;
    QPoint ourPixelOf(QPoint theirs) const;

    CommandFileSource m_commandFile;
    void showImages();
    void refreshDifference();
    void refreshTexts();
    void refreshPixel();

    Inspection* m_inspection = nullptr;
    QString m_path;
    QString m_provenance;                      // their image's format, and what was cropped
    std::shared_ptr<const rl::Scene> m_scene;  // the scene compared
    std::unique_ptr<rl::OurFrame> m_ours;
    rl::Rgba8Image m_theirs;
    std::unique_ptr<rl::ImageComparison> m_comparison;
    rl::LightingFit m_fit;
    QImage m_theirImage, m_ourImage, m_difference;
    std::size_t m_aboveThreshold = 0;
    bool m_flickerTheirs = true;
    QTimer m_flicker;

    QComboBox* m_mode = nullptr;
    QSpinBox* m_threshold = nullptr;
    QPushButton* m_again = nullptr;
    bool m_cancelled = false;
    QPushButton* m_useFit = nullptr;
    CompareCanvas* m_canvas = nullptr;
    QLabel* m_summary = nullptr;
    QLabel* m_diagnosis = nullptr;
    QLabel* m_pixel = nullptr;
};

}  // namespace rasterlab
