// Their colour at a pixel, held to our lighting of it: which Phong term, changed alone, would
// give their colour, and whether a simple factor does (the term left out, times Od, without
// Od). The Compare dock and, after a check, the pixel inspector both say it.
#pragma once

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <array>
#include <cstdint>

#include "views/lighting_breakdown.h"

namespace rasterlab {

class TheirColourTerms {
    // The texts were the Compare dock's first: they keep its translation context.
    Q_DECLARE_TR_FUNCTIONS(rasterlab::ComparePanel)

public:
    // Whether the terms can be worked out for this fragment: the course's lighting model, in
    // flat or Phong shading.
    static bool workedOutFor(const LightingBreakdown& b);
    // One line per term (ambient, diffuse, specular): what it would have to be, and the
    // simple factor that gives it where one does; then the clamped channels, and a line when
    // no term alone explains their colour. colourScale: the scene's (1 or 255).
    static QStringList lines(const LightingBreakdown& b, const std::array<std::uint8_t, 4>& theirs,
                             float colourScale);
    static QString channelName(int c);                  // "red", "green", "blue", "alpha"
    static QString listText(const QStringList& parts);  // "a, b and c" in the language shown
};

}  // namespace rasterlab
