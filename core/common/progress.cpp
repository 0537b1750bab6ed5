#include "common/progress.hpp"

#include <algorithm>

#include "common/error.hpp"

namespace plumb {

struct Progress::Shared {
  Callback callback;
  std::atomic<double> fraction{0.0};
  std::atomic<bool> canceled{false};
  mutable std::mutex stage_mutex;
  std::string stage;
};

Progress::Progress() : Progress(Callback{}) {}

Progress::Progress(Callback callback) : shared_(std::make_shared<Shared>()) {
  shared_->callback = std::move(callback);
}

Progress::Progress(std::shared_ptr<Shared> shared, double begin, double end)
    : shared_(std::move(shared)), begin_(begin), end_(end) {}

void Progress::report(double fraction, std::string_view stage) {
  const double f = begin_ + (end_ - begin_) * std::clamp(fraction, 0.0, 1.0);
  shared_->fraction.store(f, std::memory_order_relaxed);
  if (!stage.empty()) {
    std::lock_guard lock(shared_->stage_mutex);
    shared_->stage.assign(stage);
  }
  if (shared_->callback) shared_->callback(f, stage);
}

double Progress::fraction() const { return shared_->fraction.load(std::memory_order_relaxed); }

std::string Progress::stage() const {
  std::lock_guard lock(shared_->stage_mutex);
  return shared_->stage;
}

void Progress::cancel() { shared_->canceled.store(true); }
bool Progress::canceled() const { return shared_->canceled.load(std::memory_order_relaxed); }

void Progress::check() const {
  if (canceled()) throw Canceled();
}

Progress Progress::sub(double begin, double end) const {
  const double span = end_ - begin_;
  return Progress(shared_, begin_ + span * std::clamp(begin, 0.0, 1.0),
                  begin_ + span * std::clamp(end, 0.0, 1.0));
}

}  // namespace plumb
