#pragma once
// Internal to the planes registration: the steps that build a translation for a rotation
// (2021 §4, eqs. 21-22, see plane_registration.hpp), apart so that each can be tested alone.
#include <Eigen/Core>

#include <optional>
#include <vector>

#include "registration/clustering/direction_clustering.hpp"
#include "registration/common/rotation_from_directions.hpp"

namespace plumb::planes_registration_detail {

/// Three cluster associations of a rotation whose directions determine a translation.
struct Associations {
  std::vector<int> clusters;                ///< source cluster indices, at most 3
  std::vector<Eigen::Vector3d> directions;  ///< their directions rotated by the rotation
};

/// The heaviest matched source cluster, the heaviest one at least 30° from it, and the
/// heaviest one at least 30° out of their plane (fewer when there are none).
Associations independentAssociations(const DirectionClusteringResult& source_clusters,
                                     const RotationCandidate& rotation);

/// Eq. 22: the translation t solving N t = rhs (one eq. 21 row per plane pair), or nothing
/// when N is ill-conditioned (smallest singular value below `min_conditioning` times the
/// largest).
std::optional<Eigen::Vector3d> solveTranslation(const Eigen::Matrix3d& N, const Eigen::Vector3d& rhs,
                                                double min_conditioning);

}  // namespace plumb::planes_registration_detail
