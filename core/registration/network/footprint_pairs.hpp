#pragma once
// Pairs chosen by footprint overlap after a first placement (issue 15 "footprint overlap after a
// first placement"; docs/NETWORK.md "Candidate pairs", step 4).
//
// Layout and expansion pairs only ever join stations whose relative place is unknown; once links
// place a part of the network, the stations of that part that overlap on the ground are the
// neighbours a surveyor would link (a room's two stations, a room and its doorway). Registering
// those pairs closes loops inside the part, so a wrong link in it is contradicted by more than
// one path (docs/NETWORK.md "One loop cannot tell which link is wrong").
//
// Placement: each part of the accepted links is adjusted on its own (adjustNetwork, the part's
// first station held), so a link the robust loop drops does not place anything. Footprint: the
// plan cells (`footprint_cell`, 0.5 m) holding a station's points at its placed pose; two
// stations overlap by |A ∩ B| / min(|A|, |B|).
#include <cstdint>
#include <optional>
#include <set>
#include <unordered_set>
#include <utility>
#include <vector>

#include "registration/network/link.hpp"
#include "registration/network/pair_selection.hpp"
#include "registration/network/station.hpp"

namespace plumb {

/// The plan cells of a station's points at a pose (at most ~`max_points` points looked at).
struct Footprint {
  std::unordered_set<std::uint64_t> cells;
};
Footprint placedFootprint(const Station& station, const RigidTransform& pose, double cell,
                          std::size_t max_points = 50000);
/// |A ∩ B| / min(|A|, |B|); 0 when either is empty.
double footprintOverlap(const Footprint& a, const Footprint& b);

/// Each station's pose within its part of the accepted links (the part's first station at the
/// identity), adjusted robustly; nullopt for a station its part's adjustment does not place or
/// that is alone. `part[i]` is the part's index (placements of different parts are unrelated).
struct PartPlacements {
  std::vector<std::optional<RigidTransform>> poses;
  std::vector<std::size_t> part;
};
PartPlacements placeParts(const std::vector<Station>& stations, const std::vector<Link>& links,
                          const PoseGraphParams& params);

/// Untried pairs of scan stations placed in the same part whose footprints overlap by at least
/// params.footprint_overlap, largest overlap first, at most params.footprint_per_station per
/// station; reason "footprint", similarity = the overlap.
std::vector<CandidatePair> footprintPairs(const std::vector<Station>& stations, const PartPlacements& placed,
                                          const std::set<std::pair<std::size_t, std::size_t>>& tried,
                                          const PairSelectionParams& params);

}  // namespace plumb
