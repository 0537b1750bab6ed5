#include "free_space.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <vector>

namespace plumb::bimst {

namespace {

/// Height of the upper ring: `upper_ring` above the floor, or just below a lower ceiling.
double upperRingZ(const RayCaster& caster, const Eigen::Vector3d& station, double height,
                  const FootprintParams& p) {
  const RayHit up = caster.cast(Ray{station, Eigen::Vector3d::UnitZ()}, p.max_range);
  const double ceiling = up.hit() ? station.z() + up.distance : station.z() + p.max_range;
  return std::min(station.z() - height + p.upper_ring, ceiling - p.ceiling_gap);
}

/// Per azimuth the nearer hit of the two rings (max_range when neither hits); counts misses.
std::vector<double> ringRanges(const RayCaster& caster, const Eigen::Vector3d& station,
                               double upper_z, const FootprintParams& p, int& open) {
  std::vector<double> ranges(std::size_t(p.azimuths), p.max_range);
  open = 0;
  for (int i = 0; i < p.azimuths; ++i) {
    const double a = 2.0 * M_PI * i / p.azimuths;
    const Eigen::Vector3d d(std::cos(a), std::sin(a), 0.0);
    bool hit = false;
    for (double z : {station.z(), upper_z}) {
      const RayHit h = caster.cast(Ray{{station.x(), station.y(), z}, d}, p.max_range);
      if (!h.hit()) continue;
      hit = true;
      ranges[std::size_t(i)] = std::min(ranges[std::size_t(i)], h.distance);
    }
    if (!hit) ++open;
  }
  return ranges;
}

/// Area and second moment (about the station) of the fan of triangles (station, hit i,
/// hit i+1): for a triangle, integral of x x^T = A/12 (sum v v^T + s s^T), s = sum v.
Footprint fanMoments(const std::vector<double>& ranges) {
  const std::size_t n = ranges.size();
  double area = 0.0;
  Eigen::Vector2d first = Eigen::Vector2d::Zero();
  Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
  auto point = [&](std::size_t i) {
    const double a = 2.0 * M_PI * double(i % n) / double(n);
    return Eigen::Vector2d(ranges[i % n] * std::cos(a), ranges[i % n] * std::sin(a));
  };
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d b = point(i), c = point(i + 1);
    const double t = 0.5 * std::abs(b.x() * c.y() - b.y() * c.x());
    const Eigen::Vector2d s = b + c;
    area += t;
    first += t * s / 3.0;
    second += t / 12.0 * (b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  Footprint f;
  f.area_m2 = area;
  if (area <= 0.0) return f;
  const Eigen::Vector2d mean = first / area;
  const Eigen::Matrix2d cov = second / area - mean * mean.transpose();
  const Eigen::Vector2d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(cov).eigenvalues();
  // A rectangle a x b has variances a^2/12 and b^2/12: the ratio of their roots is a / b.
  f.elongation = std::sqrt(std::max(ev(1), 1e-12) / std::max(ev(0), 1e-12));
  f.short_side_m = std::sqrt(area / f.elongation);
  return f;
}

}  // namespace

Footprint measureFootprint(const RayCaster& caster, const Eigen::Vector3d& station, double height,
                           const FootprintParams& p) {
  int open = 0;
  const double upper_z = upperRingZ(caster, station, height, p);
  Footprint f = fanMoments(ringRanges(caster, station, std::max(upper_z, station.z()), p, open));
  f.open_rays = open;
  return f;
}

}  // namespace plumb::bimst
