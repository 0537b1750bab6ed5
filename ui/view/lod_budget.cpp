#include "ui/view/lod_budget.hpp"

#include <algorithm>
#include <cmath>

namespace plumb::ui {

LodBudget::LodBudget(const Params& params)
    : params_(params),
      points_(std::clamp(params.initial_points, params.min_points, params.max_points)) {}

bool LodBudget::addFrame(std::size_t points_drawn, double frame_ms) {
  if (points_drawn == 0 || !(frame_ms > 0.0)) return false;
  const double n = static_cast<double>(points_drawn);
  // n' = n T / t, damped: geometric mean of the current budget and the proposal. Growth is
  // limited to max_growth per frame (a tiny first frame must not jump straight to the maximum).
  const double proposal = n * std::min(params_.target_ms / frame_ms, params_.max_growth);
  const double current = static_cast<double>(points_);
  // The dead band applies to the proposal (the frame time's distance from the target), the
  // step taken is the damped one.
  if (std::abs(proposal - current) <= params_.dead_band * current) return false;
  const double step = params_.damped ? std::sqrt(proposal * current) : proposal;
  const auto next = static_cast<std::size_t>(
      std::clamp(step, static_cast<double>(params_.min_points),
                 static_cast<double>(params_.max_points)));
  if (next == points_) return false;
  points_ = next;
  return true;
}

}  // namespace plumb::ui
