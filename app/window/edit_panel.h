// The edit panel: the course scene's camera, lights, ambient light, material and shading
// model as spin boxes that change the scene as they change (a held arrow or a typed number
// re-renders at each value), with undo/redo and Save.
//
// The panel edits a SceneDocument it does not own (the main window's) and tells the window
// through sceneEdited() that the scene must be rendered again; the window calls refresh()
// whenever it changed the document itself (a file opened, a layout chosen, the shading picked
// in a menu), so that the panel shows the document's values.
//
// Undo: a QUndoStack of FieldEdit commands (scene_edits.h), one per change of one spin box;
// the changes of one spin box merge into one step while they come with no pause longer than
// mergeInterval() (1 s): a drag, a held arrow, a typed number. Opening a file over the camera
// or the lighting clears the history (its steps were about values no longer shown): refresh()
// notices it through SceneDocument::partsReplaced().
//
// Save writes each modified part to its file in the layout it was read in; the built-in
// scene, which lives in the program's resources, asks for a file first. maybeSave() asks
// Save / Discard / Cancel for each modified part: the window calls it before closing and
// before a file replaces a modified part.
#pragma once

#include <QElapsedTimer>
#include <QWidget>

#include <cstdint>
#include <utility>
#include <vector>

#include "app/documents/scene_document.h"

class QAction;
class QCheckBox;
class QComboBox;
class QGridLayout;
class QDoubleSpinBox;
class QLabel;
class QMenu;
class QToolButton;
class QUndoStack;

namespace rasterlab {

class EditPanel : public QWidget {
    Q_OBJECT
public:
    using Field = SceneDocument::Field;
    using Part = SceneDocument::Part;

    explicit EditPanel(SceneDocument* document, QWidget* parent = nullptr);

    QUndoStack* undoStack() const { return m_stack; }
    // For the window's menus (the panel holds them too, so that their shortcuts work where
    // the panel is, docked or floating).
    QAction* undoAction() const { return m_undoAction; }      // QKeySequence::Undo
    QAction* redoAction() const { return m_redoAction; }      // QKeySequence::Redo
    QAction* saveAction() const { return m_saveAction; }      // QKeySequence::Save
    QAction* saveAsAction() const { return m_saveAsAction; }  // a submenu: Camera, Lighting

    // Whether the camera or the lighting differs from its file.
    bool isModified() const;
    // For each modified part, asks whether to save it (Save / Discard / Cancel); true when
    // the caller may go on (saved or discarded), false on Cancel or a failed save. True at
    // once when nothing is modified.
    bool maybeSave(QWidget* parent);
    bool maybeSave(QWidget* parent, Part part);
    // Saves every modified part (the Save action); false when one failed or was cancelled.
    // Errors are shown in a message box.
    bool save(QWidget* parent = nullptr);
    // Saves one part to its file, or asks for one (built-in scene).
    bool save(Part part, QWidget* parent = nullptr);
    // Asks for a file and a layout, and saves the part there.
    bool saveAs(Part part, QWidget* parent = nullptr);

    // The spin box of one number of a field (component 0..2), for tests and for focus.
    QDoubleSpinBox* spinBox(Field field, int component = 0) const;
    QComboBox* lightSelector() const { return m_lightSelector; }
    // The check box of a field that is on or off (directional, spot, two-sided, Blinn-Phong).
    QCheckBox* checkBox(Field field) const;
    QToolButton* addLightButton() const { return m_addLight; }
    QToolButton* removeLightButton() const { return m_removeLight; }
    QComboBox* shadingBox() const { return m_shading; }
    // Checked: kd's three channels change together (the UFPE files have one kd).
    QToolButton* kdLinkButton() const { return m_kdLink; }
    // The light whose values are shown.
    std::size_t currentLight() const;
    void setCurrentLight(std::size_t light);

    // Sets several fields at once as one undo step named `text` (Compare's fitted lighting).
    struct Setting {
        Field field;
        std::size_t light = 0;
        SceneDocument::Numbers value{};
    };
    void setValues(const std::vector<Setting>& settings, const QString& text);

    // The longest pause (ms) between two changes of one spin box that still merge them.
    qint64 mergeInterval() const { return m_mergeIntervalMs; }
    void setMergeInterval(qint64 ms) { m_mergeIntervalMs = ms; }

public slots:
    // Shows the document's values; clears the undo history when a file replaced the camera
    // or the lighting since the last refresh.
    void refresh();
    // Adds a copy of the light shown after the last one, and shows it; removes the light
    // shown (not the last one left). Each is one undo step.
    void addLight();
    void removeLight();

signals:
    // The document's scene changed (an edit, an undo or redo): render it again.
    void sceneEdited();
    // isModified() changed.
    void modifiedChanged(bool modified);
    // A part was written to its file (its source and warnings may have changed).
    void saved(SceneDocument::Part part);

private:
    struct Box {
        Field field;
        int component;
        QDoubleSpinBox* box;
    };

    QWidget* buildContent();
    QDoubleSpinBox* addBox(Field field, int component, double minimum, double maximum, double step,
                           bool adaptive = false);
    // A check box for a field that is on (1) or off (0); for the spot cutoff, on is a spot
    // (30 degrees when switched on) and off is 180 degrees.
    void addCheck(QGridLayout* grid, int row, Field field, const QString& text, const QString& tip);
    void onCheckToggled(Field field, bool checked);
    void showChecks(bool lightOnly);
    // One undo step adding or removing `light` at `index`.
    void pushLightList(bool adding, std::size_t index, const rl::Light& light, const QString& text);
    void applyLightList(bool insert, std::size_t index, const rl::Light& light);
    void createActions();
    void onBoxChanged(Field field, int component, double value);
    void onShadingChanged(int index);
    void push(Field field, std::size_t light, int source, const SceneDocument::Numbers& before,
              const SceneDocument::Numbers& after);
    void apply(Field field, std::size_t light, const SceneDocument::Numbers& value);
    bool isEditable() const;  // a course scene is shown
    void showBox(const Box& b);
    void showShading();
    void showField(Field field);
    void showLight();
    void updateModified();
    void updateFileLabel();
    QString fieldName(Field field, int source, std::size_t light) const;
    bool saveError(Part part, const QString& message, QWidget* parent);

    SceneDocument* m_document;
    QUndoStack* m_stack = nullptr;
    QAction* m_undoAction = nullptr;
    QAction* m_redoAction = nullptr;
    QAction* m_saveAction = nullptr;
    QAction* m_saveAsAction = nullptr;

    QWidget* m_content = nullptr;
    QLabel* m_fileLabel = nullptr;
    std::vector<Box> m_boxes;
    std::vector<std::pair<Field, QCheckBox*>> m_checks;
    QComboBox* m_lightSelector = nullptr;
    QToolButton* m_addLight = nullptr;
    QToolButton* m_removeLight = nullptr;
    QComboBox* m_shading = nullptr;
    QToolButton* m_kdLink = nullptr;

    QElapsedTimer m_clock;
    qint64 m_mergeIntervalMs = 1000;
    std::uint64_t m_session = 0;           // edits of different sessions never merge
    std::uint64_t m_seenReplaced = ~0ull;  // the document's partsReplaced() last shown
    bool m_pushing = false;                // a new edit is being pushed (not an undo or redo)
    QDoubleSpinBox* m_editing = nullptr;   // the spin box whose change is being pushed
    bool m_modified = false;
};

}  // namespace rasterlab
