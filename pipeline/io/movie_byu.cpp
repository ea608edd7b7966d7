// The original Movie.BYU format: "parts vertices polygons edges", a "first last" polygon range
// per part, the vertices, then the polygons' 1-based indices, the last of each negated.
#include <algorithm>
#include <cstdlib>
#include <limits>

#include "course_fields.h"

namespace rl::course_io {

namespace {

// The tokens of the lines after the current one, one at a time (Movie.BYU is free format:
// several vertices or indices may share a line).
class TokenReader {
public:
    explicit TokenReader(LineScanner& scanner) : m_scanner(scanner) {}

    bool next(Token& token) {
        while (m_index >= m_line.tokens.size()) {
            if (!m_scanner.next(m_line)) return false;
            m_index = 0;
        }
        token = m_line.tokens[m_index++];
        return true;
    }
    // Tokens from here to the end, without consuming them.
    long long countRemaining() const {
        long long count = static_cast<long long>(m_line.tokens.size() - m_index);
        LineScanner copy = m_scanner;
        TextLine line;
        while (copy.next(line)) count += static_cast<long long>(line.tokens.size());
        return count;
    }

private:
    LineScanner& m_scanner;
    TextLine m_line;
    std::size_t m_index = 0;
};

}  // namespace

bool isMovieByuHeader(const TextLine& line) {
    return line.tokens.size() == 4 &&
           std::all_of(line.tokens.begin(), line.tokens.end(),
                       [](const Token& t) { return parseInteger(t.text).has_value(); });
}

// `summary` receives "1 part, 8 vertices and 6 polygons" for the note.
Result<Mesh> readMovieByu(LineScanner& scanner, const TextLine& header, std::string& summary,
                          Diagnostics& diagnostics) {
    auto parts = readCount(scanner, header.tokens[0], "parts");
    if (!parts) return parts.error();
    auto vertexCount = readCount(scanner, header.tokens[1], "vertices");
    if (!vertexCount) return vertexCount.error();
    auto polygonCount = readCount(scanner, header.tokens[2], "polygons");
    if (!polygonCount) return polygonCount.error();
    auto indexCount = readCount(scanner, header.tokens[3], "polygon indices (edges)");
    if (!indexCount) return indexCount.error();

    // Reject counts the file cannot hold before allocating anything (compared without
    // multiplying the counts, which may overflow).
    TokenReader tokens(scanner);
    const long long available = tokens.countRemaining();
    bool fits = *parts <= available / 2;
    long long rest = fits ? available - 2 * *parts : 0;
    fits = fits && *vertexCount <= rest / 3;
    rest = fits ? rest - 3 * *vertexCount : 0;
    fits = fits && *indexCount <= rest;
    const std::string declared = plural(*parts, "part", "parts") + ", " +
                                 plural(*vertexCount, "vertex", "vertices") + " and " +
                                 plural(*indexCount, "polygon index", "polygon indices");
    if (!fits) {
        unsigned long long total = 0, term = 0;
        const bool overflow =
            __builtin_mul_overflow(static_cast<unsigned long long>(*parts), 2ull, &total) ||
            __builtin_mul_overflow(static_cast<unsigned long long>(*vertexCount), 3ull, &term) ||
            __builtin_add_overflow(total, term, &total) ||
            __builtin_add_overflow(total, static_cast<unsigned long long>(*indexCount), &total);
        return makeError(
            ErrorCode::Range, scanner.at(header.tokens[0]),
            "the header declares " + declared + " (" +
                (overflow ? std::string("more numbers than a file can hold")
                          : plural(static_cast<long long>(total), "number", "numbers")) +
                ": 2 a part, 3 a vertex, 1 an index), but only " +
                plural(available, "number follows", "numbers follow"));
    }
    if (*polygonCount > *indexCount / 3)
        return makeError(ErrorCode::Range, scanner.at(header.tokens[2]),
                         "the header declares " + plural(*polygonCount, "polygon", "polygons") +
                             " but only " +
                             plural(*indexCount, "polygon index", "polygon indices") +
                             ", fewer than the 3 each polygon needs");

    // One "first last" polygon range per part (parts only group polygons: the mesh is one).
    Token token;
    for (long long p = 1; p <= *parts; ++p) {
        long long range[2] = {0, 0};
        SourceLocation rangeAt;
        for (int k = 0; k < 2; ++k) {
            tokens.next(token);  // present: counted above
            if (k == 0) rangeAt = scanner.at(token);
            const std::string what =
                std::string(k == 0 ? "first" : "last") + " polygon of part " + std::to_string(p);
            if (isComment(token)) return commentError(scanner, token, "the " + what);
            const auto value = parseInteger(token.text);
            if (!value)
                return makeError(
                    ErrorCode::Syntax, scanner.at(token),
                    "expected the " + what + " (a positive integer), found " + quoted(token.text));
            range[k] = *value;
        }
        if (range[0] < 1 || range[1] < range[0] || range[1] > *polygonCount)
            return makeError(ErrorCode::Range, rangeAt,
                             "expected the polygon range of part " + std::to_string(p) +
                                 " within 1 to " + std::to_string(*polygonCount) +
                                 ", first <= last, found " + std::to_string(range[0]) + " to " +
                                 std::to_string(range[1]));
    }

    Mesh mesh;
    mesh.source = scanner.at(0, 0);
    mesh.positions.reserve(static_cast<std::size_t>(*vertexCount));
    static const char* const kAxis[] = {"x", "y", "z"};
    for (long long i = 0; i < *vertexCount; ++i) {
        const std::string which =
            "vertex " + std::to_string(i + 1) + " of " + std::to_string(*vertexCount);
        dvec4 p(0.0, 0.0, 0.0, 1.0);
        for (int k = 0; k < 3; ++k) {
            tokens.next(token);
            if (isComment(token)) return commentError(scanner, token, which + " (x y z)");
            const auto value = parseReal(token.text);
            if (!value)
                return makeError(ErrorCode::Syntax, scanner.at(token),
                                 std::string("expected a number for the ") + kAxis[k] +
                                     " coordinate of " + which + ", " + whyNotNumber(token.text));
            p[k] = *value;
        }
        mesh.positions.push_back(p);
    }

    // The polygons: 1-based indices, the last of each negated; each fan-triangulated.
    std::vector<unsigned char> used(mesh.positions.size(), 0);
    std::vector<std::uint32_t> polygon;
    long long completed = 0;
    int polygonLine = 0;
    SourceLocation lastIndex;
    for (long long e = 0; e < *indexCount; ++e) {
        tokens.next(token);
        const std::string which = "polygon " + std::to_string(completed + 1);
        if (isComment(token)) return commentError(scanner, token, "an index of " + which);
        const auto index = parseInteger(token.text);
        if (!index)
            return makeError(ErrorCode::Syntax, scanner.at(token),
                             "expected a vertex index (a non-zero integer, negated at the end of "
                             "a polygon) for " +
                                 which + ", found " + quoted(token.text));
        if (completed == *polygonCount)
            return makeError(ErrorCode::Range, scanner.at(token),
                             which + " starts here, but the header declares only " +
                                 plural(*polygonCount, "polygon", "polygons"));
        if (*index == 0)
            return makeError(ErrorCode::Range, scanner.at(token),
                             which + " refers to vertex 0, but indices are 1-based (1 to " +
                                 std::to_string(*vertexCount) + ")");
        // |index|, or 0 for the one value whose magnitude does not fit.
        const long long vertex =
            *index == std::numeric_limits<long long>::min() ? 0 : std::llabs(*index);
        if (vertex == 0 || vertex > *vertexCount)
            return makeError(ErrorCode::Range, scanner.at(token),
                             which + " refers to vertex " + std::string(withoutSign(token.text)) +
                                 ", but the file declares only " +
                                 plural(*vertexCount, "vertex", "vertices"));
        if (polygon.empty()) polygonLine = token.line;
        polygon.push_back(static_cast<std::uint32_t>(vertex - 1));
        used[static_cast<std::size_t>(vertex - 1)] = 1;
        lastIndex = scanner.at(token);
        if (*index > 0) continue;
        if (polygon.size() < 3)
            return makeError(
                ErrorCode::Range, scanner.at(token),
                which + " has " +
                    plural(static_cast<long long>(polygon.size()), "vertex", "vertices") +
                    ", but a polygon needs at least 3");
        for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
            mesh.triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
            mesh.triangleLines.push_back(polygonLine);
        }
        polygon.clear();
        ++completed;
    }
    if (!polygon.empty())
        return makeError(ErrorCode::Syntax, lastIndex,
                         "expected the last index of polygon " + std::to_string(completed + 1) +
                             " to be negative (it ends the polygon), found the end of the "
                             "header's " +
                             plural(*indexCount, "polygon index", "polygon indices"));
    if (completed < *polygonCount)
        return makeError(ErrorCode::Range, scanner.at(header.tokens[2]),
                         "the header declares " + plural(*polygonCount, "polygon", "polygons") +
                             ", but its " +
                             plural(*indexCount, "polygon index", "polygon indices") +
                             " end only " + std::to_string(completed));

    if (tokens.next(token)) {
        const long long remaining = 1 + tokens.countRemaining();
        diagnostics.warn(scanner.at(token),
                         "ignored " + plural(remaining, "value", "values") +
                             " after the declared " + declared +
                             " (the header's counts may be wrong, or a second object follows)");
    }
    warnUnusedVertices(mesh, used, diagnostics);
    summary = plural(*parts, "part", "parts") + ", " + plural(*vertexCount, "vertex", "vertices") +
              " and " + plural(*polygonCount, "polygon", "polygons");
    return mesh;
}

}  // namespace rl::course_io
