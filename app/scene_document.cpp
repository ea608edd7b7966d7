#include "scene_document.h"

#include "camera_basis.h"
#include "default_scene_resource.h"

namespace rasterlab {

rl::Status SceneDocument::loadDefault() {
    SceneDocument fresh;
    fresh.m_settings = m_settings;
    for (CoursePart part : kCourseParts) {
        auto status = fresh.open(part, defaultScenePath(part));
        if (!status) return status;
    }
    fresh.m_loaded = true;
    *this = std::move(fresh);
    return rl::success();
}

rl::Status SceneDocument::open(Part part, const QString& path) {
    rl::Diagnostics diagnostics;
    switch (part) {
        case Part::Camera: {
            auto camera = loadCamera(path, diagnostics);
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
            auto lighting = loadLighting(path, diagnostics);
            if (!lighting) return lighting.error();
            m_parts.lighting = lighting.value();
            break;
        }
        case Part::Object: {
            auto object = loadObject(path, diagnostics);
            if (!object) return object.error();
            m_parts.object = object.value();
            break;
        }
    }
    m_sources[index(part)] = path;
    m_partDiagnostics[index(part)] = std::move(diagnostics);
    return rl::success();
}

rl::Diagnostics SceneDocument::diagnostics() const {
    rl::Diagnostics all;
    for (const auto& d : m_partDiagnostics) all.append(d);
    return all;
}

void SceneDocument::setSize(int width, int height) {
    m_settings.width = width;
    m_settings.height = height;
}

std::shared_ptr<const rl::Scene> SceneDocument::scene() const {
    return std::make_shared<const rl::Scene>(rl::makeCourseScene(m_parts, m_settings));
}

}  // namespace rasterlab
