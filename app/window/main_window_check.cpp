// MainWindow's Check dock (File > Check My Renderer...): a student's program checked stage by
// stage on a worker (check_panel.h), and the stage strip's marks.
#include <QDir>
#include <QDockWidget>

#include <algorithm>

#include "app/window/check_panel.h"
#include "app/window/main_window.h"
#include "views/pixel_inspector.h"
#include "views/projection_view.h"
#include "views/scanline_view.h"
#include "views/stage_strip.h"
#include "views/zbuffer_view.h"

namespace rasterlab {

void MainWindow::setUpCheckDock(QDockWidget* beside) {
    m_check = new CheckPanel(m_inspection);
    m_checkDock = addDock(tr("Check"), QStringLiteral("checkDock"), m_check, Qt::LeftDockWidgetArea,
                          true, tr("Check your renderer"));
    tabifyDockWidget(beside, m_checkDock);
    m_checkDock->hide();
    connect(m_check, &CheckPanel::finished, this, &MainWindow::showCheckMarks);
    // Their frame in the Compare dock, through a PNG of its own as any image compared.
    connect(m_check, &CheckPanel::compareFrame, this, [this](const QImage& theirs) {
        const QString path = QDir(m_checkFrames.path()).filePath(QStringLiteral("their-frame.png"));
        if (!theirs.save(path, "PNG")) {
            showError(tr("Cannot write their frame to %1").arg(path));
            return;
        }
        compareWithImage(path);
    });
    // The marks belong to the scene checked: a new scene drops them.
    connect(m_inspection, &Inspection::frameChanged, this, [this] {
        const auto* report = m_check->report();
        const auto& frame = m_inspection->frame();
        if (!report || report->scenes.empty() || !frame || !frame->scene) return;
        if (frame->scene->name != report->scenes.front().name ||
            frame->scene->width != report->scenes.front().width ||
            frame->scene->height != report->scenes.front().height)
            m_stageStrip->setCheckMarks({});
    });
}

void MainWindow::showCheckMarks() {
    std::array<StageStrip::CheckMark, rl::kStageCount> marks{};
    for (rl::StageId stage : rl::kAllStages)
        if (const auto verdict = m_check->verdict(stage))
            marks[std::size_t(stage)] = *verdict == check::Verdict::Passed
                                            ? StageStrip::CheckMark::Passed
                                            : StageStrip::CheckMark::Failed;
    m_stageStrip->setCheckMarks(marks);
    const check::CheckReport* report = m_check->report();
    const auto departures = [report](check::Stage stage) {
        const check::StageResult* r = report ? report->result(stage) : nullptr;
        return r ? r->departures : std::vector<check::Departure>();
    };
    // The projection view draws their vertices over ours.
    std::vector<ProjectionCanvas::VertexPair> pairs;
    for (const check::Departure& d : departures(check::Stage::Projection))
        pairs.emplace_back(QPointF(d.ours.x, d.ours.y), QPointF(d.theirs.x, d.theirs.y));
    m_projection->canvas()->setTheirVertices(std::move(pairs));
    // The z-buffer view marks the pixels whose winner differs.
    std::vector<QPoint> pixels;
    for (const check::Departure& d : departures(check::Stage::ZBuffer))
        pixels.emplace_back(int(d.ours.x), int(d.ours.y));
    m_zbuffer->markPixels(pixels);
    // The scan view puts their span of the row shown beside ours.
    ScanlineView::TheirSpans spans;
    if (report && !report->scenes.empty())
        for (const check::Row& r : report->scenes.front().theirSpans) {
            const auto key = std::make_pair(std::uint32_t(r[0]), int(r[1]));
            const auto it = spans.find(key);
            spans[key] = it == spans.end() ? std::make_pair(int(r[2]), int(r[3]))
                                           : std::make_pair(std::min(it->second.first, int(r[2])),
                                                            std::max(it->second.second, int(r[3])));
        }
    m_scanline->setTheirSpans(m_check->checkedFrame(), std::move(spans));
    // The pixel inspector gives their colour at the pixel picked beside ours.
    m_inspector->setTheirFrame(m_check->checkedFrame(), m_check->theirFrame());
    if (!m_checkDock->isHidden()) m_checkDock->raise();
}

void MainWindow::showCheckDock() {
    // The first time, a window of its own over the left of this one, tall enough for the list,
    // the words and the picture; it can be docked like the others.
    if (!m_checkShown && m_checkDock->isHidden()) {
        m_checkShown = true;
        m_checkDock->setFloating(true);
        const QRect area = geometry();
        const QSize size(std::min(620, area.width() / 2), std::min(640, area.height() * 9 / 10));
        m_checkDock->setGeometry(
            QRect(area.topLeft() + QPoint(8, (area.height() - size.height()) / 2), size));
    }
    m_checkDock->show();
    m_checkDock->raise();
    if (m_check->command().isEmpty())
        m_check->findChild<QWidget*>(QStringLiteral("checkCommand"))->setFocus();
}

}  // namespace rasterlab
