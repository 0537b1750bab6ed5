#pragma once
// Internal to the segments module: region growing over planar voxels and merging of adjacent
// coplanar regions (Lu, Liu, Li 2019 steps 2-3, on voxels).
#include <Eigen/Core>

#include <vector>

#include "features/planes/plane_fit.hpp"
#include "features/segments/voxel_grid.hpp"

namespace plumb::segments_detail {

/// A region of voxels and the moments of their points.
struct PlaneRegion {
  double count = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
  PlaneFit fit;
  std::vector<int> cells;  ///< in the order they joined
};

struct RegionGrowth {
  std::vector<PlaneRegion> regions;
  std::vector<int> cell_region;  ///< per grid cell, -1: in no region
};

/// Seeds in increasing curvature (planar cells only, curvature <= 0.02); a neighbour joins when
/// its normal is within `smoothness_deg` of both the cell it is reached from and the region's
/// plane, and its centroid within 2 `tolerance` of that plane. The plane is refitted each time
/// the region doubles (8, 16, ... cells) and at the end.
RegionGrowth growRegions(const VoxelGrid& grid, double smoothness_deg, double tolerance);

/// Regions merged into patches.
struct MergedRegions {
  std::vector<PlaneFit> fits;    ///< per patch, from the summed moments of its regions
  std::vector<int> cell_patch;   ///< per grid cell, -1: in no patch
};

/// Unites regions that touch (26-neighbouring cells), whose normals are within
/// `merge_angle_deg` and whose centroids lie within `tolerance` of each other's plane.
/// Patches are numbered in the order of their lowest region.
MergedRegions mergeCoplanarRegions(const VoxelGrid& grid, const RegionGrowth& growth, double merge_angle_deg,
                                   double tolerance);

}  // namespace plumb::segments_detail
