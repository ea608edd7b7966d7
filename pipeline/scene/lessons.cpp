#include "lessons.h"

#include <array>
#include <cmath>
#include <initializer_list>

#include "pipeline/core/format.h"
#include "pipeline/core/math.h"
#include "pipeline/scene/benchmark_scenes.h"

namespace rl {

namespace {

constexpr double kPi = 3.14159265358979323846;

// A mesh being put together: its vertices and its triangles (0-based), written as .byu text.
struct MeshText {
    std::vector<dvec3> vertices;
    std::vector<std::array<int, 3>> triangles;

    int vertex(const dvec3& p) {
        vertices.push_back(p);
        return static_cast<int>(vertices.size()) - 1;
    }
    void triangle(int a, int b, int c) { triangles.push_back({a, b, c}); }
    // Another mesh, scaled about the origin and then moved by offset.
    void append(const Mesh& mesh, double scale, const dvec3& offset) {
        const int first = static_cast<int>(vertices.size());
        for (const dvec4& p : mesh.positions) vertex(dvec3(p) * scale + offset);
        for (const auto& t : mesh.triangles)
            triangle(first + int(t[0]), first + int(t[1]), first + int(t[2]));
    }
    std::string byu() const;
};

// Numbers separated by spaces on one line, each as short as "%g" writes it.
std::string line(std::initializer_list<double> values) {
    std::string text;
    for (double v : values) {
        if (!text.empty()) text += ' ';
        text += formatNumber(v);
    }
    return text + '\n';
}

std::string line(const dvec3& v) {
    return line({v.x, v.y, v.z});
}

std::string MeshText::byu() const {
    std::string text = std::to_string(vertices.size()) + ' ' + std::to_string(triangles.size()) + '\n';
    for (const dvec3& v : vertices) text += line(v);
    for (const auto& t : triangles)
        text += std::to_string(t[0] + 1) + ' ' + std::to_string(t[1] + 1) + ' ' +
                std::to_string(t[2] + 1) + '\n';
    return text;
}

// A UFPE camera at `eye` looking at `target` (N = target - eye), y up, d = 1.
std::string cameraText(const dvec3& eye, const dvec3& target, double hx, double hy) {
    return line(eye) + line(target - eye) + line({0.0, 1.0, 0.0}) + line({1.0, hx, hy});
}

// One light and the material, in the UFPE order: Pl, ka, Ia, kd, Od, ks, Il, n.
struct UfpeLighting {
    dvec3 pl;
    double ka;
    dvec3 ia;
    double kd;
    dvec3 od;
    double ks;
    dvec3 il;
    double n;

    std::string text() const {
        return line(pl) + line({ka}) + line(ia) + line({kd}) + line(od) + line({ks}) + line(il) +
               line({n});
    }
};

// The camera of the small lessons: 10 units in front of the xy plane, looking down -z, so
// that world x is to the right and y up; the view is 8 x 6 units wide at z = 0.
std::string frontCamera() {
    return cameraText({0.0, 0.0, 10.0}, {0.0, 0.0, 0.0}, 0.4, 0.3);
}

// A surface of revolution about the y axis: the profile's (r, y) points turned in `segments`
// steps. A point with r = 0 is one vertex on the axis. Counter-clockwise seen from outside
// when the profile runs from the bottom's centre outward and up (as a goblet's does).
void lathe(MeshText& mesh, const std::vector<dvec2>& profile, int segments) {
    std::vector<std::vector<int>> rings;
    for (const dvec2& p : profile) {
        std::vector<int> ring;
        if (p.x == 0.0) {
            ring.assign(segments, mesh.vertex({0.0, p.y, 0.0}));
        } else {
            for (int j = 0; j < segments; ++j) {
                const double phi = 2.0 * kPi * j / segments;
                ring.push_back(mesh.vertex({p.x * std::cos(phi), p.y, p.x * std::sin(phi)}));
            }
        }
        rings.push_back(std::move(ring));
    }
    for (std::size_t i = 0; i + 1 < rings.size(); ++i) {
        for (int j = 0; j < segments; ++j) {
            const int k = (j + 1) % segments;
            const int a = rings[i][j], b = rings[i + 1][j], c = rings[i + 1][k], d = rings[i][k];
            if (b != c) mesh.triangle(a, b, c);
            if (a != d) mesh.triangle(a, c, d);
        }
    }
}

// A square grid of quads on the plane y = 0, facing up: x and z from -half to half.
void floorGrid(MeshText& mesh, double half, int cells) {
    const int first = static_cast<int>(mesh.vertices.size());
    for (int i = 0; i <= cells; ++i)
        for (int j = 0; j <= cells; ++j)
            mesh.vertex({-half + 2.0 * half * j / cells, 0.0, -half + 2.0 * half * i / cells});
    const auto at = [first, cells](int i, int j) { return first + i * (cells + 1) + j; };
    for (int i = 0; i < cells; ++i)
        for (int j = 0; j < cells; ++j) {
            mesh.triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1));
            mesh.triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1));
        }
}

// One triangle, large in a 32 x 24 image: a scanline's pixels can be read one by one.
LessonFiles triangleLesson() {
    MeshText mesh;
    mesh.triangle(mesh.vertex({-2.6, -2.1, 0.0}), mesh.vertex({3.1, -0.9, 0.0}),
                  mesh.vertex({-0.4, 2.45, 0.0}));
    const UfpeLighting lighting{{-3.0, 4.0, 9.0}, 0.3, {60, 60, 60}, 0.8, {0.95, 0.55, 0.2},
                                0.5,              {255, 255, 255}, 6};
    return {"triangle", "triangle.byu", {frontCamera(), lighting.text(), mesh.byu()}};
}

// Two triangles tilted against each other: each is nearer the camera over half of the other,
// so neither can simply be drawn first; the z-buffer decides pixel by pixel.
LessonFiles zbufferLesson() {
    MeshText mesh;
    mesh.triangle(mesh.vertex({-3.0, -2.2, -1.5}), mesh.vertex({3.0, -2.2, -1.5}),
                  mesh.vertex({0.0, 2.4, 1.5}));
    mesh.triangle(mesh.vertex({-2.7, 2.0, -1.5}), mesh.vertex({0.2, -2.4, 1.5}),
                  mesh.vertex({2.9, 2.0, -1.5}));
    // Lit from above the camera: the triangle facing up is the brighter one.
    const UfpeLighting lighting{{0.0, 6.0, 10.0}, 0.25, {60, 60, 60}, 0.85, {0.35, 0.6, 0.95},
                                0.4,              {255, 255, 255}, 10};
    return {"zbuffer", "zbuffer.byu", {frontCamera(), lighting.text(), mesh.byu()}};
}

// A triangle on the floor whose far vertex is behind the camera: clipping at the near plane
// cuts it into a quad (two triangles); the plain divide turns that vertex over the horizon.
LessonFiles nearPlaneLesson() {
    MeshText mesh;
    mesh.triangle(mesh.vertex({-2.0, -1.0, 0.0}), mesh.vertex({0.0, -1.0, 16.0}),
                  mesh.vertex({2.0, -1.0, 0.0}));
    const UfpeLighting lighting{{0.0, 5.0, 5.0}, 0.3, {60, 60, 60}, 0.8, {0.4, 0.85, 0.45},
                                0.3,             {255, 255, 255}, 8};
    const std::string camera = cameraText({0.0, 0.0, 10.0}, {0.0, 0.0, 0.0}, 0.8, 0.6);
    return {"near-plane", "near-plane.byu", {camera, lighting.text(), mesh.byu()}};
}

// A goblet turned from a profile, foot to rim and back down inside the bowl: the course's
// chalice idea, with a mesh of our own.
LessonFiles gobletLesson() {
    const std::vector<dvec2> profile = {
        {0.0, 0.0},   {1.6, 0.0},   {1.6, 0.15},  {1.2, 0.25},  {0.4, 0.4},  {0.26, 0.8},
        {0.22, 1.5},  {0.3, 1.9},   {0.5, 2.05},  {0.3, 2.2},   {0.55, 2.4}, {1.05, 2.75},
        {1.4, 3.3},   {1.55, 4.0},  {1.5, 4.8},   {1.42, 4.8},  {1.46, 4.0}, {1.32, 3.35},
        {0.98, 2.85}, {0.5, 2.58},  {0.0, 2.52},
    };
    MeshText mesh;
    lathe(mesh, profile, 40);
    const std::string camera = cameraText({0.0, 6.0, 10.0}, {0.0, 2.3, 0.0}, 0.48, 0.36);
    const UfpeLighting lighting{{-6.0, 9.0, 8.0}, 0.2, {70, 70, 80}, 0.7, {0.85, 0.65, 0.25},
                                0.7,              {255, 250, 240}, 30};
    return {"goblet", "goblet.byu", {camera, lighting.text(), mesh.byu()}};
}

// A sphere of 168 triangles: flat shading shows every facet, Gouraud smooths them and
// blurs the highlight, Phong draws it round.
LessonFiles sphereLesson() {
    MeshText mesh;
    mesh.append(*uvSphere(12, 8), 2.2, {0.0, 0.0, 0.0});
    const UfpeLighting lighting{{-5.0, 6.0, 8.0}, 0.2, {50, 50, 60}, 0.75, {0.3, 0.55, 0.95},
                                0.6,              {255, 255, 255}, 40};
    return {"sphere", "sphere.byu", {frontCamera(), lighting.text(), mesh.byu()}};
}

// A floor and a ball under three lights of the lecture slides: a spot, a directional light
// and a positional light whose strength falls with distance.
LessonFiles lightsLesson() {
    MeshText mesh;
    floorGrid(mesh, 4.0, 24);
    mesh.append(*uvSphere(32, 16), 1.0, {0.0, 1.0, 0.0});
    const std::string camera = cameraText({0.0, 6.5, 11.0}, {0.0, 0.0, 0.0}, 0.48, 0.36);
    const std::string lighting =
        "Iamb = 40 40 40\n"
        "Ka = 0.3\n"
        "Kd = 0.8 0.8 0.8\n"
        "Od = 0.9 0.9 0.9\n"
        "Ks = 0.4\n"
        "eta = 20\n"
        "Pl = -1.8 4 1 1\n"
        "Il = 255 230 150\n"
        "spot_dir = 0.35 -1 -0.2\n"
        "spot_cutoff = 25\n"
        "spot_exp = 6\n"
        "Pl2 = 1 1 0.5 0\n"
        "Il2 = 50 70 130\n"
        "Pl3 = 2.6 0.5 1.8 1\n"
        "Il3 = 255 70 50\n"
        "atten3 = 1 0 0.6\n";
    return {"lights", "lights.byu", {camera, lighting, mesh.byu()}};
}

// Three long triangles, each in front of the next and behind the one before: no order of
// whole triangles draws them right, so the painter's algorithm must fail somewhere.
LessonFiles painterCycleLesson() {
    MeshText mesh;
    // Each blade runs along a line 0.9 from the centre, from a wide tail (far from the camera)
    // to its point (near): where it crosses the next blade, it is near its point and the next
    // blade near its tail.
    constexpr double r = 0.9, tail = 2.2, point = 3.4, width = 1.6, tilt = 1.0;
    for (int k = 0; k < 3; ++k) {
        const double phi = 2.0 * kPi * k / 3.0;
        const dvec3 along(std::cos(phi), std::sin(phi), 0.0);
        const dvec3 across(-std::sin(phi), std::cos(phi), 0.0);
        const dvec3 centre = r * across;
        const dvec3 head = centre + point * along + dvec3(0.0, 0.0, tilt);
        const dvec3 base = centre - tail * along - dvec3(0.0, 0.0, tilt);
        mesh.triangle(mesh.vertex(head), mesh.vertex(base + 0.5 * width * across),
                      mesh.vertex(base - 0.5 * width * across));
    }
    const UfpeLighting lighting{{-4.0, 5.0, 8.0}, 0.3, {60, 60, 60}, 0.8, {0.9, 0.8, 0.35},
                                0.2,              {255, 255, 255}, 8};
    const std::string camera = cameraText({0.0, 0.0, 10.0}, {0.0, 0.0, 0.0}, 0.5, 0.375);
    return {"painter-cycle", "painter-cycle.byu", {camera, lighting.text(), mesh.byu()}};
}

// Gouraud's two faults: a coarse sphere whose shading bends at every edge (the eye sees Mach
// bands there), and a square of two triangles whose highlight falls between its corners,
// where Gouraud never lights it.
LessonFiles gouraudLesson() {
    MeshText mesh;
    mesh.append(*uvSphere(10, 7), 1.4, {-2.0, 0.0, 0.0});
    const int a = mesh.vertex({0.6, -1.5, 0.0}), b = mesh.vertex({3.6, -1.5, 0.0});
    const int c = mesh.vertex({3.6, 1.5, 0.0}), d = mesh.vertex({0.6, 1.5, 0.0});
    mesh.triangle(a, b, c);
    mesh.triangle(a, c, d);
    // The first light is up and to the left of the sphere; the second is where the square's
    // mirror sends its highlight to the camera, at the square's centre.
    const std::string lighting =
        "Iamb = 50 50 50\n"
        "Ka = 0.2\n"
        "Kd = 0.7 0.7 0.7\n"
        "Od = 0.85 0.3 0.3\n"
        "Ks = 0.9\n"
        "eta = 60\n"
        "Pl = -6 5 7 1\n"
        "Il = 255 255 255\n"
        "Pl2 = 2.94 0 4 1\n"
        "Il2 = 200 200 200\n";
    return {"gouraud", "gouraud.byu", {frontCamera(), lighting, mesh.byu()}};
}

}  // namespace

const std::vector<std::string>& lessonNames() {
    static const std::vector<std::string> names = {
        "triangle", "zbuffer", "near-plane", "goblet", "sphere", "lights", "painter-cycle", "gouraud",
    };
    return names;
}

std::optional<LessonFiles> generateLesson(std::string_view name) {
    if (name == "triangle") return triangleLesson();
    if (name == "zbuffer") return zbufferLesson();
    if (name == "near-plane") return nearPlaneLesson();
    if (name == "goblet") return gobletLesson();
    if (name == "sphere") return sphereLesson();
    if (name == "lights") return lightsLesson();
    if (name == "painter-cycle") return painterCycleLesson();
    if (name == "gouraud") return gouraudLesson();
    return std::nullopt;
}

}  // namespace rl
