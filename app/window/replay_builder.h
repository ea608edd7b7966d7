// Builds the replay of a frame (pipeline/replay.h) on a worker thread, so that stepping is
// ready shortly after a frame is shown without the window ever waiting for it. A newer frame
// cancels the replay of an older one still being built; results of frames no longer wanted
// are dropped.
#pragma once

#include <QObject>
#include <QThreadPool>

#include <atomic>
#include <memory>

#include "pipeline/render/frame_trace.h"
#include "pipeline/render/replay.h"

namespace rasterlab {

class ReplayBuilder : public QObject {
    Q_OBJECT
public:
    explicit ReplayBuilder(QObject* parent = nullptr);
    ~ReplayBuilder() override;

    void build(std::shared_ptr<const rl::FrameTrace> frame);
    void cancel();  // the build under way, if any, is dropped
    bool isBusy() const { return m_busy > 0; }
    rl::ReplayLimits limits;

signals:
    void built(std::shared_ptr<const rl::FrameReplay> replay);
    void failed(std::shared_ptr<const rl::FrameTrace> frame, QString message);
    void busyChanged(bool busy);

private:
    QThreadPool m_pool;
    std::shared_ptr<std::atomic<bool>> m_cancel;
    int m_busy = 0;
};

}  // namespace rasterlab
