#include "ui/network/link_decisions.hpp"

#include <algorithm>

namespace plumb::ui {

namespace {

bool samePair(StationPair p, StationPair q) {
  return (p.first == q.first && p.second == q.second) || (p.first == q.second && p.second == q.first);
}

bool contains(const std::vector<StationPair>& pairs, StationPair pair) {
  return std::any_of(pairs.begin(), pairs.end(), [&](StationPair p) { return samePair(p, pair); });
}

void erase(std::vector<StationPair>& pairs, StationPair pair) {
  std::erase_if(pairs, [&](StationPair p) { return samePair(p, pair); });
}

}  // namespace

LinkDecision decisionOf(const NetworkDecisions& d, StationPair pair) {
  if (contains(d.accepted, pair)) return LinkDecision::Accept;
  if (contains(d.rejected, pair)) return LinkDecision::Reject;
  return LinkDecision::None;
}

void setDecision(NetworkDecisions& d, StationPair pair, LinkDecision decision) {
  erase(d.accepted, pair);
  erase(d.rejected, pair);
  if (decision == LinkDecision::Accept) d.accepted.push_back(pair);
  if (decision == LinkDecision::Reject) d.rejected.push_back(pair);
}

void setStationLock(NetworkDecisions& d, std::size_t station, const std::optional<RigidTransform>& pose) {
  if (pose) d.locked[station] = *pose;
  else d.locked.erase(station);
}

}  // namespace plumb::ui
