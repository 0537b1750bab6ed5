#include "registration/bounded/bounded_datasets.hpp"

#include "common/error.hpp"
#include "common/memory_budget.hpp"
#include "io/io.hpp"
#include "io/stream/point_count.hpp"
#include "registration/bounded/bounded_input.hpp"

namespace plumb {
namespace {

[[noreturn]] void refuseModel(const std::filesystem::path& path) {
  throw FileError(path, "is a model, not a point file (a BIM goes in with --model)");
}

BoundedDataset readWhole(const std::filesystem::path& path, std::uint64_t estimate) {
  LoadedData data = readFile(path);
  if (!std::holds_alternative<Dataset>(data)) refuseModel(path);
  BoundedDataset b{path, std::move(std::get<Dataset>(data)), false, 0.0, estimate, 0, 0};
  b.points_kept = b.data.pointCount();
  return b;
}

BoundedDataset readSubsampled(const std::filesystem::path& path, const SubsampleParams& sub, std::uint64_t estimate,
                              Progress* progress) {
  SubsampleResult s = subsampleDataset(path, sub, StreamOptions{}, progress);
  return {path, std::move(s.data), true, s.voxel, estimate, s.points_read, s.points_kept};
}

}  // namespace

std::vector<BoundedDataset> readDatasetsWithin(const std::vector<std::filesystem::path>& paths,
                                               const PipelineParams& params, Progress* progress) {
  std::vector<PointCountEstimate> estimates;
  std::uint64_t total = 0;
  for (const auto& path : paths) {
    estimates.push_back(estimatePointCount(path));
    if (estimates.back().model) refuseModel(path);
    total += estimates.back().points;
  }
  const std::uint64_t budget = memoryBudgetBytes(params.memory);
  const bool fits = total * kRegistrationBytesPerPoint <= budget;
  std::vector<BoundedDataset> out;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    // Each file's share of the budget in proportion to its points: the same voxel for all when
    // the stations are alike.
    const auto share = static_cast<std::uint64_t>(double(budget) * double(estimates[i].points) / double(std::max<std::uint64_t>(total, 1)));
    const auto sub = fits ? std::nullopt : subsampleToFit(estimates[i], share, kRegistrationBytesPerPoint, subsampleVoxel(params));
    out.push_back(sub ? readSubsampled(paths[i], *sub, estimates[i].points, progress) : readWhole(paths[i], estimates[i].points));
  }
  return out;
}

}  // namespace plumb
