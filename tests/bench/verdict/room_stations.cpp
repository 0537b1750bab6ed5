#include "room_stations.hpp"

#include <algorithm>
#include <cmath>

#include "simulation/scan_scene.hpp"

namespace plumb::verdict {

std::vector<Eigen::Vector3d> sphereDirections(int n) {
  std::vector<Eigen::Vector3d> out;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z);
    out.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return out;
}

std::vector<Eigen::Vector3d> floorsBelow(const RayCaster& caster, double x, double y, double top,
                                         double height) {
  std::vector<Eigen::Vector3d> out;
  Ray ray{{x, y, top}, -Eigen::Vector3d::UnitZ()};
  for (int k = 0; k < 20; ++k) {
    const RayHit h = caster.cast(ray);
    if (!h.hit()) break;
    const Eigen::Vector3d p = ray.origin + h.distance * ray.direction;
    if (std::abs(caster.triangleNormal(h.triangle).z()) > 0.9 && h.distance > height + 0.3)
      out.emplace_back(x, y, p.z() + height);
    ray.origin = p - 0.02 * Eigen::Vector3d::UnitZ();
  }
  return out;
}

double clearance(const RayCaster& caster, const Eigen::Vector3d& p,
                 const std::vector<Eigen::Vector3d>& dirs) {
  double nearest = 1e30;
  for (const auto& d : dirs) {
    const RayHit h = caster.cast(Ray{p, d}, 60.0);
    if (!h.hit()) return -1.0;
    nearest = std::min(nearest, h.distance);
  }
  return nearest;
}

std::vector<Eigen::Vector3d> findRoomStations(const BimModel& model, const StationSearch& s) {
  ScanSceneOptions opt;
  opt.ground = false;
  const ScanScene scene(model, {}, opt);
  const RayCaster& caster = scene.caster();
  const Bounds b = model.mesh.bounds();
  const auto dirs = sphereDirections(160);
  std::vector<std::pair<double, Eigen::Vector3d>> candidates;
  for (double x = b.min.x() + 0.5 * s.grid_step; x < b.max.x(); x += s.grid_step)
    for (double y = b.min.y() + 0.5 * s.grid_step; y < b.max.y(); y += s.grid_step)
      for (const auto& p : floorsBelow(caster, x, y, b.max.z() + 1.0, s.height)) {
        const double c = clearance(caster, p, dirs);
        if (c >= s.min_clearance) candidates.emplace_back(c, p);
      }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& a, const auto& c) { return a.first > c.first; });
  std::vector<Eigen::Vector3d> chosen;
  for (const auto& [c, p] : candidates) {
    if (int(chosen.size()) >= s.max_stations) break;
    const bool apart = std::all_of(chosen.begin(), chosen.end(), [&](const Eigen::Vector3d& q) {
      return (q - p).norm() >= s.min_separation;
    });
    if (apart) chosen.push_back(p);
  }
  return chosen;
}

}  // namespace plumb::verdict
