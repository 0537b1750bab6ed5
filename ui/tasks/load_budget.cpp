#include "ui/tasks/load_budget.hpp"

#include "common/memory_budget.hpp"
#include "io/stream/point_count.hpp"
#include "registration/bounded/bounded_input.hpp"
#include "ui/app_context.hpp"
#include "ui/registration/registration_panel.hpp"

namespace plumb::ui {

std::uint64_t memoryBudget(const AppContext& app) {
  return memoryBudgetBytes(app.registration ? app.registration->params().memory : MemoryParams{});
}

std::optional<SubsampleParams> planLoad(const std::filesystem::path& path, std::uint64_t budget, double voxel) {
  if (budget == 0) return std::nullopt;
  return subsampleToFit(estimatePointCount(path), budget, kDisplayBytesPerPoint, voxel);
}

}  // namespace plumb::ui
