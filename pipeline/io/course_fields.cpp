// The helpers the course readers share (course_fields.h): number tokens and their messages,
// field lines, the camera and lighting built from fields, and the tokens of .byu files.
#include "course_fields.h"

#include <cctype>
#include <charconv>

#include "pipeline/core/format.h"

namespace rl::course_io {

namespace {

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

bool startsLikeNumber(std::string_view token) {
    const char c = token.empty() ? ' ' : token.front();
    return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.';
}

}  // namespace

Message countText(unsigned counts) {
    std::vector<int> accepted;
    for (int k = 0; k < 32; ++k)
        if (counts & (1u << k)) accepted.push_back(k);
    if (accepted.size() == 1) return numbersText(accepted[0]);
    std::string first;  // "1, 2" of "1, 2 or 3 numbers"
    for (std::size_t i = 0; i + 1 < accepted.size(); ++i)
        first += (i > 0 ? ", " : "") + std::to_string(accepted[i]);
    return "%1 or %2 numbers"_msg(first, accepted.back());
}

int maxCount(unsigned counts) {
    int m = 0;
    for (int k = 0; k < 32; ++k)
        if (counts & (1u << k)) m = k;
    return m;
}

Message linesText(long long n) {
    return counted(n, "%1 line"_msg, "%1 lines"_msg);
}

Message valuesText(long long n) {
    return counted(n, "%1 value"_msg, "%1 values"_msg);
}

Message verticesText(long long n) {
    return counted(n, "%1 vertex"_msg, "%1 vertices"_msg);
}

Message trianglesText(long long n) {
    return counted(n, "%1 triangle"_msg, "%1 triangles"_msg);
}

Message numbersText(long long n) {
    return counted(n, "%1 number"_msg, "%1 numbers"_msg);
}

Message fieldName(const FieldSpec& field) {
    if (field.light == 0) return Message::untranslated(std::string(field.name));
    return "%1 of light %2"_msg(field.name, field.light);
}

// The token without one leading sign.
std::string_view withoutSign(std::string_view token) {
    if (!token.empty() && (token.front() == '+' || token.front() == '-')) token.remove_prefix(1);
    return token;
}

// Why a token is not a number, for the end of an error message.
Message whyNotNumber(std::string_view token) {
    const std::string found = quoted(token);
    const bool hasDigit = token.find_first_of("0123456789") != std::string_view::npos;
    if (token.size() > 1 && token.back() == ',' && parseReal(token.substr(0, token.size() - 1)))
        return "found %1 (separate the values with spaces, not commas)"_msg(found);
    if (token.find(',') != std::string_view::npos && hasDigit)
        return "found %1 (the decimal separator is '.')"_msg(found);
    if (isOutOfRange(token)) return "found %1, which is out of range"_msg(found);
    if (isNotFinite(token)) return "found %1, which is not a finite number"_msg(found);
    return "found %1"_msg(found);
}

// "a, b and c".
Message listText(const std::vector<Message>& items) {
    if (items.empty()) return {};
    Message list = items[0];
    for (std::size_t i = 1; i < items.size(); ++i)
        list = (i + 1 == items.size() ? "%1 and %2"_msg : "%1, %2"_msg)(list, items[i]);
    return list;
}

Message listText(const std::vector<std::string>& names) {
    std::vector<Message> items;
    for (const std::string& name : names) items.push_back(Message::untranslated(name));
    return listText(items);
}

// ---- field lines

// The fields of readFieldLines, without the check for lines after the last one.
Result<std::vector<FieldValue>> readFields(LineScanner& scanner, std::span<const FieldSpec> fields,
                                           Diagnostics& diagnostics) {
    std::vector<FieldValue> result;
    result.reserve(fields.size());
    TextLine line;
    for (const FieldSpec& field : fields) {
        if (!scanner.next(line))
            return makeError(ErrorCode::MissingData, scanner.endOfInput(),
                             "expected %1, %2 (%3), found the end of the file"_msg(
                                 fieldName(field), field.description, countText(field.counts)));

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
                return makeError(
                    ErrorCode::Syntax, scanner.at(bad),
                    "expected a number for %1, %2"_msg(fieldName(field), whyNotNumber(bad.text)));
            }
            if (!(field.counts & (1u << available)))
                return makeError(ErrorCode::Syntax, scanner.afterLast(line),
                                 "expected %1 for %2, found %3"_msg(countText(field.counts),
                                                                    fieldName(field), available));
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
                             "ignored %1 after %2"_msg(valuesText(static_cast<long long>(extra)),
                                                       fieldName(field)));
        }
        result.push_back(std::move(value));
    }
    return result;
}

// A warning for the lines after the `lineCount` lines of a layout, if any.
void warnTrailingLines(LineScanner& scanner, MessageTemplate what, long long lineCount,
                       Diagnostics& diagnostics) {
    TextLine line;
    if (!scanner.next(line)) return;
    const int remaining = 1 + scanner.countRemainingLines();
    diagnostics.warn(scanner.at(line.number, 1),
                     "ignored %1 after %2"_msg(linesText(remaining), what(linesText(lineCount))));
}

// ---- the camera and the lighting, from the fields of any layout

dvec3 vec3Of(const FieldValue& f) {
    return dvec3(f.values[0], f.values[1], f.values[2]);
}

vec3 rgbOf(const FieldValue& f) {
    if (f.values.size() == 1) return vec3(static_cast<float>(f.values[0]));
    return vec3(static_cast<float>(f.values[0]), static_cast<float>(f.values[1]),
                static_cast<float>(f.values[2]));
}

CourseCamera makeCamera(const FieldValue& c, const FieldValue& n, const FieldValue& v, Scalar d,
                        Scalar hx, Scalar hy) {
    CourseCamera camera;
    camera.c = vec3Of(c);
    camera.n = vec3Of(n);
    camera.v = vec3Of(v);
    camera.d = d.field->values[d.index];
    camera.hx = hx.field->values[hx.index];
    camera.hy = hy.field->values[hy.index];
    camera.where = {c.line,
                    n.line,
                    v.line,
                    d.field->where[d.index],
                    hx.field->where[hx.index],
                    hy.field->where[hy.index]};
    return camera;
}

// Values outside the ranges the course gives (seed 004) still render, with a warning.
void checkRange(const FieldValue& field, const std::string& name, std::size_t light, double low,
                double high, const char* range, Diagnostics& diagnostics) {
    for (std::size_t i = 0; i < field.values.size(); ++i) {
        const double v = field.values[i];
        if (v >= low && v <= high) continue;
        std::string label = name;
        if (field.values.size() == 3) label += std::string(".") + "rgb"[i];
        diagnostics.warn(
            field.where[i],
            light == 0 ? "%1 = %2 is outside %3, the range the course gives for it"_msg(
                             label, formatNumber(v), range)
                       : "%1 of light %2 = %3 is outside %4, the range the course gives for it"_msg(
                             label, light, formatNumber(v), range));
    }
}

// The lighting, with the course's range warnings, in the order ka, Ia, kd, Od, ks, Il, n.
CourseLighting makeLighting(const LightingFields& f, const LightingNames& names,
                            Diagnostics& diagnostics) {
    CourseLighting lighting;
    const bool numbered = f.lights.size() > 1;
    for (const auto& [pl, il] : f.lights) {
        Light light;
        light.pWorld = dvec4(vec3Of(*pl), 1.0);
        light.intensity = rgbOf(*il);
        light.where = pl->line;
        lighting.lights.push_back(light);
    }
    lighting.material.ka = static_cast<float>(f.ka->values[0]);
    lighting.ambientIntensity = rgbOf(*f.ia);
    lighting.material.kd = rgbOf(*f.kd);
    lighting.material.od = rgbOf(*f.od);
    lighting.material.ks = static_cast<float>(f.ks->values[0]);
    lighting.material.shininess = static_cast<float>(f.n->values[0]);

    checkRange(*f.ka, names.ka, 0, 0.0, 1.0, "[0, 1]", diagnostics);
    checkRange(*f.ia, names.ia, 0, 0.0, 255.0, "[0, 255]", diagnostics);
    checkRange(*f.kd, names.kd, 0, 0.0, 1.0, "[0, 1]", diagnostics);
    checkRange(*f.od, names.od, 0, 0.0, 1.0, "[0, 1]", diagnostics);
    checkRange(*f.ks, names.ks, 0, 0.0, 1.0, "[0, 1]", diagnostics);
    for (std::size_t k = 0; k < f.lights.size(); ++k)
        checkRange(*f.lights[k].second, names.il, numbered ? k + 1 : 0, 0.0, 255.0, "[0, 255]",
                   diagnostics);
    const double n = f.n->values[0];
    if (!(n > 0.0))
        diagnostics.warn(f.n->where[0],
                         "%1 = %2 is not positive: (R.V)^n then makes no highlight (it is 1 "
                         "everywhere for n = 0 and grows without bound where R.V nears 0 for n "
                         "< 0, where the specular term is left out)"_msg(names.n, formatNumber(n)));
    return lighting;
}

// ---- .byu tokens

// Reads a header count: a non-negative integer.
Result<long long> readCount(const LineScanner& scanner, const Token& token, const Message& what) {
    const auto n = parseInteger(token.text);
    if (!n || *n < 0)
        return makeError(ErrorCode::Syntax, scanner.at(token),
                         "expected the number of %1 (a non-negative integer), found %2"_msg(
                             what, quoted(token.text)));
    return *n;
}

bool isComment(const Token& token) {
    return token.text.starts_with('#') || token.text.starts_with("//");
}

Error commentError(const LineScanner& scanner, const Token& token, const Message& expected) {
    return makeError(ErrorCode::Syntax, scanner.at(token),
                     "expected %1, found a comment (%2), but .byu files have no comments"_msg(
                         expected, quoted(token.text)));
}

Result<double> readCoordinate(const LineScanner& scanner, const Token& token, int axis,
                              const Message& which) {
    static const char* const kAxis[] = {"x", "y", "z"};
    const auto value = parseReal(token.text);
    if (!value)
        return makeError(ErrorCode::Syntax, scanner.at(token),
                         "expected a number for the %1 coordinate of %2, %3"_msg(
                             kAxis[axis], which, whyNotNumber(token.text)));
    return *value;
}

Result<dvec3> readPointLine(const LineScanner& scanner, const TextLine& line,
                            const Message& which) {
    if (isComment(line.tokens[0]))
        return commentError(scanner, line.tokens[0], "%1 (x y z)"_msg(which));
    dvec3 p(0.0);
    for (int k = 0; k < 3; ++k) {
        if (static_cast<std::size_t>(k) >= line.tokens.size())
            return makeError(ErrorCode::Syntax, scanner.afterLast(line),
                             "expected 3 coordinates for %1, found %2"_msg(which, k));
        auto value = readCoordinate(scanner, line.tokens[static_cast<std::size_t>(k)], k, which);
        if (!value) return value.error();
        p[k] = *value;
    }
    return p;
}

void ExtraValues::note(const LineScanner& scanner, const TextLine& line) {
    if (line.tokens.size() > 3 && lines++ == 0) first = scanner.at(line.tokens[3]);
}

void ExtraValues::warn(Diagnostics& diagnostics) const {
    if (lines > 0)
        diagnostics.warn(first, "ignored extra values at the end of %1 (the first is here)"_msg(
                                    linesText(lines)));
}

// "used by no triangle" and "no triangles" warnings, as for course meshes.
void warnUnusedVertices(const Mesh& mesh, const std::vector<unsigned char>& used,
                        Diagnostics& diagnostics) {
    long long unused = 0;
    for (unsigned char u : used) unused += u ? 0 : 1;
    const auto vertexCount = static_cast<long long>(mesh.positions.size());
    if (unused > 0 && !mesh.triangles.empty())
        diagnostics.warn(
            mesh.source,
            unused == 1
                ? "%1 vertex of %2 is not used by any triangle"_msg(unused, vertexCount)
                : "%1 vertices of %2 are not used by any triangle"_msg(unused, vertexCount));
    if (mesh.triangles.empty()) diagnostics.warn(mesh.source, "the object has no triangles"_msg);
}

}  // namespace rl::course_io

namespace rl {

Result<std::vector<FieldValue>> readFieldLines(LineScanner& scanner,
                                               std::span<const FieldSpec> fields,
                                               MessageTemplate what, Diagnostics& diagnostics) {
    auto result = course_io::readFields(scanner, fields, diagnostics);
    if (result)
        course_io::warnTrailingLines(scanner, what, static_cast<long long>(fields.size()),
                                     diagnostics);
    return result;
}

}  // namespace rl
