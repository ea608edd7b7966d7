// How the pixel inspector, its history and its lighting breakdown write numbers, vectors and
// channel names.
#pragma once

#include <QString>

#include <array>
#include <cmath>

#include "pipeline/core/math.h"
#include "views/number_text.h"

namespace rasterlab {

// number(), with the depth buffer's clear value written "+inf" and a NaN depth "NaN".
inline QString num(double v, int precision = 6) {
    if (std::isnan(v)) return QStringLiteral("NaN");
    if (std::isinf(v)) return v > 0 ? QStringLiteral("+inf") : QStringLiteral("-inf");
    return number(v, precision);
}

inline QString vector3(const rl::vec3& v) {
    return vector(v, 'g', 4);
}

inline const std::array<QString, 3>& channelNames() {
    static const std::array<QString, 3> names{QStringLiteral("R"), QStringLiteral("G"),
                                              QStringLiteral("B")};
    return names;
}

}  // namespace rasterlab
