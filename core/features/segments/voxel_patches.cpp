// Planar patches on a voxel grid (Lu, Liu, Li 2019 steps 1-3, adapted): per-voxel moments,
// normals from the moments of each voxel's 3x3x3 block (PCA), region growing over 26-connected
// voxels whose normals differ by less than the smoothness angle and whose centroids lie near
// the growing plane, merging of adjacent coplanar patches, then point assignment: each point
// of a patch voxel or of a voxel next to patches joins the nearest patch plane within
// plane_tolerance (this carries patches up to their true edges).
#include "features/segments/voxel_patches.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "features/segments/voxel_regions.hpp"

namespace plumb::segments_detail {
namespace {

/// Points of each patch (sorted cloud indices), the plane refitted on them (3 points or more),
/// and the adjacency lists.
std::vector<Patch> collectPatches(const PointCloud& cloud, const VoxelGrid& grid, const std::vector<int>& point_patch,
                                  const std::vector<PlaneFit>& fits, const std::vector<std::set<int>>& adj) {
  std::vector<Patch> patches(fits.size());
  for (std::size_t p = 0; p < fits.size(); ++p) patches[p].fit = fits[p];
  for (std::size_t k = 0; k < grid.keyed.size(); ++k)
    if (point_patch[k] >= 0) patches[point_patch[k]].points.push_back(grid.keyed[k].second);
  for (std::size_t p = 0; p < patches.size(); ++p) {
    auto& pts = patches[p].points;
    std::sort(pts.begin(), pts.end());
    if (pts.size() >= 3) {
      const PlaneFit f = fitPlaneLocal(cloud, pts);
      if (f.valid) patches[p].fit = f;
    }
    patches[p].neighbours.assign(adj[p].begin(), adj[p].end());
  }
  return patches;
}

}  // namespace

void patchesAround(const VoxelGrid& grid, const std::vector<int>& cell_patch, std::size_t cell,
                   std::vector<int>& nb, std::vector<int>& out) {
  out.clear();
  const int own = cell_patch[cell];
  grid.neighbours(grid.cells[cell], nb, own >= 0 ? 1 : 2);
  if (own >= 0) out.push_back(own);
  for (int j : nb)
    if (cell_patch[j] >= 0 && std::find(out.begin(), out.end(), cell_patch[j]) == out.end())
      out.push_back(cell_patch[j]);
}

std::vector<int> assignPointsToPatches(const PointCloud& cloud, const VoxelGrid& grid,
                                       const std::vector<int>& cell_patch, const std::vector<PlaneFit>& fits,
                                       double tolerance) {
  std::vector<int> point_patch(grid.keyed.size(), -1);
  tbb::parallel_for(std::size_t(0), grid.cells.size(), [&](std::size_t ci) {
    std::vector<int> nb, cand;
    patchesAround(grid, cell_patch, ci, nb, cand);
    const VoxelCell& c = grid.cells[ci];
    for (auto k = c.begin; k < c.end; ++k) {
      const Eigen::Vector3d p = cloud.positions[grid.keyed[k].second].cast<double>();
      double best = tolerance;
      for (int r : cand) {
        if (!fits[r].valid) continue;
        const double d = std::abs(fits[r].normal.dot(p) - fits[r].offset);
        if (d < best) { best = d; point_patch[k] = r; }
      }
    }
  });
  return point_patch;
}

std::vector<std::set<int>> patchAdjacency(const VoxelGrid& grid, const std::vector<int>& cell_patch,
                                          std::size_t patch_count) {
  std::vector<std::set<int>> adj(patch_count);
  std::vector<int> nb, seen;
  for (std::size_t ci = 0; ci < grid.cells.size(); ++ci) {
    patchesAround(grid, cell_patch, ci, nb, seen);
    for (std::size_t a = 0; a < seen.size(); ++a)
      for (std::size_t b = a + 1; b < seen.size(); ++b) {
        adj[seen[a]].insert(seen[b]);
        adj[seen[b]].insert(seen[a]);
      }
  }
  return adj;
}

std::vector<Patch> growPatches(const PointCloud& cloud, const SegmentDetectionParams& params,
                               Progress* progress) {
  const double tol = params.plane_tolerance;
  const VoxelGrid grid = buildVoxelGrid(cloud, params.voxel_size);
  checkCanceled(progress);
  reportProgress(progress, 0.3, "patches");
  const RegionGrowth growth = growRegions(grid, params.smoothness_deg, tol);
  checkCanceled(progress);
  const MergedRegions merged = mergeCoplanarRegions(grid, growth, params.merge_angle_deg, tol);
  reportProgress(progress, 0.5, "point assignment");
  const std::vector<int> point_patch = assignPointsToPatches(cloud, grid, merged.cell_patch, merged.fits, tol);
  const auto adjacency = patchAdjacency(grid, merged.cell_patch, merged.fits.size());
  return collectPatches(cloud, grid, point_patch, merged.fits, adjacency);
}

}  // namespace plumb::segments_detail
