#pragma once
// Simulated survey control (issue 15): sphere targets on tripods beside some TLS stations, whose
// true positions become control or check points, and which stations see them (a clear line of
// sight through the model within a range). What a surveyor's target list would hold: each
// target's centre in each station's own frame, exactly (no centre-fit noise).
#include <Eigen/Core>

#include <string>
#include <vector>

#include "model/rigid_transform.hpp"
#include "simulation/ray_caster.hpp"

namespace plumb {

struct ControlTarget {
  std::string name;  ///< "CP1".. for control, "CK1".. for check points
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< model frame
  bool check = false;
};

struct TargetSighting {
  std::size_t station = 0;  ///< index into the stations' true poses
  std::size_t target = 0;
  Eigen::Vector3d in_station = Eigen::Vector3d::Zero();  ///< the centre in the station's frame
};

/// `control` + `check` targets, each 0.9 m east, 0.6 m north and 0.5 m below a station
/// (model frame), the stations taken evenly through `stations`, control points first.
/// Throws InputError when there are fewer stations than targets.
std::vector<ControlTarget> placeControlTargets(const std::vector<Eigen::Vector3d>& stations, int control, int check);

/// Every (station, target) pair with a clear line of sight within `max_range` m (the segment
/// hits no triangle closer than 5 cm before the target); `true_poses` map each station's
/// frame to the model frame.
std::vector<TargetSighting> sightTargets(const RayCaster& caster, const std::vector<RigidTransform>& true_poses,
                                         const std::vector<ControlTarget>& targets, double max_range = 25.0);

}  // namespace plumb
