// Numbers and vectors as short text for messages and files, always with '.' as the
// decimal separator, whatever the program's locale.
#pragma once

#include <string>

#include "pipeline/core/math.h"

namespace rl {

std::string formatNumber(double value);               // like "%g": "0.667", "1e-08", "300"
std::string formatFixed(double value, int decimals);  // like "%.4f": "162.0000"
std::string formatVector(const dvec3& value);         // "(0.667, 0.172, -1)"

}  // namespace rl
