#include "edit_panel.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QScrollArea>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <algorithm>
#include <iterator>

#include "app/documents/examples.h"
#include "app/window/scene_edits.h"
#include "pipeline/io/course_writers.h"
#include "views/messages/pipeline_messages.h"
#include "views/wrapping_check_box.h"

namespace rasterlab {

namespace {

// A spin box for one number of a course file: '.' as the decimal separator whatever the
// system's locale (course files use it), six decimals kept but trailing zeros not shown
// ("0.667", not "0.667000"), Ctrl+Z and Ctrl+Y left to the panel's undo rather than to the
// line edit's own, and the wheel only when it has the focus (so that scrolling the panel
// does not change values on the way).
class NumberBox : public QDoubleSpinBox {
public:
    explicit NumberBox(QWidget* parent = nullptr) : QDoubleSpinBox(parent) {
        QLocale c = QLocale::c();
        c.setNumberOptions(QLocale::OmitGroupSeparator);
        setLocale(c);
        setDecimals(6);
        setKeyboardTracking(true);
        setAccelerated(true);
        setFocusPolicy(Qt::StrongFocus);
        setAlignment(Qt::AlignRight);
    }

    QString textFromValue(double value) const override {
        QString text = locale().toString(value, 'f', decimals());
        if (text.contains(QLatin1Char('.'))) {
            while (text.endsWith(QLatin1Char('0'))) text.chop(1);
            if (text.endsWith(QLatin1Char('.'))) text.chop(1);
        }
        if (text == QLatin1String("-0")) text = QStringLiteral("0");
        return text;
    }

    // As wide as a typical number ("-000.00"), not as the range's ends (-1000000): a dock of
    // 350 pixels holds three in a row; longer numbers scroll, or show when the dock widens.
    QSize sizeHint() const override { return narrowed(QDoubleSpinBox::sizeHint()); }
    QSize minimumSizeHint() const override { return narrowed(QDoubleSpinBox::minimumSizeHint()); }

protected:
    bool event(QEvent* event) override {
        if (event->type() == QEvent::ShortcutOverride) {
            auto* key = static_cast<QKeyEvent*>(event);
            if (key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo)) {
                event->ignore();  // not the line edit's: the shortcut of the undo action
                return true;
            }
        }
        return QDoubleSpinBox::event(event);
    }

    void wheelEvent(QWheelEvent* event) override {
        if (!hasFocus()) {
            event->ignore();
            return;
        }
        QDoubleSpinBox::wheelEvent(event);
    }

private:
    QSize narrowed(QSize hint) const {
        const QFontMetrics metrics = fontMetrics();
        const int longest = std::max(metrics.horizontalAdvance(textFromValue(minimum())),
                                     metrics.horizontalAdvance(textFromValue(maximum())));
        const int typical = metrics.horizontalAdvance(QStringLiteral("-000.00"));
        if (longest > typical) hint.rwidth() -= longest - typical;
        return hint;
    }
};

// The course's symbol of each field ("" for the shading model).
const char* symbolOf(SceneDocument::Field field) {
    static const char* const kSymbols[] = {
        "C",   "N",  "V",  "d",  "hx", "hy", "Pl", "Il", "directional", "att",   "spot", "cutoff",
        "exp", "Ia", "ka", "kd", "Od", "ks", "n",  "Ke", "two_sided",   "blinn", ""};
    static_assert(std::size(kSymbols) == std::size_t(SceneDocument::Field::Shading) + 1);
    return kSymbols[int(field)];
}

bool isColour(SceneDocument::Field field) {
    return field == SceneDocument::Field::LightIntensity ||
           field == SceneDocument::Field::Ambient || field == SceneDocument::Field::Kd ||
           field == SceneDocument::Field::Od || field == SceneDocument::Field::Emission;
}

// "x", "y", "z", "r", "g", "b", or the attenuation's "c", "l", "q" (kc, kl, kq).
QLatin1Char componentLetter(SceneDocument::Field field, int component) {
    if (field == SceneDocument::Field::LightAttenuation) return QLatin1Char("clq"[component]);
    return QLatin1Char((isColour(field) ? "rgb" : "xyz")[component]);
}

// The value the document will hold: the lighting's colours and coefficients are floats.
SceneDocument::Numbers storedAs(SceneDocument::Field field, SceneDocument::Numbers numbers) {
    const auto part = SceneDocument::partOf(field);
    if (part == SceneDocument::Part::Lighting && field != SceneDocument::Field::LightPosition &&
        field != SceneDocument::Field::LightSpotDirection)
        for (double& n : numbers) n = double(float(n));
    return numbers;
}

// Shows a value in a spin box without a valueChanged signal, and only when the box shows
// another value: a box being typed in keeps its text ("2.0" on the way to "2.05" is not
// rewritten to "2" when the window refreshes the panel after each change).
void showValue(QDoubleSpinBox* box, double value) {
    const double shown = QString::number(value, 'f', box->decimals()).toDouble();
    if (box->value() == shown) return;
    const QSignalBlocker blocker(box);
    box->setValue(value);
}

QLabel* symbolLabel(const QString& symbol, const QString& tip) {
    auto* label = new QLabel(symbol);
    label->setToolTip(tip);
    label->setTextFormat(Qt::RichText);
    return label;
}

// "x  y  z" or "R  G  B" above three columns of spin boxes.
void addHeader(QGridLayout* grid, int row, const QStringList& names) {
    for (int k = 0; k < names.size(); ++k) {
        auto* label = new QLabel(names[k]);
        label->setAlignment(Qt::AlignCenter);
        label->setForegroundRole(QPalette::PlaceholderText);
        grid->addWidget(label, row, k + 1);
    }
}

}  // namespace

EditPanel::EditPanel(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    setObjectName(QStringLiteral("editPanel"));
    m_clock.start();
    m_stack = new QUndoStack(this);
    m_stack->setObjectName(QStringLiteral("editUndoStack"));

    auto* scroll = new QScrollArea(this);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    m_content = buildContent();
    scroll->setWidget(m_content);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(scroll);

    createActions();
    refresh();
}

QDoubleSpinBox* EditPanel::addBox(Field field, int component, double minimum, double maximum,
                                  double step, bool adaptive) {
    auto* box = new NumberBox;
    box->setRange(minimum, maximum);
    box->setSingleStep(step);
    if (adaptive) box->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
    // "edit_C_x", "edit_kd_r", "edit_n".
    QString name = QStringLiteral("edit_") + QLatin1String(symbolOf(field));
    if (SceneDocument::componentCount(field) == 3) {
        name += QLatin1Char('_');
        name += componentLetter(field, component);
    }
    box->setObjectName(name);
    m_boxes.push_back({field, component, box});
    connect(box, &QDoubleSpinBox::valueChanged, this, [this, field, component, box](double value) {
        m_editing = box;
        onBoxChanged(field, component, value);
        m_editing = nullptr;
    });
    return box;
}

QWidget* EditPanel::buildContent() {
    auto* content = new QWidget;
    auto* groups = new QVBoxLayout(content);

    m_fileLabel = new QLabel;
    m_fileLabel->setObjectName(QStringLiteral("editFiles"));
    m_fileLabel->setWordWrap(true);
    m_fileLabel->setTextFormat(Qt::RichText);
    groups->addWidget(m_fileLabel);

    m_kdLink = new QToolButton;
    m_kdLink->setObjectName(QStringLiteral("editKdLink"));
    m_kdLink->setText(QStringLiteral("="));
    m_kdLink->setCheckable(true);
    m_kdLink->setAutoRaise(true);
    m_kdLink->setToolTip(
        tr("One kd for the three channels (the UFPE files have one number): changing one "
           "changes all three"));

    // One group per part of the lecture's formula; a row per symbol, its numbers in columns
    // that line up from group to group (the symbols' column, and kd's link button's, are as
    // wide in every group).
    const int symbolWidth = fontMetrics().horizontalAdvance(QStringLiteral("hx"));
    const int linkWidth = m_kdLink->sizeHint().width();
    const auto group = [groups, symbolWidth, linkWidth](const QString& title) {
        auto* box = new QGroupBox(title);
        auto* grid = new QGridLayout(box);
        grid->setHorizontalSpacing(4);
        grid->setVerticalSpacing(3);
        grid->setColumnMinimumWidth(0, symbolWidth);
        grid->setColumnMinimumWidth(4, linkWidth);
        grid->setColumnStretch(1, 1);
        grid->setColumnStretch(2, 1);
        grid->setColumnStretch(3, 1);
        groups->addWidget(box);
        return grid;
    };
    const auto vectorRow = [this](QGridLayout* grid, int row, Field field, const QString& symbol,
                                  const QString& tip, double minimum, double maximum, double step) {
        grid->addWidget(symbolLabel(symbol, tip), row, 0);
        for (int k = 0; k < 3; ++k) {
            QDoubleSpinBox* box = addBox(field, k, minimum, maximum, step);
            box->setToolTip(tip);
            grid->addWidget(box, row, k + 1);
        }
    };
    const auto scalarRow = [this](QGridLayout* grid, int row, int column, Field field,
                                  const QString& symbol, const QString& tip, double minimum,
                                  double maximum, double step, bool adaptive = false) {
        QLabel* label = symbolLabel(symbol, tip);
        if (column > 1) label->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        grid->addWidget(label, row, column - 1);
        QDoubleSpinBox* box = addBox(field, 0, minimum, maximum, step, adaptive);
        box->setToolTip(tip);
        grid->addWidget(box, row, column);
    };
    const QStringList xyz = {QStringLiteral("x"), QStringLiteral("y"), QStringLiteral("z")};
    const QStringList rgb = {tr("R"), tr("G"), tr("B")};

    // Camera: C, N, V; d, hx, hy (adaptive steps: about 1% of the value).
    QGridLayout* camera = group(tr("Camera"));
    addHeader(camera, 0, xyz);
    vectorRow(camera, 1, Field::C, QStringLiteral("C"), tr("C: the camera's position (world)"),
              -1e6, 1e6, 10.0);
    vectorRow(camera, 2, Field::N, QStringLiteral("N"),
              tr("N: the view direction (normalised by the camera basis)"), -1e4, 1e4, 0.05);
    vectorRow(camera, 3, Field::V, QStringLiteral("V"),
              tr("V: the up vector (made orthogonal to N by Gram-Schmidt)"), -1e4, 1e4, 0.05);
    scalarRow(camera, 4, 1, Field::D, QStringLiteral("d"),
              tr("d: the distance from C to the projection plane"), 1e-6, 1e6, 0.1, true);
    scalarRow(camera, 5, 1, Field::Hx, QStringLiteral("hx"),
              tr("hx: half the width of the window on the projection plane"), 1e-6, 1e6, 0.1, true);
    scalarRow(camera, 5, 3, Field::Hy, QStringLiteral("hy"),
              tr("hy: half the height of the window on the projection plane"), 1e-6, 1e6, 0.1,
              true);

    // Light: Pl, Il of the light chosen; directional or not; attenuation; spot.
    QGridLayout* light = group(tr("Light"));
    m_lightSelector = new QComboBox;
    m_lightSelector->setObjectName(QStringLiteral("editLightSelector"));
    m_lightSelector->setToolTip(tr("The light whose values are shown"));
    light->addWidget(m_lightSelector, 0, 0, 1, 3);
    connect(m_lightSelector, &QComboBox::currentIndexChanged, this, [this] { showLight(); });
    m_addLight = new QToolButton;
    m_addLight->setObjectName(QStringLiteral("editAddLight"));
    m_addLight->setText(QStringLiteral("+"));
    m_addLight->setToolTip(tr("Add a light: a copy of the light shown"));
    connect(m_addLight, &QToolButton::clicked, this, &EditPanel::addLight);
    m_removeLight = new QToolButton;
    m_removeLight->setObjectName(QStringLiteral("editRemoveLight"));
    m_removeLight->setText(QStringLiteral("\u2212"));
    m_removeLight->setToolTip(tr("Remove the light shown (the scene keeps one light at least)"));
    connect(m_removeLight, &QToolButton::clicked, this, &EditPanel::removeLight);
    auto* buttons = new QHBoxLayout;
    buttons->setSpacing(2);
    buttons->addWidget(m_addLight);
    buttons->addWidget(m_removeLight);
    light->addLayout(buttons, 0, 3, 1, 2);
    addHeader(light, 1, xyz);
    vectorRow(light, 2, Field::LightPosition, QStringLiteral("P<sub>l</sub>"),
              tr("Pl: the light's position (world), or the direction toward it for a directional "
                 "light"),
              -1e6, 1e6, 10.0);
    addCheck(light, 3, Field::LightDirectional, tr("Directional (w = 0)"),
             tr("A directional light is infinitely far: L is the same everywhere and it is not "
                "attenuated"));
    addHeader(light, 4, rgb);
    vectorRow(light, 5, Field::LightIntensity, QStringLiteral("I<sub>l</sub>"),
              tr("Il: the light's colour, 0 to 255 per channel"), 0.0, 1000.0, 5.0);
    addHeader(light, 6,
              {QStringLiteral("k<sub>c</sub>"), QStringLiteral("k<sub>l</sub>"),
               QStringLiteral("k<sub>q</sub>")});
    vectorRow(light, 7, Field::LightAttenuation, tr("att"),
              tr("Attenuation: the light's diffuse and specular terms are divided by kc + kl d + "
                 "kq d\u00B2, d its distance to the point (1 0 0: none)"),
              0.0, 1e6, 0.01);
    addCheck(light, 8, Field::LightSpotCutoff, tr("Spot"),
             tr("A spot lights only the points within its cutoff angle of its direction"));
    addHeader(light, 9, xyz);
    vectorRow(light, 10, Field::LightSpotDirection, QStringLiteral("D"),
              tr("D: the direction the spot points to (world)"), -1e6, 1e6, 0.1);
    scalarRow(light, 11, 1, Field::LightSpotCutoff, tr("cut"),
              tr("The spot's cutoff angle, 0 to 90 degrees"), 0.0, 90.0, 1.0);
    scalarRow(light, 11, 3, Field::LightSpotExponent, tr("exp"),
              tr("The spot's exponent: its light falls off as (-L.D)^exp toward the edge"), 0.0,
              128.0, 1.0);

    // Ambient: Ia, ka.
    QGridLayout* ambient = group(tr("Ambient"));
    addHeader(ambient, 0, rgb);
    vectorRow(ambient, 1, Field::Ambient, QStringLiteral("I<sub>a</sub>"),
              tr("Ia: the ambient light's colour, 0 to 255 per channel"), 0.0, 1000.0, 5.0);
    scalarRow(ambient, 2, 1, Field::Ka, QStringLiteral("k<sub>a</sub>"),
              tr("ka: the ambient coefficient, 0 to 1"), 0.0, 1.0, 0.05);

    // Material: kd (linked or per channel), Od, ks, n.
    QGridLayout* material = group(tr("Material"));
    addHeader(material, 0, rgb);
    vectorRow(material, 1, Field::Kd, QStringLiteral("k<sub>d</sub>"),
              tr("kd: the diffuse coefficient of each channel, 0 to 1"), 0.0, 1.0, 0.05);
    material->addWidget(m_kdLink, 1, 4);
    vectorRow(material, 2, Field::Od, QStringLiteral("O<sub>d</sub>"),
              tr("Od: the object's diffuse colour, 0 to 1 per channel"), 0.0, 1.0, 0.05);
    vectorRow(material, 4, Field::Emission, QStringLiteral("K<sub>e</sub>"),
              tr("Ke: the light the object gives off by itself, 0 to 255 per channel (added to "
                 "every lit point)"),
              0.0, 1000.0, 5.0);
    scalarRow(material, 3, 1, Field::Ks, QStringLiteral("k<sub>s</sub>"),
              tr("ks: the specular coefficient, 0 to 1"), 0.0, 1.0, 0.05);
    scalarRow(material, 3, 3, Field::Shininess, QStringLiteral("n"),
              tr("n: the specular exponent (larger: a smaller, sharper highlight)"), 0.0, 10000.0,
              1.0);

    // Shading: where the formula is evaluated.
    QGridLayout* shading = group(tr("Shading"));
    m_shading = new QComboBox;
    m_shading->setObjectName(QStringLiteral("editShading"));
    m_shading->addItem(tr("Phong (per pixel)"), int(rl::ShadingModel::Phong));
    m_shading->addItem(tr("Gouraud (per vertex)"), int(rl::ShadingModel::Gouraud));
    m_shading->addItem(tr("Flat (per triangle)"), int(rl::ShadingModel::Flat));
    m_shading->addItem(tr("Painter's algorithm (flat, no depth test)"),
                       int(rl::ShadingModel::Painter));
    // As wide as the grid, not as the longest model's name (the painter's, in Portuguese
    // wider than the dock): a longer name is elided, whole in the list and the tooltip.
    m_shading->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_shading->setMinimumContentsLength(12);
    for (int k = 0; k < m_shading->count(); ++k)
        m_shading->setItemData(k, m_shading->itemText(k), Qt::ToolTipRole);
    shading->addWidget(m_shading, 0, 0, 1, 4);
    connect(m_shading, &QComboBox::currentIndexChanged, this, &EditPanel::onShadingChanged);
    addCheck(shading, 1, Field::TwoSided, tr("Two-sided lighting"),
             tr("On (the course's rule): where V.N < 0 the normal is turned round, so the back "
                "of a surface is lit like its front. Off: one-sided, the back keeps a normal "
                "pointing away"));
    addCheck(shading, 2, Field::BlinnPhong, tr("Blinn-Phong highlight"),
             tr("The highlight with the half vector H = (L + V)/|L + V| instead of Phong's "
                "reflection R: (N.H)^n instead of (R.V)^n"));

    groups->addStretch(1);
    return content;
}

void EditPanel::addCheck(QGridLayout* grid, int row, Field field, const QString& text,
                         const QString& tip) {
    auto* check = new WrappingCheckBox(text);
    check->setObjectName(QStringLiteral("edit_check_") + QLatin1String(symbolOf(field)));
    check->setToolTip(tip);
    grid->addWidget(check, row, 0, 1, 5);
    m_checks.emplace_back(field, check);
    connect(check, &QCheckBox::toggled, this,
            [this, field](bool checked) { onCheckToggled(field, checked); });
}

QCheckBox* EditPanel::checkBox(Field field) const {
    for (const auto& [f, check] : m_checks)
        if (f == field) return check;
    return nullptr;
}

void EditPanel::onCheckToggled(Field field, bool checked) {
    const std::size_t light = SceneDocument::isLightField(field) ? currentLight() : 0;
    const SceneDocument::Numbers before = m_document->value(field, light);
    SceneDocument::Numbers after = before;
    if (field == Field::LightSpotCutoff)
        after[0] = checked ? 30.0 : 180.0;
    else
        after[0] = checked ? 1.0 : 0.0;
    if (after == before) return;
    push(field, light, 0, before, after);
}

void EditPanel::showChecks(bool lightOnly) {
    const std::size_t light = currentLight();
    for (const auto& [field, check] : m_checks) {
        if (lightOnly && !SceneDocument::isLightField(field)) continue;
        const double v =
            m_document->value(field, SceneDocument::isLightField(field) ? light : 0)[0];
        const QSignalBlocker blocker(check);
        check->setChecked(field == Field::LightSpotCutoff ? v != 180.0 : v != 0.0);
    }
    // What does not apply to the light shown is greyed: a spot's values when it is no spot,
    // the attenuation of a directional light.
    const bool lights = !m_document->parts().lighting.lights.empty();
    const bool spot = checkBox(Field::LightSpotCutoff)->isChecked();
    const bool directional = checkBox(Field::LightDirectional)->isChecked();
    for (const Box& b : m_boxes) {
        if (b.field == Field::LightSpotDirection || b.field == Field::LightSpotCutoff ||
            b.field == Field::LightSpotExponent)
            b.box->setEnabled(lights && spot);
        else if (b.field == Field::LightAttenuation)
            b.box->setEnabled(lights && !directional);
    }
}

void EditPanel::addLight() {
    const auto& lights = m_document->parts().lighting.lights;
    if (!isEditable() || lights.empty() || lights.size() >= rl::kMaxKeyValueLights) return;
    const std::size_t index = lights.size();
    pushLightList(true, index, lights[std::min(currentLight(), index - 1)],
                  tr("Add light %1").arg(index + 1));
}

void EditPanel::removeLight() {
    const auto& lights = m_document->parts().lighting.lights;
    const std::size_t index = currentLight();
    if (!isEditable() || lights.size() < 2 || index >= lights.size()) return;
    pushLightList(false, index, lights[index], tr("Remove light %1").arg(index + 1));
}

void EditPanel::pushLightList(bool adding, std::size_t index, const rl::Light& light,
                              const QString& text) {
    ++m_session;
    m_stack->push(new LightListEdit(
        adding, index, light,
        [this](bool insert, std::size_t i, const rl::Light& l) { applyLightList(insert, i, l); },
        text));
}

void EditPanel::applyLightList(bool insert, std::size_t index, const rl::Light& light) {
    if (!m_pushing) ++m_session;
    if (insert)
        m_document->insertLight(index, light);
    else
        m_document->takeLight(index);
    const std::size_t count = m_document->parts().lighting.lights.size();
    refresh();
    setCurrentLight(std::min(index, count - 1));
    emit sceneEdited();
}

void EditPanel::createActions() {
    m_undoAction = m_stack->createUndoAction(this, tr("&Undo"));
    m_undoAction->setObjectName(QStringLiteral("editUndoAction"));
    m_undoAction->setShortcuts(QKeySequence::Undo);
    m_redoAction = m_stack->createRedoAction(this, tr("&Redo"));
    m_redoAction->setObjectName(QStringLiteral("editRedoAction"));
    m_redoAction->setShortcuts(QKeySequence::Redo);

    m_saveAction = new QAction(tr("&Save Camera and Lighting"), this);
    m_saveAction->setObjectName(QStringLiteral("editSaveAction"));
    m_saveAction->setShortcuts(QKeySequence::Save);
    m_saveAction->setToolTip(tr("Write the edited camera and lighting to their files"));
    connect(m_saveAction, &QAction::triggered, this, [this] { save(window()); });

    // Disabled with the Save As action, whose submenu they are.
    auto* saveAsMenu = new QMenu(this);
    QAction* camera =
        saveAsMenu->addAction(tr("&Camera..."), this, [this] { saveAs(Part::Camera, window()); });
    camera->setObjectName(QStringLiteral("editSaveCameraAsAction"));
    QAction* lighting = saveAsMenu->addAction(tr("&Lighting..."), this,
                                              [this] { saveAs(Part::Lighting, window()); });
    lighting->setObjectName(QStringLiteral("editSaveLightingAsAction"));
    m_saveAsAction = new QAction(tr("Save &As"), this);
    m_saveAsAction->setObjectName(QStringLiteral("editSaveAsAction"));
    m_saveAsAction->setMenu(saveAsMenu);

    // Shortcuts where the panel is, also in a floating dock.
    addAction(m_undoAction);
    addAction(m_redoAction);
    addAction(m_saveAction);
}

QDoubleSpinBox* EditPanel::spinBox(Field field, int component) const {
    for (const Box& b : m_boxes)
        if (b.field == field && b.component == component) return b.box;
    return nullptr;
}

std::size_t EditPanel::currentLight() const {
    return std::size_t(std::max(0, m_lightSelector->currentIndex()));
}

void EditPanel::setCurrentLight(std::size_t light) {
    if (light < std::size_t(m_lightSelector->count())) m_lightSelector->setCurrentIndex(int(light));
}

void EditPanel::refresh() {
    if (m_document->partsReplaced() != m_seenReplaced) {
        // A file replaced the camera or lighting: the steps were about other values. kd is
        // linked when its channels are equal (a UFPE file's one number).
        m_seenReplaced = m_document->partsReplaced();
        m_stack->clear();
        ++m_session;
        const rl::vec3 kd = m_document->parts().lighting.material.kd;
        m_kdLink->setChecked(kd.r == kd.g && kd.g == kd.b);
    }
    // A command file's scene has no course camera or lighting: the last course scene's
    // values would read as this one's. The label saying so stays, readable.
    const bool commandFile = m_document->showsCommandFile();
    m_content->setEnabled(isEditable() || commandFile);
    for (QGroupBox* box : m_content->findChildren<QGroupBox*>(Qt::FindDirectChildrenOnly)) {
        box->setHidden(commandFile);
        box->setEnabled(isEditable());
    }

    const std::size_t lights = m_document->parts().lighting.lights.size();
    const std::size_t shown = std::min(currentLight(), lights > 0 ? lights - 1 : 0);
    {
        const QSignalBlocker blocker(m_lightSelector);
        m_lightSelector->clear();
        for (std::size_t k = 0; k < lights; ++k)
            m_lightSelector->addItem(tr("Light %1 of %2").arg(k + 1).arg(lights));
        m_lightSelector->setCurrentIndex(int(shown));
    }
    m_addLight->setEnabled(lights > 0 && lights < rl::kMaxKeyValueLights);
    m_removeLight->setEnabled(lights > 1);
    for (const Box& b : m_boxes) {
        b.box->setEnabled(!SceneDocument::isLightField(b.field) || lights > 0);
        showBox(b);
    }
    showChecks(false);
    showShading();
    m_saveAsAction->setEnabled(isEditable());
    updateModified();
}

bool EditPanel::isEditable() const {
    return m_document->isLoaded() && !m_document->showsCommandFile();
}

void EditPanel::showBox(const Box& b) {
    showValue(b.box, m_document->value(b.field, currentLight())[std::size_t(b.component)]);
}

void EditPanel::showShading() {
    const QSignalBlocker blocker(m_shading);
    m_shading->setCurrentIndex(m_shading->findData(int(m_document->settings().shading)));
    m_shading->setToolTip(m_shading->currentText());
}

void EditPanel::showLight() {
    for (const Box& b : m_boxes)
        if (SceneDocument::isLightField(b.field)) showBox(b);
    showChecks(true);
}

void EditPanel::showField(Field field) {
    if (field == Field::Shading) {
        showShading();
        return;
    }
    for (const Box& b : m_boxes)
        if (b.field == field && b.box != m_editing) showBox(b);  // not under the user's fingers
    showChecks(false);
}

void EditPanel::onBoxChanged(Field field, int component, double value) {
    const std::size_t light = SceneDocument::isLightField(field) ? currentLight() : 0;
    const SceneDocument::Numbers before = m_document->value(field, light);
    SceneDocument::Numbers after = before;
    int source = component;
    if (field == Field::Kd && m_kdLink->isChecked()) {
        after = {value, value, value};
        source = -1;
    } else {
        after[std::size_t(component)] = value;
    }
    after = storedAs(field, after);
    if (after == before) return;
    push(field, light, source, before, after);
}

void EditPanel::onShadingChanged(int index) {
    m_shading->setToolTip(m_shading->currentText());
    const SceneDocument::Numbers before = m_document->value(Field::Shading);
    const SceneDocument::Numbers after = {double(m_shading->itemData(index).toInt()), 0.0, 0.0};
    if (after != before) push(Field::Shading, 0, 0, before, after);
}

void EditPanel::push(Field field, std::size_t light, int source,
                     const SceneDocument::Numbers& before, const SceneDocument::Numbers& after) {
    FieldEdit::Change change;
    change.field = field;
    change.light = light;
    change.source = source;
    change.before = before;
    change.after = after;
    change.atMs = m_clock.elapsed();
    change.session = m_session;
    auto apply = [this](Field f, std::size_t l, const SceneDocument::Numbers& v) {
        this->apply(f, l, v);
    };
    m_pushing = true;
    m_stack->push(new FieldEdit(change, m_mergeIntervalMs, apply,
                                tr("Change %1").arg(fieldName(field, source, light))));
    m_pushing = false;
}

void EditPanel::setValues(const std::vector<Setting>& settings, const QString& text) {
    ++m_session;  // merges with no edit before or after
    m_stack->beginMacro(text);
    for (const Setting& s : settings) {
        const SceneDocument::Numbers before = m_document->value(s.field, s.light);
        const SceneDocument::Numbers after = storedAs(s.field, s.value);
        if (after != before) push(s.field, s.light, -1, before, after);
    }
    m_stack->endMacro();
    ++m_session;
}

void EditPanel::apply(Field field, std::size_t light, const SceneDocument::Numbers& value) {
    // An undo or redo ends the merging: the next edit is a step of its own.
    if (!m_pushing) ++m_session;
    m_document->setValue(field, value, light);
    if (SceneDocument::isLightField(field) && light != currentLight()) {
        const QSignalBlocker blocker(m_lightSelector);
        m_lightSelector->setCurrentIndex(int(light));
        showLight();
    }
    showField(field);
    updateModified();
    emit sceneEdited();
}

bool EditPanel::isModified() const {
    return m_document->isModified();
}

void EditPanel::updateModified() {
    const bool modified = isModified();
    m_saveAction->setEnabled(isEditable() && modified);
    updateFileLabel();
    if (modified == m_modified) return;
    m_modified = modified;
    emit modifiedChanged(modified);
}

namespace {

// Short names of the layouts, for the panel's file lines.
QString layoutLabel(rl::CameraLayout layout) {
    switch (layout) {
        case rl::CameraLayout::Ufpe:
            return QStringLiteral("UFPE");
        case rl::CameraLayout::Ufrpe6:
        case rl::CameraLayout::Ufrpe5:
            return QStringLiteral("UFRPE");
        case rl::CameraLayout::KeyValue:
            return QStringLiteral("key = value");
        case rl::CameraLayout::Auto:
            break;
    }
    return {};
}

QString layoutLabel(rl::LightingLayout layout) {
    switch (layout) {
        case rl::LightingLayout::Ufpe:
            return QStringLiteral("UFPE");
        case rl::LightingLayout::UfpeMulti:
            return QStringLiteral("UFPE multi-light");
        case rl::LightingLayout::Ufrpe:
            return QStringLiteral("UFRPE");
        case rl::LightingLayout::KeyValue:
            return QStringLiteral("key = value");
        case rl::LightingLayout::Auto:
            break;
    }
    return {};
}

}  // namespace

void EditPanel::updateFileLabel() {
    if (m_document->showsCommandFile()) {
        m_fileLabel->setText(tr("A command file is shown: its scene is not edited here."));
        return;
    }
    const auto line = [this](Part part, const QString& title, const QString& layout) {
        const QString path = m_document->source(part);
        const std::optional<QString> example = exampleOfPath(path);
        const QString name = example ? tr("%1 of the %2 example")
                                           .arg(QFileInfo(path).fileName(), *example)
                                           .toHtmlEscaped()
                             : m_document->needsPath(part)
                                 ? tr("built-in scene")
                                 : QFileInfo(path).fileName().toHtmlEscaped();
        QString text = QStringLiteral("<b>%1</b> %2 <span style='color:gray'>(%3)</span>")
                           .arg(title, name, layout.toHtmlEscaped());
        if (m_document->isModified(part)) text += QStringLiteral(" <i>%1</i>").arg(tr("modified"));
        return text;
    };
    m_fileLabel->setText(
        line(Part::Camera, tr("Camera"), layoutLabel(m_document->cameraFileLayout())) +
        QStringLiteral("<br>") +
        line(Part::Lighting, tr("Lighting"), layoutLabel(m_document->lightingFileLayout())));
    m_fileLabel->setToolTip(QDir::toNativeSeparators(m_document->source(Part::Camera)) +
                            QLatin1Char('\n') +
                            QDir::toNativeSeparators(m_document->source(Part::Lighting)));
}

QString EditPanel::fieldName(Field field, int source, std::size_t light) const {
    QString name;
    switch (field) {
        case Field::Shading:
            return tr("shading");
        case Field::TwoSided:
            return tr("two-sided lighting");
        case Field::BlinnPhong:
            return tr("the highlight's model");
        case Field::LightDirectional:
            name = tr("directional");
            break;
        case Field::LightSpotCutoff:
            name = tr("spot cutoff");
            break;
        case Field::LightSpotExponent:
            name = tr("spot exponent");
            break;
        case Field::LightSpotDirection:
            name = tr("spot direction");
            break;
        case Field::LightAttenuation:
            name = tr("attenuation");
            break;
        default:
            name = QLatin1String(symbolOf(field));
    }
    if (SceneDocument::componentCount(field) == 3 && source >= 0) {
        name += QLatin1Char('.');
        name += componentLetter(field, source);
    }
    if (SceneDocument::isLightField(field) && m_document->parts().lighting.lights.size() > 1)
        name = tr("%1 of light %2").arg(name).arg(light + 1);
    return name;
}

// ---- Saving

bool EditPanel::saveError(Part part, const QString& message, QWidget* parent) {
    QMessageBox box(
        QMessageBox::Warning, tr("Save"),
        part == Part::Camera ? tr("The camera was not saved.") : tr("The lighting was not saved."),
        QMessageBox::Ok, parent ? parent : this);
    box.setObjectName(QStringLiteral("saveErrorBox"));
    box.setInformativeText(message);
    box.exec();
    return false;
}

bool EditPanel::save(Part part, QWidget* parent) {
    if (m_document->needsPath(part)) return saveAs(part, parent);
    const rl::Status status = m_document->save(part);
    ++m_session;  // the next edit is a step of its own
    if (!status) return saveError(part, translated(status.error()), parent);
    updateModified();
    emit saved(part);
    return true;
}

bool EditPanel::save(QWidget* parent) {
    for (Part part : {Part::Camera, Part::Lighting})
        if (m_document->isModified(part) && !save(part, parent)) return false;
    return true;
}

bool EditPanel::saveAs(Part part, QWidget* parent) {
    // One filter per layout that can hold the part.
    // Each shows every file: course files end in .cfg, .txt, .lux ..., and a filter with
    // extensions would make the dialog rewrite the name typed to its first one.
    QStringList filters;
    std::vector<int> layouts;
    int current = 0;
    const QString patterns = QStringLiteral(" (*)");
    if (part == Part::Camera) {
        for (rl::CameraLayout layout : rl::kCameraLayouts) {
            if (layout == rl::CameraLayout::Auto) continue;
            if (layout == m_document->cameraFileLayout()) current = int(filters.size());
            filters << QString::fromUtf8(rl::cameraLayoutDescription(layout)) + patterns;
            layouts.push_back(int(layout));
        }
    } else {
        // Only the layouts that hold this lighting (several lights, the slides' lighting).
        const rl::CourseLighting& lighting = m_document->parts().lighting;
        for (rl::LightingLayout layout : rl::kLightingLayouts) {
            if (layout == rl::LightingLayout::Auto || !rl::writeLightingFile(lighting, layout).ok())
                continue;
            if (layout == m_document->lightingFileLayout()) current = int(filters.size());
            filters << QString::fromUtf8(rl::lightingLayoutDescription(layout)) + patterns;
            layouts.push_back(int(layout));
        }
    }
    const QString source = m_document->source(part);
    const QString start = m_document->needsPath(part) ? QFileInfo(source).fileName() : source;
    QString selected = filters[current];
    const QString path = QFileDialog::getSaveFileName(
        parent ? parent : this,
        part == Part::Camera ? tr("Save Camera As") : tr("Save Lighting As"), start,
        filters.join(QStringLiteral(";;")), &selected);
    if (path.isEmpty()) return false;
    const int chosen = layouts[std::size_t(std::max<qsizetype>(0, filters.indexOf(selected)))];
    const rl::Status status =
        part == Part::Camera
            ? m_document->saveCameraAs(path, static_cast<rl::CameraLayout>(chosen))
            : m_document->saveLightingAs(path, static_cast<rl::LightingLayout>(chosen));
    ++m_session;
    if (!status) return saveError(part, translated(status.error()), parent);
    updateModified();
    emit saved(part);
    return true;
}

bool EditPanel::maybeSave(QWidget* parent, Part part) {
    if (!m_document->isModified(part)) return true;
    const std::optional<QString> example = exampleOfPath(m_document->source(part));
    const QString file = example ? tr("the %1 example").arg(*example)
                         : m_document->needsPath(part)
                             ? tr("the built-in scene")
                             : QFileInfo(m_document->source(part)).fileName();
    QMessageBox box(QMessageBox::Warning, tr("Unsaved changes"),
                    (part == Part::Camera ? tr("The camera has changes that are not saved (%1).")
                                          : tr("The lighting has changes that are not saved (%1)."))
                        .arg(file),
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
                    parent ? parent : this);
    box.setObjectName(QStringLiteral("saveChangesBox"));
    box.setInformativeText(tr("Save them?"));
    box.setDefaultButton(QMessageBox::Save);
    switch (box.exec()) {
        case QMessageBox::Save:
            return save(part, parent);
        case QMessageBox::Discard:
            return true;
        default:
            return false;
    }
}

bool EditPanel::maybeSave(QWidget* parent) {
    for (Part part : {Part::Camera, Part::Lighting})
        if (!maybeSave(parent, part)) return false;
    return true;
}

}  // namespace rasterlab
