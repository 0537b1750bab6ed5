#pragma once
// Greedy direction clustering (2021 Alg. 1 for plane normals weighted by inlier count, 2023
// Alg. 1 for segment directions weighted by length), with ONE angle tolerance theta: an item
// joins a cluster when |d·c| >= cos(theta), and seeds are mutually farther than theta
// (docs/ALGORITHMS.md §3: the printed versions mix 1-|cos| with an angle and omit |.| in seeding).
#include <Eigen/Core>

#include <vector>

#include "common/params.hpp"
#include "model/feature_set.hpp"

namespace plumb {

struct DirectionClusteringParams {
  /// Angle tolerance theta, degrees, (0, 45]. Default 10: walls of a building meet at >= 30°.
  double angle_tolerance_deg = 10.0;
  /// Number of clusters seeded, [1, 8]. The papers use 3 (two wall directions + horizontal);
  /// 6 leaves room for ramps or sloped ceilings without losing a wall direction.
  int max_clusters = 6;
  static const ParamSchema<DirectionClusteringParams>& schema();
};

struct DirectionItem {
  Eigen::Vector3d direction;  ///< any length > 0, sign meaningless
  double weight = 1.0;        ///< inlier count or length
};

struct DirectionCluster {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  ///< unit, sign-aligned weighted mean
  double weight = 0.0;          ///< sum of member weights
  std::vector<int> members;     ///< item indices, heaviest first
};

struct DirectionClusteringResult {
  std::vector<DirectionCluster> clusters;  ///< heaviest first
  std::vector<int> cluster_of_item;        ///< -1 when unclustered
  int horizontal = -1;  ///< plane clusters: the one whose direction is closest to Z (2021 Alg. 1)
  /// Directions of the clusters, in cluster order (input of enumerateRotations()).
  std::vector<Eigen::Vector3d> directions() const;
};

/// The greedy algorithm on arbitrary weighted directions. Deterministic (ties by index).
DirectionClusteringResult clusterDirections(const std::vector<DirectionItem>& items,
                                            const DirectionClusteringParams& params);
/// 2021 Alg. 1: plane normals weighted by inlier count (area when no inliers are recorded).
DirectionClusteringResult clusterPlaneNormals(const std::vector<PlanarPolygon>& planes,
                                              const DirectionClusteringParams& params);
/// 2023 Alg. 1: segment directions weighted by length.
DirectionClusteringResult clusterSegmentDirections(const std::vector<Segment3D>& segments,
                                                   const DirectionClusteringParams& params);

}  // namespace plumb
