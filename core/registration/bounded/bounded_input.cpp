#include "registration/bounded/bounded_input.hpp"

#include <algorithm>

#include "common/memory_budget.hpp"
#include "io/stream/point_count.hpp"
#include "io/stream/stream_subsample.hpp"

namespace plumb {

double subsampleVoxel(const PipelineParams& p) {
  double v = p.memory.subsample_voxel;
  if (p.refinement.voxel_size > 0) v = std::min(v, p.refinement.voxel_size / 2);
  return std::min(v, p.segment_detection.voxel_size / 4);
}

std::optional<SubsampleParams> subsampleToFit(const PointCountEstimate& estimate, std::uint64_t budget,
                                              std::uint64_t bytes_per_point, double voxel) {
  if (estimate.model || estimate.points * bytes_per_point <= budget) return std::nullopt;
  SubsampleParams sub;
  sub.voxel = voxel;
  sub.max_points = std::max(kMinSubsamplePoints, budget / bytes_per_point);
  return sub;
}

std::optional<SubsampledInput> boundedRegistrationInput(const std::filesystem::path& path,
                                                        const PipelineParams& params, Progress* progress) {
  const PointCountEstimate estimate = estimatePointCount(path);
  const std::uint64_t budget = memoryBudgetBytes(params.memory);
  const std::optional<SubsampleParams> sub =
      subsampleToFit(estimate, budget, kRegistrationBytesPerPoint, subsampleVoxel(params));
  if (!sub) return std::nullopt;
  SubsampleResult s = subsampleDataset(path, *sub, StreamOptions{}, progress);
  SubsampledInput out;
  out.estimated_points = estimate.points;
  out.budget_bytes = budget;
  out.points_read = s.points_read;
  out.points_kept = s.points_kept;
  out.voxel = s.voxel;
  out.input = makeRegistrationInput(s.data, RigidTransform());
  return out;
}

}  // namespace plumb
