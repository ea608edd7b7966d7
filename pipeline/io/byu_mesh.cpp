// The course's .byu triangle mesh: "vertices triangles", then the vertices (x y z), then the
// triangles (three 1-based indices), one a line.
#include "course_fields.h"

namespace rl {

using namespace course_io;  // the helpers the course readers share

Result<Mesh> readByuMesh(std::string_view text, const std::string& fileName,
                         Diagnostics& diagnostics) {
    LineScanner scanner(text, fileName);
    TextLine line;
    const std::string header = "the header 'vertices triangles' (two integers)";
    if (!scanner.next(line))
        return makeError(ErrorCode::MissingData, scanner.endOfInput(),
                         "expected " + header + ", found the end of the file");
    if (isComment(line.tokens[0])) return commentError(scanner, line.tokens[0], header);
    const TextLine headerLine = line;
    if (line.tokens.size() == 4 && parseInteger(line.tokens[0].text) &&
        parseInteger(line.tokens[1].text) && parseInteger(line.tokens[2].text) &&
        parseInteger(line.tokens[3].text)) {
        return makeError(ErrorCode::Unsupported, scanner.at(line.tokens[0]),
                         "this is an original Movie.BYU file (header 'parts vertices polygons "
                         "edges'), not the course's .byu format (header 'vertices triangles')");
    }
    auto vertexCount = readCount(scanner, line.tokens[0], "vertices");
    if (!vertexCount) return vertexCount.error();
    if (line.tokens.size() < 2)
        return makeError(ErrorCode::Syntax, scanner.afterLast(line),
                         "expected the number of triangles after the number of vertices, "
                         "found the end of the line");
    auto triangleCount = readCount(scanner, line.tokens[1], "triangles");
    if (!triangleCount) return triangleCount.error();
    if (line.tokens.size() > 2)
        diagnostics.warn(
            scanner.at(line.tokens[2]),
            "ignored " + plural(static_cast<long long>(line.tokens.size() - 2), "value", "values") +
                " after the header's two counts");

    // A course Bezier surface also ships as .byu: "m n", then one number (evaluations).
    if (scanner.next(line)) {
        if (line.tokens.size() == 1 && parseInteger(line.tokens[0].text)) {
            return makeError(ErrorCode::Unsupported, scanner.at(headerLine.tokens[0]),
                             "this looks like a course Bezier surface (degrees " +
                                 std::to_string(*vertexCount) + " x " +
                                 std::to_string(*triangleCount) + ", " +
                                 std::string(line.tokens[0].text) +
                                 " evaluations per direction), not a triangle mesh");
        }
        scanner.unread();
    }

    // Reject counts the file cannot hold before allocating anything.
    // (Compared without adding the counts, which may overflow; their sum fits unsigned.)
    const long long available = scanner.countRemainingLines();
    if (*vertexCount > available || *triangleCount > available - *vertexCount) {
        const unsigned long long declared = static_cast<unsigned long long>(*vertexCount) +
                                            static_cast<unsigned long long>(*triangleCount);
        return makeError(ErrorCode::Range, scanner.at(headerLine.tokens[0]),
                         "the header declares " + plural(*vertexCount, "vertex", "vertices") +
                             " and " + plural(*triangleCount, "triangle", "triangles") + " (" +
                             std::to_string(declared) + (declared == 1 ? " line" : " lines") +
                             "), but only " + plural(available, "line follows", "lines follow"));
    }

    Mesh mesh;
    mesh.source = scanner.at(0, 0);
    mesh.positions.reserve(static_cast<std::size_t>(*vertexCount));
    mesh.triangles.reserve(static_cast<std::size_t>(*triangleCount));
    mesh.triangleLines.reserve(static_cast<std::size_t>(*triangleCount));

    static const char* const kAxis[] = {"x", "y", "z"};
    long long linesWithExtraValues = 0;
    SourceLocation firstExtra;
    for (long long i = 0; i < *vertexCount; ++i) {
        scanner.next(line);  // present: counted above
        const std::string which =
            "vertex " + std::to_string(i + 1) + " of " + std::to_string(*vertexCount);
        if (isComment(line.tokens[0]))
            return commentError(scanner, line.tokens[0], which + " (x y z)");
        dvec4 p(0.0, 0.0, 0.0, 1.0);
        for (int k = 0; k < 3; ++k) {
            if (static_cast<std::size_t>(k) >= line.tokens.size())
                return makeError(
                    ErrorCode::Syntax, scanner.afterLast(line),
                    "expected 3 coordinates for " + which + ", found " + std::to_string(k));
            const Token& token = line.tokens[static_cast<std::size_t>(k)];
            const auto value = parseReal(token.text);
            if (!value)
                return makeError(ErrorCode::Syntax, scanner.at(token),
                                 std::string("expected a number for the ") + kAxis[k] +
                                     " coordinate of " + which + ", " + whyNotNumber(token.text));
            p[k] = *value;
        }
        if (line.tokens.size() > 3 && linesWithExtraValues++ == 0)
            firstExtra = scanner.at(line.tokens[3]);
        mesh.positions.push_back(p);
    }

    std::vector<unsigned char> used(mesh.positions.size(), 0);
    for (long long i = 0; i < *triangleCount; ++i) {
        scanner.next(line);
        const std::string which = "triangle " + std::to_string(i + 1);
        if (isComment(line.tokens[0]))
            return commentError(
                scanner, line.tokens[0],
                which + " of " + std::to_string(*triangleCount) + " (three vertex indices)");
        if (line.tokens.size() < 3)
            return makeError(ErrorCode::Syntax, scanner.afterLast(line),
                             "expected 3 vertex indices for " + which + " of " +
                                 std::to_string(*triangleCount) + ", found " +
                                 std::to_string(line.tokens.size()));
        if (line.tokens.size() > 3 && parseInteger(line.tokens[3].text))
            return makeError(ErrorCode::Unsupported, scanner.at(line.tokens[3]),
                             "polygon " + std::to_string(i + 1) + " has " +
                                 std::to_string(line.tokens.size()) +
                                 " vertex indices, but only triangles (3 indices) are supported");
        std::array<std::uint32_t, 3> tri{};
        for (int k = 0; k < 3; ++k) {
            const Token& token = line.tokens[static_cast<std::size_t>(k)];
            const auto index = parseInteger(token.text);
            if (!index)
                return makeError(ErrorCode::Syntax, scanner.at(token),
                                 "expected a vertex index (a positive integer) for " + which +
                                     ", found " + quoted(token.text));
            if (*index < 1)
                return makeError(ErrorCode::Range, scanner.at(token),
                                 which + " refers to vertex " + std::to_string(*index) +
                                     ", but indices are 1-based (1 to " +
                                     std::to_string(*vertexCount) + ")");
            if (*index > *vertexCount)
                return makeError(ErrorCode::Range, scanner.at(token),
                                 which + " refers to vertex " + std::to_string(*index) +
                                     ", but the file declares only " +
                                     plural(*vertexCount, "vertex", "vertices"));
            tri[static_cast<std::size_t>(k)] = static_cast<std::uint32_t>(*index - 1);
            used[static_cast<std::size_t>(*index - 1)] = 1;
        }
        if (line.tokens.size() > 3 && linesWithExtraValues++ == 0)
            firstExtra = scanner.at(line.tokens[3]);
        mesh.triangles.push_back(tri);
        mesh.triangleLines.push_back(line.number);
    }

    if (linesWithExtraValues > 0)
        diagnostics.warn(firstExtra, "ignored extra values at the end of " +
                                         plural(linesWithExtraValues, "line", "lines") +
                                         " (the first is here)");
    if (scanner.next(line)) {
        const int remaining = 1 + scanner.countRemainingLines();
        diagnostics.warn(scanner.at(line.number, 1),
                         "ignored " + plural(remaining, "line", "lines") + " after the declared " +
                             plural(*vertexCount, "vertex", "vertices") + " and " +
                             plural(*triangleCount, "triangle", "triangles") +
                             " (the header's counts may be wrong, or a second object follows)");
    }
    long long unused = 0;
    for (unsigned char u : used) unused += u ? 0 : 1;
    if (unused > 0 && *triangleCount > 0)
        diagnostics.warn(mesh.source, plural(unused, "vertex", "vertices") + " of " +
                                          std::to_string(*vertexCount) +
                                          (unused == 1 ? " is" : " are") +
                                          " not used by any triangle");
    if (*triangleCount == 0) diagnostics.warn(mesh.source, "the object has no triangles");
    return mesh;
}

}  // namespace rl
