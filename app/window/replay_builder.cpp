#include "replay_builder.h"

#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

#include <exception>

#include "views/messages/pipeline_messages.h"

#ifdef Q_OS_LINUX
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace rasterlab {

namespace {

// The replay's thread yields to the renders and to the window: a drag in the Edit dock renders
// frame after frame while each one's replay is being built behind it. Linux gives each thread
// its own nice value; elsewhere the thread keeps the process's priority.
void yieldToRenders() {
#ifdef Q_OS_LINUX
    setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 10);
#endif
}

struct Outcome {
    std::shared_ptr<const rl::FrameReplay> replay;
    QString error;
    bool cancelled = false;
};

}  // namespace

ReplayBuilder::ReplayBuilder(QObject* parent) : QObject(parent) {
    // One build at a time, on a thread of its own: a frame being rendered never waits in the
    // shared pool behind replays that are still finishing after their cancel.
    m_pool.setMaxThreadCount(1);
    qRegisterMetaType<std::shared_ptr<const rl::FrameReplay>>();
    qRegisterMetaType<std::shared_ptr<const rl::FrameTrace>>();
}

ReplayBuilder::~ReplayBuilder() {
    cancel();
}

void ReplayBuilder::cancel() {
    if (m_cancel) m_cancel->store(true);
    m_cancel.reset();
}

void ReplayBuilder::build(std::shared_ptr<const rl::FrameTrace> frame) {
    cancel();
    auto flag = std::make_shared<std::atomic<bool>>(false);
    m_cancel = flag;
    if (m_busy++ == 0) emit busyChanged(true);
    auto* watcher = new QFutureWatcher<Outcome>(this);
    connect(watcher, &QFutureWatcher<Outcome>::finished, this, [this, watcher, flag, frame] {
        const Outcome outcome = watcher->result();
        watcher->deleteLater();
        const bool wanted = !flag->load() && !outcome.cancelled;
        if (wanted) {
            if (outcome.replay)
                emit built(outcome.replay);
            else
                emit failed(frame, outcome.error);
        }
        if (--m_busy == 0) emit busyChanged(false);
    });
    const rl::ReplayLimits copy = limits;
    watcher->setFuture(QtConcurrent::run(&m_pool, [frame, flag, copy] {
        yieldToRenders();
        Outcome outcome;
        try {
            auto replay = rl::FrameReplay::build(frame, copy, flag.get());
            if (flag->load()) {
                outcome.cancelled = true;
            } else if (replay) {
                outcome.replay = replay.value();
            } else {
                outcome.error = translated(replay.error().translatable);
            }
        } catch (const std::exception& e) {
            outcome.error = QString::fromUtf8(e.what());
        }
        return outcome;
    }));
}

}  // namespace rasterlab
