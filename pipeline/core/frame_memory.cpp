#include "frame_memory.h"

// Any C library header defines __GLIBC__ (through <features.h>); without one the test below
// would be false and the settings silently left out.
#include <cstdlib>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace rl {

void keepFrameMemory() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
    mallopt(M_TRIM_THRESHOLD, 512 * 1024 * 1024);
#endif
}

}  // namespace rl
