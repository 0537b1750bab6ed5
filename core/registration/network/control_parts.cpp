#include "registration/network/control_parts.hpp"

#include <set>

namespace plumb {
namespace {

/// The links whose stations both lie in `part`, and each one's index in the network's links.
struct PartLinks {
  std::vector<AdjustmentLink> links;
  std::vector<std::size_t> index;
};

PartLinks linksWithin(const std::vector<AdjustmentLink>& links, const std::vector<std::size_t>& component,
                      std::size_t part) {
  PartLinks out;
  for (std::size_t k = 0; k < links.size(); ++k)
    if (component[links[k].a] == part && component[links[k].b] == part) {
      out.links.push_back(links[k]);
      out.index.push_back(k);
    }
  return out;
}

/// Parts of the stations `placed` leaves out, joined by the links among them (placed stations
/// and the model each end up alone).
std::vector<std::size_t> unplacedParts(const std::vector<Station>& stations, const std::vector<AdjustmentLink>& links,
                                       const std::vector<std::optional<RigidTransform>>& placed) {
  std::vector<GraphEdge> edges;
  for (const auto& l : links)
    if (!placed[l.a] && !placed[l.b] && !stations[l.a].is_model && !stations[l.b].is_model)
      edges.push_back({l.a, l.b, l.transform});
  return connectedComponents(stations.size(), edges);
}

/// The part's adjustment `a` (georeferenced) and its checks merged into the network's.
void mergePart(const PartLinks& part, const NetworkAdjustment& a, const CompetingPlacements& competing,
               const std::vector<std::size_t>& one_loop, NetworkResult& out) {
  NetworkAdjustment& m = out.adjustment;
  std::vector<std::size_t> placed;
  for (std::size_t i = 0; i < a.poses.size(); ++i) {
    if (!a.poses[i]) continue;
    m.poses[i] = a.poses[i];
    m.sigma_position[i] = a.sigma_position[i];
    m.sigma_rotation_deg[i] = a.sigma_rotation_deg[i];
    if (i < m.chain_poses.size() && i < a.chain_poses.size()) m.chain_poses[i] = a.chain_poses[i];
    placed.push_back(i);
  }
  sortedUnion(out.placed_by_own_control, placed);
  for (std::size_t j = 0; j < part.links.size(); ++j) m.links[part.index[j]] = a.links[j];
  for (LoopClosure loop : a.loops) {
    loop.edge = part.index[loop.edge];
    m.loops.push_back(std::move(loop));
  }
  for (const std::size_t j : a.dropped_order) m.dropped_order.push_back(part.index[j]);
  for (CompetingPlacement alt : competing.alternatives) {
    alt.link = part.index[alt.link];
    out.competing.alternatives.push_back(std::move(alt));
  }
  sortedUnion(out.competing.ambiguous, competing.ambiguous);
  sortedUnion(out.one_loop, one_loop);
}

}  // namespace

void placePartsByOwnControl(const std::vector<Station>& stations, const std::vector<AdjustmentLink>& links,
                            const NetworkParams& params, const ControlSurvey& control, NetworkResult& out) {
  if (!out.georeference || !out.georeference->done) return;
  const std::size_t n = stations.size();
  const auto component = unplacedParts(stations, links, out.adjustment.poses);
  std::set<std::size_t> seen;
  std::size_t parts = 0;
  for (std::size_t root = 0; root < n; ++root) {
    if (out.adjustment.poses[root] || stations[root].is_model || !seen.insert(component[root]).second) continue;
    const PartLinks part = linksWithin(links, component, component[root]);
    NetworkAdjustment a = adjustNetwork(n, part.links, root, RigidTransform{}, params.graph);
    const CompetingPlacements competing =
        params.graph.check_competing
            ? findCompetingPlacements(n, part.links, root, RigidTransform{}, params.graph, a)
            : CompetingPlacements{};
    std::vector<std::size_t> one_loop;  // decidedByOneLoop counts every station off the root's part as beyond
    for (const std::size_t i : decidedByOneLoop(n, part.links, a, root))
      if (component[i] == component[root]) one_loop.push_back(i);
    const Georeference g = georeferenceNetwork(control, stationNames(stations), part.links, params.graph, a);
    if (!g.done) continue;
    mergePart(part, a, competing, one_loop, out);
    mergeGeoreference(*out.georeference, g);
    ++parts;
  }
  if (parts)
    out.georeference->message += "; " + std::to_string(parts) + " part(s) the links leave apart placed by their own control points";
}

}  // namespace plumb
