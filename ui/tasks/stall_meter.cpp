#include "ui/tasks/stall_meter.hpp"

#include <algorithm>

namespace plumb::ui {

StallMeter::StallMeter(int interval_ms, QObject* parent) : QObject(parent) {
  clock_.start();
  ticker_.setInterval(interval_ms);
  connect(&ticker_, &QTimer::timeout, this, [this] {
    const double now = nowMs();
    longest_ms_ = std::max(longest_ms_, now - last_ms_);
    last_ms_ = now;
  });
  ticker_.start();
}

double StallMeter::nowMs() const { return static_cast<double>(clock_.nsecsElapsed()) / 1e6; }

double StallMeter::longestMs() const { return std::max(longest_ms_, nowMs() - last_ms_); }

}  // namespace plumb::ui
