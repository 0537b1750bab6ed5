#pragma once
// Wall-clock seconds for the timings reports and benchmarks print.
#include <chrono>

namespace plumb {

/// Seconds elapsed since `t0` on the steady clock.
inline double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace plumb
