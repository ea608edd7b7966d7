// Runs the pipeline on a worker thread so the window never freezes. The newest request
// wins: while a frame renders, further requests replace one another and only the last
// is rendered next; a result older than what is already shown is dropped. Results reach
// the UI thread as immutable snapshots.
#pragma once

#include <QImage>
#include <QObject>
#include <QString>

#include <memory>
#include <optional>

#include "pipeline/render/frame_trace.h"
#include "pipeline/render/renderer.h"
#include "pipeline/scene/scene.h"

namespace rasterlab {

struct RenderedFrame {
    std::shared_ptr<const rl::FrameTrace> trace;
    QImage image;  // the final colour image, 8-bit RGBA
    quint64 generation = 0;  // the request it answers (RenderController::lastRequest())
};

class RenderController : public QObject {
    Q_OBJECT
public:
    explicit RenderController(QObject* parent = nullptr);
    ~RenderController() override;

    void request(std::shared_ptr<const rl::Scene> scene, rl::RenderOptions options = {});
    bool isBusy() const { return m_running; }
    // The number of the last request made; frames carry the number of theirs.
    quint64 lastRequest() const { return m_nextGeneration - 1; }

signals:
    void frameReady(rasterlab::RenderedFrame frame);
    void failed(QString message);
    void busyChanged(bool busy);

private:
    struct Request {
        quint64 generation = 0;
        std::shared_ptr<const rl::Scene> scene;
        rl::RenderOptions options;
    };
    void start(Request request);

    quint64 m_nextGeneration = 1;
    quint64 m_shownGeneration = 0;
    bool m_running = false;
    std::optional<Request> m_pending;
};

}  // namespace rasterlab

Q_DECLARE_METATYPE(rasterlab::RenderedFrame)
