// What the views of one triangle's steps share (scan conversion, trapezoids, near-plane
// clipping): a title over the view's own controls and canvas over an explanation, the title's
// and the explanation's font enlarged in presentation, and a refresh on the Inspection's
// signals while the view is visible (a hidden view catches up when it is shown).
#pragma once

#include <QString>
#include <QWidget>

#include <cstdint>
#include <optional>

class QLabel;
class QTextBrowser;

namespace rl {
struct TriangleSetup;
}

namespace rasterlab {

class Inspection;

class ExplainedView : public QWidget {
public:
    // The explanation shown, as plain text (for tests).
    QString explanationText() const;

protected:
    // name: the object names' prefix, <name>View, <name>Title and <name>Explanation. The view
    // lays out title() and explanation() with its own widgets.
    ExplainedView(Inspection* inspection, const QString& name, QWidget* parent);

    // Makes what is shown again from the Inspection.
    virtual void refresh() = 0;
    // A new frame, before the refresh that cursorChanged brings (nothing by default).
    virtual void frameChanged() {}
    // The presentation mode changed, the fonts already set: a refresh by default.
    virtual void presentationChanged();

    void showEvent(QShowEvent* event) override;
    bool event(QEvent* event) override;  // kRaisedEvent (on_screen.h)

    QLabel* title() const { return m_title; }
    QTextBrowser* explanation() const { return m_text; }
    // Sets the explanation only when it changed: a step or a signal that leaves it as it was
    // (a new frame brings several) costs no layout, and the reader's scroll position stays.
    // True when it changed.
    bool setExplanation(QString html);

    Inspection* m_inspection = nullptr;

private:
    void updateFonts();

    QLabel* m_title = nullptr;
    QTextBrowser* m_text = nullptr;
    QString m_html;  // what m_text shows
    bool m_stale = false;  // a refresh was left out while the view was covered
};

// The scanline the views of one triangle's scan show (scan conversion, trapezoids): the
// stepping cursor's row and the pixel last tested on it; at the start or the end of the
// frame (or without a replay), the triangle selected, at the row of the pixel picked when
// that is one of its rows on the screen (the pixel too when it lies on the row's span), else
// at its middle row. None without a frame or a triangle.
struct FollowedRow {
    std::uint32_t triangle = 0;  // Projection::triangles
    int y = 0;
    std::optional<int> pixel;
    bool followsCursor = false;
};
std::optional<FollowedRow> followedRow(const Inspection& inspection);

// The rows of a triangle set up for the scan that lie on a screen `height` rows high,
// [first, last]: its sampled rows cut to the screen, none (last < first) when it is
// degenerate.
struct ScreenRows {
    int first = 0, last = -1;
    bool contains(int y) const { return y >= first && y <= last; }
};
ScreenRows screenRows(const rl::TriangleSetup& s, int height);

}  // namespace rasterlab
