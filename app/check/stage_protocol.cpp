#include "app/check/stage_protocol.h"

#include <charconv>
#include <cmath>

namespace rasterlab::check {

namespace {

constexpr int kWidest = 1 << 20;  // pixels of a frame's row, far beyond any screen

constexpr std::array<std::string_view, 8> kNames = {"basis", "view",    "normals",  "projection",
                                                    "scan",  "zbuffer", "lighting", "frame"};

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

// The fields of a line with their 1-based columns.
struct Field {
    std::string_view text;
    int column = 0;
};

std::vector<Field> fieldsOf(std::string_view line) {
    std::vector<Field> fields;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isSpace(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !isSpace(line[i])) ++i;
        if (i > start) fields.push_back({line.substr(start, i - start), int(start) + 1});
    }
    return fields;
}

std::optional<double> parseNumber(std::string_view text) {
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    double value = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

// What a student should read for a field that is not a number: the text itself, cut short.
std::string shown(std::string_view text) {
    std::string s(text.substr(0, 24));
    if (text.size() > 24) s += "...";
    return "'" + s + "'";
}

class AnswerReader {
public:
    AnswerReader(const std::vector<std::string>& lines, const std::string& where)
        : m_lines(lines), m_where(where) {}

    std::optional<rl::Error> read(const RecordShape& shape, Record& record) {
        if (m_next >= m_lines.size())
            return error(int(m_lines.size()) + 1, 1,
                         "expected '" + std::string(shape.name) + "', the answer ended ('end')");
        const int line = int(m_next) + 1;
        const std::vector<Field> fields = fieldsOf(m_lines[m_next++]);
        if (fields.empty() || fields[0].text != shape.name)
            return error(
                line, fields.empty() ? 1 : fields[0].column,
                "expected '" + std::string(shape.name) + "', found " +
                    (fields.empty() ? std::string("an empty line") : shown(fields[0].text)));
        record.name = std::string(shape.name);
        record.line = line;
        const int wanted = shape.numbers;
        if (auto e = numbers(fields, 1, wanted, line, record.numbers,
                             "after '" + std::string(shape.name) + "'"))
            return e;
        if (!shape.list) return std::nullopt;
        return rows(shape, fields, line, record);
    }

    std::optional<rl::Error> extraLines() const {
        if (m_next >= m_lines.size()) return std::nullopt;
        const std::vector<Field> fields = fieldsOf(m_lines[m_next]);
        return error(int(m_next) + 1, fields.empty() ? 1 : fields[0].column,
                     "expected 'end', found " +
                         (fields.empty() ? std::string("an empty line") : shown(fields[0].text)));
    }

private:
    rl::Error error(int line, int column, const std::string& message) const {
        return rl::makeError(rl::ErrorCode::Syntax, rl::SourceLocation{m_where, line, column},
                             message);
    }

    std::optional<rl::Error> numbers(const std::vector<Field>& fields, std::size_t first,
                                     int wanted, int line, std::vector<double>& out,
                                     const std::string& context) const {
        const int found = int(fields.size() - first);
        if (found != wanted) {
            const int column = found > wanted ? fields[first + wanted].column
                               : fields.empty()
                                   ? 1
                                   : fields.back().column + int(fields.back().text.size());
            return error(line, column,
                         "expected " + std::to_string(wanted) +
                             (wanted == 1 ? " number " : " numbers ") + context + ", found " +
                             std::to_string(found));
        }
        out.reserve(out.size() + std::size_t(wanted));
        for (std::size_t i = first; i < fields.size(); ++i) {
            const std::optional<double> v = parseNumber(fields[i].text);
            if (!v)
                return error(line, fields[i].column,
                             "expected a finite number ('.' as the decimal point), found " +
                                 shown(fields[i].text));
            out.push_back(*v);
        }
        return std::nullopt;
    }

    std::optional<rl::Error> rows(const RecordShape& shape, const std::vector<Field>& fields,
                                  int line, Record& record) {
        // The image's header is "image width height"; every other list's is "name count".
        const bool image = shape.rowWidth == 0;
        const double count = image ? record.numbers[1] : record.numbers[0];
        const double width = image ? 3.0 * record.numbers[0] : double(shape.rowWidth);
        const std::size_t left = m_lines.size() - m_next;
        if (image && !(width >= 0 && width == std::floor(width) && width <= 3.0 * kWidest))
            return error(line, fields[1].column,
                         "expected a whole width from 0 to " + std::to_string(kWidest) +
                             " pixels after 'image'");
        if (count < 0 || count != std::floor(count) ||
            (image && (width < 0 || width != std::floor(width))))
            return error(line, fields[1].column,
                         std::string("expected a whole number of rows, not negative, after '") +
                             std::string(shape.name) + "'");
        if (count > double(left))
            return error(line, fields[1].column,
                         "expected " + protocolNumber(count) + " rows after '" +
                             std::string(shape.name) + "', the answer has " + std::to_string(left) +
                             " lines before 'end'");
        record.rows.resize(std::size_t(count));
        for (std::vector<double>& row : record.rows) {
            const int rowLine = int(m_next) + 1;
            const std::vector<Field> rowFields = fieldsOf(m_lines[m_next++]);
            if (auto e = numbers(rowFields, 0, int(width), rowLine, row,
                                 "in a row of '" + std::string(shape.name) + "'"))
                return e;
        }
        return std::nullopt;
    }

    const std::vector<std::string>& m_lines;
    const std::string& m_where;
    std::size_t m_next = 0;
};

}  // namespace

std::string_view stageName(Stage stage) {
    return kNames[std::size_t(stage)];
}

std::optional<Stage> stageNamed(std::string_view name) {
    for (Stage s : kStages)
        if (stageName(s) == name) return s;
    return std::nullopt;
}

std::string protocolNumber(double value) {
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return ec == std::errc() ? std::string(buffer, end) : std::string("0");
}

void Request::add(std::string_view name, std::initializer_list<double> numbers) {
    add(name, std::vector<double>(numbers));
}

void Request::add(std::string_view name, const std::vector<double>& numbers) {
    m_body += name;
    for (double v : numbers) m_body += ' ' + protocolNumber(v);
    m_body += '\n';
}

void Request::addList(std::string_view name, const std::vector<std::vector<double>>& rows) {
    m_body += std::string(name) + ' ' + std::to_string(rows.size()) + '\n';
    for (const std::vector<double>& row : rows) {
        for (std::size_t i = 0; i < row.size(); ++i) {
            if (i) m_body += ' ';
            m_body += protocolNumber(row[i]);
        }
        m_body += '\n';
    }
}

std::string Request::text() const {
    return std::string(stageName(m_stage)) + '\n' + m_body + "end\n";
}

const std::vector<RecordShape>& answerShape(Stage stage) {
    static const std::array<std::vector<RecordShape>, 8> shapes = {{
        {{"U", 3}, {"V", 3}, {"N", 3}},
        {{"light", 3}, {"vertices", 1, true, 3}},
        {{"triangle-normals", 1, true, 3}, {"vertex-normals", 1, true, 3}},
        {{"screen", 1, true, 2}},
        {{"spans", 1, true, 4}},
        {{"pixels", 1, true, 4}},
        {{"colours", 1, true, 3}},
        {{"image", 2, true, 0}},
    }};
    return shapes[std::size_t(stage)];
}

rl::Result<std::vector<Record>> parseAnswer(Stage stage, const std::vector<std::string>& lines,
                                            const std::string& where) {
    AnswerReader reader(lines, where);
    std::vector<Record> records;
    for (const RecordShape& shape : answerShape(stage)) {
        Record record;
        if (auto e = reader.read(shape, record)) return *e;
        records.push_back(std::move(record));
    }
    if (auto e = reader.extraLines()) return *e;
    return records;
}

}  // namespace rasterlab::check
