#pragma once
// How long the UI thread's event loop was blocked (a frozen UI): a timer ticks on this thread
// at a short interval; the longest gap between ticks (or since the last one) is the longest
// freeze. Used by tests and benchmarks of the background tasks.
#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace plumb::ui {

class StallMeter : public QObject {
 public:
  /// Starts ticking every `interval_ms` on the calling thread.
  explicit StallMeter(int interval_ms = 10, QObject* parent = nullptr);
  /// Longest time between two ticks, or since the last tick, in ms.
  double longestMs() const;

 private:
  double nowMs() const;
  QElapsedTimer clock_;
  QTimer ticker_;
  double last_ms_ = 0;
  double longest_ms_ = 0;
};

}  // namespace plumb::ui
