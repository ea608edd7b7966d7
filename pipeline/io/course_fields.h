// What the course readers share, internal to io/ (other folders include course_readers.h):
// the number tokens and their messages, the field lines of the line layouts, the course's
// camera and lighting built from fields, and the tokens of .byu files, all defined in
// course_fields.cpp; then the readers one family's file calls in another's.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pipeline/io/course_readers.h"

namespace rl::course_io {

// ---- number tokens and their messages

// The counts a field accepts, for messages: "3 numbers", "1 or 3 numbers".
Message countText(unsigned counts);
// The largest count a field accepts.
int maxCount(unsigned counts);
// "1 line", "8 lines"; "1 value", "8 values": pieces of many messages.
Message linesText(long long n);
Message valuesText(long long n);
Message verticesText(long long n);
Message trianglesText(long long n);
Message numbersText(long long n);
// A field's name in messages: "N", or "Pl of light 2" for a light's field.
Message fieldName(const FieldSpec& field);
// The token without one leading sign.
std::string_view withoutSign(std::string_view token);
// Why a token is not a number, for the end of an error message: "found 'x'" and a hint.
Message whyNotNumber(std::string_view token);
// "a, b and c".
Message listText(const std::vector<Message>& items);
Message listText(const std::vector<std::string>& names);  // names shown as they are: "C", "hx"

// The counts of a FieldSpec or a key: bit k set when k numbers are accepted.
inline constexpr unsigned kOne = 1u << 1;
inline constexpr unsigned kTwo = 1u << 2;
inline constexpr unsigned kThree = 1u << 3;
inline constexpr unsigned kFour = 1u << 4;

// The layouts' descriptions (cameraLayoutDescription ...) as message templates.
MessageTemplate cameraLayoutText(CameraLayout layout);
MessageTemplate lightingLayoutText(LightingLayout layout);

// ---- field lines

// The fields of readFieldLines, without the check for lines after the last one.
Result<std::vector<FieldValue>> readFields(LineScanner& scanner, std::span<const FieldSpec> fields,
                                           Diagnostics& diagnostics);
// A warning for the lines after the `lineCount` lines of a layout, if any. `what` names those
// lines: "the camera's %1"_msg.
void warnTrailingLines(LineScanner& scanner, MessageTemplate what, long long lineCount,
                       Diagnostics& diagnostics);

// ---- the camera and the lighting, from the fields of any layout

dvec3 vec3Of(const FieldValue& f);
// An RGB triple, or one number for all three channels.
vec3 rgbOf(const FieldValue& f);

// One of the numbers of a field: d of "d hx hy" is {field, 0}.
struct Scalar {
    const FieldValue* field;
    std::size_t index;
};

CourseCamera makeCamera(const FieldValue& c, const FieldValue& n, const FieldValue& v, Scalar d,
                        Scalar hx, Scalar hy);

// The fields of a lighting file, whatever its layout, and the names the file gives them.
struct LightingFields {
    const FieldValue* ka = nullptr;
    const FieldValue* ia = nullptr;
    const FieldValue* kd = nullptr;
    const FieldValue* od = nullptr;
    const FieldValue* ks = nullptr;
    const FieldValue* n = nullptr;
    std::vector<std::pair<const FieldValue*, const FieldValue*>> lights;  // Pl, Il
};
struct LightingNames {
    const char* ka;
    const char* ia;
    const char* kd;
    const char* od;
    const char* ks;
    const char* il;
    const char* n;
};

// Values outside the ranges the course gives (seed 004) still render, with a warning. `light`
// numbers the light of an Il when the file has several (0 otherwise).
void checkRange(const FieldValue& field, const std::string& name, std::size_t light, double low,
                double high, const char* range, Diagnostics& diagnostics);

// The lighting, with the course's range warnings, in the order ka, Ia, kd, Od, ks, Il, n.
CourseLighting makeLighting(const LightingFields& f, const LightingNames& names,
                            Diagnostics& diagnostics);

// ---- .byu tokens

// Reads a header count: a non-negative integer; `what` is "vertices"_msg ...
Result<long long> readCount(const LineScanner& scanner, const Token& token, const Message& what);
bool isComment(const Token& token);
Error commentError(const LineScanner& scanner, const Token& token, const Message& expected);

// Coordinate `axis` (0 for x) of the point `which` ("vertex 3 of 8"): a number.
Result<double> readCoordinate(const LineScanner& scanner, const Token& token, int axis,
                              const Message& which);
// The x y z of a point on a line of its own (a vertex, a control point).
Result<dvec3> readPointLine(const LineScanner& scanner, const TextLine& line, const Message& which);

// The lines holding values after their first three (x y z, or a triangle's three indices),
// for one warning after the last.
struct ExtraValues {
    long long lines = 0;
    SourceLocation first;

    void note(const LineScanner& scanner, const TextLine& line);
    void warn(Diagnostics& diagnostics) const;
};

// "used by no triangle" and "no triangles" warnings.
void warnUnusedVertices(const Mesh& mesh, const std::vector<unsigned char>& used,
                        Diagnostics& diagnostics);

// ---- key = value files, for readCameraFile and readLightingFile (course_key_value.cpp)

Result<CourseCamera> readKeyValueCamera(std::string_view text, const std::string& fileName,
                                        Diagnostics& diagnostics);
Result<CourseLighting> readKeyValueLighting(std::string_view text, const std::string& fileName,
                                            Diagnostics& diagnostics);

// ---- the .byu flavours that readByuObject (course_readers.cpp) tells apart

// A header of four integers, "parts vertices polygons edges" (movie_byu.cpp).
bool isMovieByuHeader(const TextLine& line);
// An original Movie.BYU file after its header, each polygon fan-triangulated
// (movie_byu.cpp). `summary` receives "1 part, 8 vertices and 6 polygons" for the note.
Result<Mesh> readMovieByu(LineScanner& scanner, const TextLine& header, Message& summary,
                          Diagnostics& diagnostics);
// A course Bezier surface after its lines "m n" and E, evaluated on an E x E grid
// (bezier_surface.cpp).
Result<Mesh> readBezierSurface(LineScanner& scanner, const TextLine& header,
                               const TextLine& evaluationsLine, Diagnostics& diagnostics);

}  // namespace rl::course_io
