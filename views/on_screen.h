// Docks tabbed behind another stay visible to Qt (isVisible()) but are covered: the views that
// follow every step refresh only when they are on screen, and the window sends a dock's content
// kRaisedEvent when its tab comes to the front, so that a view left stale refreshes then.
#pragma once

#include <QEvent>
#include <QWidget>

namespace rasterlab {

inline bool onScreen(const QWidget* widget) {
    return widget->isVisible() && !widget->visibleRegion().isEmpty();
}

inline const QEvent::Type kRaisedEvent = static_cast<QEvent::Type>(QEvent::registerEventType());

}  // namespace rasterlab
