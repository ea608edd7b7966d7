#include "text_scanner.h"

#include <charconv>
#include <cmath>

namespace rl {

namespace {

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

}  // namespace

LineScanner::LineScanner(std::string_view text, std::string fileName)
    : m_text(text), m_fileName(std::move(fileName)) {
    if (m_text.substr(0, 3) == "\xEF\xBB\xBF") m_pos = 3;  // UTF-8 byte-order mark
}

bool LineScanner::next(TextLine& line) {
    while (m_pos < m_text.size()) {
        const std::size_t lineStart = m_pos;
        const int lineNumber = m_line;
        std::size_t end = m_text.find('\n', m_pos);
        if (end == std::string_view::npos) end = m_text.size();
        m_pos = end < m_text.size() ? end + 1 : end;
        ++m_line;

        line.number = lineNumber;
        line.tokens.clear();
        std::size_t i = lineStart;
        while (i < end) {
            while (i < end && isSpace(m_text[i])) ++i;
            if (i >= end) break;
            const std::size_t tokenStart = i;
            while (i < end && !isSpace(m_text[i])) ++i;
            line.tokens.push_back({m_text.substr(tokenStart, i - tokenStart), lineNumber,
                                   static_cast<int>(tokenStart - lineStart) + 1});
        }
        if (!line.tokens.empty()) {
            const Token& last = line.tokens.back();
            line.endColumn = last.column + static_cast<int>(last.text.size());
            m_lastLineStart = lineStart;
            m_lastLineNumber = lineNumber;
            return true;
        }
    }
    return false;
}

void LineScanner::unread() {
    m_pos = m_lastLineStart;
    m_line = m_lastLineNumber;
}

int LineScanner::countRemainingLines() const {
    LineScanner copy = *this;
    TextLine line;
    int n = 0;
    while (copy.next(line)) ++n;
    return n;
}

SourceLocation LineScanner::endOfInput() const {
    // Line and column of the position just past the last byte.
    // Columns on line 1 start after a byte-order mark, as the tokens' columns do.
    int line = 1;
    std::size_t lineStart = m_text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
    for (std::size_t i = lineStart; i < m_text.size(); ++i) {
        if (m_text[i] == '\n') {
            ++line;
            lineStart = i + 1;
        }
    }
    std::size_t column = m_text.size() - lineStart;
    // A trailing CR belongs to the line ending, not to the line.
    if (column > 0 && m_text.back() == '\r') --column;
    return {m_fileName, line, static_cast<int>(column) + 1};
}

std::optional<double> parseReal(std::string_view text) {
    if (!text.empty() && text.front() == '+') {
        text.remove_prefix(1);
        if (!text.empty() && text.front() == '-') return std::nullopt;  // "+-2"
    }
    if (text.empty()) return std::nullopt;
    // from_chars would accept "inf" and "nan": only digits, a sign, '.', and an exponent
    // may start a number here.
    const char c = text.front();
    if (!(c == '-' || c == '.' || (c >= '0' && c <= '9'))) return std::nullopt;
    double value = 0.0;
    const auto [end, ec] =
        std::from_chars(text.data(), text.data() + text.size(), value, std::chars_format::general);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    if (!std::isfinite(value)) return std::nullopt;
    return value;
}

std::optional<long long> parseInteger(std::string_view text) {
    if (!text.empty() && text.front() == '+') {
        text.remove_prefix(1);
        if (!text.empty() && text.front() == '-') return std::nullopt;  // "+-3"
    }
    if (text.empty()) return std::nullopt;
    long long value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

std::string quoted(std::string_view text) {
    std::string s;
    const std::size_t limit = 24;
    for (char c : text.substr(0, limit)) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7f) {
            static const char* hex = "0123456789abcdef";
            s += "\\x";
            s += hex[u >> 4];
            s += hex[u & 15];
        } else {
            s += c;
        }
    }
    if (text.size() > limit) s += "...";
    return "'" + s + "'";
}

}  // namespace rl
