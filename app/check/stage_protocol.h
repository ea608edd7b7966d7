// The stage protocol (docs/stage-protocol.md), version 1: the stages' names, a request as
// the lines RasterLab writes, and an answer read back from a student's program, checked
// record by record so that a bad answer gets "answer line N, column C: what was expected".
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/core/diagnostics.h"

namespace rasterlab::check {

inline constexpr int kProtocolVersion = 1;

enum class Stage { Basis, View, Normals, Projection, Scan, ZBuffer, Lighting, Frame };
inline constexpr std::array<Stage, 8> kStages = {Stage::Basis,      Stage::View, Stage::Normals,
                                                 Stage::Projection, Stage::Scan, Stage::ZBuffer,
                                                 Stage::Lighting,   Stage::Frame};

// The request's first line: "basis", "view", ... "frame".
std::string_view stageName(Stage stage);
std::optional<Stage> stageNamed(std::string_view name);

// One record: a name and its numbers; a list's record also holds its rows.
struct Record {
    std::string name;
    std::vector<double> numbers;
    std::vector<std::vector<double>> rows;
    int line = 0;  // in the answer, 1-based (the record's own line)
};

// A request, written as the protocol's lines.
class Request {
public:
    explicit Request(Stage stage) : m_stage(stage) {}
    Stage stage() const { return m_stage; }
    void add(std::string_view name, std::initializer_list<double> numbers);
    void add(std::string_view name, const std::vector<double>& numbers);
    // A list: "name count" (and the extra numbers after the count), then the rows.
    void addList(std::string_view name, const std::vector<std::vector<double>>& rows);
    // The request's text: the stage's line, the records, "end", each ending with '\n'.
    std::string text() const;

private:
    Stage m_stage;
    std::string m_body;
};

// The shape of an answer's record: a name followed by `numbers` numbers; a list has a count
// first, then that many rows of `rowWidth` numbers (the image's rows: 3 times its width).
struct RecordShape {
    std::string_view name;
    int numbers = 0;
    bool list = false;
    int rowWidth = 0;  // for a list; 0 for the image's 3 x width
};
const std::vector<RecordShape>& answerShape(Stage stage);

// A number as the protocol writes it: the shortest text that reads back to the same double.
std::string protocolNumber(double value);

// The answer's lines (without "end"), checked against the stage's shape. Errors name the
// answer's line and column (counted from the stage's first answer line) and what was
// expected; `where` is the pseudo-file of the messages ("their answer to basis").
rl::Result<std::vector<Record>> parseAnswer(Stage stage, const std::vector<std::string>& lines,
                                            const std::string& where);

}  // namespace rasterlab::check
