// Bad input is a value, not an exception: readers and stages return Result<T>, whose
// error prints as "file:line:col: message" and names what was expected and what was found.
// Warnings (trailing data, unused vertices, a mirrored image ...) are collected in
// Diagnostics and shown beside the result; they never stop a render. Each message is kept in
// English and as a template with its arguments (message.h), which the window translates.
#pragma once

#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "pipeline/core/message.h"

namespace rl {

// A place in an input: a file (or a pseudo-file such as "<camera>" for values edited in
// the GUI), a 1-based line and a 1-based column. Line 0 means "the file as a whole".
struct SourceLocation {
    std::string file;
    int line = 0;
    int column = 0;

    std::string toString() const;  // "file:line:col", "file" when line is 0
};

enum class ErrorCode {
    Io,           // the file could not be read
    Syntax,       // a token is not what the format expects at this place
    MissingData,  // the input ends before the format is complete
    Range,        // a value is outside the range the format allows (an index, a count)
    Unsupported,  // a recognised format or feature that RasterLab does not read
    Degenerate,   // values that make the geometry undefined (N parallel to V, d = 0 ...)
    Usage,        // a command-line or API misuse
};

struct Error {
    ErrorCode code = ErrorCode::Syntax;
    std::string message;  // English; says what was expected and what was found
    SourceLocation where;
    Message translatable;  // the same message as a template and its arguments

    std::string toString() const;  // "file:line:col: message"
};

Error makeError(ErrorCode code, SourceLocation where, Message message);
#ifndef RASTERLAB_PIPELINE
// An error in plain English, for code outside the pipeline (tests, the app's own checks): the
// window shows it as it is. Inside the pipeline every message is a template (message.h).
inline Error makeError(ErrorCode code, SourceLocation where, std::string message) {
    return makeError(code, std::move(where), Message::untranslated(std::move(message)));
}
#endif

// Either a value or an Error. The pipeline never throws; it returns one of these.
template <typename T>
class [[nodiscard]] Result {
public:
    Result(T value) : m_state(std::move(value)) {}
    Result(Error error) : m_state(std::move(error)) {}

    bool ok() const { return m_state.index() == 0; }
    explicit operator bool() const { return ok(); }

    const T& value() const& { return std::get<0>(m_state); }
    T& value() & { return std::get<0>(m_state); }
    T&& value() && { return std::get<0>(std::move(m_state)); }
    const T* operator->() const { return &value(); }
    T* operator->() { return &value(); }
    const T& operator*() const { return value(); }

    const Error& error() const { return std::get<1>(m_state); }

private:
    std::variant<T, Error> m_state;
};

// Result of an operation that produces no value.
struct Done {};
using Status = Result<Done>;
inline Status success() {
    return Done{};
}

enum class Severity { Note, Warning };

struct Diagnostic {
    Severity severity = Severity::Warning;
    std::string message;  // English
    SourceLocation where;
    Message translatable;  // the same message as a template and its arguments

    std::string toString() const;  // "file:line:col: warning: message"
};

// An ordered list of notes and warnings, appended to by readers and stages.
class Diagnostics {
public:
    void warn(SourceLocation where, Message message);
    void note(SourceLocation where, Message message);
    void append(const Diagnostics& other);

    const std::vector<Diagnostic>& items() const { return m_items; }
    bool empty() const { return m_items.empty(); }
    std::size_t size() const { return m_items.size(); }
    std::size_t warningCount() const;
    bool contains(std::string_view fragment) const;  // any message containing fragment

private:
    std::vector<Diagnostic> m_items;
};

}  // namespace rl
