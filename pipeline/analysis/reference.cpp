#include "reference.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "pipeline/core/parallel.h"

namespace rl {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

dvec3 toD(const vec3& v) {
    return dvec3(v);
}

// A triangle as the rays see it: vertex a and the edges to b and c, in view space.
struct RefTriangle {
    dvec3 a, e1, e2;
    std::uint32_t draw = 0, source = 0;
};

struct Node {
    dvec3 lo, hi;
    std::uint32_t first = 0;  // leaf: first triangle; inner: the left child (right = left + 1)
    std::uint32_t count = 0;  // triangles of a leaf; 0 for an inner node
};

struct Hit {
    double t = std::numeric_limits<double>::infinity();  // view z (the ray's direction has z = 1)
    double u = 0.0, v = 0.0;                             // barycentrics of b and c
    std::uint32_t triangle = ReferenceImage::kNoHit;
};

class Hierarchy {
public:
    explicit Hierarchy(std::vector<RefTriangle> triangles) : m_triangles(std::move(triangles)) {
        if (m_triangles.empty()) return;
        std::vector<std::uint32_t> order(m_triangles.size());
        for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
        m_nodes.reserve(2 * m_triangles.size() / kLeafSize + 2);
        m_nodes.emplace_back();
        build(0, order, 0, static_cast<std::uint32_t>(order.size()));
        std::vector<RefTriangle> sorted;
        sorted.reserve(order.size());
        for (std::uint32_t i : order) sorted.push_back(m_triangles[i]);
        m_triangles = std::move(sorted);
    }

    const RefTriangle& triangle(std::uint32_t i) const { return m_triangles[i]; }

    // The nearest hit with nearZ <= t, of the ray from the origin along dir.
    Hit cast(const dvec3& dir, double nearZ) const {
        Hit best;
        if (m_nodes.empty()) return best;
        const dvec3 inv(1.0 / dir.x, 1.0 / dir.y, 1.0 / dir.z);
        std::uint32_t stack[128];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& node = m_nodes[stack[--top]];
            if (!boxHit(node, inv, nearZ, best.t)) continue;
            if (node.count > 0) {
                for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
                    intersect(m_triangles[i], i, dir, nearZ, best);
                continue;
            }
            if (top + 2 > 128) continue;  // deeper than a balanced tree of 2^64 leaves
            stack[top++] = node.first + 1;
            stack[top++] = node.first;
        }
        return best;
    }

private:
    static constexpr std::uint32_t kLeafSize = 4;

    static void grow(dvec3& lo, dvec3& hi, const RefTriangle& t) {
        for (const dvec3& p : {t.a, t.a + t.e1, t.a + t.e2}) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    }

    void build(std::uint32_t index, std::vector<std::uint32_t>& order, std::uint32_t begin,
               std::uint32_t end) {
        dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
        dvec3 cLo = lo, cHi = hi;
        for (std::uint32_t i = begin; i < end; ++i) {
            const RefTriangle& t = m_triangles[order[i]];
            grow(lo, hi, t);
            const dvec3 c = t.a + (t.e1 + t.e2) / 3.0;
            cLo = glm::min(cLo, c);
            cHi = glm::max(cHi, c);
        }
        m_nodes[index].lo = lo;
        m_nodes[index].hi = hi;
        const dvec3 extent = cHi - cLo;
        if (end - begin <= kLeafSize || !(std::max({extent.x, extent.y, extent.z}) > 0.0)) {
            m_nodes[index].first = begin;
            m_nodes[index].count = end - begin;
            return;
        }
        const int axis =
            extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        const std::uint32_t middle = begin + (end - begin) / 2;
        const auto centroid = [&](std::uint32_t i) {
            const RefTriangle& t = m_triangles[i];
            return t.a[axis] + (t.e1[axis] + t.e2[axis]) / 3.0;
        };
        std::nth_element(
            order.begin() + begin, order.begin() + middle, order.begin() + end,
            [&](std::uint32_t x, std::uint32_t y) { return centroid(x) < centroid(y); });
        const auto left = static_cast<std::uint32_t>(m_nodes.size());
        m_nodes.emplace_back();
        m_nodes.emplace_back();
        m_nodes[index].first = left;
        m_nodes[index].count = 0;
        build(left, order, begin, middle);
        build(left + 1, order, middle, end);
    }

    static bool boxHit(const Node& node, const dvec3& inv, double nearZ, double farT) {
        double t0 = nearZ, t1 = farT;
        for (int axis = 0; axis < 3; ++axis) {
            double a = node.lo[axis] * inv[axis];
            double b = node.hi[axis] * inv[axis];
            if (std::isnan(a) || std::isnan(b))
                continue;  // 0 * inf: the ray lies in the slab's plane
            if (a > b) std::swap(a, b);
            t0 = std::max(t0, a);
            t1 = std::min(t1, b);
        }
        return t0 <= t1;
    }

    // Moller-Trumbore with the origin at the eye: P = a + u e1 + v e2 = t dir.
    static void intersect(const RefTriangle& tri, std::uint32_t index, const dvec3& dir,
                          double nearZ, Hit& best) {
        const dvec3 p = glm::cross(dir, tri.e2);
        const double det = glm::dot(tri.e1, p);
        if (det == 0.0 || !std::isfinite(det)) return;
        const double inv = 1.0 / det;
        const dvec3 s = -tri.a;
        const double u = glm::dot(s, p) * inv;
        if (!(u >= 0.0 && u <= 1.0)) return;
        const dvec3 q = glm::cross(s, tri.e1);
        const double v = glm::dot(dir, q) * inv;
        if (!(v >= 0.0 && u + v <= 1.0)) return;
        const double t = glm::dot(tri.e2, q) * inv;
        if (!(t >= nearZ && t < best.t)) return;
        best.t = t;
        best.u = u;
        best.v = v;
        best.triangle = index;
    }

    std::vector<RefTriangle> m_triangles;
    std::vector<Node> m_nodes;
};

Error unsupported(const Message& what) {
    return makeError(
        ErrorCode::Unsupported, {},
        "the exact reference handles course scenes (the course camera, view z as "
        "depth, the course's Phong lighting with the material's colour); %1"_msg(what));
}

}  // namespace

dvec3 referencePhong(const Scene& scene, const Draw& draw, const std::vector<ViewLight>& lights,
                     const dvec3& pView, const dvec3& nView) {
    const Material& m = draw.material;
    dvec3 colour = toD(scene.ambientIntensity) * double(m.ka) + toD(m.emission);
    const double nLength = glm::length(nView);
    if (!(nLength > 0.0)) return colour;
    const double vLength = glm::length(pView);
    const dvec3 v = vLength > 0.0 ? -pView / vLength : dvec3(0.0);
    dvec3 n = nView / nLength;
    if (scene.conventions.flipNormalsTowardViewer && glm::dot(v, n) < 0.0) n = -n;
    const std::size_t count = std::min(draw.lightCount, lights.size());
    for (std::size_t i = 0; i < count; ++i) {
        const ViewLight& light = lights[i];
        const dvec3 toLight =
            light.pView.w == 0.0 ? dvec3(light.pView) : dvec3(light.pView) - pView;
        const double lLength = glm::length(toLight);
        if (!(lLength > 0.0)) continue;
        const dvec3 l = toLight / lLength;
        const double nDotL = glm::dot(n, l);
        if (nDotL < 0.0) continue;
        double factor = 1.0;
        if (light.attenuated) {
            const double d = lLength;
            const dvec3 k = toD(light.attenuation);
            const double denominator = k.x + k.y * d + k.z * d * d;
            factor = denominator > 0.0 ? 1.0 / denominator : 0.0;
        }
        if (light.spot) {
            const double spotCos = -glm::dot(l, toD(light.spotDirection));
            factor *= spotCos < double(light.spotCosCutoff)
                          ? 0.0
                          : (light.spotExponent == 0.0f
                                 ? 1.0
                                 : std::pow(std::max(spotCos, 0.0), double(light.spotExponent)));
        }
        const dvec3 intensity = toD(light.intensity) * factor;
        colour += intensity * toD(m.od) * toD(m.kd) * nDotL;
        double highlight = 0.0;
        if (draw.specular == SpecularModel::BlinnPhong) {
            const dvec3 sum = l + v;
            const double length = glm::length(sum);
            highlight = length > 0.0 ? glm::dot(n, sum / length) : 0.0;
        } else {
            highlight = glm::dot(2.0 * nDotL * n - l, v);
        }
        if (highlight >= 0.0 && m.ks != 0.0f) {
            const double power = std::pow(highlight, double(m.shininess));
            if (std::isfinite(power)) colour += intensity * double(m.ks) * power;
        }
    }
    return colour;
}

namespace {

// Why the reference cannot render a scene, or nothing.
std::optional<Error> whyNotSupported(const Scene& scene) {
    if (!scene.camera) return unsupported("this scene has no course camera"_msg);
    if (scene.conventions.depth != DepthSource::ViewZ)
        return unsupported("this scene's depth is NDC z"_msg);
    for (const Draw& draw : scene.draws) {
        if (draw.clipFromView)
            return unsupported("%1 has its own projection matrix"_msg(draw.name));
        if (draw.lighting != LightingModel::CoursePhong)
            return unsupported("%1 is not lit by the course's Phong model"_msg(draw.name));
        if (draw.colour != ColourSource::Material)
            return unsupported("%1 takes its colour from its vertices or a texture"_msg(draw.name));
        if (draw.flatNormals) return unsupported("%1 is lit with flat normals"_msg(draw.name));
    }
    return std::nullopt;
}

dvec3 pointOf(const dvec4& p) {
    return p.w != 0.0 && p.w != 1.0 ? dvec3(p) / p.w : dvec3(p);
}

// The triangles in view space, draw by draw (firstOfDraw: the index of each draw's first).
std::vector<RefTriangle> viewTriangles(const Scene& scene, const ViewTransform& view,
                                       std::vector<std::uint32_t>& firstOfDraw) {
    std::vector<RefTriangle> triangles;
    for (std::size_t d = 0; d < scene.draws.size(); ++d) {
        firstOfDraw.push_back(static_cast<std::uint32_t>(triangles.size()));
        const Draw& draw = scene.draws[d];
        if (!draw.mesh) continue;
        const std::vector<dvec4>& p = view.pView[d];
        for (std::size_t t = 0; t < draw.mesh->triangles.size(); ++t) {
            const auto& tri = draw.mesh->triangles[t];
            const dvec3 a = pointOf(p[tri[0]]), b = pointOf(p[tri[1]]), c = pointOf(p[tri[2]]);
            if (!isFinite(a.x + a.y + a.z + b.x + b.y + b.z + c.x + c.y + c.z)) continue;
            triangles.push_back(
                {a, b - a, c - a, static_cast<std::uint32_t>(d), static_cast<std::uint32_t>(t)});
        }
    }
    return triangles;
}

// The colour of a point a ray hit, by its draw's shading model, in double.
class ReferenceShader {
public:
    ReferenceShader(const Scene& scene, const ViewTransform& view, const Normals& normals)
        : m_scene(scene), m_view(view), m_normals(normals) {}

    // Triangle tri hit at barycentrics (u, v) of its second and third vertices, at point.
    dvec3 shade(const RefTriangle& tri, double u, double v, const dvec3& point) const {
        const Draw& draw = m_scene.draws[tri.draw];
        const auto& corners = draw.mesh->triangles[tri.source];
        const double w = 1.0 - u - v;
        const auto& lights = m_view.lights;
        switch (draw.shading) {
            case ShadingModel::Flat:
            case ShadingModel::Painter: {
                const dvec3 centre = tri.a + (tri.e1 + tri.e2) / 3.0;
                const dvec3 n =
                    m_normals.skipped ? dvec3(0.0)
                                      : toD(m_normals.draws[tri.draw].triangle[tri.source]);
                return referencePhong(m_scene, draw, lights, centre, n);
            }
            case ShadingModel::Gouraud: {
                dvec3 c(0.0);
                const double weight[3] = {w, u, v};
                for (int k = 0; k < 3; ++k)
                    c += weight[k] * referencePhong(m_scene, draw, lights,
                                                    vertexPoint(tri.draw, corners[k]),
                                                    vertexNormal(tri.draw, corners[k]));
                return c;
            }
            case ShadingModel::Phong:
                break;
        }
        const dvec3 n = w * vertexNormal(tri.draw, corners[0]) +
                        u * vertexNormal(tri.draw, corners[1]) +
                        v * vertexNormal(tri.draw, corners[2]);
        return referencePhong(m_scene, draw, lights, point, n);
    }

private:
    dvec3 vertexNormal(std::uint32_t d, std::uint32_t v) const {
        return m_normals.skipped ? dvec3(0.0) : toD(m_normals.draws[d].vertex[v]);
    }
    dvec3 vertexPoint(std::uint32_t d, std::uint32_t v) const {
        return pointOf(m_view.pView[d][v]);
    }

    const Scene& m_scene;
    const ViewTransform& m_view;
    const Normals& m_normals;
};

// What the rays through one pixel's k x k samples found.
struct PixelRays {
    dvec3 colour = dvec3(0.0);  // the samples' mean, each clamped to [0, 1]
    double depth = 0.0;         // the mean view z of the samples that hit
    int hits = 0;
    std::uint32_t lastHit = ReferenceImage::kNoHit;  // the triangle the last hit met
};

PixelRays castPixel(const Scene& scene, const Hierarchy& hierarchy, const ReferenceShader& shader,
                    const std::vector<std::uint32_t>& firstOfDraw, int x, int y, int k,
                    double nearZ) {
    const CourseCamera& camera = *scene.camera;
    const double scale = scene.conventions.colourScale;
    const dvec3 background = dvec3(vec3(scene.conventions.background));
    PixelRays out;
    dvec3 sum(0.0);
    double depthSum = 0.0;
    for (int j = 0; j < k; ++j) {
        for (int i = 0; i < k; ++i) {
            // The sample's NDC, as projection maps NDC to pixels, inverted.
            const double sx = x + (i + 0.5) / k, sy = y + (j + 0.5) / k;
            const double ndcX = 2.0 * sx / scene.width - 1.0;
            const double ndcY = scene.conventions.ndcYUp ? 1.0 - 2.0 * sy / scene.height
                                                         : 2.0 * sy / scene.height - 1.0;
            const dvec3 dir(ndcX * camera.hx / camera.d, ndcY * camera.hy / camera.d, 1.0);
            const Hit hit = hierarchy.cast(dir, nearZ);
            if (hit.triangle == ReferenceImage::kNoHit) {
                sum += background;
                continue;
            }
            const RefTriangle& tri = hierarchy.triangle(hit.triangle);
            const dvec3 colour = shader.shade(tri, hit.u, hit.v, hit.t * dir);
            sum += glm::clamp(colour / scale, dvec3(0.0), dvec3(1.0));
            depthSum += hit.t;
            ++out.hits;
            out.lastHit = firstOfDraw[tri.draw] + tri.source;
        }
    }
    out.colour = sum / double(k * k);
    if (out.hits > 0) out.depth = depthSum / out.hits;
    return out;
}

}  // namespace

Result<ReferenceImage> renderReference(const Scene& scene, const ViewTransform& view,
                                       const Normals& normals, const ReferenceOptions& options) {
    if (const std::optional<Error> why = whyNotSupported(scene)) return *why;
    if (options.samplesPerAxis < 1 || options.samplesPerAxis > 16)
        return makeError(ErrorCode::Usage, {}, "samples per axis must be 1 to 16"_msg);

    ReferenceImage out;
    out.samplesPerAxis = options.samplesPerAxis;
    const auto started = Clock::now();
    std::vector<std::uint32_t> firstOfDraw;
    std::vector<RefTriangle> triangles = viewTriangles(scene, view, firstOfDraw);
    out.triangles = triangles.size();
    const Hierarchy hierarchy(std::move(triangles));
    out.buildMilliseconds = millisecondsSince(started);

    const ReferenceShader shader(scene, view, normals);
    const int k = options.samplesPerAxis;
    out.colour.reset(scene.width, scene.height, dvec3(0.0));
    out.hits.reset(scene.width, scene.height, 0);
    out.depth.reset(scene.width, scene.height, std::numeric_limits<double>::infinity());
    out.triangle.reset(scene.width, scene.height, ReferenceImage::kNoHit);
    const auto castStarted = Clock::now();
    const int parts = std::max(1, std::min(resolveThreads(options.threads), scene.height));
    runParts(parts, [&](int part) {
        for (int y = 0; y < scene.height; ++y) {
            if (!ownsRow(y, part, parts)) continue;
            for (int x = 0; x < scene.width; ++x) {
                const PixelRays rays =
                    castPixel(scene, hierarchy, shader, firstOfDraw, x, y, k, options.nearZ);
                out.colour.at(x, y) = rays.colour;
                out.hits.at(x, y) = static_cast<std::uint16_t>(rays.hits);
                if (rays.hits > 0) out.depth.at(x, y) = rays.depth;
                if (k == 1) out.triangle.at(x, y) = rays.lastHit;
            }
        }
    });
    out.rays = static_cast<std::size_t>(scene.width) * scene.height * k * k;
    out.castMilliseconds = millisecondsSince(castStarted);
    return out;
}

}  // namespace rl
