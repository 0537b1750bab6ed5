#include "registration/planes/polygon_raster.hpp"

#include <algorithm>
#include <cmath>

namespace plumb {

PolygonRaster::PolygonRaster(const PlanarPolygon& p, int cells_across, int max_samples)
    : origin_(p.origin), u_(p.u_axis), v_(p.v_axis) {
  if (p.rings.empty() || p.rings[0].size() < 3) return;
  Eigen::Vector2d lo = p.rings[0][0], hi = p.rings[0][0];
  for (const auto& q : p.rings[0]) {
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const Eigen::Vector2d ext = hi - lo;
  cell_ = std::max(ext.maxCoeff() / std::max(cells_across, 1), 1e-4);
  lo_ = lo;
  nu_ = std::max(1, int(std::ceil(ext.x() / cell_)));
  nv_ = std::max(1, int(std::ceil(ext.y() / cell_)));
  mask_.assign(std::size_t(nu_) * nv_, 0);
  // Even-odd scanline fill at cell-centre rows, all rings together (holes toggle parity).
  std::vector<double> xs;
  for (int j = 0; j < nv_; ++j) {
    const double y = lo_.y() + (j + 0.5) * cell_;
    xs.clear();
    for (const auto& ring : p.rings) {
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const Eigen::Vector2d& a = ring[k];
        const Eigen::Vector2d& b = ring[(k + 1) % ring.size()];
        if ((a.y() <= y) != (b.y() <= y)) xs.push_back(a.x() + (y - a.y()) / (b.y() - a.y()) * (b.x() - a.x()));
      }
    }
    std::sort(xs.begin(), xs.end());
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
      // Cells whose centre lies in [xs[k], xs[k+1]).
      const int i0 = std::max(0, int(std::ceil((xs[k] - lo_.x()) / cell_ - 0.5)));
      const int i1 = std::min(nu_ - 1, int(std::ceil((xs[k + 1] - lo_.x()) / cell_ - 0.5)) - 1);
      for (int i = i0; i <= i1; ++i) mask_[std::size_t(j) * nu_ + i] = 1;
    }
  }
  std::size_t count = 0;
  for (auto m : mask_) count += m;
  area_ = double(count) * cell_ * cell_;
  const std::size_t stride = std::max<std::size_t>(1, (count + max_samples - 1) / max_samples);
  // Regular subset of inside cells: every stride-th in raster order.
  std::size_t seen = 0;
  for (int j = 0; j < nv_; ++j)
    for (int i = 0; i < nu_; ++i)
      if (mask_[std::size_t(j) * nu_ + i] && (seen++ % stride) == 0)
        samples_.push_back(p.to3d(lo_ + Eigen::Vector2d((i + 0.5) * cell_, (j + 0.5) * cell_)));
  sample_area_ = samples_.empty() ? 0.0 : area_ / double(samples_.size());
  const std::size_t cstride = std::max<std::size_t>(1, samples_.size() / 64);
  for (std::size_t k = 0; k < samples_.size(); k += cstride) coarse_.push_back(samples_[k]);
  coarse_area_ = coarse_.empty() ? 0.0 : area_ / double(coarse_.size());
  centre_ = p.to3d(lo_ + 0.5 * ext);
  radius_ = 0.5 * ext.norm();
}

bool PolygonRaster::inside(const Eigen::Vector2d& uv) const {
  const int i = int(std::floor((uv.x() - lo_.x()) / cell_));
  const int j = int(std::floor((uv.y() - lo_.y()) / cell_));
  if (i < 0 || j < 0 || i >= nu_ || j >= nv_) return false;
  return mask_[std::size_t(j) * nu_ + i] != 0;
}

double overlapArea(const PolygonRaster& a, const PolygonRaster& b, const RigidTransform& t,
                   bool coarse) {
  if (a.samples().empty() || b.samples().empty()) return 0.0;
  // The smaller polygon is the sampler: its samples are looked up in the other's raster.
  if (a.area() <= b.area()) {
    std::size_t hits = 0;
    for (const auto& s : coarse ? a.coarseSamples() : a.samples()) {
      const Eigen::Vector3d q = t.apply(s);
      if (b.inside(b.project(q))) ++hits;
    }
    return double(hits) * (coarse ? a.coarseSampleArea() : a.sampleArea());
  }
  const RigidTransform inv = t.inverse();
  std::size_t hits = 0;
  for (const auto& s : coarse ? b.coarseSamples() : b.samples()) {
    const Eigen::Vector3d q = inv.apply(s);
    if (a.inside(a.project(q))) ++hits;
  }
  return double(hits) * (coarse ? b.coarseSampleArea() : b.sampleArea());
}

}  // namespace plumb
