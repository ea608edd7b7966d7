#include "scene_edits.h"

#include <utility>

namespace rasterlab {

FieldEdit::FieldEdit(const Change& change, qint64 mergeIntervalMs, Apply apply, const QString& text)
    : m_change(change), m_mergeIntervalMs(mergeIntervalMs), m_apply(std::move(apply)) {
    setText(text);
}

bool FieldEdit::mergeWith(const QUndoCommand* other) {
    if (other->id() != kId) return false;
    const Change& next = static_cast<const FieldEdit*>(other)->m_change;
    if (next.field != m_change.field || next.light != m_change.light ||
        next.source != m_change.source || next.session != m_change.session ||
        next.atMs - m_change.atMs > m_mergeIntervalMs)
        return false;
    m_change.after = next.after;
    m_change.atMs = next.atMs;
    // Back where it started (typed "5" over "65", then "65" again): no step at all.
    setObsolete(m_change.after == m_change.before);
    return true;
}

void FieldEdit::undo() {
    m_apply(m_change.field, m_change.light, m_change.before);
}

void FieldEdit::redo() {
    m_apply(m_change.field, m_change.light, m_change.after);
}

LightListEdit::LightListEdit(bool adding, std::size_t index, const rl::Light& light, Apply apply,
                             const QString& text)
    : m_adding(adding), m_index(index), m_light(light), m_apply(std::move(apply)) {
    setText(text);
}

void LightListEdit::undo() {
    m_apply(!m_adding, m_index, m_light);
}

void LightListEdit::redo() {
    m_apply(m_adding, m_index, m_light);
}

}  // namespace rasterlab
