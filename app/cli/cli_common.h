// What rasterlab-cli's subcommands share: the limits, the messages for a wrong command line
// or a bad input, the subcommand help, pixels and PNG output, and the options that choose and
// set up a scene. Each subcommand has a file of its own in app/cli/ (cli_render.cpp, cli_run.cpp,
// cli_compare.cpp, cli_bench.cpp, cli_accuracy.cpp, cli_generate.cpp, cli_stability.cpp);
// cli.cpp dispatches to them.
#pragma once

#include <optional>

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QString>
#include <QStringList>
#include <QTextStream>

#include <memory>

#include "app/cli/cli.h"
#include "pipeline/core/diagnostics.h"
#include "pipeline/io/course_scene.h"
#include "pipeline/io/hw2_reader.h"
#include "pipeline/render/output_image.h"
#include "pipeline/scene/scene.h"

namespace rasterlab::cli {

// The buffers of one frame take about 40 bytes a pixel (depth, triangle ids, barycentrics,
// colour, the RGBA image): 40 million pixels, such as 7680x4320, need about 1.6 GB.
constexpr qint64 kDefaultMaxPixels = 40'000'000;

inline QString lit(const char* s) {
    return QString::fromUtf8(s);
}

void printDiagnostics(const rl::Diagnostics& diagnostics, QTextStream& err);
int usageError(QTextStream& err, const QString& message);
int inputError(QTextStream& err, const rl::Error& error);
// A subcommand's help. QCommandLineParser names the running executable in its usage line
// (from QCoreApplication::arguments(), not from the list it parsed): name the command.
QString commandHelp(const QCommandLineParser& parser, const QString& command);

// A number with a fixed count of decimals; in JSON, null when it is not finite.
QString number(double v, int decimals);
QString jsonNumber(double v, int decimals);
// "X,Y" such as 400,300.
bool parsePixel(const QString& text, int& x, int& y);
// Writes the image and says so on out ("wrote PATH (WHAT, WxH)"); false, with the error on
// err, when it cannot.
bool writePng(const rl::Rgba8Image& image, const QString& path, QTextStream& out, QTextStream& err,
              const QString& what);

// --max-pixels's value: ExitOk, or a usage error's code when it is not a positive whole number.
int readMaxPixels(const QCommandLineParser& parser, const QCommandLineOption& option,
                  QTextStream& err, qint64& limit);
// ExitOk, or an input error's code (printed) when a command file's image has more pixels than
// the limit.
int checkPixelLimit(const rl::Hw2Image& image, qint64 limit, QTextStream& err);

// The options that choose and set up a course scene, shared by render, bench and accuracy.
struct SceneOptions {
    QCommandLineOption camera{lit("camera"), lit("Camera file, in a layout --camera-format names."),
                              lit("FILE")};
    QCommandLineOption cameraFormat{
        lit("camera-format"),
        lit("Layout of the camera file: auto (default: detected, and named in a note), ufpe "
            "(C; N; V; d hx hy), ufrpe6 (N; V; d; hx; hy; C), ufrpe5 (C; N; V; hx hy; d) or "
            "keyvalue (C = x y z, N, V, d, hx, hy in any order). Detection: key = value when a "
            "line contains '='; otherwise the layout whose lines hold as many numbers as the "
            "file's, or the one layout a single line away."),
        lit("FORMAT"), lit("auto")};
    QCommandLineOption lighting{
        lit("lighting"), lit("Lighting file, in a layout --lighting-format names."), lit("FILE")};
    QCommandLineOption lightingFormat{
        lit("lighting-format"),
        lit("Layout of the lighting file: auto (default: detected, and named in a note), ufpe "
            "(Pl; ka; Ia; kd; Od; ks; Il; n), multi (ka; Ia; kd; Od; ks; n; L; then L times Pl; "
            "Il), ufrpe (Iamb; Ka; Il; Pl; Kd; Od; Ks; n) or keyvalue (Iamb = r g b, Ka, Il, Pl, "
            "Kd, Od, Ks, eta in any order; optionally the lecture slides' lighting: Ke = r g b "
            "(emission), two_sided = 1|0, blinn = 1|0, Pl = x y z w (w = 0: directional), "
            "atten = kc kl kq, spot_dir = x y z, spot_cutoff = degrees, spot_exp = e, and "
            "lights 2 to 8 as Pl2, Il2, atten2 ...). One key = value file may hold both the "
            "camera and the lighting."),
        lit("FORMAT"), lit("auto")};
    QCommandLineOption object{
        lit("object"),
        lit("Object file (.byu: a triangle mesh, a course Bezier surface or a Movie.BYU file)."),
        lit("FILE")};
    QCommandLineOption size{lit("size"), lit("Image size, default 800x600."), lit("WxH"),
                            lit("800x600")};
    QCommandLineOption shading{
        lit("shading"),
        lit("phong (default), flat, gouraud or painter (flat, triangles painted far to "
            "near without a depth test: seed 004)."),
        lit("MODEL"), lit("phong")};
    QCommandLineOption near{lit("near"),
                            lit("View-space z of the near plane (default: 0.001 times the "
                                "farthest vertex's z)."),
                            lit("Z")};
    QCommandLineOption naive{lit("naive-projection"),
                             lit("Divide by z even at or behind the camera, without clipping "
                                 "(shows why clipping exists).")};
    QCommandLineOption backFaces{
        lit("back-faces"),
        lit("draw (default for course files): draw every triangle, as seed 000 does; cull "
            "(default for --scene): leave out the triangles of a closed surface that face away "
            "from the camera when the camera is outside it and nothing cuts the surface open "
            "(hidden but for a few silhouette pixels; a note counts them)."),
        lit("MODE")};
    QCommandLineOption rules{
        lit("rules"),
        lit("Rasterization rules: course (default: seed 000 as written, vertices truncated to "
            "whole pixels, samples at pixel corners, screen-space interpolation), gpu (vertices "
            "on a 1/256-pixel grid, samples at pixel centres, top-left fill rule, "
            "perspective-correct interpolation and depth) or hw2 (seed 001's DDA in double on "
            "unsnapped vertices, samples at pixel corners, half-open rows and spans, "
            "perspective-correct)."),
        lit("RULES"), lit("course")};
    QCommandLineOption maxPixels{lit("max-pixels"),
                                 lit("Refuse images with more pixels than this (default "
                                     "40000000, about 1.6 GB of buffers)."),
                                 lit("N"), QString::number(kDefaultMaxPixels)};

    void addTo(QCommandLineParser& parser) const {
        parser.addOptions({camera, cameraFormat, lighting, lightingFormat, object, size, shading,
                           near, naive, backFaces, rules, maxPixels});
    }

    // Checks the options; ExitOk with the settings filled in, or a usage error's code.
    int settings(const QCommandLineParser& parser, QTextStream& err,
                 rl::CourseSceneSettings& out) const;

    bool anyFile(const QCommandLineParser& parser) const;

    // Reads the scene: each part from its file, or from the default scene where no file is
    // given. ExitOk, or the code of a usage error or a bad file (already printed).
    int load(const QCommandLineParser& parser, const rl::CourseSceneSettings& settings,
             QTextStream& err, rl::Diagnostics& diagnostics,
             std::shared_ptr<const rl::Scene>& scene) const;

    // The names --scene takes: the shipped lessons, then the benchmark scenes.
    static QStringList generatedSceneNames();
    static QCommandLineOption generatedSceneOption();
    // A shipped lesson's own settings (image size, shading, near plane, rules) where the
    // command line does not set them; nothing for other names.
    void lessonSettings(const QCommandLineParser& parser, const QCommandLineOption& sceneName,
                        rl::CourseSceneSettings& settings) const;

    // The lesson or generated scene --scene names, or the course files (load). ExitOk, or the
    // code of an error already printed.
    int loadAny(const QCommandLineParser& parser, const QCommandLineOption& sceneName,
                const rl::CourseSceneSettings& settings, QTextStream& err,
                rl::Diagnostics& diagnostics, std::shared_ptr<const rl::Scene>& scene,
                QString& sceneLabel) const;
};

// The steps every scene command (render, bench, accuracy, stability) takes first: parse the
// arguments, answer --help, refuse file names, read the scene options into settings (and a
// lesson's own). Each returns nullopt to go on, or the exit code to return, already printed.
std::optional<int> parseSceneCommand(QCommandLineParser& parser, const QStringList& arguments,
                                     const QCommandLineOption& help, const QString& command,
                                     const SceneOptions& sceneOptions,
                                     const QCommandLineOption& sceneName,
                                     rl::CourseSceneSettings& settings, QTextStream& out,
                                     QTextStream& err);
// --format: md, csv or json.
std::optional<int> checkTableFormat(const QString& format, QTextStream& err);
// --threads N, from 1 to rl::kMaxThreads, when given (threads stays 0 otherwise).
std::optional<int> readThreads(const QCommandLineParser& parser, const QCommandLineOption& option,
                               int& threads, QTextStream& err);

// The subcommands.
int runRender(const QStringList& arguments, QTextStream& out, QTextStream& err);
int runCommandFile(const QStringList& arguments, QTextStream& out, QTextStream& err);
int runCompare(const QStringList& arguments, QTextStream& out, QTextStream& err);
int runCheck(const QStringList& arguments, QTextStream& out, QTextStream& err);
int runGrade(const QStringList& arguments, QTextStream& out, QTextStream& err);
int runBench(const QStringList& arguments, QTextStream& out, QTextStream& err);
int runAccuracy(const QStringList& arguments, QTextStream& out, QTextStream& err);
int runStability(const QStringList& arguments, QTextStream& out, QTextStream& err);
int runGenerateDefaultScene(const QStringList& arguments, QTextStream& out, QTextStream& err);
int runGenerateLessons(const QStringList& arguments, QTextStream& out, QTextStream& err);

}  // namespace rasterlab::cli
