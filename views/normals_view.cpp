#include "normals_view.h"

#include <QApplication>
#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QResizeEvent>
#include <QScrollArea>
#include <QSplitter>
#include <QTabWidget>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pipeline/render/animation.h"
#include "views/frame_image_view.h"
#include "views/inspection.h"
#include "views/key_figures.h"
#include "views/number_text.h"
#include "views/view_font.h"
#include "views/wrapping_check_box.h"

namespace rasterlab {

NormalsView::NormalsView(Inspection* inspection, QWidget* parent)
    : QWidget(parent), m_inspection(inspection) {
    setObjectName(QStringLiteral("normalsView"));
    m_canvas = new NormalsCanvas(this);
    m_canvas->setObjectName(QStringLiteral("normalsCanvas"));
    m_canvas->setPicture(&m_model.picture());
    m_mapView = new FrameImageView(this);
    m_mapView->setObjectName(QStringLiteral("normalMapImage"));
    m_triangleHairs = new WrappingCheckBox(tr("Triangle normals"), this);
    m_triangleHairs->setObjectName(QStringLiteral("normalsTriangleHairs"));
    m_triangleHairs->setChecked(true);
    m_vertexHairs = new WrappingCheckBox(tr("Vertex normals"), this);
    m_vertexHairs->setObjectName(QStringLiteral("normalsVertexHairs"));
    m_vertexHairs->setChecked(false);
    m_onlyVisible = new WrappingCheckBox(tr("Only on triangles that are seen"), this);
    m_onlyVisible->setObjectName(QStringLiteral("normalsOnlyVisible"));
    m_onlyVisible->setToolTip(
        tr("Hairs only on the triangles that hold a pixel at the end of the frame, and on "
           "their corners"));
    m_onlyVisible->setChecked(true);
    m_wrong = new WrappingCheckBox(tr("Normals by M (wrong)"), this);
    m_wrong->setObjectName(QStringLiteral("normalsWrong"));
    m_wrong->setToolTip(
        tr("Beside each triangle normal, the model normal carried by viewFromModel itself "
           "instead of its inverse transpose: it leaves the surface under a non-uniform scale "
           "(set one in the Animation panel)"));
    // A plain wrapped label: its column's layout gives it the height its lines need.
    m_legend = new QLabel(this);
    m_legend->setObjectName(QStringLiteral("normalsLegend"));
    m_legend->setWordWrap(true);
    m_legend->setTextFormat(Qt::RichText);
    m_pixelValue = new QLabel(this);
    m_pixelValue->setObjectName(QStringLiteral("normalMapValue"));
    m_pixelValue->setWordWrap(true);
    m_explanation = new QTextBrowser(this);
    m_explanation->setObjectName(QStringLiteral("normalsExplanation"));

    // The drawing alone on its page; its switches head the column of words.
    auto* meshPage = new QWidget(this);
    auto* meshLayout = new QVBoxLayout(meshPage);
    meshLayout->setContentsMargins(0, 0, 0, 0);
    meshLayout->addWidget(m_canvas, 1);
    auto* mapPage = new QWidget(this);
    auto* mapLayout = new QVBoxLayout(mapPage);
    mapLayout->setContentsMargins(0, 0, 0, 0);
    auto* caption = new QLabel(
        tr("Per pixel at the stepping cursor, the unit normal shading uses there: the vertex "
           "normals interpolated with the pixel's barycentrics and normalised (the triangle's "
           "normal for flat shading), turned toward the viewer as the course does before "
           "lighting; shown as RGB = (n + 1) / 2. Red grows to the right, green upward, blue "
           "away from the camera: turned normals face the camera, so blue is mostly below "
           "128. Black: no triangle."),
        this);
    caption->setObjectName(QStringLiteral("normalMapCaption"));
    caption->setWordWrap(true);
    m_mapView->setPreferredSize(QSize(160, 120));
    mapLayout->addWidget(m_mapView, 1);
    mapLayout->addWidget(m_pixelValue);
    mapLayout->addWidget(caption);
    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName(QStringLiteral("normalsTabs"));
    m_tabs->addTab(meshPage, tr("Mesh and normals"));
    m_tabs->addTab(mapPage, tr("Normal map"));
    m_tabs->setUsesScrollButtons(false);  // both titles whole: the tabs are no narrower
    // The legend and the explanation in a column that scrolls, beside the drawing when the
    // view is wider than tall, below it otherwise: the drawing keeps the view's height or
    // width whatever the text's length.
    auto* words = new QWidget;
    words->setObjectName(QStringLiteral("normalsWords"));
    auto* wordsLayout = new QVBoxLayout(words);
    wordsLayout->setContentsMargins(0, 0, 0, 0);
    wordsLayout->setSpacing(2);
    for (QCheckBox* toggle : {m_triangleHairs, m_vertexHairs, m_onlyVisible, m_wrong})
        wordsLayout->addWidget(toggle);
    wordsLayout->addSpacing(4);
    m_figures = new KeyFigures(this);
    m_figures->setParent(words);
    wordsLayout->addWidget(m_figures);
    wordsLayout->addWidget(m_legend);
    wordsLayout->addWidget(m_explanation, 1);
    m_legend->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Minimum);
    m_explanation->setMinimumHeight(m_explanation->fontMetrics().lineSpacing() * 5);
    auto* wordsScroll = new QScrollArea(this);
    wordsScroll->setObjectName(QStringLiteral("normalsWordsScroll"));
    wordsScroll->setFrameShape(QFrame::NoFrame);
    wordsScroll->setWidgetResizable(true);
    wordsScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    wordsScroll->setWidget(words);
    wordsScroll->setMinimumWidth(m_legend->fontMetrics().averageCharWidth() * 18);
    m_words = wordsScroll;
    m_splitter = new QSplitter(Qt::Horizontal, this);
    m_splitter->setObjectName(QStringLiteral("normalsSplitter"));
    m_splitter->addWidget(m_tabs);
    m_splitter->addWidget(wordsScroll);
    m_splitter->setStretchFactor(0, 3);
    m_splitter->setStretchFactor(1, 2);
    m_splitter->setChildrenCollapsible(false);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_splitter);
    connect(m_splitter, &QSplitter::splitterMoved, this, [this] { m_splitMoved = true; });

    const auto hairs = [this] {
        m_canvas->setHairs(m_triangleHairs->isChecked(), m_vertexHairs->isChecked());
    };
    connect(m_triangleHairs, &QCheckBox::toggled, this, hairs);
    connect(m_vertexHairs, &QCheckBox::toggled, this, hairs);
    connect(m_onlyVisible, &QCheckBox::toggled, this, [this] {
        m_geometryDirty = true;
        if (isVisible()) refreshGeometry();
    });
    connect(m_wrong, &QCheckBox::toggled, this, [this](bool on) {
        m_canvas->setWrongHairs(on);
        m_geometryDirty = true;
        if (isVisible()) refreshGeometry();
    });
    m_canvas->setHairs(true, false);
    connect(m_tabs, &QTabWidget::currentChanged, this, [this] {
        // The legend and the switches are the mesh tab's.
        for (QWidget* w : std::initializer_list<QWidget*>{m_legend, m_triangleHairs, m_vertexHairs,
                                                         m_onlyVisible, m_wrong})
            w->setVisible(!mapShown());
        if (mapShown() && m_mapDirty) refreshMap();
    });
    connect(m_canvas, &NormalsCanvas::pixelPicked, m_inspection, &Inspection::pickPixel);
    connect(m_mapView, &FrameImageView::pixelPicked, m_inspection, &Inspection::pickPixel);
    connect(m_mapView, &FrameImageView::pixelHovered, this, &NormalsView::showPixelValue);

    connect(m_inspection, &Inspection::frameChanged, this, [this] {
        m_geometryDirty = m_mapDirty = true;
        m_pixelNormals.reset();
        if (isVisible()) refreshGeometry();
    });
    connect(m_inspection, &Inspection::cursorChanged, this, [this] {
        m_mapDirty = true;
        if (!isVisible()) return;
        if (mapShown()) refreshMap();
        refreshExplanation();
    });
    // A picked pixel selects its triangle: the explanation's pixel follows from here too.
    connect(m_inspection, &Inspection::selectionChanged, this, [this] {
        if (isVisible() && !m_geometryDirty) refreshSelection();
    });
    connect(m_inspection, &Inspection::presentationChanged, this, [this] {
        m_canvas->setLineWidth(m_inspection->lineWidth());
        const QFont f = scaledFont(this, m_inspection->textScale(1.4));
        m_explanation->setFont(f);
        m_legend->setFont(f);
    });
    m_canvas->setLineWidth(m_inspection->lineWidth());
}

void NormalsView::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    // Beside the drawing when the view is wider than tall and both fit across it.
    const int across = m_tabs->minimumSizeHint().width() + m_words->minimumWidth() +
                       m_splitter->handleWidth() + m_splitter->x() * 2;
    const Qt::Orientation along =
        width() >= height() && width() >= across ? Qt::Horizontal : Qt::Vertical;
    if (m_splitter->orientation() != along) {
        m_splitter->setOrientation(along);
        m_splitMoved = false;
    }
    // Three fifths for the drawing, along the splitter, until its handle is moved by hand.
    if (!m_splitMoved) {
        const int length = (along == Qt::Horizontal ? event->size().width()
                                                    : event->size().height()) -
                           m_splitter->handleWidth();
        m_splitter->setSizes({length * 3 / 5, length - length * 3 / 5});
    }
}

void NormalsView::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    // The selection, the pixel picked and the cursor may have moved while hidden.
    if (m_geometryDirty)
        refreshGeometry();
    else
        refreshSelection();
    if (mapShown() && m_mapDirty) refreshMap();
}

bool NormalsView::mapShown() const {
    return m_tabs->currentIndex() == 1;
}

void NormalsView::setTriangleHairs(bool on) {
    m_triangleHairs->setChecked(on);
}

void NormalsView::setVertexHairs(bool on) {
    m_vertexHairs->setChecked(on);
}

void NormalsView::setOnlyVisibleHairs(bool on) {
    m_onlyVisible->setChecked(on);
}

void NormalsView::setWrongNormals(bool on) {
    m_wrong->setChecked(on);
}

bool NormalsView::wrongNormals() const {
    return m_wrong->isChecked();
}

bool NormalsView::onlyVisibleHairs() const {
    return m_onlyVisible->isChecked();
}

void NormalsView::showNormalMap(bool on) {
    m_tabs->setCurrentIndex(on ? 1 : 0);
}

const QImage& NormalsView::normalMap() {
    if (m_mapDirty) refreshMap();
    return m_map;
}

QString NormalsView::legendText() const {
    return m_legend->text();
}

QString NormalsView::explanationText() const {
    return m_explanation->toPlainText();
}

void NormalsView::refreshGeometry() {
    m_geometryDirty = false;
    m_model.rebuild(m_inspection->frame(), m_onlyVisible->isChecked(), m_wrong->isChecked());
    m_canvas->setPicture(&m_model.picture());
    refreshLegend();
    refreshSelection();
}

void NormalsView::refreshSelection() {
    m_model.select(m_inspection->frame(), m_inspection->selectedTriangle(), m_wrong->isChecked());
    m_canvas->update();
    refreshExplanation();
}

void NormalsView::refreshMap() {
    const auto& frame = m_inspection->frame();
    const rl::DepthTest* buffers = m_inspection->buffers();
    if (!frame || !buffers) {
        m_map = QImage();
    } else {
        if (!m_pixelNormals) m_pixelNormals = std::make_unique<PixelNormals>(frame);
        m_map = m_pixelNormals->image(*buffers);
    }
    m_mapDirty = false;
    m_mapView->setImage(m_map);
}

void NormalsView::refreshLegend() {
    const auto& frame = m_inspection->frame();
    if (!frame || !frame->projection) {
        m_legend->setText(tr("No frame yet."));
        return;
    }
    const NormalsPicture& p = m_model.picture();
    QStringList parts;
    QString front = swatch(NormalsCanvas::kFrontColour) + QLatin1Char(' ') +
                    tr("front faces %1").arg(p.meshTriangles - p.backFaces);
    if (p.culledFront > 0)
        front += QLatin1Char(' ') + tr("(%1 hidden, left out by culling)").arg(p.culledFront);
    QString back = swatch(NormalsCanvas::kBackColour) + QLatin1Char(' ') +
                   tr("back faces (n · pView &gt; 0) %1").arg(p.backFaces);
    if (p.culledBack > 0)
        back += QLatin1Char(' ') + tr("(%1 hidden, left out by culling)").arg(p.culledBack);
    parts << front << back;
    parts << swatch(NormalsCanvas::kInconsistentColour) + QLatin1Char(' ') +
                 tr("inconsistent winding: %1 triangles, %2 edges run the same way by two "
                    "triangles")
                     .arg(p.inconsistentTriangles)
                     .arg(p.inconsistentEdges);
    QString text = parts.join(QStringLiteral(" &nbsp; "));
    if (std::find(p.viewWinding.begin(), p.viewWinding.end(), -1) != p.viewWinding.end())
        text += QStringLiteral("<br>") +
                tr("%1% of the pixels seen are back faces: the surface is closed and its "
                   "normals point inward in view space (the course's [U; V; N] mirrors, so a "
                   "file wound counter-clockwise seen from outside turns over). Shading turns "
                   "every normal toward the viewer: the image does not change.")
                    .arg(p.coveredPixels > 0 ? (100 * p.backFacePixels) / p.coveredPixels : 0);
    if (p.normalsSkipped) {
        text += QStringLiteral("<br>") +
                tr("No normals: %1.")
                    .arg(QString::fromStdString(frame->normals ? frame->normals->skipReason
                                                               : std::string()));
    } else {
        text += QStringLiteral("<br>") + swatch(NormalsCanvas::kTriangleHairColour) +
                QLatin1Char(' ') + tr("triangle normals") + QStringLiteral(" &nbsp; ") +
                swatch(NormalsCanvas::kVertexHairColour) + QLatin1Char(' ') + tr("vertex normals") +
                QStringLiteral(" &nbsp; ") +
                tr("length L = %1 (%2% of the mesh's size)")
                    .arg(number(p.hairLength, 3))
                    .arg(number(p.hairFraction * 100.0, 2));
        if (m_wrong->isChecked())
            text += QStringLiteral(" &nbsp; ") + swatch(NormalsCanvas::kWrongHairColour) +
                    QLatin1Char(' ') + tr("triangle normals carried by M itself (wrong)");
        if (m_onlyVisible->isChecked())
            text += QStringLiteral(", ") +
                    tr("on the %1 triangles seen and their corners").arg(p.hairTriangles);
        if (p.triangleHairStep > 1 || p.vertexHairStep > 1)
            text += QStringLiteral("<br>") +
                    tr("Large mesh: one triangle normal in %1 and one vertex normal in %2 are "
                       "drawn; the selected triangle's always.")
                        .arg(p.triangleHairStep)
                        .arg(p.vertexHairStep);
    }
    if (p.wireStep > 1)
        text += QStringLiteral("<br>") +
                tr("One triangle in %1 of the wireframe is drawn.").arg(p.wireStep);
    m_legend->setText(text);
}

QString NormalsView::wrongNormalHtml(const rl::FrameTrace& frame, std::uint32_t d,
                                     std::uint32_t t) const {
    const rl::Draw& draw = frame.scene->draws[d];
    const rl::dmat4& a = frame.view->viewFromModel[d];
    const rl::CarriedNormal n = rl::carriedTriangleNormal(a, *draw.mesh, t);
    if (n.nModel == rl::dvec3(0.0)) return {};
    const auto unit = [](const rl::dvec3& v) {
        const double l = glm::length(v);
        return l > 0.0 ? v / l : rl::dvec3(0.0);
    };
    const rl::dvec3 e1 = unit(n.edges[0]), e2 = unit(n.edges[1]);
    const double between =
        std::acos(std::clamp(glm::dot(n.right, n.wrong), -1.0, 1.0)) * 180.0 / std::numbers::pi;
    QString html = tr("<p><b>Normals by M, right and wrong</b>: A = viewFromModel = "
                      "viewFromWorld · M(t) · worldFromModel (M: the animation matrix, the "
                      "identity when the animation is off). The model-space normal n = %1, "
                      "det A = %2; the carried edges, made unit: e1 = A (P2 − P1) / |…| = %3, "
                      "e2 = A (P3 − P1) / |…| = %4.<br>")
                       .arg(vector(n.nModel, 'f', 4), number(glm::determinant(rl::dmat3(a)), 4),
                            vector(e1, 'f', 4), vector(e2, 'f', 4));
    html += tr("Right: A<sup>−T</sup> n, normalised = <b>%1</b>; its dots with e1 and e2 are %2 "
               "and %3: perpendicular to the surface.<br>")
                .arg(vector(n.right, 'f', 4), number(glm::dot(n.right, e1), 3, 'f'),
                     number(glm::dot(n.right, e2), 3, 'f'));
    html += tr("Wrong: A n, normalised = <b>%1</b>; its dots with e1 and e2 are %2 and %3: "
               "%4° off the surface's normal.</p>")
                .arg(vector(n.wrong, 'f', 4), number(glm::dot(n.wrong, e1), 3, 'f'),
                     number(glm::dot(n.wrong, e2), 3, 'f'), number(between, 4));
    if (between < 0.01)
        html +=
            tr("<p>Here both agree: A has no non-uniform scale. Set a scale such as "
               "(2, 1, 1) in the Animation panel to see them part.</p>");
    return html;
}

void NormalsView::refreshExplanation() {
    const auto& frame = m_inspection->frame();
    if (!frame || !frame->projection) {
        m_explanation->setHtml(tr("<p>No frame yet.</p>"));
        m_figures->setText(QString());
        return;
    }
    QString html =
        tr("<p><b>Stage 3, normals</b>, in view space: each triangle's normal "
           "n = (P2 − P1) × (P3 − P1) / |(P2 − P1) × (P3 − P1)|, and each vertex's "
           "normal the normalised sum of the normals of the triangles around it. "
           "A triangle faces away from the camera (at the origin) when n · P1 &gt; 0; "
           "the course turns such normals toward the viewer when it shades.</p>");
    const bool skipped = m_model.picture().normalsSkipped;
    if (skipped)
        html += tr("<p>Skipped for this frame: %1.</p>")
                    .arg(QString::fromStdString(frame->normals ? frame->normals->skipReason
                                                               : std::string())
                             .toHtmlEscaped());

    const std::optional<std::uint32_t> selected = m_inspection->selectedTriangle();
    QString figures;  // the selected triangle's normal, large
    if (selected && *selected < frame->projection->triangles.size()) {
        const rl::ScreenTriangle& tri = frame->projection->triangles[*selected];
        const rl::Draw& draw = frame->scene->draws[tri.draw];
        const rl::DrawProjection& proj = frame->projection->draws[tri.draw];
        const auto& c = draw.mesh->triangles[tri.source];
        const rl::dvec3 p1 = rl::cartesian(proj.pView[c[0]]), p2 = rl::cartesian(proj.pView[c[1]]),
                        p3 = rl::cartesian(proj.pView[c[2]]);
        const rl::dvec3 cross = glm::cross(p2 - p1, p3 - p1);
        const double length = glm::length(cross);
        html += tr("<p><b>Triangle %1</b> (vertices %2, %3, %4):<br>P1 = %5, P2 = %6, P3 = %7<br>"
                   "(P2 − P1) × (P3 − P1) = %8 × %9")
                    .arg(tri.source + 1)
                    .arg(c[0] + 1)
                    .arg(c[1] + 1)
                    .arg(c[2] + 1)
                    .arg(vector(p1), vector(p2), vector(p3), vector(p2 - p1), vector(p3 - p1));
        html += tr(" = %1, length %2<br>").arg(vector(cross), number(length));
        if (length > 0.0) {
            const rl::dvec3 n = cross / length;
            const double facing = glm::dot(n, p1);
            figures = QStringLiteral("n = %1  n · P1 = %2").arg(vector(n, 'f', 4), number(facing, 4));
            html += tr("n = <b>%1</b>; n · P1 = %2: %3</p>")
                        .arg(vector(n, 'f', 4), number(facing, 4),
                             facing > 0.0 ? tr("a back face, drawn in red") : tr("a front face"));
        } else {
            html += tr("a degenerate triangle: no normal.</p>");
        }
        if (m_model.inconsistent(tri.draw, tri.source))
            html +=
                tr("<p>It runs an edge in the same direction as a neighbour does: the two "
                   "are wound inconsistently (magenta), and one of their normals points "
                   "the wrong way.</p>");
        if (m_wrong->isChecked() && frame->view)
            html += wrongNormalHtml(*frame, tri.draw, tri.source);
        if (!skipped) {
            const rl::DrawNormals& normals = frame->normals->draws[tri.draw];
            html += tr("<p>Vertex normals: N1 = %1 (vertex %2), N2 = %3 (vertex %4), N3 = %5 "
                       "(vertex %6)</p>")
                        .arg(vector(normals.vertex[c[0]], 'f', 4), QString::number(c[0] + 1),
                             vector(normals.vertex[c[1]], 'f', 4), QString::number(c[1] + 1),
                             vector(normals.vertex[c[2]], 'f', 4), QString::number(c[2] + 1));
        }
    } else {
        html +=
            tr("<p>Pick a pixel (here or in any image) to select its triangle and see its "
               "normal worked out.</p>");
    }

    // The picked pixel's normal, as the normal map shows it.
    const QPoint pixel = m_inspection->pickedPixel();
    const rl::DepthTest* buffers = m_inspection->buffers();
    if (pixel.x() >= 0 && buffers) {
        if (!m_pixelNormals) m_pixelNormals = std::make_unique<PixelNormals>(frame);
        const PixelNormal n = m_pixelNormals->at(*buffers, pixel.x(), pixel.y());
        html += tr("<p><b>Pixel (%1, %2)</b>: ").arg(pixel.x()).arg(pixel.y());
        if (!n.covered) {
            html += tr("no triangle holds it at the cursor (black in the normal map).</p>");
        } else if (n.n == rl::vec3(0.0f)) {
            html += tr("no normal: %1 (grey in the normal map).</p>").arg(n.none.toHtmlEscaped());
        } else {
            if (n.flat)
                html += tr("the triangle's normal (flat) %1").arg(vector(n.interpolated, 'f', 4));
            else
                html += tr("N = α N1 + β N2 + γ N3 with (α, β, γ) = %1: %2, normalised %3")
                            .arg(vector(n.weights, 'f', 4), vector(n.interpolated, 'f', 4),
                                 vector(n.flipped ? -n.n : n.n, 'f', 4));
            if (n.flipped)
                html += tr("; V · N &lt; 0, turned toward the viewer: <b>%1</b>")
                            .arg(vector(n.n, 'f', 4));
            const QRgb rgb = normalColour(n.n);
            html += tr(". Colour (N + 1) / 2 = (%1, %2, %3).</p>")
                        .arg(qRed(rgb))
                        .arg(qGreen(rgb))
                        .arg(qBlue(rgb));
        }
    }
    m_explanation->setHtml(html);
    const NormalsPicture& p = m_model.picture();
    if (figures.isEmpty() && !p.normalsSkipped)
        figures = tr("%1 front faces · %2 back faces")
                      .arg(p.meshTriangles - p.backFaces)
                      .arg(p.backFaces);
    m_figures->setText(figures);
}

void NormalsView::showPixelValue(QPoint pixel) {
    const rl::DepthTest* buffers = m_inspection->buffers();
    const auto& frame = m_inspection->frame();
    if (pixel.x() < 0 || !buffers || !frame) {
        m_pixelValue->clear();
        return;
    }
    if (!m_pixelNormals) m_pixelNormals = std::make_unique<PixelNormals>(frame);
    const PixelNormal n = m_pixelNormals->at(*buffers, pixel.x(), pixel.y());
    if (!n.covered) {
        m_pixelValue->setText(tr("x %1, y %2: no triangle").arg(pixel.x()).arg(pixel.y()));
        return;
    }
    const QRgb rgb = normalColour(n.n);
    m_pixelValue->setText(tr("x %1, y %2: triangle %3, N = %4, colour (%5, %6, %7)")
                              .arg(pixel.x())
                              .arg(pixel.y())
                              .arg(frame->projection->triangles[n.triangle].source + 1)
                              .arg(vector(n.n, 'f', 4))
                              .arg(qRed(rgb))
                              .arg(qGreen(rgb))
                              .arg(qBlue(rgb)));
}

}  // namespace rasterlab
