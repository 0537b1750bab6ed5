#pragma once
// The voxel subsample of a point file from its level-of-detail cache (issue 16: a file above
// the memory budget reopens in seconds). The cache's upper levels are grid samples of the
// whole file; read level by level, coarsest first, up to about twice the subsample's point
// limit, and put through the same voxel grids as the file's stream (VoxelSubsampler), they
// give a subsample of the same voxel to within one doubling, with the file's scans, names and
// poses (read from its header). Not for files whose scans carry per-point sensor origins,
// normals or times (a mobile pass): the cache does not keep them, and the registration needs
// them; those stream the file (subsampleDataset).
#include <filesystem>
#include <optional>
#include <string>

#include "common/progress.hpp"
#include "io/lod/lod_cache.hpp"
#include "io/stream/stream_subsample.hpp"

namespace plumb {

/// How many times the subsample's point limit is read from the cache at most (whole levels;
/// the root always): enough input for the voxel grids to reach their limit.
inline constexpr double kLodSubsampleReadFactor = 2.0;

struct LodSubsampleResult {
  std::optional<SubsampleResult> subsample;  ///< empty: use the file (see `why_not`)
  std::string why_not;                       ///< plain language, for the log
  std::uint64_t points_from_cache = 0;       ///< points read from the cache
  int levels = 0;                            ///< octree levels read
};

/// The subsample of `source` (whose valid cache `cache` is: openLodCache) at `params`
/// (max_points > 0), or why the file must be streamed instead. points_read is the points the
/// file holds. Throws the outline's and the cache's FileErrors.
LodSubsampleResult subsampleFromLodCache(const std::filesystem::path& source, const LodCache& cache,
                                         const SubsampleParams& params, Progress* progress = nullptr);

}  // namespace plumb
