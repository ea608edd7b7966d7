// The lighting of one fragment of the pixel's history, term by term, as the frame's shading
// stage works it out: ambient, diffuse and specular per channel, each light's share, the
// special cases (flags) and the formula with the numbers filled in. The pixel inspector
// shows it below the history.
#pragma once

#include <QString>
#include <QStringList>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "pipeline/render/frame_trace.h"
#include "pipeline/render/replay.h"
#include "pipeline/stages/probe.h"
#include "views/pixel_history.h"

namespace rasterlab {

enum class LightingFlag : std::uint8_t {
    Flipped,       // V.N < 0: N was turned toward the viewer
    LightBehind,   // N.L < 0: no diffuse, no specular
    NoSpecular,    // R.V < 0: no specular
    Clamped,       // a channel above the colour scale
    ZeroNormal,    // N = 0: ambient only
    LightAtPoint,  // L = 0: the light sits on the point
    OutsideCone,   // outside a spot light's cone: no light from it
    OneSided,      // one-sided lighting: N not turned toward the viewer
    Texel,         // the texel a textured draw read, and where seed 001's rules disagree
};

// The lighting of one fragment, as the frame's shading stage works it out.
struct LightingBreakdown {
    int historyRow = -1;                       // the row of history() it belongs to
    std::uint32_t fragment = rl::kNoFragment;  // with a replay
    rl::ShadeEvent event;                      // model, sample (terms, vectors), colour
    rl::LightingModel lighting = rl::LightingModel::CoursePhong;
    std::size_t lights = 0;  // the lights the draw sees
    // The terms per channel, in the scene's colour scale: Phong and flat shading.
    rl::vec3 ambient = rl::vec3(0.0f), diffuse = rl::vec3(0.0f), specular = rl::vec3(0.0f);
    rl::vec3 unlit = rl::vec3(0.0f);     // a draw that is not lit: the object colour
    rl::vec3 emission = rl::vec3(0.0f);  // Ke (the course's model)
    // The course's model: what each light gives (attenuation, spot, N.L, R.V or N.H, its
    // diffuse and specular), from the same code as the render (rl::phong's perLight).
    std::vector<rl::LightTerms> perLight;
    // The lecture slides' lighting is in play (attenuation, spots, directional lights,
    // emission, Blinn-Phong): the formula is written with the light factors.
    bool slides = false;
    rl::vec3 objectColour = rl::vec3(0.0f);  // Od (O for command files) at the point
    // Gouraud: the weights (alpha, beta, gamma) and the vertices' colours they mix.
    std::array<float, 3> weights{};
    std::array<rl::vec3, 3> vertexColours{};
    rl::vec3 colour = rl::vec3(0.0f);  // before clamping
    std::array<std::uint8_t, 4> bytes{};
    std::vector<LightingFlag> flags;
    QStringList flagTexts;  // one sentence per flag, in the order of flags
    QStringList formula;    // the formula, then one line per channel with its numbers
    QString heading;        // "Phong shading, the course's lighting model", ...
    bool has(LightingFlag flag) const;
};

// The breakdown of the fragment of history row `row` (number historyRow), lit as `event`
// records it in the frame.
LightingBreakdown lightingBreakdown(const rl::FrameTrace& frame, const PixelHistoryRow& row,
                                    int historyRow, const rl::ShadeEvent& event);

class Inspection;
// The breakdown of history row `row` of the inspection's frame, from the replay's shading of
// its fragment (or, traced again without a replay, the fragment holding the pixel at the end);
// none for a row without a fragment, or when its shading is not known.
std::optional<LightingBreakdown> rowBreakdown(const Inspection& inspection,
                                              const PixelHistory& history, int row);

}  // namespace rasterlab
