#include "lesson_file.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocale>

#include <algorithm>
#include <array>
#include <cmath>

#include "app/documents/input_file.h"

namespace rasterlab {

namespace {

using Field = SceneDocument::Field;
using rl::operator""_msg;  // message templates, translated in the window (pipeline_messages.h)

QString lit(const char* text) {
    return QString::fromLatin1(text);
}

// The names of the edited values in a lesson file: the course's own keys (those of key =
// value files), so that a teacher can read them.
struct FieldKey {
    Field field;
    const char* key;
};
constexpr std::array<FieldKey, 6> kCameraKeys = {{
    {Field::C, "C"}, {Field::N, "N"}, {Field::V, "V"},
    {Field::D, "d"}, {Field::Hx, "hx"}, {Field::Hy, "hy"},
}};
constexpr std::array<FieldKey, 9> kLightingKeys = {{
    {Field::Ambient, "Iamb"}, {Field::Ka, "Ka"}, {Field::Kd, "Kd"},
    {Field::Od, "Od"}, {Field::Ks, "Ks"}, {Field::Shininess, "eta"},
    {Field::Emission, "Ke"}, {Field::TwoSided, "two_sided"}, {Field::BlinnPhong, "blinn"},
}};
constexpr std::array<FieldKey, 7> kLightKeys = {{
    {Field::LightPosition, "Pl"}, {Field::LightDirectional, "directional"},
    {Field::LightIntensity, "Il"}, {Field::LightAttenuation, "atten"},
    {Field::LightSpotDirection, "spot_dir"}, {Field::LightSpotCutoff, "spot_cutoff"},
    {Field::LightSpotExponent, "spot_exp"},
}};

constexpr std::array<rl::StepGranularity, 5> kGranularities = {
    rl::StepGranularity::Stage, rl::StepGranularity::Triangle, rl::StepGranularity::Scanline,
    rl::StepGranularity::Span, rl::StepGranularity::Pixel};
constexpr std::array<const char*, 5> kGranularityKeys = {"stage", "triangle", "scanline", "span",
                                                         "pixel"};

struct BreakpointKey {
    rl::Breakpoint::Kind kind;
    const char* key;
};
constexpr std::array<BreakpointKey, 5> kBreakpointKeys = {{
    {rl::Breakpoint::Kind::Triangle, "triangle"},
    {rl::Breakpoint::Kind::Scanline, "scanline"},
    {rl::Breakpoint::Kind::DepthRejection, "depth-rejection"},
    {rl::Breakpoint::Kind::LightBehind, "light-behind"},
    {rl::Breakpoint::Kind::NthWrite, "nth-write"},
}};

struct ProjectionKey {
    rl::NearPlane::Mode mode;
    const char* key;
};
constexpr std::array<ProjectionKey, 3> kProjectionKeys = {{
    {rl::NearPlane::Mode::Clip, "clip"},
    {rl::NearPlane::Mode::Naive, "plain-divide"},
    {rl::NearPlane::Mode::SameSide, "same-side"},
}};

QString quoted(const QStringList& names) {
    return names.join(lit(", "));
}

// Where a key sits in the text: its line and column, found by looking for each key of its
// path in turn ("edits", "lighting", "lights", "Pl"), each after the one before. An array
// index n moves to the n-th '{' after the array's key.
class Locator {
public:
    Locator(const QByteArray& text, const QString& fileName) : m_text(text), m_file(fileName) {}

    rl::SourceLocation at(const QStringList& path) const {
        qsizetype pos = 0;
        for (const QString& step : path) {
            bool isIndex = false;
            const int index = step.toInt(&isIndex);
            if (isIndex) {
                for (int k = 0; k <= index && pos >= 0; ++k) pos = m_text.indexOf('{', pos + 1);
            } else {
                const qsizetype found = m_text.indexOf('"' + step.toUtf8() + '"', pos);
                if (found >= 0) pos = found;
            }
            if (pos < 0) pos = 0;
        }
        return location(pos);
    }
    rl::SourceLocation location(qsizetype offset) const {
        int line = 1, column = 1;
        for (qsizetype i = 0; i < offset && i < m_text.size(); ++i) {
            if (m_text[i] == '\n') {
                ++line;
                column = 1;
            } else if ((m_text[i] & 0xC0) != 0x80) {  // count characters, not UTF-8 bytes
                ++column;
            }
        }
        return {m_file.toStdString(), line, column};
    }
    const QString& file() const { return m_file; }

private:
    const QByteArray& m_text;
    QString m_file;
};

// What a JSON value is, as an error message says it was found.
rl::Message typeName(const QJsonValue& value) {
    switch (value.type()) {
        case QJsonValue::Null: return "null"_msg;
        case QJsonValue::Bool: return "true or false"_msg;
        case QJsonValue::Double: return "a number"_msg;
        case QJsonValue::String: return "the text '%1'"_msg(value.toString().toStdString());
        case QJsonValue::Array: return "a list"_msg;
        case QJsonValue::Object: return "an object"_msg;
        case QJsonValue::Undefined: break;
    }
    return "nothing"_msg;
}

// Reads one JSON object's keys, each checked, with errors at the key's place.
class Reader {
public:
    Reader(const Locator& locator, rl::Diagnostics& diagnostics)
        : m_locator(locator), m_diagnostics(diagnostics) {}

    std::optional<rl::Error> error() const { return m_error; }

    rl::Error fail(const QStringList& path, rl::Message message) {
        rl::Error e = rl::makeError(rl::ErrorCode::Syntax, m_locator.at(path), std::move(message));
        if (!m_error) m_error = e;
        return e;
    }
    void expected(const QStringList& path, const rl::Message& what, const QJsonValue& found) {
        fail(path, "expected %1 for \"%2\", found %3"_msg(what, path.last().toStdString(),
                                                          typeName(found)));
    }
    // Keys of `object` that are not in `known`: a warning each, the rest of the file read.
    void warnUnknown(const QJsonObject& object, const QStringList& path, const QStringList& known) {
        for (const QString& key : object.keys())
            if (!known.contains(key))
                m_diagnostics.warn(m_locator.at(path + QStringList{key}),
                                   "unknown key \"%1\" ignored (known here: %2)"_msg(
                                       key.toStdString(), quoted(known).toStdString()));
    }

    std::optional<double> number(const QJsonValue& value, const QStringList& path) {
        if (!value.isDouble()) {
            expected(path, "a number"_msg, value);
            return std::nullopt;
        }
        return value.toDouble();
    }
    std::optional<int> whole(const QJsonValue& value, const QStringList& path, int lowest) {
        const double v = value.toDouble(-1e300);
        if (!value.isDouble() || v != double(int(v)) || v < lowest || v > 1e9) {
            expected(path, "a whole number from %1"_msg(lowest), value);
            return std::nullopt;
        }
        return int(v);
    }
    std::optional<std::vector<double>> numbers(const QJsonValue& value, const QStringList& path,
                                               int count) {
        const QJsonArray array = value.toArray();
        bool ok = value.isArray() && array.size() == count;
        std::vector<double> out;
        for (const QJsonValue& v : array) {
            ok = ok && v.isDouble();
            out.push_back(v.toDouble());
        }
        if (!ok) {
            expected(path, "a list of %1 numbers"_msg(count), value);
            return std::nullopt;
        }
        return out;
    }
    std::optional<QString> text(const QJsonValue& value, const QStringList& path) {
        if (!value.isString()) {
            expected(path, "text in quotes"_msg, value);
            return std::nullopt;
        }
        return value.toString();
    }
    std::optional<bool> flag(const QJsonValue& value, const QStringList& path) {
        if (!value.isBool()) {
            expected(path, "true or false"_msg, value);
            return std::nullopt;
        }
        return value.toBool();
    }
    // One of a list of names; the names are listed in the message when it is not one.
    template <typename T, std::size_t N>
    std::optional<T> choice(const QJsonValue& value, const QStringList& path,
                            const std::array<T, N>& values, const std::array<const char*, N>& keys) {
        QStringList names;
        for (const char* key : keys) names << lit(key);
        const qsizetype i = names.indexOf(value.toString());
        if (!value.isString() || i < 0) {
            expected(path, "one of %1"_msg(quoted(names).toStdString()), value);
            return std::nullopt;
        }
        return values[std::size_t(i)];
    }

private:
    const Locator& m_locator;
    rl::Diagnostics& m_diagnostics;
    std::optional<rl::Error> m_error;
};

template <std::size_t N>
QStringList keysOf(const std::array<FieldKey, N>& keys) {
    QStringList out;
    for (const FieldKey& k : keys) out << lit(k.key);
    return out;
}

// The edited values of one part (or one light), as numbers under their course keys.
template <std::size_t N>
void readFields(Reader& r, const QJsonObject& object, const QStringList& path,
                const std::array<FieldKey, N>& keys, std::size_t light, Lesson& lesson) {
    for (const FieldKey& k : keys) {
        const QJsonValue value = object.value(lit(k.key));
        if (value.isUndefined()) continue;
        const int count = SceneDocument::componentCount(k.field);
        const QStringList at = path + QStringList{lit(k.key)};
        Lesson::Edit edit{k.field, light, {}};
        if (count == 1) {
            const auto v = r.number(value, at);
            if (!v) return;
            edit.value[0] = *v;
        } else {
            const auto v = r.numbers(value, at, count);
            if (!v) return;
            for (int i = 0; i < count; ++i) edit.value[std::size_t(i)] = (*v)[std::size_t(i)];
        }
        lesson.edits.push_back(edit);
    }
}

void readEdits(Reader& r, const QJsonObject& edits, Lesson& lesson) {
    r.warnUnknown(edits, {lit("edits")}, {lit("camera"), lit("lighting")});
    const QJsonObject camera = edits.value(lit("camera")).toObject();
    r.warnUnknown(camera, {lit("edits"), lit("camera")}, keysOf(kCameraKeys));
    readFields(r, camera, {lit("edits"), lit("camera")}, kCameraKeys, 0, lesson);
    const QJsonObject lighting = edits.value(lit("lighting")).toObject();
    const QStringList at{lit("edits"), lit("lighting")};
    r.warnUnknown(lighting, at, keysOf(kLightingKeys) << lit("lights"));
    readFields(r, lighting, at, kLightingKeys, 0, lesson);
    if (!lighting.contains(lit("lights"))) return;
    const QJsonValue lights = lighting.value(lit("lights"));
    if (!lights.isArray() || lights.toArray().isEmpty() || lights.toArray().size() > 8) {
        r.expected(at + QStringList{lit("lights")}, "a list of 1 to 8 lights"_msg, lights);
        return;
    }
    const QJsonArray list = lights.toArray();
    lesson.lightCount = std::size_t(list.size());
    for (qsizetype i = 0; i < list.size(); ++i) {
        const QStringList lightPath = at + QStringList{lit("lights"), QString::number(i)};
        r.warnUnknown(list[i].toObject(), lightPath, keysOf(kLightKeys));
        readFields(r, list[i].toObject(), lightPath, kLightKeys, std::size_t(i), lesson);
    }
}

void readScene(Reader& r, const QJsonObject& scene, Lesson& lesson) {
    const QStringList known = {lit("example"),       lit("camera"),        lit("lighting"),
                               lit("object"),        lit("command_file"),  lit("image"),
                               lit("camera_layout"), lit("lighting_layout")};
    r.warnUnknown(scene, {lit("scene")}, known);
    const auto path = [](const char* key) { return QStringList{lit("scene"), lit(key)}; };
    const auto textOf = [&](const char* key, QString& out) {
        if (scene.contains(lit(key)))
            if (auto v = r.text(scene.value(lit(key)), path(key))) out = *v;
    };
    textOf("example", lesson.example);
    textOf("camera", lesson.camera);
    textOf("lighting", lesson.lighting);
    textOf("object", lesson.object);
    textOf("command_file", lesson.commandFile);
    if (scene.contains(lit("image")))
        if (auto v = r.whole(scene.value(lit("image")), path("image"), 0)) lesson.commandImage = *v;
    if (scene.contains(lit("camera_layout"))) {
        const QString name = scene.value(lit("camera_layout")).toString();
        if (auto layout = rl::cameraLayoutFromName(name.toStdString()))
            lesson.cameraLayout = *layout;
        else
            r.expected(path("camera_layout"), "one of %1"_msg("auto, ufpe, ufrpe6, ufrpe5, keyvalue"),
                       scene.value(lit("camera_layout")));
    }
    if (scene.contains(lit("lighting_layout"))) {
        const QString name = scene.value(lit("lighting_layout")).toString();
        if (auto layout = rl::lightingLayoutFromName(name.toStdString()))
            lesson.lightingLayout = *layout;
        else
            r.expected(path("lighting_layout"), "one of %1"_msg("auto, ufpe, multi, ufrpe, keyvalue"),
                       scene.value(lit("lighting_layout")));
    }
}

std::optional<SceneDocument::Animation> readAnimation(Reader& r, const QJsonObject& a) {
    const QStringList at{lit("animation")};
    r.warnUnknown(a, at,
                  {lit("enabled"), lit("time"), lit("degrees_per_second"), lit("axis"),
                   lit("centre"), lit("velocity"), lit("scale")});
    SceneDocument::Animation out;
    const auto vector = [&](const char* key) -> std::optional<rl::dvec3> {
        if (!a.contains(lit(key))) return std::nullopt;
        auto v = r.numbers(a.value(lit(key)), at + QStringList{lit(key)}, 3);
        if (!v) return std::nullopt;
        return rl::dvec3((*v)[0], (*v)[1], (*v)[2]);
    };
    if (a.contains(lit("enabled")))
        out.enabled = r.flag(a.value(lit("enabled")), at + QStringList{lit("enabled")}).value_or(false);
    if (a.contains(lit("time")))
        out.time = r.number(a.value(lit("time")), at + QStringList{lit("time")}).value_or(0.0);
    if (a.contains(lit("degrees_per_second")))
        out.motion.degreesPerSecond =
            r.number(a.value(lit("degrees_per_second")), at + QStringList{lit("degrees_per_second")})
                .value_or(36.0);
    out.motion.axis = vector("axis");
    out.motion.centre = vector("centre");
    out.motion.velocity = vector("velocity").value_or(rl::dvec3(0.0));
    out.motion.scale = vector("scale").value_or(rl::dvec3(1.0));
    return out;
}

std::optional<rl::Breakpoint> readBreakpoint(Reader& r, const QJsonObject& b, const QStringList& at) {
    r.warnUnknown(b, at, {lit("kind"), lit("triangle"), lit("x"), lit("y"), lit("n"), lit("enabled")});
    std::array<rl::Breakpoint::Kind, kBreakpointKeys.size()> kinds{};
    std::array<const char*, kBreakpointKeys.size()> names{};
    for (std::size_t i = 0; i < kBreakpointKeys.size(); ++i) {
        kinds[i] = kBreakpointKeys[i].kind;
        names[i] = kBreakpointKeys[i].key;
    }
    const auto kind = r.choice(b.value(lit("kind")), at + QStringList{lit("kind")}, kinds, names);
    if (!kind) return std::nullopt;
    rl::Breakpoint out;
    out.kind = *kind;
    const auto whole = [&](const char* key, int lowest, auto& field) {
        if (!b.contains(lit(key))) return;
        if (auto v = r.whole(b.value(lit(key)), at + QStringList{lit(key)}, lowest))
            field = static_cast<std::remove_reference_t<decltype(field)>>(*v);
    };
    whole("triangle", 0, out.triangle);
    whole("x", -1, out.x);
    whole("y", -1, out.y);
    whole("n", 1, out.n);
    if (b.contains(lit("enabled")))
        out.enabled = r.flag(b.value(lit("enabled")), at + QStringList{lit("enabled")}).value_or(true);
    return out;
}

void readStepping(Reader& r, const QJsonObject& s, Lesson& lesson) {
    const QStringList at{lit("stepping")};
    r.warnUnknown(s, at, {lit("granularity"), lit("stage"), lit("cursor"), lit("pixel"),
                          lit("breakpoints")});
    if (s.contains(lit("granularity")))
        lesson.granularity = r.choice(s.value(lit("granularity")), at + QStringList{lit("granularity")},
                                      kGranularities, kGranularityKeys);
    if (s.contains(lit("stage"))) {
        std::array<rl::StageId, rl::kStageCount> stages{};
        std::array<const char*, rl::kStageCount> names{};
        for (int i = 0; i < rl::kStageCount; ++i) {
            stages[std::size_t(i)] = rl::kAllStages[std::size_t(i)];
            names[std::size_t(i)] = rl::stageName(rl::kAllStages[std::size_t(i)]);
        }
        lesson.stage = r.choice(s.value(lit("stage")), at + QStringList{lit("stage")}, stages, names);
    }
    if (s.contains(lit("cursor"))) {
        const auto v = r.numbers(s.value(lit("cursor")), at + QStringList{lit("cursor")}, 2);
        if (v && (*v)[0] >= 0 && (*v)[1] >= 0 && (*v)[0] < 4e9 && (*v)[1] < 4e9)
            lesson.cursor = rl::ReplayCursor{std::uint32_t((*v)[0]), std::uint32_t((*v)[1])};
        else if (v)
            r.expected(at + QStringList{lit("cursor")}, "[rows, fragments], two whole numbers"_msg,
                       s.value(lit("cursor")));
    }
    if (s.contains(lit("pixel"))) {
        if (auto v = r.numbers(s.value(lit("pixel")), at + QStringList{lit("pixel")}, 2))
            lesson.pixel = QPoint(int((*v)[0]), int((*v)[1]));
    }
    if (!s.contains(lit("breakpoints"))) return;
    const QJsonValue list = s.value(lit("breakpoints"));
    if (!list.isArray()) {
        r.expected(at + QStringList{lit("breakpoints")}, "a list"_msg, list);
        return;
    }
    std::vector<rl::Breakpoint> breakpoints;
    const QJsonArray array = list.toArray();
    for (qsizetype i = 0; i < array.size(); ++i)
        if (auto b = readBreakpoint(r, array[i].toObject(),
                                    at + QStringList{lit("breakpoints"), QString::number(i)}))
            breakpoints.push_back(*b);
    lesson.breakpoints = std::move(breakpoints);
}

QStringList stringList(Reader& r, const QJsonValue& value, const QStringList& path) {
    QStringList out;
    if (!value.isArray()) {
        r.expected(path, "a list of dock names"_msg, value);
        return out;
    }
    for (const QJsonValue& v : value.toArray()) {
        if (!v.isString()) {
            r.expected(path, "a list of dock names"_msg, value);
            return {};
        }
        out << v.toString();
    }
    return out;
}

void readWindow(Reader& r, const QJsonObject& w, Lesson& lesson) {
    const QStringList at{lit("window")};
    r.warnUnknown(w, at, {lit("zoom"), lit("centre"), lit("docks_shown"), lit("docks_raised"),
                          lit("dock_state"), lit("presentation"), lit("text_zoom")});
    if (w.contains(lit("zoom"))) {
        const QJsonValue zoom = w.value(lit("zoom"));
        if (zoom.toString() != lit("fit")) {
            if (zoom.isDouble() && zoom.toDouble() > 0.0)
                lesson.zoom = zoom.toDouble();
            else
                r.expected(at + QStringList{lit("zoom")}, "a positive number or \"fit\""_msg, zoom);
        }
    }
    if (w.contains(lit("centre")))
        if (auto v = r.numbers(w.value(lit("centre")), at + QStringList{lit("centre")}, 2))
            lesson.centre = QPointF((*v)[0], (*v)[1]);
    if (w.contains(lit("docks_shown")))
        lesson.docksShown = stringList(r, w.value(lit("docks_shown")), at + QStringList{lit("docks_shown")});
    if (w.contains(lit("docks_raised")))
        lesson.docksRaised =
            stringList(r, w.value(lit("docks_raised")), at + QStringList{lit("docks_raised")});
    if (w.contains(lit("dock_state")))
        if (auto v = r.text(w.value(lit("dock_state")), at + QStringList{lit("dock_state")}))
            lesson.dockState = QByteArray::fromBase64(v->toLatin1());
    if (w.contains(lit("presentation")))
        lesson.presentation = r.flag(w.value(lit("presentation")), at + QStringList{lit("presentation")});
    // The window keeps the zoom to its steps' range.
    if (w.contains(lit("text_zoom")))
        lesson.textZoom = r.number(w.value(lit("text_zoom")), at + QStringList{lit("text_zoom")});
}

// Check My Renderer's command and folder.
void readCheck(Reader& r, const QJsonObject& c, Lesson& lesson) {
    const QStringList at{lit("check")};
    r.warnUnknown(c, at, {lit("command"), lit("folder")});
    if (c.contains(lit("command")))
        lesson.checkCommand = r.text(c.value(lit("command")), at + QStringList{lit("command")}).value_or(QString());
    if (c.contains(lit("folder")))
        lesson.checkFolder = r.text(c.value(lit("folder")), at + QStringList{lit("folder")}).value_or(QString());
}

void readRendering(Reader& r, const QJsonObject& top, Lesson& lesson) {
    if (top.contains(lit("shading"))) {
        const QString name = top.value(lit("shading")).toString();
        lesson.shading = rl::shadingModelFromName(name.toStdString());
        if (!lesson.shading)
            r.expected({lit("shading")}, "one of %1"_msg("phong, flat, gouraud, painter"),
                       top.value(lit("shading")));
    }
    if (top.contains(lit("rules"))) {
        lesson.rules = rl::ruleSetFromName(top.value(lit("rules")).toString().toStdString());
        if (!lesson.rules)
            r.expected({lit("rules")}, "one of %1"_msg("course, gpu, hw2"), top.value(lit("rules")));
    }
    if (top.contains(lit("projection"))) {
        std::array<rl::NearPlane::Mode, kProjectionKeys.size()> modes{};
        std::array<const char*, kProjectionKeys.size()> names{};
        for (std::size_t i = 0; i < kProjectionKeys.size(); ++i) {
            modes[i] = kProjectionKeys[i].mode;
            names[i] = kProjectionKeys[i].key;
        }
        lesson.projection = r.choice(top.value(lit("projection")), {lit("projection")}, modes, names);
    }
    if (top.contains(lit("near"))) {
        const QJsonValue near = top.value(lit("near"));
        if (near.isDouble() && near.toDouble() > 0.0)
            lesson.nearW = near.toDouble();
        else if (near.toString() != lit("auto"))
            r.expected({lit("near")}, "a positive number or \"auto\""_msg, near);
    }
    if (top.contains(lit("image_size"))) {
        const QJsonValue size = top.value(lit("image_size"));
        const QJsonArray wh = size.toArray();
        const int w = wh.at(0).toInt(-1), h = wh.at(1).toInt(-1);
        if (size.isArray() && wh.size() == 2 && w >= 1 && h >= 1 && w <= 4096 && h <= 4096)
            lesson.imageSize = QSize(w, h);
        else
            r.expected({lit("image_size")}, "[width, height], whole numbers from %1 to %2"_msg(1, 4096),
                       size);
    }
    if (top.contains(lit("animation")))
        lesson.animation = readAnimation(r, top.value(lit("animation")).toObject());
}

}  // namespace

QString granularityKey(rl::StepGranularity granularity) {
    for (std::size_t i = 0; i < kGranularities.size(); ++i)
        if (kGranularities[i] == granularity) return lit(kGranularityKeys[i]);
    return {};
}

std::optional<rl::StepGranularity> granularityFromKey(const QString& key) {
    for (std::size_t i = 0; i < kGranularities.size(); ++i)
        if (key == lit(kGranularityKeys[i])) return kGranularities[i];
    return std::nullopt;
}

rl::Result<Lesson> parseLesson(const QByteArray& text, const QString& fileName,
                               rl::Diagnostics& diagnostics) {
    const Locator locator(text, fileName);
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(text, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return rl::makeError(rl::ErrorCode::Syntax, locator.location(parseError.offset),
                             "not a lesson file: %1"_msg(parseError.errorString().toStdString()));
    const QJsonObject top = document.object();
    if (!document.isObject() || top.value(lit("rasterlab_lesson")).toInt(-1) != Lesson::kVersion)
        return rl::makeError(rl::ErrorCode::Unsupported, locator.location(0),
                             "expected a lesson file: a JSON object with \"rasterlab_lesson\": %1"_msg(
                                 Lesson::kVersion));
    rl::Diagnostics warnings;
    Reader r(locator, warnings);
    r.warnUnknown(top, {},
                  {lit("rasterlab_lesson"), lit("title"), lit("notes"), lit("scene"), lit("edits"),
                   lit("shading"), lit("rules"), lit("projection"), lit("near"), lit("image_size"),
                   lit("animation"), lit("stepping"), lit("window"), lit("check")});
    Lesson lesson;
    if (top.contains(lit("title"))) lesson.title = r.text(top.value(lit("title")), {lit("title")}).value_or(QString());
    if (top.contains(lit("notes"))) lesson.notes = r.text(top.value(lit("notes")), {lit("notes")}).value_or(QString());
    readScene(r, top.value(lit("scene")).toObject(), lesson);
    readEdits(r, top.value(lit("edits")).toObject(), lesson);
    readRendering(r, top, lesson);
    readStepping(r, top.value(lit("stepping")).toObject(), lesson);
    readWindow(r, top.value(lit("window")).toObject(), lesson);
    readCheck(r, top.value(lit("check")).toObject(), lesson);
    if (r.error()) return *r.error();
    diagnostics.append(warnings);
    return lesson;
}

rl::Result<Lesson> readLesson(const QString& path, rl::Diagnostics& diagnostics) {
    auto bytes = readInputFile(path);
    if (!bytes) return bytes.error();
    return parseLesson(bytes.value(), path, diagnostics);
}

namespace {

QJsonArray jsonNumbers(const SceneDocument::Numbers& value, int count) {
    QJsonArray out;
    for (int i = 0; i < count; ++i) out.append(value[std::size_t(i)]);
    return out;
}

QJsonValue fieldJson(const Lesson::Edit& edit) {
    const int count = SceneDocument::componentCount(edit.field);
    return count == 1 ? QJsonValue(edit.value[0]) : QJsonValue(jsonNumbers(edit.value, count));
}

template <std::size_t N>
const char* keyOf(const std::array<FieldKey, N>& keys, Field field) {
    for (const FieldKey& k : keys)
        if (k.field == field) return k.key;
    return nullptr;
}

QJsonObject editsJson(const Lesson& lesson) {
    QJsonObject camera, lighting;
    QJsonArray lights;
    const std::size_t lightCount = lesson.lightCount.value_or(0);
    std::vector<QJsonObject> lightObjects(lightCount);
    for (const Lesson::Edit& edit : lesson.edits) {
        if (const char* key = keyOf(kCameraKeys, edit.field)) camera[lit(key)] = fieldJson(edit);
        if (const char* key = keyOf(kLightingKeys, edit.field)) lighting[lit(key)] = fieldJson(edit);
        if (const char* key = keyOf(kLightKeys, edit.field); key && edit.light < lightCount)
            lightObjects[edit.light][lit(key)] = fieldJson(edit);
    }
    for (const QJsonObject& light : lightObjects) lights.append(light);
    if (lesson.lightCount) lighting[lit("lights")] = lights;
    QJsonObject edits;
    if (!camera.isEmpty()) edits[lit("camera")] = camera;
    if (!lighting.isEmpty()) edits[lit("lighting")] = lighting;
    return edits;
}

QJsonObject sceneJson(const Lesson& lesson) {
    QJsonObject scene;
    const auto put = [&](const char* key, const QString& value) {
        if (!value.isEmpty()) scene[lit(key)] = value;
    };
    put("example", lesson.example);
    put("camera", lesson.camera);
    put("lighting", lesson.lighting);
    put("object", lesson.object);
    put("command_file", lesson.commandFile);
    if (!lesson.commandFile.isEmpty()) scene[lit("image")] = lesson.commandImage;
    if (lesson.cameraLayout != rl::CameraLayout::Auto)
        scene[lit("camera_layout")] = lit(rl::cameraLayoutName(lesson.cameraLayout));
    if (lesson.lightingLayout != rl::LightingLayout::Auto)
        scene[lit("lighting_layout")] = lit(rl::lightingLayoutName(lesson.lightingLayout));
    return scene;
}

QJsonArray vectorJson(const rl::dvec3& v) {
    return {v.x, v.y, v.z};
}

QJsonObject animationJson(const SceneDocument::Animation& a) {
    QJsonObject out{{lit("enabled"), a.enabled},
                    {lit("time"), a.time},
                    {lit("degrees_per_second"), a.motion.degreesPerSecond},
                    {lit("velocity"), vectorJson(a.motion.velocity)},
                    {lit("scale"), vectorJson(a.motion.scale)}};
    if (a.motion.axis) out[lit("axis")] = vectorJson(*a.motion.axis);
    if (a.motion.centre) out[lit("centre")] = vectorJson(*a.motion.centre);
    return out;
}

QJsonObject breakpointJson(const rl::Breakpoint& b) {
    QJsonObject out;
    for (const BreakpointKey& k : kBreakpointKeys)
        if (k.kind == b.kind) out[lit("kind")] = lit(k.key);
    switch (b.kind) {
        case rl::Breakpoint::Kind::Triangle:
            out[lit("triangle")] = qint64(b.triangle);
            break;
        case rl::Breakpoint::Kind::Scanline:
            out[lit("y")] = b.y;
            break;
        case rl::Breakpoint::Kind::NthWrite:
            out[lit("n")] = qint64(b.n);
            [[fallthrough]];
        case rl::Breakpoint::Kind::DepthRejection:
        case rl::Breakpoint::Kind::LightBehind:
            out[lit("x")] = b.x;
            out[lit("y")] = b.y;
            break;
    }
    out[lit("enabled")] = b.enabled;
    return out;
}

QJsonObject steppingJson(const Lesson& lesson) {
    QJsonObject s;
    if (lesson.granularity) s[lit("granularity")] = granularityKey(*lesson.granularity);
    if (lesson.stage) s[lit("stage")] = lit(rl::stageName(*lesson.stage));
    if (lesson.cursor)
        s[lit("cursor")] = QJsonArray{qint64(lesson.cursor->rows), qint64(lesson.cursor->fragments)};
    if (lesson.pixel) s[lit("pixel")] = QJsonArray{lesson.pixel->x(), lesson.pixel->y()};
    if (lesson.breakpoints) {
        QJsonArray list;
        for (const rl::Breakpoint& b : *lesson.breakpoints) list.append(breakpointJson(b));
        s[lit("breakpoints")] = list;
    }
    return s;
}

QJsonObject windowJson(const Lesson& lesson) {
    QJsonObject w;
    w[lit("zoom")] = lesson.zoom ? QJsonValue(*lesson.zoom) : QJsonValue(lit("fit"));
    if (lesson.centre) w[lit("centre")] = QJsonArray{lesson.centre->x(), lesson.centre->y()};
    if (!lesson.docksShown.isEmpty()) w[lit("docks_shown")] = QJsonArray::fromStringList(lesson.docksShown);
    if (!lesson.docksRaised.isEmpty())
        w[lit("docks_raised")] = QJsonArray::fromStringList(lesson.docksRaised);
    if (!lesson.dockState.isEmpty()) w[lit("dock_state")] = QString::fromLatin1(lesson.dockState.toBase64());
    if (lesson.presentation) w[lit("presentation")] = *lesson.presentation;
    if (lesson.textZoom) w[lit("text_zoom")] = *lesson.textZoom;
    return w;
}

}  // namespace

namespace {

// The order keys are written in: the version first, then as a lesson reads; other keys after,
// alphabetically.
int keyRank(const QString& key) {
    static const QStringList order = {
        lit("rasterlab_lesson"), lit("title"),    lit("notes"),      lit("scene"),
        lit("example"),          lit("camera"),   lit("lighting"),   lit("object"),
        lit("edits"),            lit("shading"),  lit("rules"),      lit("projection"),
        lit("near"),             lit("image_size"), lit("animation"), lit("stepping"),
        lit("window"),           lit("check")};
    const qsizetype i = order.indexOf(key);
    return i < 0 ? int(order.size()) : int(i);
}

QByteArray scalarJson(const QJsonValue& value) {
    if (value.isDouble()) {
        const double v = value.toDouble();
        if (v == double(qint64(v)) && std::abs(v) < 1e15) return QByteArray::number(qint64(v));
        return QByteArray::number(v, 'g', QLocale::FloatingPointShortest);
    }
    // Strings, booleans and null as Qt writes them (escaped), without the list around them.
    const QByteArray list = QJsonDocument(QJsonArray{value}).toJson(QJsonDocument::Compact);
    return list.mid(1, list.size() - 2);
}

// Indented JSON with lists of plain values on one line ([800, 600]), so that a teacher can
// read and edit the file.
void writeJson(const QJsonValue& value, int indent, QByteArray& out) {
    const QByteArray pad(indent + 4, ' ');
    if (value.isObject()) {
        const QJsonObject object = value.toObject();
        QStringList keys = object.keys();
        std::stable_sort(keys.begin(), keys.end(), [](const QString& a, const QString& b) {
            return keyRank(a) < keyRank(b);
        });
        out += "{\n";
        for (qsizetype i = 0; i < keys.size(); ++i) {
            out += pad + scalarJson(keys[i]) + ": ";
            writeJson(object.value(keys[i]), indent + 4, out);
            out += i + 1 < keys.size() ? ",\n" : "\n";
        }
        out += QByteArray(indent, ' ') + '}';
    } else if (value.isArray()) {
        const QJsonArray array = value.toArray();
        const bool flat = std::none_of(array.begin(), array.end(), [](const QJsonValue& v) {
            return v.isObject() || v.isArray();
        });
        out += flat ? "[" : "[\n";
        for (qsizetype i = 0; i < array.size(); ++i) {
            if (!flat) out += pad;
            writeJson(array[i], indent + 4, out);
            if (i + 1 < array.size()) out += flat ? ", " : ",\n";
        }
        out += flat ? QByteArray("]") : "\n" + QByteArray(indent, ' ') + ']';
    } else {
        out += scalarJson(value);
    }
}

}  // namespace

QByteArray lessonJson(const Lesson& lesson) {
    QJsonObject top;
    top[lit("rasterlab_lesson")] = Lesson::kVersion;
    if (!lesson.title.isEmpty()) top[lit("title")] = lesson.title;
    if (!lesson.notes.isEmpty()) top[lit("notes")] = lesson.notes;
    top[lit("scene")] = sceneJson(lesson);
    if (const QJsonObject edits = editsJson(lesson); !edits.isEmpty()) top[lit("edits")] = edits;
    if (lesson.shading) top[lit("shading")] = lit(rl::shadingModelName(*lesson.shading));
    if (lesson.rules) top[lit("rules")] = lit(rl::ruleSetName(*lesson.rules));
    for (const ProjectionKey& k : kProjectionKeys)
        if (lesson.projection == k.mode) top[lit("projection")] = lit(k.key);
    top[lit("near")] = lesson.nearW ? QJsonValue(*lesson.nearW) : QJsonValue(lit("auto"));
    if (lesson.imageSize)
        top[lit("image_size")] = QJsonArray{lesson.imageSize->width(), lesson.imageSize->height()};
    if (lesson.animation) top[lit("animation")] = animationJson(*lesson.animation);
    if (const QJsonObject s = steppingJson(lesson); !s.isEmpty()) top[lit("stepping")] = s;
    top[lit("window")] = windowJson(lesson);
    if (!lesson.checkCommand.isEmpty() || !lesson.checkFolder.isEmpty())
        top[lit("check")] = QJsonObject{{lit("command"), lesson.checkCommand},
                                        {lit("folder"), lesson.checkFolder}};
    QByteArray out;
    writeJson(top, 0, out);
    return out + '\n';
}

}  // namespace rasterlab
