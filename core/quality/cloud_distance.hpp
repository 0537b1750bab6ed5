#pragma once
// Visual QA of a registration: the distance of every point of the registered source to the
// target, cloud-to-cloud (nearest target point, PCL kd-tree) or cloud-to-mesh (closest point on
// the model's triangles, CGAL AABB tree), and a histogram of those distances. Both inputs carry
// their own transform to world, so the registered source is measured where it is shown.
#include <cstdint>
#include <span>
#include <vector>

#include "common/params.hpp"
#include "common/progress.hpp"
#include "model/bim_model.hpp"
#include "model/point_cloud.hpp"
#include "model/rigid_transform.hpp"

namespace plumb {

struct DistanceParams {
  /// Search radius, metres, [0.001, 100]: points with nothing closer get NaN (no match; they
  /// are outside the overlap and not counted in the statistics).
  double max_distance = 0.1;
  static const ParamSchema<DistanceParams>& schema();
};

struct DistanceResult {
  std::vector<float> distances;  ///< per source point, metres; NaN: nothing within max_distance
  std::size_t matched = 0;       ///< finite distances
  double mean = 0.0, rms = 0.0, median = 0.0, p95 = 0.0;  ///< over matched points, metres
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

/// Fills matched/mean/rms/median/p95 of `r.distances`.
void summarizeDistances(DistanceResult& r);

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
