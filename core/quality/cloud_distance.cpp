#include "quality/cloud_distance.hpp"

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.hpp"

namespace plumb {

const ParamSchema<DistanceParams>& DistanceParams::schema() {
  static const auto s = ParamSchema<DistanceParams>("distance").real(
      &DistanceParams::max_distance, "max-distance", "Max distance", "m", 0.001, 100.0,
      "Search radius: points with nothing closer are left unmatched (outside the overlap)");
  return s;
}

void summarizeDistances(DistanceResult& r) {
  std::vector<float> finite;
  finite.reserve(r.distances.size());
  double sum = 0.0, sum2 = 0.0;
  for (float d : r.distances)
    if (std::isfinite(d)) {
      finite.push_back(d);
      sum += d;
      sum2 += double(d) * d;
    }
  r.matched = finite.size();
  if (finite.empty()) {
    r.mean = r.rms = r.median = r.p95 = 0.0;
    return;
  }
  const double n = double(finite.size());
  r.mean = sum / n;
  r.rms = std::sqrt(sum2 / n);
  auto quantile = [&finite](double q) {
    const auto k = static_cast<std::size_t>(q * double(finite.size() - 1));
    std::nth_element(finite.begin(), finite.begin() + long(k), finite.end());
    return double(finite[k]);
  };
  r.median = quantile(0.5);
  r.p95 = quantile(0.95);
}

DistanceResult cloudToCloudDistances(const PointCloud& source, const RigidTransform& source_to_world,
                                     const PointCloud& target, const RigidTransform& target_to_world,
                                     const DistanceParams& params, Progress* progress) {
  if (target.empty()) throw InputError("distance: the target cloud has no points");
  reportProgress(progress, 0.0, "distance: kd-tree");
  // Everything is measured in the target's local frame (float precision near its offset).
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  cloud->reserve(target.size());
  for (const auto& p : target.positions)
    if (p.allFinite()) cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  if (cloud->empty()) throw InputError("distance: the target cloud has no finite points");
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(cloud);
  checkCanceled(progress);
  // source local -> target local: T_t^-1 * T_s, with the offsets folded in (double).
  const RigidTransform s2t = target_to_world.inverse() * source_to_world;
  const Eigen::Matrix3d R = s2t.rotation();
  const Eigen::Vector3d t = s2t.apply(source.offset) - target.offset;
  const float max_sq = float(params.max_distance * params.max_distance);
  DistanceResult r;
  r.distances.assign(source.size(), std::numeric_limits<float>::quiet_NaN());
  const std::size_t chunk = 1 << 16;
  const std::size_t chunks = (source.size() + chunk - 1) / chunk;
  for (std::size_t c = 0; c < chunks; ++c) {
    checkCanceled(progress);
    reportProgress(progress, 0.05 + 0.9 * double(c) / double(chunks), "distance: nearest points");
    const std::size_t end = std::min(source.size(), (c + 1) * chunk);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(c * chunk, end, 2048),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        pcl::Indices k(1);
                        std::vector<float> d2(1);
                        for (std::size_t i = range.begin(); i != range.end(); ++i) {
                          if (!source.positions[i].allFinite()) continue;
                          const Eigen::Vector3d q = R * source.positions[i].cast<double>() + t;
                          const pcl::PointXYZ p(float(q.x()), float(q.y()), float(q.z()));
                          if (tree.nearestKSearch(p, 1, k, d2) == 1 && d2[0] <= max_sq)
                            r.distances[i] = std::sqrt(d2[0]);
                        }
                      });
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
