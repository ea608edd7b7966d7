#include "replay_builder.h"

#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

#include <exception>

#include "pipeline_messages.h"

namespace rasterlab {

namespace {

struct Outcome {
    std::shared_ptr<const rl::FrameReplay> replay;
    QString error;
    bool cancelled = false;
};

}  // namespace

ReplayBuilder::ReplayBuilder(QObject* parent) : QObject(parent) {
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
    watcher->setFuture(QtConcurrent::run([frame, flag, copy] {
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
