#include "accuracy_plot.h"

#include <QCoreApplication>
#include <QFontMetrics>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace rasterlab {

namespace {

QString lit(const char* s) {
    return QString::fromLatin1(s);
}

QColor shadingColour(rl::ShadingModel shading) {
    switch (shading) {
        case rl::ShadingModel::Flat:
        case rl::ShadingModel::Painter:
            return QColor(230, 120, 20);
        case rl::ShadingModel::Gouraud:
            return QColor(40, 100, 220);
        case rl::ShadingModel::Phong:
            return QColor(30, 150, 60);
    }
    return Qt::black;
}

// The marker of a rule set: course a circle, gpu a square, hw2 a triangle.
QPainterPath marker(rl::RuleSet rules, QPointF centre, double radius) {
    QPainterPath path;
    switch (rules) {
        case rl::RuleSet::Course:
            path.addEllipse(centre, radius, radius);
            break;
        case rl::RuleSet::Gpu:
            path.addRect(QRectF(centre.x() - radius, centre.y() - radius, 2 * radius, 2 * radius));
            break;
        case rl::RuleSet::Hw2:
            path.moveTo(centre.x(), centre.y() - radius * 1.2);
            path.lineTo(centre.x() + radius * 1.1, centre.y() + radius * 0.8);
            path.lineTo(centre.x() - radius * 1.1, centre.y() + radius * 0.8);
            path.closeSubpath();
            break;
    }
    return path;
}

}  // namespace

void decades(double lo, double hi, double& first, double& last) {
    first = std::floor(std::log10(lo));
    last = std::ceil(std::log10(hi));
    if (last <= first) last = first + 1;
}

QString decadeLabel(double exponent) {
    const double v = std::pow(10.0, exponent);
    if (exponent >= 0 && exponent < 6) return QString::number(v, 'f', 0);
    if (exponent < 0 && exponent > -4) return QString::number(v, 'f', int(-exponent));
    return lit("1e%1").arg(int(exponent));
}

QImage accuracyPlot(const rl::AccuracyReport& report, const QString& title, QSize size) {
    QImage image(size, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    QFont font = p.font();
    font.setPixelSize(13);
    p.setFont(font);

    const QRectF plot(90, 50, size.width() - 320, size.height() - 120);
    // RMSE in byte steps; an exact zero is drawn on the floor of the scale.
    constexpr double kFloor = 1e-3;
    double xLo = 1e300, xHi = 0, yLo = 1e300, yHi = 0;
    for (const rl::AccuracyRow& row : report.rows) {
        const double ms = std::max(row.milliseconds, 1e-3);
        const double e = std::max(row.metrics.rmse * 255.0, kFloor);
        xLo = std::min(xLo, ms);
        xHi = std::max(xHi, ms);
        yLo = std::min(yLo, e);
        yHi = std::max(yHi, e);
    }
    if (report.rows.empty()) xLo = yLo = 1, xHi = yHi = 10;
    double x0, x1, y0, y1;
    decades(xLo, xHi, x0, x1);
    decades(yLo, yHi, y0, y1);
    const auto mapX = [&](double ms) {
        return plot.left() + (std::log10(std::max(ms, 1e-3)) - x0) / (x1 - x0) * plot.width();
    };
    const auto mapY = [&](double e) {
        return plot.bottom() - (std::log10(std::max(e, kFloor)) - y0) / (y1 - y0) * plot.height();
    };

    // Grid and axes.
    p.setPen(QPen(QColor(225, 225, 225), 1));
    for (double d = x0; d <= x1; ++d)
        for (int m = 1; m < 10; ++m) {
            const double x = mapX(std::pow(10.0, d) * m);
            if (x <= plot.right() + 0.5)
                p.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
        }
    for (double d = y0; d <= y1; ++d)
        for (int m = 1; m < 10; ++m) {
            const double y = mapY(std::pow(10.0, d) * m);
            if (y >= plot.top() - 0.5)
                p.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
        }
    p.setPen(QPen(Qt::black, 1.5));
    p.drawRect(plot);
    for (double d = x0; d <= x1; ++d) {
        const double x = mapX(std::pow(10.0, d));
        p.drawText(QRectF(x - 40, plot.bottom() + 6, 80, 18), Qt::AlignCenter, decadeLabel(d));
    }
    for (double d = y0; d <= y1; ++d) {
        const double y = mapY(std::pow(10.0, d));
        p.drawText(QRectF(plot.left() - 86, y - 9, 80, 18), Qt::AlignRight | Qt::AlignVCenter,
                   decadeLabel(d));
    }
    p.drawText(
        QRectF(plot.left(), plot.bottom() + 30, plot.width(), 20), Qt::AlignCenter,
        QCoreApplication::translate("AccuracyPlot", "median time per frame (ms, log scale)"));
    p.save();
    p.translate(20, plot.center().y());
    p.rotate(-90);
    p.drawText(
        QRectF(-plot.height() / 2, -10, plot.height(), 20), Qt::AlignCenter,
        QCoreApplication::translate(
            "AccuracyPlot", "colour RMSE against the exact reference (byte steps, log scale)"));
    p.restore();
    QFont bold = font;
    bold.setBold(true);
    bold.setPixelSize(15);
    p.setFont(bold);
    p.drawText(QRectF(plot.left(), 12, size.width() - plot.left() - 10, 24), Qt::AlignLeft, title);
    p.setFont(font);

    // The points: float filled, double hollow. Each float point is named where its label
    // overlaps no other (right, left, above or below it); a double point sits on its float
    // point's row, to the right, and is left unnamed.
    std::vector<QRectF> taken;
    const QFontMetrics metrics(p.font());
    const QRectF canvas(0, 0, size.width(), size.height());
    for (const rl::AccuracyRow& row : report.rows) {
        const QPointF at(mapX(row.milliseconds), mapY(row.metrics.rmse * 255.0));
        const double radius = 4.0 + 2.0 * std::log2(double(row.mode.supersample));
        const bool inDouble = row.precision == "double";
        p.setPen(inDouble ? QPen(shadingColour(row.mode.shading), 2) : QPen(Qt::black, 1));
        p.setBrush(inDouble ? QBrush(Qt::white) : QBrush(shadingColour(row.mode.shading)));
        p.drawPath(marker(row.mode.rules, at, radius));
        taken.push_back(QRectF(at.x() - radius, at.y() - radius, 2 * radius, 2 * radius));
    }
    p.setPen(Qt::black);
    for (const rl::AccuracyRow& row : report.rows) {
        if (row.precision == "double") continue;
        const QPointF at(mapX(row.milliseconds), mapY(row.metrics.rmse * 255.0));
        const double radius = 4.0 + 2.0 * std::log2(double(row.mode.supersample));
        const QString label = QString::fromStdString(rl::accuracyModeName(row.mode));
        const QSizeF box(metrics.horizontalAdvance(label) + 2, metrics.height());
        const QPointF places[] = {
            {at.x() + radius + 3, at.y() - box.height() / 2},
            {at.x() - radius - 3 - box.width(), at.y() - box.height() / 2},
            {at.x() - box.width() / 2, at.y() - radius - 2 - box.height()},
            {at.x() - box.width() / 2, at.y() + radius + 2},
        };
        for (const QPointF& place : places) {
            const QRectF rect(place, box);
            if (!canvas.contains(rect)) continue;
            bool free = true;
            for (const QRectF& other : taken) free = free && !other.intersects(rect);
            if (!free) continue;
            p.drawText(rect, Qt::AlignLeft | Qt::AlignVCenter, label);
            taken.push_back(rect);
            break;
        }
    }

    // The legend.
    double y = plot.top();
    const double lx = plot.right() + 24;
    p.setPen(Qt::black);
    p.drawText(QPointF(lx, y), QCoreApplication::translate("AccuracyPlot", "colour: shading"));
    for (rl::ShadingModel s :
         {rl::ShadingModel::Flat, rl::ShadingModel::Gouraud, rl::ShadingModel::Phong}) {
        y += 20;
        p.setBrush(shadingColour(s));
        p.drawPath(marker(rl::RuleSet::Course, QPointF(lx + 6, y - 4), 5));
        p.drawText(QPointF(lx + 18, y), QString::fromLatin1(rl::shadingModelName(s)));
    }
    y += 30;
    p.drawText(QPointF(lx, y), QCoreApplication::translate("AccuracyPlot", "shape: rules"));
    p.setBrush(QColor(160, 160, 160));
    for (rl::RuleSet r : {rl::RuleSet::Course, rl::RuleSet::Gpu, rl::RuleSet::Hw2}) {
        y += 20;
        p.drawPath(marker(r, QPointF(lx + 6, y - 4), 5));
        p.drawText(QPointF(lx + 18, y), QString::fromLatin1(rl::ruleSetName(r)));
    }
    y += 30;
    p.drawText(QPointF(lx, y),
               QCoreApplication::translate("AccuracyPlot", "filled: float; hollow: double"));
    y += 20;
    p.drawText(QPointF(lx, y),
               QCoreApplication::translate("AccuracyPlot", "size: samples per pixel"));
    y += 20;
    p.drawText(QPointF(lx, y), QCoreApplication::translate("AccuracyPlot", "exact reference:"));
    y += 18;
    p.drawText(QPointF(lx, y), QCoreApplication::translate("AccuracyPlot", "%1 ms, %2 rays")
                                   .arg(report.referenceMilliseconds, 0, 'f', 0)
                                   .arg(report.referenceRays));
    y += 18;
    p.drawText(QPointF(lx, y),
               QCoreApplication::translate("AccuracyPlot", "an RMSE of 0 sits on the floor"));
    return image;
}

QRgb heatColour(float t) {
    t = std::clamp(t, 0.0f, 1.0f);
    // An exact pixel is dark blue (black is left for pixels neither image covers); above
    // zero, a hot body: red, then yellow, then white.
    if (t == 0.0f) return qRgb(20, 20, 70);
    const float r = std::clamp(0.15f + t * 2.6f, 0.0f, 1.0f);
    const float g = std::clamp(t * 3.0f - 1.0f, 0.0f, 1.0f);
    const float b = std::clamp(t * 3.0f - 2.0f, 0.0f, 1.0f);
    return qRgb(int(std::lround(255 * r)), int(std::lround(255 * g)), int(std::lround(255 * b)));
}

QImage errorHeatMap(const rl::Image<float>& error, float maxError) {
    const int barWidth = 110;
    const int width = error.width(), height = std::max(error.height(), 160);
    QImage image(width + barWidth, height, QImage::Format_RGB32);
    image.fill(Qt::black);
    const float scale = maxError > 0.0f ? maxError : 1.0f;
    for (int y = 0; y < error.height(); ++y) {
        auto* line = reinterpret_cast<QRgb*>(image.scanLine(y));
        for (int x = 0; x < width; ++x) {
            const float e = error.at(x, y);
            if (std::isnan(e)) continue;  // neither image covers it: black
            line[x] = e < 0.0f ? qRgb(255, 0, 255) : heatColour(e / scale);
        }
    }
    // The colour bar, top = maxError.
    QPainter p(&image);
    QFont font = p.font();
    font.setPixelSize(11);
    p.setFont(font);
    const int top = 10, bottom = height - 40, x = width + 10;
    for (int y = top; y <= bottom; ++y) {
        const float t = 1.0f - float(y - top) / float(bottom - top);
        p.setPen(QColor::fromRgb(heatColour(t)));
        p.drawLine(x, y, x + 16, y);
    }
    p.setPen(Qt::white);
    p.drawRect(x, top, 16, bottom - top);
    p.drawText(QPointF(x + 20, top + 8), QString::number(scale * 255.0f, 'g', 3) + lit("+"));
    p.drawText(QPointF(x + 20, (top + bottom) / 2 + 4), QString::number(scale * 127.5f, 'g', 3));
    p.drawText(QPointF(x + 20, bottom + 4), lit("0"));
    p.drawText(QPointF(x, bottom + 18), QCoreApplication::translate("AccuracyPlot", "byte steps"));
    p.fillRect(x, bottom + 24, 10, 10, QColor(255, 0, 255));
    p.drawText(QPointF(x + 14, bottom + 33),
               QCoreApplication::translate("AccuracyPlot", "coverage"));
    return image;
}

}  // namespace rasterlab
