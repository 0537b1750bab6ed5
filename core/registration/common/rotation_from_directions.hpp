#pragma once
// Rotation from two associated direction pairs (2021 eqs. 12-19, 2023 eq. 10) and the
// enumeration of every rotation consistent with an association of direction clusters
// (docs/ALGORITHMS.md §4 "beyond the paper": all pairings, all signs, optional up/down flip).
#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

#include "common/params.hpp"

namespace plumb {

/// Orthonormal frame [x y z] with x = u, y = v - (v·u)u normalised (eq. 12-13 as corrected in
/// docs/ALGORITHMS.md §4), z = x × y (eq. 14-15). nullopt when u and v are nearly parallel.
std::optional<Eigen::Matrix3d> frameFromDirections(const Eigen::Vector3d& u,
                                                   const Eigen::Vector3d& v);

/// R with R u_s = u_t and R v_s as close as possible to v_t: R = M_t M_s^-1 (eq. 19 / eq. 10).
std::optional<Eigen::Matrix3d> rotationFromDirectionPairs(const Eigen::Vector3d& u_s,
                                                          const Eigen::Vector3d& v_s,
                                                          const Eigen::Vector3d& u_t,
                                                          const Eigen::Vector3d& v_t);

struct RotationEnumerationParams {
  /// deg, (0, 45]: how well mapped directions must agree. Not in the schema: the plane and
  /// segment registrations set it to their clustering angle ("cluster-angle").
  double angle_tolerance_deg = 10.0;
  bool up_axis_known = true;  ///< both datasets are Z-up (levelled scanners, BIM): keep Z up
  bool allow_up_down_flip = false;  ///< also try R z = -z (up axis sign unknown)
  double max_tilt_deg = 10.0;  ///< deg, [0, 90]: with up_axis_known, max angle between R z and z
  /// The two directions defining a frame must be at least this far apart, deg, [5, 90]
  /// (a 10° ramp next to the floor makes a badly conditioned frame).
  double min_frame_angle_deg = 30.0;
  /// up-axis-known, allow-up-down-flip, max-tilt, min-frame-angle (nested in the plane and
  /// segment registration schemas).
  static const ParamSchema<RotationEnumerationParams>& schema();
};

struct RotationCandidate {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  /// For each source direction, the target direction index it maps to (-1 none) and sign.
  std::vector<int> target_of_source;
  std::vector<int> sign_of_source;
  std::string label;
};

/// Every rotation mapping the heaviest source direction and the heaviest one at least
/// min_frame_angle_deg from it onto an ordered pair of target directions, with both signs each,
/// keeping those under which at least min(3, |source|, |target|) source directions find a
/// target within tolerance and (with up_axis_known) that keep Z up. Directions are unsigned
/// and given heaviest first. Duplicate rotations (closer than tolerance/4) are merged.
std::vector<RotationCandidate> enumerateRotations(const std::vector<Eigen::Vector3d>& source,
                                                  const std::vector<Eigen::Vector3d>& target,
                                                  const RotationEnumerationParams& params);

/// Weighted least-squares rotation aligning direction pairs (Kabsch / SVD), signs already fixed.
Eigen::Matrix3d fitRotation(const std::vector<Eigen::Vector3d>& source,
                            const std::vector<Eigen::Vector3d>& target,
                            const std::vector<double>& weights);

}  // namespace plumb
