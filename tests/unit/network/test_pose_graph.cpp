// The pose graph and its robust adjustment on synthetic networks with known poses.
#include <gtest/gtest.h>

#include "support/synthetic_network.hpp"

namespace plumb {
namespace {

TEST(PoseGraph, ExactLinksGiveTheTruePosesFromAPerturbedStart) {
  const auto net = test::ringNetwork(8, 6.0, 3, 1e-9, 1e-9, 3, false);
  PoseGraphProblem pg;
  for (std::size_t i = 0; i < net.truth.size(); ++i)  // start 0.3 m and 2 deg away (not the reference)
    pg.initial.push_back(i == 0 ? net.truth[i] : RigidTransform::fromYaw(0.035, {0.3, -0.2, 0.1}) * net.truth[i]);
  for (const auto& l : net.links) pg.edges.push_back({l.a, l.b, l.transform, 0.001, 1e-4});
  const PoseGraphSolution s = solvePoseGraph(pg);
  EXPECT_TRUE(s.converged) << s.message;
  for (std::size_t i = 0; i < net.truth.size(); ++i) {
    EXPECT_LT(RigidTransform::translationError(s.poses[i], net.truth[i]), 1e-6) << i;
    EXPECT_LT(RigidTransform::rotationErrorDeg(s.poses[i], net.truth[i]), 1e-5) << i;
  }
  EXPECT_TRUE(s.covariance_ok);
  EXPECT_EQ(s.sigma_position[0].norm(), 0.0);  // the reference is fixed
  EXPECT_GT(s.sigma_position[4].x(), 0.0);
}

TEST(PoseGraph, EdgeResidualMeasuresDisagreement) {
  PoseGraphEdge e{0, 1, RigidTransform::fromYaw(0.0, {1, 0, 0}), 0.01, 0.001};
  const auto r = edgeResidual(e, RigidTransform(), RigidTransform::fromYaw(0.0, {1.05, 0, 0}));
  EXPECT_NEAR(r.translation, 0.05, 1e-12);
  EXPECT_NEAR(r.rotation_deg, 0.0, 1e-9);
  EXPECT_NEAR(r.normalised, 5.0, 1e-9);
}

TEST(RobustAdjustment, WrongLinkIsFlaggedDroppedAndStationsBeatTheChain) {
  const auto net = test::ringNetwork(12, 10.0, 4, 0.001, 0.005, 11, true);
  const auto adj = adjustNetwork(net.truth.size(), net.links, 0, net.truth[0], test::graphParams());
  ASSERT_EQ(adj.dropped_order.size(), 1u);
  EXPECT_EQ(adj.dropped_order[0], net.wrong_link);
  EXPECT_TRUE(adj.links[net.wrong_link].flagged);
  EXPECT_GT(adj.links[net.wrong_link].residual.translation, 1.0);
  for (std::size_t k = 0; k < net.links.size(); ++k)
    if (k != net.wrong_link) {
      EXPECT_FALSE(adj.links[k].dropped) << k;
    }
  const double network = test::maxPositionError(adj.poses, net.truth);
  const double chain = test::maxPositionError(adj.chain_poses, net.truth);
  EXPECT_LT(network, 0.004);
  EXPECT_LT(network, chain) << "the adjustment must beat the chain of the same links";
  EXPECT_FALSE(adj.loops.empty());
}

TEST(RobustAdjustment, SequenceLinksOutvoteAStackedCliqueOfIdenticalRooms) {
  auto net = test::ringNetwork(12, 10.0, 4, 0.001, 0.005, 21, false);
  for (std::size_t k = 0; k < 12; ++k) net.links[k].sequence = true;  // the ring: shot in order
  const std::size_t first_wrong = net.links.size();
  test::addStackedClique(net, {0, 3, 6, 9}, 0.0005, 0.002);  // 6 wrong links, all agreeing
  const auto adj = adjustNetwork(net.truth.size(), net.links, 0, net.truth[0], test::graphParams());
  for (std::size_t k = first_wrong; k < net.links.size(); ++k) {
    EXPECT_TRUE(adj.links[k].dropped) << k;
    EXPECT_GE(adj.links[k].triangles.closing, 2) << "the clique's triangles close";
  }
  EXPECT_EQ(adj.dropped_order.size(), net.links.size() - first_wrong);
  EXPECT_LT(test::maxPositionError(adj.poses, net.truth), 0.004);
}

TEST(RobustAdjustment, ReportedSigmasCoverTheTrueErrors) {
  int covered = 0, total = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto net = test::ringNetwork(12, 10.0, 4, 0.001, 0.005, seed, false);
    const auto adj = adjustNetwork(net.truth.size(), net.links, 0, net.truth[0], test::graphParams());
    ASSERT_TRUE(adj.covariance_ok);
    for (std::size_t i = 1; i < net.truth.size(); ++i) {
      const Eigen::Vector3d err = adj.poses[i]->translation() - net.truth[i].translation();
      for (int c = 0; c < 3; ++c) covered += std::abs(err[c]) <= 3.0 * adj.sigma_position[i][c], ++total;
    }
  }
  EXPECT_GE(covered, total * 95 / 100) << covered << " of " << total << " coordinates within 3 sigma";
}

TEST(RobustAdjustment, DisconnectedStationIsNotPlaced) {
  auto net = test::ringNetwork(6, 5.0, 2, 0.001, 0.005, 5, false);
  net.truth.push_back(RigidTransform::fromYaw(0.3, {20, 0, 0}));  // station 6: no link
  const auto adj = adjustNetwork(net.truth.size(), net.links, 0, net.truth[0], test::graphParams());
  EXPECT_FALSE(adj.poses[6].has_value());
  for (std::size_t i = 0; i < 6; ++i) EXPECT_TRUE(adj.poses[i].has_value()) << i;
}

TEST(RobustAdjustment, WithoutAutoDropTheWrongLinkIsOnlyFlagged) {
  const auto net = test::ringNetwork(12, 10.0, 4, 0.001, 0.005, 11, true);
  PoseGraphParams p = test::graphParams();
  p.auto_drop = false;
  const auto adj = adjustNetwork(net.truth.size(), net.links, 0, net.truth[0], p);
  EXPECT_TRUE(adj.dropped_order.empty());
  EXPECT_TRUE(adj.links[net.wrong_link].flagged);
  EXPECT_FALSE(adj.links[net.wrong_link].dropped);
}

}  // namespace
}  // namespace plumb
