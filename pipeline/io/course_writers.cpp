#include "course_writers.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "pipeline/io/course_fields.h"
#include "pipeline/io/text_scanner.h"

namespace rl {

std::string formatExact(double value) {
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    if (ec != std::errc()) return "nan";  // not reached: 64 characters hold any double
    return std::string(buffer, end);
}

std::string formatExact(float value) {
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    if (ec == std::errc()) {
        std::string text(buffer, end);
        // The readers parse a double and narrow it: the float's shortest text, read as a
        // double, could in principle lie on the other side of a rounding boundary.
        const std::optional<double> back = parseReal(text);
        if (back && std::bit_cast<std::uint32_t>(static_cast<float>(*back)) ==
                        std::bit_cast<std::uint32_t>(value))
            return text;
    }
    return formatExact(static_cast<double>(value));
}

namespace {

// The line ending of a file's text: CRLF when it has one.
std::string_view lineEndingOf(std::string_view previous) {
    return previous.find("\r\n") != std::string_view::npos ? "\r\n" : "\n";
}

// The numbers of one line: "x y z".
template <typename Vec>
std::string numbers(const Vec& v) {
    std::string s;
    for (int k = 0; k < v.length(); ++k) {
        if (k > 0) s += ' ';
        s += formatExact(v[k]);
    }
    return s;
}

// kd: one number when the channels are equal (bit for bit, so that -0 and 0 stay apart),
// else three.
std::string scalarOrTriple(const vec3& v) {
    const auto bits = [](float f) { return std::bit_cast<std::uint32_t>(f); };
    if (bits(v.r) == bits(v.g) && bits(v.g) == bits(v.b)) return formatExact(v.r);
    return numbers(v);
}

// One field of a file: its key in a key = value file and its numbers.
struct Entry {
    std::string key;
    std::string value;
};

// The text of a line layout.
std::string joinLines(const std::vector<std::string>& lines, std::string_view eol) {
    std::string text;
    for (const std::string& line : lines) {
        text += line;
        text += eol;
    }
    return text;
}

bool sameKey(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

std::string_view trimmed(std::string_view s) {
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f'; };
    while (!s.empty() && space(s.front())) s.remove_prefix(1);
    while (!s.empty() && space(s.back())) s.remove_suffix(1);
    return s;
}

// A key = value file: `previous` with the lines of `entries`' keys replaced where they stand
// (a key given twice keeps its first place only), its lines of keys `dropped` says are no
// longer wanted (an optional key now at its default, a light removed) left out, its other
// lines kept, and the keys it lacks added at the end.
std::string writeKeyValues(const std::vector<Entry>& entries, std::string_view previous,
                           bool (*dropped)(std::string_view key) = nullptr) {
    const std::string_view eol = lineEndingOf(previous);
    std::vector<bool> written(entries.size(), false);
    std::string text;
    const auto writeEntry = [&](std::size_t i) {
        written[i] = true;
        text += std::string(entries[i].key) + " = " + entries[i].value;
        text += eol;
    };
    // A byte-order mark stays in front of the first line.
    if (previous.starts_with("\xEF\xBB\xBF")) {
        text += previous.substr(0, 3);
        previous.remove_prefix(3);
    }
    while (!previous.empty()) {
        const std::size_t newline = previous.find('\n');
        std::string_view line = previous.substr(0, newline);
        previous.remove_prefix(newline == std::string_view::npos ? previous.size() : newline + 1);
        if (line.ends_with('\r')) line.remove_suffix(1);
        const std::size_t equals = line.find('=');
        std::optional<std::size_t> entry;
        if (equals != std::string_view::npos) {
            const std::string_view key = trimmed(line.substr(0, equals));
            for (std::size_t i = 0; i < entries.size() && !entry; ++i)
                if (sameKey(key, entries[i].key)) entry = i;
        }
        if (!entry) {
            if (equals != std::string_view::npos && dropped &&
                dropped(trimmed(line.substr(0, equals))))
                continue;
            text += line;
            text += eol;
            continue;
        }
        // A repeated key (the reader refuses those) is dropped.
        if (!written[*entry]) writeEntry(*entry);
    }
    for (std::size_t i = 0; i < entries.size(); ++i)
        if (!written[i]) writeEntry(i);
    return text;
}

Error writeError(ErrorCode code, Message message) {
    return makeError(code, SourceLocation{}, std::move(message));
}

}  // namespace

Result<std::string> writeCameraFile(const CourseCamera& camera, CameraLayout layout,
                                    std::string_view previous) {
    if (!isFinite(camera.c) || !isFinite(camera.n) || !isFinite(camera.v) ||
        !isFinite(dvec3(camera.d, camera.hx, camera.hy)))
        return writeError(ErrorCode::Range,
                          "cannot write the camera: its values must be finite numbers (a course "
                          "file cannot hold nan or inf)"_msg);
    const std::string c = numbers(camera.c), n = numbers(camera.n), v = numbers(camera.v);
    const std::string d = formatExact(camera.d), hx = formatExact(camera.hx),
                      hy = formatExact(camera.hy);
    const std::string_view eol = lineEndingOf(previous);
    switch (layout) {
        case CameraLayout::Ufpe:
            return joinLines({c, n, v, d + ' ' + hx + ' ' + hy}, eol);
        case CameraLayout::Ufrpe6:
            return joinLines({n, v, d, hx, hy, c}, eol);
        case CameraLayout::Ufrpe5:
            return joinLines({c, n, v, hx + ' ' + hy, d}, eol);
        case CameraLayout::KeyValue:
            return writeKeyValues({{"C", c}, {"N", n}, {"V", v}, {"d", d}, {"hx", hx}, {"hy", hy}},
                                  previous);
        case CameraLayout::Auto:
            break;
    }
    return writeError(ErrorCode::Usage,
                      "cannot write a camera in the layout 'auto': choose UFPE, UFRPE or key = "
                      "value"_msg);
}

namespace {

// What only key = value files hold (the lecture slides' lighting, seed 003): the first such
// feature the lighting uses, or nothing when it uses none.
std::optional<MessageTemplate> beyondCourse(const CourseLighting& lighting) {
    std::optional<MessageTemplate> beyond;
    const auto use = [&](bool used, MessageTemplate what) {
        if (used && !beyond) beyond = what;
    };
    const Material& m = lighting.material;
    use(m.emission != vec3(0.0f), "an emission (Ke)"_msg);
    use(!lighting.twoSided, "one-sided lighting"_msg);
    use(lighting.specular != SpecularModel::Phong, "Blinn-Phong highlights"_msg);
    for (const Light& light : lighting.lights) {
        use(light.pWorld.w != 1.0, "a directional light (w = 0)"_msg);
        use(light.attenuation != vec3(1.0f, 0.0f, 0.0f), "an attenuated light"_msg);
        use(light.spot(), "a spot light"_msg);
    }
    return beyond;
}

bool isFiniteLighting(const CourseLighting& lighting) {
    const Material& m = lighting.material;
    bool finite = isFinite(vec3(m.ka, m.ks, m.shininess)) && isFinite(m.kd) && isFinite(m.od) &&
                  isFinite(lighting.ambientIntensity) && isFinite(m.emission);
    for (const Light& light : lighting.lights)
        finite = finite && isFinite(dvec3(light.pWorld)) && isFinite(light.intensity) &&
                 isFinite(light.attenuation) && isFinite(light.spotDirection) &&
                 isFinite(vec3(light.spotCutoff, light.spotExponent, 0.0f));
    return finite;
}

// Why the lighting cannot be written in `layout`, if it cannot: the layout's number of
// lights, what only key = value files hold, values that are not finite.
std::optional<Error> unwritableLighting(const CourseLighting& lighting, LightingLayout layout) {
    if (layout == LightingLayout::Auto)
        return writeError(ErrorCode::Usage,
                          "cannot write lighting in the layout 'auto': choose UFPE, UFPE "
                          "multi-light, UFRPE or key = value"_msg);
    const std::size_t count = lighting.lights.size();
    const bool keyValue = layout == LightingLayout::KeyValue;
    if (layout != LightingLayout::UfpeMulti && !(keyValue && count >= 1) && count != 1)
        return writeError(
            ErrorCode::Unsupported,
            (count == 1 ? "cannot write %1 light in the layout %2, which holds exactly one: choose "
                          "the UFPE multi-light layout or key = value"_msg
                        : "cannot write %1 lights in the layout %2, which holds exactly one: "
                          "choose the UFPE multi-light layout or key = value"_msg)(
                count, course_io::lightingLayoutText(layout)));
    if (count == 0)
        return writeError(ErrorCode::Unsupported,
                          "cannot write lighting without lights: the UFPE multi-light and key = "
                          "value layouts hold one light or more"_msg);
    if (keyValue && count > kMaxKeyValueLights)
        return writeError(ErrorCode::Unsupported,
                          "cannot write %1 lights in a key = value file, which holds %2 at most "
                          "(Pl to %3)"_msg(count, kMaxKeyValueLights,
                                           lightKeyName("Pl", kMaxKeyValueLights - 1)));
    if (const auto beyond = beyondCourse(lighting); !keyValue && beyond)
        return writeError(
            ErrorCode::Unsupported,
            "cannot write %1 in the layout %2, which holds the course's point "
            "lights only: choose key = value"_msg(*beyond, course_io::lightingLayoutText(layout)));
    if (!isFiniteLighting(lighting))
        return writeError(ErrorCode::Range,
                          "cannot write the lighting: its values must be finite numbers (a "
                          "course file cannot hold nan or inf)"_msg);
    return std::nullopt;
}

// The entries of a key = value lighting file: the course's keys in the course's order, then
// the slides' (only when used).
std::vector<Entry> lightingEntries(const CourseLighting& lighting) {
    const Material& m = lighting.material;
    const auto position = [](const Light& light) {
        return light.pWorld.w == 1.0 ? numbers(dvec3(light.pWorld)) : numbers(light.pWorld);
    };
    std::vector<Entry> entries = {{"Iamb", numbers(lighting.ambientIntensity)},
                                  {"Ka", formatExact(m.ka)},
                                  {"Il", numbers(lighting.lights[0].intensity)},
                                  {"Pl", position(lighting.lights[0])},
                                  {"Kd", numbers(m.kd)},
                                  {"Od", numbers(m.od)},
                                  {"Ks", formatExact(m.ks)},
                                  {"eta", formatExact(m.shininess)}};
    if (m.emission != vec3(0.0f)) entries.push_back({"Ke", numbers(m.emission)});
    if (!lighting.twoSided) entries.push_back({"two_sided", "0"});
    if (lighting.specular == SpecularModel::BlinnPhong) entries.push_back({"blinn", "1"});
    for (std::size_t k = 0; k < lighting.lights.size(); ++k) {
        const Light& light = lighting.lights[k];
        const auto key = [k](std::string_view base) { return lightKeyName(base, k); };
        if (k > 0) {
            entries.push_back({key("Il"), numbers(light.intensity)});
            entries.push_back({key("Pl"), position(light)});
        }
        if (light.attenuation != vec3(1.0f, 0.0f, 0.0f))
            entries.push_back({key("atten"), numbers(light.attenuation)});
        if (light.spot()) {
            entries.push_back({key("spot_dir"), numbers(light.spotDirection)});
            entries.push_back({key("spot_cutoff"), formatExact(light.spotCutoff)});
            if (light.spotExponent != 0.0f)
                entries.push_back({key("spot_exp"), formatExact(light.spotExponent)});
        }
    }
    return entries;
}

}  // namespace

Result<std::string> writeLightingFile(const CourseLighting& lighting, LightingLayout layout,
                                      std::string_view previous) {
    if (auto error = unwritableLighting(lighting, layout)) return *error;
    const Material& m = lighting.material;
    const std::string ka = formatExact(m.ka), ia = numbers(lighting.ambientIntensity),
                      od = numbers(m.od), ks = formatExact(m.ks), n = formatExact(m.shininess);
    const std::string pl = numbers(dvec3(lighting.lights[0].pWorld)),
                      il = numbers(lighting.lights[0].intensity);
    const std::string_view eol = lineEndingOf(previous);
    switch (layout) {
        case LightingLayout::Ufpe:
            return joinLines({pl, ka, ia, scalarOrTriple(m.kd), od, ks, il, n}, eol);
        case LightingLayout::UfpeMulti: {
            std::vector<std::string> lines = {
                ka, ia, scalarOrTriple(m.kd), od, ks, n, std::to_string(lighting.lights.size())};
            for (const Light& light : lighting.lights) {
                lines.push_back(numbers(dvec3(light.pWorld)));
                lines.push_back(numbers(light.intensity));
            }
            return joinLines(lines, eol);
        }
        case LightingLayout::Ufrpe:
            return joinLines({ia, ka, il, pl, numbers(m.kd), od, ks, n}, eol);
        case LightingLayout::KeyValue:
            return writeKeyValues(lightingEntries(lighting), previous, isLightingKey);
        case LightingLayout::Auto:
            break;
    }
    return writeError(ErrorCode::Usage, "cannot write lighting in the layout 'auto'"_msg);
}

}  // namespace rl
