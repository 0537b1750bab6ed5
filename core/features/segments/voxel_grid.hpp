#pragma once
// Internal to the segments module: the voxel grid under the patch growing (Lu, Liu, Li 2019
// step 1, on voxels instead of per-point kNN). Points are sorted by voxel key; each occupied
// voxel keeps its point range, its first and second moments, and a normal and curvature from
// the PCA of its 3x3x3 block.
#include <Eigen/Core>

#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "model/point_cloud.hpp"

namespace plumb::segments_detail {

/// One occupied voxel.
struct VoxelCell {
  std::uint64_t key = 0;
  std::uint32_t begin = 0, end = 0;  ///< range in VoxelGrid::keyed
  double count = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();  ///< sum of p p^T
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< of the 3x3x3 block (zero: too few points)
  double curvature = 1.0;  ///< lambda_min / (lambda_0 + lambda_1 + lambda_2) of the block
};

struct VoxelGrid {
  /// (voxel key, cloud index) of every finite point, sorted by key then index.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
  std::vector<VoxelCell> cells;  ///< in key order
  std::unordered_map<std::uint64_t, int> index;  ///< key -> cell

  /// Occupied cells in the (2 ring + 1)^3 block around `cell` (itself excluded), in dx, dy, dz
  /// order. `out` is cleared first (callers reuse it).
  void neighbours(const VoxelCell& cell, std::vector<int>& out, int ring = 1) const;
};

/// 21 bits per axis, biased so that negative voxel coordinates pack too.
std::uint64_t packVoxelKey(std::int64_t x, std::int64_t y, std::int64_t z);
void unpackVoxelKey(std::uint64_t key, std::int64_t& x, std::int64_t& y, std::int64_t& z);

/// Points sorted by voxel, cells with their point ranges and moments, normals of the blocks.
VoxelGrid buildVoxelGrid(const PointCloud& cloud, double voxel_size);

}  // namespace plumb::segments_detail
