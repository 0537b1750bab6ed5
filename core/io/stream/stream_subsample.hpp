#pragma once
// A per-scan voxel subsample of a point file built while streaming it (docs/IO.md, "Bounded
// registration input"): each scan keeps one point per occupied voxel of its own grid, the
// centroid of the points that fell in it, with the mean normal, sensor origin, intensity and
// time when the scan has them. Memory is the subsample (plus one chunk), never the file.
// When the subsample would exceed `max_points`, the voxel is doubled and every cell merged
// into its parent (exact: a parent cell is the union of its eight children), so the result
// is the subsample at the final voxel whatever the order of the chunks.
#include <cstdint>
#include <filesystem>
#include <memory>

#include "common/progress.hpp"
#include "io/stream/chunk_sink.hpp"

namespace plumb {

struct SubsampleParams {
  double voxel = 0.02;            ///< starting voxel edge, metres (> 0)
  std::uint64_t max_points = 0;   ///< most points kept over all scans; 0: no limit
};

struct SubsampleResult {
  /// The file's dataset (source, format, metadata, scan names and poses) with each scan's
  /// cloud replaced by its subsample, in the scan's own frame.
  Dataset data;
  double voxel = 0;                ///< voxel edge finally used, metres
  std::uint64_t points_read = 0;   ///< points the file delivered (or holds: subsampleFromLodCache)
  std::uint64_t points_kept = 0;   ///< points of the subsample
};

/// The voxel grids of a subsample, fed scan by scan with points in each scan's own frame (the
/// file's stream, or another source of the same points: io/lod/lod_subsample.hpp).
class VoxelSubsampler {
 public:
  /// `path` names the file in errors; `outline` is the dataset the result starts from (its
  /// scans' clouds are replaced).
  VoxelSubsampler(std::filesystem::path path, const SubsampleParams& params, Dataset outline);
  ~VoxelSubsampler();
  VoxelSubsampler(const VoxelSubsampler&) = delete;
  VoxelSubsampler& operator=(const VoxelSubsampler&) = delete;
  /// Adds points of scan `scan` (its own frame). The fields of a scan's first non-empty call
  /// decide which sums it keeps. Coarsens every grid while the cells exceed max_points.
  void add(std::size_t scan, const PointCloud& points);
  Dataset& outline();
  /// The subsample (points_read counts the points added); the subsampler is empty after.
  SubsampleResult take();

 private:
  struct Grids;
  std::unique_ptr<Grids> grids_;
};

/// Streams `path` (streamDataset: errors are its FileErrors) into a voxel subsample.
SubsampleResult subsampleDataset(const std::filesystem::path& path, const SubsampleParams& params,
                                 const StreamOptions& options = {}, Progress* progress = nullptr);

}  // namespace plumb
