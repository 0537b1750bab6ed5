// Graph bookkeeping: components, spanning tree, chained poses, loop closures, triangles.
#include <gtest/gtest.h>

#include "support/synthetic_network.hpp"

namespace plumb {
namespace {

std::vector<GraphEdge> edgesOf(const test::SyntheticNetwork& net) {
  std::vector<GraphEdge> e;
  for (const auto& l : net.links) e.push_back({l.a, l.b, l.transform});
  return e;
}

TEST(GraphTools, ComponentsSplitWhereNoLinkJoins) {
  const std::vector<GraphEdge> e{{0, 1, {}}, {1, 2, {}}, {3, 4, {}}};
  const auto c = connectedComponents(6, e);
  EXPECT_EQ(c[0], c[2]);
  EXPECT_NE(c[0], c[3]);
  EXPECT_EQ(c[3], c[4]);
  EXPECT_NE(c[5], c[0]);
  EXPECT_NE(c[5], c[3]);
}

TEST(GraphTools, BridgesAreTheLinksNoLoopChecks) {
  // A triangle 0-1-2 with a tail 2-3: only 2-3 is a bridge.
  const std::vector<GraphEdge> e{{0, 1, {}}, {1, 2, {}}, {2, 0, {}}, {2, 3, {}}};
  const auto b = bridgeEdges(4, e);
  EXPECT_FALSE(b[0]);
  EXPECT_FALSE(b[1]);
  EXPECT_FALSE(b[2]);
  EXPECT_TRUE(b[3]);
}

TEST(GraphTools, ExactLinksChainToTheTruthAndCloseEveryLoop) {
  const auto net = test::ringNetwork(10, 8.0, 3, 0.0, 0.0, 2, false);
  const auto e = edgesOf(net);
  std::vector<std::size_t> order(e.size());
  for (std::size_t k = 0; k < e.size(); ++k) order[k] = e.size() - 1 - k;
  const auto tree = spanningTree(10, e, order);
  EXPECT_EQ(tree.size(), 9u);
  const auto poses = chainPoses(10, e, tree, 0, net.truth[0]);
  EXPECT_LT(test::maxPositionError(poses, net.truth), 1e-9);
  const auto loops = loopClosures(10, e, tree);
  EXPECT_EQ(loops.size(), e.size() - tree.size());
  for (const auto& l : loops) {
    EXPECT_LT(l.translation, 1e-9);
    EXPECT_GE(l.nodes.size(), 2u);
  }
}

TEST(GraphTools, WrongLinkOpensItsLoopsAndFailsItsTriangles) {
  auto net = test::ringNetwork(8, 6.0, 2, 0.0, 0.0, 4, false);
  net.links[0].transform = RigidTransform::fromYaw(0.0, {1.0, 0, 0}) * net.links[0].transform;  // 0 -> 1 off by 1 m
  const auto e = edgesOf(net);
  const auto support = triangleSupport(8, e, 0.01, 0.1);
  EXPECT_GE(support[0].failing, 1);
  EXPECT_EQ(support[0].closing, 0);
  std::vector<std::size_t> order(e.size());
  for (std::size_t k = 0; k < e.size(); ++k) order[k] = k;
  const auto loops = loopClosures(8, e, spanningTree(8, e, order));
  double worst = 0;
  for (const auto& l : loops) worst = std::max(worst, l.translation);
  EXPECT_GT(worst, 0.5);
}

}  // namespace
}  // namespace plumb
