#include "course_readers.h"

#include <algorithm>

#include <cctype>
#include <charconv>
#include "format.h"

namespace rl {

namespace {

std::string countText(unsigned counts) {
    std::vector<int> accepted;
    for (int k = 0; k < 32; ++k)
        if (counts & (1u << k)) accepted.push_back(k);
    std::string s;
    for (std::size_t i = 0; i < accepted.size(); ++i) {
        if (i > 0) s += i + 1 == accepted.size() ? " or " : ", ";
        s += std::to_string(accepted[i]);
    }
    s += accepted.size() == 1 && accepted[0] == 1 ? " number" : " numbers";
    return s;
}

int maxCount(unsigned counts) {
    int m = 0;
    for (int k = 0; k < 32; ++k)
        if (counts & (1u << k)) m = k;
    return m;
}

std::string plural(long long n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

// The token without one leading sign.
std::string_view withoutSign(std::string_view token) {
    if (!token.empty() && (token.front() == '+' || token.front() == '-')) token.remove_prefix(1);
    return token;
}

// A well-formed decimal number too large (or too small) for a double, such as "1e999"; not
// a malformed one such as "1.2.3" or "1e".
bool isOutOfRange(std::string_view token) {
    const std::string_view digits = withoutSign(token);
    if (digits.empty() || digits.find_first_not_of(".0123456789eE+-") != std::string_view::npos ||
        !(digits.front() == '.' || (digits.front() >= '0' && digits.front() <= '9')))
        return false;
    if (token.front() == '+') token.remove_prefix(1);  // from_chars takes '-' only
    double value = 0.0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return ec == std::errc::result_out_of_range && end == token.data() + token.size();
}

// "nan", "-nan", "inf", "+Inf", "infinity" ... in any case.
bool isNotFinite(std::string_view token) {
    std::string lower(withoutSign(token));
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return lower == "nan" || lower == "inf" || lower == "infinity";
}

// Why a token is not a number, for the end of an error message.
std::string whyNotNumber(std::string_view token) {
    std::string s = "found " + quoted(token);
    const bool hasDigit = token.find_first_of("0123456789") != std::string_view::npos;
    if (token.find(',') != std::string_view::npos && hasDigit) {
        s += " (the decimal separator is '.')";
    } else if (isOutOfRange(token)) {
        s += ", which is out of range";
    } else if (isNotFinite(token)) {
        s += ", which is not a finite number";
    }
    return s;
}

bool startsLikeNumber(std::string_view token) {
    const char c = token.empty() ? ' ' : token.front();
    return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.';
}

}  // namespace

Result<std::vector<FieldValue>> readFieldLines(LineScanner& scanner,
                                               std::span<const FieldSpec> fields,
                                               std::string_view what, Diagnostics& diagnostics) {
    std::vector<FieldValue> result;
    result.reserve(fields.size());
    TextLine line;
    for (const FieldSpec& field : fields) {
        const std::string expected = std::string(field.name) + ", " +
                                     std::string(field.description) + " (" +
                                     countText(field.counts) + ")";
        if (!scanner.next(line))
            return makeError(ErrorCode::MissingData, scanner.endOfInput(),
                             "expected " + expected + ", found the end of the file");

        FieldValue value;
        value.line = scanner.at(line.number, 1);
        // Numbers first: the line's leading numeric tokens.
        std::size_t numeric = 0;
        for (; numeric < line.tokens.size(); ++numeric) {
            const Token& token = line.tokens[numeric];
            if (!parseReal(token.text)) break;
        }
        // Take all the numbers the field accepts; what follows them is ignored with a
        // warning. A field may accept several counts (kd: one number or an RGB triple).
        const int limit = maxCount(field.counts);
        const int available = static_cast<int>(numeric);
        int taken = limit;
        if (available < limit) {
            // After a count the field accepts, text that does not start like a number is a
            // trailing remark (ignored with a warning below, as after a full line); a token
            // that starts like a number but is not one is an error.
            const bool accepted = (field.counts & (1u << available)) != 0;
            if (numeric < line.tokens.size() &&
                (!accepted || startsLikeNumber(line.tokens[numeric].text))) {
                const Token& bad = line.tokens[numeric];
                return makeError(ErrorCode::Syntax, scanner.at(bad),
                                 "expected a number for " + std::string(field.name) + ", " +
                                     whyNotNumber(bad.text));
            }
            if (!(field.counts & (1u << available)))
                return makeError(ErrorCode::Syntax, scanner.afterLast(line),
                                 "expected " + countText(field.counts) + " for " +
                                     std::string(field.name) + ", found " +
                                     std::to_string(available));
            taken = available;
        }
        for (int k = 0; k < taken; ++k) {
            const Token& token = line.tokens[static_cast<std::size_t>(k)];
            value.values.push_back(*parseReal(token.text));
            value.where.push_back(scanner.at(token));
        }
        if (line.tokens.size() > static_cast<std::size_t>(taken)) {
            const std::size_t extra = line.tokens.size() - static_cast<std::size_t>(taken);
            diagnostics.warn(scanner.at(line.tokens[static_cast<std::size_t>(taken)]),
                             "ignored " + plural(static_cast<long long>(extra), "value", "values") +
                                 " after " + std::string(field.name));
        }
        result.push_back(std::move(value));
    }
    if (scanner.next(line)) {
        const int remaining = 1 + scanner.countRemainingLines();
        diagnostics.warn(scanner.at(line.number, 1),
                         "ignored " + plural(remaining, "line", "lines") + " after the " +
                             std::string(what) + "'s " +
                             plural(static_cast<long long>(fields.size()), "line", "lines"));
    }
    return result;
}

namespace {

dvec3 vec3Of(const FieldValue& f) {
    return dvec3(f.values[0], f.values[1], f.values[2]);
}

vec3 rgbOf(const FieldValue& f) {
    if (f.values.size() == 1) return vec3(static_cast<float>(f.values[0]));
    return vec3(static_cast<float>(f.values[0]), static_cast<float>(f.values[1]),
                static_cast<float>(f.values[2]));
}

constexpr unsigned kOne = 1u << 1;
constexpr unsigned kThree = 1u << 3;

}  // namespace

Result<CourseCamera> readCourseCamera(std::string_view text, const std::string& fileName,
                                      Diagnostics& diagnostics) {
    static constexpr FieldSpec kUfpeCamera[] = {
        {"C", "the camera position", kThree},
        {"N", "the view direction", kThree},
        {"V", "the up vector", kThree},
        {"d hx hy", "the projection distance and half-sizes", kThree},
    };
    LineScanner scanner(text, fileName);
    auto fields = readFieldLines(scanner, kUfpeCamera, "camera", diagnostics);
    if (!fields) return fields.error();
    const auto& f = fields.value();
    CourseCamera camera;
    camera.c = vec3Of(f[0]);
    camera.n = vec3Of(f[1]);
    camera.v = vec3Of(f[2]);
    camera.d = f[3].values[0];
    camera.hx = f[3].values[1];
    camera.hy = f[3].values[2];
    camera.where = {f[0].line, f[1].line, f[2].line, f[3].where[0], f[3].where[1], f[3].where[2]};
    return camera;
}

Result<CourseLighting> readCourseLighting(std::string_view text, const std::string& fileName,
                                          Diagnostics& diagnostics) {
    static constexpr FieldSpec kUfpeLighting[] = {
        {"Pl", "the light position", kThree},
        {"ka", "the ambient coefficient", kOne},
        {"Ia", "the ambient light colour", kThree},
        {"kd", "the diffuse coefficient", kOne | kThree},
        {"Od", "the diffuse colour of the object", kThree},
        {"ks", "the specular coefficient", kOne},
        {"Il", "the light colour", kThree},
        {"n", "the specular exponent", kOne},
    };
    LineScanner scanner(text, fileName);
    auto fields = readFieldLines(scanner, kUfpeLighting, "lighting", diagnostics);
    if (!fields) return fields.error();
    const auto& f = fields.value();
    CourseLighting lighting;
    Light light;
    light.pWorld = dvec4(vec3Of(f[0]), 1.0);
    light.intensity = rgbOf(f[6]);
    light.where = f[0].line;
    lighting.lights.push_back(light);
    lighting.material.ka = static_cast<float>(f[1].values[0]);
    lighting.ambientIntensity = rgbOf(f[2]);
    lighting.material.kd = rgbOf(f[3]);
    lighting.material.od = rgbOf(f[4]);
    lighting.material.ks = static_cast<float>(f[5].values[0]);
    lighting.material.shininess = static_cast<float>(f[7].values[0]);

    // Values outside the ranges the course gives (seed 004) still render, with a warning.
    const auto check = [&](const FieldValue& field, const char* name, double low, double high,
                           const char* range) {
        for (std::size_t i = 0; i < field.values.size(); ++i) {
            const double v = field.values[i];
            if (v >= low && v <= high) continue;
            std::string label = name;
            if (field.values.size() == 3) label += std::string(".") + "rgb"[i];
            diagnostics.warn(field.where[i], label + " = " + formatNumber(v) + " is outside " +
                                                 range + ", the range the course gives for it");
        }
    };
    check(f[1], "ka", 0.0, 1.0, "[0, 1]");
    check(f[2], "Ia", 0.0, 255.0, "[0, 255]");
    check(f[3], "kd", 0.0, 1.0, "[0, 1]");
    check(f[4], "Od", 0.0, 1.0, "[0, 1]");
    check(f[5], "ks", 0.0, 1.0, "[0, 1]");
    check(f[6], "Il", 0.0, 255.0, "[0, 255]");
    if (!(f[7].values[0] > 0.0))
        diagnostics.warn(f[7].where[0],
                         "n = " + formatNumber(f[7].values[0]) +
                             " is not positive: (R.V)^n then makes no highlight (it is 1 "
                             "everywhere for n = 0 and grows without bound where R.V nears 0 "
                             "for n < 0, where the specular term is left out)");
    return lighting;
}

namespace {

// Reads a header count: a non-negative integer.
Result<long long> readCount(const LineScanner& scanner, const Token& token, const char* what) {
    const auto n = parseInteger(token.text);
    if (!n || *n < 0)
        return makeError(ErrorCode::Syntax, scanner.at(token),
                         std::string("expected the number of ") + what +
                             " (a non-negative integer), found " + quoted(token.text));
    return *n;
}

bool isComment(const Token& token) {
    return token.text.starts_with('#') || token.text.starts_with("//");
}

Error commentError(const LineScanner& scanner, const Token& token, const std::string& expected) {
    return makeError(ErrorCode::Syntax, scanner.at(token),
                     "expected " + expected + ", found a comment (" + quoted(token.text) +
                         "), but .byu files have no comments");
}

}  // namespace

Result<Mesh> readByuMesh(std::string_view text, const std::string& fileName,
                         Diagnostics& diagnostics) {
    LineScanner scanner(text, fileName);
    TextLine line;
    const std::string header = "the header 'vertices triangles' (two integers)";
    if (!scanner.next(line))
        return makeError(ErrorCode::MissingData, scanner.endOfInput(),
                         "expected " + header + ", found the end of the file");
    if (isComment(line.tokens[0])) return commentError(scanner, line.tokens[0], header);
    const TextLine headerLine = line;
    if (line.tokens.size() == 4 && parseInteger(line.tokens[0].text) &&
        parseInteger(line.tokens[1].text) && parseInteger(line.tokens[2].text) &&
        parseInteger(line.tokens[3].text)) {
        return makeError(ErrorCode::Unsupported, scanner.at(line.tokens[0]),
                         "this is an original Movie.BYU file (header 'parts vertices polygons "
                         "edges'), not the course's .byu format (header 'vertices triangles')");
    }
    auto vertexCount = readCount(scanner, line.tokens[0], "vertices");
    if (!vertexCount) return vertexCount.error();
    if (line.tokens.size() < 2)
        return makeError(ErrorCode::Syntax, scanner.afterLast(line),
                         "expected the number of triangles after the number of vertices, "
                         "found the end of the line");
    auto triangleCount = readCount(scanner, line.tokens[1], "triangles");
    if (!triangleCount) return triangleCount.error();
    if (line.tokens.size() > 2)
        diagnostics.warn(
            scanner.at(line.tokens[2]),
            "ignored " + plural(static_cast<long long>(line.tokens.size() - 2), "value", "values") +
                " after the header's two counts");

    // A course Bezier surface also ships as .byu: "m n", then one number (evaluations).
    if (scanner.next(line)) {
        if (line.tokens.size() == 1 && parseInteger(line.tokens[0].text)) {
            return makeError(ErrorCode::Unsupported, scanner.at(headerLine.tokens[0]),
                             "this looks like a course Bezier surface (degrees " +
                                 std::to_string(*vertexCount) + " x " +
                                 std::to_string(*triangleCount) + ", " +
                                 std::string(line.tokens[0].text) +
                                 " evaluations per direction), not a triangle mesh");
        }
        scanner.unread();
    }

    // Reject counts the file cannot hold before allocating anything.
    // (Compared without adding the counts, which may overflow; their sum fits unsigned.)
    const long long available = scanner.countRemainingLines();
    if (*vertexCount > available || *triangleCount > available - *vertexCount) {
        const unsigned long long declared = static_cast<unsigned long long>(*vertexCount) +
                                            static_cast<unsigned long long>(*triangleCount);
        return makeError(ErrorCode::Range, scanner.at(headerLine.tokens[0]),
                         "the header declares " + plural(*vertexCount, "vertex", "vertices") +
                             " and " + plural(*triangleCount, "triangle", "triangles") + " (" +
                             std::to_string(declared) + (declared == 1 ? " line" : " lines") +
                             "), but only " + plural(available, "line follows", "lines follow"));
    }

    Mesh mesh;
    mesh.source = scanner.at(0, 0);
    mesh.positions.reserve(static_cast<std::size_t>(*vertexCount));
    mesh.triangles.reserve(static_cast<std::size_t>(*triangleCount));
    mesh.triangleLines.reserve(static_cast<std::size_t>(*triangleCount));

    static const char* const kAxis[] = {"x", "y", "z"};
    long long linesWithExtraValues = 0;
    SourceLocation firstExtra;
    for (long long i = 0; i < *vertexCount; ++i) {
        scanner.next(line);  // present: counted above
        const std::string which =
            "vertex " + std::to_string(i + 1) + " of " + std::to_string(*vertexCount);
        if (isComment(line.tokens[0]))
            return commentError(scanner, line.tokens[0], which + " (x y z)");
        dvec4 p(0.0, 0.0, 0.0, 1.0);
        for (int k = 0; k < 3; ++k) {
            if (static_cast<std::size_t>(k) >= line.tokens.size())
                return makeError(
                    ErrorCode::Syntax, scanner.afterLast(line),
                    "expected 3 coordinates for " + which + ", found " + std::to_string(k));
            const Token& token = line.tokens[static_cast<std::size_t>(k)];
            const auto value = parseReal(token.text);
            if (!value)
                return makeError(ErrorCode::Syntax, scanner.at(token),
                                 std::string("expected a number for the ") + kAxis[k] +
                                     " coordinate of " + which + ", " + whyNotNumber(token.text));
            p[k] = *value;
        }
        if (line.tokens.size() > 3 && linesWithExtraValues++ == 0)
            firstExtra = scanner.at(line.tokens[3]);
        mesh.positions.push_back(p);
    }

    std::vector<unsigned char> used(mesh.positions.size(), 0);
    for (long long i = 0; i < *triangleCount; ++i) {
        scanner.next(line);
        const std::string which = "triangle " + std::to_string(i + 1);
        if (isComment(line.tokens[0]))
            return commentError(
                scanner, line.tokens[0],
                which + " of " + std::to_string(*triangleCount) + " (three vertex indices)");
        if (line.tokens.size() < 3)
            return makeError(ErrorCode::Syntax, scanner.afterLast(line),
                             "expected 3 vertex indices for " + which + " of " +
                                 std::to_string(*triangleCount) + ", found " +
                                 std::to_string(line.tokens.size()));
        if (line.tokens.size() > 3 && parseInteger(line.tokens[3].text))
            return makeError(ErrorCode::Unsupported, scanner.at(line.tokens[3]),
                             "polygon " + std::to_string(i + 1) + " has " +
                                 std::to_string(line.tokens.size()) +
                                 " vertex indices, but only triangles (3 indices) are supported");
        std::array<std::uint32_t, 3> tri{};
        for (int k = 0; k < 3; ++k) {
            const Token& token = line.tokens[static_cast<std::size_t>(k)];
            const auto index = parseInteger(token.text);
            if (!index)
                return makeError(ErrorCode::Syntax, scanner.at(token),
                                 "expected a vertex index (a positive integer) for " + which +
                                     ", found " + quoted(token.text));
            if (*index < 1)
                return makeError(ErrorCode::Range, scanner.at(token),
                                 which + " refers to vertex " + std::to_string(*index) +
                                     ", but indices are 1-based (1 to " +
                                     std::to_string(*vertexCount) + ")");
            if (*index > *vertexCount)
                return makeError(ErrorCode::Range, scanner.at(token),
                                 which + " refers to vertex " + std::to_string(*index) +
                                     ", but the file declares only " +
                                     plural(*vertexCount, "vertex", "vertices"));
            tri[static_cast<std::size_t>(k)] = static_cast<std::uint32_t>(*index - 1);
            used[static_cast<std::size_t>(*index - 1)] = 1;
        }
        if (line.tokens.size() > 3 && linesWithExtraValues++ == 0)
            firstExtra = scanner.at(line.tokens[3]);
        mesh.triangles.push_back(tri);
        mesh.triangleLines.push_back(line.number);
    }

    if (linesWithExtraValues > 0)
        diagnostics.warn(firstExtra, "ignored extra values at the end of " +
                                         plural(linesWithExtraValues, "line", "lines") +
                                         " (the first is here)");
    if (scanner.next(line)) {
        const int remaining = 1 + scanner.countRemainingLines();
        diagnostics.warn(scanner.at(line.number, 1),
                         "ignored " + plural(remaining, "line", "lines") + " after the declared " +
                             plural(*vertexCount, "vertex", "vertices") + " and " +
                             plural(*triangleCount, "triangle", "triangles") +
                             " (the header's counts may be wrong, or a second object follows)");
    }
    long long unused = 0;
    for (unsigned char u : used) unused += u ? 0 : 1;
    if (unused > 0 && *triangleCount > 0)
        diagnostics.warn(mesh.source, plural(unused, "vertex", "vertices") + " of " +
                                          std::to_string(*vertexCount) +
                                          (unused == 1 ? " is" : " are") +
                                          " not used by any triangle");
    if (*triangleCount == 0) diagnostics.warn(mesh.source, "the object has no triangles");
    return mesh;
}

}  // namespace rl
