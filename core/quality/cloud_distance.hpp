#pragma once
// Visual QA of a registration: the distance of every point of the registered source to the
// target, cloud-to-cloud (nearest target point, PCL kd-tree) or cloud-to-mesh (closest point on
// the model's triangles, CGAL AABB tree), and a histogram of those distances. Both inputs carry
// their own transform to world, so the registered source is measured where it is shown.
//
// Sign convention (DistanceParams::signed_distances): the magnitude is always the distance to
// the nearest target point (or triangle); the sign says on which side of the target's surface
// the point lies. Positive: on the side the surface normal points to, negative: behind it.
// Cloud-to-mesh: the normal of the closest triangle (its winding). Cloud-to-cloud: the normal at
// the nearest target point, the cloud's own normal when it has one, else the plane fitted to its
// `normal_neighbours` nearest target points; it is turned towards the target's sensor origin
// (per point) when the target has sensor origins, so "+" means "in front of the scanned surface,
// on the scanner's side". A target with neither normals nor sensor origins has its fitted normals
// turned towards a viewpoint above the middle of its bounds (one bounding-box diagonal above the
// centre, world up): floors and roofs then point up.
#include <cstdint>
#include <span>
#include <vector>

#include "common/params.hpp"
#include "common/progress.hpp"
#include "model/bim_model.hpp"
#include "model/dataset.hpp"
#include "model/point_cloud.hpp"
#include "model/rigid_transform.hpp"

namespace plumb {

struct DistanceParams {
  /// Search radius, metres, [0.001, 100]: points with nothing closer get NaN (no match; they
  /// are outside the overlap and not counted in the statistics).
  double max_distance = 0.1;
  /// Signed distances (see the sign convention above); false: unsigned (every value >= 0).
  bool signed_distances = true;
  /// Target points fitted by a plane for the normal at a nearest point, [3, 100], when the
  /// target cloud has no normals (cloud-to-cloud, signed only).
  int normal_neighbours = 12;
  static const ParamSchema<DistanceParams>& schema();
};

struct DistanceResult {
  std::vector<float> distances;  ///< per source point, metres, signed or not; NaN: no match
  std::size_t matched = 0;       ///< finite distances
  /// Of the absolute distances of the matched points, metres.
  double mean = 0.0, rms = 0.0, median = 0.0, p95 = 0.0;
  double mean_signed = 0.0;  ///< mean of the signed values (a bias along the normals), metres
};

/// Distance of each point of `source` (mapped by `source_to_world`) to the nearest point of
/// `target` (mapped by `target_to_world`). Throws InputError for an empty target.
DistanceResult cloudToCloudDistances(const PointCloud& source, const RigidTransform& source_to_world,
                                     const PointCloud& target, const RigidTransform& target_to_world,
                                     const DistanceParams& params = {}, Progress* progress = nullptr);

/// Distance of each point of `source` to the closest point of the triangles of `mesh` (mapped
/// by `mesh_to_world`). Throws InputError for a mesh without triangles.
DistanceResult cloudToMeshDistances(const PointCloud& source, const RigidTransform& source_to_world,
                                    const TriangleMesh& mesh, const RigidTransform& mesh_to_world,
                                    const DistanceParams& params = {}, Progress* progress = nullptr);

/// Fills matched/mean/rms/median/p95/mean_signed of `r.distances`.
void summarizeDistances(DistanceResult& r);

/// The surface the distances of a whole dataset are measured to, in world coordinates: a cloud
/// (with sensor origins when known, as makeRegistrationInput gives it) or a model's triangles.
struct DistanceTarget {
  const PointCloud* cloud = nullptr;  ///< used when set
  const TriangleMesh* mesh = nullptr;  ///< used when cloud is null
};

/// Distances of every scan of a dataset, one vector per scan, and their statistics.
struct DatasetDistances {
  std::vector<std::vector<float>> per_scan;
  DistanceResult all;  ///< statistics over all scans (distances concatenated)
  bool signed_values = false;  ///< the params asked for signed distances
};

/// Distances of each scan of `source` (placed by `source_to_world` times its pose) to `target`.
/// InputError when the target has neither a cloud nor a mesh, or no points / triangles.
DatasetDistances datasetDistances(const Dataset& source, const RigidTransform& source_to_world,
                                  const DistanceTarget& target, const DistanceParams& params,
                                  Progress* progress = nullptr);

/// Name of the per-point scalar field the distances are exported as (metres, float32).
inline constexpr const char* kDistanceField = "distance";

/// Stores `per_scan` (one value per point of each scan) as the scalar field "distance" of each
/// scan's cloud, replacing one of that name. InputError when a size does not match.
void attachDistanceField(Dataset& dataset, const std::vector<std::vector<float>>& per_scan);

struct DistanceHistogram {
  double lo = 0.0, hi = 1.0;          ///< range of the bins, metres
  std::vector<std::size_t> counts;    ///< bins of equal width over [lo, hi)
  std::size_t below = 0, above = 0;   ///< finite values outside [lo, hi)
  std::size_t invalid = 0;            ///< NaN values (no match)
  double binWidth() const { return counts.empty() ? 0.0 : (hi - lo) / double(counts.size()); }
};

/// Histogram of the finite values in [lo, hi) with `bins` bins (>= 1, hi > lo, else InputError).
DistanceHistogram distanceHistogram(std::span<const float> values, double lo, double hi, int bins);

}  // namespace plumb
