#pragma once
// Beyond the papers (issue 13, symmetry): the best placement of the source away from the one
// chosen. A repeated room, a second identical storey or the other unit of a mirrored building
// can score below unrelated hypotheses in the global search (a stair seen through a door, a
// modelling difference) and so never be refined and compared. Here the target features that
// the chosen placement covers are set aside and the global search runs again on the rest: its
// answer is the best competitor elsewhere, refined and compared like the runner-up
// (candidate_refinement.hpp), and judged by the free space when it fits about as well. It
// examines more translation peaks than the first search (CandidateParams::elsewhere_peak_factor).
#include <optional>

#include "model/feature_set.hpp"
#include "model/point_cloud.hpp"
#include "registration/common/registration_result.hpp"

namespace plumb {

struct PipelineParams;

/// The target's features whose anchor (plane centroid, opening centre, segment midpoint) lies
/// outside `source_box` placed by `chosen` and grown by `margin` (m).
FeatureSet featuresOutside(const FeatureSet& target, const Bounds& source_box,
                           const RigidTransform& chosen, double margin);

/// True when the target's feature box holds at least `min_volume_ratio` times the source's
/// (room for another copy of the source).
bool roomForAnotherCopy(const Bounds& source_box, const Bounds& target_box,
                        double min_volume_ratio);

/// The global search's best hypothesis on the target features outside the chosen placement
/// (std::nullopt when there is no room for another copy, or nothing was found there scoring
/// at least CandidateParams::alternative_min_score times `chosen_score`).
std::optional<Hypothesis> searchElsewhere(const FeatureSet& source, const FeatureSet& target,
                                          const RigidTransform& chosen, double chosen_score,
                                          bool target_is_model, const PipelineParams& params);

}  // namespace plumb
