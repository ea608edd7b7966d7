#include "bezier.h"

namespace rl {

namespace {

PatchPoint mix(const PatchPoint& a, const PatchPoint& b, double t) {
    return {glm::mix(a.p, b.p, t), glm::mix(a.colour, b.colour, static_cast<float>(t)),
            glm::mix(a.st, b.st, static_cast<float>(t))};
}

// a + (b - a) s + (c - a) t, for the triangular steps (weights u, v, w on a, b, c).
PatchPoint blend(const PatchPoint& a, const PatchPoint& b, const PatchPoint& c, double u, double v,
                 double w) {
    const auto fu = static_cast<float>(u), fv = static_cast<float>(v), fw = static_cast<float>(w);
    return {u * a.p + v * b.p + w * c.p, fu * a.colour + fv * b.colour + fw * c.colour,
            fu * a.st + fv * b.st + fw * c.st};
}

dvec3 position(const PatchPoint& p) {
    return p.p.w != 0.0 ? dvec3(p.p) / p.p.w : dvec3(p.p);
}

vec3 unit(const dvec3& n) {
    const double length = glm::length(n);
    return length > 0.0 ? vec3(n / length) : vec3(0.0f);
}

}  // namespace

PatchVertex evaluateRectBezier(const std::array<PatchPoint, 16>& control, double s, double t) {
    // 4x4 points -> 3x3 -> 2x2, each point the (s, t) point of a control quad.
    std::array<PatchPoint, 16> q = control;
    int size = 4;
    while (size > 2) {
        for (int row = 0; row + 1 < size; ++row)
            for (int col = 0; col + 1 < size; ++col) {
                const auto at = [&](int r, int c) {
                    return q[static_cast<std::size_t>(r * 4 + c)];
                };
                const PatchPoint bottom = mix(at(row, col), at(row, col + 1), s);
                const PatchPoint top = mix(at(row + 1, col), at(row + 1, col + 1), s);
                q[static_cast<std::size_t>(row * 4 + col)] = mix(bottom, top, t);
            }
        --size;
    }
    // The last quad: its (s, t) point is on the surface; its diagonals give the normal.
    const PatchPoint& p00 = q[0];
    const PatchPoint& p01 = q[1];  // next along s
    const PatchPoint& p10 = q[4];  // next along t
    const PatchPoint& p11 = q[5];
    const PatchPoint point = mix(mix(p00, p01, s), mix(p10, p11, s), t);
    PatchVertex v{point.p, point.colour, point.st, vec3(0.0f)};
    // (P11 - P00) x (P10 - P01) = 2 (dP/ds x dP/dt) for a parallelogram.
    v.normal = unit(glm::cross(position(p11) - position(p00), position(p10) - position(p01)));
    return v;
}

PatchMesh subdivideRectBezier(const std::array<PatchPoint, 16>& control, int subdivisions) {
    PatchMesh mesh;
    const int n = 1 << subdivisions;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            mesh.vertices.push_back(evaluateRectBezier(control, double(i) / n, double(j) / n));
    const auto index = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
    // Each quad is cut along its diagonal from (i + 1, j) to (i, j + 1), as the HW2 reference
    // images are: where the patch leaves the depth range [0, 1], the outline follows the
    // triangles, so the other diagonal would move it.
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            mesh.triangles.push_back({index(i, j), index(i + 1, j), index(i, j + 1)});
            mesh.triangles.push_back({index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)});
        }
    return mesh;
}

PatchVertex evaluateTriBezier(const std::array<PatchPoint, 10>& control, double u, double v,
                              double w) {
    // Points of a triangular patch of degree d, row r (0..d) holding d + 1 - r points.
    std::array<PatchPoint, 10> q = control;
    const auto at = [](int r, int c) {
        // The first index of row r in rows of 4, 3, 2, 1.
        static constexpr int kRowStart[4] = {0, 4, 7, 9};
        return static_cast<std::size_t>(kRowStart[r] + c);
    };
    for (int degree = 3; degree > 1; --degree)
        for (int r = 0; r < degree; ++r)
            for (int c = 0; c + r < degree; ++c)
                q[at(r, c)] = blend(q[at(r, c)], q[at(r, c + 1)], q[at(r + 1, c)], u, v, w);
    // The last triangle: its (u, v, w) point is on the surface; its edges give the normal.
    const PatchPoint& a = q[at(0, 0)];
    const PatchPoint& b = q[at(0, 1)];
    const PatchPoint& c = q[at(1, 0)];
    const PatchPoint point = blend(a, b, c, u, v, w);
    PatchVertex vertex{point.p, point.colour, point.st, vec3(0.0f)};
    vertex.normal = unit(glm::cross(position(b) - position(a), position(c) - position(a)));
    return vertex;
}

PatchMesh subdivideTriBezier(const std::array<PatchPoint, 10>& control, int subdivisions) {
    PatchMesh mesh;
    const int n = 1 << subdivisions;
    // Grid points (i, j) with i + j <= n: weights u = (n - i - j)/n, v = i/n, w = j/n.
    std::vector<std::uint32_t> rowStart;
    for (int j = 0; j <= n; ++j) {
        rowStart.push_back(static_cast<std::uint32_t>(mesh.vertices.size()));
        for (int i = 0; i + j <= n; ++i)
            mesh.vertices.push_back(
                evaluateTriBezier(control, double(n - i - j) / n, double(i) / n, double(j) / n));
    }
    const auto index = [&](int i, int j) {
        return rowStart[static_cast<std::size_t>(j)] + static_cast<std::uint32_t>(i);
    };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i + j < n; ++i) {
            mesh.triangles.push_back({index(i, j), index(i + 1, j), index(i, j + 1)});
            if (i + j + 1 < n)
                mesh.triangles.push_back({index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)});
        }
    return mesh;
}

std::vector<double> bernsteinWeights(int degree, double t) {
    // Raising the degree one step at a time: B(k, d) = (1 - t) B(k, d - 1) + t B(k - 1, d - 1).
    std::vector<double> weights(static_cast<std::size_t>(degree) + 1, 0.0);
    weights[0] = 1.0;
    for (int d = 1; d <= degree; ++d)
        for (int k = d; k >= 0; --k) {
            const auto at = static_cast<std::size_t>(k);
            weights[at] = (1.0 - t) * weights[at] + (k > 0 ? t * weights[at - 1] : 0.0);
        }
    return weights;
}

namespace {

// The point at t of the Bezier curve through `points` (modified in place).
dvec3 deCasteljau(std::vector<dvec3>& points, double t) {
    for (std::size_t size = points.size(); size > 1; --size)
        for (std::size_t k = 0; k + 1 < size; ++k)
            points[k] = glm::mix(points[k], points[k + 1], t);
    return points.front();
}

}  // namespace

dvec3 evaluateBezierSurface(std::span<const dvec3> control, int m, int n, double u, double v) {
    const auto columns = static_cast<std::size_t>(n) + 1;
    std::vector<dvec3> column(static_cast<std::size_t>(m) + 1);
    std::vector<dvec3> row(columns);
    for (std::size_t i = 0; i < column.size(); ++i) {
        row.assign(control.begin() + static_cast<std::ptrdiff_t>(i * columns),
                   control.begin() + static_cast<std::ptrdiff_t>((i + 1) * columns));
        column[i] = deCasteljau(row, v);
    }
    return deCasteljau(column, u);
}

std::vector<dvec3> evaluateBezierSurfaceGrid(std::span<const dvec3> control, int m, int n,
                                             int evaluations) {
    const auto count = static_cast<std::size_t>(evaluations);
    const auto rows = static_cast<std::size_t>(m) + 1;
    const auto columns = static_cast<std::size_t>(n) + 1;
    const auto parameter = [&](std::size_t k) {
        return static_cast<double>(k) / static_cast<double>(count - 1);
    };
    // Each row's curve at every v first, then each grid point from the rows' curves.
    std::vector<dvec3> rowCurves(rows * count, dvec3(0.0));  // [i * count + b]
    for (std::size_t b = 0; b < count; ++b) {
        const std::vector<double> weights = bernsteinWeights(n, parameter(b));
        for (std::size_t i = 0; i < rows; ++i) {
            dvec3 sum(0.0);
            for (std::size_t j = 0; j < columns; ++j) sum += weights[j] * control[i * columns + j];
            rowCurves[i * count + b] = sum;
        }
    }
    std::vector<dvec3> grid(count * count, dvec3(0.0));
    for (std::size_t a = 0; a < count; ++a) {
        const std::vector<double> weights = bernsteinWeights(m, parameter(a));
        for (std::size_t b = 0; b < count; ++b) {
            dvec3 sum(0.0);
            for (std::size_t i = 0; i < rows; ++i) sum += weights[i] * rowCurves[i * count + b];
            grid[a * count + b] = sum;
        }
    }
    return grid;
}

}  // namespace rl
