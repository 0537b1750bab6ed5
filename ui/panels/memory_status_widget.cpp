#include "ui/panels/memory_status_widget.hpp"

#include <QTimer>

#include "common/process_memory.hpp"

namespace plumb::ui {

namespace {
QString gigabytes(std::uint64_t bytes) {
  return QString::number(static_cast<double>(bytes) / (1024.0 * 1024.0 * 1024.0), 'f', 1);
}
}  // namespace

MemoryStatusWidget::MemoryStatusWidget(std::function<std::uint64_t()> budget, QWidget* parent)
    : QLabel(parent), budget_(std::move(budget)), timer_(new QTimer(this)) {
  setObjectName("memoryStatus");
  setToolTip(tr("Memory Plumb holds now / memory budget.\nThe budget is the Registration dock's "
                "\"Memory budget\" (0: half of the memory available at start).\nA file whose "
                "display would exceed it opens as a subsample; exports still read the whole file."));
  connect(timer_, &QTimer::timeout, this, &MemoryStatusWidget::refresh);
  timer_->start(kPeriodMs);
  refresh();
}

QString MemoryStatusWidget::format(std::uint64_t used, std::uint64_t budget) {
  return tr("Memory %1 / %2 GB").arg(gigabytes(used), gigabytes(budget));
}

void MemoryStatusWidget::refresh() {
  const std::uint64_t used = residentBytes(), budget = budget_ ? budget_() : 0;
  setText(format(used, budget));
  setStyleSheet(budget > 0 && used > budget ? "color: #c62828;" : "");
}

}  // namespace plumb::ui
