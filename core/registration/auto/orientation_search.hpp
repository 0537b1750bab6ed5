#pragma once
// The global step from any orientation of the source (issue 14, docs/ALGORITHMS.md §9). The
// registration methods search yaw only (both datasets Z-up); a source that is not levelled is
// levelled first:
//   - levelled: the global step as it is (Z up);
//   - y-up: turned by the quarter turn about X, then the levelled search;
//   - any: each up candidate of the source (principal directions of its plane normals, both
//     signs; up_direction.hpp) is turned onto +Z, the features that depend on the vertical
//     (façades and openings) are detected again on the levelled data, the levelled search
//     runs, and the levelling is composed into its hypotheses (T = T_levelled * L). The best
//     candidate answers; the best of every other up direction becomes a runner-up or further
//     hypothesis, so the refinement compares them on points (candidate_refinement.hpp), and
//     two up directions scoring about equally make the answer ambiguous;
//   - auto: levelled when an axis of the source lies within level-tolerance of Z; when that
//     levelled search finds nothing (a 90-degree tilt: a wall looks like a floor), the other up
//     candidates are tried as in `any`. Data that looks levelled and registers takes exactly
//     the levelled path, at its cost.
// Every result is in the source's own frame.
#include <vector>
#include <string>

#include "registration/auto/registration_pipeline.hpp"

namespace plumb {

GlobalRegistrationResult registerInAnyOrientation(const RegistrationSide& source,
                                                  const FeatureSet& source_features,
                                                  const FeatureSet& target_features,
                                                  bool target_is_model, const PipelineParams& params,
                                                  std::vector<std::string>* log, Progress* progress,
                                                  const SegmentsOnDemand& segments_on_demand);

}  // namespace plumb
