// The pictures of the accuracy report, shared by the window and the command line: the plot of
// error against run time, and an error heat map with its colour bar. Drawing text needs a
// QGuiApplication (the command line makes one for `accuracy`).
#pragma once

#include <QImage>
#include <QString>

#include "pipeline/analysis/accuracy.h"

namespace rasterlab {

// Colour RMSE (in byte steps, log scale) against the median time per frame (log scale), one
// marker per mode: the colour is the shading model, the shape the rule set, the size the
// supersampling; each point labelled with its mode.
QImage accuracyPlot(const rl::AccuracyReport& report, const QString& title,
                    QSize size = {960, 640});

// The error of each pixel (errorMap: the largest channel difference) on a hot-body scale from
// 0 (dark blue) to maxError and above (white), black where neither image covers the pixel and
// magenta where only one does; a colour bar with its values on the right.
QImage errorHeatMap(const rl::Image<float>& error, float maxError);

// The whole decades covering [lo, hi] (both > 0), as exponents of 10; at least one decade.
void decades(double lo, double hi, double& first, double& last);
// 10^exponent as a log axis writes it: 0.01, 1, 1000, 1e6.
QString decadeLabel(double exponent);

// The colour of an error on the heat map's scale (t = error / maxError, clamped to [0, 1]).
QRgb heatColour(float t);

}  // namespace rasterlab
