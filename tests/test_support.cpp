#include "test_support.h"

#include <QDir>
#include <QFile>
#include <QProcess>

#include "pipeline/core/multiversion.h"

namespace testing {

void kernelLaneRows() {
    QTest::addColumn<int>("lanes");
    QTest::newRow("8 lanes") << 8;
    QTest::newRow("4 lanes") << 4;
}

void useKernelLanesOfRow() {
    QFETCH_GLOBAL(int, lanes);
    rl::setKernelLanes(lanes);
    QCOMPARE(rl::kernelLanes(), lanes);
}

std::shared_ptr<const rl::FrameTrace> renderTrace(std::shared_ptr<const rl::Scene> scene,
                                                  const rl::RenderOptions& options) {
    auto frame = rl::renderFrame(std::move(scene), options);
    if (!frame) qFatal("%s", frame.error().toString().c_str());
    return std::make_shared<const rl::FrameTrace>(std::move(frame).value());
}

std::shared_ptr<const rl::FrameReplay> replayOf(
    const std::shared_ptr<const rl::FrameTrace>& trace) {
    auto replay = rl::FrameReplay::build(trace);
    if (!replay) qFatal("%s", replay.error().toString().c_str());
    return replay.value();
}

QString samplesDir() {
    const QString fromEnv = qEnvironmentVariable("RASTERLAB_SAMPLES");
    const QString dir = fromEnv.isEmpty() ? QStringLiteral(RASTERLAB_SAMPLES_DIR) : fromEnv;
    return QDir(dir).exists() ? QDir(dir).absolutePath() : QString();
}

QString sourceDir() {
    return QStringLiteral(RASTERLAB_SOURCE_DIR);
}

QString cliPath() {
    return QStringLiteral(RASTERLAB_CLI_PATH);
}

bool runCli(const QStringList& arguments, const QString& workDir, CliRun& run,
            const QProcessEnvironment& environment) {
    run = CliRun{};
    QProcess process;
    process.setWorkingDirectory(workDir);
    process.setProcessEnvironment(environment);
    process.start(cliPath(), arguments);
    const QString command =
        QStringLiteral("rasterlab-cli %1").arg(arguments.join(QLatin1Char(' ')));
    if (!process.waitForStarted(10000)) {
        run.problem = command + QStringLiteral(": cannot start: ") + process.errorString();
        return false;
    }
    if (!process.waitForFinished(120000)) {
        process.kill();
        process.waitForFinished();
        run.problem = command + QStringLiteral(": did not finish within 120 s");
        return false;
    }
    run.out = QString::fromUtf8(process.readAllStandardOutput());
    run.err = QString::fromUtf8(process.readAllStandardError());
    if (process.exitStatus() != QProcess::NormalExit) {
        run.problem = command + QStringLiteral(": crashed; stderr: ") + run.err;
        return false;
    }
    run.exitCode = process.exitCode();
    return true;
}

QByteArray readFile(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        qWarning("cannot open %s", qPrintable(path));
        return {};
    }
    return file.readAll();
}

std::shared_ptr<const rl::Mesh> makeMesh(std::vector<rl::dvec3> positions,
                                         std::vector<std::array<std::uint32_t, 3>> triangles) {
    auto mesh = std::make_shared<rl::Mesh>();
    for (const auto& p : positions) mesh->positions.emplace_back(p, 1.0);
    mesh->triangles = std::move(triangles);
    mesh->source = {"<test>", 0, 0};
    return mesh;
}

rl::Scene makeScene(const rl::CourseCamera& camera, std::shared_ptr<const rl::Mesh> mesh, int width,
                    int height, rl::ShadingModel shading) {
    rl::Scene scene;
    scene.name = "<test>";
    scene.width = width;
    scene.height = height;
    scene.camera = camera;
    rl::Draw draw;
    draw.name = "<test mesh>";
    draw.mesh = std::move(mesh);
    draw.shading = shading;
    draw.material.ka = 1.0f;
    draw.material.kd = rl::vec3(1.0f);
    draw.material.od = rl::vec3(1.0f);
    scene.draws.push_back(draw);
    scene.ambientIntensity = rl::vec3(10.0f);
    return scene;
}

rl::Scene handScene(rl::ShadingModel shading, const std::vector<rl::dvec3>& extraPositions,
                    const std::vector<std::array<std::uint32_t, 3>>& extraTriangles) {
    std::vector<rl::dvec3> positions{{1, 1, 1},         {0, 1, 1},          {1, 0, 1},
                                     {2, 2, 2},         {0, 2, 2},          {2, 0, 2},
                                     {0.25, 0.25, 0.5}, {-0.25, 0.25, 0.5}, {0.25, -0.25, 0.5},
                                     {-0.25, 1, 1},     {-0.5, 0.25, 1},    {-0.75, 0.25, 1}};
    std::vector<std::array<std::uint32_t, 3>> triangles{
        {0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}};
    positions.insert(positions.end(), extraPositions.begin(), extraPositions.end());
    triangles.insert(triangles.end(), extraTriangles.begin(), extraTriangles.end());
    rl::Scene scene = makeScene(axisCamera(), makeMesh(std::move(positions), std::move(triangles)),
                                8, 8, shading);
    scene.lights.push_back({rl::dvec4(0.0, 0.0, 10.0, 1.0), rl::vec3(100.0f), {}});
    return scene;
}

rl::Draw ambientDraw(const char* name, std::shared_ptr<const rl::Mesh> mesh, float ka,
                     rl::ShadingModel shading) {
    rl::Draw draw;
    draw.name = name;
    draw.mesh = std::move(mesh);
    draw.shading = shading;
    draw.material.ka = ka;
    draw.material.kd = rl::vec3(1.0f);
    draw.material.od = rl::vec3(1.0f);
    return draw;
}

rl::Scene painterFailureScene(rl::ShadingModel shading, int size) {
    rl::Scene scene = makeScene(axisCamera(), nullptr, size, size);
    scene.draws = {
        ambientDraw("S", makeMesh({{3, 3, 3}, {1.5, 3, 3}, {3, 1.5, 3}}, {{0, 1, 2}}), 1.0f,
                    shading),
        ambientDraw("L", makeMesh({{1, 1, 1}, {-10, 10, 10}, {10, -10, 10}}, {{0, 1, 2}}), 0.5f,
                    shading)};
    return scene;
}

rl::Projection screenTriangles(const std::vector<rl::dvec2>& points,
                               const std::vector<std::array<std::uint32_t, 3>>& triangles,
                               const std::vector<float>& depths) {
    rl::Projection projection;
    rl::DrawProjection draw;
    draw.pScreen.assign(points.begin(), points.end());
    draw.pScreenExact = points;
    if (depths.empty())
        draw.depth.assign(points.size(), 1.0f);
    else
        draw.depth.assign(depths.begin(), depths.end());
    draw.inFront.assign(points.size(), 1);
    projection.draws.push_back(draw);
    for (std::size_t t = 0; t < triangles.size(); ++t)
        projection.triangles.push_back({0, static_cast<std::uint32_t>(t), triangles[t]});
    return projection;
}

bool sameCoveredBarycentrics(const rl::DepthTest& a, const rl::DepthTest& b) {
    if (a.triangle != b.triangle || a.barycentric.width() != b.barycentric.width() ||
        a.barycentric.height() != b.barycentric.height())
        return false;
    if (!a.barycentricsKept || !b.barycentricsKept) return true;  // nothing to compare
    const auto& ids = a.triangle.pixels();
    for (std::size_t i = 0; i < ids.size(); ++i)
        if (ids[i] != rl::kNoTriangle && a.barycentric.pixels()[i] != b.barycentric.pixels()[i])
            return false;
    return true;
}

rl::Scene screen(int width, int height) {
    rl::Scene scene;
    scene.width = width;
    scene.height = height;
    return scene;
}

rl::CourseCamera seedCamera() {
    rl::CourseCamera c;
    c.c = {-200.0, -50.0, 300.0};
    c.n = {0.667, 0.172, -1.0};
    c.v = {0.0, 3.0, 0.0};
    c.d = 65.0;
    c.hx = 0.5;
    c.hy = 0.6;
    return c;
}

rl::CourseCamera axisCamera() {
    rl::CourseCamera c;
    c.c = {0.0, 0.0, 0.0};
    c.n = {0.0, 0.0, 1.0};
    c.v = {0.0, 1.0, 0.0};
    c.d = 1.0;
    c.hx = 1.0;
    c.hy = 1.0;
    return c;
}

}  // namespace testing
