#include "lighting_breakdown.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

#include "pipeline/render/output_image.h"
#include "pipeline/stages/shading.h"
#include "views/inspection.h"
#include "views/pixel_text.h"

namespace rasterlab {

namespace {

// Works a fragment's breakdown out part by part, from its frame, draw and shading sample,
// named as the formulas name them. Its texts are the inspector's: they keep its translation
// context.
struct BreakdownBuilder {
    const rl::FrameTrace& frame;
    const PixelHistoryRow& row;
    const rl::ShadeEvent& event;
    const rl::Scene& scene;
    const rl::Conventions& conv;
    const rl::ScreenTriangle& tri;
    const rl::DrawProjection& proj;
    const rl::Draw& draw;
    const rl::Material& m;
    const rl::PhongSample& s;
    const rl::ShadingModel model;
    const float scale;  // the colour scale: what reaches it becomes byte 255
    LightingBreakdown b;

    LightingBreakdown build(int historyRow);

private:
    void addTerms(int historyRow);
    // The flags: the sample's special cases, the course's lights one by one, the texel a
    // textured draw read, the channels clamped.
    void flag(LightingFlag f, const QString& text);
    void addSampleFlags();
    void addCourseLights();
    void addTexelFlag();
    void addClampFlag();
    // The formula with the numbers filled in, one line per channel: Gouraud's mix, the object
    // colour of a draw that is not lit, or the lighting model's terms.
    QString byteOf(int c) const;
    void addGouraudFormula();
    void addUnlitFormula();
    void addLitFormula();
    void addLitEquation(bool course, bool noLight);
    void addSlidesChannels();
    void addFirstLightChannels(bool course, const rl::vec3& il, const rl::vec3& od, bool noLight);
    void addLitValues(bool course, const rl::vec3& il, const rl::vec3& od);
    // The lines of one light of the course's model: where it is, its factors, its terms.
    QStringList lightLines(std::size_t k, const rl::LightTerms& t,
                           rl::SpecularModel specular) const;

public:
    Q_DECLARE_TR_FUNCTIONS(rasterlab::PixelInspector)
};

LightingBreakdown BreakdownBuilder::build(int historyRow) {
    addTerms(historyRow);
    const bool lit =
        model != rl::ShadingModel::Gouraud && draw.lighting != rl::LightingModel::Unlit;
    if (lit) addSampleFlags();
    // The course's model light by light: the same call as the shading stage's, at the point
    // and with the normal it lit (the event's: P' for Phong, the barycentre for flat).
    if (lit && draw.lighting == rl::LightingModel::CoursePhong && frame.view) addCourseLights();
    addTexelFlag();
    addClampFlag();
    switch (model) {
        case rl::ShadingModel::Gouraud:
            addGouraudFormula();
            break;
        case rl::ShadingModel::Flat:
        case rl::ShadingModel::Painter:
        case rl::ShadingModel::Phong:
            if (draw.lighting == rl::LightingModel::Unlit)
                addUnlitFormula();
            else
                addLitFormula();
            break;
    }
    return std::move(b);
}

void BreakdownBuilder::addTerms(int historyRow) {
    b.historyRow = historyRow;
    b.fragment = row.fragment;
    b.event = event;
    b.lighting = draw.lighting;
    b.lights = std::min(draw.lightCount, frame.view ? frame.view->lights.size() : 0);
    b.colour = event.colour;
    b.bytes = rl::colourBytes(event.colour, conv);
    if (model != rl::ShadingModel::Gouraud) {
        b.ambient = s.ambient;
        b.diffuse = s.diffuse;
        b.specular = s.specular;
        b.unlit = s.unlit;
    }
    float beta = row.beta, gamma = row.gamma;
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
        b.vertexColours = event.vertexColours;
    }
}

void BreakdownBuilder::flag(LightingFlag f, const QString& text) {
    b.flags.push_back(f);
    b.flagTexts.push_back(text);
}

void BreakdownBuilder::addSampleFlags() {
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

void BreakdownBuilder::addCourseLights() {
    b.emission = s.emission;
    b.perLight.resize(b.lights);
    if (b.lights > 0)
        rl::phong(m, b.objectColour, scene.ambientIntensity, frame.view->lights.data(), b.lights,
                  event.pView, event.nInterpolated, conv.flipNormalsTowardViewer, draw.specular,
                  b.perLight.data());
    b.slides = m.emission != rl::vec3(0.0f) || draw.specular != rl::SpecularModel::Phong;
    for (std::size_t k = 0; k < b.lights; ++k) {
        const rl::ViewLight& light = frame.view->lights[k];
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

void BreakdownBuilder::addTexelFlag() {
    const auto lookup = rl::texelLookup(scene, proj, tri.v, tri.draw, row.beta, row.gamma);
    if (!lookup) return;
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

void BreakdownBuilder::addClampFlag() {
    for (int c = 0; c < 3; ++c) {
        if (event.colour[c] > scale) {
            QStringList over;
            for (int k = 0; k < 3; ++k)
                if (event.colour[k] > scale)
                    over << QStringLiteral("%1 = %2").arg(channelNames()[std::size_t(k)],
                                                          num(event.colour[k], 4));
            flag(LightingFlag::Clamped,
                 tr("Clamped: %1 above the colour scale %2, written as byte 255.")
                     .arg(over.join(QStringLiteral(", ")), num(scale)));
            break;
        }
    }
}

QString BreakdownBuilder::byteOf(int c) const {
    const QString byte = QString::number(b.bytes[static_cast<std::size_t>(c)]);
    return event.colour[c] > scale ? tr("%1 (clamped)").arg(byte) : byte;
}

void BreakdownBuilder::addGouraudFormula() {
    QStringList& f = b.formula;
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
                      num(b.vertexColours[2][c], 4), num(event.colour[c]), byteOf(c));
}

void BreakdownBuilder::addUnlitFormula() {
    QStringList& f = b.formula;
    b.heading = tr("not lit, the object colour as it is");
    f << tr("I = O (the object colour)");
    for (int c = 0; c < 3; ++c)
        f << QStringLiteral("%1 = %2 → %3")
                 .arg(channelNames()[std::size_t(c)], num(s.unlit[c]), byteOf(c));
}

void BreakdownBuilder::addLitFormula() {
    QStringList& f = b.formula;
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
    const rl::vec3 il = b.lights > 0 ? frame.view->lights[0].intensity : rl::vec3(0.0f);
    const bool noLight = b.lights == 0 || s.noNormal || s.lightAtPoint;
    const rl::vec3 od = b.objectColour;
    addLitEquation(course, noLight);
    if (course && b.slides)
        addSlidesChannels();
    else
        addFirstLightChannels(course, il, od, noLight);
    addLitValues(course, il, od);
}

// The lighting model's formula, and the numbers of the first light it reads.
void BreakdownBuilder::addLitEquation(bool course, bool noLight) {
    QStringList& f = b.formula;
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
}

// Ke + Ia ka + each light's diffuse and specular, light by light below.
void BreakdownBuilder::addSlidesChannels() {
    for (int c = 0; c < 3; ++c) {
        const auto k = static_cast<std::size_t>(c);
        QStringList sums;
        sums << num(b.emission[c]) << num(b.ambient[c]);
        for (const rl::LightTerms& t : b.perLight) sums << num(t.diffuse[c]) << num(t.specular[c]);
        b.formula << QStringLiteral("%1 = %2 = %3 → %4")
                         .arg(channelNames()[k], sums.join(QStringLiteral(" + ")),
                              num(event.colour[c]), byteOf(c));
    }
}

// Each channel with the first light's numbers filled in, the other lights' share summed.
void BreakdownBuilder::addFirstLightChannels(bool course, const rl::vec3& il, const rl::vec3& od,
                                             bool noLight) {
    for (int c = 0; c < 3; ++c) {
        const auto k = static_cast<std::size_t>(c);
        QStringList parts;
        float first = 0.0f;  // the first light's diffuse and specular
        if (course)
            parts << QStringLiteral("%1 × %2").arg(num(scene.ambientIntensity[c]), num(m.ka));
        if (noLight || s.lightBehind) {
            parts << QStringLiteral("0");
        } else {
            parts
                << (course
                        ? QStringLiteral("%1 × %2 × %3 × %4")
                              .arg(num(il[c]), num(od[c]), num(m.kd[c]), num(s.nDotL))
                        : QStringLiteral("%1 × %2 × %3").arg(num(il[c]), num(od[c]), num(s.nDotL)));
            first += course ? il[c] * od[c] * m.kd[c] * s.nDotL : il[c] * od[c] * s.nDotL;
            if (course) {
                if (s.noSpecular) {
                    parts << QStringLiteral("0");
                } else {
                    parts << QStringLiteral("%1 × %2 × %3^%4")
                                 .arg(num(il[c]), num(m.ks), num(s.rDotV), num(m.shininess));
                    if (m.ks != 0.0f) first += il[c] * m.ks * rl::fastPow(s.rDotV, m.shininess);
                }
            } else if (m.shininess > 0.0f) {
                parts
                    << QStringLiteral("%1 × %2^%3").arg(num(il[c]), num(s.rDotV), num(m.shininess));
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
        const QString values = parts.size() > 1 && sums.size() > 1
                                   ? QStringLiteral(" = ") + sums.join(QStringLiteral(" + "))
                                   : QString();
        b.formula << QStringLiteral("%1 = %2%3 = %4 → %5")
                         .arg(channelNames()[k], parts.join(QStringLiteral(" + ")), values,
                              num(event.colour[c]), byteOf(c));
    }
}

// The values the formula reads: the material, the light, and the course's lights one by one.
void BreakdownBuilder::addLitValues(bool course, const rl::vec3& il, const rl::vec3& od) {
    QStringList& f = b.formula;
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
            f << lightLines(k, b.perLight[k], draw.specular);
    }
}

QStringList BreakdownBuilder::lightLines(std::size_t k, const rl::LightTerms& t,
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

}  // namespace

bool LightingBreakdown::has(LightingFlag flag) const {
    return std::find(flags.begin(), flags.end(), flag) != flags.end();
}

LightingBreakdown lightingBreakdown(const rl::FrameTrace& frame, const PixelHistoryRow& row,
                                    int historyRow, const rl::ShadeEvent& event) {
    const rl::Scene& scene = *frame.scene;
    const rl::ScreenTriangle& tri = frame.projection->triangles[event.triangle];
    const rl::Draw& draw = scene.draws[tri.draw];
    BreakdownBuilder builder{frame,
                             row,
                             event,
                             scene,
                             scene.conventions,
                             tri,
                             frame.projection->draws[tri.draw],
                             draw,
                             draw.material,
                             event.sample,
                             event.model,
                             scene.conventions.colourScale,
                             {}};
    return builder.build(historyRow);
}

std::optional<LightingBreakdown> rowBreakdown(const Inspection& inspection,
                                              const PixelHistory& history, int row) {
    const std::vector<PixelHistoryRow>& rows = history.rows();
    const std::shared_ptr<const rl::FrameTrace>& frame = inspection.frame();
    if (!frame || row < 0 || row >= static_cast<int>(rows.size())) return std::nullopt;
    // The final row shows the lighting of the fragment that wrote it.
    const PixelHistoryRow& r = rows[row];
    if (r.kind == PixelHistoryRow::Kind::Initial || r.fragment == rl::kNoFragment)
        return std::nullopt;
    std::optional<rl::ShadeEvent> event;
    if (const rl::FrameReplay* replay = inspection.replay(); replay && !history.traced())
        event = replay->shade({r.fragment}).front();
    else if (history.tracedShade() && r.fragment == rows.back().fragment)
        event = history.tracedShade();  // the fragment that holds the pixel at the end
    if (!event) return std::nullopt;
    return lightingBreakdown(*frame, r, row, *event);
}

}  // namespace rasterlab
