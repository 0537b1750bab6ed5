#pragma once
// The PCL peers of bench_registration, run on the same cases as Plumb (issue 6):
//   - PCL ICP (point-to-point) from the initial pose (no global search);
//   - PCL GICP from the initial pose;
//   - PCL FPFH + SampleConsensusPrerejective, then PCL point-to-plane ICP (a fair global peer).
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
  double fpfh_voxel = 0.2;         ///< m: thinning for normals + FPFH + RANSAC
  double normal_radius = 0.5;      ///< m
  double feature_radius = 1.0;     ///< m (measured on indoor-indoor: 0.15/0.75 and 0.1/0.5
                                   ///< give 27 deg median errors, 0.2/1.0 0.25 deg before ICP)
  int ransac_iterations = 50000;
  double ransac_inlier_distance = 0.3;  ///< m (SampleConsensusPrerejective)
  /// After RANSAC: point-to-plane ICP (PCL IterativeClosestPointWithNormals) on clouds thinned
  /// at `refine_voxel` with normals over `refine_normal_radius`, max correspondence distance
  /// from `refine_max_distance` down to `refine_final_distance`.
  double refine_voxel = 0.04;
  double refine_normal_radius = 0.15;
  double refine_max_distance = 0.3;
  double refine_final_distance = 0.06;
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
