// Point-to-plane ICP step: factor, reduction, optimizer (point_to_plane.hpp).
#include "registration/refine/point_to_plane.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace plumb::refine_detail {

namespace {

/// Direction class of a correspondence's normal: near-vertical normals (floors, ceilings) form
/// one class; the others (walls) are binned by azimuth modulo 180 degrees in kAzimuthBins bins.
constexpr int kAzimuthBins = 6;
int normalClass(const Eigen::Vector3d& n) {
  if (std::abs(n.z()) > 0.7) return kAzimuthBins;
  double a = std::atan2(n.y(), n.x());
  if (a < 0) a += M_PI;
  return std::min(kAzimuthBins - 1, int(a / M_PI * kAzimuthBins));
}

void trimSmallestResiduals(std::vector<PlaneCorrespondence>& c, double trim_fraction) {
  const std::size_t keep = std::max<std::size_t>(6, std::size_t(trim_fraction * c.size()));
  if (keep >= c.size()) return;
  std::nth_element(c.begin(), c.begin() + (keep - 1), c.end(),
                   [](const PlaneCorrespondence& a, const PlaneCorrespondence& b) {
                     return std::abs(a.r) < std::abs(b.r);
                   });
  c.resize(keep);
}

}  // namespace

void trimCorrespondences(std::vector<PlaneCorrespondence>& c, double trim_fraction,
                         bool per_direction) {
  if (trim_fraction >= 1.0 || c.size() < 10) return;
  if (!per_direction) {
    trimSmallestResiduals(c, trim_fraction);
    return;
  }
  std::vector<std::vector<PlaneCorrespondence>> classes(kAzimuthBins + 1);
  for (const auto& k : c) classes[normalClass(k.n)].push_back(k);
  c.clear();
  for (auto& g : classes) {
    if (g.size() >= 10) trimSmallestResiduals(g, trim_fraction);
    c.insert(c.end(), g.begin(), g.end());
  }
}

void huberWeights(std::vector<PlaneCorrespondence>& c, double delta) {
  if (!(delta > 0)) return;
  for (auto& k : c) k.w = std::abs(k.r) <= delta ? 1.0 : delta / std::abs(k.r);
}

Vector6d pointToPlaneJacobian(const PlaneCorrespondence& c) {
  Vector6d j;
  j << c.p.cross(c.n), c.n;
  return j;
}

NormalEquations accumulateNormalEquations(const std::vector<PlaneCorrespondence>& c) {
  // Linearised point-to-plane (Low 2004): minimise sum (n·(x + w x x + dt - y))^2.
  NormalEquations eq;
  for (const auto& k : c) {
    const Vector6d j = pointToPlaneJacobian(k);
    eq.H += k.w * (j * j.transpose());
    eq.g += j * (k.w * k.r);
  }
  return eq;
}

IcpStep solveIcpStep(const NormalEquations& eq) {
  IcpStep step;
  const Vector6d d = eq.H.ldlt().solve(-eq.g);
  if (!d.allFinite()) return step;
  step.finite = true;
  step.angle = d.head<3>().norm();
  step.dR = step.angle > 0 ? Eigen::AngleAxisd(step.angle, d.head<3>() / step.angle).toRotationMatrix()
                           : Eigen::Matrix3d::Identity();
  step.dt = d.tail<3>();
  return step;
}

bool stepConverged(const IcpStep& step) { return step.angle < 2e-5 && step.dt.norm() < 2e-4; }

double stageDistance(double start_distance, double final_distance, int stages, int s) {
  const double ratio = stages > 1 ? std::pow(final_distance / start_distance, 1.0 / (stages - 1)) : 1.0;
  return start_distance * std::pow(ratio, s);
}

InlierFigures inlierFigures(std::vector<PlaneCorrespondence>& c, double inlier_distance) {
  c.erase(std::remove_if(c.begin(), c.end(),
                         [&](const PlaneCorrespondence& k) { return std::abs(k.r) > inlier_distance; }),
          c.end());
  InlierFigures f;
  double sq = 0.0;
  for (const auto& k : c) {
    sq += k.r * k.r;
    f.centre += k.p;
  }
  f.inliers = c.size();
  if (c.empty()) return f;
  f.rms = std::sqrt(sq / c.size());
  f.centre /= double(c.size());
  double l2 = 0.0;
  for (const auto& k : c) l2 += (k.p - f.centre).squaredNorm();
  f.length_scale = std::max(1e-3, std::sqrt(l2 / c.size()));
  for (const auto& k : c) {
    Vector6d j;
    j << (k.p - f.centre).cross(k.n) / f.length_scale, k.n;
    f.normal_matrix += j * j.transpose();
  }
  return f;
}

}  // namespace plumb::refine_detail
