#include "camera_basis_view.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QSignalBlocker>
#include <QSlider>
#include <QSplitter>
#include <QTextBrowser>
#include <QToolButton>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pipeline/render/frame_trace.h"
#include "views/inspection.h"
#include "views/key_figures.h"
#include "views/number_text.h"
#include "views/view_font.h"

namespace rasterlab {

namespace {

using rl::dvec3;

constexpr double kDefaultYaw = 35.0 * std::numbers::pi / 180.0;
constexpr double kDefaultPitch = 25.0 * std::numbers::pi / 180.0;
constexpr int kMaxCloudPoints = 3000;

// Colours on the dark background the image views share. The world axes are red, green and
// blue; the camera's vectors take other hues so that U is never mistaken for X.
const QColor kBackground(48, 48, 52);
const QColor kAxisX(235, 85, 85), kAxisY(95, 200, 95), kAxisZ(95, 145, 255);
const QColor kColourU(255, 165, 40), kColourV(235, 115, 235), kColourN(80, 225, 225);
const QColor kCloud(170, 170, 180, 130);
const QColor kFrustum(215, 215, 215);
const QColor kText(230, 230, 230);

// The mesh vertices in world space, at most kMaxCloudPoints of them (every k-th), where they
// are in this frame: placed by the view transform's worldFromModel (M(t) included).
std::vector<dvec3> cloudOf(const rl::Scene& scene, const rl::ViewTransform& view) {
    std::size_t total = 0;
    for (const rl::Draw& draw : scene.draws)
        if (draw.mesh) total += draw.mesh->positions.size();
    const std::size_t stride =
        std::max<std::size_t>(1, (total + kMaxCloudPoints - 1) / kMaxCloudPoints);
    std::vector<dvec3> cloud;
    cloud.reserve(total / stride + 1);
    std::size_t i = 0;
    for (std::size_t d = 0; d < scene.draws.size(); ++d) {
        const rl::Draw& draw = scene.draws[d];
        if (!draw.mesh) continue;
        const rl::dmat4& worldFromModel = view.worldFromModel[d];
        for (const rl::dvec4& p : draw.mesh->positions) {
            if (i++ % stride != 0) continue;
            const dvec3 w = rl::cartesian(worldFromModel * p);
            if (rl::isFinite(w)) cloud.push_back(w);
        }
    }
    return cloud;
}

// Where the picture's centre is, how big it is, how long a unit vector is drawn and how
// far the frustum is drawn.
void placePicture(CameraBasisPicture& picture) {
    const rl::CameraBasis& b = picture.basis;
    dvec3 lo = b.c, hi = b.c;
    for (const dvec3& p : picture.cloud) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    // The world origin joins the picture when it is near the scene, so the axes stand
    // where they belong; far away, they are drawn as a small tripod in a corner.
    const dvec3 centre = 0.5 * (lo + hi);
    const double radius = 0.5 * glm::length(hi - lo);
    if (glm::length(centre) <= 2.0 * std::max(radius, 1e-12)) {
        lo = glm::min(lo, dvec3(0.0));
        hi = glm::max(hi, dvec3(0.0));
    }
    picture.centre = 0.5 * (lo + hi);
    picture.radius = 0.5 * glm::length(hi - lo);
    if (!(picture.radius > 0.0)) picture.radius = std::max({1.0, std::abs(picture.d)});
    const double r = picture.radius;

    // A unit vector is 0.3 r long; a given vector keeps its length when it is between 0.4
    // and 2.5 units, and is brought to the nearer end otherwise (its label says how long).
    picture.vectorScale = 0.3 * r;
    const auto givenScale = [&](const dvec3& v) {
        const double length = glm::length(v);
        return length > 0.0 ? picture.vectorScale * std::clamp(length, 0.4, 2.5) / length
                            : picture.vectorScale;
    };
    picture.nGivenScale = givenScale(b.nGiven);
    picture.vGivenScale = givenScale(b.vGiven);
    // The arrows' tips join the picture, so that none reaches past its edge.
    for (const dvec3& tip : {b.c + picture.nGivenScale * b.nGiven,
                             b.c + picture.vGivenScale * b.vGiven, b.c + picture.vectorScale * b.u,
                             b.c + picture.vectorScale * b.v, b.c + picture.vectorScale * b.n}) {
        lo = glm::min(lo, tip);
        hi = glm::max(hi, tip);
    }
    picture.centre = 0.5 * (lo + hi);
    picture.radius = std::max(r, 0.5 * glm::length(hi - lo));

    // The frustum reaches the farthest vertex in front of the camera (or r), but stays
    // within 1.15 r of the centre, on the widget at the first zoom.
    double farthest = 0.0;
    for (const dvec3& p : picture.cloud) farthest = std::max(farthest, glm::dot(p - b.c, b.n));
    if (!(farthest > 0.0)) farthest = r;
    // Along each corner's direction e (C + t e), the t where it leaves the sphere of radius
    // 1.15 r: |q + t e| = 1.15 r with q = C - centre, C inside it.
    const double ex = std::abs(picture.hx / picture.d), ey = std::abs(picture.hy / picture.d);
    const dvec3 q = b.c - picture.centre;
    const double rho = 1.15 * picture.radius;
    double room = farthest;
    for (double sx : {-1.0, 1.0}) {
        for (double sy : {-1.0, 1.0}) {
            const dvec3 e = b.n + sx * ex * b.u + sy * ey * b.v;
            const double ee = glm::dot(e, e), qe = glm::dot(q, e);
            const double disc = qe * qe - ee * (glm::dot(q, q) - rho * rho);
            if (ee > 0.0 && disc >= 0.0) room = std::min(room, (-qe + std::sqrt(disc)) / ee);
        }
    }
    picture.frustumDepth = std::max(0.0, room);
}

void drawArrow(QPainter& painter, const QPointF& from, const QPointF& to, const QColor& colour,
               double width, Qt::PenStyle style = Qt::SolidLine) {
    QPen pen(colour, width, style, Qt::RoundCap);
    painter.setPen(pen);
    painter.drawLine(from, to);
    const QPointF d = to - from;
    const double length = std::hypot(d.x(), d.y());
    if (length < 1.0) return;
    const QPointF u = d / length;
    const QPointF side(-u.y(), u.x());
    const double head = std::min(10.0 + 2.0 * width, 0.4 * length);
    pen.setStyle(Qt::SolidLine);
    painter.setPen(pen);
    painter.drawLine(to, to - head * u + 0.45 * head * side);
    painter.drawLine(to, to - head * u - 0.45 * head * side);
}

}  // namespace

CameraBasisCanvas::CameraBasisCanvas(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("cameraBasisCanvas"));
    setMinimumSize(200, 160);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setToolTip(tr("Drag to turn the scene, wheel to zoom, double-click to reset."));
    m_reset = new QToolButton(this);
    m_reset->setObjectName(QStringLiteral("cameraBasisResetView"));
    m_reset->setText(tr("Reset view"));
    m_reset->setToolTip(tr("Turn the 3D drawing back to where it started"));
    connect(m_reset, &QToolButton::clicked, this, &CameraBasisCanvas::resetOrbit);
    resetOrbit();
}

void CameraBasisCanvas::resizeEvent(QResizeEvent*) {
    m_reset->adjustSize();
    m_reset->move(width() - m_reset->width() - 6, 6);
}

void CameraBasisCanvas::setPicture(CameraBasisPicture picture) {
    m_picture = std::move(picture);
    m_reset->setVisible(m_message.isEmpty() && m_picture.valid);  // nothing to turn otherwise
    update();
}

void CameraBasisCanvas::setMessage(const QString& message) {
    m_message = message;
    m_reset->setVisible(m_message.isEmpty() && m_picture.valid);
    update();
}

void CameraBasisCanvas::setStep(int step) {
    m_picture.step = step;
    update();
}

void CameraBasisCanvas::setLineWidth(double width) {
    m_lineWidth = width;
    update();
}

void CameraBasisCanvas::setOrbit(double yaw, double pitch, double zoom) {
    m_yaw = yaw;
    m_pitch = std::clamp(pitch, -1.5, 1.5);
    m_zoom = std::clamp(zoom, 0.1, 50.0);
    update();
}

void CameraBasisCanvas::resetOrbit() {
    setOrbit(kDefaultYaw, kDefaultPitch, 1.0);
}

void CameraBasisCanvas::orbitFrame(dvec3& right, dvec3& up, dvec3& back) const {
    up = dvec3(0.0, 1.0, 0.0);
    dvec3 n(0.0, 0.0, 1.0);
    if (m_picture.valid) {
        const dvec3 v = m_picture.basis.v;
        int axis = 0;
        for (int k = 1; k < 3; ++k)
            if (std::abs(v[k]) > std::abs(v[axis])) axis = k;
        up = dvec3(0.0);
        up[axis] = v[axis] < 0.0 ? -1.0 : 1.0;
        n = m_picture.basis.n;
    }
    back = -n - glm::dot(-n, up) * up;
    if (glm::length(back) < 1e-6) {
        // Looking straight up or down: any horizontal direction will do.
        back = std::abs(up.x) < 0.5 ? glm::cross(up, dvec3(1.0, 0.0, 0.0))
                                    : glm::cross(up, dvec3(0.0, 0.0, 1.0));
    }
    back = glm::normalize(back);
    right = glm::cross(up, back);
}

CameraBasisCanvas::Projector CameraBasisCanvas::projector() const {
    dvec3 right, up, back;
    orbitFrame(right, up, back);
    Projector p;
    p.eye = std::cos(m_pitch) * (std::sin(m_yaw) * right + std::cos(m_yaw) * back) +
            std::sin(m_pitch) * up;
    p.screenRight = glm::normalize(glm::cross(up, p.eye));
    p.screenUp = glm::cross(p.eye, p.screenRight);
    p.centre = m_picture.centre;
    const double r = m_picture.radius > 0.0 ? m_picture.radius : 1.0;
    // A mild perspective: the eye is 6 r from the centre; what is drawn lies within about
    // 1.2 r of it, so nothing comes near the eye.
    p.distance = 6.0 * r;
    p.scale = m_zoom * 0.42 * std::min(width(), height()) / r;
    p.middle = QPointF(width() / 2.0, height() / 2.0);
    return p;
}

QPointF CameraBasisCanvas::Projector::operator()(const dvec3& pWorld) const {
    const dvec3 q = pWorld - centre;
    const double toward = std::min(glm::dot(q, eye), 0.9 * distance);
    const double f = distance / (distance - toward);
    return {middle.x() + scale * f * glm::dot(q, screenRight),
            middle.y() - scale * f * glm::dot(q, screenUp)};
}

QPointF CameraBasisCanvas::toWidget(const dvec3& pWorld) const {
    return projector()(pWorld);
}

namespace {

// The point of `box` nearest `p`: where a leader line from p meets the label.
QPointF nearestOn(const QRectF& box, const QPointF& p) {
    return {std::clamp(p.x(), box.left(), box.right()), std::clamp(p.y(), box.top(), box.bottom())};
}

}  // namespace

void CameraBasisCanvas::placeLabel(const QFontMetricsF& metrics, const PendingLabel& label) {
    const QPointF& at = label.at;
    const QString& text = label.text;
    QPointF d = at - label.awayFrom;
    const double length = std::hypot(d.x(), d.y());
    d = length > 0.0 ? d / length : QPointF(1.0, 0.0);
    const QSizeF size = metrics.size(0, text);
    // The label's centre, beyond the tip in the arrow's direction.
    const QPointF centre = at + d * (6.0 + 0.5 * std::hypot(size.width(), size.height()) * 0.8);
    const double w = size.width() + 6.0, h = size.height() + 2.0;  // with its backing
    QRectF box(centre - QPointF(w / 2, h / 2), QSizeF(w, h));
    box = freePlace(box, rect(),
                    {QPointF(0, 0), QPointF(0, -h), QPointF(0, h), QPointF(w / 2 + 4, 0),
                     QPointF(-w / 2 - 4, 0), QPointF(w, -h), QPointF(-w, -h), QPointF(w, h),
                     QPointF(-w, h), QPointF(0, -2 * h), QPointF(0, 2 * h)});
    // Inside the picture; still on another label (or the button), the nearest free place
    // along the rows below and above.
    box.moveLeft(std::clamp(box.left(), 0.0, std::max(0.0, width() - box.width())));
    box.moveTop(std::clamp(box.top(), 0.0, std::max(0.0, height() - box.height())));
    for (int k = 1; k < 40 && !isFree(box, rect()); ++k) {
        const double dy = (k / 2) * h / 2 * (k % 2 ? 1.0 : -1.0);
        bool found = false;
        for (const double dx : {0.0, -w / 2, w / 2, -w, w, -1.5 * w, 1.5 * w}) {
            QRectF moved = box.translated(dx, dy);
            moved.moveLeft(std::clamp(moved.left(), 0.0, std::max(0.0, width() - w)));
            if (isFree(moved, rect())) {
                box = moved;
                found = true;
                break;
            }
        }
        if (found) break;
    }
    recordLabel(box, text);
    m_placed.append({text, at, box, label.colour});
}

void CameraBasisCanvas::drawLabels(QPainter& painter) const {
    // Pushed more than 12 px from its point: a leader line to the label's nearest edge.
    for (const PlacedLabel& label : m_placed) {
        const QPointF end = nearestOn(label.box, label.anchor);
        if (QLineF(label.anchor, end).length() <= 12.0) continue;
        QColor line = label.colour;
        line.setAlpha(170);
        painter.setPen(QPen(line, 1.0, Qt::DotLine));
        painter.drawLine(label.anchor, end);
    }
    // A dark backing keeps each label readable over the point cloud and the lines.
    for (const PlacedLabel& label : m_placed) {
        painter.setPen(Qt::NoPen);
        painter.setBrush(QColor(kBackground.red(), kBackground.green(), kBackground.blue(), 215));
        painter.drawRoundedRect(label.box, 3, 3);
        painter.setBrush(Qt::NoBrush);
        painter.setPen(label.colour);
        painter.drawText(label.box, Qt::AlignCenter, label.text);
    }
}

void CameraBasisCanvas::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.fillRect(rect(), kBackground);
    painter.setRenderHint(QPainter::Antialiasing, true);
    m_drawn.clear();
    m_placed.clear();
    clearLabels();
    // The button's place is taken: no label under it.
    if (m_reset->isVisible()) recordLabel(QRectF(m_reset->geometry()).adjusted(-2, -2, 2, 2));
    if (!m_message.isEmpty() || !m_picture.valid) {
        painter.setPen(kText);
        painter.drawText(rect().adjusted(16, 16, -16, -16), Qt::AlignCenter | Qt::TextWordWrap,
                         m_message);
        return;
    }
    const CameraBasisPicture& pic = m_picture;
    const Projector project = projector();  // once for every point drawn
    std::vector<PendingLabel> pending;      // placed once everything is drawn
    const auto queueLabel = [&pending](const QPointF& at, const QPointF& awayFrom,
                                       const QString& text, const QColor& colour, LabelRank rank) {
        pending.push_back({at, awayFrom, text, colour, rank});
    };
    const rl::CameraBasis& b = pic.basis;
    const double w = m_lineWidth;
    const double s = pic.vectorScale;
    const QPointF c = project(b.c);

    // The mesh, faint, so it shows where the camera looks without hiding the vectors.
    if (!pic.cloud.empty()) {
        QPolygonF points;
        points.reserve(static_cast<int>(pic.cloud.size()));
        for (const dvec3& p : pic.cloud) points.append(project(p));
        painter.setPen(QPen(kCloud, std::max(2.0, w + 0.5), Qt::SolidLine, Qt::RoundCap));
        painter.drawPoints(points);
        m_drawn << QStringLiteral("cloud");
    }

    // The world axes at the origin when it is in the picture, else a tripod in a corner.
    const bool originShown = glm::length(pic.centre) <= pic.radius * (1.0 + 1e-9);
    const QPointF o = project(dvec3(0.0));
    const QColor axisColours[3] = {kAxisX, kAxisY, kAxisZ};
    const QString axisNames[3] = {QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")};
    QPointF tripod[3];
    double longest = 0.0;
    for (int k = 0; k < 3; ++k) {
        dvec3 axis(0.0);
        axis[k] = 1.0;
        tripod[k] = project(pic.centre + 0.2 * pic.radius * axis) - project(pic.centre);
        longest = std::max(longest, std::hypot(tripod[k].x(), tripod[k].y()));
    }
    for (int k = 0; k < 3; ++k) {
        dvec3 axis(0.0);
        axis[k] = 1.0;
        QPointF from, to;
        if (originShown) {
            from = o;
            to = project(0.5 * pic.radius * axis);
        } else {
            from = QPointF(52.0, height() - 44.0);
            to = from + (longest > 0.0 ? tripod[k] * (28.0 / longest) : QPointF());
        }
        drawArrow(painter, from, to, axisColours[k], std::max(1.0, w - 0.5));
        queueLabel(to, from, axisNames[k], axisColours[k], LabelRank::Axes);
    }
    m_drawn << QStringLiteral("axes");

    // The frustum (U is needed for its corners): the window at distance d, lines from C to
    // its corners, and its edges carried on, faint, to the farthest vertex.
    if (pic.step >= 4) {
        const double ex = std::abs(pic.hx / pic.d), ey = std::abs(pic.hy / pic.d);
        const double t = pic.frustumDepth;
        const double signs[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
        QPolygonF window, far;
        for (const auto& sg : signs) {
            window << project(b.c + pic.d * b.n + sg[0] * pic.hx * b.u + sg[1] * pic.hy * b.v);
            far << project(b.c + t * (b.n + sg[0] * ex * b.u + sg[1] * ey * b.v));
        }
        QColor faint = kFrustum;
        faint.setAlpha(90);
        painter.setPen(QPen(faint, 1.0, Qt::DashLine));
        painter.setBrush(Qt::NoBrush);
        for (const QPointF& p : far) painter.drawLine(c, p);
        painter.drawPolygon(far);
        m_drawn << QStringLiteral("frustum");
        painter.setPen(QPen(kFrustum, w));
        for (const QPointF& p : window) painter.drawLine(c, p);
        painter.setBrush(QColor(255, 255, 255, 45));
        painter.drawPolygon(window);
        painter.setBrush(Qt::NoBrush);
        m_drawn << QStringLiteral("window");
        // Labels above the topmost corners; the window's only when it is big enough to see
        // (with d = 1 in a scene hundreds of units wide it is a dot at C).
        const auto topmost = [](const QPolygonF& polygon) {
            QPointF top = polygon[0];
            for (const QPointF& p : polygon)
                if (p.y() < top.y()) top = p;
            return top;
        };
        const QRectF windowBox = window.boundingRect();
        if (std::max(windowBox.width(), windowBox.height()) > 24.0) {
            const QPointF top = topmost(window);
            queueLabel(top, top + QPointF(0, 1), tr("window (d = %1)").arg(number(pic.d)), kFrustum,
                       LabelRank::Frustum);
        }
        const QPointF farTop = topmost(far);
        queueLabel(farTop, farTop + QPointF(0, 1), tr("frustum"), faint.lighter(150),
                   LabelRank::Frustum);
    }

    // The vectors, from C; the given ones dashed (their scale: CameraBasisPicture).
    auto arrow = [&](const dvec3& v, double scale, const QColor& colour, const QString& label,
                     Qt::PenStyle style, const QString& item) {
        const QPointF tip = project(b.c + scale * v);
        drawArrow(painter, c, tip, colour, style == Qt::SolidLine ? w + 1.0 : w, style);
        queueLabel(tip, c, label, colour,
                   style == Qt::DashLine ? LabelRank::Given : LabelRank::Basis);
        m_drawn << item;
    };
    const double sn = pic.nGivenScale, sv = pic.vGivenScale;
    arrow(b.nGiven, sn, kColourN.darker(140),
          tr("N given, |N| = %1").arg(number(glm::length(b.nGiven), 4)), Qt::DashLine,
          QStringLiteral("N given"));
    arrow(b.vGiven, sv, kColourV.darker(140),
          tr("V given, |V| = %1").arg(number(glm::length(b.vGiven), 4)), Qt::DashLine,
          QStringLiteral("V given"));
    if (pic.step >= 1)
        arrow(b.n, s, kColourN, QStringLiteral("N"), Qt::SolidLine, QStringLiteral("N"));
    if (pic.step == 2 || pic.step == 3) {
        // V = (V.N) N + V': the projection on N, the drop from V's tip onto N, and V'.
        const QPointF projectionTip = project(b.c + sv * b.vProjection);
        painter.setPen(QPen(kColourV, w, Qt::DotLine));
        painter.drawLine(project(b.c + sv * b.vGiven), projectionTip);
        arrow(b.vProjection, sv, kColourV.lighter(115), QStringLiteral("(V·N) N"), Qt::DotLine,
              QStringLiteral("(V.N) N"));
        arrow(b.vOrthogonal, sv, kColourV, QStringLiteral("V'"), Qt::SolidLine,
              QStringLiteral("V'"));
    }
    if (pic.step >= 3)
        arrow(b.v, s, kColourV, QStringLiteral("V"), Qt::SolidLine, QStringLiteral("V"));
    if (pic.step >= 4)
        arrow(b.u, s, kColourU, QStringLiteral("U"), Qt::SolidLine, QStringLiteral("U"));

    // The camera.
    painter.setPen(QPen(Qt::black, 1.0));
    painter.setBrush(kText);
    painter.drawEllipse(c, 3.0 + w, 3.0 + w);
    queueLabel(c, c + QPointF(1, -1), QStringLiteral("C"), kText, LabelRank::Camera);
    m_drawn << QStringLiteral("C");

    std::stable_sort(pending.begin(), pending.end(),
                     [](const PendingLabel& x, const PendingLabel& y) { return x.rank < y.rank; });
    const QFontMetricsF metrics(painter.font());
    for (const PendingLabel& label : pending) placeLabel(metrics, label);
    drawLabels(painter);
}

void CameraBasisCanvas::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) return;
    m_dragging = true;
    m_dragStart = event->position().toPoint();
    m_yawAtDragStart = m_yaw;
    m_pitchAtDragStart = m_pitch;
}

void CameraBasisCanvas::mouseMoveEvent(QMouseEvent* event) {
    if (!m_dragging) return;
    const QPoint d = event->position().toPoint() - m_dragStart;
    setOrbit(m_yawAtDragStart - 0.01 * d.x(), m_pitchAtDragStart + 0.01 * d.y(), m_zoom);
}

void CameraBasisCanvas::mouseReleaseEvent(QMouseEvent*) {
    m_dragging = false;
}

void CameraBasisCanvas::mouseDoubleClickEvent(QMouseEvent*) {
    resetOrbit();
}

void CameraBasisCanvas::wheelEvent(QWheelEvent* event) {
    const double steps = event->angleDelta().y() / 120.0;
    if (steps != 0.0) setOrbit(m_yaw, m_pitch, m_zoom * std::pow(1.2, steps));
}

CameraBasisView::CameraBasisView(Inspection* inspection, QWidget* parent)
    : QWidget(parent), m_inspection(inspection) {
    setObjectName(QStringLiteral("cameraBasisView"));
    m_canvas = new CameraBasisCanvas(this);

    m_back = new QToolButton(this);
    m_back->setObjectName(QStringLiteral("cameraBasisStepBack"));
    m_back->setArrowType(Qt::LeftArrow);
    m_back->setToolTip(tr("Previous step"));
    m_forward = new QToolButton(this);
    m_forward->setObjectName(QStringLiteral("cameraBasisStepForward"));
    m_forward->setArrowType(Qt::RightArrow);
    m_forward->setToolTip(tr("Next step"));
    m_stepSlider = new QSlider(Qt::Horizontal, this);
    m_stepSlider->setObjectName(QStringLiteral("cameraBasisStep"));
    m_stepSlider->setRange(0, 4);
    m_stepSlider->setPageStep(1);
    m_stepSlider->setTickPosition(QSlider::TicksBelow);
    m_stepSlider->setValue(m_step);
    m_stepLabel = new QLabel(this);
    m_text = new QTextBrowser(this);
    m_text->setObjectName(QStringLiteral("cameraBasisText"));
    m_text->setOpenLinks(false);

    auto* controls = new QHBoxLayout;
    controls->addWidget(m_back);
    controls->addWidget(m_stepSlider, 1);
    controls->addWidget(m_forward);
    controls->addWidget(m_stepLabel);
    auto* panel = new QWidget;
    auto* panelLayout = new QVBoxLayout(panel);
    panelLayout->setContentsMargins(4, 4, 4, 0);
    panelLayout->addLayout(controls);
    m_figures = new KeyFigures(this);
    m_figures->setParent(panel);
    panelLayout->addWidget(m_figures);
    panelLayout->addWidget(m_text, 1);

    m_splitter = new QSplitter(Qt::Vertical, this);
    m_splitter->addWidget(m_canvas);
    m_splitter->addWidget(panel);
    m_splitter->setStretchFactor(0, 3);
    m_splitter->setStretchFactor(1, 2);
    m_splitter->setChildrenCollapsible(false);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_splitter);

    connect(m_stepSlider, &QSlider::valueChanged, this, &CameraBasisView::setStep);
    connect(m_back, &QToolButton::clicked, this, [this] { setStep(m_step - 1); });
    connect(m_forward, &QToolButton::clicked, this, [this] { setStep(m_step + 1); });
    if (m_inspection) {
        connect(m_inspection, &Inspection::frameChanged, this, [this] {
            m_error.clear();  // an error shows until the next frame
            m_dirty = true;
            refresh();
        });
        connect(m_inspection, &Inspection::presentationChanged, this,
                &CameraBasisView::applyPresentation);
    }
    applyPresentation();
    refresh();
}

void CameraBasisView::setError(const QString& message) {
    m_error = message;
    m_dirty = true;
    refresh();
}

void CameraBasisView::setStep(int step) {
    step = std::clamp(step, 0, 4);
    if (step == m_step && m_stepSlider->value() == step) return;
    m_step = step;
    showStep();
}

QStringList CameraBasisView::stepTexts() const {
    return m_allSteps.mid(0, m_step);
}

void CameraBasisView::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    if (m_dirty) refresh();
}

void CameraBasisView::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    // Side by side when wide, one above the other when tall (a narrow dock); the drawing
    // gets 60% when the orientation changes, then whatever the user drags it to. Side by
    // side, the steps keep 34 characters a line, up to half the width (a docked view), so
    // that each step's vectors do not break a number a line.
    const Qt::Orientation orientation = width() > 1.25 * height() ? Qt::Horizontal : Qt::Vertical;
    if (orientation != m_splitter->orientation() || !m_splitterPlaced) {
        m_splitter->setOrientation(orientation);
        const int total = orientation == Qt::Horizontal ? width() : height();
        int text = total - total * 3 / 5;
        if (orientation == Qt::Horizontal)
            text = std::max(text, std::min(total / 2, fontMetrics().averageCharWidth() * 34));
        m_splitter->setSizes({total - text, text});
        m_splitterPlaced = true;
    }
}

void CameraBasisView::applyPresentation() {
    m_canvas->setLineWidth(m_inspection ? m_inspection->lineWidth() : 1.5);
    setFont(scaledFont(parentWidget(), m_inspection ? m_inspection->textScale(1.35) : 1.0));
}

void CameraBasisView::refresh() {
    if (!isVisible()) {
        m_dirty = true;
        return;
    }
    m_dirty = false;
    const std::shared_ptr<const rl::FrameTrace> frame =
        m_inspection ? m_inspection->frame() : nullptr;
    m_allSteps.clear();
    m_allFigures.clear();
    m_residualText.clear();
    m_matrixText.clear();
    m_statusText.clear();
    m_explanationHtml.clear();
    m_matrixHtml.clear();
    m_illConditioned = false;
    m_conditionRatio = 1.0;

    const rl::CameraBasis* basis = frame ? frame->cameraBasis.get() : nullptr;
    QString message;
    if (!m_error.isEmpty()) {
        m_statusText = tr("The camera was rejected: %1").arg(m_error);
        message = m_statusText;
    } else if (!frame) {
        message = tr("No frame yet.");
    } else if (!basis || basis->skipped) {
        m_statusText = tr("This stage is skipped: %1.")
                           .arg(basis ? QString::fromStdString(basis->skipReason)
                                      : tr("the frame has no camera basis"));
        message = m_statusText;
    }
    if (!message.isEmpty()) {
        m_canvas->setMessage(message);
        m_canvas->setPicture(CameraBasisPicture{});
        m_explanationHtml =
            tr("<p><b>Camera basis.</b> From the course camera (C, N, V) Gram-Schmidt makes "
               "the orthonormal basis U, V, N of view space. A scene whose draws carry their "
               "own model/view matrices (HW2 command files) has no course camera: this stage "
               "does nothing for it.</p>");
        showStep();
        return;
    }

    const rl::CameraBasis& b = *basis;
    const rl::CourseCamera& camera = *frame->scene->camera;
    m_conditionRatio = b.vOrthogonalLength / glm::length(b.vGiven);
    m_illConditioned = m_conditionRatio < kIllConditionedRatio;
    if (m_illConditioned)
        m_statusText = tr("N and V are nearly parallel: |V − (V·N) N| / |V| = %1, below %2. "
                          "The basis is ill-conditioned: a tiny change of N or V turns U and V "
                          "a lot. Choose a V further from N.")
                           .arg(number(m_conditionRatio, 3), number(kIllConditionedRatio));

    // The key numbers of each step, large: what it starts from and what it makes.
    m_allFigures = {QStringLiteral("C = %1  N = %2  V = %3")
                        .arg(vector(camera.c), vector(b.nGiven), vector(b.vGiven)),
                    QStringLiteral("|N| = %1  N = %2").arg(number(b.nLength), vector(b.n)),
                    QStringLiteral("V·N = %1  V − (V·N) N = %2")
                        .arg(number(b.vDotN), vector(b.vOrthogonal)),
                    QStringLiteral("|V| = %1  V = %2")
                        .arg(number(b.vOrthogonalLength), vector(b.v)),
                    QStringLiteral("U = %1  V = %2  N = %3")
                        .arg(vector(b.u), vector(b.v), vector(b.n))};
    m_allSteps << tr("1. N := N / |N| = %1 / %2 = %3")
                      .arg(vector(b.nGiven), number(b.nLength), vector(b.n))
               << tr("2. V := V − (V·N) N: V·N = %1, (V·N) N = %2, V − (V·N) N = %3")
                      .arg(number(b.vDotN), vector(b.vProjection), vector(b.vOrthogonal))
               << tr("3. V := V / |V| = %1 / %2 = %3")
                      .arg(vector(b.vOrthogonal), number(b.vOrthogonalLength), vector(b.v))
               << tr("4. U := N × V = %1 × %2 = %3").arg(vector(b.n), vector(b.v), vector(b.u));

    m_residualText = tr("U·V = %1, U·N = %2, V·N = %3, |U| − 1 = %4, |V| − 1 = %5, |N| − 1 = %6; "
                        "largest %7")
                         .arg(number(b.uDotV, 3), number(b.uDotN, 3), number(b.vDotNResidual, 3),
                              number(b.uLengthError, 3), number(b.vLengthError, 3),
                              number(b.nLengthError, 3), number(b.maxResidual(), 3));
    // The conditioning: V - (V.N) N keeps sin(angle) of V, and the residuals grow as it shrinks.
    m_residualText += QStringLiteral("; ") +
                      tr("N and V %1 degrees apart (under %2 degrees from the line of N, the "
                         "residuals pass a float's precision)")
                          .arg(number(b.angleNV), number(rl::CameraBasisStage::kWarnAngleDegrees));

    // viewFromWorld is column-major: row r is m[0][r] .. m[3][r].
    QStringList rows;
    QString table = QStringLiteral("<table cellspacing=\"0\" cellpadding=\"2\">");
    const QString rowNames[4] = {QStringLiteral("U"), QStringLiteral("V"), QStringLiteral("N"),
                                 QString()};
    for (int r = 0; r < 4; ++r) {
        QStringList cells;
        table += QStringLiteral("<tr><td><b>%1</b></td>").arg(rowNames[r]);
        for (int col = 0; col < 4; ++col) {
            cells << number(b.viewFromWorld[col][r]);
            table += QStringLiteral("<td align=\"right\">&nbsp;%1&nbsp;</td>").arg(cells.back());
        }
        table += QStringLiteral("</tr>");
        rows << cells.join(QLatin1Char(' '));
    }
    table += QStringLiteral("</table>");
    m_matrixText = rows.join(QLatin1Char('\n'));
    m_matrixHtml = QStringLiteral("<p>") +
                   tr("<b>viewFromWorld</b> = [U; V; N] · translate(−C): rows U, V, N, then "
                      "(0 0 0 1); the last column is −U·C, −V·C, −N·C.") +
                   QStringLiteral("</p>") + table;

    // The formula with the numbers of the first vertex of the first mesh.
    QString example;
    const rl::Scene& scene = *frame->scene;
    if (!scene.draws.empty() && scene.draws[0].mesh && !scene.draws[0].mesh->positions.empty()) {
        const dvec3 pWorld =
            rl::cartesian(frame->view->worldFromModel[0] * scene.draws[0].mesh->positions[0]);
        const dvec3 q = pWorld - b.c;
        const dvec3 pView(glm::dot(b.u, q), glm::dot(b.v, q), glm::dot(b.n, q));
        example = tr("<p>Vertex 1: P = %1, P − C = %2, pView = (U·(P − C), V·(P − C), "
                     "N·(P − C)) = %3%4.</p>")
                      .arg(vector(pWorld), vector(q), vector(pView),
                           pView.z > 0.0 ? tr(", in front of the camera (z > 0)")
                                         : tr(", behind the camera (z ≤ 0)"));
    }
    m_explanationHtml =
        tr("<p><b>Camera basis.</b> Gram-Schmidt keeps the direction of N (where the camera "
           "looks), removes from V its part along N so that up is perpendicular to the view "
           "direction, and completes the frame with U = N × V, the image's right. "
           "viewFromWorld = [U; V; N] (P − C) puts the camera at the origin looking along "
           "+z.</p>"
           "<p>C = %1, N = %2, V = %3, d = %4, hx = %5, hy = %6.</p>")
            .arg(vector(b.c), vector(b.nGiven), vector(b.vGiven), number(camera.d),
                 number(camera.hx), number(camera.hy)) +
        example;

    CameraBasisPicture picture;
    picture.valid = true;
    picture.basis = b;
    picture.d = camera.d;
    picture.hx = camera.hx;
    picture.hy = camera.hy;
    picture.cloud = cloudOf(scene, *frame->view);
    placePicture(picture);
    m_canvas->setMessage(QString());
    m_canvas->setPicture(std::move(picture));
    showStep();
}

void CameraBasisView::showStep() {
    {
        const QSignalBlocker block(m_stepSlider);
        m_stepSlider->setValue(m_step);
    }
    const bool numbers = !m_allSteps.isEmpty();
    m_stepSlider->setEnabled(numbers);
    m_back->setEnabled(numbers && m_step > 0);
    m_forward->setEnabled(numbers && m_step < 4);
    m_stepLabel->setText(tr("Step %1 of 4").arg(m_step));
    m_figures->setText(numbers ? m_allFigures.value(m_step) : QString());
    m_canvas->setStep(m_step);

    // One page: why to distrust the numbers, the steps revealed so far (the newest in
    // bold), the matrix, the residuals, and the explanation.
    QString html;
    if (!m_statusText.isEmpty())
        html += QStringLiteral(
                    "<table width=\"100%\" cellpadding=\"6\"><tr><td "
                    "bgcolor=\"#fff3cd\"><font color=\"#664d03\">%1</font></td>"
                    "</tr></table>")
                    .arg(m_statusText.toHtmlEscaped());
    if (numbers) {
        static const char* const next[5] = {
            QT_TR_NOOP("Step forward to normalise N."),
            QT_TR_NOOP("Step forward to remove from V its part along N."),
            QT_TR_NOOP("Step forward to normalise V."),
            QT_TR_NOOP("Step forward to make U = N × V."),
            QT_TR_NOOP("The basis is complete; the frustum is drawn with it."),
        };
        html += QStringLiteral("<p>");
        const QStringList shown = stepTexts();
        for (int k = 0; k < shown.size(); ++k) {
            const QString line = shown[k].toHtmlEscaped();
            html += (k + 1 == shown.size() ? QStringLiteral("<b>%1</b>") : QStringLiteral("%1"))
                        .arg(line) +
                    QStringLiteral("<br>");
        }
        html += QStringLiteral("<i>%1</i></p>").arg(tr(next[m_step]));
        html += m_matrixHtml;
        html += QStringLiteral("<p>") +
                tr("<b>Orthonormality residuals</b> (0 up to rounding): %1")
                    .arg(m_residualText.toHtmlEscaped()) +
                QStringLiteral("</p>");
    }
    html += m_explanationHtml;
    m_text->setHtml(html);
}

}  // namespace rasterlab
