// Dropped links judged by one loop alone (one_loop_drops.hpp).
#include "registration/network/one_loop_drops.hpp"

#include <algorithm>
#include <queue>
#include <set>

namespace plumb {
namespace {

/// Edge indices (into `edges`) of a path from `from` to `to` (breadth first); empty when none.
std::vector<std::size_t> pathBetween(std::size_t nodes, const std::vector<GraphEdge>& edges, std::size_t from,
                                     std::size_t to) {
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> adj(nodes);  // (neighbour, edge)
  for (std::size_t k = 0; k < edges.size(); ++k) {
    adj[edges[k].a].push_back({edges[k].b, k});
    adj[edges[k].b].push_back({edges[k].a, k});
  }
  std::vector<long> via(nodes, -1);
  std::vector<bool> seen(nodes, false);
  std::queue<std::size_t> q;
  q.push(from);
  seen[from] = true;
  while (!q.empty()) {
    const std::size_t n = q.front();
    q.pop();
    for (const auto& [m, k] : adj[n])
      if (!seen[m]) seen[m] = true, via[m] = long(k), q.push(m);
  }
  std::vector<std::size_t> path;
  for (std::size_t n = to; n != from && via[n] >= 0;) {
    const auto k = std::size_t(via[n]);
    path.push_back(k);
    n = edges[k].a == n ? edges[k].b : edges[k].a;
  }
  return seen[to] ? path : std::vector<std::size_t>{};
}

}  // namespace

std::vector<std::size_t> decidedByOneLoop(std::size_t stations, const std::vector<AdjustmentLink>& links,
                                          const NetworkAdjustment& adjustment, std::size_t reference) {
  std::vector<GraphEdge> kept;
  for (std::size_t k = 0; k < links.size(); ++k)
    if (!adjustment.links[k].dropped) kept.push_back({links[k].a, links[k].b, links[k].transform});
  const auto bridge = bridgeEdges(stations, kept);
  std::set<std::size_t> out;
  for (const std::size_t d : adjustment.dropped_order) {
    for (const std::size_t k : pathBetween(stations, kept, links[d].a, links[d].b)) {
      if (!bridge[k]) continue;
      // The side of the bridge without the reference.
      std::vector<GraphEdge> without = kept;
      without.erase(without.begin() + long(k));
      const auto part = connectedComponents(stations, without);
      for (std::size_t i = 0; i < stations; ++i)
        if (part[i] != part[reference]) out.insert(i);
    }
  }
  return {out.begin(), out.end()};
}

}  // namespace plumb
