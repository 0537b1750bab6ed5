// Region growing over voxels and merging of coplanar regions (docs/ALGORITHMS.md §7: "region
// growing into planar patches, patch merging").
#include "features/segments/voxel_regions.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <utility>

namespace plumb::segments_detail {
namespace {

/// Cells above this block curvature are not planar: they neither seed nor join a region.
constexpr double kMaxCurvature = 0.02;

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) {
    a = find(a); b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

std::vector<int> cellsByCurvature(const VoxelGrid& grid) {
  std::vector<int> order(grid.cells.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return grid.cells[a].curvature < grid.cells[b].curvature; });
  return order;
}

/// Grows one region from `seed`, labelling its cells `id` in `cell_region`.
PlaneRegion growRegion(const VoxelGrid& grid, int seed, int id, double cos_smooth, double tol,
                       std::vector<int>& cell_region) {
  const auto& cells = grid.cells;
  PlaneRegion r;
  cell_region[seed] = id;
  r.cells.push_back(seed);
  r.count = cells[seed].count; r.sum = cells[seed].sum; r.outer = cells[seed].outer;
  r.fit.normal = cells[seed].normal;
  r.fit.offset = r.fit.normal.dot(cells[seed].centroid);
  double refit_at = 8;
  std::vector<int> nb;
  for (std::size_t k = 0; k < r.cells.size(); ++k) {
    const VoxelCell& c = cells[r.cells[k]];
    grid.neighbours(c, nb);
    for (int j : nb) {
      const VoxelCell& d = cells[j];
      if (cell_region[j] >= 0 || d.curvature > kMaxCurvature) continue;
      if (std::abs(d.normal.dot(c.normal)) < cos_smooth) continue;
      if (std::abs(d.normal.dot(r.fit.normal)) < cos_smooth) continue;
      if (std::abs(r.fit.normal.dot(d.centroid) - r.fit.offset) > 2 * tol) continue;
      cell_region[j] = id;
      r.cells.push_back(j);
      r.count += d.count; r.sum += d.sum; r.outer += d.outer;
    }
    if (double(r.cells.size()) >= refit_at) {
      const PlaneFit f = fitPlaneFromMoments(r.count, r.sum, r.outer);
      if (f.valid) r.fit = f;
      refit_at *= 2;
    }
  }
  const PlaneFit f = fitPlaneFromMoments(r.count, r.sum, r.outer);
  if (f.valid) r.fit = f;
  return r;
}

/// Pairs (a < b) of regions with 26-neighbouring cells.
std::set<std::pair<int, int>> touchingRegions(const VoxelGrid& grid, const std::vector<int>& cell_region) {
  std::set<std::pair<int, int>> adjacent;
  std::vector<int> nb;
  for (std::size_t ci = 0; ci < grid.cells.size(); ++ci) {
    const int a = cell_region[ci];
    if (a < 0) continue;
    grid.neighbours(grid.cells[ci], nb);
    for (int j : nb)
      if (cell_region[j] >= 0 && cell_region[j] != a)
        adjacent.emplace(std::min(a, cell_region[j]), std::max(a, cell_region[j]));
  }
  return adjacent;
}

bool coplanar(const PlaneFit& fa, const PlaneFit& fb, double cos_merge, double tol) {
  if (std::abs(fa.normal.dot(fb.normal)) < cos_merge) return false;
  return !(std::abs(fa.normal.dot(fb.centroid) - fa.offset) > tol ||
           std::abs(fb.normal.dot(fa.centroid) - fb.offset) > tol);
}

}  // namespace

RegionGrowth growRegions(const VoxelGrid& grid, double smoothness_deg, double tolerance) {
  const double cos_smooth = std::cos(smoothness_deg * M_PI / 180.0);
  RegionGrowth g;
  g.cell_region.assign(grid.cells.size(), -1);
  for (int seed : cellsByCurvature(grid)) {
    if (g.cell_region[seed] >= 0 || grid.cells[seed].curvature > kMaxCurvature) continue;
    const int id = static_cast<int>(g.regions.size());
    g.regions.push_back(growRegion(grid, seed, id, cos_smooth, tolerance, g.cell_region));
  }
  return g;
}

MergedRegions mergeCoplanarRegions(const VoxelGrid& grid, const RegionGrowth& growth, double merge_angle_deg,
                                   double tolerance) {
  const double cos_merge = std::cos(merge_angle_deg * M_PI / 180.0);
  const auto& regions = growth.regions;
  const int nr = static_cast<int>(regions.size());
  UnionFind uf(std::max(nr, 1));
  for (auto [a, b] : touchingRegions(grid, growth.cell_region))
    if (coplanar(regions[a].fit, regions[b].fit, cos_merge, tolerance)) uf.unite(a, b);
  std::vector<int> region_patch(nr, -1);
  std::vector<PlaneRegion> merged;
  for (int r = 0; r < nr; ++r) {
    const int root = uf.find(r);
    if (region_patch[root] < 0) {
      region_patch[root] = static_cast<int>(merged.size());
      merged.emplace_back();
    }
    region_patch[r] = region_patch[root];
    auto& m = merged[region_patch[r]];
    m.count += regions[r].count; m.sum += regions[r].sum; m.outer += regions[r].outer;
  }
  MergedRegions out;
  for (const auto& m : merged) out.fits.push_back(fitPlaneFromMoments(m.count, m.sum, m.outer));
  out.cell_patch.assign(grid.cells.size(), -1);
  for (std::size_t c = 0; c < grid.cells.size(); ++c)
    if (growth.cell_region[c] >= 0) out.cell_patch[c] = region_patch[growth.cell_region[c]];
  return out;
}

}  // namespace plumb::segments_detail
