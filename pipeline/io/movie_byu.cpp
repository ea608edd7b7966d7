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

// The header's counts: "parts vertices polygons edges", the edges being the polygon indices.
struct MovieCounts {
    long long parts = 0;
    long long vertices = 0;
    long long polygons = 0;
    long long indices = 0;
};

Result<MovieCounts> readMovieCounts(const LineScanner& scanner, const TextLine& header) {
    auto parts = readCount(scanner, header.tokens[0], "parts");
    if (!parts) return parts.error();
    auto vertexCount = readCount(scanner, header.tokens[1], "vertices");
    if (!vertexCount) return vertexCount.error();
    auto polygonCount = readCount(scanner, header.tokens[2], "polygons");
    if (!polygonCount) return polygonCount.error();
    auto indexCount = readCount(scanner, header.tokens[3], "polygon indices (edges)");
    if (!indexCount) return indexCount.error();
    return MovieCounts{*parts, *vertexCount, *polygonCount, *indexCount};
}

// "1 part, 4 vertices and 4 polygon indices": the numbers the header declares.
std::string declaredText(const MovieCounts& counts) {
    return plural(counts.parts, "part", "parts") + ", " +
           plural(counts.vertices, "vertex", "vertices") + " and " +
           plural(counts.indices, "polygon index", "polygon indices");
}

// Reject counts the file cannot hold before allocating anything (compared without
// multiplying the counts, which may overflow).
Status checkMovieFits(const LineScanner& scanner, const TextLine& header, const MovieCounts& counts,
                      const TokenReader& tokens) {
    const long long available = tokens.countRemaining();
    bool fits = counts.parts <= available / 2;
    long long rest = fits ? available - 2 * counts.parts : 0;
    fits = fits && counts.vertices <= rest / 3;
    rest = fits ? rest - 3 * counts.vertices : 0;
    fits = fits && counts.indices <= rest;
    if (!fits) {
        unsigned long long total = 0, term = 0;
        const bool overflow =
            __builtin_mul_overflow(static_cast<unsigned long long>(counts.parts), 2ull, &total) ||
            __builtin_mul_overflow(static_cast<unsigned long long>(counts.vertices), 3ull, &term) ||
            __builtin_add_overflow(total, term, &total) ||
            __builtin_add_overflow(total, static_cast<unsigned long long>(counts.indices), &total);
        return makeError(
            ErrorCode::Range, scanner.at(header.tokens[0]),
            "the header declares " + declaredText(counts) + " (" +
                (overflow ? std::string("more numbers than a file can hold")
                          : plural(static_cast<long long>(total), "number", "numbers")) +
                ": 2 a part, 3 a vertex, 1 an index), but only " +
                plural(available, "number follows", "numbers follow"));
    }
    if (counts.polygons > counts.indices / 3)
        return makeError(ErrorCode::Range, scanner.at(header.tokens[2]),
                         "the header declares " + plural(counts.polygons, "polygon", "polygons") +
                             " but only " +
                             plural(counts.indices, "polygon index", "polygon indices") +
                             ", fewer than the 3 each polygon needs");
    return success();
}

// One "first last" polygon range per part (parts only group polygons: the mesh is one).
Status readPartRanges(const LineScanner& scanner, TokenReader& tokens, const MovieCounts& counts) {
    Token token;
    for (long long p = 1; p <= counts.parts; ++p) {
        long long range[2] = {0, 0};
        SourceLocation rangeAt;
        for (int k = 0; k < 2; ++k) {
            tokens.next(token);  // present: counted by checkMovieFits
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
        if (range[0] < 1 || range[1] < range[0] || range[1] > counts.polygons)
            return makeError(ErrorCode::Range, rangeAt,
                             "expected the polygon range of part " + std::to_string(p) +
                                 " within 1 to " + std::to_string(counts.polygons) +
                                 ", first <= last, found " + std::to_string(range[0]) + " to " +
                                 std::to_string(range[1]));
    }
    return success();
}

// The vertices, x y z each, however the lines group them.
Status readMovieVertices(const LineScanner& scanner, TokenReader& tokens, const MovieCounts& counts,
                         Mesh& mesh) {
    mesh.positions.reserve(static_cast<std::size_t>(counts.vertices));
    Token token;
    for (long long i = 0; i < counts.vertices; ++i) {
        const std::string which =
            "vertex " + std::to_string(i + 1) + " of " + std::to_string(counts.vertices);
        dvec4 p(0.0, 0.0, 0.0, 1.0);
        for (int k = 0; k < 3; ++k) {
            tokens.next(token);
            if (isComment(token)) return commentError(scanner, token, which + " (x y z)");
            auto value = readCoordinate(scanner, token, k, which);
            if (!value) return value.error();
            p[k] = *value;
        }
        mesh.positions.push_back(p);
    }
    return success();
}

// An index of polygon `which`, the polygons before it `completed`: a 1-based vertex,
// negated when it ends the polygon.
Result<long long> readPolygonIndex(const LineScanner& scanner, const Token& token,
                                   const std::string& which, const MovieCounts& counts,
                                   long long completed) {
    if (isComment(token)) return commentError(scanner, token, "an index of " + which);
    const auto index = parseInteger(token.text);
    if (!index)
        return makeError(ErrorCode::Syntax, scanner.at(token),
                         "expected a vertex index (a non-zero integer, negated at the end of "
                         "a polygon) for " +
                             which + ", found " + quoted(token.text));
    if (completed == counts.polygons)
        return makeError(ErrorCode::Range, scanner.at(token),
                         which + " starts here, but the header declares only " +
                             plural(counts.polygons, "polygon", "polygons"));
    if (*index == 0)
        return makeError(ErrorCode::Range, scanner.at(token),
                         which + " refers to vertex 0, but indices are 1-based (1 to " +
                             std::to_string(counts.vertices) + ")");
    // |index|, or 0 for the one value whose magnitude does not fit.
    const long long vertex =
        *index == std::numeric_limits<long long>::min() ? 0 : std::llabs(*index);
    if (vertex == 0 || vertex > counts.vertices)
        return makeError(ErrorCode::Range, scanner.at(token),
                         which + " refers to vertex " + std::string(withoutSign(token.text)) +
                             ", but the file declares only " +
                             plural(counts.vertices, "vertex", "vertices"));
    return *index;
}

// A polygon being read: its vertices (0-based) and the line it starts on.
struct OpenPolygon {
    std::vector<std::uint32_t> vertices;
    int line = 0;
};

// Ends polygon `which` at `token`, its negated last index: fan-triangulated into `mesh`.
Status endPolygon(const LineScanner& scanner, const Token& token, const std::string& which,
                  OpenPolygon& polygon, Mesh& mesh) {
    const std::vector<std::uint32_t>& v = polygon.vertices;
    if (v.size() < 3)
        return makeError(ErrorCode::Range, scanner.at(token),
                         which + " has " +
                             plural(static_cast<long long>(v.size()), "vertex", "vertices") +
                             ", but a polygon needs at least 3");
    for (std::size_t k = 1; k + 1 < v.size(); ++k) {
        mesh.triangles.push_back({v[0], v[k], v[k + 1]});
        mesh.triangleLines.push_back(polygon.line);
    }
    polygon.vertices.clear();
    return success();
}

// The polygons: 1-based indices, the last of each negated; each fan-triangulated.
Status readPolygons(const LineScanner& scanner, const TextLine& header, TokenReader& tokens,
                    const MovieCounts& counts, Mesh& mesh, std::vector<unsigned char>& used) {
    OpenPolygon polygon;
    long long completed = 0;
    SourceLocation lastIndex;
    Token token;
    for (long long e = 0; e < counts.indices; ++e) {
        tokens.next(token);
        const std::string which = "polygon " + std::to_string(completed + 1);
        auto index = readPolygonIndex(scanner, token, which, counts, completed);
        if (!index) return index.error();
        const long long vertex = std::llabs(*index);  // checked by readPolygonIndex
        if (polygon.vertices.empty()) polygon.line = token.line;
        polygon.vertices.push_back(static_cast<std::uint32_t>(vertex - 1));
        used[static_cast<std::size_t>(vertex - 1)] = 1;
        lastIndex = scanner.at(token);
        if (*index > 0) continue;
        if (Status ended = endPolygon(scanner, token, which, polygon, mesh); !ended)
            return ended.error();
        ++completed;
    }
    if (!polygon.vertices.empty())
        return makeError(ErrorCode::Syntax, lastIndex,
                         "expected the last index of polygon " + std::to_string(completed + 1) +
                             " to be negative (it ends the polygon), found the end of the "
                             "header's " +
                             plural(counts.indices, "polygon index", "polygon indices"));
    if (completed < counts.polygons)
        return makeError(ErrorCode::Range, scanner.at(header.tokens[2]),
                         "the header declares " + plural(counts.polygons, "polygon", "polygons") +
                             ", but its " +
                             plural(counts.indices, "polygon index", "polygon indices") +
                             " end only " + std::to_string(completed));
    return success();
}

}  // namespace

bool isMovieByuHeader(const TextLine& line) {
    return line.tokens.size() == 4 &&
           std::all_of(line.tokens.begin(), line.tokens.end(),
                       [](const Token& t) { return parseInteger(t.text).has_value(); });
}

Result<Mesh> readMovieByu(LineScanner& scanner, const TextLine& header, std::string& summary,
                          Diagnostics& diagnostics) {
    auto counts = readMovieCounts(scanner, header);
    if (!counts) return counts.error();
    TokenReader tokens(scanner);
    if (Status fits = checkMovieFits(scanner, header, *counts, tokens); !fits) return fits.error();
    if (Status ranges = readPartRanges(scanner, tokens, *counts); !ranges) return ranges.error();

    Mesh mesh;
    mesh.source = scanner.at(0, 0);
    if (Status read = readMovieVertices(scanner, tokens, *counts, mesh); !read) return read.error();
    std::vector<unsigned char> used(mesh.positions.size(), 0);
    if (Status read = readPolygons(scanner, header, tokens, *counts, mesh, used); !read)
        return read.error();

    Token token;
    if (tokens.next(token)) {
        const long long remaining = 1 + tokens.countRemaining();
        diagnostics.warn(scanner.at(token),
                         "ignored " + plural(remaining, "value", "values") +
                             " after the declared " + declaredText(*counts) +
                             " (the header's counts may be wrong, or a second object follows)");
    }
    warnUnusedVertices(mesh, used, diagnostics);
    summary = plural(counts->parts, "part", "parts") + ", " +
              plural(counts->vertices, "vertex", "vertices") + " and " +
              plural(counts->polygons, "polygon", "polygons");
    return mesh;
}

}  // namespace rl::course_io
