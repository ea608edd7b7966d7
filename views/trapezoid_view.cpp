#include "trapezoid_view.h"

#include <QLabel>
#include <QPainter>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

#include "pipeline/stages/depth_test.h"
#include "views/inspection.h"
#include "views/near_clip_view.h"
#include "views/number_text.h"
#include "views/view_font.h"

namespace rasterlab {

namespace {

const QColor kBackground(32, 32, 36);
const QColor kText(225, 225, 230);
const std::array<QColor, 2> kPartColour{QColor(90, 170, 255), QColor(235, 100, 235)};
const QColor kScanline(255, 221, 51);

QString pz(double v) {
    return number(v, 6);
}

QString rgb(const rl::vec3& c) {
    return vector(c, 'f', 2);
}

}  // namespace

TrapezoidModel trapezoidModel(const rl::FrameTrace& frame, std::uint32_t triangle,
                              std::optional<int> y,
                              const std::optional<std::array<rl::vec3, 3>>& colours) {
    const rl::Scene& scene = *frame.scene;
    const rl::Projection& projection = *frame.projection;
    const rl::ScreenTriangle& tri = projection.triangles[triangle];
    const rl::DrawProjection& draw = projection.draws[tri.draw];
    TrapezoidModel m;
    m.triangle = triangle;
    m.setup = rl::setupTriangle(rl::screenVertices(projection, tri), scene.rules);
    m.hasColour = colours.has_value();
    m.inverseDepth = rl::perspectiveDepth(scene);
    std::array<rl::TrapezoidPoint, 3> values{};
    for (std::size_t k = 0; k < 3; ++k) {
        const double depth = draw.depth[tri.v[k]];
        values[k].pz = m.inverseDepth ? 1.0 / depth : depth;
        if (colours) values[k].colour = (*colours)[k];
    }
    m.split = rl::splitIntoTrapezoids(m.setup, values, scene.rules);
    if (!y || !screenRows(m.setup, scene.height).contains(*y)) return m;
    for (std::size_t k = 0; k < m.split.parts.size(); ++k) {
        const rl::Trapezoid& part = m.split.parts[k];
        if (*y >= part.firstRow && *y <= part.lastRow) {
            m.part = k;
            m.row = rl::trapezoidRow(m.setup, part, scene.rules, *y, scene.width);
        }
    }
    return m;
}

// The triangle, its two trapezoids, the corners, the scanline with L and R, the pixels.
class TrapezoidCanvas : public QWidget {
public:
    explicit TrapezoidCanvas(QWidget* parent) : QWidget(parent) {
        setMinimumSize(240, 170);
        setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    }
    void setContent(std::optional<TrapezoidModel> model, int width, int height, double offset,
                    double lineWidth, bool presentation) {
        m_model = std::move(model);
        m_width = width;
        m_height = height;
        m_offset = offset;
        m_lineWidth = lineWidth;
        m_presentation = presentation;
        update();
    }
    QSize sizeHint() const override { return {420, 300}; }

protected:
    void paintEvent(QPaintEvent*) override;

private:
    std::optional<TrapezoidModel> m_model;
    int m_width = 0, m_height = 0;
    double m_offset = 0.0;
    double m_lineWidth = 1.5;
    bool m_presentation = false;
};

void TrapezoidCanvas::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), kBackground);
    if (!m_model) {
        painter.setPen(kText);
        painter.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap,
                         TrapezoidView::tr("No triangle to show: step into the frame or pick a "
                                           "pixel."));
        return;
    }
    painter.setRenderHint(QPainter::Antialiasing);
    // The view's font (the dock's: larger when presenting or zoomed), a little smaller on
    // the drawing unless presenting.
    const QFont font = labelFont(this, m_presentation ? 1.0 : 0.95);
    painter.setFont(font);
    const QFontMetrics metrics(font);
    const TrapezoidModel& m = *m_model;

    // What is shown: the triangle's box, within the image and a margin of a quarter of it
    // (a clipped triangle may reach the guard band), and at least a few pixels.
    double xMin = m.setup.sorted[0].x, xMax = xMin;
    for (const rl::dvec2& p : m.setup.sorted) {
        xMin = std::min(xMin, p.x);
        xMax = std::max(xMax, p.x);
    }
    QRectF box(QPointF(xMin, m.setup.sorted[0].y), QPointF(xMax, m.setup.sorted[2].y));
    box = box.intersected(QRectF(-m_width * 0.25, -m_height * 0.25, m_width * 1.5, m_height * 1.5));
    box = box.adjusted(-1, -1, 1, 1);
    if (box.width() < 8) box.adjust(-(8 - box.width()) / 2, 0, (8 - box.width()) / 2, 0);
    if (box.height() < 6) box.adjust(0, -(6 - box.height()) / 2, 0, (6 - box.height()) / 2);
    const QRectF plot =
        QRectF(rect()).adjusted(60, metrics.height() + 10, -60, -metrics.height() * 2 - 10);
    const double scale = std::min(plot.width() / box.width(), plot.height() / box.height());
    const QPointF origin(plot.center().x() - box.center().x() * scale,
                         plot.center().y() - box.center().y() * scale);
    const auto at = [&](const rl::dvec2& p) {
        return QPointF(origin.x() + p.x * scale, origin.y() + p.y * scale);
    };
    const auto shown = [&](QPolygonF polygon) {
        QPolygonF out;
        for (const QPointF& p : clipPolygonToRect(std::move(polygon), box))
            out << at({p.x(), p.y()});
        return out;
    };

    // The image's border, where it is in the picture (each side cut to the box).
    painter.setPen(QPen(QColor(110, 110, 120), 1.0, Qt::DashLine));
    painter.setBrush(Qt::NoBrush);
    for (const double x : {0.0, double(m_width)}) {
        const double y0 = std::max(0.0, box.top()), y1 = std::min(double(m_height), box.bottom());
        if (x >= box.left() && x <= box.right() && y0 < y1)
            painter.drawLine(at({x, y0}), at({x, y1}));
    }
    for (const double y : {0.0, double(m_height)}) {
        const double x0 = std::max(0.0, box.left()), x1 = std::min(double(m_width), box.right());
        if (y >= box.top() && y <= box.bottom() && x0 < x1)
            painter.drawLine(at({x0, y}), at({x1, y}));
    }

    // The trapezoids.
    const auto corner = [](const rl::TrapezoidPoint& c) { return QPointF(c.p.x, c.p.y); };
    for (std::size_t k = 0; k < m.split.parts.size(); ++k) {
        const rl::Trapezoid& t = m.split.parts[k];
        const QColor colour = kPartColour[t.upper ? 0 : 1];
        QColor fill = colour;
        fill.setAlpha(m.part == k ? 90 : 45);
        painter.setBrush(fill);
        painter.setPen(QPen(colour, m_lineWidth * (m.part == k ? 1.6 : 1.0)));
        painter.drawPolygon(
            shown(QPolygonF({corner(t.tl), corner(t.tr), corner(t.br), corner(t.bl)})));
    }
    // The split at the middle vertex's row.
    if (m.split.parts.size() == 2) {
        painter.setPen(QPen(Qt::white, m_lineWidth, Qt::DashLine));
        const QPolygonF line = shown(QPolygonF({corner(m.split.split), corner(m.split.sorted[1])}));
        if (line.size() >= 2) painter.drawLine(line[0], line[1]);
    }

    // The scanline, its pixels, L and R.
    if (m.row) {
        const rl::TrapezoidRow& row = *m.row;
        const double y = row.left.p.y;
        const double cell = scale;
        if (!row.empty()) {
            if (cell >= 5.0) {
                for (int i = row.xBegin; i < row.xEnd; ++i) {
                    const QPointF c = at({i + m_offset, y});
                    if (!rect().contains(c.toPoint())) continue;
                    const QRectF square(c - QPointF(cell / 2, cell / 2), QSizeF(cell, cell));
                    painter.fillRect(square, QColor(255, 221, 51, 70));
                    painter.setPen(QPen(QColor(255, 221, 51, 160), 1.0));
                    painter.drawRect(square);
                }
            }
            // The span's samples, cut to the box (the line is horizontal: its x only).
            const double x0 = std::clamp(row.xBegin + m_offset, box.left(), box.right());
            const double x1 = std::clamp(row.xEnd - 1 + m_offset, box.left(), box.right());
            painter.setPen(QPen(kScanline, m_lineWidth * 2.5, Qt::SolidLine, Qt::RoundCap));
            painter.drawLine(at({x0, y}), at({x1, y}));
        }
        painter.setPen(QPen(kScanline, m_lineWidth, Qt::DashLine));
        painter.drawLine(QPointF(plot.left() - 50, at({0, y}).y()),
                         QPointF(plot.right() + 50, at({0, y}).y()));
        const double d = m_lineWidth * 2.6;
        for (const auto& [p, name] : {std::pair{row.left.p, QStringLiteral("L")},
                                      std::pair{row.right.p, QStringLiteral("R")}}) {
            const QPointF c(std::clamp(at(p).x(), plot.left() - 40, plot.right() + 40), at(p).y());
            QPolygonF diamond;
            diamond << c + QPointF(0, -d) << c + QPointF(d, 0) << c + QPointF(0, d)
                    << c + QPointF(-d, 0);
            painter.setPen(QPen(Qt::black, 1.0));
            painter.setBrush(kScanline);
            painter.drawPolygon(diamond);
            painter.setPen(Qt::white);
            painter.drawText(c + QPointF(name == QStringLiteral("L") ? -d - 10 : d + 3, -d - 2),
                             name);
        }
        if (m.pixel) {
            const QPointF c = at({*m.pixel + m_offset, y});
            const double r = std::max(m_lineWidth * 2.5, cell * 0.45);
            painter.setPen(QPen(Qt::white, m_lineWidth * 1.5));
            painter.setBrush(Qt::NoBrush);
            painter.drawRect(QRectF(c - QPointF(r, r), QSizeF(2 * r, 2 * r)));
        }
    }

    // The corners' names: two corners at one vertex share a label.
    painter.setPen(kText);
    for (const rl::Trapezoid& t : m.split.parts) {
        const std::array<std::pair<const rl::TrapezoidPoint*, QString>, 4> corners{
            std::pair{&t.tl, QStringLiteral("TL")}, std::pair{&t.tr, QStringLiteral("TR")},
            std::pair{&t.bl, QStringLiteral("BL")}, std::pair{&t.br, QStringLiteral("BR")}};
        for (std::size_t k = 0; k < 4; ++k) {
            const rl::TrapezoidPoint& c = *corners[k].first;
            if (!box.contains(QPointF(c.p.x, c.p.y))) continue;
            if (k % 2 == 1 && corners[k - 1].first->p == c.p) continue;  // drawn with its twin
            QString name = corners[k].second;
            if (k % 2 == 0 && corners[k + 1].first->p == c.p)
                name += QStringLiteral("=") + corners[k + 1].second;
            const bool left = k % 2 == 0 && !(corners[k + 1].first->p == c.p);
            const QPointF p = at(c.p);
            const double w = metrics.horizontalAdvance(name);
            // The upper trapezoid's names above its corners, the lower's below: at the split
            // both name the same points.
            const QPointF where(left ? p.x() - w - 6 : p.x() + 6,
                                t.upper ? p.y() - 4 : p.y() + metrics.ascent() + 2);
            painter.setPen(kPartColour[t.upper ? 0 : 1].lighter(130));
            painter.drawText(where, name);
        }
    }
    painter.setPen(Qt::NoPen);
    painter.setBrush(Qt::white);
    for (const rl::dvec2& p : m.setup.sorted)
        if (box.contains(QPointF(p.x, p.y)))
            painter.drawEllipse(at(p), m_lineWidth * 1.6, m_lineWidth * 1.6);

    // The legend.
    double x = 8.0;
    const double y = height() - metrics.height() - 4;
    const std::array<QString, 2> names{TrapezoidView::tr("upper trapezoid"),
                                       TrapezoidView::tr("lower trapezoid")};
    for (std::size_t k = 0; k < 2; ++k) {
        painter.fillRect(QRectF(x, y + 2, 14, metrics.height() - 4), kPartColour[k]);
        painter.setPen(kText);
        painter.drawText(QPointF(x + 18, y + metrics.ascent()), names[k]);
        x += 18 + metrics.horizontalAdvance(names[k]) + 14;
    }
    painter.setPen(QPen(kScanline, m_lineWidth, Qt::DashLine));
    painter.drawLine(QPointF(x, y + metrics.height() / 2.0),
                     QPointF(x + 14, y + metrics.height() / 2.0));
    painter.setPen(kText);
    painter.drawText(QPointF(x + 18, y + metrics.ascent()), TrapezoidView::tr("scanline j"));
}

TrapezoidView::TrapezoidView(Inspection* inspection, QWidget* parent)
    : ExplainedView(inspection, QStringLiteral("trapezoid"), parent) {
    m_canvas = new TrapezoidCanvas(this);
    m_canvas->setObjectName(QStringLiteral("trapezoidCanvas"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(title());
    layout->addWidget(m_canvas, 3);
    layout->addWidget(explanation(), 4);
}

std::optional<std::array<rl::vec3, 3>> TrapezoidView::gouraudColours(std::uint32_t triangle) const {
    const rl::FrameReplay* replay = m_inspection->replay();
    const rl::FrameTrace& frame = *m_inspection->frame();
    const rl::ScreenTriangle& tri = frame.projection->triangles[triangle];
    if (!replay || frame.scene->draws[tri.draw].shading != rl::ShadingModel::Gouraud ||
        triangle >= replay->triangleCount())
        return std::nullopt;
    // The shading stage's vertex colours, as it mixes them for any fragment of the triangle.
    for (std::uint32_t r = replay->firstRow(triangle); r < replay->endRow(triangle); ++r) {
        const rl::ReplayRow& row = replay->rows()[r];
        if (row.fragmentBegin < row.fragmentEnd)
            return replay->shade({row.fragmentBegin}).front().vertexColours;
    }
    return std::nullopt;
}

void TrapezoidView::refresh() {
    m_model.reset();
    m_followsCursor = false;
    if (const std::optional<FollowedRow> followed = followedRow(*m_inspection)) {
        const rl::FrameTrace& frame = *m_inspection->frame();
        m_followsCursor = followed->followsCursor;
        m_model = trapezoidModel(frame, followed->triangle, followed->y,
                                 gouraudColours(followed->triangle));
        m_model->pixel = followed->pixel;
        m_canvas->setContent(m_model, frame.scene->width, frame.scene->height,
                             frame.scene->rules.sampleOffset, m_inspection->lineWidth(),
                             m_inspection->presentation());
    } else {
        m_canvas->setContent(std::nullopt, 0, 0, 0.0, 1.5, false);
    }
    title()->setText(titleText());
    setExplanation(explanationHtml());
}

QString TrapezoidView::titleText() const {
    const std::shared_ptr<const rl::FrameTrace>& frame = m_inspection->frame();
    if (!frame) return tr("No frame yet.");
    if (!m_model)
        return tr(
            "Pick a pixel, or step through the frame, to see a triangle split into "
            "trapezoids.");
    const rl::ScreenTriangle& tri = frame->projection->triangles[m_model->triangle];
    const rl::Draw& draw = frame->scene->draws[tri.draw];
    QString text =
        tr("<b>Triangle %1</b> of %2").arg(tri.source + 1).arg(draw.mesh->triangles.size());
    if (m_model->row) text += QStringLiteral(", ") + tr("scanline %1").arg(m_model->row->j);
    if (m_model->pixel) text += QStringLiteral(", ") + tr("pixel %1").arg(*m_model->pixel);
    text += QStringLiteral(" &mdash; ") +
            (m_followsCursor ? tr("at the stepping cursor") : tr("the triangle selected"));
    return text;
}

QString TrapezoidView::explanationHtml() const {
    if (!m_model) return {};
    const rl::FrameTrace& frame = *m_inspection->frame();
    const rl::Scene& scene = *frame.scene;
    const rl::RasterRules& rules = scene.rules;
    const TrapezoidModel& m = *m_model;
    const rl::TrapezoidSplit& split = m.split;
    const double offset = rules.sampleOffset;
    const bool topLeft = rules.fill == rl::RasterRules::FillRule::TopLeft;
    const QString pzName = m.inverseDepth ? QStringLiteral("1/z") : QStringLiteral("pz");
    QString html;
    const auto values = [&](const rl::TrapezoidPoint& p) {
        QString s = QStringLiteral("%1 = %2").arg(pzName, pz(p.pz));
        if (m.hasColour) s += QStringLiteral(", rgb ") + rgb(p.colour);
        return s;
    };

    if (m.setup.degenerate()) {
        return QStringLiteral("<p>") +
               tr("Its area on the screen is zero: it has no inside, no trapezoid, and is not "
                  "scanned.") +
               QStringLiteral("</p>");
    }
    const rl::TrapezoidPoint& top = split.sorted[0];
    const rl::TrapezoidPoint& middle = split.sorted[1];
    const rl::TrapezoidPoint& bottom = split.sorted[2];
    html += QStringLiteral("<p>") +
            tr("Vertices sorted by j: top %1, middle %2, bottom %3. The triangle is split at "
               "the middle vertex's row j = %4.")
                .arg(vector(top.p), vector(middle.p), vector(bottom.p), number(middle.p.y));
    if (split.parts.size() == 2)
        html += QLatin1Char(' ') +
                tr("The long edge from top to bottom meets that row at s = (%1 &minus; %2) / (%3 "
                   "&minus; %2) = %4: M' = lerp(s, top, bottom) = %5, %6.")
                    .arg(number(middle.p.y), number(top.p.y), number(bottom.p.y), number(split.s),
                         vector(split.split.p), values(split.split));
    else
        html += QLatin1Char(' ') +
                tr("Two vertices share a row: the triangle is one trapezoid, two of whose "
                   "corners are the same vertex.");
    html += QStringLiteral("</p>");
    if (m.hasColour)
        html += QStringLiteral("<p>") +
                tr("Each corner carries the colour Gouraud shading worked out at its vertex, and "
                   "the depth.") +
                QStringLiteral("</p>");
    else
        html +=
            QStringLiteral("<p>") +
            tr("Each corner carries the depth%1 (colours are carried under Gouraud shading, "
               "for a triangle with a pixel on the screen, once the frame's replay is built).")
                .arg(m.inverseDepth ? tr(" as 1/z, which is linear on the screen") : QString()) +
            QStringLiteral("</p>");

    // The corners.
    html += QStringLiteral("<table cellspacing='0' cellpadding='3' border='1'><tr><th></th><th>") +
            tr("corner") + QStringLiteral("</th><th>(i, j)</th><th>") + pzName +
            QStringLiteral("</th>");
    if (m.hasColour) html += QStringLiteral("<th>(r, g, b)</th>");
    html += QStringLiteral("<th>") + tr("rows") + QStringLiteral("</th></tr>");
    for (std::size_t k = 0; k < split.parts.size(); ++k) {
        const rl::Trapezoid& t = split.parts[k];
        const std::array<std::pair<const rl::TrapezoidPoint*, QString>, 4> corners{
            std::pair{&t.tl, QStringLiteral("TL")}, std::pair{&t.tr, QStringLiteral("TR")},
            std::pair{&t.bl, QStringLiteral("BL")}, std::pair{&t.br, QStringLiteral("BR")}};
        const QString name =
            QStringLiteral("<font color='%1'>%2</font>")
                .arg(kPartColour[t.upper ? 0 : 1].name(), t.upper ? tr("upper") : tr("lower"));
        for (std::size_t c = 0; c < 4; ++c) {
            const rl::TrapezoidPoint& p = *corners[c].first;
            html += QStringLiteral("<tr>");
            if (c == 0)
                html += QStringLiteral("<th rowspan='4'>%1%2</th>")
                            .arg(name, m.part == k ? QStringLiteral(" &#9664;") : QString());
            html += QStringLiteral("<td>%1</td><td nowrap>%2</td><td>%3</td>")
                        .arg(corners[c].second, vector(p.p), pz(p.pz));
            if (m.hasColour) html += QStringLiteral("<td nowrap>%1</td>").arg(rgb(p.colour));
            if (c == 0)
                html += QStringLiteral("<td rowspan='4'>%1</td>")
                            .arg(t.firstRow <= t.lastRow
                                     ? QStringLiteral("%1&ndash;%2").arg(t.firstRow).arg(t.lastRow)
                                     : tr("none"));
            html += QStringLiteral("</tr>");
        }
    }
    html += QStringLiteral("</table>");

    // The current scanline.
    if (m.row && m.part) {
        const rl::TrapezoidRow& row = *m.row;
        const rl::Trapezoid& t = split.parts[*m.part];
        const QString j = offset != 0.0 ? QStringLiteral("(%1 + %2)").arg(row.j).arg(number(offset))
                                        : QString::number(row.j);
        html += QStringLiteral("<p><b>") +
                tr("Scanline j = %1, in the %2 trapezoid")
                    .arg(row.j)
                    .arg(t.upper ? tr("upper") : tr("lower")) +
                QStringLiteral("</b>:<br>") +
                QStringLiteral(
                    "t_j = (j &minus; TL_j) / (BL_j &minus; TL_j) = (%1 &minus; %2) / "
                    "(%3 &minus; %2) = %4")
                    .arg(j, number(t.tl.p.y), number(t.bl.p.y), number(row.tj)) +
                QStringLiteral("<br>L = lerp(t_j, TL, BL): i = %1, %2<br>")
                    .arg(number(row.left.p.x), values(row.left)) +
                QStringLiteral("R = lerp(t_j, TR, BR): i = %1, %2<br>")
                    .arg(number(row.right.p.x), values(row.right));
        const QString off =
            offset != 0.0 ? QStringLiteral(" &minus; %1").arg(number(offset)) : QString();
        if (row.empty())
            html += tr("No pixel of this row lies between L and R on the screen.");
        else if (topLeft)
            html +=
                tr("Pixels i with L_i &le; i%1 &lt; R_i: %2 to %3.")
                    .arg(offset != 0.0 ? QStringLiteral(" + %1").arg(number(offset)) : QString())
                    .arg(row.xBegin)
                    .arg(row.xEnd - 1);
        else
            html += tr("Pixels i from ceil(L_i%1) to floor(R_i%1): %2 to %3.")
                        .arg(off)
                        .arg(row.xBegin)
                        .arg(row.xEnd - 1);
        html += QStringLiteral("</p>");
        if (m.pixel && *m.pixel >= row.xBegin && *m.pixel < row.xEnd) {
            double ti = 0.0;
            const rl::TrapezoidPoint p = rl::trapezoidPixel(row, rules, *m.pixel, &ti);
            const QString i = offset != 0.0
                                  ? QStringLiteral("(%1 + %2)").arg(*m.pixel).arg(number(offset))
                                  : QString::number(*m.pixel);
            html += QStringLiteral("<p><b>") + tr("Pixel i = %1").arg(*m.pixel) +
                    QStringLiteral(
                        "</b>: t_i = (i &minus; L_i) / (R_i &minus; L_i) = (%1 &minus; "
                        "%2) / (%3 &minus; %2) = %4<br>(r, g, b, pz) = lerp(t_i, L, R): "
                        "%5")
                        .arg(i, number(row.left.p.x), number(row.right.p.x), number(ti), values(p));
            const rl::FragmentDepth fragment = rl::fragmentDepth(
                scene, *frame.projection, m.triangle, row.j, row.xBegin, *m.pixel);
            html += QStringLiteral("<br>") +
                    (rules.scan == rl::RasterRules::Scan::Dda
                         ? tr("The depth test's z there: %1 (stepped by seed 001's DDA in "
                              "double, then rounded to float).")
                               .arg(number(fragment.depth))
                     : m.inverseDepth
                         ? tr("z = 1 / (1/z) = %1; the depth test's z there: %2 (from the "
                              "barycentrics, in float).")
                               .arg(number(1.0 / p.pz), number(fragment.depth))
                         : tr("The depth test's z there: %1 (from the barycentrics, in float).")
                               .arg(number(fragment.depth)));
            html += QStringLiteral("</p>");
        }
    }

    // How this is the scan converter's scan.
    QStringList rulesText;
    rulesText << tr(
        "The row through the middle vertex belongs to the lower trapezoid only, so "
        "no row is scanned twice.");
    if (offset != 0.0)
        rulesText << tr("Pixel (i, j) is sampled at (i + %1, j + %1): t_j and t_i use those.")
                         .arg(number(offset));
    rulesText << (topLeft ? tr("Top-left rule: a sample exactly on the bottom vertex's row or on "
                               "R belongs to the next triangle.")
                          : tr("Inclusive rule: samples exactly on L, R or the bottom row are "
                               "inside."));
    if (rules.interpolation == rl::RasterRules::Interpolation::PerspectiveCorrect)
        rulesText << tr(
            "These rules interpolate colours perspective-correctly (weights over w): "
            "the lerps of the seed, linear on the screen, are what the course rules "
            "do; the rows and pixels are the same either way.");
    html += QStringLiteral("<p><i>") +
            tr("The same rows and pixels as the edge walk (scan conversion view): L_i and R_i "
               "are where the scanline crosses the triangle's edges.") +
            QLatin1Char(' ') + rulesText.join(QLatin1Char(' ')) + QStringLiteral("</i></p>");
    return html;
}

}  // namespace rasterlab
