#include "cli.h"

#include <QCommandLineParser>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QGuiApplication>
#include <QRegularExpression>
#include <QSaveFile>

#include <algorithm>
#include <cmath>
#include <new>
#include <optional>

#include "accuracy.h"
#include "accuracy_plot.h"
#include "animation.h"
#include "benchmark_scenes.h"
#include "command_file.h"
#include "default_scene.h"
#include "default_scene_resource.h"
#include "explain.h"
#include "image_io.h"
#include "output_image.h"
#include "painter.h"
#include "parallel.h"
#include "renderer.h"

namespace rasterlab {

namespace {

constexpr int kMaxImageSide = 16384;
// The buffers of one frame take about 40 bytes a pixel (depth, triangle ids, barycentrics,
// colour, the RGBA image): 40 million pixels, such as 7680x4320, need about 1.6 GB.
constexpr qint64 kDefaultMaxPixels = 40'000'000;

QString lit(const char* s) {
    return QString::fromUtf8(s);
}

void printDiagnostics(const rl::Diagnostics& diagnostics, QTextStream& err) {
    for (const auto& d : diagnostics.items()) err << QString::fromStdString(d.toString()) << '\n';
}

int usageError(QTextStream& err, const QString& message) {
    err << "rasterlab-cli: " << message << '\n'
        << "Try 'rasterlab-cli --help' for more information.\n";
    err.flush();
    return ExitUsage;
}

int inputError(QTextStream& err, const rl::Error& error) {
    err << QString::fromStdString(error.toString()) << '\n';
    err.flush();
    return ExitBadInput;
}

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
        "  bench                    Time a scene's frames (median, min, max, per stage).\n"
        "  accuracy                 Error against run time of each mode, against an exact\n"
        "                           ray-cast reference (table, plot, heat maps).\n"
        "  generate-default-scene   Write the default scene's three course files.\n"
        "\n"
        "Run 'rasterlab-cli <command> --help' for a command's options.\n");
}

// A subcommand's help. QCommandLineParser names the running executable in its usage line
// (from QCoreApplication::arguments(), not from the list it parsed): name the command.
QString commandHelp(const QCommandLineParser& parser, const QString& command) {
    QString text = parser.helpText();
    const QString prefix = lit("Usage: ");
    const qsizetype end = text.indexOf(lit(" [options]"));
    const qsizetype lineEnd = text.indexOf(QLatin1Char('\n'));
    if (text.startsWith(prefix) && end > 0 && (lineEnd < 0 || end < lineEnd))
        text.replace(0, end, prefix + lit("rasterlab-cli ") + command);
    return text;
}

bool parseSize(const QString& text, int& width, int& height) {
    static const QRegularExpression pattern(lit("^(\\d{1,6})[xX](\\d{1,6})$"));
    const auto match = pattern.match(text);
    if (!match.hasMatch()) return false;
    width = match.captured(1).toInt();
    height = match.captured(2).toInt();
    return true;
}

bool parsePixel(const QString& text, int& x, int& y) {
    static const QRegularExpression pattern(lit("^(\\d{1,6}),(\\d{1,6})$"));
    const auto match = pattern.match(text);
    if (!match.hasMatch()) return false;
    x = match.captured(1).toInt();
    y = match.captured(2).toInt();
    return true;
}

bool writePng(const rl::Rgba8Image& image, const QString& path, QTextStream& out, QTextStream& err,
              const QString& what) {
    QString error;
    if (!savePng(toQImage(image), path, &error)) {
        err << path << ": cannot write the " << what << ": " << error << '\n';
        return false;
    }
    out << "wrote " << QFileInfo(path).absoluteFilePath() << " (" << what << ", " << image.width
        << "x" << image.height << ")\n";
    return true;
}

// The options that choose and set up a course scene, shared by render and bench.
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
            "perspective-correct interpolation and depth) or hw2 (seed 001's: 1/65536-pixel "
            "grid, samples at pixel corners, top-left, perspective-correct)."),
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
                 rl::CourseSceneSettings& out) const {
        if (!parseSize(parser.value(size), out.width, out.height) || out.width < 1 ||
            out.height < 1)
            return usageError(err, lit("--size expects WIDTHxHEIGHT such as 800x600, found '%1'")
                                       .arg(parser.value(size)));
        if (out.width > kMaxImageSide || out.height > kMaxImageSide)
            return usageError(err, lit("--size %1 is larger than the limit of %2 pixels a side")
                                       .arg(parser.value(size))
                                       .arg(kMaxImageSide));
        bool maxOk = false;
        const qint64 pixelLimit = parser.value(maxPixels).toLongLong(&maxOk);
        if (!maxOk || pixelLimit < 1)
            return usageError(err, lit("--max-pixels expects a positive whole number, found '%1'")
                                       .arg(parser.value(maxPixels)));
        if (qint64(out.width) * out.height > pixelLimit)
            return usageError(err, lit("--size %1 has %2 pixels, more than the limit of %3 (raise "
                                       "it with --max-pixels if the memory is there)")
                                       .arg(parser.value(size))
                                       .arg(qint64(out.width) * out.height)
                                       .arg(pixelLimit));
        const auto model = rl::shadingModelFromName(parser.value(shading).toStdString());
        if (!model)
            return usageError(err,
                              lit("--shading expects phong, flat, gouraud or painter, found '%1'")
                                  .arg(parser.value(shading)));
        out.shading = *model;
        const auto ruleSet = rl::ruleSetFromName(parser.value(rules).toStdString());
        if (!ruleSet)
            return usageError(
                err,
                lit("--rules expects course, gpu or hw2, found '%1'").arg(parser.value(rules)));
        out.rules = rl::rulesOf(*ruleSet);
        if (parser.isSet(near)) {
            bool ok = false;
            const double z = parser.value(near).toDouble(&ok);
            if (!ok || !(z > 0.0))
                return usageError(
                    err,
                    lit("--near expects a positive number, found '%1'").arg(parser.value(near)));
            out.nearPlane.fixedW = z;
        }
        if (parser.isSet(naive)) out.nearPlane.mode = rl::NearPlane::Mode::Naive;
        if (parser.isSet(backFaces)) {
            const QString faces = parser.value(backFaces);
            if (faces != lit("draw") && faces != lit("cull"))
                return usageError(err,
                                  lit("--back-faces expects draw or cull, found '%1'").arg(faces));
            out.cullHiddenBackFaces = faces == lit("cull");
        }
        return ExitOk;
    }

    bool anyFile(const QCommandLineParser& parser) const {
        return parser.isSet(camera) || parser.isSet(lighting) || parser.isSet(object);
    }

    // Reads the scene: each part from its file, or from the default scene where no file is
    // given. ExitOk, or the code of a usage error or a bad file (already printed).
    int load(const QCommandLineParser& parser, const rl::CourseSceneSettings& settings,
             QTextStream& err, rl::Diagnostics& diagnostics,
             std::shared_ptr<const rl::Scene>& scene) const {
        const auto cameraLayout =
            rl::cameraLayoutFromName(parser.value(cameraFormat).toStdString());
        if (!cameraLayout)
            return usageError(err, lit("--camera-format expects auto, ufpe, ufrpe6, ufrpe5 or "
                                       "keyvalue, found '%1'")
                                       .arg(parser.value(cameraFormat)));
        if (parser.isSet(cameraFormat) && !parser.isSet(camera))
            return usageError(err, lit("--camera-format applies to the file of --camera, which "
                                       "is not given"));
        const auto lightingLayout =
            rl::lightingLayoutFromName(parser.value(lightingFormat).toStdString());
        if (!lightingLayout)
            return usageError(err, lit("--lighting-format expects auto, ufpe, multi, ufrpe or "
                                       "keyvalue, found '%1'")
                                       .arg(parser.value(lightingFormat)));
        if (parser.isSet(lightingFormat) && !parser.isSet(lighting))
            return usageError(err, lit("--lighting-format applies to the file of --lighting, "
                                       "which is not given"));
        const auto source = [&](const QCommandLineOption& option, CoursePart part) {
            return parser.isSet(option) ? parser.value(option) : defaultScenePath(part);
        };
        auto c = loadCamera(source(camera, CoursePart::Camera), diagnostics, *cameraLayout);
        if (!c) return inputError(err, c.error());
        auto l = loadLighting(source(lighting, CoursePart::Lighting), diagnostics, *lightingLayout);
        if (!l) return inputError(err, l.error());
        auto o = loadObject(source(object, CoursePart::Object), diagnostics);
        if (!o) return inputError(err, o.error());
        scene = std::make_shared<const rl::Scene>(
            rl::makeCourseScene({c.value(), l.value(), o.value()}, settings));
        return ExitOk;
    }

    static QStringList generatedSceneNames() {
        QStringList names;
        for (const auto& s : rl::benchmarkScenes()) names << QString::fromStdString(s.name);
        return names;
    }
    static QCommandLineOption generatedSceneOption() {
        return {lit("scene"),
                lit("A generated scene instead of course files: %1.")
                    .arg(generatedSceneNames().join(lit(", "))),
                lit("NAME")};
    }

    // The generated scene --scene names, or the course files (load). ExitOk, or the code of
    // an error already printed.
    int loadAny(const QCommandLineParser& parser, const QCommandLineOption& sceneName,
                const rl::CourseSceneSettings& settings, QTextStream& err,
                rl::Diagnostics& diagnostics, std::shared_ptr<const rl::Scene>& scene,
                QString& sceneLabel) const {
        if (parser.isSet(sceneName)) {
            if (anyFile(parser))
                return usageError(err, lit("--scene replaces --camera, --lighting and --object"));
            auto generated =
                rl::makeBenchmarkScene(parser.value(sceneName).toStdString(), settings.width,
                                       settings.height, settings.shading);
            if (!generated)
                return usageError(
                    err, lit("--scene expects one of %1, found '%2'")
                             .arg(generatedSceneNames().join(lit(", ")), parser.value(sceneName)));
            if (parser.isSet(backFaces))
                generated->cullHiddenBackFaces = settings.cullHiddenBackFaces;
            generated->rules = settings.rules;
            scene = std::make_shared<const rl::Scene>(std::move(*generated));
            sceneLabel = parser.value(sceneName);
            return ExitOk;
        }
        if (int code = load(parser, settings, err, diagnostics, scene); code != ExitOk) return code;
        sceneLabel = anyFile(parser) ? QString::fromStdString(scene->name) : lit("default scene");
        return ExitOk;
    }
};

bool parseVector(const QString& text, rl::dvec3& v) {
    const QStringList parts = text.split(QLatin1Char(','));
    if (parts.size() != 3) return false;
    for (int i = 0; i < 3; ++i) {
        bool ok = false;
        v[i] = parts[i].trimmed().toDouble(&ok);
        if (!ok || !rl::isFinite(v[i])) return false;
    }
    return true;
}

// Seed 002's animation matrix M for render: a turntable (or a motion of one's own) set on
// every draw, and the time of the frame or the frames to write.
struct AnimationOptions {
    QCommandLineOption time{lit("time"),
                            lit("Render the frame at T seconds of the animation (turns the "
                                "animation on; default turntable: 36 degrees a second about "
                                "the camera's up through the object's centre)."),
                            lit("T")};
    QCommandLineOption animate{lit("animate"),
                               lit("Write FRAMES frames of the animation, at t = frame / fps, "
                                   "as numbered PNGs frame_0000.png ... into the folder "
                                   "--output names."),
                               lit("FRAMES")};
    QCommandLineOption fps{lit("fps"), lit("Frames per second of --animate (default 24)."),
                           lit("F"), lit("24")};
    QCommandLineOption turn{lit("turn"),
                            lit("Degrees a second the object turns (default 36; turns the "
                                "animation on)."),
                            lit("DEG")};
    QCommandLineOption axis{lit("axis"),
                            lit("World axis of the turn (default: the camera's up, V made "
                                "perpendicular to N)."),
                            lit("X,Y,Z")};
    QCommandLineOption move{lit("move"), lit("Translation in world units a second."), lit("X,Y,Z")};
    QCommandLineOption scale{lit("scale"),
                             lit("Scale about the object's centre along the world axes, fixed "
                                 "in time (a non-uniform one shows why normals take the inverse "
                                 "transpose of M)."),
                             lit("X,Y,Z")};

    void addTo(QCommandLineParser& parser) const {
        parser.addOptions({time, animate, fps, turn, axis, move, scale});
    }
    bool any(const QCommandLineParser& parser) const {
        for (const auto* o : {&time, &animate, &turn, &axis, &move, &scale})
            if (parser.isSet(*o)) return true;
        return false;
    }

    // ExitOk with the animation, the time and the frame count filled in (frames 0 without
    // --animate), or a usage error's code.
    int read(const QCommandLineParser& parser, QTextStream& err, rl::Animation& out, double& t,
             int& frames, double& framesPerSecond) const {
        const auto number = [&](const QCommandLineOption& option, double& value) {
            bool ok = false;
            value = parser.value(option).toDouble(&ok);
            return ok && rl::isFinite(value);
        };
        t = 0.0;
        if (parser.isSet(time) && !number(time, t))
            return usageError(
                err, lit("--time expects a number of seconds, found '%1'").arg(parser.value(time)));
        frames = 0;
        if (parser.isSet(animate)) {
            bool ok = false;
            frames = parser.value(animate).toInt(&ok);
            if (!ok || frames < 1 || frames > 100000)
                return usageError(err, lit("--animate expects a number of frames from 1 to "
                                           "100000, found '%1'")
                                           .arg(parser.value(animate)));
            if (parser.isSet(time))
                return usageError(err, lit("--time and --animate exclude each other"));
        }
        if (!number(fps, framesPerSecond) || !(framesPerSecond > 0.0))
            return usageError(
                err, lit("--fps expects a positive number, found '%1'").arg(parser.value(fps)));
        if (parser.isSet(turn) && !number(turn, out.degreesPerSecond))
            return usageError(
                err, lit("--turn expects degrees a second, found '%1'").arg(parser.value(turn)));
        if (parser.isSet(axis)) {
            rl::dvec3 a;
            if (!parseVector(parser.value(axis), a) || a == rl::dvec3(0.0))
                return usageError(err, lit("--axis expects a non-zero vector X,Y,Z such as "
                                           "0,1,0, found '%1'")
                                           .arg(parser.value(axis)));
            out.axis = a;
        }
        if (parser.isSet(move) && !parseVector(parser.value(move), out.velocity))
            return usageError(
                err, lit("--move expects X,Y,Z such as 0,0,1, found '%1'").arg(parser.value(move)));
        if (parser.isSet(scale) && (!parseVector(parser.value(scale), out.scale) ||
                                    out.scale.x == 0.0 || out.scale.y == 0.0 || out.scale.z == 0.0))
            return usageError(err, lit("--scale expects X,Y,Z, none zero, such as 2,1,1, found "
                                       "'%1'")
                                       .arg(parser.value(scale)));
        return ExitOk;
    }
};

// The scene with the animation on every draw, at time t.
std::shared_ptr<const rl::Scene> animatedScene(const rl::Scene& scene,
                                               const rl::Animation& animation, double t) {
    auto copy = std::make_shared<rl::Scene>(scene);
    rl::animateEveryDraw(*copy, animation, t);
    return copy;
}

// --animate: frame k at t = k / fps, written to folder/frame_0000.png ...
int renderAnimation(const rl::Scene& scene, const rl::Animation& animation, int frames,
                    double framesPerSecond, const QString& folderPath, rl::Diagnostics& diagnostics,
                    QTextStream& out, QTextStream& err) {
    const QDir folder(folderPath);
    if (!QDir().mkpath(folder.path())) {
        err << folder.path() << ": cannot create the folder\n";
        return ExitBadInput;
    }
    bool written = true;
    const rl::Status rendered = rl::renderAnimationFrames(
        *animatedScene(scene, animation, 0.0), frames, framesPerSecond,
        [&](int k, double t, const rl::FrameTrace& trace) {
            if (k == 0) {
                diagnostics.append(trace.diagnostics);
                printDiagnostics(diagnostics, err);
            }
            const QString path =
                folder.filePath(QString::fromStdString(rl::animationFrameFileName(k)));
            written =
                writePng(rl::colourImage(*trace.shading, *trace.depth, trace.scene->conventions),
                         path, out, err, lit("frame %1, t = %2 s").arg(k).arg(t, 0, 'f', 3));
            return written;
        });
    if (!rendered) {
        printDiagnostics(diagnostics, err);
        return inputError(err, rendered.error());
    }
    if (!written) return ExitBadInput;
    out.flush();
    return ExitOk;
}

int runRender(const QStringList& arguments, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        lit("Render a course scene to PNG, or the frames of its animation (seed 002's M)."));
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({lit("h"), lit("help")}, lit("Show this help."));
    const SceneOptions sceneOptions;
    const QCommandLineOption output(lit("output"),
                                    lit("The PNG to write (required); with --animate, the "
                                        "folder of the frames."),
                                    lit("FILE.png"));
    const QCommandLineOption depthOutput(lit("depth-output"),
                                         lit("Also write the z-buffer as a grey PNG "
                                             "(near white, far dark, empty black)."),
                                         lit("FILE.png"));
    const QCommandLineOption normalsOutput(lit("normals-output"),
                                           lit("Also write the normals as a PNG, (N + 1) / 2 "
                                               "per channel, in view coordinates."),
                                           lit("FILE.png"));
    const QCommandLineOption explain(lit("explain-pixel"),
                                     lit("Print the story of one pixel: the triangles that "
                                         "covered it, each depth test, and its Phong terms."),
                                     lit("X,Y"));
    const AnimationOptions animationOptions;
    const QCommandLineOption painterDiff(
        lit("painter-diff"),
        lit("With --shading painter: also write where the painter's image differs from the "
            "z-buffer's (the same flat colours, with a depth test), over the z-buffer image "
            "darkened: red where a farther triangle was painted last, yellow where two "
            "triangles are as near (an edge they share)."),
        lit("FILE.png"));
    parser.addOption(help);
    sceneOptions.addTo(parser);
    parser.addOptions({output, depthOutput, normalsOutput, explain, painterDiff});
    animationOptions.addTo(parser);
    if (!parser.parse(arguments)) return usageError(err, parser.errorText());
    if (parser.isSet(help)) {
        out << commandHelp(parser, lit("render"));
        return ExitOk;
    }
    if (!parser.positionalArguments().isEmpty())
        return usageError(
            err, lit("unexpected argument '%1'").arg(parser.positionalArguments().first()));

    rl::CourseSceneSettings settings;
    if (int code = sceneOptions.settings(parser, err, settings); code != ExitOk) return code;
    if (!parser.isSet(output)) return usageError(err, lit("render needs --output FILE.png"));
    if (parser.isSet(painterDiff) && settings.shading != rl::ShadingModel::Painter)
        return usageError(err, lit("--painter-diff needs --shading painter"));
    int explainX = -1, explainY = -1;
    if (parser.isSet(explain)) {
        if (!parsePixel(parser.value(explain), explainX, explainY))
            return usageError(err, lit("--explain-pixel expects X,Y such as 400,300, found '%1'")
                                       .arg(parser.value(explain)));
        if (explainX >= settings.width || explainY >= settings.height)
            return usageError(err, lit("--explain-pixel %1 is outside the %2x%3 image")
                                       .arg(parser.value(explain))
                                       .arg(settings.width)
                                       .arg(settings.height));
    }

    rl::Animation animation;
    double time = 0.0, framesPerSecond = 24.0;
    int frames = 0;
    if (int code = animationOptions.read(parser, err, animation, time, frames, framesPerSecond);
        code != ExitOk)
        return code;
    if (frames > 0 &&
        (parser.isSet(depthOutput) || parser.isSet(normalsOutput) || parser.isSet(explain)))
        return usageError(err, lit("--animate writes colour frames only (no --depth-output, "
                                   "--normals-output or --explain-pixel)"));

    rl::Diagnostics diagnostics;
    std::shared_ptr<const rl::Scene> scene;
    if (int code = sceneOptions.load(parser, settings, err, diagnostics, scene); code != ExitOk)
        return code;
    if (!sceneOptions.anyFile(parser)) out << "rendering the embedded default scene\n";
    if (frames > 0)
        return renderAnimation(*scene, animation, frames, framesPerSecond, parser.value(output),
                               diagnostics, out, err);
    if (animationOptions.any(parser)) scene = animatedScene(*scene, animation, time);

    rl::RenderOptions options;
    options.shading.keepNormals = parser.isSet(normalsOutput);
    // The image needs no z-buffer after the depth test; --depth-output does, and the painter's
    // comparison with the z-buffer render below reads this frame's (kept, it need not render
    // the painter's frame again). --explain-pixel's recording frame keeps it anyway.
    options.keepDepth = parser.isSet(depthOutput) || settings.shading == rl::ShadingModel::Painter;
    // Nor the ids and barycentrics of the winning fragments, but for the painter's comparison
    // and the normals image: then the depth test and shading may run band by band.
    options.keepFragments = options.keepDepth || parser.isSet(normalsOutput);
    // Nor what only the window's views read: the normals no draw's shading reads (all are
    // kept for the normals image) and the vertices' NDC and unsnapped positions.
    options.keepForViews = false;
    // With --explain-pixel the one render records that pixel's events; the recording probe
    // leaves every buffer as the plain render would.
    std::optional<rl::RecordingProbe> probe;
    if (parser.isSet(explain)) probe = rl::RecordingProbe::forPixel(explainX, explainY);
    auto trace = probe ? rl::traceFrame(scene, options, *probe) : rl::renderFrame(scene, options);
    if (!trace) {
        printDiagnostics(diagnostics, err);
        return inputError(err, trace.error());
    }
    diagnostics.append(trace->diagnostics);
    printDiagnostics(diagnostics, err);
    if (const std::size_t mirrored = rl::trianglesBehindEye(*trace->projection, *scene);
        mirrored > 0 && rl::everyTriangleBehind(*trace->projection, *scene))
        err << "hint: --naive-projection draws the " << mirrored
            << " triangles behind the eye with seed 000's plain divide\n";

    const rl::Rgba8Image colour =
        rl::colourImage(*trace->shading, *trace->depth, scene->conventions);
    if (!writePng(colour, parser.value(output), out, err, lit("image"))) return ExitBadInput;
    if (parser.isSet(depthOutput)) {
        const rl::DepthRange range = rl::depthRange(trace->depth->depth);
        if (!writePng(rl::depthImage(trace->depth->depth, range), parser.value(depthOutput), out,
                      err, lit("z-buffer")))
            return ExitBadInput;
        if (!range.empty)
            out << "  z-buffer range: " << range.nearest << " (white) to " << range.farthest
                << " (dark grey)\n";
    }
    if (parser.isSet(normalsOutput) &&
        !writePng(rl::normalImage(trace->shading->normal, *trace->depth),
                  parser.value(normalsOutput), out, err, lit("normals")))
        return ExitBadInput;

    out << "  " << scene->triangleCount() << " triangles, "
        << rl::shadingModelName(settings.shading) << " shading, " << trace->depth->coveredPixels()
        << " pixels covered, " << QString::number(trace->totalMilliseconds, 'f', 1) << " ms\n";
    if (settings.shading == rl::ShadingModel::Painter) {
        // One more render, with the z-buffer, to show what the order got wrong (the painter's
        // is this one).
        const auto comparison =
            rl::compareWithZBuffer(std::make_shared<const rl::FrameTrace>(trace.value()), options);
        if (!comparison) return inputError(err, comparison.error());
        out << "  painter: " << comparison->differing << " pixels differ from the z-buffer render ("
            << comparison->wrongOrder << " where a farther triangle was painted last, "
            << comparison->ties << " where two triangles are as near)\n";
        if (parser.isSet(painterDiff) &&
            !writePng(rl::differenceImage(*comparison), parser.value(painterDiff), out, err,
                      lit("painter difference")))
            return ExitBadInput;
    }

    if (probe) out << QString::fromStdString(rl::explainPixel(trace.value(), *probe));
    out.flush();
    return ExitOk;
}

int runCommandFile(const QStringList& arguments, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        lit("Run a command file and write the PNG images it names (8-bit RGBA, untouched "
            "pixels transparent black)."));
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({lit("h"), lit("help")}, lit("Show this help."));
    const QCommandLineOption outdir(lit("outdir"),
                                    lit("The folder to write the images into (default: the "
                                        "current folder)."),
                                    lit("DIR"), lit("."));
    const QCommandLineOption maxPixels(lit("max-pixels"),
                                       lit("Refuse images with more pixels than this "
                                           "(default 40000000)."),
                                       lit("N"), QString::number(kDefaultMaxPixels));
    const QCommandLineOption explain(lit("explain-pixel"),
                                     lit("Print the story of one pixel of each image: the "
                                         "triangles that covered it, each depth test, and its "
                                         "lighting."),
                                     lit("X,Y"));
    parser.addOptions({help, outdir, maxPixels, explain});
    parser.addPositionalArgument(lit("FILE"), lit("The command file."));
    if (!parser.parse(arguments)) return usageError(err, parser.errorText());
    if (parser.isSet(help)) {
        out << commandHelp(parser, lit("run"));
        return ExitOk;
    }
    const QStringList files = parser.positionalArguments();
    if (files.size() != 1)
        return usageError(err, files.isEmpty()
                                   ? lit("run needs a command file")
                                   : lit("run takes one command file, found %1").arg(files.size()));
    bool maxOk = false;
    const qint64 pixelLimit = parser.value(maxPixels).toLongLong(&maxOk);
    if (!maxOk || pixelLimit < 1)
        return usageError(err, lit("--max-pixels expects a positive whole number, found '%1'")
                                   .arg(parser.value(maxPixels)));

    int explainX = -1, explainY = -1;
    if (parser.isSet(explain) && !parsePixel(parser.value(explain), explainX, explainY))
        return usageError(err, lit("--explain-pixel expects X,Y such as 400,300, found '%1'")
                                   .arg(parser.value(explain)));

    rl::Diagnostics diagnostics;
    auto file = loadCommandFile(files.first(), diagnostics);
    if (!file) {
        printDiagnostics(diagnostics, err);
        return inputError(err, file.error());
    }
    printDiagnostics(diagnostics, err);
    const QDir folder(parser.value(outdir));
    if (!QDir().mkpath(folder.path())) {
        err << folder.path() << ": cannot create the folder\n";
        return ExitBadInput;
    }
    for (const rl::Hw2Image& image : file->images) {
        const rl::Scene& scene = image.scene;
        if (qint64(scene.width) * scene.height > pixelLimit)
            return inputError(
                err, rl::makeError(
                         rl::ErrorCode::Range, image.where,
                         "the image " + std::to_string(scene.width) + "x" +
                             std::to_string(scene.height) + " has more pixels than the limit of " +
                             std::to_string(pixelLimit) + " (raise it with --max-pixels)"));
        const bool explainHere =
            parser.isSet(explain) && explainX < scene.width && explainY < scene.height;
        std::optional<rl::RecordingProbe> probe;
        if (explainHere) probe = rl::RecordingProbe::forPixel(explainX, explainY);
        auto shared = std::make_shared<const rl::Scene>(scene);
        // The image alone is written: no z-buffer, ids or barycentrics are kept, and each
        // draw gets only the normals its shading reads (the recording probe keeps them all).
        rl::RenderOptions options;
        options.keepDepth = false;
        options.keepFragments = false;
        options.keepForViews = false;
        auto trace = probe ? rl::traceFrame(shared, {}, *probe) : rl::renderFrame(shared, options);
        if (!trace) return inputError(err, trace.error());
        printDiagnostics(trace->diagnostics, err);
        const QString name = QString::fromStdString(image.fileName);
        if (!writePng(rl::colourImage(*trace->shading, *trace->depth, scene.conventions),
                      folder.filePath(name), out, err, lit("image")))
            return ExitBadInput;
        out << "  " << scene.triangleCount() << " triangles in " << scene.draws.size() << " draws, "
            << trace->depth->coveredPixels() << " pixels covered, "
            << QString::number(trace->totalMilliseconds, 'f', 1) << " ms\n";
        if (probe)
            out << QString::fromStdString(rl::explainPixel(trace.value(), *probe));
        else if (parser.isSet(explain))
            err << "rasterlab-cli: --explain-pixel " << parser.value(explain) << " is outside the "
                << scene.width << "x" << scene.height << " image " << name << '\n';
    }
    out.flush();
    return ExitOk;
}

// A line of /proc/self/status in MiB (VmRSS: resident now, VmHWM: resident at its peak),
// or -1 where the system has no such file.
double memoryMiB(const char* key) {
    QFile status(lit("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly | QIODevice::Text)) return -1.0;
    const QByteArray wanted(key);
    for (const QByteArray& line : status.readAll().split('\n')) {
        if (!line.startsWith(wanted)) continue;
        const QList<QByteArray> fields = line.mid(wanted.size()).simplified().split(' ');
        bool ok = false;
        const double kib = fields.value(0).toDouble(&ok);
        return ok ? kib / 1024.0 : -1.0;
    }
    return -1.0;
}

int runBench(const QStringList& arguments, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        lit("Render a scene again and again and print the time per frame: median, fastest "
            "and slowest of --frames frames after --warmup untimed ones, shaded pixels and "
            "triangles per second, and the time of each stage."));
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({lit("h"), lit("help")}, lit("Show this help."));
    const SceneOptions sceneOptions;
    const QCommandLineOption sceneName = SceneOptions::generatedSceneOption();
    const QCommandLineOption frames(lit("frames"), lit("Timed frames (default 21)."), lit("N"),
                                    lit("21"));
    const QCommandLineOption warmup(lit("warmup"), lit("Untimed frames first (default 1)."),
                                    lit("N"), lit("1"));
    const QCommandLineOption threads(
        lit("threads"), lit("Threads to render with (default: every core)."), lit("N"));
    const QCommandLineOption format(lit("format"), lit("md (default) or json."), lit("FORMAT"),
                                    lit("md"));
    const QCommandLineOption keepDepth(
        lit("keep-depth"),
        lit("Keep the whole z-buffer and the winning fragments in memory, as the window does "
            "(by default only the band of rows a thread is testing is kept, shaded as soon as it "
            "is tested when that pays, as render does without --depth-output)."));
    parser.addOption(help);
    sceneOptions.addTo(parser);
    parser.addOptions({sceneName, frames, warmup, threads, format, keepDepth});
    if (!parser.parse(arguments)) return usageError(err, parser.errorText());
    if (parser.isSet(help)) {
        out << commandHelp(parser, lit("bench"));
        return ExitOk;
    }
    if (!parser.positionalArguments().isEmpty())
        return usageError(
            err, lit("unexpected argument '%1'").arg(parser.positionalArguments().first()));
    rl::CourseSceneSettings settings;
    if (int code = sceneOptions.settings(parser, err, settings); code != ExitOk) return code;
    const auto count = [&](const QCommandLineOption& option, int least, int& value) {
        bool ok = false;
        value = parser.value(option).toInt(&ok);
        return ok && value >= least;
    };
    int frameCount = 0, warmupCount = 0, threadCount = 0;
    if (!count(frames, 1, frameCount))
        return usageError(err, lit("--frames expects a whole number of at least 1, found '%1'")
                                   .arg(parser.value(frames)));
    if (!count(warmup, 0, warmupCount))
        return usageError(err, lit("--warmup expects a whole number of at least 0, found '%1'")
                                   .arg(parser.value(warmup)));
    if (parser.isSet(threads) && (!count(threads, 1, threadCount) || threadCount > rl::kMaxThreads))
        return usageError(err, lit("--threads expects a whole number from 1 to %1, found '%2'")
                                   .arg(rl::kMaxThreads)
                                   .arg(parser.value(threads)));
    const QString outputFormat = parser.value(format);
    if (outputFormat != lit("md") && outputFormat != lit("json"))
        return usageError(err, lit("--format expects md or json, found '%1'").arg(outputFormat));

    rl::Diagnostics diagnostics;
    std::shared_ptr<const rl::Scene> scene;
    QString sceneLabel;
    if (int code =
            sceneOptions.loadAny(parser, sceneName, settings, err, diagnostics, scene, sceneLabel);
        code != ExitOk)
        return code;
    printDiagnostics(diagnostics, err);

    rl::RenderOptions options;
    options.threads = threadCount;  // 0: every core
    options.keepDepth = parser.isSet(keepDepth);
    options.keepFragments = options.keepDepth;
    options.keepForViews = false;
    rl::RenderContext context;  // buffers reused from frame to frame
    std::vector<double> total;
    std::vector<std::array<double, rl::kStageCount>> stages;
    std::size_t covered = 0, fragments = 0;
    bool inBands = false;  // depth test and shading run together (RenderOptions::keepFragments)
    std::size_t triangleNormalsLeftOut = 0, vertexNormalsLeftOut = 0;  // draws (normalsRead)
    int usedThreads = 0;
    double firstRss = -1.0;  // resident memory after the first timed frame, MiB
    for (int i = 0; i < warmupCount + frameCount; ++i) {
        auto trace = rl::renderFrame(scene, options, &context);
        if (!trace) return inputError(err, trace.error());
        if (i < warmupCount) continue;
        total.push_back(trace->totalMilliseconds);
        stages.push_back(trace->stageMilliseconds);
        // Counted on the last frame only: reading the whole triangle buffer between frames
        // would bring it into the cache for the next one.
        if (i + 1 == warmupCount + frameCount) covered = trace->depth->coveredPixels();
        inBands = !trace->depth->fragmentsKept;
        triangleNormalsLeftOut = trace->normals->triangleNormalsLeftOut;
        vertexNormalsLeftOut = trace->normals->vertexNormalsLeftOut;
        fragments = trace->depth->fragments;
        usedThreads = trace->threads;
        if (i == warmupCount) firstRss = memoryMiB("VmRSS:");
    }
    // Memory: the peak over the whole run (scene included), and whether the frames after
    // the first one added any.
    const double lastRss = memoryMiB("VmRSS:");
    const double peakRss = memoryMiB("VmHWM:");
    const auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    };
    const double medianMs = median(total);
    const double minMs = *std::min_element(total.begin(), total.end());
    const double maxMs = *std::max_element(total.begin(), total.end());
    std::array<double, rl::kStageCount> stageMedian{};
    for (std::size_t k = 0; k < stageMedian.size(); ++k) {
        std::vector<double> v;
        for (const auto& f : stages) v.push_back(f[k]);
        stageMedian[k] = median(v);
    }
    const double mpixels = double(covered) / (medianMs * 1e3);
    const double triangles = double(scene->triangleCount()) / (medianMs / 1e3);
    const QString shadingName = QString::fromUtf8(rl::shadingModelName(settings.shading));
    const auto number = [](double v, int decimals) { return QString::number(v, 'f', decimals); };
    if (outputFormat == lit("json")) {
        out << "{\"scene\": \"" << sceneLabel << "\", \"shading\": \"" << shadingName
            << "\", \"width\": " << scene->width << ", \"height\": " << scene->height
            << ", \"triangles\": " << scene->triangleCount() << ", \"threads\": " << usedThreads
            << ", \"frames\": " << frameCount
            << ", \"z_buffer_kept\": " << (options.keepDepth ? "true" : "false")
            << ", \"shaded_in_bands\": " << (inBands ? "true" : "false")
            << ", \"draws_without_triangle_normals\": " << triangleNormalsLeftOut
            << ", \"draws_without_vertex_normals\": " << vertexNormalsLeftOut
            << ", \"median_ms\": " << number(medianMs, 3) << ", \"min_ms\": " << number(minMs, 3)
            << ", \"max_ms\": " << number(maxMs, 3) << ", \"covered_pixels\": " << covered
            << ", \"fragments\": " << fragments << ", \"mpixels_per_s\": " << number(mpixels, 2)
            << ", \"triangles_per_s\": " << number(triangles, 0)
            << ", \"peak_rss_mib\": " << number(peakRss, 1)
            << ", \"rss_first_frame_mib\": " << number(firstRss, 1)
            << ", \"rss_last_frame_mib\": " << number(lastRss, 1) << ", \"stages_ms\": {";
        for (std::size_t k = 0; k < stageMedian.size(); ++k)
            out << (k ? ", " : "") << "\"" << rl::stageName(rl::kAllStages[k])
                << "\": " << number(stageMedian[k], 3);
        out << "}}\n";
    } else {
        out << "| scene | size | shading | threads | triangles | median ms | min ms | max ms | "
               "shaded Mpixel/s | triangles/s |\n"
            << "|---|---|---|---|---|---|---|---|---|---|\n"
            << "| " << sceneLabel << " | " << scene->width << "x" << scene->height << " | "
            << shadingName << " | " << usedThreads << " | " << scene->triangleCount() << " | "
            << number(medianMs, 2) << " | " << number(minMs, 2) << " | " << number(maxMs, 2)
            << " | " << number(mpixels, 1) << " | " << number(triangles, 0) << " |\n\n"
            << "Memory: peak " << number(peakRss, 1) << " MiB resident; " << number(firstRss, 1)
            << " MiB after the first timed frame, " << number(lastRss, 1)
            << " MiB after the last. Z-buffer: "
            << (options.keepDepth ? "kept whole (--keep-depth)"
                                  : "a band of rows per thread, in the cache")
            << "."
            << (inBands ? " Depth test and shading: together, each chunk of rows shaded by the "
                          "thread that tested it, from its band (the two stages' times are "
                          "their sum split as the threads spent it)."
                        : "")
            << (triangleNormalsLeftOut + vertexNormalsLeftOut > 0
                    ? lit(" Normals: only those the shading reads (left out: the triangles' of "
                          "%1 draw(s), the vertices' of %2).")
                          .arg(triangleNormalsLeftOut)
                          .arg(vertexNormalsLeftOut)
                    : QString())
            << "\n\n"
            << "| stage | median ms |\n|---|---|\n";
        for (std::size_t k = 0; k < stageMedian.size(); ++k)
            out << "| " << rl::stageName(rl::kAllStages[k]) << " | " << number(stageMedian[k], 3)
                << " |\n";
    }
    out.flush();
    return ExitOk;
}

// A list of whole numbers such as "1,2,4", each from least to most.
bool parseList(const QString& text, int least, int most, std::vector<int>& values) {
    values.clear();
    for (const QString& part : text.split(QLatin1Char(','))) {
        bool ok = false;
        const int v = part.trimmed().toInt(&ok);
        if (!ok || v < least || v > most) return false;
        if (std::find(values.begin(), values.end(), v) == values.end()) values.push_back(v);
    }
    return !values.empty();
}

QString jsonNumber(double v, int decimals) {
    return std::isfinite(v) ? QString::number(v, 'f', decimals) : lit("null");
}

int runAccuracy(const QStringList& arguments, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        lit("Render a scene in each mode (flat, Gouraud and Phong under the course, gpu and hw2 "
            "rules, optionally supersampled), time each (median of --repeats frames) and compare "
            "it with an exact reference: a ray cast per sample in double precision, exact "
            "barycentrics, perspective-correct attributes, the same lighting formula. Colours "
            "are compared as displayed, clamped and scaled to 0..1: RMSE, largest error and PSNR "
            "over the pixels both cover, the share of pixels whose coverage differs, the share "
            "within 1/255, and the relative error of the depth. --shading and --rules, when given, "
            "keep only that shading model or rule set."));
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({lit("h"), lit("help")}, lit("Show this help."));
    const SceneOptions sceneOptions;
    const QCommandLineOption sceneName = SceneOptions::generatedSceneOption();
    const QCommandLineOption format(lit("format"), lit("md (default), csv or json."), lit("FORMAT"),
                                    lit("md"));
    const QCommandLineOption plot(lit("plot"), lit("Also draw error against time to a PNG."),
                                  lit("FILE.png"));
    const QCommandLineOption heatmaps(
        lit("heatmaps"),
        lit("Also write each mode's error heat map to DIR (error-<mode>.png: 0 to 8 byte "
            "steps, dark blue to white; magenta where only one of the two covers a pixel)."),
        lit("DIR"));
    const QCommandLineOption repeats(lit("repeats"),
                                     lit("Frames timed per mode; the median is reported "
                                         "(default 5)."),
                                     lit("N"), lit("5"));
    const QCommandLineOption supersample(
        lit("supersample"),
        lit("Samples per pixel axis to measure, a list such as 1,2,4 (default 1): 2 is 2x2 "
            "samples averaged, for the render and the reference alike."),
        lit("LIST"), lit("1"));
    const QCommandLineOption threads(
        lit("threads"), lit("Threads to render with (default: every core)."), lit("N"));
    parser.addOption(help);
    sceneOptions.addTo(parser);
    parser.addOptions({sceneName, format, plot, heatmaps, repeats, supersample, threads});
    if (!parser.parse(arguments)) return usageError(err, parser.errorText());
    if (parser.isSet(help)) {
        out << commandHelp(parser, lit("accuracy"));
        return ExitOk;
    }
    if (!parser.positionalArguments().isEmpty())
        return usageError(
            err, lit("unexpected argument '%1'").arg(parser.positionalArguments().first()));
    rl::CourseSceneSettings settings;
    if (int code = sceneOptions.settings(parser, err, settings); code != ExitOk) return code;
    const QString outputFormat = parser.value(format);
    if (outputFormat != lit("md") && outputFormat != lit("csv") && outputFormat != lit("json"))
        return usageError(err,
                          lit("--format expects md, csv or json, found '%1'").arg(outputFormat));
    std::vector<int> repeatList, samples;
    if (!parseList(parser.value(repeats), 1, 1000, repeatList) || repeatList.size() != 1)
        return usageError(err, lit("--repeats expects a whole number from 1 to 1000, found '%1'")
                                   .arg(parser.value(repeats)));
    if (!parseList(parser.value(supersample), 1, 8, samples))
        return usageError(err, lit("--supersample expects whole numbers from 1 to 8 separated "
                                   "by commas, such as 1,2,4, found '%1'")
                                   .arg(parser.value(supersample)));
    int threadCount = 0;
    if (parser.isSet(threads)) {
        bool ok = false;
        threadCount = parser.value(threads).toInt(&ok);
        if (!ok || threadCount < 1 || threadCount > rl::kMaxThreads)
            return usageError(err, lit("--threads expects a whole number from 1 to %1, found '%2'")
                                       .arg(rl::kMaxThreads)
                                       .arg(parser.value(threads)));
    }
    if (parser.isSet(plot) && !qobject_cast<QGuiApplication*>(QCoreApplication::instance()))
        return usageError(err, lit("--plot needs the program's own start-up (run rasterlab-cli)"));

    rl::Diagnostics diagnostics;
    std::shared_ptr<const rl::Scene> scene;
    QString sceneLabel;
    if (int code =
            sceneOptions.loadAny(parser, sceneName, settings, err, diagnostics, scene, sceneLabel);
        code != ExitOk)
        return code;
    printDiagnostics(diagnostics, err);

    std::vector<rl::ShadingModel> shadings = {rl::ShadingModel::Flat, rl::ShadingModel::Gouraud,
                                              rl::ShadingModel::Phong};
    if (parser.isSet(sceneOptions.shading)) shadings = {settings.shading};
    std::vector<rl::RuleSet> ruleSets = {rl::RuleSet::Course, rl::RuleSet::Gpu, rl::RuleSet::Hw2};
    if (parser.isSet(sceneOptions.rules)) ruleSets = {*rl::ruleSetOf(settings.rules)};
    rl::AccuracyOptions options;
    options.modes = rl::defaultAccuracyModes(shadings, ruleSets, samples);
    options.repeats = repeatList.front();
    options.threads = threadCount;
    options.keepErrorMaps = parser.isSet(heatmaps);
    auto report = rl::measureAccuracy(*scene, options);
    if (!report) return inputError(err, report.error());

    const auto number = [](double v, int decimals) { return QString::number(v, 'f', decimals); };
    if (outputFormat == lit("json")) {
        out << "[";
        bool first = true;
        for (const rl::AccuracyRow& row : report->rows) {
            const rl::AccuracyMetrics& m = row.metrics;
            out << (first ? "\n" : ",\n") << "  {\"mode\": \""
                << rl::shadingModelName(row.mode.shading) << "\", \"rules\": \""
                << rl::ruleSetName(row.mode.rules) << "\", \"precision\": \""
                << QString::fromStdString(row.precision)
                << "\", \"supersample\": " << row.mode.supersample * row.mode.supersample
                << ", \"ms\": " << number(row.milliseconds, 3)
                << ", \"rmse\": " << jsonNumber(m.rmse, 7)
                << ", \"max_error\": " << jsonNumber(m.maxError, 7)
                << ", \"psnr\": " << jsonNumber(m.psnr, 2)
                << ", \"coverage_mismatch\": " << jsonNumber(m.coverageMismatchShare(), 6)
                << ", \"within_1_255\": " << jsonNumber(m.within1Of255, 6)
                << ", \"depth_error_mean\": " << jsonNumber(m.depthMeanRelative, 9)
                << ", \"depth_error_max\": " << jsonNumber(m.depthMaxRelative, 9)
                << ", \"worst_x\": " << m.worstX << ", \"worst_y\": " << m.worstY
                << ", \"both_covered\": " << m.bothCovered
                << ", \"either_covered\": " << m.eitherCovered
                << ", \"coverage_mismatch_pixels\": " << m.coverageMismatch << "}";
            first = false;
        }
        out << "\n]\n";
    } else if (outputFormat == lit("csv")) {
        out << "mode,rules,precision,supersample,ms,rmse,max_error,psnr,coverage_mismatch,"
               "within_1_255,depth_error_mean,depth_error_max\n";
        for (const rl::AccuracyRow& row : report->rows) {
            const rl::AccuracyMetrics& m = row.metrics;
            out << rl::shadingModelName(row.mode.shading) << "," << rl::ruleSetName(row.mode.rules)
                << "," << QString::fromStdString(row.precision) << ","
                << row.mode.supersample * row.mode.supersample << "," << number(row.milliseconds, 3)
                << "," << number(m.rmse, 7) << "," << number(m.maxError, 7) << ","
                << (std::isfinite(m.psnr) ? number(m.psnr, 2) : lit("inf")) << ","
                << number(m.coverageMismatchShare(), 6) << "," << number(m.within1Of255, 6) << ","
                << number(m.depthMeanRelative, 9) << "," << number(m.depthMaxRelative, 9) << "\n";
        }
    } else {
        out << "Accuracy of " << sceneLabel << " at " << scene->width << "x" << scene->height
            << " (" << scene->triangleCount() << " triangles) against the exact reference ("
            << report->referenceRays << " rays, " << number(report->referenceMilliseconds, 0)
            << " ms). Colour errors in byte steps (1/255) over the pixels both cover; time is "
               "the median per frame.\n\n"
            << "| mode | rules | precision | samples | ms | RMSE | max error | PSNR dB | "
               "coverage mismatch | within 1/255 | depth error mean / max |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|\n";
        for (const rl::AccuracyRow& row : report->rows) {
            const rl::AccuracyMetrics& m = row.metrics;
            out << "| " << rl::shadingModelName(row.mode.shading) << " | "
                << rl::ruleSetName(row.mode.rules) << " | " << QString::fromStdString(row.precision)
                << " | " << row.mode.supersample * row.mode.supersample << " | "
                << number(row.milliseconds, 2) << " | " << number(m.rmse * 255.0, 4) << " | "
                << number(m.maxError * 255.0, 3)
                << (m.worstX >= 0 ? lit(" at (%1, %2)").arg(m.worstX).arg(m.worstY) : QString())
                << " | " << (std::isfinite(m.psnr) ? number(m.psnr, 1) : lit("inf")) << " | "
                << number(100.0 * m.coverageMismatchShare(), 3) << " % (" << m.coverageMismatch
                << " px) | " << number(100.0 * m.within1Of255, 3) << " % | "
                << (std::isnan(m.depthMeanRelative)
                        ? lit("-")
                        : QString::number(m.depthMeanRelative, 'g', 2) + lit(" / ") +
                              QString::number(m.depthMaxRelative, 'g', 2))
                << " |\n";
        }
    }
    if (parser.isSet(plot)) {
        const QString title = lit("Error against run time: %1, %2x%3, %4 triangles")
                                  .arg(sceneLabel)
                                  .arg(scene->width)
                                  .arg(scene->height)
                                  .arg(scene->triangleCount());
        QString error;
        if (!savePng(accuracyPlot(report.value(), title), parser.value(plot), &error)) {
            err << parser.value(plot) << ": cannot write the plot: " << error << "\n";
            return ExitBadInput;
        }
        out << "wrote " << QFileInfo(parser.value(plot)).absoluteFilePath() << " (plot)\n";
    }
    if (parser.isSet(heatmaps)) {
        const QDir folder(parser.value(heatmaps));
        if (!QDir().mkpath(folder.path())) {
            err << folder.path() << ": cannot create the folder\n";
            return ExitBadInput;
        }
        for (const rl::AccuracyRow& row : report->rows) {
            QString name = QString::fromStdString(rl::accuracyModeName(row.mode));
            name.replace(QLatin1Char('/'), QLatin1Char('-')).replace(lit(" "), QString());
            const QString path = folder.filePath(lit("error-%1.png").arg(name));
            // One scale for every mode: 0 to 8 byte steps, larger errors white.
            QString error;
            if (!savePng(errorHeatMap(row.errorMap, 8.0f / 255.0f), path, &error)) {
                err << path << ": cannot write the heat map: " << error << "\n";
                return ExitBadInput;
            }
            out << "wrote " << QFileInfo(path).absoluteFilePath() << " (heat map)\n";
        }
    }
    out.flush();
    return ExitOk;
}

int runGenerateDefaultScene(const QStringList& arguments, QTextStream& out, QTextStream& err) {
    QCommandLineParser parser;
    parser.setApplicationDescription(lit("Write the default scene's three course files."));
    const QCommandLineOption help({lit("h"), lit("help")}, lit("Show this help."));
    const QCommandLineOption dir(lit("dir"), lit("The folder to write into (created if needed)."),
                                 lit("DIR"));
    parser.addOptions({help, dir});
    if (!parser.parse(arguments)) return usageError(err, parser.errorText());
    if (parser.isSet(help)) {
        out << commandHelp(parser, lit("generate-default-scene"));
        return ExitOk;
    }
    if (!parser.isSet(dir)) return usageError(err, lit("generate-default-scene needs --dir DIR"));
    const QDir folder(parser.value(dir));
    if (!QDir().mkpath(folder.path())) {
        err << folder.path() << ": cannot create the folder\n";
        return ExitBadInput;
    }
    const rl::CourseSceneTexts texts = rl::generateDefaultScene();
    const std::pair<const char*, const std::string*> files[] = {
        {rl::kDefaultCameraFile, &texts.camera},
        {rl::kDefaultLightingFile, &texts.lighting},
        {rl::kDefaultObjectFile, &texts.object},
    };
    for (const auto& [name, text] : files) {
        const QString path = folder.filePath(QString::fromUtf8(name));
        QSaveFile file(path);
        if (!file.open(QIODevice::WriteOnly) ||
            file.write(text->data(), static_cast<qint64>(text->size())) !=
                static_cast<qint64>(text->size()) ||
            !file.commit()) {
            err << path << ": cannot write: " << file.errorString() << '\n';
            return ExitBadInput;
        }
        out << "wrote " << QFileInfo(path).absoluteFilePath() << '\n';
    }
    return ExitOk;
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
            code = runRender(rest, out, err);
        else if (command == lit("bench"))
            code = runBench(rest, out, err);
        else if (command == lit("accuracy"))
            code = runAccuracy(rest, out, err);
        else if (command == lit("run"))
            code = runCommandFile(rest, out, err);
        else if (command == lit("generate-default-scene"))
            code = runGenerateDefaultScene(rest, out, err);
        else
            code = usageError(err, lit("unknown command '%1' (commands: render, run, bench, "
                                       "accuracy, generate-default-scene)")
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
