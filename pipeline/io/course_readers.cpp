#include "course_readers.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "course_fields.h"
#include "format.h"
#include "mesh_topology.h"

namespace rl {

using namespace course_io;  // the helpers the course readers share

namespace {

// The line layouts, shared by their readers and by the detection.
constexpr FieldSpec kUfpeCamera[] = {
    {"C", "the camera position", kThree},
    {"N", "the view direction", kThree},
    {"V", "the up vector", kThree},
    {"d hx hy", "the projection distance and half-sizes", kThree},
};
constexpr FieldSpec kUfrpeCamera6[] = {
    {"N", "the view direction", kThree},
    {"V", "the up vector", kThree},
    {"d", "the projection distance", kOne},
    {"hx", "the horizontal half-size of the window", kOne},
    {"hy", "the vertical half-size of the window", kOne},
    {"C", "the camera position", kThree},
};
constexpr FieldSpec kUfrpeCamera5[] = {
    {"C", "the camera position", kThree},   {"N", "the view direction", kThree},
    {"V", "the up vector", kThree},         {"hx hy", "the half-sizes of the window", kTwo},
    {"d", "the projection distance", kOne},
};
constexpr FieldSpec kUfpeLighting[] = {
    {"Pl", "the light position", kThree},
    {"ka", "the ambient coefficient", kOne},
    {"Ia", "the ambient light colour", kThree},
    {"kd", "the diffuse coefficient", kOne | kThree},
    {"Od", "the diffuse colour of the object", kThree},
    {"ks", "the specular coefficient", kOne},
    {"Il", "the light colour", kThree},
    {"n", "the specular exponent", kOne},
};
// The multi-light file's first seven lines; then L pairs of kUfpeMultiLight.
constexpr FieldSpec kUfpeMultiHead[] = {
    {"ka", "the ambient coefficient", kOne},
    {"Ia", "the ambient light colour", kThree},
    {"kd", "the diffuse coefficient", kOne | kThree},
    {"Od", "the diffuse colour of the object", kThree},
    {"ks", "the specular coefficient", kOne},
    {"n", "the specular exponent", kOne},
    {"L", "the number of lights", kOne},
};
constexpr FieldSpec kUfpeMultiLight[] = {
    {"Pl", "the light position", kThree},
    {"Il", "the light colour", kThree},
};
constexpr FieldSpec kUfrpeLighting[] = {
    {"Iamb", "the ambient light colour", kThree},
    {"Ka", "the ambient coefficient", kOne},
    {"Il", "the light colour", kThree},
    {"Pl", "the light position", kThree},
    {"Kd", "the diffuse coefficient of each channel", kThree},
    {"Od", "the diffuse colour of the object", kThree},
    {"Ks", "the specular coefficient", kOne},
    {"n", "the specular exponent", kOne},
};
constexpr LightingNames kUfpeNames = {"ka", "Ia", "kd", "Od", "ks", "Il", "n"};
constexpr LightingNames kUfrpeNames = {"Ka", "Iamb", "Kd", "Od", "Ks", "Il", "n"};
constexpr LightingNames kKeyValueNames = {"Ka", "Iamb", "Kd", "Od", "Ks", "Il", "eta"};

}  // namespace

Result<CourseCamera> readCourseCamera(std::string_view text, const std::string& fileName,
                                      Diagnostics& diagnostics) {
    LineScanner scanner(text, fileName);
    auto fields = readFieldLines(scanner, kUfpeCamera, "camera", diagnostics);
    if (!fields) return fields.error();
    const auto& f = fields.value();
    return makeCamera(f[0], f[1], f[2], {&f[3], 0}, {&f[3], 1}, {&f[3], 2});
}

Result<CourseLighting> readCourseLighting(std::string_view text, const std::string& fileName,
                                          Diagnostics& diagnostics) {
    LineScanner scanner(text, fileName);
    auto fields = readFieldLines(scanner, kUfpeLighting, "lighting", diagnostics);
    if (!fields) return fields.error();
    const auto& f = fields.value();
    LightingFields parts;
    parts.ka = &f[1];
    parts.ia = &f[2];
    parts.kd = &f[3];
    parts.od = &f[4];
    parts.ks = &f[5];
    parts.n = &f[7];
    parts.lights = {{&f[0], &f[6]}};
    return makeLighting(parts, kUfpeNames, diagnostics);
}

// ---------------------------------------------------------------------------------------
// Course file variants: layout names, detection, key = value files

const char* cameraLayoutName(CameraLayout layout) {
    switch (layout) {
        case CameraLayout::Auto:
            return "auto";
        case CameraLayout::Ufpe:
            return "ufpe";
        case CameraLayout::Ufrpe6:
            return "ufrpe6";
        case CameraLayout::Ufrpe5:
            return "ufrpe5";
        case CameraLayout::KeyValue:
            return "keyvalue";
    }
    return "auto";
}

const char* lightingLayoutName(LightingLayout layout) {
    switch (layout) {
        case LightingLayout::Auto:
            return "auto";
        case LightingLayout::Ufpe:
            return "ufpe";
        case LightingLayout::UfpeMulti:
            return "multi";
        case LightingLayout::Ufrpe:
            return "ufrpe";
        case LightingLayout::KeyValue:
            return "keyvalue";
    }
    return "auto";
}

std::optional<CameraLayout> cameraLayoutFromName(std::string_view name) {
    for (CameraLayout layout : kCameraLayouts)
        if (name == cameraLayoutName(layout)) return layout;
    return std::nullopt;
}

std::optional<LightingLayout> lightingLayoutFromName(std::string_view name) {
    for (LightingLayout layout : kLightingLayouts)
        if (name == lightingLayoutName(layout)) return layout;
    return std::nullopt;
}

const char* cameraLayoutDescription(CameraLayout layout) {
    switch (layout) {
        case CameraLayout::Auto:
            return "detected from the file";
        case CameraLayout::Ufpe:
            return "UFPE (C; N; V; d hx hy)";
        case CameraLayout::Ufrpe6:
            return "UFRPE (N; V; d; hx; hy; C)";
        case CameraLayout::Ufrpe5:
            return "UFRPE (C; N; V; hx hy; d)";
        case CameraLayout::KeyValue:
            return "key = value";
    }
    return "";
}

const char* lightingLayoutDescription(LightingLayout layout) {
    switch (layout) {
        case LightingLayout::Auto:
            return "detected from the file";
        case LightingLayout::Ufpe:
            return "UFPE (Pl; ka; Ia; kd; Od; ks; Il; n)";
        case LightingLayout::UfpeMulti:
            return "UFPE multi-light (ka; Ia; kd; Od; ks; n; L; L times Pl; Il)";
        case LightingLayout::Ufrpe:
            return "UFRPE (Iamb; Ka; Il; Pl; Kd; Od; Ks; n)";
        case LightingLayout::KeyValue:
            return "key = value";
    }
    return "";
}

std::string lightKeyName(std::string_view key, std::size_t light) {
    return std::string(key) + (light > 0 ? std::to_string(light + 1) : std::string());
}

namespace {

// What the notes call each flavour.
std::string cameraFlavour(CameraLayout layout) {
    switch (layout) {
        case CameraLayout::Ufpe:
            return "a UFPE camera, C; N; V; d hx hy";
        case CameraLayout::Ufrpe6:
            return "a UFRPE camera, N; V; d; hx; hy; C";
        case CameraLayout::Ufrpe5:
            return "a UFRPE camera, C; N; V; hx hy; d";
        case CameraLayout::KeyValue:
            return "a key = value camera";
        case CameraLayout::Auto:
            break;
    }
    return "a camera";
}

std::string lightingFlavour(LightingLayout layout) {
    switch (layout) {
        case LightingLayout::Ufpe:
            return "a UFPE lighting file, Pl; ka; Ia; kd; Od; ks; Il; n";
        case LightingLayout::UfpeMulti:
            return "a UFPE multi-light lighting file, ka; Ia; kd; Od; ks; n; L; L times Pl; Il";
        case LightingLayout::Ufrpe:
            return "a UFRPE lighting file, Iamb; Ka; Il; Pl; Kd; Od; Ks; n";
        case LightingLayout::KeyValue:
            return "a key = value lighting file";
        case LightingLayout::Auto:
            break;
    }
    return "a lighting file";
}

// The shape detection looks at: for each non-blank line, how many numbers it starts with.
struct FileShape {
    std::vector<int> numbers;  // leading numeric tokens of each non-blank line
    std::vector<int> lines;    // the line number of each non-blank line
    bool hasEquals = false;    // some line contains '='
};

FileShape shapeOf(std::string_view text) {
    FileShape shape;
    LineScanner scanner(text, std::string());
    TextLine line;
    while (scanner.next(line)) {
        int count = 0;
        while (static_cast<std::size_t>(count) < line.tokens.size() &&
               parseReal(line.tokens[static_cast<std::size_t>(count)].text))
            ++count;
        shape.numbers.push_back(count);
        shape.lines.push_back(line.number);
        // A line holding '=', unless it is a comment ("# d = 5", "// ...", "; ...").
        const std::string_view first = line.tokens[0].text;
        const bool comment =
            first.starts_with('#') || first.starts_with("//") || first.starts_with(';');
        for (const Token& token : line.tokens)
            if (!comment && token.text.find('=') != std::string_view::npos) shape.hasEquals = true;
    }
    return shape;
}

// "3, 3, 1" (at most 24 counts, then "...").
std::string countsText(const std::vector<int>& numbers) {
    constexpr std::size_t kShown = 24;
    std::string s;
    for (std::size_t i = 0; i < numbers.size() && i < kShown; ++i) {
        if (i > 0) s += ", ";
        s += std::to_string(numbers[i]);
    }
    if (numbers.size() > kShown) s += ", ...";
    return s;
}

// "the 4 lines have 3, 3, 3, 3 numbers", "the 1 line has 1 number".
std::string shapeText(const FileShape& shape) {
    const std::size_t n = shape.numbers.size();
    if (n == 1) return "the 1 line has " + plural(shape.numbers[0], "number", "numbers");
    return "the " + std::to_string(n) + " lines have " + countsText(shape.numbers) + " numbers";
}

// One candidate layout for detection: the counts each of its lines accepts.
struct Profile {
    int layout = 0;
    std::vector<const FieldSpec*> fields;
};

bool accepts(const FieldSpec& field, int count) {
    return count < 32 && (field.counts & (1u << count)) != 0;
}

// How far a file is from a layout: lines with other counts, plus lines missing or extra.
struct Distance {
    long long lines = 0;
    std::string why;  // for a distance of 1: which line
};

Distance distanceTo(const Profile& profile, const FileShape& shape) {
    Distance distance;
    const std::size_t m = profile.fields.size();
    const std::size_t n = shape.numbers.size();
    std::size_t differing = 0;
    for (std::size_t i = 0; i < std::min(m, n); ++i) {
        if (accepts(*profile.fields[i], shape.numbers[i])) continue;
        if (distance.lines++ == 0) differing = i;
    }
    distance.lines += static_cast<long long>(m > n ? m - n : n - m);
    if (distance.lines != 1) return distance;
    if (m == n) {
        const FieldSpec& field = *profile.fields[differing];
        distance.why = "line " + std::to_string(shape.lines[differing]) + " has " +
                       plural(shape.numbers[differing], "number", "numbers") + " where " +
                       std::string(field.name) + " needs " + countText(field.counts);
    } else if (m > n) {
        distance.why =
            "its last line, " + std::string(profile.fields[m - 1]->name) + ", is missing";
    } else {
        distance.why = "line " + std::to_string(shape.lines[n - 1]) + " is one line more";
    }
    return distance;
}

// The detection's verdict: a layout (as an int) and why, or none.
struct Detection {
    int layout = -1;
    std::string why;
    std::string ambiguity;  // when several layouts are one line away: their names
};

// Steps 2 and 3 of the rule in course_readers.h, over the candidate profiles (a layout may
// have several, one per length). `describe` names a layout in messages.
Detection chooseLayout(const std::vector<Profile>& profiles, const FileShape& shape,
                       const char* (*describe)(int)) {
    std::vector<std::pair<int, Distance>> best;  // the nearest profile of each layout
    for (const Profile& profile : profiles) {
        Distance d = distanceTo(profile, shape);
        auto it = std::find_if(best.begin(), best.end(),
                               [&](const auto& b) { return b.first == profile.layout; });
        if (it == best.end())
            best.emplace_back(profile.layout, std::move(d));
        else if (d.lines < it->second.lines)
            it->second = std::move(d);
    }
    Detection detection;
    const std::string shapeWhy = "no line contains '=' and " + shapeText(shape);
    // A layout whose lines the file's first lines match exactly, with lines left over: the
    // known quirk of data after the counts (warned about when read). The longest such
    // layout wins, so that a stray line after a good file does not make it ambiguous.
    const Profile* prefix = nullptr;
    for (const Profile& profile : profiles) {
        const std::size_t m = profile.fields.size();
        if (m >= shape.numbers.size() || (prefix && prefix->fields.size() >= m)) continue;
        bool match = true;
        for (std::size_t i = 0; i < m && match; ++i)
            match = accepts(*profile.fields[i], shape.numbers[i]);
        if (match) prefix = &profile;
    }
    const bool exact =
        std::any_of(best.begin(), best.end(), [](const auto& b) { return b.second.lines == 0; });
    if (!exact && prefix) {
        detection.layout = prefix->layout;
        detection.why = shapeWhy + ": its first " + std::to_string(prefix->fields.size()) +
                        " lines fit this layout, and the rest is left over";
        return detection;
    }
    for (long long wanted : {0LL, 1LL}) {
        std::vector<const std::pair<int, Distance>*> at;
        for (const auto& b : best)
            if (b.second.lines == wanted) at.push_back(&b);
        if (at.size() == 1) {
            detection.layout = at[0]->first;
            detection.why = wanted == 0 ? shapeWhy + ", as in that layout"
                                        : shapeWhy + ": no layout fits exactly, and this one is " +
                                              "one line away (" + at[0]->second.why + ")";
            return detection;
        }
        if (at.size() > 1) {
            std::vector<std::string> names;
            for (const auto* b : at) names.emplace_back(describe(b->first));
            detection.ambiguity = "one line away from " + listText(names);
            return detection;
        }
    }
    return detection;
}

const char* describeCamera(int layout) {
    return cameraLayoutDescription(static_cast<CameraLayout>(layout));
}
const char* describeLighting(int layout) {
    return lightingLayoutDescription(static_cast<LightingLayout>(layout));
}

Profile profileOf(int layout, std::span<const FieldSpec> fields) {
    Profile profile{layout, {}};
    for (const FieldSpec& field : fields) profile.fields.push_back(&field);
    return profile;
}

std::vector<Profile> cameraProfiles() {
    return {profileOf(static_cast<int>(CameraLayout::Ufpe), kUfpeCamera),
            profileOf(static_cast<int>(CameraLayout::Ufrpe6), kUfrpeCamera6),
            profileOf(static_cast<int>(CameraLayout::Ufrpe5), kUfrpeCamera5)};
}

// The multi-light layout holds 7 + 2 L lines (L >= 1): the lengths near the file's are tried.
std::vector<Profile> lightingProfiles(std::size_t fileLines) {
    std::vector<Profile> profiles = {
        profileOf(static_cast<int>(LightingLayout::Ufpe), kUfpeLighting),
        profileOf(static_cast<int>(LightingLayout::Ufrpe), kUfrpeLighting)};
    const std::size_t head = std::size(kUfpeMultiHead);
    std::vector<std::size_t> lengths = {head + 2};
    for (std::size_t length : {fileLines - 1, fileLines, fileLines + 1})
        if (fileLines >= 1 && length > head + 2 && (length - head) % 2 == 0)
            lengths.push_back(length);
    for (std::size_t length : lengths) {
        Profile profile = profileOf(static_cast<int>(LightingLayout::UfpeMulti), kUfpeMultiHead);
        for (std::size_t k = head; k < length; ++k)
            profile.fields.push_back(&kUfpeMultiLight[(k - head) % 2]);
        profiles.push_back(std::move(profile));
    }
    return profiles;
}

// Where the general detection error points: the first non-blank line, or the end of input.
SourceLocation startOf(std::string_view text, const std::string& fileName) {
    LineScanner scanner(text, fileName);
    TextLine line;
    if (scanner.next(line)) return scanner.at(line.number, 1);
    return scanner.endOfInput();
}

// Runs the detection rule; on failure, the error naming the layouts tried.
template <typename Layout>
Result<std::pair<Layout, std::string>> detectLayout(std::string_view text,
                                                    const std::string& fileName,
                                                    const std::vector<Profile>& profiles,
                                                    const char* (*describe)(int),
                                                    const std::string& layoutsTried) {
    const FileShape shape = shapeOf(text);
    if (shape.hasEquals) return std::pair{Layout::KeyValue, std::string("lines contain '='")};
    const Detection detection = chooseLayout(profiles, shape, describe);
    if (detection.layout >= 0)
        return std::pair{static_cast<Layout>(detection.layout), detection.why};
    std::string found;
    if (shape.numbers.empty()) {
        const bool empty = text.empty() || text == "\xEF\xBB\xBF";  // a BOM alone is empty
        found = empty ? "an empty file" : "only blank lines";
    } else if (shape.numbers.size() == 1) {
        found = "1 line with " + plural(shape.numbers[0], "number", "numbers");
    } else {
        found = std::to_string(shape.numbers.size()) + " lines with " + countsText(shape.numbers) +
                " numbers";
    }
    if (!detection.ambiguity.empty()) found += " (" + detection.ambiguity + ")";
    return makeError(shape.numbers.empty() ? ErrorCode::MissingData : ErrorCode::Syntax,
                     startOf(text, fileName),
                     "expected " + layoutsTried + " or key = value, found " + found +
                         " (if the layout is known, choose it by hand: --camera-format / "
                         "--lighting-format, or File > Course File Layouts)");
}

const std::string kCamerasTried =
    "a camera in one of the layouts UFPE (C; N; V; d hx hy), UFRPE (N; V; d; hx; hy; C), "
    "UFRPE (C; N; V; hx hy; d)";
const std::string kLightingsTried =
    "lighting in one of the layouts UFPE (Pl; ka; Ia; kd; Od; ks; Il; n), UFPE multi-light (ka; "
    "Ia; kd; Od; ks; n; L; L times Pl; Il), UFRPE (Iamb; Ka; Il; Pl; Kd; Od; Ks; n)";

Result<std::pair<CameraLayout, std::string>> detectCamera(std::string_view text,
                                                          const std::string& fileName) {
    return detectLayout<CameraLayout>(text, fileName, cameraProfiles(), describeCamera,
                                      kCamerasTried);
}

Result<std::pair<LightingLayout, std::string>> detectLighting(std::string_view text,
                                                              const std::string& fileName) {
    return detectLayout<LightingLayout>(text, fileName,
                                        lightingProfiles(shapeOf(text).numbers.size()),
                                        describeLighting, kLightingsTried);
}

// ---- key = value files

struct KeySpec {
    std::string_view key;  // as the course writes it; matched without regard to case
    std::string_view description;
    unsigned counts;
    bool required = true;   // every file has it (for the first light, when perLight)
    bool perLight = false;  // one per light: "Pl" (or "Pl1") for the first, "Pl2" ...
};

constexpr int kMaxKeyLights = static_cast<int>(kMaxKeyValueLights);

constexpr KeySpec kCameraKeys[] = {
    {"C", "the camera position", kThree},
    {"N", "the view direction", kThree},
    {"V", "the up vector", kThree},
    {"d", "the projection distance", kOne},
    {"hx", "the horizontal half-size of the window", kOne},
    {"hy", "the vertical half-size of the window", kOne},
};
constexpr KeySpec kLightingKeys[] = {
    {"Iamb", "the ambient light colour", kThree},
    {"Ka", "the ambient coefficient", kOne},
    {"Il", "the light colour", kThree, true, true},
    {"Pl", "the light position (x y z, or x y z w: w = 0 for a directional light)", kThree | kFour,
     true, true},
    {"Kd", "the diffuse coefficient of each channel", kThree},
    {"Od", "the diffuse colour of the object", kThree},
    {"Ks", "the specular coefficient", kOne},
    {"eta", "the specular exponent", kOne},
    // The lecture slides' lighting (seed 003), beyond the course's files.
    {"Ke", "the emission of the object", kThree, false},
    {"two_sided", "two-sided lighting, 1 or 0", kOne, false},
    {"blinn", "Blinn-Phong highlights, 1 or 0", kOne, false},
    {"atten", "the attenuation kc kl kq", kThree, false, true},
    {"spot_dir", "the spot direction", kThree, false, true},
    {"spot_cutoff", "the spot cutoff angle in degrees", kOne, false, true},
    {"spot_exp", "the spot exponent", kOne, false, true},
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

template <std::size_t N>
std::optional<KeyMatch> findKey(const KeySpec (&keys)[N], std::string_view key) {
    for (std::size_t i = 0; i < N; ++i) {
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
template <std::size_t N>
std::string keyList(const KeySpec (&keys)[N]) {
    std::vector<std::string> names;
    for (const KeySpec& key : keys)
        if (key.required) names.emplace_back(key.key);
    return listText(names);
}

// keyList, then the keys a file may have: "...; optionally Ke, ... (Pl2, Il2 ... for more
// lights)".
template <std::size_t N>
std::string keyListWithOptional(const KeySpec (&keys)[N]) {
    std::vector<std::string> optional;
    bool perLight = false;
    for (const KeySpec& key : keys) {
        if (!key.required) optional.emplace_back(key.key);
        perLight = perLight || key.perLight;
    }
    if (optional.empty()) return keyList(keys);
    return keyList(keys) + "; optionally " + listText(optional) +
           (perLight ? "; Pl2, Il2 ... for lights 2 to " + std::to_string(kMaxKeyLights)
                     : std::string());
}

// The keys of one role (camera or lighting) from a key = value file, in the order of `keys`.
// Keys of the other role are skipped; keys of neither are skipped with a warning.
template <std::size_t N, std::size_t M>
Result<std::vector<FieldValue>> readKeyValues(std::string_view text, const std::string& fileName,
                                              const char* what, const KeySpec (&keys)[N],
                                              const char* otherWhat, const KeySpec (&otherKeys)[M],
                                              bool isCamera, Diagnostics& diagnostics) {
    LineScanner scanner(text, fileName);
    // Key i of light k at i + N k.
    std::vector<FieldValue> values(N * kMaxKeyLights);
    std::vector<int> givenOn(N * kMaxKeyLights, 0);  // the line each was given on, 0 when not yet
    bool otherRoleSeen = false;
    TextLine line;
    while (scanner.next(line)) {
        // Split the line at its first '=': the key before it, the values after it.
        std::size_t at = 0;
        std::size_t equals = std::string_view::npos;
        for (; at < line.tokens.size(); ++at) {
            equals = line.tokens[at].text.find('=');
            if (equals != std::string_view::npos) break;
        }
        if (at == line.tokens.size())
            return makeError(ErrorCode::Syntax, scanner.at(line.tokens[0]),
                             "expected 'key = value', found a line without '=' (" +
                                 quoted(line.tokens[0].text) +
                                 (line.tokens.size() > 1 ? " ...)" : ")"));
        std::string keyText;
        std::size_t keyWords = 0;
        for (std::size_t k = 0; k <= at; ++k) {
            const std::string_view part =
                k < at ? line.tokens[k].text : line.tokens[k].text.substr(0, equals);
            if (part.empty()) continue;
            if (keyWords++ > 0) keyText += ' ';
            keyText += part;
        }
        const SourceLocation keyAt = scanner.at(line.tokens[0]);
        if (keyWords == 0)
            return makeError(ErrorCode::Syntax, keyAt, "expected a key before '=', found nothing");
        if (keyWords > 1)
            return makeError(ErrorCode::Syntax, keyAt,
                             "expected one key before '=', found " + quoted(keyText));
        std::vector<Token> valueTokens;
        const Token& split = line.tokens[at];
        if (equals + 1 < split.text.size())
            valueTokens.push_back({split.text.substr(equals + 1), split.line,
                                   split.column + static_cast<int>(equals) + 1});
        valueTokens.insert(valueTokens.end(),
                           line.tokens.begin() + static_cast<std::ptrdiff_t>(at) + 1,
                           line.tokens.end());

        const auto match = findKey(keys, keyText);
        if (!match) {
            if (findKey(otherKeys, keyText)) {
                otherRoleSeen = true;
            } else if (sameKey(keyText, kUnusedCameraKey)) {
                if (isCamera)
                    diagnostics.note(
                        keyAt, "ignored " + keyText + ": the camera's axes come from N and V");
            } else {
                diagnostics.warn(keyAt, "ignored the unknown key " + quoted(keyText) + " (a " +
                                            std::string(what) + " has " +
                                            keyListWithOptional(keys) + "; a " + otherWhat +
                                            " has " + keyListWithOptional(otherKeys) + ")");
            }
            continue;
        }
        const KeySpec& key = keys[match->index];
        const std::size_t slot = match->index + N * static_cast<std::size_t>(match->light);
        const std::string name = keyName(key, match->light);
        if (givenOn[slot] != 0)
            return makeError(ErrorCode::Syntax, keyAt,
                             "expected each key once, found " + name +
                                 " again (first given on line " + std::to_string(givenOn[slot]) +
                                 ")");
        givenOn[slot] = line.number;

        FieldValue& value = values[slot];
        value.line = scanner.at(line.number, 1);
        for (const Token& token : valueTokens) {
            const auto number = parseReal(token.text);
            if (!number)
                return makeError(ErrorCode::Syntax, scanner.at(token),
                                 "expected a number for " + name + ", " + whyNotNumber(token.text));
            value.values.push_back(*number);
            value.where.push_back(scanner.at(token));
        }
        const int count = static_cast<int>(value.values.size());
        const int most = maxCount(key.counts);
        if (count > most)
            return makeError(ErrorCode::Syntax, value.where[static_cast<std::size_t>(most)],
                             "expected " + countText(key.counts) + " for " + name + ", found " +
                                 std::to_string(count));
        if (!(key.counts & (1u << count)))
            return makeError(ErrorCode::Syntax, scanner.afterLast(line),
                             "expected " + countText(key.counts) + " for " + name + ", found " +
                                 (count == 0 ? std::string("none") : std::to_string(count)));
    }

    std::vector<std::string> missing;
    std::size_t required = 0;
    for (std::size_t i = 0; i < N; ++i) {
        required += keys[i].required ? 1 : 0;
        if (keys[i].required && givenOn[i] == 0) missing.emplace_back(keys[i].key);
    }
    if (missing.empty()) return values;
    std::string message;
    if (missing.size() == required) {
        message = "expected the " + std::string(what) + " keys " + keyList(keys) +
                  ", found none of them" +
                  (otherRoleSeen ? " (only " + std::string(otherWhat) + " keys)" : std::string());
    } else if (missing.size() == 1) {
        const KeySpec& key = keys[findKey(keys, missing[0])->index];
        message = "expected a line '" + missing[0] + " = ...' (" + std::string(key.description) +
                  ", " + countText(key.counts) + "), found no " + missing[0];
    } else {
        message = "expected lines for " + listText(missing) + " (a " + std::string(what) +
                  " needs " + keyList(keys) + "), found none";
    }
    return makeError(ErrorCode::MissingData, scanner.endOfInput(), message);
}

// ---- the readers of each layout

Result<CourseCamera> readCameraAs(std::string_view text, const std::string& fileName,
                                  CameraLayout layout, Diagnostics& diagnostics) {
    if (layout == CameraLayout::KeyValue) {
        auto f = readKeyValues(text, fileName, "camera", kCameraKeys, "lighting file",
                               kLightingKeys, true, diagnostics);
        if (!f) return f.error();
        const auto& v = f.value();
        return makeCamera(v[0], v[1], v[2], {&v[3], 0}, {&v[4], 0}, {&v[5], 0});
    }
    LineScanner scanner(text, fileName);
    if (layout == CameraLayout::Ufrpe6) {  // N; V; d; hx; hy; C
        auto f = readFieldLines(scanner, kUfrpeCamera6, "camera", diagnostics);
        if (!f) return f.error();
        const auto& v = f.value();
        return makeCamera(v[5], v[0], v[1], {&v[2], 0}, {&v[3], 0}, {&v[4], 0});
    }
    if (layout == CameraLayout::Ufrpe5) {  // C; N; V; hx hy; d
        auto f = readFieldLines(scanner, kUfrpeCamera5, "camera", diagnostics);
        if (!f) return f.error();
        const auto& v = f.value();
        return makeCamera(v[0], v[1], v[2], {&v[4], 0}, {&v[3], 0}, {&v[3], 1});
    }
    return readCourseCamera(text, fileName, diagnostics);
}

Result<CourseLighting> readMultiLight(std::string_view text, const std::string& fileName,
                                      Diagnostics& diagnostics) {
    LineScanner scanner(text, fileName);
    auto head = readFields(scanner, kUfpeMultiHead, diagnostics);
    if (!head) return head.error();
    const auto& h = head.value();
    // L: a positive whole number of lights, each a pair of lines the file must hold.
    const double declared = h[6].values[0];
    const SourceLocation lAt = h[6].where[0];
    if (!(declared >= 1.0) || declared != std::floor(declared))
        return makeError(ErrorCode::Syntax, lAt,
                         "expected the number of lights L (a positive whole number), found " +
                             formatNumber(declared));
    const long long available = scanner.countRemainingLines();
    if (declared > static_cast<double>(available / 2)) {
        const std::string count = declared < 1e15 ? std::to_string(static_cast<long long>(declared))
                                                  : formatNumber(declared);
        return makeError(ErrorCode::Range, lAt,
                         "L = " + count + " lights need " +
                             (declared < 1e15 ? std::to_string(2 * static_cast<long long>(declared))
                                              : "twice as many") +
                             " lines after it (Pl and Il for each), but only " +
                             plural(available, "line follows", "lines follow"));
    }
    const auto lightCount = static_cast<std::size_t>(declared);
    std::vector<FieldValue> pairs;
    pairs.reserve(2 * lightCount);
    for (std::size_t k = 0; k < lightCount; ++k) {
        const std::string number = std::to_string(k + 1);
        const std::string plName = "Pl of light " + number;
        const std::string ilName = "Il of light " + number;
        const FieldSpec pair[] = {{plName, kUfpeMultiLight[0].description, kThree},
                                  {ilName, kUfpeMultiLight[1].description, kThree}};
        auto fields = readFields(scanner, pair, diagnostics);
        if (!fields) return fields.error();
        for (FieldValue& f : fields.value()) pairs.push_back(std::move(f));
    }
    warnTrailingLines(scanner, "lighting",
                      static_cast<long long>(std::size(kUfpeMultiHead) + pairs.size()),
                      diagnostics);
    LightingFields parts;
    parts.ka = &h[0];
    parts.ia = &h[1];
    parts.kd = &h[2];
    parts.od = &h[3];
    parts.ks = &h[4];
    parts.n = &h[5];
    for (std::size_t k = 0; k < lightCount; ++k)
        parts.lights.emplace_back(&pairs[2 * k], &pairs[2 * k + 1]);
    return makeLighting(parts, kUfpeNames, diagnostics);
}

// A key = value lighting file's values (readKeyValues over kLightingKeys): the course's keys,
// then the lecture slides' (emission, two-sided, Blinn-Phong, more lights, w, attenuation,
// spots), each checked against the range OpenGL allows it.
Result<CourseLighting> keyValueLighting(const std::vector<FieldValue>& v,
                                        Diagnostics& diagnostics) {
    constexpr std::size_t N = kLightingKeyCount;
    const auto at = [&](std::size_t key, int light) -> const FieldValue& {
        return v[key + N * static_cast<std::size_t>(light)];
    };
    const auto given = [&](std::size_t key, int light) { return !at(key, light).values.empty(); };
    const auto name = [](std::size_t key, int light) { return keyName(kLightingKeys[key], light); };
    LightingFields parts;
    parts.ia = &v[kIamb];
    parts.ka = &v[kKa];
    parts.kd = &v[kKd];
    parts.od = &v[kOd];
    parts.ks = &v[kKs];
    parts.n = &v[kEta];
    parts.lights = {{&v[kPl], &v[kIl]}};
    // Lights 2 ... are numbered without gaps, each with its Pl and Il.
    for (int k = 1; k < kMaxKeyLights; ++k) {
        std::optional<std::size_t> first;
        for (std::size_t key = 0; key < N; ++key)
            if (kLightingKeys[key].perLight && given(key, k) &&
                (!first || at(key, k).line.line < at(*first, k).line.line))
                first = key;
        if (!first) continue;
        const int expected = static_cast<int>(parts.lights.size());
        if (k != expected)
            return makeError(ErrorCode::Syntax, at(*first, k).line,
                             "expected light " + std::to_string(expected + 1) + " (" +
                                 name(kPl, expected) + ", " + name(kIl, expected) +
                                 ") before light " + std::to_string(k + 1) + ", found " +
                                 name(*first, k) + " (lights are numbered without gaps)");
        for (const std::size_t key : {std::size_t(kPl), std::size_t(kIl)})
            if (!given(key, k))
                return makeError(ErrorCode::MissingData, at(*first, k).line,
                                 "expected a line '" + name(key, k) + " = ...' (" +
                                     std::string(kLightingKeys[key].description) + " of light " +
                                     std::to_string(k + 1) + "), found " + name(*first, k) +
                                     " without it");
        parts.lights.emplace_back(&at(kPl, k), &at(kIl, k));
    }
    CourseLighting lighting = makeLighting(parts, kKeyValueNames, diagnostics);

    const auto flag = [&](std::size_t key) -> Result<std::optional<bool>> {
        if (!given(key, 0)) return std::optional<bool>();
        const double value = at(key, 0).values[0];
        if (value != 0.0 && value != 1.0)
            return makeError(
                ErrorCode::Range, at(key, 0).where[0],
                "expected 1 or 0 for " + name(key, 0) + ", found " + formatNumber(value));
        return std::optional<bool>(value == 1.0);
    };
    auto twoSided = flag(kTwoSided);
    if (!twoSided) return twoSided.error();
    if (twoSided.value()) lighting.twoSided = *twoSided.value();
    auto blinn = flag(kBlinn);
    if (!blinn) return blinn.error();
    if (blinn.value() && *blinn.value()) lighting.specular = SpecularModel::BlinnPhong;
    if (given(kKe, 0)) {
        lighting.material.emission = rgbOf(at(kKe, 0));
        checkRange(at(kKe, 0), "Ke", "", 0.0, 255.0, "[0, 255]", diagnostics);
    }

    for (std::size_t k = 0; k < lighting.lights.size(); ++k) {
        const int light = static_cast<int>(k);
        Light& l = lighting.lights[k];
        const FieldValue& pl = at(kPl, light);
        if (pl.values.size() == 4) {
            // Homogeneous, as GL_POSITION: w = 0 a direction toward the light, otherwise the
            // point (x/w, y/w, z/w).
            const double w = pl.values[3];
            l.pWorld = w == 0.0 ? dvec4(vec3Of(pl), 0.0) : dvec4(vec3Of(pl) / w, 1.0);
        }
        if (given(kAtten, light)) {
            const FieldValue& a = at(kAtten, light);
            for (std::size_t i = 0; i < 3; ++i)
                if (!(a.values[i] >= 0.0))
                    return makeError(ErrorCode::Range, a.where[i],
                                     "expected " + name(kAtten, light) +
                                         " coefficients of 0 or more (kc kl kq), found " +
                                         formatNumber(a.values[i]));
            if (a.values[0] == 0.0 && a.values[1] == 0.0 && a.values[2] == 0.0)
                return makeError(ErrorCode::Range, a.where[0],
                                 "expected " + name(kAtten, light) +
                                     " with a coefficient above 0, found 0 0 0 (1 / 0 light)");
            l.attenuation = rgbOf(a);
            if (l.pWorld.w == 0.0)
                diagnostics.warn(a.line, name(kAtten, light) +
                                             " has no effect: a directional light (w = 0) is "
                                             "not attenuated");
        }
        if (given(kSpotDir, light)) {
            const FieldValue& d = at(kSpotDir, light);
            if (vec3Of(d) == dvec3(0.0))
                return makeError(
                    ErrorCode::Range, d.where[0],
                    "expected a spot direction other than 0 0 0 for " + name(kSpotDir, light));
            l.spotDirection = vec3Of(d);
        }
        if (given(kSpotCutoff, light)) {
            const FieldValue& c = at(kSpotCutoff, light);
            const double cutoff = c.values[0];
            if (!((cutoff >= 0.0 && cutoff <= 90.0) || cutoff == 180.0))
                return makeError(ErrorCode::Range, c.where[0],
                                 "expected " + name(kSpotCutoff, light) +
                                     " from 0 to 90 degrees, or 180 (not a spot), found " +
                                     formatNumber(cutoff));
            l.spotCutoff = static_cast<float>(cutoff);
            if (l.spot() && !given(kSpotDir, light))
                diagnostics.note(c.line, name(kSpotCutoff, light) + ": no " +
                                             name(kSpotDir, light) +
                                             ", the spot points along -z (OpenGL's default)");
        }
        if (given(kSpotExp, light)) {
            const FieldValue& e = at(kSpotExp, light);
            if (!(e.values[0] >= 0.0 && e.values[0] <= 128.0))
                return makeError(ErrorCode::Range, e.where[0],
                                 "expected " + name(kSpotExp, light) + " from 0 to 128, found " +
                                     formatNumber(e.values[0]));
            l.spotExponent = static_cast<float>(e.values[0]);
        }
        if (!l.spot() && (given(kSpotDir, light) || given(kSpotExp, light)))
            diagnostics.warn(at(given(kSpotDir, light) ? kSpotDir : kSpotExp, light).line,
                             "light " + std::to_string(k + 1) + " is not a spot without " +
                                 name(kSpotCutoff, light) +
                                 " (0 to 90 degrees): its spot direction and exponent are unused");
    }
    return lighting;
}

}  // namespace

bool isLightingKey(std::string_view key) {
    return findKey(kLightingKeys, key).has_value();
}

namespace {

Result<CourseLighting> readLightingAs(std::string_view text, const std::string& fileName,
                                      LightingLayout layout, Diagnostics& diagnostics) {
    if (layout == LightingLayout::KeyValue) {
        auto f = readKeyValues(text, fileName, "lighting file", kLightingKeys, "camera",
                               kCameraKeys, false, diagnostics);
        if (!f) return f.error();
        return keyValueLighting(f.value(), diagnostics);
    }
    if (layout == LightingLayout::UfpeMulti) return readMultiLight(text, fileName, diagnostics);
    if (layout == LightingLayout::Ufrpe) {  // Iamb; Ka; Il; Pl; Kd; Od; Ks; n
        LineScanner scanner(text, fileName);
        auto f = readFieldLines(scanner, kUfrpeLighting, "lighting", diagnostics);
        if (!f) return f.error();
        const auto& v = f.value();
        LightingFields parts;
        parts.ia = &v[0];
        parts.ka = &v[1];
        parts.kd = &v[4];
        parts.od = &v[5];
        parts.ks = &v[6];
        parts.n = &v[7];
        parts.lights = {{&v[3], &v[2]}};
        return makeLighting(parts, kUfrpeNames, diagnostics);
    }
    return readCourseLighting(text, fileName, diagnostics);
}

// For an error under a layout the caller chose: what detection would have chosen instead.
template <typename Layout>
std::string forcedLayoutHint(Layout chosen, const char* chosenText,
                             const Result<std::pair<Layout, std::string>>& detected,
                             const char* (*describe)(int)) {
    std::string hint = "; the layout was set to " + std::string(chosenText);
    if (!detected) return hint;
    if (detected->first == chosen) return {};
    return hint + ", but the file looks like " + describe(static_cast<int>(detected->first)) +
           " (" + detected->second + ")";
}

}  // namespace

std::optional<CameraLayout> detectCameraLayout(std::string_view text) {
    auto detected = detectCamera(text, std::string());
    if (!detected) return std::nullopt;
    return detected->first;
}

std::optional<LightingLayout> detectLightingLayout(std::string_view text) {
    auto detected = detectLighting(text, std::string());
    if (!detected) return std::nullopt;
    return detected->first;
}

Result<CourseCamera> readCameraFile(std::string_view text, const std::string& fileName,
                                    Diagnostics& diagnostics, CameraLayout layout) {
    CameraLayout chosen = layout;
    std::string why = "the layout was chosen, not detected";
    if (layout == CameraLayout::Auto) {
        auto detected = detectCamera(text, fileName);
        if (!detected) return detected.error();
        chosen = detected->first;
        why = detected->second;
    }
    Diagnostics read;  // after the note
    auto camera = readCameraAs(text, fileName, chosen, read);
    if (!camera) {
        diagnostics.append(read);
        if (layout == CameraLayout::Auto) return camera.error();
        Error error = camera.error();
        error.message += forcedLayoutHint(chosen, cameraLayoutDescription(chosen),
                                          detectCamera(text, fileName), describeCamera);
        return error;
    }
    diagnostics.note(SourceLocation{fileName, 0, 0},
                     "read as " + cameraFlavour(chosen) + " (" + why + ")");
    diagnostics.append(read);
    return camera;
}

Result<CourseLighting> readLightingFile(std::string_view text, const std::string& fileName,
                                        Diagnostics& diagnostics, LightingLayout layout) {
    LightingLayout chosen = layout;
    std::string why = "the layout was chosen, not detected";
    if (layout == LightingLayout::Auto) {
        auto detected = detectLighting(text, fileName);
        if (!detected) return detected.error();
        chosen = detected->first;
        why = detected->second;
    }
    Diagnostics read;  // after the note
    auto lighting = readLightingAs(text, fileName, chosen, read);
    if (!lighting) {
        diagnostics.append(read);
        if (layout == LightingLayout::Auto) return lighting.error();
        Error error = lighting.error();
        error.message += forcedLayoutHint(chosen, lightingLayoutDescription(chosen),
                                          detectLighting(text, fileName), describeLighting);
        return error;
    }
    diagnostics.note(SourceLocation{fileName, 0, 0},
                     "read as " + lightingFlavour(chosen) + " (" + why + ")");
    diagnostics.append(read);
    return lighting;
}

// ---------------------------------------------------------------------------------------
// .byu objects: the course's triangle mesh, the course's Bezier surface and the original
// Movie.BYU format, told apart by the header

namespace {

Result<Mesh> readAnyByuObject(std::string_view text, const std::string& fileName,
                              Diagnostics& diagnostics) {
    LineScanner scanner(text, fileName);
    TextLine header;
    if (scanner.next(header)) {
        if (isMovieByuHeader(header)) {
            Diagnostics read;  // after the note
            std::string summary;
            auto mesh = readMovieByu(scanner, header, summary, read);
            if (mesh)
                diagnostics.note(
                    mesh->source,
                    "read as an original Movie.BYU file (the header has four integers: parts, "
                    "vertices, polygons, edges): " +
                        summary + ", fan-triangulated into " +
                        plural(static_cast<long long>(mesh->triangles.size()), "triangle",
                               "triangles"));
            diagnostics.append(read);
            return mesh;
        }
        TextLine second;
        if (header.tokens.size() >= 2 && parseInteger(header.tokens[0].text) &&
            parseInteger(header.tokens[1].text) && scanner.next(second) &&
            second.tokens.size() == 1 && parseInteger(second.tokens[0].text)) {
            Diagnostics read;
            auto mesh = readBezierSurface(scanner, header, second, read);
            if (mesh) {
                const std::string e = std::to_string(*parseInteger(second.tokens[0].text));
                diagnostics.note(
                    mesh->source,
                    "read as a course Bezier surface (the header 'm n' is followed by a line of "
                    "one number, the evaluations per direction): degrees " +
                        std::to_string(*parseInteger(header.tokens[0].text)) + " x " +
                        std::to_string(*parseInteger(header.tokens[1].text)) + ", evaluated on a " +
                        e + " x " + e + " grid into " +
                        plural(static_cast<long long>(mesh->positions.size()), "vertex",
                               "vertices") +
                        " and " +
                        plural(static_cast<long long>(mesh->triangles.size()), "triangle",
                               "triangles"));
            }
            diagnostics.append(read);
            return mesh;
        }
    }
    return readByuMesh(text, fileName, diagnostics);
}

}  // namespace

Result<Mesh> readByuObject(std::string_view text, const std::string& fileName,
                           Diagnostics& diagnostics) {
    auto mesh = readAnyByuObject(text, fileName, diagnostics);
    if (mesh) mesh->closedWinding = closedSurfaceWinding(*mesh);
    return mesh;
}

}  // namespace rl
