#include "breakpoints_view.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace rasterlab {

namespace {

using Kind = rl::Breakpoint::Kind;

bool needsPixel(Kind kind) {
    return kind == Kind::DepthRejection || kind == Kind::LightBehind || kind == Kind::NthWrite;
}

// The projected triangle of the first draw's mesh triangle `number` (1-based), if drawn.
std::optional<std::uint32_t> projectedTriangle(const rl::FrameTrace& frame, int number) {
    const auto& triangles = frame.projection->triangles;
    for (std::size_t t = 0; t < triangles.size(); ++t)
        if (triangles[t].draw == 0 && static_cast<int>(triangles[t].source) == number - 1)
            return static_cast<std::uint32_t>(t);
    return std::nullopt;
}

}  // namespace

QString BreakpointsView::describe(const rl::Breakpoint& b, int triangleNumber) {
    switch (b.kind) {
        case Kind::Triangle:
            return tr("triangle %1 starts").arg(triangleNumber);
        case Kind::Scanline:
            return tr("a triangle reaches scanline %1").arg(b.y);
        case Kind::DepthRejection:
            return tr("first depth rejection at (%1, %2)").arg(b.x).arg(b.y);
        case Kind::LightBehind:
            return tr("N.L < 0 at (%1, %2)").arg(b.x).arg(b.y);
        case Kind::NthWrite:
            return b.x < 0 ? tr("any pixel written %n time(s)", nullptr, static_cast<int>(b.n))
                           : tr("(%1, %2) written %n time(s)", nullptr, static_cast<int>(b.n))
                                 .arg(b.x)
                                 .arg(b.y);
    }
    return {};
}

BreakpointsView::BreakpointsView(Inspection* inspection, QWidget* parent)
    : QWidget(parent), m_inspection(inspection) {
    setObjectName(QStringLiteral("breakpointsView"));
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    m_kind = new QComboBox(this);
    m_kind->setObjectName(QStringLiteral("breakpointKind"));
    m_kind->addItem(tr("At triangle"), static_cast<int>(Kind::Triangle));
    m_kind->addItem(tr("At scanline"), static_cast<int>(Kind::Scanline));
    m_kind->addItem(tr("First depth rejection at the picked pixel"),
                    static_cast<int>(Kind::DepthRejection));
    m_kind->addItem(tr("N.L < 0 at the picked pixel"), static_cast<int>(Kind::LightBehind));
    m_kind->addItem(tr("A pixel written n times"), static_cast<int>(Kind::NthWrite));
    form->addRow(tr("Stop when"), m_kind);
    m_value = new QSpinBox(this);
    m_value->setObjectName(QStringLiteral("breakpointValue"));
    m_value->setRange(0, 1 << 30);
    form->addRow(tr("Number"), m_value);
    m_where = new QComboBox(this);
    m_where->addItem(tr("the picked pixel"));
    m_where->addItem(tr("any pixel"));
    form->addRow(tr("Pixel"), m_where);
    layout->addLayout(form);
    auto* buttons = new QHBoxLayout;
    auto* addButton = new QPushButton(tr("&Add"), this);
    addButton->setObjectName(QStringLiteral("addBreakpoint"));
    auto* removeButton = new QPushButton(tr("&Remove"), this);
    auto* clearButton = new QPushButton(tr("Remove A&ll"), this);
    buttons->addWidget(addButton);
    buttons->addWidget(removeButton);
    buttons->addWidget(clearButton);
    layout->addLayout(buttons);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    layout->addWidget(m_status);
    m_list = new QTreeWidget(this);
    m_list->setObjectName(QStringLiteral("breakpointList"));
    m_list->setHeaderLabels({tr("Breakpoint")});
    m_list->setRootIsDecorated(false);
    layout->addWidget(m_list, 1);

    connect(m_kind, &QComboBox::currentIndexChanged, this, &BreakpointsView::updateForm);
    connect(addButton, &QPushButton::clicked, this, [this] {
        const auto kind = static_cast<Kind>(m_kind->currentData().toInt());
        if (!add(kind, m_value->value(), m_where->currentIndex() == 1))
            m_status->setText(tr("Pick a pixel in the image first."));
    });
    connect(removeButton, &QPushButton::clicked, this, &BreakpointsView::removeSelected);
    connect(clearButton, &QPushButton::clicked, this, &BreakpointsView::clear);
    connect(m_list, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item) {
        const int i = m_list->indexOfTopLevelItem(item);
        if (i < 0 || i >= static_cast<int>(m_entries.size())) return;
        m_entries[static_cast<std::size_t>(i)].breakpoint.enabled =
            item->checkState(0) == Qt::Checked;
        publish();
    });
    connect(inspection, &Inspection::frameChanged, this, &BreakpointsView::publish);
    connect(inspection, &Inspection::breakpointHit, this, [this](int index) {
        m_hit = index;
        refreshList();
        if (index >= 0 && index < static_cast<int>(m_entries.size())) {
            const Entry& e = m_entries[static_cast<std::size_t>(index)];
            m_status->setText(tr("Stopped: %1").arg(describe(e.breakpoint, e.triangleNumber)));
        }
    });
    connect(inspection, &Inspection::cursorChanged, this, [this] {
        if (m_hit >= 0 && m_inspection->atEnd()) {
            m_hit = -1;
            refreshList();
        }
    });
    updateForm();
}

void BreakpointsView::updateForm() {
    const auto kind = static_cast<Kind>(m_kind->currentData().toInt());
    m_value->setEnabled(kind == Kind::Triangle || kind == Kind::Scanline || kind == Kind::NthWrite);
    m_value->setMinimum(kind == Kind::Scanline ? 0 : 1);
    if (kind == Kind::NthWrite && m_value->value() < 2) m_value->setValue(2);
    m_where->setEnabled(kind == Kind::NthWrite);
}

bool BreakpointsView::add(Kind kind, int value, bool anyPixel) {
    const QPoint pixel = m_inspection->pickedPixel();
    const bool pixelNeeded = needsPixel(kind) && !(kind == Kind::NthWrite && anyPixel);
    if (pixelNeeded && pixel.x() < 0) return false;
    Entry e;
    e.breakpoint.kind = kind;
    if (pixelNeeded) {
        e.breakpoint.x = pixel.x();
        e.breakpoint.y = pixel.y();
    }
    if (kind == Kind::Scanline) e.breakpoint.y = value;
    if (kind == Kind::NthWrite) e.breakpoint.n = static_cast<std::uint32_t>(std::max(1, value));
    if (kind == Kind::Triangle) e.triangleNumber = value;
    m_entries.push_back(e);
    m_status->clear();
    publish();
    return true;
}

void BreakpointsView::removeSelected() {
    const int i = m_list->indexOfTopLevelItem(m_list->currentItem());
    if (i < 0) return;
    m_entries.erase(m_entries.begin() + i);
    m_hit = -1;
    publish();
}

void BreakpointsView::clear() {
    m_entries.clear();
    m_hit = -1;
    publish();
}

std::vector<rl::Breakpoint> BreakpointsView::entries() const {
    std::vector<rl::Breakpoint> out;
    for (const Entry& e : m_entries) {
        rl::Breakpoint b = e.breakpoint;
        if (b.kind == Kind::Triangle) b.triangle = static_cast<std::uint32_t>(e.triangleNumber);
        out.push_back(b);
    }
    return out;
}

void BreakpointsView::setEntries(const std::vector<rl::Breakpoint>& breakpoints) {
    m_entries.clear();
    for (const rl::Breakpoint& b : breakpoints)
        m_entries.push_back({b, b.kind == Kind::Triangle ? static_cast<int>(b.triangle) : 0});
    m_hit = -1;
    publish();
}

void BreakpointsView::publish() {
    // Triangle numbers become the frame's projected triangles (they change with the frame).
    std::vector<rl::Breakpoint> list;
    const auto& frame = m_inspection->frame();
    for (Entry& e : m_entries) {
        rl::Breakpoint b = e.breakpoint;
        if (b.kind == Kind::Triangle) {
            const std::optional<std::uint32_t> t =
                frame ? projectedTriangle(*frame, e.triangleNumber) : std::nullopt;
            b.triangle = t.value_or(0);
            b.enabled = b.enabled && t.has_value();
        }
        list.push_back(b);
    }
    m_inspection->setBreakpoints(std::move(list));
    refreshList();
}

void BreakpointsView::refreshList() {
    const QSignalBlocker block(m_list);
    m_list->clear();
    for (std::size_t i = 0; i < m_entries.size(); ++i) {
        const Entry& e = m_entries[i];
        auto* item = new QTreeWidgetItem(m_list, {describe(e.breakpoint, e.triangleNumber)});
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(0, e.breakpoint.enabled ? Qt::Checked : Qt::Unchecked);
        if (static_cast<int>(i) == m_hit) {
            QFont f = item->font(0);
            f.setBold(true);
            item->setFont(0, f);
            item->setIcon(0, style()->standardIcon(QStyle::SP_MediaStop));
        }
    }
}

}  // namespace rasterlab
