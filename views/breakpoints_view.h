// The stepper's breakpoints: at a triangle, at a scanline, at the first depth rejection at a
// pixel, when N.L < 0 at a pixel, when a pixel is written the n-th time (a chosen pixel or
// any). Each can be turned off; the one that stopped the replay is marked. Triangles are
// numbered as in the object file (1-based, the first draw's).
#pragma once

#include <QWidget>

#include "views/inspection.h"

class QComboBox;
class QLabel;
class QSpinBox;
class QTreeWidget;

namespace rasterlab {

class BreakpointsView : public QWidget {
    Q_OBJECT
public:
    explicit BreakpointsView(Inspection* inspection, QWidget* parent = nullptr);

    // Adds a breakpoint as the form would (a pixel kind uses the picked pixel; NthWrite with
    // anyPixel ignores it). False when it needs a picked pixel and there is none.
    bool add(rl::Breakpoint::Kind kind, int value, bool anyPixel = false);
    void removeSelected();
    void clear();
    // The breakpoints as the list holds them, a Triangle's `triangle` being the mesh's 1-based
    // number; and all of them replaced by such a list (what lesson files keep).
    std::vector<rl::Breakpoint> entries() const;
    void setEntries(const std::vector<rl::Breakpoint>& breakpoints);
    // What a breakpoint says, translated ("first depth rejection at (12, 40)").
    static QString describe(const rl::Breakpoint& breakpoint, int triangleNumber);

private:
    struct Entry {
        rl::Breakpoint breakpoint;
        int triangleNumber = 0;  // Triangle: the mesh's 1-based number
    };
    void publish();
    void refreshList();
    void updateForm();

    Inspection* m_inspection;
    std::vector<Entry> m_entries;
    int m_hit = -1;
    QTreeWidget* m_list = nullptr;
    QComboBox* m_kind = nullptr;
    QSpinBox* m_value = nullptr;
    QComboBox* m_where = nullptr;
    QLabel* m_status = nullptr;
};

}  // namespace rasterlab
