// Runs the seven stages in lecture order on a scene and keeps every output in a
// FrameTrace. renderFrame runs the fast paths (fast/: several threads, vector kernels,
// bands); traceFrame runs the lecture's stages (stages/) with a RecordingProbe that logs what
// happens at one pixel or to one triangle, on one thread, in drawing order. The two give the
// same bits. Both are pure functions of the scene: no global state, so two renders can run at
// the same time.
#pragma once

#include <memory>

#include "pipeline/core/diagnostics.h"
#include "pipeline/render/frame_trace.h"
#include "pipeline/scene/scene.h"
#include "pipeline/stages/probe.h"
#include "pipeline/stages/shading.h"

namespace rl {

struct ShadingOptions {
    bool keepNormals = false;  // also keep the unit normal used at each pixel
};

struct RenderOptions {
    ShadingOptions shading;
    // Threads for the stages that share out their work (all but the first two and normals): 0
    // for one per core, at most kMaxThreads. The image does not depend on it.
    int threads = 0;
    // Whether the frame keeps its z-buffer (DepthTest::depth): the window's views and a
    // z-buffer image read it; an image alone does not, and then each thread keeps only the
    // depths of the band of rows it is testing, in the cache. The image is the same.
    bool keepDepth = true;
    // Whether the frame keeps, per pixel, the triangle that won it and its barycentrics
    // (DepthTest::triangle and barycentric): the window's views, the normals image and the
    // painter's comparison read them. Without them (and without the z-buffer or the normals),
    // when fast::shadeInBands says it pays, the depth test and shading run together chunk by
    // chunk (fast::depthTestAndShading) and the frame keeps the image and which pixels a
    // triangle covered. The image is the same.
    bool keepFragments = true;
    // The rows of the bands a chunk is then tested and shaded in (bandRowsFor, parallel.h: 0
    // for kRowChunk). Fewer rows take less of the cache a thread has. The image is the same.
    int bandRows = 0;
    // Whether the frame keeps what only the window's views read: every triangle's and every
    // vertex's normal (the normals view's hairs), and each vertex's NDC and unsnapped screen
    // position (the projection view). Without it, each draw gets only the normals its shading
    // reads (normalsRead: a flat sphere, say, sums no vertex normals; the normals image keeps
    // them all), and projection only the snapped positions. The image is the same.
    // A traced frame (traceFrame) runs the lecture's stages, which keep everything.
    bool keepForViews = true;
};

// Buffers kept from one frame to the next, so that rendering the same size again costs no
// new memory (and no page faults). A buffer still held by an earlier frame's trace (the
// window showing it, say) is left alone and a new one is made; so is a z-buffer for a frame
// that keeps it after one that did not (RenderOptions::keepDepth), cleared whole.
struct RenderContext {
    std::shared_ptr<DepthTest> depth;
    std::shared_ptr<Shading> shading;
    // The scene whose lights were last checked against its surfaces (lightsOnSurfaces) and the
    // warnings found: the same scene rendered again is not checked again.
    std::weak_ptr<const Scene> lightsChecked;
    Diagnostics lightWarnings;
};

Result<FrameTrace> renderFrame(std::shared_ptr<const Scene> scene,
                               const RenderOptions& options = {}, RenderContext* context = nullptr);
Result<FrameTrace> traceFrame(std::shared_ptr<const Scene> scene, const RenderOptions& options,
                              RecordingProbe& probe);

}  // namespace rl
