// Numbers and vectors as short text for messages: "%g" style, C locale.
#pragma once

#include <string>

#include "math.h"

namespace rl {

std::string formatNumber(double value);          // "0.667", "1e-08", "300"
std::string formatVector(const dvec3& value);    // "(0.667, 0.172, -1)"

}  // namespace rl
