#pragma once
// Adaptive level-of-detail budget: how many points the view draws while the camera moves, chosen
// from measured frame times so that moving stays interactive on whatever OpenGL the machine has
// (a few million points on a GPU, a few hundred thousand on software rendering).
//
// Frame time is modelled as t = a + b n (fixed cost a, cost b per point). The update
// n' = n (T / t) has its fixed point exactly where a + b n = T whatever a is, so the budget
// converges to the target frame time T without knowing the fixed cost. Steps are damped
// (geometric mean of old and proposed) and not taken while the frame time is within a dead band
// around the target, so the subset is not rebuilt for every small timing jitter.
#include <cstddef>

namespace plumb::ui {

class LodBudget {
 public:
  struct Params {
    double target_ms = 50.0;           ///< frame time aimed at while moving, ms (> 0)
    std::size_t min_points = 20'000;   ///< never fewer points than this while moving
    std::size_t max_points = 5'000'000;  ///< never more (bounds the subset's memory)
    std::size_t initial_points = 300'000;  ///< before any frame has been measured
    double dead_band = 0.1;   ///< |T/t - 1| below which the budget stays as it is
    double max_growth = 4.0;  ///< largest factor T/t taken from one frame (>= 1)
    /// Step to the geometric mean of the current budget and the proposal (smooth, for the
    /// many moving frames). Off, the proposal is taken as it is: n T / (a + b n) < T / b, so
    /// even an undamped step overshoots the target by at most the fixed cost a (still frames,
    /// where one step should reach the right size).
    bool damped = true;
  };

  LodBudget() : LodBudget(Params{}) {}
  explicit LodBudget(const Params& params);

  /// Points to draw per frame (the whole scene).
  std::size_t points() const { return points_; }
  const Params& params() const { return params_; }

  /// Reports a frame that drew `points_drawn` points in `frame_ms` milliseconds.
  /// Returns true when the budget changed (the caller rebuilds its subsets).
  bool addFrame(std::size_t points_drawn, double frame_ms);

 private:
  Params params_;
  std::size_t points_;
};

}  // namespace plumb::ui
