#include "pixel_inspector.h"

#include <QApplication>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPainter>
#include <QPixmap>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

#include <QPolygonF>
#include <QScrollBar>

#include <algorithm>
#include <cmath>

#include "inspection.h"
#include "number_text.h"
#include "output_image.h"
#include "pixel_history.h"
#include "pixel_text.h"
#include "renderer.h"
#include "shading.h"

namespace rasterlab {

namespace {

QString bytesText(const std::array<std::uint8_t, 4>& b) {
    return QStringLiteral("(%1,%2,%3)").arg(b[0]).arg(b[1]).arg(b[2]);
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

bool LightingBreakdown::has(LightingFlag flag) const {
    return std::find(flags.begin(), flags.end(), flag) != flags.end();
}

// Three stacked bars, one per channel: the terms side by side from 0, the colour scale (the
// value that becomes byte 255) marked by a line, the total written at the bar's end.
class TermBars : public QWidget {
public:
    struct Segment {
        QString name;
        QColor colour;
        rl::vec3 value;
    };

    explicit TermBars(QWidget* parent) : QWidget(parent) {
        setMinimumSize(220, 120);
        setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    }
    void setBars(std::vector<Segment> segments, rl::vec3 total, float scale, bool presentation) {
        m_segments = std::move(segments);
        m_total = total;
        m_scale = scale;
        m_presentation = presentation;
        QFont f = font();
        f.setPointSizeF(presentation ? 12.0 : 8.0);
        setFixedHeight(QFontMetrics(f).height() * 6 + 20);
        update();
    }
    QSize sizeHint() const override { return {320, 130}; }

protected:
    void paintEvent(QPaintEvent*) override {
        QPainter painter(this);
        painter.fillRect(rect(), QColor(32, 32, 36));
        if (m_segments.empty()) return;
        QFont f = painter.font();
        f.setPointSizeF(m_presentation ? 12.0 : 8.0);
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
        const double barHeight = line * 1.2;
        const double top = line + 6;
        const std::array<QColor, 3> channelColours{QColor(255, 110, 110), QColor(110, 220, 110),
                                                   QColor(120, 160, 255)};
        for (int c = 0; c < 3; ++c) {
            const double y = top + c * (barHeight + 6);
            painter.setPen(channelColours[static_cast<std::size_t>(c)]);
            painter.drawText(QRectF(0, y, left - 4, barHeight), Qt::AlignRight | Qt::AlignVCenter,
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
            painter.setPen(QColor(230, 230, 230));
            painter.drawText(QRectF(x + 4, y, width() - x - 4, barHeight), Qt::AlignVCenter,
                             num(m_total[c], 4));
        }
        // The colour scale: what reaches it or goes beyond becomes byte 255.
        const double scaleX = left + double(m_scale) * unit;
        const double bottom = top + 3 * (barHeight + 6) - 6;
        painter.setPen(QPen(QColor(255, 255, 255), 1.0, Qt::DashLine));
        painter.drawLine(QPointF(scaleX, top - 3), QPointF(scaleX, bottom + 3));
        painter.setPen(QColor(230, 230, 230));
        const QString scaleText = m_scale == 255.0f
                                      ? QStringLiteral("255")
                                      : PixelInspector::tr("%1 = byte 255").arg(num(m_scale));
        painter.drawText(QPointF(std::min(scaleX - metrics.horizontalAdvance(scaleText) / 2.0,
                                          width() - metrics.horizontalAdvance(scaleText) - 2.0),
                                 metrics.ascent() + 2),
                         scaleText);
        // Legend.
        double x = left;
        const double y = bottom + 8;
        for (const Segment& s : m_segments) {
            painter.fillRect(QRectF(x, y + 2, 10, line - 4), s.colour);
            painter.setPen(QColor(220, 220, 220));
            painter.drawText(QPointF(x + 14, y + metrics.ascent()), s.name);
            x += 14 + metrics.horizontalAdvance(s.name) + 12;
        }
    }

private:
    std::vector<Segment> m_segments;
    rl::vec3 m_total = rl::vec3(0.0f);
    float m_scale = 255.0f;
    bool m_presentation = false;
};

// N, L, V and R (or H) from the surface point, drawn in the plane of incidence (the plane
// of N and L, in which R lies too): N points up, the surface is the horizontal line, L and R
// are at their true angles, and V is projected onto the page (dashed when it leaves it by
// more than a little).
class LightingVectors : public QWidget {
public:
    explicit LightingVectors(QWidget* parent) : QWidget(parent) { setFixedSize(180, 160); }
    void setVectors(std::optional<std::array<rl::vec3, 4>> vectors, QString reflectionName,
                    double lineWidth, bool presentation) {
        m_vectors = vectors;
        m_reflection = std::move(reflectionName);
        m_lineWidth = lineWidth;
        m_presentation = presentation;
        setFixedSize(presentation ? QSize(250, 220) : QSize(180, 160));
        update();
    }

protected:
    void paintEvent(QPaintEvent*) override {
        QPainter painter(this);
        painter.fillRect(rect(), QColor(32, 32, 36));
        if (!m_vectors) return;
        const auto& [n, l, v, r] = *m_vectors;
        QFont f = painter.font();
        f.setPointSizeF(m_presentation ? 12.0 : 8.0);
        painter.setFont(f);
        const QFontMetrics metrics(f);
        painter.setRenderHint(QPainter::Antialiasing);
        if (!(glm::length(n) > 0.0f)) {
            painter.setPen(QColor(200, 200, 200));
            painter.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap,
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
        for (const Label& label : labels) {
            painter.setPen(label.colour);
            const double w = metrics.horizontalAdvance(label.text) + 4.0;
            const double x = std::max(2.0, std::min(label.at.x() - w / 2.0, width() - w - 2.0));
            painter.drawText(QRectF(x, label.at.y() - 9, w, 18), Qt::AlignCenter, label.text);
        }
        painter.setPen(Qt::NoPen);
        painter.setBrush(Qt::white);
        painter.drawEllipse(centre, 2.5, 2.5);
        painter.setPen(QColor(170, 170, 180));
        painter.drawText(QRectF(0, height() - metrics.height() - 4, width(), metrics.height()),
                         Qt::AlignCenter, PixelInspector::tr("in the plane of N and L"));
    }

private:
    std::optional<std::array<rl::vec3, 4>> m_vectors;
    QString m_reflection;
    double m_lineWidth = 1.5;
    bool m_presentation = false;
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
    m_table->setHorizontalHeaderLabels(
        {tr("Step"), tr("Triangle"), tr("Depth test"), tr("Before"), tr("After"), tr("Result")});
    m_table->verticalHeader()->setVisible(false);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setWordWrap(false);
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

    auto* pictures = new QHBoxLayout;
    pictures->addWidget(m_bars, 1);
    pictures->addWidget(m_vectors, 0, Qt::AlignTop);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_verdictLabel);
    layout->addWidget(m_table);
    layout->addWidget(m_legend);
    layout->addWidget(m_breakdownTitle);
    layout->addLayout(pictures);
    layout->addWidget(m_formula);
    layout->addWidget(m_flags);
    layout->addStretch(1);

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
    refresh();
}

void PixelInspector::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    // Another font (presentation mode): the table's height is worked out again once the
    // header has taken it.
    if (event->type() == QEvent::FontChange)
        QMetaObject::invokeMethod(this, &PixelInspector::fitTableHeight, Qt::QueuedConnection);
}

void PixelInspector::applyPresentation() {
    // Larger text when presenting, for the whole inspector.
    m_presenting = m_inspection->presentation();
    QFont base = QApplication::font(this);
    if (m_presenting) base.setPointSizeF(base.pointSizeF() * 1.4);
    setFont(base);
    m_table->setFont(base);
    QFont bold = base;
    bold.setBold(true);
    m_verdictLabel->setFont(bold);
    m_breakdownTitle->setFont(bold);
    QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    if (m_presenting) mono.setPointSizeF(mono.pointSizeF() * 1.4);
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

void PixelInspector::selectRow(int row) {
    m_userSelected = true;
    m_selected = row >= 0 && row < static_cast<int>(m_history.rows().size()) ? row : -1;
    updateBreakdown();
    showBreakdown();
}

QString PixelInspector::formulaText() const {
    return m_breakdown ? m_breakdown->formula.join(QLatin1Char('\n')) : QString();
}

QStringList PixelInspector::lightLines(std::size_t k, const rl::LightTerms& t,
                                       const rl::FrameTrace& frame,
                                       rl::SpecularModel specular) const {
    const rl::ViewLight& light = frame.view->lights[k];
    const rl::Light& world = frame.scene->lights[k];
    QStringList lines;
    QString where = light.pView.w == 0.0 ? tr("Light %1, directional toward %2 (view), Il = %3")
                                         : tr("Light %1 at %2 (view), Il = %3");
    lines << where.arg(k + 1).arg(vector3(rl::vec3(light.pView)), vector3(light.intensity));
    if (t.atPoint) {
        lines << tr("  at the point itself (L = 0): nothing");
        return lines;
    }
    QStringList factors;
    if (light.attenuated)
        factors << tr("att = 1 / (%1 + %2 × %3 + %4 × %3²) = %5")
                       .arg(num(light.attenuation.x), num(light.attenuation.y), num(t.distance),
                            num(light.attenuation.z), num(t.attenuation, 4));
    else if (light.pView.w != 0.0)
        factors << tr("d = %1, not attenuated").arg(num(t.distance));
    if (light.spot)
        factors << (t.outsideCone ? tr("spot: −L.D = %1 < cos %2° = %3, outside the cone: 0")
                                        .arg(num(t.spotCos, 4), num(world.spotCutoff),
                                             num(light.spotCosCutoff, 4))
                                  : tr("spot: −L.D = %1 ≥ cos %2° = %3, %1^%4 = %5")
                                        .arg(num(t.spotCos, 4), num(world.spotCutoff),
                                             num(light.spotCosCutoff, 4), num(light.spotExponent),
                                             num(t.spot, 4)));
    if (!factors.isEmpty()) lines << QStringLiteral("  ") + factors.join(QStringLiteral("; "));
    const QString highlight =
        specular == rl::SpecularModel::BlinnPhong ? QStringLiteral("N.H") : QStringLiteral("R.V");
    if (t.behind)
        lines << tr("  N.L = %1 < 0: behind the surface, nothing").arg(num(t.nDotL));
    else
        lines << tr("  N.L = %1, %2 = %3: diffuse %4, specular %5")
                     .arg(num(t.nDotL), highlight, num(t.rDotV), vector3(t.diffuse),
                          vector3(t.specular));
    return lines;
}

void PixelInspector::updateBreakdown() {
    const std::shared_ptr<const rl::FrameTrace>& frame = m_inspection->frame();
    const PixelHistoryRow* row =
        m_selected >= 0 && m_selected < static_cast<int>(m_history.rows().size())
            ? &m_history.rows()[m_selected]
            : nullptr;
    // The final row shows the lighting of the fragment that wrote it.
    const bool hasFragment =
        row && row->kind != PixelHistoryRow::Kind::Initial && row->fragment != rl::kNoFragment;
    if (m_breakdown && hasFragment && m_breakdown->historyRow == m_selected &&
        m_breakdown->fragment == row->fragment)
        return;  // already shown
    m_breakdown.reset();
    if (!frame || !hasFragment) return;
    std::optional<rl::ShadeEvent> event;
    if (const rl::FrameReplay* replay = m_inspection->replay(); replay && !m_history.traced()) {
        event = replay->shade({row->fragment}).front();
    } else if (m_history.tracedShade() && row->fragment == m_history.rows().back().fragment) {
        event = m_history.tracedShade();  // the fragment that holds the pixel at the end
    }
    if (!event) return;

    const rl::Scene& scene = *frame->scene;
    const rl::Conventions& conv = scene.conventions;
    const rl::ScreenTriangle& tri = frame->projection->triangles[event->triangle];
    const rl::DrawProjection& proj = frame->projection->draws[tri.draw];
    const rl::Draw& draw = scene.draws[tri.draw];
    const rl::Material& m = draw.material;
    const rl::PhongSample& s = event->sample;
    LightingBreakdown b;
    b.historyRow = m_selected;
    b.fragment = row->fragment;
    b.event = *event;
    b.lighting = draw.lighting;
    b.lights = std::min(draw.lightCount, frame->view ? frame->view->lights.size() : 0);
    b.colour = event->colour;
    b.bytes = rl::colourBytes(event->colour, conv);
    const rl::ShadingModel model = event->model;
    const bool lit =
        model != rl::ShadingModel::Gouraud && draw.lighting != rl::LightingModel::Unlit;
    if (model != rl::ShadingModel::Gouraud) {
        b.ambient = s.ambient;
        b.diffuse = s.diffuse;
        b.specular = s.specular;
        b.unlit = s.unlit;
    }
    float beta = row->beta, gamma = row->gamma;
    rl::attributeWeights(scene.rules, proj, tri.v, beta, gamma);
    // The object colour as shading reads it, from the mesh's values at the projected vertices.
    const rl::Mesh& mesh = *draw.mesh;
    const rl::ProjectedValues<rl::vec3> colours{mesh.colours, proj};
    const rl::ProjectedValues<rl::vec2> texcoords{mesh.texcoords, proj};
    if (rl::litPerTriangle(model)) {
        // At the barycentre of the whole (unclipped) mesh triangle.
        const auto& corners = mesh.triangles[tri.source];
        b.objectColour = rl::objectColour(draw, scene.rules.texel, colours, texcoords, corners,
                                          1.0f / 3.0f, 1.0f / 3.0f);
    } else {
        b.objectColour =
            rl::objectColour(draw, scene.rules.texel, colours, texcoords, tri.v, beta, gamma);
    }
    if (model == rl::ShadingModel::Gouraud) {
        b.weights = {1.0f - beta - gamma, beta, gamma};
        b.vertexColours = event->vertexColours;
    }

    // Flags.
    const auto flag = [&](LightingFlag f, const QString& text) {
        b.flags.push_back(f);
        b.flagTexts.push_back(text);
    };
    if (lit) {
        if (s.flipped)
            flag(LightingFlag::Flipped,
                 tr("N flipped toward the viewer: V.N < 0, so N := −N before lighting."));
        if (s.noNormal)
            flag(LightingFlag::ZeroNormal,
                 tr("Zero normal: only degenerate triangles meet here, or the vertex normals "
                    "cancel out; ambient only."));
        if (s.lightAtPoint)
            flag(LightingFlag::LightAtPoint,
                 tr("The light is at the point itself (L = 0): it adds nothing."));
        if (s.lightBehind)
            flag(LightingFlag::LightBehind,
                 tr("N.L < 0: the light is behind the surface; no diffuse, no specular."));
        if (s.noSpecular)
            flag(LightingFlag::NoSpecular,
                 tr("R.V < 0: the reflected ray points away from the viewer; no specular."));
    }
    // The course's model light by light: the same call as the shading stage's, at the point
    // and with the normal it lit (the event's: P' for Phong, the barycentre for flat).
    if (lit && draw.lighting == rl::LightingModel::CoursePhong && frame->view) {
        b.emission = s.emission;
        b.perLight.resize(b.lights);
        if (b.lights > 0)
            rl::phong(m, b.objectColour, scene.ambientIntensity, frame->view->lights.data(),
                      b.lights, event->pView, event->nInterpolated, conv.flipNormalsTowardViewer,
                      draw.specular, b.perLight.data());
        b.slides = m.emission != rl::vec3(0.0f) || draw.specular != rl::SpecularModel::Phong;
        for (std::size_t k = 0; k < b.lights; ++k) {
            const rl::ViewLight& light = frame->view->lights[k];
            b.slides = b.slides || !light.plain() || light.pView.w == 0.0;
            const rl::LightTerms& t = b.perLight[k];
            if (t.outsideCone && !t.behind)
                flag(LightingFlag::OutsideCone,
                     tr("Outside the cone of light %1: −L.D = %2 is below cos %3° = %4; it adds "
                        "nothing here.")
                         .arg(k + 1)
                         .arg(num(t.spotCos, 4), num(scene.lights[k].spotCutoff),
                              num(light.spotCosCutoff, 4)));
        }
        if (!conv.flipNormalsTowardViewer && !s.noNormal && glm::dot(s.n, s.v) < 0.0f)
            flag(LightingFlag::OneSided,
                 tr("One-sided lighting: the back of the surface is seen (V.N < 0) and N is not "
                    "turned toward the viewer."));
    }
    if (const auto lookup = rl::texelLookup(scene, proj, tri.v, tri.draw, row->beta, row->gamma)) {
        const auto texel = [](const rl::ivec2& t) {
            return QStringLiteral("(%1, %2)").arg(t.x).arg(t.y);
        };
        QString text = tr("Texture at (s, t) = (%1, %2): texel %3.")
                           .arg(num(lookup->st.x, 4), num(lookup->st.y, 4), texel(lookup->used));
        if (lookup->rulesDisagree())
            text += QLatin1Char(' ') +
                    (scene.rules.texel == rl::RasterRules::TexelRounding::Truncate
                         ? tr("Seed 001's text and its reference images disagree here: the "
                              "texel nearest to (s w, t h) once the coordinates wrap is %1; the "
                              "images' (int)(s w + 0.5) mod w gives %2, which these rules "
                              "follow.")
                         : tr("Seed 001's text and its reference images disagree here: the "
                              "texel nearest to (s w, t h) once the coordinates wrap is %1, "
                              "which these rules follow; the images' (int)(s w + 0.5) mod w "
                              "gives %2."))
                        .arg(texel(lookup->nearest), texel(lookup->truncated));
        flag(LightingFlag::Texel, text);
    }
    const float scale = conv.colourScale;
    for (int c = 0; c < 3; ++c) {
        if (event->colour[c] > scale) {
            QStringList over;
            for (int k = 0; k < 3; ++k)
                if (event->colour[k] > scale)
                    over << QStringLiteral("%1 = %2").arg(channelNames()[std::size_t(k)],
                                                          num(event->colour[k], 4));
            flag(LightingFlag::Clamped,
                 tr("Clamped: %1 above the colour scale %2, written as byte 255.")
                     .arg(over.join(QStringLiteral(", ")), num(scale)));
            break;
        }
    }

    // The formula with the numbers filled in, one line per channel.
    const auto byteOf = [&](int c) {
        const QString byte = QString::number(b.bytes[static_cast<std::size_t>(c)]);
        return event->colour[c] > scale ? tr("%1 (clamped)").arg(byte) : byte;
    };
    QStringList& f = b.formula;
    switch (model) {
        case rl::ShadingModel::Gouraud: {
            b.heading = tr("Gouraud shading, the vertices' colours mixed");
            f << tr("C = α C1 + β C2 + γ C3");
            f << QStringLiteral("α = %1, β = %2, γ = %3")
                     .arg(num(b.weights[0]), num(b.weights[1]), num(b.weights[2]));
            f << QStringLiteral("C1 = %1, C2 = %2, C3 = %3")
                     .arg(vector3(b.vertexColours[0]), vector3(b.vertexColours[1]),
                          vector3(b.vertexColours[2]));
            for (int c = 0; c < 3; ++c)
                f << QStringLiteral("%1 = %2 × %3 + %4 × %5 + %6 × %7 = %8 → %9")
                         .arg(channelNames()[std::size_t(c)], num(b.weights[0], 4),
                              num(b.vertexColours[0][c], 4), num(b.weights[1], 4),
                              num(b.vertexColours[1][c], 4), num(b.weights[2], 4),
                              num(b.vertexColours[2][c], 4), num(event->colour[c]), byteOf(c));
            break;
        }
        case rl::ShadingModel::Flat:
        case rl::ShadingModel::Painter:
        case rl::ShadingModel::Phong: {
            if (draw.lighting == rl::LightingModel::Unlit) {
                b.heading = tr("not lit, the object colour as it is");
                f << tr("I = O (the object colour)");
                for (int c = 0; c < 3; ++c)
                    f << QStringLiteral("%1 = %2 → %3")
                             .arg(channelNames()[std::size_t(c)], num(s.unlit[c]), byteOf(c));
                break;
            }
            const bool course = draw.lighting == rl::LightingModel::CoursePhong;
            b.heading = course ? tr("the course's Phong lighting model")
                               : tr("Lambert with Blinn-Phong highlights (command files)");
            if (model == rl::ShadingModel::Painter)
                f << tr(
                    "Painter's algorithm: lit as flat shading, once at the triangle's "
                    "barycentre; the triangles are painted far to near without a depth "
                    "test.");
            if (rl::litPerTriangle(model))
                f << tr(
                    "Flat shading: evaluated once, at the triangle's barycentre with the "
                    "triangle's normal; every pixel of the triangle gets this colour.");
            if (b.lights > 1 && !(course && b.slides))
                f << tr("%1 lights: the diffuse and specular terms are sums over them; the "
                        "numbers filled in are the first light's.")
                         .arg(b.lights);
            const rl::vec3 il = b.lights > 0 ? frame->view->lights[0].intensity : rl::vec3(0.0f);
            const bool noLight = b.lights == 0 || s.noNormal || s.lightAtPoint;
            const rl::vec3 od = b.objectColour;
            if (course && b.slides) {
                f << (draw.specular == rl::SpecularModel::BlinnPhong
                          ? tr("I = Ke + Ia ka + Σ att spot (Il Od kd (N.L) + Il ks (N.H)^n)")
                          : tr("I = Ke + Ia ka + Σ att spot (Il Od kd (N.L) + Il ks (R.V)^n)"));
                f << tr(
                    "att = 1 / (kc + kl d + kq d²) for a positional light, 1 for a "
                    "directional one; spot = (−L.D)^exp inside the cone, 0 outside, 1 for "
                    "a light that is no spot.");
            } else if (course) {
                f << tr("I = Ia ka + Il Od kd (N.L) + Il ks (R.V)^n");
                if (!noLight && s.lightBehind)
                    f << QStringLiteral("N.L = %1 < 0").arg(num(s.nDotL));
                else if (!noLight)
                    f << QStringLiteral("N.L = %1, R.V = %2, n = %3")
                             .arg(num(s.nDotL), num(s.rDotV), num(m.shininess));
            } else {
                f << (m.shininess > 0.0f ? tr("I = Σ Il O (N.L) + Il (H.N)^s, over the lights "
                                              "with N.L ≥ 0")
                                         : tr("I = Σ Il O (N.L), over the lights with N.L ≥ 0"));
                if (!noLight && s.lightBehind)
                    f << QStringLiteral("N.L = %1 < 0").arg(num(s.nDotL));
                else if (!noLight && m.shininess > 0.0f)
                    f << QStringLiteral("N.L = %1, H.N = %2, s = %3")
                             .arg(num(s.nDotL), num(s.rDotV), num(m.shininess));
                else if (!noLight)
                    f << QStringLiteral("N.L = %1").arg(num(s.nDotL));
            }
            if (course && b.slides) {
                // Ke + Ia ka + each light's diffuse and specular, light by light below.
                for (int c = 0; c < 3; ++c) {
                    const auto k = static_cast<std::size_t>(c);
                    QStringList sums;
                    sums << num(b.emission[c]) << num(b.ambient[c]);
                    for (const rl::LightTerms& t : b.perLight)
                        sums << num(t.diffuse[c]) << num(t.specular[c]);
                    f << QStringLiteral("%1 = %2 = %3 → %4")
                             .arg(channelNames()[k], sums.join(QStringLiteral(" + ")),
                                  num(event->colour[c]), byteOf(c));
                }
            } else {
                for (int c = 0; c < 3; ++c) {
                    const auto k = static_cast<std::size_t>(c);
                    QStringList parts;
                    float first = 0.0f;  // the first light's diffuse and specular
                    if (course)
                        parts << QStringLiteral("%1 × %2").arg(num(scene.ambientIntensity[c]),
                                                               num(m.ka));
                    if (noLight || s.lightBehind) {
                        parts << QStringLiteral("0");
                    } else {
                        parts << (course
                                      ? QStringLiteral("%1 × %2 × %3 × %4")
                                            .arg(num(il[c]), num(od[c]), num(m.kd[c]), num(s.nDotL))
                                      : QStringLiteral("%1 × %2 × %3")
                                            .arg(num(il[c]), num(od[c]), num(s.nDotL)));
                        first +=
                            course ? il[c] * od[c] * m.kd[c] * s.nDotL : il[c] * od[c] * s.nDotL;
                        if (course) {
                            if (s.noSpecular) {
                                parts << QStringLiteral("0");
                            } else {
                                parts << QStringLiteral("%1 × %2 × %3^%4")
                                             .arg(num(il[c]), num(m.ks), num(s.rDotV),
                                                  num(m.shininess));
                                if (m.ks != 0.0f)
                                    first += il[c] * m.ks * rl::fastPow(s.rDotV, m.shininess);
                            }
                        } else if (m.shininess > 0.0f) {
                            parts << QStringLiteral("%1 × %2^%3")
                                         .arg(num(il[c]), num(s.rDotV), num(m.shininess));
                            first += il[c] * rl::fastPow(s.rDotV, m.shininess);
                        }
                    }
                    const float others = b.diffuse[c] + b.specular[c] - first;
                    if (b.lights > 1) parts << tr("%1 (the other lights)").arg(num(others, 4));
                    QStringList sums;
                    if (course) sums << num(b.ambient[c]);
                    sums << num(b.diffuse[c]);
                    if (course || m.shininess > 0.0f) sums << num(b.specular[c]);
                    // The terms' values between the formula and the total, when there are several.
                    const QString values =
                        parts.size() > 1 && sums.size() > 1
                            ? QStringLiteral(" = ") + sums.join(QStringLiteral(" + "))
                            : QString();
                    f << QStringLiteral("%1 = %2%3 = %4 → %5")
                             .arg(channelNames()[k], parts.join(QStringLiteral(" + ")), values,
                                  num(event->colour[c]), byteOf(c));
                }
            }
            if (course)
                f << tr("Ia = %1, ka = %2, Il = %3, Od = %4, kd = %5, ks = %6")
                         .arg(vector3(scene.ambientIntensity), num(m.ka), vector3(il), vector3(od),
                              vector3(m.kd), num(m.ks));
            else
                f << tr("Il = %1, O = %2").arg(vector3(il), vector3(od));
            if (course && (b.slides || b.lights > 1)) {
                if (b.emission != rl::vec3(0.0f))
                    f << tr("Ke = %1: the material's own light").arg(vector3(b.emission));
                for (std::size_t k = 0; k < b.perLight.size(); ++k)
                    f << lightLines(k, b.perLight[k], *frame, draw.specular);
            }
            break;
        }
    }
    m_breakdown = std::move(b);
}

void PixelInspector::fillTable() {
    const QSignalBlocker block(m_table);
    QFont bold = m_table->font();
    bold.setBold(true);
    m_verdictLabel->setText(m_history.verdict());
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
        };
        colourCell(3, row.before);
        colourCell(4, row.after);
    }
    m_table->setIconSize(QSize(swatchSize, swatchSize));
    m_table->resizeColumnsToContents();
    m_table->resizeRowsToContents();
    fitTableHeight();
    showBreakdown();
}

void PixelInspector::fitTableHeight() {
    // Tall enough for every row, up to ten; beyond, it scrolls.
    int height = m_table->horizontalHeader()->height() + 2 * m_table->frameWidth();
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
    m_bars->setBars(std::move(segments), b.colour, frame.scene->conventions.colourScale,
                    m_presenting);
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
                              half ? QStringLiteral("H") : QStringLiteral("R"), lineWidth,
                              m_presenting);
    }
    m_vectors->setVisible(vectors);
    m_formula->setText(formulaText());
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
