#pragma once
// What the local refinement (registration/refine, docs/ALGORITHMS.md §8) reports: the refined
// transform and the figures the quality report and the candidate comparison read. Here, beside
// the other registration results, so that readers of the figures (core/quality) do not link
// the refinement itself.
#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <string>

#include "model/rigid_transform.hpp"

namespace plumb {

struct RefineResult {
  RigidTransform transform;       ///< refined source -> target
  bool converged = false;
  int iterations = 0;
  double rms = 0.0;               ///< m, point-to-plane RMS of inliers
  /// Fraction of used source points with an inlier match: nearest target point within
  /// max(final_distance, 0.15 m) and point-to-plane residual below final_distance.
  double overlap = 0.0;
  std::size_t inliers = 0;
  /// Mean capped point-to-plane cost of the used source points at the result, min(r^2, d^2)
  /// / d^2 with d the final distance (a point without a target neighbour costs 1): one figure
  /// of the fit that counts both the unexplained points and the residuals of the explained
  /// ones (0: every point exactly on the target). Compares refined candidate placements.
  double fit_cost = 1.0;
  /// Fraction of the source's structure points (those on its large planes) with an inlier
  /// match at this transform, in [0, 1]; < 0 when not measured. Not set by the refinement: the
  /// candidate comparison measures it (registration/auto/structure_overlap.hpp).
  double structure_overlap = -1.0;
  std::size_t source_points = 0;  ///< used (after thinning)
  std::size_t target_points = 0;  ///< used: thinned target points, or visible triangles
  /// What the source was matched against: "points" (a scan or model samples), "points both
  /// stations see" (a scan, both sides' stations known: the target point's front faces its own
  /// station and the source point's), "visible triangles" (a model, visibility from the
  /// source's sensor origins) or "front-facing triangles" (a model, the source has no sensor
  /// origins).
  std::string surface = "points";
  double visibility_seconds = 0.0;  ///< spent finding the visible triangles (a model target)
  /// Normal matrix sum J^T J of the final point-to-plane problem, J = [(p x n)/L, n], rotation
  /// scaled by the length L (RMS radius of the inliers about their centroid) so eigenvalues are
  /// comparable, and expressed about that centroid.
  Eigen::Matrix<double, 6, 6> normal_matrix = Eigen::Matrix<double, 6, 6>::Zero();
  double length_scale = 1.0;
  /// Resistance of each eigen-direction v_k of normal_matrix (ascending eigenvalues, the order
  /// of Eigen::SelfAdjointEigenSolver), from a finite slide: the source is moved by
  /// kSlideDistance along +v_k and -v_k (rotations scaled so that points at length_scale from
  /// the centre move that far), and the figure is the smaller increase of the mean capped
  /// point-to-plane cost, min(r^2, d^2) / d^2 with d the final distance, over the overlap
  /// ratio: about the fraction of the matched points pushed off their surface. Beyond the papers: an eigenvalue cannot tell a direction
  /// held by real geometry (a few dozen points on a perpendicular wall) from one "held" by the
  /// noise of thousands of estimated normals (a corridor's axis, a plane's in-plane shifts);
  /// after a finite slide the noisy normals no longer push back, the perpendicular wall does.
  std::array<double, 6> direction_resistance{};
  static constexpr double kSlideDistance = 0.2;  ///< m
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< centroid of the inliers (world)
  std::string message;
};

}  // namespace plumb
