#pragma once
// The surveyor's decisions on a network (NetworkDecisions): a link accepted or rejected by its
// station pair, a station locked at its adjusted pose. Kept by pair, not by link index, so they
// hold across re-runs (adjustRegisteredLinks keeps the links' order, but a pair is what the
// core's decisions name).
#include <optional>

#include "registration/network/network_registration.hpp"

namespace plumb::ui {

enum class LinkDecision { None, Accept, Reject };

using StationPair = std::pair<std::size_t, std::size_t>;

LinkDecision decisionOf(const NetworkDecisions& d, StationPair pair);
/// Sets the pair's decision (removing any other one for it).
void setDecision(NetworkDecisions& d, StationPair pair, LinkDecision decision);
/// Locks station i at `pose` (station -> registered frame), or unlocks it (nullopt).
void setStationLock(NetworkDecisions& d, std::size_t station, const std::optional<RigidTransform>& pose);

}  // namespace plumb::ui
