#pragma once
// Status-bar widget (issue 16): the memory Plumb holds now against the memory budget (the
// "memory" parameter group of the Registration dock, shared with plumb-cli's --memory-budget),
// refreshed every few seconds. Over the budget it turns red; files whose display would exceed
// the budget are opened as a subsample (ui/tasks/load_budget.hpp).
#include <QLabel>

#include <cstdint>
#include <functional>

class QTimer;

namespace plumb::ui {

class MemoryStatusWidget : public QLabel {
  Q_OBJECT
 public:
  /// `budget` gives the budget in bytes when asked (it follows the dock's parameter).
  explicit MemoryStatusWidget(std::function<std::uint64_t()> budget, QWidget* parent = nullptr);
  /// Refresh period, ms.
  static constexpr int kPeriodMs = 2000;
  /// Reads the process's memory and the budget now (also called by the timer).
  void refresh();
  /// "1.2 GB / 11.6 GB" for bytes used and allowed (public for tests).
  static QString format(std::uint64_t used, std::uint64_t budget);

 private:
  std::function<std::uint64_t()> budget_;
  QTimer* timer_;
};

}  // namespace plumb::ui
