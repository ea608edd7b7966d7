// A message the window can show in the user's language while the command line and the tests
// read its English text: a template, English with %1, %2 ... where the arguments go, and the
// arguments. Templates are string literals with the suffix _msg, written where they are used:
//
//     makeError(ErrorCode::Syntax, where, "expected a number for %1, %2"_msg(name, why));
//
// The template is also the key of its translation. The pipeline has no Qt, so Qt's lupdate
// cannot see it: views/messages/pipeline_messages.cpp lists every template for lupdate, and
// tests/tst_pipeline_messages.cpp fails when a template written here is missing there.
//
// An argument is either text shown as it is in every language (a number, a key such as "hx",
// a token from the file) or a message of its own, translated in turn:
//     "found %1 (the decimal separator is '.')"_msg(quoted(token))
#pragma once

#include <concepts>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace rl {

class Message {
public:
    Message() = default;
    // Text shown as it is in every language: the arguments that are numbers, names or tokens,
    // and messages made outside the pipeline without a template. The pipeline's own messages
    // are templates (the test of the translations checks that it never calls this).
    static Message untranslated(std::string text);

    const std::string& text() const { return m_text; }  // the template, or the text itself
    bool translatable() const { return m_translatable; }
    const std::vector<Message>& arguments() const { return m_arguments; }

    // The English text: the template with its arguments (in English) in place of %1, %2 ...
    std::string english() const;

private:
    friend class MessageTemplate;
    std::string m_text;
    std::vector<Message> m_arguments;
    bool m_translatable = false;
};

namespace message_detail {
inline Message argument(const Message& message) {
    return message;
}
inline Message argument(std::string_view text) {
    return Message::untranslated(std::string(text));
}
inline Message argument(std::integral auto number) {
    return Message::untranslated(std::to_string(number));
}
}  // namespace message_detail

// A template as written in the source, "..."_msg; called with its arguments, it makes a
// Message. Only the literal suffix makes one, so every template is a literal in the source.
class MessageTemplate {
public:
    const char* text() const { return m_text; }

    // The message with these arguments for %1, %2 ...: messages, strings or integers.
    template <typename... Args>
    Message operator()(const Args&... args) const {
        Message message;
        message.m_text = m_text;
        message.m_translatable = true;
        (message.m_arguments.push_back(message_detail::argument(args)), ...);
        return message;
    }
    // A template without placeholders is a message as it is.
    operator Message() const { return (*this)(); }

private:
    constexpr explicit MessageTemplate(const char* text) : m_text(text) {}
    friend constexpr MessageTemplate operator""_msg(const char* text, std::size_t);
    const char* m_text;
};

constexpr MessageTemplate operator""_msg(const char* text, std::size_t) {
    return MessageTemplate(text);
}

// "1 vertex", "8 vertices": `one` when the count is 1, `many` otherwise, with the count as %1
// and any further arguments as %2, %3 ...
template <typename... Args>
Message counted(long long count, MessageTemplate one, MessageTemplate many, const Args&... args) {
    return count == 1 ? one(count, args...) : many(count, args...);
}

}  // namespace rl
