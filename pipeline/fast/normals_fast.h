// The normals stage on several threads, leaving out what no draw's shading reads. It must
// equal NormalsStage::run (stages/normals.h) bit for bit in every normal it keeps.
#pragma once

#include <cstdint>

#include "pipeline/stages/normals.h"

namespace rl::fast {

enum class NormalsScope : std::uint8_t {
    All,   // every triangle's and every vertex's normal (the window's normals view draws them)
    Read,  // only what each draw's shading reads (normalsRead); the image is the same
};

// threads: the triangles and vertices are shared out between them (parallel.h); each vertex
// still sums its triangles' normals in triangle order, so the result is the same bits for
// any number.
Normals normals(const NormalsInput& in, int threads, NormalsScope scope);

}  // namespace rl::fast
