// Seed 004's painter's algorithm beside the z-buffer. The scene of the frame shown is rendered
// both ways (rl::compareWithZBuffer: the same flat colours, one painted far to near without a
// depth test, one with it), whatever shading the frame itself uses; a flat frame is the
// z-buffer's render already, and is not rendered again:
//  - the sort order: the triangles in painted order with their barycentre's distance, and an
//    image of each pixel's painted rank (far blue, near red);
//  - the painter's image and the z-buffer's side by side, the pixels where they differ
//    marked: red where a farther triangle was painted after a nearer one, yellow where two
//    triangles are as near (an edge they share: the z-buffer keeps the first drawn, the
//    painter the last);
//  - the explanation, with the numbers of the frame and of the selected triangle.
// Selecting a row selects the triangle in Inspection (every view follows); the two renders
// run only while the view is shown.
#pragma once

#include <QWidget>

#include <memory>
#include <optional>

#include "pipeline/analysis/painter.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QSplitter;
class QTableView;

namespace rasterlab {

class FrameImageView;
class Inspection;
class PainterOrderModel;

class PainterView : public QWidget {
    Q_OBJECT

public:
    explicit PainterView(Inspection* inspection, QWidget* parent = nullptr);

    // The comparison of the frame shown, or null (no frame, or not worked out yet).
    const rl::PainterComparison* comparison() const { return m_comparison.get(); }
    QString explanation() const;
    // The painted rank of triangle t of the frame shown, and back.
    std::optional<std::uint32_t> rankOf(std::uint32_t frameTriangle) const;
    std::optional<std::uint32_t> frameTriangleOf(std::uint32_t rank) const;
    QTableView* orderTable() const { return m_table; }
    FrameImageView* painterImageView() const { return m_painterImage; }
    FrameImageView* zBufferImageView() const { return m_zBufferImage; }
    // The left image: 0 the painter's image, 1 the painted order.
    void setLeftImage(int which);

protected:
    void showEvent(QShowEvent* event) override;
    void changeEvent(QEvent* event) override;
    bool event(QEvent* event) override;  // kRaisedEvent (on_screen.h)

private:
    void recompute();
    void refreshWhenShown();
    void showSelection();
    void showImages();
    void applyPresentation();
    void makeMask();  // the differences as a translucent overlay

    Inspection* m_inspection = nullptr;
    std::shared_ptr<const rl::PainterComparison> m_comparison;
    std::weak_ptr<const rl::FrameTrace> m_comparedFrame;
    QString m_error;
    std::vector<std::uint32_t> m_zBufferPixels;  // per rank: pixels the z-buffer shows it at
    bool m_following = false;  // the table follows Inspection's selection
    bool m_splitSet = false;
    QSplitter* m_split = nullptr;
    QCheckBox* m_marksTies = nullptr;
    QLabel* m_explanation = nullptr;
    QLabel* m_painterCaption = nullptr;
    QLabel* m_zBufferCaption = nullptr;
    QComboBox* m_leftChoice = nullptr;
    QTableView* m_table = nullptr;
    PainterOrderModel* m_model = nullptr;
    FrameImageView* m_painterImage = nullptr;
    FrameImageView* m_zBufferImage = nullptr;
    QImage m_painted, m_order, m_zImage, m_mask;
};

}  // namespace rasterlab
