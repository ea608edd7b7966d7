// The course scene being shown: its three parts (camera, lighting, object), where each
// came from, their warnings, and the render settings. Each part is replaced on its own;
// a part that fails to load leaves the previous one in place.
#pragma once

#include <QString>

#include <memory>

#include "course_scene.h"
#include "default_scene_resource.h"
#include "diagnostics.h"
#include "scene.h"

namespace rasterlab {

class SceneDocument {
public:
    using Part = CoursePart;

    // The embedded default scene; fails only if the resources are broken.
    rl::Status loadDefault();
    // Replaces one part from a file; on error nothing changes.
    rl::Status open(Part part, const QString& path);

    bool isLoaded() const { return m_loaded; }
    const rl::CourseSceneParts& parts() const { return m_parts; }
    QString source(Part part) const { return m_sources[index(part)]; }
    rl::Diagnostics diagnostics() const;  // of all three parts, in order

    rl::CourseSceneSettings settings() const { return m_settings; }
    void setShading(rl::ShadingModel model) { m_settings.shading = model; }
    void setSize(int width, int height);

    std::shared_ptr<const rl::Scene> scene() const;

private:
    static std::size_t index(Part part) { return static_cast<std::size_t>(part); }

    bool m_loaded = false;
    rl::CourseSceneParts m_parts;
    QString m_sources[3];
    rl::Diagnostics m_partDiagnostics[3];
    rl::CourseSceneSettings m_settings;
};

}  // namespace rasterlab
