#pragma once
// Beyond the papers (issue 13): the share of the source's structure (the points of its large
// planes: walls, floors, ceilings) that a refined placement explains. When a source fits
// nearly wholly in the target, the points no placement explains are mostly clutter (furniture,
// people, equipment) and the few percent of overall overlap that separate two placements can
// be chance: clutter of the source meeting clutter of the target. Structure cannot be
// explained by chance, so the candidate comparison (candidate_refinement.hpp) asks it to agree
// before a near-whole placement counts as clearly worse on the absolute overlap gap.
#include <vector>

#include "model/feature_set.hpp"
#include "model/point_cloud.hpp"
#include "registration/auto/candidate_refinement.hpp"
#include "registration/refine/icp_refinement.hpp"

namespace plumb {

/// The source points lying on planes of at least `min_area` m^2 (PlanarPolygon::inliers index
/// `source`); empty when there are none or fewer than `min_points`.
PointCloud structurePoints(const PointCloud& source, const std::vector<PlanarPolygon>& planes,
                           double min_area, std::size_t min_points = 100);

/// Sets RefineResult::structure_overlap of every hypothesis from index `first` on: the overlap of `structure` under
/// its refined transform, measured as the refinement measures its own overlap (same target,
/// same distances, no iteration; `viewpoint`: the source's scanner when its points carry no
/// sensor origins). Leaves it unmeasured (< 0) when `structure` is empty.
void measureStructureOverlap(const PointCloud& structure, const std::optional<Eigen::Vector3d>& viewpoint,
                             const RefineTarget& target,
                             const RefineParams& params, std::vector<RefinedHypothesis>& h,
                             std::size_t first = 0);

}  // namespace plumb
