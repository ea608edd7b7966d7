#include "views/their_colour.h"

#include <cmath>

#include "views/number_text.h"

namespace rasterlab {

namespace {

QString vec(const rl::vec3& v) {
    return vector(v, 'g', 3);
}

}  // namespace

bool TheirColourTerms::workedOutFor(const LightingBreakdown& b) {
    return b.lighting == rl::LightingModel::CoursePhong && !b.slides &&
           b.event.model != rl::ShadingModel::Gouraud;
}

QString TheirColourTerms::channelName(int c) {
    switch (c) {
        case 0:
            return tr("red");
        case 1:
            return tr("green");
        case 2:
            return tr("blue");
        default:
            return tr("alpha");
    }
}

// "a, b and c" in the language shown.
QString TheirColourTerms::listText(const QStringList& parts) {
    if (parts.size() < 2) return parts.value(0);
    return tr("%1 and %2")
        .arg(parts.mid(0, parts.size() - 1).join(QStringLiteral(", ")), parts.last());
}

QStringList TheirColourTerms::lines(const LightingBreakdown& b,
                                    const std::array<std::uint8_t, 4>& theirs, float colourScale) {
    const float scale = colourScale;
    const float byte = scale / 255.0f;  // one byte in the colour scale: the rounding's margin
    // What the colour (before clamping) would have to change by, per channel, to give their
    // byte. Where we clamp to 255 and so do they, any colour at least as high gives it: the
    // change is then at least delta (and is shown as none).
    rl::vec3 delta(0.0f);
    std::array<bool, 3> atLeast{};
    QStringList clamped;
    for (int c = 0; c < 3; ++c) {
        atLeast[c] = theirs[c] == 255 && b.colour[c] >= scale;
        delta[c] = (atLeast[c] ? scale : float(theirs[c]) * byte) - b.colour[c];
        if (atLeast[c]) clamped << channelName(c);
    }
    const rl::vec3& od = b.objectColour;
    struct Term {
        QString name;
        rl::vec3 value;
    };
    const Term terms[] = {{tr("the ambient term Ia·ka"), b.ambient},
                          {tr("the diffuse term Il·Od·kd·(N·L)"), b.diffuse},
                          {tr("the specular term Il·ks·(R·V)^n"), b.specular}};
    QStringList lines;
    bool explained = false;  // a term changed by a simple factor gives their colour
    for (const Term& t : terms) {
        const rl::vec3 needed = t.value + delta;
        rl::vec3 shown = needed;  // a clamped channel as it is
        QStringList zero, negative;
        for (int c = 0; c < 3; ++c) {
            if (atLeast[c]) {
                shown[c] = t.value[c];
                continue;
            }
            if (std::abs(delta[c]) > byte && t.value[c] <= byte) zero << channelName(c);
            if (needed[c] < -byte) negative << channelName(c);
        }
        if (!zero.isEmpty()) {
            lines << tr("• %1 is 0 in %2 here: changing it alone cannot give their colour.")
                         .arg(t.name, listText(zero));
            continue;
        }
        if (!negative.isEmpty()) {
            lines << tr("• %1 would have to be below 0 in %2: not this term alone.")
                         .arg(t.name, listText(negative));
            continue;
        }
        // The factor per channel, and whether a simple one fits every channel to within the
        // rounding of a byte: 0 (the term left out), Od (multiplied by Od), 1/Od (without Od).
        rl::vec3 factor(1.0f);
        const auto fits = [&](const rl::vec3& f) {
            for (int c = 0; c < 3; ++c) {
                if (t.value[c] <= byte) continue;
                if (f[c] < (needed[c] - byte) / t.value[c]) return false;
                if (!atLeast[c] && f[c] > (needed[c] + byte) / t.value[c]) return false;
            }
            return true;
        };
        for (int c = 0; c < 3; ++c)
            if (t.value[c] > byte) factor[c] = shown[c] / t.value[c];
        QString line = tr("• %1 would have to be %2 instead of %3, × %4 per channel")
                           .arg(t.name, vec(shown), vec(t.value), vec(factor));
        if (fits(rl::vec3(0.0f))) {
            line += tr(": the term left out");
            explained = true;
        } else if (fits(od)) {
            line += tr(": that is the term times Od %1").arg(vec(od));
            explained = true;
        } else if (od.x > 0.0f && od.y > 0.0f && od.z > 0.0f && fits(1.0f / od)) {
            line += tr(": that is the term without Od %1").arg(vec(od));
            explained = true;
        }
        lines << line + QLatin1Char('.');
    }
    if (!clamped.isEmpty())
        lines << tr("(%1: 255 in both images, clamped; any value at least as high gives it.)")
                     .arg(listText(clamped));
    if (!explained)
        lines << tr(
            "No term changed by a simple factor (left out, times Od, without Od) gives "
            "their colour: look at several terms, or at what the diagnosis says.");
    return lines;
}

}  // namespace rasterlab
