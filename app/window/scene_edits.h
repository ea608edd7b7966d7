// The undoable edits of the edit panel: one command per change of one field of the scene
// document, holding the field's old and new value.
//
// Merging: a drag, a held arrow key or typed digits change one spin box many times a second;
// those changes merge into one undo step while the same spin box changes with no pause longer
// than the merge interval (1 s by default) and nothing else happens in between (another
// field's change, an undo or redo, a save: each starts a new session). A step whose merged
// change ends where it started is dropped.
#pragma once

#include <QUndoCommand>

#include <cstdint>
#include <functional>

#include "app/documents/scene_document.h"

namespace rasterlab {

class FieldEdit : public QUndoCommand {
public:
    using Field = SceneDocument::Field;
    using Numbers = SceneDocument::Numbers;
    // Sets a field of the document and shows it (the panel's doing).
    using Apply = std::function<void(Field field, std::size_t light, const Numbers& value)>;

    // What changed and when: `source` tells the spin box that made the change apart (0..2 for
    // one component, -1 for kd's three at once); `atMs` is a monotonic clock's time; edits of
    // different sessions never merge.
    struct Change {
        Field field = Field::C;
        std::size_t light = 0;
        int source = 0;
        Numbers before{};
        Numbers after{};
        qint64 atMs = 0;
        std::uint64_t session = 0;
    };

    FieldEdit(const Change& change, qint64 mergeIntervalMs, Apply apply, const QString& text);

    static constexpr int kId = 0x4544;  // "ED"
    int id() const override { return kId; }
    bool mergeWith(const QUndoCommand* other) override;
    void undo() override;
    void redo() override;

    const Change& change() const { return m_change; }

private:
    Change m_change;  // atMs: the time of the latest merged change
    qint64 m_mergeIntervalMs;
    Apply m_apply;
};

// A light added or removed: `light` at `index`. Adding puts it there on redo and takes it
// away on undo; removing the reverse.
class LightListEdit : public QUndoCommand {
public:
    // Inserts (true) or removes (false) the light at index, and shows the change.
    using Apply = std::function<void(bool insert, std::size_t index, const rl::Light& light)>;

    LightListEdit(bool adding, std::size_t index, const rl::Light& light, Apply apply,
                  const QString& text);
    void undo() override;
    void redo() override;

private:
    bool m_adding;
    std::size_t m_index;
    rl::Light m_light;
    Apply m_apply;
};

}  // namespace rasterlab
