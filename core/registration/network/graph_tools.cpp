#include "registration/network/graph_tools.hpp"

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <iterator>
#include <functional>
#include <map>

namespace plumb {
namespace {

/// Boost's disjoint sets; join() says whether a and b were apart.
struct DisjointSets {
  boost::disjoint_sets_with_storage<> sets;
  explicit DisjointSets(std::size_t n) : sets(n) {}
  std::size_t find(std::size_t x) { return sets.find_set(x); }
  bool join(std::size_t a, std::size_t b) {
    if (find(a) == find(b)) return false;
    sets.union_set(a, b);
    return true;
  }
};

/// Neighbour lists of the tree: (node, edge index).
using TreeAdjacency = std::vector<std::vector<std::pair<std::size_t, std::size_t>>>;
TreeAdjacency treeAdjacency(
    std::size_t nodes, const std::vector<GraphEdge>& edges, const std::vector<std::size_t>& tree) {
  TreeAdjacency adj(nodes);
  for (std::size_t k : tree) {
    adj[edges[k].a].push_back({edges[k].b, k});
    adj[edges[k].b].push_back({edges[k].a, k});
  }
  return adj;
}

/// The transform mapping `to`'s frame into `from`'s frame along edge k.
RigidTransform step(const GraphEdge& e, std::size_t from) {
  return e.a == from ? e.transform : e.transform.inverse();
}

}  // namespace

std::vector<std::size_t> connectedComponents(std::size_t nodes, const std::vector<GraphEdge>& edges) {
  DisjointSets sets(nodes);
  for (const auto& e : edges) sets.join(e.a, e.b);
  std::vector<std::size_t> root(nodes), out(nodes);
  std::map<std::size_t, std::size_t> number;
  for (std::size_t i = 0; i < nodes; ++i) {
    const std::size_t r = sets.find(i);
    if (!number.count(r)) number[r] = number.size();
    out[i] = number[r];
  }
  return out;
}

std::vector<std::size_t> spanningTree(std::size_t nodes, const std::vector<GraphEdge>& edges,
                                      const std::vector<std::size_t>& order) {
  DisjointSets sets(nodes);
  std::vector<std::size_t> tree;
  for (std::size_t k : order)
    if (sets.join(edges[k].a, edges[k].b)) tree.push_back(k);
  return tree;
}

std::vector<std::optional<RigidTransform>> chainPoses(std::size_t nodes, const std::vector<GraphEdge>& edges,
                                                      const std::vector<std::size_t>& tree, std::size_t reference,
                                                      const RigidTransform& reference_pose) {
  const auto adj = treeAdjacency(nodes, edges, tree);
  std::vector<std::optional<RigidTransform>> pose(nodes);
  pose[reference] = reference_pose;
  std::vector<std::size_t> stack{reference};
  while (!stack.empty()) {
    const std::size_t u = stack.back();
    stack.pop_back();
    for (const auto& [v, k] : adj[u])
      if (!pose[v]) {
        pose[v] = *pose[u] * step(edges[k], u);
        stack.push_back(v);
      }
  }
  return pose;
}

namespace {

/// The tree path from `from` to `to` (both included); empty when the tree does not join them.
std::vector<std::size_t> treePath(std::size_t nodes, const TreeAdjacency& adj, std::size_t from, std::size_t to) {
  std::vector<std::optional<std::size_t>> parent(nodes);
  parent[from] = from;
  std::vector<std::size_t> stack{from};
  while (!stack.empty()) {
    const std::size_t u = stack.back();
    stack.pop_back();
    for (const auto& [v, e] : adj[u])
      if (!parent[v]) parent[v] = u, stack.push_back(v);
  }
  if (!parent[to]) return {};
  std::vector<std::size_t> path{to};
  while (path.back() != from) path.push_back(*parent[path.back()]);
  std::reverse(path.begin(), path.end());
  return path;
}

/// The transform mapping the frame of path.back() into the frame of path.front() along the tree.
RigidTransform alongPath(const std::vector<GraphEdge>& edges, const TreeAdjacency& adj,
                         const std::vector<std::size_t>& path) {
  RigidTransform around;
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    for (const auto& [v, e] : adj[path[i]])
      if (v == path[i + 1]) {
        around = around * step(edges[e], path[i]);
        break;
      }
  return around;
}

}  // namespace

std::vector<LoopClosure> loopClosures(std::size_t nodes, const std::vector<GraphEdge>& edges,
                                      const std::vector<std::size_t>& tree) {
  const auto adj = treeAdjacency(nodes, edges, tree);
  std::vector<bool> in_tree(edges.size(), false);
  for (std::size_t k : tree) in_tree[k] = true;
  std::vector<LoopClosure> loops;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    if (in_tree[k]) continue;
    LoopClosure loop;
    loop.edge = k;
    loop.nodes = treePath(nodes, adj, edges[k].a, edges[k].b);
    if (loop.nodes.empty()) continue;
    const RigidTransform mis = edges[k].transform.inverse() * alongPath(edges, adj, loop.nodes);
    loop.translation = mis.translation().norm();
    loop.rotation_deg = mis.rotationAngleDeg();
    loops.push_back(std::move(loop));
  }
  return loops;
}

std::vector<bool> bridgeEdges(std::size_t nodes, const std::vector<GraphEdge>& edges) {
  std::vector<bool> bridge(edges.size(), false);
  for (std::size_t k = 0; k < edges.size(); ++k) {
    std::vector<GraphEdge> others = edges;
    others.erase(others.begin() + static_cast<long>(k));
    const auto component = connectedComponents(nodes, others);
    bridge[k] = component[edges[k].a] != component[edges[k].b];
  }
  return bridge;
}

std::vector<TriangleSupport> triangleSupport(std::size_t nodes, const std::vector<GraphEdge>& edges,
                                             double tolerance_m, double tolerance_deg) {
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> index;
  for (std::size_t k = 0; k < edges.size(); ++k) index[{edges[k].a, edges[k].b}] = k;
  // c's frame -> x's frame through the edge between x and c, if any.
  auto between = [&](std::size_t x, std::size_t c) -> std::optional<std::pair<std::size_t, RigidTransform>> {
    if (auto it = index.find({x, c}); it != index.end()) return std::make_pair(it->second, edges[it->second].transform);
    if (auto it = index.find({c, x}); it != index.end())
      return std::make_pair(it->second, edges[it->second].transform.inverse());
    return std::nullopt;
  };
  std::vector<TriangleSupport> support(edges.size());
  for (std::size_t k = 0; k < edges.size(); ++k)
    for (std::size_t c = 0; c < nodes; ++c) {
      if (c == edges[k].a || c == edges[k].b) continue;
      const auto ac = between(edges[k].a, c), cb = between(c, edges[k].b);
      if (!ac || !cb) continue;
      const RigidTransform mis = edges[k].transform.inverse() * ac->second * cb->second;
      const bool closes = mis.translation().norm() <= tolerance_m && mis.rotationAngleDeg() <= tolerance_deg;
      (closes ? support[k].closing : support[k].failing) += 1;
    }
  return support;
}

void sortedUnion(std::vector<std::size_t>& into, const std::vector<std::size_t>& more) {
  std::vector<std::size_t> out;
  std::set_union(into.begin(), into.end(), more.begin(), more.end(), std::back_inserter(out));
  into = std::move(out);
}

}  // namespace plumb
