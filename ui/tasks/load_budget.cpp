#include "ui/tasks/load_budget.hpp"

#include <algorithm>

#include "common/memory_budget.hpp"
#include "io/stream/point_count.hpp"
#include "registration/bounded/bounded_input.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/registration/registration_panel.hpp"

namespace plumb::ui {

std::uint64_t memoryBudget(const AppContext& app) {
  return memoryBudgetBytes(app.registration ? app.registration->params().memory : MemoryParams{});
}

std::uint64_t heldBytes(const AppContext& app) {
  std::uint64_t points = 0;
  for (const auto& layer : app.scene.layers())
    if (layer->kind() == LayerKind::Dataset)
      points += static_cast<const DatasetLayer&>(*layer).dataset().pointCount();
  return points * kDisplayBytesPerPoint;
}

std::uint64_t loadShare(const AppContext& app, std::size_t point_files) {
  const std::uint64_t budget = memoryBudget(app);
  if (budget == 0) return 0;
  const std::uint64_t held = heldBytes(app) + app.loads_reserved;
  const std::uint64_t left = budget > held ? budget - held : 0;
  return std::max<std::uint64_t>(1, left / std::max<std::size_t>(1, point_files));
}

std::optional<SubsampleParams> planLoad(const std::filesystem::path& path, std::uint64_t budget, double voxel) {
  if (budget == 0) return std::nullopt;
  return subsampleToFit(estimatePointCount(path), budget, kDisplayBytesPerPoint, voxel);
}

}  // namespace plumb::ui
