// The default scene embedded in the executables (resources/default-scene, under the
// resource prefix ":/default-scene/").
#pragma once

#include <QString>

#include "pipeline/core/diagnostics.h"
#include "pipeline/io/course_scene.h"

namespace rasterlab {

// The three parts of a course scene.
enum class CoursePart { Camera, Lighting, Object };
inline constexpr CoursePart kCourseParts[] = {CoursePart::Camera, CoursePart::Lighting,
                                              CoursePart::Object};

// ":/default-scene/camera.cfg", ".../lighting.txt", ".../trefoil.byu".
QString defaultScenePath(CoursePart part);

// Reads the three embedded course files.
rl::Result<rl::CourseSceneParts> loadDefaultCourseScene(rl::Diagnostics& diagnostics);

// Reads one course file from disk or from the resources (paths starting with ":/").
// Cameras and lighting come in any layout of course_readers.h, detected (Auto) or as given,
// with a note naming the layout; objects in any .byu flavour (rl::readByuObject). The
// embedded default scene's own files are always read as the UFPE files they are, without
// the note (it is meant for the user's files), whatever layout is asked for.
rl::Result<rl::CourseCamera> loadCamera(const QString& path, rl::Diagnostics& diagnostics,
                                        rl::CameraLayout layout = rl::CameraLayout::Auto);
rl::Result<rl::CourseLighting> loadLighting(const QString& path, rl::Diagnostics& diagnostics,
                                            rl::LightingLayout layout = rl::LightingLayout::Auto);
rl::Result<rl::CourseObject> loadObject(const QString& path, rl::Diagnostics& diagnostics);

}  // namespace rasterlab
