// The readers of the UFPE course files (camera, lighting, .byu object): the values they
// give, where each value came from, the quirks of real files that must load, and the exact
// warnings and errors for everything else. The last tests read the real course samples.
#include <QtTest>

#include <string_view>

#include "pipeline/io/course_readers.h"
#include "pipeline/io/course_scene.h"
#include "tests/test_support.h"

namespace {

std::string_view viewOf(const QByteArray& bytes) {
    return {bytes.constData(), static_cast<std::size_t>(bytes.size())};
}

QString qs(const std::string& s) {
    return QString::fromStdString(s);
}

QStringList messagesOf(const rl::Diagnostics& diagnostics) {
    QStringList messages;
    for (const rl::Diagnostic& d : diagnostics.items()) messages << qs(d.toString());
    return messages;
}

// "file:line:col" of each location, without the file name.
QStringList positionsOf(std::initializer_list<const rl::SourceLocation*> locations,
                        const std::string& file) {
    QStringList out;
    for (const rl::SourceLocation* where : locations) {
        if (where->file != file) {
            out << QStringLiteral("file %1").arg(qs(where->file));
            continue;
        }
        out << QStringLiteral("%1:%2").arg(where->line).arg(where->column);
    }
    return out;
}

const QByteArray kBom = QByteArrayLiteral("\xEF\xBB\xBF");

// Seed 000's camera, four lines.
const QByteArray kCamera(R"(-200 -50 300
0.667 0.172 -1
0 3 0
65 0.5 0.6
)");
const QByteArray kCameraCrlf("-200 -50 300\r\n0.667 0.172 -1\r\n0 3 0\r\n65 0.5 0.6\r\n");

// A lighting file whose fields all differ, with values exact in float; kd is filled in.
QByteArray lightingWithKd(const QByteArray& kd, const QByteArray& eol = "\n") {
    const QList<QByteArray> lines = {"-220 -150 700",    "0.25", "10 20 30", kd,
                                     "0.125 0.25 0.375", "0.5",  "40 50 60", "8"};
    QByteArray text;
    for (const QByteArray& line : lines) text += line + eol;
    return text;
}

// The reference object: four vertices (with the course's number quirks) and two triangles.
const QByteArray kObject(R"(4 2
50.0000 0.0000 0.000
0 50 0
0 0 50
-1E-15 9.5e-005 +2
1 2 3
1 3 4
)");

void checkSeedCamera(const rl::CourseCamera& camera) {
    const rl::CourseCamera expected = testing::seedCamera();
    RL_COMPARE_VEC(camera.c, expected.c, 0.0);
    RL_COMPARE_VEC(camera.n, expected.n, 0.0);
    RL_COMPARE_VEC(camera.v, expected.v, 0.0);
    RL_COMPARE_NEAR(camera.d, expected.d, 0.0);
    RL_COMPARE_NEAR(camera.hx, expected.hx, 0.0);
    RL_COMPARE_NEAR(camera.hy, expected.hy, 0.0);
}

}  // namespace

// A failed Result prints its error.
#define RL_VERIFY_OK(result) \
    QVERIFY2((result).ok(), (result).ok() ? "" : qPrintable(qs((result).error().toString())))

class TestCourseReaders : public QObject {
    Q_OBJECT

private slots:
    // Camera
    void camera_data();
    void camera();
    void cameraWarnings_data();
    void cameraWarnings();
    void cameraErrors_data();
    void cameraErrors();

    // Lighting
    void lighting_data();
    void lighting();
    void lightingWarnings_data();
    void lightingWarnings();
    void lightingRanges_data();
    void lightingRanges();
    void lightingErrors_data();
    void lightingErrors();

    // Object
    void object_data();
    void object();
    void objectWarnings_data();
    void objectWarnings();
    void objectErrors_data();
    void objectErrors();
    void objectName_data();
    void objectName();

    // The course's own files
    void samplesSeedExample();
    void samplesUfpeObjects_data();
    void samplesUfpeObjects();
    void samplesUfpeCameras_data();
    void samplesUfpeCameras();
    void samplesUfpeLighting();
};

// ---------------------------------------------------------------------------------------
// Camera

void TestCourseReaders::camera_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QStringList>("where");  // C, N, V (line starts), then d, hx, hy

    const QStringList plain = {"1:1", "2:1", "3:1", "4:1", "4:4", "4:8"};
    QTest::newRow("LF") << kCamera << plain;
    QTest::newRow("CRLF") << kCameraCrlf << plain;
    QTest::newRow("no final newline") << kCamera.chopped(1) << plain;
    QTest::newRow("CRLF, no final newline") << kCameraCrlf.chopped(2) << plain;
    QTest::newRow("blank lines before, between and after") << QByteArray(R"(
-200 -50 300

0.667 0.172 -1

0 3 0


65 0.5 0.6


)") << QStringList{"2:1", "4:1", "6:1", "9:1", "9:4", "9:8"};
    QTest::newRow("blank lines, CRLF")
        << QByteArray(
               "\r\n-200 -50 300\r\n\r\n0.667 0.172 -1\r\n0 3 0\r\n \t\r\n65 0.5 0.6\r\n\r\n")
        << QStringList{"2:1", "4:1", "5:1", "7:1", "7:4", "7:8"};
    QTest::newRow("TABs, leading and trailing spaces")
        << QByteArray("  -200\t-50 300  \n\t0.667  0.172\t-1\n0 3 0 \t\n 65\t0.5   0.6\t\n")
        << QStringList{"1:1", "2:1", "3:1", "4:2", "4:5", "4:11"};
    QTest::newRow("exponents and signs")
        << QByteArray("-2e2 -5.0E+1 3e+002\n6.67e-1 1.72E-1 -1.0\n+0 3e0 -0\n6.5e1 5e-1 6E-1\n")
        << QStringList{"1:1", "2:1", "3:1", "4:1", "4:7", "4:12"};
    QTest::newRow("fixed decimals") << QByteArray(
                                           "-200.0000 -50.0000 300.0000\n0.6670 0.1720 -1.0000\n"
                                           "0.0000 3.0000 0.0000\n65.0000 0.5000 0.6000\n")
                                    << QStringList{"1:1", "2:1", "3:1", "4:1", "4:9", "4:16"};
    QTest::newRow("UTF-8 BOM") << kBom + kCamera << plain;
}

void TestCourseReaders::camera() {
    QFETCH(QByteArray, text);
    QFETCH(QStringList, where);

    rl::Diagnostics diagnostics;
    const auto camera = rl::readCourseCamera(viewOf(text), "camera.cfg", diagnostics);
    RL_VERIFY_OK(camera);
    QCOMPARE(messagesOf(diagnostics), QStringList());
    checkSeedCamera(*camera);
    const auto& w = camera->where;
    QCOMPARE(positionsOf({&w.c, &w.n, &w.v, &w.d, &w.hx, &w.hy}, "camera.cfg"), where);
}

void TestCourseReaders::cameraWarnings_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QStringList>("warnings");

    QTest::newRow("one value after N")
        << QByteArray("-200 -50 300\n0.667 0.172 -1 7\n0 3 0\n65 0.5 0.6\n")
        << QStringList{"camera.cfg:2:16: warning: ignored 1 value after N"};
    QTest::newRow("a comment after d hx hy")
        << QByteArray("-200 -50 300\n0.667 0.172 -1\n0 3 0\n65 0.5 0.6 ; d hx hy\n")
        << QStringList{"camera.cfg:4:12: warning: ignored 4 values after d hx hy"};
    QTest::newRow("two lines after the fourth")
        << kCamera + "1 2 3\n\n4 5 6\n"
        << QStringList{"camera.cfg:5:1: warning: ignored 2 lines after the camera's 4 lines"};
    QTest::newRow("one line after the fourth, CRLF, no final newline")
        << kCameraCrlf + "\r\n\r\n7"
        << QStringList{"camera.cfg:7:1: warning: ignored 1 line after the camera's 4 lines"};
    QTest::newRow("an extra value and extra lines")
        << QByteArray("-200 -50 300 0\n0.667 0.172 -1\n0 3 0\n65 0.5 0.6\n1\n2\n3\n")
        << QStringList{"camera.cfg:1:14: warning: ignored 1 value after C",
                       "camera.cfg:5:1: warning: ignored 3 lines after the camera's 4 lines"};
}

void TestCourseReaders::cameraWarnings() {
    QFETCH(QByteArray, text);
    QFETCH(QStringList, warnings);

    rl::Diagnostics diagnostics;
    const auto camera = rl::readCourseCamera(viewOf(text), "camera.cfg", diagnostics);
    RL_VERIFY_OK(camera);
    checkSeedCamera(*camera);
    QCOMPARE(messagesOf(diagnostics), warnings);
    QCOMPARE(diagnostics.warningCount(), std::size_t(warnings.size()));
}

void TestCourseReaders::cameraErrors_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<rl::ErrorCode>("code");
    QTest::addColumn<QString>("message");

    const auto syntax = rl::ErrorCode::Syntax;
    const auto missing = rl::ErrorCode::MissingData;
    QTest::newRow("a letter where a number belongs")
        << QByteArray("-200 -50 300\n0.667 x -1\n0 3 0\n65 0.5 0.6\n") << syntax
        << "camera.cfg:2:7: expected a number for N, found 'x'";
    QTest::newRow("decimal comma")
        << QByteArray("-200 -50 300\n0.667 0.172 -1\n0 3 0\n65 0,5 0,6\n") << syntax
        << "camera.cfg:4:4: expected a number for d hx hy, found '0,5' "
           "(the decimal separator is '.')";
    QTest::newRow("nan") << QByteArray("-200 -50 300\n0.667 0.172 -1\n0 nan 0\n65 0.5 0.6\n")
                         << syntax
                         << "camera.cfg:3:3: expected a number for V, found 'nan', "
                            "which is not a finite number";
    QTest::newRow("-inf") << QByteArray("-inf -50 300\n0.667 0.172 -1\n0 3 0\n65 0.5 0.6\n")
                          << syntax
                          << "camera.cfg:1:1: expected a number for C, found '-inf', "
                             "which is not a finite number";
    QTest::newRow("1e999") << QByteArray("-200 1e999 300\n0.667 0.172 -1\n0 3 0\n65 0.5 0.6\n")
                           << syntax
                           << "camera.cfg:1:6: expected a number for C, found '1e999', "
                              "which is out of range";
    QTest::newRow("malformed 1.2.3, not out of range")
        << QByteArray("-200 -50 1.2.3\n0.667 0.172 -1\n0 3 0\n65 0.5 0.6\n") << syntax
        << "camera.cfg:1:10: expected a number for C, found '1.2.3'";
    QTest::newRow("malformed 6e, not out of range")
        << QByteArray("-200 -50 300\n0.667 0.172 -1\n0 3 0\n6e 0.5 0.6\n") << syntax
        << "camera.cfg:4:1: expected a number for d hx hy, found '6e'";
    QTest::newRow("two signs") << QByteArray("+-200 -50 300\n0.667 0.172 -1\n0 3 0\n65 0.5 0.6\n")
                               << syntax
                               << "camera.cfg:1:1: expected a number for C, found '+-200'";
    QTest::newRow("too few numbers on V")
        << QByteArray("-200 -50 300\n0.667 0.172 -1\n0 3\n65 0.5 0.6\n") << syntax
        << "camera.cfg:3:4: expected 3 numbers for V, found 2";
    QTest::newRow("too few numbers on d hx hy, CRLF")
        << QByteArray("-200 -50 300\r\n0.667 0.172 -1\r\n0 3 0\r\n65 0.5\r\n") << syntax
        << "camera.cfg:4:7: expected 3 numbers for d hx hy, found 2";
    QTest::newRow("missing line")
        << QByteArray("-200 -50 300\n0.667 0.172 -1\n0 3 0\n") << missing
        << "camera.cfg:4:1: expected d hx hy, the projection distance and half-sizes "
           "(3 numbers), found the end of the file";
    QTest::newRow("missing line, no final newline")
        << QByteArray("-200 -50 300\n0.667 0.172 -1\n0 3 0") << missing
        << "camera.cfg:3:6: expected d hx hy, the projection distance and half-sizes "
           "(3 numbers), found the end of the file";
    QTest::newRow("missing lines, CRLF and blank lines")
        << QByteArray("-200 -50 300\r\n\r\n0.667 0.172 -1\r\n\r\n") << missing
        << "camera.cfg:5:1: expected V, the up vector (3 numbers), found the end of the file";
    QTest::newRow("BOM and one line, no final newline")
        << kBom + "-200 -50 300" << missing
        << "camera.cfg:1:13: expected N, the view direction (3 numbers), "
           "found the end of the file";
    QTest::newRow("empty file") << QByteArray() << missing
                                << "camera.cfg:1:1: expected C, the camera position "
                                   "(3 numbers), found the end of the file";
    QTest::newRow("blank lines only") << QByteArray("\r\n  \r\n") << missing
                                      << "camera.cfg:3:1: expected C, the camera position "
                                         "(3 numbers), found the end of the file";
}

void TestCourseReaders::cameraErrors() {
    QFETCH(QByteArray, text);
    QFETCH(rl::ErrorCode, code);
    QFETCH(QString, message);

    rl::Diagnostics diagnostics;
    const auto camera = rl::readCourseCamera(viewOf(text), "camera.cfg", diagnostics);
    QVERIFY(!camera.ok());
    QCOMPARE(qs(camera.error().toString()), message);
    QCOMPARE(camera.error().code, code);
}

// ---------------------------------------------------------------------------------------
// Lighting

void TestCourseReaders::lighting_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<float>("kdR");
    QTest::addColumn<float>("kdG");
    QTest::addColumn<float>("kdB");
    QTest::addColumn<QString>("lightWhere");

    QTest::newRow("kd scalar, broadcast")
        << lightingWithKd("0.75") << 0.75f << 0.75f << 0.75f << "light.txt:1:1";
    QTest::newRow("kd RGB triple")
        << lightingWithKd("0.5 0.625 0.75") << 0.5f << 0.625f << 0.75f << "light.txt:1:1";
    QTest::newRow("kd scalar, CRLF, no final newline")
        << lightingWithKd("0.75", "\r\n").chopped(2) << 0.75f << 0.75f << 0.75f << "light.txt:1:1";
    QTest::newRow("kd triple, blank lines and TABs")
        << QByteArray(
               "\n\n-220\t-150 700\n\n 0.25\n10 20\t30\n\t0.5 0.625 0.75  \n\n"
               "0.125 0.25 0.375\n0.5\n\n40 50 60\n8\n\n")
        << 0.5f << 0.625f << 0.75f << "light.txt:3:1";
    QTest::newRow("exponents")
        << QByteArray(
               "-2.2e2 -1.5E+2 7e2\n2.5e-1\n1e1 2E1 3e+001\n7.5E-1\n1.25e-1 2.5e-1 "
               "3.75e-1\n5e-1\n4e1 5e1 6e1\n8.0\n")
        << 0.75f << 0.75f << 0.75f << "light.txt:1:1";
}

void TestCourseReaders::lighting() {
    QFETCH(QByteArray, text);
    QFETCH(float, kdR);
    QFETCH(float, kdG);
    QFETCH(float, kdB);
    QFETCH(QString, lightWhere);

    rl::Diagnostics diagnostics;
    const auto lighting = rl::readCourseLighting(viewOf(text), "light.txt", diagnostics);
    RL_VERIFY_OK(lighting);
    QCOMPARE(messagesOf(diagnostics), QStringList());

    const rl::Material& m = lighting->material;
    RL_COMPARE_NEAR(m.ka, 0.25, 0.0);
    RL_COMPARE_VEC(m.kd, rl::vec3(kdR, kdG, kdB), 0.0);
    RL_COMPARE_VEC(m.od, rl::vec3(0.125f, 0.25f, 0.375f), 0.0);
    RL_COMPARE_NEAR(m.ks, 0.5, 0.0);
    RL_COMPARE_NEAR(m.shininess, 8.0, 0.0);
    RL_COMPARE_VEC(lighting->ambientIntensity, rl::vec3(10.0f, 20.0f, 30.0f), 0.0);

    QCOMPARE(lighting->lights.size(), std::size_t(1));
    const rl::Light& light = lighting->lights[0];
    RL_COMPARE_VEC(light.pWorld, rl::dvec4(-220.0, -150.0, 700.0, 1.0), 0.0);
    RL_COMPARE_VEC(light.intensity, rl::vec3(40.0f, 50.0f, 60.0f), 0.0);
    QCOMPARE(qs(light.where.toString()), lightWhere);
}

void TestCourseReaders::lightingWarnings_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QStringList>("warnings");

    QTest::newRow("ka with three numbers")
        << QByteArray(
               "-220 -150 700\n0.25 0.5 0.75\n10 20 30\n0.75\n0.125 0.25 0.375\n0.5\n"
               "40 50 60\n8\n")
        << QStringList{"light.txt:2:6: warning: ignored 2 values after ka"};
    QTest::newRow("kd with four numbers")
        << lightingWithKd("0.75 0.75 0.75 1")
        << QStringList{"light.txt:4:16: warning: ignored 1 value after kd"};
    QTest::newRow("a line after the eighth")
        << lightingWithKd("0.75") + "1 1 1\n"
        << QStringList{"light.txt:9:1: warning: ignored 1 line after the lighting's 8 lines"};
    // A remark after one number is ignored for kd as it is for ka: one number is a valid kd.
    QTest::newRow("kd with a remark")
        << lightingWithKd("0.75 ; kd, the diffuse constant")
        << QStringList{"light.txt:4:6: warning: ignored 5 values after kd"};
}

void TestCourseReaders::lightingRanges_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QStringList>("warnings");
    QTest::newRow("within the course's ranges") << lightingWithKd("0.75") << QStringList();
    QTest::newRow("every value outside")
        << QByteArray(
               "-220 -150 700\n1.5\n300 -1 20\n2\n0.5 1.25 -0.5\n-0.25\n"
               "255 256 0\n-2\n")
        << QStringList{
               "light.txt:2:1: warning: ka = 1.5 is outside [0, 1], the range the course gives for "
               "it",
               "light.txt:3:1: warning: Ia.r = 300 is outside [0, 255], the range the course gives "
               "for it",
               "light.txt:3:5: warning: Ia.g = -1 is outside [0, 255], the range the course gives "
               "for it",
               "light.txt:4:1: warning: kd = 2 is outside [0, 1], the range the course gives for "
               "it",
               "light.txt:5:5: warning: Od.g = 1.25 is outside [0, 1], the range the course gives "
               "for it",
               "light.txt:5:10: warning: Od.b = -0.5 is outside [0, 1], the range the course gives "
               "for it",
               "light.txt:6:1: warning: ks = -0.25 is outside [0, 1], the range the course gives "
               "for it",
               "light.txt:7:5: warning: Il.g = 256 is outside [0, 255], the range the course gives "
               "for it",
               "light.txt:8:1: warning: n = -2 is not positive: (R.V)^n then makes no highlight "
               "(it "
               "is 1 everywhere for n = 0 and grows without bound where R.V nears 0 for n < 0, "
               "where "
               "the specular term is left out)"};
}

void TestCourseReaders::lightingRanges() {
    QFETCH(QByteArray, text);
    QFETCH(QStringList, warnings);
    rl::Diagnostics diagnostics;
    const auto lighting = rl::readCourseLighting(viewOf(text), "light.txt", diagnostics);
    RL_VERIFY_OK(lighting);
    QCOMPARE(messagesOf(diagnostics), warnings);
}

void TestCourseReaders::lightingWarnings() {
    QFETCH(QByteArray, text);
    QFETCH(QStringList, warnings);

    rl::Diagnostics diagnostics;
    const auto lighting = rl::readCourseLighting(viewOf(text), "light.txt", diagnostics);
    RL_VERIFY_OK(lighting);
    QCOMPARE(messagesOf(diagnostics), warnings);
    // The values read are those before the ignored ones.
    RL_COMPARE_NEAR(lighting->material.ka, 0.25, 0.0);
    RL_COMPARE_VEC(lighting->material.kd, rl::vec3(0.75f), 0.0);
    RL_COMPARE_NEAR(lighting->material.shininess, 8.0, 0.0);
}

void TestCourseReaders::lightingErrors_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<rl::ErrorCode>("code");
    QTest::addColumn<QString>("message");

    const auto syntax = rl::ErrorCode::Syntax;
    const auto missing = rl::ErrorCode::MissingData;
    QTest::newRow("kd with 2 numbers") << lightingWithKd("0.5 0.625") << syntax
                                       << "light.txt:4:10: expected 1 or 3 numbers for kd, found 2";
    QTest::newRow("kd with a letter")
        << lightingWithKd("x") << syntax << "light.txt:4:1: expected a number for kd, found 'x'";
    QTest::newRow("kd with a decimal comma in its second channel")
        << lightingWithKd("0.5 0,3 0.2") << syntax
        << "light.txt:4:5: expected a number for kd, found '0,3' (the decimal separator is '.')";
    QTest::newRow("missing n line")
        << lightingWithKd("0.75").chopped(2) << missing
        << "light.txt:8:1: expected n, the specular exponent (1 number), "
           "found the end of the file";
    QTest::newRow("missing n line, CRLF, no final newline")
        << lightingWithKd("0.75", "\r\n").chopped(5) << missing
        << "light.txt:7:9: expected n, the specular exponent (1 number), "
           "found the end of the file";
    QTest::newRow("a word in Od")
        << QByteArray(
               "-220 -150 700\n0.25\n10 20 30\n0.75\n0.125 green 0.375\n0.5\n"
               "40 50 60\n8\n")
        << syntax << "light.txt:5:7: expected a number for Od, found 'green'";
    QTest::newRow("decimal comma in ks")
        << QByteArray(
               "-220 -150 700\n0.25\n10 20 30\n0.75\n0.125 0.25 0.375\n0,5\n"
               "40 50 60\n8\n")
        << syntax
        << "light.txt:6:1: expected a number for ks, found '0,5' "
           "(the decimal separator is '.')";
    QTest::newRow("Ia with one number")
        << QByteArray("-220 -150 700\n0.25\n10\n0.75\n0.125 0.25 0.375\n0.5\n40 50 60\n8\n")
        << syntax << "light.txt:3:3: expected 3 numbers for Ia, found 1";
    QTest::newRow("empty file") << QByteArray() << missing
                                << "light.txt:1:1: expected Pl, the light position "
                                   "(3 numbers), found the end of the file";
}

void TestCourseReaders::lightingErrors() {
    QFETCH(QByteArray, text);
    QFETCH(rl::ErrorCode, code);
    QFETCH(QString, message);

    rl::Diagnostics diagnostics;
    const auto lighting = rl::readCourseLighting(viewOf(text), "light.txt", diagnostics);
    QVERIFY(!lighting.ok());
    QCOMPARE(qs(lighting.error().toString()), message);
    QCOMPARE(lighting.error().code, code);
}

// ---------------------------------------------------------------------------------------
// Object

void TestCourseReaders::object_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QList<int>>("triangleLines");

    QByteArray crlf = kObject;
    crlf.replace("\n", "\r\n");
    QTest::newRow("LF") << kObject << QList<int>{6, 7};
    QTest::newRow("CRLF") << crlf << QList<int>{6, 7};
    QTest::newRow("no final newline") << kObject.chopped(1) << QList<int>{6, 7};
    QTest::newRow("CRLF, no final newline") << crlf.chopped(2) << QList<int>{6, 7};
    QTest::newRow("blank lines between and inside blocks")
        << QByteArray(
               "\n4 2\n\n50.0000 0.0000 0.000\n0 50 0\n\n0 0 50\n-1E-15 9.5e-005 +2\n"
               "\r\n\n1 2 3\n   \n1 3 4\n\n")
        << QList<int>{11, 13};
    QTest::newRow("blank lines, CRLF, no final newline")
        << QByteArray(
               "4 2\r\n\r\n50.0000 0.0000 0.000\r\n0 50 0\r\n0 0 50\r\n\r\n"
               "-1E-15 9.5e-005 +2\r\n\r\n1 2 3\r\n\r\n\r\n1 3 4")
        << QList<int>{9, 12};
    QTest::newRow("TABs, leading and trailing spaces")
        << QByteArray(
               "4\t2\n  50.0000\t0.0000 0.000  \n\t0 50 0\n0\t0\t50\n"
               " -1E-15 9.5e-005   +2\t\n1\t2 3\n  1 3 4 \n")
        << QList<int>{6, 7};
    QTest::newRow("UTF-8 BOM and CRLF") << kBom + crlf << QList<int>{6, 7};
}

void TestCourseReaders::object() {
    QFETCH(QByteArray, text);
    QFETCH(QList<int>, triangleLines);

    rl::Diagnostics diagnostics;
    const auto mesh = rl::readByuMesh(viewOf(text), "objeto.byu", diagnostics);
    RL_VERIFY_OK(mesh);
    QCOMPARE(messagesOf(diagnostics), QStringList());

    QCOMPARE(mesh->positions.size(), std::size_t(4));
    RL_COMPARE_VEC(mesh->positions[0], rl::dvec4(50.0, 0.0, 0.0, 1.0), 0.0);
    RL_COMPARE_VEC(mesh->positions[1], rl::dvec4(0.0, 50.0, 0.0, 1.0), 0.0);
    RL_COMPARE_VEC(mesh->positions[2], rl::dvec4(0.0, 0.0, 50.0, 1.0), 0.0);
    RL_COMPARE_VEC(mesh->positions[3], rl::dvec4(-1e-15, 9.5e-5, 2.0, 1.0), 0.0);

    using Triangle = std::array<std::uint32_t, 3>;
    QCOMPARE(mesh->triangles.size(), std::size_t(2));
    QVERIFY(mesh->triangles[0] == (Triangle{0, 1, 2}));
    QVERIFY(mesh->triangles[1] == (Triangle{0, 2, 3}));
    QCOMPARE(QList<int>(mesh->triangleLines.begin(), mesh->triangleLines.end()), triangleLines);
    QCOMPARE(qs(mesh->source.toString()), QStringLiteral("objeto.byu"));
}

void TestCourseReaders::objectWarnings_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<int>("vertexCount");
    QTest::addColumn<QList<int>>("triangleLines");
    QTest::addColumn<QStringList>("warnings");

    QTest::newRow("a second object after the declared counts")
        << kObject + "3 1\n0 0 0\n1 0 0\n0 1 0\n1 2 3\n"
        << 4 << QList<int>{6, 7}
        << QStringList{
               "objeto.byu:8:1: warning: ignored 5 lines after the declared 4 vertices "
               "and 2 triangles (the header's counts may be wrong, or a second object "
               "follows)"};
    QTest::newRow("header declares one triangle fewer, CRLF, no final newline")
        << QByteArray(
               "4 1\r\n50.0000 0.0000 0.000\r\n0 50 0\r\n0 0 50\r\n-1E-15 9.5e-005 +2\r\n"
               "1 2 3\r\n1 3 4")
        << 4 << QList<int>{6}
        << QStringList{
               "objeto.byu:7:1: warning: ignored 1 line after the declared 4 vertices "
               "and 1 triangle (the header's counts may be wrong, or a second object "
               "follows)",
               "objeto.byu: warning: 1 vertex of 4 is not used by any triangle"};
    QTest::newRow("one unused vertex")
        << QByteArray("5 2\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n9 9 9\n1 2 3\n1 3 4\n") << 5
        << QList<int>{7, 8}
        << QStringList{"objeto.byu: warning: 1 vertex of 5 is not used by any triangle"};
    QTest::newRow("two unused vertices")
        << QByteArray("5 1\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n9 9 9\n1 2 3\n") << 5 << QList<int>{7}
        << QStringList{"objeto.byu: warning: 2 vertices of 5 are not used by any triangle"};
    QTest::newRow("duplicated positions (faceted)")
        << QByteArray("6 2\n0 0 0\n1 0 0\n0 1 0\n1 0 0\n0 1 0\n1 1 0\n1 2 3\n4 6 5\n") << 6
        << QList<int>{8, 9} << QStringList{};
    QTest::newRow("inconsistent winding")
        << QByteArray("4 2\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n1 2 3\n2 3 4\n") << 4 << QList<int>{6, 7}
        << QStringList{};
    QTest::newRow("non-manifold edge, open mesh")
        << QByteArray("5 3\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n1 2 3\n2 1 4\n1 2 5\n") << 5
        << QList<int>{7, 8, 9} << QStringList{};
    QTest::newRow("extra values on two lines")
        << QByteArray("3 1\n0 0 0\n1 0 0 7\n0 1 0\n1 2 3 ; triangle\n") << 3 << QList<int>{5}
        << QStringList{
               "objeto.byu:3:7: warning: ignored extra values at the end of 2 lines "
               "(the first is here)"};
    QTest::newRow("extra values on one line")
        << QByteArray("3 1\n0 0 0\n1 0 0\n0 1 0\t1\n1 2 3\n") << 3 << QList<int>{5}
        << QStringList{
               "objeto.byu:4:7: warning: ignored extra values at the end of 1 line "
               "(the first is here)"};
    QTest::newRow("an extra value on the header")
        << QByteArray("3 1 0\n0 0 0\n1 0 0\n0 1 0\n1 2 3\n") << 3 << QList<int>{5}
        << QStringList{"objeto.byu:1:5: warning: ignored 1 value after the header's two counts"};
    QTest::newRow("no triangles") << QByteArray("3 0\n0 0 0\n1 0 0\n0 1 0\n") << 3 << QList<int>{}
                                  << QStringList{
                                         "objeto.byu: warning: the object has no triangles"};
    QTest::newRow("nothing at all: 0 0") << QByteArray("0 0\r\n") << 0 << QList<int>{}
                                         << QStringList{
                                                "objeto.byu: warning: the object has "
                                                "no triangles"};
}

void TestCourseReaders::objectWarnings() {
    QFETCH(QByteArray, text);
    QFETCH(int, vertexCount);
    QFETCH(QList<int>, triangleLines);
    QFETCH(QStringList, warnings);

    rl::Diagnostics diagnostics;
    const auto mesh = rl::readByuMesh(viewOf(text), "objeto.byu", diagnostics);
    RL_VERIFY_OK(mesh);
    QCOMPARE(messagesOf(diagnostics), warnings);
    QCOMPARE(int(mesh->positions.size()), vertexCount);
    QCOMPARE(int(mesh->triangles.size()), int(triangleLines.size()));
    QCOMPARE(QList<int>(mesh->triangleLines.begin(), mesh->triangleLines.end()), triangleLines);
    for (const auto& triangle : mesh->triangles)
        for (std::uint32_t index : triangle) QVERIFY(index < mesh->positions.size());
    if (!mesh->triangles.empty()) {  // 1-based in the file, 0-based here
        using Triangle = std::array<std::uint32_t, 3>;
        QVERIFY(mesh->triangles[0] == (Triangle{0, 1, 2}));
    }
}

void TestCourseReaders::objectErrors_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<rl::ErrorCode>("code");
    QTest::addColumn<QString>("message");

    const auto syntax = rl::ErrorCode::Syntax;
    const auto missing = rl::ErrorCode::MissingData;
    const auto range = rl::ErrorCode::Range;
    const auto unsupported = rl::ErrorCode::Unsupported;

    // Coordinates.
    QTest::newRow("a letter where a coordinate belongs")
        << QByteArray("3 1\n0 0 0\n1 a 0\n0 1 0\n1 2 3\n") << syntax
        << "objeto.byu:3:3: expected a number for the y coordinate of vertex 2 of 3, found 'a'";
    QTest::newRow("decimal comma in a coordinate")
        << QByteArray("3 1\n0 0 0\n1 0 0\n0 1 0,5\n1 2 3\n") << syntax
        << "objeto.byu:4:5: expected a number for the z coordinate of vertex 3 of 3, found "
           "'0,5' (the decimal separator is '.')";
    QTest::newRow("nan coordinate")
        << QByteArray("3 1\nnan 0 0\n1 0 0\n0 1 0\n1 2 3\n") << syntax
        << "objeto.byu:2:1: expected a number for the x coordinate of vertex 1 of 3, found "
           "'nan', which is not a finite number";
    QTest::newRow("-nan coordinate")
        << QByteArray("3 1\n-nan 0 0\n1 0 0\n0 1 0\n1 2 3\n") << syntax
        << "objeto.byu:2:1: expected a number for the x coordinate of vertex 1 of 3, found "
           "'-nan', which is not a finite number";
    QTest::newRow("out-of-range coordinate")
        << QByteArray("3 1\n0 0 -1e999\n1 0 0\n0 1 0\n1 2 3\n") << syntax
        << "objeto.byu:2:5: expected a number for the z coordinate of vertex 1 of 3, found "
           "'-1e999', which is out of range";
    QTest::newRow("malformed coordinate 1.2.3")
        << QByteArray("3 1\n0 0 0\n1.2.3 0 0\n0 1 0\n1 2 3\n") << syntax
        << "objeto.byu:3:1: expected a number for the x coordinate of vertex 2 of 3, "
           "found '1.2.3'";
    QTest::newRow("malformed coordinate 1e-")
        << QByteArray("3 1\n0 0 0\n1e- 0 0\n0 1 0\n1 2 3\n") << syntax
        << "objeto.byu:3:1: expected a number for the x coordinate of vertex 2 of 3, "
           "found '1e-'";
    QTest::newRow("too few coordinates")
        << QByteArray("3 1\n0 0 0\n1 0\n0 1 0\n1 2 3\n") << syntax
        << "objeto.byu:3:4: expected 3 coordinates for vertex 2 of 3, found 2";
    QTest::newRow("too few coordinates, CRLF")
        << QByteArray("3 1\r\n0 0 0\r\n1 0 0\r\n0\r\n1 2 3\r\n") << syntax
        << "objeto.byu:4:2: expected 3 coordinates for vertex 3 of 3, found 1";

    // Triangles.
    QTest::newRow("index out of range")
        << QByteArray("3 1\n0 0 0\n1 0 0\n0 1 0\n1 2 4\n") << range
        << "objeto.byu:5:5: triangle 1 refers to vertex 4, but the file declares only "
           "3 vertices";
    QTest::newRow("index out of range, one vertex")
        << QByteArray("1 1\n0 0 0\n1 1 2\n") << range
        << "objeto.byu:3:5: triangle 1 refers to vertex 2, but the file declares only 1 vertex";
    QTest::newRow("index 0") << QByteArray("3 1\n0 0 0\n1 0 0\n0 1 0\n0 1 2\n") << range
                             << "objeto.byu:5:1: triangle 1 refers to vertex 0, but indices "
                                "are 1-based (1 to 3)";
    QTest::newRow("negative index")
        << QByteArray("3 2\n0 0 0\n1 0 0\n0 1 0\n1 2 3\n1 -2 3\n") << range
        << "objeto.byu:6:3: triangle 2 refers to vertex -2, but indices are 1-based (1 to 3)";
    QTest::newRow("non-integer index 1.5")
        << QByteArray("3 1\n0 0 0\n1 0 0\n0 1 0\n1 1.5 3\n") << syntax
        << "objeto.byu:5:3: expected a vertex index (a positive integer) for triangle 1, "
           "found '1.5'";
    QTest::newRow("too few indices") << QByteArray("3 1\n0 0 0\n1 0 0\n0 1 0\n1 2\n") << syntax
                                     << "objeto.byu:5:4: expected 3 vertex indices for "
                                        "triangle 1 of 1, found 2";
    QTest::newRow("polygon with 4 indices")
        << QByteArray("4 1\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n1 2 3 4\n") << unsupported
        << "objeto.byu:6:7: polygon 1 has 4 vertex indices, but only triangles (3 indices) "
           "are supported";

    // Header.
    QTest::newRow("header count the file cannot hold")
        << QByteArray("1000000 1\n0 0 0\n1 0 0\n0 1 0\n1 2 3\n") << range
        << "objeto.byu:1:1: the header declares 1000000 vertices and 1 triangle "
           "(1000001 lines), but only 4 lines follow";
    QTest::newRow("header declares one triangle more than the file holds")
        << QByteArray("3 2\n0 0 0\n1 0 0\n0 1 0\n1 2 3\n") << range
        << "objeto.byu:1:1: the header declares 3 vertices and 2 triangles (5 lines), "
           "but only 4 lines follow";
    QTest::newRow("only one line follows the header")
        << QByteArray("3 1\n0 0 0\n") << range
        << "objeto.byu:1:1: the header declares 3 vertices and 1 triangle (4 lines), "
           "but only 1 line follows";
    QTest::newRow("header counts whose sum overflows")
        << QByteArray("9223372036854775807 9223372036854775807\n0 0 0\n") << range
        << "objeto.byu:1:1: the header declares 9223372036854775807 vertices and "
           "9223372036854775807 triangles (18446744073709551614 lines), but only 1 line follows";
    QTest::newRow("negative vertex count")
        << QByteArray("-3 1\n0 0 0\n1 0 0\n0 1 0\n1 2 3\n") << syntax
        << "objeto.byu:1:1: expected the number of vertices (a non-negative integer), "
           "found '-3'";
    QTest::newRow("non-integer triangle count")
        << QByteArray("3 1.0\n0 0 0\n1 0 0\n0 1 0\n1 2 3\n") << syntax
        << "objeto.byu:1:3: expected the number of triangles (a non-negative integer), "
           "found '1.0'";
    QTest::newRow("header with only one number")
        << QByteArray("3\n0 0 0\n1 0 0\n0 1 0\n1 2 3\n") << syntax
        << "objeto.byu:1:2: expected the number of triangles after the number of vertices, "
           "found the end of the line";
    QTest::newRow("words as header")
        << QByteArray("vertices triangles\n0 0 0\n") << syntax
        << "objeto.byu:1:1: expected the number of vertices (a non-negative integer), "
           "found 'vertices'";

    // Comments.
    QTest::newRow("comment as the first line")
        << QByteArray("# chalice\n3 1\n0 0 0\n1 0 0\n0 1 0\n1 2 3\n") << syntax
        << "objeto.byu:1:1: expected the header 'vertices triangles' (two integers), found a "
           "comment ('#'), but .byu files have no comments";
    QTest::newRow("comment among the vertices")
        << QByteArray("3 1\n0 0 0\n// next\n1 0 0\n0 1 0\n1 2 3\n") << syntax
        << "objeto.byu:3:1: expected vertex 2 of 3 (x y z), found a comment ('//'), but .byu "
           "files have no comments";
    QTest::newRow("comment among the triangles")
        << QByteArray("3 1\n0 0 0\n1 0 0\n0 1 0\n#1 2 3\n1 2 3\n") << syntax
        << "objeto.byu:5:1: expected triangle 1 of 1 (three vertex indices), found a comment "
           "('#1'), but .byu files have no comments";

    // Other layouts.
    QTest::newRow("original Movie.BYU header")
        << QByteArray("1 3 1 3\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 2 -3\n") << unsupported
        << "objeto.byu:1:1: this is an original Movie.BYU file (header 'parts vertices "
           "polygons edges'), not the course's .byu format (header 'vertices triangles')";
    QTest::newRow("course Bezier surface")
        << QByteArray("1 2\r\n40\r\n0 0 0\r\n1 0 1\r\n2 0 0\r\n0 1 0\r\n1 1 1\r\n2 1 0\r\n")
        << unsupported
        << "objeto.byu:1:1: this looks like a course Bezier surface (degrees 1 x 2, "
           "40 evaluations per direction), not a triangle mesh";

    // Nothing to read.
    QTest::newRow("empty file") << QByteArray() << missing
                                << "objeto.byu:1:1: expected the header 'vertices triangles' "
                                   "(two integers), found the end of the file";
    QTest::newRow("blank lines only, CRLF")
        << QByteArray("\r\n\r\n") << missing
        << "objeto.byu:3:1: expected the header 'vertices triangles' (two integers), found "
           "the end of the file";
    QTest::newRow("only a BOM") << kBom << missing
                                << "objeto.byu:1:1: expected the header 'vertices triangles' "
                                   "(two integers), found the end of the file";
}

void TestCourseReaders::objectErrors() {
    QFETCH(QByteArray, text);
    QFETCH(rl::ErrorCode, code);
    QFETCH(QString, message);

    rl::Diagnostics diagnostics;
    const auto mesh = rl::readByuMesh(viewOf(text), "objeto.byu", diagnostics);
    QVERIFY(!mesh.ok());
    QCOMPARE(qs(mesh.error().toString()), message);
    QCOMPARE(mesh.error().code, code);
}

void TestCourseReaders::objectName_data() {
    QTest::addColumn<QString>("fileName");
    QTest::addColumn<QString>("name");

    QTest::newRow("bare name") << "objeto.byu"
                               << "objeto.byu";
    QTest::newRow("absolute path") << "/home/aluno/entradas/calice2.byu"
                                   << "calice2.byu";
    QTest::newRow("relative path") << "entradas/vaso.byu"
                                   << "vaso.byu";
    QTest::newRow("dots in the path") << "./a/../b/tri.angulos.byu"
                                      << "tri.angulos.byu";
}

void TestCourseReaders::objectName() {
    QFETCH(QString, fileName);
    QFETCH(QString, name);

    rl::Diagnostics diagnostics;
    const auto object = rl::parseCourseObject(viewOf(kObject), fileName.toStdString(), diagnostics);
    RL_VERIFY_OK(object);
    QCOMPARE(qs(object->name), name);
    QVERIFY(object->mesh);
    QCOMPARE(object->mesh->triangles.size(), std::size_t(2));
    // Messages keep the whole path.
    QCOMPARE(qs(object->mesh->source.file), fileName);
    const auto bad =
        rl::parseCourseObject(viewOf(kObject.left(4)), fileName.toStdString(), diagnostics);
    QVERIFY(!bad.ok());
    QCOMPARE(qs(bad.error().toString()),
             fileName +
                 ":1:1: the header declares 4 vertices and 2 triangles (6 lines), "
                 "but only 0 lines follow");
}

// ---------------------------------------------------------------------------------------
// The course's own files

#define RL_REQUIRE_SAMPLES()                                                             \
    do {                                                                                 \
        if (testing::samplesDir().isEmpty())                                             \
            QSKIP(                                                                       \
                "course samples not found: set RASTERLAB_SAMPLES to the folder holding " \
                "course/");                                                              \
    } while (false)

namespace {

QString samplePath(const QString& relative) {
    return testing::samplesDir() + QStringLiteral("/course/") + relative;
}

}  // namespace

void TestCourseReaders::samplesSeedExample() {
    RL_REQUIRE_SAMPLES();
    rl::Diagnostics diagnostics;

    const QString cameraPath = samplePath(QStringLiteral("seed-example/camera.cfg"));
    const QByteArray cameraText = testing::readFile(cameraPath);
    const auto camera =
        rl::readCourseCamera(viewOf(cameraText), cameraPath.toStdString(), diagnostics);
    RL_VERIFY_OK(camera);
    checkSeedCamera(*camera);

    const QString lightingPath = samplePath(QStringLiteral("seed-example/iluminacao.txt"));
    const QByteArray lightingText = testing::readFile(lightingPath);
    const auto lighting =
        rl::readCourseLighting(viewOf(lightingText), lightingPath.toStdString(), diagnostics);
    RL_VERIFY_OK(lighting);
    QCOMPARE(lighting->lights.size(), std::size_t(1));
    RL_COMPARE_VEC(lighting->lights[0].pWorld, rl::dvec4(-200.0, -50.0, 300.0, 1.0), 0.0);
    RL_COMPARE_NEAR(lighting->material.ka, 1.0, 0.0);
    RL_COMPARE_VEC(lighting->ambientIntensity, rl::vec3(2.0f), 0.0);
    RL_COMPARE_VEC(lighting->material.kd, rl::vec3(1.0f), 0.0);
    RL_COMPARE_VEC(lighting->material.od, rl::vec3(1.0f), 0.0);
    RL_COMPARE_NEAR(lighting->material.ks, 0.5, 0.0);
    RL_COMPARE_VEC(lighting->lights[0].intensity, rl::vec3(0.0f, 255.0f, 0.0f), 0.0);
    RL_COMPARE_NEAR(lighting->material.shininess, 2.0, 0.0);

    const QString objectPath = samplePath(QStringLiteral("seed-example/objeto.byu"));
    const QByteArray objectText = testing::readFile(objectPath);
    const auto object =
        rl::parseCourseObject(viewOf(objectText), objectPath.toStdString(), diagnostics);
    RL_VERIFY_OK(object);
    QCOMPARE(qs(object->name), QStringLiteral("objeto.byu"));
    const rl::Mesh& mesh = *object->mesh;
    QCOMPARE(mesh.positions.size(), std::size_t(3));
    RL_COMPARE_VEC(mesh.positions[0], rl::dvec4(50.0, 0.0, 0.0, 1.0), 0.0);
    RL_COMPARE_VEC(mesh.positions[1], rl::dvec4(0.0, 50.0, 0.0, 1.0), 0.0);
    RL_COMPARE_VEC(mesh.positions[2], rl::dvec4(0.0, 0.0, 50.0, 1.0), 0.0);
    QCOMPARE(mesh.triangles.size(), std::size_t(1));
    QVERIFY(mesh.triangles[0] == (std::array<std::uint32_t, 3>{0, 1, 2}));
    QCOMPARE(QList<int>(mesh.triangleLines.begin(), mesh.triangleLines.end()), QList<int>{5});

    QCOMPARE(messagesOf(diagnostics), QStringList());
}

void TestCourseReaders::samplesUfpeObjects_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("vertices");
    QTest::addColumn<int>("triangles");
    QTest::addColumn<double>("x1");  // the first vertex
    QTest::addColumn<double>("y1");
    QTest::addColumn<double>("z1");

    // Counts from the files' headers; CRLF, no blank lines.
    QTest::newRow("calice2.byu") << "ufpe/calice2.byu" << 1062 << 2120 << 20.9095156136808
                                 << 410.241584925467 << 0.0;
    QTest::newRow("vaso.byu") << "ufpe/vaso.byu" << 681 << 1340 << 9.24850261369368
                              << 431.041790139218 << 0.0;
}

void TestCourseReaders::samplesUfpeObjects() {
    RL_REQUIRE_SAMPLES();
    QFETCH(QString, file);
    QFETCH(int, vertices);
    QFETCH(int, triangles);
    QFETCH(double, x1);
    QFETCH(double, y1);
    QFETCH(double, z1);

    const QString path = samplePath(file);
    const QByteArray text = testing::readFile(path);
    QVERIFY2(!text.isEmpty(), qPrintable(path));
    rl::Diagnostics diagnostics;
    const auto object = rl::parseCourseObject(viewOf(text), path.toStdString(), diagnostics);
    RL_VERIFY_OK(object);
    QCOMPARE(messagesOf(diagnostics), QStringList());
    const rl::Mesh& mesh = *object->mesh;
    QCOMPARE(int(mesh.positions.size()), vertices);
    QCOMPARE(int(mesh.triangles.size()), triangles);
    RL_COMPARE_VEC(mesh.positions[0], rl::dvec4(x1, y1, z1, 1.0), 0.0);
    // One line per triangle after the header and the vertices.
    QCOMPARE(int(mesh.triangleLines.size()), triangles);
    QCOMPARE(mesh.triangleLines.front(), vertices + 2);
    QCOMPARE(mesh.triangleLines.back(), vertices + triangles + 1);
}

void TestCourseReaders::samplesUfpeCameras_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<rl::dvec3>("c");
    QTest::addColumn<rl::dvec3>("n");
    QTest::addColumn<rl::dvec3>("v");
    QTest::addColumn<rl::dvec3>("dhxhy");

    QTest::newRow("calice2.cfg") << "ufpe/calice2.cfg" << rl::dvec3(50.0, -50.0, 600.0)
                                 << rl::dvec3(0.0, 0.0, -1.0) << rl::dvec3(1.0, -100.0, 10.0)
                                 << rl::dvec3(1.0, 1.0, 1.0);
    QTest::newRow("vaso.cfg") << "ufpe/vaso.cfg" << rl::dvec3(-620.0, -150.0, 700.0)
                              << rl::dvec3(1.0, 0.2, -1.0) << rl::dvec3(0.0, -1.0, 0.0)
                              << rl::dvec3(1.0, 0.6, 0.5);
}

void TestCourseReaders::samplesUfpeCameras() {
    RL_REQUIRE_SAMPLES();
    QFETCH(QString, file);
    QFETCH(rl::dvec3, c);
    QFETCH(rl::dvec3, n);
    QFETCH(rl::dvec3, v);
    QFETCH(rl::dvec3, dhxhy);

    const QString path = samplePath(file);
    const QByteArray text = testing::readFile(path);
    rl::Diagnostics diagnostics;
    const auto camera = rl::readCourseCamera(viewOf(text), path.toStdString(), diagnostics);
    RL_VERIFY_OK(camera);
    QCOMPARE(messagesOf(diagnostics), QStringList());
    RL_COMPARE_VEC(camera->c, c, 0.0);
    RL_COMPARE_VEC(camera->n, n, 0.0);
    RL_COMPARE_VEC(camera->v, v, 0.0);
    RL_COMPARE_VEC(rl::dvec3(camera->d, camera->hx, camera->hy), dhxhy, 0.0);
}

void TestCourseReaders::samplesUfpeLighting() {
    RL_REQUIRE_SAMPLES();
    const QString path = samplePath(QStringLiteral("ufpe/iluminacao.txt"));
    const QByteArray text = testing::readFile(path);
    rl::Diagnostics diagnostics;
    const auto lighting = rl::readCourseLighting(viewOf(text), path.toStdString(), diagnostics);
    RL_VERIFY_OK(lighting);
    QCOMPARE(messagesOf(diagnostics), QStringList());
    QCOMPARE(lighting->lights.size(), std::size_t(1));
    RL_COMPARE_VEC(lighting->lights[0].pWorld, rl::dvec4(-220.0, -150.0, 700.0, 1.0), 0.0);
    RL_COMPARE_NEAR(lighting->material.ka, 1.0, 0.0);
    RL_COMPARE_VEC(lighting->ambientIntensity, rl::vec3(64.0f), 0.0);
    RL_COMPARE_VEC(lighting->material.kd, rl::vec3(1.0f), 0.0);
    RL_COMPARE_VEC(lighting->material.od, rl::vec3(0.0f, 0.8f, 0.0f), 1e-7);
    RL_COMPARE_NEAR(lighting->material.ks, 0.5, 0.0);
    RL_COMPARE_VEC(lighting->lights[0].intensity, rl::vec3(255.0f), 0.0);
    RL_COMPARE_NEAR(lighting->material.shininess, 2.0, 0.0);
}

QTEST_GUILESS_MAIN(TestCourseReaders)
#include "tst_course_readers.moc"
