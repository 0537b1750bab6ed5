#include "quality/cloud_distance.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.hpp"
#include "quality/target_surface.hpp"

namespace plumb {

const ParamSchema<DistanceParams>& DistanceParams::schema() {
  static const auto s =
      ParamSchema<DistanceParams>("distance")
          .real(&DistanceParams::max_distance, "max-distance", "Max distance", "m", 0.001, 100.0,
                "Search radius: points with nothing closer are left unmatched (outside the overlap)")
          .boolean(&DistanceParams::signed_distances, "signed", "Signed",
                   "Positive in front of the target's surface (the scanner's side, or the side its "
                   "normals face), negative behind it; off: unsigned distances")
          .integer(&DistanceParams::normal_neighbours, "normal-neighbours", "Normal neighbours", "",
                   3, 100,
                   "Target points fitted by a plane to find the surface's facing at a nearest "
                   "point (target clouds without normals)",
                   true);
  return s;
}

void summarizeDistances(DistanceResult& r) {
  std::vector<float> finite;
  finite.reserve(r.distances.size());
  double sum = 0.0, sum_signed = 0.0, sum2 = 0.0;
  for (float d : r.distances)
    if (std::isfinite(d)) {
      finite.push_back(std::abs(d));
      sum += std::abs(d);
      sum_signed += d;
      sum2 += double(d) * d;
    }
  r.matched = finite.size();
  if (finite.empty()) {
    r.mean = r.rms = r.median = r.p95 = r.mean_signed = 0.0;
    return;
  }
  const double n = double(finite.size());
  r.mean = sum / n;
  r.mean_signed = sum_signed / n;
  r.rms = std::sqrt(sum2 / n);
  auto quantile = [&finite](double q) {
    const auto k = static_cast<std::size_t>(q * double(finite.size() - 1));
    std::nth_element(finite.begin(), finite.begin() + long(k), finite.end());
    return double(finite[k]);
  };
  r.median = quantile(0.5);
  r.p95 = quantile(0.95);
}

namespace {

/// Where fitted normals of a target without sensor origins face: one bounding-box diagonal
/// above the centre of its bounds (world up), in the target's local frame.
Eigen::Vector3f fallbackViewpoint(const PointCloud& target, const RigidTransform& target_to_world) {
  const Bounds b = target.bounds();
  const Eigen::Vector3d up = target_to_world.rotation().transpose() * Eigen::Vector3d::UnitZ();
  return (b.center() + up * std::max(1.0, b.diagonal()) - target.offset).cast<float>();
}

/// Negates the distances of the points behind the target's surface at their nearest point.
void applySigns(const PointCloud& source, const Eigen::Matrix3d& R, const Eigen::Vector3d& t,
                const detail::TargetTree& tree, const detail::TargetNormals& normals,
                const std::vector<int>& nearest, std::vector<float>& distances) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, distances.size(), 4096),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        if (nearest[i] < 0) continue;
                        const Eigen::Vector3d q = R * source.positions[i].cast<double>() + t;
                        const Eigen::Vector3d away = q - tree.at(nearest[i]).cast<double>();
                        if (away.dot(normals.at(nearest[i]).cast<double>()) < 0) distances[i] = -distances[i];
                      }
                    });
}

}  // namespace

DistanceResult cloudToCloudDistances(const PointCloud& source, const RigidTransform& source_to_world,
                                     const PointCloud& target, const RigidTransform& target_to_world,
                                     const DistanceParams& params, Progress* progress) {
  validateParams(DistanceParams::schema(), params);
  if (target.empty()) throw InputError("distance: the target cloud has no points");
  reportProgress(progress, 0.0, "distance: kd-tree");
  // Everything is measured in the target's local frame (float precision near its offset).
  const detail::TargetTree tree(target);
  if (tree.index.empty()) throw InputError("distance: the target cloud has no finite points");
  checkCanceled(progress);
  // source local -> target local: T_t^-1 * T_s, with the offsets folded in (double).
  const RigidTransform s2t = target_to_world.inverse() * source_to_world;
  const Eigen::Matrix3d R = s2t.rotation();
  const Eigen::Vector3d t = s2t.apply(source.offset) - target.offset;
  const float max_sq = float(params.max_distance * params.max_distance);
  DistanceResult r;
  r.distances.assign(source.size(), std::numeric_limits<float>::quiet_NaN());
  std::vector<int> nearest(source.size(), -1);  // tree point of each matched source point
  const std::size_t chunk = 1 << 16;
  const std::size_t chunks = (source.size() + chunk - 1) / chunk;
  for (std::size_t c = 0; c < chunks; ++c) {
    checkCanceled(progress);
    reportProgress(progress, 0.05 + 0.8 * double(c) / double(chunks), "distance: nearest points");
    const std::size_t end = std::min(source.size(), (c + 1) * chunk);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(c * chunk, end, 2048),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        pcl::Indices k(1);
                        std::vector<float> d2(1);
                        for (std::size_t i = range.begin(); i != range.end(); ++i) {
                          if (!source.positions[i].allFinite()) continue;
                          const Eigen::Vector3d q = R * source.positions[i].cast<double>() + t;
                          const pcl::PointXYZ p(float(q.x()), float(q.y()), float(q.z()));
                          if (tree.tree.nearestKSearch(p, 1, k, d2) == 1 && d2[0] <= max_sq) {
                            r.distances[i] = std::sqrt(d2[0]);
                            nearest[i] = k[0];
                          }
                        }
                      });
  }
  if (params.signed_distances) {
    checkCanceled(progress);
    reportProgress(progress, 0.85, "distance: surface normals");
    const detail::TargetNormals normals(target, tree, nearest, params.normal_neighbours,
                                        fallbackViewpoint(target, target_to_world));
    applySigns(source, R, t, tree, normals, nearest, r.distances);
  }
  summarizeDistances(r);
  reportProgress(progress, 1.0, "distance: done");
  return r;
}

DistanceHistogram distanceHistogram(std::span<const float> values, double lo, double hi, int bins) {
  if (bins < 1 || !(hi > lo))
    throw InputError("histogram: needs at least one bin and hi > lo");
  DistanceHistogram h;
  h.lo = lo;
  h.hi = hi;
  h.counts.assign(std::size_t(bins), 0);
  const double scale = double(bins) / (hi - lo);
  for (float v : values) {
    if (!std::isfinite(v)) ++h.invalid;
    else if (v < lo) ++h.below;
    else if (v >= hi) ++h.above;
    else h.counts[std::min<std::size_t>(std::size_t((v - lo) * scale), std::size_t(bins) - 1)]++;
  }
  return h;
}

}  // namespace plumb
