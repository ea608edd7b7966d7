// The edit panel and the document's editing: a spin box changes the document's scene, one
// field's quick changes merge into one undo step (not across a pause, another field, or back
// to where they started), undo and redo of two fields restore the values in the document and
// in the panel, Ctrl+Z in a spin box undoes the panel's step, kd linked or per channel, a
// second light chosen and restored by undo; Save writes each part in its own layout (the
// UFPE samples' CRLF kept, a key = value file's other lines kept), reads back to the edited
// values and clears the modified flag; a failing save leaves the old file whole and shows the
// error; the built-in scene asks for a path; maybeSave asks only when something changed;
// opening a file clears the history. Screenshots of the panel: /tmp/edit_panel_*.png.
#include <QtTest>

#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QToolButton>
#include <QUndoStack>

#include <sys/resource.h>
#include <unistd.h>
#include <csignal>
#include <functional>

#include "app/documents/scene_document.h"
#include "app/window/edit_panel.h"
#include "pipeline/io/course_readers.h"
#include "tests/test_support.h"

using rasterlab::EditPanel;
using rasterlab::SceneDocument;
using Field = SceneDocument::Field;
using Part = SceneDocument::Part;

namespace {

QString sample(const QString& relative) {
    return testing::samplesDir() + QStringLiteral("/course/") + relative;
}

// A writable copy of a sample in `dir` (the samples are read-only).
QString copySample(const QTemporaryDir& dir, const QString& relative) {
    const QByteArray bytes = testing::readFile(sample(relative));
    const QString path = dir.filePath(QFileInfo(relative).fileName());
    QFile file(path);
    if (bytes.isEmpty() || !file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size())
        return {};
    return path;
}

QByteArray contentOf(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// Runs `action` while answering the first modal dialog it opens with `button` (or closing
// it): returns what the dialog said ("objectName: text / informative text"), or "" when none
// opened.
QString answeringDialogs(const std::function<void()>& action,
                         QMessageBox::StandardButton button = QMessageBox::NoButton) {
    QString seen;
    QTimer timer;
    timer.setInterval(20);
    QObject::connect(&timer, &QTimer::timeout, [&] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box) return;
        seen = box->objectName() + QStringLiteral(": ") + box->text() + QStringLiteral(" / ") +
               box->informativeText();
        if (button != QMessageBox::NoButton && box->button(button))
            box->button(button)->click();
        else
            box->reject();
    });
    timer.start();
    action();
    return seen;
}

// The document of the tests: the default scene's object with calice2's camera and the
// UFPE lighting, copied into `dir`.
struct Fixture {
    QTemporaryDir dir;
    SceneDocument document;
    QString cameraPath;
    QString lightingPath;

    bool load(const QString& camera = QStringLiteral("ufpe/calice2.cfg"),
              const QString& lighting = QStringLiteral("ufpe/iluminacao.txt")) {
        if (!dir.isValid() || !document.loadDefault()) return false;
        cameraPath = copySample(dir, camera);
        lightingPath = copySample(dir, lighting);
        return !cameraPath.isEmpty() && !lightingPath.isEmpty() &&
               document.open(Part::Camera, cameraPath) &&
               document.open(Part::Lighting, lightingPath);
    }
};

#define REQUIRE_SAMPLES() \
    if (testing::samplesDir().isEmpty()) QSKIP("the course samples are absent")

#define LOAD(fixture, ...) QVERIFY2((fixture).load(__VA_ARGS__), "the samples did not load")

}  // namespace

class TestEditPanel : public QObject {
    Q_OBJECT
private slots:
    void spinBoxChangesTheScene();
    void typedNumberIsOneStep();
    void changesOfOneFieldMerge();
    void pauseSplitsSteps();
    void backToTheStartIsNoStep();
    void undoRedoTwoFields();
    void undoShortcutInASpinBox();
    void kdLinkedOrPerChannel();
    void secondLight();
    void slidesLighting();
    void shadingIsUndoable();
    void layoutsRemembered();
    void saveWritesTheFileInItsLayout();
    void saveKeyValueKeepsOtherLines();
    void failedSaveLeavesTheOldFile();
    void saveInReadOnlyFolderFails();
    void degenerateCameraIsNotSaved();
    void builtInSceneNeedsAPath();
    void saveAsDialogChoosesTheLayout();
    void maybeSave();
    void openingAFileClearsTheHistory();
    void commandFileDisablesThePanel();
    void screenshots();
};

void TestEditPanel::spinBoxChangesTheScene() {
    REQUIRE_SAMPLES();
    Fixture f;
    LOAD(f);
    EditPanel panel(&f.document);
    QCOMPARE(panel.objectName(), QStringLiteral("editPanel"));
    QCOMPARE(panel.spinBox(Field::C, 0)->objectName(), QStringLiteral("edit_C_x"));
    QCOMPARE(panel.spinBox(Field::Kd, 2)->objectName(), QStringLiteral("edit_kd_b"));
    QCOMPARE(panel.spinBox(Field::Shininess)->objectName(), QStringLiteral("edit_n"));
    QVERIFY(panel.spinBox(Field::C, 0)->keyboardTracking());
    QSignalSpy edited(&panel, &EditPanel::sceneEdited);
    QSignalSpy modified(&panel, &EditPanel::modifiedChanged);
    // calice2: C = (50, -50, 600), N = (0, 0, -1), V = (1, -100, 10), d = hx = hy = 1.
    QCOMPARE(panel.spinBox(Field::C, 0)->value(), 50.0);
    QCOMPARE(panel.spinBox(Field::V, 1)->value(), -100.0);
    QCOMPARE(panel.spinBox(Field::LightIntensity, 2)->value(), 255.0);
    QVERIFY(!panel.isModified());
    QVERIFY(!panel.saveAction()->isEnabled());

    panel.spinBox(Field::C, 0)->setValue(75.0);
    QCOMPARE(f.document.parts().camera.c, rl::dvec3(75, -50, 600));
    QCOMPARE(f.document.scene()->camera->c, rl::dvec3(75, -50, 600));
    QCOMPARE(edited.count(), 1);
    QCOMPARE(modified.count(), 1);
    QCOMPARE(modified.at(0).at(0).toBool(), true);
    QVERIFY(f.document.isModified(Part::Camera));
    QVERIFY(!f.document.isModified(Part::Lighting));
    QVERIFY(panel.saveAction()->isEnabled());

    // The lighting: Il.g of the one light, then Od.b (floats in the document).
    panel.spinBox(Field::LightIntensity, 1)->setValue(128.0);
    panel.spinBox(Field::Od, 2)->setValue(0.3);
    const auto scene = f.document.scene();
    QCOMPARE(scene->lights.at(0).intensity, rl::vec3(255, 128, 255));
    QCOMPARE(scene->draws.at(0).material.od, rl::vec3(0.0f, 0.8f, 0.3f));
    QVERIFY(f.document.isModified(Part::Lighting));
    QCOMPARE(edited.count(), 3);
    QCOMPARE(modified.count(), 1);  // still modified: no second signal
    QCOMPARE(panel.undoStack()->count(), 3);
    QCOMPARE(panel.undoStack()->undoText(), QStringLiteral("Change Od.b"));
}

// Typing "2.5" over d is one step, whatever values pass on the way.
void TestEditPanel::typedNumberIsOneStep() {
    REQUIRE_SAMPLES();
    Fixture f;
    LOAD(f);
    EditPanel panel(&f.document);
    panel.show();
    QDoubleSpinBox* d = panel.spinBox(Field::D);
    d->setFocus();
    d->selectAll();
    QTest::keyClicks(d, QStringLiteral("2.5"));
    QCOMPARE(f.document.parts().camera.d, 2.5);
    QCOMPARE(panel.undoStack()->count(), 1);
    QCOMPARE(panel.undoStack()->undoText(), QStringLiteral("Change d"));
    panel.undoStack()->undo();
    QCOMPARE(f.document.parts().camera.d, 1.0);
    QCOMPARE(d->value(), 1.0);

    // The window refreshes the panel after each change: the text being typed stays as typed
    // ("2.0" on the way to "2.05" is not rewritten to "2").
    connect(&panel, &EditPanel::sceneEdited, &panel, &EditPanel::refresh);
    d->selectAll();
    QTest::keyClicks(d, QStringLiteral("2.05"));
    QCOMPARE(f.document.parts().camera.d, 2.05);
    QTest::keyClick(d, Qt::Key_Backspace);
    QCOMPARE(f.document.parts().camera.d, 2.0);
    QTest::keyClick(d, Qt::Key_1);
    QCOMPARE(f.document.parts().camera.d, 2.01);
}

void TestEditPanel::changesOfOneFieldMerge() {
    REQUIRE_SAMPLES();
    Fixture f;
    LOAD(f);
    EditPanel panel(&f.document);
    panel.show();
    QSignalSpy edited(&panel, &EditPanel::sceneEdited);
    QDoubleSpinBox* nx = panel.spinBox(Field::N, 0);
    for (double v : {0.1, 0.2, 0.3, 0.4}) nx->setValue(v);
    QCOMPARE(f.document.parts().camera.n, rl::dvec3(0.4, 0, -1));
    QCOMPARE(panel.undoStack()->count(), 1);
    QCOMPARE(edited.count(), 4);  // each value renders

    // A held arrow: C.x goes up by its step (10) five times, one more step.
    QDoubleSpinBox* cx = panel.spinBox(Field::C, 0);
    cx->setFocus();
    for (int i = 0; i < 5; ++i) QTest::keyClick(cx, Qt::Key_Up);
    QCOMPARE(f.document.parts().camera.c.x, 100.0);
    QCOMPARE(panel.undoStack()->count(), 2);

    panel.undoStack()->undo();
    QCOMPARE(f.document.parts().camera.c.x, 50.0);
    QCOMPARE(cx->value(), 50.0);
    panel.undoStack()->undo();
    QCOMPARE(f.document.parts().camera.n, rl::dvec3(0, 0, -1));
    QCOMPARE(nx->value(), 0.0);
    QVERIFY(!f.document.isModified());  // back to the file's values
    QVERIFY(!panel.saveAction()->isEnabled());
    panel.undoStack()->redo();
    QCOMPARE(f.document.parts().camera.n.x, 0.4);
    QCOMPARE(nx->value(), 0.4);
}

void TestEditPanel::pauseSplitsSteps() {
    REQUIRE_SAMPLES();
    Fixture f;
    LOAD(f);
    EditPanel panel(&f.document);
    QCOMPARE(panel.mergeInterval(), 1000);
    panel.setMergeInterval(50);
    QDoubleSpinBox* ks = panel.spinBox(Field::Ks);
    ks->setValue(0.6);
    ks->setValue(0.7);
    QTest::qWait(150);
    ks->setValue(0.8);
    QCOMPARE(panel.undoStack()->count(), 2);
    panel.undoStack()->undo();
    QCOMPARE(f.document.parts().lighting.material.ks, 0.7f);
    // After an undo, a change of the same field within the interval is a new step.
    panel.setMergeInterval(100000);
    ks->setValue(0.9);
    ks->setValue(0.95);
    QCOMPARE(panel.undoStack()->count(), 2);
    QCOMPARE(panel.undoStack()->index(), 2);
    panel.undoStack()->undo();
    QCOMPARE(f.document.parts().lighting.material.ks, 0.7f);
}

// Changes that come back to the value they started from leave no step.
void TestEditPanel::backToTheStartIsNoStep() {
    REQUIRE_SAMPLES();
    Fixture f;
    LOAD(f);
    EditPanel panel(&f.document);
    QDoubleSpinBox* n = panel.spinBox(Field::Shininess);
    QCOMPARE(n->value(), 2.0);
    n->setValue(3.0);
    n->setValue(2.0);
    QCOMPARE(panel.undoStack()->count(), 0);
    QVERIFY(!panel.isModified());
}

void TestEditPanel::undoRedoTwoFields() {
    REQUIRE_SAMPLES();
    Fixture f;
    LOAD(f);
    EditPanel panel(&f.document);
    QSignalSpy edited(&panel, &EditPanel::sceneEdited);
    QSignalSpy modified(&panel, &EditPanel::modifiedChanged);
    panel.spinBox(Field::C, 1)->setValue(-80.0);
    panel.spinBox(Field::Ka)->setValue(0.25);
    QCOMPARE(panel.undoStack()->count(), 2);
    QCOMPARE(panel.undoAction()->text(), QStringLiteral("&Undo Change ka"));

    panel.undoAction()->trigger();
    QCOMPARE(f.document.parts().lighting.material.ka, 1.0f);
    QCOMPARE(panel.spinBox(Field::Ka)->value(), 1.0);
    QCOMPARE(f.document.parts().camera.c.y, -80.0);
    QCOMPARE(panel.spinBox(Field::C, 1)->value(), -80.0);
    QVERIFY(!f.document.isModified(Part::Lighting));
    QVERIFY(f.document.isModified(Part::Camera));

    panel.undoAction()->trigger();
    QCOMPARE(f.document.parts().camera.c.y, -50.0);
    QCOMPARE(panel.spinBox(Field::C, 1)->value(), -50.0);
    QVERIFY(!panel.isModified());
    QVERIFY(!panel.undoAction()->isEnabled());

    panel.redoAction()->trigger();
    panel.redoAction()->trigger();
    QCOMPARE(f.document.parts().camera.c.y, -80.0);
    QCOMPARE(f.document.parts().lighting.material.ka, 0.25f);
    QCOMPARE(panel.spinBox(Field::Ka)->value(), 0.25);
    QCOMPARE(edited.count(), 6);  // two edits, two undos, two redos
    // modified: true (edit), false (second undo), true (redo)
    QCOMPARE(modified.count(), 3);
    QCOMPARE(modified.at(1).at(0).toBool(), false);
    QCOMPARE(panel.undoAction()->shortcut(), QKeySequence(QKeySequence::Undo));
    QCOMPARE(panel.redoAction()->shortcuts(), QKeySequence::keyBindings(QKeySequence::Redo));
    QCOMPARE(panel.saveAction()->shortcut(), QKeySequence(QKeySequence::Save));
}

// Ctrl+Z typed in a spin box undoes the panel's step, not the line edit's text.
void TestEditPanel::undoShortcutInASpinBox() {
    REQUIRE_SAMPLES();
    Fixture f;
    LOAD(f);
    EditPanel panel(&f.document);
    panel.show();
    QApplication::setActiveWindow(&panel);
    QVERIFY(QTest::qWaitForWindowActive(&panel));
    panel.spinBox(Field::Hy)->setValue(3.0);
    QDoubleSpinBox* hx = panel.spinBox(Field::Hx);
    hx->setFocus();
    hx->selectAll();
    QTest::keyClicks(hx, QStringLiteral("4"));
    QCOMPARE(f.document.parts().camera.hx, 4.0);
    QCOMPARE(panel.undoStack()->count(), 2);
    QTest::keyClick(hx, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(f.document.parts().camera.hx, 1.0);
    QCOMPARE(hx->value(), 1.0);
    QCOMPARE(panel.undoStack()->index(), 1);
    QTest::keyClick(hx, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(f.document.parts().camera.hy, 1.0);
    QCOMPARE(panel.undoStack()->index(), 0);
}

void TestEditPanel::kdLinkedOrPerChannel() {
    REQUIRE_SAMPLES();
    Fixture f;
    LOAD(f);
    EditPanel panel(&f.document);
    QVERIFY(panel.kdLinkButton()->isChecked());  // iluminacao.txt: kd = 1, one number
    panel.spinBox(Field::Kd, 0)->setValue(0.5);
    QCOMPARE(f.document.parts().lighting.material.kd, rl::vec3(0.5f));
    QCOMPARE(panel.spinBox(Field::Kd, 2)->value(), 0.5);
    QCOMPARE(panel.undoStack()->undoText(), QStringLiteral("Change kd"));
    panel.kdLinkButton()->setChecked(false);
    panel.spinBox(Field::Kd, 1)->setValue(0.25);
    QCOMPARE(f.document.parts().lighting.material.kd, rl::vec3(0.5f, 0.25f, 0.5f));
    QCOMPARE(panel.undoStack()->undoText(), QStringLiteral("Change kd.g"));
    panel.undoStack()->undo();
    panel.undoStack()->undo();
    QCOMPARE(f.document.parts().lighting.material.kd, rl::vec3(1.0f));
    QCOMPARE(panel.spinBox(Field::Kd, 0)->value(), 1.0);
    QCOMPARE(panel.spinBox(Field::Kd, 1)->value(), 1.0);

    // basic.lux has a Kd per channel: not linked.
    Fixture g;
    LOAD(g, QStringLiteral("ufpe/calice2.cfg"), QStringLiteral("ufrpe/basic.lux"));
    EditPanel other(&g.document);
    QVERIFY(!other.kdLinkButton()->isChecked());
    QCOMPARE(other.spinBox(Field::Kd, 1)->value(), 0.3);
}

void TestEditPanel::secondLight() {
    REQUIRE_SAMPLES();
    Fixture f;
    LOAD(f, QStringLiteral("ufpe/calice2.cfg"), QStringLiteral("ufpe/multi_iluminacao.txt"));
    EditPanel panel(&f.document);
    panel.show();
    QVERIFY(panel.lightSelector()->isVisible());
    QCOMPARE(panel.lightSelector()->count(), 2);
    QCOMPARE(panel.spinBox(Field::LightPosition, 0)->value(), -220.0);
    panel.setCurrentLight(1);
    QCOMPARE(panel.spinBox(Field::LightPosition, 0)->value(), 820.0);
    QCOMPARE(panel.spinBox(Field::LightIntensity, 2)->value(), 255.0);
    panel.spinBox(Field::LightPosition, 2)->setValue(-100.0);
    const auto& lights = f.document.parts().lighting.lights;
    QCOMPARE(lights.at(1).pWorld, rl::dvec4(820, -150, -100, 1));
    QCOMPARE(lights.at(0).pWorld, rl::dvec4(-220, -150, 700, 1));
    QCOMPARE(panel.undoStack()->undoText(), QStringLiteral("Change Pl.z of light 2"));
    // Undone while light 1 is shown: the panel shows light 2 again, restored.
    panel.setCurrentLight(0);
    panel.undoStack()->undo();
    QCOMPARE(panel.currentLight(), std::size_t(1));
    QCOMPARE(panel.spinBox(Field::LightPosition, 2)->value(), -200.0);
    QCOMPARE(lights.at(1).pWorld, rl::dvec4(820, -150, -200, 1));

    // One light: the selector stays (with Add beside it), Remove is off.
    Fixture g;
    LOAD(g);
    EditPanel single(&g.document);
    single.show();
    QCOMPARE(single.lightSelector()->currentText(), QStringLiteral("Light 1 of 1"));
    QVERIFY(single.addLightButton()->isEnabled());
    QVERIFY(!single.removeLightButton()->isEnabled());
}

// The lecture slides' lighting in the panel: a light added (a copy) and removed, each one
// undo step; directional, spot, attenuation, emission, one-sided, Blinn-Phong set, each
// undoable, in the scene; the UFPE file cannot hold them (a clear message, the file kept),
// key = value can, and reads back the same.
void TestEditPanel::slidesLighting() {
    REQUIRE_SAMPLES();
    Fixture f;
    LOAD(f);
    EditPanel panel(&f.document);
    QSignalSpy edited(&panel, &EditPanel::sceneEdited);
    const auto& lights = f.document.parts().lighting.lights;
    QCOMPARE(lights.size(), std::size_t(1));
    panel.addLightButton()->click();
    QCOMPARE(lights.size(), std::size_t(2));
    QCOMPARE(lights.at(1).pWorld, lights.at(0).pWorld);
    QCOMPARE(panel.currentLight(), std::size_t(1));
    QCOMPARE(panel.lightSelector()->currentText(), QStringLiteral("Light 2 of 2"));
    QCOMPARE(panel.undoStack()->undoText(), QStringLiteral("Add light 2"));
    QCOMPARE(f.document.scene()->lights.size(), std::size_t(2));
    QVERIFY(panel.removeLightButton()->isEnabled());

    // Light 2 becomes a directional light toward +z; light 1 an attenuated spot.
    panel.spinBox(Field::LightPosition, 0)->setValue(0.0);
    panel.spinBox(Field::LightPosition, 1)->setValue(0.0);
    panel.spinBox(Field::LightPosition, 2)->setValue(1.0);
    panel.checkBox(Field::LightDirectional)->setChecked(true);
    QCOMPARE(lights.at(1).pWorld, rl::dvec4(0.0, 0.0, 1.0, 0.0));
    QVERIFY(!panel.spinBox(Field::LightAttenuation, 0)->isEnabled());  // not attenuated
    panel.setCurrentLight(0);
    QVERIFY(panel.spinBox(Field::LightAttenuation, 0)->isEnabled());
    QVERIFY(!panel.spinBox(Field::LightSpotCutoff)->isEnabled());  // no spot yet
    panel.checkBox(Field::LightSpotCutoff)->setChecked(true);
    QCOMPARE(lights.at(0).spotCutoff, 30.0f);
    QVERIFY(panel.spinBox(Field::LightSpotCutoff)->isEnabled());
    panel.spinBox(Field::LightSpotCutoff)->setValue(20.0);
    panel.spinBox(Field::LightSpotExponent)->setValue(4.0);
    panel.spinBox(Field::LightSpotDirection, 2)->setValue(-1.0);
    panel.spinBox(Field::LightAttenuation, 1)->setValue(0.01);
    panel.spinBox(Field::Emission, 0)->setValue(10.0);
    panel.checkBox(Field::TwoSided)->setChecked(false);
    panel.checkBox(Field::BlinnPhong)->setChecked(true);
    QCOMPARE(panel.undoStack()->undoText(), QStringLiteral("Change the highlight's model"));
    const auto scene = f.document.scene();
    QCOMPARE(scene->lights.at(0).spotCutoff, 20.0f);
    QCOMPARE(scene->lights.at(0).spotExponent, 4.0f);
    QCOMPARE(scene->lights.at(0).spotDirection.z, -1.0);
    QCOMPARE(scene->lights.at(0).attenuation, rl::vec3(1.0f, 0.01f, 0.0f));
    QCOMPARE(scene->draws.at(0).material.emission, rl::vec3(10.0f, 0.0f, 0.0f));
    QCOMPARE(scene->draws.at(0).specular, rl::SpecularModel::BlinnPhong);
    QVERIFY(!scene->conventions.flipNormalsTowardViewer);

    // The UFPE file holds none of it: Save says so and leaves the file.
    const QByteArray before = contentOf(f.lightingPath);
    const QString said = answeringDialogs([&] { QVERIFY(!panel.save(Part::Lighting, &panel)); });
    QCOMPARE(said, QStringLiteral("saveErrorBox: The lighting was not saved. / ") + f.lightingPath +
                       QStringLiteral(": cannot write 2 lights in the layout UFPE (Pl; ka; Ia; "
                                      "kd; Od; ks; Il; n), which holds exactly one: choose the "
                                      "UFPE multi-light layout or key = value"));
    QCOMPARE(contentOf(f.lightingPath), before);
    // In key = value it is all kept.
    const QString keyValue = f.dir.filePath(QStringLiteral("slides.txt"));
    QVERIFY(f.document.saveLightingAs(keyValue, rl::LightingLayout::KeyValue));
    SceneDocument again;
    QVERIFY(again.loadDefault());
    QVERIFY(again.open(Part::Lighting, keyValue));
    const rl::CourseLighting& back = again.parts().lighting;
    QCOMPARE(back.lights.size(), std::size_t(2));
    QCOMPARE(back.lights.at(0).spotCutoff, 20.0f);
    QCOMPARE(back.lights.at(1).pWorld, rl::dvec4(0.0, 0.0, 1.0, 0.0));
    QCOMPARE(back.material.emission, rl::vec3(10.0f, 0.0f, 0.0f));
    QVERIFY(!back.twoSided);
    QCOMPARE(back.specular, rl::SpecularModel::BlinnPhong);

    // Undo all of it, step by step, back to the one light of the file.
    while (panel.undoStack()->canUndo()) panel.undoStack()->undo();
    QCOMPARE(lights.size(), std::size_t(1));
    QVERIFY(!lights.at(0).spot());
    QCOMPARE(f.document.parts().lighting.material.emission, rl::vec3(0.0f));
    QVERIFY(f.document.parts().lighting.twoSided);
    QVERIFY(!panel.checkBox(Field::BlinnPhong)->isChecked());
    QVERIFY(!panel.removeLightButton()->isEnabled());
    QVERIFY(edited.count() >= 12);
}

void TestEditPanel::shadingIsUndoable() {
    REQUIRE_SAMPLES();
    Fixture f;
    LOAD(f);
    EditPanel panel(&f.document);
    QSignalSpy edited(&panel, &EditPanel::sceneEdited);
    QCOMPARE(panel.shadingBox()->currentText(), QStringLiteral("Phong (per pixel)"));
    panel.shadingBox()->setCurrentIndex(2);
    QCOMPARE(f.document.settings().shading, rl::ShadingModel::Flat);
    QCOMPARE(f.document.scene()->draws.at(0).shading, rl::ShadingModel::Flat);
    QCOMPARE(edited.count(), 1);
    QVERIFY(!panel.isModified());  // the shading model is in no file
    panel.undoStack()->undo();
    QCOMPARE(f.document.settings().shading, rl::ShadingModel::Phong);
    QCOMPARE(panel.shadingBox()->currentIndex(), 0);
    // Chosen elsewhere (the window's menu): refresh() shows it.
    f.document.setShading(rl::ShadingModel::Gouraud);
    panel.refresh();
    QCOMPARE(panel.shadingBox()->currentText(), QStringLiteral("Gouraud (per vertex)"));
}

// The layout each part was read in, detected or chosen, is what Save writes.
void TestEditPanel::layoutsRemembered() {
    REQUIRE_SAMPLES();
    Fixture f;
    LOAD(f, QStringLiteral("ufrpe/camera_1.txt"), QStringLiteral("ufpe/multi_iluminacao.txt"));
    QCOMPARE(f.document.cameraLayout(), rl::CameraLayout::Auto);
    QCOMPARE(f.document.cameraFileLayout(), rl::CameraLayout::KeyValue);
    QCOMPARE(f.document.lightingFileLayout(), rl::LightingLayout::UfpeMulti);
    // Chosen by hand: camera_1.txt does not fit UFRPE (C; N; V; hx hy; d), so it stays, in
    // its layout; a file that fits is then read, and remembered, in the chosen layout.
    QVERIFY(!f.document.setCameraLayout(rl::CameraLayout::Ufrpe5));
    QCOMPARE(f.document.cameraFileLayout(), rl::CameraLayout::KeyValue);
    const QString ufrpe5 = f.dir.filePath(QStringLiteral("five.cfg"));
    QFile file(ufrpe5);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("0 -500 500\n0 1 -1\n0 -1 -1\n2 2\n5\n");
    file.close();
    QVERIFY(f.document.open(Part::Camera, ufrpe5));
    QCOMPARE(f.document.cameraFileLayout(), rl::CameraLayout::Ufrpe5);
    QVERIFY(f.document.setCameraLayout(rl::CameraLayout::Auto));
    QCOMPARE(f.document.cameraFileLayout(), rl::CameraLayout::Ufrpe5);  // detected so too
    // The built-in scene's files are UFPE.
    SceneDocument builtIn;
    QVERIFY(builtIn.loadDefault());
    QCOMPARE(builtIn.cameraFileLayout(), rl::CameraLayout::Ufpe);
    QCOMPARE(builtIn.lightingFileLayout(), rl::LightingLayout::Ufpe);
}

void TestEditPanel::saveWritesTheFileInItsLayout() {
    REQUIRE_SAMPLES();
    Fixture f;
    LOAD(f);
    EditPanel panel(&f.document);
    QSignalSpy modified(&panel, &EditPanel::modifiedChanged);
    QSignalSpy saved(&panel, &EditPanel::saved);
    panel.spinBox(Field::C, 0)->setValue(75.0);
    panel.spinBox(Field::N, 0)->setValue(0.1);
    panel.spinBox(Field::LightIntensity, 1)->setValue(127.5);
    panel.spinBox(Field::Kd, 0)->setValue(0.85);  // linked: one number in the file
    QVERIFY(panel.isModified());
    QVERIFY(panel.save());
    QVERIFY(!panel.isModified());
    QVERIFY(!f.document.isModified(Part::Camera));
    QVERIFY(!f.document.isModified(Part::Lighting));
    QCOMPARE(modified.count(), 2);
    QCOMPARE(modified.at(1).at(0).toBool(), false);
    QCOMPARE(saved.count(), 2);
    QVERIFY(!panel.saveAction()->isEnabled());

    // The UFPE layouts, with the samples' CRLF line endings.
    QCOMPARE(contentOf(f.cameraPath),
             QByteArray("75 -50 600\r\n0.1 0 -1\r\n1 -100 10\r\n1 1 1\r\n"));
    QCOMPARE(contentOf(f.lightingPath),
             QByteArray("-220 -150 700\r\n1\r\n64 64 64\r\n0.85\r\n0 0.8 0\r\n0.5\r\n255 127.5 "
                        "255\r\n2\r\n"));
    rl::Diagnostics diagnostics;
    const QByteArray cameraText = contentOf(f.cameraPath);
    const auto camera = rl::readCameraFile(testing::viewOf(cameraText), "camera", diagnostics);
    QVERIFY(camera.ok());
    QCOMPARE(camera->c, rl::dvec3(75, -50, 600));
    QCOMPARE(camera->n, rl::dvec3(0.1, 0, -1));
    QVERIFY(f.document.fileHoldsLastSave(Part::Camera));
    QVERIFY(f.document.fileHoldsLastSave(Part::Lighting));

    // Opened again, the files give the values edited.
    SceneDocument again;
    QVERIFY(again.loadDefault());
    QVERIFY(again.open(Part::Camera, f.cameraPath));
    QVERIFY(again.open(Part::Lighting, f.lightingPath));
    QCOMPARE(again.parts().camera.c, f.document.parts().camera.c);
    QCOMPARE(again.parts().lighting.lights.at(0).intensity, rl::vec3(255, 127.5f, 255));
    QCOMPARE(again.parts().lighting.material.kd, rl::vec3(0.85f));

    // An edit after the save does not merge into the step before it (the same kd, at once).
    panel.spinBox(Field::Kd, 0)->setValue(0.9);
    QCOMPARE(panel.undoStack()->count(), 5);
    // The file is as saved until another program writes it (a file watcher can tell).
    QVERIFY(f.document.fileHoldsLastSave(Part::Camera));
    QFile other(f.cameraPath);
    QVERIFY(other.open(QIODevice::Append));
    other.write("\r\n");
    other.close();
    QVERIFY(!f.document.fileHoldsLastSave(Part::Camera));
}

// A key = value file shared by camera and lighting keeps the other part's lines.
void TestEditPanel::saveKeyValueKeepsOtherLines() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("scene.txt"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(
        "C = 0 -500 500\nN = 0 1 -1\nV = 0 -1 -1\nd = 5\nhx = 2\nhy = 2\n"
        "Iamb = 100 100 100\nKa = 0.2\nIl = 127 213 254\nPl = 60 5 -10\n"
        "Kd = 0.5 0.3 0.2\nOd = 0.7 0.5 0.8\nKs = 0.5\neta = 1\n");
    file.close();
    SceneDocument document;
    QVERIFY(document.loadDefault());
    QVERIFY(document.open(Part::Camera, path));
    QVERIFY(document.open(Part::Lighting, path));
    QCOMPARE(document.cameraFileLayout(), rl::CameraLayout::KeyValue);
    EditPanel panel(&document);
    panel.spinBox(Field::Hy, 0)->setValue(1.5);
    panel.spinBox(Field::Kd, 1)->setValue(0.35);
    QVERIFY(panel.save());
    QCOMPARE(contentOf(path),
             QByteArray("C = 0 -500 500\nN = 0 1 -1\nV = 0 -1 -1\nd = 5\nhx = 2\nhy = 1.5\n"
                        "Iamb = 100 100 100\nKa = 0.2\nIl = 127 213 254\nPl = 60 5 -10\n"
                        "Kd = 0.5 0.35 0.2\nOd = 0.7 0.5 0.8\nKs = 0.5\neta = 1\n"));
}

// A save that fails (here: the file system refuses more than 8 bytes a file, also to root)
// leaves the old file whole, keeps the changes and the modified flag, and shows why.
void TestEditPanel::failedSaveLeavesTheOldFile() {
    REQUIRE_SAMPLES();
    Fixture f;
    LOAD(f);
    EditPanel panel(&f.document);
    panel.spinBox(Field::C, 2)->setValue(650.0);
    const QByteArray before = contentOf(f.cameraPath);

    rlimit old{};
    QVERIFY(getrlimit(RLIMIT_FSIZE, &old) == 0);
    const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit small = old;
    small.rlim_cur = 8;
    QVERIFY(setrlimit(RLIMIT_FSIZE, &small) == 0);
    const rl::Status status = f.document.save(Part::Camera);
    bool saved = true;
    const QString dialog = answeringDialogs([&] { saved = panel.save(Part::Camera); });
    setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, previousHandler);

    QVERIFY(!status.ok());
    QCOMPARE(status.error().code, rl::ErrorCode::Io);
    QVERIFY2(QString::fromStdString(status.error().message)
                 .startsWith(QStringLiteral("cannot write the file (it is left as it was): ")),
             status.error().message.c_str());
    QVERIFY(!saved);
    QVERIFY2(dialog.startsWith(QStringLiteral("saveErrorBox: The camera was not saved. / ")),
             qPrintable(dialog));
    QVERIFY(dialog.contains(QStringLiteral("cannot write the file")));
    QCOMPARE(contentOf(f.cameraPath), before);
    QVERIFY(f.document.isModified(Part::Camera));
    QVERIFY(panel.isModified());
    QCOMPARE(f.document.parts().camera.c.z, 650.0);
    QCOMPARE(QDir(f.dir.path()).entryList(QDir::Files).size(), 2);  // no temporary left
}

void TestEditPanel::saveInReadOnlyFolderFails() {
    REQUIRE_SAMPLES();
    if (geteuid() == 0) QSKIP("root writes into read-only folders");
    Fixture f;
    LOAD(f);
    f.document.setValue(Field::Ambient, {10.0, 10.0, 10.0});
    const QByteArray before = contentOf(f.lightingPath);
    QFile::setPermissions(f.dir.path(), QFileDevice::ReadOwner | QFileDevice::ExeOwner);
    const rl::Status status = f.document.save(Part::Lighting);
    QFile::setPermissions(f.dir.path(),
                          QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
    QVERIFY(!status.ok());
    QCOMPARE(status.error().code, rl::ErrorCode::Io);
    QCOMPARE(contentOf(f.lightingPath), before);
    QVERIFY(f.document.isModified(Part::Lighting));
}

void TestEditPanel::degenerateCameraIsNotSaved() {
    REQUIRE_SAMPLES();
    Fixture f;
    LOAD(f);
    f.document.setValue(Field::V, {0.0, 0.0, 2.0});  // parallel to N = (0, 0, -1)
    const QByteArray before = contentOf(f.cameraPath);
    const rl::Status status = f.document.save(Part::Camera);
    QVERIFY(!status.ok());
    QCOMPARE(status.error().code, rl::ErrorCode::Degenerate);
    QVERIFY(QString::fromStdString(status.error().message)
                .startsWith(QStringLiteral("the camera was not saved, as it would not load "
                                           "again: V (0, 0, 2) is parallel to N")));
    QCOMPARE(contentOf(f.cameraPath), before);
}

// The built-in scene lives in the resources: Save needs a file, then the part comes from it.
void TestEditPanel::builtInSceneNeedsAPath() {
    SceneDocument document;
    QVERIFY(document.loadDefault());
    EditPanel panel(&document);
    QVERIFY(panel.isEnabled());
    QCOMPARE(panel.spinBox(Field::C, 1)->value(), -380.0);  // the default camera
    panel.spinBox(Field::C, 1)->setValue(-400.0);
    QVERIFY(document.needsPath(Part::Camera));
    const rl::Status status = document.save(Part::Camera);
    QVERIFY(!status.ok());
    QCOMPARE(status.error().code, rl::ErrorCode::Usage);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("camera.cfg"));
    QVERIFY(document.saveAs(Part::Camera, path));
    QCOMPARE(document.source(Part::Camera), path);
    QVERIFY(!document.needsPath(Part::Camera));
    QVERIFY(!document.isModified());
    QCOMPARE(contentOf(path), QByteArray("0 -400 330\n0 380 -330\n0 0 1\n1 0.4 0.3\n"));
    // Save As in another layout: the part is in that layout from now on.
    panel.spinBox(Field::D)->setValue(2.0);
    const QString keys = dir.filePath(QStringLiteral("camera.txt"));
    QVERIFY(document.saveCameraAs(keys, rl::CameraLayout::KeyValue));
    QCOMPARE(document.cameraFileLayout(), rl::CameraLayout::KeyValue);
    QCOMPARE(contentOf(keys),
             QByteArray("C = 0 -400 330\nN = 0 380 -330\nV = 0 0 1\nd = 2\nhx = 0.4\nhy = 0.3\n"));
    // A lighting of two lights does not fit a one-light layout.
    if (!testing::samplesDir().isEmpty()) {
        QVERIFY(document.open(Part::Lighting, sample(QStringLiteral("ufpe/multi_iluminacao.txt"))));
        const rl::Status one = document.saveLightingAs(dir.filePath(QStringLiteral("l.txt")),
                                                       rl::LightingLayout::Ufpe);
        QVERIFY(!one.ok());
        QCOMPARE(one.error().code, rl::ErrorCode::Unsupported);
        QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("l.txt"))));
    }
}

// Save on the built-in scene asks for a file; the filter chosen is the layout written.
void TestEditPanel::saveAsDialogChoosesTheLayout() {
    SceneDocument document;
    QVERIFY(document.loadDefault());
    EditPanel panel(&document);
    panel.spinBox(Field::Ks)->setValue(0.5);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("lighting.lux"));
    QStringList filters;
    QTimer timer;
    timer.setInterval(20);
    connect(&timer, &QTimer::timeout, [&] {
        auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
        if (!dialog) return;
        filters = dialog->nameFilters();
        dialog->selectNameFilter(QStringLiteral("key = value (*)"));
        // Typed, as a person would (selectFile leaves a focused line edit as it is).
        auto* name = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
        if (name) name->setText(path);
        QMetaObject::invokeMethod(dialog, "accept");
    });
    timer.start();
    QVERIFY(panel.save(Part::Lighting));
    timer.stop();
    QCOMPARE(filters,
             QStringList({QStringLiteral("UFPE (Pl; ka; Ia; kd; Od; ks; Il; n) (*)"),
                          QStringLiteral("UFPE multi-light (ka; Ia; kd; Od; ks; n; L; L times Pl; "
                                         "Il) (*)"),
                          QStringLiteral("UFRPE (Iamb; Ka; Il; Pl; Kd; Od; Ks; n) (*)"),
                          QStringLiteral("key = value (*)")}));
    QCOMPARE(document.source(Part::Lighting), path);
    QCOMPARE(document.lightingFileLayout(), rl::LightingLayout::KeyValue);
    QVERIFY(!panel.isModified());
    QCOMPARE(contentOf(path),
             QByteArray("Iamb = 60 60 72\nKa = 0.35\nIl = 255 248 235\nPl = -260 -420 520\n"
                        "Kd = 0.85 0.85 0.85\nOd = 0.88 0.42 0.18\nKs = 0.5\neta = 40\n"));
}

void TestEditPanel::maybeSave() {
    REQUIRE_SAMPLES();
    Fixture f;
    LOAD(f);
    EditPanel panel(&f.document);
    bool result = false;
    // Nothing changed: true, and no question.
    QCOMPARE(answeringDialogs([&] { result = panel.maybeSave(nullptr); }), QString());
    QVERIFY(result);

    panel.spinBox(Field::Ks)->setValue(0.75);
    const QByteArray before = contentOf(f.lightingPath);
    QString asked =
        answeringDialogs([&] { result = panel.maybeSave(nullptr); }, QMessageBox::Cancel);
    QCOMPARE(asked, QStringLiteral("saveChangesBox: The lighting has changes that are not saved "
                                   "(iluminacao.txt). / Save them?"));
    QVERIFY(!result);
    QVERIFY(panel.isModified());
    // The camera is not modified: no question about it.
    QCOMPARE(answeringDialogs([&] { result = panel.maybeSave(nullptr, Part::Camera); }), QString());
    QVERIFY(result);

    asked = answeringDialogs([&] { result = panel.maybeSave(nullptr); }, QMessageBox::Discard);
    QVERIFY(!asked.isEmpty());
    QVERIFY(result);
    QVERIFY(panel.isModified());  // discarding leaves the caller to replace the values
    QCOMPARE(contentOf(f.lightingPath), before);

    asked = answeringDialogs([&] { result = panel.maybeSave(nullptr); }, QMessageBox::Save);
    QVERIFY(!asked.isEmpty());
    QVERIFY(result);
    QVERIFY(!panel.isModified());
    QVERIFY(contentOf(f.lightingPath).contains("\r\n0.75\r\n"));
}

void TestEditPanel::openingAFileClearsTheHistory() {
    REQUIRE_SAMPLES();
    Fixture f;
    LOAD(f);
    EditPanel panel(&f.document);
    panel.spinBox(Field::C, 0)->setValue(70.0);
    panel.spinBox(Field::Ka)->setValue(0.5);
    QCOMPARE(panel.undoStack()->count(), 2);
    panel.refresh();  // nothing opened: the history stays
    QCOMPARE(panel.undoStack()->count(), 2);
    QVERIFY(f.document.open(Part::Camera, sample(QStringLiteral("ufpe/vaso.cfg"))));
    panel.refresh();
    QCOMPARE(panel.undoStack()->count(), 0);
    QCOMPARE(panel.spinBox(Field::C, 0)->value(), f.document.parts().camera.c.x);
    QVERIFY(!f.document.isModified(Part::Camera));
    QVERIFY(f.document.isModified(Part::Lighting));  // the lighting keeps its change
    QCOMPARE(panel.spinBox(Field::Ka)->value(), 0.5);
}

void TestEditPanel::commandFileDisablesThePanel() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("scene.txt"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(
        "png 8 8 a.png\nxyz -0.8 -0.5 0.1\nxyz 0.1 -0.9 0.5\nxyz 0.9 0 0.9\n"
        "trif 1 2 3\n");
    file.close();
    SceneDocument document;
    QVERIFY(document.loadDefault());
    EditPanel panel(&document);
    QVERIFY(panel.spinBox(Field::C, 0)->isEnabled());
    QVERIFY(document.openCommandFile(path));
    panel.refresh();
    QVERIFY(!panel.spinBox(Field::C, 0)->isEnabled());
    QVERIFY(!panel.saveAsAction()->isEnabled());
    // The default scene's camera is not shown as if it were the command file's; the label
    // says why.
    QVERIFY(!panel.spinBox(Field::C, 0)->isVisibleTo(&panel));
    auto* files = panel.findChild<QLabel*>(QStringLiteral("editFiles"));
    QVERIFY(files && files->isVisibleTo(&panel));
    QCOMPARE(files->text(),
             QStringLiteral("A command file is shown: its scene is not edited here."));
    QVERIFY(document.loadDefault());
    panel.refresh();
    QVERIFY(panel.spinBox(Field::C, 0)->isEnabled());
    QVERIFY(panel.spinBox(Field::C, 0)->isVisibleTo(&panel));
}

void TestEditPanel::screenshots() {
    REQUIRE_SAMPLES();
    Fixture f;
    LOAD(f, QStringLiteral("ufpe/calice2.cfg"), QStringLiteral("ufpe/multi_iluminacao.txt"));
    EditPanel panel(&f.document);
    panel.spinBox(Field::Ks)->setValue(0.6);
    panel.resize(340, 760);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QVERIFY(panel.grab().save(QStringLiteral("/tmp/edit_panel_multi.png")));
    qInfo("panel width %d", panel.sizeHint().width());
    QVERIFY(panel.sizeHint().width() <= 350);

    SceneDocument builtIn;
    QVERIFY(builtIn.loadDefault());
    EditPanel plain(&builtIn);
    plain.resize(340, 760);
    plain.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plain));
    QVERIFY(plain.grab().save(QStringLiteral("/tmp/edit_panel_default.png")));
}

QTEST_MAIN(TestEditPanel)
#include "tst_edit_panel.moc"
