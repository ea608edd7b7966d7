// The scene: what every input format becomes, and the only thing the stages read.
//
// A scene is a list of draws (a mesh with its per-vertex attributes, material, model and
// projection matrices, lighting model and flags), the lights, an optional course camera
// (C, N, V, d, hx, hy), the image size, the conventions of the format it came from (how
// NDC maps to pixels, what the depth buffer stores, the colour scale, how bytes are
// rounded) and its rasterization rules. The stages read conventions and rules from the
// scene; they have no "if course format" branches.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/core/diagnostics.h"
#include "pipeline/core/math.h"

namespace rl {

// A triangle mesh in model space. Vertex indices are 0-based here (files are 1-based).
// The attributes beside the positions are optional: empty when the source gives none.
struct Mesh {
    std::vector<dvec4> positions;  // model space, w = 1 unless the file gives w (HW2 xyzw)
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<vec3> colours;       // object colour per vertex, in the scene's colour scale
    std::vector<vec3> normals;       // model-space normals given by the file
    std::vector<vec2> texcoords;     // texture coordinates (s, t)
    SourceLocation source;           // the file it was read from
    std::vector<int> triangleLines;  // source line of each triangle (may be empty)
    // closedSurfaceWinding() (mesh_topology.h), worked out by whoever builds the mesh: +1 or
    // -1 for the closed surface of a solid, 0 for an open one (or not worked out).
    int closedWinding = 0;
};

// Phong material as the course writes it: I = Ia*ka + Il*Od*kd*(N.L) + Il*ks*(R.V)^n.
struct Material {
    float ka = 0.0f;         // ambient coefficient
    vec3 kd = vec3(0.0f);    // diffuse coefficient, per channel (a scalar kd is broadcast)
    vec3 od = vec3(0.0f);    // diffuse colour of the object, 0..1
    float ks = 0.0f;         // specular coefficient
    float shininess = 1.0f;  // n, the Phong exponent
    // Ke, the light the surface gives off by itself (OpenGL's GL_EMISSION, seed 003), in the
    // scene's colour scale like Ia: added to every lit point, lights or not.
    vec3 emission = vec3(0.0f);
};

// A positional light (w != 0) or a directional light (w = 0, position is the direction
// toward it), as OpenGL's GL_POSITION (seed 003), optionally attenuated and a spot.
struct Light {
    dvec4 pWorld = dvec4(0.0, 0.0, 0.0, 1.0);
    vec3 intensity = vec3(0.0f);  // Il, in the scene's colour scale (may exceed it, or be < 0)
    SourceLocation where;
    // A positional light's diffuse and specular terms are multiplied by
    // 1 / (kc + kl d + kq d^2), d its distance to the point (GL_CONSTANT_, GL_LINEAR_ and
    // GL_QUADRATIC_ATTENUATION); (1, 0, 0) leaves them as they are. Not for directional lights.
    vec3 attenuation = vec3(1.0f, 0.0f, 0.0f);  // (kc, kl, kq)
    // A spot (GL_SPOT_CUTOFF 0..90 degrees; 180 is not a spot): a point whose direction from
    // the light, -L, makes an angle above the cutoff with spotDirection gets no light from it;
    // inside the cone the terms are multiplied by (-L . D)^spotExponent, D = spotDirection
    // normalised.
    dvec3 spotDirection = dvec3(0.0, 0.0, -1.0);  // world space
    float spotCutoff = 180.0f;                    // degrees
    float spotExponent = 0.0f;

    bool attenuated() const { return attenuation != vec3(1.0f, 0.0f, 0.0f) && pWorld.w != 0.0; }
    bool spot() const { return spotCutoff != 180.0f; }
};

// How the course's model makes its highlight.
enum class SpecularModel : std::uint8_t {
    Phong,       // Il ks (R.V)^n, R the reflection of L about N (seed 000)
    BlinnPhong,  // Il ks (N.H)^n, H = (L + V)/|L + V|, the half vector (seed 003)
};

// A texture: RGBA texels, 0..1, row 0 at the top (t = 0).
struct Texture {
    int width = 0;
    int height = 0;
    std::vector<vec4> texels;
    std::string name;
    vec4 at(int x, int y) const {
        return texels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                      static_cast<std::size_t>(x)];
    }
};

// The course camera of seed 000: position C, view direction N, up hint V, and the
// projection parameters d, hx, hy: pNdc = ((d/hx) x/z, (d/hy) y/z) in view coordinates.
struct CourseCamera {
    dvec3 c = dvec3(0.0);
    dvec3 n = dvec3(0.0, 0.0, 1.0);
    dvec3 v = dvec3(0.0, 1.0, 0.0);
    double d = 1.0;
    double hx = 1.0;
    double hy = 1.0;

    struct Sources {
        SourceLocation c, n, v, d, hx, hy;
    } where;
};

enum class ShadingModel : std::uint8_t {
    Flat,     // one lighting evaluation per triangle, at its barycentre (seed 004)
    Gouraud,  // lighting at the vertices, colours interpolated
    Phong,    // lighting per pixel with interpolated P' and N (seed 000)
    // Seed 004's painter's algorithm: lit as Flat, but the frame's triangles are painted far
    // to near by the distance of their barycentres, without a depth test
    // (painters_algorithm.h).
    Painter,
};

const char* shadingModelName(ShadingModel model);  // "flat", "gouraud", "phong", "painter"
std::optional<ShadingModel> shadingModelFromName(std::string_view name);
// One lighting evaluation per triangle, at its barycentre: Flat, and Painter, which lights as
// Flat.
inline bool litPerTriangle(ShadingModel model) {
    return model == ShadingModel::Flat || model == ShadingModel::Painter;
}

// How a point is lit.
enum class LightingModel : std::uint8_t {
    CoursePhong,  // seed 000: Ia ka + Il Od kd (N.L) + Il ks (R.V)^n, N turned to the viewer
    Lambert,      // seed 001: sum over lights of (N.L) Il O, lights behind (N.L < 0) left
                  // out, plus Blinn-Phong Il (H.N)^shininess when shininess > 0
    Unlit,        // the object colour as it is
};

// Where the object colour (the course's Od) comes from.
enum class ColourSource : std::uint8_t {
    Material,  // material.od
    Vertex,    // the mesh's per-vertex colours, interpolated
    Texture,   // the draw's texture at the interpolated (s, t)
};

// A draw's motion over time (seed 002's animation matrix M; animation.h writes M out). Not
// part of any course or command file: the GUI's animation panel and the CLI set it.
struct Animation {
    double degreesPerSecond = 36.0;  // the turn: 36 degrees a second, a turn in 10 s
    std::optional<dvec3> axis;       // world; absent: the camera's up (a turntable)
    std::optional<dvec3> centre;     // world; absent: the centre of the draw's bounding box
    dvec3 velocity = dvec3(0.0);     // translation, world units per second
    dvec3 scale = dvec3(1.0);        // about the centre, along the world axes (fixed in time)
    bool operator==(const Animation&) const = default;
};

struct Draw {
    std::string name;  // for messages and views, e.g. "calice2.byu"
    std::shared_ptr<const Mesh> mesh;
    Material material;
    dmat4 worldFromModel = dmat4(1.0);
    // The projection of this draw; when absent, the course camera's (d, hx, hy).
    std::optional<dmat4> clipFromView;
    ShadingModel shading = ShadingModel::Phong;
    LightingModel lighting = LightingModel::CoursePhong;
    SpecularModel specular = SpecularModel::Phong;  // of the course's model
    ColourSource colour = ColourSource::Material;
    std::shared_ptr<const Texture> texture;  // with ColourSource::Texture
    bool decals = false;                     // texture alpha-blended over the vertex colour
    bool flatNormals = false;       // light with the triangle's normal, not the vertex normals
    bool cull = false;              // drop triangles that are clockwise on screen
    std::vector<dvec4> clipPlanes;  // view space: keep points with plane . (x, y, z, w) >= 0
    // The lights this draw sees: the first lightCount of the scene's (all by default).
    std::size_t lightCount = std::numeric_limits<std::size_t>::max();
    // Seed 002's M: when present, the draw is placed by M(scene.time) * worldFromModel.
    std::optional<Animation> animation;
};

// What the depth buffer holds.
enum class DepthSource : std::uint8_t {
    ViewZ,  // the view-space z of P' (seed 000)
    NdcZ,   // pClip.z / pClip.w (seed 001)
};

// How a channel in the scene's colour scale becomes a byte.
enum class ByteRounding : std::uint8_t {
    Truncate,  // (int) of the clamped value, as the course's C code does
    Nearest,   // round half up
};

// How NDC becomes pixels: the same in exact arithmetic, not always in double (x_ndc = -0.7
// on 120 pixels: 18.000000000000004 and 18).
enum class ViewportFormula : std::uint8_t {
    ShiftThenScale,  // (x_ndc + 1) W/2 (seed 000)
    ScaleThenShift,  // x_ndc W/2 + W/2 (seed 001)
};

struct Conventions {
    bool ndcYUp = true;  // NDC y = +1 is the top row (the course flips y)
    ViewportFormula viewport = ViewportFormula::ShiftThenScale;
    DepthSource depth = DepthSource::ViewZ;
    float depthClear = std::numeric_limits<float>::infinity();  // the empty depth buffer
    bool depthWinsOnTie = false;  // z <= stored writes (seed 001); otherwise z < stored
    bool depthRangeClip = false;  // discard fragments whose depth is outside [0, 1]
    // N := -N when V.N < 0 (seed 000): two-sided lighting, the back of a surface lit like its
    // front (OpenGL's GL_LIGHT_MODEL_TWO_SIDE). False: one-sided, a back lit with the normal
    // pointing away from the viewer.
    bool flipNormalsTowardViewer = true;
    float colourScale = 255.0f;  // the value that becomes byte 255 (course colours are 0..255)
    ByteRounding rounding = ByteRounding::Truncate;
    vec4 background = vec4(0.0f, 0.0f, 0.0f, 1.0f);  // RGBA 0..1 of pixels no triangle covers

    static Conventions course();
    static Conventions hw2();
};

// The rasterization rules: where a pixel is sampled, how vertices are snapped, which
// pixels on an edge belong to the triangle, and how attributes are interpolated.
struct RasterRules {
    enum class VertexSnap : std::uint8_t {
        Truncate,  // toward zero, onto the sub-pixel grid: C's (int) when subpixelBits = 0
        Nearest,   // to the nearest point of the sub-pixel grid
        None,      // kept as computed, in double (seed 001's DDA)
    };
    enum class FillRule : std::uint8_t {
        Inclusive,  // a sample exactly on an edge is inside: shared edges are covered twice
        TopLeft,    // on an edge, inside only on a left or a horizontal top edge: once
    };
    // How a triangle becomes spans (stage 5). The DDA has seed 001's sampling and fill rule
    // built in (samples at integer points, half-open rows and spans), whatever sampleOffset
    // and fill say; the hw2 preset says the same.
    enum class Scan : std::uint8_t {
        ExactWalk,  // the edge walk on the snapped vertices, in exact integer arithmetic
        Dda,        // seed 001's DDA in double: x stepped by dx/dy row by row (dda.h)
    };
    enum class Interpolation : std::uint8_t {
        ScreenAffine,        // screen barycentrics applied to view-space P and N (seed 000)
        PerspectiveCorrect,  // barycentrics weighted by 1/w (seed 001)
    };
    // Which texel of a w x h texture the coordinate s picks (t likewise with h).
    enum class TexelRounding : std::uint8_t {
        Nearest,   // the texel nearest to s w once s has wrapped into [0, 1) (seed 001's text)
        Truncate,  // (int)(s w + 0.5) mod w, (int) toward zero: the HW2 reference images'
                   // rule, which differs from Nearest where s w + 0.5 < 0
    };

    int subpixelBits = 0;       // vertices lie on a grid of 1/2^bits pixel (at most 16)
    double sampleOffset = 0.0;  // pixel (x, y) is sampled at (x + offset, y + offset)
    VertexSnap snap = VertexSnap::Truncate;
    FillRule fill = FillRule::Inclusive;
    Scan scan = Scan::ExactWalk;
    Interpolation interpolation = Interpolation::ScreenAffine;
    TexelRounding texel = TexelRounding::Nearest;

    static RasterRules course();  // seed 000 as written: integer vertices, inclusive edges
    // Seed 001's DDA as its lecture writes it: unsnapped vertices, samples at integer points,
    // half-open rows and spans, x stepped in double.
    static RasterRules hw2();
    // What a GPU does: vertices on a 1/256-pixel grid (nearest), samples at pixel centres
    // (+0.5), the top-left fill rule, perspective-correct attributes (and depth).
    static RasterRules gpu();

    bool operator==(const RasterRules&) const = default;
};

// The presets by name: "course", "gpu", "hw2".
enum class RuleSet : std::uint8_t { Course, Gpu, Hw2 };
const char* ruleSetName(RuleSet set);
std::optional<RuleSet> ruleSetFromName(std::string_view name);
RasterRules rulesOf(RuleSet set);
// The preset these rules are, if any.
std::optional<RuleSet> ruleSetOf(const RasterRules& rules);

// What happens to triangles at or behind the camera (w <= 0 in clip space).
struct NearPlane {
    enum class Mode : std::uint8_t {
        // Clip against the plane w = near before dividing by w (for the course camera, w is
        // the view z: the plane z = near in view space).
        Clip,
        // Divide by w without clipping, as seed 001 does ("frustum clipping ... we won't
        // add it"); a triangle whose vertices' w differ in sign would wrap through
        // infinity, so it is dropped (and counted) instead.
        SameSide,
        // The course's naive projection: every vertex divided by its own w, even w <= 0.
        // Only for showing why clipping exists.
        Naive,
    };
    Mode mode = Mode::Clip;
    // A fixed w (the course: view z); when absent, near = autoFraction * the largest w.
    std::optional<double> fixedW;
    double autoFraction = 1e-3;
};

struct Scene {
    std::string name;
    int width = 800;
    int height = 600;
    std::optional<CourseCamera> camera;
    std::vector<Draw> draws;
    std::vector<Light> lights;
    vec3 ambientIntensity = vec3(0.0f);  // Ia
    Conventions conventions;
    RasterRules rules = RasterRules::course();
    NearPlane nearPlane;
    // Leave out the triangles of a closed surface that face away from the camera when the
    // camera is outside it and nothing cuts it open (projection.h): they are hidden behind
    // its front faces, except where the course's integer vertices let one poke through at a
    // silhouette (14 of calice2's 16,907 pixels). False (course files) draws them all, as
    // seed 000 does; the benchmark scenes cull.
    bool cullHiddenBackFaces = false;
    // The time of this frame in seconds: where the draws with an animation are (animation.h).
    double time = 0.0;

    bool lit() const { return !lights.empty() || ambientIntensity != vec3(0.0f); }
    std::size_t triangleCount() const;
    std::size_t vertexCount() const;
};

// Whether the frame is painted by the painter's algorithm (painters_algorithm.h): some draw's
// shading is ShadingModel::Painter. Then every draw's triangles take part in the one far-to-near
// order.
bool paintersAlgorithm(const Scene& scene);

}  // namespace rl
