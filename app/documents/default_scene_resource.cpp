#include "default_scene_resource.h"

#include <filesystem>

#include "app/documents/input_file.h"
#include "pipeline/scene/default_scene.h"

namespace rasterlab {

QString defaultScenePath(CoursePart part) {
    const char* name = part == CoursePart::Camera     ? rl::kDefaultCameraFile
                       : part == CoursePart::Lighting ? rl::kDefaultLightingFile
                                                      : rl::kDefaultObjectFile;
    return QStringLiteral(":/default-scene/") + QString::fromUtf8(name);
}

namespace {

template <typename Parse>
auto load(const QString& path, rl::Diagnostics& diagnostics, Parse parse)
    -> decltype(parse(std::string_view(), std::string(), diagnostics)) {
    auto bytes = readInputFile(path);
    if (!bytes) return bytes.error();
    const QByteArray& data = bytes.value();
    return parse(std::string_view(data.constData(), static_cast<std::size_t>(data.size())),
                 path.toStdString(), diagnostics);
}

// One of the files embedded in the program (the default scene, the shipped lessons): read in
// the layout detected, without a note saying so.
bool isEmbedded(const QString& path) {
    return path.startsWith(QStringLiteral(":/"));
}

// The object in any .byu flavour, named after its file.
rl::Result<rl::CourseObject> parseAnyObject(std::string_view text, const std::string& fileName,
                                            rl::Diagnostics& diagnostics) {
    auto mesh = rl::readByuObject(text, fileName, diagnostics);
    if (!mesh) return mesh.error();
    rl::CourseObject object;
    object.name = std::filesystem::path(fileName).filename().string();
    object.mesh = std::make_shared<const rl::Mesh>(std::move(mesh).value());
    return object;
}

}  // namespace

namespace {

// Reads a camera or lighting file: an embedded one in the layout detected in it, keeping its
// warnings but not the note naming the layout (the program's own files need no such note).
template <typename Layout, typename Detect, typename Read>
auto loadPart(const QString& path, rl::Diagnostics& diagnostics, Layout layout, Detect detect,
              Read read) {
    return load(path, diagnostics,
                [&](std::string_view text, const std::string& fileName, rl::Diagnostics& d) {
                    if (!isEmbedded(path)) return read(text, fileName, d, layout);
                    rl::Diagnostics all;
                    auto part = read(text, fileName, all, detect(text).value_or(Layout::Ufpe));
                    for (const rl::Diagnostic& item : all.items())
                        if (item.severity == rl::Severity::Warning) d.warn(item.where, item.translatable);
                    return part;
                });
}

}  // namespace

rl::Result<rl::CourseCamera> loadCamera(const QString& path, rl::Diagnostics& diagnostics,
                                        rl::CameraLayout layout) {
    return loadPart(path, diagnostics, layout, rl::detectCameraLayout, rl::readCameraFile);
}

rl::Result<rl::CourseLighting> loadLighting(const QString& path, rl::Diagnostics& diagnostics,
                                            rl::LightingLayout layout) {
    return loadPart(path, diagnostics, layout, rl::detectLightingLayout, rl::readLightingFile);
}

rl::Result<rl::CourseObject> loadObject(const QString& path, rl::Diagnostics& diagnostics) {
    return load(path, diagnostics, parseAnyObject);
}

rl::Result<rl::CourseSceneParts> loadDefaultCourseScene(rl::Diagnostics& diagnostics) {
    auto camera = loadCamera(defaultScenePath(CoursePart::Camera), diagnostics);
    if (!camera) return camera.error();
    auto lighting = loadLighting(defaultScenePath(CoursePart::Lighting), diagnostics);
    if (!lighting) return lighting.error();
    auto object = loadObject(defaultScenePath(CoursePart::Object), diagnostics);
    if (!object) return object.error();
    return rl::CourseSceneParts{camera.value(), lighting.value(), object.value()};
}

}  // namespace rasterlab
