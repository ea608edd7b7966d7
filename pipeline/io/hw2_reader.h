// The command language of seed 001 ("HW2: 3D Rasterizer"): one command per line, a keyword
// and its arguments. The reader keeps the state the commands change (the current colour,
// normal and texture coordinate, the model/view and projection matrices, clip planes,
// cull, the texture, the lights, the shininess) and turns each drawing command into
// triangles of a draw, so that a command file becomes a Scene for the same seven stages
// as the course files. Blank lines and unknown keywords are skipped (a note lists the
// unknown ones); a known command with missing or malformed arguments is an error with
// file:line:col.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/core/diagnostics.h"
#include "pipeline/scene/scene.h"

namespace rl {

// One image a command file asks for: its `png` line, and the scene drawn into it.
struct Hw2Image {
    std::string fileName;  // as written in the png command
    SourceLocation where;  // the png command
    Scene scene;
};

struct Hw2File {
    std::vector<Hw2Image> images;
};

// Loads the image a `texture` command names (relative to the command file's folder);
// supplied by the caller, since the pipeline reads no image formats itself.
using TextureLoader = std::function<Result<std::shared_ptr<const Texture>>(
    const std::string& name, const SourceLocation& where)>;

// One command read the way a student's program may get it wrong, for compare's search for
// the command behind their image: the command on `line` ignored; its matrix multiplied on
// the other side (M = A M instead of M A); its sixteen numbers taken column by column; its
// angle taken as radians; or lookat's side vector s = f x up left unnormalised.
// With `everywhere`, every occurrence of the command is read that way (a command never
// implemented is ignored wherever it stands); `line` is then its first line, `count` how many
// there are.
struct Hw2Misreading {
    enum class Kind : std::uint8_t { Ignored, OtherSide, Transposed, Radians, UnnormalisedSide };
    int line = 0;
    Kind kind = Kind::Ignored;
    std::string keyword;  // the command on that line
    bool everywhere = false;
    int count = 1;
};

// Reads the text; with a misreading, that one command as it says.
Result<Hw2File> readHw2(std::string_view text, const std::string& fileName,
                        const TextureLoader& loadTexture, Diagnostics& diagnostics,
                        const Hw2Misreading* misreading = nullptr);

// Every misreading that changes a matrix command of the text, in line order; then, for each
// such command that stands more than once, the same misreadings of all its occurrences.
std::vector<Hw2Misreading> possibleMisreadings(std::string_view text);

// Whether a text looks like a command file: its first command line starts with a known
// keyword (png, xyz, ...). Used to tell command files from course files.
bool looksLikeHw2(std::string_view text);

}  // namespace rl
