// rasterizer.cpp - a student's software rasterizer for seed 000 (UFPE course project).
//
// Written from the seed's text, the course's file formats and RasterLab's stage
// protocol (docs/stage-protocol.md), in C++17 with the standard library only.
//
//   rasterizer --camera F --lighting F --object F --size WxH --output out.png|out.ppm
//   rasterizer --stages        (stage protocol, version 1, on stdin/stdout)
//
// Readings of the seed where its text leaves a choice:
//   * screen vertices are truncated with a C cast (toward zero);
//   * pixel (x, y) is sampled at the point (x, y); a sample on an edge is inside;
//   * the z-buffer starts at +inf and keeps a fragment when z < stored z, so on a
//     tie the earlier triangle stays;
//   * a colour channel is clamped to 0..255, then truncated to a byte;
//   * a triangle with a vertex at view z == 0 is skipped (the seed divides by z);
//     vertices behind the camera are divided by their negative z, as written.

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

// ---------------------------------------------------------------------------
// Vectors

struct Vec3 {
    double x = 0, y = 0, z = 0;
};

Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
Vec3 operator*(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }

double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

Vec3 cross(Vec3 a, Vec3 b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// a / |a|; the zero vector has no direction and stays zero.
Vec3 normalize(Vec3 a)
{
    double length = std::sqrt(dot(a, a));
    if (length == 0)
        return {0, 0, 0};
    return {a.x / length, a.y / length, a.z / length};
}

// ---------------------------------------------------------------------------
// The scene

using Triangle = std::array<int, 3>;  // vertex indices, from 0

struct Camera {
    Vec3 C, N, V;
    double d = 1, hx = 1, hy = 1;
};

struct Lighting {
    Vec3 Pl;           // light position (world in the files, view inside phong)
    Vec3 Ia, Il;       // ambient and light colours, 0..255
    double ka = 0;
    Vec3 kd, Od;       // kd is one number in the UFPE file, r g b in the protocol
    double ks = 0, n = 1;
};

struct Mesh {
    std::vector<Vec3> points;
    std::vector<Triangle> triangles;
};

// ---------------------------------------------------------------------------
// Stage 1: the camera's basis {U, V, N} (Gram-Schmidt)

struct Basis {
    Vec3 U, V, N;
};

Basis basis(Vec3 N, Vec3 V)
{
    Basis b;
    b.N = normalize(N);
    b.V = normalize(V - b.N * dot(V, b.N));
    b.U = cross(b.N, b.V);
    return b;
}

// Stage 2: world to view coordinates, [U; V; N] (P - C)
Vec3 toView(const Basis& b, Vec3 C, Vec3 P)
{
    Vec3 D = P - C;
    return {dot(b.U, D), dot(b.V, D), dot(b.N, D)};
}

// Stage 3: triangle normals and vertex normals (both unit, or 0 0 0)
struct Normals {
    std::vector<Vec3> triangle, vertex;
};

Normals normals(const std::vector<Vec3>& view, const std::vector<Triangle>& triangles)
{
    Normals result;
    result.vertex.assign(view.size(), Vec3{});
    for (const Triangle& t : triangles) {
        Vec3 a = view[t[0]], b = view[t[1]], c = view[t[2]];
        Vec3 n = normalize(cross(b - a, c - a));
        result.triangle.push_back(n);
        for (int i : t)
            result.vertex[i] = result.vertex[i] + n;
    }
    for (Vec3& n : result.vertex)
        n = normalize(n);
    return result;
}

// Stage 4: view to screen. The (int) casts are done here with trunc, so the
// values are whole numbers kept in doubles (they may be far off the screen).
struct ScreenPoint {
    double x, y;
};

ScreenPoint project(Vec3 P, double d, double hx, double hy, int width, int height)
{
    double sx = (d / hx) * (P.x / P.z);
    double sy = (d / hy) * (P.y / P.z);
    // + 0.0 turns a -0 from trunc into 0
    return {std::trunc((sx + 1) * width / 2) + 0.0, std::trunc((1 - sy) * height / 2) + 0.0};
}

// ---------------------------------------------------------------------------
// Stage 5: scan conversion with exact integer edge functions
//
// For the triangle (p0, p1, p2), E_i(x, y) is twice the signed area of the
// triangle the sample makes with the edge opposite p_i; E_0 + E_1 + E_2 = den and
// the barycentrics are E_i / den. E_i(x, y) = A_i x + B_i + C_i y.

struct Pixel {
    long long x, y;
};
using ScreenTriangle = std::array<Pixel, 3>;

// Vertices farther than this from the origin would overflow 64-bit edge functions.
const long long kMaxCoordinate = 1LL << 30;

struct EdgeFunctions {
    long long den = 0;  // twice the signed area; 0 for a line or a point
    long long A[3], B[3], C[3];

    long long at(int i, long long x, long long y) const { return A[i] * x + B[i] + C[i] * y; }
};

EdgeFunctions edgeFunctions(const ScreenTriangle& p)
{
    EdgeFunctions e;
    for (int i = 0; i < 3; ++i) {
        const Pixel& a = p[(i + 1) % 3];
        const Pixel& b = p[(i + 2) % 3];
        // (a - s) x (b - s) for the sample s = (x, y)
        e.A[i] = a.y - b.y;
        e.B[i] = a.x * b.y - b.x * a.y;
        e.C[i] = b.x - a.x;
    }
    e.den = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
    return e;
}

bool fitsScan(const ScreenTriangle& p)
{
    for (const Pixel& v : p)
        if (std::llabs(v.x) >= kMaxCoordinate || std::llabs(v.y) >= kMaxCoordinate)
            return false;
    return true;
}

// floor(p / q) for q > 0
long long floorDiv(long long p, long long q)
{
    long long r = p / q;
    return (p % q != 0 && p < 0) ? r - 1 : r;
}

struct Span {
    int t;
    long long y, first, last;
};

// The spans of every triangle, clipped to the screen. Edges are inclusive.
std::vector<Span> scan(int width, int height, const std::vector<ScreenTriangle>& triangles)
{
    std::vector<Span> spans;
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
        const ScreenTriangle& p = triangles[t];
        if (!fitsScan(p)) {
            std::fprintf(stderr, "warning: triangle %d lies too far off the screen, skipped\n", t);
            continue;
        }
        EdgeFunctions e = edgeFunctions(p);
        if (e.den == 0)
            continue;  // zero area covers nothing
        long long sign = e.den > 0 ? 1 : -1;
        long long top = std::max(0LL, std::min({p[0].y, p[1].y, p[2].y}));
        long long bottom = std::min(height - 1LL, std::max({p[0].y, p[1].y, p[2].y}));
        for (long long y = top; y <= bottom; ++y) {
            long long first = 0, last = width - 1;
            for (int i = 0; i < 3; ++i) {
                // inside this edge: a x + b >= 0
                long long a = sign * e.A[i];
                long long b = sign * (e.B[i] + e.C[i] * y);
                if (a > 0)
                    first = std::max(first, -floorDiv(b, a));
                else if (a < 0)
                    last = std::min(last, floorDiv(b, -a));
                else if (b < 0)
                    last = -1;
            }
            if (first <= last)
                spans.push_back({t, y, first, last});
        }
    }
    return spans;
}

struct Barycentric {
    double alpha, beta, gamma;
};

Barycentric barycentric(const EdgeFunctions& e, long long x, long long y)
{
    double den = static_cast<double>(e.den);
    return {e.at(0, x, y) / den, e.at(1, x, y) / den, e.at(2, x, y) / den};
}

Vec3 interpolate(const Barycentric& w, Vec3 a, Vec3 b, Vec3 c)
{
    return a * w.alpha + b * w.beta + c * w.gamma;
}

// ---------------------------------------------------------------------------
// Stage 6: the z-buffer

struct Fragment {
    int t;
    long long x, y;
    double z;
};

class ZBuffer {
public:
    ZBuffer(int width, int height)
        : width_(width), height_(height),
          depth_(static_cast<size_t>(width) * height, std::numeric_limits<double>::infinity()),
          triangle_(static_cast<size_t>(width) * height, -1)
    {
    }

    // Keeps the fragment when it is nearer than the stored one (strict <).
    bool offer(const Fragment& f)
    {
        if (f.x < 0 || f.y < 0 || f.x >= width_ || f.y >= height_)
            return false;
        size_t i = static_cast<size_t>(f.y) * width_ + f.x;
        if (!(f.z < depth_[i]))
            return false;
        depth_[i] = f.z;
        triangle_[i] = f.t;
        return true;
    }

    // The fragments kept, row by row.
    std::vector<Fragment> kept() const
    {
        std::vector<Fragment> result;
        for (int y = 0; y < height_; ++y)
            for (int x = 0; x < width_; ++x) {
                size_t i = static_cast<size_t>(y) * width_ + x;
                if (triangle_[i] >= 0)
                    result.push_back({triangle_[i], x, y, depth_[i]});
            }
        return result;
    }

private:
    int width_, height_;
    std::vector<double> depth_;
    std::vector<int> triangle_;
};

std::vector<Fragment> zbuffer(int width, int height, const std::vector<Fragment>& fragments)
{
    ZBuffer buffer(width, height);
    for (const Fragment& f : fragments)
        buffer.offer(f);
    return buffer.kept();
}

// ---------------------------------------------------------------------------
// Stage 7: Phong at a point P' (view coordinates), light Pl in view coordinates.
// Returns each channel as min(I, 255), not rounded.

Vec3 phong(Vec3 P, Vec3 N, Vec3 Pl, const Lighting& l)
{
    Vec3 V = normalize(-P);
    Vec3 L = normalize(Pl - P);
    N = normalize(N);
    if (dot(V, N) < 0)
        N = -N;

    Vec3 I = l.Ia * l.ka;
    double NL = dot(N, L);
    if (NL >= 0) {
        I = I + Vec3{l.Il.x * l.Od.x * l.kd.x * NL, l.Il.y * l.Od.y * l.kd.y * NL,
                     l.Il.z * l.Od.z * l.kd.z * NL};
        Vec3 R = N * (2 * NL) - L;
        double RV = dot(R, V);
        if (RV >= 0)
            I = I + l.Il * (l.ks * std::pow(RV, l.n));
    }
    return {std::min(I.x, 255.0), std::min(I.y, 255.0), std::min(I.z, 255.0)};
}

// Clamp to 0..255, then truncate as a C cast would.
uint8_t toByte(double value)
{
    return static_cast<uint8_t>(std::max(0.0, std::min(value, 255.0)));
}

// ---------------------------------------------------------------------------
// The whole pipeline

struct Image {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb;  // row 0 at the top, black background
};

Image render(const Camera& camera, const Lighting& lighting, const Mesh& mesh, int width,
             int height)
{
    Basis b = basis(camera.N, camera.V);
    Vec3 light = toView(b, camera.C, lighting.Pl);
    std::vector<Vec3> view;
    for (Vec3 P : mesh.points)
        view.push_back(toView(b, camera.C, P));
    Normals n = normals(view, mesh.triangles);

    std::vector<ScreenPoint> screen;
    for (Vec3 P : view)
        screen.push_back(project(P, camera.d, camera.hx, camera.hy, width, height));

    // The triangles that can be drawn, and where each came from in the mesh.
    std::vector<ScreenTriangle> drawn;
    std::vector<int> source;
    int atEye = 0, tooFar = 0;
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
        const Triangle& tri = mesh.triangles[t];
        ScreenTriangle s;
        bool ok = true;
        for (int k = 0; k < 3 && ok; ++k) {
            const ScreenPoint& p = screen[tri[k]];
            if (view[tri[k]].z == 0) {
                ++atEye;
                ok = false;
            } else if (!(std::fabs(p.x) < kMaxCoordinate && std::fabs(p.y) < kMaxCoordinate)) {
                ++tooFar;
                ok = false;
            } else {
                s[k] = {static_cast<long long>(p.x), static_cast<long long>(p.y)};
            }
        }
        if (ok) {
            drawn.push_back(s);
            source.push_back(t);
        }
    }
    if (atEye > 0)
        std::fprintf(stderr, "warning: %d triangles with a vertex at view z = 0 skipped\n", atEye);
    if (tooFar > 0)
        std::fprintf(stderr, "warning: %d triangles with a vertex far off the screen skipped\n",
                     tooFar);

    std::vector<EdgeFunctions> edges;
    for (const ScreenTriangle& s : drawn)
        edges.push_back(edgeFunctions(s));

    // Depth of each covered pixel from the screen barycentrics, through the z-buffer
    // (the same ZBuffer the zbuffer stage uses, fed without storing every fragment).
    ZBuffer buffer(width, height);
    for (const Span& span : scan(width, height, drawn)) {
        const Triangle& tri = mesh.triangles[source[span.t]];
        for (long long x = span.first; x <= span.last; ++x) {
            Barycentric w = barycentric(edges[span.t], x, span.y);
            double z = view[tri[0]].z * w.alpha + view[tri[1]].z * w.beta + view[tri[2]].z * w.gamma;
            buffer.offer({span.t, x, span.y, z});
        }
    }

    // Phong at the fragments kept: P' and N with the same barycentrics.
    Image image;
    image.width = width;
    image.height = height;
    image.rgb.assign(static_cast<size_t>(width) * height * 3, 0);
    for (const Fragment& f : buffer.kept()) {
        const Triangle& tri = mesh.triangles[source[f.t]];
        Barycentric w = barycentric(edges[f.t], f.x, f.y);
        Vec3 P = interpolate(w, view[tri[0]], view[tri[1]], view[tri[2]]);
        Vec3 N = interpolate(w, n.vertex[tri[0]], n.vertex[tri[1]], n.vertex[tri[2]]);
        Vec3 colour = phong(P, N, light, lighting);
        size_t i = (static_cast<size_t>(f.y) * width + f.x) * 3;
        image.rgb[i] = toByte(colour.x);
        image.rgb[i + 1] = toByte(colour.y);
        image.rgb[i + 2] = toByte(colour.z);
    }
    return image;
}

// ---------------------------------------------------------------------------
// Errors

[[noreturn]] void fail(const std::string& message)
{
    std::fprintf(stderr, "%s\n", message.c_str());
    std::exit(1);
}

[[noreturn]] void failAt(const std::string& file, int line, const std::string& message)
{
    fail(file + ":" + std::to_string(line) + ": " + message);
}

// A decimal number with '.' and an optional exponent; no nan, inf or hex.
bool parseNumber(const std::string& text, double& value)
{
    if (text.empty())
        return false;
    for (char c : text)
        if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' ||
              c == 'e' || c == 'E'))
            return false;
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);  // the C locale: '.' is the decimal point
    return *end == '\0' && std::isfinite(value);
}

bool isWhole(double v) { return std::floor(v) == v && std::fabs(v) < 1e15; }

// ---------------------------------------------------------------------------
// Course files: whitespace-separated numbers, each remembered with its line

class NumberFile {
public:
    explicit NumberFile(const std::string& path) : path_(path)
    {
        std::ifstream in(path, std::ios::binary);
        if (!in)
            fail(path + ": cannot open the file");
        std::stringstream text;
        text << in.rdbuf();
        int line = 1;
        std::string token;
        for (char c : text.str() + "\n") {
            if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
                if (!token.empty())
                    tokens_.push_back({token, line});
                token.clear();
                if (c == '\n')
                    ++line;
            } else {
                token += c;
            }
        }
        lastLine_ = tokens_.empty() ? 1 : tokens_.back().line;
    }

    const std::string& path() const { return path_; }
    bool atEnd() const { return next_ >= tokens_.size(); }
    int line() const { return atEnd() ? lastLine_ : tokens_[next_].line; }
    // The line of the token just read.
    int lastReadLine() const { return next_ == 0 ? 1 : tokens_[next_ - 1].line; }

    // How many tokens the line of the next token holds.
    int tokensOnLine() const
    {
        int count = 0;
        for (size_t i = next_; i < tokens_.size() && tokens_[i].line == line(); ++i)
            ++count;
        return count;
    }

    double number(const std::string& what)
    {
        if (atEnd())
            failAt(path_, lastLine_, "expected " + what + ", but the file ends");
        const Token& t = tokens_[next_];
        double value;
        if (!parseNumber(t.text, value))
            failAt(path_, t.line, "expected " + what + ", found '" + t.text + "'");
        ++next_;
        return value;
    }

    long long whole(const std::string& what)
    {
        double value = number(what);
        if (!isWhole(value))
            failAt(path_, lastReadLine(), "expected " + what + " (a whole number), found '" +
                                              tokens_[next_ - 1].text + "'");
        return static_cast<long long>(value);
    }

    Vec3 vec3(const std::string& what)
    {
        Vec3 v;
        v.x = number(what);
        v.y = number(what);
        v.z = number(what);
        return v;
    }

    void warnIfMore(const std::string& what)
    {
        if (!atEnd())
            std::fprintf(stderr, "%s:%d: warning: data after %s ignored\n", path_.c_str(), line(),
                         what.c_str());
    }

private:
    struct Token {
        std::string text;
        int line;
    };
    std::string path_;
    std::vector<Token> tokens_;
    size_t next_ = 0;
    int lastLine_ = 1;
};

// UFPE camera: C, N, V, then d hx hy.
Camera readCamera(const std::string& path)
{
    NumberFile f(path);
    Camera c;
    c.C = f.vec3("C, the camera's position (x y z)");
    int lineN = f.line();
    c.N = f.vec3("N, the view direction (x y z)");
    int lineV = f.line();
    c.V = f.vec3("V, the up vector (x y z)");
    int lineD = f.line();
    c.d = f.number("d hx hy");
    c.hx = f.number("d hx hy");
    c.hy = f.number("d hx hy");
    f.warnIfMore("the camera's 12 numbers");
    if (dot(c.N, c.N) == 0)
        failAt(path, lineN, "N must not be the zero vector");
    Vec3 n = normalize(c.N);
    if (dot(c.V - n * dot(c.V, n), c.V - n * dot(c.V, n)) == 0)
        failAt(path, lineV, "V must not be zero or parallel to N");
    if (c.hx == 0 || c.hy == 0)
        failAt(path, lineD, "hx and hy must not be zero");
    return c;
}

// UFPE lighting, eight lines: Pl, ka, Ia, kd, Od, ks, Il, n.
Lighting readLighting(const std::string& path)
{
    NumberFile f(path);
    Lighting l;
    l.Pl = f.vec3("Pl, the light's position (x y z)");
    l.ka = f.number("ka, the ambient coefficient");
    l.Ia = f.vec3("Ia, the ambient colour (r g b)");
    double kd = f.number("kd, the diffuse coefficient");
    l.kd = {kd, kd, kd};
    l.Od = f.vec3("Od, the diffuse colour (r g b, 0..1)");
    l.ks = f.number("ks, the specular coefficient");
    l.Il = f.vec3("Il, the light's colour (r g b)");
    l.n = f.number("n, the shininess exponent");
    f.warnIfMore("the lighting's 16 numbers");
    return l;
}

// .byu: "nVerts nTris", the vertices, the triangles (indices from 1).
Mesh readObject(const std::string& path)
{
    NumberFile f(path);
    if (f.tokensOnLine() == 4)
        failAt(path, f.line(), "expected 'vertices triangles'; four numbers look like a "
                               "Movie.BYU header, which this program does not read");
    long long nPoints = f.whole("the number of vertices");
    long long nTriangles = f.whole("the number of triangles");
    if (nPoints < 1 || nTriangles < 0 || nPoints > 100000000 || nTriangles > 100000000)
        failAt(path, f.lastReadLine(), "expected the counts of vertices (at least 1) and "
                                       "triangles");
    Mesh mesh;
    for (long long i = 1; i <= nPoints; ++i)
        mesh.points.push_back(f.vec3("vertex " + std::to_string(i) + " (x y z)"));
    for (long long t = 1; t <= nTriangles; ++t) {
        Triangle tri;
        for (int& index : tri) {
            long long v = f.whole("triangle " + std::to_string(t) + " (three vertex numbers)");
            if (v < 1 || v > nPoints)
                failAt(path, f.lastReadLine(),
                       "expected vertex numbers 1.." + std::to_string(nPoints) + " in triangle " +
                           std::to_string(t) + ", found " + std::to_string(v));
            index = static_cast<int>(v - 1);
        }
        mesh.triangles.push_back(tri);
    }
    f.warnIfMore("the declared " + std::to_string(nTriangles) + " triangles");
    return mesh;
}

// ---------------------------------------------------------------------------
// Image files

uint32_t crc32(const uint8_t* data, size_t size, uint32_t crc = 0)
{
    static uint32_t table[256];
    static bool ready = false;
    if (!ready) {
        for (uint32_t n = 0; n < 256; ++n) {
            uint32_t c = n;
            for (int k = 0; k < 8; ++k)
                c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            table[n] = c;
        }
        ready = true;
    }
    crc = ~crc;
    for (size_t i = 0; i < size; ++i)
        crc = table[(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
    return ~crc;
}

uint32_t adler32(const std::vector<uint8_t>& data)
{
    uint32_t a = 1, b = 0;
    for (uint8_t byte : data) {
        a = (a + byte) % 65521;
        b = (b + a) % 65521;
    }
    return (b << 16) | a;
}

void putBigEndian(std::vector<uint8_t>& out, uint32_t v)
{
    for (int shift = 24; shift >= 0; shift -= 8)
        out.push_back(static_cast<uint8_t>(v >> shift));
}

void pngChunk(std::vector<uint8_t>& out, const char* type, const std::vector<uint8_t>& data)
{
    putBigEndian(out, static_cast<uint32_t>(data.size()));
    std::vector<uint8_t> body(type, type + 4);
    body.insert(body.end(), data.begin(), data.end());
    out.insert(out.end(), body.begin(), body.end());
    putBigEndian(out, crc32(body.data(), body.size()));
}

// 8-bit RGB PNG; the zlib stream holds uncompressed ("stored") deflate blocks.
std::vector<uint8_t> encodePng(const Image& image)
{
    std::vector<uint8_t> raw;  // each row: filter 0, then r g b ...
    size_t stride = static_cast<size_t>(image.width) * 3;
    for (int y = 0; y < image.height; ++y) {
        raw.push_back(0);
        raw.insert(raw.end(), image.rgb.begin() + y * stride, image.rgb.begin() + (y + 1) * stride);
    }
    std::vector<uint8_t> zlib = {0x78, 0x01};
    size_t done = 0;
    do {
        size_t size = std::min<size_t>(65535, raw.size() - done);
        bool last = done + size == raw.size();
        zlib.push_back(last ? 1 : 0);
        zlib.push_back(static_cast<uint8_t>(size & 0xFF));
        zlib.push_back(static_cast<uint8_t>(size >> 8));
        zlib.push_back(static_cast<uint8_t>(~size & 0xFF));
        zlib.push_back(static_cast<uint8_t>((~size >> 8) & 0xFF));
        zlib.insert(zlib.end(), raw.begin() + done, raw.begin() + done + size);
        done += size;
    } while (done < raw.size());
    putBigEndian(zlib, adler32(raw));

    std::vector<uint8_t> header;
    putBigEndian(header, static_cast<uint32_t>(image.width));
    putBigEndian(header, static_cast<uint32_t>(image.height));
    header.insert(header.end(), {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, filter 0, no interlace

    std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    pngChunk(png, "IHDR", header);
    pngChunk(png, "IDAT", zlib);
    pngChunk(png, "IEND", {});
    return png;
}

std::vector<uint8_t> encodePpm(const Image& image)
{
    std::string header = "P6\n" + std::to_string(image.width) + " " +
                         std::to_string(image.height) + "\n255\n";
    std::vector<uint8_t> out(header.begin(), header.end());
    out.insert(out.end(), image.rgb.begin(), image.rgb.end());
    return out;
}

bool endsWith(const std::string& s, const std::string& suffix)
{
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void writeImage(const std::string& path, const Image& image)
{
    std::vector<uint8_t> bytes = endsWith(path, ".ppm") ? encodePpm(image) : encodePng(image);
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!out)
        fail(path + ": cannot write the image");
}

// ---------------------------------------------------------------------------
// The stage protocol (docs/stage-protocol.md, version 1)

const std::set<std::string> kLists = {"vertices", "triangles", "samples", "fragments"};

struct Request {
    std::string stage;
    int line = 0;  // the stage's line, for error messages
    std::map<std::string, std::vector<double>> records;
    std::map<std::string, std::vector<std::vector<double>>> lists;
};

class Protocol {
public:
    // The fields of the next line; false at the end of the input.
    bool readLine(std::vector<std::string>& fields)
    {
        std::string line;
        if (!std::getline(std::cin, line))
            return false;
        ++lineNumber_;
        fields.clear();
        std::string field;
        for (char c : line + " ") {
            if (c == ' ' || c == '\t' || c == '\r') {
                if (!field.empty())
                    fields.push_back(field);
                field.clear();
            } else {
                field += c;
            }
        }
        return true;
    }

    [[noreturn]] void error(const std::string& message) { failAt("stdin", lineNumber_, message); }

    std::vector<double> numbers(const std::vector<std::string>& fields, size_t from)
    {
        std::vector<double> values;
        for (size_t i = from; i < fields.size(); ++i) {
            double v;
            if (!parseNumber(fields[i], v))
                error("expected a number, found '" + fields[i] + "'");
            values.push_back(v);
        }
        return values;
    }

    // The lines of a request this program does not answer, up to "end".
    void skipRequest()
    {
        std::vector<std::string> fields;
        while (!(fields.size() == 1 && fields[0] == "end"))
            if (!readLine(fields))
                error("expected 'end', the input ends");
    }

    // The records up to "end"; a list's items follow its record.
    Request readRequest(const std::string& stage)
    {
        Request request;
        request.stage = stage;
        request.line = lineNumber_;
        std::vector<std::string> fields;
        while (true) {
            if (!readLine(fields))
                error("expected 'end', the input ends");
            if (fields.empty())
                continue;
            const std::string& name = fields[0];
            if (name == "end")
                return request;
            std::vector<double> values = numbers(fields, 1);
            if (kLists.count(name) == 0) {
                request.records[name] = values;
                continue;
            }
            if (values.size() != 1 || !isWhole(values[0]) || values[0] < 0)
                error("expected '" + name + " count'");
            auto& items = request.lists[name];
            for (long long i = 0; i < static_cast<long long>(values[0]); ++i) {
                if (!readLine(fields))
                    error("expected " + name + " item " + std::to_string(i) + ", the input ends");
                items.push_back(numbers(fields, 0));
            }
        }
    }

private:
    int lineNumber_ = 0;
};

// Accessors that say what a request lacks.
class Fields {
public:
    explicit Fields(const Request& r) : r_(r) {}

    [[noreturn]] void missing(const std::string& what) const
    {
        failAt("stdin", r_.line, "the " + r_.stage + " request lacks " + what);
    }

    std::vector<double> record(const std::string& name, size_t count) const
    {
        auto it = r_.records.find(name);
        if (it == r_.records.end() || it->second.size() != count)
            missing("'" + name + "' with " + std::to_string(count) + " numbers");
        return it->second;
    }

    Vec3 vec3(const std::string& name) const
    {
        std::vector<double> v = record(name, 3);
        return {v[0], v[1], v[2]};
    }

    double scalar(const std::string& name) const { return record(name, 1)[0]; }

    // kd: r g b, or one number for all three channels
    Vec3 colourOrScalar(const std::string& name) const
    {
        auto it = r_.records.find(name);
        if (it != r_.records.end() && it->second.size() == 1)
            return {it->second[0], it->second[0], it->second[0]};
        return vec3(name);
    }

    int size(const std::string& name, int index) const
    {
        double v = record(name, 2)[index];
        if (!isWhole(v) || v < 1 || v > 65536)
            missing("'" + name + " width height' with whole sizes 1..65536");
        return static_cast<int>(v);
    }

    const std::vector<std::vector<double>>& list(const std::string& name, size_t columns) const
    {
        auto it = r_.lists.find(name);
        if (it == r_.lists.end())
            missing("'" + name + " count'");
        for (const auto& item : it->second)
            if (item.size() != columns)
                missing(name + " lines of " + std::to_string(columns) + " numbers");
        return it->second;
    }

    std::vector<Vec3> points(const std::string& name) const
    {
        std::vector<Vec3> result;
        for (const auto& item : list(name, 3))
            result.push_back({item[0], item[1], item[2]});
        return result;
    }

    std::vector<Triangle> triangles(size_t vertexCount) const
    {
        std::vector<Triangle> result;
        for (const auto& item : list("triangles", 3)) {
            Triangle t;
            for (int k = 0; k < 3; ++k) {
                if (!isWhole(item[k]) || item[k] < 0 || item[k] >= static_cast<double>(vertexCount))
                    missing("triangles of vertex indices 0.." + std::to_string(vertexCount - 1));
                t[k] = static_cast<int>(item[k]);
            }
            result.push_back(t);
        }
        return result;
    }

    Lighting lighting() const
    {
        Lighting l;
        l.Pl = vec3("light");
        l.Ia = vec3("Ia");
        l.Il = vec3("Il");
        l.ka = scalar("ka");
        l.kd = colourOrScalar("kd");
        l.Od = vec3("Od");
        l.ks = scalar("ks");
        l.n = scalar("n");
        return l;
    }

private:
    const Request& r_;
};

void printVec(const char* name, Vec3 v)
{
    if (name)
        std::printf("%s %.17g %.17g %.17g\n", name, v.x, v.y, v.z);
    else
        std::printf("%.17g %.17g %.17g\n", v.x, v.y, v.z);
}

void answerBasis(const Fields& f)
{
    Basis b = basis(f.vec3("N"), f.vec3("V"));
    printVec("U", b.U);
    printVec("V", b.V);
    printVec("N", b.N);
}

void answerView(const Fields& f)
{
    Basis b{f.vec3("U"), f.vec3("V"), f.vec3("N")};
    Vec3 C = f.vec3("C");
    std::vector<Vec3> points = f.points("vertices");
    printVec("light", toView(b, C, f.vec3("light")));
    std::printf("vertices %zu\n", points.size());
    for (Vec3 P : points)
        printVec(nullptr, toView(b, C, P));
}

void answerNormals(const Fields& f)
{
    std::vector<Vec3> view = f.points("vertices");
    Normals n = normals(view, f.triangles(view.size()));
    std::printf("triangle-normals %zu\n", n.triangle.size());
    for (Vec3 v : n.triangle)
        printVec(nullptr, v);
    std::printf("vertex-normals %zu\n", n.vertex.size());
    for (Vec3 v : n.vertex)
        printVec(nullptr, v);
}

void answerProjection(const Fields& f)
{
    std::vector<double> camera = f.record("camera", 3);
    int width = f.size("size", 0), height = f.size("size", 1);
    std::vector<Vec3> view = f.points("vertices");
    std::printf("screen %zu\n", view.size());
    for (Vec3 P : view) {
        ScreenPoint s = project(P, camera[0], camera[1], camera[2], width, height);
        if (!std::isfinite(s.x) || !std::isfinite(s.y))
            f.missing("vertices with z > 0");
        std::printf("%.0f %.0f\n", s.x, s.y);
    }
}

void answerScan(const Fields& f)
{
    int width = f.size("size", 0), height = f.size("size", 1);
    std::vector<ScreenTriangle> triangles;
    for (const auto& item : f.list("triangles", 6)) {
        ScreenTriangle t;
        for (int k = 0; k < 3; ++k) {
            if (!isWhole(item[2 * k]) || !isWhole(item[2 * k + 1]))
                f.missing("triangles of whole pixels");
            t[k] = {static_cast<long long>(item[2 * k]), static_cast<long long>(item[2 * k + 1])};
        }
        triangles.push_back(t);
    }
    std::vector<Span> spans = scan(width, height, triangles);
    std::printf("spans %zu\n", spans.size());
    for (const Span& s : spans)
        std::printf("%d %lld %lld %lld\n", s.t, s.y, s.first, s.last);
}

void answerZbuffer(const Fields& f)
{
    int width = f.size("size", 0), height = f.size("size", 1);
    std::vector<Fragment> fragments;
    for (const auto& item : f.list("fragments", 4)) {
        if (!isWhole(item[0]) || !isWhole(item[1]) || !isWhole(item[2]) || item[0] < 0 ||
            item[0] > 2e9)
            f.missing("fragments 't x y z' with whole t, x, y");
        fragments.push_back({static_cast<int>(item[0]), static_cast<long long>(item[1]),
                             static_cast<long long>(item[2]), item[3]});
    }
    std::vector<Fragment> kept = zbuffer(width, height, fragments);
    std::printf("pixels %zu\n", kept.size());
    for (const Fragment& p : kept)
        std::printf("%lld %lld %d %.17g\n", p.x, p.y, p.t, p.z);
}

void answerLighting(const Fields& f)
{
    Lighting l = f.lighting();
    const auto& samples = f.list("samples", 6);
    std::printf("colours %zu\n", samples.size());
    for (const auto& s : samples)
        printVec(nullptr, phong({s[0], s[1], s[2]}, {s[3], s[4], s[5]}, l.Pl, l));
}

void answerFrame(const Fields& f)
{
    int width = f.size("size", 0), height = f.size("size", 1);
    Camera c;
    c.C = f.vec3("C");
    c.N = f.vec3("N");
    c.V = f.vec3("V");
    std::vector<double> dh = f.record("camera", 3);
    c.d = dh[0];
    c.hx = dh[1];
    c.hy = dh[2];
    Mesh mesh;
    mesh.points = f.points("vertices");
    mesh.triangles = f.triangles(mesh.points.size());
    Image image = render(c, f.lighting(), mesh, width, height);

    std::printf("image %d %d\n", width, height);
    std::string row;
    for (int y = 0; y < height; ++y) {
        row.clear();
        for (int i = 0; i < width * 3; ++i) {
            if (i > 0)
                row += ' ';
            row += std::to_string(image.rgb[static_cast<size_t>(y) * width * 3 + i]);
        }
        row += '\n';
        std::fputs(row.c_str(), stdout);
    }
}

int runStages()
{
    Protocol protocol;
    std::vector<std::string> fields;
    if (!protocol.readLine(fields) || fields.size() != 2 || fields[0] != "rasterlab")
        protocol.error("expected 'rasterlab VERSION'");
    std::printf("speaks 1\n");
    std::fflush(stdout);

    const std::map<std::string, void (*)(const Fields&)> stages = {
        {"basis", answerBasis},         {"view", answerView}, {"normals", answerNormals},
        {"projection", answerProjection}, {"scan", answerScan}, {"zbuffer", answerZbuffer},
        {"lighting", answerLighting},   {"frame", answerFrame},
    };
    while (protocol.readLine(fields)) {
        if (fields.empty())
            continue;
        if (fields[0] == "bye")
            return 0;
        auto stage = stages.find(fields[0]);
        if (stage == stages.end()) {
            protocol.skipRequest();
            std::printf("unsupported\n");
        } else {
            Request request = protocol.readRequest(fields[0]);
            stage->second(Fields(request));
            std::printf("end\n");
        }
        std::fflush(stdout);
    }
    return 0;  // the input ended without "bye"
}

// ---------------------------------------------------------------------------
// Command line

const char* kUsage =
    "usage: rasterizer --camera FILE --lighting FILE --object FILE [--size WxH]\n"
    "                  --output OUT.png|OUT.ppm\n"
    "       rasterizer --stages     (RasterLab's stage protocol on stdin/stdout)\n";

bool parseSize(const std::string& text, int& width, int& height)
{
    size_t x = text.find_first_of("xX");
    if (x == std::string::npos || x == 0 || x + 1 == text.size())
        return false;
    std::string w = text.substr(0, x), h = text.substr(x + 1);
    for (const std::string& part : {w, h})
        if (part.size() > 5 || part.find_first_not_of("0123456789") != std::string::npos)
            return false;
    width = std::stoi(w);
    height = std::stoi(h);
    return width >= 1 && height >= 1 && width <= 16384 && height <= 16384;
}

}  // namespace

int main(int argc, char** argv)
{
    std::map<std::string, std::string> options;
    bool stages = false;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "--stages") {
            stages = true;
        } else if (arg == "--help" || arg == "-h") {
            std::fputs(kUsage, stdout);
            return 0;
        } else if (arg == "--camera" || arg == "--lighting" || arg == "--object" ||
                   arg == "--size" || arg == "--output") {
            if (i + 1 == argc)
                fail(arg + ": expected a value\n" + kUsage);
            options[arg] = argv[++i];
        } else {
            fail("unknown option '" + arg + "'\n" + kUsage);
        }
    }
    if (stages)
        return runStages();

    for (const char* required : {"--camera", "--lighting", "--object", "--output"})
        if (options.count(required) == 0)
            fail(std::string("missing ") + required + "\n" + kUsage);
    int width = 800, height = 600;
    if (options.count("--size") && !parseSize(options["--size"], width, height))
        fail("--size: expected WxH (1..16384 each), found '" + options["--size"] + "'");

    Camera camera = readCamera(options["--camera"]);
    Lighting lighting = readLighting(options["--lighting"]);
    Mesh mesh = readObject(options["--object"]);
    writeImage(options["--output"], render(camera, lighting, mesh, width, height));
    return 0;
}
