#include "compare_panel.h"

#include <QApplication>
#include <QComboBox>
#include <QEventLoop>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QProgressDialog>
#include <QPushButton>
#include <QSpinBox>
#include <QTextDocument>
#include <QTimer>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

#include "app/compare/compare_image.h"
#include "app/image_io.h"
#include "views/inspection.h"
#include "views/messages/pipeline_messages.h"
#include "views/number_text.h"
#include "views/pixel_history.h"
#include "views/their_colour.h"

namespace rasterlab {

// The images side by side, each under its caption, scaled to fit without smoothing (a pixel
// stays a square); a click picks the pixel under it, marked on every image: on theirs where
// their image holds that pixel's point of the surface (moved, when the diagnosis found it so).
class CompareCanvas : public QWidget {
public:
    explicit CompareCanvas(QWidget* parent = nullptr) : QWidget(parent) {
        setObjectName(QStringLiteral("compareImages"));
        setMinimumSize(240, 160);
        QSizePolicy policy(QSizePolicy::Expanding, QSizePolicy::Preferred);
        policy.setHeightForWidth(true);
        setSizePolicy(policy);
        setCursor(Qt::CrossCursor);
    }
    struct Shown {
        QString caption;
        QImage image;
        bool theirs = false;
    };
    void setImages(QList<Shown> images) {
        m_images = std::move(images);
        update();
    }
    // Our pixel picked, and where their image holds its point.
    void setPicked(QPoint pixel, QPoint theirs) {
        m_picked = pixel;
        m_theirPicked = theirs;
        update();
    }
    // A click: the pixel under it, and whether it is on their image.
    std::function<void(QPoint, bool)> picked;
    QSize sizeHint() const override { return {520, heightForWidth(520)}; }
    // As tall as two images side by side need, whatever the mode: the texts below stay put.
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int width) const override {
        const QSize image = m_images.isEmpty() || m_images.front().image.isNull()
                                ? QSize(4, 3)
                                : m_images.front().image.size();
        return fontMetrics().height() + 4 + (width - kGap) / 2 * image.height() / image.width();
    }
    static constexpr int kGap = 8;

protected:
    void paintEvent(QPaintEvent*) override {
        QPainter p(this);
        m_rects.clear();
        const int n = int(m_images.size());
        if (n == 0) return;
        const int gap = kGap, caption = fontMetrics().height() + 4;
        const int slot = (width() - gap * (n - 1)) / n;
        for (int i = 0; i < n; ++i) {
            const QImage& image = m_images[i].image;
            const QPoint mark = m_images[i].theirs ? m_theirPicked : m_picked;
            const QRect area(i * (slot + gap), caption, slot, height() - caption);
            p.setPen(palette().color(QPalette::WindowText));
            p.drawText(QRect(area.left(), 0, slot, caption), Qt::AlignCenter, m_images[i].caption);
            if (image.isNull() || area.width() <= 0 || area.height() <= 0) continue;
            QSize size = image.size().scaled(area.size(), Qt::KeepAspectRatio);
            QRect target(QPoint(0, 0), size);
            target.moveCenter(area.center());
            target.moveTop(area.top());
            p.drawImage(target, image);
            m_rects.append(target);
            if (mark.x() >= 0 && mark.x() < image.width() && mark.y() >= 0 &&
                mark.y() < image.height()) {
                const double sx = double(target.width()) / image.width();
                const double sy = double(target.height()) / image.height();
                const QPointF c(target.left() + (mark.x() + 0.5) * sx,
                                target.top() + (mark.y() + 0.5) * sy);
                const double r = std::max(4.0, sx);
                p.setPen(QPen(Qt::black, 3));
                p.drawRect(QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r));
                p.setPen(QPen(Qt::white, 1.5));
                p.drawRect(QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r));
            }
        }
    }
    void mousePressEvent(QMouseEvent* event) override {
        for (int i = 0; i < m_rects.size() && i < m_images.size(); ++i) {
            const QRect& r = m_rects[i];
            if (!r.contains(event->position().toPoint())) continue;
            const QSize s = m_images[i].image.size();
            const QPointF at = event->position() - r.topLeft();
            const QPoint pixel(
                std::clamp(int(at.x() * s.width() / r.width()), 0, s.width() - 1),
                std::clamp(int(at.y() * s.height() / r.height()), 0, s.height() - 1));
            if (picked) picked(pixel, m_images[i].theirs);
            return;
        }
    }

private:
    QList<Shown> m_images;
    QList<QRect> m_rects;
    QPoint m_picked{-1, -1}, m_theirPicked{-1, -1};
};

namespace {

std::array<std::uint8_t, 4> bytesAt(const rl::Rgba8Image& image, int x, int y) {
    const std::uint8_t* p = image.pixel(x, y);
    return {p[0], p[1], p[2], p[3]};
}

QString bytesText(const std::array<std::uint8_t, 4>& b) {
    return QStringLiteral("(%1, %2, %3, %4)").arg(b[0]).arg(b[1]).arg(b[2]).arg(b[3]);
}

QString channels(const std::array<int, 4>& v) {
    return ComparePanel::tr("R %1, G %2, B %3, A %4").arg(v[0]).arg(v[1]).arg(v[2]).arg(v[3]);
}

QString channels(const std::array<double, 4>& v) {
    return ComparePanel::tr("R %1, G %2, B %3, A %4")
        .arg(v[0], 0, 'f', 1)
        .arg(v[1], 0, 'f', 1)
        .arg(v[2], 0, 'f', 1)
        .arg(v[3], 0, 'f', 1);
}

}  // namespace

ComparePanel::ComparePanel(Inspection* inspection, QWidget* parent)
    : QWidget(parent), m_inspection(inspection) {
    auto* layout = new QVBoxLayout(this);
    auto* bar = new QHBoxLayout;
    m_mode = new QComboBox;
    m_mode->setObjectName(QStringLiteral("compareMode"));
    m_mode->addItem(tr("Side by side"));
    m_mode->addItem(tr("Flicker"));
    m_mode->addItem(tr("Difference"));
    m_mode->setToolTip(
        tr("Theirs beside ours, one after the other twice a second, or the "
           "pixels that differ"));
    bar->addWidget(m_mode);
    auto* thresholdLabel = new QLabel(tr("Differ by more than"));
    bar->addWidget(thresholdLabel);
    m_threshold = new QSpinBox;
    m_threshold->setObjectName(QStringLiteral("compareThreshold"));
    m_threshold->setRange(0, 255);
    m_threshold->setToolTip(
        tr("The difference view shows the pixels where some channel differs "
           "by more than this (0: every difference)"));
    thresholdLabel->setBuddy(m_threshold);
    bar->addWidget(m_threshold);
    bar->addStretch();
    m_again = new QPushButton(tr("Compare Again"));
    m_again->setObjectName(QStringLiteral("compareAgainButton"));
    m_again->setToolTip(
        tr("The scene changed since the comparison: compare their image with "
           "the scene shown now"));
    m_again->setVisible(false);
    bar->addWidget(m_again);
    m_useFit = new QPushButton(tr("Render Ours with the Fitted Lighting"));
    m_useFit->setObjectName(QStringLiteral("compareUseFitButton"));
    m_useFit->setToolTip(
        tr("Set the light's position, Ia, Il, kd, ks and n to the values fitted to their "
           "colours (one edit, undoable), and render ours with them"));
    m_useFit->setVisible(false);
    bar->addWidget(m_useFit);
    connect(m_useFit, &QPushButton::clicked, this,
            [this] { emit useFittedLighting(fittedSettings()); });
    layout->addLayout(bar);

    m_canvas = new CompareCanvas;
    m_canvas->picked = [this](QPoint pixel, bool onTheirs) {
        m_inspection->pickPixel(onTheirs ? ourPixelOf(pixel) : pixel);
    };
    layout->addWidget(m_canvas);

    const auto textLabel = [layout](const char* name, Qt::TextFormat format) {
        auto* label = new QLabel;
        label->setObjectName(QLatin1String(name));
        label->setWordWrap(true);
        label->setTextFormat(format);
        label->setTextInteractionFlags(Qt::TextSelectableByMouse);
        layout->addWidget(label);
        return label;
    };
    // The diagnosis first, under the images: at 1280x720 the counts below it scroll, the
    // mistake found does not.
    m_diagnosis = textLabel("compareDiagnosis", Qt::RichText);
    m_pixel = textLabel("comparePixel", Qt::PlainText);
    m_summary = textLabel("compareSummary", Qt::PlainText);
    layout->addStretch(1);
    m_summary->setText(
        tr("File > Compare with Image... compares a PNG of your own renderer "
           "with this scene's render."));

    m_flicker.setInterval(kFlickerMs);
    connect(&m_flicker, &QTimer::timeout, this, [this] {
        m_flickerTheirs = !m_flickerTheirs;
        showImages();
    });
    connect(m_mode, &QComboBox::currentIndexChanged, this, [this] {
        m_flickerTheirs = true;
        if (mode() == Mode::Flicker)
            m_flicker.start();
        else
            m_flicker.stop();
        showImages();
    });
    connect(m_threshold, &QSpinBox::valueChanged, this, [this] {
        refreshDifference();
        showImages();
        refreshTexts();
    });
    connect(m_again, &QPushButton::clicked, this, [this] {
        const QString problem = compare(m_path);
        if (!problem.isEmpty() && !m_cancelled) m_summary->setText(problem);
    });
    connect(m_inspection, &Inspection::pixelPicked, this, [this](QPoint pixel) {
        m_canvas->setPicked(pixel, theirPixelOf(pixel));
        refreshPixel();
    });
    connect(m_inspection, &Inspection::frameChanged, this, [this] {
        refreshTexts();
        refreshPixel();
    });
    connect(m_inspection, &Inspection::replayChanged, this, &ComparePanel::refreshPixel);
}

namespace {

// What the worker hands back: our frame, their image as compared, and the diagnosis; or the
// problem that stopped it.
struct CompareOutcome {
    QString problem, provenance;
    std::optional<rl::OurFrame> ours;
    rl::Rgba8Image theirs;
    std::optional<CompareImage::Diagnosis> diagnosis;
};

CompareOutcome compareOnWorker(const std::shared_ptr<const rl::Scene>& scene, const QString& path,
                               rl::Rgba8Image theirs, const CompareImage::Format& format,
                               const QString& commandFile, int imageIndex,
                               const std::atomic<bool>* cancel) {
    CompareOutcome out;
    out.provenance = ComparePanel::tr("Their image: %1.").arg(format.describe());
    auto ours = rl::renderOurFrame(scene);
    if (!ours) {
        out.problem = QString::fromStdString(ours.error().message);
        return out;
    }
    // A screenshot with a window border: the frame found inside it is compared.
    const int theirWidth = theirs.width, theirHeight = theirs.height;
    if (const auto at = CompareImage::cropToFrame(ours->image, theirs))
        out.provenance +=
            QLatin1Char(' ') +
            ComparePanel::tr("Cropped to %1x%2 at (%3, %4) from %5x%6: the frame found inside it.")
                .arg(ours->image.width)
                .arg(ours->image.height)
                .arg(at->x)
                .arg(at->y)
                .arg(theirWidth)
                .arg(theirHeight);
    if (!format.alpha) CompareImage::takeAlpha(ours->image, theirs);
    out.problem = CompareImage::sizeMismatch(path, theirs, ours->image);
    if (!out.problem.isEmpty()) return out;
    auto diagnosis = CompareImage::diagnose(ours.value(), theirs, format, commandFile,
                                            static_cast<std::size_t>(imageIndex), cancel);
    if (!diagnosis) {
        out.problem = QString::fromStdString(diagnosis.error().message);
        return out;
    }
    out.ours = std::move(ours.value());
    out.theirs = std::move(theirs);
    out.diagnosis = std::move(diagnosis.value());
    return out;
}

}  // namespace

QString ComparePanel::compare(const QString& path) {
    const std::shared_ptr<const rl::FrameTrace>& frame = m_inspection->frame();
    if (!frame || !frame->scene) return tr("There is no render to compare with yet.");
    rl::Rgba8Image theirs;
    CompareImage::Format format;
    if (QString problem = CompareImage::read(path, theirs, &format); !problem.isEmpty())
        return problem;
    const auto [commandFile, imageIndex] =
        m_commandFile ? m_commandFile() : std::pair<QString, int>();
    const std::shared_ptr<const rl::Scene> scene = frame->scene;
    // Our render and the diagnosis take seconds on a large image: they run on a worker, and
    // the window keeps painting meanwhile. Its input waits until they end; after a moment a
    // dialog says what runs, with a Cancel that stops the worker and keeps the comparison
    // shown before.
    m_cancelled = false;
    auto cancel = std::make_shared<std::atomic<bool>>(false);
    QApplication::setOverrideCursor(Qt::WaitCursor);
    QFutureWatcher<CompareOutcome> watcher;
    QEventLoop wait;
    connect(&watcher, &QFutureWatcherBase::finished, &wait, &QEventLoop::quit);
    watcher.setFuture(QtConcurrent::run(
        [scene, path, theirs = std::move(theirs), format, commandFile, imageIndex, cancel]() mutable {
            return compareOnWorker(scene, path, std::move(theirs), format, commandFile, imageIndex,
                                   cancel.get());
        }));
    QProgressDialog progress(tr("Comparing %1 with our render...").arg(QFileInfo(path).fileName()),
                             tr("Cancel"), 0, 0, window());
    progress.setObjectName(QStringLiteral("compareProgress"));
    progress.setWindowTitle(tr("Compare with Image"));
    progress.setWindowModality(Qt::ApplicationModal);
    progress.setMinimumDuration(std::numeric_limits<int>::max());  // shown below, not by itself
    progress.reset();
    connect(&progress, &QProgressDialog::canceled, this, [&] {
        cancel->store(true);
        wait.quit();
    });
    QTimer moment;
    moment.setSingleShot(true);
    connect(&moment, &QTimer::timeout, &wait, &QEventLoop::quit);
    moment.start(kProgressAfterMs);
    if (!watcher.isFinished()) wait.exec(QEventLoop::ExcludeUserInputEvents);
    if (!watcher.isFinished()) {
        // Modal: the dialog takes input, the windows behind it none.
        QApplication::restoreOverrideCursor();
        progress.show();
        wait.exec();
        progress.hide();
        QApplication::setOverrideCursor(Qt::WaitCursor);
    }
    // Cancelled: the worker stops at its next check; the window's input waits until then.
    if (!watcher.isFinished()) wait.exec(QEventLoop::ExcludeUserInputEvents);
    watcher.waitForFinished();
    CompareOutcome outcome = watcher.future().takeResult();
    QApplication::restoreOverrideCursor();
    if (cancel->load()) {
        m_cancelled = true;
        return tr("The comparison with %1 was cancelled.").arg(QFileInfo(path).fileName());
    }
    if (!outcome.problem.isEmpty()) return outcome.problem;
    m_path = path;
    m_provenance = outcome.provenance;
    m_scene = scene;
    m_ours = std::make_unique<rl::OurFrame>(std::move(*outcome.ours));
    m_theirs = std::move(outcome.theirs);
    m_comparison = std::make_unique<rl::ImageComparison>(std::move(outcome.diagnosis->comparison));
    m_fit = std::move(outcome.diagnosis->fit);
    m_theirImage = toQImage(m_theirs);
    m_ourImage = toQImage(m_ours->image);
    refreshDifference();
    showImages();
    refreshTexts();
    m_canvas->setPicked(m_inspection->pickedPixel(), theirPixelOf(m_inspection->pickedPixel()));
    refreshPixel();
    emit compared();
    return {};
}

bool ComparePanel::isStale() const {
    return m_comparison && (!m_inspection->frame() || m_inspection->frame()->scene != m_scene);
}

ComparePanel::Mode ComparePanel::mode() const {
    return static_cast<Mode>(m_mode->currentIndex());
}

void ComparePanel::setMode(Mode mode) {
    m_mode->setCurrentIndex(static_cast<int>(mode));
}

int ComparePanel::threshold() const {
    return m_threshold->value();
}

void ComparePanel::setThreshold(int threshold) {
    m_threshold->setValue(threshold);
}

void ComparePanel::refreshDifference() {
    m_aboveThreshold = 0;
    if (!m_comparison) return;
    // The comparison's own difference image where a pixel differs by more than the threshold,
    // ours darkened as it darkens the others.
    rl::Rgba8Image shown = m_comparison->differenceImage;
    const int limit = threshold();
    for (int y = 0; y < shown.height; ++y) {
        for (int x = 0; x < shown.width; ++x) {
            const auto a = bytesAt(m_ours->image, x, y), b = bytesAt(m_theirs, x, y);
            int d = 0;
            for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
            if (d > limit) {
                ++m_aboveThreshold;
            } else {
                std::uint8_t* p =
                    shown.rgba.data() + (std::size_t(y) * std::size_t(shown.width) + x) * 4;
                for (int c = 0; c < 3; ++c) p[c] = std::uint8_t(a[c] / 3);
                p[3] = 255;
            }
        }
    }
    m_difference = toQImage(shown);
}

void ComparePanel::showImages() {
    if (!m_comparison) {
        m_canvas->setImages({});
        return;
    }
    switch (mode()) {
        case Mode::SideBySide:
            m_canvas->setImages({{tr("Theirs"), m_theirImage, true}, {tr("Ours"), m_ourImage, false}});
            break;
        case Mode::Flicker:
            m_canvas->setImages({{m_flickerTheirs ? tr("Theirs") : tr("Ours"),
                                  m_flickerTheirs ? m_theirImage : m_ourImage, m_flickerTheirs}});
            break;
        case Mode::Difference:
            m_canvas->setImages(
                {{tr("%n pixel(s) differ by more than %1", "", int(m_aboveThreshold))
                      .arg(threshold()),
                  m_difference, false}});
            break;
    }
}

QPoint ComparePanel::theirPixelOf(QPoint ours) const {
    const auto move = m_comparison ? rl::dominantMove(*m_comparison) : std::nullopt;
    if (!move) return ours;
    const rl::dvec2 q = move->theirPoint({ours.x() + 0.5, ours.y() + 0.5});
    return QPoint(int(std::floor(q.x)), int(std::floor(q.y)));
}

QPoint ComparePanel::ourPixelOf(QPoint theirs) const {
    const auto move = m_comparison ? rl::dominantMove(*m_comparison) : std::nullopt;
    if (!move || !(std::abs(move->determinant()) > 1e-12)) return theirs;
    const rl::dvec2 q = move->ourPoint({theirs.x() + 0.5, theirs.y() + 0.5});
    return QPoint(int(std::floor(q.x)), int(std::floor(q.y)));
}

QString ComparePanel::summaryText() const {
    return m_summary->text();
}

QString ComparePanel::diagnosisText() const {
    QTextDocument doc;
    doc.setHtml(m_diagnosis->text());
    return doc.toPlainText();
}

QString ComparePanel::fittedName(const std::string& name) {
    // The fit's value names (lighting_fit.cpp), in the user's language.
    static const char* const names[] = {
        QT_TR_NOOP("light x (view)"),     QT_TR_NOOP("light y (view)"),
        QT_TR_NOOP("light z (view)"),     QT_TR_NOOP("n"),
        QT_TR_NOOP("ambient Ia*ka R"),    QT_TR_NOOP("ambient Ia*ka G"),
        QT_TR_NOOP("ambient Ia*ka B"),    QT_TR_NOOP("diffuse Il*Od*kd R"),
        QT_TR_NOOP("diffuse Il*Od*kd G"), QT_TR_NOOP("diffuse Il*Od*kd B"),
        QT_TR_NOOP("specular Il*ks R"),   QT_TR_NOOP("specular Il*ks G"),
        QT_TR_NOOP("specular Il*ks B"),
    };
    for (const char* known : names)
        if (name == known) return tr(known);
    return QString::fromStdString(name);
}

std::vector<ComparePanel::FittedSetting> ComparePanel::fittedSettings() const {
    if (!m_ours || !m_fit.fitted || !m_ours->trace->cameraBasis) return {};
    const auto fitted = rl::sceneWithFit(*m_ours->trace->scene, *m_ours->trace->cameraBasis, m_fit);
    const rl::Light& light = fitted->lights.front();
    const auto draw = std::find_if(
        fitted->draws.begin(), fitted->draws.end(),
        [](const rl::Draw& d) { return d.lighting == rl::LightingModel::CoursePhong; });
    if (draw == fitted->draws.end()) return {};
    const rl::Material& m = draw->material;
    const auto triple = [](const auto& v) { return SceneDocument::Numbers{v[0], v[1], v[2]}; };
    using Field = SceneDocument::Field;
    return {{Field::LightPosition, 0, triple(rl::dvec3(light.pWorld) / light.pWorld.w)},
            {Field::LightIntensity, 0, triple(light.intensity)},
            {Field::Ambient, 0, triple(fitted->ambientIntensity)},
            {Field::Kd, 0, triple(m.kd)},
            {Field::Ks, 0, {m.ks, 0.0, 0.0}},
            {Field::Shininess, 0, {m.shininess, 0.0, 0.0}},
            {Field::Emission, 0, triple(m.emission)}};
}

QString ComparePanel::pixelText() const {
    return m_pixel->text();
}

void ComparePanel::refreshTexts() {
    m_again->setVisible(isStale());
    m_useFit->setVisible(m_comparison && m_fit.explainsBetter() && !isStale() &&
                         !(m_commandFile && !m_commandFile().first.isEmpty()));
    if (!m_comparison) return;
    const rl::ImageComparison& c = *m_comparison;
    QStringList summary;
    summary << tr("%1 against our render (%2x%3): %4 pixels compared, %5 differ (%6%).")
                   .arg(QFileInfo(m_path).fileName())
                   .arg(c.width)
                   .arg(c.height)
                   .arg(c.compared)
                   .arg(c.differing)
                   .arg(100.0 * double(c.differing) / double(c.compared), 0, 'f', 1);
    summary << m_provenance;
    if (c.unlit)
        summary << tr("Their image is unlit: one colour %1 wherever it covers. Only coverage is "
                      "compared (our covered pixels in that colour), and only projection and "
                      "scan conversion mistakes are tried.")
                       .arg(bytesText(c.unlitColour));
    if (c.unlitWhite())
        summary << tr("White wherever it covers is also what a lit image becomes with every "
                      "colour multiplied by 255 (a colour scaled by 255 where it was already "
                      "0..255).");
    if (c.differing > 0) {
        summary << tr("Largest difference per channel: %1.").arg(channels(c.largest));
        summary << tr("Mean difference per channel, over the differing pixels: %1.")
                       .arg(channels(c.mean));
        summary << tr("Pixels covered: %1 by both, %2 only by ours (our depth buffer), %3 only "
                      "by theirs (not the background).")
                       .arg(c.coveredByBoth)
                       .arg(c.onlyOurs)
                       .arg(c.onlyTheirs);
    }
    if (isStale())
        summary << tr(
            "The scene has changed since this comparison: Compare Again compares "
            "their image with the scene shown now.");
    m_summary->setText(summary.join(QLatin1Char('\n')));

    QString html;
    if (c.differing == 0) {
        html = tr("The images are the same.").toHtmlEscaped();
    } else if (c.diagnosis.empty()) {
        html = tr("Diagnosis: none of the mistakes RasterLab knows explains these differences.")
                   .toHtmlEscaped();
    } else {
        html = QStringLiteral("<p><b>%1</b></p>")
                   .arg(tr("Diagnosis, each mistake applied before the next is ranked:"));
        int rank = 0;
        for (const rl::Finding& f : c.diagnosis) {
            html += QStringLiteral("<p><b>%1. %2</b><br>%3<br>%4<br>%5")
                        .arg(++rank)
                        .arg(translated(f.title).toHtmlEscaped(),
                             tr("Removes %1% of the difference; makes %2 differing pixels "
                                "match.")
                                 .arg(100.0 * f.share, 0, 'f', 1)
                                 .arg(f.explained)
                                 .toHtmlEscaped(),
                             tr("Evidence: %1").arg(translated(f.evidence)).toHtmlEscaped(),
                             tr("Check: %1").arg(translated(f.advice)).toHtmlEscaped());
            for (const rl::PixelExample& e : f.examples)
                html += QStringLiteral("<br>") + tr("At (%1, %2): ours %3, theirs %4")
                                                     .arg(e.x)
                                                     .arg(e.y)
                                                     .arg(bytesText(e.ours), bytesText(e.theirs))
                                                     .toHtmlEscaped();
            html += QStringLiteral("</p>");
        }
    }
    if (c.differing > 0) {
        html += QStringLiteral("<p><b>%1</b>")
                    .arg(tr("Unexplained: %1% of the difference; %2 pixels still differ with "
                            "every mistake above applied.")
                             .arg(100.0 * c.unexplained, 0, 'f', 1)
                             .arg(c.unexplainedPixels)
                             .toHtmlEscaped());
        if (c.mostlyUnexplained())
            html +=
                QStringLiteral("<br>") +
                tr("None of the known mistakes explains most of this difference.").toHtmlEscaped();
        html += QStringLiteral("</p>");
    }
    if (m_fit.fitted) {
        html += QStringLiteral("<p><b>%1</b><br>%2")
                    .arg(tr("Lighting fitted to their colours").toHtmlEscaped(),
                         (m_fit.carriedBack
                              ? tr("%1 pixels inside triangles, their image carried back onto "
                                   "ours by the move above: rms %2 with ours, %3 fitted.")
                              : tr("%1 pixels inside triangles: rms %2 with ours, %3 fitted."))
                             .arg(m_fit.samples)
                             .arg(m_fit.rmsOurs, 0, 'f', 1)
                             .arg(m_fit.rmsFitted, 0, 'f', 1)
                             .toHtmlEscaped());
        for (const rl::FittedValue& v : m_fit.values)
            if (v.apart)
                html += QStringLiteral("<br>") + tr("%1: theirs %2 ± %3, ours %4")
                                                     .arg(fittedName(v.name))
                                                     .arg(v.theirs, 0, 'g', 4)
                                                     .arg(v.uncertainty, 0, 'g', 2)
                                                     .arg(v.ours, 0, 'g', 4)
                                                     .toHtmlEscaped();
        for (const rl::Message& m : m_fit.findings)
            html += QStringLiteral("<br>") + translated(m).toHtmlEscaped();
        html += QStringLiteral("</p>");
    }
    m_diagnosis->setText(html);
    showImages();
}

void ComparePanel::refreshPixel() {
    const QPoint p = m_inspection->pickedPixel();
    if (!m_comparison || p.x() < 0 || p.x() >= m_theirs.width || p.y() < 0 ||
        p.y() >= m_theirs.height) {
        m_pixel->setText(m_comparison ? tr("Pick a pixel (here or on the image) to see their "
                                           "colour beside ours.")
                                      : QString());
        return;
    }
    const auto ours = bytesAt(m_ours->image, p.x(), p.y());
    QStringList lines;
    // Their image moved first of all: their colour of this point of the surface is where the
    // move takes it.
    const QPoint there = theirPixelOf(p);
    if (rl::dominantMove(*m_comparison)) {
        if (there.x() < 0 || there.x() >= m_theirs.width || there.y() < 0 ||
            there.y() >= m_theirs.height) {
            m_pixel->setText(tr("Their image is moved (the first finding): this pixel's point of "
                                "the surface is outside it."));
            return;
        }
        lines << tr("Their image is moved (the first finding): this pixel's point of the surface "
                    "is their pixel (%1, %2).")
                     .arg(there.x())
                     .arg(there.y());
    }
    const auto theirs = bytesAt(m_theirs, there.x(), there.y());
    lines << tr("Pixel (%1, %2): theirs %3, ours %4.")
                 .arg(p.x())
                 .arg(p.y())
                 .arg(bytesText(theirs), bytesText(ours));
    QStringList changes;
    for (int c = 0; c < 4; ++c) {
        const int d = int(theirs[c]) - int(ours[c]);
        if (d < 0) changes << tr("minus %1 in %2").arg(-d).arg(TheirColourTerms::channelName(c));
        if (d > 0) changes << tr("plus %1 in %2").arg(d).arg(TheirColourTerms::channelName(c));
    }
    if (changes.isEmpty()) {
        lines << tr("Their colour is ours.");
        m_pixel->setText(lines.join(QLatin1Char('\n')));
        return;
    }
    lines << tr("Their colour is ours %1.").arg(TheirColourTerms::listText(changes));
    if (isStale()) {
        lines << tr(
            "The scene has changed since the comparison: the lighting shown now is not "
            "the one compared.");
        m_pixel->setText(lines.join(QLatin1Char('\n')));
        return;
    }
    // The lighting of the fragment that holds the pixel at the end of the frame.
    PixelHistory history;
    history.rebuild(*m_inspection);
    if (history.rows().empty()) {
        lines << history.verdict();
    } else if (!m_ours->covered(p.x(), p.y())) {
        lines << tr("No triangle of ours covers this pixel: it is the background.");
    } else if (const auto b = rowBreakdown(*m_inspection, history,
                                           static_cast<int>(history.rows().size()) - 1);
               !b) {
        lines << tr("The lighting of this pixel is not known.");
    } else if (!TheirColourTerms::workedOutFor(*b)) {
        lines << tr(
            "The terms that would have to change are worked out for the course's "
            "lighting model in flat or Phong shading; this pixel is shaded otherwise "
            "(the pixel inspector shows how).");
    } else {
        lines << TheirColourTerms::lines(*b, theirs, m_scene->conventions.colourScale);
    }
    m_pixel->setText(lines.join(QLatin1Char('\n')));
}

}  // namespace rasterlab
