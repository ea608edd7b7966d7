// What no known mistake explains in a stage's answer, said in numbers a student can act on:
// an offset or a scale of their vectors, whole or fractional screen coordinates, how many rows'
// spans start or end k pixels left or right, a colour's bias per channel and whether it follows
// N.L or R.V. Each function takes their answer, the best hypothesis's (the lecture's with the
// findings applied) and the elements still differing.
#pragma once

#include <string>
#include <vector>

#include "app/check/stage_findings.h"
#include "app/check/stage_mistakes.h"

namespace rasterlab::check {

// Vectors (basis, view coordinates, normals): `names` names the first rows ("U", "the light").
std::vector<std::string> describeVectors(const std::vector<Row>& theirs,
                                         const std::vector<Row>& best, const ElementKeys& left,
                                         const std::vector<std::string>& names);
// Screen coordinates x y.
std::vector<std::string> describeScreen(const std::vector<Row>& theirs,
                                        const std::vector<Row>& best, const ElementKeys& left);
// Colours r g b of the lighting's samples.
std::vector<std::string> describeColours(const std::vector<Row>& theirs,
                                         const std::vector<Row>& best, const ElementKeys& left,
                                         const Lighting& lighting,
                                         const std::vector<Sample>& samples);
// Spans t y first last: per triangle's row, where theirs start and end against the best's.
std::vector<std::string> describeSpans(const std::vector<Row>& theirs,
                                       const std::vector<Row>& best);

// The epsilons worth trying for the special cases: a round number (1, 2 or 5 times a power of
// ten) in each gap between the samples' small positive V.N, N.L and R.V.
std::vector<double> epsilonsOf(const Lighting& lighting, const std::vector<Sample>& samples);

}  // namespace rasterlab::check
