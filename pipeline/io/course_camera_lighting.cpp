// Cameras and lighting files in the course's line layouts (UFPE; UFRPE; UFPE multi-light),
// the layouts' names, and the detection rule of course_readers.h that tells them apart.
#include <algorithm>
#include <cmath>

#include "pipeline/core/format.h"
#include "pipeline/io/course_fields.h"

namespace rl {

using namespace course_io;  // the helpers the course readers share

namespace {

// The line layouts, shared by their readers and by the detection.
constexpr FieldSpec kUfpeCamera[] = {
    {"C", "the camera position"_msg, kThree},
    {"N", "the view direction"_msg, kThree},
    {"V", "the up vector"_msg, kThree},
    {"d hx hy", "the projection distance and half-sizes"_msg, kThree},
};
constexpr FieldSpec kUfrpeCamera6[] = {
    {"N", "the view direction"_msg, kThree},
    {"V", "the up vector"_msg, kThree},
    {"d", "the projection distance"_msg, kOne},
    {"hx", "the horizontal half-size of the window"_msg, kOne},
    {"hy", "the vertical half-size of the window"_msg, kOne},
    {"C", "the camera position"_msg, kThree},
};
constexpr FieldSpec kUfrpeCamera5[] = {
    {"C", "the camera position"_msg, kThree},   {"N", "the view direction"_msg, kThree},
    {"V", "the up vector"_msg, kThree},         {"hx hy", "the half-sizes of the window"_msg, kTwo},
    {"d", "the projection distance"_msg, kOne},
};
constexpr FieldSpec kUfpeLighting[] = {
    {"Pl", "the light position"_msg, kThree},
    {"ka", "the ambient coefficient"_msg, kOne},
    {"Ia", "the ambient light colour"_msg, kThree},
    {"kd", "the diffuse coefficient"_msg, kOne | kThree},
    {"Od", "the diffuse colour of the object"_msg, kThree},
    {"ks", "the specular coefficient"_msg, kOne},
    {"Il", "the light colour"_msg, kThree},
    {"n", "the specular exponent"_msg, kOne},
};
// The multi-light file's first seven lines; then L pairs of kUfpeMultiLight.
constexpr FieldSpec kUfpeMultiHead[] = {
    {"ka", "the ambient coefficient"_msg, kOne},
    {"Ia", "the ambient light colour"_msg, kThree},
    {"kd", "the diffuse coefficient"_msg, kOne | kThree},
    {"Od", "the diffuse colour of the object"_msg, kThree},
    {"ks", "the specular coefficient"_msg, kOne},
    {"n", "the specular exponent"_msg, kOne},
    {"L", "the number of lights"_msg, kOne},
};
constexpr FieldSpec kUfpeMultiLight[] = {
    {"Pl", "the light position"_msg, kThree},
    {"Il", "the light colour"_msg, kThree},
};
constexpr FieldSpec kUfrpeLighting[] = {
    {"Iamb", "the ambient light colour"_msg, kThree},
    {"Ka", "the ambient coefficient"_msg, kOne},
    {"Il", "the light colour"_msg, kThree},
    {"Pl", "the light position"_msg, kThree},
    {"Kd", "the diffuse coefficient of each channel"_msg, kThree},
    {"Od", "the diffuse colour of the object"_msg, kThree},
    {"Ks", "the specular coefficient"_msg, kOne},
    {"n", "the specular exponent"_msg, kOne},
};
constexpr LightingNames kUfpeNames = {"ka", "Ia", "kd", "Od", "ks", "Il", "n"};
constexpr LightingNames kUfrpeNames = {"Ka", "Iamb", "Kd", "Od", "Ks", "Il", "n"};

}  // namespace

Result<CourseCamera> readCourseCamera(std::string_view text, const std::string& fileName,
                                      Diagnostics& diagnostics) {
    LineScanner scanner(text, fileName);
    auto fields = readFieldLines(scanner, kUfpeCamera, "the camera's %1"_msg, diagnostics);
    if (!fields) return fields.error();
    const auto& f = fields.value();
    return makeCamera(f[0], f[1], f[2], {&f[3], 0}, {&f[3], 1}, {&f[3], 2});
}

Result<CourseLighting> readCourseLighting(std::string_view text, const std::string& fileName,
                                          Diagnostics& diagnostics) {
    LineScanner scanner(text, fileName);
    auto fields = readFieldLines(scanner, kUfpeLighting, "the lighting's %1"_msg, diagnostics);
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
// Course file variants: layout names and detection

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

// The layouts for people, in menus (as text) and in messages (translated).
MessageTemplate course_io::cameraLayoutText(CameraLayout layout) {
    switch (layout) {
        case CameraLayout::Ufpe:
            return "UFPE (C; N; V; d hx hy)"_msg;
        case CameraLayout::Ufrpe6:
            return "UFRPE (N; V; d; hx; hy; C)"_msg;
        case CameraLayout::Ufrpe5:
            return "UFRPE (C; N; V; hx hy; d)"_msg;
        case CameraLayout::KeyValue:
            return "key = value"_msg;
        case CameraLayout::Auto:
            break;
    }
    return "detected from the file"_msg;
}

MessageTemplate course_io::lightingLayoutText(LightingLayout layout) {
    switch (layout) {
        case LightingLayout::Ufpe:
            return "UFPE (Pl; ka; Ia; kd; Od; ks; Il; n)"_msg;
        case LightingLayout::UfpeMulti:
            return "UFPE multi-light (ka; Ia; kd; Od; ks; n; L; L times Pl; Il)"_msg;
        case LightingLayout::Ufrpe:
            return "UFRPE (Iamb; Ka; Il; Pl; Kd; Od; Ks; n)"_msg;
        case LightingLayout::KeyValue:
            return "key = value"_msg;
        case LightingLayout::Auto:
            break;
    }
    return "detected from the file"_msg;
}

const char* cameraLayoutDescription(CameraLayout layout) {
    return cameraLayoutText(layout).text();
}

const char* lightingLayoutDescription(LightingLayout layout) {
    return lightingLayoutText(layout).text();
}

namespace {

// What the notes call each flavour.
Message cameraFlavour(CameraLayout layout) {
    switch (layout) {
        case CameraLayout::Ufpe:
            return "a UFPE camera, C; N; V; d hx hy"_msg;
        case CameraLayout::Ufrpe6:
            return "a UFRPE camera, N; V; d; hx; hy; C"_msg;
        case CameraLayout::Ufrpe5:
            return "a UFRPE camera, C; N; V; hx hy; d"_msg;
        case CameraLayout::KeyValue:
            return "a key = value camera"_msg;
        case CameraLayout::Auto:
            break;
    }
    return "a camera"_msg;
}

Message lightingFlavour(LightingLayout layout) {
    switch (layout) {
        case LightingLayout::Ufpe:
            return "a UFPE lighting file, Pl; ka; Ia; kd; Od; ks; Il; n"_msg;
        case LightingLayout::UfpeMulti:
            return "a UFPE multi-light lighting file, ka; Ia; kd; Od; ks; n; L; L times Pl; Il"_msg;
        case LightingLayout::Ufrpe:
            return "a UFRPE lighting file, Iamb; Ka; Il; Pl; Kd; Od; Ks; n"_msg;
        case LightingLayout::KeyValue:
            return "a key = value lighting file"_msg;
        case LightingLayout::Auto:
            break;
    }
    return "a lighting file"_msg;
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
Message shapeText(const FileShape& shape) {
    const std::size_t n = shape.numbers.size();
    if (n == 1) return "the 1 line has %1"_msg(numbersText(shape.numbers[0]));
    return "the %1 lines have %2 numbers"_msg(n, countsText(shape.numbers));
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
    Message why;  // for a distance of 1: which line
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
        distance.why = "line %1 has %2 where %3 needs %4"_msg(shape.lines[differing],
                                                              numbersText(shape.numbers[differing]),
                                                              field.name, countText(field.counts));
    } else if (m > n) {
        distance.why = "its last line, %1, is missing"_msg(profile.fields[m - 1]->name);
    } else {
        distance.why = "line %1 is one line more"_msg(shape.lines[n - 1]);
    }
    return distance;
}

// The detection's verdict: a layout (as an int) and why, or none.
struct Detection {
    int layout = -1;
    Message why;
    Message ambiguity;  // when several layouts are one line away: their names
};

// Steps 2 and 3 of the rule in course_readers.h, over the candidate profiles (a layout may
// have several, one per length). `describe` names a layout in messages.
Detection chooseLayout(const std::vector<Profile>& profiles, const FileShape& shape,
                       MessageTemplate (*describe)(int)) {
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
    const Message shapeWhy = "no line contains '=' and %1"_msg(shapeText(shape));
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
        detection.why = "%1: its first %2 lines fit this layout, and the rest is left over"_msg(
            shapeWhy, prefix->fields.size());
        return detection;
    }
    for (long long wanted : {0LL, 1LL}) {
        std::vector<const std::pair<int, Distance>*> at;
        for (const auto& b : best)
            if (b.second.lines == wanted) at.push_back(&b);
        if (at.size() == 1) {
            detection.layout = at[0]->first;
            detection.why =
                wanted == 0 ? "%1, as in that layout"_msg(shapeWhy)
                            : "%1: no layout fits exactly, and this one is one line away (%2)"_msg(
                                  shapeWhy, at[0]->second.why);
            return detection;
        }
        if (at.size() > 1) {
            std::vector<Message> names;
            for (const auto* b : at) names.emplace_back(describe(b->first));
            detection.ambiguity = "one line away from %1"_msg(listText(names));
            return detection;
        }
    }
    return detection;
}

MessageTemplate describeCamera(int layout) {
    return cameraLayoutText(static_cast<CameraLayout>(layout));
}
MessageTemplate describeLighting(int layout) {
    return lightingLayoutText(static_cast<LightingLayout>(layout));
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
// What the file holds, for the error when no layout fits: "3 lines with 3, 3, 1 numbers".
Message foundText(std::string_view text, const FileShape& shape, const Detection& detection) {
    Message found;
    if (shape.numbers.empty()) {
        const bool empty = text.empty() || text == "\xEF\xBB\xBF";  // a BOM alone is empty
        found = empty ? "an empty file"_msg : "only blank lines"_msg;
    } else if (shape.numbers.size() == 1) {
        found = "1 line with %1"_msg(numbersText(shape.numbers[0]));
    } else {
        found = "%1 lines with %2 numbers"_msg(shape.numbers.size(), countsText(shape.numbers));
    }
    if (detection.ambiguity.text().empty()) return found;
    return "%1 (%2)"_msg(found, detection.ambiguity);
}

template <typename Layout>
Result<std::pair<Layout, Message>> detectLayout(std::string_view text, const std::string& fileName,
                                                const std::vector<Profile>& profiles,
                                                MessageTemplate (*describe)(int),
                                                const Message& layoutsTried) {
    const FileShape shape = shapeOf(text);
    if (shape.hasEquals) return std::pair{Layout::KeyValue, Message("lines contain '='"_msg)};
    const Detection detection = chooseLayout(profiles, shape, describe);
    if (detection.layout >= 0)
        return std::pair{static_cast<Layout>(detection.layout), detection.why};
    return makeError(shape.numbers.empty() ? ErrorCode::MissingData : ErrorCode::Syntax,
                     startOf(text, fileName),
                     "expected %1 or key = value, found %2 (if the layout is known, choose it by "
                     "hand: --camera-format / --lighting-format, or File > Course File "
                     "Layouts)"_msg(layoutsTried, foundText(text, shape, detection)));
}

Result<std::pair<CameraLayout, Message>> detectCamera(std::string_view text,
                                                      const std::string& fileName) {
    return detectLayout<CameraLayout>(
        text, fileName, cameraProfiles(), describeCamera,
        "a camera in one of the layouts UFPE (C; N; V; d hx hy), UFRPE (N; V; d; hx; hy; C), "
        "UFRPE (C; N; V; hx hy; d)"_msg);
}

Result<std::pair<LightingLayout, Message>> detectLighting(std::string_view text,
                                                          const std::string& fileName) {
    return detectLayout<LightingLayout>(
        text, fileName, lightingProfiles(shapeOf(text).numbers.size()), describeLighting,
        "lighting in one of the layouts UFPE (Pl; ka; Ia; kd; Od; ks; Il; n), UFPE multi-light "
        "(ka; Ia; kd; Od; ks; n; L; L times Pl; Il), UFRPE (Iamb; Ka; Il; Pl; Kd; Od; Ks; n)"_msg);
}

// ---- the readers of each layout

Result<CourseCamera> readCameraAs(std::string_view text, const std::string& fileName,
                                  CameraLayout layout, Diagnostics& diagnostics) {
    if (layout == CameraLayout::KeyValue) return readKeyValueCamera(text, fileName, diagnostics);
    LineScanner scanner(text, fileName);
    if (layout == CameraLayout::Ufrpe6) {  // N; V; d; hx; hy; C
        auto f = readFieldLines(scanner, kUfrpeCamera6, "the camera's %1"_msg, diagnostics);
        if (!f) return f.error();
        const auto& v = f.value();
        return makeCamera(v[5], v[0], v[1], {&v[2], 0}, {&v[3], 0}, {&v[4], 0});
    }
    if (layout == CameraLayout::Ufrpe5) {  // C; N; V; hx hy; d
        auto f = readFieldLines(scanner, kUfrpeCamera5, "the camera's %1"_msg, diagnostics);
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
                         "expected the number of lights L (a positive whole number), found %1"_msg(
                             formatNumber(declared)));
    const long long available = scanner.countRemainingLines();
    if (declared > static_cast<double>(available / 2)) {
        const Message follow = counted(available, "%1 line follows"_msg, "%1 lines follow"_msg);
        if (declared >= 1e15)
            return makeError(ErrorCode::Range, lAt,
                             "L = %1 lights need twice as many lines after it (Pl and Il for "
                             "each), but only %2"_msg(formatNumber(declared), follow));
        const auto count = static_cast<long long>(declared);
        return makeError(
            ErrorCode::Range, lAt,
            "L = %1 lights need %2 lines after it (Pl and Il for each), but only %3"_msg(
                count, 2 * count, follow));
    }
    const auto lightCount = static_cast<std::size_t>(declared);
    std::vector<FieldValue> pairs;
    pairs.reserve(2 * lightCount);
    for (std::size_t k = 0; k < lightCount; ++k) {
        const FieldSpec pair[] = {{"Pl", kUfpeMultiLight[0].description, kThree, k + 1},
                                  {"Il", kUfpeMultiLight[1].description, kThree, k + 1}};
        auto fields = readFields(scanner, pair, diagnostics);
        if (!fields) return fields.error();
        for (FieldValue& f : fields.value()) pairs.push_back(std::move(f));
    }
    warnTrailingLines(scanner, "the lighting's %1"_msg,
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

}  // namespace

namespace {

Result<CourseLighting> readLightingAs(std::string_view text, const std::string& fileName,
                                      LightingLayout layout, Diagnostics& diagnostics) {
    if (layout == LightingLayout::KeyValue)
        return readKeyValueLighting(text, fileName, diagnostics);
    if (layout == LightingLayout::UfpeMulti) return readMultiLight(text, fileName, diagnostics);
    if (layout == LightingLayout::Ufrpe) {  // Iamb; Ka; Il; Pl; Kd; Od; Ks; n
        LineScanner scanner(text, fileName);
        auto f = readFieldLines(scanner, kUfrpeLighting, "the lighting's %1"_msg, diagnostics);
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

// An error under a layout the caller chose, followed by what detection would have chosen
// instead.
template <typename Layout>
Error withLayoutHint(const Error& error, Layout chosen,
                     const Result<std::pair<Layout, Message>>& detected,
                     MessageTemplate (*describe)(int)) {
    const Message chosenText = describe(static_cast<int>(chosen));
    if (!detected)
        return makeError(error.code, error.where,
                         "%1; the layout was set to %2"_msg(error.translatable, chosenText));
    if (detected->first == chosen) return error;
    return makeError(error.code, error.where,
                     "%1; the layout was set to %2, but the file looks like %3 (%4)"_msg(
                         error.translatable, chosenText,
                         describe(static_cast<int>(detected->first)), detected->second));
}

// Reads a camera or lighting file in the layout chosen, or in the one detected (Auto), with a
// note saying which and why; an error under a chosen layout says what detection would choose.
template <typename Layout, typename Detect, typename ReadAs, typename Flavour>
auto readInLayout(std::string_view text, const std::string& fileName, Diagnostics& diagnostics,
                  Layout layout, Detect detect, ReadAs readAs, Flavour flavour,
                  MessageTemplate (*describe)(int)) {
    using Part = decltype(readAs(text, fileName, layout, diagnostics));  // Result<...>
    Layout chosen = layout;
    Message why = "the layout was chosen, not detected"_msg;
    if (layout == Layout::Auto) {
        auto detected = detect(text, fileName);
        if (!detected) return Part(detected.error());
        chosen = detected->first;
        why = detected->second;
    }
    Diagnostics read;  // after the note
    auto part = readAs(text, fileName, chosen, read);
    if (!part) {
        diagnostics.append(read);
        if (layout == Layout::Auto) return part;
        return Part(withLayoutHint(part.error(), chosen, detect(text, fileName), describe));
    }
    diagnostics.note(SourceLocation{fileName, 0, 0}, "read as %1 (%2)"_msg(flavour(chosen), why));
    diagnostics.append(read);
    return part;
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
    return readInLayout(text, fileName, diagnostics, layout, detectCamera, readCameraAs,
                        cameraFlavour, describeCamera);
}

Result<CourseLighting> readLightingFile(std::string_view text, const std::string& fileName,
                                        Diagnostics& diagnostics, LightingLayout layout) {
    return readInLayout(text, fileName, diagnostics, layout, detectLighting, readLightingAs,
                        lightingFlavour, describeLighting);
}

}  // namespace rl
