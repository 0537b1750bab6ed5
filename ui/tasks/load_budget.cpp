#include "ui/tasks/load_budget.hpp"

#include <algorithm>

#include "common/memory_budget.hpp"
#include "io/stream/point_count.hpp"
#include "registration/bounded/bounded_input.hpp"
#include "ui/app_context.hpp"
#include "ui/registration/registration_panel.hpp"

namespace plumb::ui {

std::uint64_t memoryBudget(const AppContext& app) {
  return memoryBudgetBytes(app.registration ? app.registration->params().memory : MemoryParams{});
}

LoadPlan planLoad(const std::filesystem::path& path, std::uint64_t budget, double voxel) {
  LoadPlan plan;
  const PointCountEstimate estimate = estimatePointCount(path);
  plan.estimated_points = estimate.points;
  if (estimate.model || budget == 0 || estimate.points * kDisplayBytesPerPoint <= budget) return plan;
  plan.subsample = true;
  plan.params.voxel = voxel;
  plan.params.max_points = std::max(kMinSubsamplePoints, budget / kDisplayBytesPerPoint);
  return plan;
}

}  // namespace plumb::ui
