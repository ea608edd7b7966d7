// Splits a text file into lines of whitespace-separated tokens, keeping the line and
// column of each token so that every reader can report "file:line:col: message".
// Tolerates what real course files contain: CRLF or LF endings, no newline at the end,
// blank lines anywhere, leading and trailing spaces, TABs, and a UTF-8 byte-order mark.
// Numbers are parsed with the C locale ('.' is the decimal separator) whatever the
// user's locale.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/core/diagnostics.h"

namespace rl {

struct Token {
    std::string_view text;
    int line = 0;
    int column = 0;  // 1-based, in bytes
};

struct TextLine {
    int number = 0;             // 1-based line number
    std::vector<Token> tokens;  // never empty for lines returned by LineScanner::next
    int endColumn = 1;          // column just after the last token
};

class LineScanner {
public:
    LineScanner(std::string_view text, std::string fileName);

    // The next line holding at least one token; false at the end of the input.
    bool next(TextLine& line);
    // Puts the last line returned by next() back, so that next() returns it again.
    void unread();
    // Lines holding tokens from here to the end, without consuming them.
    int countRemainingLines() const;

    const std::string& fileName() const { return m_fileName; }
    SourceLocation at(const Token& token) const { return {m_fileName, token.line, token.column}; }
    SourceLocation at(int line, int column) const { return {m_fileName, line, column}; }
    SourceLocation afterLast(const TextLine& line) const {
        return {m_fileName, line.number, line.endColumn};
    }
    SourceLocation endOfInput() const;  // where the input ends
    std::size_t bytesRemaining() const { return m_text.size() - m_pos; }
    std::size_t bytesTotal() const { return m_text.size(); }

private:
    std::string_view m_text;
    std::string m_fileName;
    std::size_t m_pos = 0;
    int m_line = 1;
    std::size_t m_lastLineStart = 0;  // for unread()
    int m_lastLineNumber = 1;
};

// A token parsed as a finite real number in the C locale ("50.0000", "9.5e-005", "-1E-15",
// "+2"). std::nullopt for anything else, including "nan", "inf" and "1,5".
std::optional<double> parseReal(std::string_view text);
// A token parsed as a decimal integer ("12", "+3", "-1"); std::nullopt for "1.0" or "x".
std::optional<long long> parseInteger(std::string_view text);

// A token quoted for an error message: 'abc', shortened with "..." past 24 characters.
std::string quoted(std::string_view text);

}  // namespace rl
