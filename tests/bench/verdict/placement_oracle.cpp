#include "placement_oracle.hpp"

#include <algorithm>
#include <cmath>

namespace plumb::verdict {

namespace {

std::vector<Eigen::Vector3d> scannerDirections() {
  std::vector<Eigen::Vector3d> out;
  for (int az = 0; az < 360; ++az)
    for (int el = -60; el <= 90; ++el) {
      const double a = az * M_PI / 180.0, e = el * M_PI / 180.0;
      out.emplace_back(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
    }
  return out;
}

bool agree(const RayHit& a, const RayHit& b) {
  if (!a.hit() || !b.hit()) return a.hit() == b.hit();
  return std::abs(a.distance - b.distance) <= 0.05 + 0.01 * a.distance;
}

bool onWall(const ScanScene& scene, const RayHit& h) {
  return h.hit() && !scene.isGround(h.triangle) &&
         std::abs(scene.caster().triangleNormal(h.triangle).z()) < 0.7;
}

}  // namespace

Agreement rangeAgreement(const ScanScene& source_bare, const ScanScene& target_bare,
                      const std::vector<Eigen::Vector3d>& stations, const RigidTransform& placement) {
  static const std::vector<Eigen::Vector3d> dirs = scannerDirections();
  const Eigen::Matrix3d R = placement.rotation();
  std::vector<Ray> src, tgt;
  for (const auto& s : stations)
    for (const auto& d : dirs) {
      src.push_back({s, d});
      tgt.push_back({placement.apply(s), (R * d).normalized()});
    }
  std::vector<RayHit> hs, ht;
  constexpr double kMaxRange = 80.0, kMinRange = 0.3;  // the TLS's
  source_bare.caster().castAll(src, hs, kMaxRange, kMinRange);
  target_bare.caster().castAll(tgt, ht, kMaxRange, kMinRange);
  std::size_t agreeing = 0, wall = 0, wall_agreeing = 0;
  for (std::size_t i = 0; i < hs.size(); ++i) {
    const bool a = agree(hs[i], ht[i]);
    agreeing += a;
    if (onWall(source_bare, hs[i]) || onWall(target_bare, ht[i])) {
      ++wall;
      wall_agreeing += a;
    }
  }
  Agreement out;
  if (hs.empty()) return out;
  out.all = double(agreeing) / double(hs.size());
  out.walls = wall == 0 ? out.all : double(wall_agreeing) / double(wall);
  return out;
}

bool onWall(const ScanScene& scene, const RayHit& h) {
  return h.hit() && !scene.isGround(h.triangle) &&
         std::abs(scene.caster().triangleNormal(h.triangle).z()) < 0.7;
}

}  // namespace plumb::verdict
