#include "registration/clustering/direction_clustering.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace plumb {

const ParamSchema<DirectionClusteringParams>& DirectionClusteringParams::schema() {
  static const auto s =
      ParamSchema<DirectionClusteringParams>("direction-clustering")
          .real(&DirectionClusteringParams::angle_tolerance_deg, "cluster-angle", "Cluster angle",
                "deg", 0.5, 45.0, "Angle tolerance of direction clustering")
          .integer(&DirectionClusteringParams::max_clusters, "max-clusters", "Max clusters", "", 1,
                   8, "Number of direction clusters", true);
  return s;
}

std::vector<Eigen::Vector3d> DirectionClusteringResult::directions() const {
  std::vector<Eigen::Vector3d> d;
  for (const auto& c : clusters) d.push_back(c.direction);
  return d;
}

namespace {

/// Items with a usable direction (finite, non-zero, positive weight), as unit vectors, in
/// decreasing weight (inliers / length), ties by index: deterministic.
std::vector<int> usableByWeight(const std::vector<DirectionItem>& items,
                                std::vector<Eigen::Vector3d>& unit) {
  std::vector<int> order;
  unit.resize(items.size());
  for (std::size_t i = 0; i < items.size(); ++i) {
    const double n = items[i].direction.norm();
    if (n > 0 && std::isfinite(n) && items[i].weight > 0) {
      unit[i] = items[i].direction / n;
      order.push_back(int(i));
    }
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return items[a].weight > items[b].weight; });
  return order;
}

/// A cluster's seed direction and the weighted sum of its sign-aligned members.
struct Accumulator {
  Eigen::Vector3d ref, sum;
};

/// Seeds: heaviest item, then the heaviest one farther than theta from every seed (|.|).
std::vector<Accumulator> seedClusters(const std::vector<DirectionItem>& items,
                                      const std::vector<Eigen::Vector3d>& unit,
                                      const std::vector<int>& order, double cos_tol,
                                      int max_clusters, DirectionClusteringResult& r) {
  std::vector<Accumulator> acc;
  for (int i : order) {
    if (int(acc.size()) >= max_clusters) break;
    bool far = true;
    for (const auto& a : acc)
      if (std::abs(unit[i].dot(a.ref)) >= cos_tol) far = false;
    if (!far) continue;
    acc.push_back({unit[i], items[i].weight * unit[i]});
    r.clusters.push_back({unit[i], items[i].weight, {i}});
    r.cluster_of_item[i] = int(r.clusters.size()) - 1;
  }
  return acc;
}

/// Remaining items by decreasing weight join the closest cluster within theta; the cluster
/// direction is the weighted mean with members flipped to agree with the seed (2023 step 5).
void joinClusters(const std::vector<DirectionItem>& items, const std::vector<Eigen::Vector3d>& unit,
                  const std::vector<int>& order, double cos_tol, std::vector<Accumulator>& acc,
                  DirectionClusteringResult& r) {
  for (int i : order) {
    if (r.cluster_of_item[i] >= 0) continue;
    int best = -1;
    double best_dot = cos_tol;
    for (std::size_t k = 0; k < r.clusters.size(); ++k) {
      const double d = std::abs(unit[i].dot(r.clusters[k].direction));
      if (d >= best_dot) {
        best_dot = d;
        best = int(k);
      }
    }
    if (best < 0) continue;
    auto& c = r.clusters[best];
    const double s = unit[i].dot(acc[best].ref) >= 0 ? 1.0 : -1.0;
    acc[best].sum += s * items[i].weight * unit[i];
    c.direction = acc[best].sum.normalized();
    c.weight += items[i].weight;
    c.members.push_back(i);
    r.cluster_of_item[i] = best;
  }
}

/// Heaviest cluster first (stable), remapping indices.
void sortByWeight(DirectionClusteringResult& r) {
  std::vector<int> perm(r.clusters.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::stable_sort(perm.begin(), perm.end(),
                   [&](int a, int b) { return r.clusters[a].weight > r.clusters[b].weight; });
  std::vector<DirectionCluster> sorted;
  std::vector<int> inv(perm.size());
  for (std::size_t k = 0; k < perm.size(); ++k) {
    sorted.push_back(r.clusters[perm[k]]);
    inv[perm[k]] = int(k);
  }
  r.clusters = std::move(sorted);
  for (auto& c : r.cluster_of_item)
    if (c >= 0) c = inv[c];
}

/// Canonical sign: the larger of |z|, |x|, |y| component positive, so directions are stable.
/// Then the horizontal cluster: the one with the largest |z| (the normal of horizontal planes).
void canonicalSignsAndHorizontal(DirectionClusteringResult& r) {
  for (auto& c : r.clusters) {
    Eigen::Index k;
    c.direction.cwiseAbs().maxCoeff(&k);
    if (c.direction[k] < 0) c.direction = -c.direction;
  }
  double best_z = -1;
  for (std::size_t k = 0; k < r.clusters.size(); ++k) {
    const double z = std::abs(r.clusters[k].direction.z());
    if (z > best_z) {
      best_z = z;
      r.horizontal = int(k);
    }
  }
}

}  // namespace

DirectionClusteringResult clusterDirections(const std::vector<DirectionItem>& items,
                                            const DirectionClusteringParams& p) {
  DirectionClusteringResult r;
  r.cluster_of_item.assign(items.size(), -1);
  const double cos_tol = std::cos(p.angle_tolerance_deg * M_PI / 180.0);
  std::vector<Eigen::Vector3d> unit;
  const std::vector<int> order = usableByWeight(items, unit);
  std::vector<Accumulator> acc = seedClusters(items, unit, order, cos_tol, p.max_clusters, r);
  joinClusters(items, unit, order, cos_tol, acc, r);
  sortByWeight(r);
  canonicalSignsAndHorizontal(r);
  return r;
}

DirectionClusteringResult clusterPlaneNormals(const std::vector<PlanarPolygon>& planes,
                                              const DirectionClusteringParams& params) {
  std::vector<DirectionItem> items;
  for (const auto& pl : planes)
    items.push_back({pl.normal, pl.inlier_count > 0 ? double(pl.inlier_count) : pl.area});
  return clusterDirections(items, params);
}

DirectionClusteringResult clusterSegmentDirections(const std::vector<Segment3D>& segments,
                                                   const DirectionClusteringParams& params) {
  std::vector<DirectionItem> items;
  for (const auto& s : segments) items.push_back({s.b - s.a, s.length()});
  return clusterDirections(items, params);
}

}  // namespace plumb
