#pragma once
// Internal to the segments module: voxel-grid normals and region growing into planar patches
// (the first stages of Lu, Liu, Li 2019, on voxels instead of per-point kNN).
#include <cstdint>
#include <vector>

#include "features/planes/plane_fit.hpp"
#include "features/segments/segment_detection.hpp"

namespace plumb::segments_detail {

struct Patch {
  PlaneFit fit;                          ///< local coordinates
  std::vector<std::uint32_t> points;     ///< cloud indices within plane_tolerance
  std::vector<int> neighbours;           ///< adjacent patches (shared voxel neighbourhood)
};

/// Normals per voxel (moments of the 3x3x3 block), region growing over voxels, patch merging,
/// and assignment of every point to the nearest adjacent patch plane within tolerance.
std::vector<Patch> growPatches(const PointCloud& cloud, const SegmentDetectionParams& params,
                               Progress* progress);

}  // namespace plumb::segments_detail
