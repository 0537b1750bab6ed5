#pragma once
// Local refinement after every global method (docs/ALGORITHMS.md §8): trimmed point-to-plane ICP
// (PCL kd-tree and normals, linearised least squares after Low 2004) or PCL GICP, run
// coarse-to-fine over a shrinking correspondence distance. For a BIM target: point-to-triangle
// correspondences on the model triangles visible from the scan's stations (RefineTarget from a
// mesh, triangle_target.hpp), or points sampled on the model (sampleMeshSurface).
// The result (RefineResult, registration/common/refine_result.hpp) carries the 6x6 normal matrix
// of the final point-to-plane problem, from which the quality report derives the weakly
// constrained degrees of freedom.
#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>

#include "common/params.hpp"
#include "common/progress.hpp"
#include "model/bim_model.hpp"
#include "model/point_cloud.hpp"
#include "model/rigid_transform.hpp"
#include "registration/common/refine_result.hpp"

namespace plumb {

struct RefineParams {
  enum class Method { PointToPlane, Gicp };
  Method method = Method::PointToPlane;
  /// What a model target is refined against: its triangles (closest point on the triangles
  /// the scan's stations see, with the triangle normal; point-to-plane only) or points sampled
  /// on its surface every model-sample-spacing (the behaviour before issue 14; GICP always
  /// uses the samples). Default: triangles, far more accurate on real models (0.001 deg
  /// instead of 0.05-0.07 deg on duplex.ifc, bench_surface_refine), with the verdict suites
  /// run on them (docs/VERDICT.md).
  enum class ModelSurface { Triangles, Samples };
  ModelSurface model_surface = ModelSurface::Triangles;
  /// Huber threshold of the point-to-plane residual, metres, [0, 1]: correspondences with a
  /// larger residual get the weight threshold/|r| (point_to_plane.hpp); 0: no weights (the
  /// trimming alone).
  double huber = 0.0;
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
  /// Apply trim_fraction within each normal-direction class (floors/ceilings, walls by
  /// azimuth) rather than over all correspondences (point_to_plane.hpp). Default on.
  bool trim_per_direction = true;
  /// Scan targets whose stations are known (sensor origins or a viewpoint), sources too: match
  /// only surfaces both stations see (the target point's front faces its own station and the
  /// source point's: RefineTarget). Off: the nearest target point, whichever side of it was
  /// seen (the behaviour before issue 14).
  bool both_stations = true;
  /// Measure RefineResult::direction_resistance (the slide test: 12 more passes over the
  /// source points). Not a user setting (not in the schema: a report without it would find
  /// every direction unconstrained): the pipeline turns it off for the runner-up candidates
  /// it only compares.
  bool slide_test = true;
  /// Model triangles: find the visible triangles again at each stage (true) or once, under the
  /// initial placement (false). Not a user setting: bench_surface_refine compares the two.
  bool visibility_per_stage = true;
  static const ParamSchema<RefineParams>& schema();
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
  /// Throws InputError for an empty cloud. When the target's stations are known (per-point
  /// sensor origins, else `viewpoint`: the scanner of a single static scan, world), each
  /// target point's normal is turned towards the station that saw it, and a source that has
  /// stations too is matched only to surfaces both stations saw (the other face of a wall, a
  /// partition's far side and surfaces behind the source's station are never correspondences;
  /// RefineResult::surface says "points both stations see").
  RefineTarget(const PointCloud& target, const RefineParams& params,
               const std::optional<Eigen::Vector3d>& viewpoint = std::nullopt);
  /// A model surface: point-to-triangle correspondences, in the first (coarsest) stage on
  /// every triangle, then on the triangles the source's stations see (rays from its sensor
  /// origins, found again at each stage); without sensor origins, every triangle whose front
  /// faces the point (RefineResult::surface says which).
  /// Throws InputError for a mesh without triangles.
  RefineTarget(const TriangleMesh& mesh, const RefineParams& params);
  ~RefineTarget();
  RefineTarget(const RefineTarget&) = delete;
  RefineTarget& operator=(const RefineTarget&) = delete;
  struct Data;  ///< PCL types, defined in icp_refinement.cpp
  const Data& data() const { return *d_; }

 private:
  std::unique_ptr<Data> d_;
};

/// As above, against a prepared target (same result as with the cloud it was prepared from).
/// `source_viewpoint` (world, before `initial`): the scanner of a source without per-point
/// sensor origins, for the visibility rule of a point target whose stations are known.
RefineResult refineRegistration(const PointCloud& source, const RefineTarget& target,
                                const RigidTransform& initial, const RefineParams& params,
                                Progress* progress = nullptr,
                                const std::optional<Eigen::Vector3d>& source_viewpoint = std::nullopt);

/// Points on a mesh surface, about one per `spacing`^2 of area, with the triangle normals;
/// deterministic for a seed.
PointCloud sampleMeshSurface(const TriangleMesh& mesh, double spacing, std::uint64_t seed = 1);

}  // namespace plumb
