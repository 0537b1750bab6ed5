#pragma once
// Registration input within the memory budget (issue 16, docs/IO.md "Bounded registration
// input"). A point file whose whole-file registration would exceed memory.budget
// (kRegistrationBytesPerPoint a point) is not read whole: it is streamed into a per-station
// voxel subsample (io/stream/stream_subsample.hpp) and the features, the refinement and the
// quality checks run on that. Files within the budget, and models, take today's path
// (readFile + makeRegistrationInput), so their results do not change.
#include <cstdint>
#include <filesystem>
#include <optional>

#include "common/progress.hpp"
#include "io/stream/point_count.hpp"
#include "io/stream/stream_subsample.hpp"
#include "registration/auto/registration_input.hpp"

namespace plumb {

/// Fewest points a subsample keeps whatever the budget (below this the features starve):
/// a budget under ~50 MB is exceeded rather than registering on a few thousand points.
inline constexpr std::uint64_t kMinSubsamplePoints = 250000;

struct SubsampledInput {
  RegistrationInput input;             ///< world frame, as makeRegistrationInput gives it
  std::uint64_t estimated_points = 0;  ///< what the header declares (estimatePointCount)
  std::uint64_t budget_bytes = 0;      ///< memoryBudgetBytes(params.memory)
  std::uint64_t points_read = 0;       ///< points streamed
  std::uint64_t points_kept = 0;       ///< points of the subsample
  double voxel = 0;                    ///< voxel edge used, metres
};

/// The subsample a file of `estimate` points needs to fit `budget` bytes at `bytes_per_point`:
/// nullopt for a model or when the whole file fits; else `voxel` and at most
/// budget / bytes_per_point points (never fewer than kMinSubsamplePoints). The registration
/// (kRegistrationBytesPerPoint) and the desktop (kDisplayBytesPerPoint) plan with it.
std::optional<SubsampleParams> subsampleToFit(const PointCountEstimate& estimate, std::uint64_t budget,
                                              std::uint64_t bytes_per_point, double voxel);

/// The starting voxel of the subsample: memory.subsample-voxel, and never coarser than half
/// the refinement voxel or a quarter of the segment voxel, so both see several points a cell.
double subsampleVoxel(const PipelineParams& params);

/// The subsampled input of `path`, or nullopt when the file is a model or its estimated
/// whole-file cost fits the budget (then read it whole: readFile + makeRegistrationInput).
/// Throws FileError as readDataset, and when the file holds no points.
std::optional<SubsampledInput> boundedRegistrationInput(const std::filesystem::path& path,
                                                        const PipelineParams& params,
                                                        Progress* progress = nullptr);

}  // namespace plumb
