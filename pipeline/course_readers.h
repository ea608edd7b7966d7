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
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "diagnostics.h"
#include "scene.h"
#include "text_scanner.h"

namespace rl {

// One line of a line-oriented layout: a name for messages and how many numbers it holds.
struct FieldSpec {
    std::string_view name;         // "N", "d hx hy", "kd"
    std::string_view description;  // "the view direction"
    unsigned counts;               // bit k set: k numbers are accepted (1u << 3 | 1u << 1)
};

struct FieldValue {
    std::vector<double> values;
    std::vector<SourceLocation> where;  // one location per value
    SourceLocation line;                // the start of the line
};

// Reads one field per non-blank line, in order. Extra numbers on a line and lines after
// the last field are warnings; a missing line, a token that is not a number, or too few
// numbers are errors. `what` names the file's role in messages ("camera").
Result<std::vector<FieldValue>> readFieldLines(LineScanner& scanner,
                                               std::span<const FieldSpec> fields,
                                               std::string_view what, Diagnostics& diagnostics);

// The lighting of a course scene: the material of the object, the ambient light and the
// point lights.
struct CourseLighting {
    Material material;
    vec3 ambientIntensity = vec3(0.0f);  // Ia
    std::vector<Light> lights;
};

Result<CourseCamera> readCourseCamera(std::string_view text, const std::string& fileName,
                                      Diagnostics& diagnostics);
Result<CourseLighting> readCourseLighting(std::string_view text, const std::string& fileName,
                                          Diagnostics& diagnostics);
Result<Mesh> readByuMesh(std::string_view text, const std::string& fileName,
                         Diagnostics& diagnostics);

}  // namespace rl
