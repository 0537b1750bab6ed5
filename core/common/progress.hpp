#pragma once
// Progress and cancellation for long work (QGIS "feedback" style): the caller owns a Progress,
// passes it down, polls it from another thread, and may cancel. No global state.
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

namespace plumb {

class Progress {
 public:
  /// Called (from the working thread) with the overall fraction in [0,1] and the stage name.
  using Callback = std::function<void(double fraction, std::string_view stage)>;

  Progress();
  explicit Progress(Callback callback);

  /// Report progress of this (sub-)task as a fraction in [0,1] of its own range.
  void report(double fraction, std::string_view stage = {});
  /// Overall fraction of the root task in [0,1].
  double fraction() const;
  std::string stage() const;

  void cancel();
  bool canceled() const;
  /// Throws plumb::Canceled if cancelled. Call it between units of work.
  void check() const;

  /// A child covering [begin,end] of this task's range; shares the cancel flag.
  Progress sub(double begin, double end) const;

 private:
  struct Shared;
  Progress(std::shared_ptr<Shared> shared, double begin, double end);
  std::shared_ptr<Shared> shared_;
  double begin_ = 0.0;
  double end_ = 1.0;
};

/// Convenience for optional progress arguments: reports/checks only when p is not null.
inline void reportProgress(Progress* p, double fraction, std::string_view stage = {}) {
  if (p) p->report(fraction, stage);
}
inline void checkCanceled(const Progress* p) {
  if (p) p->check();
}

}  // namespace plumb
