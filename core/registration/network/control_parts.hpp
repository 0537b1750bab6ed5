#pragma once
// Parts of a network placed by their own control points (issue 15 "control seen only by
// unplaced parts"; docs/NETWORK.md "Parts placed by their own control").
//
// Links may leave a campaign in several parts: a corridor nobody scanned, a link that failed.
// Without control, only the reference's part is placed; the others are reported, never forced.
// With control points, a part that sees 3 of them (not in a line) is placed by them, in the same
// grid as the rest, exactly as a surveyor georeferences each block on its own targets: each such
// part is adjusted on its own links (its first station held, wrong links dropped, competing
// placements and one-loop drops checked as for the whole network), then georeferenced on its
// control points. Parts that see fewer stay unplaced.
#include <vector>

#include "registration/network/network_registration.hpp"

namespace plumb {

/// When `out.georeference` is done: each part of the stations `out.adjustment` left unplaced
/// (joined by the accepted `links` among themselves) is adjusted and georeferenced on its own;
/// the parts georeferenced are merged into `out` (poses, sigmas, link outcomes, loops, drops,
/// competing and one-loop stations, point residuals; out.placed_by_own_control). `links` are
/// those given to the network's adjustment (indices into out.adjusted).
void placePartsByOwnControl(const std::vector<Station>& stations, const std::vector<AdjustmentLink>& links,
                            const NetworkParams& params, const ControlSurvey& control, NetworkResult& out);

}  // namespace plumb
