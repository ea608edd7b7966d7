#include "message.h"

namespace rl {

Message Message::untranslated(std::string text) {
    Message message;
    message.m_text = std::move(text);
    return message;
}

// One pass over the template, so that an argument holding "%1" (a token from the file) is
// left as it is. %1 to %9 name the arguments; any other '%' is kept.
std::string Message::english() const {
    if (!m_translatable) return m_text;
    std::string s;
    s.reserve(m_text.size() + 16 * m_arguments.size());
    for (std::size_t i = 0; i < m_text.size(); ++i) {
        const char c = m_text[i];
        const char next = i + 1 < m_text.size() ? m_text[i + 1] : '\0';
        const auto k = static_cast<std::size_t>(next - '1');
        if (c == '%' && next >= '1' && next <= '9' && k < m_arguments.size()) {
            s += m_arguments[k].english();
            ++i;
        } else {
            s += c;
        }
    }
    return s;
}

}  // namespace rl
