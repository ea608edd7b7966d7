// The pipeline's errors, warnings and notes in the user's language. The pipeline keeps each
// message as an English template with its arguments (pipeline/core/message.h); the window
// translates the template (context "Messages") and puts in the arguments, translated in turn.
// The command line prints the English text (Error::toString), which scripts compare.
#pragma once

#include <QString>

#include <span>

#include "pipeline/core/diagnostics.h"

namespace rasterlab {

QString translated(const rl::Message& message);
// "file:line:col: message" and "file:line:col: warning: message", translated.
QString translated(const rl::Error& error);
QString translated(const rl::Diagnostic& diagnostic);

// Every template of the pipeline and of the app's file reading and saving, as
// pipeline_messages.cpp lists them for lupdate (which cannot see the pipeline's strings).
std::span<const char* const> messageCatalogue();

}  // namespace rasterlab
