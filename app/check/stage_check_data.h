// What StageCheck keeps of one scene, shared by its files (stage_check.cpp makes the requests,
// stage_judges.cpp and stage_judges_pixels.cpp judge the answers): the lecture's stages run
// once, and the inputs the requests carry.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "app/check/stage_check.h"
#include "app/check/stage_frame.h"
#include "app/check/stage_mistakes.h"
#include "pipeline/analysis/mistakes.h"
#include "pipeline/stages/camera_basis.h"
#include "pipeline/stages/depth_test.h"
#include "pipeline/stages/normals.h"
#include "pipeline/stages/projection.h"
#include "pipeline/stages/scan_conversion.h"
#include "pipeline/stages/view_transform.h"

namespace rasterlab::check {

// The inputs the requests carry: ours, or in a chained run the student's own earlier answers
// wherever they gave one of the right size.
struct StageCheck::Inputs {
    std::array<rl::dvec3, 3> uvn;
    rl::dvec3 light;          // in view coordinates
    std::vector<Row> view;    // every vertex, in view coordinates
    std::vector<Row> screen;  // every projected vertex of the draw, in pixels (x, y)
    std::vector<Fragment> fragments;
    std::vector<Sample> samples;
    bool chained = false;  // some input is the student's own
};

struct StageCheck::Data {
    std::shared_ptr<const rl::Scene> scene;
    const rl::Draw* draw = nullptr;
    rl::CameraBasis basis;
    rl::ViewTransform view;
    rl::DrawNormals normals;
    rl::Projection projection;
    rl::ScanConversion scan;
    rl::DepthTest depth;
    std::vector<std::uint32_t> projected;  // the projection request's vertex k is this vertex
    // Our inputs of every request, made once: the z-buffer's fragments in drawing order, the
    // lighting's samples, the basis, view coordinates and screen vertices.
    Inputs ours;
    std::vector<Row> colours;  // ours for the samples, clamped
    rl::OurFrame frame;        // our render, for the frame stage and compare
    Lighting lighting;         // the scene's, in view coordinates
    // The stages' formulas with no mistake give our frame (to a byte on all but 0.1% of it):
    // the frame's findings may start from the stages' (stage_frame.h).
    bool stagesFrameTrusted = false;

    const rl::Mesh& mesh() const { return *draw->mesh; }
    const rl::CourseCamera& camera() const { return *scene->camera; }
    const std::vector<std::array<std::uint32_t, 3>>& triangles() const {
        return mesh().triangles;
    }
    // The scan request's rows x1 y1 x2 y2 x3 y3, from these screen vertices.
    std::vector<Row> screenTriangles(const std::vector<Row>& screen) const;
    // What the frame request carries, for the stages' own frame (stage_frame.h).
    FrameScene frameScene() const;
};

// How far off the screen an answer may list a pixel (as a span or a z-buffer's pixel), and
// a number of a pixel's answer: whole and within those bounds.
inline constexpr double kFarthest = 1000000;
inline bool whole(double v, double low, double high) {
    return v == std::floor(v) && v >= low && v <= high;
}

// A stage's findings and what stays unexplained, from the search's explanation.
inline void takeExplanation(StageResult& result, const Explanation& e) {
    result.findings = e.findings;
    result.applied = e.applied;
    result.unexplained = e.unexplained.size();
}

}  // namespace rasterlab::check
