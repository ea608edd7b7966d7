#include "format.h"

#include <cstdio>

namespace rl {

std::string formatNumber(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

std::string formatVector(const dvec3& value) {
    std::string s;
    s.reserve(40);
    s += '(';
    s += formatNumber(value.x);
    s += ", ";
    s += formatNumber(value.y);
    s += ", ";
    s += formatNumber(value.z);
    s += ')';
    return s;
}

}  // namespace rl
