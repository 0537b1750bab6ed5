#include "registration/segment_distance/segment_set_distance.hpp"

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "registration/segment_distance/segment_pair_distance.hpp"

namespace plumb {

const ParamSchema<SegmentDistanceParams>& SegmentDistanceParams::schema() {
  static const auto s =
      ParamSchema<SegmentDistanceParams>("segment-distance")
          .real(&SegmentDistanceParams::robust_distance, "robust-distance", "Robust distance", "m",
                0.001, 10.0, "Segments further apart than this count as unmatched (the robust cut-off)\n"
                "(d of the global robust segment distance, 2023 eq. 7)")
          .real(&SegmentDistanceParams::max_angle_deg, "segment-angle", "Segment angle", "deg",
                0.5, 45.0, "Max angle between segments that may match", true);
  return s;
}

namespace {
constexpr std::int64_t kBias = 1 << 20;
std::uint64_t packKey(std::int64_t x, std::int64_t y, std::int64_t z) {
  return (std::uint64_t(x + kBias) << 42) | (std::uint64_t(y + kBias) << 21) |
         std::uint64_t(z + kBias);
}
}  // namespace

SegmentSetIndex::SegmentSetIndex(std::vector<Segment3D> target,
                                 const SegmentDistanceParams& params)
    : target_(std::move(target)), params_(params) {
  if (!(params.robust_distance > 0)) throw InputError("robust distance must be positive");
  cos_max_angle_ = std::cos(params.max_angle_deg * M_PI / 180.0);
  // A cell of a few times d: a source segment's samples (every cell_) look up one cell each;
  // each target segment is registered in every cell within one cell of its samples, so any
  // target closer than cell_ to a sample is found.
  cell_ = std::max(4.0 * params.robust_distance, 0.25);
  dir_.reserve(target_.size());
  for (std::uint32_t i = 0; i < target_.size(); ++i) {
    const auto& s = target_[i];
    const double len = s.length();
    dir_.push_back(len > 0 ? Eigen::Vector3d((s.b - s.a) / len) : Eigen::Vector3d::UnitX());
    const int n = std::max(1, int(std::ceil(len / cell_)));
    std::vector<std::uint64_t> keys;
    for (int k = 0; k <= n; ++k) {
      const Eigen::Vector3d p = s.a + (s.b - s.a) * (double(k) / n);
      const std::int64_t cx = std::int64_t(std::floor(p.x() / cell_));
      const std::int64_t cy = std::int64_t(std::floor(p.y() / cell_));
      const std::int64_t cz = std::int64_t(std::floor(p.z() / cell_));
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz) keys.push_back(packKey(cx + dx, cy + dy, cz + dz));
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    for (auto k : keys) grid_[k].push_back(i);
  }
}

std::uint64_t SegmentSetIndex::key(const Eigen::Vector3d& p) const {
  return packKey(std::int64_t(std::floor(p.x() / cell_)), std::int64_t(std::floor(p.y() / cell_)),
                 std::int64_t(std::floor(p.z() / cell_)));
}

void SegmentSetIndex::candidates(const Eigen::Vector3d& p, std::vector<std::uint32_t>& out) const {
  const auto it = grid_.find(key(p));
  if (it != grid_.end()) out.insert(out.end(), it->second.begin(), it->second.end());
}

SegmentMatch SegmentSetIndex::match(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  const double d2 = params_.robust_distance * params_.robust_distance;
  SegmentMatch m;
  m.cost = d2;
  const double len = (b - a).norm();
  if (len <= 0) return m;
  const Eigen::Vector3d dir = (b - a) / len;
  thread_local std::vector<std::uint32_t> cand;
  cand.clear();
  // Samples every cell_/2: with cell_ >= 4 d, any target within d of the segment is
  // registered in the cell of some sample.
  const int n = std::max(1, int(std::ceil(2.0 * len / cell_)));
  for (int k = 0; k <= n; ++k) candidates(a + (b - a) * (double(k) / n), cand);
  std::sort(cand.begin(), cand.end());
  cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  double sum = 0.0, best_term = 0.0;
  for (std::uint32_t j : cand) {
    if (std::abs(dir.dot(dir_[j])) < cos_max_angle_) continue;
    const auto& t = target_[j];
    const SegmentPairMeasure pm = measureSegmentPair(a, b, t.a, t.b);
    if (pm.relative_overlap <= 0 || pm.distance >= params_.robust_distance) continue;
    // Eq. 7 term: relative overlap * max(0, d^2 - D^2).
    const double term = pm.relative_overlap * (d2 - pm.distance * pm.distance);
    sum += term;
    if (term > best_term) {
      best_term = term;
      m.target = int(j);
      m.distance = pm.distance;
    }
  }
  m.cost = std::max(0.0, d2 - sum);  // eq. 7, clamped at 0 (docs/ALGORITHMS.md §5)
  return m;
}

double SegmentSetIndex::distance(const std::vector<Segment3D>& source,
                                 const RigidTransform& t) const {
  double total = 0.0;  // eq. 8
  for (const auto& s : source) total += match(t.apply(s.a), t.apply(s.b)).cost;
  return total;
}

double SegmentSetIndex::similarity(const std::vector<Segment3D>& source,
                                   const RigidTransform& t) const {
  const double d2 = params_.robust_distance * params_.robust_distance;
  return double(source.size()) - distance(source, t) / d2;
}

}  // namespace plumb
