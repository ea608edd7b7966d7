// A pixel's story in plain English, from a RecordingProbe run on that pixel: every
// triangle whose span covered it, each depth test with both depths and the verdict, and
// the shading of the fragment that won, term by term. Used by `rasterlab-cli render
// --explain-pixel X,Y`, which answers a student's "why is this pixel black?".
#pragma once

#include <string>

#include "pipeline/render/frame_trace.h"
#include "pipeline/stages/probe.h"

namespace rl {

std::string explainPixel(const FrameTrace& trace, const RecordingProbe& probe);

}  // namespace rl
