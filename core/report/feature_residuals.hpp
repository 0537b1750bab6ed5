#pragma once
// Per-feature residuals of a registration, for the report's residual plot: each source feature
// (plane, opening, segment) moved by the final transform and compared with the nearest target
// feature of its kind that is parallel within a tolerance.
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "model/feature_set.hpp"
#include "model/rigid_transform.hpp"

namespace plumb::report {

struct ResidualParams {
  double max_angle_deg = 5.0;  ///< a target feature farther in direction is not its match, degrees
  double max_distance = 0.1;   ///< a match farther than this is "unmatched", metres
  std::size_t max_segments = 300;  ///< the longest source segments compared
};

struct FeatureResidual {
  std::string kind;        ///< "plane", "opening", "segment"
  std::size_t index = 0;   ///< in the source FeatureSet's list of that kind
  double size = 0.0;       ///< m^2 (plane, opening) or m (segment)
  bool matched = false;
  /// Plane: centroid to target plane; opening: centre to target centre within the façade
  /// (across the wall does not count: indoor and outdoor faces differ by the wall thickness);
  /// segment: midpoint to target segment. Metres; NaN when unmatched.
  double distance_m = std::numeric_limits<double>::quiet_NaN();
  double angle_deg = std::numeric_limits<double>::quiet_NaN();  ///< between directions
};

std::vector<FeatureResidual> featureResiduals(const FeatureSet& source, const FeatureSet& target,
                                              const RigidTransform& source_to_target,
                                              const ResidualParams& params = {});

}  // namespace plumb::report
