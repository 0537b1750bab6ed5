// Simulated survey control targets (control_targets.hpp).
#include "simulation/control_targets.hpp"

#include <algorithm>

#include "common/error.hpp"

namespace plumb {

std::vector<ControlTarget> placeControlTargets(const std::vector<Eigen::Vector3d>& stations, int control, int check) {
  const std::size_t n = std::size_t(std::max(0, control) + std::max(0, check));
  if (n > stations.size())
    throw InputError("simulate: " + std::to_string(n) + " control and check targets need as many stations, there are " +
                     std::to_string(stations.size()));
  std::vector<ControlTarget> out;
  const Eigen::Vector3d beside(0.9, 0.6, -0.5);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t s = k * stations.size() / n;
    const bool is_check = k >= std::size_t(control);
    const std::size_t number = is_check ? k - std::size_t(control) + 1 : k + 1;
    out.push_back({(is_check ? "CK" : "CP") + std::to_string(number), stations[s] + beside, is_check});
  }
  return out;
}

std::vector<TargetSighting> sightTargets(const RayCaster& caster, const std::vector<RigidTransform>& true_poses,
                                         const std::vector<ControlTarget>& targets, double max_range) {
  std::vector<TargetSighting> out;
  for (std::size_t s = 0; s < true_poses.size(); ++s) {
    const Eigen::Vector3d origin = true_poses[s].translation();
    for (std::size_t t = 0; t < targets.size(); ++t) {
      const Eigen::Vector3d d = targets[t].position - origin;
      const double range = d.norm();
      if (!(range > 0.1) || range > max_range) continue;
      const RayHit hit = caster.cast({origin, d / range}, range);
      if (hit.hit() && hit.distance < range - 0.05) continue;
      out.push_back({s, t, true_poses[s].inverse().apply(targets[t].position)});
    }
  }
  return out;
}

}  // namespace plumb
