#include "cli.h"

#include <QStringList>

#include <new>

#include "app/cli/cli_common.h"

namespace rasterlab {

using cli::lit;

namespace {

QString generalHelp() {
    return lit(
        "Usage: rasterlab-cli <command> [options]\n"
        "\n"
        "RasterLab's software rasterization pipeline, without a window.\n"
        "\n"
        "Commands:\n"
        "  render                   Render a course scene (camera, lighting, object) to PNG.\n"
        "                           Without scene files, renders the embedded default scene.\n"
        "  run FILE                 Run a command file (seed 001's png, xyz, trif ...) and\n"
        "                           write the PNGs it names.\n"
        "  compare                  Compare your rasterizer's image with ours (render's scene\n"
        "                           options, or a command file): summary, difference image\n"
        "                           and a ranked diagnosis of likely mistakes.\n"
        "  check                    Check your rasterizer stage by stage: your program answers\n"
        "                           each stage over the stage protocol, held to the lecture's.\n"
        "  grade                    Check every submission of a class: a table of\n"
        "                           submissions x stages, and each one's report.\n"
        "  bench                    Time a scene's frames (median, min, max, per stage).\n"
        "  accuracy                 Error against run time of each mode, against an exact\n"
        "                           ray-cast reference (table, plot, heat maps).\n"
        "  stability                Error of float and double as a scene grows stiff (moved,\n"
        "                           scaled, near the eye, slivers, shininess, V along N, a\n"
        "                           light on the surface), against the exact reference.\n"
        "  generate-default-scene   Write the default scene's three course files.\n"
        "  generate-lessons         Write the shipped lessons' course and lesson files.\n"
        "\n"
        "Run 'rasterlab-cli <command> --help' for a command's options.\n");
}

}  // namespace

int runCli(const QStringList& arguments, QTextStream& out, QTextStream& err) {
    const QString command = arguments.value(1);
    if (command.isEmpty() || command == lit("-h") || command == lit("--help") ||
        command == lit("help")) {
        out << generalHelp();
        out.flush();
        return command.isEmpty() ? ExitUsage : ExitOk;
    }
    if (command == lit("--version")) {
        out << "rasterlab-cli " << RASTERLAB_VERSION << '\n';
        return ExitOk;
    }
    QStringList rest = arguments.mid(2);
    rest.prepend(arguments.first() + QLatin1Char(' ') + command);
    int code = ExitUsage;
    try {
        if (command == lit("render"))
            code = cli::runRender(rest, out, err);
        else if (command == lit("bench"))
            code = cli::runBench(rest, out, err);
        else if (command == lit("accuracy"))
            code = cli::runAccuracy(rest, out, err);
        else if (command == lit("stability"))
            code = cli::runStability(rest, out, err);
        else if (command == lit("run"))
            code = cli::runCommandFile(rest, out, err);
        else if (command == lit("compare"))
            code = cli::runCompare(rest, out, err);
        else if (command == lit("check"))
            code = cli::runCheck(rest, out, err);
        else if (command == lit("grade"))
            code = cli::runGrade(rest, out, err);
        else if (command == lit("generate-default-scene"))
            code = cli::runGenerateDefaultScene(rest, out, err);
        else if (command == lit("generate-lessons"))
            code = cli::runGenerateLessons(rest, out, err);
        else
            code = cli::usageError(err, lit("unknown command '%1' (commands: render, run, compare, "
                                            "check, grade, bench, accuracy, stability, generate-default-scene, "
                                            "generate-lessons)")
                                            .arg(command));
    } catch (const std::bad_alloc&) {
        // The only exception the pipeline can meet: a frame larger than the memory.
        out.flush();
        err << "rasterlab-cli: not enough memory for this render (try a smaller --size)\n";
        code = ExitBadInput;
    }
    out.flush();
    err.flush();
    return code;
}

}  // namespace rasterlab
