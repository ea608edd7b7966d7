#include "stability_plot.h"

#include <QCoreApplication>
#include <QPainter>

#include <algorithm>
#include <cmath>

#include "app/plots/accuracy_plot.h"

namespace rasterlab {

namespace {

// Colour RMSE in byte steps: an exact zero sits on the floor, the top holds the crosses.
constexpr double kFloor = 1e-4, kCeiling = 1e3;

QColor rulesColour(rl::RuleSet rules) {
    switch (rules) {
        case rl::RuleSet::Course:
            return QColor(230, 120, 20);
        case rl::RuleSet::Gpu:
            return QColor(40, 100, 220);
        case rl::RuleSet::Hw2:
            return QColor(30, 150, 60);
    }
    return Qt::black;
}

QString translated(const char* text) {
    return QCoreApplication::translate("StabilityPlot", text);
}

// A log-log panel: its rectangle, its decades and the mapping of values into it.
struct Panel {
    QRectF rect;
    double x0, x1, y0, y1;
    bool reversed;  // larger values on the left

    double mapX(double v) const {
        double t = (std::log10(v) - x0) / (x1 - x0);
        if (reversed) t = 1.0 - t;
        return rect.left() + t * rect.width();
    }
    double mapY(double e) const {
        const double c = std::clamp(e, kFloor, kCeiling);
        return rect.bottom() - (std::log10(c) - y0) / (y1 - y0) * rect.height();
    }
};

void drawFrame(QPainter& p, const Panel& panel, const QString& title, const QString& xLabel) {
    p.setPen(QPen(QColor(225, 225, 225), 1));
    for (double d = panel.x0; d <= panel.x1; ++d) {
        const double x = panel.mapX(std::pow(10.0, d));
        p.drawLine(QPointF(x, panel.rect.top()), QPointF(x, panel.rect.bottom()));
    }
    for (double d = panel.y0; d <= panel.y1; ++d) {
        const double y = panel.mapY(std::pow(10.0, d));
        p.drawLine(QPointF(panel.rect.left(), y), QPointF(panel.rect.right(), y));
    }
    p.setPen(QPen(Qt::black, 1.2));
    p.setBrush(Qt::NoBrush);
    p.drawRect(panel.rect);
    const int step = panel.x1 - panel.x0 > 7 ? 3 : (panel.x1 - panel.x0 > 4 ? 2 : 1);
    for (double d = panel.x0; d <= panel.x1; d += step) {
        const double x = panel.mapX(std::pow(10.0, d));
        p.drawText(QRectF(x - 30, panel.rect.bottom() + 3, 60, 16), Qt::AlignCenter,
                   decadeLabel(d));
    }
    for (double d = panel.y0; d <= panel.y1; d += 2) {
        const double y = panel.mapY(std::pow(10.0, d));
        p.drawText(QRectF(panel.rect.left() - 48, y - 8, 44, 16), Qt::AlignRight | Qt::AlignVCenter,
                   decadeLabel(d));
    }
    p.drawText(QRectF(panel.rect.left(), panel.rect.bottom() + 19, panel.rect.width(), 16),
               Qt::AlignCenter, xLabel);
    QFont bold = p.font();
    bold.setBold(true);
    p.save();
    p.setFont(bold);
    p.drawText(QRectF(panel.rect.left(), panel.rect.top() - 20, panel.rect.width(), 18),
               Qt::AlignLeft | Qt::AlignVCenter, title);
    p.restore();
}

bool sameCurve(const rl::StabilityPoint& a, const rl::StabilityPoint& b) {
    return a.axis == b.axis && a.row.mode.rules == b.row.mode.rules &&
           a.row.precision == b.row.precision;
}

// The curves: against the reference, float solid and double dashed; float against double
// (the largest difference) dotted.
double againstReference(const rl::StabilityPoint& point) {
    return point.row.metrics.rmse * 255.0;
}
double floatAgainstDouble(const rl::StabilityPoint& point) {
    return point.floatDoubleMax * 255.0;  // NaN on double rows
}

QPen curvePen(const rl::StabilityPoint& point, bool floatAgainstDoubleCurve = false) {
    QPen pen(rulesColour(point.row.mode.rules), floatAgainstDoubleCurve ? 1.6 : 2.0);
    if (floatAgainstDoubleCurve)
        pen.setStyle(Qt::DotLine);
    else if (point.row.precision == "double")
        pen.setStyle(Qt::DashLine);
    return pen;
}

void drawCurves(QPainter& p, const Panel& panel, const rl::StabilityReport& report,
                rl::StiffnessAxis axis, double (*metric)(const rl::StabilityPoint&)) {
    const auto& points = report.points;
    const bool dotted = metric == floatAgainstDouble;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const rl::StabilityPoint& point = points[i];
        if (point.axis != axis || point.error || !std::isfinite(metric(point))) continue;
        const QPointF at(panel.mapX(point.value), panel.mapY(metric(point)));
        p.setPen(curvePen(point, dotted));
        p.setBrush(point.row.precision == "double" || dotted
                       ? QBrush(Qt::white)
                       : QBrush(rulesColour(point.row.mode.rules)));
        p.drawEllipse(at, dotted ? 2.0 : 3.0, dotted ? 2.0 : 3.0);
        for (std::size_t j = i + 1; j < points.size(); ++j) {
            if (!sameCurve(points[j], point)) continue;
            if (!points[j].error && std::isfinite(metric(points[j])))
                p.drawLine(at, QPointF(panel.mapX(points[j].value), panel.mapY(metric(points[j]))));
            break;
        }
    }
}

// One axis's curves, and a cross at the top for each point that could not be rendered.
void drawAxis(QPainter& p, const Panel& panel, const rl::StabilityReport& report,
              rl::StiffnessAxis axis) {
    drawCurves(p, panel, report, axis, againstReference);
    drawCurves(p, panel, report, axis, floatAgainstDouble);
    for (const rl::StabilityPoint& point : report.points) {
        if (point.axis != axis || !point.error) continue;
        const double x = panel.mapX(point.value), y = panel.rect.top() + 8;
        p.setPen(QPen(rulesColour(point.row.mode.rules), 2));
        p.drawLine(QPointF(x - 5, y - 5), QPointF(x + 5, y + 5));
        p.drawLine(QPointF(x - 5, y + 5), QPointF(x + 5, y - 5));
    }
}

void drawTimePanel(QPainter& p, const QRectF& rect, const rl::StabilityReport& report) {
    double lo = 1e300, hi = 0;
    for (const rl::StabilityPoint& point : report.points)
        if (!point.error) {
            lo = std::min(lo, std::max(point.row.milliseconds, 1e-2));
            hi = std::max(hi, std::max(point.row.milliseconds, 1e-2));
        }
    if (hi == 0) lo = 1, hi = 10;
    Panel panel{rect, 0, 0, std::log10(kFloor), std::log10(kCeiling), false};
    decades(lo, hi, panel.x0, panel.x1);
    drawFrame(p, panel,
              QCoreApplication::translate("StabilityPlot", "every point: error against time"),
              QCoreApplication::translate("StabilityPlot", "time per frame (ms, log scale)"));
    for (const rl::StabilityPoint& point : report.points) {
        if (point.error) continue;
        p.setPen(curvePen(point));
        p.setBrush(point.row.precision == "double" ? QBrush(Qt::white)
                                                   : QBrush(rulesColour(point.row.mode.rules)));
        p.drawEllipse(QPointF(panel.mapX(std::max(point.row.milliseconds, 1e-2)),
                              panel.mapY(point.row.metrics.rmse * 255.0)),
                      3.0, 3.0);
    }
}

void drawLegend(QPainter& p, QPointF at) {
    double x = at.x();
    for (rl::RuleSet rules : {rl::RuleSet::Course, rl::RuleSet::Gpu})
        for (const char* precision : {QT_TRANSLATE_NOOP("StabilityPlot", "float"),
                                      QT_TRANSLATE_NOOP("StabilityPlot", "double")}) {
            QPen pen(rulesColour(rules), 2);
            if (std::string_view(precision) == "double") pen.setStyle(Qt::DashLine);
            p.setPen(pen);
            p.drawLine(QPointF(x, at.y()), QPointF(x + 30, at.y()));
            p.setPen(Qt::black);
            const QString label = QString::fromLatin1(rl::ruleSetName(rules)) + QLatin1Char(' ') +
                                  translated(precision);
            p.drawText(QPointF(x + 36, at.y() + 5), label);
            x += 60 + p.fontMetrics().horizontalAdvance(label);
        }
    QPen dotted(Qt::black, 1.6);
    dotted.setStyle(Qt::DotLine);
    p.setPen(dotted);
    p.drawLine(QPointF(x, at.y()), QPointF(x + 30, at.y()));
    p.setPen(Qt::black);
    const QString floatDouble =
        QCoreApplication::translate("StabilityPlot", "float against double, largest difference");
    p.drawText(QPointF(x + 36, at.y() + 5), floatDouble);
    x += 60 + p.fontMetrics().horizontalAdvance(floatDouble);
    p.drawText(QPointF(16, at.y() + 24),
               QCoreApplication::translate(
                   "StabilityPlot",
                   "y: colour error in byte steps (log; RMSE against the exact reference, "
                   "or the largest float-double difference); x: stiffer to the right; a "
                   "cross: the scene could not be rendered"));
}

// The axes of the report, in sweep order.
std::vector<rl::StiffnessAxis> sweptAxes(const rl::StabilityReport& report) {
    std::vector<rl::StiffnessAxis> axes;
    for (const rl::StabilityPoint& point : report.points)
        if (std::find(axes.begin(), axes.end(), point.axis) == axes.end())
            axes.push_back(point.axis);
    return axes;
}

// Four panels a row at most: every axis and the time panel make 4 x 2, one axis 2 x 1.
struct Grid {
    int columns, rows;
};
Grid gridFor(int axes) {
    const int panels = std::max(1, axes + 1);
    const int columns = std::min(4, panels);
    return {columns, std::min(2, (panels + columns - 1) / columns)};
}

}  // namespace

QSize stabilityPlotSize(int axes) {
    const Grid grid = gridFor(axes);
    return {20 + 370 * grid.columns, 84 + 408 * grid.rows};
}

QSize stabilityPlotSize(const rl::StabilityReport& report) {
    return stabilityPlotSize(int(sweptAxes(report).size()));
}

QImage stabilityPlot(const rl::StabilityReport& report, const QString& title, QSize size) {
    QImage image(size, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    QFont font = p.font();
    font.setPixelSize(12);
    p.setFont(font);
    QFont big = font;
    big.setBold(true);
    big.setPixelSize(15);
    p.setFont(big);
    p.drawText(QRectF(16, 8, size.width() - 32, 22), Qt::AlignLeft | Qt::AlignVCenter, title);
    p.setFont(font);
    drawLegend(p, QPointF(16, 44));

    const std::vector<rl::StiffnessAxis> axes = sweptAxes(report);
    const auto [columns, rows] = gridFor(int(axes.size()));
    const double top = 84, cellW = (size.width() - 20.0) / columns,
                 cellH = (size.height() - top) / rows;
    for (std::size_t i = 0; i <= axes.size() && i < std::size_t(columns * rows); ++i) {
        const double left = 10 + (i % columns) * cellW, cellTop = top + (i / columns) * cellH;
        const QRectF rect(left + 56, cellTop + 26, cellW - 72, cellH - 70);
        if (i == axes.size()) {
            drawTimePanel(p, rect, report);
            break;
        }
        const rl::StiffnessAxisInfo& info = rl::axisInfo(axes[i]);
        const auto [lo, hi] = std::minmax_element(info.values.begin(), info.values.end());
        Panel panel{rect,
                    0,
                    0,
                    std::log10(kFloor),
                    std::log10(kCeiling),
                    info.values.front() > info.values.back()};
        decades(*lo, *hi, panel.x0, panel.x1);
        drawFrame(p, panel, QString::fromLatin1(info.name),
                  QCoreApplication::translate("StabilityPlot", "%1 (%2, log scale)")
                      .arg(QString::fromLatin1(info.name), QString::fromLatin1(info.unit)));
        drawAxis(p, panel, report, axes[i]);
    }
    return image;
}

}  // namespace rasterlab
