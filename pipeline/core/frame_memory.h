// Rendering frame after frame allocates and frees the same large arrays (projected
// vertices, spans, bins). By default the C library hands each one above 128 KiB back to
// the system when freed and asks for fresh pages for the next frame, which then cost a page
// fault each. Called once at start-up, keepFrameMemory() has such arrays (up to 32 MiB
// each, the most the C library allows) kept in the heap and reused, and the heap's free
// top kept rather than trimmed. Memory does not grow: each frame reuses what the last one
// freed. Does nothing where the C library has no such settings.
#pragma once

namespace rl {

void keepFrameMemory();

}  // namespace rl
