// Stage 1, camera basis: seed 000's camera worked out by hand, orthonormality of random
// cameras, and an exact message for each degenerate camera.
#include <QtTest>

#include <random>

#include "pipeline/core/format.h"
#include "pipeline/stages/camera_basis.h"
#include "tests/test_support.h"

using namespace rl;

class TestCameraBasis : public QObject {
    Q_OBJECT

private:
    static Scene sceneWith(const CourseCamera& camera) {
        Scene scene;
        scene.name = "cam";
        scene.camera = camera;
        return scene;
    }
    static CourseCamera locatedSeedCamera() {
        CourseCamera c = testing::seedCamera();
        c.where = {{"camera.cfg", 1, 1}, {"camera.cfg", 2, 1}, {"camera.cfg", 3, 1},
                   {"camera.cfg", 4, 1}, {"camera.cfg", 4, 4}, {"camera.cfg", 4, 8}};
        return c;
    }

private slots:
    void seedCameraByHand() {
        // |N| = sqrt(0.667^2 + 0.172^2 + 1) = sqrt(1.474473); V.N = 3 * 0.172 / |N|;
        // V' = V - (V.N) N; U = N x V'. Values from a separate double-precision computation.
        Diagnostics diagnostics;
        auto basis = CameraBasisStage().run(sceneWith(testing::seedCamera()), diagnostics);
        QVERIFY(basis.ok());
        RL_COMPARE_NEAR(basis->nLength, 1.2142787982996328, 1e-12);
        RL_COMPARE_VEC(basis->n, dvec3(0.549297246179384, 0.1416478655814903, -0.8235341022179671),
                       1e-6);
        RL_COMPARE_NEAR(basis->vDotN, 0.4249435967444709, 1e-12);
        RL_COMPARE_VEC(basis->vProjection,
                       dvec3(0.23342034747330054, 0.06019235347137584, -0.3499555434382317), 1e-12);
        RL_COMPARE_VEC(basis->vOrthogonal,
                       dvec3(-0.23342034747330054, 2.939807646528624, 0.3499555434382317), 1e-12);
        RL_COMPARE_VEC(basis->v, dvec3(-0.07859929059124296, 0.9899171087400238, 0.117840015878925),
                       1e-6);
        RL_COMPARE_VEC(basis->u, dvec3(0.8319222841457599, 0.0, 0.5548921635252217), 1e-6);
        QVERIFY(basis->maxResidual() < 1e-15);
        QVERIFY(!basis->skipped);
        QVERIFY(diagnostics.empty());
    }

    void viewMatrixMapsCameraToOrigin() {
        Diagnostics diagnostics;
        const CourseCamera camera = testing::seedCamera();
        auto basis = CameraBasisStage().run(sceneWith(camera), diagnostics);
        QVERIFY(basis.ok());
        const dvec4 origin = basis->viewFromWorld * dvec4(camera.c, 1.0);
        RL_COMPARE_VEC(origin, dvec4(0.0, 0.0, 0.0, 1.0), 1e-12);
        // A point along N, 10 units away, is straight ahead: (0, 0, 10).
        const dvec4 ahead = basis->viewFromWorld * dvec4(camera.c + 10.0 * basis->n, 1.0);
        RL_COMPARE_VEC(ahead, dvec4(0.0, 0.0, 10.0, 1.0), 1e-12);
        // The rows [U; V; N] mirror handedness: determinant -1 (see math.h).
        RL_COMPARE_NEAR(glm::determinant(dmat3(basis->viewFromWorld)), -1.0, 1e-12);
    }

    void randomCamerasAreOrthonormal() {
        std::mt19937 rng(2026);
        std::uniform_real_distribution<double> coord(-1000.0, 1000.0);
        int tested = 0;
        for (int i = 0; i < 10000; ++i) {
            CourseCamera c;
            c.c = {coord(rng), coord(rng), coord(rng)};
            c.n = {coord(rng), coord(rng), coord(rng)};
            c.v = {coord(rng), coord(rng), coord(rng)};
            const double sine = glm::length(glm::cross(glm::normalize(c.n), glm::normalize(c.v)));
            if (sine < 1e-3) continue;  // nearly parallel: covered by the error test
            Diagnostics diagnostics;
            auto basis = CameraBasisStage().run(sceneWith(c), diagnostics);
            QVERIFY(basis.ok());
            if (basis->maxResidual() > 1e-12)
                QFAIL(qPrintable(
                    QStringLiteral("camera %1: residual %2").arg(i).arg(basis->maxResidual())));
            // U, V and N span the same plane as the given N and V: U is orthogonal to both.
            QVERIFY(std::abs(glm::dot(basis->u, glm::normalize(c.v))) < 1e-12);
            ++tested;
        }
        QVERIFY(tested > 9000);
    }

    void degenerateCameras_data() {
        QTest::addColumn<int>("field");  // 0 N, 1 V, 2 d, 3 hx, 4 hy
        QTest::addColumn<double>("value");
        QTest::addColumn<QString>("message");
        QTest::newRow("N zero") << 0 << 0.0
                                << "camera.cfg:2:1: N, the view direction, is the zero vector: it "
                                   "must point from the camera toward the scene";
        QTest::newRow("V zero")
            << 1 << 0.0
            << "camera.cfg:3:1: V, the up vector, is the zero vector: it must say which way is up";
        QTest::newRow("V parallel to N") << 1 << 2.0
                                         << "camera.cfg:3:1: V (1.334, 0.344, -2) is parallel to N "
                                            "(0.667, 0.172, -1): Gram-Schmidt leaves nothing of V, "
                                            "so 'up' is undefined; choose a V that is not along N";
        QTest::newRow("V opposite to N")
            << 1 << -1.0
            << "camera.cfg:3:1: V (-0.667, -0.172, 1) is parallel to N (0.667, 0.172, -1): "
               "Gram-Schmidt leaves nothing of V, so 'up' is undefined; choose a V that is not "
               "along N";
        QTest::newRow("d zero")
            << 2 << 0.0
            << "camera.cfg:4:1: d, the distance to the projection plane, is 0: the projection "
               "(d/hx) x/z would squash every point to the centre";
        QTest::newRow("hx zero") << 3 << 0.0
                                 << "camera.cfg:4:4: hx, the horizontal half-size of the window, "
                                    "is 0: the projection (d/hx) x/z divides by it";
        QTest::newRow("hy zero") << 4 << 0.0
                                 << "camera.cfg:4:8: hy, the vertical half-size of the window, is "
                                    "0: the projection (d/hy) y/z divides by it";
    }

    void degenerateCameras() {
        QFETCH(int, field);
        QFETCH(double, value);
        QFETCH(QString, message);
        CourseCamera c = locatedSeedCamera();
        switch (field) {
            case 0:
                c.n = dvec3(value);
                break;
            case 1:
                c.v = value == 0.0 ? dvec3(0.0) : value * c.n;
                break;
            case 2:
                c.d = value;
                break;
            case 3:
                c.hx = value;
                break;
            case 4:
                c.hy = value;
                break;
        }
        Diagnostics diagnostics;
        auto basis = CameraBasisStage().run(sceneWith(c), diagnostics);
        QVERIFY(!basis.ok());
        QCOMPARE(QString::fromStdString(basis.error().toString()), message);
        QCOMPARE(basis.error().code, ErrorCode::Degenerate);
    }

    void negativeHalfSizesWarn() {
        CourseCamera c = locatedSeedCamera();
        c.hx = -0.5;
        c.hy = -0.6;
        c.d = -65.0;
        Diagnostics diagnostics;
        auto basis = CameraBasisStage().run(sceneWith(c), diagnostics);
        QVERIFY(basis.ok());
        QCOMPARE(diagnostics.size(), std::size_t(3));
        QCOMPARE(
            QString::fromStdString(diagnostics.items()[0].toString()),
            QStringLiteral(
                "camera.cfg:4:4: warning: hx is negative: the image is mirrored left to right"));
        QCOMPARE(
            QString::fromStdString(diagnostics.items()[1].toString()),
            QStringLiteral(
                "camera.cfg:4:8: warning: hy is negative: the image is mirrored top to bottom"));
        QCOMPARE(QString::fromStdString(diagnostics.items()[2].toString()),
                 QStringLiteral("camera.cfg:4:1: warning: d is negative: the image is turned "
                                "upside down and mirrored"));
    }

    // V close to N: the angle is reported, the residuals grow as 1e-16 / sin(angle), and
    // under kWarnAngleDegrees (1e-6) the stage warns that they pass a float's precision.
    void conditioningNearlyParallel_data() {
        QTest::addColumn<double>("degrees");
        QTest::addColumn<bool>("warns");
        QTest::newRow("1 degree") << 1.0 << false;
        QTest::newRow("1e-3 degrees") << 1e-3 << false;
        QTest::newRow("1e-5 degrees") << 1e-5 << false;
        QTest::newRow("2e-6 degrees") << 2e-6 << false;
        QTest::newRow("5e-7 degrees") << 5e-7 << true;
        QTest::newRow("1e-9 degrees") << 1e-9 << true;
        QTest::newRow("180 - 1e-8 degrees") << 180.0 - 1e-8 << true;
    }
    void conditioningNearlyParallel() {
        QFETCH(double, degrees);
        QFETCH(bool, warns);
        std::mt19937 rng(7);
        std::normal_distribution<double> normal;
        double worst = 0.0;
        for (int i = 0; i < 200; ++i) {
            // N along a random axis a, V at the angle from it toward a random perpendicular p.
            const dvec3 a = glm::normalize(dvec3(normal(rng), normal(rng), normal(rng)));
            const dvec3 p =
                glm::normalize(glm::cross(a, dvec3(normal(rng), normal(rng), normal(rng))));
            const double t = glm::radians(degrees);
            CourseCamera c = locatedSeedCamera();
            c.n = 10.0 * a;
            c.v = 3.0 * (std::cos(t) * a + std::sin(t) * p);
            Diagnostics diagnostics;
            auto basis = CameraBasisStage().run(sceneWith(c), diagnostics);
            QVERIFY(basis.ok());
            QVERIFY2(std::abs(basis->angleNV - degrees) <= 1e-6 * std::max(degrees, 1e-3),
                     qPrintable(QString::number(basis->angleNV, 'g', 17)));
            worst = std::max(worst, basis->maxResidual());
            QCOMPARE(diagnostics.size(), std::size_t(warns ? 1 : 0));
            if (warns) {
                const QString text = QString::fromStdString(diagnostics.items()[0].toString());
                const double fromAxis = std::min(degrees, 180.0 - degrees);
                QVERIFY2(text.startsWith(QStringLiteral("camera.cfg:3:1: warning: V is %1 degrees "
                                                        "from the line of N: ")
                                             .arg(QString::fromStdString(formatNumber(
                                                 basis->angleNV < 90 ? basis->angleNV
                                                                     : 180.0 - basis->angleNV)))),
                         qPrintable(text));
                QVERIFY(
                    text.endsWith(QStringLiteral(", less than a float's precision; choose "
                                                 "a V farther from N")));
                QVERIFY(fromAxis < CameraBasisStage::kWarnAngleDegrees);
            }
        }
        // Above the threshold the basis is orthonormal to within a float's precision.
        if (!warns) QVERIFY2(worst < 6e-8, qPrintable(QString::number(worst)));
    }

    void sceneWithoutCameraSkips() {
        Scene scene;
        Diagnostics diagnostics;
        auto basis = CameraBasisStage().run(scene, diagnostics);
        QVERIFY(basis.ok());
        QVERIFY(basis->skipped);
        QCOMPARE(QString::fromStdString(basis->skipReason),
                 QStringLiteral("the scene gives its model/view matrices directly"));
        QCOMPARE(basis->viewFromWorld, dmat4(1.0));
    }
};

QTEST_GUILESS_MAIN(TestCameraBasis)
#include "tst_camera_basis.moc"
