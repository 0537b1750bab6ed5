#pragma once
// Structural explanation (issue 13, beyond the papers): does the other side explain the
// tested side's large planar structure (walls, floors, ceilings) under a transform? The
// free-space test (visibility_evidence.hpp) says, per tested point, whether the observer saw
// it on its surface, saw through it, or could not tell. Pooled over every point, a wrong
// building's misplaced wall drowns among the points it shares with the right-sized rooms it
// was put onto (contradiction ratios 0.02 - 0.04, as low as a right pair's moved objects).
// Per plane, it stands out: a wall lying in the space the other scanners saw through is
// unexplained as a whole, while a right pair's contradictions (people, moved furniture, glass)
// are scattered over many planes or lie off the large ones.
#include <cstddef>
#include <vector>

#include "model/feature_set.hpp"
#include "quality/station_range_images.hpp"
#include "quality/visibility_evidence.hpp"

namespace plumb {

/// What the observer said about each tested point: the point's index in the tested cloud and
/// its sighting (freeSpaceEvidence, modelRayEvidence fill it when asked).
struct TestedSightings {
  std::vector<std::size_t> index;
  std::vector<Sighting> sighting;
  /// Scan to model: Occluded means "measured in front of every model surface" (the model is
  /// empty where the scan saw a surface; modelRayEvidence turns points lying on a
  /// non-structural surface, such as a ceiling covering, into Consistent), which leaves a
  /// point unexplained; scan to scan it means "behind the observer's surface" (no evidence).
  bool occluded_unexplained = false;
};

/// Per-plane tally of `sightings` over the planes of `planes` (tested cloud of `cloud_size`
/// points; PlanarPolygon::inliers index it) of at least params.structure_min_area.
StructureEvidence structureEvidence(const std::vector<PlanarPolygon>& planes,
                                    std::size_t cloud_size, const TestedSightings& sightings,
                                    const VisibilityParams& params);

}  // namespace plumb
