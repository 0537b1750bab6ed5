// Footprint pairs (footprint_pairs.hpp, docs/NETWORK.md "Candidate pairs"): once links place a
// part of the network, its stations that overlap on the ground are paired, never stations of
// different parts, pairs already tried, or more than the per-station cap.
#include <gtest/gtest.h>

#include "registration/network/footprint_pairs.hpp"

namespace plumb {
namespace {

/// A station whose points cover the floor of a `w` x `d` m room at its own origin (its frame).
Station floorStation(const std::string& name, double w, double d) {
  Station s;
  s.name = name;
  for (double x = 0.05; x < w; x += 0.1)
    for (double y = 0.05; y < d; y += 0.1) s.input.cloud.positions.push_back(Eigen::Vector3f(float(x), float(y), 0.f));
  return s;
}

/// An accepted link placing b at `b_in_a` in a's frame.
Link placedLink(std::size_t a, std::size_t b, const RigidTransform& b_in_a) {
  Link l;
  l.a = a, l.b = b, l.transform = b_in_a;
  l.registered = l.accepted = true;
  l.sigma_translation = 0.001, l.sigma_rotation_deg = 0.01;
  l.reason = "layout";
  return l;
}

TEST(Footprint, OverlapIsTheSharedShareOfTheSmallerFootprint) {
  const Station a = floorStation("a", 4, 4), b = floorStation("b", 2, 4);
  const auto fa = placedFootprint(a, RigidTransform{}, 0.5);
  EXPECT_EQ(fa.cells.size(), 64u);
  // b moved 1 m east: its 2 x 4 m lie inside a's 4 x 4 m.
  EXPECT_NEAR(footprintOverlap(fa, placedFootprint(b, RigidTransform::fromYaw(0, {1, 0, 0}), 0.5)), 1.0, 1e-12);
  // b turned a half turn about a's origin: it lies west of a, nothing shared.
  EXPECT_EQ(footprintOverlap(fa, placedFootprint(b, RigidTransform::fromYaw(M_PI, {-0.01, -0.01, 0}), 0.5)), 0.0);
  EXPECT_EQ(footprintOverlap(fa, Footprint{}), 0.0);
}

TEST(FootprintPairs, PairOverlappingStationsOfOnePartOnly) {
  // Part {0, 1, 2}: 1 beside 0 (half its floor shared), 2 far east of both. Part {3, 4}: 4 on 3.
  std::vector<Station> st{floorStation("s0", 4, 4), floorStation("s1", 4, 4), floorStation("s2", 4, 4),
                          floorStation("s3", 4, 4), floorStation("s4", 4, 4)};
  const std::vector<Link> links{placedLink(0, 1, RigidTransform::fromYaw(0, {2, 0, 0})),
                                placedLink(1, 2, RigidTransform::fromYaw(0, {20, 0, 0})),
                                placedLink(3, 4, RigidTransform::fromYaw(0, {0.5, 0, 0}))};
  const auto placed = placeParts(st, links, PoseGraphParams{});
  ASSERT_TRUE(placed.poses[0] && placed.poses[2] && placed.poses[4]);
  EXPECT_EQ(placed.part[0], placed.part[2]);
  EXPECT_NE(placed.part[0], placed.part[3]);
  EXPECT_NEAR(placed.poses[2]->translation().x() - placed.poses[0]->translation().x(), 22.0, 1e-6);
  // Station 0 at the origin of its own part, 3 of its own: the two parts are unrelated even
  // where their placements happen to overlap (0 and 3 both sit at their part's origin).
  PairSelectionParams p;
  p.footprint_per_station = 3;  // off by default
  auto pairs = footprintPairs(st, placed, {}, p);
  std::set<std::pair<std::size_t, std::size_t>> got;
  for (const auto& c : pairs) {
    got.insert({c.a, c.b});
    EXPECT_EQ(c.reason, "footprint");
    EXPECT_GE(c.similarity, p.footprint_overlap);
  }
  EXPECT_EQ(got, (std::set<std::pair<std::size_t, std::size_t>>{{0, 1}, {3, 4}}));
  // Tried pairs are not offered again; no footprint pairs at all when the cap is 0.
  EXPECT_EQ(footprintPairs(st, placed, {{0, 1}, {3, 4}}, p).size(), 0u);
  p.footprint_per_station = 0;
  EXPECT_TRUE(footprintPairs(st, placed, {}, p).empty());
}

TEST(FootprintPairs, AtMostTheCapPerStationLargestOverlapFirst) {
  // Stations 1..4 all on top of station 0, each shifted a little more: with a cap of 2, station
  // 0 gets its two most overlapping neighbours.
  std::vector<Station> st;
  for (int i = 0; i < 5; ++i) st.push_back(floorStation("s" + std::to_string(i), 4, 4));
  std::vector<Link> links;
  for (std::size_t i = 1; i < 5; ++i) links.push_back(placedLink(0, i, RigidTransform::fromYaw(0, {0.5 * double(i), 0, 0})));
  PairSelectionParams p;
  p.footprint_per_station = 2;
  std::set<std::pair<std::size_t, std::size_t>> tried;
  for (std::size_t i = 1; i < 5; ++i) tried.insert({0, i});
  const auto pairs = footprintPairs(st, placeParts(st, links, PoseGraphParams{}), tried, p);
  std::vector<int> used(5, 0);
  for (const auto& c : pairs) {
    EXPECT_LE(++used[c.a], 2);
    EXPECT_LE(++used[c.b], 2);
  }
  ASSERT_FALSE(pairs.empty());
  // The best pair (1, 2): 0.5 m apart, 7/8 of the floor shared, is among them.
  EXPECT_TRUE(std::any_of(pairs.begin(), pairs.end(), [](const CandidatePair& c) { return c.a == 1 && c.b == 2; }));
}

}  // namespace
}  // namespace plumb
