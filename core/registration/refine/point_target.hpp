#pragma once
// A point cloud as a refinement target (docs/ALGORITHMS.md §8): voxel thinning in a local
// frame, normals by PCA, and the nearest-point surface over a PCL kd-tree. Internal to the
// refinement module (PCL types).
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "model/point_cloud.hpp"
#include "model/rigid_transform.hpp"
#include "registration/refine/target_surface.hpp"

namespace plumb::refine_detail {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

/// World points of `c` moved by t, relative to `origin`, as float (keeps precision for
/// georeferenced data); thinned to one centroid per occupied voxel of `voxel` m when there
/// are more than 1000 points (voxel > 0). `first`, when given, receives for each output point
/// the index in `c` of the first point of its voxel (or of the point itself).
Cloud::Ptr toPcl(const PointCloud& c, const RigidTransform& t, const Eigen::Vector3d& origin,
                 double voxel, std::vector<std::uint32_t>* first = nullptr);

/// Normals of a thinned target: PCA per grid cell of max(0.15, 3 voxel) m where planar, else
/// of the 10 nearest neighbours; NaN where neither works.
std::vector<Eigen::Vector3d> targetNormals(const Cloud& c, const pcl::KdTreeFLANN<pcl::PointXYZ>& tree,
                                           double voxel);

/// Turns each finite normal to face the sensor origin its point was seen from (`origins`, one
/// per point, local frame), so that its front side is the side the target's station saw.
void orientTowards(const Cloud& c, const std::vector<Eigen::Vector3f>& origins,
                   std::vector<Eigen::Vector3d>& normals);

/// The nearest target point (kd-tree) with its normal. With `oriented` (normals turned towards
/// the target's own stations, orientTowards), nearestSeenFrom keeps only points whose front
/// side faces the source point's station as well.
class PointSurface final : public TargetSurface {
 public:
  PointSurface(const Cloud& cloud, const pcl::KdTreeFLANN<pcl::PointXYZ>& tree,
               const std::vector<Eigen::Vector3d>& normals, bool oriented = false)
      : cloud_(cloud), tree_(tree), normals_(normals), oriented_(oriented) {}
  bool nearest(const Eigen::Vector3d& x, double max_d, Eigen::Vector3d& q,
               Eigen::Vector3d& n) const override;
  /// The nearest point within max_d whose front faces `viewer`: the nearest, else among the
  /// kSeenCandidates nearest, then the 8 kSeenCandidates nearest (false beyond).
  bool nearestSeenFrom(const Eigen::Vector3d& x, const Eigen::Vector3d& viewer, double max_d,
                       Eigen::Vector3d& q, Eigen::Vector3d& n) const override;
  static constexpr int kSeenCandidates = 8;
  /// The normals face the target's own stations: nearestSeenFrom applies its rule.
  bool oriented() const { return oriented_; }

 private:
  const Cloud& cloud_;
  const pcl::KdTreeFLANN<pcl::PointXYZ>& tree_;
  const std::vector<Eigen::Vector3d>& normals_;
  bool oriented_;
};

}  // namespace plumb::refine_detail
