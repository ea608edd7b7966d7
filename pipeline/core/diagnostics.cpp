#include "diagnostics.h"

namespace rl {

std::string SourceLocation::toString() const {
    std::string s = file.empty() ? std::string("<input>") : file;
    if (line > 0) {
        s += ':' + std::to_string(line);
        if (column > 0) s += ':' + std::to_string(column);
    }
    return s;
}

std::string Error::toString() const {
    return where.toString() + ": " + message;
}

Error makeError(ErrorCode code, SourceLocation where, Message message) {
    std::string english = message.english();
    return Error{code, std::move(english), std::move(where), std::move(message)};
}

std::string Diagnostic::toString() const {
    const char* kind = severity == Severity::Warning ? "warning" : "note";
    return where.toString() + ": " + kind + ": " + message;
}

void Diagnostics::warn(SourceLocation where, Message message) {
    std::string english = message.english();
    m_items.push_back(
        {Severity::Warning, std::move(english), std::move(where), std::move(message)});
}

void Diagnostics::note(SourceLocation where, Message message) {
    std::string english = message.english();
    m_items.push_back({Severity::Note, std::move(english), std::move(where), std::move(message)});
}

void Diagnostics::append(const Diagnostics& other) {
    m_items.insert(m_items.end(), other.m_items.begin(), other.m_items.end());
}

std::size_t Diagnostics::warningCount() const {
    std::size_t n = 0;
    for (const auto& d : m_items) n += d.severity == Severity::Warning ? 1 : 0;
    return n;
}

bool Diagnostics::contains(std::string_view fragment) const {
    for (const auto& d : m_items)
        if (d.message.find(fragment) != std::string::npos) return true;
    return false;
}

}  // namespace rl
