// Planar patches on a voxel grid (Lu, Liu, Li 2019 steps 1-3, adapted): per-voxel moments,
// normals from the moments of each voxel's 3x3x3 block (PCA), region growing over 26-connected
// voxels whose normals differ by less than the smoothness angle and whose centroids lie near
// the growing plane, merging of adjacent coplanar patches, then point assignment: each point
// of a patch voxel or of a voxel next to patches joins the nearest patch plane within
// plane_tolerance (this carries patches up to their true edges).
#include "features/segments/voxel_patches.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <unordered_map>

#include "common/error.hpp"

namespace plumb::segments_detail {
namespace {

struct Cell {
  std::uint64_t key = 0;
  std::uint32_t begin = 0, end = 0;  // range in the sorted point order
  double count = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double curvature = 1.0;
  int region = -1;
};

constexpr std::uint64_t kBias = 1 << 20;
std::uint64_t packKey(std::int64_t x, std::int64_t y, std::int64_t z) {
  return ((std::uint64_t(x + kBias) & 0x1FFFFF) << 42) | ((std::uint64_t(y + kBias) & 0x1FFFFF) << 21) |
         (std::uint64_t(z + kBias) & 0x1FFFFF);
}
void unpackKey(std::uint64_t k, std::int64_t& x, std::int64_t& y, std::int64_t& z) {
  x = std::int64_t((k >> 42) & 0x1FFFFF) - std::int64_t(kBias);
  y = std::int64_t((k >> 21) & 0x1FFFFF) - std::int64_t(kBias);
  z = std::int64_t(k & 0x1FFFFF) - std::int64_t(kBias);
}

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

}  // namespace

std::vector<Patch> growPatches(const PointCloud& cloud, const SegmentDetectionParams& params,
                               Progress* progress) {
  const double h = params.voxel_size;
  const double tol = params.plane_tolerance;
  // 1. Voxel keys, points sorted by key.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
  keyed.reserve(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const auto& p = cloud.positions[i];
    if (!p.allFinite()) continue;
    keyed.emplace_back(packKey(std::int64_t(std::floor(p.x() / h)), std::int64_t(std::floor(p.y() / h)),
                               std::int64_t(std::floor(p.z() / h))),
                       static_cast<std::uint32_t>(i));
  }
  tbb::parallel_sort(keyed.begin(), keyed.end());
  std::vector<Cell> cells;
  for (std::uint32_t k = 0; k < keyed.size();) {
    Cell c;
    c.key = keyed[k].first;
    c.begin = k;
    while (k < keyed.size() && keyed[k].first == c.key) ++k;
    c.end = k;
    cells.push_back(c);
  }
  std::unordered_map<std::uint64_t, int> index;
  index.reserve(cells.size() * 2);
  for (std::size_t c = 0; c < cells.size(); ++c) index.emplace(cells[c].key, static_cast<int>(c));
  auto neighbours = [&](const Cell& c, std::vector<int>& out, int ring = 1) {
    out.clear();
    std::int64_t x, y, z;
    unpackKey(c.key, x, y, z);
    for (int dx = -ring; dx <= ring; ++dx)
      for (int dy = -ring; dy <= ring; ++dy)
        for (int dz = -ring; dz <= ring; ++dz) {
          if (!dx && !dy && !dz) continue;
          auto it = index.find(packKey(x + dx, y + dy, z + dz));
          if (it != index.end()) out.push_back(it->second);
        }
  };
  checkCanceled(progress);
  // 2. Moments per cell, then normals from 3x3x3 blocks.
  tbb::parallel_for(std::size_t(0), cells.size(), [&](std::size_t ci) {
    auto& c = cells[ci];
    for (auto k = c.begin; k < c.end; ++k) {
      const Eigen::Vector3d p = cloud.positions[keyed[k].second].cast<double>();
      c.sum += p;
      c.outer += p * p.transpose();
    }
    c.count = c.end - c.begin;
    c.centroid = c.sum / c.count;
  });
  tbb::parallel_for(std::size_t(0), cells.size(), [&](std::size_t ci) {
    std::vector<int> nb;
    auto& c = cells[ci];
    neighbours(c, nb);
    double n = c.count;
    Eigen::Vector3d s = c.sum;
    Eigen::Matrix3d o = c.outer;
    for (int j : nb) {
      n += cells[j].count;
      s += cells[j].sum;
      o += cells[j].outer;
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
  reportProgress(progress, 0.3, "patches");
  // 3. Region growing over planar cells, lowest curvature first.
  const double max_curv = 0.02;
  const double cos_smooth = std::cos(params.smoothness_deg * M_PI / 180.0);
  std::vector<int> order(cells.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return cells[a].curvature < cells[b].curvature; });
  struct Region {
    double count = 0;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
    PlaneFit fit;
    std::vector<int> cells;
  };
  std::vector<Region> regions;
  std::vector<int> nb;
  for (int seed : order) {
    if (cells[seed].region >= 0 || cells[seed].curvature > max_curv) continue;
    Region r;
    const int id = static_cast<int>(regions.size());
    cells[seed].region = id;
    r.cells.push_back(seed);
    r.count = cells[seed].count; r.sum = cells[seed].sum; r.outer = cells[seed].outer;
    r.fit.normal = cells[seed].normal;
    r.fit.offset = r.fit.normal.dot(cells[seed].centroid);
    double refit_at = 8;
    for (std::size_t k = 0; k < r.cells.size(); ++k) {
      const Cell& c = cells[r.cells[k]];
      neighbours(c, nb);
      for (int j : nb) {
        Cell& d = cells[j];
        if (d.region >= 0 || d.curvature > max_curv) continue;
        if (std::abs(d.normal.dot(c.normal)) < cos_smooth) continue;
        if (std::abs(d.normal.dot(r.fit.normal)) < cos_smooth) continue;
        if (std::abs(r.fit.normal.dot(d.centroid) - r.fit.offset) > 2 * tol) continue;
        d.region = id;
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
    regions.push_back(std::move(r));
  }
  checkCanceled(progress);
  // 4. Merge adjacent coplanar regions.
  const double cos_merge = std::cos(params.merge_angle_deg * M_PI / 180.0);
  const int nr = static_cast<int>(regions.size());
  UnionFind uf(std::max(nr, 1));
  std::set<std::pair<int, int>> adjacent;
  for (const auto& c : cells) {
    if (c.region < 0) continue;
    neighbours(c, nb);
    for (int j : nb)
      if (cells[j].region >= 0 && cells[j].region != c.region)
        adjacent.emplace(std::min(c.region, cells[j].region), std::max(c.region, cells[j].region));
  }
  for (auto [a, b] : adjacent) {
    const auto& fa = regions[a].fit;
    const auto& fb = regions[b].fit;
    if (std::abs(fa.normal.dot(fb.normal)) < cos_merge) continue;
    if (std::abs(fa.normal.dot(fb.centroid) - fa.offset) > tol ||
        std::abs(fb.normal.dot(fa.centroid) - fb.offset) > tol)
      continue;
    uf.unite(a, b);
  }
  std::vector<int> region_patch(nr, -1);
  std::vector<Patch> patches;
  std::vector<Region> merged;
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
  patches.resize(merged.size());
  for (std::size_t p = 0; p < merged.size(); ++p) patches[p].fit = fitPlaneFromMoments(merged[p].count, merged[p].sum, merged[p].outer);
  for (auto& c : cells)
    if (c.region >= 0) c.region = region_patch[c.region];
  reportProgress(progress, 0.5, "point assignment");
  // 5. Assign points: own patch, or for unassigned/edge cells the nearest adjacent patch.
  std::vector<int> point_patch(keyed.size(), -1);
  std::vector<std::set<int>> adj(patches.size());
  tbb::parallel_for(std::size_t(0), cells.size(), [&](std::size_t ci) {
    std::vector<int> nbl;
    std::vector<int> cand;
    const Cell& c = cells[ci];
    // Edge voxels see the patches two voxels away (their own block straddles the edge).
    neighbours(c, nbl, c.region >= 0 ? 1 : 2);
    if (c.region >= 0) cand.push_back(c.region);
    for (int j : nbl)
      if (cells[j].region >= 0 && std::find(cand.begin(), cand.end(), cells[j].region) == cand.end())
        cand.push_back(cells[j].region);
    if (cand.empty()) return;
    for (auto k = c.begin; k < c.end; ++k) {
      const Eigen::Vector3d p = cloud.positions[keyed[k].second].cast<double>();
      double best = tol;
      for (int r : cand) {
        if (!patches[r].fit.valid) continue;
        const double d = std::abs(patches[r].fit.normal.dot(p) - patches[r].fit.offset);
        if (d < best) { best = d; point_patch[k] = r; }
      }
    }
  });
  // Patches are adjacent when they meet in some voxel's neighbourhood (edge voxels between
  // two walls belong to neither region but see both).
  for (const auto& c : cells) {
    neighbours(c, nb, c.region >= 0 ? 1 : 2);
    std::vector<int> seen;
    if (c.region >= 0) seen.push_back(c.region);
    for (int j : nb)
      if (cells[j].region >= 0 && std::find(seen.begin(), seen.end(), cells[j].region) == seen.end())
        seen.push_back(cells[j].region);
    for (std::size_t a = 0; a < seen.size(); ++a)
      for (std::size_t b = a + 1; b < seen.size(); ++b) {
        adj[seen[a]].insert(seen[b]);
        adj[seen[b]].insert(seen[a]);
      }
  }
  for (std::size_t k = 0; k < keyed.size(); ++k)
    if (point_patch[k] >= 0) patches[point_patch[k]].points.push_back(keyed[k].second);
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

}  // namespace plumb::segments_detail
