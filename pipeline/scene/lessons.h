// The lessons that ship with RasterLab: small scenes, each made to show one idea of the
// lecture, written as the course's three files (a UFPE camera, a lighting file and a .byu
// object). The files in resources/lessons/NAME/ are this generator's output (`rasterlab-cli
// generate-lessons`), and a test keeps them identical to it. How each lesson opens (its
// shading, image size, stepping) is the application's: app/documents/examples.h.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/scene/default_scene.h"

namespace rl {

struct LessonFiles {
    std::string name;        // "goblet"
    std::string objectFile;  // "goblet.byu"
    CourseSceneTexts texts;  // camera.cfg, lighting.txt and the object
};

// The lessons' names, in the order a class meets them: triangle, zbuffer, near-plane, goblet,
// sphere, lights, painter-cycle, gouraud.
const std::vector<std::string>& lessonNames();

// The course files of the lesson with that name, or nullopt for an unknown name.
std::optional<LessonFiles> generateLesson(std::string_view name);

}  // namespace rl
