// Scenes made from the program's own files, for the suites that link rasterlab_core: the
// default course scene (the trefoil), the course's chalice and the HW2 sample command files
// as data rows.
#pragma once

#include <QtTest>

#include <initializer_list>
#include <memory>
#include <optional>

#include "app/documents/command_file.h"
#include "app/documents/default_scene_resource.h"
#include "pipeline/io/course_scene.h"
#include "tests/test_support.h"

namespace testing {

// The default course scene's camera, lighting and object (the trefoil).
inline rl::CourseSceneParts defaultCourseParts() {
    rl::Diagnostics diagnostics;
    auto parts = rasterlab::loadDefaultCourseScene(diagnostics);
    if (!parts) qFatal("%s", parts.error().toString().c_str());
    return parts.value();
}

// The default course scene with the given shading, rules and image size.
inline std::shared_ptr<const rl::Scene> defaultCourseScene(rl::ShadingModel model,
                                                           rl::RuleSet rules, int width,
                                                           int height) {
    rl::CourseSceneSettings settings;
    settings.shading = model;
    settings.rules = rl::rulesOf(rules);
    settings.width = width;
    settings.height = height;
    return std::make_shared<const rl::Scene>(rl::makeCourseScene(defaultCourseParts(), settings));
}

// The course's chalice: samples/course/ufpe/calice2.cfg, iluminacao.txt and calice2.byu; none
// where the samples are absent.
inline std::optional<rl::CourseSceneParts> calice2Parts() {
    const QString dir = samplesDir();
    if (dir.isEmpty()) return std::nullopt;
    rl::Diagnostics diagnostics;
    const QString ufpe = dir + QStringLiteral("/course/ufpe/");
    auto c = rasterlab::loadCamera(ufpe + QStringLiteral("calice2.cfg"), diagnostics);
    auto l = rasterlab::loadLighting(ufpe + QStringLiteral("iluminacao.txt"), diagnostics);
    auto o = rasterlab::loadObject(ufpe + QStringLiteral("calice2.byu"), diagnostics);
    if (!c || !l || !o) qFatal("cannot load calice2");
    return rl::CourseSceneParts{c.value(), l.value(), o.value()};
}

// The chalice at the default size and shading; null where the samples are absent.
inline std::shared_ptr<const rl::Scene> calice2Scene() {
    const std::optional<rl::CourseSceneParts> parts = calice2Parts();
    if (!parts) return nullptr;
    return std::make_shared<const rl::Scene>(
        rl::makeCourseScene(*parts, rl::CourseSceneSettings{}));
}

// A data row per HW2 sample named (samples/hw2/<name>.txt), holding its first image's scene
// in a std::shared_ptr<const rl::Scene> column; none where the samples are absent.
inline void addHw2Rows(std::initializer_list<const char*> names) {
    const QString dir = samplesDir();
    if (dir.isEmpty()) return;
    for (const char* name : names) {
        rl::Diagnostics diagnostics;
        auto hw2 = rasterlab::loadCommandFile(
            dir + QStringLiteral("/hw2/") + QLatin1String(name) + QStringLiteral(".txt"),
            diagnostics);
        QVERIFY2(hw2, name);
        QTest::newRow(name) << std::make_shared<const rl::Scene>(hw2->images.at(0).scene);
    }
}

}  // namespace testing
