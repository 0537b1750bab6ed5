#include "quality/target_surface.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>

#include <algorithm>

namespace plumb::detail {

TargetTree::TargetTree(const PointCloud& target) : points(pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>()) {
  points->reserve(target.size());
  index.reserve(target.size());
  for (std::size_t i = 0; i < target.size(); ++i) {
    const auto& p = target.positions[i];
    if (!p.allFinite()) continue;
    points->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
    index.push_back(i);
  }
  if (!points->empty()) tree.setInputCloud(points);
}

TargetNormals::TargetNormals(const PointCloud& target, const TargetTree& tree,
                             const std::vector<int>& wanted, int neighbours,
                             const Eigen::Vector3f& viewpoint)
    : target_(target), tree_(tree), neighbours_(std::max(3, neighbours)), viewpoint_(viewpoint) {
  points_.reserve(wanted.size());
  for (int k : wanted)
    if (k >= 0) points_.push_back(k);
  std::sort(points_.begin(), points_.end());
  points_.erase(std::unique(points_.begin(), points_.end()), points_.end());
  normals_.resize(points_.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points_.size(), 512),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i)
                        normals_[i] = compute(points_[i]);
                    });
}

const Eigen::Vector3f& TargetNormals::at(int tree_point) const {
  const auto it = std::lower_bound(points_.begin(), points_.end(), tree_point);
  return normals_[static_cast<std::size_t>(it - points_.begin())];
}

Eigen::Vector3f TargetNormals::compute(int tree_point) const {
  const std::size_t j = tree_.index[static_cast<std::size_t>(tree_point)];
  Eigen::Vector3f n = Eigen::Vector3f::Zero();
  const bool stored = target_.hasNormals() && target_.normals[j].allFinite() && target_.normals[j].norm() > 0.5f;
  n = stored ? Eigen::Vector3f(target_.normals[j].normalized()) : fitted(tree_point);
  const Eigen::Vector3f p = tree_.at(tree_point);
  if (target_.hasSensorOrigins()) {
    if (n.dot(target_.sensor_origins[j] - p) < 0) n = -n;
  } else if (!stored && n.dot(viewpoint_ - p) < 0) {
    n = -n;
  }
  return n;
}

/// The normal of the plane through the point's nearest target points (least squares: the
/// direction of least spread); zero when the tree has fewer than 3 points.
Eigen::Vector3f TargetNormals::fitted(int tree_point) const {
  pcl::Indices k;
  std::vector<float> d2;
  const auto& q = (*tree_.points)[static_cast<std::size_t>(tree_point)];
  if (tree_.tree.nearestKSearch(q, neighbours_, k, d2) < 3) return Eigen::Vector3f::Zero();
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int i : k) mean += tree_.at(i).cast<double>();
  mean /= double(k.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (int i : k) {
    const Eigen::Vector3d d = tree_.at(i).cast<double>() - mean;
    cov += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  return eig.eigenvectors().col(0).cast<float>();
}

}  // namespace plumb::detail
