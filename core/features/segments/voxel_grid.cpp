// Voxel grid of the segment detector: keys, sorted point ranges, moments and block normals
// (docs/ALGORITHMS.md §7, "kNN PCA normals", here from the 3x3x3 voxel block).
#include "features/segments/voxel_grid.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace plumb::segments_detail {
namespace {

constexpr std::uint64_t kBias = 1 << 20;

/// (key, index) of the finite points, sorted.
std::vector<std::pair<std::uint64_t, std::uint32_t>> sortedVoxelKeys(const PointCloud& cloud, double h) {
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
  keyed.reserve(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const auto& p = cloud.positions[i];
    if (!p.allFinite()) continue;
    keyed.emplace_back(packVoxelKey(std::int64_t(std::floor(p.x() / h)), std::int64_t(std::floor(p.y() / h)),
                                    std::int64_t(std::floor(p.z() / h))),
                       static_cast<std::uint32_t>(i));
  }
  tbb::parallel_sort(keyed.begin(), keyed.end());
  return keyed;
}

/// One cell per run of equal keys.
std::vector<VoxelCell> cellsOfSortedKeys(const std::vector<std::pair<std::uint64_t, std::uint32_t>>& keyed) {
  std::vector<VoxelCell> cells;
  for (std::uint32_t k = 0; k < keyed.size();) {
    VoxelCell c;
    c.key = keyed[k].first;
    c.begin = k;
    while (k < keyed.size() && keyed[k].first == c.key) ++k;
    c.end = k;
    cells.push_back(c);
  }
  return cells;
}

void accumulateMoments(const PointCloud& cloud, VoxelGrid& grid) {
  tbb::parallel_for(std::size_t(0), grid.cells.size(), [&](std::size_t ci) {
    auto& c = grid.cells[ci];
    for (auto k = c.begin; k < c.end; ++k) {
      const Eigen::Vector3d p = cloud.positions[grid.keyed[k].second].cast<double>();
      c.sum += p;
      c.outer += p * p.transpose();
    }
    c.count = c.end - c.begin;
    c.centroid = c.sum / c.count;
  });
}

/// Normal and curvature of each cell from the summed moments of its 3x3x3 block (at least 6
/// points).
void estimateBlockNormals(VoxelGrid& grid) {
  tbb::parallel_for(std::size_t(0), grid.cells.size(), [&](std::size_t ci) {
    std::vector<int> nb;
    auto& c = grid.cells[ci];
    grid.neighbours(c, nb);
    double n = c.count;
    Eigen::Vector3d s = c.sum;
    Eigen::Matrix3d o = c.outer;
    for (int j : nb) {
      n += grid.cells[j].count;
      s += grid.cells[j].sum;
      o += grid.cells[j].outer;
    }
    if (n < 6) return;
    const Eigen::Vector3d m = s / n;
    const Eigen::Matrix3d cov = o / n - m * m.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    const auto ev = eig.eigenvalues();
    const double total = ev.sum();
    if (!(total > 0)) return;
    c.normal = eig.eigenvectors().col(0);
    c.curvature = std::max(0.0, ev(0)) / total;
  });
}

}  // namespace

std::uint64_t packVoxelKey(std::int64_t x, std::int64_t y, std::int64_t z) {
  return ((std::uint64_t(x + kBias) & 0x1FFFFF) << 42) | ((std::uint64_t(y + kBias) & 0x1FFFFF) << 21) |
         (std::uint64_t(z + kBias) & 0x1FFFFF);
}

void unpackVoxelKey(std::uint64_t k, std::int64_t& x, std::int64_t& y, std::int64_t& z) {
  x = std::int64_t((k >> 42) & 0x1FFFFF) - std::int64_t(kBias);
  y = std::int64_t((k >> 21) & 0x1FFFFF) - std::int64_t(kBias);
  z = std::int64_t(k & 0x1FFFFF) - std::int64_t(kBias);
}

void VoxelGrid::neighbours(const VoxelCell& c, std::vector<int>& out, int ring) const {
  out.clear();
  std::int64_t x, y, z;
  unpackVoxelKey(c.key, x, y, z);
  for (int dx = -ring; dx <= ring; ++dx)
    for (int dy = -ring; dy <= ring; ++dy)
      for (int dz = -ring; dz <= ring; ++dz) {
        if (!dx && !dy && !dz) continue;
        auto it = index.find(packVoxelKey(x + dx, y + dy, z + dz));
        if (it != index.end()) out.push_back(it->second);
      }
}

VoxelGrid buildVoxelGrid(const PointCloud& cloud, double voxel_size) {
  VoxelGrid grid;
  grid.keyed = sortedVoxelKeys(cloud, voxel_size);
  grid.cells = cellsOfSortedKeys(grid.keyed);
  grid.index.reserve(grid.cells.size() * 2);
  for (std::size_t c = 0; c < grid.cells.size(); ++c) grid.index.emplace(grid.cells[c].key, static_cast<int>(c));
  accumulateMoments(cloud, grid);
  estimateBlockNormals(grid);
  return grid;
}

}  // namespace plumb::segments_detail
