#include "support/pcl_peers.hpp"
#include "common/stopwatch.hpp"

#include <pcl/features/fpfh_omp.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/point_types.h>
#include <pcl/registration/gicp.h>
#include <pcl/common/io.h>
#include <pcl/registration/icp.h>
#include <pcl/registration/sample_consensus_prerejective.h>
#include <pcl/search/kdtree.h>

#include <chrono>
#include <stdexcept>

namespace plumb::bench {

namespace {

using Xyz = pcl::PointXYZ;
using Cloud = pcl::PointCloud<Xyz>;
using Normals = pcl::PointCloud<pcl::Normal>;
using Fpfh = pcl::PointCloud<pcl::FPFHSignature33>;

/// World points minus `origin` (float precision near the data), thinned by pcl::VoxelGrid.
Cloud::Ptr thinned(const PointCloud& c, const Eigen::Vector3d& origin, double voxel) {
  Cloud::Ptr all(new Cloud);
  all->reserve(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Eigen::Vector3d p = c.world(i) - origin;
    if (p.allFinite()) all->push_back(Xyz(float(p.x()), float(p.y()), float(p.z())));
  }
  pcl::VoxelGrid<Xyz> grid;
  grid.setLeafSize(float(voxel), float(voxel), float(voxel));
  grid.setInputCloud(all);
  Cloud::Ptr out(new Cloud);
  grid.filter(*out);
  if (out->size() >= all->size())
    throw std::runtime_error("pcl::VoxelGrid did not thin the cloud (grid too large?)");
  return out;
}

Normals::Ptr normalsOf(const Cloud::Ptr& c, double radius) {
  pcl::NormalEstimationOMP<Xyz, pcl::Normal> ne(2);
  ne.setInputCloud(c);
  ne.setSearchMethod(pcl::search::KdTree<Xyz>::Ptr(new pcl::search::KdTree<Xyz>));
  ne.setRadiusSearch(radius);
  ne.setViewPoint(0, 0, 0);
  Normals::Ptr n(new Normals);
  ne.compute(*n);
  return n;
}

Fpfh::Ptr fpfhOf(const Cloud::Ptr& c, const Normals::Ptr& n, double radius) {
  pcl::FPFHEstimationOMP<Xyz, pcl::Normal, pcl::FPFHSignature33> fe(2);
  fe.setInputCloud(c);
  fe.setInputNormals(n);
  fe.setSearchMethod(pcl::search::KdTree<Xyz>::Ptr(new pcl::search::KdTree<Xyz>));
  fe.setRadiusSearch(radius);
  Fpfh::Ptr f(new Fpfh);
  fe.compute(*f);
  return f;
}

/// Thinned cloud with normals, for point-to-plane ICP.
pcl::PointCloud<pcl::PointNormal>::Ptr withNormals(const PointCloud& c, const Eigen::Vector3d& origin,
                                                   double voxel, double radius) {
  const Cloud::Ptr xyz = thinned(c, origin, voxel);
  const Normals::Ptr n = normalsOf(xyz, radius);
  pcl::PointCloud<pcl::PointNormal>::Ptr out(new pcl::PointCloud<pcl::PointNormal>);
  pcl::concatenateFields(*xyz, *n, *out);
  // PCL leaves NaN normals where a neighbourhood is too small: drop those points.
  pcl::PointCloud<pcl::PointNormal>::Ptr finite(new pcl::PointCloud<pcl::PointNormal>);
  for (const auto& q : *out)
    if (std::isfinite(q.normal_x)) finite->push_back(q);
  return finite;
}

Eigen::Matrix4f runIcp(const Cloud::Ptr& src, const Cloud::Ptr& tgt, const Eigen::Matrix4f& guess,
                       double max_distance, int iterations, bool* converged) {
  pcl::IterativeClosestPoint<Xyz, Xyz> icp;
  icp.setInputSource(src);
  icp.setInputTarget(tgt);
  icp.setMaxCorrespondenceDistance(max_distance);
  icp.setMaximumIterations(iterations);
  icp.setTransformationEpsilon(1e-9);
  icp.setEuclideanFitnessEpsilon(1e-9);
  Cloud aligned;
  icp.align(aligned, guess);
  *converged = icp.hasConverged();
  return icp.getFinalTransformation();
}

}  // namespace

std::string peerName(Peer p) {
  switch (p) {
    case Peer::Icp: return "PCL ICP";
    case Peer::Gicp: return "PCL GICP";
    case Peer::FpfhRansac: return "PCL FPFH+SAC-PR+ICP";
  }
  return "?";
}

struct PeerTarget::Impl {
  PeerParams params;
  Eigen::Vector3d origin;
  Cloud::Ptr fine, coarse;
  Normals::Ptr coarse_normals;
  Fpfh::Ptr coarse_fpfh;
  pcl::PointCloud<pcl::PointNormal>::Ptr refine;
  double seconds_prepare = 0.0;
};

PeerTarget::PeerTarget(const PointCloud& target, const PeerParams& params)
    : impl_(std::make_unique<Impl>()) {
  const auto t0 = std::chrono::steady_clock::now();
  impl_->params = params;
  impl_->origin = target.bounds().center();
  impl_->fine = thinned(target, impl_->origin, params.voxel);
  impl_->coarse = thinned(target, impl_->origin, params.fpfh_voxel);
  impl_->coarse_normals = normalsOf(impl_->coarse, params.normal_radius);
  impl_->coarse_fpfh = fpfhOf(impl_->coarse, impl_->coarse_normals, params.feature_radius);
  impl_->refine = withNormals(target, impl_->origin, params.refine_voxel, params.refine_normal_radius);
  impl_->seconds_prepare = secondsSince(t0);
}

PeerTarget::~PeerTarget() = default;

double PeerTarget::secondsPrepare() const { return impl_->seconds_prepare; }

PeerOutcome PeerTarget::run(Peer peer, const PointCloud& source) const {
  const auto t0 = std::chrono::steady_clock::now();
  const PeerParams& p = impl_->params;
  PeerOutcome out;
  Eigen::Matrix4f local = Eigen::Matrix4f::Identity();
  bool ok = false;
  const Cloud::Ptr src = thinned(source, impl_->origin, p.voxel);
  if (peer == Peer::Icp) {
    local = runIcp(src, impl_->fine, local, p.icp_max_distance, p.icp_iterations, &ok);
  } else if (peer == Peer::Gicp) {
    pcl::GeneralizedIterativeClosestPoint<Xyz, Xyz> gicp;
    gicp.setInputSource(src);
    gicp.setInputTarget(impl_->fine);
    gicp.setMaxCorrespondenceDistance(p.icp_max_distance);
    gicp.setMaximumIterations(p.icp_iterations);
    gicp.setTransformationEpsilon(1e-9);
    Cloud aligned;
    gicp.align(aligned, local);
    ok = gicp.hasConverged();
    local = gicp.getFinalTransformation();
  } else {
    const Cloud::Ptr coarse = thinned(source, impl_->origin, p.fpfh_voxel);
    const Normals::Ptr normals = normalsOf(coarse, p.normal_radius);
    const Fpfh::Ptr fpfh = fpfhOf(coarse, normals, p.feature_radius);
    pcl::SampleConsensusPrerejective<Xyz, Xyz, pcl::FPFHSignature33> sac;
    sac.setInputSource(coarse);
    sac.setSourceFeatures(fpfh);
    sac.setInputTarget(impl_->coarse);
    sac.setTargetFeatures(impl_->coarse_fpfh);
    sac.setMaximumIterations(p.ransac_iterations);
    sac.setNumberOfSamples(3);
    sac.setCorrespondenceRandomness(5);
    sac.setSimilarityThreshold(0.9f);
    sac.setMaxCorrespondenceDistance(p.ransac_inlier_distance);
    sac.setInlierFraction(0.25f);
    Cloud aligned;
    sac.align(aligned);
    if (sac.hasConverged()) {
      const auto fine = withNormals(source, impl_->origin, p.refine_voxel, p.refine_normal_radius);
      pcl::IterativeClosestPointWithNormals<pcl::PointNormal, pcl::PointNormal> icp;
      icp.setInputSource(fine);
      icp.setInputTarget(impl_->refine);
      icp.setMaximumIterations(p.icp_iterations);
      icp.setTransformationEpsilon(1e-10);
      local = sac.getFinalTransformation();
      ok = true;
      for (double d : {p.refine_max_distance, p.refine_final_distance}) {
        icp.setMaxCorrespondenceDistance(d);
        pcl::PointCloud<pcl::PointNormal> aligned;
        icp.align(aligned, local);
        ok = ok && icp.hasConverged();
        local = icp.getFinalTransformation();
      }
    }
  }
  out.seconds = secondsSince(t0);
  out.returned = ok;
  // World: x -> origin + local(x - origin).
  const RigidTransform to_local(Eigen::Matrix3d::Identity(), -impl_->origin);
  const RigidTransform from_local(Eigen::Matrix3d::Identity(), impl_->origin);
  out.transform = from_local *
                  RigidTransform(local.topLeftCorner<3, 3>().cast<double>(),
                                 local.topRightCorner<3, 1>().cast<double>()) *
                  to_local;
  return out;
}

}  // namespace plumb::bench
