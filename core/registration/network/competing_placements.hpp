#pragma once
// Competing placements of a network (docs/NETWORK.md "Competing placements").
//
// The robust adjustment keeps the links that agree with its solution and drops the others. One
// wrong link among right ones is dropped and nothing else changes. But a building with
// identical rooms, or one symmetric under a half turn, gives wrong links that agree with each
// other (every triangle of them closes): two self-consistent sets of links, of which the
// adjustment adopts one. Agreement cannot tell which, so the result must not claim it knows.
//
// For each dropped link, the network is solved again with that link taken as true
// (adjustNetwork's `forced`). That alternative *competes* with the adopted solution when
//  - a loop of its kept links checks the forced link (it is not a bridge there): the
//    alternative is corroborated, not one lone link forced through; and
//  - the adopted solution does not win outright: it does not give up fewer links to the BIM
//    (a station placed in the whole building and checked against its copies there: of 29
//    stations of office-floor registered onto its model, 14 usable, all right, and 15
//    ambiguous), nor as many and fewer sequence links (the shot order, evidence identical
//    rooms cannot fake, though it can be wrong where the walk crosses a symmetric corridor).
// Stations a competing alternative places differently from the adopted solution (by more than
// the drop thresholds) are *ambiguous*: reported with both placements, and not placed.
#include <cstddef>
#include <vector>

#include "registration/network/robust_adjustment.hpp"

namespace plumb {

struct CompetingPlacement {
  std::size_t link = 0;          ///< the dropped link taken as true (index into the adjusted links)
  bool corroborated = false;     ///< a loop of the alternative's kept links checks it
  std::size_t dropped = 0;       ///< links the alternative drops ...
  std::size_t dropped_sequence = 0;  ///< ... of which sequence links
  std::size_t dropped_anchors = 0;   ///< ... of which links to the BIM
  bool competes = false;         ///< corroborated, moves stations, and not dominated by the adopted solution
  std::vector<std::size_t> stations;  ///< placed differently from the adopted solution
  double max_translation = 0.0;       ///< m, largest station position difference
  double max_rotation_deg = 0.0;      ///< deg, largest station rotation difference
  std::vector<std::optional<RigidTransform>> poses;  ///< every station as the alternative places it
};

struct CompetingPlacements {
  std::vector<CompetingPlacement> alternatives;  ///< one per dropped link, in the order dropped
  std::vector<std::size_t> ambiguous;            ///< stations of competing alternatives, sorted
};

/// `adopted` is adjustNetwork(stations, links, reference, reference_pose, params).
CompetingPlacements findCompetingPlacements(std::size_t stations, const std::vector<AdjustmentLink>& links,
                                            std::size_t reference, const RigidTransform& reference_pose,
                                            const PoseGraphParams& params, const NetworkAdjustment& adopted);

}  // namespace plumb
