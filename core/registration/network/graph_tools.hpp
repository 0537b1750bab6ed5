#pragma once
// Graph bookkeeping of a station network (no geometry solver): connected parts, a spanning tree
// chosen in a given order (Kruskal), the poses a tree gives by chaining its links from the
// reference, and the loops each non-tree link closes with the tree (loop-closure errors).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "model/rigid_transform.hpp"

namespace plumb {

struct GraphEdge {
  std::size_t a = 0, b = 0;
  RigidTransform transform;  ///< b's frame -> a's frame
};

/// Component index of every node (0 .. count-1, numbered by lowest node).
std::vector<std::size_t> connectedComponents(std::size_t nodes, const std::vector<GraphEdge>& edges);

/// A spanning forest: edges taken in `order` (indices into edges) when they join two parts.
/// Returns the indices of the chosen edges.
std::vector<std::size_t> spanningTree(std::size_t nodes, const std::vector<GraphEdge>& edges,
                                      const std::vector<std::size_t>& order);

/// Poses (node frame -> reference frame) chained along the tree edges from `reference`, whose
/// pose is `reference_pose`; nodes the tree does not reach stay empty.
std::vector<std::optional<RigidTransform>> chainPoses(std::size_t nodes, const std::vector<GraphEdge>& edges,
                                                      const std::vector<std::size_t>& tree, std::size_t reference,
                                                      const RigidTransform& reference_pose);

struct LoopClosure {
  std::size_t edge = 0;            ///< the non-tree edge closing the loop
  std::vector<std::size_t> nodes;  ///< the loop, from a to b along the tree
  double translation = 0.0;        ///< misclosure of the links around the loop, m
  double rotation_deg = 0.0;
};

/// The loop each non-tree edge closes with the tree, and its misclosure: the composition of
/// the measured links around the loop, which is the identity for consistent links.
std::vector<LoopClosure> loopClosures(std::size_t nodes, const std::vector<GraphEdge>& edges,
                                      const std::vector<std::size_t>& tree);

/// For each edge, whether it is a bridge: the only connection between two parts of the graph.
/// A bridge has no redundancy, so no adjustment can check it.
std::vector<bool> bridgeEdges(std::size_t nodes, const std::vector<GraphEdge>& edges);

/// For each edge, how many triangles (a, b, c) with both other edges present close within
/// `tolerance_m` / `tolerance_deg` (closing) and how many do not (failing).
struct TriangleSupport {
  int closing = 0, failing = 0;
};
std::vector<TriangleSupport> triangleSupport(std::size_t nodes, const std::vector<GraphEdge>& edges,
                                             double tolerance_m, double tolerance_deg);

/// `into` (sorted station indices) becomes its union with `more` (sorted).
void sortedUnion(std::vector<std::size_t>& into, const std::vector<std::size_t>& more);

}  // namespace plumb
