#pragma once
// The optional final refinement on points (issue 15, docs/NETWORK.md "Final refinement on
// points"): once the network is adjusted, every pair of placed scan stations whose points
// overlap at their adjusted poses is refined on its points (point-to-plane ICP, surfaces both
// stations see, starting from the adjusted relative pose), whether or not the pair was
// registered as a link; the refined pairs join the links and the network is adjusted once
// more. The adjustment then rests on every overlap the campaign has, not only the pairs the
// selection chose, each weighted by its own fit (weighLink).
#include <vector>

#include "registration/network/link.hpp"
#include "registration/network/robust_adjustment.hpp"

namespace plumb {

/// Link::reason (and method) of a refined pair: the report tells them from registered pairs.
inline constexpr const char* kFinalRefinementReason = "final refinement";

struct FinalRefinementSummary {
  bool done = false;
  std::size_t pairs_tried = 0;  ///< placed scan-station pairs whose boxes overlap
  std::size_t pairs_used = 0;   ///< refined with enough overlap: links of the last adjustment
  double seconds = 0.0;
};

/// Links from refining each overlapping pair of placed scan stations at `poses` (station ->
/// registered frame; nullopt: not placed; `skip`: stations left out, e.g. ambiguous), reason
/// "final refinement", usable and weighted; pairs matched below params.min_overlap, and pairs
/// whose link in `links` the surveyor rejected, are left out.
std::vector<Link> refinedPairLinks(const std::vector<Station>& stations,
                                   const std::vector<std::optional<RigidTransform>>& poses,
                                   const std::vector<std::size_t>& skip, const std::vector<Link>& links,
                                   const NetworkParams& params, FinalRefinementSummary& summary);

/// `links` and the `refined` pairs beside them (earlier refined links removed: a re-run refines
/// again). The registered links stay: measured on four campaigns, keeping them beside the
/// refined pairs gave smaller errors than replacing them (docs/NETWORK.md).
std::vector<Link> withRefinedPairs(const std::vector<Link>& links, const std::vector<Link>& refined);

}  // namespace plumb
