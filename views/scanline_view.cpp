#include "scanline_view.h"

#include <QEvent>
#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <vector>

#include "pipeline/stages/dda.h"
#include "pipeline/stages/depth_test.h"
#include "pipeline/stages/scan_conversion.h"
#include "pipeline/stages/shading.h"
#include "views/inspection.h"
#include "views/number_text.h"
#include "views/painted_labels.h"
#include "views/view_font.h"

namespace rasterlab {

namespace {

// number(), with infinities written "+inf" and "-inf".
QString num(double v, int precision = 6) {
    if (std::isinf(v)) return v > 0 ? QStringLiteral("+inf") : QStringLiteral("-inf");
    return number(v, precision);
}

// The fewest rows and columns drawn (when the screen has them), and the smallest pixel
// square: a triangle whose box needs smaller ones is shown through a window around the
// scanline instead.
constexpr int kMinRows = 7, kMinColumns = 9;
constexpr double kMinCell = 6.0;

// [lo, hi] grown to at least n around c, or cut to at most n around c, within [0, limit).
std::pair<int, int> windowRange(int lo, int hi, int c, int minimum, int maximum, int limit) {
    if (hi - lo + 1 > maximum) {
        lo = std::clamp(c - maximum / 2, lo, hi - maximum + 1);
        hi = lo + maximum - 1;
    }
    while (hi - lo + 1 < minimum && (lo > 0 || hi < limit - 1)) {
        if (lo > 0) --lo;
        if (hi - lo + 1 < minimum && hi < limit - 1) ++hi;
    }
    return {lo, hi};
}

// The pixels drawn: the triangle's box grown by a pixel, or, when more than maxRows rows or
// maxColumns columns, a window of them around the scanline and the span (or the pixel at
// the cursor when the span is wider).
QRect windowOf(const ScanlineModel& m, int width, int height, int maxColumns, int maxRows) {
    double xMin = m.setup.sorted[0].x, xMax = xMin;
    for (const rl::dvec2& p : m.setup.sorted) {
        xMin = std::min(xMin, p.x);
        xMax = std::max(xMax, p.x);
    }
    const auto clampTo = [](double v, int limit) {
        return static_cast<int>(std::clamp(v, 0.0, double(limit - 1)));
    };
    int left = clampTo(std::floor(xMin) - 1.0, width);
    int right = clampTo(std::ceil(xMax) + 1.0, width);
    int top = clampTo(std::floor(m.setup.sorted[0].y) - 1.0, height);
    int bottom = clampTo(std::ceil(m.setup.sorted[2].y) + 1.0, height);
    const int cy = m.row ? m.row->y : (m.rows.first + m.rows.last) / 2;
    int cx = (left + right) / 2;
    const bool spanFits = m.row && !m.row->empty() && m.row->xEnd - m.row->xBegin + 2 <= maxColumns;
    if (spanFits)
        cx = (m.row->xBegin + m.row->xEnd - 1) / 2;
    else if (m.currentPixel)
        cx = *m.currentPixel;
    else if (m.row && !m.row->empty())
        cx = (m.row->xBegin + m.row->xEnd - 1) / 2;
    maxRows = std::max(maxRows, kMinRows);
    maxColumns = std::max(maxColumns, kMinColumns);
    std::tie(top, bottom) = windowRange(top, bottom, cy, kMinRows, maxRows, height);
    std::tie(left, right) = windowRange(left, right, cx, kMinColumns, maxColumns, width);
    return QRect(left, top, right - left + 1, bottom - top + 1);
}

}  // namespace

SpanEnd spanEnd(const rl::FrameTrace& frame, std::uint32_t triangle, int y, int xBegin, int x) {
    const rl::Scene& scene = *frame.scene;
    const rl::Projection& projection = *frame.projection;
    const rl::ScreenTriangle& tri = projection.triangles[triangle];
    const double offset = scene.rules.sampleOffset;
    // The depth test's numbers (depth_test.h).
    const rl::FragmentDepth fragment = rl::fragmentDepth(scene, projection, triangle, y, xBegin, x);
    SpanEnd out;
    out.x = x;
    out.y = y;
    out.sample = rl::dvec2(x + offset, y + offset);
    out.beta = fragment.beta;
    out.gamma = fragment.gamma;
    out.alpha = 1.0f - out.beta - out.gamma;
    out.depth = fragment.depth;

    // The normal shading interpolates with these barycentrics (shading.h).
    if (frame.normals && !frame.normals->skipped && tri.draw < frame.normals->draws.size()) {
        const rl::DrawNormals& normals = frame.normals->draws[tri.draw];
        rl::vec3 n(0.0f);
        if (scene.draws[tri.draw].flatNormals) {
            n = normals.triangle[tri.source];
        } else {
            const rl::DrawProjection& draw = projection.draws[tri.draw];
            float beta = out.beta, gamma = out.gamma;
            rl::attributeWeights(scene.rules, draw, tri.v, beta, gamma);
            n = rl::interpolate(rl::ProjectedValues<rl::vec3>{normals.vertex, draw}, tri.v, beta,
                                gamma);
        }
        const float length = glm::length(n);
        out.hasNormal = true;
        out.normal = length > 0.0f ? n * (1.0f / length) : rl::vec3(0.0f);
    }
    return out;
}

ScanlineModel scanlineModel(const rl::FrameTrace& frame, std::uint32_t triangle,
                            std::optional<int> y) {
    const rl::Scene& scene = *frame.scene;
    const rl::RasterRules& rules = scene.rules;
    ScanlineModel m;
    m.triangle = triangle;
    m.setup = rl::setupTriangle(
        rl::screenVertices(*frame.projection, frame.projection->triangles[triangle]), rules);
    const rl::TriangleSetup& s = m.setup;
    const int upperLast = rl::lastUpperRow(s, rules);
    const bool dda = rules.scan == rl::RasterRules::Scan::Dda;
    // The edges' ends as the walk sees them: the vertices sorted by y.
    const std::array<const rl::ScanEdge*, 3> edges{&s.longEdge, &s.upperEdge, &s.lowerEdge};
    const std::array<std::pair<std::size_t, std::size_t>, 3> ends{
        std::pair<std::size_t, std::size_t>{0, 2}, {0, 1}, {1, 2}};
    for (std::size_t k = 0; k < 3; ++k) {
        const rl::ScanEdge& e = *edges[k];
        ScanEdgeEntry& entry = m.edges[k];
        entry.top = s.sorted[ends[k].first];
        entry.bottom = s.sorted[ends[k].second];
        entry.dxdy = e.dxdy();
        entry.horizontal = dda ? !(entry.top.y < entry.bottom.y) : e.yTop == e.yBottom;
        entry.onLeft = (k == 0) == s.longEdgeOnLeft;
        if (s.degenerate()) continue;  // not walked
        switch (k) {
            case 0:
                entry.firstRow = s.yFirst;
                entry.lastRow = s.yLast;
                break;
            case 1:
                entry.firstRow = s.yFirst;
                entry.lastRow = upperLast;
                break;
            default:  // none when the bottom is flat: then upperLast is the last row
                entry.firstRow = std::max(s.yFirst, upperLast + 1);
                entry.lastRow = s.yLast;
                break;
        }
        if (entry.horizontal) entry.lastRow = entry.firstRow - 1;
        if (dda) {
            // Seed 001's DDA: the edge's own dx/dy in double, and its x on its first row on
            // the screen, where the walk starts.
            const rl::DdaEdge d = rl::ddaEdge(entry.top, entry.bottom);
            entry.dxdy = d.dxdy;
            entry.firstRow = std::max(entry.firstRow, d.y);
            entry.xFirstRow = entry.walked() ? d.x : entry.top.x;
        } else {
            entry.xFirstRow =
                entry.walked() ? rl::edgeCrossing(e, rules, entry.firstRow) : entry.top.x;
        }
    }
    m.rows = screenRows(s, scene.height);
    if (!y || !m.rows.contains(*y)) return m;

    ScanRowInfo row;
    static_cast<rl::ScanRow&>(row) = rl::scanRow(s, rules, *y, scene.width);
    if (!row.empty()) {
        row.first = spanEnd(frame, triangle, *y, row.xBegin, row.xBegin);
        row.last = spanEnd(frame, triangle, *y, row.xBegin, row.xEnd - 1);
    }
    m.row = row;
    return m;
}

// The triangle on the pixel grid around the scanline: the pixels written so far in their
// colour, the span's pixels, the sample points, the three edges, the scanline and its
// crossings. Each square is a pixel, drawn around its sample point.
class ScanlineCanvas : public QWidget, public PaintedLabels {
public:
    explicit ScanlineCanvas(QWidget* parent) : QWidget(parent) {
        setMinimumSize(220, 170);
        setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    }

    void setContent(std::optional<ScanlineModel> model, QRect window, double offset,
                    std::vector<QRgb> colours, std::vector<std::uint8_t> written, double lineWidth,
                    bool presentation,
                    std::optional<ScanlineView::TheirCoverage> theirs = std::nullopt) {
        m_theirs = std::move(theirs);
        m_model = std::move(model);
        m_window = window;
        m_offset = offset;
        m_colours = std::move(colours);
        m_written = std::move(written);
        m_lineWidth = lineWidth;
        m_presentation = presentation;
        update();
    }
    QRect window() const { return m_window; }
    QSize sizeHint() const override { return {420, 300}; }

protected:
    void paintEvent(QPaintEvent*) override;

private:
    struct Grid;
    // paintEvent's layers, bottom to top: the pixels and samples; the triangle and the scanline
    // (clipped to the grid); the row and column numbers; the legend.
    void paintPixels(QPainter& painter, const Grid& grid) const;
    void paintTriangle(QPainter& painter, const Grid& grid) const;
    void paintScanline(QPainter& painter, const Grid& grid) const;
    // Their span of the row, outlined in red; the pixels where their coverage departs from
    // ours: a red square where only they cover, a red cross where only we do.
    void paintTheirs(QPainter& painter, const Grid& grid) const;
    // The crossings' values, unclipped, between the row numbers and the right edge, above the
    // legend; drawn before the numbers, which give way to them.
    void paintCrossings(QPainter& painter, const Grid& grid, double marginLeft,
                        const QFontMetrics& metrics);
    void paintNumbers(QPainter& painter, const Grid& grid, double marginLeft,
                      const QFontMetrics& metrics);
    // The legend's entries at `places` (flowPlaces) below the grid.
    void paintLegend(QPainter& painter, const Grid& grid, const QFontMetrics& metrics,
                     const std::vector<FlowPlace>& places);

    std::optional<ScanlineModel> m_model;
    QRect m_window;
    double m_offset = 0.0;
    std::vector<QRgb> m_colours;
    std::vector<std::uint8_t> m_written;
    double m_lineWidth = 1.5;
    bool m_presentation = false;
    std::optional<ScanlineView::TheirCoverage> m_theirs;
};

namespace {

const QColor kLongColour(255, 150, 40);
const QColor kUpperColour(90, 200, 255);
const QColor kLowerColour(235, 100, 235);
const QColor kSpanColour(255, 221, 51);
const QColor kTheirColour(255, 70, 70);
const std::array<QColor, 3> kEdgeColours{kLongColour, kUpperColour, kLowerColour};

std::array<QString, 3> edgeNames() {
    return {ScanlineView::tr("long edge"), ScanlineView::tr("upper edge"),
            ScanlineView::tr("lower edge")};
}

// The legend's names: the edges, and after a check what their marks mean.
std::vector<QString> legendNames(bool theirs) {
    const std::array<QString, 3> edges = edgeNames();
    std::vector<QString> names(edges.begin(), edges.end());
    if (theirs) {
        names.push_back(ScanlineView::tr("your span"));
        names.push_back(ScanlineView::tr("only yours"));
        names.push_back(ScanlineView::tr("only ours"));
    }
    return names;
}

// Each legend entry's width: its mark, then its name.
std::vector<double> legendWidths(const QFontMetrics& metrics, bool theirs) {
    std::vector<double> widths;
    for (const QString& name : legendNames(theirs))
        widths.push_back(18 + metrics.horizontalAdvance(name));
    return widths;
}

}  // namespace

// Where the pixels are drawn: pixel (x, y) is the square of side 1 around its sample
// (x + offset, y + offset), cell widget pixels a side; (u0, v0) is the window's corner.
struct ScanlineCanvas::Grid {
    double cell = 0.0, originX = 0.0, originY = 0.0, u0 = 0.0, v0 = 0.0, offset = 0.0;
    QRectF rect;  // the window's pixels, in the widget
    QPointF at(double u, double v) const {
        return QPointF(originX + (u - u0) * cell, originY + (v - v0) * cell);
    }
    QRectF square(int x, int y) const {
        return QRectF(at(x + offset - 0.5, y + offset - 0.5), QSizeF(cell, cell));
    }
};

void ScanlineCanvas::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), QColor(32, 32, 36));
    clearLabels();
    if (!m_model || m_window.isEmpty()) {
        painter.setPen(QColor(200, 200, 200));
        painter.drawText(
            rect(), Qt::AlignCenter | Qt::TextWordWrap,
            ScanlineView::tr("No triangle to show: step into the frame or pick a pixel."));
        return;
    }
    painter.setRenderHint(QPainter::Antialiasing);
    // The view's font (the dock's: larger when presenting or zoomed), a little smaller on
    // the drawing unless presenting.
    const QFont font = labelFont(this, m_presentation ? 1.0 : 0.95);
    painter.setFont(font);
    const QFontMetrics metrics(font);
    const int cols = m_window.width(), rows = m_window.height();

    // Room for the row numbers on the left, the column numbers on top, the legend below.
    const double marginLeft = metrics.horizontalAdvance(QStringLiteral("0000")) + 6;
    const double marginTop = metrics.height() + 4;
    const std::vector<FlowPlace> legend =
        flowPlaces(legendWidths(metrics, m_theirs.has_value()), 8.0, width() - 4);
    const double marginBottom = metrics.height() * (legend.back().line + 1) + 8;
    Grid grid;
    grid.cell = std::max(2.0, std::min((width() - marginLeft - 6) / cols,
                                       (height() - marginTop - marginBottom) / rows));
    const double gridWidth = grid.cell * cols, gridHeight = grid.cell * rows;
    grid.originX = marginLeft + (width() - marginLeft - 6 - gridWidth) / 2;
    grid.originY = marginTop + (height() - marginTop - marginBottom - gridHeight) / 2;
    grid.u0 = m_window.left() + m_offset - 0.5;
    grid.v0 = m_window.top() + m_offset - 0.5;
    grid.offset = m_offset;
    grid.rect = QRectF(grid.originX, grid.originY, gridWidth, gridHeight);

    paintPixels(painter, grid);
    painter.save();
    painter.setClipRect(grid.rect);
    paintTriangle(painter, grid);
    if (m_model->row) paintScanline(painter, grid);
    if (m_theirs) paintTheirs(painter, grid);
    painter.restore();
    if (m_model->row) paintCrossings(painter, grid, marginLeft, metrics);
    paintNumbers(painter, grid, marginLeft, metrics);
    paintLegend(painter, grid, metrics, legend);
}

// The pixels as they are at the cursor, the span, the pixel at the cursor and the samples.
void ScanlineCanvas::paintPixels(QPainter& painter, const Grid& grid) const {
    const ScanlineModel& m = *m_model;
    const int cols = m_window.width(), rows = m_window.height();
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) {
            const auto i = static_cast<std::size_t>(r * cols + c);
            const bool written = i < m_written.size() && m_written[i];
            painter.fillRect(grid.square(m_window.left() + c, m_window.top() + r),
                             written ? QColor(m_colours[i]) : QColor(52, 52, 58));
        }
    }
    // The span.
    const bool hasRow = m.row.has_value();
    if (hasRow && !m.row->empty()) {
        for (int x = std::max(m.row->xBegin, m_window.left());
             x < std::min(m.row->xEnd, m_window.right() + 1); ++x) {
            painter.fillRect(grid.square(x, m.row->y), QColor(255, 221, 51, 120));
        }
    }
    if (grid.cell >= 5.0) {
        painter.setPen(QPen(QColor(90, 90, 100), 1.0));
        for (int c = 0; c <= cols; ++c)
            painter.drawLine(QPointF(grid.originX + c * grid.cell, grid.originY),
                             QPointF(grid.originX + c * grid.cell, grid.rect.bottom()));
        for (int r = 0; r <= rows; ++r)
            painter.drawLine(QPointF(grid.originX, grid.originY + r * grid.cell),
                             QPointF(grid.rect.right(), grid.originY + r * grid.cell));
    }
    if (hasRow && !m.row->empty()) {
        const int x0 = std::max(m.row->xBegin, m_window.left());
        const int x1 = std::min(m.row->xEnd, m_window.right() + 1);
        if (x0 < x1) {
            painter.setPen(QPen(kSpanColour, m_lineWidth));
            painter.setBrush(Qt::NoBrush);
            painter.drawRect(grid.square(x0, m.row->y).united(grid.square(x1 - 1, m.row->y)));
        }
    }
    if (m.currentPixel && hasRow && m_window.contains(*m.currentPixel, m.row->y)) {
        painter.setPen(QPen(Qt::white, m_lineWidth * 2.0));
        painter.setBrush(Qt::NoBrush);
        painter.drawRect(grid.square(*m.currentPixel, m.row->y).adjusted(1, 1, -1, -1));
    }

    // Sample points: filled on the span, hollow elsewhere.
    if (grid.cell >= 9.0) {
        const double radius = std::max(1.5, grid.cell * 0.08);
        for (int r = 0; r < rows; ++r) {
            for (int c = 0; c < cols; ++c) {
                const int x = m_window.left() + c, y = m_window.top() + r;
                const bool onSpan =
                    hasRow && y == m.row->y && x >= m.row->xBegin && x < m.row->xEnd;
                painter.setPen(onSpan ? Qt::NoPen : QPen(QColor(120, 120, 130), 1.0));
                painter.setBrush(onSpan ? QBrush(QColor(20, 20, 20)) : QBrush(Qt::NoBrush));
                painter.drawEllipse(grid.at(x + m_offset, y + m_offset), radius, radius);
            }
        }
    }
}

// The triangle and its three edges.
void ScanlineCanvas::paintTriangle(QPainter& painter, const Grid& grid) const {
    const ScanlineModel& m = *m_model;
    QPainterPath outline;
    outline.moveTo(grid.at(m.setup.sorted[0].x, m.setup.sorted[0].y));
    outline.lineTo(grid.at(m.setup.sorted[1].x, m.setup.sorted[1].y));
    outline.lineTo(grid.at(m.setup.sorted[2].x, m.setup.sorted[2].y));
    outline.closeSubpath();
    painter.fillPath(outline, QColor(255, 255, 255, 22));
    for (std::size_t k = 0; k < 3; ++k) {
        const ScanEdgeEntry& e = m.edges[k];
        painter.setPen(QPen(kEdgeColours[k], m_lineWidth * 1.4, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(grid.at(e.top.x, e.top.y), grid.at(e.bottom.x, e.bottom.y));
    }
    painter.setPen(Qt::NoPen);
    painter.setBrush(Qt::white);
    for (const rl::dvec2& p : m.setup.sorted)
        painter.drawEllipse(grid.at(p.x, p.y), m_lineWidth * 1.6, m_lineWidth * 1.6);
}

// The scanline through the samples of row y and its crossings with the two edges.
void ScanlineCanvas::paintScanline(QPainter& painter, const Grid& grid) const {
    const ScanlineModel& m = *m_model;
    const double v = m.row->y + m_offset;
    painter.setPen(QPen(kSpanColour, m_lineWidth, Qt::DashLine));
    painter.drawLine(grid.at(grid.u0, v), grid.at(grid.u0 + m_window.width(), v));
    // The long edge bounds the span on one side, the short edge of this row on the other.
    const QColor shortColour = kEdgeColours[m.row->upperPart ? 1 : 2];
    const bool longOnLeft = m.edges[0].onLeft;
    const QColor leftColour = longOnLeft ? kLongColour : shortColour;
    const QColor rightColour = longOnLeft ? shortColour : kLongColour;
    const double d = m_lineWidth * 2.6;
    for (const auto& [x, colour] :
         {std::pair{m.row->xLeft, leftColour}, std::pair{m.row->xRight, rightColour}}) {
        const QPointF c = grid.at(x, v);
        QPolygonF diamond;
        diamond << c + QPointF(0, -d) << c + QPointF(d, 0) << c + QPointF(0, d)
                << c + QPointF(-d, 0);
        painter.setPen(QPen(Qt::black, 1.0));
        painter.setBrush(colour);
        painter.drawPolygon(diamond);
    }
}

void ScanlineCanvas::paintTheirs(QPainter& painter, const Grid& grid) const {
    const ScanlineView::TheirCoverage& theirs = *m_theirs;
    const double inset = std::min(3.0, grid.cell / 6.0);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(kTheirColour, m_lineWidth));
    for (const QPoint& p : theirs.onlyTheirs) {
        const QRectF square = grid.square(p.x(), p.y()).adjusted(inset, inset, -inset, -inset);
        painter.fillRect(square, QColor(255, 70, 70, 110));
        painter.drawRect(square);
    }
    for (const QPoint& p : theirs.onlyOurs) {
        const QRectF square = grid.square(p.x(), p.y()).adjusted(inset, inset, -inset, -inset);
        painter.drawLine(square.topLeft(), square.bottomRight());
        painter.drawLine(square.topRight(), square.bottomLeft());
    }
    if (theirs.rowSpan && m_model->row) {
        const auto [first, last] = *theirs.rowSpan;
        const int y = m_model->row->y;
        painter.setPen(QPen(kTheirColour, m_lineWidth * 1.4, Qt::DashLine));
        painter.drawRect(grid.square(first, y)
                             .united(grid.square(last, y))
                             .adjusted(inset, inset, -inset, -inset));
    }
}

void ScanlineCanvas::paintCrossings(QPainter& painter, const Grid& grid, double marginLeft,
                                    const QFontMetrics& metrics) {
    const ScanlineModel& m = *m_model;
    const double v = m.row->y + m_offset;
    const double d = m_lineWidth * 2.6;
    const double line = grid.at(0, v).y();
    const QRectF bounds(marginLeft, 0, width() - marginLeft, grid.rect.bottom() + 2);
    painter.setPen(Qt::white);
    // Beside its crossing, above the line or else below it (or a line further out), the
    // first place that meets nothing drawn; inside `bounds`.
    const auto label = [&](double crossing, bool left, const QString& text) {
        const double w = metrics.horizontalAdvance(text) + 4, h = metrics.height() + 2;
        const double x =
            std::max(bounds.left() + 2,
                     std::min(left ? crossing - d - w : crossing + d, bounds.right() - w - 2));
        const auto inside = [&](double top) {  // a pixel inside, for the gap around it
            return std::clamp(top, bounds.top() + 1,
                              std::max(bounds.top() + 1, bounds.bottom() - h - 1));
        };
        const double above = line - d - 2 - h, below = line + d + 2;
        QRectF box(x, inside(above), w, h);
        for (const double top : {above, below, above - h, below + h}) {
            const QRectF candidate(x, inside(top), w, h);
            if (isFree(candidate.adjusted(-1, -1, 1, 1), bounds)) {
                box = candidate;
                break;
            }
        }
        painter.fillRect(box, QColor(0, 0, 0, 170));
        recordLabel(box);
        painter.drawText(QPointF(box.left() + 2, box.top() + 1 + metrics.ascent()), text);
    };
    label(grid.at(m.row->xLeft, v).x(), true,
          QStringLiteral("x_left %1").arg(num(m.row->xLeft, 4)));
    label(grid.at(m.row->xRight, v).x(), false,
          QStringLiteral("x_right %1").arg(num(m.row->xRight, 4)));
}

namespace {

// The first of 1, 2, 5, 10, 20, 50 ... whose multiples of `cell` leave `room` between numbers.
int numberStep(double cell, double room) {
    for (int step = 1;; step *= 10)
        for (const int k : {1, 2, 5})
            if (step * k * cell >= room || step * k >= 100000) return step * k;
}

}  // namespace

// Row and column numbers, as many as fit without meeting each other or the crossings'
// values; the current row's always.
void ScanlineCanvas::paintNumbers(QPainter& painter, const Grid& grid, double marginLeft,
                                  const QFontMetrics& metrics) {
    const ScanlineModel& m = *m_model;
    const bool hasRow = m.row.has_value();
    const double h = metrics.height();
    // Row numbers: right-aligned left of the grid, centred on their row, above the legend.
    const QRectF rowBounds(0, 0, marginLeft, grid.rect.bottom() + 2);
    const auto rowBox = [&](int y) {
        const double centre = grid.originY + (y - m_window.top() + 0.5) * grid.cell;
        return QRectF(0, std::min(centre - h / 2, rowBounds.bottom() - h - 1), marginLeft - 4, h);
    };
    const auto rowNumber = [&](int y, const QColor& colour) {
        painter.setPen(colour);
        drawLabel(painter, rowBox(y), Qt::AlignRight | Qt::AlignVCenter, QString::number(y));
    };
    if (hasRow && m_window.contains(m_window.left(), m.row->y)) rowNumber(m.row->y, kSpanColour);
    const int every = numberStep(grid.cell, h + 2);
    for (int y = m_window.top(); y <= m_window.bottom(); ++y) {
        if (y % every != 0 || (hasRow && y == m.row->y)) continue;
        if (isFree(rowBox(y).adjusted(0, -1, 0, 1), rowBounds)) rowNumber(y, QColor(190, 190, 200));
    }
    // Column numbers, centred above their column, inside the canvas.
    painter.setPen(QColor(190, 190, 200));
    const QString widest =
        QString::number(std::max(std::abs(m_window.left()), std::abs(m_window.right())));
    const int everyColumn =
        numberStep(grid.cell, metrics.horizontalAdvance(widest) + metrics.horizontalAdvance(u' '));
    for (int x = m_window.left(); x <= m_window.right(); ++x) {
        if (x % everyColumn != 0) continue;
        const QString label = QString::number(x);
        const QPointF baseline(grid.originX + (x - m_window.left() + 0.5) * grid.cell -
                                   metrics.horizontalAdvance(label) / 2.0,
                               grid.originY - metrics.descent() - 3);
        if (isFree(textBox(painter, baseline, label).adjusted(-1, 0, 1, 0), rect()))
            drawLabel(painter, baseline, label);
    }
}

// The legend: which colour is which edge.
void ScanlineCanvas::paintLegend(QPainter& painter, const Grid& grid, const QFontMetrics& metrics,
                                 const std::vector<FlowPlace>& places) {
    const std::vector<QString> names = legendNames(m_theirs.has_value());
    for (std::size_t k = 0; k < names.size(); ++k) {
        const double x = places[k].x;
        const double y = grid.rect.bottom() + 4 + places[k].line * metrics.height();
        const double middle = y + metrics.height() / 2.0;
        const QRectF mark(x + 2, middle - 5, 10, 10);
        painter.setBrush(Qt::NoBrush);
        if (k < 3) {
            painter.setPen(QPen(kEdgeColours[k], m_lineWidth * 1.4));
            painter.drawLine(QPointF(x, middle), QPointF(x + 14, middle));
        } else if (k == 3) {
            painter.setPen(QPen(kTheirColour, m_lineWidth * 1.4, Qt::DashLine));
            painter.drawRect(QRectF(x, middle - 4, 14, 8));
        } else if (k == 4) {
            painter.setPen(QPen(kTheirColour, m_lineWidth));
            painter.fillRect(mark, QColor(255, 70, 70, 110));
            painter.drawRect(mark);
        } else {
            painter.setPen(QPen(kTheirColour, m_lineWidth));
            painter.drawLine(mark.topLeft(), mark.bottomRight());
            painter.drawLine(mark.topRight(), mark.bottomLeft());
        }
        painter.setPen(QColor(220, 220, 220));
        drawLabel(painter, QPointF(x + 18, y + metrics.ascent()), names[k]);
    }
}

ScanlineView::ScanlineView(Inspection* inspection, QWidget* parent)
    : ExplainedView(inspection, QStringLiteral("scanline"), parent) {
    m_canvas = new ScanlineCanvas(this);
    m_canvas->setObjectName(QStringLiteral("scanlineCanvas"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(title());
    layout->addWidget(m_canvas, 3);
    layout->addWidget(explanation(), 4);
    m_canvas->installEventFilter(this);
}

bool ScanlineView::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_canvas && event->type() == QEvent::Resize && isVisible() && m_model) refresh();
    return QWidget::eventFilter(watched, event);
}

QRect ScanlineView::drawnWindow() const {
    return m_canvas->window();
}

void ScanlineView::refresh() {
    m_model.reset();
    m_followsCursor = false;
    if (const std::optional<FollowedRow> followed = followedRow(*m_inspection)) {
        const rl::FrameTrace& frame = *m_inspection->frame();
        const rl::Scene& scene = *frame.scene;
        m_followsCursor = followed->followsCursor;
        m_model = scanlineModel(frame, followed->triangle, followed->y);
        m_model->currentPixel = followed->pixel;
        // As many pixels as fit at the smallest square (the margins take about 50 pixels
        // across and 40 down).
        const int maxColumns = static_cast<int>(std::max(0.0, m_canvas->width() - 50.0) / kMinCell);
        const int maxRows = static_cast<int>(std::max(0.0, m_canvas->height() - 40.0) / kMinCell);
        const QRect window = windowOf(*m_model, scene.width, scene.height, maxColumns, maxRows);
        const QImage image = m_inspection->image();
        const rl::DepthTest* buffers = m_inspection->buffers();
        std::vector<QRgb> colours(static_cast<std::size_t>(window.width() * window.height()));
        std::vector<std::uint8_t> written(colours.size(), 0);
        for (int r = 0; r < window.height(); ++r) {
            for (int c = 0; c < window.width(); ++c) {
                const int x = window.left() + c, y = window.top() + r;
                const auto i = static_cast<std::size_t>(r * window.width() + c);
                if (buffers && buffers->triangle.contains(x, y))
                    written[i] = buffers->triangle.at(x, y) != rl::kNoTriangle;
                if (image.valid(x, y)) colours[i] = image.pixel(x, y);
            }
        }
        m_theirCoverage = theirCoverageIn(window);
        m_canvas->setContent(m_model, window, scene.rules.sampleOffset, std::move(colours),
                             std::move(written), m_inspection->lineWidth(),
                             m_inspection->presentation(), m_theirCoverage);
    } else {
        m_theirCoverage.reset();
        m_canvas->setContent(std::nullopt, QRect(), 0.0, {}, {}, 1.5, false);
    }
    title()->setText(titleText());
    setExplanation(explanationHtml());
}

QString ScanlineView::titleText() const {
    const std::shared_ptr<const rl::FrameTrace>& frame = m_inspection->frame();
    if (!frame) return tr("No frame yet.");
    if (!m_model) {
        if (m_inspection->canStep() && m_inspection->atStart())
            return tr(
                "Start of the frame: step forward to walk the first triangle, or pick a "
                "pixel to see the triangle holding it.");
        return tr("Pick a pixel, or step through the frame, to see a triangle scan converted.");
    }
    const rl::ScreenTriangle& tri = frame->projection->triangles[m_model->triangle];
    const rl::Draw& draw = frame->scene->draws[tri.draw];
    QString text =
        tr("<b>Triangle %1</b> of %2").arg(tri.source + 1).arg(draw.mesh->triangles.size());
    if (frame->scene->draws.size() > 1)
        text += QStringLiteral(" (%1)").arg(QString::fromStdString(draw.name).toHtmlEscaped());
    if (m_model->row) text += QStringLiteral(", ") + tr("scanline %1").arg(m_model->row->y);
    if (m_model->currentPixel)
        text += QStringLiteral(", ") + tr("pixel %1").arg(*m_model->currentPixel);
    text += QStringLiteral(" &mdash; ") +
            (m_followsCursor
                 ? tr("at the stepping cursor")
                 : tr("the triangle selected (the cursor is at the %1 of the frame)")
                       .arg(m_inspection->canStep() && m_inspection->atStart() ? tr("start")
                                                                               : tr("end")));
    return text;
}

namespace {

// The edges' colours in the text, as the drawing shows them: long, upper, lower.
const std::array<QString, 3>& edgeColours() {
    static const std::array<QString, 3> colours{
        QStringLiteral("#ff9628"), QStringLiteral("#2a9fd6"), QStringLiteral("#c040c0")};
    return colours;
}

}  // namespace

std::array<QString, 3> ScanlineView::edgeNames() {
    return {tr("long"), tr("upper"), tr("lower")};
}

QString ScanlineView::explanationHtml() const {
    if (!m_model) return {};
    const rl::FrameTrace& frame = *m_inspection->frame();
    const ScanlineModel& m = *m_model;
    const rl::TriangleSetup& s = m.setup;
    QString html;

    // The vertices sorted by y and the edge table.
    html += QStringLiteral("<p>") +
            tr("Vertices sorted by y: top %1, middle %2, bottom %3. The long edge runs from the "
               "top to the bottom; the two short edges meet at the middle vertex.")
                .arg(vector(s.sorted[0]), vector(s.sorted[1]), vector(s.sorted[2]));
    if (s.degenerate()) {
        html += QLatin1Char(' ') +
                tr("Its area on the screen is zero: it has no inside and is not scanned.") +
                QStringLiteral("</p>");
        return html;
    }
    html += QLatin1Char(' ') +
            tr("(s1 &minus; s0) &times; (s2 &minus; s0) = %1, so the middle vertex is %2 of "
               "the long edge: the long edge bounds the spans on the %3.")
                .arg(num(s.doubleArea()))
                .arg(s.longEdgeOnLeft ? tr("right") : tr("left"))
                .arg(s.longEdgeOnLeft ? tr("left") : tr("right")) +
            QStringLiteral("</p>");
    html += edgeTableHtml(m);

    // The scanline: the edges' x stepped by dx/dy, the span, its ends.
    if (!m.row) {
        html += QStringLiteral("<p>") + tr("No row of this triangle is on the screen.") +
                QStringLiteral("</p>");
        return html;
    }
    html += scanlineHtml(m, *frame.scene);
    // Depth and normal at both ends of the span.
    if (!m.row->empty()) html += spanEndsHtml(m, frame);
    html += QStringLiteral("<p><i>") +
            tr("Edge walking: from one scanline to the next, each edge's x changes by its "
               "constant dx/dy, one addition per edge and row: x_left(y+1) = x_left(y) + dx/dy. "
               "The span between the two crossings is filled; the long edge bounds every row, the "
               "upper edge the rows above the middle vertex, the lower edge the rest.");
    if (frame.scene->rules.scan == rl::RasterRules::Scan::Dda)
        html += QLatin1Char(' ') +
                tr("Here the additions are seed 001's DDA, in double: an edge that lands a hair "
                   "below a row in double leaves that row to the triangle above, where an exact "
                   "walk would find the edge through the row's samples.");
    html += QStringLiteral("</i></p>");
    return html;
}

// The edge table, one column per edge, and the rows of it on the screen.
QString ScanlineView::edgeTableHtml(const ScanlineModel& m) const {
    const rl::TriangleSetup& s = m.setup;
    const std::array<QString, 3> names = edgeNames();
    const std::array<QString, 3>& colours = edgeColours();
    const auto tableRow = [&](const QString& header, const auto& cell) {
        QString line = QStringLiteral("<tr><th align='left'>%1</th>").arg(header);
        for (std::size_t k = 0; k < 3; ++k)
            line += QStringLiteral("<td nowrap>%1</td>").arg(cell(m.edges[k]));
        return line + QStringLiteral("</tr>");
    };
    QString html =
        QStringLiteral("<table cellspacing='0' cellpadding='3' border='1'><tr><th></th>");
    for (std::size_t k = 0; k < 3; ++k)
        html += QStringLiteral("<th><font color='%1'>%2</font></th>").arg(colours[k], names[k]);
    html += QStringLiteral("</tr>");
    // Non-breaking spaces: a point is not cut across two lines.
    const auto unbroken = [](const rl::dvec2& p) {
        return vector(p).replace(QLatin1Char(' '), QStringLiteral("&nbsp;"));
    };
    html += tableRow(tr("from"), [&](const ScanEdgeEntry& e) { return unbroken(e.top); });
    html += tableRow(tr("to"), [&](const ScanEdgeEntry& e) { return unbroken(e.bottom); });
    html += tableRow(tr("x on its first row"), [](const ScanEdgeEntry& e) {
        return e.walked() ? num(e.xFirstRow) : QStringLiteral("&mdash;");
    });
    html += tableRow(tr("dx/dy"), [this](const ScanEdgeEntry& e) {
        return e.horizontal ? tr("horizontal") : num(e.dxdy);
    });
    html += tableRow(tr("rows"), [this](const ScanEdgeEntry& e) {
        return e.walked() ? QStringLiteral("%1&ndash;%2").arg(e.firstRow).arg(e.lastRow)
                          : tr("none");
    });
    html += tableRow(
        tr("side"), [this](const ScanEdgeEntry& e) { return e.onLeft ? tr("left") : tr("right"); });
    html += QStringLiteral("</table>");
    if (m.rows.first > s.yFirst || m.rows.last < s.yLast)
        html += QStringLiteral("<p>") +
                tr("Only rows %1 to %2 are on the screen: the walk starts and stops there.")
                    .arg(m.rows.first)
                    .arg(m.rows.last) +
                QStringLiteral("</p>");
    return html;
}

// The scanline shown: its edges' crossings stepped by dx/dy, the fill rule and the span.
void ScanlineView::setTheirSpans(std::shared_ptr<const rl::FrameTrace> frame, TheirSpans spans) {
    m_theirFrame = frame;
    m_theirSpans = std::move(spans);
    refresh();
}

std::optional<ScanlineView::TheirCoverage> ScanlineView::theirCoverageIn(
    const QRect& window) const {
    const auto checked = m_theirFrame.lock();
    if (!checked || checked != m_inspection->frame() || m_theirSpans.empty() || !m_model)
        return std::nullopt;
    const rl::ScanConversion& scan = *checked->scan;
    const std::uint32_t t = m_model->triangle;
    std::map<int, std::pair<int, int>> ours;  // row to [xBegin, xEnd)
    for (std::uint32_t i = scan.spanStart[t]; i < scan.spanStart[t + 1]; ++i)
        ours[scan.spans[i].y] = {scan.spans[i].xBegin, scan.spans[i].xEnd};
    TheirCoverage coverage;
    for (int y = window.top(); y <= window.bottom(); ++y) {
        const auto o = ours.find(y);
        const auto th = m_theirSpans.find({t, y});
        for (int x = window.left(); x <= window.right(); ++x) {
            const bool inOurs = o != ours.end() && x >= o->second.first && x < o->second.second;
            const bool inTheirs =
                th != m_theirSpans.end() && x >= th->second.first && x <= th->second.second;
            if (inOurs != inTheirs)
                (inOurs ? coverage.onlyOurs : coverage.onlyTheirs).push_back({x, y});
        }
    }
    if (m_model->row)
        if (const auto th = m_theirSpans.find({t, m_model->row->y}); th != m_theirSpans.end())
            coverage.rowSpan = th->second;
    return coverage;
}

QString ScanlineView::theirSpanHtml(const ScanlineModel& m) const {
    // Their coverage was worked out with the model (refresh), their span of this row with it.
    if (!m_theirCoverage || !m.row) return {};
    const ScanRowInfo& row = *m.row;
    const QString ours =
        row.empty() ? tr("none") : tr("%1 to %2").arg(row.xBegin).arg(row.xEnd - 1);
    if (!m_theirCoverage->rowSpan)
        return row.empty() ? QString()
                           : QStringLiteral(" <font color='#c81e1e'><b>") +
                                 tr("Your renderer: no pixel on this row (ours: %1).").arg(ours) +
                                 QStringLiteral("</b></font>");
    const auto [first, last] = *m_theirCoverage->rowSpan;
    const bool same = !row.empty() && first == row.xBegin && last == row.xEnd - 1;
    const QString text =
        tr("Your renderer: pixels %1 to %2 (ours: %3).").arg(first).arg(last).arg(ours);
    return same ? QStringLiteral(" <font color='#148c28'>") + text + QStringLiteral("</font>")
                : QStringLiteral(" <font color='#c81e1e'><b>") + text +
                      QStringLiteral("</b></font>");
}

QString ScanlineView::scanlineHtml(const ScanlineModel& m, const rl::Scene& scene) const {
    const rl::RasterRules& rules = scene.rules;
    const bool topLeft = rules.fill == rl::RasterRules::FillRule::TopLeft;
    const double offset = rules.sampleOffset;
    const std::array<QString, 3> names = edgeNames();
    const std::array<QString, 3>& colours = edgeColours();
    const bool dda = rules.scan == rl::RasterRules::Scan::Dda;
    const ScanRowInfo& row = *m.row;
    const std::size_t shortIndex = row.upperPart ? 1 : 2;
    const ScanEdgeEntry& longEdge = m.edges[0];
    const ScanEdgeEntry& shortEdge = m.edges[shortIndex];
    const auto step = [&](const ScanEdgeEntry& e, std::size_t k, const QString& name, double x) {
        const QString which =
            QStringLiteral("<font color='%1'>%2</font>").arg(colours[k], names[k]);
        if (row.y == e.firstRow)
            return tr("%1(%2) = %3, where the %4 edge crosses its first row")
                .arg(name)
                .arg(row.y)
                .arg(num(x))
                .arg(which);
        if (row.y == m.rows.first)
            return tr("%1(%2) = %3, where the %4 edge crosses the first row on the screen")
                .arg(name)
                .arg(row.y)
                .arg(num(x))
                .arg(which);
        // Under the DDA, the sums as the doubles hold them, every digit.
        const int digits = dda ? 17 : 6;
        const double previous = dda ? rl::ddaEdgeAtRow(e.top, e.bottom, row.y - 1).x : x - e.dxdy;
        return tr("%1(%2) = %1(%3) + dx/dy = %4 + %5 = %6 along the %7 edge")
            .arg(name)
            .arg(row.y)
            .arg(row.y - 1)
            .arg(num(previous, digits))
            .arg(e.dxdy < 0.0 ? QStringLiteral("(%1)").arg(num(e.dxdy, digits))
                              : num(e.dxdy, digits))
            .arg(num(x, digits))
            .arg(which);
    };
    const ScanEdgeEntry& leftEdge = longEdge.onLeft ? longEdge : shortEdge;
    const ScanEdgeEntry& rightEdge = longEdge.onLeft ? shortEdge : longEdge;
    const std::size_t leftIndex = longEdge.onLeft ? 0 : shortIndex;
    const std::size_t rightIndex = longEdge.onLeft ? shortIndex : 0;
    QString html =
        QStringLiteral("<p><b>") + tr("Scanline y = %1").arg(row.y) + QStringLiteral("</b>");
    if (offset != 0.0)
        html += QLatin1Char(' ') + tr("(sampled at y = %1)").arg(num(row.y + offset));
    html += QStringLiteral(":<br>") +
            step(leftEdge, leftIndex, QStringLiteral("x_left"), row.xLeft) +
            QStringLiteral(";<br>") +
            step(rightEdge, rightIndex, QStringLiteral("x_right"), row.xRight) +
            QStringLiteral(".<br>");
    const QString off = offset != 0.0 ? QStringLiteral(" &minus; %1").arg(num(offset)) : QString();
    const double leftSample = row.xLeft - offset, rightSample = row.xRight - offset;
    const long long first = static_cast<long long>(std::ceil(leftSample));
    const long long last = topLeft ? static_cast<long long>(std::ceil(rightSample)) - 1
                                   : static_cast<long long>(std::floor(rightSample));
    if (dda) {
        html += tr("Seed 001's DDA: x_left and x_right are sums in double, one addition of dx/dy "
                   "a row, the rounding of each carried along (no snapping). Pixels x = "
                   "ceil(x_left) = %1 while x &lt; x_right: up to ceil(x_right) &minus; 1 = %2 (a "
                   "sample exactly on the right edge belongs to the next triangle).")
                    .arg(first)
                    .arg(last);
    } else if (topLeft) {
        html += tr("Top-left rule: the samples with x_left &le; x%1 &lt; x_right, pixels "
                   "ceil(x_left%2) = %3 to ceil(x_right%2) &minus; 1 = %4 (a sample exactly on "
                   "the right edge belongs to the next triangle).")
                    .arg(offset != 0.0 ? QStringLiteral(" + %1").arg(num(offset)) : QString(), off)
                    .arg(first)
                    .arg(last);
    } else {
        html += tr("Inclusive rule: the pixels from ceil(x_left%1) = %2 to floor(x_right%1) = %3, "
                   "both ends included (a sample exactly on an edge is inside).")
                    .arg(off)
                    .arg(first)
                    .arg(last);
    }
    html += QLatin1Char(' ');
    if (row.empty()) {
        html += QStringLiteral("<b>") + tr("No pixel on this row") + QStringLiteral("</b>: ") +
                (first > last ? tr("the edges cross it between two samples.")
                              : tr("they are all off the screen."));
    } else {
        const int n = row.xEnd - row.xBegin;
        html += n == 1 ? tr("Span [%1, %2): 1 pixel.").arg(row.xBegin).arg(row.xEnd)
                       : tr("Span [%1, %2): %3 pixels.").arg(row.xBegin).arg(row.xEnd).arg(n);
        if (row.xBegin != first || row.xEnd - 1 != last)
            html +=
                QLatin1Char(' ') + tr("(cut to the screen's columns 0 to %1)").arg(scene.width - 1);
    }
    if (m.currentPixel)
        html += QLatin1Char(' ') + tr("The pixel at the cursor is x = %1.").arg(*m.currentPixel);
    html += theirSpanHtml(m);
    html += QStringLiteral("</p>");
    return html;
}

// The ends of a row's span: its first pixel, and its last when it has more than one.
std::vector<const SpanEnd*> ScanlineView::spanEnds(const ScanRowInfo& row) {
    std::vector<const SpanEnd*> ends{&*row.first};
    if (row.xEnd - row.xBegin > 1) ends.push_back(&*row.last);
    return ends;
}

// The table of the span's ends: each one's barycentrics, depth and normal.
QString ScanlineView::spanEndsTable(const ScanRowInfo& row) const {
    QString html = QStringLiteral(
                       "<table cellspacing='0' cellpadding='3' border='1'><tr><th></th>"
                       "<th>&alpha;, &beta;, &gamma;</th><th>") +
                   tr("depth") + QStringLiteral("</th><th>") + tr("normal") +
                   QStringLiteral("</th></tr>");
    for (const SpanEnd* e : spanEnds(row)) {
        const QString normal = !e->hasNormal                 ? tr("not computed (nothing is lit)")
                               : e->normal == rl::vec3(0.0f) ? tr("zero")
                                                             : vector(e->normal, 'g', 4);
        html +=
            QStringLiteral(
                "<tr><th>(%1, %2)</th><td nowrap>%3, %4, %5</td><td><b>%6</b></td>"
                "<td nowrap>%7</td></tr>")
                .arg(e->x)
                .arg(e->y)
                .arg(num(e->alpha, 4), num(e->beta, 4), num(e->gamma, 4), num(e->depth), normal);
    }
    return html + QStringLiteral("</table>");
}

// The depth and the normal at both ends of the span, from the barycentrics of their samples.
QString ScanlineView::spanEndsHtml(const ScanlineModel& m, const rl::FrameTrace& frame) const {
    const rl::Scene& scene = *frame.scene;
    const rl::RasterRules& rules = scene.rules;
    if (rules.scan == rl::RasterRules::Scan::Dda) return ddaSpanEndsHtml(m, frame);
    const double offset = rules.sampleOffset;
    const ScanRowInfo& row = *m.row;
    const rl::ScreenTriangle& tri = frame.projection->triangles[m.triangle];
    const rl::DrawProjection& draw = frame.projection->draws[tri.draw];
    const bool perspective = rl::perspectiveDepth(scene);
    const float z1 = draw.depth[tri.v[0]], z2 = draw.depth[tri.v[1]], z3 = draw.depth[tri.v[2]];
    const std::array<rl::dvec2, 3> p = rl::screenVertices(*frame.projection, tri);
    QString html = QStringLiteral("<p>") +
                   tr("At the ends of the span, the barycentrics (&alpha;, &beta;, &gamma;) of the "
                      "sample with respect to the screen triangle P1 %1, P2 %2, P3 %3 give the "
                      "depth, from the vertices' z1 = %4, z2 = %5, z3 = %6:")
                       .arg(vector(p[0]), vector(p[1]), vector(p[2]), num(z1), num(z2), num(z3));
    html += QStringLiteral("<br><i>") +
            (perspective ? tr("1/z = 1/z1 + &beta; (1/z2 &minus; 1/z1) + &gamma; (1/z3 &minus; "
                              "1/z1) (perspective-correct: 1/z is linear on the screen)")
                         : tr("z = z1 + &beta; (z2 &minus; z1) + &gamma; (z3 &minus; z1)")) +
            QStringLiteral("</i></p>");
    html += spanEndsTable(row);
    QString lines;
    for (const SpanEnd* e : spanEnds(row)) {
        const QString which = QStringLiteral("(%1, %2)").arg(e->x).arg(e->y);
        if (perspective)
            lines += QStringLiteral("<br>%1: z = 1 / (%2 + %3 &times; %4 + %5 &times; %6) = %7")
                         .arg(which, num(1.0f / z1), num(e->beta), num(1.0f / z2 - 1.0f / z1),
                              num(e->gamma), num(1.0f / z3 - 1.0f / z1), num(e->depth));
        else
            lines += QStringLiteral("<br>%1: z = %2 + %3 &times; %4 + %5 &times; %6 = %7")
                         .arg(which, num(z1), num(e->beta), num(z2 - z1), num(e->gamma),
                              num(z3 - z1), num(e->depth));
    }
    html += QStringLiteral("<p>") +
            (offset == 0.0 ? tr("Pixel (x, y) is sampled at the point (x, y) itself.")
                           : tr("Pixel (x, y) is sampled at (x + %1, y + %1).").arg(num(offset))) +
            lines + QStringLiteral("</p>");
    html += QStringLiteral("<p>") +
            tr("The normal is N1 + &beta; (N2 &minus; N1) + &gamma; (N3 &minus; N1) from the "
               "vertex normals, normalised%1.")
                .arg(rules.interpolation == rl::RasterRules::Interpolation::PerspectiveCorrect
                         ? tr(", with the barycentrics weighted by 1/w (perspective-correct)")
                         : QString()) +
            QStringLiteral("</p>");
    return html;
}

// Under seed 001's DDA the depth and the weights are stepped as x is: the values at the
// row's crossings, their increment a pixel, and the sums at the ends of the span.
QString ScanlineView::ddaSpanEndsHtml(const ScanlineModel& m, const rl::FrameTrace& frame) const {
    const rl::Scene& scene = *frame.scene;
    const ScanRowInfo& row = *m.row;
    const bool perspective = rl::perspectiveDepth(scene);
    const auto [longEdge, shortEdge] = rl::ddaEdgesAtRow(
        m.setup, rl::ddaVertexValues(scene, *frame.projection, m.triangle, m.setup), row.y);
    const rl::DdaEdge& left = longEdge.x <= shortEdge.x ? longEdge : shortEdge;
    const rl::DdaEdge& right = longEdge.x <= shortEdge.x ? shortEdge : longEdge;
    const rl::DdaSpan span = rl::ddaSpan(longEdge, shortEdge, row.xBegin);
    const QString z = perspective ? QStringLiteral("1/z") : QStringLiteral("z");
    const auto term = [](double increment) {  // an increment after "+", in brackets when negative
        return increment < 0.0 ? QStringLiteral("(%1)").arg(num(increment, 17))
                               : num(increment, 17);
    };
    QString html =
        QStringLiteral("<p>") +
        tr("Seed 001's DDA steps the depth and the weights (&beta;, &gamma;) of P2 and P3 as it "
           "steps x: down each edge by the edge's own increment a row, then along the row from "
           "their values at x_left by (value at x_right &minus; value at x_left) / (x_right "
           "&minus; x_left), one addition a pixel, in double. Every attribute (colour, normal, "
           "texture coordinates) is mixed with these weights.") +
        QStringLiteral("<br>") +
        tr("On this row %1 = %2 at x_left and %3 at x_right: %1 + %4 a pixel; &beta; + %5 and "
           "&gamma; + %6 a pixel.")
            .arg(z, num(left.values.z, 17), num(right.values.z, 17), term(span.perPixel.z),
                 term(span.perPixel.beta), term(span.perPixel.gamma)) +
        QStringLiteral("</p>") + spanEndsTable(row);
    html += QStringLiteral("<p>") + tr("(%1, %2): %3 = %4 + (%1 &minus; %5) &times; %6 = %7.")
                                        .arg(row.xBegin)
                                        .arg(row.y)
                                        .arg(z, num(left.values.z, 17), num(left.x, 17),
                                             term(span.perPixel.z), num(span.values.z, 17));
    if (row.xEnd - row.xBegin > 1) {
        rl::DdaSpan stepped = span;
        for (int x = row.xBegin; x < row.xEnd - 1; ++x) stepped.next();
        html +=
            QStringLiteral("<br>") + tr("(%1, %2): %3 after %4 additions of %5 = %6.")
                                         .arg(row.xEnd - 1)
                                         .arg(row.y)
                                         .arg(z)
                                         .arg(row.xEnd - 1 - row.xBegin)
                                         .arg(num(span.perPixel.z, 17), num(stepped.values.z, 17));
    }
    return html + QStringLiteral("</p>");
}

}  // namespace rasterlab
