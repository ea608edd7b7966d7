// The projection stage on several threads. It must equal ProjectionStage::run
// (stages/projection.h) bit for bit: the same vertices, fates, counts and screen triangles in
// the same order, and the same messages.
#pragma once

#include "pipeline/stages/projection.h"

namespace rl::fast {

// threads: the vertices, and the triangles' fates when the near plane is clipped, are worked
// out on several; the triangles are emitted on several when none needs clipping, else in
// order on one. keepExact: whether pNdc and pScreenExact are kept (only the views read them).
Projection projection(const ProjectionInput& in, Diagnostics& diagnostics, int threads,
                      bool keepExact);

}  // namespace rl::fast
