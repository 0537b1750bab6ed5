#pragma once
// Stations one unchecked link places, judged by the free space too (docs/NETWORK.md "A station
// one unchecked link places").
//
// A station whose only kept link is a bridge is placed by that one registration: no loop checks
// it. Its verdict may be "usable" and still wrong: in a building of identical rooms, the BIM
// fits a scan of one room into the twin of that room as well as into its own, and when the copy
// search compares only some of the copies, nothing says so (big-office, seed 1, session 22: a
// station placed 180 deg wrong by a usable link to the BIM, its links to its neighbours all
// ambiguous). Such a station is not confirmed: it does not observe for the free-space judge,
// and the judge tests it like an ambiguous one, against every placement its other links and the
// BIM offered:
//  - its registered links the adjustment could not use because they were ambiguous: each of
//    their placements (the chosen one and the competing ones), from the neighbour's pose;
//  - the other copies the BIM fitted it in, when its link to the BIM is the bridge.
// Settled (its placement clean and refuting the others): a confirmed station. Decided
// elsewhere: the link or copy chosen is taken as true and the network adjusted again. Neither,
// and the free space contests the placement (the placement lies in the confirmed stations'
// free space, or another placement is clean): ambiguous, not placed. Otherwise it stays placed
// as before, unconfirmed.
#include <cstddef>
#include <vector>

#include "registration/network/free_space_judge.hpp"
#include "registration/network/network_params.hpp"
#include "registration/network/station.hpp"

namespace plumb {

struct NetworkResult;

/// Placed scan stations (not the reference, the model or an MMS window) whose only kept link is
/// a bridge nobody decided on (neither the surveyor nor the free space), and which nothing else
/// places: not ambiguous, locked, placed or settled by control points. Sorted.
std::vector<std::size_t> uncheckedStations(const std::vector<Station>& stations, const NetworkResult& result);

/// The placements of the `unchecked` stations (sorted) their ambiguous links offer: each
/// placement of the link (its chosen transform and every competing one) from the neighbour's
/// adopted pose, the neighbour placed and not ambiguous. Placements within the drop thresholds
/// of the adopted one or of an earlier one are left out. PlacementHypothesis::link_transform is
/// the link's transform under the hypothesis.
std::vector<PlacementHypothesis> uncheckedLinkHypotheses(const std::vector<Station>& stations,
                                                         const NetworkResult& result,
                                                         const std::vector<std::size_t>& unchecked,
                                                         const PoseGraphParams& graph);

/// The `unchecked` stations (sorted) the judge neither settled nor decided and whose placement
/// the free space contests: its adopted placement seen and not clean, or another placement clean.
/// Sorted.
std::vector<std::size_t> contestedStations(const FreeSpaceJudgement& judged, const std::vector<std::size_t>& unchecked,
                                           const PoseGraphParams& graph);

}  // namespace plumb
