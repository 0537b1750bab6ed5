#pragma once
// Internal to the segments module: voxel-grid normals and region growing into planar patches
// (the first stages of Lu, Liu, Li 2019, on voxels instead of per-point kNN).
#include <cstdint>
#include <set>
#include <vector>

#include "features/planes/plane_fit.hpp"
#include "features/segments/segment_detection.hpp"
#include "features/segments/voxel_grid.hpp"

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

// Steps of growPatches after the voxel grid and the regions (voxel_grid.hpp, voxel_regions.hpp).

/// Patches seen from a cell: its own first, then those of the cells within `ring`, each once.
/// Cells in a patch look 1 voxel around; edge cells (in none) 2, since their own block
/// straddles the edge. `nb` is scratch space.
void patchesAround(const VoxelGrid& grid, const std::vector<int>& cell_patch, std::size_t cell,
                   std::vector<int>& nb, std::vector<int>& out);

/// Per entry of grid.keyed: the patch whose plane is nearest to the point among the patches
/// around its cell, if nearer than `tolerance` (-1 otherwise). Invalid fits take no points.
std::vector<int> assignPointsToPatches(const PointCloud& cloud, const VoxelGrid& grid,
                                       const std::vector<int>& cell_patch, const std::vector<PlaneFit>& fits,
                                       double tolerance);

/// Patches are adjacent when they meet in some cell's neighbourhood (edge voxels between two
/// walls belong to neither patch but see both).
std::vector<std::set<int>> patchAdjacency(const VoxelGrid& grid, const std::vector<int>& cell_patch,
                                          std::size_t patch_count);

}  // namespace plumb::segments_detail
