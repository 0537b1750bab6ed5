#pragma once
// One candidate placement of the source on the target, as the report lists it: the chosen
// answer, and every other hypothesis the pipeline refined and compared with it (issue 13:
// a failed or ambiguous registration lists every candidate placement).
#include <string>
#include <utility>
#include <vector>

#include "model/rigid_transform.hpp"

namespace plumb {

struct PlacementCandidate {
  /// "chosen", "same placement" (converged onto the chosen one), "competing" (a different
  /// placement fitting about as well: ambiguous), "worse" (clearly worse refined fit).
  std::string role;
  std::string label;               ///< how the global step built it
  RigidTransform transform;        ///< refined when `refined`, else the global hypothesis
  double feature_score = 0.0;      ///< the global method's score (GlobalRegistrationResult unit)
  bool refined = false;
  double overlap = 0.0;            ///< refined overlap ratio
  double point_rms = 0.0;          ///< m, refined point-to-plane RMS of the inliers
  std::size_t inliers = 0;         ///< refined point inliers
  double fit_cost = 0.0;           ///< RefineResult::fit_cost
  /// Further evidence per candidate (name, value), e.g. free-space contradictions.
  std::vector<std::pair<std::string, double>> figures;
};

}  // namespace plumb
