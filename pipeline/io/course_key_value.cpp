// Key = value camera and lighting files: "C = x y z", "Pl2 = ..." in any order, in any case,
// camera and lighting keys in one file or two; the lighting may use the lecture slides' keys.
#include <algorithm>
#include <cctype>
#include <optional>
#include <span>

#include "pipeline/core/format.h"
#include "pipeline/io/course_fields.h"

namespace rl {

using namespace course_io;  // the helpers the course readers share

namespace {

struct KeySpec {
    std::string_view key;  // as the course writes it; matched without regard to case
    MessageTemplate description;
    unsigned counts;
    bool required = true;   // every file has it (for the first light, when perLight)
    bool perLight = false;  // one per light: "Pl" (or "Pl1") for the first, "Pl2" ...
};

constexpr int kMaxKeyLights = static_cast<int>(kMaxKeyValueLights);

constexpr KeySpec kCameraKeys[] = {
    {"C", "the camera position"_msg, kThree},
    {"N", "the view direction"_msg, kThree},
    {"V", "the up vector"_msg, kThree},
    {"d", "the projection distance"_msg, kOne},
    {"hx", "the horizontal half-size of the window"_msg, kOne},
    {"hy", "the vertical half-size of the window"_msg, kOne},
};
constexpr KeySpec kLightingKeys[] = {
    {"Iamb", "the ambient light colour"_msg, kThree},
    {"Ka", "the ambient coefficient"_msg, kOne},
    {"Il", "the light colour"_msg, kThree, true, true},
    {"Pl", "the light position (x y z, or x y z w: w = 0 for a directional light)"_msg,
     kThree | kFour, true, true},
    {"Kd", "the diffuse coefficient of each channel"_msg, kThree},
    {"Od", "the diffuse colour of the object"_msg, kThree},
    {"Ks", "the specular coefficient"_msg, kOne},
    {"eta", "the specular exponent"_msg, kOne},
    // The lecture slides' lighting (seed 003), beyond the course's files.
    {"Ke", "the emission of the object"_msg, kThree, false},
    {"two_sided", "two-sided lighting, 1 or 0"_msg, kOne, false},
    {"blinn", "Blinn-Phong highlights, 1 or 0"_msg, kOne, false},
    {"atten", "the attenuation kc kl kq"_msg, kThree, false, true},
    {"spot_dir", "the spot direction"_msg, kThree, false, true},
    {"spot_cutoff", "the spot cutoff angle in degrees"_msg, kOne, false, true},
    {"spot_exp", "the spot exponent"_msg, kOne, false, true},
};
// Index of each in kLightingKeys.
enum LightingKey : std::size_t {
    kIamb,
    kKa,
    kIl,
    kPl,
    kKd,
    kOd,
    kKs,
    kEta,
    kKe,
    kTwoSided,
    kBlinn,
    kAtten,
    kSpotDir,
    kSpotCutoff,
    kSpotExp,
    kLightingKeyCount
};
constexpr std::string_view kUnusedCameraKey = "U";  // a dummy some camera files carry

bool sameKey(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

// A key of `keys` and the light it is for (0 for the first): "Pl" and "Pl1" are the first
// light's, "Pl2" the second's, for the keys given per light.
struct KeyMatch {
    std::size_t index = 0;
    int light = 0;
};

std::optional<KeyMatch> findKey(std::span<const KeySpec> keys, std::string_view key) {
    for (std::size_t i = 0; i < keys.size(); ++i) {
        if (sameKey(keys[i].key, key)) return KeyMatch{i, 0};
        const std::size_t base = keys[i].key.size();
        if (keys[i].perLight && key.size() == base + 1 &&
            sameKey(keys[i].key, key.substr(0, base)) && key[base] >= '1' &&
            key[base] < '1' + kMaxKeyLights)
            return KeyMatch{i, key[base] - '1'};
    }
    return std::nullopt;
}

std::string keyName(const KeySpec& key, int light) {
    return lightKeyName(key.key, static_cast<std::size_t>(light));
}

// The keys every file has, "C, N, V, d, hx and hy".
Message keyList(std::span<const KeySpec> keys) {
    std::vector<std::string> names;
    for (const KeySpec& key : keys)
        if (key.required) names.emplace_back(key.key);
    return listText(names);
}

// keyList, then the keys a file may have: "...; optionally Ke, ... (Pl2, Il2 ... for more
// lights)".
Message keyListWithOptional(std::span<const KeySpec> keys) {
    std::vector<std::string> optional;
    bool perLight = false;
    for (const KeySpec& key : keys) {
        if (!key.required) optional.emplace_back(key.key);
        perLight = perLight || key.perLight;
    }
    if (optional.empty()) return keyList(keys);
    if (!perLight) return "%1; optionally %2"_msg(keyList(keys), listText(optional));
    return "%1; optionally %2; Pl2, Il2 ... for lights 2 to %3"_msg(
        keyList(keys), listText(optional), kMaxKeyLights);
}

// The keys a reader reads (the camera's or the lighting's), and the other reader's, which
// the same file may hold.
struct KeyRoles {
    std::span<const KeySpec> keys;
    std::span<const KeySpec> otherKeys;
    bool isCamera;  // the camera's reader; the lighting's otherwise
};

// A line "key = values", split at its first '=', which may touch the key or the values.
struct KeyLine {
    std::string key;
    SourceLocation keyAt;
    std::vector<Token> values;
};

Result<KeyLine> splitKeyLine(const LineScanner& scanner, const TextLine& line) {
    std::size_t at = 0;
    std::size_t equals = std::string_view::npos;
    for (; at < line.tokens.size(); ++at) {
        equals = line.tokens[at].text.find('=');
        if (equals != std::string_view::npos) break;
    }
    if (at == line.tokens.size())
        return makeError(ErrorCode::Syntax, scanner.at(line.tokens[0]),
                         (line.tokens.size() > 1
                              ? "expected 'key = value', found a line without '=' (%1 ...)"_msg
                              : "expected 'key = value', found a line without '=' (%1)"_msg)(
                             quoted(line.tokens[0].text)));
    KeyLine result;
    std::size_t keyWords = 0;
    for (std::size_t k = 0; k <= at; ++k) {
        const std::string_view part =
            k < at ? line.tokens[k].text : line.tokens[k].text.substr(0, equals);
        if (part.empty()) continue;
        if (keyWords++ > 0) result.key += ' ';
        result.key += part;
    }
    result.keyAt = scanner.at(line.tokens[0]);
    if (keyWords == 0)
        return makeError(ErrorCode::Syntax, result.keyAt,
                         "expected a key before '=', found nothing"_msg);
    if (keyWords > 1)
        return makeError(ErrorCode::Syntax, result.keyAt,
                         "expected one key before '=', found %1"_msg(quoted(result.key)));
    const Token& split = line.tokens[at];
    if (equals + 1 < split.text.size())
        result.values.push_back({split.text.substr(equals + 1), split.line,
                                 split.column + static_cast<int>(equals) + 1});
    result.values.insert(result.values.end(),
                         line.tokens.begin() + static_cast<std::ptrdiff_t>(at) + 1,
                         line.tokens.end());
    return result;
}

// A key the reader does not read: the other role's is skipped, the camera's dummy U with a
// note, any other with a warning. True for the other role's.
bool skipKey(const KeyLine& line, const KeyRoles& roles, Diagnostics& diagnostics) {
    if (findKey(roles.otherKeys, line.key)) return true;
    if (sameKey(line.key, kUnusedCameraKey)) {
        if (roles.isCamera)
            diagnostics.note(line.keyAt,
                             "ignored %1: the camera's axes come from N and V"_msg(line.key));
    } else {
        diagnostics.warn(
            line.keyAt,
            (roles.isCamera
                 ? "ignored the unknown key %1 (a camera has %2; a lighting file has %3)"_msg
                 : "ignored the unknown key %1 (a lighting file has %2; a camera has %3)"_msg)(
                quoted(line.key), keyListWithOptional(roles.keys),
                keyListWithOptional(roles.otherKeys)));
    }
    return false;
}

// The numbers after the '=' of `line`, as many as `key` accepts; `name` is the key as
// written for its light ("Pl2").
Status readKeyNumbers(const LineScanner& scanner, const TextLine& line, const KeyLine& keyLine,
                      const KeySpec& key, const std::string& name, FieldValue& value) {
    value.line = scanner.at(line.number, 1);
    for (const Token& token : keyLine.values) {
        const auto number = parseReal(token.text);
        if (!number)
            return makeError(ErrorCode::Syntax, scanner.at(token),
                             "expected a number for %1, %2"_msg(name, whyNotNumber(token.text)));
        value.values.push_back(*number);
        value.where.push_back(scanner.at(token));
    }
    const int count = static_cast<int>(value.values.size());
    const int most = maxCount(key.counts);
    if (count > most)
        return makeError(ErrorCode::Syntax, value.where[static_cast<std::size_t>(most)],
                         "expected %1 for %2, found %3"_msg(countText(key.counts), name, count));
    if (!(key.counts & (1u << count)))
        return makeError(
            ErrorCode::Syntax, scanner.afterLast(line),
            count == 0 ? "expected %1 for %2, found none"_msg(countText(key.counts), name)
                       : "expected %1 for %2, found %3"_msg(countText(key.counts), name, count));
    return success();
}

// The error for the keys every file has that this one lacks (`givenOn` is 0 for them), if
// any.
std::optional<Error> missingKeys(const LineScanner& scanner, const KeyRoles& roles,
                                 const std::vector<int>& givenOn, bool otherRoleSeen) {
    const std::span<const KeySpec> keys = roles.keys;
    std::vector<std::string> missing;
    std::size_t required = 0;
    for (std::size_t i = 0; i < keys.size(); ++i) {
        required += keys[i].required ? 1 : 0;
        if (keys[i].required && givenOn[i] == 0) missing.emplace_back(keys[i].key);
    }
    if (missing.empty()) return std::nullopt;
    Message message;
    if (missing.size() == required && roles.isCamera) {
        message =
            (otherRoleSeen
                 ? "expected the camera keys %1, found none of them (only lighting file keys)"_msg
                 : "expected the camera keys %1, found none of them"_msg)(keyList(keys));
    } else if (missing.size() == required) {
        message =
            (otherRoleSeen
                 ? "expected the lighting file keys %1, found none of them (only camera keys)"_msg
                 : "expected the lighting file keys %1, found none of them"_msg)(keyList(keys));
    } else if (missing.size() == 1) {
        const KeySpec& key = keys[findKey(keys, missing[0])->index];
        message = "expected a line '%1 = ...' (%2, %3), found no %1"_msg(
            missing[0], key.description, countText(key.counts));
    } else {
        message =
            (roles.isCamera ? "expected lines for %1 (a camera needs %2), found none"_msg
                            : "expected lines for %1 (a lighting file needs %2), found none"_msg)(
                listText(missing), keyList(keys));
    }
    return makeError(ErrorCode::MissingData, scanner.endOfInput(), message);
}

// The keys of one role (camera or lighting) from a key = value file, in the order of `keys`.
// Keys of the other role are skipped; keys of neither are skipped with a warning.
Result<std::vector<FieldValue>> readKeyValues(std::string_view text, const std::string& fileName,
                                              const KeyRoles& roles, Diagnostics& diagnostics) {
    LineScanner scanner(text, fileName);
    const std::size_t n = roles.keys.size();
    // Key i of light k at i + n k.
    std::vector<FieldValue> values(n * kMaxKeyLights);
    std::vector<int> givenOn(n * kMaxKeyLights, 0);  // the line each was given on, 0 when not yet
    bool otherRoleSeen = false;
    TextLine line;
    while (scanner.next(line)) {
        auto keyLine = splitKeyLine(scanner, line);
        if (!keyLine) return keyLine.error();
        const auto match = findKey(roles.keys, keyLine->key);
        if (!match) {
            otherRoleSeen = skipKey(*keyLine, roles, diagnostics) || otherRoleSeen;
            continue;
        }
        const KeySpec& key = roles.keys[match->index];
        const std::size_t slot = match->index + n * static_cast<std::size_t>(match->light);
        const std::string name = keyName(key, match->light);
        if (givenOn[slot] != 0)
            return makeError(ErrorCode::Syntax, keyLine->keyAt,
                             "expected each key once, found %1 again (first given on line %2)"_msg(
                                 name, givenOn[slot]));
        givenOn[slot] = line.number;
        if (Status read = readKeyNumbers(scanner, line, *keyLine, key, name, values[slot]); !read)
            return read.error();
    }
    if (auto missing = missingKeys(scanner, roles, givenOn, otherRoleSeen)) return *missing;
    return values;
}

constexpr LightingNames kKeyValueNames = {"Ka", "Iamb", "Kd", "Od", "Ks", "Il", "eta"};

// A key = value lighting file's values (readKeyValues over kLightingKeys), by key and light.
class LightingValues {
public:
    explicit LightingValues(const std::vector<FieldValue>& values) : m_values(values) {}

    const FieldValue& at(std::size_t key, int light) const {
        return m_values[key + kLightingKeyCount * static_cast<std::size_t>(light)];
    }
    bool given(std::size_t key, int light) const { return !at(key, light).values.empty(); }
    static std::string name(std::size_t key, int light) {
        return keyName(kLightingKeys[key], light);
    }

private:
    const std::vector<FieldValue>& m_values;
};

// The course's keys, and the lights: Pl and Il, then lights 2 ... numbered without gaps,
// each with its Pl and Il.
Result<LightingFields> courseFields(const LightingValues& v) {
    LightingFields parts;
    parts.ia = &v.at(kIamb, 0);
    parts.ka = &v.at(kKa, 0);
    parts.kd = &v.at(kKd, 0);
    parts.od = &v.at(kOd, 0);
    parts.ks = &v.at(kKs, 0);
    parts.n = &v.at(kEta, 0);
    parts.lights = {{&v.at(kPl, 0), &v.at(kIl, 0)}};
    for (int k = 1; k < kMaxKeyLights; ++k) {
        std::optional<std::size_t> first;
        for (std::size_t key = 0; key < kLightingKeyCount; ++key)
            if (kLightingKeys[key].perLight && v.given(key, k) &&
                (!first || v.at(key, k).line.line < v.at(*first, k).line.line))
                first = key;
        if (!first) continue;
        const int expected = static_cast<int>(parts.lights.size());
        if (k != expected)
            return makeError(
                ErrorCode::Syntax, v.at(*first, k).line,
                "expected light %1 (%2, %3) before light %4, found %5 (lights are "
                "numbered without gaps)"_msg(expected + 1, v.name(kPl, expected),
                                             v.name(kIl, expected), k + 1, v.name(*first, k)));
        for (const std::size_t key : {std::size_t(kPl), std::size_t(kIl)})
            if (!v.given(key, k))
                return makeError(ErrorCode::MissingData, v.at(*first, k).line,
                                 "expected a line '%1 = ...' (%2 of light %3), found %4 without "
                                 "it"_msg(v.name(key, k), kLightingKeys[key].description, k + 1,
                                          v.name(*first, k)));
        parts.lights.emplace_back(&v.at(kPl, k), &v.at(kIl, k));
    }
    return parts;
}

// A flag of the lecture slides, 1 or 0, if given.
Result<std::optional<bool>> readFlag(const LightingValues& v, std::size_t key) {
    if (!v.given(key, 0)) return std::optional<bool>();
    const double value = v.at(key, 0).values[0];
    if (value != 0.0 && value != 1.0)
        return makeError(
            ErrorCode::Range, v.at(key, 0).where[0],
            "expected 1 or 0 for %1, found %2"_msg(v.name(key, 0), formatNumber(value)));
    return std::optional<bool>(value == 1.0);
}

// The lecture slides' keys for the whole lighting: two_sided, blinn and Ke.
Status readSlidesLighting(const LightingValues& v, CourseLighting& lighting,
                          Diagnostics& diagnostics) {
    auto twoSided = readFlag(v, kTwoSided);
    if (!twoSided) return twoSided.error();
    if (twoSided.value()) lighting.twoSided = *twoSided.value();
    auto blinn = readFlag(v, kBlinn);
    if (!blinn) return blinn.error();
    if (blinn.value() && *blinn.value()) lighting.specular = SpecularModel::BlinnPhong;
    if (v.given(kKe, 0)) {
        lighting.material.emission = rgbOf(v.at(kKe, 0));
        checkRange(v.at(kKe, 0), "Ke", 0, 0.0, 255.0, "[0, 255]", diagnostics);
    }
    return success();
}

// atten of one light: kc kl kq, none negative, not all 0.
Status readAttenuation(const LightingValues& v, int light, Light& l, Diagnostics& diagnostics) {
    if (!v.given(kAtten, light)) return success();
    const FieldValue& a = v.at(kAtten, light);
    const std::string name = v.name(kAtten, light);
    for (std::size_t i = 0; i < 3; ++i)
        if (!(a.values[i] >= 0.0))
            return makeError(ErrorCode::Range, a.where[i],
                             "expected %1 coefficients of 0 or more (kc kl kq), found %2"_msg(
                                 name, formatNumber(a.values[i])));
    if (a.values[0] == 0.0 && a.values[1] == 0.0 && a.values[2] == 0.0)
        return makeError(
            ErrorCode::Range, a.where[0],
            "expected %1 with a coefficient above 0, found 0 0 0 (1 / 0 light)"_msg(name));
    l.attenuation = rgbOf(a);
    if (l.pWorld.w == 0.0)
        diagnostics.warn(
            a.line, "%1 has no effect: a directional light (w = 0) is not attenuated"_msg(name));
    return success();
}

// spot_dir, spot_cutoff and spot_exp of one light, in the ranges OpenGL allows.
Status readSpot(const LightingValues& v, int light, Light& l, Diagnostics& diagnostics) {
    if (v.given(kSpotDir, light)) {
        const FieldValue& d = v.at(kSpotDir, light);
        if (vec3Of(d) == dvec3(0.0))
            return makeError(
                ErrorCode::Range, d.where[0],
                "expected a spot direction other than 0 0 0 for %1"_msg(v.name(kSpotDir, light)));
        l.spotDirection = vec3Of(d);
    }
    if (v.given(kSpotCutoff, light)) {
        const FieldValue& c = v.at(kSpotCutoff, light);
        const double cutoff = c.values[0];
        if (!((cutoff >= 0.0 && cutoff <= 90.0) || cutoff == 180.0))
            return makeError(ErrorCode::Range, c.where[0],
                             "expected %1 from 0 to 90 degrees, or 180 (not a spot), found %2"_msg(
                                 v.name(kSpotCutoff, light), formatNumber(cutoff)));
        l.spotCutoff = static_cast<float>(cutoff);
        if (l.spot() && !v.given(kSpotDir, light))
            diagnostics.note(c.line, "%1: no %2, the spot points along -z (OpenGL's default)"_msg(
                                         v.name(kSpotCutoff, light), v.name(kSpotDir, light)));
    }
    if (v.given(kSpotExp, light)) {
        const FieldValue& e = v.at(kSpotExp, light);
        if (!(e.values[0] >= 0.0 && e.values[0] <= 128.0))
            return makeError(ErrorCode::Range, e.where[0],
                             "expected %1 from 0 to 128, found %2"_msg(v.name(kSpotExp, light),
                                                                       formatNumber(e.values[0])));
        l.spotExponent = static_cast<float>(e.values[0]);
    }
    if (!l.spot() && (v.given(kSpotDir, light) || v.given(kSpotExp, light)))
        diagnostics.warn(v.at(v.given(kSpotDir, light) ? kSpotDir : kSpotExp, light).line,
                         "light %1 is not a spot without %2 (0 to 90 degrees): its spot direction "
                         "and exponent are unused"_msg(light + 1, v.name(kSpotCutoff, light)));
    return success();
}

// The lecture slides' keys of one light: w, attenuation and spot.
Status readSlidesLight(const LightingValues& v, int light, Light& l, Diagnostics& diagnostics) {
    const FieldValue& pl = v.at(kPl, light);
    if (pl.values.size() == 4) {
        // Homogeneous, as GL_POSITION: w = 0 a direction toward the light, otherwise the
        // point (x/w, y/w, z/w).
        const double w = pl.values[3];
        l.pWorld = w == 0.0 ? dvec4(vec3Of(pl), 0.0) : dvec4(vec3Of(pl) / w, 1.0);
    }
    if (Status read = readAttenuation(v, light, l, diagnostics); !read) return read;
    return readSpot(v, light, l, diagnostics);
}

// A key = value lighting file's values (readKeyValues over kLightingKeys): the course's keys,
// then the lecture slides' (emission, two-sided, Blinn-Phong, more lights, w, attenuation,
// spots), each checked against the range OpenGL allows it.
Result<CourseLighting> keyValueLighting(const std::vector<FieldValue>& values,
                                        Diagnostics& diagnostics) {
    const LightingValues v(values);
    auto parts = courseFields(v);
    if (!parts) return parts.error();
    CourseLighting lighting = makeLighting(*parts, kKeyValueNames, diagnostics);
    if (Status read = readSlidesLighting(v, lighting, diagnostics); !read) return read.error();
    for (std::size_t k = 0; k < lighting.lights.size(); ++k)
        if (Status read = readSlidesLight(v, static_cast<int>(k), lighting.lights[k], diagnostics);
            !read)
            return read.error();
    return lighting;
}

}  // namespace

std::string lightKeyName(std::string_view key, std::size_t light) {
    return std::string(key) + (light > 0 ? std::to_string(light + 1) : std::string());
}

bool isLightingKey(std::string_view key) {
    return findKey(kLightingKeys, key).has_value();
}

Result<CourseCamera> course_io::readKeyValueCamera(std::string_view text,
                                                   const std::string& fileName,
                                                   Diagnostics& diagnostics) {
    const KeyRoles roles{kCameraKeys, kLightingKeys, true};
    auto f = readKeyValues(text, fileName, roles, diagnostics);
    if (!f) return f.error();
    const auto& v = f.value();
    return makeCamera(v[0], v[1], v[2], {&v[3], 0}, {&v[4], 0}, {&v[5], 0});
}

Result<CourseLighting> course_io::readKeyValueLighting(std::string_view text,
                                                       const std::string& fileName,
                                                       Diagnostics& diagnostics) {
    const KeyRoles roles{kLightingKeys, kCameraKeys, false};
    auto f = readKeyValues(text, fileName, roles, diagnostics);
    if (!f) return f.error();
    return keyValueLighting(f.value(), diagnostics);
}

}  // namespace rl
