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

Error makeError(ErrorCode code, SourceLocation where, std::string message) {
    return Error{code, std::move(message), std::move(where)};
}

std::string Diagnostic::toString() const {
    const char* kind = severity == Severity::Warning ? "warning" : "note";
    return where.toString() + ": " + kind + ": " + message;
}

void Diagnostics::warn(SourceLocation where, std::string message) {
    m_items.push_back({Severity::Warning, std::move(message), std::move(where)});
}

void Diagnostics::note(SourceLocation where, std::string message) {
    m_items.push_back({Severity::Note, std::move(message), std::move(where)});
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
