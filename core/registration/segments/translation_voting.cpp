#include "registration/segments/translation_voting.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "model/point_cloud.hpp"

namespace plumb {

std::vector<Eigen::Vector3d> voteTranslations(const std::vector<Segment3D>& source,
                                              const DirectionClusteringResult& cs,
                                              const std::vector<Segment3D>& target,
                                              const DirectionClusteringResult& ct,
                                              const RotationCandidate& rot, double cell,
                                              int max_peaks) {
  const Eigen::Matrix3d& R = rot.rotation;
  // Range of t: target box minus rotated source box.
  Bounds bs, bt;
  std::vector<Eigen::Vector3d> mid_s(source.size());
  for (std::size_t i = 0; i < source.size(); ++i) {
    bs.extend(R * source[i].a);
    bs.extend(R * source[i].b);
    mid_s[i] = R * source[i].midpoint();
  }
  for (const auto& s : target) {
    bt.extend(s.a);
    bt.extend(s.b);
  }
  const Eigen::Vector3d lo = bt.min - bs.max - Eigen::Vector3d::Constant(cell);
  const Eigen::Vector3d hi = bt.max - bs.min + Eigen::Vector3d::Constant(cell);
  const Eigen::Vector3d ext = hi - lo;
  while (std::ceil(ext.x() / cell) * std::ceil(ext.y() / cell) * std::ceil(ext.z() / cell) > 16e6)
    cell *= 1.25;
  const int nx = int(std::ceil(ext.x() / cell)), ny = int(std::ceil(ext.y() / cell)),
            nz = int(std::ceil(ext.z() / cell));
  std::vector<float> grid(std::size_t(nx) * ny * nz, 0.0f);
  auto index = [&](const Eigen::Vector3d& t) -> std::int64_t {
    const int ix = int(std::floor((t.x() - lo.x()) / cell));
    const int iy = int(std::floor((t.y() - lo.y()) / cell));
    const int iz = int(std::floor((t.z() - lo.z()) / cell));
    if (ix < 0 || iy < 0 || iz < 0 || ix >= nx || iy >= ny || iz >= nz) return -1;
    return (std::int64_t(iz) * ny + iy) * nx + ix;
  };
  for (std::size_t k = 0; k < cs.clusters.size(); ++k) {
    const int m = k < rot.target_of_source.size() ? rot.target_of_source[k] : -1;
    if (m < 0) continue;
    for (int i : cs.clusters[k].members) {
      const double li = source[i].length();
      for (int j : ct.clusters[m].members) {
        const auto& sj = target[j];
        const double lj = sj.length();
        const Eigen::Vector3d dj = (sj.b - sj.a) / lj;
        const Eigen::Vector3d base = sj.midpoint() - mid_s[i];
        // Overlap >= half the shorter segment <=> |shift along d_j| <= (li+lj)/2 - min/2.
        const double half = 0.5 * (li + lj) - 0.5 * std::min(li, lj);
        const int steps = std::max(1, int(std::ceil(2.0 * half / (0.5 * cell))));
        const float w = float(std::min(li, lj));
        std::int64_t last = -2;
        for (int s = 0; s <= steps; ++s) {
          const double tau = -half + 2.0 * half * double(s) / steps;
          const std::int64_t c = index(base + tau * dj);
          if (c >= 0 && c != last) grid[c] += w;
          last = c;
        }
      }
    }
  }
  // Local maxima over the 26-neighbourhood, best first, then suppression within 2 cells.
  struct Peak {
    float v;
    int x, y, z;
  };
  std::vector<Peak> peaks;
  const float floor_v = 1e-6f;
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const float v = grid[(std::size_t(z) * ny + y) * nx + x];
        if (v <= floor_v) continue;
        bool is_max = true;
        for (int dz = -1; dz <= 1 && is_max; ++dz)
          for (int dy = -1; dy <= 1 && is_max; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              if (!dx && !dy && !dz) continue;
              const int xx = x + dx, yy = y + dy, zz = z + dz;
              if (xx < 0 || yy < 0 || zz < 0 || xx >= nx || yy >= ny || zz >= nz) continue;
              const float o = grid[(std::size_t(zz) * ny + yy) * nx + xx];
              // Ties broken by index so plateaus yield one maximum.
              if (o > v || (o == v && (std::size_t(zz) * ny + yy) * nx + xx <
                                          (std::size_t(z) * ny + y) * nx + x)) {
                is_max = false;
                break;
              }
            }
        if (is_max) peaks.push_back({v, x, y, z});
      }
  std::stable_sort(peaks.begin(), peaks.end(), [](const Peak& a, const Peak& b) { return a.v > b.v; });
  std::vector<Eigen::Vector3d> out;
  std::vector<Peak> kept;
  for (const auto& pk : peaks) {
    if (int(out.size()) >= max_peaks) break;
    bool near = false;
    for (const auto& k : kept)
      if (std::abs(k.x - pk.x) <= 2 && std::abs(k.y - pk.y) <= 2 && std::abs(k.z - pk.z) <= 2)
        near = true;
    if (near) continue;
    kept.push_back(pk);
    out.push_back(lo + cell * Eigen::Vector3d(pk.x + 0.5, pk.y + 0.5, pk.z + 0.5));
  }
  return out;
}

}  // namespace plumb
