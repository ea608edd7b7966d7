// The course's .byu triangle mesh: "vertices triangles", then the vertices (x y z), then the
// triangles (three 1-based indices), one a line.
#include <array>

#include "pipeline/io/course_fields.h"

namespace rl {

using namespace course_io;  // the helpers the course readers share

namespace {

// The header's two counts, and its line for the messages that point at it.
struct MeshHeader {
    long long vertices = 0;
    long long triangles = 0;
    TextLine line;
};

// The header "vertices triangles"; a Movie.BYU header gets a message of its own.
Result<MeshHeader> readMeshHeader(LineScanner& scanner, Diagnostics& diagnostics) {
    TextLine line;
    const Message header = "the header 'vertices triangles' (two integers)"_msg;
    if (!scanner.next(line))
        return makeError(ErrorCode::MissingData, scanner.endOfInput(),
                         "expected %1, found the end of the file"_msg(header));
    if (isComment(line.tokens[0])) return commentError(scanner, line.tokens[0], header);
    if (isMovieByuHeader(line)) {
        return makeError(ErrorCode::Unsupported, scanner.at(line.tokens[0]),
                         "this is an original Movie.BYU file (header 'parts vertices polygons "
                         "edges'), not the course's .byu format (header 'vertices triangles')"_msg);
    }
    auto vertexCount = readCount(scanner, line.tokens[0], "vertices"_msg);
    if (!vertexCount) return vertexCount.error();
    if (line.tokens.size() < 2)
        return makeError(ErrorCode::Syntax, scanner.afterLast(line),
                         "expected the number of triangles after the number of vertices, "
                         "found the end of the line"_msg);
    auto triangleCount = readCount(scanner, line.tokens[1], "triangles"_msg);
    if (!triangleCount) return triangleCount.error();
    if (line.tokens.size() > 2)
        diagnostics.warn(scanner.at(line.tokens[2]),
                         "ignored %1 after the header's two counts"_msg(
                             valuesText(static_cast<long long>(line.tokens.size() - 2))));
    return MeshHeader{*vertexCount, *triangleCount, line};
}

// Before anything is allocated: not a course Bezier surface, and counts the file can hold.
Status checkMeshFits(LineScanner& scanner, const MeshHeader& header) {
    // A course Bezier surface also ships as .byu: "m n", then one number (evaluations).
    TextLine line;
    if (scanner.next(line)) {
        if (line.tokens.size() == 1 && parseInteger(line.tokens[0].text)) {
            return makeError(ErrorCode::Unsupported, scanner.at(header.line.tokens[0]),
                             "this looks like a course Bezier surface (degrees %1 x %2, %3 "
                             "evaluations per direction), not a triangle mesh"_msg(
                                 header.vertices, header.triangles, line.tokens[0].text));
        }
        scanner.unread();
    }

    // (Compared without adding the counts, which may overflow; their sum fits unsigned.)
    const long long available = scanner.countRemainingLines();
    if (header.vertices > available || header.triangles > available - header.vertices) {
        const unsigned long long declared = static_cast<unsigned long long>(header.vertices) +
                                            static_cast<unsigned long long>(header.triangles);
        return makeError(ErrorCode::Range, scanner.at(header.line.tokens[0]),
                         "the header declares %1 and %2 (%3), but only %4"_msg(
                             verticesText(header.vertices), trianglesText(header.triangles),
                             (declared == 1 ? "%1 line"_msg : "%1 lines"_msg)(declared),
                             counted(available, "%1 line follows"_msg, "%1 lines follow"_msg)));
    }
    return success();
}

Status readMeshVertices(LineScanner& scanner, const MeshHeader& header, Mesh& mesh,
                        ExtraValues& extra) {
    TextLine line;
    for (long long i = 0; i < header.vertices; ++i) {
        scanner.next(line);  // present: counted by checkMeshFits
        auto p = readPointLine(scanner, line, "vertex %1 of %2"_msg(i + 1, header.vertices));
        if (!p) return p.error();
        extra.note(scanner, line);
        mesh.positions.emplace_back(*p, 1.0);
    }
    return success();
}

// Triangle i (0 the first): three 1-based indices, returned 0-based.
Result<std::array<std::uint32_t, 3>> readTriangle(const LineScanner& scanner, const TextLine& line,
                                                  long long i, const MeshHeader& header) {
    const long long number = i + 1;
    if (isComment(line.tokens[0]))
        return commentError(
            scanner, line.tokens[0],
            "triangle %1 of %2 (three vertex indices)"_msg(number, header.triangles));
    if (line.tokens.size() < 3)
        return makeError(ErrorCode::Syntax, scanner.afterLast(line),
                         "expected 3 vertex indices for triangle %1 of %2, found %3"_msg(
                             number, header.triangles, line.tokens.size()));
    if (line.tokens.size() > 3 && parseInteger(line.tokens[3].text))
        return makeError(ErrorCode::Unsupported, scanner.at(line.tokens[3]),
                         "polygon %1 has %2 vertex indices, but only triangles (3 indices) are "
                         "supported"_msg(number, line.tokens.size()));
    std::array<std::uint32_t, 3> tri{};
    for (std::size_t k = 0; k < 3; ++k) {
        const Token& token = line.tokens[k];
        const auto index = parseInteger(token.text);
        if (!index)
            return makeError(ErrorCode::Syntax, scanner.at(token),
                             "expected a vertex index (a positive integer) for triangle %1, found "
                             "%2"_msg(number, quoted(token.text)));
        if (*index < 1)
            return makeError(ErrorCode::Range, scanner.at(token),
                             "triangle %1 refers to vertex %2, but indices are 1-based (1 to "
                             "%3)"_msg(number, *index, header.vertices));
        if (*index > header.vertices)
            return makeError(ErrorCode::Range, scanner.at(token),
                             "triangle %1 refers to vertex %2, but the file declares only %3"_msg(
                                 number, *index, verticesText(header.vertices)));
        tri[k] = static_cast<std::uint32_t>(*index - 1);
    }
    return tri;
}

// The triangles, marking in `used` the vertices they use.
Status readMeshTriangles(LineScanner& scanner, const MeshHeader& header, Mesh& mesh,
                         std::vector<unsigned char>& used, ExtraValues& extra) {
    TextLine line;
    for (long long i = 0; i < header.triangles; ++i) {
        scanner.next(line);  // present: counted by checkMeshFits
        auto tri = readTriangle(scanner, line, i, header);
        if (!tri) return tri.error();
        for (std::uint32_t vertex : *tri) used[vertex] = 1;
        extra.note(scanner, line);
        mesh.triangles.push_back(*tri);
        mesh.triangleLines.push_back(line.number);
    }
    return success();
}

// Lines after the declared counts: a wrong header, or a second object.
void warnTrailingMeshLines(LineScanner& scanner, const MeshHeader& header,
                           Diagnostics& diagnostics) {
    TextLine line;
    if (!scanner.next(line)) return;
    const int remaining = 1 + scanner.countRemainingLines();
    diagnostics.warn(
        scanner.at(line.number, 1),
        "ignored %1 after the declared %2 and %3 (the header's counts may be wrong, "
        "or a second object follows)"_msg(linesText(remaining), verticesText(header.vertices),
                                          trianglesText(header.triangles)));
}

}  // namespace

Result<Mesh> readByuMesh(std::string_view text, const std::string& fileName,
                         Diagnostics& diagnostics) {
    LineScanner scanner(text, fileName);
    auto header = readMeshHeader(scanner, diagnostics);
    if (!header) return header.error();
    if (Status fits = checkMeshFits(scanner, *header); !fits) return fits.error();

    Mesh mesh;
    mesh.source = scanner.at(0, 0);
    mesh.positions.reserve(static_cast<std::size_t>(header->vertices));
    mesh.triangles.reserve(static_cast<std::size_t>(header->triangles));
    mesh.triangleLines.reserve(static_cast<std::size_t>(header->triangles));
    ExtraValues extra;
    if (Status read = readMeshVertices(scanner, *header, mesh, extra); !read) return read.error();
    std::vector<unsigned char> used(mesh.positions.size(), 0);
    if (Status read = readMeshTriangles(scanner, *header, mesh, used, extra); !read)
        return read.error();

    extra.warn(diagnostics);
    warnTrailingMeshLines(scanner, *header, diagnostics);
    warnUnusedVertices(mesh, used, diagnostics);
    return mesh;
}

}  // namespace rl
