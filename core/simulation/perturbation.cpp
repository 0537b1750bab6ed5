#include "simulation/perturbation.hpp"

#include <cmath>

#include "simulation/pulse_random.hpp"

namespace plumb {

RigidTransform randomPerturbation(double yaw_max_deg, double shift_max_m, std::uint64_t seed) {
  sim::PulseRandom rng(seed, 0x5EEDull);
  const double yaw = (2 * rng.uniform() - 1) * yaw_max_deg * M_PI / 180.0;
  const Eigen::Vector3d t((2 * rng.uniform() - 1) * shift_max_m, (2 * rng.uniform() - 1) * shift_max_m,
                          (2 * rng.uniform() - 1) * shift_max_m / 4);
  return RigidTransform::fromYaw(yaw, t);
}

RigidTransform perturbDataset(Dataset& data, const RigidTransform& perturbation) {
  data.transform(perturbation);
  return perturbation.inverse();
}

std::vector<RigidTransform> perturbScans(Dataset& data, double yaw_max_deg, double shift_max_m,
                                         std::uint64_t seed) {
  std::vector<RigidTransform> undo;
  for (std::size_t i = 0; i < data.scans.size(); ++i) {
    const RigidTransform p = randomPerturbation(yaw_max_deg, shift_max_m, sim::splitmix64(seed * 7919 + i));
    Scan& scan = data.scans[i];
    scan.pose = p * scan.pose;
    scan.has_pose = true;
    undo.push_back(p.inverse());
  }
  return undo;
}

}  // namespace plumb
