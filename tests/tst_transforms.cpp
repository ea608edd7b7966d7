// The matrices of seed 001 against the formulas of the OpenGL documentation, written out
// here with concrete numbers (glTranslate, glScale, glRotate, glFrustum, glOrtho with the
// seed's near value 2n - f, gluLookAt), their properties, and the Bezier patches of
// pipeline/bezier: corners, Bernstein values, normals and subdivision.
#include <QtTest>

#include <QSet>

#include <cmath>
#include <functional>

#include <glm/gtc/matrix_access.hpp>

#include "pipeline/scene/bezier.h"
#include "pipeline/scene/transforms.h"
#include "tests/test_support.h"

using namespace rl;

namespace {

using Rows = QList<double>;

// "" when `m` equals the 16 values of `rows` (row by row) within `tolerance`, else a
// message naming the first element that differs and both matrices.
QString differs(const dmat4& m, const Rows& rows, double tolerance) {
    if (rows.size() != 16) return QStringLiteral("expected 16 values, found %1").arg(rows.size());
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            const double expected = rows[r * 4 + c];
            if (std::abs(m[c][r] - expected) <= tolerance) continue;
            QString text = QStringLiteral("row %1 column %2 is %3, expected %4\nactual rows:")
                               .arg(r + 1)
                               .arg(c + 1)
                               .arg(m[c][r], 0, 'g', 15)
                               .arg(expected, 0, 'g', 15);
            for (int rr = 0; rr < 4; ++rr)
                text += QStringLiteral("\n  %1 %2 %3 %4")
                            .arg(m[0][rr], 0, 'g', 10)
                            .arg(m[1][rr], 0, 'g', 10)
                            .arg(m[2][rr], 0, 'g', 10)
                            .arg(m[3][rr], 0, 'g', 10);
            return text;
        }
    }
    return {};
}

#define RL_COMPARE_MATRIX(actual, rows, tolerance)                       \
    do {                                                                 \
        const QString problem_ = differs((actual), (rows), (tolerance)); \
        QVERIFY2(problem_.isEmpty(), qPrintable(problem_));              \
    } while (false)

dvec3 vec3Of(const Rows& v) {
    return dvec3(v.value(0), v.value(1), v.value(2));
}

dvec3 transformPoint(const dmat4& m, const dvec3& p) {
    const dvec4 q = m * dvec4(p, 1.0);
    return dvec3(q) / q.w;
}

// The largest |element| of R^T R - I for the upper-left 3x3 of m.
double orthonormalityError(const dmat4& m) {
    const dmat3 r(m);
    const dmat3 e = glm::transpose(r) * r - dmat3(1.0);
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(e[c][k]));
    return worst;
}

// Bernstein polynomials of degree 3.
double bernstein(int i, double x) {
    static const double kBinomial[4] = {1.0, 3.0, 3.0, 1.0};
    return kBinomial[i] * std::pow(x, i) * std::pow(1.0 - x, 3 - i);
}

// A bicubic control grid: point (i, j) of row j is at index 4j + i.
std::array<PatchPoint, 16> rectGrid(const std::function<dvec3(int, int)>& position) {
    std::array<PatchPoint, 16> control;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            PatchPoint& p = control[std::size_t(4 * j + i)];
            p.p = dvec4(position(i, j), 1.0);
            p.colour = vec3(float(i) / 3.0f, float(j) / 3.0f, 0.25f);
            p.st = vec2(float(i) / 3.0f, 1.0f - float(j) / 3.0f);
        }
    return control;
}

// A cubic triangular control net: rows of 4, 3, 2, 1; point (column c, row r) is the one the
// weight u^(3-r-c) v^c w^r multiplies.
std::array<PatchPoint, 10> triNet(const std::function<dvec3(int, int)>& position) {
    std::array<PatchPoint, 10> control;
    std::size_t k = 0;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c + r < 4; ++c) {
            PatchPoint& p = control[k++];
            p.p = dvec4(position(c, r), 1.0);
            p.colour = vec3(float(c) / 3.0f, float(r) / 3.0f, 0.5f);
            p.st = vec2(float(c) / 3.0f, float(r) / 3.0f);
        }
    return control;
}

// The Bernstein-Bezier value of the triangular net at (u, v, w):
// sum over r + c <= 3 of 3!/(a! c! r!) u^a v^c w^r P(c, r), a = 3 - r - c.
dvec3 triBernsteinValue(const std::array<PatchPoint, 10>& control, double u, double v, double w) {
    static const double kFactorial[4] = {1.0, 1.0, 2.0, 6.0};
    dvec3 sum(0.0);
    std::size_t k = 0;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c + r < 4; ++c) {
            const int a = 3 - r - c;
            const double weight = 6.0 / (kFactorial[a] * kFactorial[c] * kFactorial[r]) *
                                  std::pow(u, a) * std::pow(v, c) * std::pow(w, r);
            sum += weight * dvec3(control[k++].p);
        }
    return sum;
}

double signedAreaZ(const dvec3& a, const dvec3& b, const dvec3& c) {
    return glm::cross(b - a, c - a).z;
}

}  // namespace

class TestTransforms : public QObject {
    Q_OBJECT

private slots:
    void matrixFromRowsIsRowMajor();
    void translation_data();
    void translation();
    void scale_data();
    void scale();
    void rotation_data();
    void rotation();
    void rotationProperties_data();
    void rotationProperties();
    void rotationPermutesAxes();
    void frustum_data();
    void frustum();
    void frustumCorners();
    void ortho_data();
    void ortho();
    void orthoDepthRange_data();
    void orthoDepthRange();
    void lookAt_data();
    void lookAt();
    void lookAtProperties_data();
    void lookAtProperties();

    void rectCorners();
    void rectBernstein_data();
    void rectBernstein();
    void rectInteriorByHand();
    void rectPlanarNormal_data();
    void rectPlanarNormal();
    void triCorners();
    void triBernstein_data();
    void triBernstein();
    void triInteriorByHand();
    void triPlanarNormal_data();
    void triPlanarNormal();
    void subdivideRect_data();
    void subdivideRect();
    void subdivideTri_data();
    void subdivideTri();
};

void TestTransforms::matrixFromRowsIsRowMajor() {
    const double rows[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
    const dmat4 m = matrixFromRows(rows);
    QCOMPARE(m[0][1], 5.0);  // column 0, row 1
    QCOMPARE(m[3][0], 4.0);  // column 3, row 0: the translation column
    RL_COMPARE_VEC(m * dvec4(1.0, 0.0, 0.0, 0.0), dvec4(1.0, 5.0, 9.0, 13.0), 0.0);
}

void TestTransforms::translation_data() {
    QTest::addColumn<Rows>("d");
    QTest::addColumn<Rows>("rows");
    // glTranslate: the identity with (x, y, z) in the last column.
    QTest::newRow("1 2 3") << Rows{1, 2, 3} << Rows{1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1};
    QTest::newRow("-0.25 0.1 -0.2")
        << Rows{-0.25, 0.1, -0.2} << Rows{1, 0, 0, -0.25, 0, 1, 0, 0.1, 0, 0, 1, -0.2, 0, 0, 0, 1};
    QTest::newRow("zero") << Rows{0, 0, 0} << Rows{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
}

void TestTransforms::translation() {
    QFETCH(Rows, d);
    QFETCH(Rows, rows);
    const dmat4 m = translationMatrix(vec3Of(d));
    RL_COMPARE_MATRIX(m, rows, 0.0);
    RL_COMPARE_VEC(transformPoint(m, dvec3(10.0, 20.0, 30.0)),
                   dvec3(10.0 + d[0], 20.0 + d[1], 30.0 + d[2]), 1e-12);
}

void TestTransforms::scale_data() {
    QTest::addColumn<Rows>("s");
    QTest::addColumn<Rows>("rows");
    // glScale: diag(x, y, z, 1).
    QTest::newRow("2 3 4") << Rows{2, 3, 4} << Rows{2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 4, 0, 0, 0, 0, 1};
    QTest::newRow("mirror x") << Rows{-1, 1, 1}
                              << Rows{-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    QTest::newRow("0.5 0.25 1") << Rows{0.5, 0.25, 1}
                                << Rows{0.5, 0, 0, 0, 0, 0.25, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
}

void TestTransforms::scale() {
    QFETCH(Rows, s);
    QFETCH(Rows, rows);
    const dmat4 m = scaleMatrix(vec3Of(s));
    RL_COMPARE_MATRIX(m, rows, 0.0);
    RL_COMPARE_VEC(transformPoint(m, dvec3(1.0, -2.0, 3.0)),
                   dvec3(s[0] * 1.0, s[1] * -2.0, s[2] * 3.0), 1e-12);
}

void TestTransforms::rotation_data() {
    QTest::addColumn<double>("degrees");
    QTest::addColumn<Rows>("axis");
    QTest::addColumn<Rows>("rows");
    const double h = std::sqrt(0.5);          // cos 45 = sin 45
    const double c30 = std::sqrt(3.0) / 2.0;  // cos 30
    // glRotate about x: [1 0 0; 0 c -s; 0 s c]; about y: [c 0 s; 0 1 0; -s 0 c];
    // about z: [c -s 0; s c 0; 0 0 1].
    QTest::newRow("x 90") << 90.0 << Rows{1, 0, 0}
                          << Rows{1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1};
    QTest::newRow("x -45") << -45.0 << Rows{1, 0, 0}
                           << Rows{1, 0, 0, 0, 0, h, h, 0, 0, -h, h, 0, 0, 0, 0, 1};
    QTest::newRow("y 90") << 90.0 << Rows{0, 1, 0}
                          << Rows{0, 0, 1, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 0, 1};
    QTest::newRow("y 30") << 30.0 << Rows{0, 1, 0}
                          << Rows{c30, 0, 0.5, 0, 0, 1, 0, 0, -0.5, 0, c30, 0, 0, 0, 0, 1};
    QTest::newRow("z 90") << 90.0 << Rows{0, 0, 1}
                          << Rows{0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    QTest::newRow("z 180") << 180.0 << Rows{0, 0, 1}
                           << Rows{-1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    QTest::newRow("-z 90 (= z -90)")
        << 90.0 << Rows{0, 0, -1} << Rows{0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    QTest::newRow("x 90, axis of length 5")
        << 90.0 << Rows{5, 0, 0} << Rows{1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1};
    // The oblique axis (1, 2, 2)/3 at 90 degrees: c = 0, s = 1, so the glRotate matrix is
    // a a^T + [a]x: [xx  xy-z  xz+y; xy+z  yy  yz-x; xz-y  yz+x  zz] with x = 1/3,
    // y = z = 2/3, i.e. [1 -4 8; 8 4 1; -4 7 4] / 9.
    QTest::newRow("(1,2,2) 90") << 90.0 << Rows{1, 2, 2}
                                << Rows{1.0 / 9, -4.0 / 9, 8.0 / 9,  0,       8.0 / 9, 4.0 / 9,
                                        1.0 / 9, 0,        -4.0 / 9, 7.0 / 9, 4.0 / 9, 0,
                                        0,       0,        0,        1};
    // The same axis unnormalised, 180 degrees: c = -1, s = 0, so 2 a a^T - I:
    // [2/9-1 4/9 4/9; 4/9 8/9-1 8/9; 4/9 8/9 8/9-1].
    QTest::newRow("(2,4,4) 180") << 180.0 << Rows{2, 4, 4}
                                 << Rows{-7.0 / 9, 4.0 / 9, 4.0 / 9, 0,       4.0 / 9,  -1.0 / 9,
                                         8.0 / 9,  0,       4.0 / 9, 8.0 / 9, -1.0 / 9, 0,
                                         0,        0,       0,       1};
}

void TestTransforms::rotation() {
    QFETCH(double, degrees);
    QFETCH(Rows, axis);
    QFETCH(Rows, rows);
    RL_COMPARE_MATRIX(rotationMatrix(degrees, vec3Of(axis)), rows, 1e-12);
}

void TestTransforms::rotationProperties_data() {
    QTest::addColumn<double>("degrees");
    QTest::addColumn<Rows>("axis");
    QTest::newRow("x 37") << 37.0 << Rows{1, 0, 0};
    QTest::newRow("y -123") << -123.0 << Rows{0, 1, 0};
    QTest::newRow("z 271") << 271.0 << Rows{0, 0, 1};
    QTest::newRow("oblique 17") << 17.0 << Rows{0.3, -1.2, 2.5};
    QTest::newRow("oblique 200") << 200.0 << Rows{-4, 1, 0.5};
    QTest::newRow("tiny axis 60") << 60.0 << Rows{1e-9, 2e-9, -1e-9};
}

void TestTransforms::rotationProperties() {
    QFETCH(double, degrees);
    QFETCH(Rows, axis);
    const dvec3 a = vec3Of(axis);
    const dmat4 m = rotationMatrix(degrees, a);
    QVERIFY2(orthonormalityError(m) < 1e-12, qPrintable(QString::number(orthonormalityError(m))));
    RL_COMPARE_NEAR(glm::determinant(dmat3(m)), 1.0, 1e-12);
    // No translation, no projection.
    RL_COMPARE_VEC(m[3], dvec4(0.0, 0.0, 0.0, 1.0), 0.0);
    RL_COMPARE_VEC(glm::row(m, 3), dvec4(0.0, 0.0, 0.0, 1.0), 0.0);
    // The axis stays where it is; a vector perpendicular to it turns by the angle,
    // counter-clockwise seen from the tip of the axis: (a x p) . p' > 0 for angles in (0, 180).
    const dvec3 unit = glm::normalize(a);
    RL_COMPARE_VEC(dmat3(m) * unit, unit, 1e-12);
    const dvec3 p =
        glm::normalize(glm::cross(unit, std::abs(unit.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
    const dvec3 turned = dmat3(m) * p;
    const double radians = degrees * 3.14159265358979323846 / 180.0;
    RL_COMPARE_NEAR(glm::dot(p, turned), std::cos(radians), 1e-12);
    RL_COMPARE_NEAR(glm::dot(glm::cross(p, turned), unit), std::sin(radians), 1e-12);
}

void TestTransforms::rotationPermutesAxes() {
    // 120 degrees about (1, 1, 1) takes x to y, y to z and z to x.
    const dmat4 m = rotationMatrix(120.0, dvec3(1.0, 1.0, 1.0));
    RL_COMPARE_MATRIX(m, (Rows{0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1}), 1e-12);
    RL_COMPARE_VEC(transformPoint(m, dvec3(1, 0, 0)), dvec3(0, 1, 0), 1e-12);
    RL_COMPARE_VEC(transformPoint(m, dvec3(0, 1, 0)), dvec3(0, 0, 1), 1e-12);
    // The zero axis leaves everything where it is (the reader rejects it before).
    RL_COMPARE_MATRIX(rotationMatrix(30.0, dvec3(0.0)),
                      (Rows{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}), 0.0);
}

void TestTransforms::frustum_data() {
    QTest::addColumn<Rows>("lrbtnf");
    QTest::addColumn<Rows>("rows");
    // glFrustum: [2n/(r-l) 0 (r+l)/(r-l) 0; 0 2n/(t-b) (t+b)/(t-b) 0;
    //             0 0 -(f+n)/(f-n) -2fn/(f-n); 0 0 -1 0].
    QTest::newRow("-1 1 -1 1 1 10")
        << Rows{-1, 1, -1, 1, 1, 10}
        << Rows{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -11.0 / 9, -20.0 / 9, 0, 0, -1, 0};
    // 2n/(r-l) = 4/2 = 2, (r+l)/(r-l) = 1/2, 2n/(t-b) = 4/4 = 1, (t+b)/(t-b) = 2/4,
    // -(f+n)/(f-n) = -8/4, -2fn/(f-n) = -24/4.
    QTest::newRow("-0.5 1.5 -1 3 2 6")
        << Rows{-0.5, 1.5, -1, 3, 2, 6}
        << Rows{2, 0, 0.5, 0, 0, 1, 0.5, 0, 0, 0, -2, -6, 0, 0, -1, 0};
    // The sample hw2frustum.txt's odd arguments: t < b and negative n, f.
    // 2n/(r-l) = -1, 2n/(t-b) = -1/-0.6, (t+b)/(t-b) = -0.4/-0.6,
    // -(f+n)/(f-n) = 10.5/-9.5, -2fn/(f-n) = -10/-9.5.
    QTest::newRow("hw2frustum") << Rows{-0.5, 0.5, 0.1, -0.5, -0.5, -10}
                                << Rows{-1, 0, 0,           0,          0, 1.0 / 0.6, 0.4 / 0.6, 0,
                                        0,  0, -10.5 / 9.5, 10.0 / 9.5, 0, 0,         -1,        0};
}

void TestTransforms::frustum() {
    QFETCH(Rows, lrbtnf);
    QFETCH(Rows, rows);
    const auto& a = lrbtnf;
    RL_COMPARE_MATRIX(frustumMatrix(a[0], a[1], a[2], a[3], a[4], a[5]), rows, 1e-12);
}

void TestTransforms::frustumCorners() {
    // The near rectangle's corners (l, b, -n), (r, t, -n) go to NDC (-1, -1, -1) and
    // (1, 1, -1); the far plane's corners (l f/n, b f/n, -f) ... to z = +1; the apex is
    // the origin.
    const double l = -0.5, r = 1.5, b = -1, t = 3, n = 2, f = 6;
    const dmat4 m = frustumMatrix(l, r, b, t, n, f);
    RL_COMPARE_VEC(transformPoint(m, dvec3(l, b, -n)), dvec3(-1, -1, -1), 1e-12);
    RL_COMPARE_VEC(transformPoint(m, dvec3(r, t, -n)), dvec3(1, 1, -1), 1e-12);
    RL_COMPARE_VEC(transformPoint(m, dvec3(l * f / n, t * f / n, -f)), dvec3(-1, 1, 1), 1e-12);
    RL_COMPARE_VEC(transformPoint(m, dvec3(r * f / n, b * f / n, -f)), dvec3(1, -1, 1), 1e-12);
    // w is the distance in front of the eye.
    QCOMPARE((m * dvec4(0.3, 0.2, -4.0, 1.0)).w, 4.0);
}

void TestTransforms::ortho_data() {
    QTest::addColumn<Rows>("lrbtnf");
    QTest::addColumn<Rows>("rows");
    // glOrtho(l, r, b, t, N, f) with N = 2n - f:
    // [2/(r-l) 0 0 -(r+l)/(r-l); 0 2/(t-b) 0 -(t+b)/(t-b); 0 0 -2/(f-N) -(f+N)/(f-N); 0 0 0 1].
    // n = 1, f = 3: N = -1, f - N = 4, f + N = 2.
    QTest::newRow("-2 2 -1 1 1 3")
        << Rows{-2, 2, -1, 1, 1, 3} << Rows{0.5, 0, 0, 0, 0, 1, 0, 0, 0, 0, -0.5, -0.5, 0, 0, 0, 1};
    // n = 0.5, f = 2.5: N = -1.5, f - N = 4, f + N = 1; x: 2/4, -(4+0)/4; y: 2/2, -(3+1)/2.
    QTest::newRow("0 4 1 3 0.5 2.5")
        << Rows{0, 4, 1, 3, 0.5, 2.5}
        << Rows{0.5, 0, 0, -1, 0, 1, 0, -2, 0, 0, -0.5, -0.25, 0, 0, 0, 1};
    // n = 0, f = 10: N = -10, f - N = 20, f + N = 0.
    QTest::newRow("-1 1 -1 1 0 10")
        << Rows{-1, 1, -1, 1, 0, 10} << Rows{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -0.1, 0, 0, 0, 0, 1};
}

void TestTransforms::ortho() {
    QFETCH(Rows, lrbtnf);
    QFETCH(Rows, rows);
    const auto& a = lrbtnf;
    RL_COMPARE_MATRIX(orthoMatrix(a[0], a[1], a[2], a[3], a[4], a[5]), rows, 1e-12);
}

void TestTransforms::orthoDepthRange_data() {
    QTest::addColumn<Rows>("lrbtnf");
    QTest::newRow("-2 2 -1 1 1 3") << Rows{-2, 2, -1, 1, 1, 3};
    QTest::newRow("0 4 1 3 0.5 2.5") << Rows{0, 4, 1, 3, 0.5, 2.5};
    QTest::newRow("-3 -1 2 5 -2 7") << Rows{-3, -1, 2, 5, -2, 7};
}

void TestTransforms::orthoDepthRange() {
    // The seed's box [l, r] x [b, t] x [-f, -n]: z = -n lands on NDC 0, z = -f on 1 (not
    // -1 and 1 as glOrtho's own near value would give).
    QFETCH(Rows, lrbtnf);
    const auto& a = lrbtnf;
    const dmat4 m = orthoMatrix(a[0], a[1], a[2], a[3], a[4], a[5]);
    RL_COMPARE_VEC(transformPoint(m, dvec3(a[0], a[2], -a[4])), dvec3(-1, -1, 0), 1e-12);
    RL_COMPARE_VEC(transformPoint(m, dvec3(a[1], a[3], -a[5])), dvec3(1, 1, 1), 1e-12);
    RL_COMPARE_VEC(
        transformPoint(m, dvec3((a[0] + a[1]) / 2, (a[2] + a[3]) / 2, -(a[4] + a[5]) / 2)),
        dvec3(0, 0, 0.5), 1e-12);
    QCOMPARE((m * dvec4(0.3, 0.2, -4.0, 1.0)).w, 1.0);
}

void TestTransforms::lookAt_data() {
    QTest::addColumn<Rows>("eye");
    QTest::addColumn<Rows>("center");
    QTest::addColumn<Rows>("up");
    QTest::addColumn<Rows>("rows");
    // gluLookAt: F = center - eye, f = F/|F|, s = f x up/|f x up|, u = s x f;
    // M = [s 0; u 0; -f 0; 0 0 0 1] times the translation by -eye.
    QTest::newRow("from +z") << Rows{0, 0, 5} << Rows{0, 0, 0} << Rows{0, 1, 0}
                             << Rows{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, -5, 0, 0, 0, 1};
    // f = (-1, 0, 0), s = (0, 0, -1), u = (0, 1, 0); the last column is M * (-eye).
    QTest::newRow("from +x") << Rows{3, 0, 0} << Rows{0, 0, 0} << Rows{0, 1, 0}
                             << Rows{0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, -3, 0, 0, 0, 1};
    // An up that is not perpendicular to the line of sight: only its part across it counts.
    QTest::newRow("from +x, up tilted") << Rows{3, 0, 0} << Rows{0, 0, 0} << Rows{-7, 2, 0}
                                        << Rows{0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, -3, 0, 0, 0, 1};
    // f = -(1, 1, 1)/sqrt3, s = (-1, 1, 0)/sqrt2, u = (-1, -1, 2)/sqrt6; eye . s = eye . u = 0
    // and eye . (-f) = sqrt3, so the last column is (0, 0, -sqrt3).
    const double r2 = std::sqrt(2.0), r3 = std::sqrt(3.0), r6 = std::sqrt(6.0);
    QTest::newRow("from (1,1,1), z up")
        << Rows{1, 1, 1} << Rows{0, 0, 0} << Rows{0, 0, 1}
        << Rows{-1 / r2, 1 / r2, 0,      0,   -1 / r6, -1 / r6, 2 / r6, 0,
                1 / r3,  1 / r3, 1 / r3, -r3, 0,       0,       0,      1};
    // Translated: eye (2, 3, 4) looking down -y at (2, -1, 4) with up +z: f = (0, -1, 0),
    // s = f x z = (-1, 0, 0), u = s x f = (0, 0, 1); last column -(s.eye, u.eye, -f.eye) =
    // (2, -4, -3).
    QTest::newRow("eye (2,3,4) looking down")
        << Rows{2, 3, 4} << Rows{2, -1, 4} << Rows{0, 0, 1}
        << Rows{-1, 0, 0, 2, 0, 0, 1, -4, 0, 1, 0, -3, 0, 0, 0, 1};
}

void TestTransforms::lookAt() {
    QFETCH(Rows, eye);
    QFETCH(Rows, center);
    QFETCH(Rows, up);
    QFETCH(Rows, rows);
    RL_COMPARE_MATRIX(lookAtMatrix(vec3Of(eye), vec3Of(center), vec3Of(up)), rows, 1e-12);
}

void TestTransforms::lookAtProperties_data() {
    QTest::addColumn<Rows>("eye");
    QTest::addColumn<Rows>("center");
    QTest::addColumn<Rows>("up");
    QTest::newRow("general") << Rows{1.5, -2, 7} << Rows{-0.5, 0.25, 1} << Rows{0.2, 1, 0.1};
    QTest::newRow("far") << Rows{100, 200, -300} << Rows{0, 0, 0} << Rows{0, 0, 1};
    QTest::newRow("up almost along the sight")
        << Rows{0, 0, 0} << Rows{0, 10, 0} << Rows{0.001, 1, 0};
}

void TestTransforms::lookAtProperties() {
    QFETCH(Rows, eye);
    QFETCH(Rows, center);
    QFETCH(Rows, up);
    const dvec3 e = vec3Of(eye), c = vec3Of(center), u = vec3Of(up);
    const dmat4 m = lookAtMatrix(e, c, u);
    QVERIFY2(orthonormalityError(m) < 1e-12, qPrintable(QString::number(orthonormalityError(m))));
    RL_COMPARE_NEAR(glm::determinant(dmat3(m)), 1.0, 1e-12);
    const double scale = std::max(1.0, glm::length(e));
    // The eye goes to the origin, the center onto the -z axis at its distance.
    RL_COMPARE_VEC(transformPoint(m, e), dvec3(0.0), 1e-12 * scale);
    RL_COMPARE_VEC(transformPoint(m, c), dvec3(0.0, 0.0, -glm::length(c - e)), 1e-12 * scale);
    // The up hint lands in the upper half of the y-z plane: x = 0, y > 0.
    const dvec3 upView = dmat3(m) * u;
    RL_COMPARE_NEAR(upView.x, 0.0, 1e-12);
    QVERIFY2(upView.y > 0.0, qPrintable(testing::describe(upView)));
}

void TestTransforms::rectCorners() {
    const auto control = rectGrid(
        [](int i, int j) { return dvec3(i * 1.5 + j * 0.25, j - 0.5 * i, (i - 1.5) * (j - 2.0)); });
    // s runs along a row (index 4j + i), t across the rows.
    const struct {
        double s, t;
        std::size_t index;
    } corners[] = {{0, 0, 0}, {1, 0, 3}, {0, 1, 12}, {1, 1, 15}};
    for (const auto& corner : corners) {
        const PatchVertex v = evaluateRectBezier(control, corner.s, corner.t);
        const PatchPoint& p = control[corner.index];
        RL_COMPARE_VEC(v.p, p.p, 1e-15);
        RL_COMPARE_VEC(v.colour, p.colour, 1e-7);
        RL_COMPARE_VEC(v.st, p.st, 1e-7);
    }
}

void TestTransforms::rectBernstein_data() {
    QTest::addColumn<double>("s");
    QTest::addColumn<double>("t");
    QTest::newRow("centre") << 0.5 << 0.5;
    QTest::newRow("0.25 0.75") << 0.25 << 0.75;
    QTest::newRow("1/3 0.1") << 1.0 / 3.0 << 0.1;
    QTest::newRow("edge t = 0") << 0.6 << 0.0;
    QTest::newRow("edge s = 1") << 1.0 << 0.3;
}

void TestTransforms::rectBernstein() {
    // P(s, t) = sum_ij B_i(s) B_j(t) P_ij, for a grid that is neither planar nor regular.
    QFETCH(double, s);
    QFETCH(double, t);
    const auto control = rectGrid([](int i, int j) {
        return dvec3(i * 1.5 + j * j * 0.25, j - 0.5 * i * i, (i - 1.5) * (j - 2.0) + i * j * j);
    });
    dvec3 expected(0.0);
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i)
            expected +=
                bernstein(i, s) * bernstein(j, t) * dvec3(control[std::size_t(4 * j + i)].p);
    const PatchVertex v = evaluateRectBezier(control, s, t);
    RL_COMPARE_VEC(dvec3(v.p), expected, 1e-12);
    QCOMPARE(v.p.w, 1.0);
    // Colours and texture coordinates are linear in (i, j), and Bernstein polynomials
    // reproduce linear functions: (i/3, j/3) becomes (s, t).
    RL_COMPARE_VEC(v.colour, vec3(float(s), float(t), 0.25f), 1e-6);
    RL_COMPARE_VEC(v.st, vec2(float(s), 1.0f - float(t)), 1e-6);
}

void TestTransforms::rectInteriorByHand() {
    // A flat grid P_ij = (i, j, 0) with the four inner points raised to z = 1. At
    // (0.5, 0.5) the Bernstein weights are (1, 3, 3, 1)/8 in each direction, so
    // x = y = 1.5 and z = (3/8 + 3/8)^2 = 9/16.
    const auto control = rectGrid(
        [](int i, int j) { return dvec3(i, j, (i == 1 || i == 2) && (j == 1 || j == 2)); });
    RL_COMPARE_VEC(evaluateRectBezier(control, 0.5, 0.5).p, dvec4(1.5, 1.5, 0.5625, 1.0), 1e-15);
    // At (0.5, 0): the first row only, z = 0; at (1/3, 0.5): weights (8, 12, 6, 1)/27 in s,
    // so x = (12 + 12 + 3)/27 = 1, z = (12 + 6)/27 * 6/8 = 0.5.
    RL_COMPARE_VEC(evaluateRectBezier(control, 0.5, 0.0).p, dvec4(1.5, 0.0, 0.0, 1.0), 1e-15);
    RL_COMPARE_VEC(evaluateRectBezier(control, 1.0 / 3.0, 0.5).p, dvec4(1.0, 1.5, 0.5, 1.0), 1e-15);
}

void TestTransforms::rectPlanarNormal_data() {
    QTest::addColumn<double>("s");
    QTest::addColumn<double>("t");
    QTest::newRow("corner 0 0") << 0.0 << 0.0;
    QTest::newRow("corner 1 1") << 1.0 << 1.0;
    QTest::newRow("centre") << 0.5 << 0.5;
    QTest::newRow("0.2 0.9") << 0.2 << 0.9;
}

void TestTransforms::rectPlanarNormal() {
    // bezier.cpp: the normal is (P11 - P00) x (P10 - P01) of the last quad, which is
    // 2 dP/ds x dP/dt: with s along +x and t along +y it is +z.
    QFETCH(double, s);
    QFETCH(double, t);
    const auto flat = rectGrid([](int i, int j) { return dvec3(i + 0.1 * j * j, j + 0.2 * i, 0); });
    RL_COMPARE_VEC(evaluateRectBezier(flat, s, t).normal, vec3(0, 0, 1), 1e-6);
    // Irregular points of the plane z = 0.5 x + y: normal (-0.5, -1, 1)/1.5.
    const auto tilted = rectGrid([](int i, int j) {
        const double x = i * 1.3 - 0.2 * j, y = j * 0.7 + 0.05 * i * i;
        return dvec3(x, y, 0.5 * x + y);
    });
    RL_COMPARE_VEC(evaluateRectBezier(tilted, s, t).normal, vec3(-1.0 / 3, -2.0 / 3, 2.0 / 3),
                   1e-6);
    // Running s the other way (mirroring each row) turns the normal over.
    auto mirrored = flat;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i)
            mirrored[std::size_t(4 * j + i)] = flat[std::size_t(4 * j + 3 - i)];
    RL_COMPARE_VEC(evaluateRectBezier(mirrored, s, t).normal, vec3(0, 0, -1), 1e-6);
}

void TestTransforms::triCorners() {
    const auto control = triNet([](int c, int r) { return dvec3(c * 2.0 - r, r * 1.5, c * r); });
    // u = 1: the first point; v = 1: the fourth (end of the first row); w = 1: the last.
    const struct {
        double u, v, w;
        std::size_t index;
    } corners[] = {{1, 0, 0, 0}, {0, 1, 0, 3}, {0, 0, 1, 9}};
    for (const auto& corner : corners) {
        const PatchVertex v = evaluateTriBezier(control, corner.u, corner.v, corner.w);
        const PatchPoint& p = control[corner.index];
        RL_COMPARE_VEC(v.p, p.p, 1e-15);
        RL_COMPARE_VEC(v.colour, p.colour, 1e-7);
        RL_COMPARE_VEC(v.st, p.st, 1e-7);
    }
}

void TestTransforms::triBernstein_data() {
    QTest::addColumn<double>("u");
    QTest::addColumn<double>("v");
    QTest::newRow("centre") << 1.0 / 3.0 << 1.0 / 3.0;
    QTest::newRow("0.5 0.25") << 0.5 << 0.25;
    QTest::newRow("0.1 0.7") << 0.1 << 0.7;
    QTest::newRow("edge w = 0") << 0.4 << 0.6;
}

void TestTransforms::triBernstein() {
    QFETCH(double, u);
    QFETCH(double, v);
    const double w = 1.0 - u - v;
    const auto control =
        triNet([](int c, int r) { return dvec3(c * 2.0 - r * r, r * 1.5 + c * c, c * r + r - c); });
    const PatchVertex p = evaluateTriBezier(control, u, v, w);
    RL_COMPARE_VEC(dvec3(p.p), triBernsteinValue(control, u, v, w), 1e-12);
    // Linear attributes (c/3, r/3) become (v, w).
    RL_COMPARE_VEC(p.colour, vec3(float(v), float(w), 0.5f), 1e-6);
    RL_COMPARE_VEC(p.st, vec2(float(v), float(w)), 1e-6);
}

void TestTransforms::triInteriorByHand() {
    // A flat net P(c, r) = (c, r, 0) with the middle point (c = r = 1) raised to z = 1. At
    // the centre, u = v = w = 1/3, its weight is 3!/(1! 1! 1!) / 27 = 6/27, so z = 2/9;
    // x = 3 v = 1 and y = 3 w = 1.
    const auto control = triNet([](int c, int r) { return dvec3(c, r, c == 1 && r == 1); });
    RL_COMPARE_VEC(evaluateTriBezier(control, 1.0 / 3, 1.0 / 3, 1.0 / 3).p,
                   dvec4(1.0, 1.0, 2.0 / 9.0, 1.0), 1e-15);
    // At (0.5, 0.5, 0), on the first edge: the first row only, x = 1.5, z = 0.
    RL_COMPARE_VEC(evaluateTriBezier(control, 0.5, 0.5, 0.0).p, dvec4(1.5, 0.0, 0.0, 1.0), 1e-15);
}

void TestTransforms::triPlanarNormal_data() {
    QTest::addColumn<double>("u");
    QTest::addColumn<double>("v");
    QTest::newRow("corner u") << 1.0 << 0.0;
    QTest::newRow("corner v") << 0.0 << 1.0;
    QTest::newRow("centre") << 1.0 / 3.0 << 1.0 / 3.0;
    QTest::newRow("0.6 0.1") << 0.6 << 0.1;
}

void TestTransforms::triPlanarNormal() {
    // bezier.cpp: the normal is (b - a) x (c - a) of the last triangle, b along v and c
    // along w: dP/dv x dP/dw. With v along +x and w along +y it is +z.
    QFETCH(double, u);
    QFETCH(double, v);
    const double w = 1.0 - u - v;
    const auto flat = triNet([](int c, int r) { return dvec3(c + 0.1 * r * r, r + 0.05 * c, 0); });
    RL_COMPARE_VEC(evaluateTriBezier(flat, u, v, w).normal, vec3(0, 0, 1), 1e-6);
    // Points of the plane x + 2y + 2z = 3: normal (1, 2, 2)/3.
    const auto tilted = triNet([](int c, int r) {
        const double x = c * 1.1 + 0.1 * r, y = r * 0.9 - 0.05 * c * c;
        return dvec3(x, y, (3.0 - x - 2.0 * y) / 2.0);
    });
    RL_COMPARE_VEC(evaluateTriBezier(tilted, u, v, w).normal, vec3(1.0 / 3, 2.0 / 3, 2.0 / 3),
                   1e-6);
}

void TestTransforms::subdivideRect_data() {
    QTest::addColumn<int>("subdivisions");
    QTest::addColumn<int>("vertices");   // (2^n + 1)^2
    QTest::addColumn<int>("triangles");  // 2 * 4^n
    QTest::newRow("1") << 1 << 9 << 8;
    QTest::newRow("2") << 2 << 25 << 32;
    QTest::newRow("3") << 3 << 81 << 128;
    QTest::newRow("5") << 5 << 1089 << 2048;
}

void TestTransforms::subdivideRect() {
    QFETCH(int, subdivisions);
    QFETCH(int, vertices);
    QFETCH(int, triangles);
    // A regular flat grid over [0, 3] x [0, 3]: the patch is that square, s = x/3, t = y/3.
    const auto control = rectGrid([](int i, int j) { return dvec3(i, j, 0); });
    const PatchMesh mesh = subdivideRectBezier(control, subdivisions);
    QCOMPARE(int(mesh.vertices.size()), vertices);
    QCOMPARE(int(mesh.triangles.size()), triangles);
    const int n = 1 << subdivisions;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const PatchVertex& v = mesh.vertices[std::size_t(j * (n + 1) + i)];
            const double s = double(i) / n, t = double(j) / n;
            RL_COMPARE_VEC(v.p, dvec4(3 * s, 3 * t, 0, 1), 1e-12);
            RL_COMPARE_VEC(v.colour, vec3(float(s), float(t), 0.25f), 1e-6);
            RL_COMPARE_VEC(v.st, vec2(float(s), 1.0f - float(t)), 1e-6);
            RL_COMPARE_VEC(v.normal, vec3(0, 0, 1), 1e-6);
        }
    // Each quad is cut along its diagonal from (i + 1, j) to (i, j + 1), as the HW2 reference
    // images are (hw2rectbezf matches pixel for pixel only so), two triangles per quad in order.
    const auto at = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::size_t q = std::size_t(2 * (j * n + i));
            QCOMPARE(mesh.triangles[q],
                     (std::array<std::uint32_t, 3>{at(i, j), at(i + 1, j), at(i, j + 1)}));
            QCOMPARE(mesh.triangles[q + 1],
                     (std::array<std::uint32_t, 3>{at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}));
        }
    // The triangles tile the square: all wound like the normal (+z), areas summing to 9.
    double area = 0.0;
    for (const auto& tri : mesh.triangles) {
        for (std::uint32_t k : tri) QVERIFY(k < mesh.vertices.size());
        const double a = signedAreaZ(dvec3(mesh.vertices[tri[0]].p), dvec3(mesh.vertices[tri[1]].p),
                                     dvec3(mesh.vertices[tri[2]].p));
        QVERIFY2(a > 0.0, "a triangle is wound against the patch normal");
        area += a / 2.0;
    }
    RL_COMPARE_NEAR(area, 9.0, 1e-9);
}

void TestTransforms::subdivideTri_data() {
    QTest::addColumn<int>("subdivisions");
    QTest::addColumn<int>("vertices");   // (N + 1)(N + 2)/2, N = 2^n
    QTest::addColumn<int>("triangles");  // N^2
    QTest::newRow("1") << 1 << 6 << 4;
    QTest::newRow("2") << 2 << 15 << 16;
    QTest::newRow("3") << 3 << 45 << 64;
    QTest::newRow("4") << 4 << 153 << 256;
}

void TestTransforms::subdivideTri() {
    QFETCH(int, subdivisions);
    QFETCH(int, vertices);
    QFETCH(int, triangles);
    // A regular flat net: the patch is the triangle (0, 0), (3, 0), (0, 3), x = 3v, y = 3w.
    const auto control = triNet([](int c, int r) { return dvec3(c, r, 0); });
    const PatchMesh mesh = subdivideTriBezier(control, subdivisions);
    QCOMPARE(int(mesh.vertices.size()), vertices);
    QCOMPARE(int(mesh.triangles.size()), triangles);
    const int n = 1 << subdivisions;
    // Every point (v, w) = (i/N, j/N) with i + j <= N appears once.
    QSet<QPair<int, int>> seen;
    for (const PatchVertex& v : mesh.vertices) {
        const double x = v.p.x, y = v.p.y;
        const int i = int(std::lround(x * n / 3.0)), j = int(std::lround(y * n / 3.0));
        RL_COMPARE_VEC(v.p, dvec4(3.0 * i / n, 3.0 * j / n, 0, 1), 1e-12);
        QVERIFY(i >= 0 && j >= 0 && i + j <= n);
        seen.insert({i, j});
        RL_COMPARE_VEC(v.colour, vec3(float(i) / float(n), float(j) / float(n), 0.5f), 1e-6);
        RL_COMPARE_VEC(v.st, vec2(float(i) / float(n), float(j) / float(n)), 1e-6);
        RL_COMPARE_VEC(v.normal, vec3(0, 0, 1), 1e-6);
    }
    QCOMPARE(int(seen.size()), vertices);
    double area = 0.0;
    for (const auto& tri : mesh.triangles) {
        for (std::uint32_t k : tri) QVERIFY(k < mesh.vertices.size());
        const double a = signedAreaZ(dvec3(mesh.vertices[tri[0]].p), dvec3(mesh.vertices[tri[1]].p),
                                     dvec3(mesh.vertices[tri[2]].p));
        QVERIFY2(a > 0.0, "a triangle is wound against the patch normal");
        area += a / 2.0;
    }
    RL_COMPARE_NEAR(area, 4.5, 1e-9);
}

QTEST_GUILESS_MAIN(TestTransforms)
#include "tst_transforms.moc"
