#include "default_scene.h"

#include <cmath>
#include <vector>

#include "pipeline/core/format.h"
#include "pipeline/core/math.h"

namespace rl {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The knot's centre line: it winds p = 2 times around the z axis and q = 3 times through
// the hole of a torus of radii R (core circle) and r (tube of the torus).
constexpr int kP = 2, kQ = 3;
constexpr double kR = 100.0, kr = 40.0;
constexpr double kTube = 22.0;  // radius of the tube around the centre line
constexpr int kSegments = 216;  // along the knot
constexpr int kRings = 18;      // around the tube

dvec3 centreLine(double phi) {
    const double radius = kR + kr * std::cos(kQ * phi);
    return {radius * std::cos(kP * phi), radius * std::sin(kP * phi), -kr * std::sin(kQ * phi)};
}

// The core circle point below the centre line: the tube's frame points away from it.
dvec3 corePoint(double phi) {
    return {kR * std::cos(kP * phi), kR * std::sin(kP * phi), 0.0};
}

std::string vertexLine(const dvec3& p) {
    return formatFixed(p.x, 4) + ' ' + formatFixed(p.y, 4) + ' ' + formatFixed(p.z, 4) + '\n';
}

}  // namespace

CourseSceneTexts generateDefaultScene() {
    CourseSceneTexts texts;

    // Camera: above and in front of the knot, looking at its centre; z is up.
    texts.camera =
        "0 -380 330\n"
        "0 380 -330\n"
        "0 0 1\n"
        "1 0.4 0.3\n";
    // Lighting (UFPE order): Pl, ka, Ia, kd, Od, ks, Il, n.
    texts.lighting =
        "-260 -420 520\n"
        "0.35\n"
        "60 60 72\n"
        "0.85\n"
        "0.88 0.42 0.18\n"
        "0.6\n"
        "255 248 235\n"
        "40\n";

    // A tube of kRings vertices around each of kSegments points of the centre line.
    std::vector<dvec3> vertices;
    vertices.reserve(kSegments * kRings);
    for (int i = 0; i < kSegments; ++i) {
        const double phi = 2.0 * kPi * i / kSegments;
        const double h = 1e-4;
        const dvec3 c = centreLine(phi);
        const dvec3 tangent = glm::normalize(centreLine(phi + h) - centreLine(phi - h));
        const dvec3 away = c - corePoint(phi);
        const dvec3 normal = glm::normalize(away - glm::dot(away, tangent) * tangent);
        const dvec3 binormal = glm::cross(tangent, normal);
        for (int j = 0; j < kRings; ++j) {
            const double theta = 2.0 * kPi * j / kRings;
            vertices.push_back(c + kTube * (std::cos(theta) * normal + std::sin(theta) * binormal));
        }
    }

    std::string& o = texts.object;
    o = std::to_string(vertices.size()) + " " + std::to_string(2 * kSegments * kRings) + "\n";
    for (const dvec3& v : vertices) o += vertexLine(v);
    auto index = [](int segment, int ring) {
        return (segment % kSegments) * kRings + (ring % kRings) + 1;  // 1-based
    };
    for (int i = 0; i < kSegments; ++i) {
        for (int j = 0; j < kRings; ++j) {
            const int a = index(i, j), b = index(i + 1, j);
            const int c = index(i + 1, j + 1), d = index(i, j + 1);
            o += std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\n";
            o += std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) + "\n";
        }
    }
    return texts;
}

}  // namespace rl
