// A course scene (seed 000): a camera file, a lighting file and an object file, each
// loaded on its own so that any one can be swapped without touching the others, and put
// together into a Scene with the course's conventions.
#pragma once

#include <memory>
#include <string>

#include "pipeline/core/diagnostics.h"
#include "pipeline/io/course_readers.h"
#include "pipeline/scene/scene.h"

namespace rl {

struct CourseObject {
    std::string name;  // file name, for messages and views
    std::shared_ptr<const Mesh> mesh;
};

struct CourseSceneParts {
    CourseCamera camera;
    CourseLighting lighting;
    CourseObject object;
};

struct CourseSceneSettings {
    int width = 800;
    int height = 600;
    ShadingModel shading = ShadingModel::Phong;
    NearPlane nearPlane;
    bool cullHiddenBackFaces = false;  // Scene::cullHiddenBackFaces
    RasterRules rules = RasterRules::course();
};

// The object from text in memory, named after its file (fileName is used in messages only;
// the app reads the files). The camera and lighting come from readCourseCamera and
// readCourseLighting (course_readers.h).
Result<CourseObject> parseCourseObject(std::string_view text, const std::string& fileName,
                                       Diagnostics& diagnostics);

// The scene with the course's conventions: NDC y up, depth = view z cleared to +infinity,
// normals turned toward the viewer, colours in 0..255 truncated to bytes, black background.
Scene makeCourseScene(const CourseSceneParts& parts, const CourseSceneSettings& settings);

}  // namespace rl
