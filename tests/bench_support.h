// What the window benchmarks (bench_stepping, bench_editing) share: a generated torus written
// as course files, and percentiles of a list of times.
#pragma once

#include <QString>

#include <vector>

namespace rasterlab::bench {

// A torus of about `triangles` triangles as the three course files in `dir` (the camera and
// lighting in the UFPE layout, by the course writers): paths[0] camera, [1] lighting,
// [2] object. False when a file cannot be written.
bool writeTorus(const QString& dir, int triangles, QString paths[3]);

// The p-th quantile (0..1) of v, by rank.
double percentile(std::vector<double> v, double p);

}  // namespace rasterlab::bench
