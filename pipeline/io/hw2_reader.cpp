#include "hw2_reader.h"

#include <algorithm>
#include <array>
#include <map>
#include <optional>

#include "pipeline/core/format.h"
#include "pipeline/io/text_scanner.h"
#include "pipeline/scene/bezier.h"
#include "pipeline/scene/transforms.h"

namespace rl {

namespace {

// A vertex as `xyz`/`xyzw` defines it, with the current colour, normal and texture
// coordinate of that moment.
struct Vertex {
    dvec4 p = dvec4(0.0, 0.0, 0.0, 1.0);
    vec3 colour = vec3(1.0f);
    vec2 st = vec2(0.0f);
    std::optional<vec3> normal;
};

// How a drawing command colours its triangles.
enum class Fill { Flat, Gouraud, Textured };

// The state a draw is made with; consecutive triangles with equal state share a draw.
struct DrawState {
    dmat4 modelView = dmat4(1.0);
    dmat4 projection = dmat4(1.0);
    std::vector<dvec4> clipPlanes;
    bool cull = false;
    std::size_t lightCount = 0;
    float shininess = 0.0f;
    Fill fill = Fill::Flat;
    bool flatNormals = false;
    std::shared_ptr<const Texture> texture;
    bool operator==(const DrawState&) const = default;
};

// At most this many triangles in one command file (a rectbezf 10 alone makes 2 million).
constexpr std::size_t kMaxTriangles = std::size_t(1) << 23;

const char* const kKnownCommands[] = {
    "png",      "xyz",      "xyzw",    "trif",      "trig",       "trit",      "color",
    "loadmv",   "loadp",    "multmv",  "frustum",   "ortho",      "translate", "rotatex",
    "rotatey",  "rotatez",  "rotate",  "scale",     "lookat",     "clipplane", "cull",
    "rectbezf", "rectbezg", "tribezf", "tribezg",   "texcoord",   "texture",   "decals",
    "normal",   "sunlight", "bulb",    "shininess", "flatnormals"};

// "1 argument", "3 arguments".
Message argumentsText(std::size_t n) {
    return counted(static_cast<long long>(n), "%1 argument"_msg, "%1 arguments"_msg);
}

bool isKnown(std::string_view keyword) {
    return std::find(std::begin(kKnownCommands), std::end(kKnownCommands), keyword) !=
           std::end(kKnownCommands);
}

// gluLookAt with s = f x up left at its length: the image stretched across by |f x up|.
dmat4 lookAtWithUnnormalisedSide(const dvec3& eye, const dvec3& center, const dvec3& up) {
    const double length = glm::length(glm::cross(glm::normalize(center - eye), up));
    // Row 0 is s (and its part of the translation by -eye): scaled by |s|.
    dmat4 out = lookAtMatrix(eye, center, up);
    for (int column = 0; column < 4; ++column) out[column][0] *= length;
    return out;
}

class Hw2Reader {
public:
    Hw2Reader(std::string_view text, const std::string& fileName, const TextureLoader& loader,
              Diagnostics& diagnostics, const Hw2Misreading* misreading)
        : m_text(text),
          m_scanner(text, fileName),
          m_loader(loader),
          m_diagnostics(diagnostics),
          m_misreading(misreading) {}

    Result<Hw2File> read();

private:
    using Args = std::vector<double>;

    Status command(const TextLine& line);
    // One command each (command dispatches by keyword).
    Status readImage(const TextLine& line);
    Status readVertex(const TextLine& line);
    Status readColour(const TextLine& line);
    Status readNormal(const TextLine& line);
    Status readTexcoord(const TextLine& line);
    Status readTriangle(const TextLine& line);
    Status readPatch(const TextLine& line);
    Status readMatrix(const TextLine& line);
    Status readProjection(const TextLine& line);
    Status readTranslateOrScale(const TextLine& line);
    Status readAxisRotation(const TextLine& line);
    Status readRotation(const TextLine& line);
    Status readLookAt(const TextLine& line);
    Status readClipPlane(const TextLine& line);
    Status readFlag(const TextLine& line);
    Status readTexture(const TextLine& line);
    Status readLight(const TextLine& line);
    Status readShininess(const TextLine& line);
    // `names` names the arguments in messages: "x y z"_msg.
    Result<Args> numbers(const TextLine& line, std::size_t count, const Message& names);
    Result<std::uint32_t> vertexIndex(const Token& token, const std::string& command);
    // Vertex indices from token `first` on; tokens after them are warned about as extra
    // values unless the command has more arguments (warnExtraValues false).
    Result<std::vector<std::uint32_t>> indices(const TextLine& line, std::size_t first,
                                               std::size_t count, const Message& names,
                                               bool warnExtraValues = true);
    Result<int> subdivisions(const TextLine& line);
    Status requireImage(const TextLine& line);
    void warnExtra(const TextLine& line, std::size_t used);

    Draw& drawFor(const DrawState& state);
    void addTriangle(const DrawState& state, const std::array<Vertex, 3>& corners,
                     const SourceLocation& where);
    void addPatch(const PatchMesh& patch, Fill fill, const SourceLocation& where);
    DrawState stateFor(Fill fill, bool hasNormals, bool flatFill) const;
    void finishImage();
    // Counts triangles against the file's limit before they are made.
    Status reserveTriangles(std::size_t count, const SourceLocation& where);

    std::string_view m_text;
    LineScanner m_scanner;
    const TextureLoader& m_loader;
    Diagnostics& m_diagnostics;
    const Hw2Misreading* m_misreading = nullptr;
    // Whether the command on this line is misread that way.
    bool misread(const TextLine& line, Hw2Misreading::Kind kind) const {
        if (!m_misreading || m_misreading->kind != kind) return false;
        return m_misreading->everywhere ? line.tokens[0].text == m_misreading->keyword
                                        : m_misreading->line == line.number;
    }
    // An angle in degrees, or misread as radians (the number used as radians is that many
    // times 180/pi degrees).
    double degreesRead(const TextLine& line, double degrees) const {
        return misread(line, Hw2Misreading::Kind::Radians) ? glm::degrees(degrees) : degrees;
    }
    // The model/view with a transform added: on the right, or misread on the left.
    void addToModelView(const TextLine& line, const dmat4& a) {
        m_modelView = misread(line, Hw2Misreading::Kind::OtherSide) ? a * m_modelView
                                                                      : m_modelView * a;
    }

    Hw2File m_file;
    std::optional<Hw2Image> m_image;
    std::vector<std::shared_ptr<Mesh>> m_meshes;  // the current image's, one per draw
    std::optional<DrawState> m_lastState;

    // The state commands change.
    std::vector<Vertex> m_vertices;
    vec3 m_colour = vec3(1.0f);
    std::optional<vec3> m_normal;
    vec2 m_texcoord = vec2(0.0f);
    dmat4 m_modelView = dmat4(1.0);
    dmat4 m_projection = dmat4(1.0);
    std::vector<dvec4> m_clipPlanes;
    bool m_cull = false;
    std::shared_ptr<const Texture> m_texture;
    float m_shininess = 0.0f;
    bool m_decals = false;       // anywhere in the file (seed 001)
    bool m_flatNormals = false;  // anywhere in the file (seed 001)

    std::map<std::string, std::pair<int, SourceLocation>> m_unknown;
    std::size_t m_triangleCount = 0;
};

Result<Hw2File> Hw2Reader::read() {
    // decals and flatnormals act on the whole file, wherever they appear.
    {
        LineScanner scan(m_text, m_scanner.fileName());
        TextLine line;
        while (scan.next(line)) {
            m_decals = m_decals || line.tokens[0].text == "decals";
            m_flatNormals = m_flatNormals || line.tokens[0].text == "flatnormals";
        }
    }
    TextLine line;
    while (m_scanner.next(line)) {
        auto status = command(line);
        if (!status) return status.error();
    }
    finishImage();
    for (const auto& [keyword, seen] : m_unknown)
        m_diagnostics.note(seen.second,
                           counted(seen.first, "skipped %1 line with the unknown command '%2'"_msg,
                                   "skipped %1 lines with the unknown command '%2'"_msg, keyword));
    if (m_file.images.empty())
        return makeError(ErrorCode::MissingData, m_scanner.endOfInput(),
                         "expected a 'png width height file' command, found none"_msg);
    return std::move(m_file);
}

void Hw2Reader::finishImage() {
    if (!m_image) return;
    for (std::size_t d = 0; d < m_meshes.size(); ++d) m_image->scene.draws[d].mesh = m_meshes[d];
    m_file.images.push_back(std::move(*m_image));
    m_image.reset();
    m_meshes.clear();
    m_lastState.reset();
}

Result<Hw2Reader::Args> Hw2Reader::numbers(const TextLine& line, std::size_t count,
                                           const Message& names) {
    const std::string keyword(line.tokens[0].text);
    Args values;
    for (std::size_t k = 0; k < count; ++k) {
        if (k + 1 >= line.tokens.size())
            return makeError(
                ErrorCode::Syntax, m_scanner.afterLast(line),
                counted(count, "expected %1 number after '%2' (%3), found %4"_msg,
                        "expected %1 numbers after '%2' (%3), found %4"_msg, keyword, names, k));
        const Token& token = line.tokens[k + 1];
        const auto value = parseReal(token.text);
        if (!value)
            return makeError(
                ErrorCode::Syntax, m_scanner.at(token),
                "expected a number in '%1' (%2), found %3"_msg(keyword, names, quoted(token.text)));
        values.push_back(*value);
    }
    warnExtra(line, count + 1);
    return values;
}

void Hw2Reader::warnExtra(const TextLine& line, std::size_t used) {
    if (line.tokens.size() > used)
        m_diagnostics.warn(m_scanner.at(line.tokens[used]),
                           counted(line.tokens.size() - used, "ignored %1 value after '%2'"_msg,
                                   "ignored %1 values after '%2'"_msg, line.tokens[0].text));
}

Result<std::uint32_t> Hw2Reader::vertexIndex(const Token& token, const std::string& command) {
    const auto index = parseInteger(token.text);
    if (!index)
        return makeError(
            ErrorCode::Syntax, m_scanner.at(token),
            "expected a vertex index in '%1', found %2"_msg(command, quoted(token.text)));
    const auto count = static_cast<long long>(m_vertices.size());
    // 1 is the first vertex defined, -1 the last one.
    const long long resolved = *index > 0 ? *index - 1 : count + *index;
    if (*index == 0)
        return makeError(ErrorCode::Range, m_scanner.at(token),
                         "'%1' refers to vertex %2, but indices start at 1 (or count back from -1, "
                         "the last)"_msg(command, token.text));
    if (resolved < 0 || resolved >= count)
        return makeError(
            ErrorCode::Range, m_scanner.at(token),
            counted(count, "'%2' refers to vertex %3, but only %1 vertex is defined so far"_msg,
                    "'%2' refers to vertex %3, but only %1 vertices are defined so "
                    "far"_msg,
                    command, token.text));
    return static_cast<std::uint32_t>(resolved);
}

Result<std::vector<std::uint32_t>> Hw2Reader::indices(const TextLine& line, std::size_t first,
                                                      std::size_t count, const Message& names,
                                                      bool warnExtraValues) {
    const std::string keyword(line.tokens[0].text);
    std::vector<std::uint32_t> out;
    for (std::size_t k = 0; k < count; ++k) {
        if (first + k >= line.tokens.size())
            return makeError(ErrorCode::Syntax, m_scanner.afterLast(line),
                             counted(count, "expected %1 vertex index in '%2' (%3), found %4"_msg,
                                     "expected %1 vertex indices in '%2' (%3), found %4"_msg,
                                     keyword, names, k));
        auto index = vertexIndex(line.tokens[first + k], keyword);
        if (!index) return index.error();
        out.push_back(index.value());
    }
    if (warnExtraValues) warnExtra(line, first + count);
    return out;
}

Result<int> Hw2Reader::subdivisions(const TextLine& line) {
    const std::string keyword(line.tokens[0].text);
    if (line.tokens.size() < 2)
        return makeError(
            ErrorCode::Syntax, m_scanner.afterLast(line),
            "expected the number of subdivisions after '%1', found the end of the line"_msg(
                keyword));
    const auto n = parseInteger(line.tokens[1].text);
    if (!n || *n < 1 || *n > 10)
        return makeError(ErrorCode::Range, m_scanner.at(line.tokens[1]),
                         "expected the number of subdivisions (a whole number from 1 to 10) after "
                         "'%1', found %2"_msg(keyword, quoted(line.tokens[1].text)));
    return static_cast<int>(*n);
}

Status Hw2Reader::requireImage(const TextLine& line) {
    if (m_image) return success();
    return makeError(
        ErrorCode::MissingData, m_scanner.at(line.tokens[0]),
        "expected a 'png width height file' command before '%1'"_msg(line.tokens[0].text));
}

DrawState Hw2Reader::stateFor(Fill fill, bool hasNormals, bool flatFill) const {
    DrawState s;
    s.modelView = m_modelView;
    s.projection = m_projection;
    s.clipPlanes = m_clipPlanes;
    s.cull = m_cull;
    s.lightCount = m_image ? m_image->scene.lights.size() : 0;
    s.shininess = s.lightCount > 0 ? m_shininess : 0.0f;
    s.fill = fill;
    // Lit triangles without normals, and flat ones under `flatnormals`, light with the
    // triangle's own normal.
    s.flatNormals = s.lightCount > 0 && (!hasNormals || (flatFill && m_flatNormals));
    if (fill == Fill::Textured) s.texture = m_texture;
    return s;
}

Draw& Hw2Reader::drawFor(const DrawState& state) {
    Scene& scene = m_image->scene;
    if (!m_lastState || !(*m_lastState == state)) {
        Draw draw;
        const std::string& path = m_scanner.fileName();
        draw.name = path.substr(path.find_last_of('/') + 1);  // the command file's name
        draw.worldFromModel = state.modelView;
        draw.clipFromView = state.projection;
        draw.clipPlanes = state.clipPlanes;
        draw.cull = state.cull;
        draw.lightCount = state.lightCount;
        draw.lighting = state.lightCount > 0 ? LightingModel::Lambert : LightingModel::Unlit;
        draw.material.shininess = state.shininess;
        draw.material.od = vec3(1.0f);
        draw.shading = ShadingModel::Phong;  // per-fragment lighting and interpolation
        draw.flatNormals = state.flatNormals;
        draw.colour = state.fill == Fill::Textured ? ColourSource::Texture : ColourSource::Vertex;
        draw.texture = state.texture;
        draw.decals = state.fill == Fill::Textured && m_decals;
        scene.draws.push_back(std::move(draw));
        auto mesh = std::make_shared<Mesh>();
        mesh->source = SourceLocation{m_scanner.fileName(), 0, 0};
        m_meshes.push_back(std::move(mesh));
        m_lastState = state;
    }
    return scene.draws.back();
}

Status Hw2Reader::reserveTriangles(std::size_t count, const SourceLocation& where) {
    if (m_triangleCount + count > kMaxTriangles)
        return makeError(
            ErrorCode::Range, where,
            "this command would bring the file to %1 triangles, more than the limit "
            "of %2 a command file may draw"_msg(m_triangleCount + count, kMaxTriangles));
    m_triangleCount += count;
    return success();
}

void Hw2Reader::addTriangle(const DrawState& state, const std::array<Vertex, 3>& corners,
                            const SourceLocation& where) {
    drawFor(state);
    Mesh& mesh = *m_meshes.back();
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (const Vertex& v : corners) {
        mesh.positions.push_back(v.p);
        mesh.colours.push_back(state.fill == Fill::Flat ? m_colour : v.colour);
        mesh.texcoords.push_back(v.st);
        mesh.normals.push_back(v.normal.value_or(vec3(0.0f)));
    }
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangleLines.push_back(where.line);
}

void Hw2Reader::addPatch(const PatchMesh& patch, Fill fill, const SourceLocation& where) {
    const DrawState state = stateFor(fill, true, fill == Fill::Flat);
    drawFor(state);
    Mesh& mesh = *m_meshes.back();
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (const PatchVertex& v : patch.vertices) {
        mesh.positions.push_back(v.p);
        mesh.colours.push_back(fill == Fill::Flat ? m_colour : v.colour);
        mesh.texcoords.push_back(v.st);
        mesh.normals.push_back(v.normal);  // Bezier normals: those of the interpolated shape
    }
    for (const auto& t : patch.triangles) {
        mesh.triangles.push_back({base + t[0], base + t[1], base + t[2]});
        mesh.triangleLines.push_back(where.line);
    }
}

Status Hw2Reader::command(const TextLine& line) {
    const std::string keyword(line.tokens[0].text);
    const SourceLocation where = m_scanner.at(line.tokens[0]);
    if (!isKnown(keyword)) {
        auto& seen = m_unknown[keyword];
        if (seen.first++ == 0) seen.second = where;
        return success();
    }
    if (misread(line, Hw2Misreading::Kind::Ignored)) return success();
    if (keyword == "png") return readImage(line);
    if (keyword == "xyz" || keyword == "xyzw") return readVertex(line);
    if (keyword == "color") return readColour(line);
    if (keyword == "normal") return readNormal(line);
    if (keyword == "texcoord") return readTexcoord(line);
    if (keyword == "trif" || keyword == "trig" || keyword == "trit") return readTriangle(line);
    if (keyword == "rectbezf" || keyword == "rectbezg" || keyword == "tribezf" ||
        keyword == "tribezg")
        return readPatch(line);
    if (keyword == "loadmv" || keyword == "loadp" || keyword == "multmv") return readMatrix(line);
    if (keyword == "frustum" || keyword == "ortho") return readProjection(line);
    if (keyword == "translate" || keyword == "scale") return readTranslateOrScale(line);
    if (keyword == "rotatex" || keyword == "rotatey" || keyword == "rotatez")
        return readAxisRotation(line);
    if (keyword == "rotate") return readRotation(line);
    if (keyword == "lookat") return readLookAt(line);
    if (keyword == "clipplane") return readClipPlane(line);
    if (keyword == "cull" || keyword == "decals" || keyword == "flatnormals") return readFlag(line);
    if (keyword == "texture") return readTexture(line);
    if (keyword == "sunlight" || keyword == "bulb") return readLight(line);
    if (keyword == "shininess") return readShininess(line);
    return success();
}

// png width height file: a new image, its scene in seed 001's conventions and rules.
Status Hw2Reader::readImage(const TextLine& line) {
    const SourceLocation where = m_scanner.at(line.tokens[0]);
    if (line.tokens.size() < 4)
        return makeError(ErrorCode::Syntax, m_scanner.afterLast(line),
                         "expected 'png width height file', found %1"_msg(
                             argumentsText(line.tokens.size() - 1)));
    long long size[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
        const Token& token = line.tokens[std::size_t(k + 1)];
        const auto n = parseInteger(token.text);
        if (!n || *n < 1 || *n > 65536)
            return makeError(
                ErrorCode::Syntax, m_scanner.at(token),
                (k == 0
                     ? "expected the image width (a whole number from 1 to 65536), found %1"_msg
                     : "expected the image height (a whole number from 1 to 65536), found %1"_msg)(
                    quoted(token.text)));
        size[k] = *n;
    }
    warnExtra(line, 4);
    finishImage();
    Hw2Image image;
    // The image is written beside the others: a name that reaches into folders keeps
    // only its last part, so a command file cannot write outside the output folder.
    const std::string asWritten(line.tokens[3].text);
    const std::size_t slash = asWritten.find_last_of("/\\");
    image.fileName = slash == std::string::npos ? asWritten : asWritten.substr(slash + 1);
    if (image.fileName.empty() || image.fileName == "." || image.fileName == "..")
        return makeError(ErrorCode::Syntax, m_scanner.at(line.tokens[3]),
                         "expected an image file name after 'png width height', found %1"_msg(
                             quoted(asWritten)));
    if (image.fileName != asWritten)
        m_diagnostics.warn(m_scanner.at(line.tokens[3]),
                           "the image name %1 reaches into folders: it is written as %2 in the "
                           "output folder"_msg(quoted(asWritten), quoted(image.fileName)));
    for (const Hw2Image& earlier : m_file.images)
        if (earlier.fileName == image.fileName)
            m_diagnostics.warn(m_scanner.at(line.tokens[3]),
                               "an earlier png command (line %1) names %2 too: this image "
                               "replaces it"_msg(earlier.where.line, quoted(image.fileName)));
    image.where = where;
    image.scene.name = image.fileName;
    image.scene.width = static_cast<int>(size[0]);
    image.scene.height = static_cast<int>(size[1]);
    image.scene.conventions = Conventions::hw2();
    image.scene.rules = RasterRules::hw2();
    // Seed 001: "Frustum clipping happens here in OpenGL, but we won't add it": every
    // vertex is divided by its w, the per-pixel depth test in [0, 1] does the rest.
    image.scene.nearPlane.mode = NearPlane::Mode::Naive;
    m_image = std::move(image);
    return success();
}

// xyz x y z, xyzw x y z w: a vertex with the current colour, normal and texture coordinate.
Status Hw2Reader::readVertex(const TextLine& line) {
    const std::string keyword(line.tokens[0].text);
    const bool w = keyword == "xyzw";
    auto v = numbers(line, w ? 4 : 3, w ? "x y z w"_msg : "x y z"_msg);
    if (!v) return v.error();
    Vertex vertex;
    vertex.p = dvec4(v->at(0), v->at(1), v->at(2), w ? v->at(3) : 1.0);
    vertex.colour = m_colour;
    vertex.st = m_texcoord;
    vertex.normal = m_normal;
    m_vertices.push_back(vertex);
    return success();
}

// color r g b: the current colour.
Status Hw2Reader::readColour(const TextLine& line) {
    auto v = numbers(line, 3, "r g b"_msg);
    if (!v) return v.error();
    m_colour = vec3(float(v->at(0)), float(v->at(1)), float(v->at(2)));
    return success();
}

// normal x y z: the current normal.
Status Hw2Reader::readNormal(const TextLine& line) {
    auto v = numbers(line, 3, "x y z"_msg);
    if (!v) return v.error();
    m_normal = vec3(float(v->at(0)), float(v->at(1)), float(v->at(2)));
    return success();
}

// texcoord s t: the current texture coordinate.
Status Hw2Reader::readTexcoord(const TextLine& line) {
    auto v = numbers(line, 2, "s t"_msg);
    if (!v) return v.error();
    m_texcoord = vec2(float(v->at(0)), float(v->at(1)));
    return success();
}

// trif, trig, trit i1 i2 i3: a triangle, flat, with vertex colours, or textured.
Status Hw2Reader::readTriangle(const TextLine& line) {
    const std::string keyword(line.tokens[0].text);
    const SourceLocation where = m_scanner.at(line.tokens[0]);
    if (auto s = requireImage(line); !s) return s;
    auto idx = indices(line, 1, 3, "i1 i2 i3"_msg);
    if (!idx) return idx.error();
    const Fill fill = keyword == "trif"   ? Fill::Flat
                      : keyword == "trig" ? Fill::Gouraud
                                          : Fill::Textured;
    if (fill == Fill::Textured && !m_texture)
        return makeError(
            ErrorCode::MissingData, where,
            "'trit' needs a texture: expected a 'texture file.png' command before it"_msg);
    const std::array<Vertex, 3> corners = {m_vertices[idx->at(0)], m_vertices[idx->at(1)],
                                           m_vertices[idx->at(2)]};
    const bool hasNormals = corners[0].normal && corners[1].normal && corners[2].normal;
    if (auto s = reserveTriangles(1, where); !s) return s;
    addTriangle(stateFor(fill, hasNormals, fill == Fill::Flat), corners, where);
    return success();
}

// rectbezf, rectbezg subd i1 ... i16 and tribezf, tribezg subd i1 ... i10: a Bezier patch.
Status Hw2Reader::readPatch(const TextLine& line) {
    const std::string keyword(line.tokens[0].text);
    const SourceLocation where = m_scanner.at(line.tokens[0]);
    if (auto s = requireImage(line); !s) return s;
    auto subd = subdivisions(line);
    if (!subd) return subd.error();
    const bool rect = keyword.starts_with("rect");
    const std::size_t count = rect ? 16 : 10;
    auto idx = indices(line, 2, count, rect ? "subd i1 ... i16"_msg : "subd i1 ... i10"_msg);
    if (!idx) return idx.error();
    const auto point = [&](std::uint32_t i) {
        const Vertex& v = m_vertices[i];
        return PatchPoint{v.p, v.colour, v.st};
    };
    const std::size_t cells = std::size_t(1) << (2 * subd.value());  // 4^subd
    if (auto s = reserveTriangles(rect ? 2 * cells : cells, where); !s) return s;
    PatchMesh patch;
    if (rect) {
        std::array<PatchPoint, 16> control;
        for (std::size_t k = 0; k < 16; ++k) control[k] = point(idx->at(k));
        patch = subdivideRectBezier(control, subd.value());
    } else {
        std::array<PatchPoint, 10> control;
        for (std::size_t k = 0; k < 10; ++k) control[k] = point(idx->at(k));
        patch = subdivideTriBezier(control, subd.value());
    }
    addPatch(patch, keyword.ends_with('f') ? Fill::Flat : Fill::Gouraud, where);
    return success();
}

// loadmv, multmv, loadp a11 ... a44: a model/view or projection matrix, row by row.
Status Hw2Reader::readMatrix(const TextLine& line) {
    const std::string keyword(line.tokens[0].text);
    auto v = numbers(line, 16, "a11 a12 ... a44, row by row"_msg);
    if (!v) return v.error();
    double rows[16];
    std::copy(v->begin(), v->end(), rows);
    dmat4 m = matrixFromRows(rows);
    if (misread(line, Hw2Misreading::Kind::Transposed)) m = glm::transpose(m);
    if (keyword == "loadmv")
        m_modelView = m;
    else if (keyword == "multmv")
        addToModelView(line, m);
    else
        m_projection = m;
    return success();
}

// frustum, ortho l r b t n f: the projection.
Status Hw2Reader::readProjection(const TextLine& line) {
    const std::string keyword(line.tokens[0].text);
    const SourceLocation where = m_scanner.at(line.tokens[0]);
    auto v = numbers(line, 6, "l r b t n f"_msg);
    if (!v) return v.error();
    const Args& a = v.value();
    if (a[0] == a[1] || a[2] == a[3] || a[4] == a[5])
        return makeError(ErrorCode::Degenerate, where,
                         "'%1' needs l != r, b != t and n != f, found %2 %3 %4 %5 %6 %7"_msg(
                             keyword, formatNumber(a[0]), formatNumber(a[1]), formatNumber(a[2]),
                             formatNumber(a[3]), formatNumber(a[4]), formatNumber(a[5])));
    m_projection = keyword == "frustum" ? frustumMatrix(a[0], a[1], a[2], a[3], a[4], a[5])
                                        : orthoMatrix(a[0], a[1], a[2], a[3], a[4], a[5]);
    return success();
}

// translate dx dy dz, scale sx sy sz: added to the model/view.
Status Hw2Reader::readTranslateOrScale(const TextLine& line) {
    const std::string keyword(line.tokens[0].text);
    auto v = numbers(line, 3, keyword == "translate" ? "dx dy dz"_msg : "sx sy sz"_msg);
    if (!v) return v.error();
    const dvec3 d(v->at(0), v->at(1), v->at(2));
    addToModelView(line, keyword == "translate" ? translationMatrix(d) : scaleMatrix(d));
    return success();
}

// rotatex, rotatey, rotatez degrees: added to the model/view.
Status Hw2Reader::readAxisRotation(const TextLine& line) {
    const std::string keyword(line.tokens[0].text);
    auto v = numbers(line, 1, "degrees"_msg);
    if (!v) return v.error();
    const dvec3 axis = keyword == "rotatex"   ? dvec3(1, 0, 0)
                       : keyword == "rotatey" ? dvec3(0, 1, 0)
                                              : dvec3(0, 0, 1);
    addToModelView(line, rotationMatrix(degreesRead(line, v->at(0)), axis));
    return success();
}

// rotate degrees x y z: added to the model/view.
Status Hw2Reader::readRotation(const TextLine& line) {
    auto v = numbers(line, 4, "degrees x y z"_msg);
    if (!v) return v.error();
    const dvec3 axis(v->at(1), v->at(2), v->at(3));
    if (axis == dvec3(0.0))
        return makeError(ErrorCode::Degenerate, m_scanner.at(line.tokens[2]),
                         "'rotate' needs an axis, found the zero vector"_msg);
    addToModelView(line, rotationMatrix(degreesRead(line, v->at(0)), axis));
    return success();
}

// lookat eye center upx upy upz: replaces the model/view.
Status Hw2Reader::readLookAt(const TextLine& line) {
    const SourceLocation where = m_scanner.at(line.tokens[0]);
    // Two indices, then the up vector: only values after the up vector are extra.
    auto idx = indices(line, 1, 2, "eye center upx upy upz"_msg, false);
    if (!idx) return idx.error();
    if (line.tokens.size() < 6)
        return makeError(ErrorCode::Syntax, m_scanner.afterLast(line),
                         "expected 'lookat eye center upx upy upz', found %1"_msg(
                             argumentsText(line.tokens.size() - 1)));
    dvec3 up(0.0);
    for (int k = 0; k < 3; ++k) {
        const Token& token = line.tokens[std::size_t(3 + k)];
        const auto value = parseReal(token.text);
        if (!value)
            return makeError(ErrorCode::Syntax, m_scanner.at(token),
                             "expected a number in 'lookat' (eye center upx upy upz), found %1"_msg(
                                 quoted(token.text)));
        up[k] = *value;
    }
    warnExtra(line, 6);
    const auto position = [&](std::uint32_t i) {
        const dvec4& p = m_vertices[i].p;
        return p.w != 0.0 ? dvec3(p) / p.w : dvec3(p);
    };
    const dvec3 eye = position(idx->at(0)), center = position(idx->at(1));
    if (eye == center || glm::length(glm::cross(center - eye, up)) == 0.0)
        return makeError(ErrorCode::Degenerate, where,
                         "'lookat' needs an eye apart from the center and an up that is "
                         "not along the line of sight"_msg);
    m_modelView = misread(line, Hw2Misreading::Kind::UnnormalisedSide)
                      ? lookAtWithUnnormalisedSide(eye, center, up)
                      : lookAtMatrix(eye, center, up);
    return success();
}

// clipplane p1 p2 p3 p4: a plane of eye coordinates for the draws that follow.
Status Hw2Reader::readClipPlane(const TextLine& line) {
    auto v = numbers(line, 4, "p1 p2 p3 p4"_msg);
    if (!v) return v.error();
    // A plane of eye coordinates, kept as given (seed 001 applies it after the
    // model/view; the reference images do not carry it through the model/view).
    const dvec4 plane(v->at(0), v->at(1), v->at(2), v->at(3));
    m_clipPlanes.push_back(plane);
    return success();
}

// cull, decals, flatnormals (the last two act on the whole file, read ahead).
Status Hw2Reader::readFlag(const TextLine& line) {
    const std::string keyword(line.tokens[0].text);
    warnExtra(line, 1);
    if (keyword == "cull") m_cull = true;
    return success();
}

// texture file.png: the texture of the textured triangles that follow.
Status Hw2Reader::readTexture(const TextLine& line) {
    if (line.tokens.size() < 2)
        return makeError(ErrorCode::Syntax, m_scanner.afterLast(line),
                         "expected a file name after 'texture', found the end of the line"_msg);
    warnExtra(line, 2);
    auto texture = m_loader(std::string(line.tokens[1].text), m_scanner.at(line.tokens[1]));
    if (!texture) return texture.error();
    m_texture = texture.value();
    return success();
}

// sunlight lx ly lz, bulb i: a light of the current colour.
Status Hw2Reader::readLight(const TextLine& line) {
    const std::string keyword(line.tokens[0].text);
    const SourceLocation where = m_scanner.at(line.tokens[0]);
    if (auto s = requireImage(line); !s) return s;
    Light light;
    light.intensity = m_colour;
    light.where = where;
    if (keyword == "sunlight") {
        auto v = numbers(line, 3, "lx ly lz"_msg);
        if (!v) return v.error();
        const dvec3 direction(v->at(0), v->at(1), v->at(2));
        if (direction == dvec3(0.0))
            return makeError(ErrorCode::Degenerate, m_scanner.at(line.tokens[1]),
                             "'sunlight' needs a direction, found the zero vector"_msg);
        // A direction, carried to eye coordinates like a normal, then made unit length.
        light.pWorld = dvec4(glm::normalize(normalMatrix(m_modelView) * direction), 0.0);
    } else {
        auto idx = indices(line, 1, 1, "i1"_msg);
        if (!idx) return idx.error();
        const dvec4 p = m_modelView * m_vertices[idx->at(0)].p;
        light.pWorld = dvec4(p.w != 0.0 ? dvec3(p) / p.w : dvec3(p), 1.0);
    }
    m_image->scene.lights.push_back(light);
    return success();
}

// shininess alpha: the Blinn-Phong exponent of the lit draws that follow.
Status Hw2Reader::readShininess(const TextLine& line) {
    auto v = numbers(line, 1, "alpha"_msg);
    if (!v) return v.error();
    m_shininess = static_cast<float>(v->at(0));
    return success();
}
}  // namespace

Result<Hw2File> readHw2(std::string_view text, const std::string& fileName,
                        const TextureLoader& loadTexture, Diagnostics& diagnostics,
                        const Hw2Misreading* misreading) {
    Hw2Reader reader(text, fileName, loadTexture, diagnostics, misreading);
    return reader.read();
}

std::vector<Hw2Misreading> possibleMisreadings(std::string_view text) {
    using Kind = Hw2Misreading::Kind;
    std::vector<Hw2Misreading> out;
    LineScanner scanner(text, "");
    TextLine line;
    while (scanner.next(line)) {
        const std::string keyword(line.tokens[0].text);
        const auto add = [&](Kind kind) { out.push_back({line.number, kind, keyword}); };
        const bool transform = keyword == "translate" || keyword == "scale" ||
                               keyword == "rotate" || keyword.starts_with("rotate") ||
                               keyword == "multmv";
        const bool matrix = keyword == "loadmv" || keyword == "multmv" || keyword == "loadp";
        if (!transform && !matrix && keyword != "lookat" && keyword != "frustum" &&
            keyword != "ortho")
            continue;
        add(Kind::Ignored);
        if (transform) add(Kind::OtherSide);
        if (matrix) add(Kind::Transposed);
        if (keyword.starts_with("rotate")) add(Kind::Radians);
        if (keyword == "lookat") add(Kind::UnnormalisedSide);
    }
    // The same, command by command, for every occurrence at once.
    std::map<std::pair<std::string, Kind>, Hw2Misreading> every;
    for (const Hw2Misreading& m : out) {
        auto [it, fresh] = every.try_emplace({m.keyword, m.kind}, m);
        if (!fresh) ++it->second.count;
    }
    for (auto& [key, m] : every)
        if (m.count > 1) {
            m.everywhere = true;
            out.push_back(m);
        }
    return out;
}

bool looksLikeHw2(std::string_view text) {
    LineScanner scanner(text, "");
    TextLine line;
    while (scanner.next(line)) {
        const std::string_view first = line.tokens[0].text;
        if (isKnown(first)) return true;
        if (parseReal(first)) return false;  // a course file starts with numbers
    }
    return false;
}

}  // namespace rl
