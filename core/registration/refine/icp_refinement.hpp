#pragma once
// Local refinement after every global method (docs/ALGORITHMS.md §8): trimmed point-to-plane ICP
// (PCL kd-tree and normals, linearised least squares after Low 2004) or PCL GICP, run
// coarse-to-fine over a shrinking correspondence distance. For a BIM target the caller passes
// points sampled on the model (sampleMeshSurface) with the mesh normals.
// The result carries the 6x6 normal matrix of the final point-to-plane problem, from which the
// quality report derives the weakly constrained degrees of freedom.
#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <memory>

#include "common/params.hpp"
#include "common/progress.hpp"
#include "model/bim_model.hpp"
#include "model/point_cloud.hpp"
#include "model/rigid_transform.hpp"

namespace plumb {

struct RefineParams {
  enum class Method { PointToPlane, Gicp };
  Method method = Method::PointToPlane;
  /// Voxel grid used to thin both clouds, metres, [0, 1] (0 keeps every point).
  double voxel_size = 0.05;
  /// Source points used (regular subset after voxel thinning), [100, 1e7].
  int max_source_points = 20000;
  /// First-stage max correspondence distance, metres, [0.01, 10].
  double start_distance = 0.5;
  /// Last-stage max correspondence distance, metres, [0.005, 1]. Also the inlier distance of
  /// the reported RMS and overlap.
  double final_distance = 0.05;
  /// Number of stages from start to final distance (geometric), [1, 10].
  int stages = 4;
  /// Max iterations per stage, [1, 200].
  int iterations = 10;
  /// Fraction of correspondences kept (smallest residuals), (0, 1]. Trimmed ICP.
  double trim_fraction = 0.9;
  /// Measure RefineResult::direction_resistance (the slide test: 12 more passes over the
  /// source points). Not a user setting (not in the schema: a report without it would find
  /// every direction unconstrained): the pipeline turns it off for the runner-up candidates
  /// it only compares.
  bool slide_test = true;
  static const ParamSchema<RefineParams>& schema();
};

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
  std::size_t source_points = 0;  ///< used (after thinning)
  std::size_t target_points = 0;
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

/// Refines `initial` (source -> target). Throws InputError for empty clouds.
RefineResult refineRegistration(const PointCloud& source, const PointCloud& target,
                                const RigidTransform& initial, const RefineParams& params,
                                Progress* progress = nullptr);

/// A refinement target prepared once (voxel-thinned points in a local frame, kd-tree, normals)
/// for refining several starting placements against it (the pipeline's candidates). Built
/// with the RefineParams::voxel_size it is then refined with.
class RefineTarget {
 public:
  /// Throws InputError for an empty cloud.
  RefineTarget(const PointCloud& target, const RefineParams& params);
  ~RefineTarget();
  RefineTarget(const RefineTarget&) = delete;
  RefineTarget& operator=(const RefineTarget&) = delete;
  struct Data;  ///< PCL types, defined in icp_refinement.cpp
  const Data& data() const { return *d_; }

 private:
  std::unique_ptr<Data> d_;
};

/// As above, against a prepared target (same result as with the cloud it was prepared from).
RefineResult refineRegistration(const PointCloud& source, const RefineTarget& target,
                                const RigidTransform& initial, const RefineParams& params,
                                Progress* progress = nullptr);

/// Points on a mesh surface, about one per `spacing`^2 of area, with the triangle normals;
/// deterministic for a seed.
PointCloud sampleMeshSurface(const TriangleMesh& mesh, double spacing, std::uint64_t seed = 1);

}  // namespace plumb
