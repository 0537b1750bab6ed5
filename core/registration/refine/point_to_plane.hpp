#pragma once
// The point-to-plane ICP step of the local refinement (docs/ALGORITHMS.md §8), split the way
// small_gicp splits it: a factor per correspondence (residual and Jacobian of the linearised
// cost, Low 2004), a reduction (normal equations summed over the correspondences) and an
// optimizer step (solve, turn the rotation vector into a rotation, test convergence). Pure
// Eigen: the neighbour search that makes the correspondences stays in icp_refinement.cpp.
#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace plumb::refine_detail {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// Source point p (placed by the current estimate), its nearest target point q with the target
/// normal n there, and the signed point-to-plane residual r = n·(p - q).
struct PlaneCorrespondence {
  Eigen::Vector3d p, q, n;
  double r;
  double w = 1.0;  ///< robust weight of the correspondence (huberWeights)
};

/// Trimmed ICP: keeps the max(6, trim_fraction x size) correspondences of smallest |r| (in no
/// particular order); nothing is dropped when trim_fraction >= 1 or there are fewer than 10.
/// With `per_direction`, the fraction is kept within each normal-direction class (floors and
/// ceilings; walls by azimuth in 30-degree bins) of at least 10 correspondences: a start a few
/// centimetres off along one wall direction gives that direction's points the largest residuals,
/// and a global trim would drop exactly the points that constrain it (the refinement then
/// settles beside the truth).
void trimCorrespondences(std::vector<PlaneCorrespondence>& c, double trim_fraction,
                         bool per_direction);

/// Huber weights (Huber 1964; the IRLS weight of the Huber loss): w = 1 for |r| <= delta,
/// delta / |r| beyond, so a residual beyond delta pulls with a constant force rather than one
/// growing with its size. delta in metres; <= 0 leaves every weight at 1.
void huberWeights(std::vector<PlaneCorrespondence>& c, double delta);

/// Jacobian of r with respect to (w, dt) for x -> x + w x x + dt: J = [p x n; n] (Low 2004,
/// small-angle rotation).
Vector6d pointToPlaneJacobian(const PlaneCorrespondence& c);

/// Normal equations of sum w (r + J·xi)^2: H = sum w J J^T, g = sum w J r.
struct NormalEquations {
  Matrix6d H = Matrix6d::Zero();
  Vector6d g = Vector6d::Zero();
};
NormalEquations accumulateNormalEquations(const std::vector<PlaneCorrespondence>& c);

/// One Gauss-Newton step: xi = -H^-1 g, applied as x -> dR x + dt with dR the rotation of the
/// vector xi.head(3) (angle = its norm).
struct IcpStep {
  Eigen::Matrix3d dR = Eigen::Matrix3d::Identity();
  Eigen::Vector3d dt = Eigen::Vector3d::Zero();
  double angle = 0.0;  ///< rad
  bool finite = false; ///< false: H was singular, the step is not usable
};
IcpStep solveIcpStep(const NormalEquations& eq);

/// The step is small enough to stop: rotation below 2e-5 rad and translation below 0.2 mm.
bool stepConverged(const IcpStep& step);

/// Correspondence distance of stage s of `stages`, geometric from start to final.
double stageDistance(double start_distance, double final_distance, int stages, int s);

/// What the refinement reports about its inliers (RefineResult), in the local frame.
struct InlierFigures {
  std::size_t inliers = 0;
  double rms = 0.0;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< centroid of the inlier points p
  double length_scale = 1.0;  ///< RMS radius about the centre, at least 1 mm
  Matrix6d normal_matrix = Matrix6d::Zero();  ///< sum J J^T, J = [(p - centre) x n / L; n]
};
/// Figures of the correspondences with |r| <= inlier_distance (the others are dropped from c).
InlierFigures inlierFigures(std::vector<PlaneCorrespondence>& c, double inlier_distance);

}  // namespace plumb::refine_detail
