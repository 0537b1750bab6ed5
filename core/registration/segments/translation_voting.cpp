#include "registration/segments/translation_voting.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "model/point_cloud.hpp"

namespace plumb {

namespace {

/// Vote grid over the range of t (target box minus rotated source box, one cell margin).
struct VoteGrid {
  Eigen::Vector3d lo;
  double cell;
  int nx, ny, nz;
  std::vector<float> votes;

  std::size_t at(int x, int y, int z) const { return (std::size_t(z) * ny + y) * nx + x; }
  bool inside(int x, int y, int z) const {
    return x >= 0 && y >= 0 && z >= 0 && x < nx && y < ny && z < nz;
  }
  /// Cell of translation t, -1 outside the grid.
  std::int64_t index(const Eigen::Vector3d& t) const {
    const int ix = int(std::floor((t.x() - lo.x()) / cell));
    const int iy = int(std::floor((t.y() - lo.y()) / cell));
    const int iz = int(std::floor((t.z() - lo.z()) / cell));
    if (ix < 0 || iy < 0 || iz < 0 || ix >= nx || iy >= ny || iz >= nz) return -1;
    return (std::int64_t(iz) * ny + iy) * nx + ix;
  }
  Eigen::Vector3d centre(int x, int y, int z) const {
    return lo + cell * Eigen::Vector3d(x + 0.5, y + 0.5, z + 0.5);
  }
};

/// Grid of `cell` (coarsened by 1.25 until it has at most 16e6 cells) over the range of t:
/// target box minus rotated source box.
VoteGrid makeGrid(const Bounds& rotated_source, const Bounds& target, double cell) {
  VoteGrid g;
  g.lo = target.min - rotated_source.max - Eigen::Vector3d::Constant(cell);
  const Eigen::Vector3d hi = target.max - rotated_source.min + Eigen::Vector3d::Constant(cell);
  const Eigen::Vector3d ext = hi - g.lo;
  while (std::ceil(ext.x() / cell) * std::ceil(ext.y() / cell) * std::ceil(ext.z() / cell) > 16e6)
    cell *= 1.25;
  g.cell = cell;
  g.nx = int(std::ceil(ext.x() / cell));
  g.ny = int(std::ceil(ext.y() / cell));
  g.nz = int(std::ceil(ext.z() / cell));
  g.votes.assign(std::size_t(g.nx) * g.ny * g.nz, 0.0f);
  return g;
}

/// The pair (source segment with rotated midpoint `mid_s` and length `li`, target segment
/// `sj`) votes along the line of translations t = base + tau d_j where the two overlap by at
/// least half the shorter one, weight the shorter length, once per cell.
void votePair(VoteGrid& g, const Eigen::Vector3d& mid_s, double li, const Segment3D& sj) {
  const double lj = sj.length();
  const Eigen::Vector3d dj = (sj.b - sj.a) / lj;
  const Eigen::Vector3d base = sj.midpoint() - mid_s;
  // Overlap >= half the shorter segment <=> |shift along d_j| <= (li+lj)/2 - min/2.
  const double half = 0.5 * (li + lj) - 0.5 * std::min(li, lj);
  const int steps = std::max(1, int(std::ceil(2.0 * half / (0.5 * g.cell))));
  const float w = float(std::min(li, lj));
  std::int64_t last = -2;
  for (int s = 0; s <= steps; ++s) {
    const double tau = -half + 2.0 * half * double(s) / steps;
    const std::int64_t c = g.index(base + tau * dj);
    if (c >= 0 && c != last) g.votes[c] += w;
    last = c;
  }
}

struct Peak {
  float v;
  int x, y, z;
};

/// Whether cell (x, y, z) beats its 26 neighbours; ties broken by index so plateaus yield
/// one maximum.
bool isLocalMax(const VoteGrid& g, int x, int y, int z) {
  const float v = g.votes[g.at(x, y, z)];
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if (!dx && !dy && !dz) continue;
        const int xx = x + dx, yy = y + dy, zz = z + dz;
        if (!g.inside(xx, yy, zz)) continue;
        const float o = g.votes[g.at(xx, yy, zz)];
        if (o > v || (o == v && g.at(xx, yy, zz) < g.at(x, y, z))) return false;
      }
  return true;
}

/// Local maxima over the 26-neighbourhood, best first (stable: ties in index order).
std::vector<Peak> localMaxima(const VoteGrid& g) {
  std::vector<Peak> peaks;
  const float floor_v = 1e-6f;
  for (int z = 0; z < g.nz; ++z)
    for (int y = 0; y < g.ny; ++y)
      for (int x = 0; x < g.nx; ++x) {
        const float v = g.votes[g.at(x, y, z)];
        if (v <= floor_v) continue;
        if (isLocalMax(g, x, y, z)) peaks.push_back({v, x, y, z});
      }
  std::stable_sort(peaks.begin(), peaks.end(), [](const Peak& a, const Peak& b) { return a.v > b.v; });
  return peaks;
}

/// Up to `max_peaks` cell centres of the peaks, each farther than 2 cells from those kept.
std::vector<Eigen::Vector3d> strongestSeparated(const VoteGrid& g, const std::vector<Peak>& peaks,
                                                int max_peaks) {
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
    out.push_back(g.centre(pk.x, pk.y, pk.z));
  }
  return out;
}

}  // namespace

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
  VoteGrid grid = makeGrid(bs, bt, cell);
  for (std::size_t k = 0; k < cs.clusters.size(); ++k) {
    const int m = k < rot.target_of_source.size() ? rot.target_of_source[k] : -1;
    if (m < 0) continue;
    for (int i : cs.clusters[k].members) {
      const double li = source[i].length();
      for (int j : ct.clusters[m].members) votePair(grid, mid_s[i], li, target[j]);
    }
  }
  // Local maxima over the 26-neighbourhood, best first, then suppression within 2 cells.
  return strongestSeparated(grid, localMaxima(grid), max_peaks);
}

}  // namespace plumb
