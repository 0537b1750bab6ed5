#pragma once
// Internal to cloud_distance.cpp: the target cloud as the kd-tree holds it, and the surface
// normals at the target points that were nearest to some source point (the signs of the
// cloud-to-cloud distances; the convention is in cloud_distance.hpp).
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <vector>

#include "model/point_cloud.hpp"

namespace plumb::detail {

/// The finite points of a cloud in a kd-tree (local coordinates), with their index in the cloud.
struct TargetTree {
  explicit TargetTree(const PointCloud& target);
  pcl::PointCloud<pcl::PointXYZ>::Ptr points;
  std::vector<std::size_t> index;  ///< tree point -> point of the target
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  Eigen::Vector3f at(int tree_point) const {
    const auto& p = (*points)[static_cast<std::size_t>(tree_point)];
    return {p.x, p.y, p.z};
  }
};

/// Unit normals at some tree points (each computed once, by one thread: deterministic).
class TargetNormals {
 public:
  /// `wanted`: tree points (any order, repeats allowed; negative ones ignored). `viewpoint`
  /// (target local frame) orients the normals of a target without sensor origins or normals.
  TargetNormals(const PointCloud& target, const TargetTree& tree, const std::vector<int>& wanted,
                int neighbours, const Eigen::Vector3f& viewpoint);
  /// The normal at a tree point given to the constructor.
  const Eigen::Vector3f& at(int tree_point) const;

 private:
  Eigen::Vector3f compute(int tree_point) const;
  Eigen::Vector3f fitted(int tree_point) const;
  const PointCloud& target_;
  const TargetTree& tree_;
  int neighbours_;
  Eigen::Vector3f viewpoint_;
  std::vector<int> points_;  ///< sorted, unique
  std::vector<Eigen::Vector3f> normals_;
};

}  // namespace plumb::detail
