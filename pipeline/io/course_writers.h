// Writers for the course's camera and lighting files: the inverse of the readers of
// course_readers.h, in each layout they read (UFPE, UFRPE and key = value cameras; UFPE,
// UFPE multi-light, UFRPE and key = value lighting), so that an edited scene is saved in the
// layout its file came in.
//
// Numbers are written in the C locale, in the shortest form that reads back as the same
// value (std::to_chars): a camera's doubles come back bit for bit, and so do a lighting's
// floats (read as doubles by the readers, then narrowed). So readCameraFile(writeCameraFile(c,
// L), L) gives c again, -0.0 included; likewise for lighting.
//
// kd is one number when its three channels are equal and three otherwise, in the UFPE
// layouts (which accept both); UFRPE and key = value files always hold three (their readers
// take no scalar kd).
//
// Lights: UFPE and UFRPE files hold exactly one light. A lighting with several
// lights (or none) asked for in one of those layouts is an error that names the multi-light and
// key = value layouts, rather than a file silently written in another layout than asked: the layout
// a file is saved in is the caller's choice. The multi-light layout holds one light or more, key =
// value files one to eight, and only key = value files hold the lecture slides' lighting
// (directional lights, attenuation, spots, emission, one-sided lighting, Blinn-Phong): the other
// layouts refuse a lighting that uses it, naming what they cannot hold.
#pragma once

#include <string>
#include <string_view>

#include "pipeline/core/diagnostics.h"
#include "pipeline/io/course_readers.h"
#include "pipeline/scene/scene.h"

namespace rl {

// The shortest decimal text (C locale, '.' separator, exponent when shorter: "0.1", "1e-07",
// "-0", "600") that parseReal reads back as exactly `value`.
std::string formatExact(double value);
// The same for a float read back through a double: the float's shortest text when it
// survives parseReal and the narrowing (it always does for normal values), else the double's.
std::string formatExact(float value);

// The camera as the text of a file in `layout` (not Auto).
//
// `previous` is the file's current text, if any. Its line ending is kept: "\r\n" when it has
// one, "\n" otherwise. For a key = value file, its lines whose key is one of the camera's
// (C, N, V, d, hx, hy) are replaced in place; every other line (the lighting's keys of a file
// shared by both, a dummy U, blank lines) is kept as it is; camera keys it lacks are added
// at its end. A line layout is written whole.
Result<std::string> writeCameraFile(const CourseCamera& camera, CameraLayout layout,
                                    std::string_view previous = {});

// The lighting as the text of a file in `layout` (not Auto); `previous` as for the camera,
// with the lighting's keys (Iamb, Ka, Il, Pl, Kd, Od, Ks, eta).
Result<std::string> writeLightingFile(const CourseLighting& lighting, LightingLayout layout,
                                      std::string_view previous = {});

}  // namespace rl
