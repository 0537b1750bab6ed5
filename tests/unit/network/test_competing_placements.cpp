// Competing placements (competing_placements.hpp): a network whose wrong links agree with each
// other has two loop-checked placements of some stations; those stations are ambiguous, while
// one lone wrong link, or wrong links the shot order contradicts, leave nothing ambiguous.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "registration/network/competing_placements.hpp"
#include "registration/network/network_report.hpp"
#include "support/synthetic_network.hpp"

namespace plumb {
namespace {

CompetingPlacements competingOf(const test::SyntheticNetwork& net, const PoseGraphParams& p) {
  const auto adopted = adjustNetwork(net.truth.size(), net.links, 0, net.truth[0], p);
  return findCompetingPlacements(net.truth.size(), net.links, 0, net.truth[0], p, adopted);
}

TEST(CompetingPlacements, OneLoneWrongLinkLeavesNothingAmbiguous) {
  const auto net = test::ringNetwork(12, 10.0, 4, 0.001, 0.005, 11, true);
  const auto c = competingOf(net, test::graphParams());
  ASSERT_EQ(c.alternatives.size(), 1u);
  EXPECT_EQ(c.alternatives[0].link, net.wrong_link);
  EXPECT_FALSE(c.alternatives[0].corroborated) << "no loop of right links can agree with a 4 m / 180 deg link";
  EXPECT_FALSE(c.alternatives[0].competes);
  EXPECT_FALSE(c.alternatives[0].stations.empty()) << "taken as true, it moves stations";
  EXPECT_TRUE(c.ambiguous.empty());
}

TEST(CompetingPlacements, ShotOrderSettlesAStackedCliqueOfIdenticalRooms) {
  auto net = test::ringNetwork(12, 10.0, 4, 0.001, 0.005, 21, false);
  for (std::size_t k = 0; k < 12; ++k) net.links[k].sequence = true;
  test::addStackedClique(net, {0, 3, 6, 9}, 0.0005, 0.002);
  const auto c = competingOf(net, test::graphParams());
  ASSERT_EQ(c.alternatives.size(), 6u);
  for (const auto& a : c.alternatives) {
    EXPECT_GT(a.dropped_sequence, 0u) << "stacking the rooms contradicts the shot order";
    EXPECT_FALSE(a.competes);
  }
  EXPECT_TRUE(c.ambiguous.empty());
}

/// Twelve stations on a ring; stations 6, 7, 8 (a wing) also fit at their half-turn image
/// about the wing's centre, and two wrong links join that twin to the rest as consistently as
/// two right links join the true wing.
test::SyntheticNetwork twinWingNetwork() {
  auto net = test::ringNetwork(12, 10.0, 4, 0.001, 0.005, 5, false);
  net.links.clear();
  std::mt19937_64 rng(7);
  auto add = [&](std::size_t a, std::size_t b, const RigidTransform& pose_a, const RigidTransform& pose_b) {
    AdjustmentLink l;
    l.a = a, l.b = b;
    l.transform = test::noisy(pose_a.inverse() * pose_b, 0.001, 0.005, rng);
    l.sigma_translation = 0.001, l.sigma_rotation_deg = 0.005;
    net.links.push_back(l);
  };
  const auto& t = net.truth;
  for (std::size_t i = 0; i + 1 < 12; ++i)
    if (i != 5 && i != 8) add(i, i + 1, t[i], t[i + 1]);  // the ring, the wing's ends left open
  add(11, 0, t[11], t[0]);
  add(0, 3, t[0], t[3]);
  add(9, 0, t[9], t[0]);
  add(6, 8, t[6], t[8]);
  const Eigen::Vector3d c = (t[6].translation() + t[7].translation() + t[8].translation()) / 3.0;
  const RigidTransform half_turn = RigidTransform::fromYaw(0.0, c) * RigidTransform::fromYaw(M_PI, {0, 0, 0}) *
                                   RigidTransform::fromYaw(0.0, -c);
  add(5, 6, t[5], t[6]);  // right
  add(8, 9, t[8], t[9]);  // right
  add(4, 7, t[4], half_turn * t[7]);  // wrong, consistent with the twin wing
  add(10, 6, t[10], half_turn * t[6]);  // wrong, consistent with the twin wing
  return net;
}

TEST(CompetingPlacements, TwoLoopCheckedPlacementsOfAWingMakeItAmbiguous) {
  const auto net = twinWingNetwork();
  const auto p = test::graphParams();
  const auto adopted = adjustNetwork(net.truth.size(), net.links, 0, net.truth[0], p);
  ASSERT_EQ(adopted.dropped_order.size(), 2u) << "one pair of wing links is dropped, whichever";
  const auto c = findCompetingPlacements(net.truth.size(), net.links, 0, net.truth[0], p, adopted);
  ASSERT_EQ(c.alternatives.size(), 2u);
  for (const auto& a : c.alternatives) {
    EXPECT_TRUE(a.corroborated);
    EXPECT_TRUE(a.competes);
    EXPECT_EQ(a.stations, (std::vector<std::size_t>{6, 7, 8}));
    EXPECT_NEAR(a.max_rotation_deg, 180.0, 0.1);
    EXPECT_GT(a.max_translation, 5.0);
  }
  EXPECT_EQ(c.ambiguous, (std::vector<std::size_t>{6, 7, 8})) << "the stations outside the wing are placed";
}

TEST(CompetingPlacements, AmbiguousStationsAreNotPlacedAndTheNetworkFails) {
  NetworkResult r;
  r.adjustment.poses = {RigidTransform(), RigidTransform::fromYaw(0.5, {1, 2, 0})};
  r.adjustment.sigma_position.assign(2, Eigen::Vector3d::Zero());
  r.adjustment.sigma_rotation_deg.assign(2, Eigen::Vector3d::Zero());
  std::vector<Station> st(2);
  st[0].name = "tls-0", st[1].name = "tls-1";
  EXPECT_EQ(networkExitCode(r), 0);
  EXPECT_TRUE(r.placed(1));
  r.competing.ambiguous = {1};
  EXPECT_FALSE(r.placed(1));
  EXPECT_TRUE(r.placed(0));
  EXPECT_EQ(networkExitCode(r), 2);
  const auto j = networkReportToJson(r, st);
  EXPECT_FALSE(j["stations"][1]["placed"].get<bool>());
  EXPECT_TRUE(j["stations"][1]["ambiguous"].get<bool>());
  EXPECT_EQ(j["network"]["ambiguous"], nlohmann::json::array({"tls-1"}));
  EXPECT_NE(networkReportToText(r, st).find("AMBIGUOUS"), std::string::npos);
}

}  // namespace
}  // namespace plumb

namespace plumb {
namespace {

Link linkBetween(std::size_t a, std::size_t b, const char* status, bool accepted) {
  Link l;
  l.a = a, l.b = b, l.status = status, l.accepted = accepted, l.registered = accepted;
  return l;
}

TEST(CopiesUnchecked, AStationTheBimFitsInCopiesNeedsALoopCheckedLink) {
  // Scan stations 0-3, the model 4. The BIM places 0 and 3; it fits 1 and 2 in several copies.
  std::vector<Station> st(5);
  st[4].is_model = true;
  NetworkResult r;
  r.links = {linkBetween(0, 4, "success", true),   linkBetween(1, 4, "ambiguous", false),
             linkBetween(2, 4, "ambiguous", false), linkBetween(3, 4, "success", true),
             linkBetween(0, 1, "success", true),   linkBetween(1, 2, "success", true),
             linkBetween(2, 3, "success", true),   linkBetween(0, 2, "success", true)};
  r.adjustment.poses.assign(5, RigidTransform());
  for (std::size_t k = 0; k < r.links.size(); ++k)
    if (r.links[k].accepted) r.adjusted.push_back(k);
  r.adjustment.links.resize(r.adjusted.size());
  // Kept links 0-4, 3-4, 0-1, 1-2, 2-3, 0-2: every one on a loop (0-1-2-0, 0-2-3-4-0).
  EXPECT_TRUE(copiesUnchecked(st, r).empty());
  // Drop 0-2 and 2-3: stations 1 and 2 then hang on bridges (0-1, 1-2), and the BIM could not
  // choose their copy.
  r.adjustment.links[5].dropped = true;  // 0-2
  r.adjustment.links[4].dropped = true;  // 2-3
  r.adjustment.links[2].bridge = true;   // 0-1
  r.adjustment.links[3].bridge = true;   // 1-2
  EXPECT_EQ(copiesUnchecked(st, r), (std::vector<std::size_t>{1, 2}));
  r.links[1].status = "too few features";  // the BIM saw nothing to judge: not a copy question
  EXPECT_EQ(copiesUnchecked(st, r), (std::vector<std::size_t>{2}));
  st[4].is_model = false;  // no model: nothing to say
  EXPECT_TRUE(copiesUnchecked(st, r).empty());
}

TEST(NetworkReport, EachLinkListsTheOtherPlacementsItsPipelineRefined) {
  std::vector<Station> st(2);
  st[0].name = "tls-0", st[1].name = "tls-1";
  NetworkResult r;
  r.adjustment.poses = {RigidTransform(), RigidTransform()};
  r.adjustment.sigma_position.assign(2, Eigen::Vector3d::Zero());
  r.adjustment.sigma_rotation_deg.assign(2, Eigen::Vector3d::Zero());
  r.links = {linkBetween(0, 1, "success", true)};
  r.links[0].transform = RigidTransform::fromYaw(0.1, {1, 0, 0});
  r.links[0].alternatives.push_back({RigidTransform::fromYaw(0.1 + M_PI, {1, 0, 0}), "worse", 0.62, 0.0047});
  const auto j = networkReportToJson(r, st)["links"][0]["alternatives"];
  ASSERT_EQ(j.size(), 1u);
  EXPECT_EQ(j[0]["role"], "worse");
  EXPECT_DOUBLE_EQ(j[0]["overlap"].get<double>(), 0.62);
  EXPECT_NEAR(j[0]["rotation_from_chosen_deg"].get<double>(), 180.0, 1e-6);
}

}  // namespace
}  // namespace plumb
