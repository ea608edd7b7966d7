// The embedded default scene: a trefoil knot tube (a (2, 3) torus knot) with a copper
// Phong material under one white light, written as the three course files. The files in
// resources/default-scene are this generator's output (`rasterlab-cli
// generate-default-scene`), and a test keeps them identical to it.
#pragma once

#include <string>

namespace rl {

struct CourseSceneTexts {
    std::string camera;    // camera.cfg
    std::string lighting;  // lighting.txt
    std::string object;    // trefoil.byu
};

CourseSceneTexts generateDefaultScene();

inline constexpr const char* kDefaultCameraFile = "camera.cfg";
inline constexpr const char* kDefaultLightingFile = "lighting.txt";
inline constexpr const char* kDefaultObjectFile = "trefoil.byu";

}  // namespace rl
