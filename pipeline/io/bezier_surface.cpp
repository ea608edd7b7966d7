// The course's Bezier surface, shipped as .byu: "m n", the evaluations per direction E, then
// the (m+1)(n+1) control points row by row, evaluated on an E x E grid.
#include "pipeline/io/course_fields.h"
#include "pipeline/scene/bezier.h"

namespace rl::course_io {

namespace {

// What the first two lines declare: the degrees m x n and the evaluations per direction E.
struct BezierHeader {
    int m = 0;
    int n = 0;
    long long evaluations = 0;
};

Result<BezierHeader> readBezierHeader(const LineScanner& scanner, const TextLine& header,
                                      const TextLine& evaluationsLine, Diagnostics& diagnostics) {
    int degree[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
        const Token& token = header.tokens[static_cast<std::size_t>(k)];
        const long long value = *parseInteger(token.text);  // an integer: detected so
        if (value < 1 || value > kMaxBezierDegree)
            return makeError(
                ErrorCode::Range, scanner.at(token),
                "expected the degree %1 of the Bezier surface (an integer from 1 to "
                "%2), found %3"_msg(k == 0 ? "m" : "n", kMaxBezierDegree, quoted(token.text)));
        degree[k] = static_cast<int>(value);
    }
    if (header.tokens.size() > 2)
        diagnostics.warn(scanner.at(header.tokens[2]),
                         "ignored %1 after the Bezier surface's two degrees"_msg(
                             valuesText(static_cast<long long>(header.tokens.size() - 2))));
    const Token& evaluationsToken = evaluationsLine.tokens[0];
    const long long evaluations = *parseInteger(evaluationsToken.text);
    if (evaluations < 2 || evaluations > kMaxBezierEvaluations)
        return makeError(
            ErrorCode::Range, scanner.at(evaluationsToken),
            "expected the number of evaluations per direction (an integer from 2 "
            "to %1), found %2"_msg(kMaxBezierEvaluations, quoted(evaluationsToken.text)));
    return BezierHeader{degree[0], degree[1], evaluations};
}

// The (m+1)(n+1) control points, one a line, row by row.
Result<std::vector<dvec3>> readControlPoints(LineScanner& scanner, const TextLine& header,
                                             const BezierHeader& surface,
                                             Diagnostics& diagnostics) {
    const int m = surface.m, n = surface.n;
    const long long pointCount = static_cast<long long>(m + 1) * (n + 1);
    const long long available = scanner.countRemainingLines();
    if (pointCount > available)
        return makeError(ErrorCode::Range, scanner.at(header.tokens[0]),
                         "the header declares a Bezier surface of degrees %1 x %2, so %3 control "
                         "points (one a line), but only %4"_msg(
                             m, n, pointCount,
                             counted(available, "%1 line follows"_msg, "%1 lines follow"_msg)));

    std::vector<dvec3> control;
    control.reserve(static_cast<std::size_t>(pointCount));
    ExtraValues extra;
    TextLine line;
    for (int i = 0; i <= m; ++i) {
        for (int j = 0; j <= n; ++j) {
            scanner.next(line);  // present: counted above
            auto p = readPointLine(scanner, line, "control point (%1, %2)"_msg(i, j));
            if (!p) return p.error();
            extra.note(scanner, line);
            control.push_back(*p);
        }
    }
    extra.warn(diagnostics);
    if (scanner.next(line)) {
        const int remaining = 1 + scanner.countRemainingLines();
        diagnostics.warn(scanner.at(line.number, 1),
                         "ignored %1 after the %2 control points of the Bezier surface"_msg(
                             linesText(remaining), pointCount));
    }
    return control;
}

// The surface evaluated on E x E points, two triangles for each of the (E - 1)^2 cells.
Mesh gridMesh(const std::vector<dvec3>& control, const BezierHeader& surface,
              SourceLocation source) {
    const auto count = static_cast<std::uint32_t>(surface.evaluations);
    Mesh mesh;
    mesh.source = std::move(source);
    const std::vector<dvec3> grid =
        evaluateBezierSurfaceGrid(control, surface.m, surface.n, static_cast<int>(count));
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

}  // namespace

Result<Mesh> readBezierSurface(LineScanner& scanner, const TextLine& header,
                               const TextLine& evaluationsLine, Diagnostics& diagnostics) {
    auto surface = readBezierHeader(scanner, header, evaluationsLine, diagnostics);
    if (!surface) return surface.error();
    auto control = readControlPoints(scanner, header, *surface, diagnostics);
    if (!control) return control.error();
    return gridMesh(*control, *surface, scanner.at(0, 0));
}

}  // namespace rl::course_io
