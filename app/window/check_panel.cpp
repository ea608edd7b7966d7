#include "app/window/check_panel.h"

#include <QCheckBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include "views/inspection.h"

namespace rasterlab {

namespace {

QString text(const std::string& s) {
    return QString::fromStdString(s);
}

QColor departureColour(check::Departure::Kind kind) {
    switch (kind) {
        case check::Departure::Kind::OnlyOurs:
            return QColor(255, 0, 255);
        case check::Departure::Kind::OnlyTheirs:
            return QColor(0, 230, 255);
        case check::Departure::Kind::Different:
            return QColor(255, 40, 40);
        case check::Departure::Kind::Vertex:
            return QColor(255, 40, 40);
    }
    return Qt::red;
}

}  // namespace

CheckPanel::CheckPanel(Inspection* inspection, QWidget* parent)
    : QWidget(parent), m_inspection(inspection) {
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    m_command = new QLineEdit;
    m_command->setObjectName(QStringLiteral("checkCommand"));
    m_command->setPlaceholderText(tr("python3 stages.py"));
    m_command->setToolTip(
        tr("The command that starts your program, run by /bin/sh in the "
           "folder below; it answers the stage protocol on its standard "
           "input and output (docs/stage-protocol.md)."));
    form->addRow(tr("Command:"), m_command);
    auto* folderRow = new QHBoxLayout;
    m_folder = new QLineEdit;
    m_folder->setObjectName(QStringLiteral("checkFolder"));
    m_browse = new QPushButton(tr("Browse..."));
    folderRow->addWidget(m_folder, 1);
    folderRow->addWidget(m_browse);
    form->addRow(tr("Folder:"), folderRow);
    layout->addLayout(form);

    auto* buttons = new QHBoxLayout;
    m_run = new QPushButton(tr("Check"));
    m_run->setObjectName(QStringLiteral("checkRun"));
    m_cancel = new QPushButton(tr("Cancel"));
    m_cancel->setEnabled(false);
    m_stop = new QPushButton(tr("Stop at the First Departure"));
    m_stop->setToolTip(
        tr("Step the frame to where the selected stage first departs from "
           "the lecture's"));
    m_stop->setEnabled(false);
    m_progress = new QProgressBar;
    m_progress->setTextVisible(true);
    m_progress->setFormat(QString());
    m_chain = new QCheckBox(tr("Chained"));
    m_chain->setToolTip(
        tr("Give each stage your program's own earlier answers as its input, to "
           "see how errors add up (unticked, each stage gets RasterLab's, so no "
           "mistake hides another)"));
    // Two rows of buttons and the progress on a row of its own, so that the dock fits a
    // 1280x720 screen and the progress text ("goblet.byu: frame") its bar.
    buttons->addWidget(m_run);
    buttons->addWidget(m_chain);
    buttons->addWidget(m_cancel);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    auto* after = new QHBoxLayout;
    after->addWidget(m_stop);
    m_compare = new QPushButton(tr("Compare Their Frame"));
    m_compare->setToolTip(
        tr("Their whole frame in the Compare dock: each pixel's colour beside "
           "ours, and the Phong term that would have to change"));
    m_compare->setEnabled(false);
    after->addWidget(m_compare);
    after->addStretch(1);
    layout->addLayout(after);
    m_progress->setObjectName(QStringLiteral("checkProgress"));
    layout->addWidget(m_progress);

    m_protections = new QLabel;
    m_protections->setWordWrap(true);
    layout->addWidget(m_protections);
    // The list, the selected stage's words, and its picture, one above the other, resizable.
    auto* split = new QSplitter(Qt::Vertical);
    m_split = split;
    m_stages = new QTreeWidget;
    m_stages->setObjectName(QStringLiteral("checkStages"));
    m_stages->setHeaderLabels({tr("Stage"), tr("Verdict"), tr("Elements"), tr("Likely cause")});
    m_stages->setRootIsDecorated(false);
    m_stages->header()->setStretchLastSection(true);
    split->addWidget(m_stages);
    m_details = new QLabel;
    m_details->setWordWrap(true);
    m_details->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_details->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* scroll = new QScrollArea;
    scroll->setWidget(m_details);
    scroll->setWidgetResizable(true);
    split->addWidget(scroll);
    auto* picture = new QWidget;
    auto* pictureLayout = new QVBoxLayout(picture);
    pictureLayout->setContentsMargins(0, 0, 0, 0);
    m_canvas = new DepartureCanvas;
    pictureLayout->addWidget(m_canvas, 1);
    m_legend = new QLabel;
    m_legend->setWordWrap(true);
    pictureLayout->addWidget(m_legend);
    split->addWidget(picture);
    split->setStretchFactor(0, 2);
    split->setStretchFactor(1, 2);
    split->setStretchFactor(2, 3);
    layout->addWidget(split, 1);

    connect(m_run, &QPushButton::clicked, this, [this] {
        const QString problem = start();
        if (!problem.isEmpty()) m_details->setText(problem);
    });
    connect(m_cancel, &QPushButton::clicked, this, &CheckPanel::cancel);
    connect(m_stop, &QPushButton::clicked, this, &CheckPanel::stopAtFirstDeparture);
    connect(m_compare, &QPushButton::clicked, this, [this] {
        if (const QImage theirs = theirFrame(); !theirs.isNull()) emit compareFrame(theirs);
    });
    connect(m_browse, &QPushButton::clicked, this, [this] {
        const QString dir =
            QFileDialog::getExistingDirectory(this, tr("Your Program's Folder"), m_folder->text());
        if (!dir.isEmpty()) setFolder(dir);
    });
    connect(m_command, &QLineEdit::editingFinished, this, &CheckPanel::settingsChanged);
    connect(m_folder, &QLineEdit::editingFinished, this, &CheckPanel::settingsChanged);
    connect(m_stages, &QTreeWidget::currentItemChanged, this, &CheckPanel::showSelected);
    connect(&m_watcher, &QFutureWatcher<check::CheckReport>::finished, this,
            &CheckPanel::onFinished);
    // A new scene is not the one checked: its marks go.
    connect(m_inspection, &Inspection::frameChanged, this, [this] {
        if (!m_report || isRunning()) return;
        const auto& frame = m_inspection->frame();
        if (frame && frame->scene && m_report->scenes.size() == 1 &&
            (frame->scene->width != m_report->scenes.front().width ||
             frame->scene->height != m_report->scenes.front().height))
            m_image = QImage();
    });
}

CheckPanel::~CheckPanel() {
    m_cancelled = true;
    m_watcher.waitForFinished();
}

QString CheckPanel::command() const {
    return m_command->text();
}

void CheckPanel::setCommand(const QString& command) {
    m_command->setText(command);
    emit settingsChanged();
}

QString CheckPanel::folder() const {
    return m_folder->text();
}

void CheckPanel::setFolder(const QString& folder) {
    m_folder->setText(folder);
    emit settingsChanged();
}

QString CheckPanel::start() {
    if (isRunning()) return tr("A check is running.");
    const QString command = m_command->text().trimmed();
    if (command.isEmpty()) return tr("Give the command that starts your program.");
    const QString folder =
        m_folder->text().trimmed().isEmpty() ? QDir::currentPath() : m_folder->text();
    if (!QFileInfo(folder).isDir()) return tr("The folder %1 does not exist.").arg(folder);
    const auto& frame = m_inspection->frame();
    if (!frame || !frame->scene) return tr("There is no frame to check against.");
    m_image = m_inspection->frameImage();
    m_frame = frame;
    m_cancelled = false;
    check::CheckOptions options;
    options.limits.cancel = &m_cancelled;
    options.chain = m_chain->isChecked();
    const std::vector<check::CheckScene> scenes{{frame->scene->name, frame->scene}};
    const std::string cmd = command.toStdString();
    const std::string dir = QFileInfo(folder).absoluteFilePath().toStdString();
    const auto progress = [this](int done, int total, const std::string& what) {
        QMetaObject::invokeMethod(
            this, [this, done, total, what = text(what)] { setProgress(done, total, what); },
            Qt::QueuedConnection);
        return !m_cancelled.load();
    };
    m_watcher.setFuture(
        QtConcurrent::run([=] { return check::runCheck(cmd, dir, scenes, options, progress); }));
    m_run->setEnabled(false);
    m_cancel->setEnabled(true);
    m_compare->setEnabled(false);
    m_stop->setEnabled(false);
    m_progress->setRange(0, int(check::kStages.size()));
    m_progress->setValue(0);
    m_details->setText(tr("Checking %1...").arg(command));
    return {};
}

void CheckPanel::cancel() {
    m_cancelled = true;
}

void CheckPanel::setProgress(int done, int total, const QString& what) {
    m_progress->setRange(0, total);
    m_progress->setValue(done);
    m_progress->setFormat(what);
}

void CheckPanel::onFinished() {
    m_report = m_watcher.result();
    m_run->setEnabled(true);
    m_cancel->setEnabled(false);
    m_progress->setFormat(m_report->cancelled ? tr("cancelled") : tr("done"));
    m_compare->setEnabled(!theirFrame().isNull());
    showReport();
    emit finished();
}

QString CheckPanel::legend(check::Stage stage, bool any) {
    if (!any) return {};
    switch (stage) {
        case check::Stage::Projection:
            return tr(
                "Over our image: each vertex that departs, ours a green dot, theirs a red "
                "cross, joined by a line.");
        case check::Stage::Scan:
            return tr(
                "Over our image: magenta, pixels only we cover; cyan, pixels only they "
                "cover.");
        case check::Stage::ZBuffer:
            return tr(
                "Over our image: red, pixels another triangle wins (or at another depth); "
                "magenta, only ours keeps one; cyan, only theirs.");
        case check::Stage::Frame:
            return tr("Over our image: red, pixels whose colour differs by more than 1.");
        default:
            return {};
    }
}

QString CheckPanel::verdictText(check::Verdict verdict) {
    switch (verdict) {
        case check::Verdict::Passed:
            return tr("passed");
        case check::Verdict::Failed:
            return tr("failed");
        case check::Verdict::Unsupported:
            return tr("unsupported");
        case check::Verdict::Broken:
            return tr("broken");
    }
    return {};
}

rl::StageId CheckPanel::lectureStage(check::Stage stage) {
    switch (stage) {  // the frame is the whole pipeline: shown with the last stage
        case check::Stage::Basis:
            return rl::StageId::CameraBasis;
        case check::Stage::View:
            return rl::StageId::ViewTransform;
        case check::Stage::Normals:
            return rl::StageId::Normals;
        case check::Stage::Projection:
            return rl::StageId::Projection;
        case check::Stage::Scan:
            return rl::StageId::ScanConversion;
        case check::Stage::ZBuffer:
            return rl::StageId::DepthTest;
        case check::Stage::Lighting:
        case check::Stage::Frame:
            return rl::StageId::Shading;
    }
    return rl::StageId::Shading;
}

std::optional<check::Verdict> CheckPanel::verdict(rl::StageId stage) const {
    if (!m_report) return std::nullopt;
    std::optional<check::Verdict> worst;
    for (const check::SceneReport& s : m_report->scenes)
        for (const check::StageResult& r : s.stages)
            if (r.stage != check::Stage::Frame && lectureStage(r.stage) == stage &&
                (!worst || r.verdict != check::Verdict::Passed))
                worst = r.verdict;
    return worst;
}

void CheckPanel::showReport() {
    m_stages->clear();
    const check::CheckReport& r = *m_report;
    // In a line, what protected the machine; every limit in the tooltip.
    QStringList protections;
    for (const std::string& p : r.protections) protections << text(p);
    for (const std::string& p : r.missing) protections << tr("not applied: %1").arg(text(p));
    // Each protection's name: the words before its colon ("CPU time: 100 s").
    const auto names = [](const std::vector<std::string>& list) {
        QStringList out;
        for (const std::string& p : list) out << text(p.substr(0, p.find(':')));
        return out.join(QStringLiteral(", "));
    };
    m_protections->setText(
        r.missing.empty()
            ? tr("Protected by: %1.").arg(names(r.protections))
            : tr("Protected by: %1. Not applied: %2.").arg(names(r.protections), names(r.missing)));
    m_protections->setToolTip(protections.join(QLatin1Char('\n')));
    if (!r.failure.empty()) m_details->setText(text(r.failure));
    for (const check::SceneReport& s : r.scenes) {
        if (!s.error.empty()) m_details->setText(tr("Not checked: %1").arg(text(s.error)));
        for (const check::StageResult& st : s.stages) {
            auto* item = new QTreeWidgetItem(m_stages);
            item->setText(0, text(std::string(check::stageName(st.stage))));
            item->setText(1, verdictText(st.verdict));
            if (st.verdict == check::Verdict::Failed || st.verdict == check::Verdict::Passed)
                item->setText(2, tr("%1 of %2 differ").arg(st.differing).arg(st.elements));
            item->setText(3, text(st.verdict == check::Verdict::Broken ? st.problem : st.causes()));
            item->setToolTip(3, item->text(3));
            item->setData(0, Qt::UserRole, int(st.stage));
            item->setForeground(1, st.verdict == check::Verdict::Passed ? QColor(20, 140, 40)
                                                                        : QColor(200, 30, 30));
        }
    }
    for (int column = 0; column < 3; ++column) m_stages->resizeColumnToContents(column);
    fitSplit();
    // The first stage that departs is shown first, its row in view.
    for (int i = 0; i < m_stages->topLevelItemCount(); ++i)
        if (m_stages->topLevelItem(i)->text(1) != verdictText(check::Verdict::Passed)) {
            m_stages->setCurrentItem(m_stages->topLevelItem(i));
            m_stages->scrollToItem(m_stages->topLevelItem(i));
            return;
        }
    if (m_stages->topLevelItemCount() > 0) m_stages->setCurrentItem(m_stages->topLevelItem(0));
    if (r.passed()) m_details->setText(tr("Every stage passed (%1 s).").arg(r.seconds, 0, 'f', 1));
}

void CheckPanel::fitSplit() {
    // The list as tall as its rows (at most 40 % of the height), the words and the picture
    // sharing the rest: the first departure's row, explanation and overlay all in view.
    const QList<int> sizes = m_split->sizes();
    int total = 0;
    for (int size : sizes) total += size;
    if (total <= 0 || m_stages->topLevelItemCount() == 0) return;
    const int rows = m_stages->topLevelItemCount();
    const int needed = m_stages->header()->sizeHint().height() +
                       rows * m_stages->sizeHintForRow(0) + 2 * m_stages->frameWidth() + 2;
    const int list = std::min(needed, int(0.4 * total));
    const int words = (total - list) * 9 / 20;
    m_split->setSizes({list, words, total - list - words});
}

std::optional<check::Stage> CheckPanel::selectedStage() const {
    const QTreeWidgetItem* item = m_stages->currentItem();
    if (!item) return std::nullopt;
    return check::Stage(item->data(0, Qt::UserRole).toInt());
}

const check::StageResult* CheckPanel::selectedResult() const {
    const auto stage = selectedStage();
    return stage && m_report ? m_report->result(*stage) : nullptr;
}

QImage CheckPanel::theirFrame() const {
    if (!m_report || m_report->scenes.empty()) return {};
    const rl::Rgba8Image& f = m_report->scenes.front().theirFrame;
    if (f.rgba.empty()) return {};
    return QImage(f.rgba.data(), f.width, f.height, f.width * 4, QImage::Format_RGBA8888).copy();
}

QString CheckPanel::detailsText() const {
    return m_details->text();
}

void CheckPanel::showSelected() {
    const check::StageResult* r = selectedResult();
    if (!r) {
        m_canvas->show(m_image, {});
        m_legend->clear();
        m_stop->setEnabled(false);
        return;
    }
    QStringList lines;
    lines << tr("%1: %2").arg(text(std::string(check::stageName(r->stage))),
                              verdictText(r->verdict));
    if (r->verdict == check::Verdict::Broken) lines << text(r->problem);
    if (r->first) {
        lines << tr("First departure: %1: theirs %2, ours %3")
                     .arg(text(r->first->element), text(r->first->theirs), text(r->first->ours));
        lines << text(r->first->formula);
    }
    for (const check::StageFinding& f : r->findings)
        lines << tr("Likely cause: %1 (explains %2 of %3, %4% of the difference)")
                     .arg(text(f.cause))
                     .arg(f.explained)
                     .arg(r->differing)
                     .arg(100.0 * f.share, 0, 'f', 1);
    if (r->verdict == check::Verdict::Failed && r->findings.empty())
        lines << tr("No known mistake of this stage gives their answer.");
    if (r->verdict == check::Verdict::Failed && r->unexplained > 0 && !r->findings.empty())
        lines << tr("Unexplained: %1 of %2.").arg(r->unexplained).arg(r->differing);
    for (const std::string& d : r->description) lines << tr("In numbers: %1").arg(text(d));
    if (r->carried)
        lines << tr("Carried from the earlier stages: %1 elements of the lecture's answer change "
                    "with what was sent.")
                     .arg(*r->carried);
    for (const std::string& e : r->standardError) lines << text(e);
    if (!r->hint.empty()) lines << text(r->hint);
    if (!r->tolerance.empty()) lines << tr("Tolerance: %1").arg(text(r->tolerance));
    m_details->setText(lines.join(QLatin1Char('\n')));
    m_canvas->show(m_image, r->departures);
    m_legend->setText(legend(r->stage, !r->departures.empty()));
    m_stop->setEnabled(r->first.has_value() && m_inspection->frame());
}

bool CheckPanel::stopAtFirstDeparture() {
    const check::StageResult* r = selectedResult();
    if (!r || !r->first) return false;
    m_inspection->setStage(lectureStage(r->stage));
    if (r->departures.empty()) {
        // The normals name a triangle ("triangle 3") or a vertex: select it.
        const QString element = text(r->first->element);
        if (element.startsWith(QStringLiteral("triangle ")))
            m_inspection->selectTriangle(element.mid(9).toUInt());
        else if (element.startsWith(QStringLiteral("vertex ")))
            m_inspection->selectVertices({VertexRef{0, element.mid(7).toUInt()}});
        return true;
    }
    const check::Departure& d = r->departures.front();
    if (d.kind == check::Departure::Kind::Vertex) {
        const QString element = text(r->first->element);
        m_inspection->selectVertices({VertexRef{0, element.mid(7).toUInt()}});
        return true;
    }
    const QPoint pixel(int(d.ours.x), int(d.ours.y));
    m_inspection->pickPixel(pixel);
    if (!m_inspection->canStep()) return true;
    // The frame stepped to the first fragment written at the pixel: a breakpoint of its own,
    // the user's put back after.
    const std::vector<rl::Breakpoint> kept = m_inspection->breakpoints();
    rl::Breakpoint first;
    first.kind = rl::Breakpoint::Kind::NthWrite;
    first.x = pixel.x();
    first.y = pixel.y();
    first.n = 1;
    m_inspection->setBreakpoints({first});
    m_inspection->toStart();
    m_inspection->continueToBreakpoint();
    m_inspection->setBreakpoints(kept);
    return true;
}

DepartureCanvas::DepartureCanvas(QWidget* parent) : QWidget(parent) {
    setMinimumSize(160, 120);
}

void DepartureCanvas::show(const QImage& image, const std::vector<check::Departure>& departures) {
    m_image = image;
    m_departures = departures;
    update();
}

void DepartureCanvas::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), palette().window());
    if (m_image.isNull()) return;
    const double scale =
        std::min(double(width()) / m_image.width(), double(height()) / m_image.height());
    const QSizeF size(m_image.width() * scale, m_image.height() * scale);
    const QRectF target(QPointF((width() - size.width()) / 2, (height() - size.height()) / 2),
                        size);
    // Ours darkened, so that the departures stand out.
    p.drawImage(target, m_image);
    p.fillRect(target, QColor(0, 0, 0, 140));
    const auto at = [&](const rl::dvec2& pixel) {
        return QPointF(target.left() + (pixel.x + 0.5) * scale,
                       target.top() + (pixel.y + 0.5) * scale);
    };
    const double cell = std::max(1.0, scale);
    for (const check::Departure& d : m_departures) {
        const QColor colour = departureColour(d.kind);
        if (d.kind != check::Departure::Kind::Vertex) {
            const QPointF c = at(d.ours);
            p.fillRect(QRectF(c.x() - cell / 2, c.y() - cell / 2, cell, cell), colour);
            continue;
        }
        // A vertex: ours a green dot, theirs a red cross, a line between them.
        const QPointF ours = at(d.ours), theirs = at(d.theirs);
        p.setPen(QPen(QColor(255, 255, 255, 160), 1));
        p.drawLine(ours, theirs);
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(40, 220, 60));
        p.drawEllipse(ours, 3, 3);
        p.setPen(QPen(colour, 2));
        p.drawLine(theirs + QPointF(-4, -4), theirs + QPointF(4, 4));
        p.drawLine(theirs + QPointF(-4, 4), theirs + QPointF(4, -4));
    }
}

}  // namespace rasterlab
