#pragma once
// The memory budget (issue 16, docs/IO.md "Memory budget"): how many megabytes a command may
// use for point data. It decides whether a registration input is read whole (today's path)
// or subsampled while streaming, how fine that subsample may be, and bounds the chunk size
// of info and convert. One parameter group ("memory"), so `register --set memory.budget=...`,
// the JSON of --params, the desktop's panel and the `--memory-budget` flag of info/convert
// all come from this one definition.
#include <cstdint>

#include "common/params.hpp"

namespace plumb {

struct MemoryParams {
  /// Megabytes of point data a command may hold, [0, 1e7]. 0 (default): half of the
  /// machine's MemAvailable when the command starts (at least 256 MB). Set it explicitly for
  /// results that do not depend on the machine's load: above the budget the registration
  /// runs on a subsample whose voxel grows with the file.
  double budget_mb = 0.0;
  /// Voxel edge of the per-station subsample a registration uses for files above the
  /// budget, metres, [0.002, 1]. The default 2 cm is the plane inlier distance (20 mm),
  /// a quarter of the segment voxel (80 mm) and below the refinement voxel (50 mm), so the
  /// features see the same surfaces; doubled while the subsample would exceed the budget.
  double subsample_voxel = 0.02;
  static const ParamSchema<MemoryParams>& schema();
};

/// Bytes the budget allows: budget_mb, or when 0 half of MemAvailable (/proc/meminfo, read
/// once, at the process's first call; 4 GB when it cannot be read), never below 256 MB.
std::uint64_t memoryBudgetBytes(const MemoryParams& params);

/// Planning figure of the registration: bytes per input point while a side is read whole and
/// registered (the Dataset's columns, the merged world cloud, the features' and the
/// refinement's working sets; a 21-million-point station peaked at 2.2 GB, ~105 B/point, with
/// a margin for the target side).
inline constexpr std::uint64_t kRegistrationBytesPerPoint = 200;

}  // namespace plumb
