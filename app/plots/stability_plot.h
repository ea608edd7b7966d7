// The picture of the stability sweep (stability.h), shared by the window and the command line:
// one log-log panel per axis, colour RMSE against the stiffness, one curve per rule set and
// precision (float solid, double dashed), the stiffer end on the right; points whose scene
// could not be rendered are crosses at the top. A last panel puts every point's error against
// its time per frame. Drawing text needs a QGuiApplication.
#pragma once

#include <QImage>
#include <QString>

#include "pipeline/analysis/stability.h"

namespace rasterlab {

// The size that gives each panel the room it has in the default 1500 x 900 picture of every
// axis, for a plot of `axes` axes (and the time panel).
QSize stabilityPlotSize(int axes);
// The same for the axes the report holds.
QSize stabilityPlotSize(const rl::StabilityReport& report);

QImage stabilityPlot(const rl::StabilityReport& report, const QString& title,
                     QSize size = {1500, 900});

}  // namespace rasterlab
