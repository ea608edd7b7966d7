#include "scene_document.h"

#include <QFile>

#include <new>

#include "camera_basis.h"
#include "command_file.h"
#include "default_scene_resource.h"

namespace rasterlab {

rl::Status SceneDocument::loadDefault() {
    SceneDocument fresh;
    fresh.m_settings = m_settings;
    fresh.m_cameraLayout = m_cameraLayout;
    fresh.m_lightingLayout = m_lightingLayout;
    for (CoursePart part : kCourseParts) {
        auto status = fresh.open(part, defaultScenePath(part));
        if (!status) return status;
    }
    fresh.m_loaded = true;
    *this = std::move(fresh);
    return rl::success();
}

namespace {

// Whether a file's first bytes look like a command file.
bool isCommandFile(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return false;
    const QByteArray head = file.read(4096);
    return rl::looksLikeHw2(std::string_view(head.constData(), std::size_t(head.size())));
}

}  // namespace

namespace {

// A load that may meet a file larger than the memory: std::bad_alloc becomes an error,
// and the document is unchanged.
template <typename Load>
auto guarded(const QString& path, Load load) -> decltype(load()) {
    try {
        return load();
    } catch (const std::bad_alloc&) {
        return rl::makeError(rl::ErrorCode::Range, rl::SourceLocation{path.toStdString(), 0, 0},
                             "not enough memory to read this file");
    }
}

}  // namespace

rl::Status SceneDocument::openCommandFile(const QString& path) {
    rl::Diagnostics diagnostics;
    auto file = guarded(path, [&] { return loadCommandFile(path, diagnostics); });
    if (!file) return file.error();
    m_commandFile = std::move(file).value();
    m_commandFilePath = path;
    m_commandFileDiagnostics = std::move(diagnostics);
    m_imageIndex = 0;
    m_loaded = true;
    return rl::success();
}

QStringList SceneDocument::imageNames() const {
    QStringList names;
    if (m_commandFile)
        for (const auto& image : m_commandFile->images)
            names << QString::fromStdString(image.fileName);
    return names;
}

void SceneDocument::setImageIndex(int index) {
    if (m_commandFile && index >= 0 && index < int(m_commandFile->images.size()))
        m_imageIndex = index;
}

rl::Status SceneDocument::open(Part part, const QString& path) {
    if (part == Part::Object && isCommandFile(path)) return openCommandFile(path);
    rl::Diagnostics diagnostics;
    switch (part) {
        case Part::Camera: {
            auto camera = loadCamera(path, diagnostics, m_cameraLayout);
            if (!camera) return camera.error();
            // A camera without a basis (N or V zero or parallel, d, hx or hy zero) would fail
            // every render: refuse it here, so that the previous camera stays.
            rl::Scene check;
            check.camera = camera.value();
            rl::Diagnostics basisWarnings;  // the render reports them again
            if (auto basis = rl::CameraBasisStage().run(check, basisWarnings); !basis)
                return basis.error();
            m_parts.camera = camera.value();
            break;
        }
        case Part::Lighting: {
            auto lighting = loadLighting(path, diagnostics, m_lightingLayout);
            if (!lighting) return lighting.error();
            m_parts.lighting = lighting.value();
            break;
        }
        case Part::Object: {
            auto object = guarded(path, [&] { return loadObject(path, diagnostics); });
            if (!object) return object.error();
            m_parts.object = object.value();
            break;
        }
    }
    m_sources[index(part)] = path;
    m_partDiagnostics[index(part)] = std::move(diagnostics);
    m_commandFile.reset();  // the course scene is shown again
    m_commandFilePath.clear();
    return rl::success();
}

rl::Status SceneDocument::setCameraLayout(rl::CameraLayout layout) {
    m_cameraLayout = layout;
    const QString path = source(Part::Camera);
    if (m_commandFile || path.isEmpty() || path.startsWith(QStringLiteral(":/")))
        return rl::success();
    return open(Part::Camera, path);
}

rl::Status SceneDocument::setLightingLayout(rl::LightingLayout layout) {
    m_lightingLayout = layout;
    const QString path = source(Part::Lighting);
    if (m_commandFile || path.isEmpty() || path.startsWith(QStringLiteral(":/")))
        return rl::success();
    return open(Part::Lighting, path);
}

rl::Diagnostics SceneDocument::diagnostics() const {
    if (m_commandFile) return m_commandFileDiagnostics;
    rl::Diagnostics all;
    for (const auto& d : m_partDiagnostics) all.append(d);
    return all;
}

void SceneDocument::setSize(int width, int height) {
    m_settings.width = width;
    m_settings.height = height;
}

std::shared_ptr<const rl::Scene> SceneDocument::scene() const {
    if (m_commandFile)
        return std::make_shared<const rl::Scene>(
            m_commandFile->images[std::size_t(m_imageIndex)].scene);
    return std::make_shared<const rl::Scene>(rl::makeCourseScene(m_parts, m_settings));
}

}  // namespace rasterlab
