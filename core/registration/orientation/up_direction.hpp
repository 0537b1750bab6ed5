#pragma once
// Up-direction candidates of a dataset from its own features (issue 14, docs/ALGORITHMS.md
// §9): buildings are made of floors, ceilings and walls, so the up direction is one of the
// principal directions of the plane normals (the Manhattan frame; vertical edges when the
// segments are all there is). Each principal direction is a candidate, with both signs: the
// normals are unsigned and a wall's direction looks like a floor's after a 90-degree tilt, so
// the data alone may not tell which one is up; the registration evidence decides then. Two
// principal directions at right angles also offer the direction perpendicular to both (two
// walls of a room whose floor is outweighed by a pitched roof).
#include <Eigen/Core>

#include <string>
#include <vector>

#include "model/feature_set.hpp"
#include "registration/clustering/direction_clustering.hpp"
#include "registration/orientation/orientation_params.hpp"

namespace plumb {

struct UpCandidate {
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();  ///< unit, in the dataset's frame
  double share = 0.0;  ///< fraction of the normals' (segments') weight on this axis
  double tilt_deg = 0.0;  ///< angle between `up` and +Z
};

struct UpEstimate {
  /// Most plausible first: the axis nearest +Z, then by weight; each axis with +sign (towards
  /// +Z) first.
  std::vector<UpCandidate> candidates;
  /// An axis lies within level_tolerance_deg of Z (the dataset may be levelled as it is).
  bool looks_levelled = false;
  /// Number of distinct axes (candidates / 2).
  std::size_t axes = 0;
  std::string message;  ///< plain language, for the log
};

/// The up candidates of a dataset from its plane normals (weighted by inlier count), or from
/// its segment directions (weighted by length) when the planes span fewer than two directions.
/// `clustering` is the plane/segment direction clustering (its angle tolerance).
UpEstimate estimateUpDirections(const std::vector<PlanarPolygon>& planes,
                                const std::vector<Segment3D>& segments,
                                const OrientationParams& params,
                                const DirectionClusteringParams& clustering);

}  // namespace plumb
