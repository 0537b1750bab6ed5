#pragma once
// The peer of the network adjustment (issue 15): Open3D's multiway registration, i.e. its
// pose-graph GlobalOptimization (Levenberg-Marquardt with a line process that prunes loop
// closures disagreeing with the odometry; Choi et al. 2015), from Debian's libopen3d-dev, run on
// the same links. Open3D headers stay in open3d_multiway.cpp.
#include <optional>
#include <vector>

#include "registration/network/robust_adjustment.hpp"

namespace plumb::bench {

struct MultiwayResult {
  std::vector<std::optional<RigidTransform>> poses;  ///< station -> reference frame
  std::vector<bool> pruned;  ///< per input link: removed by the line process
  double seconds = 0.0;
};

/// Links with `certain[k]` are Open3D's certain odometry edges (never pruned), every other link
/// an uncertain loop closure. Each link's information matrix has Open3D's form:
/// `correspondences` x diag((sigma_t / sigma_r)^2 x3, 1 x3) (rotation first), so its relative
/// weights are those of the Plumb adjustment. Initial poses: the certain links chained from
/// `reference`, held at `reference_pose`; stations they do not reach are not placed.
MultiwayResult open3dMultiway(std::size_t stations, const std::vector<AdjustmentLink>& links,
                              const std::vector<bool>& certain, std::size_t reference,
                              const RigidTransform& reference_pose, double correspondences = 1000.0,
                              double max_correspondence_distance = 0.075);

/// Links between consecutive stations (i, i+1, and a ring's closing link): the odometry of a
/// sequence of stations.
std::vector<bool> consecutiveLinks(std::size_t stations, const std::vector<AdjustmentLink>& links);

}  // namespace plumb::bench
