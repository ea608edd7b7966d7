#include "pipeline_messages.h"

#include <QCoreApplication>
#include <QStringList>

namespace rasterlab {

namespace {

// The templates for lupdate, each once, under the first file that writes it. A template
// written in the sources and missing here, or listed here and written nowhere, fails
// tests/tst_pipeline_messages.cpp, which prints the lines to add or remove.
const char* const kCatalogue[] = {
    // pipeline/io/bezier_surface.cpp
    QT_TRANSLATE_NOOP("Messages",
                      "expected the degree %1 of the Bezier surface (an integer from 1 to %2), "
                      "found %3"),
    QT_TRANSLATE_NOOP("Messages", "ignored %1 after the Bezier surface's two degrees"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected the number of evaluations per direction (an integer from 2 to "
                      "%1), found %2"),
    QT_TRANSLATE_NOOP("Messages",
                      "the header declares a Bezier surface of degrees %1 x %2, so %3 control "
                      "points (one a line), but only %4"),
    QT_TRANSLATE_NOOP("Messages", "%1 line follows"),
    QT_TRANSLATE_NOOP("Messages", "%1 lines follow"),
    QT_TRANSLATE_NOOP("Messages", "control point (%1, %2)"),
    QT_TRANSLATE_NOOP("Messages", "ignored %1 after the %2 control points of the Bezier surface"),
    // pipeline/io/byu_mesh.cpp
    QT_TRANSLATE_NOOP("Messages", "the header 'vertices triangles' (two integers)"),
    QT_TRANSLATE_NOOP("Messages", "expected %1, found the end of the file"),
    QT_TRANSLATE_NOOP("Messages",
                      "this is an original Movie.BYU file (header 'parts vertices polygons "
                      "edges'), not the course's .byu format (header 'vertices triangles')"),
    QT_TRANSLATE_NOOP("Messages", "vertices"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected the number of triangles after the number of vertices, found the "
                      "end of the line"),
    QT_TRANSLATE_NOOP("Messages", "triangles"),
    QT_TRANSLATE_NOOP("Messages", "ignored %1 after the header's two counts"),
    QT_TRANSLATE_NOOP("Messages",
                      "this looks like a course Bezier surface (degrees %1 x %2, %3 evaluations "
                      "per direction), not a triangle mesh"),
    QT_TRANSLATE_NOOP("Messages", "the header declares %1 and %2 (%3), but only %4"),
    QT_TRANSLATE_NOOP("Messages", "%1 line"),
    QT_TRANSLATE_NOOP("Messages", "%1 lines"),
    QT_TRANSLATE_NOOP("Messages", "vertex %1 of %2"),
    QT_TRANSLATE_NOOP("Messages", "triangle %1 of %2 (three vertex indices)"),
    QT_TRANSLATE_NOOP("Messages", "expected 3 vertex indices for triangle %1 of %2, found %3"),
    QT_TRANSLATE_NOOP("Messages",
                      "polygon %1 has %2 vertex indices, but only triangles (3 indices) are "
                      "supported"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected a vertex index (a positive integer) for triangle %1, found %2"),
    QT_TRANSLATE_NOOP("Messages",
                      "triangle %1 refers to vertex %2, but indices are 1-based (1 to %3)"),
    QT_TRANSLATE_NOOP("Messages", "triangle %1 refers to vertex %2, but the file declares only %3"),
    QT_TRANSLATE_NOOP("Messages",
                      "ignored %1 after the declared %2 and %3 (the header's counts may be "
                      "wrong, or a second object follows)"),
    // pipeline/io/course_camera_lighting.cpp
    QT_TRANSLATE_NOOP("Messages", "the camera position"),
    QT_TRANSLATE_NOOP("Messages", "the view direction"),
    QT_TRANSLATE_NOOP("Messages", "the up vector"),
    QT_TRANSLATE_NOOP("Messages", "the projection distance and half-sizes"),
    QT_TRANSLATE_NOOP("Messages", "the projection distance"),
    QT_TRANSLATE_NOOP("Messages", "the horizontal half-size of the window"),
    QT_TRANSLATE_NOOP("Messages", "the vertical half-size of the window"),
    QT_TRANSLATE_NOOP("Messages", "the half-sizes of the window"),
    QT_TRANSLATE_NOOP("Messages", "the light position"),
    QT_TRANSLATE_NOOP("Messages", "the ambient coefficient"),
    QT_TRANSLATE_NOOP("Messages", "the ambient light colour"),
    QT_TRANSLATE_NOOP("Messages", "the diffuse coefficient"),
    QT_TRANSLATE_NOOP("Messages", "the diffuse colour of the object"),
    QT_TRANSLATE_NOOP("Messages", "the specular coefficient"),
    QT_TRANSLATE_NOOP("Messages", "the light colour"),
    QT_TRANSLATE_NOOP("Messages", "the specular exponent"),
    QT_TRANSLATE_NOOP("Messages", "the number of lights"),
    QT_TRANSLATE_NOOP("Messages", "the diffuse coefficient of each channel"),
    QT_TRANSLATE_NOOP("Messages", "the camera's %1"),
    QT_TRANSLATE_NOOP("Messages", "the lighting's %1"),
    QT_TRANSLATE_NOOP("Messages", "UFPE (C; N; V; d hx hy)"),
    QT_TRANSLATE_NOOP("Messages", "UFRPE (N; V; d; hx; hy; C)"),
    QT_TRANSLATE_NOOP("Messages", "UFRPE (C; N; V; hx hy; d)"),
    QT_TRANSLATE_NOOP("Messages", "key = value"),
    QT_TRANSLATE_NOOP("Messages", "detected from the file"),
    QT_TRANSLATE_NOOP("Messages", "UFPE (Pl; ka; Ia; kd; Od; ks; Il; n)"),
    QT_TRANSLATE_NOOP("Messages", "UFPE multi-light (ka; Ia; kd; Od; ks; n; L; L times Pl; Il)"),
    QT_TRANSLATE_NOOP("Messages", "UFRPE (Iamb; Ka; Il; Pl; Kd; Od; Ks; n)"),
    QT_TRANSLATE_NOOP("Messages", "a UFPE camera, C; N; V; d hx hy"),
    QT_TRANSLATE_NOOP("Messages", "a UFRPE camera, N; V; d; hx; hy; C"),
    QT_TRANSLATE_NOOP("Messages", "a UFRPE camera, C; N; V; hx hy; d"),
    QT_TRANSLATE_NOOP("Messages", "a key = value camera"),
    QT_TRANSLATE_NOOP("Messages", "a camera"),
    QT_TRANSLATE_NOOP("Messages", "a UFPE lighting file, Pl; ka; Ia; kd; Od; ks; Il; n"),
    QT_TRANSLATE_NOOP("Messages",
                      "a UFPE multi-light lighting file, ka; Ia; kd; Od; ks; n; L; L times Pl; Il"),
    QT_TRANSLATE_NOOP("Messages", "a UFRPE lighting file, Iamb; Ka; Il; Pl; Kd; Od; Ks; n"),
    QT_TRANSLATE_NOOP("Messages", "a key = value lighting file"),
    QT_TRANSLATE_NOOP("Messages", "a lighting file"),
    QT_TRANSLATE_NOOP("Messages", "the 1 line has %1"),
    QT_TRANSLATE_NOOP("Messages", "the %1 lines have %2 numbers"),
    QT_TRANSLATE_NOOP("Messages", "line %1 has %2 where %3 needs %4"),
    QT_TRANSLATE_NOOP("Messages", "its last line, %1, is missing"),
    QT_TRANSLATE_NOOP("Messages", "line %1 is one line more"),
    QT_TRANSLATE_NOOP("Messages", "no line contains '=' and %1"),
    QT_TRANSLATE_NOOP("Messages",
                      "%1: its first %2 lines fit this layout, and the rest is left over"),
    QT_TRANSLATE_NOOP("Messages", "%1, as in that layout"),
    QT_TRANSLATE_NOOP("Messages", "%1: no layout fits exactly, and this one is one line away (%2)"),
    QT_TRANSLATE_NOOP("Messages", "one line away from %1"),
    QT_TRANSLATE_NOOP("Messages", "an empty file"),
    QT_TRANSLATE_NOOP("Messages", "only blank lines"),
    QT_TRANSLATE_NOOP("Messages", "1 line with %1"),
    QT_TRANSLATE_NOOP("Messages", "%1 lines with %2 numbers"),
    QT_TRANSLATE_NOOP("Messages", "%1 (%2)"),
    QT_TRANSLATE_NOOP("Messages", "lines contain '='"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected %1 or key = value, found %2 (if the layout is known, choose it "
                      "by hand: --camera-format / --lighting-format, or File > Course File "
                      "Layouts)"),
    QT_TRANSLATE_NOOP("Messages",
                      "a camera in one of the layouts UFPE (C; N; V; d hx hy), UFRPE (N; V; d; "
                      "hx; hy; C), UFRPE (C; N; V; hx hy; d)"),
    QT_TRANSLATE_NOOP("Messages",
                      "lighting in one of the layouts UFPE (Pl; ka; Ia; kd; Od; ks; Il; n), UFPE "
                      "multi-light (ka; Ia; kd; Od; ks; n; L; L times Pl; Il), UFRPE (Iamb; Ka; "
                      "Il; Pl; Kd; Od; Ks; n)"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected the number of lights L (a positive whole number), found %1"),
    QT_TRANSLATE_NOOP("Messages",
                      "L = %1 lights need twice as many lines after it (Pl and Il for each), but "
                      "only %2"),
    QT_TRANSLATE_NOOP("Messages",
                      "L = %1 lights need %2 lines after it (Pl and Il for each), but only %3"),
    QT_TRANSLATE_NOOP("Messages", "%1; the layout was set to %2"),
    QT_TRANSLATE_NOOP("Messages", "%1; the layout was set to %2, but the file looks like %3 (%4)"),
    QT_TRANSLATE_NOOP("Messages", "the layout was chosen, not detected"),
    QT_TRANSLATE_NOOP("Messages", "read as %1 (%2)"),
    // pipeline/io/course_fields.cpp
    QT_TRANSLATE_NOOP("Messages", "%1 or %2 numbers"),
    QT_TRANSLATE_NOOP("Messages", "%1 value"),
    QT_TRANSLATE_NOOP("Messages", "%1 values"),
    QT_TRANSLATE_NOOP("Messages", "%1 vertex"),
    QT_TRANSLATE_NOOP("Messages", "%1 vertices"),
    QT_TRANSLATE_NOOP("Messages", "%1 triangle"),
    QT_TRANSLATE_NOOP("Messages", "%1 triangles"),
    QT_TRANSLATE_NOOP("Messages", "%1 number"),
    QT_TRANSLATE_NOOP("Messages", "%1 numbers"),
    QT_TRANSLATE_NOOP("Messages", "%1 of light %2"),
    QT_TRANSLATE_NOOP("Messages", "found %1 (separate the values with spaces, not commas)"),
    QT_TRANSLATE_NOOP("Messages", "found %1 (the decimal separator is '.')"),
    QT_TRANSLATE_NOOP("Messages", "found %1, which is out of range"),
    QT_TRANSLATE_NOOP("Messages", "found %1, which is not a finite number"),
    QT_TRANSLATE_NOOP("Messages", "found %1"),
    QT_TRANSLATE_NOOP("Messages", "%1 and %2"),
    QT_TRANSLATE_NOOP("Messages", "%1, %2"),
    QT_TRANSLATE_NOOP("Messages", "expected %1, %2 (%3), found the end of the file"),
    QT_TRANSLATE_NOOP("Messages", "expected a number for %1, %2"),
    QT_TRANSLATE_NOOP("Messages", "expected %1 for %2, found %3"),
    QT_TRANSLATE_NOOP("Messages", "ignored %1 after %2"),
    QT_TRANSLATE_NOOP("Messages", "%1 = %2 is outside %3, the range the course gives for it"),
    QT_TRANSLATE_NOOP("Messages",
                      "%1 of light %2 = %3 is outside %4, the range the course gives for it"),
    QT_TRANSLATE_NOOP("Messages",
                      "%1 = %2 is not positive: (R.V)^n then makes no highlight (it is 1 "
                      "everywhere for n = 0 and grows without bound where R.V nears 0 for n < 0, "
                      "where the specular term is left out)"),
    QT_TRANSLATE_NOOP("Messages", "expected the number of %1 (a non-negative integer), found %2"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected %1, found a comment (%2), but .byu files have no comments"),
    QT_TRANSLATE_NOOP("Messages", "expected a number for the %1 coordinate of %2, %3"),
    QT_TRANSLATE_NOOP("Messages", "%1 (x y z)"),
    QT_TRANSLATE_NOOP("Messages", "expected 3 coordinates for %1, found %2"),
    QT_TRANSLATE_NOOP("Messages", "ignored extra values at the end of %1 (the first is here)"),
    QT_TRANSLATE_NOOP("Messages", "%1 vertex of %2 is not used by any triangle"),
    QT_TRANSLATE_NOOP("Messages", "%1 vertices of %2 are not used by any triangle"),
    QT_TRANSLATE_NOOP("Messages", "the object has no triangles"),
    // pipeline/io/course_key_value.cpp
    QT_TRANSLATE_NOOP("Messages",
                      "the light position (x y z, or x y z w: w = 0 for a directional light)"),
    QT_TRANSLATE_NOOP("Messages", "the emission of the object"),
    QT_TRANSLATE_NOOP("Messages", "two-sided lighting, 1 or 0"),
    QT_TRANSLATE_NOOP("Messages", "Blinn-Phong highlights, 1 or 0"),
    QT_TRANSLATE_NOOP("Messages", "the attenuation kc kl kq"),
    QT_TRANSLATE_NOOP("Messages", "the spot direction"),
    QT_TRANSLATE_NOOP("Messages", "the spot cutoff angle in degrees"),
    QT_TRANSLATE_NOOP("Messages", "the spot exponent"),
    QT_TRANSLATE_NOOP("Messages", "%1; optionally %2"),
    QT_TRANSLATE_NOOP("Messages", "%1; optionally %2; Pl2, Il2 ... for lights 2 to %3"),
    QT_TRANSLATE_NOOP("Messages", "expected 'key = value', found a line without '=' (%1 ...)"),
    QT_TRANSLATE_NOOP("Messages", "expected 'key = value', found a line without '=' (%1)"),
    QT_TRANSLATE_NOOP("Messages", "expected a key before '=', found nothing"),
    QT_TRANSLATE_NOOP("Messages", "expected one key before '=', found %1"),
    QT_TRANSLATE_NOOP("Messages", "ignored %1: the camera's axes come from N and V"),
    QT_TRANSLATE_NOOP("Messages",
                      "ignored the unknown key %1 (a camera has %2; a lighting file has %3)"),
    QT_TRANSLATE_NOOP("Messages",
                      "ignored the unknown key %1 (a lighting file has %2; a camera has %3)"),
    QT_TRANSLATE_NOOP("Messages", "expected %1 for %2, found none"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected the camera keys %1, found none of them (only lighting file keys)"),
    QT_TRANSLATE_NOOP("Messages", "expected the camera keys %1, found none of them"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected the lighting file keys %1, found none of them (only camera keys)"),
    QT_TRANSLATE_NOOP("Messages", "expected the lighting file keys %1, found none of them"),
    QT_TRANSLATE_NOOP("Messages", "expected a line '%1 = ...' (%2, %3), found no %1"),
    QT_TRANSLATE_NOOP("Messages", "expected lines for %1 (a camera needs %2), found none"),
    QT_TRANSLATE_NOOP("Messages", "expected lines for %1 (a lighting file needs %2), found none"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected each key once, found %1 again (first given on line %2)"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected light %1 (%2, %3) before light %4, found %5 (lights are numbered "
                      "without gaps)"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected a line '%1 = ...' (%2 of light %3), found %4 without it"),
    QT_TRANSLATE_NOOP("Messages", "expected 1 or 0 for %1, found %2"),
    QT_TRANSLATE_NOOP("Messages", "expected %1 coefficients of 0 or more (kc kl kq), found %2"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected %1 with a coefficient above 0, found 0 0 0 (1 / 0 light)"),
    QT_TRANSLATE_NOOP("Messages",
                      "%1 has no effect: a directional light (w = 0) is not attenuated"),
    QT_TRANSLATE_NOOP("Messages", "expected a spot direction other than 0 0 0 for %1"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected %1 from 0 to 90 degrees, or 180 (not a spot), found %2"),
    QT_TRANSLATE_NOOP("Messages", "%1: no %2, the spot points along -z (OpenGL's default)"),
    QT_TRANSLATE_NOOP("Messages", "expected %1 from 0 to 128, found %2"),
    QT_TRANSLATE_NOOP("Messages",
                      "light %1 is not a spot without %2 (0 to 90 degrees): its spot direction "
                      "and exponent are unused"),
    // pipeline/io/course_readers.cpp
    QT_TRANSLATE_NOOP("Messages",
                      "read as an original Movie.BYU file (the header has four integers: parts, "
                      "vertices, polygons, edges): %1, fan-triangulated into %2"),
    QT_TRANSLATE_NOOP("Messages",
                      "read as a course Bezier surface (the header 'm n' is followed by a line "
                      "of one number, the evaluations per direction): degrees %1 x %2, evaluated "
                      "on a %3 x %3 grid into %4 and %5"),
    // pipeline/io/course_writers.cpp
    QT_TRANSLATE_NOOP("Messages",
                      "cannot write the camera: its values must be finite numbers (a course file "
                      "cannot hold nan or inf)"),
    QT_TRANSLATE_NOOP("Messages",
                      "cannot write a camera in the layout 'auto': choose UFPE, UFRPE or key = "
                      "value"),
    QT_TRANSLATE_NOOP("Messages", "an emission (Ke)"),
    QT_TRANSLATE_NOOP("Messages", "one-sided lighting"),
    QT_TRANSLATE_NOOP("Messages", "Blinn-Phong highlights"),
    QT_TRANSLATE_NOOP("Messages", "a directional light (w = 0)"),
    QT_TRANSLATE_NOOP("Messages", "an attenuated light"),
    QT_TRANSLATE_NOOP("Messages", "a spot light"),
    QT_TRANSLATE_NOOP("Messages",
                      "cannot write lighting in the layout 'auto': choose UFPE, UFPE "
                      "multi-light, UFRPE or key = value"),
    QT_TRANSLATE_NOOP("Messages",
                      "cannot write %1 light in the layout %2, which holds exactly one: choose "
                      "the UFPE multi-light layout or key = value"),
    QT_TRANSLATE_NOOP("Messages",
                      "cannot write %1 lights in the layout %2, which holds exactly one: choose "
                      "the UFPE multi-light layout or key = value"),
    QT_TRANSLATE_NOOP("Messages",
                      "cannot write lighting without lights: the UFPE multi-light and key = "
                      "value layouts hold one light or more"),
    QT_TRANSLATE_NOOP("Messages",
                      "cannot write %1 lights in a key = value file, which holds %2 at most (Pl "
                      "to %3)"),
    QT_TRANSLATE_NOOP("Messages",
                      "cannot write %1 in the layout %2, which holds the course's point lights "
                      "only: choose key = value"),
    QT_TRANSLATE_NOOP("Messages",
                      "cannot write the lighting: its values must be finite numbers (a course "
                      "file cannot hold nan or inf)"),
    QT_TRANSLATE_NOOP("Messages", "cannot write lighting in the layout 'auto'"),
    // pipeline/io/hw2_reader.cpp
    QT_TRANSLATE_NOOP("Messages", "%1 argument"),
    QT_TRANSLATE_NOOP("Messages", "%1 arguments"),
    QT_TRANSLATE_NOOP("Messages", "skipped %1 line with the unknown command '%2'"),
    QT_TRANSLATE_NOOP("Messages", "skipped %1 lines with the unknown command '%2'"),
    QT_TRANSLATE_NOOP("Messages", "expected a 'png width height file' command, found none"),
    QT_TRANSLATE_NOOP("Messages", "expected %1 number after '%2' (%3), found %4"),
    QT_TRANSLATE_NOOP("Messages", "expected %1 numbers after '%2' (%3), found %4"),
    QT_TRANSLATE_NOOP("Messages", "expected a number in '%1' (%2), found %3"),
    QT_TRANSLATE_NOOP("Messages", "ignored %1 value after '%2'"),
    QT_TRANSLATE_NOOP("Messages", "ignored %1 values after '%2'"),
    QT_TRANSLATE_NOOP("Messages", "expected a vertex index in '%1', found %2"),
    QT_TRANSLATE_NOOP("Messages",
                      "'%1' refers to vertex %2, but indices start at 1 (or count back from -1, "
                      "the last)"),
    QT_TRANSLATE_NOOP("Messages", "'%2' refers to vertex %3, but only %1 vertex is defined so far"),
    QT_TRANSLATE_NOOP("Messages",
                      "'%2' refers to vertex %3, but only %1 vertices are defined so far"),
    QT_TRANSLATE_NOOP("Messages", "expected %1 vertex index in '%2' (%3), found %4"),
    QT_TRANSLATE_NOOP("Messages", "expected %1 vertex indices in '%2' (%3), found %4"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected the number of subdivisions after '%1', found the end of the line"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected the number of subdivisions (a whole number from 1 to 10) after "
                      "'%1', found %2"),
    QT_TRANSLATE_NOOP("Messages", "expected a 'png width height file' command before '%1'"),
    QT_TRANSLATE_NOOP("Messages",
                      "this command would bring the file to %1 triangles, more than the limit of "
                      "%2 a command file may draw"),
    QT_TRANSLATE_NOOP("Messages", "expected 'png width height file', found %1"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected the image width (a whole number from 1 to 65536), found %1"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected the image height (a whole number from 1 to 65536), found %1"),
    QT_TRANSLATE_NOOP("Messages", "expected an image file name after 'png width height', found %1"),
    QT_TRANSLATE_NOOP("Messages",
                      "the image name %1 reaches into folders: it is written as %2 in the output "
                      "folder"),
    QT_TRANSLATE_NOOP("Messages",
                      "an earlier png command (line %1) names %2 too: this image replaces it"),
    QT_TRANSLATE_NOOP("Messages", "x y z w"),
    QT_TRANSLATE_NOOP("Messages", "x y z"),
    QT_TRANSLATE_NOOP("Messages", "r g b"),
    QT_TRANSLATE_NOOP("Messages", "s t"),
    QT_TRANSLATE_NOOP("Messages", "i1 i2 i3"),
    QT_TRANSLATE_NOOP("Messages",
                      "'trit' needs a texture: expected a 'texture file.png' command before it"),
    QT_TRANSLATE_NOOP("Messages", "subd i1 ... i16"),
    QT_TRANSLATE_NOOP("Messages", "subd i1 ... i10"),
    QT_TRANSLATE_NOOP("Messages", "a11 a12 ... a44, row by row"),
    QT_TRANSLATE_NOOP("Messages", "l r b t n f"),
    QT_TRANSLATE_NOOP("Messages", "'%1' needs l != r, b != t and n != f, found %2 %3 %4 %5 %6 %7"),
    QT_TRANSLATE_NOOP("Messages", "dx dy dz"),
    QT_TRANSLATE_NOOP("Messages", "sx sy sz"),
    QT_TRANSLATE_NOOP("Messages", "degrees"),
    QT_TRANSLATE_NOOP("Messages", "degrees x y z"),
    QT_TRANSLATE_NOOP("Messages", "'rotate' needs an axis, found the zero vector"),
    QT_TRANSLATE_NOOP("Messages", "eye center upx upy upz"),
    QT_TRANSLATE_NOOP("Messages", "expected 'lookat eye center upx upy upz', found %1"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected a number in 'lookat' (eye center upx upy upz), found %1"),
    QT_TRANSLATE_NOOP("Messages",
                      "'lookat' needs an eye apart from the center and an up that is not along "
                      "the line of sight"),
    QT_TRANSLATE_NOOP("Messages", "p1 p2 p3 p4"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected a file name after 'texture', found the end of the line"),
    QT_TRANSLATE_NOOP("Messages", "lx ly lz"),
    QT_TRANSLATE_NOOP("Messages", "'sunlight' needs a direction, found the zero vector"),
    QT_TRANSLATE_NOOP("Messages", "i1"),
    QT_TRANSLATE_NOOP("Messages", "alpha"),
    // pipeline/io/movie_byu.cpp
    QT_TRANSLATE_NOOP("Messages", "parts"),
    QT_TRANSLATE_NOOP("Messages", "polygons"),
    QT_TRANSLATE_NOOP("Messages", "polygon indices (edges)"),
    QT_TRANSLATE_NOOP("Messages", "%1 part"),
    QT_TRANSLATE_NOOP("Messages", "%1 parts"),
    QT_TRANSLATE_NOOP("Messages", "%1 polygon"),
    QT_TRANSLATE_NOOP("Messages", "%1 polygons"),
    QT_TRANSLATE_NOOP("Messages", "%1 polygon index"),
    QT_TRANSLATE_NOOP("Messages", "%1 polygon indices"),
    QT_TRANSLATE_NOOP("Messages", "%1, %2 and %3"),
    QT_TRANSLATE_NOOP("Messages",
                      "the header declares %1 (%2: 2 a part, 3 a vertex, 1 an index), but only %3"),
    QT_TRANSLATE_NOOP("Messages", "more numbers than a file can hold"),
    QT_TRANSLATE_NOOP("Messages", "%1 number follows"),
    QT_TRANSLATE_NOOP("Messages", "%1 numbers follow"),
    QT_TRANSLATE_NOOP("Messages",
                      "the header declares %1 but only %2, fewer than the 3 each polygon needs"),
    QT_TRANSLATE_NOOP("Messages", "the first polygon of part %1"),
    QT_TRANSLATE_NOOP("Messages", "the last polygon of part %1"),
    QT_TRANSLATE_NOOP("Messages", "expected %1 (a positive integer), found %2"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected the polygon range of part %1 within 1 to %2, first <= last, "
                      "found %3 to %4"),
    QT_TRANSLATE_NOOP("Messages", "an index of polygon %1"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected a vertex index (a non-zero integer, negated at the end of a "
                      "polygon) for polygon %1, found %2"),
    QT_TRANSLATE_NOOP("Messages", "polygon %1 starts here, but the header declares only %2"),
    QT_TRANSLATE_NOOP("Messages",
                      "polygon %1 refers to vertex 0, but indices are 1-based (1 to %2)"),
    QT_TRANSLATE_NOOP("Messages", "polygon %1 refers to vertex %2, but the file declares only %3"),
    QT_TRANSLATE_NOOP("Messages", "polygon %1 has %2, but a polygon needs at least 3"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected the last index of polygon %1 to be negative (it ends the "
                      "polygon), found the end of the header's %2"),
    QT_TRANSLATE_NOOP("Messages", "the header declares %1, but its %2 end only %3"),
    QT_TRANSLATE_NOOP("Messages",
                      "ignored %1 after the declared %2 (the header's counts may be wrong, or a "
                      "second object follows)"),
    // pipeline/stages/camera_basis.cpp
    QT_TRANSLATE_NOOP("Messages", "the camera's C, N and V must be finite numbers"),
    QT_TRANSLATE_NOOP("Messages",
                      "N, the view direction, is the zero vector: it must point from the camera "
                      "toward the scene"),
    QT_TRANSLATE_NOOP("Messages",
                      "V, the up vector, is the zero vector: it must say which way is up"),
    QT_TRANSLATE_NOOP("Messages",
                      "d, the distance to the projection plane, is 0: the projection (d/hx) x/z "
                      "would squash every point to the centre"),
    QT_TRANSLATE_NOOP("Messages",
                      "hx, the horizontal half-size of the window, is 0: the projection (d/hx) "
                      "x/z divides by it"),
    QT_TRANSLATE_NOOP("Messages",
                      "hy, the vertical half-size of the window, is 0: the projection (d/hy) y/z "
                      "divides by it"),
    QT_TRANSLATE_NOOP("Messages",
                      "V %1 is parallel to N %2: Gram-Schmidt leaves nothing of V, so 'up' is "
                      "undefined; choose a V that is not along N"),
    QT_TRANSLATE_NOOP("Messages", "hx is negative: the image is mirrored left to right"),
    QT_TRANSLATE_NOOP("Messages", "hy is negative: the image is mirrored top to bottom"),
    QT_TRANSLATE_NOOP("Messages", "d is negative: the image is turned upside down and mirrored"),
    // pipeline/stages/projection.cpp
    QT_TRANSLATE_NOOP("Messages", "the near plane z = %1 and the clip planes"),
    QT_TRANSLATE_NOOP("Messages", "the near plane z = %1"),
    QT_TRANSLATE_NOOP("Messages", "%1 lies wholly behind the near plane"),
    QT_TRANSLATE_NOOP("Messages", "%1 lie wholly behind the near plane"),
    QT_TRANSLATE_NOOP("Messages", "%1 and %2 wholly outside a clip plane"),
    QT_TRANSLATE_NOOP("Messages", "the clip planes or the guard band 2^28 pixels around the image"),
    QT_TRANSLATE_NOOP("Messages", "the guard band 2^28 pixels around the image"),
    QT_TRANSLATE_NOOP("Messages", "%1 lie wholly outside a clip plane"),
    QT_TRANSLATE_NOOP("Messages", "%1 triangle was clipped against %2"),
    QT_TRANSLATE_NOOP("Messages", "%1 triangles were clipped against %2"),
    QT_TRANSLATE_NOOP("Messages", "%1; %2, not drawn"),
    QT_TRANSLATE_NOOP("Messages",
                      "every triangle is behind the camera (is N pointing away from the "
                      "object?): the image is empty"),
    QT_TRANSLATE_NOOP("Messages",
                      "%1. The plain divide of seed 000, x/z and y/z with z < 0, would draw it: "
                      "the object's point reflection through the eye (turned half a turn on the "
                      "screen), where the z-buffer, keeping the smallest z, keeps the side "
                      "farthest from the camera"),
    QT_TRANSLATE_NOOP("Messages",
                      "%1. The plain divide of seed 000, x/z and y/z with z < 0, would draw all "
                      "%2 of them: the object's point reflection through the eye (turned half a "
                      "turn on the screen), where the z-buffer, keeping the smallest z, keeps "
                      "the side farthest from the camera"),
    QT_TRANSLATE_NOOP("Messages",
                      "%1. The plain divide of seed 000, x/z and y/z with z < 0, would draw %2 "
                      "of them: the object's point reflection through the eye (turned half a "
                      "turn on the screen), where the z-buffer, keeping the smallest z, keeps "
                      "the side farthest from the camera"),
    QT_TRANSLATE_NOOP("Messages",
                      "plain divide: %1 triangle reaches from in front of the eye to at or "
                      "behind it (w of different signs, or 0): divided by w without clipping, it "
                      "wraps through infinity and is drawn wrong (clipping at the near plane "
                      "draws its front part)"),
    QT_TRANSLATE_NOOP("Messages",
                      "plain divide: %1 triangles reach from in front of the eye to at or behind "
                      "it (w of different signs, or 0): divided by w without clipping, it wraps "
                      "through infinity and is drawn wrong (clipping at the near plane draws its "
                      "front part)"),
    QT_TRANSLATE_NOOP("Messages",
                      "%1 vertices project more than 2^28 pixels from the image and were pulled "
                      "in to that distance: triangles through them may be distorted on screen"),
    QT_TRANSLATE_NOOP("Messages",
                      "%1 triangles project to infinite or undefined coordinates and were not "
                      "drawn"),
    QT_TRANSLATE_NOOP("Messages",
                      "%1 triangle faces away from the camera on a closed surface seen from "
                      "outside: hidden, so not drawn (back-face culling)"),
    QT_TRANSLATE_NOOP("Messages",
                      "%1 triangles face away from the camera on a closed surface seen from "
                      "outside: hidden, so not drawn (back-face culling)"),
    QT_TRANSLATE_NOOP("Messages", "%1 triangle is clockwise on screen and culled"),
    QT_TRANSLATE_NOOP("Messages", "%1 triangles are clockwise on screen and culled"),
    QT_TRANSLATE_NOOP("Messages",
                      "%1 triangle reaches from in front of the eye to at or behind it (w of "
                      "different signs): only the part with w >= %2 is drawn"),
    QT_TRANSLATE_NOOP("Messages",
                      "%1 triangles reach from in front of the eye to at or behind it (w of "
                      "different signs): only the part with w >= %2 is drawn"),
    QT_TRANSLATE_NOOP("Messages",
                      "plain divide: %1 triangle lies wholly behind the eye (w < 0), drawn "
                      "without clipping as the point reflection through the eye"),
    QT_TRANSLATE_NOOP("Messages",
                      "plain divide: %1 triangles lie wholly behind the eye (w < 0), drawn "
                      "without clipping as the point reflection through the eye"),
    // pipeline/render/renderer.cpp
    QT_TRANSLATE_NOOP("Messages", "no scene to render"),
    QT_TRANSLATE_NOOP("Messages", "the image size %1x%2 is empty"),
    QT_TRANSLATE_NOOP("Messages",
                      "no triangle covers a pixel: all %1 triangles in front of the camera "
                      "project outside the image (check N, d, hx and hy)"),
    QT_TRANSLATE_NOOP("Messages", "%1 triangles have zero area and no normal"),
    // pipeline/render/replay.cpp
    QT_TRANSLATE_NOOP("Messages", "no frame to step through"),
    QT_TRANSLATE_NOOP("Messages",
                      "stepping keeps at most %1 fragments, and this frame has %2: the final "
                      "image and the views still work"),
    QT_TRANSLATE_NOOP("Messages", "cancelled"),
    QT_TRANSLATE_NOOP("Messages",
                      "internal error: the rows hold %1 pixels and the depth test saw %2 "
                      "fragments"),
    // pipeline/render/renderer.cpp (lightsOnSurfaces)
    QT_TRANSLATE_NOOP("Messages",
                      "light %1 is %2 above triangle %3 of %4, nearer than float can resolve "
                      "points there (%5): the pixels under it may be lit from the wrong side"),
    // pipeline/analysis/accuracy.cpp
    QT_TRANSLATE_NOOP("Messages", "measurement cancelled"),
    QT_TRANSLATE_NOOP("Messages", "supersampling must be 1 to 16 samples per axis"),
    // pipeline/analysis/stability.cpp
    QT_TRANSLATE_NOOP("Messages", "the scene has no light to move"),
    QT_TRANSLATE_NOOP("Messages", "no triangle is in front of the camera"),
    // pipeline/analysis/reference.cpp
    QT_TRANSLATE_NOOP("Messages",
                      "the exact reference handles course scenes (the course camera, view z as "
                      "depth, the course's Phong lighting with the material's colour); %1"),
    QT_TRANSLATE_NOOP("Messages", "this scene has no course camera"),
    QT_TRANSLATE_NOOP("Messages", "this scene's depth is NDC z"),
    QT_TRANSLATE_NOOP("Messages", "%1 has its own projection matrix"),
    QT_TRANSLATE_NOOP("Messages", "%1 is not lit by the course's Phong model"),
    QT_TRANSLATE_NOOP("Messages", "%1 takes its colour from its vertices or a texture"),
    QT_TRANSLATE_NOOP("Messages", "%1 is lit with flat normals"),
    QT_TRANSLATE_NOOP("Messages", "samples per axis must be 1 to 16"),
    // pipeline/analysis/mistakes.cpp
    QT_TRANSLATE_NOOP("Messages", "(%1, %2, %3, %4)"),
    QT_TRANSLATE_NOOP("Messages",
                      "the ambient term multiplied by the object colour: Ia*ka*Od instead of "
                      "Ia*ka"),
    QT_TRANSLATE_NOOP("Messages", "the normal not turned toward the viewer where V.N < 0"),
    QT_TRANSLATE_NOOP("Messages", "specular added where R.V < 0 (no check before (R.V)^n)"),
    QT_TRANSLATE_NOOP("Messages",
                      "diffuse and specular computed where N.L < 0 (the light is behind the "
                      "surface)"),
    QT_TRANSLATE_NOOP("Messages", "the interpolated normal not normalised"),
    QT_TRANSLATE_NOOP("Messages", "%1 shading where another model was asked"),
    QT_TRANSLATE_NOOP("Messages", "%1 shading where %2 was asked"),
    QT_TRANSLATE_NOOP("Messages", "the image mirrored left-right (x runs the other way)"),
    QT_TRANSLATE_NOOP("Messages", "the image upside down (row 0 at the bottom: y not flipped)"),
    QT_TRANSLATE_NOOP("Messages", "the image shifted by one pixel: (%1, %2)"),
    QT_TRANSLATE_NOOP("Messages", "%1; pixels covered by one side only: %2 as ours is, %3 with ours carried by the map"),
    QT_TRANSLATE_NOOP("Messages", "check the screen formulas, x = (x_ndc + 1) * width / 2 and y = (1 - y_ndc) * height / 2, each with its own size, and that pixel (x, y) is written at column x of row y"),
    QT_TRANSLATE_NOOP("Messages", "its centre moved by (%1, %2) pixels"),
    QT_TRANSLATE_NOOP("Messages", "mirrored left-right"),
    QT_TRANSLATE_NOOP("Messages", "comparison cancelled"),
    QT_TRANSLATE_NOOP("Messages", "the vertex normals summed over every vertex at the same position instead of by the vertex's index (a faceted mesh drawn smooth)"),
    QT_TRANSLATE_NOOP("Messages", "seed 000: a vertex's normal sums the normals of the triangles that use that vertex, by its index; vertices repeated at one position keep their own"),
    QT_TRANSLATE_NOOP("Messages", "our image carried by that map of the screen (each pixel from the nearest of ours) gives their pixels"),
    QT_TRANSLATE_NOOP("Messages", "stretched %1 times across"),
    QT_TRANSLATE_NOOP("Messages", "stretched %1 times across and %2 times up and down"),
    QT_TRANSLATE_NOOP("Messages", "stretched %1 times up and down"),
    QT_TRANSLATE_NOOP("Messages", "the ratio of the image's sides (one size used for both axes)"),
    QT_TRANSLATE_NOOP("Messages", "the screen mapped another way: theirs is ours %1 (x' = %2 x + %3 y + %4, y' = %5 x + %6 y + %7)"),
    QT_TRANSLATE_NOOP("Messages", "turned %1 degrees clockwise"),
    QT_TRANSLATE_NOOP("Messages", "turned %1 degrees counter-clockwise"),
    QT_TRANSLATE_NOOP("Messages", "turned 90 degrees clockwise"),
    QT_TRANSLATE_NOOP("Messages", "turned 90 degrees counter-clockwise"),
    QT_TRANSLATE_NOOP("Messages", "upside down"),
    QT_TRANSLATE_NOOP("Messages", "x and y swapped (transposed)"),
    QT_TRANSLATE_NOOP("Messages", "x and y swapped and both mirrored"),
    QT_TRANSLATE_NOOP("Messages",
                      "pixels sampled at their centres (x + 0.5) instead of their corners"),
    QT_TRANSLATE_NOOP("Messages",
                      "pixels sampled at their corners instead of their centres (x + 0.5)"),
    QT_TRANSLATE_NOOP("Messages", "vertex positions rounded instead of truncated to whole pixels"),
    QT_TRANSLATE_NOOP("Messages", "vertex positions kept fractional (never made whole) instead of "
                                  "truncated to whole pixels"),
    QT_TRANSLATE_NOOP("Messages", "vertex positions truncated instead of rounded to whole pixels"),
    QT_TRANSLATE_NOOP("Messages",
                      "vertex positions rounded instead of truncated to the sub-pixel grid"),
    QT_TRANSLATE_NOOP("Messages",
                      "vertex positions truncated instead of rounded to the sub-pixel grid"),
    QT_TRANSLATE_NOOP(
        "Messages", "vertex positions truncated to the sub-pixel grid instead of kept as computed"),
    QT_TRANSLATE_NOOP("Messages", "the top-left fill rule where edges are inclusive"),
    QT_TRANSLATE_NOOP("Messages", "inclusive edges where the fill rule is top-left"),
    QT_TRANSLATE_NOOP("Messages", "colour bytes rounded instead of truncated (off by one)"),
    QT_TRANSLATE_NOOP("Messages", "colour bytes truncated instead of rounded (off by one)"),
    QT_TRANSLATE_NOOP("Messages", "colours above 255 wrap around instead of clamping"),
    QT_TRANSLATE_NOOP("Messages",
                      "the painter's order (far to near, no depth test) instead of the z-buffer"),
    QT_TRANSLATE_NOOP("Messages",
                      "z < stored instead of z <= stored in the depth test (ties keep the "
                      "earlier triangle)"),
    QT_TRANSLATE_NOOP("Messages",
                      "z <= stored instead of z < stored in the depth test (ties go to the "
                      "later triangle)"),
    QT_TRANSLATE_NOOP("Messages", "a different background: %1 where the scene's is %2"),
    QT_TRANSLATE_NOOP("Messages", "alpha %1 on covered pixels instead of 255"),
    QT_TRANSLATE_NOOP("Messages",
                      "our pixels lit again with that formula (the same triangles, "
                      "barycentrics, P', N, lights and material) give theirs"),
    QT_TRANSLATE_NOOP("Messages",
                      "the scene rendered again in that shading model gives their pixels"),
    QT_TRANSLATE_NOOP("Messages", "our image moved that way gives their pixels"),
    QT_TRANSLATE_NOOP("Messages", "the scene rendered again with that rule gives their pixels"),
    QT_TRANSLATE_NOOP("Messages", "our float colours made bytes that way give their pixels"),
    QT_TRANSLATE_NOOP("Messages",
                      "the scene painted far to near without a depth test gives their pixels"),
    QT_TRANSLATE_NOOP("Messages", "their pixels where no triangle of ours is take that colour"),
    QT_TRANSLATE_NOOP("Messages", "their pixels where a triangle of ours is take that alpha"),
    QT_TRANSLATE_NOOP("Messages", "seed 000's ambient term is Ia*ka, without the object colour Od"),
    QT_TRANSLATE_NOOP("Messages", "seed 000: if V.N < 0, N := -N before the lighting"),
    QT_TRANSLATE_NOOP("Messages", "seed 000: if R.V < 0, no specular term"),
    QT_TRANSLATE_NOOP("Messages", "seed 000: if N.L < 0, neither diffuse nor specular"),
    QT_TRANSLATE_NOOP("Messages",
                      "the interpolated N is shorter than 1: normalise it before N.L and R"),
    QT_TRANSLATE_NOOP("Messages",
                      "check where the lighting is evaluated: per pixel, per vertex or per "
                      "triangle"),
    QT_TRANSLATE_NOOP("Messages", "check the sign of x in the projection or the screen mapping"),
    QT_TRANSLATE_NOOP("Messages", "screen row 0 is the top: y = (1 - y_ndc) * height / 2"),
    QT_TRANSLATE_NOOP("Messages",
                      "check the screen mapping's offsets and the first pixel of each span"),
    QT_TRANSLATE_NOOP("Messages",
                      "where a pixel is sampled decides which pixels an edge covers (--rules)"),
    QT_TRANSLATE_NOOP("Messages",
                      "check how screen coordinates become whole pixels ((int) truncates)"),
    QT_TRANSLATE_NOOP("Messages",
                      "the pixels exactly on an edge: which triangle (or both) covers them"),
    QT_TRANSLATE_NOOP("Messages",
                      "check how the colour becomes a byte: (int) truncates, + 0.5 rounds"),
    QT_TRANSLATE_NOOP("Messages", "clamp each channel to 255 before writing it as a byte"),
    QT_TRANSLATE_NOOP("Messages",
                      "keep a depth buffer and write a pixel only when the fragment is nearer"),
    QT_TRANSLATE_NOOP("Messages",
                      "the comparison of the depth test: < keeps the first of two equal depths"),
    QT_TRANSLATE_NOOP("Messages", "the colour (and alpha) of the pixels no triangle covers"),
    QT_TRANSLATE_NOOP("Messages", "the alpha written with each shaded pixel"),
    QT_TRANSLATE_NOOP("Messages", "theirs - ours is %1 in %2 of the %3 covered channels that differ"),
    QT_TRANSLATE_NOOP("Messages", "theirs is within 2 of %1 times ours in %2 of the %3 covered channels that differ"),
    // pipeline/analysis/lighting_fit.cpp
    QT_TRANSLATE_NOOP("Messages", "the scene rendered again with the fitted lighting gives their pixels"),
    QT_TRANSLATE_NOOP("Messages", "compare the light's position, the intensities and the coefficients your program uses with the fitted ones"),
    QT_TRANSLATE_NOOP("Messages", "their lighting, fitted to their colours: %1"),
    QT_TRANSLATE_NOOP("Messages", "the lighting is fitted for a course camera and one positional light of the course's model"),
    QT_TRANSLATE_NOOP("Messages", "the lighting is fitted for Phong-shaded draws of one material"),
    QT_TRANSLATE_NOOP("Messages", "too few unclamped pixels inside triangles to fit the lighting"),
    QT_TRANSLATE_NOOP("Messages", "the fitted light is at the light's world position: it was not taken to view coordinates"),
    QT_TRANSLATE_NOOP("Messages", "the fitted light is at [I] Pl: C was not subtracted"),
    QT_TRANSLATE_NOOP("Messages", "the fitted light is ours with %1 negated"),
    QT_TRANSLATE_NOOP("Messages", "the fitted light is ours with %1 and %2 swapped"),
    QT_TRANSLATE_NOOP("Messages", "the fitted n is half of ours: n halved"),
    QT_TRANSLATE_NOOP("Messages", "the command file read again with that command so gives their pixels"),
    QT_TRANSLATE_NOOP("Messages", "every '%1' ignored (%2 of them, from line %3): the command "
                                  "never implemented"),
    QT_TRANSLATE_NOOP("Messages", "every '%1' multiplied on the other side (M = A M instead of "
                                  "M A), from line %2"),
    QT_TRANSLATE_NOOP("Messages",
                      "every '%1' read column by column (the matrix transposed), from line %2"),
    QT_TRANSLATE_NOOP("Messages", "every '%1' with its angle taken as radians, from line %2"),
    QT_TRANSLATE_NOOP("Messages", "every '%1' with s = f x up not normalised, from line %2"),
    QT_TRANSLATE_NOOP("Messages", "line %1: '%2' ignored"),
    QT_TRANSLATE_NOOP("Messages", "line %1: '%2' multiplied on the other side (M = A M instead of M A)"),
    QT_TRANSLATE_NOOP("Messages", "line %1: '%2' read column by column (the matrix transposed)"),
    QT_TRANSLATE_NOOP("Messages", "line %1: '%2' with its angle taken as radians"),
    QT_TRANSLATE_NOOP("Messages", "line %1: '%2' with s = f x up not normalised (the image stretched across)"),
    QT_TRANSLATE_NOOP("Messages", "check that your program reads '%1' and applies it"),
    QT_TRANSLATE_NOOP("Messages", "seed 001: a transform multiplies the model/view on the right, M = M A"),
    QT_TRANSLATE_NOOP("Messages", "seed 001 writes a matrix row by row: the first four numbers are its first row"),
    QT_TRANSLATE_NOOP("Messages", "seed 001's angles are in degrees: convert them before sin and cos"),
    QT_TRANSLATE_NOOP("Messages", "lookat: normalise s = f x up before it goes into the matrix"),
    QT_TRANSLATE_NOOP("Messages", "the camera's N not normalised before V - (V.N)N, nor after"),
    QT_TRANSLATE_NOOP("Messages", "the camera's U = V x N instead of N x V (x runs the other way)"),
    QT_TRANSLATE_NOOP("Messages", "the scene rendered again in view coordinates made with that basis gives their pixels"),
    QT_TRANSLATE_NOOP("Messages", "seed 000's Gram-Schmidt: normalise N first, then V - (V.N)N is V's part across N"),
    QT_TRANSLATE_NOOP("Messages", "seed 000: U = N x V, so that U, V, N is right-handed"),
    QT_TRANSLATE_NOOP("Messages", "the vertex normals left at the length of their sums (not normalised)"),
    QT_TRANSLATE_NOOP("Messages", "the triangle normals summed at their length (area-weighted) instead of normalised first"),
    QT_TRANSLATE_NOOP("Messages", "seed 000: each vertex normal is the normalised sum of its triangles' normals"),
    QT_TRANSLATE_NOOP("Messages", "normalise each triangle's normal before adding it to its vertices"),
    QT_TRANSLATE_NOOP("Messages", "the light not taken to view coordinates: its world position used as Pl_view"),
    QT_TRANSLATE_NOOP("Messages", "the light taken to view coordinates without subtracting C: [I] Pl instead of [I](Pl - C)"),
    QT_TRANSLATE_NOOP("Messages", "V = P' instead of -P' (L = P' - Pl gives the same image)"),
    QT_TRANSLATE_NOOP("Messages", "the ambient term Ia instead of Ia*ka"),
    QT_TRANSLATE_NOOP("Messages", "each Phong term truncated to a whole byte before the sum"),
    QT_TRANSLATE_NOOP("Messages", "V.N, N.L and R.V tested against %1 instead of 0"),
    QT_TRANSLATE_NOOP("Messages", "the depth test reversed: the farther fragment wins (> against a buffer cleared to -infinity, or to 0)"),
    QT_TRANSLATE_NOOP("Messages", "every covered pixel's colour off by %1 (a constant offset)"),
    QT_TRANSLATE_NOOP("Messages", "every colour multiplied by %1 (a constant scale)"),
    QT_TRANSLATE_NOOP("Messages", "every colour multiplied by 255: a colour scaled by 255 where it "
                                  "was already 0..255"),
    QT_TRANSLATE_NOOP("Messages", "every colour divided by 255: a colour scaled to 0..1 where the "
                                  "scene's are 0..255"),
    QT_TRANSLATE_NOOP("Messages", "the scene rendered again with the light where that transform puts it gives their pixels"),
    QT_TRANSLATE_NOOP("Messages", "the scene rendered again with the farther fragment winning gives their pixels"),
    QT_TRANSLATE_NOOP("Messages", "our bytes moved by that constant give their pixels"),
    QT_TRANSLATE_NOOP("Messages", "our colours multiplied by that constant give their pixels"),
    QT_TRANSLATE_NOOP("Messages", "seed 000: the light goes to view coordinates as the vertices do, Pl_view = [I](Pl - C)"),
    QT_TRANSLATE_NOOP("Messages", "seed 000: Pl_view = [I](Pl - C): subtract C before the change of basis"),
    QT_TRANSLATE_NOOP("Messages", "V points from the surface to the camera: V = -P' in view coordinates, and L = Pl - P'"),
    QT_TRANSLATE_NOOP("Messages", "seed 000's ambient term is Ia*ka"),
    QT_TRANSLATE_NOOP("Messages", "add the terms as real numbers and make a byte once, at the end"),
    QT_TRANSLATE_NOOP("Messages", "seed 000's special cases test against 0: V.N < 0, N.L < 0, R.V < 0"),
    QT_TRANSLATE_NOOP("Messages", "the z-buffer starts at +infinity and a fragment is written when its z is smaller"),
    QT_TRANSLATE_NOOP("Messages", "look for a constant added to every colour, or bytes made with an offset"),
    QT_TRANSLATE_NOOP("Messages", "look for a factor on every colour: an intensity scaled, or another colour scale"),
    QT_TRANSLATE_NOOP("Messages", "%1; no pixel that matches now would change"),
    QT_TRANSLATE_NOOP("Messages", "%2; %1 pixel that matches now would differ"),
    QT_TRANSLATE_NOOP("Messages", "%2; %1 pixels that match now would differ"),
    // app/documents/command_file.cpp
    QT_TRANSLATE_NOOP("Messages", "cannot read the texture %1: %2"),
    // pipeline/stages/camera_basis.cpp: V close to N
    QT_TRANSLATE_NOOP("Messages",
                      "V is %1 degrees from the line of N: Gram-Schmidt keeps only that much of "
                      "V, and the basis is orthonormal only to %2, less than a float's "
                      "precision; choose a V farther from N"),
    // app/documents/input_file.cpp
    QT_TRANSLATE_NOOP("Messages", "cannot open: %1"),
    QT_TRANSLATE_NOOP("Messages",
                      "the file has %1 MiB, more than the %2 MiB an input file may have"),
    QT_TRANSLATE_NOOP("Messages", "the file has more than the %1 MiB an input file may have"),
    // app/documents/scene_document.cpp
    QT_TRANSLATE_NOOP("Messages", "not enough memory to read this file"),
    QT_TRANSLATE_NOOP(
        "Messages",
        "the built-in scene's files cannot be written: save it to a file of your own (Save As)"),
    QT_TRANSLATE_NOOP("Messages", "the object is not edited, so not saved"),
    QT_TRANSLATE_NOOP("Messages", "cannot write into the built-in resources"),
    QT_TRANSLATE_NOOP("Messages", "the camera was not saved, as it would not load again: %1"),
    QT_TRANSLATE_NOOP("Messages",
                      "not saved: the text written does not read back as the same values"),
    QT_TRANSLATE_NOOP("Messages", "cannot write the file: %1"),
    QT_TRANSLATE_NOOP("Messages", "only %1 of %2 bytes could be written (is the disk full?)"),
    QT_TRANSLATE_NOOP("Messages", "cannot write the file (it is left as it was): %1"),
    // app/documents/lesson_file.cpp
    QT_TRANSLATE_NOOP("Messages", "[rows, fragments], two whole numbers"),
    QT_TRANSLATE_NOOP("Messages", "[width, height], whole numbers from %1 to %2"),
    QT_TRANSLATE_NOOP("Messages", "a list"),
    QT_TRANSLATE_NOOP("Messages", "a list of %1 numbers"),
    QT_TRANSLATE_NOOP("Messages", "a list of 1 to 8 lights"),
    QT_TRANSLATE_NOOP("Messages", "a list of dock names"),
    QT_TRANSLATE_NOOP("Messages", "a number"),
    QT_TRANSLATE_NOOP("Messages", "a positive number or \"auto\""),
    QT_TRANSLATE_NOOP("Messages", "a positive number or \"fit\""),
    QT_TRANSLATE_NOOP("Messages", "a whole number from %1"),
    QT_TRANSLATE_NOOP("Messages", "an object"),
    QT_TRANSLATE_NOOP("Messages", "expected %1 for \"%2\", found %3"),
    QT_TRANSLATE_NOOP("Messages",
                      "expected a lesson file: a JSON object with \"rasterlab_lesson\": %1"),
    QT_TRANSLATE_NOOP("Messages", "not a lesson file: %1"),
    QT_TRANSLATE_NOOP("Messages", "nothing"),
    QT_TRANSLATE_NOOP("Messages", "null"),
    QT_TRANSLATE_NOOP("Messages", "one of %1"),
    QT_TRANSLATE_NOOP("Messages", "text in quotes"),
    QT_TRANSLATE_NOOP("Messages", "the text '%1'"),
    QT_TRANSLATE_NOOP("Messages", "true or false"),
    QT_TRANSLATE_NOOP("Messages", "unknown key \"%1\" ignored (known here: %2)"),
};

// The template with its arguments in place of %1 ... %9, in one pass, as Message::english does:
// an argument holding "%1" (a token from a file) stays as it is.
QString fill(const QString& pattern, const QStringList& arguments) {
    QString s;
    s.reserve(pattern.size() + 16 * arguments.size());
    for (qsizetype i = 0; i < pattern.size(); ++i) {
        const QChar next = i + 1 < pattern.size() ? pattern[i + 1] : QChar();
        const int k = next.digitValue() - 1;
        if (pattern[i] == u'%' && k >= 0 && k < arguments.size()) {
            s += arguments[k];
            ++i;
        } else {
            s += pattern[i];
        }
    }
    return s;
}

QString where(const rl::SourceLocation& location) {
    return QString::fromStdString(location.toString());
}

}  // namespace

QString translated(const rl::Message& message) {
    if (!message.translatable()) return QString::fromStdString(message.text());
    QStringList arguments;
    for (const rl::Message& argument : message.arguments()) arguments << translated(argument);
    return fill(QCoreApplication::translate("Messages", message.text().c_str()), arguments);
}

QString translated(const rl::Error& error) {
    return QCoreApplication::translate("Messages", "%1: %2")
        .arg(where(error.where), translated(error.translatable));
}

QString translated(const rl::Diagnostic& diagnostic) {
    const char* pattern = diagnostic.severity == rl::Severity::Warning
                              ? QT_TRANSLATE_NOOP("Messages", "%1: warning: %2")
                              : QT_TRANSLATE_NOOP("Messages", "%1: note: %2");
    return QCoreApplication::translate("Messages", pattern)
        .arg(where(diagnostic.where), translated(diagnostic.translatable));
}

std::span<const char* const> messageCatalogue() {
    return kCatalogue;
}

}  // namespace rasterlab
