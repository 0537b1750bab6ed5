#pragma once
// Translation proposals for a fixed rotation from segment pairs (2023 §IV-C/D): a pair
// (s_i in a source cluster, s_j in the associated target cluster) is satisfied by every t on a
// line parallel to s_j (point-to-line distance of eq. 11 equal to zero), restricted to the
// shifts where the two segments overlap by at least half the shorter one. Each pair votes
// along its line in a 3D grid; a double pair from two associations meets where eq. 14 puts
// it, so grid maxima are translations on which many double pairs agree.
#include <Eigen/Core>

#include <vector>

#include "model/feature_set.hpp"
#include "registration/clustering/direction_clustering.hpp"
#include "registration/common/rotation_from_directions.hpp"

namespace plumb {

/// Up to `max_peaks` translations (cell centres of local maxima, best first).
std::vector<Eigen::Vector3d> voteTranslations(const std::vector<Segment3D>& source,
                                              const DirectionClusteringResult& source_clusters,
                                              const std::vector<Segment3D>& target,
                                              const DirectionClusteringResult& target_clusters,
                                              const RotationCandidate& rotation, double cell,
                                              int max_peaks);

}  // namespace plumb
