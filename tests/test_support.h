// Helpers shared by the test suites: where the sample files are, scenes built in code,
// and comparisons of GLM vectors with a tolerance that print both values on failure.
#pragma once

#include <QProcessEnvironment>
#include <QString>
#include <QStringList>
#include <QtTest>
#ifdef QT_WIDGETS_LIB
#include <QWidget>
#endif

#include <memory>
#include <optional>
#include <string_view>

#include "pipeline/core/diagnostics.h"
#include "pipeline/core/math.h"
#include "pipeline/render/renderer.h"
#include "pipeline/render/replay.h"
#include "pipeline/scene/scene.h"
#include "pipeline/stages/depth_test.h"
#include "pipeline/stages/projection.h"

namespace testing {

// A scene's frame, rendered with these options, and the replay of a frame (a failure of
// either is fatal).
std::shared_ptr<const rl::FrameTrace> renderTrace(std::shared_ptr<const rl::Scene> scene,
                                                  const rl::RenderOptions& options = {});
std::shared_ptr<const rl::FrameReplay> replayOf(const std::shared_ptr<const rl::FrameTrace>& trace);

// Global test data for running every test of a suite at both kernel widths
// (core/multiversion.h): kernelLaneRows() in initTestCase_data(), useKernelLanesOfRow() in
// init(), and setKernelLanes(0) in cleanupTestCase() to go back to the machine's own.
void kernelLaneRows();
void useKernelLanesOfRow();

// The course sample folder (../shared/samples or $RASTERLAB_SAMPLES), or an empty string.
QString samplesDir();
QString sourceDir();  // the repository's root
QString cliPath();    // the rasterlab-cli binary

// What a run of rasterlab-cli gave: its exit code (-1 unless it ran and exited normally), its
// output and error text, and why it did not run to completion.
struct CliRun {
    int exitCode = -1;
    QString out;
    QString err;
    QString problem;  // why the process did not run to completion
};
// Runs rasterlab-cli with `arguments` in `workDir` and waits for it to exit; `run` is made
// again from nothing. False when it could not start, did not finish within 120 s or crashed.
bool runCli(const QStringList& arguments, const QString& workDir, CliRun& run,
            const QProcessEnvironment& environment = QProcessEnvironment::systemEnvironment());

// The text of a file, or a failed test.
QByteArray readFile(const QString& path);
// Bytes as the readers take them.
inline std::string_view viewOf(const QByteArray& bytes) {
    return {bytes.constData(), static_cast<std::size_t>(bytes.size())};
}

// A mesh from positions and 0-based triangles.
std::shared_ptr<const rl::Mesh> makeMesh(std::vector<rl::dvec3> positions,
                                         std::vector<std::array<std::uint32_t, 3>> triangles);

// A course scene with one draw: camera, one point light, material, mesh, image size.
rl::Scene makeScene(const rl::CourseCamera& camera, std::shared_ptr<const rl::Mesh> mesh, int width,
                    int height, rl::ShadingModel shading = rl::ShadingModel::Phong);

// The hand-made scene whose numbers the stepping, scanline and normals suites work out by
// hand: four triangles on an 8x8 screen seen by the axis camera (view = (-x, y, z); screen
// x = (1 - x/z) 4, y = (1 - y/z) 4), drawn in this order:
//   0: z = 1,   screen (0,0) (4,0) (0,4): rows 0..4, spans of 5, 4, 3, 2, 1 pixels;
//   1: z = 2,   the same screen triangle, farther: its 15 fragments all rejected;
//   2: z = 0.5, screen (2,2) (6,2) (2,6): 15 pixels, nearer than everything; it writes
//      (2,2) a second time;
//   3: z = 1,   screen (5,0) (6,3) (7,3): rows 0..3, row 1 empty (its edges cross it at
//      x = 5.33 and 5.67), then 1 and 2 pixels; (6,2) is tri 2's, nearer: rejected.
// A point light at (0, 0, 10) with Il = 100, behind every triangle as seen from the camera
// (N.L < 0); the material and Ia of makeScene. extraPositions (numbered from 12) and
// extraTriangles are drawn after the four.
rl::Scene handScene(rl::ShadingModel shading = rl::ShadingModel::Phong,
                    const std::vector<rl::dvec3>& extraPositions = {},
                    const std::vector<std::array<std::uint32_t, 3>>& extraTriangles = {});

// A draw of makeScene's material with its own ka: under makeScene's ambient light alone
// (Ia = 10) its colour is 10 ka, its byte (int)(10 ka).
rl::Draw ambientDraw(const char* name, std::shared_ptr<const rl::Mesh> mesh, float ka,
                     rl::ShadingModel shading = rl::ShadingModel::Painter);

// The painter's failure (tst_painter, tst_painter_view), seen by the axis camera on a
// size x size screen: a small triangle S (draw 0, ka = 1, colour 10) at z = 3 on screen
// (0,0) (2,0) (0,2), and a long sloping triangle L (draw 1, ka = 0.5, colour 5) from z = 1 at
// screen (0,0) to z = 10 at (8,0) and (0,8) (in eighths of the screen when size is not 8).
//   S: world (3,3,3) (1.5,3,3) (3,1.5,3); barycentre view (-2.5, 2.5, 3),
//      |b| = sqrt(6.25 + 6.25 + 9) = sqrt(21.5) = 4.636809.
//   L: world (1,1,1) (-10,10,10) (10,-10,10); barycentre view (-1/3, 1/3, 7),
//      |b| = sqrt(1/9 + 1/9 + 49) = sqrt(443)/3 = 7.015855.
// L is farther by its barycentre: painted first, then S over it. But at 8x8 L's depth at pixel
// (x, y) is 1 + 9 (x + y)/8 (screen barycentrics x/8, y/8): 1 at (0,0), 2.125 at (1,0) and
// (0,1), 3.25 where x + y = 2. Of S's six pixels (x + y <= 2), L is nearer than S's 3 at
// three: (0,0), (1,0), (0,1). There the z-buffer shows L (5), the painter S (10).
rl::Scene painterFailureScene(rl::ShadingModel shading = rl::ShadingModel::Painter, int size = 8);

// A projection holding screen triangles given directly in pixels (one draw), with a depth
// per vertex (1 when not given), for the scan conversion and depth test suites.
rl::Projection screenTriangles(const std::vector<rl::dvec2>& points,
                               const std::vector<std::array<std::uint32_t, 3>>& triangles,
                               const std::vector<float>& depths = {});
// A scene that only sets the image size.
rl::Scene screen(int width, int height);

// Whether two depth tests hold the same triangles and, where a triangle won, the same
// barycentrics (elsewhere the buffer keeps what an earlier frame left), when both kept them.
bool sameCoveredBarycentrics(const rl::DepthTest& a, const rl::DepthTest& b);

// The camera of seed 000: C = (-200, -50, 300), N = (0.667, 0.172, -1), V = (0, 3, 0),
// d = 65, hx = 0.5, hy = 0.6.
rl::CourseCamera seedCamera();
// A camera at the origin looking along +z with y up, d = hx = hy = 1: view = (-x, y, z).
rl::CourseCamera axisCamera();

// "(x, y, z)" for any GLM vector.
template <int L, typename T, glm::qualifier Q>
QString describe(const glm::vec<L, T, Q>& v) {
    QString s = QStringLiteral("(");
    for (int k = 0; k < L; ++k) {
        if (k > 0) s += QStringLiteral(", ");
        s += QString::number(double(v[k]), 'g', 12);
    }
    return s + QStringLiteral(")");
}

#ifdef QT_WIDGETS_LIB  // the suites of the views (linked with Qt Widgets)
// Saves a widget's picture where RASTERLAB_VIEW_PICTURES says (to look at them), and checks
// that it is not one flat colour.
inline void lookAt(QWidget& widget, const QString& name) {
    QCoreApplication::processEvents();  // the layout requests posted by new texts
    const QImage image = widget.grab().toImage();
    QVERIFY(!image.isNull());
    bool varied = false;
    const QRgb first = image.pixel(0, 0);
    for (int y = 0; y < image.height() && !varied; y += 3)
        for (int x = 0; x < image.width() && !varied; x += 3) varied = image.pixel(x, y) != first;
    QVERIFY2(varied, qPrintable(name));
    const QString dir = qEnvironmentVariable("RASTERLAB_VIEW_PICTURES");
    if (!dir.isEmpty()) image.save(dir + QLatin1Char('/') + name + QStringLiteral(".png"));
}
#endif

}  // namespace testing

// Compare vectors component by component within a tolerance, printing both on failure.
#define RL_COMPARE_VEC(actual, expected, tolerance)                                       \
    do {                                                                                  \
        const auto a_ = (actual);                                                         \
        const auto e_ = (expected);                                                       \
        for (int k_ = 0; k_ < a_.length(); ++k_) {                                        \
            if (!(std::abs(double(a_[k_]) - double(e_[k_])) <= (tolerance)))              \
                QFAIL(qPrintable(QStringLiteral("%1 = %2, expected %3 (tolerance %4)")    \
                                     .arg(QStringLiteral(#actual), testing::describe(a_), \
                                          testing::describe(e_))                          \
                                     .arg(tolerance)));                                   \
        }                                                                                 \
    } while (false)

#define RL_COMPARE_NEAR(actual, expected, tolerance)                               \
    do {                                                                           \
        const double a_ = double(actual);                                          \
        const double e_ = double(expected);                                        \
        if (!(std::abs(a_ - e_) <= (tolerance)))                                   \
            QFAIL(qPrintable(QStringLiteral("%1 = %2, expected %3 (tolerance %4)") \
                                 .arg(QStringLiteral(#actual))                     \
                                 .arg(a_, 0, 'g', 17)                              \
                                 .arg(e_, 0, 'g', 17)                              \
                                 .arg(tolerance)));                                \
    } while (false)
