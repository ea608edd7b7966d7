#include "bench_support.h"

#include <QFile>
#include <QTextStream>

#include <algorithm>
#include <cmath>

#include "pipeline/io/course_writers.h"
#include "pipeline/scene/benchmark_scenes.h"

namespace rasterlab::bench {

bool writeTorus(const QString& dir, int triangles, QString paths[3]) {
    const int nv = 100;
    const int nu = std::max(3, triangles / (2 * nv));
    const auto mesh = rl::torusMesh(nu, nv);
    const rl::Framing framing = rl::frameMesh(*mesh, 800, 600);
    rl::CourseLighting lighting;
    lighting.material.ka = 0.2f;
    lighting.material.kd = rl::vec3(0.7f);
    lighting.material.od = rl::vec3(0.9f, 0.5f, 0.2f);
    lighting.material.ks = 0.5f;
    lighting.material.shininess = 12.0f;
    lighting.ambientIntensity = rl::vec3(90.0f);
    lighting.lights.push_back({rl::dvec4(framing.light, 1.0), rl::vec3(255.0f), {}});
    const auto cameraText = rl::writeCameraFile(framing.camera, rl::CameraLayout::Ufpe);
    const auto lightingText = rl::writeLightingFile(lighting, rl::LightingLayout::Ufpe);
    if (!cameraText || !lightingText) return false;

    paths[0] = dir + QStringLiteral("/torus.cfg");
    paths[1] = dir + QStringLiteral("/torus-light.txt");
    paths[2] = dir + QStringLiteral("/torus.byu");
    QFile camera(paths[0]), light(paths[1]), object(paths[2]);
    if (!camera.open(QIODevice::WriteOnly) || !light.open(QIODevice::WriteOnly) ||
        !object.open(QIODevice::WriteOnly))
        return false;
    camera.write(QByteArray::fromStdString(*cameraText));
    light.write(QByteArray::fromStdString(*lightingText));
    QTextStream out(&object);
    out.setRealNumberPrecision(9);
    out << mesh->positions.size() << ' ' << mesh->triangles.size() << '\n';
    for (const rl::dvec4& p : mesh->positions) out << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const auto& t : mesh->triangles)
        out << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    return true;
}

double percentile(std::vector<double> v, double p) {
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(std::min<double>(v.size() - 1, std::floor(p * v.size())))];
}

}  // namespace rasterlab::bench
