// Readers for the course files of seeds 000 and 004:
// - camera (UFPE, four lines): C; N; V; "d hx hy";
// - lighting (UFPE, eight lines): Pl; ka; Ia; kd (one number or an RGB triple); Od; ks; Il; n;
// - object (.byu): "vertices triangles", then the vertices (x y z), then the triangles
//   (three 1-based indices).
// Quirks of real files that must load (CRLF, blank lines, TABs, odd exponents, data after
// the declared counts ...) are listed in course-formats.md. Each bad input gives an Error
// "file:line:col: expected ..., found ..."; each tolerated oddity adds a warning.
//
// The camera and lighting readers are built on one layout reader (readFieldLines): a file
// variant is a list of FieldSpecs, so further layouts reuse it without a new parser.
//
// Course file variants (UFPE and UFRPE, issue 4): readCameraFile and readLightingFile read
// every layout below, detected or chosen; readByuObject reads the three .byu flavours.
//   Camera:   UFPE   C; N; V; d hx hy          (3, 3, 3, 3 numbers a line)
//             UFRPE  N; V; d; hx; hy; C        (3, 3, 1, 1, 1, 3)
//             UFRPE  C; N; V; hx hy; d         (3, 3, 3, 2, 1)
//             key = value: C, N, V, d, hx, hy in any order (a dummy U is ignored)
//   Lighting: UFPE   Pl; ka; Ia; kd; Od; ks; Il; n        (3, 1, 3, 1 or 3, 3, 1, 3, 1)
//             UFPE multi-light  ka; Ia; kd; Od; ks; n; L; then L times Pl; Il
//                                                  (1, 3, 1 or 3, 3, 1, 1, 1, then 3, 3 ...)
//             UFRPE  Iamb; Ka; Il; Pl; Kd; Od; Ks; n      (3, 1, 3, 3, 3, 3, 1, 1)
//             key = value: Iamb, Ka, Il, Pl, Kd, Od, Ks, eta in any order; optionally
//                    the lecture slides' lighting (seed 003): Ke = r g b (emission),
//                    two_sided = 1|0, blinn = 1|0, Pl = x y z w (w = 0: directional),
//                    atten = kc kl kq, spot_dir = x y z, spot_cutoff = degrees,
//                    spot_exp = e, and lights 2 to 8 as Pl2, Il2, atten2 ...
//   Camera and lighting may share one key = value file: each reader skips the other's keys.
//
// Detection rule (no field says which flavour a file is):
//   1. key = value when a non-blank line contains '='.
//   2. Otherwise by the count of numbers on each non-blank line (its leading numeric tokens):
//      the layout whose lines the file fits exactly (layouts never share a profile: the camera
//      layouts differ in length; UFPE and UFRPE lighting differ on lines 6 and 7, and a
//      multi-light file starts with a line of one number).
//   3. Otherwise the one layout the file misses by a single line (one line with other counts,
//      or one line missing or extra), so that its reader names that line in its message.
//   4. Otherwise an error naming the layouts tried and the counts the file has.
// Every successful read notes which flavour was assumed and why; a layout given by the
// caller skips detection.
//
// One file per layout family: course_camera_lighting.cpp (the line layouts, their names and
// the detection), course_key_value.cpp, byu_mesh.cpp, bezier_surface.cpp, movie_byu.cpp, and
// course_readers.cpp (readByuObject); course_fields.h holds what they share.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/core/diagnostics.h"
#include "pipeline/io/text_scanner.h"
#include "pipeline/scene/scene.h"

namespace rl {

// One line of a line-oriented layout: a name for messages and how many numbers it holds.
struct FieldSpec {
    std::string_view name;        // "N", "d hx hy", "kd"
    MessageTemplate description;  // "the view direction"_msg
    unsigned counts;              // bit k set: k numbers are accepted (1u << 3 | 1u << 1)
    std::size_t light = 0;        // a light's field in a multi-light file: "Pl of light 2"
};

struct FieldValue {
    std::vector<double> values;
    std::vector<SourceLocation> where;  // one location per value
    SourceLocation line;                // the start of the line
};

// Reads one field per non-blank line, in order. Extra numbers on a line and lines after
// the last field are warnings; a missing line, a token that is not a number, or too few
// numbers are errors. `what` names the layout's lines in messages: "the camera's %1"_msg, %1
// being "4 lines".
Result<std::vector<FieldValue>> readFieldLines(LineScanner& scanner,
                                               std::span<const FieldSpec> fields,
                                               MessageTemplate what, Diagnostics& diagnostics);

// The lighting of a course scene: the material of the object, the ambient light and the
// point lights.
struct CourseLighting {
    Material material;
    vec3 ambientIntensity = vec3(0.0f);  // Ia
    std::vector<Light> lights;
    // The lecture slides' options (seed 003), which only key = value files can write:
    // two-sided lighting (the course's N turned toward the viewer) and the highlight's model.
    bool twoSided = true;
    SpecularModel specular = SpecularModel::Phong;
};

Result<CourseCamera> readCourseCamera(std::string_view text, const std::string& fileName,
                                      Diagnostics& diagnostics);
Result<CourseLighting> readCourseLighting(std::string_view text, const std::string& fileName,
                                          Diagnostics& diagnostics);
Result<Mesh> readByuMesh(std::string_view text, const std::string& fileName,
                         Diagnostics& diagnostics);

// ---------------------------------------------------------------------------------------
// Course file variants. readCourseCamera and readCourseLighting above stay the UFPE readers
// (no detection, no note); the readers below take a layout, Auto by default.

enum class CameraLayout : std::uint8_t {
    Auto,      // detected by the rule above
    Ufpe,      // C; N; V; d hx hy
    Ufrpe6,    // N; V; d; hx; hy; C
    Ufrpe5,    // C; N; V; hx hy; d
    KeyValue,  // C = x y z, N = ..., V = ..., d = ..., hx = ..., hy = ...
};
inline constexpr CameraLayout kCameraLayouts[] = {CameraLayout::Auto, CameraLayout::Ufpe,
                                                  CameraLayout::Ufrpe6, CameraLayout::Ufrpe5,
                                                  CameraLayout::KeyValue};

enum class LightingLayout : std::uint8_t {
    Auto,       // detected by the rule above
    Ufpe,       // Pl; ka; Ia; kd; Od; ks; Il; n
    UfpeMulti,  // ka; Ia; kd; Od; ks; n; L; then L times Pl; Il
    Ufrpe,      // Iamb; Ka; Il; Pl; Kd; Od; Ks; n
    KeyValue,   // Iamb = r g b, Ka = ..., Il, Pl, Kd, Od, Ks, eta
};
inline constexpr LightingLayout kLightingLayouts[] = {
    LightingLayout::Auto, LightingLayout::Ufpe, LightingLayout::UfpeMulti, LightingLayout::Ufrpe,
    LightingLayout::KeyValue};

// Short names for command lines and settings: "auto", "ufpe", "ufrpe6", "ufrpe5", "keyvalue";
// "auto", "ufpe", "multi", "ufrpe", "keyvalue".
const char* cameraLayoutName(CameraLayout layout);
const char* lightingLayoutName(LightingLayout layout);
std::optional<CameraLayout> cameraLayoutFromName(std::string_view name);
std::optional<LightingLayout> lightingLayoutFromName(std::string_view name);
// For people: "UFPE (C; N; V; d hx hy)", "key = value", "detected from the file" ...
const char* cameraLayoutDescription(CameraLayout layout);
const char* lightingLayoutDescription(LightingLayout layout);

// The lights a key = value lighting file holds: Pl, Pl2 ... Pl8 (OpenGL's minimum, seed 003).
inline constexpr std::size_t kMaxKeyValueLights = 8;
// A key as written for light k (0 the first): "Pl", "Pl2" ...
std::string lightKeyName(std::string_view key, std::size_t light);

// A key of key = value lighting files, in any case: Iamb, Ka, Il, Pl, Kd, Od, Ks, eta, the
// lecture slides' Ke, two_sided, blinn, atten, spot_dir, spot_cutoff, spot_exp, and the
// per-light ones numbered for lights 1 to 8 (Pl2, atten3 ...).
bool isLightingKey(std::string_view key);

// The layout the detection rule chooses for a text, or nullopt when none fits.
std::optional<CameraLayout> detectCameraLayout(std::string_view text);
std::optional<LightingLayout> detectLightingLayout(std::string_view text);

// The camera (lighting) in the given layout, or in the detected one for Auto. A successful
// read adds a note on the file naming the layout and why. A layout given by the caller that
// does not fit gives that layout's error, followed by the layout detection would choose.
Result<CourseCamera> readCameraFile(std::string_view text, const std::string& fileName,
                                    Diagnostics& diagnostics,
                                    CameraLayout layout = CameraLayout::Auto);
Result<CourseLighting> readLightingFile(std::string_view text, const std::string& fileName,
                                        Diagnostics& diagnostics,
                                        LightingLayout layout = LightingLayout::Auto);

// A .byu object in any of its three flavours, told apart by the header:
// - "vertices triangles": the course's triangle mesh (readByuMesh, no note);
// - "m n", then a line of one number: the course's Bezier surface of degrees m x n, the
//   number of evaluations per direction E, then (m+1)(n+1) control points row by row;
//   evaluated on an E x E grid into E^2 vertices and 2 (E-1)^2 triangles, with a note;
// - "parts vertices polygons edges": the original Movie.BYU format (a "first last" polygon
//   range per part, the vertices, then the polygons' 1-based indices, the last of each
//   negated), every polygon fan-triangulated, with a note.
Result<Mesh> readByuObject(std::string_view text, const std::string& fileName,
                           Diagnostics& diagnostics);

// Limits of the Bezier surfaces readByuObject evaluates (the course uses degrees up to 3
// and tens of evaluations).
inline constexpr int kMaxBezierDegree = 64;
inline constexpr int kMaxBezierEvaluations = 1000;

}  // namespace rl
