#include "near_clip_view.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>
#include <array>
#include <cmath>

#include "views/inspection.h"
#include "views/number_text.h"
#include "views/painted_labels.h"
#include "views/view_font.h"

namespace rasterlab {

namespace {

const QColor kBackground(32, 32, 36);
const QColor kBehind(120, 40, 40, 90);
const QColor kPlane(255, 120, 110);
const QColor kKept(90, 220, 130);
const QColor kDropped(240, 90, 80);
const QColor kMade(255, 221, 51);
const QColor kText(225, 225, 230);
const QColor kOutline(170, 170, 185);
const std::array<QColor, 2> kFan{QColor(90, 170, 255, 110), QColor(255, 160, 60, 110)};

// At most this many triangles in the list (a frame may clip thousands).
constexpr int kMaxListed = 5000;
// The canvas's two headers: wrapped to their half when it is narrow.
constexpr int kHeaderFlags = Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap;

int stepIndex(NearClipStep s) {
    return static_cast<int>(s);
}

}  // namespace

// Sutherland-Hodgman against the rectangle's four sides, one after the other, with the
// projection stage's walk (projection.h).
QPolygonF clipPolygonToRect(QPolygonF polygon, const QRectF& r) {
    const auto side = [&](auto inside, auto cross) {
        QPolygonF out;
        rl::clipPolygonAgainstPlane(polygon, out, inside, cross);
        polygon = out;
    };
    const auto atX = [](const QPointF& a, const QPointF& b, double x) {
        return QPointF(x, a.y() + (b.y() - a.y()) * (x - a.x()) / (b.x() - a.x()));
    };
    const auto atY = [](const QPointF& a, const QPointF& b, double y) {
        return QPointF(a.x() + (b.x() - a.x()) * (y - a.y()) / (b.y() - a.y()), y);
    };
    side([&](const QPointF& p) { return p.x() >= r.left(); },
         [&](const QPointF& a, const QPointF& b) { return atX(a, b, r.left()); });
    side([&](const QPointF& p) { return p.x() <= r.right(); },
         [&](const QPointF& a, const QPointF& b) { return atX(a, b, r.right()); });
    side([&](const QPointF& p) { return p.y() >= r.top(); },
         [&](const QPointF& a, const QPointF& b) { return atY(a, b, r.top()); });
    side([&](const QPointF& p) { return p.y() <= r.bottom(); },
         [&](const QPointF& a, const QPointF& b) { return atY(a, b, r.bottom()); });
    return polygon;
}

namespace {

QString fateText(rl::TriangleFate fate) {
    switch (fate) {
        case rl::TriangleFate::Inside:
            return NearClipView::tr("wholly in front");
        case rl::TriangleFate::Clipped:
            return NearClipView::tr("clipped");
        case rl::TriangleFate::Behind:
            return NearClipView::tr("wholly behind");
        case rl::TriangleFate::ClippedAway:
            return NearClipView::tr("outside a clip plane");
        case rl::TriangleFate::Culled:
            return NearClipView::tr("culled");
        case rl::TriangleFate::BackFace:
            return NearClipView::tr("hidden back face");
        case rl::TriangleFate::BeyondGuardBand:
            return NearClipView::tr("beyond the guard band");
        case rl::TriangleFate::NonFinite:
            return NearClipView::tr("not finite");
    }
    return {};
}

// The list's data for mesh triangle `source` of draw `draw`: both in one number.
QVariant listKey(quint64 draw, quint64 source) {
    return QVariant::fromValue((draw << 32) | source);
}

}  // namespace

NearClipModel nearClipModel(const rl::FrameTrace& frame, std::uint32_t draw, std::uint32_t source) {
    const rl::Projection& projection = *frame.projection;
    NearClipModel m;
    m.draw = draw;
    m.source = source;
    m.fate = projection.draws[draw].fate[source];
    m.record = rl::nearClipOf(*frame.scene, projection, draw, source);
    m.projected = rl::screenTrianglesOf(projection, draw, source);
    m.nearClipping = projection.mode == rl::NearPlane::Mode::Clip;
    m.otherPlanes = !frame.scene->draws[draw].clipPlanes.empty();
    return m;
}

// The side view (w across, view y or x up) and the screen with the projected triangles.
class NearClipCanvas : public QWidget, public PaintedLabels {
public:
    explicit NearClipCanvas(QWidget* parent) : QWidget(parent) {
        setMinimumSize(260, 180);
        setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    }
    void setContent(std::optional<NearClipModel> model, std::shared_ptr<const rl::FrameTrace> frame,
                    int step, int axis, double lineWidth, bool presentation) {
        m_model = std::move(model);
        m_frame = std::move(frame);
        m_step = step;
        m_axis = axis;
        m_lineWidth = lineWidth;
        m_presentation = presentation;
        update();
    }
    QSize sizeHint() const override { return {460, 300}; }

protected:
    void paintEvent(QPaintEvent*) override;

private:
    void paintSide(QPainter& painter, const QRectF& area);
    void paintScreen(QPainter& painter, const QRectF& area);
    void label(QPainter& painter, QPointF at, const QString& text, const QColor& colour);
    // A sentence wrapped to the area's width, its last line at `bottom`, moved up off the
    // labels already drawn.
    void note(QPainter& painter, const QRectF& area, double bottom, const QString& text,
              const QColor& colour);

    std::optional<NearClipModel> m_model;
    std::shared_ptr<const rl::FrameTrace> m_frame;
    int m_step = 0;
    int m_axis = 0;  // 0: view y up, 1: view x up
    double m_lineWidth = 1.5;
    bool m_presentation = false;
};

void NearClipCanvas::label(QPainter& painter, QPointF at, const QString& text,
                           const QColor& colour) {
    const QFontMetrics metrics(painter.font());
    // Labels that would overlap one already there (points close in the picture): one under
    // the other.
    const auto boxAt = [&](QPointF p) {
        return QRectF(p.x() - 2, p.y() - metrics.ascent() - 1, metrics.horizontalAdvance(text) + 4,
                      metrics.height() + 2);
    };
    for (bool moved = true; moved;) {
        moved = false;
        for (const QRect& used : labelRects()) {
            if (QRectF(used).intersects(boxAt(at))) {
                at.ry() = used.y() + used.height() + metrics.ascent() + 2;
                moved = true;
            }
        }
    }
    const QRectF box = boxAt(at);
    recordLabel(box);
    painter.fillRect(box, QColor(0, 0, 0, 170));
    painter.setPen(colour);
    painter.drawText(at, text);
}

void NearClipCanvas::note(QPainter& painter, const QRectF& area, double bottom, const QString& text,
                          const QColor& colour) {
    const int flags = Qt::AlignLeft | Qt::TextWordWrap;
    const QRectF lines = painter.boundingRect(
        QRectF(area.left() + 4, area.top(), area.width() - 8, area.height()), flags, text);
    QRectF box(area.left() + 2, bottom - lines.height() - 1, lines.width() + 4, lines.height() + 2);
    for (bool moved = true; moved && box.top() > area.top();) {
        moved = false;
        for (const QRect& used : labelRects())
            if (QRectF(used).intersects(box)) {
                box.moveBottom(used.y() - 2);
                moved = true;
            }
    }
    if (box.top() < area.top()) box.moveTop(area.top());  // a short view: over the picture
    recordLabel(box);
    painter.fillRect(box, QColor(0, 0, 0, 170));
    painter.setPen(colour);
    painter.drawText(box.adjusted(2, 1, -2, -1), flags, text);
}

void NearClipCanvas::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), kBackground);
    if (!m_model || !m_frame) {
        painter.setPen(kText);
        painter.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap,
                         NearClipView::tr("No triangle to show: select one, step into the frame, "
                                          "or choose one in the list."));
        return;
    }
    painter.setRenderHint(QPainter::Antialiasing);
    // The view's font (the dock's: larger when presenting or zoomed), a little smaller on
    // the drawing unless presenting.
    const QFont font = labelFont(this, m_presentation ? 1.0 : 0.95);
    painter.setFont(font);
    clearLabels();
    const double split = width() * 0.6;
    paintSide(painter, QRectF(0, 0, split, height()).adjusted(6, 6, -6, -6));
    painter.setPen(QPen(QColor(80, 80, 90), 1.0));
    painter.drawLine(QPointF(split, 6), QPointF(split, height() - 6));
    paintScreen(painter, QRectF(split, 0, width() - split, height()).adjusted(8, 6, -6, -6));
}

void NearClipCanvas::paintSide(QPainter& painter, const QRectF& area) {
    const NearClipModel& m = *m_model;
    const rl::NearClipRecord& r = m.record;
    const QFontMetrics metrics(painter.font());
    // A point's place across: its w (w = dot(P, A) + near: the view z for the course camera);
    // up: its view y (or x).
    const auto across = [&](double distance) { return distance + r.nearW; };
    const auto up = [&](const rl::dvec4& p) { return m_axis == 0 ? p.y : p.x; };
    std::array<QPointF, 3> v{};
    for (std::size_t k = 0; k < 3; ++k)
        v[k] = QPointF(across(r.edges[k].distanceA), up(r.pView[k]));
    // The triangle; the plane and the eye too when they are not far away compared with it.
    double uMin = v[0].x(), uMax = uMin;
    double vMin = v[0].y(), vMax = vMin;
    for (const QPointF& p : v) {
        uMin = std::min(uMin, p.x());
        uMax = std::max(uMax, p.x());
        vMin = std::min(vMin, p.y());
        vMax = std::max(vMax, p.y());
    }
    const double size = std::max(uMax - uMin, vMax - vMin);
    const bool planeShown = r.nearW >= uMin - 3.0 * size && r.nearW <= uMax + 3.0 * size;
    if (planeShown) {
        uMin = std::min(uMin, r.nearW);
        uMax = std::max(uMax, r.nearW);
    }
    const bool eyeShown = planeShown && uMin <= 3.0 * size && uMax >= -3.0 * size &&
                          std::min(std::abs(vMin), std::abs(vMax)) <= 3.0 * size;
    if (eyeShown) {
        uMin = std::min(uMin, 0.0);
        uMax = std::max(uMax, 0.0);
        vMin = std::min(vMin, 0.0);
        vMax = std::max(vMax, 0.0);
    }
    const double extent = std::max({uMax - uMin, vMax - vMin, 1e-12});
    const double pad = 0.12 * extent;
    uMin -= pad;
    uMax += pad;
    vMin -= pad;
    vMax += pad;
    // The header wrapped to the side's width (it ran over the screen's header in Portuguese),
    // kept free of labels, drawn last over the picture.
    const QString title =
        NearClipView::tr("side view: w across (view z for the course camera), view %1 up")
            .arg(m_axis == 0 ? QStringLiteral("y") : QStringLiteral("x"));
    const QRectF header = painter.boundingRect(area, kHeaderFlags, title);
    recordLabel(header);
    const QRectF plot = area.adjusted(4, header.height() + 6, -4, -metrics.height() - 6);
    // One scale for both axes: the picture is not distorted.
    const double scale = std::min(plot.width() / (uMax - uMin), plot.height() / (vMax - vMin));
    const double u0 = (uMin + uMax) / 2, v0 = (vMin + vMax) / 2;
    const auto at = [&](double u, double vv) {
        return QPointF(plot.center().x() + (u - u0) * scale, plot.center().y() - (vv - v0) * scale);
    };
    const auto atP = [&](const QPointF& p) { return at(p.x(), p.y()); };

    painter.save();
    painter.setClipRect(area);
    // Behind the plane, the plane and the eye.
    const double planeX = at(r.nearW, 0).x();
    painter.fillRect(QRectF(QPointF(area.left(), area.top()), QPointF(planeX, area.bottom())),
                     kBehind);
    painter.setPen(QPen(kPlane, m_lineWidth * 1.3));
    painter.drawLine(QPointF(planeX, area.top()), QPointF(planeX, area.bottom()));
    const QPointF eye = at(0, 0);
    if (eyeShown) {
        painter.setPen(QPen(QColor(120, 120, 130), 1.0, Qt::DotLine));
        painter.drawLine(at(uMin, 0), at(uMax, 0));
        painter.setPen(Qt::NoPen);
        painter.setBrush(kText);
        QPolygonF glyph;
        glyph << eye + QPointF(-10, -6) << eye + QPointF(0, 0) << eye + QPointF(-10, 6);
        painter.drawPolygon(glyph);
    }

    const bool showPolygon = m_step >= stepIndex(NearClipStep::Polygon);
    const bool showSplit = m_step >= stepIndex(NearClipStep::Split);
    // The triangle's outline.
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(kOutline, m_lineWidth, showPolygon ? Qt::DashLine : Qt::SolidLine));
    painter.drawPolygon(QPolygonF({atP(v[0]), atP(v[1]), atP(v[2])}));
    // The output polygon, or its fan of triangles.
    QPolygonF polygon;
    for (const rl::NearClipPoint& p : r.polygon)
        polygon << at(p.made ? r.nearW : across(r.edges[p.index].distanceA), up(p.pView));
    if (showPolygon && polygon.size() >= 3) {
        if (showSplit) {
            for (std::size_t k = 0; k < r.triangles.size(); ++k) {
                const auto& t = r.triangles[k];
                painter.setPen(Qt::NoPen);
                painter.setBrush(kFan[k % 2]);
                painter.drawPolygon(QPolygonF({polygon[qsizetype(t[0])], polygon[qsizetype(t[1])],
                                               polygon[qsizetype(t[2])]}));
            }
            if (r.triangles.size() == 2) {
                painter.setPen(QPen(Qt::white, m_lineWidth * 1.2, Qt::DashLine));
                painter.drawLine(polygon[0], polygon[2]);
            }
        } else {
            painter.setPen(Qt::NoPen);
            painter.setBrush(QColor(90, 220, 130, 80));
            painter.drawPolygon(polygon);
        }
        painter.setBrush(Qt::NoBrush);
        painter.setPen(QPen(kKept, m_lineWidth * 1.3));
        painter.drawPolygon(polygon);
    }
    // Edges tested so far, vertices tested so far, points made.
    const int current = m_step;
    for (std::size_t k = 0; k < 3; ++k) {
        const rl::NearClipEdge& e = r.edges[k];
        const int vertexStep = 1 + 2 * int(k), edgeStep = 2 + 2 * int(k);
        if (current >= edgeStep && !showPolygon) {
            painter.setPen(QPen(current == edgeStep ? Qt::white : kOutline,
                                m_lineWidth * (current == edgeStep ? 2.0 : 1.0)));
            painter.drawLine(atP(v[e.a]), atP(v[e.b]));
        }
        if (current >= vertexStep) {
            const QPointF c = atP(v[k]);
            const double radius = m_lineWidth * (current == vertexStep ? 3.4 : 2.4);
            painter.setPen(current == vertexStep ? QPen(Qt::white, m_lineWidth) : Qt::NoPen);
            painter.setBrush(e.keptA ? kKept : kDropped);
            painter.drawEllipse(c, radius, radius);
        }
    }
    for (std::size_t k = 0; k < 3; ++k) {
        const rl::NearClipEdge& e = r.edges[k];
        if (!e.crosses || current < 2 + 2 * int(k)) continue;
        const QPointF c = at(r.nearW, up(e.pView));
        const double d = m_lineWidth * (current == 2 + 2 * int(k) ? 3.6 : 2.6);
        QPolygonF diamond;
        diamond << c + QPointF(0, -d) << c + QPointF(d, 0) << c + QPointF(0, d)
                << c + QPointF(-d, 0);
        painter.setPen(QPen(Qt::black, 1.0));
        painter.setBrush(kMade);
        painter.drawPolygon(diamond);
    }
    // Labels: A0..A2 (with their distance once tested), C and t, q0..q3 on the polygon.
    for (std::size_t k = 0; k < 3; ++k) {
        const rl::NearClipEdge& e = r.edges[k];
        QString text = QStringLiteral("A%1").arg(k);
        if (current >= 1 + 2 * int(k)) text += QStringLiteral("  d=%1").arg(number(e.distanceA, 4));
        label(painter, atP(v[k]) + QPointF(6, -6), text,
              current >= 1 + 2 * int(k) ? (e.keptA ? kKept : kDropped) : kText);
    }
    for (std::size_t k = 0; k < 3; ++k) {
        const rl::NearClipEdge& e = r.edges[k];
        if (!e.crosses || current < 2 + 2 * int(k)) continue;
        // Left of the plane: the vertices in front have their labels on its right.
        const QString text = QStringLiteral("C  t=%1").arg(number(e.t, 4));
        label(painter,
              at(r.nearW, up(e.pView)) +
                  QPointF(-metrics.horizontalAdvance(text) - 10, metrics.ascent() / 2.0),
              text, kMade);
    }
    if (showPolygon) {
        for (qsizetype k = 0; k < polygon.size(); ++k)
            label(painter,
                  polygon[k] + QPointF(-metrics.horizontalAdvance(QStringLiteral("q0")) - 8, -6),
                  QStringLiteral("q%1").arg(k), Qt::white);
    }
    painter.restore();

    // The axes' names and the plane's.
    painter.setPen(kText);
    painter.drawText(area, kHeaderFlags, title);
    if (planeShown)
        label(painter,
              QPointF(std::clamp(planeX + 4, area.left(), area.right() - 80),
                      area.bottom() - metrics.descent() - 2),
              NearClipView::tr("w = near = %1").arg(number(r.nearW, 4)), kPlane);
    else
        note(painter, area, area.bottom(),
             NearClipView::tr("the plane w = near = %1 is far to the left, out of the picture")
                 .arg(number(r.nearW, 4)),
             kPlane);
    if (eyeShown)
        label(painter,
              QPointF(std::clamp(eye.x() - 12, area.left(), area.right() - 20),
                      eye.y() + metrics.ascent() + 8),
              NearClipView::tr("eye"), kText);
    else if (planeShown)
        note(painter, area, area.bottom() - metrics.height() - 4,
             NearClipView::tr("the eye (w = 0) is far to the left, out of the picture"), kText);
}

void NearClipCanvas::paintScreen(QPainter& painter, const QRectF& area) {
    const NearClipModel& m = *m_model;
    const QFontMetrics metrics(painter.font());
    painter.setPen(kText);
    const QRectF header =
        drawLabel(painter, area, kHeaderFlags, NearClipView::tr("on the screen (pixels)"));
    if (m_step < stepIndex(NearClipStep::Projected)) {
        painter.setPen(QColor(150, 150, 160));
        painter.drawText(area, Qt::AlignCenter | Qt::TextWordWrap,
                         NearClipView::tr("The last step projects the triangles drawn."));
        return;
    }
    const rl::Scene& scene = *m_frame->scene;
    const rl::Projection& projection = *m_frame->projection;
    const rl::DrawProjection& proj = projection.draws[m.draw];
    // The image and a margin of a quarter of it around (what reaches beyond is cut there),
    // zoomed to the triangles when they are small in it.
    const QRectF image(0, 0, scene.width, scene.height);
    const QRectF around = image.adjusted(-scene.width * 0.25, -scene.height * 0.25,
                                         scene.width * 0.25, scene.height * 0.25);
    std::vector<QPolygonF> triangles;
    QRectF box;
    for (std::uint32_t index : m.projected) {
        const rl::ScreenTriangle& t = projection.triangles[index];
        QPolygonF polygon;
        for (std::uint32_t v : t.v) polygon << QPointF(proj.pScreen[v].x, proj.pScreen[v].y);
        triangles.push_back(clipPolygonToRect(polygon, around));
        if (triangles.back().size() >= 3) box = box.united(triangles.back().boundingRect());
    }
    QRectF shown = around;
    const bool zoomed =
        !box.isEmpty() && box.width() < image.width() / 3 && box.height() < image.height() / 3;
    if (zoomed) {
        const double grow = std::max({box.width(), box.height(), 8.0}) * 0.3;
        shown = box.adjusted(-grow, -grow, grow, grow);
    }
    const QRectF plot = area.adjusted(0, header.height() + 6, 0, 0);
    const double scale = std::min(plot.width() / shown.width(), plot.height() / shown.height());
    const QPointF origin(plot.center().x() - shown.center().x() * scale,
                         plot.center().y() - shown.center().y() * scale);
    const auto at = [&](const rl::dvec2& p) {
        return QPointF(origin.x() + p.x * scale, origin.y() + p.y * scale);
    };
    painter.save();
    painter.setClipRect(
        QRectF(at({shown.left(), shown.top()}), at({shown.right(), shown.bottom()})));
    painter.setPen(QPen(QColor(205, 205, 210), 1.0));
    painter.setBrush(QColor(62, 62, 70));
    const QRectF imageShown = image.intersected(shown.adjusted(-1, -1, 1, 1));
    painter.drawRect(QRectF(at({imageShown.left(), imageShown.top()}),
                            at({imageShown.right(), imageShown.bottom()})));
    painter.restore();
    if (zoomed) {
        painter.setPen(QColor(205, 205, 210));
        painter.drawText(QPointF(area.left(), plot.bottom() - metrics.descent()),
                         NearClipView::tr("zoomed: x %1 to %2, y %3 to %4")
                             .arg(std::floor(shown.left()))
                             .arg(std::ceil(shown.right()))
                             .arg(std::floor(shown.top()))
                             .arg(std::ceil(shown.bottom())));
    }
    for (std::size_t k = 0; k < triangles.size(); ++k) {
        const QPolygonF& polygon = triangles[k];
        if (polygon.size() < 3) continue;
        QPolygonF onCanvas;
        for (const QPointF& p : polygon) onCanvas << at({p.x(), p.y()});
        painter.setBrush(kFan[k % 2]);
        painter.setPen(QPen(QColor(kFan[k % 2].rgb()), m_lineWidth));
        painter.drawPolygon(onCanvas);
    }
    // The polygon's vertices where the stage drew the record's fan (q0 q1 q2, q0 q2 q3).
    const rl::NearClipRecord& r = m.record;
    if (m.projected.size() == r.triangles.size()) {
        std::vector<bool> named(r.polygon.size(), false);
        for (std::size_t k = 0; k < m.projected.size(); ++k) {
            const rl::ScreenTriangle& t = projection.triangles[m.projected[k]];
            for (std::size_t c = 0; c < 3; ++c) {
                const std::size_t q = r.triangles[k][c];
                const rl::dvec2 p = proj.pScreen[t.v[c]];
                if (named[q] || !shown.contains(QPointF(p.x, p.y))) continue;
                named[q] = true;
                label(painter, at(p) + QPointF(4, -4), QStringLiteral("q%1").arg(q), Qt::white);
            }
        }
    }
    if (!zoomed) {
        painter.setPen(QColor(205, 205, 210));
        painter.drawText(at({0, double(scene.height)}) + QPointF(2, metrics.ascent() + 2),
                         NearClipView::tr("image %1 × %2").arg(scene.width).arg(scene.height));
    }
    if (m.projected.empty()) {
        painter.setPen(QColor(150, 150, 160));
        painter.drawText(plot, Qt::AlignCenter | Qt::TextWordWrap,
                         NearClipView::tr("Nothing drawn."));
    }
}

NearClipView::NearClipView(Inspection* inspection, QWidget* parent)
    : ExplainedView(inspection, QStringLiteral("nearClip"), parent) {
    m_triangles = new QComboBox(this);
    m_triangles->setObjectName(QStringLiteral("nearClipTriangles"));
    m_triangles->setToolTip(tr("The triangle shown: the one selected, or one the near plane cut"));
    m_axis = new QComboBox(this);
    m_axis->setObjectName(QStringLiteral("nearClipAxis"));
    m_axis->addItem(tr("y up"));
    m_axis->addItem(tr("x up"));
    m_axis->setToolTip(tr("Which view axis the side view draws upward"));
    m_back = new QPushButton(tr("Back"), this);
    m_back->setObjectName(QStringLiteral("nearClipBack"));
    m_next = new QPushButton(tr("Next"), this);
    m_next->setObjectName(QStringLiteral("nearClipNext"));
    m_all = new QPushButton(tr("All"), this);
    m_all->setObjectName(QStringLiteral("nearClipAll"));
    m_stepLabel = new QLabel(this);
    m_stepLabel->setObjectName(QStringLiteral("nearClipStep"));
    m_canvas = new NearClipCanvas(this);
    m_canvas->setObjectName(QStringLiteral("nearClipCanvas"));
    setTabOrder(m_all, explanation());  // the explanation after the controls, made before them

    auto* controls = new QHBoxLayout;
    controls->addWidget(m_triangles, 1);
    controls->addWidget(m_axis);
    auto* steps = new QHBoxLayout;
    steps->addWidget(m_back);
    steps->addWidget(m_next);
    steps->addWidget(m_all);
    steps->addWidget(m_stepLabel, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(title());
    layout->addLayout(controls);
    layout->addLayout(steps);
    layout->addWidget(m_canvas, 3);
    layout->addWidget(explanation(), 3);

    connect(m_back, &QPushButton::clicked, this, [this] { setStep(m_step - 1); });
    connect(m_next, &QPushButton::clicked, this, [this] { setStep(m_step + 1); });
    connect(m_all, &QPushButton::clicked, this, [this] { setStep(kNearClipSteps - 1); });
    connect(m_axis, &QComboBox::currentIndexChanged, this, [this] { updateStep(); });
    connect(m_triangles, &QComboBox::activated, this, [this](int index) {
        const std::optional<std::pair<std::uint32_t, std::uint32_t>> listed = listedTriangle(index);
        if (!listed) {
            m_chosen.reset();
            refresh();
            return;
        }
        showTriangle(listed->first, listed->second);
    });
}

void NearClipView::frameChanged() {
    m_chosen.reset();
    m_triangles->clear();  // made again for the new frame
    m_modelFrame = nullptr;
}

void NearClipView::presentationChanged() {
    // Hidden too: a refresh when shown again draws nothing new for the same triangle.
    updateStep();
}

int NearClipView::listedTriangles() const {
    return m_triangles->count() - 1;
}

std::optional<std::pair<std::uint32_t, std::uint32_t>> NearClipView::listedTriangle(
    int index) const {
    const QVariant item = m_triangles->itemData(index);
    if (!item.isValid()) return std::nullopt;
    const quint64 key = item.toULongLong();
    return std::pair{static_cast<std::uint32_t>(key >> 32), static_cast<std::uint32_t>(key)};
}

void NearClipView::rebuildList() {
    const rl::FrameTrace* frame = m_inspection->frame().get();
    if (frame == m_listFrame && m_triangles->count() > 0) return;
    m_listFrame = frame;
    m_triangles->clear();
    m_triangles->addItem(tr("The triangle selected (or being drawn)"));
    if (!frame || !frame->projection || !frame->scene) return;
    const rl::Projection& projection = *frame->projection;
    for (std::size_t d = 0; d < projection.draws.size(); ++d) {
        const std::vector<rl::TriangleFate>& fates = projection.draws[d].fate;
        for (std::size_t t = 0; t < fates.size() && m_triangles->count() <= kMaxListed; ++t) {
            if (fates[t] != rl::TriangleFate::Clipped && fates[t] != rl::TriangleFate::Behind)
                continue;
            QString text = tr("triangle %1: %2").arg(t + 1).arg(fateText(fates[t]));
            if (projection.draws.size() > 1)
                text = QString::fromStdString(frame->scene->draws[d].name) + QStringLiteral(", ") +
                       text;
            m_triangles->addItem(text, listKey(d, t));
        }
    }
}

void NearClipView::showTriangle(std::uint32_t draw, std::uint32_t source) {
    m_chosen = {draw, source};
    m_selectionAtChoice = m_inspection->selectedTriangle();
    // The other views follow when it was drawn.
    const std::shared_ptr<const rl::FrameTrace>& frame = m_inspection->frame();
    if (frame && frame->projection) {
        const std::vector<std::uint32_t> drawn =
            rl::screenTrianglesOf(*frame->projection, draw, source);
        if (!drawn.empty() && m_inspection->selectedTriangle() != drawn.front()) {
            m_selectionAtChoice = drawn.front();
            m_inspection->selectTriangle(drawn.front());
            return;  // selectionChanged refreshes
        }
    }
    refresh();
}

void NearClipView::refresh() {
    rebuildList();
    const std::shared_ptr<const rl::FrameTrace>& frame = m_inspection->frame();
    std::optional<std::pair<std::uint32_t, std::uint32_t>> which;
    if (frame && frame->projection && frame->scene) {
        const rl::Projection& projection = *frame->projection;
        std::optional<std::uint32_t> projected = m_inspection->selectedTriangle();
        if (!projected && m_inspection->canStep() && !m_inspection->atEnd())
            projected = m_inspection->currentTriangle();
        std::optional<std::pair<std::uint32_t, std::uint32_t>> selected;
        if (projected && *projected < projection.triangles.size()) {
            const rl::ScreenTriangle& t = projection.triangles[*projected];
            selected = std::pair{t.draw, t.source};
        }
        // The one chosen in the list stays until another triangle is selected.
        if (m_chosen && m_inspection->selectedTriangle() == m_selectionAtChoice)
            which = m_chosen;
        else
            which = selected;
        if (!which) which = listedTriangle(1);  // none when the list offers none
        if (which && (which->first >= frame->scene->draws.size() ||
                      !frame->scene->draws[which->first].mesh ||
                      which->second >= frame->scene->draws[which->first].mesh->triangles.size()))
            which.reset();
    }
    const bool same =
        which && m_model && m_model->draw == which->first && m_model->source == which->second;
    // The same triangle of the same frame (a step of the cursor, mostly): nothing to make again.
    const bool unchanged = same && frame.get() == m_modelFrame;
    if (!which) {
        m_model.reset();
    } else if (!unchanged) {
        m_model = nearClipModel(*frame, which->first, which->second);
        if (!same) {
            // Another triangle starts at the first step, unless all steps were shown, and is
            // seen along the axis that shows it largest.
            if (m_step != kNearClipSteps - 1) m_step = 0;
            const rl::NearClipRecord& r = m_model->record;
            const auto area = [&](int axis) {
                std::array<rl::dvec2, 3> p{};
                for (std::size_t k = 0; k < 3; ++k)
                    p[k] = {r.edges[k].distanceA, axis == 0 ? r.pView[k].y : r.pView[k].x};
                return std::abs((p[1].x - p[0].x) * (p[2].y - p[0].y) -
                                (p[1].y - p[0].y) * (p[2].x - p[0].x));
            };
            const QSignalBlocker block(m_axis);
            m_axis->setCurrentIndex(area(1) > area(0) ? 1 : 0);
        }
    }
    m_modelFrame = m_model ? frame.get() : nullptr;
    // The list shows the triangle when it is in it.
    int index = 0;
    if (m_model && m_chosen) {
        index = std::max(0, m_triangles->findData(listKey(m_model->draw, m_model->source)));
    }
    m_triangles->setCurrentIndex(index);
    if (!unchanged) updateStep();
}

void NearClipView::setStep(int step) {
    m_step = std::clamp(step, 0, kNearClipSteps - 1);
    updateStep();
}

void NearClipView::updateStep() {
    m_back->setEnabled(m_model && m_step > 0);
    m_next->setEnabled(m_model && m_step < kNearClipSteps - 1);
    m_all->setEnabled(m_model && m_step < kNearClipSteps - 1);
    m_stepLabel->setText(m_model ? tr("step %1 of %2").arg(m_step + 1).arg(kNearClipSteps)
                                 : QString());
    m_canvas->setContent(m_model, m_inspection->frame(), m_step, m_axis->currentIndex(),
                         m_inspection->lineWidth(), m_inspection->presentation());
    title()->setText(titleText());
    if (setExplanation(explanationHtml())) explanation()->scrollToAnchor(QStringLiteral("current"));
}

QString NearClipView::titleText() const {
    const std::shared_ptr<const rl::FrameTrace>& frame = m_inspection->frame();
    if (!frame) return tr("No frame yet.");
    if (!m_model) return tr("No triangle to show: select one or step into the frame.");
    const rl::Draw& draw = frame->scene->draws[m_model->draw];
    QString text = tr("<b>Triangle %1</b> of %2: %3")
                       .arg(m_model->source + 1)
                       .arg(draw.mesh->triangles.size())
                       .arg(fateText(m_model->fate));
    if (frame->scene->draws.size() > 1)
        text += QStringLiteral(" (%1)").arg(QString::fromStdString(draw.name).toHtmlEscaped());
    return text;
}

QString NearClipView::explanationHtml() const {
    if (!m_model) return {};
    const NearClipModel& m = *m_model;
    const rl::NearClipRecord& r = m.record;
    const rl::FrameTrace& frame = *m_inspection->frame();
    const rl::DrawProjection& proj = frame.projection->draws[m.draw];
    const auto point = [](const rl::dvec4& p) { return vector(rl::dvec3(p)); };
    // Where each vertex of the polygon is: q0 .. q3.
    const auto polygonIndex = [&](bool made, std::size_t index) {
        for (std::size_t k = 0; k < r.polygon.size(); ++k)
            if (r.polygon[k].made == made && r.polygon[k].index == index) return int(k);
        return -1;
    };
    const bool course = r.plane == rl::dvec4(0.0, 0.0, 1.0, -r.nearW);
    QStringList paragraphs;

    // The plane.
    QString plane =
        tr("The seed clips each triangle against the plane z = &minus;&epsilon;, P = [0, 0, "
           "&minus;1, &epsilon;], before the perspective divide (OpenGL's camera looks along "
           "&minus;z). The projection stage clips against w = near in clip space, here near = "
           "%1, so P = %2 and a point A is kept when dot(P, A) = w &minus; near &ge; 0.")
            .arg(number(r.nearW), vector(r.plane));
    if (course)
        plane += QLatin1Char(' ') +
                 tr("For the course camera w is the view z: the camera looks along +z, and the "
                    "plane is z = near, P = [0, 0, 1, &minus;near].");
    plane += QLatin1Char(' ') +
             tr("(Written out, the seed's P keeps z &le; &epsilon;; the plane z = &minus;&epsilon; "
                "it names is P = [0, 0, &minus;1, &minus;&epsilon;]. Either way the plane lies a "
                "little in front of the eye, so no vertex drawn is divided by w = 0.)");
    plane +=
        QStringLiteral("<br>") + tr("A0 = %1, A1 = %2, A2 = %3 (view space).")
                                     .arg(point(r.pView[0]), point(r.pView[1]), point(r.pView[2]));
    if (!m.nearClipping)
        plane += QStringLiteral("<br><b>") +
                 tr("This scene does not clip against the near plane (the naive or same-side "
                    "projection): the steps show what clipping would do.") +
                 QStringLiteral("</b>");
    if (m.otherPlanes)
        plane += QStringLiteral("<br>") +
                 tr("The draw's clip planes cut the triangle first; the polygon the stage drew "
                    "may differ from the one here.");
    paragraphs << plane;

    for (std::size_t k = 0; k < 3; ++k) {
        const rl::NearClipEdge& e = r.edges[k];
        const QString a = QStringLiteral("A%1").arg(e.a), b = QStringLiteral("A%1").arg(e.b);
        QString vertex = tr("Vertex %1: dot(P, %1) = %2").arg(a, number(e.distanceA));
        if (e.keptA)
            vertex += QStringLiteral(" &ge; 0: ") +
                      tr("kept, added to the output polygon as q%1.").arg(polygonIndex(false, k));
        else
            vertex += QStringLiteral(" &lt; 0: ") + tr("behind the plane, left out.");
        paragraphs << vertex;
        QString edge;
        if (!e.crosses) {
            edge = tr("Edge %1&ndash;%2: dot(P, %1) = %3 and dot(P, %2) = %4 have the same sign: "
                      "the edge does not cross the plane.")
                       .arg(a, b, number(e.distanceA), number(e.distanceB));
        } else {
            edge = tr("Edge %1&ndash;%2: dot(P, %1) = %3 and dot(P, %2) = %4 differ in sign: "
                      "t = (0 &minus; %5) / (%6 &minus; %5) = %7, C = lerp(t, %1, %2) = %8, "
                      "added as q%9.")
                       .arg(a, b, number(e.distanceA), number(e.distanceB), operand(e.distanceA),
                            operand(e.distanceB), number(e.t), point(e.pView))
                       .arg(polygonIndex(true, k));
            if (!e.keptA)
                edge += QLatin1Char(' ') +
                        tr("(The stage computes the same point from %1, the end in front, with "
                           "t' = 1 &minus; t = %2, so that the two triangles sharing the edge get "
                           "it bit for bit.)")
                            .arg(b, number(e.tFromInside));
        }
        paragraphs << edge;
    }

    QString polygon;
    if (r.polygon.empty()) {
        polygon =
            tr("Output polygon: empty. The triangle lies wholly behind the plane: nothing "
               "is drawn.");
    } else {
        QStringList names;
        for (std::size_t k = 0; k < r.polygon.size(); ++k)
            names << QStringLiteral("q%1 = %2").arg(k).arg(point(r.polygon[k].pView));
        polygon = tr("Output polygon, %1 vertices: %2.")
                      .arg(r.polygon.size())
                      .arg(names.join(QStringLiteral(", ")));
        if (r.untouched())
            polygon += QLatin1Char(' ') + tr("The triangle is wholly in front: untouched.");
    }
    paragraphs << polygon;

    QString split;
    if (r.triangles.size() == 2)
        split =
            tr("Four vertices: split along the diagonal q0&ndash;q2 into the triangles q0 q1 "
               "q2 and q0 q2 q3, rendered separately.");
    else if (r.triangles.size() == 1)
        split = tr("Three vertices: one triangle, nothing to split.");
    else
        split = tr("Fewer than three vertices: no triangle.");
    paragraphs << split;

    QString projected = tr("Then each vertex is projected and taken to pixels.");
    if (m.projected.empty()) {
        projected += QLatin1Char(' ') +
                     tr("Nothing was drawn from this triangle (%1).").arg(fateText(m.fate));
    } else {
        for (std::size_t k = 0; k < m.projected.size(); ++k) {
            const rl::ScreenTriangle& t = frame.projection->triangles[m.projected[k]];
            projected += QStringLiteral("<br>") + tr("Triangle %1: %2, %3, %4 (pixels)")
                                                      .arg(k + 1)
                                                      .arg(vector(proj.pScreen[t.v[0]]),
                                                           vector(proj.pScreen[t.v[1]]),
                                                           vector(proj.pScreen[t.v[2]]));
        }
        if (m.projected.size() != r.triangles.size())
            projected += QStringLiteral("<br>") + tr("(%1 of the %2 triangles were drawn: %3.)")
                                                      .arg(m.projected.size())
                                                      .arg(r.triangles.size())
                                                      .arg(fateText(m.fate));
    }
    paragraphs << projected;

    QString html;
    for (int k = 0; k <= m_step && k < paragraphs.size(); ++k) {
        const bool current = k == m_step;
        html += (current ? QStringLiteral("<p><a name='current'></a><b>%1. %2</b></p>")
                         : QStringLiteral("<p>%1. %2</p>"))
                    .arg(k + 1)
                    .arg(paragraphs[k]);
    }
    return html;
}

}  // namespace rasterlab
