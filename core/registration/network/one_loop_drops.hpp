#pragma once
// A dropped link judged by one loop alone (docs/NETWORK.md "One loop cannot tell which link is
// wrong"). The robust adjustment drops the link that disagrees most with the others; when the
// only other path between its stations crosses a bridge of the kept links, the dropped link and
// that path form a single loop, and a single loop's misclosure says that one of its links is
// wrong, not which: the adjustment spreads the misclosure by the links' sigmas and may drop a
// right link, keeping the wrong one as a bridge nothing checks. The stations beyond such a
// bridge (away from the reference) are placed by a choice the data cannot make: ambiguous.
#include <vector>

#include "registration/network/robust_adjustment.hpp"

namespace plumb {

/// Stations (sorted) beyond a bridge of the kept links on the path between the stations of a
/// dropped link, seen from `reference`.
std::vector<std::size_t> decidedByOneLoop(std::size_t stations, const std::vector<AdjustmentLink>& links,
                                          const NetworkAdjustment& adjustment, std::size_t reference);

}  // namespace plumb
