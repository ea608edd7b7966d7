// A student's stages checked against the lecture's (docs/stage-protocol.md). For one course
// scene, each stage's request carries its input as RasterLab's own stages computed it, and
// their answer is held to what the lecture's stage gives for it, element by element: the
// first element that departs with both values and the formula with its numbers, how many
// depart, the largest error, and the likely cause when their answer is what a known mistake
// of that stage gives (the cross product's order, normals not normalised, rounding against
// truncation, y not flipped, a span's end, the z-buffer's comparison, a Phong special case).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/check/stage_findings.h"
#include "app/check/stage_protocol.h"
#include "pipeline/render/output_image.h"
#include "pipeline/scene/scene.h"

namespace rasterlab::check {

enum class Verdict { Passed, Failed, Unsupported, Broken };
std::string_view verdictName(Verdict verdict);  // "passed", "failed", ...

struct Divergence {
    std::string element;  // "vertex 3", "pixel (41, 17)", "U"
    std::string theirs;
    std::string ours;
    std::string formula;  // the lecture's formula with this element's numbers
};

// Where a stage departs on the screen, for the window to draw over our image: a vertex at
// both its positions, or a pixel covered or won by one side only, or differently.
struct Departure {
    enum class Kind { Vertex, OnlyOurs, OnlyTheirs, Different };
    Kind kind = Kind::Different;
    rl::dvec2 ours = rl::dvec2(0.0);    // pixels
    rl::dvec2 theirs = rl::dvec2(0.0);  // pixels; a pixel's own position but for a vertex
};
inline constexpr std::size_t kMostDepartures = 100000;

struct StageResult {
    Stage stage = Stage::Basis;
    Verdict verdict = Verdict::Passed;
    std::size_t elements = 0;   // compared
    std::size_t differing = 0;  // beyond the tolerance
    double largestError = 0.0;
    std::string tolerance;  // how close counts as equal, in words
    std::optional<Divergence> first;
    // The known mistakes that together explain their answer, in the order they apply (each
    // with the elements it explains), and the differing elements none of them explains.
    std::vector<StageFinding> findings;
    std::vector<StageMistake> applied;  // the findings as the catalogue's mistakes
    std::size_t unexplained = 0;
    // What stays unexplained, in numbers a student can act on: on how many rows a span starts
    // a pixel left, a colour's bias per channel and whether it follows N.L, an offset ...
    std::vector<std::string> description;
    // A chained run: how many elements of the lecture's answer to RasterLab's own inputs differ
    // from the lecture's answer to what was sent (the error carried from the earlier stages);
    // none when the request was RasterLab's own.
    std::optional<std::size_t> carried;
    std::string problem;  // Broken: what went wrong (a bad answer, a timeout ...)
    std::vector<std::string> standardError;  // Broken: the last lines of its standard error
    std::string hint;                        // Broken: a runtime's memory message explained
    // Projection, scan, z-buffer and frame: where they depart (the first kMostDepartures).
    std::vector<Departure> departures;

    // The findings' causes in one line ("A; then B"), or empty.
    std::string causes() const;
};

// The lecture's stages run over one course scene, and what the protocol asks of them.
class StageCheck {
public:
    // The scene must be one the protocol carries: seed 000's (a course camera, one draw, one
    // positional light, a scalar kd, the course's rasterization rules). Otherwise an error
    // says why.
    static rl::Result<std::shared_ptr<const StageCheck>> make(
        std::shared_ptr<const rl::Scene> scene);

    Request request(Stage stage) const;
    // A chained run's request: the stage's input made from the student's own earlier answers
    // (their basis for the view, their view coordinates for the normals and the projection,
    // their screen vertices for the scan, their spans for the z-buffer's fragments, their
    // positions and normals for the lighting's samples), ours where they gave none.
    using Answers = std::map<Stage, std::vector<Record>>;
    struct Inputs;  // what the requests carry: ours, or a chained run's
    // A chained run's inputs, made once a stage for its request and its judge.
    std::shared_ptr<const Inputs> chainedInputs(const Answers& theirs) const;
    Request chainedRequest(Stage stage, const Inputs& in) const;
    // Their answer (records as parsed) to our request held to ours; `earlier` the scene's
    // results of the stages asked before (the frame's diagnosis starts from their findings).
    StageResult judge(Stage stage, const std::vector<Record>& answer,
                      const std::vector<StageResult>& earlier = {}) const;
    // Their answer to a chained request (made from those inputs), held to the lecture's stage
    // applied to exactly what was sent.
    StageResult judgeChained(Stage stage, const std::vector<Record>& answer, const Inputs& in,
                             const std::vector<StageResult>& earlier = {}) const;
    // Our image of the scene (the frame stage's answer), and theirs from a frame answer.
    const rl::Rgba8Image& ourImage() const;
    // The frame the stages' own formulas make with these mistakes (stage_frame.h).
    rl::Rgba8Image stagesFrame(const std::map<Stage, std::vector<StageMistake>>& applied) const;
    static rl::Rgba8Image theirImage(const std::vector<Record>& answer);

    struct Data;
    explicit StageCheck(std::unique_ptr<Data> data);
    ~StageCheck();

private:
    Request request(Stage stage, const Inputs& in) const;
    StageResult judge(Stage stage, const std::vector<Record>& answer, const Inputs& in,
                      const std::vector<StageResult>& earlier) const;
    StageResult judgeBasis(const std::vector<Record>& answer) const;
    StageResult judgeView(const std::vector<Record>& answer, const Inputs& in) const;
    StageResult judgeNormals(const std::vector<Record>& answer, const Inputs& in) const;
    StageResult judgeProjection(const std::vector<Record>& answer, const Inputs& in) const;
    StageResult judgeScan(const std::vector<Record>& answer, const Inputs& in) const;
    StageResult judgeZBuffer(const std::vector<Record>& answer, const Inputs& in) const;
    StageResult judgeLighting(const std::vector<Record>& answer, const Inputs& in) const;
    StageResult judgeFrame(const std::vector<Record>& answer,
                           const std::vector<StageResult>& earlier) const;
    bool compareFrame(const rl::Rgba8Image& theirs, const std::vector<StageResult>& earlier,
                      StageResult& result) const;

    std::unique_ptr<Data> m_data;
};

}  // namespace rasterlab::check
