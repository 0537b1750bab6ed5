#pragma once
// The PCL peers of bench_registration, run on the same cases as Plumb (issue 6):
//   - PCL ICP (point-to-point) from the initial pose (no global search);
//   - PCL GICP from the initial pose;
//   - PCL FPFH + SampleConsensusPrerejective, then PCL ICP refinement (a fair global peer).
// Clouds are thinned on a voxel grid first (PCL's usual practice). A BIM target is given to
// the peers as points sampled on the model (the same samples Plumb refines against).
// PCL headers stay in pcl_peers.cpp.
#include <memory>
#include <string>

#include "model/point_cloud.hpp"
#include "model/rigid_transform.hpp"

namespace plumb::bench {

struct PeerParams {
  double voxel = 0.08;            ///< m: thinning of both clouds for ICP / GICP
  double icp_max_distance = 1.0;  ///< m: ICP / GICP max correspondence distance
  int icp_iterations = 50;
  double fpfh_voxel = 0.15;        ///< m: thinning for normals + FPFH + RANSAC
  double normal_radius = 0.35;     ///< m
  double feature_radius = 0.75;    ///< m
  int ransac_iterations = 50000;
  double ransac_inlier_distance = 0.3;  ///< m (SampleConsensusPrerejective)
  double refine_max_distance = 0.3;     ///< m: ICP after RANSAC
};

struct PeerOutcome {
  bool returned = false;       ///< the method produced a transform (converged)
  RigidTransform transform;    ///< source world -> target world
  double seconds = 0.0;        ///< source side + registration (target prepared once)
};

enum class Peer { Icp, Gicp, FpfhRansac };
std::string peerName(Peer p);

/// The target prepared once (thinned clouds, kd-trees, normals and FPFH), like Plumb's target
/// features in the acceptance runs.
class PeerTarget {
 public:
  PeerTarget(const PointCloud& target, const PeerParams& params);
  ~PeerTarget();
  PeerOutcome run(Peer peer, const PointCloud& source) const;
  double secondsPrepare() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace plumb::bench
