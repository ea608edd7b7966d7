// rasterlab-cli bench: a scene's frames timed, per stage, with the memory used.
#include "app/cli/cli_common.h"

#include <QFile>

#include <algorithm>
#include <array>

#include "pipeline/core/multiversion.h"
#include "pipeline/core/parallel.h"
#include "pipeline/render/renderer.h"

namespace rasterlab::cli {

namespace {

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

// What the timed frames gave: their times, what they covered, the memory used.
struct BenchResult {
    std::size_t covered = 0, fragments = 0;
    bool inBands = false;  // depth test and shading run together (RenderOptions::keepFragments)
    int bandRows = 0;      // the rows of their bands (FrameTrace::bandRows)
    qint64 l2Kib = 0;      // the L2 cache a thread has (l2CachePerThread), 0: not known
    std::size_t triangleNormalsLeftOut = 0, vertexNormalsLeftOut = 0;  // draws (normalsRead)
    int usedThreads = 0;
    double firstRss = -1.0;  // resident memory after the first timed frame, MiB
    // Memory: the peak over the whole run (scene included), and whether the frames after
    // the first one added any.
    double lastRss = -1.0, peakRss = -1.0;
    double medianMs = 0.0, minMs = 0.0, maxMs = 0.0;
    std::array<double, rl::kStageCount> stageMedian{};
    double mpixels = 0.0, triangles = 0.0;  // shaded Mpixel/s and triangles/s at the median
};

// --warmup untimed frames, then --frames timed ones, the buffers reused from frame to frame.
// ExitOk with the result filled in, or the code of a frame that failed (already printed).
int timeFrames(const std::shared_ptr<const rl::Scene>& scene, const rl::RenderOptions& options,
               int warmupCount, int frameCount, QTextStream& err, BenchResult& result) {
    rl::RenderContext context;  // buffers reused from frame to frame
    std::vector<double> total;
    std::vector<std::array<double, rl::kStageCount>> stages;
    for (int i = 0; i < warmupCount + frameCount; ++i) {
        auto trace = rl::renderFrame(scene, options, &context);
        if (!trace) return inputError(err, trace.error());
        if (i < warmupCount) continue;
        total.push_back(trace->totalMilliseconds);
        stages.push_back(trace->stageMilliseconds);
        // Counted on the last frame only: reading the whole triangle buffer between frames
        // would bring it into the cache for the next one.
        if (i + 1 == warmupCount + frameCount) result.covered = trace->depth->coveredPixels();
        result.inBands = !trace->depth->fragmentsKept;
        result.bandRows = trace->bandRows;
        result.triangleNormalsLeftOut = trace->normals->triangleNormalsLeftOut;
        result.vertexNormalsLeftOut = trace->normals->vertexNormalsLeftOut;
        result.fragments = trace->depth->fragments;
        result.usedThreads = trace->threads;
        if (i == warmupCount) result.firstRss = memoryMiB("VmRSS:");
    }
    result.lastRss = memoryMiB("VmRSS:");
    result.l2Kib = qint64(rl::l2CachePerThread(result.usedThreads) / 1024);
    result.peakRss = memoryMiB("VmHWM:");
    const auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    };
    result.medianMs = median(total);
    result.minMs = *std::min_element(total.begin(), total.end());
    result.maxMs = *std::max_element(total.begin(), total.end());
    for (std::size_t k = 0; k < result.stageMedian.size(); ++k) {
        std::vector<double> v;
        for (const auto& f : stages) v.push_back(f[k]);
        result.stageMedian[k] = median(v);
    }
    result.mpixels = double(result.covered) / (result.medianMs * 1e3);
    result.triangles = double(scene->triangleCount()) / (result.medianMs / 1e3);
    return ExitOk;
}

// The result as one JSON object.
void printJson(const BenchResult& r, const rl::Scene& scene, const QString& sceneLabel,
               const QString& shadingName, int frameCount, bool keepDepth, QTextStream& out) {
    out << "{\"scene\": \"" << sceneLabel << "\", \"shading\": \"" << shadingName
        << "\", \"width\": " << scene.width << ", \"height\": " << scene.height
        << ", \"triangles\": " << scene.triangleCount() << ", \"threads\": " << r.usedThreads
        << ", \"frames\": " << frameCount
        << ", \"z_buffer_kept\": " << (keepDepth ? "true" : "false")
        << ", \"shaded_in_bands\": " << (r.inBands ? "true" : "false")
        << ", \"band_rows\": " << r.bandRows << ", \"l2_cache_per_thread_kib\": "
        << (r.l2Kib > 0 ? QString::number(r.l2Kib) : lit("null"))
        << ", \"draws_without_triangle_normals\": " << r.triangleNormalsLeftOut
        << ", \"draws_without_vertex_normals\": " << r.vertexNormalsLeftOut
        << ", \"median_ms\": " << number(r.medianMs, 3) << ", \"min_ms\": " << number(r.minMs, 3)
        << ", \"max_ms\": " << number(r.maxMs, 3) << ", \"covered_pixels\": " << r.covered
        << ", \"fragments\": " << r.fragments << ", \"mpixels_per_s\": " << number(r.mpixels, 2)
        << ", \"triangles_per_s\": " << number(r.triangles, 0)
        << ", \"peak_rss_mib\": " << number(r.peakRss, 1)
        << ", \"rss_first_frame_mib\": " << number(r.firstRss, 1)
        << ", \"rss_last_frame_mib\": " << number(r.lastRss, 1) << ", \"kernels\": \""
        << rl::kernelLevel() << "\", \"kernel_lanes\": " << rl::kernelLanes()
        << ", \"stages_ms\": {";
    for (std::size_t k = 0; k < r.stageMedian.size(); ++k)
        out << (k ? ", " : "") << "\"" << rl::stageName(rl::kAllStages[k])
            << "\": " << number(r.stageMedian[k], 3);
    out << "}}\n";
}

// The result as Markdown: the frame times, the memory, and each stage's time.
void printTable(const BenchResult& r, const rl::Scene& scene, const QString& sceneLabel,
                const QString& shadingName, bool keepDepth, QTextStream& out) {
    out << "| scene | size | shading | threads | triangles | median ms | min ms | max ms | "
           "shaded Mpixel/s | triangles/s |\n"
        << "|---|---|---|---|---|---|---|---|---|---|\n"
        << "| " << sceneLabel << " | " << scene.width << "x" << scene.height << " | " << shadingName
        << " | " << r.usedThreads << " | " << scene.triangleCount() << " | "
        << number(r.medianMs, 2) << " | " << number(r.minMs, 2) << " | " << number(r.maxMs, 2)
        << " | " << number(r.mpixels, 1) << " | " << number(r.triangles, 0) << " |\n\n"
        << "Memory: peak " << number(r.peakRss, 1) << " MiB resident; " << number(r.firstRss, 1)
        << " MiB after the first timed frame, " << number(r.lastRss, 1)
        << " MiB after the last. Z-buffer: "
        << (keepDepth ? "kept whole (--keep-depth)" : "a band of rows per thread, in the cache")
        << "."
        << (r.inBands
                ? lit(" Depth test and shading: together, each band of %1 row(s) shaded by "
                      "the thread that tested it (the two stages' times are their sum "
                      "split as the threads spent it; L2 cache: %2).")
                      .arg(r.bandRows)
                      .arg(r.l2Kib > 0 ? lit("%1 KiB a thread").arg(r.l2Kib) : lit("not known"))
                : QString())
        << (r.triangleNormalsLeftOut + r.vertexNormalsLeftOut > 0
                ? lit(" Normals: only those the shading reads (left out: the triangles' of "
                      "%1 draw(s), the vertices' of %2).")
                      .arg(r.triangleNormalsLeftOut)
                      .arg(r.vertexNormalsLeftOut)
                : QString())
        << " Kernels: " << rl::kernelLevel() << ", " << rl::kernelLanes()
        << " pixels at a time.\n\n"
        << "| stage | median ms |\n|---|---|\n";
    for (std::size_t k = 0; k < r.stageMedian.size(); ++k)
        out << "| " << rl::stageName(rl::kAllStages[k]) << " | " << number(r.stageMedian[k], 3)
            << " |\n";
}

}  // namespace

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
    const QCommandLineOption bandRows(
        lit("band-rows"),
        lit("Rows of the bands the depth test and shading run in together, 1 to %1 (default "
            "%1): fewer take less of the L2 cache a thread has.")
            .arg(rl::kRowChunk),
        lit("N"));
    const QCommandLineOption keepDepth(
        lit("keep-depth"),
        lit("Keep the whole z-buffer and the winning fragments in memory, as the window does "
            "(by default only the band of rows a thread is testing is kept, shaded as soon as it "
            "is tested when that pays, as render does without --depth-output)."));
    parser.addOption(help);
    sceneOptions.addTo(parser);
    parser.addOptions({sceneName, frames, warmup, threads, format, bandRows, keepDepth});
    rl::CourseSceneSettings settings;
    if (auto code = parseSceneCommand(parser, arguments, help, lit("bench"), sceneOptions,
                                      sceneName, settings, out, err))
        return *code;
    const auto count = [&](const QCommandLineOption& option, int least, int& value) {
        bool ok = false;
        value = parser.value(option).toInt(&ok);
        return ok && value >= least;
    };
    int frameCount = 0, warmupCount = 0, threadCount = 0, rowCount = 0;
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
    if (parser.isSet(bandRows) && (!count(bandRows, 1, rowCount) || rowCount > rl::kRowChunk))
        return usageError(err, lit("--band-rows expects a whole number from 1 to %1, found '%2'")
                                   .arg(rl::kRowChunk)
                                   .arg(parser.value(bandRows)));
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
    options.bandRows = rowCount;  // 0: a chunk's (kRowChunk)
    BenchResult result;
    if (int code = timeFrames(scene, options, warmupCount, frameCount, err, result); code != ExitOk)
        return code;
    const QString shadingName = QString::fromUtf8(rl::shadingModelName(settings.shading));
    if (outputFormat == lit("json"))
        printJson(result, *scene, sceneLabel, shadingName, frameCount, options.keepDepth, out);
    else
        printTable(result, *scene, sceneLabel, shadingName, options.keepDepth, out);
    out.flush();
    return ExitOk;
}

}  // namespace rasterlab::cli
