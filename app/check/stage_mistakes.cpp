#include "app/check/stage_mistakes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace rasterlab::check {

using rl::dvec3;

namespace {

dvec3 normalised(const dvec3& v) {
    const double length = glm::length(v);
    return length > 0.0 ? v / length : dvec3(0.0);
}

const StageMistake* find(const Mistakes& applied, int code) {
    for (const StageMistake& m : applied)
        if (m.code == code) return &m;
    return nullptr;
}

bool has(const Mistakes& applied, int code) {
    return find(applied, code) != nullptr;
}

StageMistake mistake(int code, const char* id, const char* cause, unsigned groups = 0,
                     std::vector<double> values = {}) {
    const double first = values.empty() ? 0.0 : values.front();
    return {code, id, cause, groups, std::move(values), first};
}

}  // namespace

// ---- basis -----------------------------------------------------------------------------

namespace {

enum BasisCode {
    UReversed = 1,
    NNever,
    NAfter,
    NRawInCross,
    NRawInDot,
    NRawInScale,
    NRawAnswered,
    VAtLength,
    NoGramSchmidt,
    InFloat,
};
constexpr unsigned kNForms = 1u;

// The basis in the precision T, with the mistakes' steps.
template <typename T>
std::vector<Row> basisIn(const dvec3& nGiven, const dvec3& vGiven, const Mistakes& a) {
    using V3 = glm::vec<3, T>;
    const auto unit = [](const V3& x) {
        const T length = glm::length(x);
        return length > T(0) ? x / length : V3(T(0));
    };
    const V3 nRaw(nGiven), vRaw(vGiven);
    const V3 nUnit = unit(nRaw);
    const bool rawForV = has(a, NNever) || has(a, NAfter);
    const V3 nInDot = rawForV || has(a, NRawInDot) ? nRaw : nUnit;
    const V3 nInScale = rawForV || has(a, NRawInScale) ? nRaw : nUnit;
    V3 v = has(a, NoGramSchmidt) ? vRaw : vRaw - glm::dot(vRaw, nInDot) * nInScale;
    if (!has(a, VAtLength)) v = unit(v);
    const V3 nAnswer = has(a, NNever) || has(a, NRawAnswered) ? nRaw : nUnit;
    const V3 nForU = has(a, NNever) || has(a, NRawInCross) ? nRaw : nUnit;
    const V3 u = has(a, UReversed) ? glm::cross(v, nForU) : glm::cross(nForU, v);
    return {rowOf(dvec3(u)), rowOf(dvec3(v)), rowOf(dvec3(nAnswer))};
}

}  // namespace

Mistakes basisCatalogue() {
    return {
        mistake(UReversed, "basis-u-reversed", "U = V x N: the cross product in the other order"),
        mistake(NNever, "basis-n-not-normalised", "N not normalised before V - (V.N)N, nor after",
                kNForms),
        mistake(NAfter, "basis-n-normalised-after", "N normalised only after V - (V.N)N", kNForms),
        mistake(NRawInCross, "basis-n-not-normalised-in-u",
                "U = N x V with N not normalised (N normalised for V - (V.N)N only)", kNForms),
        mistake(NRawInDot, "basis-n-not-normalised-in-dot",
                "V - (V.N) N with the file's N in V.N and the unit N after it", kNForms),
        mistake(NRawInScale, "basis-n-not-normalised-in-scale",
                "V - (V.N) N with the unit N in V.N and the file's N after it", kNForms),
        mistake(NRawAnswered, "basis-n-answered-raw",
                "N answered as the file gives it, not normalised (the rest right)", kNForms),
        mistake(VAtLength, "basis-v-not-normalised", "V not normalised after V - (V.N)N"),
        mistake(NoGramSchmidt, "basis-no-gram-schmidt",
                "V not made orthogonal to N (Gram-Schmidt left out)"),
        mistake(InFloat, "basis-in-float", "the basis computed in float (single precision)"),
    };
}

std::vector<Row> basisAnswer(const dvec3& n, const dvec3& v, const Mistakes& applied) {
    return has(applied, InFloat) ? basisIn<float>(n, v, applied) : basisIn<double>(n, v, applied);
}

// ---- view ------------------------------------------------------------------------------

namespace {

enum ViewCode {
    LightInWorld = 1,
    LightWithoutC,
    LightColumns,
    LightInPlace,
    LightInPlaceOnP,
    VerticesWithoutC,
    VerticesColumns,
    VerticesInPlace,
    VerticesInPlaceOnP,
};
constexpr unsigned kLightGroup = 1u, kVertexGroup = 2u;

// A point in view coordinates, its way: 0 the lecture's, or one of the codes' mistakes.
dvec3 toView(const dvec3& p, const dvec3& c, const std::array<dvec3, 3>& uvn, int way) {
    const auto& [u, v, n] = uvn;
    switch (way) {
        case LightInWorld:
            return p;
        case LightWithoutC:
        case VerticesWithoutC:
            return {glm::dot(u, p), glm::dot(v, p), glm::dot(n, p)};
        case LightColumns:
        case VerticesColumns: {
            const dvec3 q = p - c;
            return u * q.x + v * q.y + n * q.z;
        }
        case LightInPlace:
        case VerticesInPlace: {
            // q = P - C, then q.x = U.q, q.y = V.q, q.z = N.q, each reading q as it now is.
            dvec3 q = p - c;
            q.x = glm::dot(u, q);
            q.y = glm::dot(v, q);
            q.z = glm::dot(n, q);
            return q;
        }
        case LightInPlaceOnP:
        case VerticesInPlaceOnP: {
            // P.x = U.(P - C), then P.y = V.(P - C) and P.z = N.(P - C) with the new P.
            dvec3 q = p;
            q.x = glm::dot(u, q - c);
            q.y = glm::dot(v, q - c);
            q.z = glm::dot(n, q - c);
            return q;
        }
        default: {
            const dvec3 q = p - c;
            return {glm::dot(u, q), glm::dot(v, q), glm::dot(n, q)};
        }
    }
}

int wayOf(const Mistakes& applied, unsigned group) {
    for (const StageMistake& m : applied)
        if (m.groups & group) return m.code;
    return 0;
}

}  // namespace

Mistakes viewCatalogue() {
    return {
        mistake(LightInWorld, "light-in-world", "the light left in world coordinates", kLightGroup),
        mistake(LightWithoutC, "light-without-c",
                "the light taken to view coordinates without subtracting C: [U; V; N] Pl",
                kLightGroup),
        mistake(LightColumns, "light-basis-as-columns",
                "the light taken with the basis as columns: U x + V y + N z of Pl - C",
                kLightGroup),
        mistake(LightInPlace, "light-in-place",
                "the light moved in place: q = Pl - C, then q.x = U.q overwritten before V.q and "
                "N.q read it",
                kLightGroup),
        mistake(LightInPlaceOnP, "light-in-place-on-p",
                "the light moved in place: Pl.x = U.(Pl - C) overwritten before V.(Pl - C) and "
                "N.(Pl - C) read it",
                kLightGroup),
        mistake(VerticesWithoutC, "vertices-without-c",
                "the vertices taken to view coordinates without subtracting C: [U; V; N] P",
                kVertexGroup),
        mistake(VerticesColumns, "vertices-basis-as-columns",
                "the vertices taken with the basis as columns: U x + V y + N z of P - C",
                kVertexGroup),
        mistake(VerticesInPlace, "vertices-in-place",
                "each vertex moved in place: q = P - C, then q.x = U.q overwritten before V.q and "
                "N.q read it",
                kVertexGroup),
        mistake(VerticesInPlaceOnP, "vertices-in-place-on-p",
                "each vertex moved in place: P.x = U.(P - C) overwritten before V.(P - C) and "
                "N.(P - C) read it",
                kVertexGroup),
    };
}

std::vector<Row> viewAnswer(const dvec3& c, const std::array<dvec3, 3>& uvn, const dvec3& light,
                            const std::vector<Row>& vertices, const Mistakes& applied) {
    std::vector<Row> rows{rowOf(toView(light, c, uvn, wayOf(applied, kLightGroup)))};
    const int way = wayOf(applied, kVertexGroup);
    for (const Row& r : vertices) rows.push_back(rowOf(toView(vecOf(r), c, uvn, way)));
    return rows;
}

// ---- normals ---------------------------------------------------------------------------

namespace {

enum NormalsCode {
    Crossed = 1,
    TrianglesRaw,
    SumRaw,
    VertexAtLength,
    VertexAveraged,
    SkipSmallArea,
    FrontFacingOnly,
    FrontFacingByZ,
};
constexpr unsigned kFinish = 1u, kFilter = 2u;
constexpr std::size_t kMostAreas = 32;

double screenArea(const std::vector<Row>& screen, const std::array<std::uint32_t, 3>& t) {
    const Row &a = screen[t[0]], &b = screen[t[1]], &c = screen[t[2]];
    return 0.5 * std::abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

// Whether a triangle's normal goes into its vertices' sums.
bool summed(const Mistakes& applied, const std::vector<Row>& screen,
            const std::array<std::uint32_t, 3>& t, const dvec3& a, const dvec3& cross) {
    if (const StageMistake* m = find(applied, SkipSmallArea))
        return screen.empty() || screenArea(screen, t) >= m->value;
    if (has(applied, FrontFacingOnly)) return glm::dot(cross, -a) > 0.0;
    if (has(applied, FrontFacingByZ)) return cross.z < 0.0;
    return true;
}

}  // namespace

Mistakes normalsCatalogue(const std::vector<Row>& screen,
                          const std::vector<std::array<std::uint32_t, 3>>& triangles) {
    Mistakes out = {
        mistake(Crossed, "normals-crossed",
                "the cross product in the other order: (Pc - Pa) x (Pb - Pa)"),
        mistake(TrianglesRaw, "triangle-normals-not-normalised",
                "the triangle normals not normalised"),
        mistake(SumRaw, "area-weighted-normals",
                "the vertex normals summed from triangle normals not normalised (weighted by "
                "area)"),
        mistake(VertexAtLength, "vertex-normals-not-normalised",
                "the vertex normals not normalised: the sum left at its length", kFinish),
        mistake(VertexAveraged, "vertex-normals-averaged",
                "the vertex normals averaged (divided by their count), not normalised", kFinish),
        mistake(FrontFacingOnly, "vertex-normals-front-faces",
                "the vertex normals sum only the triangles facing the camera (N.(-Pa) > 0)",
                kFilter),
        mistake(FrontFacingByZ, "vertex-normals-front-faces-by-z",
                "the vertex normals sum only the triangles whose normal has z < 0", kFilter),
    };
    if (!screen.empty()) {
        std::set<double> areas;
        for (const auto& t : triangles) areas.insert(screenArea(screen, t));
        std::vector<double> values;
        for (double a : areas) {
            if (a == *areas.begin()) continue;  // leaves nothing out
            if (values.size() == kMostAreas) break;
            values.push_back(a);
        }
        if (!values.empty())
            out.push_back(mistake(SkipSmallArea, "vertex-normals-skip-small-triangles",
                                  "the vertex normals leave out triangles of screen area below "
                                  "%v square pixels",
                                  kFilter, values));
    }
    return out;
}

std::vector<Row> normalsAnswer(const std::vector<Row>& vertices,
                               const std::vector<std::array<std::uint32_t, 3>>& triangles,
                               const std::vector<Row>& screen, const Mistakes& applied) {
    const std::size_t n = vertices.size();
    std::vector<dvec3> sum(n, dvec3(0.0));
    std::vector<int> count(n, 0);
    std::vector<Row> rows;
    for (const auto& t : triangles) {
        const dvec3 a = vecOf(vertices[t[0]]), b = vecOf(vertices[t[1]]), c = vecOf(vertices[t[2]]);
        dvec3 cross = glm::cross(b - a, c - a);
        if (has(applied, Crossed)) cross = -cross;
        const dvec3 unit = normalised(cross);
        rows.push_back(rowOf(has(applied, TrianglesRaw) ? cross : unit));
        if (!summed(applied, screen, t, a, cross)) continue;  // facing by their own normal
        for (std::uint32_t i : t) {
            sum[i] += has(applied, SumRaw) ? cross : unit;
            ++count[i];
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (has(applied, VertexAtLength))
            rows.push_back(rowOf(sum[i]));
        else if (has(applied, VertexAveraged))
            rows.push_back(rowOf(count[i] ? sum[i] / double(count[i]) : dvec3(0.0)));
        else
            rows.push_back(rowOf(normalised(sum[i])));
    }
    return rows;
}

// ---- projection ------------------------------------------------------------------------

namespace {

enum ProjectionCode { Round = 1, Floor, Ceil, Fractional, YUp, HxHySwapped, NoPlusOne };
constexpr unsigned kWhole = 1u;

}  // namespace

std::array<double, 2> projectionExact(double d, double hx, double hy, int width, int height,
                                      const Row& p) {
    return {(d / hx * (p[0] / p[2]) + 1.0) * width / 2.0,
            (1.0 - d / hy * (p[1] / p[2])) * height / 2.0};
}

Mistakes projectionCatalogue() {
    return {
        mistake(Round, "vertex-snap", "rounded to the nearest pixel instead of truncated by (int)",
                kWhole),
        mistake(Floor, "screen-floor",
                "floor instead of (int): pixels left of or above the screen one lower", kWhole),
        mistake(Ceil, "screen-ceil", "made whole by ceil instead of (int)", kWhole),
        mistake(Fractional, "screen-fractional",
                "left fractional: the coordinates never made whole (the (int) cast missing)",
                kWhole),
        mistake(YUp, "upside-down", "y not flipped: (int)((d/hy * y/z + 1) * height/2), y growing "
                                    "upward"),
        mistake(HxHySwapped, "hx-hy-swapped", "hx and hy swapped"),
        mistake(NoPlusOne, "screen-without-plus-one",
                "without the + 1: (int)(d/hx * x/z * width/2), the screen's centre at its corner"),
    };
}

std::vector<Row> projectionAnswer(double d, double hx, double hy, int width, int height,
                                  const std::vector<Row>& vertices, const Mistakes& applied) {
    if (has(applied, HxHySwapped)) std::swap(hx, hy);
    const auto whole = [&](double v) {
        if (has(applied, Round)) return std::floor(v + 0.5);
        if (has(applied, Floor)) return std::floor(v);
        if (has(applied, Ceil)) return std::ceil(v);
        if (has(applied, Fractional)) return v;
        return std::trunc(v);
    };
    std::vector<Row> rows;
    for (const Row& p : vertices) {
        const double sx = d / hx * (p[0] / p[2]), sy = d / hy * (p[1] / p[2]);
        const double one = has(applied, NoPlusOne) ? 0.0 : 1.0;
        const double x = (sx + one) * width / 2.0;
        const double y = has(applied, YUp) ? (sy + one) * height / 2.0
                                           : (one - sy) * height / 2.0;
        rows.push_back({whole(x), whole(y)});
    }
    return rows;
}

// ---- scan ------------------------------------------------------------------------------

namespace {

enum ScanCode {
    YaxbInOrder = 1,
    YaxbFromTop,
    StartFloor,
    StartRound,
    StartTrunc,
    StartOpen,
    StartDropped,
    EndOpen,
    EndDropped,
    EndCeil,
    EndRound,
    UnitSteps,
    StrictEdges,
    LastRowOut,
    FirstRowOut,
};
constexpr unsigned kCrossing = 1u, kStart = 2u, kEnd = 4u, kRows = 8u;

struct Point2 {
    double x, y;
};

// Where row y crosses the triangle's edges, as the lecture's exact arithmetic or a student's
// y = a x + b finds it: the least and the greatest x, or none.
std::optional<std::pair<double, double>> crossings(const std::array<Point2, 3>& v, double y,
                                                   int method) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    const auto take = [&](double x) {
        lo = std::min(lo, x);
        hi = std::max(hi, x);
    };
    std::array<std::pair<Point2, Point2>, 3> edges = {
        {{v[0], v[1]}, {v[1], v[2]}, {v[2], v[0]}}};
    if (method == YaxbFromTop) {
        std::array<Point2, 3> s = v;
        std::sort(s.begin(), s.end(), [](auto& a, auto& b) { return a.y < b.y; });
        edges = {{{s[0], s[1]}, {s[1], s[2]}, {s[0], s[2]}}};
    }
    for (const auto& [p, q] : edges) {
        if (y < std::min(p.y, q.y) || y > std::max(p.y, q.y)) continue;
        if (method == 0) {
            if (p.y == q.y) {
                take(p.x);
                take(q.x);
            } else {
                take(p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y));
            }
            continue;
        }
        if (p.x == q.x) {
            take(p.x);
            continue;
        }
        const double a = (q.y - p.y) / (q.x - p.x);
        if (a == 0.0) continue;
        const double b = p.y - a * p.x;
        take((y - b) / a);
    }
    if (lo > hi) return std::nullopt;
    return std::pair(lo, hi);
}

// The first and last pixel of a row whose edges cross at xl and xr.
std::pair<double, double> spanEnds(double xl, double xr, const Mistakes& a) {
    if (has(a, UnitSteps)) return {std::floor(xl), std::floor(xl) + std::floor(xr - xl)};
    double first = std::ceil(xl), last = std::floor(xr);
    if (has(a, StartFloor)) first = std::floor(xl);
    if (has(a, StartRound)) first = std::floor(xl + 0.5);
    if (has(a, StartTrunc)) first = std::trunc(xl);
    if (has(a, StartOpen)) first = std::floor(xl) + 1.0;
    if (has(a, StartDropped)) first = std::ceil(xl) + 1.0;
    if (has(a, EndOpen)) last = std::ceil(xr) - 1.0;
    if (has(a, EndDropped)) last = std::floor(xr) - 1.0;
    if (has(a, EndCeil)) last = std::ceil(xr);
    if (has(a, EndRound)) last = std::floor(xr + 0.5);
    return {first, last};
}

// Inside by the edge functions, > 0 on every edge (a sample on an edge left out).
bool strictlyInside(const std::array<Point2, 3>& v, double area, double x, double y) {
    for (int k = 0; k < 3; ++k) {
        const Point2 &p = v[std::size_t(k)], &q = v[std::size_t((k + 1) % 3)];
        const double e = (q.x - p.x) * (y - p.y) - (q.y - p.y) * (x - p.x);
        if ((area > 0 ? e : -e) <= 0.0) return false;
    }
    return true;
}

void addSpan(std::vector<Row>& spans, double t, double y, double first, double last, int width) {
    first = std::max(first, 0.0);
    last = std::min(last, double(width - 1));
    if (first <= last) spans.push_back({t, y, first, last});
}

}  // namespace

Mistakes scanCatalogue() {
    return {
        mistake(StartOpen, "span-start-open",
                "each span's first pixel left out where the edge passes through it (x > x_left "
                "instead of x >= x_left)",
                kStart),
        mistake(EndOpen, "span-end-open",
                "each span's last pixel left out where the edge passes through it (x < x_right "
                "instead of x <= x_right)",
                kEnd),
        mistake(EndDropped, "span-end-dropped",
                "each span's last pixel left out (x < last instead of x <= last)", kEnd),
        mistake(StartDropped, "span-start-dropped", "each span's first pixel left out", kStart),
        mistake(StrictEdges, "edges-strict",
                "a sample on an edge left out (edge functions > 0 instead of >= 0)",
                kStart | kEnd | kCrossing),
        mistake(UnitSteps, "span-unit-steps-from-left-x",
                "each span walked from the left edge's x in unit steps, each pixel floor(x): "
                "from floor(x_left) while x <= x_right",
                kStart | kEnd),
        mistake(StartRound, "span-start-rounded",
                "each span started at the rounded left x instead of ceil(x_left)", kStart),
        mistake(StartTrunc, "span-start-truncated",
                "each span started at the truncated left x, (int) x_left, instead of ceil(x_left)",
                kStart),
        mistake(StartFloor, "span-start-floor",
                "each span started at floor(x_left) instead of ceil(x_left)", kStart),
        mistake(EndCeil, "span-end-ceil", "each span ended at ceil(x_right) instead of floor",
                kEnd),
        mistake(EndRound, "span-end-rounded",
                "each span ended at the rounded right x instead of floor(x_right)", kEnd),
        mistake(YaxbInOrder, "edges-y-ax-b",
                "edges found as y = a x + b, each row's x as (y - b) / a in floating point (a = "
                "dy/dx from each edge's first vertex): x a hair off a whole pixel",
                kCrossing),
        mistake(YaxbFromTop, "edges-y-ax-b-from-top",
                "edges found as y = a x + b from the top vertex, each row's x as (y - b) / a in "
                "floating point: x a hair off a whole pixel",
                kCrossing),
        mistake(LastRowOut, "last-row-out",
                "each triangle's last row left out (y < y_max instead of y <= y_max)", kRows),
        mistake(FirstRowOut, "first-row-out",
                "each triangle's first row left out (y > y_min instead of y >= y_min)", kRows),
    };
}

std::vector<Row> scanAnswer(const std::vector<Row>& triangles, int width, int height,
                            const Mistakes& applied) {
    const int method = has(applied, YaxbInOrder) ? YaxbInOrder
                       : has(applied, YaxbFromTop) ? YaxbFromTop
                                                   : 0;
    std::vector<Row> spans;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const Row& r = triangles[t];
        const std::array<Point2, 3> v = {{{r[0], r[1]}, {r[2], r[3]}, {r[4], r[5]}}};
        const double area = (v[1].x - v[0].x) * (v[2].y - v[0].y) -
                            (v[1].y - v[0].y) * (v[2].x - v[0].x);
        if (area == 0.0 || !std::isfinite(area)) continue;
        const double yMin = std::min({v[0].y, v[1].y, v[2].y});
        const double yMax = std::max({v[0].y, v[1].y, v[2].y});
        double first = std::max(0.0, has(applied, FirstRowOut) ? std::floor(yMin) + 1.0
                                                                : std::ceil(yMin));
        double last = std::min(double(height - 1), has(applied, LastRowOut)
                                                       ? std::ceil(yMax) - 1.0
                                                       : std::floor(yMax));
        for (double y = first; y <= last; ++y) {
            const auto x = crossings(v, y, method);
            if (!x) continue;
            if (has(applied, StrictEdges)) {
                // Within the screen's columns: the crossings of a student's own vertices (a
                // chained run) may lie anywhere.
                double a = std::max(0.0, std::ceil(x->first));
                double b = std::min(double(width - 1), std::floor(x->second));
                while (a <= b && !strictlyInside(v, area, a, y)) ++a;
                while (b >= a && !strictlyInside(v, area, b, y)) --b;
                addSpan(spans, double(t), y, a, b, width);
                continue;
            }
            const auto [a, b] = spanEnds(x->first, x->second, applied);
            addSpan(spans, double(t), y, a, b, width);
        }
    }
    return spans;
}

// ---- zbuffer ---------------------------------------------------------------------------

namespace {

enum ZBufferCode { Farther = 1, TiesLater, NoTest, StartsAtZero };

}  // namespace

Mistakes zbufferCatalogue() {
    return {
        mistake(Farther, "depth-reversed",
                "the farther fragment wins (z > stored, the buffer starting at -infinity)", 1u),
        mistake(TiesLater, "depth-ties-later",
                "on a tie the later fragment wins (z <= stored instead of z < stored)", 1u),
        mistake(NoTest, "no-depth-test", "no depth test: the last fragment drawn wins", 1u),
        mistake(StartsAtZero, "depth-starts-at-zero",
                "the buffer starts at 0 instead of +infinity: no fragment in front of the camera "
                "passes",
                1u),
    };
}

std::vector<Row> zbufferAnswer(const std::vector<Fragment>& fragments, const Mistakes& applied) {
    struct Kept {
        std::uint32_t t;
        float z;
    };
    std::vector<Row> rows;
    if (has(applied, StartsAtZero)) return rows;
    std::map<std::pair<std::int32_t, std::int32_t>, Kept> buffer;
    for (const Fragment& f : fragments) {
        const auto key = std::make_pair(f.y, f.x);
        const auto it = buffer.find(key);
        bool keep = it == buffer.end();
        if (!keep) {
            const float stored = it->second.z;
            keep = has(applied, Farther)     ? f.z > stored
                   : has(applied, TiesLater) ? f.z <= stored
                   : has(applied, NoTest)    ? true
                                             : f.z < stored;
        }
        if (keep) buffer[key] = {f.t, f.z};
    }
    for (const auto& [key, k] : buffer)
        rows.push_back({double(key.second), double(key.first), double(k.t), double(k.z)});
    return rows;
}

// ---- lighting --------------------------------------------------------------------------

namespace {

enum LightingCode {
    NoFlip = 1,
    ViewReversed,
    DiffuseBehind,
    SpecularWithoutNl,
    SpecularBehind,
    NoClamp,
    AmbientIaOnly,
    AmbientTimesOd,
    TruncateTerms,
    Epsilon,
    SpecularTimesOd,
    BlinnPhong,
    NoSpecular,
};
constexpr unsigned kBehind = 1u, kAmbient = 2u, kHighlight = 4u;

Row phongWith(const Lighting& l, const dvec3& p, const dvec3& normal, const Mistakes& a) {
    const StageMistake* epsilon = find(a, Epsilon);
    const double eps = epsilon ? epsilon->value : 0.0;
    dvec3 n = normalised(normal);
    const dvec3 v = normalised(has(a, ViewReversed) ? p : -p);
    const dvec3 lv = normalised(l.light - p);
    if (!has(a, NoFlip) && glm::dot(v, n) < eps) n = -n;
    const dvec3 ia(l.ia), il(l.il), od(l.od);
    dvec3 ambient = has(a, AmbientIaOnly) ? ia : ia * double(l.ka);
    if (has(a, AmbientTimesOd)) ambient *= od;
    dvec3 diffuse(0.0), specular(0.0);
    const double nl = glm::dot(n, lv);
    const bool lit = nl >= eps;
    if (lit || has(a, DiffuseBehind)) diffuse = il * od * double(l.kd) * nl;
    if (lit || has(a, DiffuseBehind) || has(a, SpecularWithoutNl)) {
        const dvec3 r = 2.0 * nl * n - lv;
        const double rv = has(a, BlinnPhong) ? glm::dot(n, normalised(lv + v)) : glm::dot(r, v);
        if ((rv >= eps || has(a, SpecularBehind)) && !has(a, NoSpecular)) {
            specular = il * double(l.ks) * std::pow(rv, double(l.n));
            if (has(a, SpecularTimesOd)) specular *= od;
        }
    }
    Row out(3);
    for (int k = 0; k < 3; ++k) {
        double value = has(a, TruncateTerms) ? std::trunc(ambient[k]) + std::trunc(diffuse[k]) +
                                                   std::trunc(specular[k])
                                             : ambient[k] + diffuse[k] + specular[k];
        if (!has(a, NoClamp)) value = std::min(value, 255.0);
        out[std::size_t(k)] = value;
    }
    return out;
}

}  // namespace

Mistakes lightingCatalogue(const std::vector<double>& epsilons) {
    Mistakes out = {
        mistake(NoFlip, "normal-not-flipped", "N not turned toward the viewer where V.N < 0"),
        mistake(ViewReversed, "view-vector-reversed",
                "V = P' instead of -P' (or L = P' - Pl: the same colours)"),
        mistake(DiffuseBehind, "light-behind-not-skipped",
                "diffuse and specular added where N.L < 0 (the light behind the surface)",
                kBehind),
        mistake(SpecularWithoutNl, "specular-without-nl-test",
                "the specular term added where N.L < 0 (only the diffuse term left out there)",
                kBehind),
        mistake(SpecularBehind, "specular-where-rv-negative",
                "the specular term added where R.V < 0"),
        mistake(NoClamp, "no-clamp", "no clamp: channels above 255 kept"),
        mistake(AmbientIaOnly, "ambient-ia-only", "the ambient term Ia instead of Ia ka", kAmbient),
        mistake(AmbientTimesOd, "ambient-times-od", "the ambient term Ia ka Od instead of Ia ka",
                kAmbient),
        mistake(TruncateTerms, "terms-truncated",
                "each term truncated to a whole number before the sum"),
        mistake(SpecularTimesOd, "specular-times-od",
                "the highlight tinted by the object: Il Od ks (R.V)^n"),
        mistake(BlinnPhong, "blinn-phong", "Blinn-Phong's (N.H)^n instead of (R.V)^n", kHighlight),
        mistake(NoSpecular, "no-specular", "the specular term left out", kHighlight),
    };
    if (!epsilons.empty())
        out.push_back(mistake(Epsilon, "epsilon-special-cases",
                              "V.N, N.L and R.V compared with %v instead of 0 (the special "
                              "cases at a small epsilon)",
                              0u, epsilons));
    return out;
}

std::vector<Row> lightingAnswer(const Lighting& lighting, const std::vector<Sample>& samples,
                                const Mistakes& applied) {
    std::vector<Row> rows;
    rows.reserve(samples.size());
    for (const Sample& s : samples)
        rows.push_back(phongWith(lighting, dvec3(s.p), dvec3(s.n), applied));
    return rows;
}

Row lightingAt(const Lighting& lighting, const dvec3& p, const dvec3& n, const Mistakes& applied) {
    return phongWith(lighting, p, n, applied);
}

PhongTerms phongTerms(const Lighting& l, const Sample& s) {
    PhongTerms t;
    const dvec3 p(s.p);
    dvec3 n = normalised(dvec3(s.n));
    const dvec3 v = normalised(-p);
    const dvec3 lv = normalised(l.light - p);
    if (glm::dot(v, n) < 0.0) n = -n;
    t.vDotN = glm::dot(v, n);
    t.nDotL = glm::dot(n, lv);
    t.rDotV = glm::dot(2.0 * t.nDotL * n - lv, v);
    t.ambient = dvec3(l.ia) * double(l.ka);
    if (t.nDotL >= 0.0) {
        t.diffuse = dvec3(l.il) * dvec3(l.od) * double(l.kd) * t.nDotL;
        if (t.rDotV >= 0.0) t.specular = dvec3(l.il) * double(l.ks) * std::pow(t.rDotV, double(l.n));
    }
    return t;
}

}  // namespace rasterlab::check
