#include "render_controller.h"

#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

#include <exception>

#include "app/image_io.h"
#include "pipeline/render/output_image.h"
#include "views/messages/pipeline_messages.h"

namespace rasterlab {

namespace {

struct Outcome {
    quint64 generation = 0;
    RenderedFrame frame;
    QString error;
};

// The worker: nothing may escape it, not even std::bad_alloc.
Outcome renderOnWorker(quint64 generation, std::shared_ptr<const rl::Scene> scene,
                       rl::RenderOptions options) {
    Outcome outcome;
    outcome.generation = generation;
    outcome.frame.generation = generation;
    try {
        auto trace = rl::renderFrame(scene, options);
        if (!trace) {
            outcome.error = translated(trace.error());
            return outcome;
        }
        auto shared = std::make_shared<const rl::FrameTrace>(std::move(trace).value());
        outcome.frame.image =
            toQImage(rl::colourImage(*shared->shading, *shared->depth, scene->conventions));
        outcome.frame.trace = std::move(shared);
    } catch (const std::exception& e) {
        outcome.error = QStringLiteral("the render failed: %1").arg(QString::fromUtf8(e.what()));
    }
    return outcome;
}

}  // namespace

RenderController::RenderController(QObject* parent) : QObject(parent) {
    qRegisterMetaType<RenderedFrame>();
}

RenderController::~RenderController() = default;

void RenderController::request(std::shared_ptr<const rl::Scene> scene, rl::RenderOptions options) {
    Request request{m_nextGeneration++, std::move(scene), options};
    if (m_running) {
        m_pending = std::move(request);  // replaces any older pending request
        return;
    }
    start(std::move(request));
}

void RenderController::start(Request request) {
    if (!m_running) {
        m_running = true;
        emit busyChanged(true);
    }
    auto* watcher = new QFutureWatcher<Outcome>(this);
    connect(watcher, &QFutureWatcher<Outcome>::finished, this, [this, watcher] {
        const Outcome outcome = watcher->result();
        watcher->deleteLater();
        // A newer request may be waiting: start it first, so isBusy() is true while the
        // frame of this older one is shown (it is still newer than what is on screen).
        if (m_pending) {
            Request next = std::move(*m_pending);
            m_pending.reset();
            start(std::move(next));
        } else {
            m_running = false;
        }
        if (outcome.generation > m_shownGeneration) {
            m_shownGeneration = outcome.generation;
            if (outcome.error.isEmpty())
                emit frameReady(outcome.frame);
            else
                emit failed(outcome.error);
        }
        if (!m_running) emit busyChanged(false);
    });
    watcher->setFuture(QtConcurrent::run(renderOnWorker, request.generation,
                                         std::move(request.scene), request.options));
}

}  // namespace rasterlab
