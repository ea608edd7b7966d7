// How the stage views write numbers, vectors and colour keys in their tables and explanations.
#pragma once

#include <QColor>
#include <QLatin1Char>
#include <QString>

#include <algorithm>
#include <cmath>

namespace rasterlab {

// -0, and a negative number that rounds to 0 ("-0.0000"), are written as 0: a cross product of
// exact vectors gives -0 often, and "-0" only puzzles.
inline QString number(double v, int precision = 6, char format = 'g') {
    if (v == 0.0) v = 0.0;
    QString s = QString::number(v, format, precision);
    if (s.startsWith(QLatin1Char('-')) && s.mid(1).toDouble() == 0.0) s.remove(0, 1);
    return s;
}

// A number written after an operator: negative ones in parentheses, "2 · (-0.5)".
inline QString operand(double v) {
    const QString s = number(v);
    return s.startsWith(QLatin1Char('-')) ? QLatin1Char('(') + s + QLatin1Char(')') : s;
}

// "(x, y, z)" for any GLM vector; rounding dust beside the largest component (1e-14 next to
// 200) is written as 0.
template <typename V>
QString vector(const V& v, char format = 'g', int precision = 6) {
    double largest = 0.0;
    for (int k = 0; k < v.length(); ++k) largest = std::max(largest, std::abs(double(v[k])));
    QString s = QStringLiteral("(");
    for (int k = 0; k < v.length(); ++k) {
        if (k > 0) s += QStringLiteral(", ");
        const double c = double(v[k]);
        s += number(std::abs(c) < 1e-12 * largest ? 0.0 : c, precision, format);
    }
    return s + QLatin1Char(')');
}

// A square of a drawing's colour, for a legend written in HTML.
inline QString swatch(const QColor& colour) {
    return QStringLiteral("<span style=\"color:%1\">&#9632;</span>").arg(colour.name());
}

}  // namespace rasterlab
