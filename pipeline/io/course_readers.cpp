// readByuObject: tells the three .byu flavours apart by the header and hands each to its
// reader (byu_mesh.cpp, bezier_surface.cpp, movie_byu.cpp).
#include "course_readers.h"

#include "pipeline/io/course_fields.h"
#include "pipeline/scene/mesh_topology.h"

namespace rl {

using namespace course_io;  // the helpers the course readers share

namespace {

Result<Mesh> readAnyByuObject(std::string_view text, const std::string& fileName,
                              Diagnostics& diagnostics) {
    LineScanner scanner(text, fileName);
    TextLine header;
    if (scanner.next(header)) {
        if (isMovieByuHeader(header)) {
            Diagnostics read;  // after the note
            Message summary;
            auto mesh = readMovieByu(scanner, header, summary, read);
            if (mesh)
                diagnostics.note(
                    mesh->source,
                    "read as an original Movie.BYU file (the header has four integers: parts, "
                    "vertices, polygons, edges): %1, fan-triangulated into %2"_msg(
                        summary, trianglesText(static_cast<long long>(mesh->triangles.size()))));
            diagnostics.append(read);
            return mesh;
        }
        TextLine second;
        if (header.tokens.size() >= 2 && parseInteger(header.tokens[0].text) &&
            parseInteger(header.tokens[1].text) && scanner.next(second) &&
            second.tokens.size() == 1 && parseInteger(second.tokens[0].text)) {
            Diagnostics read;
            auto mesh = readBezierSurface(scanner, header, second, read);
            if (mesh) {
                diagnostics.note(
                    mesh->source,
                    "read as a course Bezier surface (the header 'm n' is followed by a line of "
                    "one number, the evaluations per direction): degrees %1 x %2, evaluated on a "
                    "%3 x %3 grid into %4 and %5"_msg(
                        *parseInteger(header.tokens[0].text), *parseInteger(header.tokens[1].text),
                        *parseInteger(second.tokens[0].text),
                        verticesText(static_cast<long long>(mesh->positions.size())),
                        trianglesText(static_cast<long long>(mesh->triangles.size()))));
            }
            diagnostics.append(read);
            return mesh;
        }
    }
    return readByuMesh(text, fileName, diagnostics);
}

}  // namespace

Result<Mesh> readByuObject(std::string_view text, const std::string& fileName,
                           Diagnostics& diagnostics) {
    auto mesh = readAnyByuObject(text, fileName, diagnostics);
    if (mesh) mesh->closedWinding = closedSurfaceWinding(*mesh);
    return mesh;
}

}  // namespace rl
