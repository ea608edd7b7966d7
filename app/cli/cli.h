// rasterlab-cli: the renderer without a window. Subcommands:
//   render                  render a course scene (or the default scene) to PNG
//   run                     run a command file (seed 001) and write the PNGs it names
//   compare                 a student's image against ours, with a diagnosis of mistakes
//   bench                   time a scene's frames, per stage, with the memory used
//   accuracy                error against run time of each mode, against an exact reference
//   generate-default-scene  write the default scene's three course files
//   generate-lessons        write the shipped lessons' course files and lesson files
// Exit status: 0 on success, 1 when an input is bad (one "file:line:col: message" line on
// stderr), 2 when the command line is wrong. Warnings go to stderr; what was written, to
// stdout. The command line and its output are in English and stable, for scripts.
#pragma once

#include <QStringList>
#include <QTextStream>

namespace rasterlab {

enum ExitCode { ExitOk = 0, ExitBadInput = 1, ExitUsage = 2 };

int runCli(const QStringList& arguments, QTextStream& out, QTextStream& err);

}  // namespace rasterlab
