// The course's Bezier surface, shipped as .byu: "m n", the evaluations per direction E, then
// the (m+1)(n+1) control points row by row, evaluated on an E x E grid.
#include "bezier.h"
#include "course_fields.h"

namespace rl::course_io {

Result<Mesh> readBezierSurface(LineScanner& scanner, const TextLine& header,
                               const TextLine& evaluationsLine, Diagnostics& diagnostics) {
    int degree[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
        const Token& token = header.tokens[static_cast<std::size_t>(k)];
        const long long value = *parseInteger(token.text);  // an integer: detected so
        if (value < 1 || value > kMaxBezierDegree)
            return makeError(ErrorCode::Range, scanner.at(token),
                             std::string("expected the degree ") + (k == 0 ? "m" : "n") +
                                 " of the Bezier surface (an integer from 1 to " +
                                 std::to_string(kMaxBezierDegree) + "), found " +
                                 quoted(token.text));
        degree[k] = static_cast<int>(value);
    }
    if (header.tokens.size() > 2)
        diagnostics.warn(
            scanner.at(header.tokens[2]),
            "ignored " +
                plural(static_cast<long long>(header.tokens.size() - 2), "value", "values") +
                " after the Bezier surface's two degrees");
    const Token& evaluationsToken = evaluationsLine.tokens[0];
    const long long evaluations = *parseInteger(evaluationsToken.text);
    if (evaluations < 2 || evaluations > kMaxBezierEvaluations)
        return makeError(ErrorCode::Range, scanner.at(evaluationsToken),
                         "expected the number of evaluations per direction (an integer from 2 "
                         "to " +
                             std::to_string(kMaxBezierEvaluations) + "), found " +
                             quoted(evaluationsToken.text));

    const int m = degree[0], n = degree[1];
    const long long pointCount = static_cast<long long>(m + 1) * (n + 1);
    const std::string degrees = std::to_string(m) + " x " + std::to_string(n);
    const long long available = scanner.countRemainingLines();
    if (pointCount > available)
        return makeError(ErrorCode::Range, scanner.at(header.tokens[0]),
                         "the header declares a Bezier surface of degrees " + degrees + ", so " +
                             std::to_string(pointCount) +
                             " control points (one a line), but only " +
                             plural(available, "line follows", "lines follow"));

    std::vector<dvec3> control;
    control.reserve(static_cast<std::size_t>(pointCount));
    static const char* const kAxis[] = {"x", "y", "z"};
    long long linesWithExtraValues = 0;
    SourceLocation firstExtra;
    TextLine line;
    for (int i = 0; i <= m; ++i) {
        for (int j = 0; j <= n; ++j) {
            scanner.next(line);  // present: counted above
            const std::string which =
                "control point (" + std::to_string(i) + ", " + std::to_string(j) + ")";
            if (isComment(line.tokens[0]))
                return commentError(scanner, line.tokens[0], which + " (x y z)");
            dvec3 p(0.0);
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
                                         " coordinate of " + which + ", " +
                                         whyNotNumber(token.text));
                p[k] = *value;
            }
            if (line.tokens.size() > 3 && linesWithExtraValues++ == 0)
                firstExtra = scanner.at(line.tokens[3]);
            control.push_back(p);
        }
    }
    if (linesWithExtraValues > 0)
        diagnostics.warn(firstExtra, "ignored extra values at the end of " +
                                         plural(linesWithExtraValues, "line", "lines") +
                                         " (the first is here)");
    if (scanner.next(line)) {
        const int remaining = 1 + scanner.countRemainingLines();
        diagnostics.warn(scanner.at(line.number, 1),
                         "ignored " + plural(remaining, "line", "lines") + " after the " +
                             std::to_string(pointCount) + " control points of the Bezier surface");
    }

    // E x E points, two triangles for each of the (E - 1)^2 cells.
    const auto count = static_cast<std::uint32_t>(evaluations);
    Mesh mesh;
    mesh.source = scanner.at(0, 0);
    const std::vector<dvec3> grid =
        evaluateBezierSurfaceGrid(control, m, n, static_cast<int>(count));
    mesh.positions.reserve(grid.size());
    for (const dvec3& p : grid) mesh.positions.emplace_back(p, 1.0);
    const auto index = [count](std::uint32_t a, std::uint32_t b) { return a * count + b; };
    mesh.triangles.reserve(2 * static_cast<std::size_t>(count - 1) * (count - 1));
    for (std::uint32_t a = 0; a + 1 < count; ++a)
        for (std::uint32_t b = 0; b + 1 < count; ++b) {
            mesh.triangles.push_back({index(a, b), index(a + 1, b), index(a + 1, b + 1)});
            mesh.triangles.push_back({index(a, b), index(a + 1, b + 1), index(a, b + 1)});
        }
    return mesh;
}

}  // namespace rl::course_io
