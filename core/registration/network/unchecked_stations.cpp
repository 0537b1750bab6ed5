#include "registration/network/unchecked_stations.hpp"

#include <algorithm>

#include "registration/network/network_registration.hpp"
#include "registration/network/robust_adjustment.hpp"

namespace plumb {

namespace {

bool contains(const std::vector<std::size_t>& sorted, std::size_t i) {
  return std::binary_search(sorted.begin(), sorted.end(), i);
}

/// Per station: kept links, whether its last kept link is a bridge, whether any kept link was
/// decided on (Link::decision).
struct KeptLinks {
  std::vector<int> count;
  std::vector<bool> bridge, decided;
};

KeptLinks keptLinks(std::size_t n, const NetworkResult& r) {
  KeptLinks k{std::vector<int>(n, 0), std::vector<bool>(n, false), std::vector<bool>(n, false)};
  for (std::size_t e = 0; e < r.adjusted.size(); ++e) {
    const Link& l = r.links[r.adjusted[e]];
    const LinkOutcome& o = r.adjustment.links[e];
    if (o.dropped) continue;
    for (const std::size_t s : {l.a, l.b}) {
      ++k.count[s];
      k.bridge[s] = o.bridge;
      if (!l.decision.empty()) k.decided[s] = true;
    }
  }
  return k;
}

/// Placed by something besides its links: locked, or by the control points.
bool placedOtherwise(const NetworkResult& r, std::size_t i) {
  if (contains(r.locked, i) || contains(r.placed_by_own_control, i)) return true;
  return r.georeference && r.georeference->done && contains(r.georeference->settled, i);
}

/// The link's placements of b in a's frame (b's frame -> a's frame): the chosen one, then the
/// competing ones.
std::vector<RigidTransform> linkPlacements(const Link& l) {
  std::vector<RigidTransform> out{l.transform};
  for (const auto& alt : l.alternatives)
    if (alt.role == "competing") out.push_back(alt.transform);
  return out;
}

}  // namespace

std::vector<std::size_t> uncheckedStations(const std::vector<Station>& stations, const NetworkResult& r) {
  const KeptLinks kept = keptLinks(stations.size(), r);
  const auto ambiguous = r.ambiguous();
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < stations.size(); ++i) {
    if (i == r.reference || stations[i].is_model || stations[i].mms_pass >= 0 || !r.adjustment.poses[i]) continue;
    if (kept.count[i] != 1 || !kept.bridge[i] || kept.decided[i]) continue;
    if (contains(ambiguous, i) || placedOtherwise(r, i)) continue;
    out.push_back(i);
  }
  return out;
}

std::vector<PlacementHypothesis> uncheckedLinkHypotheses(const std::vector<Station>& stations,
                                                         const NetworkResult& r,
                                                         const std::vector<std::size_t>& unchecked,
                                                         const PoseGraphParams& graph) {
  const auto& poses = r.adjustment.poses;
  const auto ambiguous = r.ambiguous();
  std::vector<PlacementHypothesis> out;
  const auto offered = [&](std::size_t i, const RigidTransform& pose) {
    if (samePlacement(pose, *poses[i], graph)) return true;
    return std::any_of(out.begin(), out.end(),
                       [&](const PlacementHypothesis& h) { return h.moved[0] == i && samePlacement(*h.poses[i], pose, graph); });
  };
  for (std::size_t k = 0; k < r.links.size(); ++k) {
    const Link& l = r.links[k];
    if (l.accepted || l.status != "ambiguous" || stations[l.a].is_model || stations[l.b].is_model) continue;
    const auto placements = linkPlacements(l);
    for (const bool judged_is_a : {true, false}) {
      const std::size_t i = judged_is_a ? l.a : l.b, j = judged_is_a ? l.b : l.a;
      if (!contains(unchecked, i) || !poses[j] || contains(ambiguous, j)) continue;
      for (std::size_t c = 0; c < placements.size(); ++c) {
        // pose_b = pose_a * T (T: b's frame -> a's frame)
        const RigidTransform pose = judged_is_a ? *poses[j] * placements[c].inverse() : *poses[j] * placements[c];
        if (offered(i, pose)) continue;
        PlacementHypothesis h{"the link " + stations[l.a].name + " - " + stations[l.b].name + " at its placement " +
                                  std::to_string(c + 1),
                              poses, {i}, k, std::nullopt, placements[c]};
        h.poses[i] = pose;
        out.push_back(std::move(h));
      }
    }
  }
  return out;
}

std::vector<std::size_t> contestedStations(const FreeSpaceJudgement& judged, const std::vector<std::size_t>& unchecked,
                                           const PoseGraphParams& graph) {
  std::vector<std::size_t> out;
  for (const auto& s : judged.stations) {
    if (!contains(unchecked, s.station) || s.decided) continue;
    const JudgedPlacement& adopted = s.placements.front();
    bool contested = adopted.judged && !adopted.clean;
    for (std::size_t k = 1; k < s.placements.size(); ++k)
      if (s.placements[k].clean && !samePlacement(s.placements[k].pose, adopted.pose, graph)) contested = true;
    if (contested) out.push_back(s.station);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace plumb
