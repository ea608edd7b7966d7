#include "cli_common.h"

#include <QFileInfo>
#include <QRegularExpression>

#include <cmath>

#include "app/documents/default_scene_resource.h"
#include "app/documents/examples.h"
#include "app/image_io.h"
#include "pipeline/core/parallel.h"
#include "pipeline/scene/benchmark_scenes.h"

namespace rasterlab::cli {

namespace {

constexpr int kMaxImageSide = 16384;

QStringList benchmarkSceneNames() {
    QStringList names;
    for (const auto& s : rl::benchmarkScenes()) names << QString::fromStdString(s.name);
    return names;
}

bool parseSize(const QString& text, int& width, int& height) {
    static const QRegularExpression pattern(lit("^(\\d{1,6})[xX](\\d{1,6})$"));
    const auto match = pattern.match(text);
    if (!match.hasMatch()) return false;
    width = match.captured(1).toInt();
    height = match.captured(2).toInt();
    return true;
}

}  // namespace

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

QString number(double v, int decimals) {
    return QString::number(v, 'f', decimals);
}

QString jsonNumber(double v, int decimals) {
    return std::isfinite(v) ? number(v, decimals) : lit("null");
}

QString commandHelp(const QCommandLineParser& parser, const QString& command) {
    QString text = parser.helpText();
    const QString prefix = lit("Usage: ");
    const qsizetype end = text.indexOf(lit(" [options]"));
    const qsizetype lineEnd = text.indexOf(QLatin1Char('\n'));
    if (text.startsWith(prefix) && end > 0 && (lineEnd < 0 || end < lineEnd))
        text.replace(0, end, prefix + lit("rasterlab-cli ") + command);
    return text;
}

std::optional<int> parseSceneCommand(QCommandLineParser& parser, const QStringList& arguments,
                                     const QCommandLineOption& help, const QString& command,
                                     const SceneOptions& sceneOptions,
                                     const QCommandLineOption& sceneName,
                                     rl::CourseSceneSettings& settings, QTextStream& out,
                                     QTextStream& err) {
    if (!parser.parse(arguments)) return usageError(err, parser.errorText());
    if (parser.isSet(help)) {
        out << commandHelp(parser, command);
        return ExitOk;
    }
    if (!parser.positionalArguments().isEmpty())
        return usageError(
            err, lit("unexpected argument '%1'").arg(parser.positionalArguments().first()));
    if (int code = sceneOptions.settings(parser, err, settings); code != ExitOk) return code;
    sceneOptions.lessonSettings(parser, sceneName, settings);
    return std::nullopt;
}

std::optional<int> checkTableFormat(const QString& format, QTextStream& err) {
    if (format == lit("md") || format == lit("csv") || format == lit("json")) return std::nullopt;
    return usageError(err, lit("--format expects md, csv or json, found '%1'").arg(format));
}

std::optional<int> readThreads(const QCommandLineParser& parser, const QCommandLineOption& option,
                               int& threads, QTextStream& err) {
    if (!parser.isSet(option)) return std::nullopt;
    bool ok = false;
    threads = parser.value(option).toInt(&ok);
    if (ok && threads >= 1 && threads <= rl::kMaxThreads) return std::nullopt;
    return usageError(err, lit("--threads expects a whole number from 1 to %1, found '%2'")
                               .arg(rl::kMaxThreads)
                               .arg(parser.value(option)));
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
    if (!savePng(viewOf(image), path, &error)) {  // the image outlives the write
        err << path << ": cannot write the " << what << ": " << error << '\n';
        return false;
    }
    out << "wrote " << QFileInfo(path).absoluteFilePath() << " (" << what << ", " << image.width
        << "x" << image.height << ")\n";
    return true;
}

int readMaxPixels(const QCommandLineParser& parser, const QCommandLineOption& option,
                  QTextStream& err, qint64& limit) {
    bool ok = false;
    limit = parser.value(option).toLongLong(&ok);
    if (!ok || limit < 1)
        return usageError(err, lit("--max-pixels expects a positive whole number, found '%1'")
                                   .arg(parser.value(option)));
    return ExitOk;
}

int checkPixelLimit(const rl::Hw2Image& image, qint64 limit, QTextStream& err) {
    const rl::Scene& scene = image.scene;
    if (qint64(scene.width) * scene.height <= limit) return ExitOk;
    return inputError(
        err, rl::makeError(rl::ErrorCode::Range, image.where,
                           "the image " + std::to_string(scene.width) + "x" +
                               std::to_string(scene.height) + " has more pixels than the limit of " +
                               std::to_string(limit) + " (raise it with --max-pixels)"));
}

int SceneOptions::settings(const QCommandLineParser& parser, QTextStream& err,
                           rl::CourseSceneSettings& out) const {
    if (!parseSize(parser.value(size), out.width, out.height) || out.width < 1 || out.height < 1)
        return usageError(
            err,
            lit("--size expects WIDTHxHEIGHT such as 800x600, found '%1'").arg(parser.value(size)));
    if (out.width > kMaxImageSide || out.height > kMaxImageSide)
        return usageError(err, lit("--size %1 is larger than the limit of %2 pixels a side")
                                   .arg(parser.value(size))
                                   .arg(kMaxImageSide));
    qint64 pixelLimit = 0;
    if (int code = readMaxPixels(parser, maxPixels, err, pixelLimit); code != ExitOk) return code;
    if (qint64(out.width) * out.height > pixelLimit)
        return usageError(err, lit("--size %1 has %2 pixels, more than the limit of %3 (raise "
                                   "it with --max-pixels if the memory is there)")
                                   .arg(parser.value(size))
                                   .arg(qint64(out.width) * out.height)
                                   .arg(pixelLimit));
    const auto model = rl::shadingModelFromName(parser.value(shading).toStdString());
    if (!model)
        return usageError(err, lit("--shading expects phong, flat, gouraud or painter, found '%1'")
                                   .arg(parser.value(shading)));
    out.shading = *model;
    const auto ruleSet = rl::ruleSetFromName(parser.value(rules).toStdString());
    if (!ruleSet)
        return usageError(
            err, lit("--rules expects course, gpu or hw2, found '%1'").arg(parser.value(rules)));
    out.rules = rl::rulesOf(*ruleSet);
    if (parser.isSet(near)) {
        bool ok = false;
        const double z = parser.value(near).toDouble(&ok);
        if (!ok || !(z > 0.0))
            return usageError(
                err, lit("--near expects a positive number, found '%1'").arg(parser.value(near)));
        out.nearPlane.fixedW = z;
    }
    if (parser.isSet(naive)) out.nearPlane.mode = rl::NearPlane::Mode::Naive;
    if (parser.isSet(backFaces)) {
        const QString faces = parser.value(backFaces);
        if (faces != lit("draw") && faces != lit("cull"))
            return usageError(err, lit("--back-faces expects draw or cull, found '%1'").arg(faces));
        out.cullHiddenBackFaces = faces == lit("cull");
    }
    return ExitOk;
}

bool SceneOptions::anyFile(const QCommandLineParser& parser) const {
    return parser.isSet(camera) || parser.isSet(lighting) || parser.isSet(object);
}

int SceneOptions::load(const QCommandLineParser& parser, const rl::CourseSceneSettings& settings,
                       QTextStream& err, rl::Diagnostics& diagnostics,
                       std::shared_ptr<const rl::Scene>& scene) const {
    const auto cameraLayout = rl::cameraLayoutFromName(parser.value(cameraFormat).toStdString());
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

QStringList SceneOptions::generatedSceneNames() {
    QStringList names = exampleNames();
    for (const auto& s : rl::benchmarkScenes()) names << QString::fromStdString(s.name);
    return names;
}

QCommandLineOption SceneOptions::generatedSceneOption() {
    return {lit("scene"),
            lit("A shipped lesson (%1: its size, shading and near plane unless given) or a "
                "generated benchmark scene (%2) instead of course files.")
                .arg(exampleNames().join(lit(", ")), benchmarkSceneNames().join(lit(", "))),
            lit("NAME")};
}

void SceneOptions::lessonSettings(const QCommandLineParser& parser,
                                  const QCommandLineOption& sceneName,
                                  rl::CourseSceneSettings& settings) const {
    if (!parser.isSet(sceneName) || !isExample(parser.value(sceneName))) return;
    const Lesson lesson = exampleLesson(parser.value(sceneName));
    if (!parser.isSet(size) && lesson.imageSize) {
        settings.width = lesson.imageSize->width();
        settings.height = lesson.imageSize->height();
    }
    if (!parser.isSet(shading) && lesson.shading) settings.shading = *lesson.shading;
    if (!parser.isSet(near)) settings.nearPlane.fixedW = lesson.nearW;
    if (!parser.isSet(rules) && lesson.rules) settings.rules = rl::rulesOf(*lesson.rules);
}

namespace {

// A shipped lesson's three course files, embedded in the program.
int loadExample(const QString& name, const rl::CourseSceneSettings& settings, QTextStream& err,
                rl::Diagnostics& diagnostics, std::shared_ptr<const rl::Scene>& scene) {
    const QString folder = exampleFolder(name) + QLatin1Char('/');
    auto c = loadCamera(folder + lit("camera.cfg"), diagnostics);
    if (!c) return inputError(err, c.error());
    auto l = loadLighting(folder + lit("lighting.txt"), diagnostics);
    if (!l) return inputError(err, l.error());
    auto o = loadObject(folder + name + lit(".byu"), diagnostics);
    if (!o) return inputError(err, o.error());
    scene = std::make_shared<const rl::Scene>(
        rl::makeCourseScene({c.value(), l.value(), o.value()}, settings));
    return ExitOk;
}

}  // namespace

int SceneOptions::loadAny(const QCommandLineParser& parser, const QCommandLineOption& sceneName,
                          const rl::CourseSceneSettings& settings, QTextStream& err,
                          rl::Diagnostics& diagnostics, std::shared_ptr<const rl::Scene>& scene,
                          QString& sceneLabel) const {
    if (parser.isSet(sceneName)) {
        if (anyFile(parser))
            return usageError(err, lit("--scene replaces --camera, --lighting and --object"));
        if (isExample(parser.value(sceneName))) {
            sceneLabel = parser.value(sceneName);
            return loadExample(sceneLabel, settings, err, diagnostics, scene);
        }
        auto generated = rl::makeBenchmarkScene(parser.value(sceneName).toStdString(),
                                                settings.width, settings.height, settings.shading);
        if (!generated)
            return usageError(
                err, lit("--scene expects one of %1, found '%2'")
                         .arg(generatedSceneNames().join(lit(", ")), parser.value(sceneName)));
        if (parser.isSet(backFaces)) generated->cullHiddenBackFaces = settings.cullHiddenBackFaces;
        generated->rules = settings.rules;
        scene = std::make_shared<const rl::Scene>(std::move(*generated));
        sceneLabel = parser.value(sceneName);
        return ExitOk;
    }
    if (int code = load(parser, settings, err, diagnostics, scene); code != ExitOk) return code;
    sceneLabel = anyFile(parser) ? QString::fromStdString(scene->name) : lit("default scene");
    return ExitOk;
}

}  // namespace rasterlab::cli
