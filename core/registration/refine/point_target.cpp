// A point cloud as a refinement target: thinning, normals, nearest points (point_target.hpp).
#include "registration/refine/point_target.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <unordered_map>

namespace plumb::refine_detail {

namespace {

/// Centroid per occupied voxel, in first-occurrence order (deterministic). A hash map rather
/// than pcl::VoxelGrid, which silently returns the cloud unthinned when the grid exceeds 2^31
/// cells (any MMS street scene at 5 cm) and then makes the refinement 30x slower.
Cloud::Ptr voxelCentroids(const Cloud& in, double voxel, std::vector<std::uint32_t>* first) {
  std::unordered_map<std::uint64_t, std::uint32_t> slot;
  slot.reserve(in.size() / 4);
  std::vector<Eigen::Vector4d> acc;  // x, y, z, count
  std::vector<std::uint32_t> first_of(0);
  const double inv = 1.0 / voxel;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const auto& q = in[i];
    const auto k = [&](float v) {
      return std::uint64_t(std::int64_t(std::floor(double(v) * inv)) + (1 << 20)) & 0x1FFFFF;
    };
    const std::uint64_t key = (k(q.x) << 42) | (k(q.y) << 21) | k(q.z);
    const auto [it, fresh] = slot.try_emplace(key, std::uint32_t(acc.size()));
    if (fresh) {
      acc.emplace_back(0, 0, 0, 0);
      if (first) first_of.push_back((*first)[i]);
    }
    acc[it->second] += Eigen::Vector4d(q.x, q.y, q.z, 1.0);
  }
  Cloud::Ptr thin(new Cloud);
  thin->reserve(acc.size());
  for (const auto& a : acc)
    thin->push_back(pcl::PointXYZ(float(a.x() / a.w()), float(a.y() / a.w()), float(a.z() / a.w())));
  if (first) *first = std::move(first_of);
  return thin;
}

std::vector<Eigen::Vector3d> gridNormals(const Cloud& c, double cell) {
  struct Acc {
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    Eigen::Matrix3d ss = Eigen::Matrix3d::Zero();
    int n = 0;
    Eigen::Vector3d normal = Eigen::Vector3d::Constant(std::nan(""));
  };
  std::unordered_map<std::uint64_t, Acc> cells;
  std::vector<std::uint64_t> keys(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Eigen::Vector3d p = c[i].getVector3fMap().cast<double>();
    const auto k = [&](double v) { return std::uint64_t(std::int64_t(std::floor(v / cell)) + (1 << 20)); };
    keys[i] = (k(p.x()) << 42) | (k(p.y()) << 21) | k(p.z());
    auto& a = cells[keys[i]];
    a.s += p;
    a.ss += p * p.transpose();
    ++a.n;
  }
  for (auto& [key, a] : cells) {
    if (a.n < 5) continue;
    const Eigen::Vector3d m = a.s / a.n;
    const Eigen::Matrix3d cov = a.ss / a.n - m * m.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
    // Planar enough: smallest eigenvalue well below the middle one.
    if (es.eigenvalues()(0) < 0.1 * es.eigenvalues()(1)) a.normal = es.eigenvectors().col(0);
  }
  std::vector<Eigen::Vector3d> out(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) out[i] = cells[keys[i]].normal;
  return out;
}

/// Points of non-planar cells (edges, corners) get the PCA normal of their 10 nearest
/// neighbours.
void fillEdgeNormals(const Cloud& tgt, const pcl::KdTreeFLANN<pcl::PointXYZ>& tree,
                     std::vector<Eigen::Vector3d>& normals) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tgt.size(), 1024), [&](const auto& range) {
    std::vector<int> idx;
    std::vector<float> d2;
    for (std::size_t i = range.begin(); i < range.end(); ++i) {
      if (normals[i].allFinite()) continue;
      if (tree.nearestKSearch(tgt[i], 10, idx, d2) < 5) continue;
      Eigen::Vector3d m = Eigen::Vector3d::Zero();
      for (int j : idx) m += tgt[j].getVector3fMap().cast<double>();
      m /= double(idx.size());
      Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
      for (int j : idx) {
        const Eigen::Vector3d q = tgt[j].getVector3fMap().cast<double>() - m;
        cov += q * q.transpose();
      }
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
      normals[i] = es.eigenvectors().col(0);
    }
  });
}

}  // namespace

Cloud::Ptr toPcl(const PointCloud& c, const RigidTransform& t, const Eigen::Vector3d& origin,
                 double voxel, std::vector<std::uint32_t>* first) {
  Cloud::Ptr out(new Cloud);
  out->reserve(c.size());
  if (first) first->clear();
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (!c.positions[i].allFinite()) continue;
    const Eigen::Vector3d p = t.apply(c.world(i)) - origin;
    out->push_back(pcl::PointXYZ(float(p.x()), float(p.y()), float(p.z())));
    if (first) first->push_back(std::uint32_t(i));
  }
  if (voxel > 0 && out->size() > 1000) return voxelCentroids(*out, voxel, first);
  return out;
}

std::vector<Eigen::Vector3d> targetNormals(const Cloud& c, const pcl::KdTreeFLANN<pcl::PointXYZ>& tree,
                                           double voxel) {
  // PCA of the points in a grid cell of a few voxels (O(n); building surfaces are planar at
  // that scale; mixed cells at edges are rare and trimmed away).
  std::vector<Eigen::Vector3d> normals = gridNormals(c, std::max(0.15, 3 * voxel));
  fillEdgeNormals(c, tree, normals);
  return normals;
}

bool PointSurface::nearest(const Eigen::Vector3d& x, double max_d, Eigen::Vector3d& q,
                           Eigen::Vector3d& n) const {
  thread_local std::vector<int> idx(1);
  thread_local std::vector<float> d2(1);
  const pcl::PointXYZ p(float(x.x()), float(x.y()), float(x.z()));
  if (tree_.nearestKSearch(p, 1, idx, d2) < 1 || d2[0] > float(max_d * max_d)) return false;
  if (!normals_[idx[0]].allFinite()) return false;
  n = normals_[idx[0]];
  q = cloud_[idx[0]].getVector3fMap().cast<double>();
  return true;
}

bool PointSurface::nearestSeenFrom(const Eigen::Vector3d& x, const Eigen::Vector3d& viewer,
                                   double max_d, Eigen::Vector3d& q, Eigen::Vector3d& n) const {
  if (!oriented_) return nearest(x, max_d, q, n);
  // The nearest point first (most are seen from both sides' stations); further ones only when
  // its front faces away (a wall's other face, the far side of a thin partition), in widening
  // rounds: the other face of a wall can hold dozens of points nearer than this one.
  thread_local std::vector<int> idx;
  thread_local std::vector<float> d2;
  const pcl::PointXYZ p(float(x.x()), float(x.y()), float(x.z()));
  const float max_d2 = float(max_d * max_d);
  int searched = 0;
  for (const int k : {1, kSeenCandidates, 8 * kSeenCandidates}) {
    const int found = tree_.nearestKSearch(p, k, idx, d2);
    for (int i = searched; i < found; ++i) {
      if (d2[i] > max_d2) return false;
      const Eigen::Vector3d& ni = normals_[idx[i]];
      if (!ni.allFinite()) continue;
      const Eigen::Vector3d qi = cloud_[idx[i]].getVector3fMap().cast<double>();
      if (ni.dot(viewer - qi) <= 0) continue;
      q = qi;
      n = ni;
      return true;
    }
    if (found < k) return false;
    searched = found;
  }
  return false;
}

void orientTowards(const Cloud& c, const std::vector<Eigen::Vector3f>& origins,
                   std::vector<Eigen::Vector3d>& normals) {
  for (std::size_t i = 0; i < c.size() && i < origins.size(); ++i) {
    if (!normals[i].allFinite()) continue;
    const Eigen::Vector3d to_station = origins[i].cast<double>() - c[i].getVector3fMap().cast<double>();
    if (normals[i].dot(to_station) < 0) normals[i] = -normals[i];
  }
}

}  // namespace plumb::refine_detail
