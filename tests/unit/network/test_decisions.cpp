// The surveyor's decisions on a network (NetworkDecisions, docs/NETWORK.md "Decisions"): a
// locked station keeps its pose bit for bit, an accepted link is never dropped, a rejected one
// is left out, and a decision naming no link is an error.
#include <gtest/gtest.h>

#include "common/error.hpp"
#include "registration/network/network_registration.hpp"
#include "support/synthetic_network.hpp"

namespace plumb {
namespace {

TEST(NetworkDecisions, ALockedStationKeepsItsPoseAndPullsItsNeighbours) {
  const auto net = test::ringNetwork(12, 10.0, 4, 0.001, 0.005, 7, false);
  // Locked 3 cm east of where the links put it: the pose is kept exactly, the neighbours follow
  // part of the way, and the links that now disagree by more than the drop threshold go.
  const RigidTransform moved = RigidTransform::fromYaw(0.0, {0.03, 0, 0}) * net.truth[6];
  const auto adj = adjustNetwork(net.truth.size(), net.links, 0, net.truth[0], test::graphParams(), {}, {{6, moved}});
  ASSERT_TRUE(adj.poses[6]);
  EXPECT_EQ(adj.poses[6]->matrix(), moved.matrix());
  EXPECT_EQ(adj.sigma_position[6].norm(), 0.0) << "a held station has no uncertainty";
  ASSERT_TRUE(adj.poses[5] && adj.poses[7]);
  const double pulled = (adj.poses[5]->translation() - net.truth[5].translation()).x();
  EXPECT_GT(pulled, 0.0005) << "the neighbours move towards the locked station";
  EXPECT_LT(pulled, 0.03);
}

TEST(NetworkDecisions, LockingAStationAtItsAdjustedPoseChangesNothingElse) {
  const auto net = test::ringNetwork(12, 10.0, 4, 0.001, 0.005, 8, false);
  const auto free = adjustNetwork(net.truth.size(), net.links, 0, net.truth[0], test::graphParams());
  const auto held = adjustNetwork(net.truth.size(), net.links, 0, net.truth[0], test::graphParams(), {},
                                  {{4, *free.poses[4]}});
  EXPECT_EQ(held.poses[4]->matrix(), free.poses[4]->matrix());
  for (std::size_t i = 0; i < net.truth.size(); ++i)
    EXPECT_LT(RigidTransform::translationError(*held.poses[i], *free.poses[i]), 2e-4) << i;
  EXPECT_TRUE(held.dropped_order.empty());
}

TEST(NetworkDecisions, AnAcceptedWrongLinkIsKeptAndItsRightNeighboursAreDroppedInstead) {
  const auto net = test::ringNetwork(12, 10.0, 4, 0.001, 0.005, 11, true);
  const auto adj =
      adjustNetwork(net.truth.size(), net.links, 0, net.truth[0], test::graphParams(), {net.wrong_link});
  EXPECT_FALSE(adj.links[net.wrong_link].dropped) << "the surveyor's accepted link is never dropped";
  EXPECT_FALSE(adj.dropped_order.empty()) << "what disagrees with it goes";
}

Station namedStation(const std::string& name) {
  Station s;
  s.name = name;
  return s;
}

Link link(std::size_t a, std::size_t b, bool registered) {
  Link l;
  l.a = a, l.b = b, l.registered = registered, l.accepted = registered;
  l.status = registered ? "success" : "too few features";
  return l;
}

template <typename F>
void expectErrorSaying(F call, const std::string& words) {
  try {
    call();
    FAIL() << "no InputError; expected one saying: " << words;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(NetworkDecisions, RejectedAndAcceptedLinksAreMarkedAndBadDecisionsNameTheStations) {
  const std::vector<Station> st = {namedStation("tls-0"), namedStation("tls-1"), namedStation("tls-2")};
  std::vector<Link> links = {link(0, 1, true), link(1, 2, true), link(0, 2, false)};
  links[1].accepted = false;  // check visually: not accepted by the verdict
  NetworkDecisions d;
  d.rejected = {{1, 0}};  // either order names the link
  d.accepted = {{1, 2}};
  applyDecisions(links, d, st);
  EXPECT_FALSE(links[0].accepted);
  EXPECT_EQ(links[0].decision, "rejected");
  EXPECT_TRUE(links[1].accepted);
  EXPECT_EQ(links[1].decision, "accepted");
  EXPECT_EQ(links[2].decision, "");

  NetworkDecisions failed;
  failed.accepted = {{0, 2}};
  expectErrorSaying([&] { applyDecisions(links, failed, st); }, "tls-0 - tls-2 failed (too few features)");
  NetworkDecisions both;
  both.rejected = both.accepted = {{0, 1}};
  EXPECT_THROW(applyDecisions(links, both, st), InputError);
  std::vector<Link> two = {link(0, 1, true)};
  NetworkDecisions none;
  none.rejected = {{1, 2}};
  expectErrorSaying([&] { applyDecisions(two, none, st); }, "no link joins tls-1 and tls-2");
}

}  // namespace
}  // namespace plumb
