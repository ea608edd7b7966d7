// Scan conversion on several threads. It must equal ScanConversionStage::run
// (stages/scan_conversion.h) bit for bit: every span, in triangle order, and every count.
#pragma once

#include "pipeline/stages/scan_conversion.h"

namespace rl::fast {

// Contiguous ranges of triangles are scanned at once (scanTriangles), the spans put together
// in triangle order: the result does not depend on the number of threads.
ScanConversion scanConversion(const ScanConversionInput& in, int threads);

}  // namespace rl::fast
