#include "format.h"

#include <charconv>

namespace rl {

// std::to_chars never looks at the C locale, unlike printf: a program whose locale uses a
// decimal comma (pt_BR) still writes "0.5".
std::string formatNumber(double value) {
    char buffer[32];
    const auto result =
        std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 6);
    return std::string(buffer, result.ptr);
}

std::string formatFixed(double value, int decimals) {
    char buffer[64];
    const auto result =
        std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
    return std::string(buffer, result.ptr);
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
