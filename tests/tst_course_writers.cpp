// The course file writers: the exact text of each layout (the same bytes as the files the
// readers' tests read), numbers in their shortest exact form, kd as one number or three, the
// errors (several lights in a one-light layout, no lights, nan, 'auto', a directional light),
// a key = value file shared by camera and lighting keeping the other part's lines, CRLF kept;
// and read(write(x)) == x bit for bit in every layout, on the course samples and on numbers
// such as 0.1, 1e-7, -0 and the extremes of double and float.
#include <QtTest>

#include <bit>
#include <cstdint>
#include <limits>
#include <random>

#include "pipeline/io/course_readers.h"
#include "pipeline/io/course_writers.h"
#include "tests/test_support.h"

namespace {

using testing::seedCamera;  // seed 000's camera
using testing::viewOf;

QString qs(const std::string& s) {
    return QString::fromStdString(s);
}

std::uint64_t bitsOf(double v) {
    return std::bit_cast<std::uint64_t>(v);
}
std::uint32_t bitsOf(float v) {
    return std::bit_cast<std::uint32_t>(v);
}

// "" when equal bit for bit, else which value differs.
template <typename Vec>
QString vecDiff(const char* name, const Vec& a, const Vec& b) {
    for (int k = 0; k < a.length(); ++k)
        if (bitsOf(a[k]) != bitsOf(b[k]))
            return QStringLiteral("%1[%2]: %3 != %4")
                .arg(QLatin1String(name))
                .arg(k)
                .arg(double(a[k]), 0, 'g', 17)
                .arg(double(b[k]), 0, 'g', 17);
    return {};
}

QString scalarDiff(const char* name, auto a, auto b) {
    if (bitsOf(a) == bitsOf(b)) return {};
    return QStringLiteral("%1: %2 != %3")
        .arg(QLatin1String(name))
        .arg(double(a), 0, 'g', 17)
        .arg(double(b), 0, 'g', 17);
}

QString cameraDiff(const rl::CourseCamera& a, const rl::CourseCamera& b) {
    for (const QString& d :
         {vecDiff("C", a.c, b.c), vecDiff("N", a.n, b.n), vecDiff("V", a.v, b.v),
          scalarDiff("d", a.d, b.d), scalarDiff("hx", a.hx, b.hx), scalarDiff("hy", a.hy, b.hy)})
        if (!d.isEmpty()) return d;
    return {};
}

QString lightingDiff(const rl::CourseLighting& a, const rl::CourseLighting& b) {
    const rl::Material &x = a.material, &y = b.material;
    for (const QString& d :
         {scalarDiff("ka", x.ka, y.ka), vecDiff("kd", x.kd, y.kd), vecDiff("Od", x.od, y.od),
          scalarDiff("ks", x.ks, y.ks), scalarDiff("n", x.shininess, y.shininess),
          vecDiff("Ia", a.ambientIntensity, b.ambientIntensity)})
        if (!d.isEmpty()) return d;
    if (a.lights.size() != b.lights.size())
        return QStringLiteral("%1 lights != %2").arg(a.lights.size()).arg(b.lights.size());
    for (std::size_t k = 0; k < a.lights.size(); ++k) {
        const QString d = vecDiff("Pl", a.lights[k].pWorld, b.lights[k].pWorld) +
                          vecDiff("Il", a.lights[k].intensity, b.lights[k].intensity);
        if (!d.isEmpty()) return QStringLiteral("light %1: %2").arg(k + 1).arg(d);
    }
    return {};
}

#define RL_SAME(diff)                                       \
    do {                                                    \
        const QString d_ = (diff);                          \
        if (!d_.isEmpty()) QFAIL(qPrintable(context + d_)); \
    } while (false)

// A one-light lighting (the values of tst_course_variants).
rl::CourseLighting oneLight() {
    rl::CourseLighting l;
    l.material.ka = 0.25f;
    l.ambientIntensity = rl::vec3(10, 20, 30);
    l.material.kd = rl::vec3(0.5f, 0.625f, 0.75f);
    l.material.od = rl::vec3(0.125f, 0.25f, 0.375f);
    l.material.ks = 0.5f;
    l.material.shininess = 8.0f;
    rl::Light light;
    light.pWorld = rl::dvec4(-220, -150, 700, 1);
    light.intensity = rl::vec3(40, 50, 60);
    l.lights.push_back(light);
    return l;
}

rl::CourseLighting twoLights() {
    rl::CourseLighting l = oneLight();
    rl::Light second;
    second.pWorld = rl::dvec4(820, -150, -200, 1);
    second.intensity = rl::vec3(0, 128, 255);
    l.lights.push_back(second);
    return l;
}

// Values whose text is easily wrong: 0.1 (not a binary fraction), 1e-7 (an exponent), -0,
// the largest and smallest doubles and floats, a denormal, and 17-digit doubles.
rl::CourseCamera awkwardCamera() {
    rl::CourseCamera c;
    c.c = rl::dvec3(0.1, 1e-7, -0.0);
    c.n = rl::dvec3(std::numeric_limits<double>::max(), -std::numeric_limits<double>::min(),
                    std::numeric_limits<double>::denorm_min());
    c.v = rl::dvec3(1.0 / 3.0, -2.0 / 3.0, 0.1 + 0.2);
    c.d = 1e22;
    c.hx = 123456789.123456789;
    c.hy = -0.0;
    return c;
}

rl::CourseLighting awkwardLighting() {
    rl::CourseLighting l = twoLights();
    l.material.ka = 0.1f;
    l.material.kd = rl::vec3(1e-7f, -0.0f, std::numeric_limits<float>::denorm_min());
    l.material.od =
        rl::vec3(std::numeric_limits<float>::max(), std::numeric_limits<float>::min(), 1.0f / 3.0f);
    l.material.ks = -0.0f;
    l.material.shininess = 16777217.0f;  // 2^24 + 1 rounds to 2^24 as a float
    l.ambientIntensity = rl::vec3(0.3f, 255.0f, 2.0f / 3.0f);
    l.lights[0].pWorld = rl::dvec4(0.1, -1e-7, -0.0, 1.0);
    l.lights[0].intensity = rl::vec3(0.7f, 1e30f, -1e-30f);
    l.lights[1].pWorld = rl::dvec4(1.0 / 7.0, 5e-324, 1e308, 1.0);
    return l;
}

QString sample(const QString& relative) {
    return testing::samplesDir() + QStringLiteral("/course/") + relative;
}

}  // namespace

class TestCourseWriters : public QObject {
    Q_OBJECT
private slots:
    void shortestNumbers();
    void doublesRoundTrip();
    void floatsRoundTrip();
    void cameraText_data();
    void cameraText();
    void lightingText_data();
    void lightingText();
    void kdOneNumberOrThree();
    void errors();
    void slidesLightingRoundTrip();
    void sharedKeyValueFileKeepsTheOtherPart();
    void lineEndingKept();
    void cameraRoundTrip_data();
    void cameraRoundTrip();
    void lightingRoundTrip_data();
    void lightingRoundTrip();
};

void TestCourseWriters::shortestNumbers() {
    QCOMPARE(qs(rl::formatExact(0.1)), QStringLiteral("0.1"));
    QCOMPARE(qs(rl::formatExact(1e-7)), QStringLiteral("1e-07"));
    QCOMPARE(qs(rl::formatExact(-0.0)), QStringLiteral("-0"));
    QCOMPARE(qs(rl::formatExact(600.0)), QStringLiteral("600"));
    QCOMPARE(qs(rl::formatExact(0.667)), QStringLiteral("0.667"));
    QCOMPARE(qs(rl::formatExact(0.1 + 0.2)), QStringLiteral("0.30000000000000004"));
    QCOMPARE(qs(rl::formatExact(1e22)), QStringLiteral("1e+22"));
    // A float keeps its own shortest text, not the double's 0.10000000149011612.
    QCOMPARE(qs(rl::formatExact(0.1f)), QStringLiteral("0.1"));
    QCOMPARE(qs(rl::formatExact(0.8f)), QStringLiteral("0.8"));
    QCOMPARE(qs(rl::formatExact(1e-7f)), QStringLiteral("1e-07"));
    QCOMPARE(qs(rl::formatExact(-0.0f)), QStringLiteral("-0"));
    QCOMPARE(qs(rl::formatExact(255.0f)), QStringLiteral("255"));
}

// Random bit patterns: every finite double's text reads back as the same bits.
void TestCourseWriters::doublesRoundTrip() {
    std::mt19937_64 random(20240611);
    int tested = 0;
    for (int i = 0; i < 200000; ++i) {
        const double v = std::bit_cast<double>(random());
        if (!std::isfinite(v)) continue;
        const std::string text = rl::formatExact(v);
        const auto back = rl::parseReal(text);
        QVERIFY2(back && bitsOf(*back) == bitsOf(v), text.c_str());
        ++tested;
    }
    QVERIFY(tested > 190000);
}

// Random floats: the text, parsed as a double by the readers and narrowed, gives the float.
void TestCourseWriters::floatsRoundTrip() {
    std::mt19937 random(20240611);
    int tested = 0;
    for (int i = 0; i < 400000; ++i) {
        const float v = std::bit_cast<float>(static_cast<std::uint32_t>(random()));
        if (!std::isfinite(v)) continue;
        const std::string text = rl::formatExact(v);
        const auto back = rl::parseReal(text);
        QVERIFY2(back && bitsOf(static_cast<float>(*back)) == bitsOf(v), text.c_str());
        ++tested;
    }
    QVERIFY(tested > 390000);
}

// The seed camera, written in each layout: the very files tst_course_variants reads.
void TestCourseWriters::cameraText_data() {
    QTest::addColumn<rl::CameraLayout>("layout");
    QTest::addColumn<QByteArray>("expected");
    QTest::newRow("ufpe") << rl::CameraLayout::Ufpe
                          << QByteArray("-200 -50 300\n0.667 0.172 -1\n0 3 0\n65 0.5 0.6\n");
    QTest::newRow("ufrpe6") << rl::CameraLayout::Ufrpe6
                            << QByteArray("0.667 0.172 -1\n0 3 0\n65\n0.5\n0.6\n-200 -50 300\n");
    QTest::newRow("ufrpe5") << rl::CameraLayout::Ufrpe5
                            << QByteArray("-200 -50 300\n0.667 0.172 -1\n0 3 0\n0.5 0.6\n65\n");
    QTest::newRow("keyvalue") << rl::CameraLayout::KeyValue
                              << QByteArray(
                                     "C = -200 -50 300\nN = 0.667 0.172 -1\nV = 0 3 0\nd = 65\n"
                                     "hx = 0.5\nhy = 0.6\n");
}

void TestCourseWriters::cameraText() {
    QFETCH(rl::CameraLayout, layout);
    QFETCH(QByteArray, expected);
    const auto text = rl::writeCameraFile(seedCamera(), layout);
    QVERIFY2(text.ok(), text.ok() ? "" : text.error().toString().c_str());
    QCOMPARE(QByteArray::fromStdString(*text), expected);
    QCOMPARE(rl::detectCameraLayout(*text), std::optional(layout));
}

void TestCourseWriters::lightingText_data() {
    QTest::addColumn<rl::LightingLayout>("layout");
    QTest::addColumn<bool>("two");
    QTest::addColumn<QByteArray>("expected");
    QTest::newRow("ufpe") << rl::LightingLayout::Ufpe << false
                          << QByteArray(
                                 "-220 -150 700\n0.25\n10 20 30\n0.5 0.625 0.75\n0.125 0.25 "
                                 "0.375\n0.5\n40 50 60\n8\n");
    QTest::newRow("ufrpe") << rl::LightingLayout::Ufrpe << false
                           << QByteArray(
                                  "10 20 30\n0.25\n40 50 60\n-220 -150 700\n0.5 0.625 "
                                  "0.75\n0.125 0.25 0.375\n0.5\n8\n");
    QTest::newRow("keyvalue") << rl::LightingLayout::KeyValue << false
                              << QByteArray(
                                     "Iamb = 10 20 30\nKa = 0.25\nIl = 40 50 60\nPl = -220 -150 "
                                     "700\nKd = 0.5 0.625 0.75\nOd = 0.125 0.25 0.375\nKs = "
                                     "0.5\neta = 8\n");
    QTest::newRow("multi, one light")
        << rl::LightingLayout::UfpeMulti << false
        << QByteArray(
               "0.25\n10 20 30\n0.5 0.625 0.75\n0.125 0.25 0.375\n0.5\n8\n1\n-220 -150 700\n40 "
               "50 60\n");
    QTest::newRow("multi, two lights")
        << rl::LightingLayout::UfpeMulti << true
        << QByteArray(
               "0.25\n10 20 30\n0.5 0.625 0.75\n0.125 0.25 0.375\n0.5\n8\n2\n-220 -150 700\n40 "
               "50 60\n820 -150 -200\n0 128 255\n");
}

void TestCourseWriters::lightingText() {
    QFETCH(rl::LightingLayout, layout);
    QFETCH(bool, two);
    QFETCH(QByteArray, expected);
    const auto text = rl::writeLightingFile(two ? twoLights() : oneLight(), layout);
    QVERIFY2(text.ok(), text.ok() ? "" : text.error().toString().c_str());
    QCOMPARE(QByteArray::fromStdString(*text), expected);
    QCOMPARE(rl::detectLightingLayout(*text), std::optional(layout));
}

// The UFPE files have a scalar kd: one number when the channels are equal. UFRPE and
// key = value files always hold three.
void TestCourseWriters::kdOneNumberOrThree() {
    rl::CourseLighting l = oneLight();
    l.material.kd = rl::vec3(0.8f);
    auto ufpe = rl::writeLightingFile(l, rl::LightingLayout::Ufpe);
    QVERIFY(ufpe.ok());
    QCOMPARE(qs(*ufpe).split(QLatin1Char('\n')).at(3), QStringLiteral("0.8"));
    auto multi = rl::writeLightingFile(l, rl::LightingLayout::UfpeMulti);
    QVERIFY(multi.ok());
    QCOMPARE(qs(*multi).split(QLatin1Char('\n')).at(2), QStringLiteral("0.8"));
    auto ufrpe = rl::writeLightingFile(l, rl::LightingLayout::Ufrpe);
    QVERIFY(ufrpe.ok());
    QCOMPARE(qs(*ufrpe).split(QLatin1Char('\n')).at(4), QStringLiteral("0.8 0.8 0.8"));
    auto keys = rl::writeLightingFile(l, rl::LightingLayout::KeyValue);
    QVERIFY(keys.ok());
    QVERIFY(qs(*keys).contains(QStringLiteral("\nKd = 0.8 0.8 0.8\n")));
    // 0 and -0 are not the same bits: three numbers, so that -0 comes back.
    l.material.kd = rl::vec3(0.0f, -0.0f, 0.0f);
    ufpe = rl::writeLightingFile(l, rl::LightingLayout::Ufpe);
    QVERIFY(ufpe.ok());
    QCOMPARE(qs(*ufpe).split(QLatin1Char('\n')).at(3), QStringLiteral("0 -0 0"));
}

void TestCourseWriters::errors() {
    const auto message = [](const auto& result) {
        return result.ok() ? QStringLiteral("(no error)") : qs(result.error().message);
    };
    QCOMPARE(
        message(rl::writeLightingFile(twoLights(), rl::LightingLayout::Ufpe)),
        QStringLiteral("cannot write 2 lights in the layout UFPE (Pl; ka; Ia; kd; Od; ks; "
                       "Il; n), which holds exactly one: choose the UFPE multi-light layout or "
                       "key = value"));
    QCOMPARE(message(rl::writeLightingFile(twoLights(), rl::LightingLayout::Ufrpe)),
             QStringLiteral("cannot write 2 lights in the layout UFRPE (Iamb; Ka; Il; Pl; Kd; "
                            "Od; Ks; n), which holds exactly one: choose the UFPE multi-light "
                            "layout or key = value"));
    rl::CourseLighting nine = oneLight();
    nine.lights.resize(9, nine.lights[0]);
    QCOMPARE(message(rl::writeLightingFile(nine, rl::LightingLayout::KeyValue)),
             QStringLiteral("cannot write 9 lights in a key = value file, which holds 8 at most "
                            "(Pl to Pl8)"));
    rl::CourseLighting none = oneLight();
    none.lights.clear();
    QCOMPARE(message(rl::writeLightingFile(none, rl::LightingLayout::UfpeMulti)),
             QStringLiteral("cannot write lighting without lights: the UFPE multi-light and key "
                            "= value layouts hold one light or more"));
    QCOMPARE(
        message(rl::writeLightingFile(none, rl::LightingLayout::Ufpe)),
        QStringLiteral("cannot write 0 lights in the layout UFPE (Pl; ka; Ia; kd; Od; ks; "
                       "Il; n), which holds exactly one: choose the UFPE multi-light layout or "
                       "key = value"));
    QCOMPARE(message(rl::writeLightingFile(oneLight(), rl::LightingLayout::Auto)),
             QStringLiteral("cannot write lighting in the layout 'auto': choose UFPE, UFPE "
                            "multi-light, UFRPE or key = value"));
    QCOMPARE(message(rl::writeCameraFile(seedCamera(), rl::CameraLayout::Auto)),
             QStringLiteral("cannot write a camera in the layout 'auto': choose UFPE, UFRPE or "
                            "key = value"));
    rl::CourseCamera nan = seedCamera();
    nan.hy = std::numeric_limits<double>::quiet_NaN();
    QCOMPARE(message(rl::writeCameraFile(nan, rl::CameraLayout::Ufpe)),
             QStringLiteral("cannot write the camera: its values must be finite numbers (a "
                            "course file cannot hold nan or inf)"));
    rl::CourseLighting infinite = oneLight();
    infinite.lights[0].intensity.g = std::numeric_limits<float>::infinity();
    QCOMPARE(message(rl::writeLightingFile(infinite, rl::LightingLayout::Ufpe)),
             QStringLiteral("cannot write the lighting: its values must be finite numbers (a "
                            "course file cannot hold nan or inf)"));
    rl::CourseLighting directional = oneLight();
    directional.lights[0].pWorld.w = 0.0;
    QCOMPARE(message(rl::writeLightingFile(directional, rl::LightingLayout::Ufpe)),
             QStringLiteral("cannot write a directional light (w = 0) in the layout UFPE (Pl; ka; "
                            "Ia; kd; Od; ks; Il; n), which holds the course's point lights only: "
                            "choose key = value"));
    rl::CourseLighting spot = twoLights();
    spot.lights[1].spotCutoff = 30.0f;
    QCOMPARE(message(rl::writeLightingFile(spot, rl::LightingLayout::UfpeMulti)),
             QStringLiteral("cannot write a spot light in the layout UFPE multi-light (ka; Ia; kd; "
                            "Od; ks; n; L; L times Pl; Il), which holds the course's point lights "
                            "only: choose key = value"));
    rl::CourseLighting blinn = oneLight();
    blinn.specular = rl::SpecularModel::BlinnPhong;
    QCOMPARE(message(rl::writeLightingFile(blinn, rl::LightingLayout::Ufrpe)),
             QStringLiteral("cannot write Blinn-Phong highlights in the layout UFRPE (Iamb; Ka; "
                            "Il; Pl; Kd; Od; Ks; n), which holds the course's point lights only: "
                            "choose key = value"));
}

// The lecture slides' lighting (seed 003) in a key = value file: three lights (a directional
// one, an attenuated spot, a plain point), emission, one-sided, Blinn-Phong, written in the
// course's order and then the slides' keys, and read back the same bit for bit.
void TestCourseWriters::slidesLightingRoundTrip() {
    rl::CourseLighting l = twoLights();
    l.material.emission = rl::vec3(12.5f, 0.0f, 3.0f);
    l.twoSided = false;
    l.specular = rl::SpecularModel::BlinnPhong;
    l.lights[0].pWorld = rl::dvec4(1.0, 2.0, -0.5, 0.0);
    l.lights[1].attenuation = rl::vec3(1.0f, 0.01f, 0.0001f);
    l.lights[1].spotDirection = rl::dvec3(0.0, -1.0, 0.25);
    l.lights[1].spotCutoff = 22.5f;
    l.lights[1].spotExponent = 8.0f;
    rl::Light third;
    third.pWorld = rl::dvec4(0.0, 0.0, 10.0, 1.0);
    third.intensity = rl::vec3(10.0f);
    l.lights.push_back(third);
    const auto text = rl::writeLightingFile(l, rl::LightingLayout::KeyValue);
    QVERIFY2(text.ok(), text.ok() ? "" : text.error().toString().c_str());
    QCOMPARE(QByteArray::fromStdString(*text),
             QByteArray("Iamb = 10 20 30\nKa = 0.25\nIl = 40 50 60\nPl = 1 2 -0.5 0\n"
                        "Kd = 0.5 0.625 0.75\nOd = 0.125 0.25 0.375\nKs = 0.5\neta = 8\n"
                        "Ke = 12.5 0 3\ntwo_sided = 0\nblinn = 1\nIl2 = 0 128 255\n"
                        "Pl2 = 820 -150 -200\natten2 = 1 0.01 1e-04\nspot_dir2 = 0 -1 0.25\n"
                        "spot_cutoff2 = 22.5\nspot_exp2 = 8\nIl3 = 10 10 10\nPl3 = 0 0 10\n"));
    rl::Diagnostics diagnostics;
    const auto back = rl::readLightingFile(*text, "slides.txt", diagnostics);
    QVERIFY2(back.ok(), back.ok() ? "" : back.error().toString().c_str());
    QCOMPARE(back->lights.size(), std::size_t(3));
    QCOMPARE(back->material.emission, l.material.emission);
    QCOMPARE(back->twoSided, false);
    QCOMPARE(back->specular, rl::SpecularModel::BlinnPhong);
    for (std::size_t k = 0; k < 3; ++k) {
        QCOMPARE(back->lights[k].pWorld, l.lights[k].pWorld);
        QCOMPARE(back->lights[k].intensity, l.lights[k].intensity);
        QCOMPARE(back->lights[k].attenuation, l.lights[k].attenuation);
        QCOMPARE(back->lights[k].spotDirection, l.lights[k].spotDirection);
        QCOMPARE(back->lights[k].spotCutoff, l.lights[k].spotCutoff);
        QCOMPARE(back->lights[k].spotExponent, l.lights[k].spotExponent);
    }
    // Saving it again after the third light and the spot are removed drops their lines.
    rl::CourseLighting fewer = l;
    fewer.lights.pop_back();
    fewer.lights[1].spotCutoff = 180.0f;
    fewer.lights[1].spotExponent = 0.0f;
    const auto again = rl::writeLightingFile(fewer, rl::LightingLayout::KeyValue, *text);
    QVERIFY(again.ok());
    QVERIFY(!qs(*again).contains(QStringLiteral("Pl3")));
    QVERIFY(!qs(*again).contains(QStringLiteral("spot")));
    QVERIFY(qs(*again).contains(QStringLiteral("atten2 = 1 0.01 1e-04\n")));
}

// One key = value file holds both parts (the readers skip each other's keys): writing the
// camera replaces only the camera's lines where they stand and adds the missing ones.
void TestCourseWriters::sharedKeyValueFileKeepsTheOtherPart() {
    const std::string previous =
        "Iamb = 1 2 3\nU = 1 0 0\nC = 9 9 9\nKa = 0.5\n\nhx = 7\nIl = 4 5 6\nPl = 7 8 9\n"
        "Kd = 0.1 0.2 0.3\nOd = 1 1 1\nKs = 0.25\neta = 3\nC = 8 8 8\n";
    const auto camera = rl::writeCameraFile(seedCamera(), rl::CameraLayout::KeyValue, previous);
    QVERIFY(camera.ok());
    QCOMPARE(qs(*camera),
             QStringLiteral("Iamb = 1 2 3\nU = 1 0 0\nC = -200 -50 300\nKa = 0.5\n\nhx = 0.5\n"
                            "Il = 4 5 6\nPl = 7 8 9\nKd = 0.1 0.2 0.3\nOd = 1 1 1\nKs = 0.25\n"
                            "eta = 3\nN = 0.667 0.172 -1\nV = 0 3 0\nd = 65\nhy = 0.6\n"));
    rl::Diagnostics diagnostics;
    const auto lighting = rl::readLightingFile(*camera, "shared", diagnostics);
    QVERIFY(lighting.ok());
    QCOMPARE(lighting->material.ka, 0.5f);
    QCOMPARE(lighting->lights.at(0).pWorld, rl::dvec4(7, 8, 9, 1));
    const auto cameraBack = rl::readCameraFile(*camera, "shared", diagnostics);
    QVERIFY(cameraBack.ok());
    const QString context;
    RL_SAME(cameraDiff(*cameraBack, seedCamera()));

    // And the lighting into the same file keeps the camera's lines.
    const auto both = rl::writeLightingFile(oneLight(), rl::LightingLayout::KeyValue, *camera);
    QVERIFY(both.ok());
    QCOMPARE(qs(*both),
             QStringLiteral("Iamb = 10 20 30\nU = 1 0 0\nC = -200 -50 300\nKa = 0.25\n\nhx = "
                            "0.5\nIl = 40 50 60\nPl = -220 -150 700\nKd = 0.5 0.625 0.75\nOd = "
                            "0.125 0.25 0.375\nKs = 0.5\neta = 8\nN = 0.667 0.172 -1\nV = 0 3 "
                            "0\nd = 65\nhy = 0.6\n"));
}

// The UFPE samples end their lines in CRLF: a file written over one keeps it.
void TestCourseWriters::lineEndingKept() {
    const auto ufpe = rl::writeCameraFile(seedCamera(), rl::CameraLayout::Ufpe, "1 2 3\r\n");
    QVERIFY(ufpe.ok());
    QCOMPARE(qs(*ufpe),
             QStringLiteral("-200 -50 300\r\n0.667 0.172 -1\r\n0 3 0\r\n65 0.5 0.6\r\n"));
    const auto keys =
        rl::writeLightingFile(oneLight(), rl::LightingLayout::KeyValue, "Ka = 1\r\nKs = 1");
    QVERIFY(keys.ok());
    QVERIFY(qs(*keys).startsWith(QStringLiteral("Ka = 0.25\r\nKs = 0.5\r\nIamb = 10 20 30\r\n")));
    QCOMPARE(qs(*keys).count(QStringLiteral("\r\n")), 8);
    QCOMPARE(qs(*keys).count(QLatin1Char('\n')), 8);
}

void TestCourseWriters::cameraRoundTrip_data() {
    QTest::addColumn<QString>("file");  // a sample, or "" for the awkward values
    QTest::addColumn<rl::CameraLayout>("layout");
    for (const char* file : {"ufpe/calice2.cfg", "ufpe/vaso.cfg", "ufrpe/camera_1.txt",
                             "seed-example/camera.cfg", ""}) {
        for (rl::CameraLayout layout : rl::kCameraLayouts) {
            if (layout == rl::CameraLayout::Auto) continue;
            QTest::addRow("%s %s", *file ? file : "awkward values", rl::cameraLayoutName(layout))
                << QString::fromLatin1(file) << layout;
        }
    }
}

void TestCourseWriters::cameraRoundTrip() {
    QFETCH(QString, file);
    QFETCH(rl::CameraLayout, layout);
    rl::CourseCamera camera = awkwardCamera();
    rl::Diagnostics diagnostics;
    if (!file.isEmpty()) {
        if (testing::samplesDir().isEmpty()) QSKIP("the course samples are absent");
        const QByteArray bytes = testing::readFile(sample(file));
        QVERIFY(!bytes.isEmpty());
        auto read = rl::readCameraFile(viewOf(bytes), file.toStdString(), diagnostics);
        QVERIFY(read.ok());
        camera = *read;
    }
    const auto text = rl::writeCameraFile(camera, layout);
    QVERIFY(text.ok());
    QCOMPARE(rl::detectCameraLayout(*text), std::optional(layout));
    const auto back = rl::readCameraFile(*text, "written", diagnostics, layout);
    QVERIFY2(back.ok(), back.ok() ? "" : back.error().toString().c_str());
    const QString context = qs(*text) + QStringLiteral("\n");
    RL_SAME(cameraDiff(*back, camera));
}

void TestCourseWriters::lightingRoundTrip_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<rl::LightingLayout>("layout");
    for (const char* file : {"ufpe/iluminacao.txt", "ufpe/multi_iluminacao.txt", "ufrpe/basic.lux",
                             "seed-example/iluminacao.txt", "", "one"}) {
        for (rl::LightingLayout layout : rl::kLightingLayouts) {
            if (layout == rl::LightingLayout::Auto) continue;
            const bool severalLights =
                std::string_view(file) == "ufpe/multi_iluminacao.txt" || !*file;
            if (severalLights && layout != rl::LightingLayout::UfpeMulti) continue;
            const char* label = !*file                            ? "awkward values, two lights"
                                : std::string_view(file) == "one" ? "awkward values, one light"
                                                                  : file;
            QTest::addRow("%s %s", label, rl::lightingLayoutName(layout))
                << QString::fromLatin1(file) << layout;
        }
    }
}

void TestCourseWriters::lightingRoundTrip() {
    QFETCH(QString, file);
    QFETCH(rl::LightingLayout, layout);
    rl::CourseLighting lighting = awkwardLighting();
    rl::Diagnostics diagnostics;
    if (file == QStringLiteral("one")) {  // the awkward values with one light
        lighting.lights.resize(1);
    } else if (!file.isEmpty()) {
        if (testing::samplesDir().isEmpty()) QSKIP("the course samples are absent");
        const QByteArray bytes = testing::readFile(sample(file));
        QVERIFY(!bytes.isEmpty());
        auto read = rl::readLightingFile(viewOf(bytes), file.toStdString(), diagnostics);
        QVERIFY(read.ok());
        lighting = *read;
    }
    const auto text = rl::writeLightingFile(lighting, layout);
    QVERIFY2(text.ok(), text.ok() ? "" : text.error().toString().c_str());
    QCOMPARE(rl::detectLightingLayout(*text), std::optional(layout));
    const auto back = rl::readLightingFile(*text, "written", diagnostics, layout);
    QVERIFY2(back.ok(), back.ok() ? "" : back.error().toString().c_str());
    const QString context = qs(*text) + QStringLiteral("\n");
    RL_SAME(lightingDiff(*back, lighting));
}

QTEST_APPLESS_MAIN(TestCourseWriters)
#include "tst_course_writers.moc"
