#include "app/check/stage_mistakes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace rasterlab::check {

using rl::dvec3;

namespace {

dvec3 normalised(const dvec3& v) {
    const double length = glm::length(v);
    return length > 0.0 ? v / length : dvec3(0.0);
}

Row rowOf(const dvec3& v) {
    return {v.x, v.y, v.z};
}

dvec3 vecOf(const Row& r) {
    return {r[0], r[1], r[2]};
}

Alternative basisRows(std::string cause, const dvec3& u, const dvec3& v, const dvec3& n) {
    return {std::move(cause), {rowOf(u), rowOf(v), rowOf(n)}};
}

}  // namespace

std::vector<Alternative> basisMistakes(const dvec3& nGiven, const dvec3& vGiven) {
    const dvec3 n = normalised(nGiven);
    const dvec3 v = normalised(vGiven - glm::dot(vGiven, n) * n);
    const dvec3 vRaw = vGiven - glm::dot(vGiven, nGiven) * nGiven;
    const dvec3 vUnnormalised = vGiven - glm::dot(vGiven, n) * n;
    const dvec3 vOnly = normalised(vGiven);
    return {
        basisRows("U = V x N: the cross product in the other order", glm::cross(v, n), v, n),
        basisRows("N not normalised before V - (V.N)N, nor after",
                  glm::cross(nGiven, normalised(vRaw)), normalised(vRaw), nGiven),
        basisRows("N normalised only after V - (V.N)N", glm::cross(n, normalised(vRaw)),
                  normalised(vRaw), n),
        basisRows("V not normalised after V - (V.N)N", glm::cross(n, vUnnormalised), vUnnormalised,
                  n),
        basisRows("V not made orthogonal to N (Gram-Schmidt left out)", glm::cross(n, vOnly), vOnly,
                  n),
    };
}

std::vector<Alternative> viewMistakes(const dvec3& c, const std::array<dvec3, 3>& uvn,
                                      const dvec3& light, const std::vector<Row>& vertices) {
    const auto rows = [&](const dvec3& p, bool minusC) {
        const dvec3 q = minusC ? p - c : p;
        return rowOf({glm::dot(uvn[0], q), glm::dot(uvn[1], q), glm::dot(uvn[2], q)});
    };
    const auto columns = [&](const dvec3& p) {
        const dvec3 q = p - c;
        return rowOf(uvn[0] * q.x + uvn[1] * q.y + uvn[2] * q.z);
    };
    std::vector<Alternative> out(5);
    out[0].cause = "the light left in world coordinates";
    out[1].cause = "the light taken to view coordinates without subtracting C: [U; V; N] Pl";
    out[2].cause = "the vertices taken to view coordinates without subtracting C: [U; V; N] P";
    out[3].cause = "C not subtracted at all: [U; V; N] P for the vertices and the light";
    out[4].cause = "the basis as columns instead of rows: U x + V y + N z of P - C";
    out[0].rows = {rowOf(light)};
    out[1].rows = {rows(light, false)};
    out[2].rows = {rows(light, true)};
    out[3].rows = {rows(light, false)};
    out[4].rows = {columns(light)};
    for (const Row& r : vertices) {
        const dvec3 p = vecOf(r);
        out[0].rows.push_back(rows(p, true));
        out[1].rows.push_back(rows(p, true));
        out[2].rows.push_back(rows(p, false));
        out[3].rows.push_back(rows(p, false));
        out[4].rows.push_back(columns(p));
    }
    return out;
}

std::vector<Alternative> normalsMistakes(
    const std::vector<Row>& vertices, const std::vector<std::array<std::uint32_t, 3>>& triangles) {
    const std::size_t n = vertices.size();
    std::vector<dvec3> raw, unit;
    std::vector<dvec3> sumUnit(n, dvec3(0.0)), sumRaw(n, dvec3(0.0));
    std::vector<int> count(n, 0);
    for (const auto& t : triangles) {
        const dvec3 a = vecOf(vertices[t[0]]), b = vecOf(vertices[t[1]]), c = vecOf(vertices[t[2]]);
        const dvec3 cross = glm::cross(b - a, c - a);
        raw.push_back(cross);
        unit.push_back(normalised(cross));
        for (std::uint32_t i : t) {
            sumUnit[i] += unit.back();
            sumRaw[i] += cross;
            ++count[i];
        }
    }
    const auto make = [&](std::string cause, auto triangle, auto vertex) {
        Alternative a{std::move(cause), {}};
        for (std::size_t t = 0; t < triangles.size(); ++t) a.rows.push_back(rowOf(triangle(t)));
        for (std::size_t i = 0; i < n; ++i) a.rows.push_back(rowOf(vertex(i)));
        return a;
    };
    const auto unitT = [&](std::size_t t) { return unit[t]; };
    const auto unitV = [&](std::size_t i) { return normalised(sumUnit[i]); };
    return {
        make(
            "the cross product in the other order: (Pc - Pa) x (Pb - Pa)",
            [&](std::size_t t) { return -unit[t]; }, [&](std::size_t i) { return -unitV(i); }),
        make(
            "the triangle normals not normalised (and summed at their length)",
            [&](std::size_t t) { return raw[t]; },
            [&](std::size_t i) { return normalised(sumRaw[i]); }),
        make("the vertex normals not normalised: the sum left at its length", unitT,
             [&](std::size_t i) { return sumUnit[i]; }),
        make("the vertex normals summed from triangle normals not normalised (weighted by area)",
             unitT, [&](std::size_t i) { return normalised(sumRaw[i]); }),
        make("the vertex normals averaged (divided by their count), not normalised", unitT,
             [&](std::size_t i) { return count[i] ? sumUnit[i] / double(count[i]) : dvec3(0.0); }),
    };
}

std::array<double, 2> projectionExact(double d, double hx, double hy, int width, int height,
                                      const Row& p) {
    return {(d / hx * (p[0] / p[2]) + 1.0) * width / 2.0,
            (1.0 - d / hy * (p[1] / p[2])) * height / 2.0};
}

std::vector<Alternative> projectionMistakes(double d, double hx, double hy, int width, int height,
                                            const std::vector<Row>& vertices) {
    std::vector<Alternative> out(5);
    out[0].cause = "rounded to the nearest pixel instead of truncated by (int)";
    out[1].cause = "y not flipped: (int)((d/hy * y/z + 1) * height/2), y growing upward";
    out[2].cause = "hx and hy swapped";
    out[3].cause = "floor instead of (int): pixels left of or above the screen one lower";
    out[4].cause =
        "without the + 1: (int)(d/hx * x/z * width/2), the screen's centre at its corner";
    for (const Row& p : vertices) {
        const auto e = projectionExact(d, hx, hy, width, height, p);
        const double yUp = (d / hy * (p[1] / p[2]) + 1.0) * height / 2.0;
        const auto s = projectionExact(d, hy, hx, width, height, p);
        out[0].rows.push_back({std::floor(e[0] + 0.5), std::floor(e[1] + 0.5)});
        out[1].rows.push_back({std::trunc(e[0]), std::trunc(yUp)});
        out[2].rows.push_back({std::trunc(s[0]), std::trunc(s[1])});
        out[3].rows.push_back({std::floor(e[0]), std::floor(e[1])});
        out[4].rows.push_back({std::trunc(d / hx * (p[0] / p[2]) * width / 2.0),
                               std::trunc(-d / hy * (p[1] / p[2]) * height / 2.0)});
    }
    return out;
}

std::vector<Row> scanSpans(const std::vector<Row>& triangles, int width, int height, bool strict) {
    std::vector<Row> spans;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const Row& r = triangles[t];
        const std::int64_t x[3] = {std::int64_t(r[0]), std::int64_t(r[2]), std::int64_t(r[4])};
        const std::int64_t y[3] = {std::int64_t(r[1]), std::int64_t(r[3]), std::int64_t(r[5])};
        const std::int64_t area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
        if (area == 0) continue;
        const std::int64_t sign = area > 0 ? 1 : -1;
        const std::int64_t yFirst = std::max<std::int64_t>(0, std::min({y[0], y[1], y[2]}));
        const std::int64_t yLast = std::min<std::int64_t>(height - 1, std::max({y[0], y[1], y[2]}));
        const std::int64_t xFirst = std::max<std::int64_t>(0, std::min({x[0], x[1], x[2]}));
        const std::int64_t xLast = std::min<std::int64_t>(width - 1, std::max({x[0], x[1], x[2]}));
        for (std::int64_t py = yFirst; py <= yLast; ++py) {
            std::int64_t first = -1, last = -1;
            for (std::int64_t px = xFirst; px <= xLast; ++px) {
                bool inside = true;
                for (int k = 0; k < 3 && inside; ++k) {
                    const int j = (k + 1) % 3;
                    const std::int64_t e =
                        sign * ((x[j] - x[k]) * (py - y[k]) - (y[j] - y[k]) * (px - x[k]));
                    inside = strict ? e > 0 : e >= 0;
                }
                if (!inside) continue;
                if (first < 0) first = px;
                last = px;
            }
            if (first >= 0) spans.push_back({double(t), double(py), double(first), double(last)});
        }
    }
    return spans;
}

std::vector<Alternative> scanMistakes(const std::vector<Row>& triangles, int width, int height) {
    const std::vector<Row> ours = scanSpans(triangles, width, height, false);
    std::vector<Alternative> out(4);
    out[0] = {"a sample on an edge left out (edge functions > 0 instead of >= 0)",
              scanSpans(triangles, width, height, true)};
    out[1].cause = "each span's last pixel left out (x < last instead of x <= last)";
    out[2].cause = "each span's first pixel left out";
    out[3].cause = "each triangle's last row left out (y < y_max instead of y <= y_max)";
    std::map<double, double> lastRow;
    for (const Row& s : ours)
        lastRow[s[0]] = std::max(lastRow.count(s[0]) ? lastRow[s[0]] : s[1], s[1]);
    for (const Row& s : ours) {
        if (s[3] > s[2]) out[1].rows.push_back({s[0], s[1], s[2], s[3] - 1});
        if (s[3] > s[2]) out[2].rows.push_back({s[0], s[1], s[2] + 1, s[3]});
        const Row& t = triangles[std::size_t(s[0])];
        const double yMax = std::max({t[1], t[3], t[5]});
        if (s[1] < yMax) out[3].rows.push_back(s);
    }
    return out;
}

std::vector<Alternative> zbufferMistakes(const std::vector<Fragment>& fragments) {
    struct Kept {
        std::uint32_t t;
        float z;
    };
    const auto run = [&](auto keep) {
        std::map<std::pair<std::int32_t, std::int32_t>, Kept> buffer;
        for (const Fragment& f : fragments) {
            const auto key = std::make_pair(f.y, f.x);
            const auto it = buffer.find(key);
            if (it == buffer.end() || keep(f.z, it->second.z)) buffer[key] = {f.t, f.z};
        }
        std::vector<Row> rows;
        for (const auto& [key, k] : buffer)
            rows.push_back({double(key.second), double(key.first), double(k.t), double(k.z)});
        return rows;
    };
    return {
        {"the farther fragment wins (z > stored, the buffer starting at -infinity)",
         run([](float z, float stored) { return z > stored; })},
        {"on a tie the later fragment wins (z <= stored instead of z < stored)",
         run([](float z, float stored) { return z <= stored; })},
        {"no depth test: the last fragment drawn wins", run([](float, float) { return true; })},
        {"the buffer starts at 0 instead of +infinity: no fragment in front of the camera passes",
         {}},
    };
}

namespace {

enum LightingSlip : unsigned {
    NoFlip = 1u << 0,
    ViewReversed = 1u << 1,
    DiffuseBehind = 1u << 2,
    SpecularBehind = 1u << 3,
    NoClamp = 1u << 4,
    AmbientIaOnly = 1u << 5,
    AmbientTimesOd = 1u << 6,
    TruncateTerms = 1u << 7,
    Epsilon = 1u << 8,
    SpecularTimesOd = 1u << 9,
    BlinnPhong = 1u << 10,
    NoSpecular = 1u << 11,
};

Row phongWith(const Lighting& l, const Sample& s, unsigned slips) {
    const dvec3 p(s.p);
    const double eps = (slips & Epsilon) ? 1e-3 : 0.0;
    dvec3 n = normalised(dvec3(s.n));
    const dvec3 v = normalised((slips & ViewReversed) ? p : -p);
    const dvec3 lv = normalised(l.light - p);
    if (!(slips & NoFlip) && glm::dot(v, n) < eps) n = -n;
    const dvec3 ia(l.ia), il(l.il), od(l.od);
    dvec3 ambient = (slips & AmbientIaOnly) ? ia : ia * double(l.ka);
    if (slips & AmbientTimesOd) ambient *= od;
    dvec3 diffuse(0.0), specular(0.0);
    const double nl = glm::dot(n, lv);
    if (nl >= eps || (slips & DiffuseBehind)) {
        diffuse = il * od * double(l.kd) * nl;
        const dvec3 r = 2.0 * nl * n - lv;
        const double rv = (slips & BlinnPhong) ? glm::dot(n, normalised(lv + v)) : glm::dot(r, v);
        if ((rv >= eps || (slips & SpecularBehind)) && !(slips & NoSpecular)) {
            specular = il * double(l.ks) * std::pow(rv, double(l.n));
            if (slips & SpecularTimesOd) specular *= od;
        }
    }
    Row out(3);
    for (int k = 0; k < 3; ++k) {
        double value = (slips & TruncateTerms) ? std::trunc(ambient[k]) + std::trunc(diffuse[k]) +
                                                     std::trunc(specular[k])
                                               : ambient[k] + diffuse[k] + specular[k];
        if (!(slips & NoClamp)) value = std::min(value, 255.0);
        out[std::size_t(k)] = value;
    }
    return out;
}

}  // namespace

std::vector<Alternative> lightingMistakes(const Lighting& lighting,
                                          const std::vector<Sample>& samples) {
    const std::pair<unsigned, const char*> slips[] = {
        {NoFlip, "N not turned toward the viewer where V.N < 0"},
        {ViewReversed, "V = P' instead of -P' (or L = P' - Pl: the same colours)"},
        {DiffuseBehind, "diffuse and specular added where N.L < 0 (the light behind the surface)"},
        {SpecularBehind, "the specular term added where R.V < 0"},
        {NoClamp, "no clamp: channels above 255 kept"},
        {AmbientIaOnly, "the ambient term Ia instead of Ia ka"},
        {AmbientTimesOd, "the ambient term Ia ka Od instead of Ia ka"},
        {TruncateTerms, "each term truncated to a whole number before the sum"},
        {Epsilon, "V.N, N.L and R.V compared with 1e-3 instead of 0"},
        {SpecularTimesOd, "the highlight tinted by the object: Il Od ks (R.V)^n"},
        {BlinnPhong, "Blinn-Phong's (N.H)^n instead of (R.V)^n"},
        {NoSpecular, "the specular term left out"},
    };
    std::vector<Alternative> out;
    for (const auto& [slip, cause] : slips) {
        Alternative a{cause, {}};
        for (const Sample& s : samples) a.rows.push_back(phongWith(lighting, s, slip));
        out.push_back(std::move(a));
    }
    return out;
}

}  // namespace rasterlab::check
