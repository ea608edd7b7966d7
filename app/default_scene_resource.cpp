#include "default_scene_resource.h"

#include <filesystem>

#include "default_scene.h"
#include "input_file.h"

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

// One of the embedded default scene's files (UFPE layouts, read without a note).
bool isEmbeddedDefault(const QString& path) {
    return path.startsWith(QStringLiteral(":/default-scene/"));
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

rl::Result<rl::CourseCamera> loadCamera(const QString& path, rl::Diagnostics& diagnostics,
                                        rl::CameraLayout layout) {
    if (isEmbeddedDefault(path)) return load(path, diagnostics, rl::readCourseCamera);
    return load(path, diagnostics,
                [layout](std::string_view text, const std::string& fileName, rl::Diagnostics& d) {
                    return rl::readCameraFile(text, fileName, d, layout);
                });
}

rl::Result<rl::CourseLighting> loadLighting(const QString& path, rl::Diagnostics& diagnostics,
                                            rl::LightingLayout layout) {
    if (isEmbeddedDefault(path)) return load(path, diagnostics, rl::readCourseLighting);
    return load(path, diagnostics,
                [layout](std::string_view text, const std::string& fileName, rl::Diagnostics& d) {
                    return rl::readLightingFile(text, fileName, d, layout);
                });
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
