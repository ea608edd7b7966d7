// What their renderer effectively used for the lighting, fitted to their colours (compare):
// from our frame's trace, each sampled pixel's P', N and V, and their colour there. Seed 000's
// model is linear in the ambient term A = Ia ka, the diffuse factor D = Il Od kd and the
// specular factor S = Il ks once the light's position and n are fixed: per channel,
// c = A + D (N.L) + S (R.V)^n. So the fit searches the light's view position and n (Nelder-
// Mead, from ours and from where the classic transform mistakes put the light) and solves
// A, D and S by least squares at each step. Samples: covered pixels inside a triangle (not on
// an edge) of a Phong-shaded draw lit by the course's model with one light, their channels
// strictly between 0 and 255 (not clamped); the worst tenth of the residuals is left out
// and the fit done again (robust to the pixels another mistake changed). The uncertainty of
// each value is the spread of four fits on halves of the samples.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/analysis/mistakes.h"

namespace rl {

struct FittedValue {
    std::string name;  // "light x (view)", "n", "ambient R" ...
    double ours = 0.0;
    double theirs = 0.0;
    double uncertainty = 0.0;  // the spread of the fits on halves of the samples
    bool apart = false;        // |theirs - ours| above its scale's least (2% of the distance
                               // to the light, 5% of n, 2 bytes of a colour)
    bool differs = false;      // and above three uncertainties too
};

struct LightingFit {
    bool fitted = false;
    Message reason;           // why not, when not fitted
    std::size_t samples = 0;  // pixels used (after the worst tenth is left out)
    double rmsOurs = 0.0;     // per channel, byte units: our parameters against their colours
    double rmsFitted = 0.0;   // the fitted parameters against their colours
    dvec3 lightOurs = dvec3(0.0), lightTheirs = dvec3(0.0);  // view coordinates
    std::vector<FittedValue> values;
    // Fitted on their image carried back onto ours by the move (mirror, shift, screen map) the
    // diagnosis found first, removing most of the difference: their colours at our pixels'
    // points of the surface.
    bool carriedBack = false;
    // The transform mistake the fitted light matches, when it does (LightInWorld,
    // LightWithoutC), else none; and the words for what the fitted values say.
    std::optional<Mistake> matches;
    std::vector<Message> findings;
    // The fitted lighting explains their colours: its rms under half ours, ours above 2.
    bool explainsBetter() const { return fitted && rmsOurs > 2.0 && rmsFitted < 0.5 * rmsOurs; }
};

// The fit on our frame and their image (our size). Not fitted (with the reason) when the scene
// has no Phong draw lit by one light of the course's model, one material, or too few samples.
LightingFit fitLighting(const OurFrame& ours, const Rgba8Image& theirs);

// The scene with the fitted lighting: the light at the fitted view position, and Ia, Il, kd,
// ks and n set so that A, D and S are the fitted ones.
std::shared_ptr<const Scene> sceneWithFit(const Scene& scene, const CameraBasis& basis,
                                          const LightingFit& fit);

// Ours rendered with the fitted lighting, then the catalogue's mistakes composed on it: put
// first when the fit explains their colours better than ours, that leaves less unexplained
// than base by kLeastShare of the difference, and the fit matches no catalogued mistake (which
// base finds itself); else base as it is.
Result<ImageComparison> withFittedLighting(ImageComparison base, const OurFrame& ours,
                                           const Rgba8Image& theirs, const CompareOptions& options,
                                           const LightingFit& fit);

}  // namespace rl
