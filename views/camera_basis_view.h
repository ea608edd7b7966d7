// Stage 1's view: Gram-Schmidt turns the course camera (C, N, V) into the orthonormal basis
// U, V, N of view space. A 3D drawing of world space (the world axes, the camera, the vectors
// given and made, the view frustum, the mesh as a point cloud) that an orbit camera turns,
// the four steps revealed one at a time with their numbers, the matrix viewFromWorld, the
// orthonormality residuals, and what makes the basis unusable (no course camera, N nearly
// parallel to V, a camera rejected with an error).
#pragma once

#include <QColor>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <vector>

#include "pipeline/stages/camera_basis.h"
#include "views/painted_labels.h"

class QFontMetricsF;
class QLabel;
class QSlider;
class QSplitter;
class QTextBrowser;
class QToolButton;

namespace rasterlab {

class Inspection;
class KeyFigures;

// Below this |V - (V.N) N| / |V|, what is left of V after removing its N part is so small
// that rounding in V or N turns U and V noticeably: the basis is ill-conditioned.
inline constexpr double kIllConditionedRatio = 1e-3;

// What the 3D drawing shows, in world space, for the steps revealed so far.
struct CameraBasisPicture {
    bool valid = false;  // a basis (or at least the camera's inputs) to draw
    int step = 4;        // 0: the inputs only; 4: the whole basis and the frustum
    rl::CameraBasis basis;
    double d = 1.0, hx = 1.0, hy = 1.0;
    std::vector<rl::dvec3> cloud;  // mesh vertices in world space, subsampled
    rl::dvec3 centre = rl::dvec3(0.0);
    double radius = 1.0;       // of the sphere around centre holding the cloud and C
    double vectorScale = 1.0;  // world length of a unit vector's arrow
    // World length per unit of the given N, and of the given V with its parts (V.N) N and
    // V': their own lengths when readable, else brought to between 0.4 and 2.5 units so
    // that a camera file's |N| = 500 neither hides the unit vectors nor leaves the picture.
    double nGivenScale = 1.0, vGivenScale = 1.0;
    double frustumDepth = 0.0;  // how far along N the frustum's edges are drawn on
};

// The world-space drawing with an orbit camera: drag to turn, wheel to zoom, double-click
// to reset. Its labels keep off one another and off the Reset view button.
class CameraBasisCanvas : public QWidget, public PaintedLabels {
    Q_OBJECT
public:
    explicit CameraBasisCanvas(QWidget* parent = nullptr);

    void setPicture(CameraBasisPicture picture);
    const CameraBasisPicture& picture() const { return m_picture; }
    void setStep(int step);  // the picture's step
    // Shown in place of the drawing (a skipped stage or a camera error); "" for none.
    void setMessage(const QString& message);
    QString message() const { return m_message; }
    void setLineWidth(double width);

    // The names of what the last paint drew ("axes", "C", "N given", "V given", "N",
    // "(V.N) N", "V'", "V", "U", "window", "frustum", "cloud"), in drawing order.
    const QStringList& drawnItems() const { return m_drawn; }
    int cloudPointCount() const { return static_cast<int>(m_picture.cloud.size()); }
    // Each label of the last paint: the point it names and where it went (a leader line
    // joins them when the labels before pushed it more than 12 px away).
    struct PlacedLabel {
        QString text;
        QPointF anchor;
        QRectF box;
        QColor colour;
    };
    const QList<PlacedLabel>& placedLabels() const { return m_placed; }

    double yaw() const { return m_yaw; }
    double pitch() const { return m_pitch; }
    double zoom() const { return m_zoom; }
    void setOrbit(double yaw, double pitch, double zoom);
    // The widget position of a world point, under the current orbit.
    QPointF toWidget(const rl::dvec3& pWorld) const;

    QSize sizeHint() const override { return {520, 420}; }

public slots:
    void resetOrbit();

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    // The orbit's frame: up is the world axis nearest the camera's V (so the scene stands
    // as the camera sees it), forward the horizontal part of -N (we start behind the camera).
    void orbitFrame(rl::dvec3& right, rl::dvec3& up, rl::dvec3& back) const;
    // World points to the widget under the current orbit, worked out once for many points.
    struct Projector {
        rl::dvec3 centre, eye, screenRight, screenUp;
        double distance = 1.0, scale = 1.0;
        QPointF middle;
        QPointF operator()(const rl::dvec3& pWorld) const;
    };
    Projector projector() const;
    // Labels are placed after everything is drawn, the lowest rank first, so that the
    // vectors of the step shown keep the places at their tips and no line crosses a label.
    enum class LabelRank { Camera, Basis, Given, Frustum, Axes };
    struct PendingLabel {
        QPointF at, awayFrom;
        QString text;
        QColor colour;
        LabelRank rank;
    };
    // A label beside a point, pushed away from where the arrow came from, and moved to a
    // free place nearby when the labels placed before (or the button) are there; a leader
    // line then joins it to its point. Placed only: drawLabels() draws them all, every
    // leader line first, so that none crosses a label.
    void placeLabel(const QFontMetricsF& metrics, const PendingLabel& label);
    void drawLabels(QPainter& painter) const;

    CameraBasisPicture m_picture;
    QToolButton* m_reset = nullptr;
    QString m_message;
    QStringList m_drawn;
    QList<PlacedLabel> m_placed;
    double m_lineWidth = 1.5;
    double m_yaw = 0.0, m_pitch = 0.0, m_zoom = 1.0;
    bool m_dragging = false;
    QPoint m_dragStart;
    double m_yawAtDragStart = 0.0, m_pitchAtDragStart = 0.0;
};

class CameraBasisView : public QWidget {
    Q_OBJECT
public:
    explicit CameraBasisView(Inspection* inspection, QWidget* parent = nullptr);

    // Shows a camera rejected by the stage (file:line:col: message) in place of the numbers,
    // until the next frame.
    void setError(const QString& message);

    // The Gram-Schmidt step shown, 0 (the inputs) to 4 (U made).
    int step() const { return m_step; }
    void setStep(int step);

    // The texts of the steps revealed so far ("1. N := N / |N| = ..."), one per step.
    QStringList stepTexts() const;
    // "U·V = 0, U·N = 0, ...; largest 2.2e-16", "" without a basis.
    QString residualText() const { return m_residualText; }
    // viewFromWorld, row by row, numbers separated by spaces, rows by newlines.
    QString matrixText() const { return m_matrixText; }
    // Why there are no numbers (skipped, the camera's error) or why to distrust them
    // (ill-conditioned); "" when all is well.
    QString statusText() const { return m_statusText; }
    bool illConditioned() const { return m_illConditioned; }
    double conditionRatio() const { return m_conditionRatio; }  // |V - (V.N) N| / |V|
    QString explanationHtml() const { return m_explanationHtml; }
    CameraBasisCanvas* canvas() const { return m_canvas; }

protected:
    void showEvent(QShowEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void refresh();
    void showStep();
    void applyPresentation();

    Inspection* m_inspection = nullptr;
    bool m_dirty = true;
    int m_step = 4;
    QString m_error;
    QStringList m_allSteps;
    QString m_residualText, m_matrixText, m_statusText, m_explanationHtml;
    bool m_illConditioned = false;
    double m_conditionRatio = 1.0;

    QSplitter* m_splitter = nullptr;
    bool m_splitterPlaced = false;
    CameraBasisCanvas* m_canvas = nullptr;
    QSlider* m_stepSlider = nullptr;
    QToolButton* m_back = nullptr;
    QToolButton* m_forward = nullptr;
    QLabel* m_stepLabel = nullptr;
    QString m_matrixHtml;
    // The steps, the status, the matrix, the residuals and the explanation, in one page.
    QTextBrowser* m_text = nullptr;
    KeyFigures* m_figures = nullptr;  // the step's numbers, large
    QStringList m_allFigures;         // for each step, 0 to 4
};

}  // namespace rasterlab
