#include "explained_view.h"

#include <QLabel>
#include <QTextBrowser>

#include <algorithm>

#include "pipeline/stages/scan_conversion.h"
#include "views/inspection.h"
#include "views/on_screen.h"
#include "views/view_font.h"

namespace rasterlab {

ExplainedView::ExplainedView(Inspection* inspection, const QString& name, QWidget* parent)
    : QWidget(parent), m_inspection(inspection) {
    setObjectName(name + QStringLiteral("View"));
    m_title = new QLabel(this);
    m_title->setObjectName(name + QStringLiteral("Title"));
    m_title->setWordWrap(true);
    m_title->setTextFormat(Qt::RichText);
    m_text = new QTextBrowser(this);
    m_text->setObjectName(name + QStringLiteral("Explanation"));
    m_text->setOpenLinks(false);
    const auto follow = [this] {
        m_stale = !onScreen(this);
        if (!m_stale) refresh();
    };
    // A new frame: the view's own reset only. Inspection::setFrame emits cursorChanged and
    // selectionChanged after frameChanged (from nothing else), and those refresh.
    connect(m_inspection, &Inspection::frameChanged, this, [this] { frameChanged(); });
    connect(m_inspection, &Inspection::replayChanged, this, follow);
    connect(m_inspection, &Inspection::cursorChanged, this, follow);
    // (A pixel picked selects its triangle: selectionChanged follows pixelPicked.)
    connect(m_inspection, &Inspection::selectionChanged, this, follow);
    connect(m_inspection, &Inspection::presentationChanged, this, [this] {
        updateFonts();
        presentationChanged();
    });
    updateFonts();
}

QString ExplainedView::explanationText() const {
    return m_text->toPlainText();
}

void ExplainedView::presentationChanged() {
    m_stale = !onScreen(this);
    if (!m_stale) refresh();
}

void ExplainedView::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    m_stale = false;
    refresh();
}

bool ExplainedView::event(QEvent* event) {
    if (event->type() == kRaisedEvent && m_stale) {
        m_stale = false;
        refresh();
        return true;
    }
    return QWidget::event(event);
}

bool ExplainedView::setExplanation(QString html) {
    if (html == m_html) return false;
    m_html = std::move(html);
    m_text->setHtml(m_html);
    return true;
}

void ExplainedView::updateFonts() {
    const QFont font = scaledFont(this, m_inspection->textScale(1.5));
    m_text->setFont(font);
    m_title->setFont(font);
}

std::optional<FollowedRow> followedRow(const Inspection& inspection) {
    const std::shared_ptr<const rl::FrameTrace>& frame = inspection.frame();
    if (!frame || !frame->scene || !frame->projection) return std::nullopt;
    if (const rl::ReplayRow* row = inspection.currentRow();
        inspection.canStep() && row && !inspection.atEnd()) {
        FollowedRow f{row->triangle, row->y, std::nullopt, true};
        if (const std::optional<std::uint32_t> fragment = inspection.currentFragment())
            f.pixel = inspection.replay()->fragments()[*fragment].x;
        return f;
    }
    const std::optional<std::uint32_t> t = inspection.selectedTriangle();
    const rl::Projection& projection = *frame->projection;
    if (!t || *t >= projection.triangles.size()) return std::nullopt;
    const rl::Scene& scene = *frame->scene;
    const rl::TriangleSetup s =
        rl::setupTriangle(rl::screenVertices(projection, projection.triangles[*t]), scene.rules);
    const ScreenRows rows = screenRows(s, scene.height);
    const QPoint picked = inspection.pickedPixel();
    const bool pickedRow = rows.contains(picked.y());
    FollowedRow f{*t, pickedRow ? picked.y() : (rows.first + rows.last) / 2, std::nullopt, false};
    if (pickedRow) {
        const rl::ScanRow row = rl::scanRow(s, scene.rules, picked.y(), scene.width);
        if (picked.x() >= row.xBegin && picked.x() < row.xEnd) f.pixel = picked.x();
    }
    return f;
}

ScreenRows screenRows(const rl::TriangleSetup& s, int height) {
    const int first = std::max(s.yFirst, 0);
    return {first, s.degenerate() ? first - 1 : std::min(s.yLast, height - 1)};
}

}  // namespace rasterlab
