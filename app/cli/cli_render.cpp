// rasterlab-cli render: a course scene (or the default one) to PNG, with its z-buffer,
// normals, the story of a pixel, the painter's difference, or the frames of its animation.
#include "app/cli/cli_common.h"

#include <QDir>

#include <optional>

#include "pipeline/analysis/painter.h"
#include "pipeline/io/course_fields.h"
#include "pipeline/render/animation.h"
#include "pipeline/render/explain.h"
#include "pipeline/render/renderer.h"

namespace rasterlab::cli {

namespace {

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

}  // namespace

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
    const QCommandLineOption sceneName = SceneOptions::generatedSceneOption();
    parser.addOption(help);
    sceneOptions.addTo(parser);
    parser.addOptions({sceneName, output, depthOutput, normalsOutput, explain, painterDiff});
    animationOptions.addTo(parser);
    rl::CourseSceneSettings settings;
    if (auto code = parseSceneCommand(parser, arguments, help, lit("render"), sceneOptions,
                                      sceneName, settings, out, err))
        return *code;
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
    QString sceneLabel;
    if (int code =
            sceneOptions.loadAny(parser, sceneName, settings, err, diagnostics, scene, sceneLabel);
        code != ExitOk)
        return code;
    if (parser.isSet(sceneName))
        out << "rendering " << sceneLabel << '\n';
    else if (!sceneOptions.anyFile(parser))
        out << "rendering the embedded default scene\n";
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

    out << "  "
        << QString::fromStdString(rl::course_io::trianglesText(scene->triangleCount()).english())
        << ", " << rl::shadingModelName(settings.shading) << " shading, "
        << trace->depth->coveredPixels() << " pixels covered, "
        << QString::number(trace->totalMilliseconds, 'f', 1) << " ms\n";
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

}  // namespace rasterlab::cli
