// The original Movie.BYU format: "parts vertices polygons edges", a "first last" polygon range
// per part, the vertices, then the polygons' 1-based indices, the last of each negated.
#include <algorithm>
#include <cstdlib>
#include <limits>

#include "pipeline/io/course_fields.h"

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
    auto parts = readCount(scanner, header.tokens[0], "parts"_msg);
    if (!parts) return parts.error();
    auto vertexCount = readCount(scanner, header.tokens[1], "vertices"_msg);
    if (!vertexCount) return vertexCount.error();
    auto polygonCount = readCount(scanner, header.tokens[2], "polygons"_msg);
    if (!polygonCount) return polygonCount.error();
    auto indexCount = readCount(scanner, header.tokens[3], "polygon indices (edges)"_msg);
    if (!indexCount) return indexCount.error();
    return MovieCounts{*parts, *vertexCount, *polygonCount, *indexCount};
}

Message partsText(long long n) {
    return counted(n, "%1 part"_msg, "%1 parts"_msg);
}

Message polygonsText(long long n) {
    return counted(n, "%1 polygon"_msg, "%1 polygons"_msg);
}

Message indicesText(long long n) {
    return counted(n, "%1 polygon index"_msg, "%1 polygon indices"_msg);
}

// "1 part, 4 vertices and 4 polygon indices": the numbers the header declares.
Message declaredText(const MovieCounts& counts) {
    return "%1, %2 and %3"_msg(partsText(counts.parts), verticesText(counts.vertices),
                               indicesText(counts.indices));
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
            "the header declares %1 (%2: 2 a part, 3 a vertex, 1 an index), but only %3"_msg(
                declaredText(counts),
                overflow ? Message("more numbers than a file can hold"_msg)
                         : numbersText(static_cast<long long>(total)),
                counted(available, "%1 number follows"_msg, "%1 numbers follow"_msg)));
    }
    if (counts.polygons > counts.indices / 3)
        return makeError(ErrorCode::Range, scanner.at(header.tokens[2]),
                         "the header declares %1 but only %2, fewer than the 3 each polygon "
                         "needs"_msg(polygonsText(counts.polygons), indicesText(counts.indices)));
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
            const Message what = (k == 0 ? "the first polygon of part %1"_msg
                                         : "the last polygon of part %1"_msg)(p);
            if (isComment(token)) return commentError(scanner, token, what);
            const auto value = parseInteger(token.text);
            if (!value)
                return makeError(
                    ErrorCode::Syntax, scanner.at(token),
                    "expected %1 (a positive integer), found %2"_msg(what, quoted(token.text)));
            range[k] = *value;
        }
        if (range[0] < 1 || range[1] < range[0] || range[1] > counts.polygons)
            return makeError(ErrorCode::Range, rangeAt,
                             "expected the polygon range of part %1 within 1 to %2, first <= last, "
                             "found %3 to %4"_msg(p, counts.polygons, range[0], range[1]));
    }
    return success();
}

// The vertices, x y z each, however the lines group them.
Status readMovieVertices(const LineScanner& scanner, TokenReader& tokens, const MovieCounts& counts,
                         Mesh& mesh) {
    mesh.positions.reserve(static_cast<std::size_t>(counts.vertices));
    Token token;
    for (long long i = 0; i < counts.vertices; ++i) {
        const Message which = "vertex %1 of %2"_msg(i + 1, counts.vertices);
        dvec4 p(0.0, 0.0, 0.0, 1.0);
        for (int k = 0; k < 3; ++k) {
            tokens.next(token);
            if (isComment(token)) return commentError(scanner, token, "%1 (x y z)"_msg(which));
            auto value = readCoordinate(scanner, token, k, which);
            if (!value) return value.error();
            p[k] = *value;
        }
        mesh.positions.push_back(p);
    }
    return success();
}

// An index of the polygon after the `completed` ones: a 1-based vertex, negated when it ends
// the polygon.
Result<long long> readPolygonIndex(const LineScanner& scanner, const Token& token,
                                   const MovieCounts& counts, long long completed) {
    const long long polygon = completed + 1;
    if (isComment(token))
        return commentError(scanner, token, "an index of polygon %1"_msg(polygon));
    const auto index = parseInteger(token.text);
    if (!index)
        return makeError(ErrorCode::Syntax, scanner.at(token),
                         "expected a vertex index (a non-zero integer, negated at the end of a "
                         "polygon) for polygon %1, found %2"_msg(polygon, quoted(token.text)));
    if (completed == counts.polygons)
        return makeError(ErrorCode::Range, scanner.at(token),
                         "polygon %1 starts here, but the header declares only %2"_msg(
                             polygon, polygonsText(counts.polygons)));
    if (*index == 0)
        return makeError(ErrorCode::Range, scanner.at(token),
                         "polygon %1 refers to vertex 0, but indices are 1-based (1 to %2)"_msg(
                             polygon, counts.vertices));
    // |index|, or 0 for the one value whose magnitude does not fit.
    const long long vertex =
        *index == std::numeric_limits<long long>::min() ? 0 : std::llabs(*index);
    if (vertex == 0 || vertex > counts.vertices)
        return makeError(ErrorCode::Range, scanner.at(token),
                         "polygon %1 refers to vertex %2, but the file declares only %3"_msg(
                             polygon, withoutSign(token.text), verticesText(counts.vertices)));
    return *index;
}

// A polygon being read: its vertices (0-based) and the line it starts on.
struct OpenPolygon {
    std::vector<std::uint32_t> vertices;
    int line = 0;
};

// Ends polygon `number` at `token`, its negated last index: fan-triangulated into `mesh`.
Status endPolygon(const LineScanner& scanner, const Token& token, long long number,
                  OpenPolygon& polygon, Mesh& mesh) {
    const std::vector<std::uint32_t>& v = polygon.vertices;
    if (v.size() < 3)
        return makeError(ErrorCode::Range, scanner.at(token),
                         "polygon %1 has %2, but a polygon needs at least 3"_msg(
                             number, verticesText(static_cast<long long>(v.size()))));
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
        auto index = readPolygonIndex(scanner, token, counts, completed);
        if (!index) return index.error();
        const long long vertex = std::llabs(*index);  // checked by readPolygonIndex
        if (polygon.vertices.empty()) polygon.line = token.line;
        polygon.vertices.push_back(static_cast<std::uint32_t>(vertex - 1));
        used[static_cast<std::size_t>(vertex - 1)] = 1;
        lastIndex = scanner.at(token);
        if (*index > 0) continue;
        if (Status ended = endPolygon(scanner, token, completed + 1, polygon, mesh); !ended)
            return ended.error();
        ++completed;
    }
    if (!polygon.vertices.empty())
        return makeError(ErrorCode::Syntax, lastIndex,
                         "expected the last index of polygon %1 to be negative (it ends the "
                         "polygon), found the end of the header's %2"_msg(
                             completed + 1, indicesText(counts.indices)));
    if (completed < counts.polygons)
        return makeError(
            ErrorCode::Range, scanner.at(header.tokens[2]),
            "the header declares %1, but its %2 end only %3"_msg(
                polygonsText(counts.polygons), indicesText(counts.indices), completed));
    return success();
}

}  // namespace

bool isMovieByuHeader(const TextLine& line) {
    return line.tokens.size() == 4 &&
           std::all_of(line.tokens.begin(), line.tokens.end(),
                       [](const Token& t) { return parseInteger(t.text).has_value(); });
}

Result<Mesh> readMovieByu(LineScanner& scanner, const TextLine& header, Message& summary,
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
        diagnostics.warn(
            scanner.at(token),
            "ignored %1 after the declared %2 (the header's counts may be wrong, or "
            "a second object follows)"_msg(valuesText(remaining), declaredText(*counts)));
    }
    warnUnusedVertices(mesh, used, diagnostics);
    summary = "%1, %2 and %3"_msg(partsText(counts->parts), verticesText(counts->vertices),
                                  polygonsText(counts->polygons));
    return mesh;
}

}  // namespace rl::course_io
