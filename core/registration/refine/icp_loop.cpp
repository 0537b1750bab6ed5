// Point-to-plane ICP loop, fit figures and slide test against a target surface (icp_loop.hpp).
#include "registration/refine/icp_loop.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <limits>

#include "registration/refine/point_to_plane.hpp"

namespace plumb::refine_detail {

namespace {

/// The surface point matched to source point i placed at x; `placed` moves a local-frame point
/// the way x was moved (its viewer goes with it).
template <typename Place>
bool matchPoint(const TargetSurface& surface, SourceViewers viewers, std::size_t i,
                const Eigen::Vector3d& x, const Place& placed, double max_d, Eigen::Vector3d& q,
                Eigen::Vector3d& n) {
  if (!viewers) return surface.nearest(x, max_d, q, n);
  return surface.nearestSeenFrom(x, placed((*viewers)[i]), max_d, q, n);
}

/// Mean capped point-to-plane cost, min(r^2, d^2) / d^2, of every source point placed by
/// (R, t) and then moved by (dR, dt) about `centre`; a point without a surface point within
/// `gate` costs 1.
double slideCost(const Cloud& src, const TargetSurface& surface, const Eigen::Matrix3d& R,
                 const Eigen::Vector3d& t, const Eigen::Vector3d& centre, const Eigen::Matrix3d& dR,
                 const Eigen::Vector3d& dt, double d, double gate, SourceViewers viewers) {
  const double d2 = d * d;
  // Deterministic reduce: the same chunks summed in the same order on every run, so the cost
  // (and the candidates compared on it) do not change with thread timing.
  return tbb::parallel_deterministic_reduce(
             tbb::blocked_range<std::size_t>(0, src.size(), 512), 0.0,
             [&](const auto& range, double sum) {
               Eigen::Vector3d q, n;
               const auto placed = [&](const Eigen::Vector3d& v) {
                 return Eigen::Vector3d(dR * (R * v + t - centre) + centre + dt);
               };
               for (std::size_t i = range.begin(); i < range.end(); ++i) {
                 const Eigen::Vector3d x = placed(src[i].getVector3fMap().cast<double>());
                 double r2 = d2;
                 if (matchPoint(surface, viewers, i, x, placed, gate, q, n)) {
                   const double r = n.dot(x - q);
                   r2 = std::min(r * r, d2);
                 }
                 sum += r2 / d2;
               }
               return sum;
             },
             std::plus<double>()) /
         double(src.size());
}

/// Gate of the slide test's neighbour search, m.
double slideGate(double final_distance) {
  return std::max(final_distance, 0.15) + RefineResult::kSlideDistance;
}

/// RefineResult::direction_resistance: each eigen-direction of res.normal_matrix slid both ways
/// by kSlideDistance (rotations scaled by res.length_scale); the smaller rise of slideCost over
/// res.fit_cost (the cost unmoved), over the overlap ratio.
std::array<double, 6> slideResistance(const Cloud& src, const TargetSurface& surface,
                                      const LocalPose& pose, const Eigen::Vector3d& centre,
                                      const RefineResult& res, double final_distance,
                                      SourceViewers viewers) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> es(res.normal_matrix);
  auto cost = [&](const Eigen::Matrix3d& dR, const Eigen::Vector3d& dt) {
    return slideCost(src, surface, pose.R, pose.t, centre, dR, dt, final_distance,
                     slideGate(final_distance), viewers);
  };
  const double base = res.fit_cost;
  std::array<double, 6> out{};
  for (int k = 0; k < 6; ++k) {
    double least = std::numeric_limits<double>::infinity();
    for (double sign : {-1.0, 1.0}) {
      const Eigen::Matrix<double, 6, 1> xi = sign * RefineResult::kSlideDistance * es.eigenvectors().col(k);
      const Eigen::Vector3d w = xi.head<3>() / res.length_scale;
      const Eigen::Matrix3d dR = w.norm() > 0 ? Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix()
                                             : Eigen::Matrix3d::Identity();
      least = std::min(least, cost(dR, xi.tail<3>()) - base);
    }
    out[k] = res.overlap > 0 ? least / res.overlap : 0.0;
  }
  return out;
}

/// Correspondences of every `step`-th source point placed by `pose`: its nearest surface point
/// within max_d with the normal there; in source order.
std::vector<PlaneCorrespondence> findCorrespondences(const Cloud& src, const TargetSurface& surface,
                                                     const LocalPose& pose, std::size_t step,
                                                     double max_d, SourceViewers viewers) {
  const std::size_t n = (src.size() + step - 1) / step;
  std::vector<PlaneCorrespondence> c(n);
  std::vector<char> valid(n, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 512), [&](const auto& range) {
    Eigen::Vector3d y, nn;
    const auto placed = [&](const Eigen::Vector3d& v) { return Eigen::Vector3d(pose.R * v + pose.t); };
    for (std::size_t i = range.begin(); i < range.end(); ++i) {
      const Eigen::Vector3d x = placed(src[i * step].getVector3fMap().cast<double>());
      if (!matchPoint(surface, viewers, i * step, x, placed, max_d, y, nn)) continue;
      c[i] = {x, y, nn, nn.dot(x - y)};
      valid[i] = 1;
    }
  });
  std::vector<PlaneCorrespondence> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    if (valid[i]) out.push_back(c[i]);
  return out;
}

/// One stage of trimmed (and Huber-weighted) point-to-plane ICP at correspondence distance
/// max_d: up to p.iterations steps (factor, reduction, optimizer: point_to_plane.hpp) until a
/// step is small, which sets out.converged (it stays set for the later stages).
void pointToPlaneStage(const Cloud& src, const TargetSurface& surface, const RefineParams& p,
                       double max_d, std::size_t step, LoopOutcome& out, Progress* progress,
                       SourceViewers viewers) {
  for (int it = 0; it < p.iterations; ++it) {
    checkCanceled(progress);
    auto c = findCorrespondences(src, surface, out.pose, step, max_d, viewers);
    trimCorrespondences(c, p.trim_fraction, p.trim_per_direction);
    huberWeights(c, p.huber);
    if (c.size() < 6) break;
    const IcpStep d = solveIcpStep(accumulateNormalEquations(c));
    if (!d.finite) break;
    out.pose.R = d.dR * out.pose.R;
    out.pose.t = d.dR * out.pose.t + d.dt;
    ++out.iterations;
    if (stepConverged(d)) {
      out.converged = true;
      break;
    }
  }
}

}  // namespace

LoopOutcome runPointToPlane(const Cloud& src, const SurfaceAt& surface, const RefineParams& p,
                            Progress* progress, SourceViewers viewers) {
  const int stages = std::max(1, p.stages);
  LoopOutcome out;
  for (int st = 0; st < stages; ++st) {
    const TargetSurface& s = surface(out.pose);
    pointToPlaneStage(src, s, p, stageDistance(p.start_distance, p.final_distance, stages, st),
                      st + 1 < stages ? 4 : 1, out, progress, viewers);
    reportProgress(progress, 0.1 + 0.8 * (st + 1) / stages, "refine: ICP");
  }
  return out;
}

void measureFit(const Cloud& src, const TargetSurface& surface, const LocalPose& pose,
                const Eigen::Vector3d& origin, const RefineParams& p, RefineResult& res,
                SourceViewers viewers) {
  // Inliers: a surface point within max(final distance, 0.15 m) (sparse or thinned targets)
  // and a point-to-plane residual below the final distance.
  auto c = findCorrespondences(src, surface, pose, 1, std::max(p.final_distance, 0.15), viewers);
  const InlierFigures f = inlierFigures(c, p.final_distance);
  res.inliers = f.inliers;
  res.rms = f.rms;
  res.overlap = double(c.size()) / double(src.size());
  res.length_scale = f.length_scale;
  res.normal_matrix = f.normal_matrix;
  res.centre = f.centre + origin;
  res.fit_cost = slideCost(src, surface, pose.R, pose.t, f.centre, Eigen::Matrix3d::Identity(),
                           Eigen::Vector3d::Zero(), p.final_distance, slideGate(p.final_distance), viewers);
  if (!c.empty() && p.slide_test)
    res.direction_resistance = slideResistance(src, surface, pose, f.centre, res, p.final_distance, viewers);
}

}  // namespace plumb::refine_detail
