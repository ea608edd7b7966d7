#include "pixel_inspector.h"

#include <QAbstractItemDelegate>
#include <QApplication>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QGridLayout>
#include <QPainter>
#include <QResizeEvent>
#include <QPixmap>
#include <QRegularExpression>
#include <QSignalBlocker>
#include <QStyle>
#include <QStyleOptionViewItem>
#include <QTableWidget>
#include <QVBoxLayout>

#include <QPolygonF>
#include <QScrollBar>

#include <algorithm>
#include <climits>
#include <cmath>
#include <vector>

#include "views/inspection.h"
#include "views/painted_labels.h"
#include "views/pixel_history.h"
#include "views/pixel_text.h"
#include "views/their_colour.h"
#include "views/view_font.h"

namespace rasterlab {

namespace {

// The text on lines no wider than `width` where it has spaces to break at.
QString wrapped(const QString& text, const QFontMetrics& metrics, int width) {
    QStringList lines;
    for (const QString& word : text.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        const QString longer = lines.isEmpty() ? word : lines.back() + QLatin1Char(' ') + word;
        if (!lines.isEmpty() && metrics.horizontalAdvance(longer) <= width)
            lines.back() = longer;
        else
            lines << word;
    }
    return lines.join(QLatin1Char('\n'));
}

// The narrowest width in which no line of `text` wraps onto more than `most` lines.
int widthForLines(const QString& text, const QFontMetrics& metrics, int most) {
    const QStringList lines = text.split(QLatin1Char('\n'));
    int widest = 0;
    for (const QString& line : lines) widest = std::max(widest, metrics.horizontalAdvance(line));
    const auto fits = [&](int width) {
        return std::all_of(lines.begin(), lines.end(), [&](const QString& line) {
            return wrapped(line, metrics, width).count(QLatin1Char('\n')) < most;
        });
    };
    int low = 0, high = widest;  // fits(high) holds: every line on one line
    while (low < high) {
        const int mid = (low + high) / 2;
        if (fits(mid))
            high = mid;
        else
            low = mid + 1;
    }
    return high;
}

QString bytesText(const std::array<std::uint8_t, 4>& b) {
    return QStringLiteral("(%1, %2, %3)").arg(b[0]).arg(b[1]).arg(b[2]);
}

QPixmap swatch(const std::array<std::uint8_t, 4>& b, int size) {
    QPixmap pixmap(size, size);
    pixmap.fill(QColor(b[0], b[1], b[2]));
    QPainter painter(&pixmap);
    painter.setPen(QColor(128, 128, 128));
    painter.drawRect(0, 0, size - 1, size - 1);
    return pixmap;
}

}  // namespace

// Three stacked bars, one per channel: the terms side by side from 0, each term's value
// written below its part of the bar (14  141.113  177.534: ambient, diffuse, specular), the
// colour scale (the value that becomes byte 255) marked by a line, the total written at the
// bar's end. The text is the widget's font, so it grows with the dock's. The legend's names
// wrap onto more lines when the bars are narrow (beside the vectors in a narrow dock), the
// bars' height growing with them.
class TermBars : public QWidget, public PaintedLabels {
public:
    struct Segment {
        QString name;
        QColor colour;
        rl::vec3 value;
    };

    explicit TermBars(QWidget* parent) : QWidget(parent) {
        setMinimumSize(140, 120);
        setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    }
    void setBars(std::vector<Segment> segments, rl::vec3 total, float scale) {
        m_segments = std::move(segments);
        m_total = total;
        m_scale = scale;
        fitHeight();
        update();
    }
    QSize sizeHint() const override { return {320, 130}; }

protected:
    void resizeEvent(QResizeEvent* event) override {
        QWidget::resizeEvent(event);
        fitHeight();
    }
    void changeEvent(QEvent* event) override {
        QWidget::changeEvent(event);
        if (event->type() == QEvent::FontChange) fitHeight();
    }

    void paintEvent(QPaintEvent*) override {
        QPainter painter(this);
        painter.fillRect(rect(), kBackground);
        clearLabels();
        if (m_segments.empty()) return;
        const QFont f = font();
        painter.setFont(f);
        const QFontMetrics metrics(f);
        const double line = metrics.height();
        float most = m_scale;
        for (int c = 0; c < 3; ++c) {
            float sum = 0.0f;
            for (const Segment& s : m_segments) sum += std::max(0.0f, s.value[c]);
            most = std::max(most, sum);
        }
        const double left = metrics.horizontalAdvance(QStringLiteral("G")) + 10;
        const double right = width() - metrics.horizontalAdvance(QStringLiteral("000.0")) - 10;
        const double unit = (right - left) / (double(most) * 1.05);
        const double barHeight = barHeightOf(line);
        const double top = line + 6;
        const std::array<QColor, 3> channelColours{QColor(255, 110, 110), QColor(110, 220, 110),
                                                   QColor(120, 160, 255)};
        std::array<QPointF, 3> totalsAt;  // where each channel's total is written
        for (int c = 0; c < 3; ++c) {
            const double y = top + c * rowHeight(line);
            painter.setPen(channelColours[static_cast<std::size_t>(c)]);
            drawLabel(painter, QRectF(0, y, left - 4, barHeight), Qt::AlignRight | Qt::AlignVCenter,
                      channelNames()[static_cast<std::size_t>(c)]);
            double x = left;
            for (const Segment& s : m_segments) {
                const double w = std::max(0.0f, s.value[c]) * unit;
                if (w <= 0.0) continue;
                painter.fillRect(QRectF(x, y, w, barHeight), s.colour);
                painter.setPen(QColor(20, 20, 20));
                painter.drawLine(QPointF(x + w, y), QPointF(x + w, y + barHeight));
                x += w;
            }
            totalsAt[static_cast<std::size_t>(c)] = QPointF(x + 4, y);
        }
        // The terms' values, written once the scale is drawn: as many digits as the width
        // lets every channel's values show whole (the formula below has them all).
        std::vector<Value> values;
        for (const int digits : {6, 4, 3}) {
            values = termValues(metrics, left, unit, top, digits);
            if (std::all_of(values.begin(), values.end(), [&](const Value& v) {
                    return v.baseline.x() + metrics.horizontalAdvance(v.text) <= width() - 2;
                }))
                break;
        }
        // The colour scale: what reaches it or goes beyond becomes byte 255. The totals go
        // over it on the background's colour, so that the line never crosses their digits.
        const double scaleX = left + double(m_scale) * unit;
        const double bottom = top + 3 * rowHeight(line) - 6;
        painter.setPen(QPen(QColor(255, 255, 255), 1.0, Qt::DashLine));
        painter.drawLine(QPointF(scaleX, top - 3), QPointF(scaleX, bottom + 3));
        for (const Value& v : values) {
            painter.fillRect(textBox(painter, v.baseline, v.text).adjusted(-2, -1, 2, 1),
                             kBackground);
            painter.setPen(v.colour);
            drawLabel(painter, v.baseline, v.text);
        }
        painter.setPen(QColor(230, 230, 230));
        for (int c = 0; c < 3; ++c) {
            const QString total = num(m_total[c], 4);
            const QPointF at = totalsAt[static_cast<std::size_t>(c)];
            painter.fillRect(
                QRectF(at.x() - 2, at.y(), metrics.horizontalAdvance(total) + 4, barHeight),
                kBackground);
            drawLabel(painter, QRectF(at.x(), at.y(), width() - at.x(), barHeight),
                      Qt::AlignVCenter, total);
        }
        const QString scaleText = m_scale == 255.0f
                                      ? QStringLiteral("255")
                                      : PixelInspector::tr("%1 = byte 255").arg(num(m_scale));
        drawLabel(painter,
                  QPointF(std::clamp(scaleX - metrics.horizontalAdvance(scaleText) / 2.0, 0.0,
                                     width() - metrics.horizontalAdvance(scaleText) - 2.0),
                          metrics.ascent() + 2),
                  scaleText);
        // Legend, on as many lines as the width needs.
        const double y = bottom + 8;
        for (const auto& [s, at] : legendPlaces(metrics, y)) {
            painter.fillRect(QRectF(at.x(), at.y() + 2, 10, line - 4), s->colour);
            painter.setPen(QColor(220, 220, 220));
            drawLabel(painter, QPointF(at.x() + 14, at.y() + metrics.ascent()), s->name);
        }
    }

private:
    static constexpr QColor kBackground{32, 32, 36};

    struct Value {
        QString text;
        QColor colour;
        QPointF baseline;
    };

    // Each term's value, under the start of its part of the bar or after the value before.
    std::vector<Value> termValues(const QFontMetrics& metrics, double left, double unit,
                                  double top, int digits) const {
        std::vector<Value> values;
        const double line = metrics.height();
        for (int c = 0; c < 3; ++c) {
            const double y = top + c * rowHeight(line) + barHeightOf(line) + 1 + metrics.ascent();
            double x = left;
            double labelX = left;  // where the next term's value may start
            for (const Segment& s : m_segments) {
                const double w = std::max(0.0f, s.value[c]) * unit;
                if (w <= 0.0) continue;
                const QString text = num(s.value[c], digits);
                const double at = std::max(x, labelX);
                // In the term's colour, lightened where it is dark on the background.
                const QColor colour = s.colour.lightness() < 140 ? s.colour.lighter(150) : s.colour;
                values.push_back({text, colour, QPointF(at, y)});
                labelX = at + metrics.horizontalAdvance(text) +
                         metrics.horizontalAdvance(QStringLiteral("  "));
                x += w;
            }
        }
        return values;
    }

    // A channel's bar, the line of its terms' values below it, and the gap to the next.
    static double barHeightOf(double line) { return line * 1.2; }
    static double rowHeight(double line) { return barHeightOf(line) + 1 + line + 8; }

    // Each legend entry's top left: after the one before, or at the start of a new line.
    std::vector<std::pair<const Segment*, QPointF>> legendPlaces(const QFontMetrics& metrics,
                                                                 double top) const {
        std::vector<double> widths;
        for (const Segment& s : m_segments)
            widths.push_back(14 + metrics.horizontalAdvance(s.name));
        const auto flow =
            flowPlaces(widths, metrics.horizontalAdvance(QStringLiteral("G")) + 10, width() - 2);
        std::vector<std::pair<const Segment*, QPointF>> places;
        for (std::size_t i = 0; i < flow.size(); ++i)
            places.emplace_back(&m_segments[i],
                                QPointF(flow[i].x, top + flow[i].line * metrics.height()));
        return places;
    }

    // Room for the bars, and below them for the legend's lines at this width.
    void fitHeight() {
        const QFontMetrics metrics(font());
        const double line = metrics.height();
        const double legendTop = line + 6 + 3 * rowHeight(line) - 6 + 8;
        const auto places = legendPlaces(metrics, legendTop);
        const double bottom = places.empty() ? legendTop + line : places.back().second.y() + line;
        const int height = std::max(int(std::ceil(bottom)) + 4, int(line * 6 + 20));
        if (height != this->height() || minimumHeight() != height) setFixedHeight(height);
    }

    std::vector<Segment> m_segments;
    rl::vec3 m_total = rl::vec3(0.0f);
    float m_scale = 255.0f;
};

// N, L, V and R (or H) from the surface point, drawn in the plane of incidence (the plane
// of N and L, in which R lies too): N points up, the surface is the horizontal line, L and R
// are at their true angles, and V is projected onto the page (dashed when it leaves it by
// more than a little).
class LightingVectors : public QWidget, public PaintedLabels {
public:
    explicit LightingVectors(QWidget* parent) : QWidget(parent) { fitSize(); }
    void setVectors(std::optional<std::array<rl::vec3, 4>> vectors, QString reflectionName,
                    double lineWidth) {
        m_vectors = vectors;
        m_reflection = std::move(reflectionName);
        m_lineWidth = lineWidth;
        update();
    }

protected:
    void changeEvent(QEvent* event) override {
        QWidget::changeEvent(event);
        if (event->type() == QEvent::FontChange) fitSize();
    }
    // The drawing grows with its labels' font: 12 by 11 lines.
    void fitSize() {
        const int line = fontMetrics().height();
        setFixedSize(std::max(180, line * 12), std::max(160, line * 11));
    }

    void paintEvent(QPaintEvent*) override {
        QPainter painter(this);
        painter.fillRect(rect(), QColor(32, 32, 36));
        clearLabels();
        if (!m_vectors) return;
        const auto& [n, l, v, r] = *m_vectors;
        const QFont f = font();
        painter.setFont(f);
        const QFontMetrics metrics(f);
        painter.setRenderHint(QPainter::Antialiasing);
        if (!(glm::length(n) > 0.0f)) {
            painter.setPen(QColor(200, 200, 200));
            drawLabel(painter, rect(), Qt::AlignCenter | Qt::TextWordWrap,
                      PixelInspector::tr("no normal"));
            return;
        }
        // The page: up = N, right = the part of L (else of V) across N.
        const rl::vec3 up = glm::normalize(n);
        rl::vec3 across(0.0f);
        for (const rl::vec3& d : {l, v, rl::vec3(1, 0, 0), rl::vec3(0, 1, 0)}) {
            const rl::vec3 t = d - glm::dot(d, up) * up;
            if (glm::length(t) > 1e-4f) {
                across = glm::normalize(t);
                break;
            }
        }
        const rl::vec3 out = glm::cross(across, up);
        const QPointF centre(width() / 2.0, height() - metrics.height() - 14.0);
        const double length = std::min(width() / 2.0 - 16.0, centre.y() - 14.0);
        const auto project = [&](const rl::vec3& d) {
            return centre + QPointF(glm::dot(d, across) * length, -glm::dot(d, up) * length);
        };
        painter.setPen(QPen(QColor(140, 140, 150), 2.0));
        painter.drawLine(QPointF(12, centre.y()), QPointF(width() - 12, centre.y()));
        // Arrows that fall on one another (N, L and R when the light is straight in front)
        // are drawn thinner one after the other, so each colour shows, and share one label.
        struct Label {
            QPointF tip, at;
            QString text;
            QColor colour;
        };
        std::vector<Label> labels;
        double penWidth = m_lineWidth * 2.2;
        const auto arrow = [&](const rl::vec3& d, const QColor& colour, const QString& name) {
            if (!(glm::length(d) > 0.0f)) return;
            const QPointF tip = project(d);
            const QPointF dir = tip - centre;
            const double len = std::hypot(dir.x(), dir.y());
            const bool leaves = std::abs(glm::dot(d, out)) > 0.25f * glm::length(d);
            painter.setPen(
                QPen(colour, penWidth, leaves ? Qt::DashLine : Qt::SolidLine, Qt::RoundCap));
            penWidth = std::max(1.0, penWidth - m_lineWidth * 0.6);
            painter.drawLine(centre, tip);
            if (len > 1.0) {
                const QPointF u = dir / len, w(-u.y(), u.x());
                QPolygonF head;
                head << tip << tip - u * 8.0 + w * 4.0 << tip - u * 8.0 - w * 4.0;
                painter.setPen(Qt::NoPen);
                painter.setBrush(colour);
                painter.drawPolygon(head);
            }
            for (Label& label : labels) {
                if (std::hypot(label.tip.x() - tip.x(), label.tip.y() - tip.y()) < 6.0) {
                    label.text += QStringLiteral(" = ") + name;
                    return;
                }
            }
            labels.push_back(
                {tip, len > 1.0 ? tip + dir / len * 10.0 : tip + QPointF(8, -8), name, colour});
        };
        arrow(up, QColor(255, 255, 255), QStringLiteral("N"));
        arrow(l, QColor(255, 210, 60), QStringLiteral("L"));
        arrow(r, QColor(240, 120, 240), m_reflection);
        arrow(v, QColor(110, 200, 255), QStringLiteral("V"));
        painter.setPen(Qt::NoPen);
        painter.setBrush(Qt::white);
        painter.drawEllipse(centre, 2.5, 2.5);
        painter.setPen(QColor(170, 170, 180));
        drawLabel(painter, QRectF(0, height() - metrics.height() - 4, width(), metrics.height()),
                  Qt::AlignCenter, PixelInspector::tr("in the plane of N and L"));
        // Each label beside its arrow's tip, inside the picture; where it would cover one
        // already drawn (tips close together: "R = V" by "N"), above, below or beside it.
        for (const Label& label : labels) {
            painter.setPen(label.colour);
            const double w = metrics.horizontalAdvance(label.text) + 4.0;
            const double h = metrics.height();
            const QRectF box(std::clamp(label.at.x() - w / 2.0, 0.0, width() - w),
                             std::clamp(label.at.y() - h / 2.0, 0.0, height() - h), w, h);
            drawLabel(painter,
                      freePlace(box, rect(),
                                {QPointF(0, 0), QPointF(0, -h), QPointF(0, h), QPointF(w, 0),
                                 QPointF(-w, 0), QPointF(w, -h), QPointF(-w, -h),
                                 QPointF(0, -2 * h), QPointF(0, 2 * h)}),
                      Qt::AlignCenter, label.text);
        }
    }

private:
    std::optional<std::array<rl::vec3, 4>> m_vectors;
    QString m_reflection;
    double m_lineWidth = 1.5;
};

PixelInspector::PixelInspector(Inspection* inspection, QWidget* parent)
    : QWidget(parent), m_inspection(inspection) {
    setObjectName(QStringLiteral("pixelInspector"));
    m_verdictLabel = new QLabel(this);
    m_verdictLabel->setObjectName(QStringLiteral("pixelVerdict"));
    m_verdictLabel->setWordWrap(true);
    m_verdictLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);

    m_table = new QTableWidget(0, 6, this);
    m_table->setObjectName(QStringLiteral("pixelHistory"));
    m_titles = {tr("Step"),   tr("Triangle"), tr("Depth test"),
                tr("Before"), tr("After"),    tr("Result")};
    m_table->setHorizontalHeaderLabels(m_titles);
    m_table->verticalHeader()->setVisible(false);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    // The columns sized by fitColumns(): the sentences wrap when the dock is narrow.
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_table->horizontalHeader()->setStretchLastSection(true);
    // Titles in the font they are measured in: not bold over the selected row's columns.
    m_table->horizontalHeader()->setHighlightSections(false);
    m_table->setWordWrap(true);
    m_table->viewport()->installEventFilter(this);
    m_table->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);

    m_legend = new QLabel(tr("▶ holds the pixel at the stepping cursor; grey rows are not "
                             "reached yet. Select a row to see its lighting."),
                          this);
    m_legend->setObjectName(QStringLiteral("pixelHistoryLegend"));
    m_legend->setWordWrap(true);
    m_breakdownTitle = new QLabel(this);
    m_breakdownTitle->setObjectName(QStringLiteral("pixelBreakdownTitle"));
    m_breakdownTitle->setWordWrap(true);
    m_bars = new TermBars(this);
    m_bars->setObjectName(QStringLiteral("pixelTermBars"));
    m_vectors = new LightingVectors(this);
    m_vectors->setObjectName(QStringLiteral("pixelVectors"));
    m_formula = new QLabel(this);
    m_formula->setObjectName(QStringLiteral("pixelFormula"));
    m_formula->setTextFormat(Qt::PlainText);
    m_formula->setWordWrap(true);
    m_formula->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_flags = new QLabel(this);
    m_flags->setObjectName(QStringLiteral("pixelFlags"));
    m_flags->setWordWrap(true);
    m_flags->setTextFormat(Qt::RichText);

    m_pictures = new QWidget(this);
    m_pictures->setObjectName(QStringLiteral("pixelPictures"));
    m_bars->setParent(m_pictures);
    m_vectors->setParent(m_pictures);
    auto* pictures = new QHBoxLayout(m_pictures);
    pictures->setContentsMargins(0, 0, 0, 0);
    pictures->addWidget(m_bars, 1);
    pictures->addWidget(m_vectors, 0, Qt::AlignTop);
    // The history (verdict, table, legend) and the lighting (title, pictures, formula), each
    // a column of its own, one above the other or side by side in a grid (arrange()).
    m_historyBox = new QWidget(this);
    m_historyLayout = new QVBoxLayout(m_historyBox);
    m_historyLayout->setContentsMargins(0, 0, 0, 0);
    for (QWidget* w : std::initializer_list<QWidget*>{m_verdictLabel, m_table, m_legend})
        m_historyLayout->addWidget(w);
    m_historyLayout->addStretch(1);
    m_lightingBox = new QWidget(this);
    m_lightingLayout = new QVBoxLayout(m_lightingBox);
    m_lightingLayout->setContentsMargins(0, 0, 0, 0);
    for (QWidget* w : std::initializer_list<QWidget*>{m_breakdownTitle, m_pictures, m_formula})
        m_lightingLayout->addWidget(w);
    m_lightingLayout->addStretch(1);
    m_grid = new QGridLayout(this);
    // Narrow margins: in the lecture layout the lit pixel's formula takes the height to the
    // last line.
    m_grid->setContentsMargins(4, 4, 4, 4);
    m_lightingLayout->setSpacing(4);
    arrange();
    const auto follow = [this] {
        if (isVisible()) refresh();
    };
    connect(m_inspection, &Inspection::frameChanged, this, follow);
    connect(m_inspection, &Inspection::replayChanged, this, follow);
    connect(m_inspection, &Inspection::cursorChanged, this, follow);
    connect(m_inspection, &Inspection::pixelPicked, this, follow);
    connect(m_inspection, &Inspection::presentationChanged, this, follow);
    connect(m_table, &QTableWidget::currentCellChanged, this, [this](int row) {
        if (row >= 0 && row != m_selected) selectRow(row);
    });
    applyPresentation();
    fillTable();
}

void PixelInspector::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    arrange();
    refresh();
}

void PixelInspector::arrange() {
    // The room it is shown in: a scroll area's viewport (a dock) makes it as tall as its
    // column needs, so its own height says nothing. Side by side from 1.4 times as wide as
    // tall, where both columns have a docked inspector's width.
    QWidget* room = parentWidget();
    if (room != m_room) {
        if (m_room) m_room->removeEventFilter(this);
        m_room = room;
        if (m_room) m_room->installEventFilter(this);
    }
    const QSize size = room ? room->size() : this->size();
    const bool beside = size.width() >= 1.4 * size.height() && size.width() >= 2 * 380;
    if (m_grid->count() > 0 && beside == m_beside) {
        widenHistory();
        return;
    }
    m_beside = beside;
    // The flags close the history's column side by side, the lighting's in one column.
    m_historyLayout->removeWidget(m_flags);
    m_lightingLayout->removeWidget(m_flags);
    (beside ? m_historyLayout : m_lightingLayout)->insertWidget(3, m_flags);
    m_grid->removeWidget(m_historyBox);
    m_grid->removeWidget(m_lightingBox);
    for (int r = 0; r < m_grid->rowCount(); ++r) m_grid->setRowStretch(r, 0);
    for (int c = 0; c < m_grid->columnCount(); ++c) m_grid->setColumnStretch(c, 0);
    m_grid->addWidget(m_historyBox, 0, 0);
    m_grid->addWidget(m_lightingBox, beside ? 0 : 1, beside ? 1 : 0);
    m_grid->setColumnStretch(0, 1);
    if (beside) m_grid->setColumnStretch(1, 1);
    const int row = beside ? 1 : 2;
    // What is left of the height below the last row.
    m_grid->setRowStretch(row, 1);
    widenHistory();
}

void PixelInspector::widenHistory() {
    // Side by side, the history's columns whole when that leaves the lighting 38 % of the
    // width; one column, no minimum.
    const QWidget* room = m_room ? m_room.data() : this;
    // Never so wide that the lighting's column falls below its own minimum (a scroll bar),
    // nor below the width in which each line of the formula takes at most three lines.
    const QMargins margins = m_grid->contentsMargins();
    const int least = m_lightingBox->minimumSizeHint().width();
    const QString key = m_formula->font().toString() + QLatin1Char('\n') + m_formula->text();
    if (key != m_formulaWidthKey) {  // worked out again only for another formula or font
        m_formulaWidthKey = key;
        m_formulaWidth = widthForLines(m_formula->text(), m_formula->fontMetrics(), 3);
    }
    const int lighting = std::max(least, m_formulaWidth) + m_grid->horizontalSpacing() +
                         margins.left() + margins.right();
    const int width = m_beside ? std::min({m_wholeTableWidth, room->width() * 62 / 100,
                                           room->width() - lighting})
                               : 0;
    m_grid->setColumnMinimumWidth(0, width);
}

void PixelInspector::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    arrange();
}

void PixelInspector::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    // Another font (presentation mode): the table's height is worked out again once the
    // header has taken it.
    if (event->type() == QEvent::FontChange) {
        followFont();
        QMetaObject::invokeMethod(this, &PixelInspector::fitTableHeight, Qt::QueuedConnection);
    }
}

void PixelInspector::applyPresentation() {
    // Larger text when presenting on its own; in the window, the dock's font (which the
    // window enlarges itself), whatever its size.
    m_presenting = m_inspection->presentation();
    setFont(scaledFont(parentWidget(), m_inspection->textScale(1.4)));
    followFont();
}

void PixelInspector::followFont() {
    // Only the weight set: the size follows the inspector's font.
    QFont bold;
    bold.setBold(true);
    m_verdictLabel->setFont(bold);
    m_breakdownTitle->setFont(bold);
    QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    mono.setPointSizeF(font().pointSizeF());
    m_formula->setFont(mono);
}

void PixelInspector::refresh() {
    const std::shared_ptr<const rl::FrameTrace>& frame = m_inspection->frame();
    const QPoint picked = m_inspection->pickedPixel();
    const bool failed = !m_inspection->replayError().isEmpty();
    const std::shared_ptr<const rl::FrameReplay> replay = m_inspection->replayPtr();
    const bool rebuild = frame != m_builtFrame.lock() || replay != m_builtReplay.lock() ||
                         picked != m_builtPixel || failed != m_builtWithoutReplay;
    if (rebuild) {
        m_builtFrame = frame;
        m_builtReplay = replay;
        m_builtPixel = picked;
        m_builtWithoutReplay = failed;
        m_userSelected = false;
        m_breakdown.reset();
        m_history.rebuild(*m_inspection);
    }
    const bool marksMoved = m_history.updateCursorMarks(*m_inspection);
    const bool restyle = m_inspection->presentation() != m_presenting;
    // Most steps do not reach this pixel's fragments: nothing to show again then.
    if (!rebuild && !marksMoved && !restyle) return;
    if (restyle) applyPresentation();
    if (!m_userSelected) m_selected = m_history.defaultRow();
    updateBreakdown();
    fillTable();
}

void PixelInspector::setTheirFrame(std::shared_ptr<const rl::FrameTrace> frame, QImage theirs) {
    m_theirFrame = frame;
    m_theirs = std::move(theirs);
    m_builtFrame.reset();  // the table and the verdict are made again
    refresh();
}

QString PixelInspector::theirColourText() const {
    const auto checked = m_theirFrame.lock();
    const QPoint p = m_inspection->pickedPixel();
    const QImage& ours = m_inspection->frameImage();
    if (!checked || checked != m_inspection->frame() || m_theirs.isNull() ||
        !m_theirs.rect().contains(p) || !ours.rect().contains(p))
        return {};
    const QColor a = m_theirs.pixelColor(p), b = ours.pixelColor(p);
    QString text = tr("Your renderer's colour here: (%1, %2, %3); ours (%4, %5, %6).")
                       .arg(a.red())
                       .arg(a.green())
                       .arg(a.blue())
                       .arg(b.red())
                       .arg(b.green())
                       .arg(b.blue());
    if (a.rgb() == b.rgb()) return text;
    // The fragment that holds the pixel at the end of the frame: which of its Phong terms,
    // changed alone, would give their colour.
    const int last = static_cast<int>(m_history.rows().size()) - 1;
    // The breakdown shown is that fragment's when its row is selected: no second trace.
    const bool shown = last >= 0 && m_breakdown && m_breakdown->historyRow == last &&
                       m_breakdown->fragment == m_history.rows()[last].fragment &&
                       m_breakdown->fragment != rl::kNoFragment;
    const auto breakdown = shown       ? m_breakdown
                           : last >= 0 ? rowBreakdown(*m_inspection, m_history, last)
                                       : std::nullopt;
    if (!breakdown) {
        text += QLatin1Char(' ') + tr("No triangle of ours holds this pixel.");
    } else if (!TheirColourTerms::workedOutFor(*breakdown)) {
        text += QLatin1Char(' ') +
                tr("The terms are worked out for the course's lighting in flat or Phong "
                   "shading only.");
    } else {
        const std::array<std::uint8_t, 4> theirs{std::uint8_t(a.red()), std::uint8_t(a.green()),
                                                 std::uint8_t(a.blue()), std::uint8_t(a.alpha())};
        text += QLatin1Char('\n') + tr("For your colour, each term alone:") + QLatin1Char('\n') +
                TheirColourTerms::lines(*breakdown, theirs, checked->scene->conventions.colourScale)
                    .join(QLatin1Char('\n'));
    }
    return text;
}

void PixelInspector::selectRow(int row) {
    m_userSelected = true;
    m_selected = row >= 0 && row < static_cast<int>(m_history.rows().size()) ? row : -1;
    updateBreakdown();
    showBreakdown();
}

QString PixelInspector::formulaText() const {
    return m_breakdown ? m_breakdown->formula.join(QLatin1Char('\n')) : QString();
}

void PixelInspector::updateBreakdown() {
    const PixelHistoryRow* row =
        m_selected >= 0 && m_selected < static_cast<int>(m_history.rows().size())
            ? &m_history.rows()[m_selected]
            : nullptr;
    if (m_breakdown && row && row->kind != PixelHistoryRow::Kind::Initial &&
        row->fragment != rl::kNoFragment && m_breakdown->historyRow == m_selected &&
        m_breakdown->fragment == row->fragment)
        return;  // already shown
    m_breakdown = rowBreakdown(*m_inspection, m_history, m_selected);
}

void PixelInspector::fillTable() {
    const QSignalBlocker block(m_table);
    QFont bold = m_table->font();
    bold.setBold(true);
    const QString theirs = theirColourText();
    m_verdictLabel->setText(theirs.isEmpty() ? m_history.verdict()
                                             : m_history.verdict() + QLatin1Char('\n') + theirs);
    const std::vector<PixelHistoryRow>& rows = m_history.rows();
    m_table->setRowCount(static_cast<int>(rows.size()));
    const int swatchSize = m_presenting ? 20 : 12;
    int number = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const PixelHistoryRow& row = rows[i];
        QString step;
        switch (row.kind) {
            case PixelHistoryRow::Kind::Initial:
                step = tr("start");
                break;
            case PixelHistoryRow::Kind::Fragment:
                step = QString::number(++number);
                break;
            case PixelHistoryRow::Kind::Final:
                step = tr("end");
                break;
        }
        if (row.atCursor) step = QStringLiteral("▶ ") + step;
        const auto item = [&](int column, const QString& text) {
            auto* cell = new QTableWidgetItem(text);
            if (!row.reached) cell->setForeground(QColor(150, 150, 150));
            if (row.atCursor) cell->setFont(bold);
            if (row.atCursor) cell->setToolTip(tr("holds the pixel at the stepping cursor"));
            if (!row.reached) cell->setToolTip(tr("not reached yet by the stepping cursor"));
            m_table->setItem(static_cast<int>(i), column, cell);
            return cell;
        };
        item(0, step);
        item(1, row.triangleText);
        item(2, row.depthText);
        item(5, row.resultText);
        const auto colourCell = [&](int column,
                                    const std::optional<std::array<std::uint8_t, 4>>& bytes) {
            if (row.kind != PixelHistoryRow::Kind::Fragment && column == 3) {
                item(column, QString());
                return;
            }
            if (!bytes) {
                item(column, tr("not kept"))
                    ->setToolTip(tr("Without stepping, the colours of writes overwritten "
                                    "later are not kept."));
                return;
            }
            QTableWidgetItem* cell = item(column, bytesText(*bytes));
            cell->setIcon(QIcon(swatch(*bytes, swatchSize)));
            // The bytes whole when a narrow column shows only the swatch.
            cell->setToolTip(cell->toolTip().isEmpty()
                                 ? cell->text()
                                 : cell->text() + QLatin1Char('\n') + cell->toolTip());
        };
        colourCell(3, row.before);
        colourCell(4, row.after);
    }
    m_table->setIconSize(QSize(swatchSize, swatchSize));
    fitColumns();
    showBreakdown();
}

bool PixelInspector::eventFilter(QObject* watched, QEvent* event) {
    // The columns follow the table's width (after the layout, which the inspector's own
    // resize comes before).
    if (watched == m_table->viewport() && event->type() == QEvent::Resize)
        QMetaObject::invokeMethod(this, &PixelInspector::fitColumns, Qt::QueuedConnection);
    if (watched == m_room && event->type() == QEvent::Resize) arrange();
    return QWidget::eventFilter(watched, event);
}

void PixelInspector::fitColumns() {
    // Each column as wide as its text when the table has the room; when not, the columns
    // shrink in proportion to what wrapping can save, down to their longest word (a cell
    // never wraps inside a word, a title wraps onto two lines), and their rows grow. Short of
    // even that, the Before column goes (each row's Before is the After of the row above,
    // and the After cell's tooltip holds it), and a colour shrinks to its swatch.
    constexpr int kBefore = 3, kAfter = 4;
    const int columns = m_table->columnCount();
    const QHeaderView* header = m_table->horizontalHeader();
    const QFontMetrics titleMetrics = header->fontMetrics();
    const int titleMargin = 2 * style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, header) + 2;
    const int margin =
        2 * (style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, m_table) + 1);
    static const QRegularExpression space(QStringLiteral("\\s+"));
    // least: a colour on two lines; fewest: down to its swatch.
    std::vector<int> whole(columns), least(columns), fewest(columns);
    QStyleOptionViewItem cellOption;
    cellOption.initFrom(m_table->viewport());
    cellOption.decorationSize = m_table->iconSize();
    for (int c = 0; c < columns; ++c) {
        const QString& title = m_titles[c];
        whole[c] = titleMetrics.horizontalAdvance(title) + titleMargin;
        least[c] = 0;
        for (const QString& word : title.split(space, Qt::SkipEmptyParts))
            least[c] = std::max(least[c], titleMetrics.horizontalAdvance(word) + titleMargin);
        fewest[c] = least[c];
        for (int r = 0; r < m_table->rowCount(); ++r) {
            const QTableWidgetItem* item = m_table->item(r, c);
            if (!item || item->text().isEmpty()) continue;
            const QFontMetrics cell(item->font());
            const int icon = item->icon().isNull() ? 0 : m_table->iconSize().width() + 4;
            // The delegate's own measure, which knows the style's margins and icon spacing.
            const int all = std::max(cell.horizontalAdvance(item->text()) + margin + icon,
                                     m_table->itemDelegate()
                                         ->sizeHint(cellOption, m_table->model()->index(r, c))
                                         .width()) +
                            2;
            whole[c] = std::max(whole[c], all);
            if (icon) {  // on two lines at the least ("(255, 240," over "180)")
                least[c] = std::max(
                    least[c], std::min(all, cell.horizontalAdvance(QStringLiteral("(255, 255,")) +
                                                margin + icon + 2));
                fewest[c] = std::max(fewest[c], margin + icon + 2);
                continue;
            }
            for (const QString& word : item->text().split(space, Qt::SkipEmptyParts))
                least[c] = std::max(least[c], cell.horizontalAdvance(word) + margin + 2);
            fewest[c] = least[c];
        }
    }
    const auto sum = [&](const std::vector<int>& widths, bool before) {
        int total = 0;
        for (int c = 0; c < columns; ++c)
            if (before || c != kBefore) total += widths[c];
        return total;
    };
    const int room = m_table->viewport()->width();
    // The first that fits: every column; without Before; without Before, colours as swatches.
    const bool before = sum(least, true) <= room;
    if (!before && sum(least, false) > room) least = fewest;
    m_table->setColumnHidden(kBefore, !before);
    // Beside the lighting, the history asks for the width of every column whole.
    const int wholeTable = sum(whole, true) + 2 * m_table->frameWidth() +
                           m_table->verticalScrollBar()->sizeHint().width();
    if (wholeTable != m_wholeTableWidth) {
        m_wholeTableWidth = wholeTable;
        widenHistory();
    }
    const int wholeSum = sum(whole, before), leastSum = sum(least, before);
    const double shrink = wholeSum <= room   ? 0.0
                          : leastSum >= room ? 1.0
                                             : double(wholeSum - room) / (wholeSum - leastSum);
    for (int c = 0; c < columns; ++c) {
        const int width = whole[c] - int(std::ceil(shrink * (whole[c] - least[c])));
        m_table->setColumnWidth(c, width);
        const QString title = wrapped(m_titles[c], titleMetrics, width - titleMargin);
        if (m_table->horizontalHeaderItem(c)->text() != title)
            m_table->horizontalHeaderItem(c)->setText(title);
    }
    // The Before column hidden: the After cells tell it.
    for (int r = 0; r < m_table->rowCount(); ++r) {
        QTableWidgetItem* was = m_table->item(r, kBefore);
        QTableWidgetItem* now = m_table->item(r, kAfter);
        if (!was || !now || was->text().isEmpty()) continue;
        QString tip = now->data(Qt::UserRole).toString();
        if (tip.isEmpty()) {
            tip = now->toolTip();
            now->setData(Qt::UserRole, tip);
        }
        if (!before) tip = tr("Before: %1").arg(was->text()) + QLatin1Char('\n') + tip;
        now->setToolTip(tip);
    }
    // The table no narrower than its columns at their least: the dock scrolls, or the window
    // gives it the room (MainWindow::fitDocks).
    int tableLeast = sum(fewest, false) + 2 * m_table->frameWidth();
    if (m_table->rowCount() > 10) tableLeast += m_table->verticalScrollBar()->sizeHint().width();
    m_table->setMinimumWidth(tableLeast);
    m_table->resizeRowsToContents();
    fitTableHeight();
}

void PixelInspector::fitTableHeight() {
    // Tall enough for every row, up to ten; beyond, it scrolls.
    // The header's hint: its titles may have just wrapped onto two lines.
    int height = m_table->horizontalHeader()->sizeHint().height() + 2 * m_table->frameWidth();
    for (int r = 0; r < std::min(m_table->rowCount(), 10); ++r) height += m_table->rowHeight(r);
    if (m_table->horizontalScrollBar()->isVisible() ||
        m_table->horizontalHeader()->length() > m_table->viewport()->width())
        height += m_table->horizontalScrollBar()->sizeHint().height();
    m_table->setFixedHeight(height);
}

void PixelInspector::showBreakdown() {
    {
        const QSignalBlocker block(m_table);
        if (m_selected >= 0)
            m_table->selectRow(m_selected);
        else
            m_table->clearSelection();
    }
    const double lineWidth = m_inspection->lineWidth();
    m_flags->clear();
    if (!m_breakdown) {
        QString why;
        if (m_history.pixel().x() >= 0) {
            const PixelHistoryRow* row =
                m_selected >= 0 ? &m_history.rows()[static_cast<std::size_t>(m_selected)] : nullptr;
            if (m_history.traced() && row && row->kind != PixelHistoryRow::Kind::Initial)
                why =
                    tr("Without stepping, only the lighting of the fragment that holds the pixel "
                       "at the end is recorded.");
            else if (row && row->kind == PixelHistoryRow::Kind::Initial)
                why = tr("The cleared pixel is not lit.");
            else
                why =
                    tr("No fragment holds the pixel at the cursor: select a row of the history "
                       "to see its lighting.");
        }
        m_breakdownTitle->setText(why);
        m_bars->setVisible(false);
        m_vectors->setVisible(false);
        m_formula->clear();
        return;
    }
    const LightingBreakdown& b = *m_breakdown;
    const PixelHistoryRow& row = m_history.rows()[static_cast<std::size_t>(b.historyRow)];
    QString title =
        tr("Lighting of step %1, triangle %2: %3")
            .arg(row.kind == PixelHistoryRow::Kind::Final ? tr("end")
                                                          : QString::number(b.historyRow))
            .arg(row.triangleText, b.heading);
    if (row.kind == PixelHistoryRow::Kind::Fragment && row.verdict != rl::FragmentVerdict::Written)
        title += QStringLiteral(" ") + tr("(rejected: this colour was never written)");
    m_breakdownTitle->setText(title);
    const rl::FrameTrace& frame = *m_inspection->frame();
    const rl::Draw& draw = frame.scene->draws[frame.projection->triangles[b.event.triangle].draw];
    std::vector<TermBars::Segment> segments;
    if (b.event.model == rl::ShadingModel::Gouraud) {
        const std::array<QColor, 3> colours{QColor(200, 120, 80), QColor(120, 180, 90),
                                            QColor(90, 140, 210)};
        const std::array<QString, 3> names{QStringLiteral("α C1"), QStringLiteral("β C2"),
                                           QStringLiteral("γ C3")};
        for (std::size_t k = 0; k < 3; ++k)
            segments.push_back({names[k], colours[k], b.weights[k] * b.vertexColours[k]});
    } else if (b.lighting == rl::LightingModel::Unlit) {
        segments.push_back({tr("object colour"), QColor(170, 170, 170), b.unlit});
    } else {
        if (b.emission != rl::vec3(0.0f))
            segments.push_back({tr("emission"), QColor(200, 110, 200), b.emission});
        if (b.lighting == rl::LightingModel::CoursePhong)
            segments.push_back({tr("ambient"), QColor(110, 110, 125), b.ambient});
        if (b.perLight.size() > 1) {
            // Light by light: each light's diffuse and specular, in shades of its own.
            for (std::size_t k = 0; k < b.perLight.size(); ++k) {
                const int shade = int(k % 4) * 30;
                segments.push_back({tr("diffuse %1").arg(k + 1),
                                    QColor(70 + shade, 150 - shade / 2, 220 - shade),
                                    b.perLight[k].diffuse});
                segments.push_back({tr("specular %1").arg(k + 1),
                                    QColor(235, 235 - shade, 190 - shade), b.perLight[k].specular});
            }
        } else {
            segments.push_back({tr("diffuse"), QColor(70, 150, 220), b.diffuse});
            if (b.lighting == rl::LightingModel::CoursePhong || draw.material.shininess > 0.0f)
                segments.push_back({tr("specular"), QColor(235, 235, 190), b.specular});
        }
    }
    m_bars->setBars(std::move(segments), b.colour, frame.scene->conventions.colourScale);
    m_bars->setVisible(true);
    const bool vectors =
        b.event.model != rl::ShadingModel::Gouraud && b.lighting != rl::LightingModel::Unlit;
    if (vectors) {
        const rl::PhongSample& s = b.event.sample;
        // R, or the half vector H under Blinn-Phong (the command files' model, or the course's
        // with the slides' option).
        const bool half = b.lighting != rl::LightingModel::CoursePhong ||
                          draw.specular == rl::SpecularModel::BlinnPhong;
        m_vectors->setVectors(std::array<rl::vec3, 4>{s.n, s.l, s.v, s.r},
                              half ? QStringLiteral("H") : QStringLiteral("R"), lineWidth);
    }
    m_vectors->setVisible(vectors);
    m_formula->setText(formulaText());
    widenHistory();  // the formula's lines may ask the lighting's column for more width
    if (!b.flagTexts.isEmpty()) {
        QString html;
        for (const QString& text : b.flagTexts)
            html += QStringLiteral("&#9888; ") + text.toHtmlEscaped() + QStringLiteral("<br>");
        m_flags->setText(html);
    } else if (b.event.model == rl::ShadingModel::Gouraud) {
        m_flags->clear();  // the vertices' own cases belong to their lighting, not shown here
    } else {
        m_flags->setText(tr("No special case: every term applies as written."));
    }
}

}  // namespace rasterlab
