// Layout descriptors and candidate pair selection.
#include <gtest/gtest.h>

#include "registration/network/pair_selection.hpp"

namespace plumb {
namespace {

/// A vertical wall polygon of `length` x `height` along X at y = `y`, facing -Y.
PlanarPolygon wall(double length, double height, double y) {
  PlanarPolygon p;
  p.normal = -Eigen::Vector3d::UnitY();
  p.offset = -y;
  p.origin = {0, y, 0};
  p.u_axis = Eigen::Vector3d::UnitX();
  p.v_axis = Eigen::Vector3d::UnitZ();
  p.rings = {{{0, 0}, {length, 0}, {length, height}, {0, height}}};
  p.area = length * height;
  return p;
}

PlanarPolygon floorOf(double area) {
  PlanarPolygon p;
  p.area = area;
  return p;
}

FeatureSet room(double a, double b) {
  FeatureSet f;
  f.planes = {wall(a, 3, 0), wall(a, 3, b), wall(b, 3, 0), wall(b, 3, a), floorOf(a * b)};
  return f;
}

TEST(LayoutDescriptor, WallLengthsAreBinnedByHalfOctaveAndWeightedByArea) {
  const auto d = layoutDescriptor(room(4.0, 8.0));
  // 4 m: bin floor(2 log2(8) + 1) = 7; 8 m: bin 9; 8 m walls carry 2/3 of the wall area.
  EXPECT_NEAR(d.wall_lengths[7], 1.0 / 3.0, 1e-9);
  EXPECT_NEAR(d.wall_lengths[9], 2.0 / 3.0, 1e-9);
  EXPECT_NEAR(d.largest_horizontal_area, 32.0, 1e-9);
}

TEST(LayoutDescriptor, SimilarityIsOneForTheSameRoomAndLowForADifferentOne) {
  const auto a = layoutDescriptor(room(4, 5)), b = layoutDescriptor(room(4, 5)), c = layoutDescriptor(room(12, 2));
  EXPECT_NEAR(layoutSimilarity(a, b), 1.0, 1e-9);
  EXPECT_LT(layoutSimilarity(a, c), 0.4);
}

TEST(PairSelection, InitialPairsAreFarFewerThanAllPairsAndIncludeNeighbours) {
  std::vector<LayoutDescriptor> layouts;
  for (int i = 0; i < 20; ++i) layouts.push_back(layoutDescriptor(room(3 + 0.5 * i, 4 + 0.25 * (i % 4))));
  PairSelectionParams p;
  p.nearest_layouts = 2;
  p.sequence_neighbours = 1;
  const auto pairs = initialPairs(similarityMatrix(layouts), p);
  EXPECT_LE(pairs.size(), 20u * 3u);
  EXPECT_LT(pairs.size(), 20u * 19u / 2u / 3u);
  std::set<std::pair<std::size_t, std::size_t>> got;
  for (const auto& c : pairs) {
    EXPECT_LT(c.a, c.b);
    EXPECT_TRUE(got.insert({c.a, c.b}).second) << "pair listed twice";
  }
  for (std::size_t i = 0; i + 1 < 20; ++i) EXPECT_TRUE(got.count({i, i + 1})) << i;
}

TEST(PairSelection, ExpansionOnlyJoinsDifferentPartsAndSkipsTriedPairs) {
  std::vector<LayoutDescriptor> layouts;
  for (int i = 0; i < 6; ++i) layouts.push_back(layoutDescriptor(room(4, 4 + i)));
  const std::vector<std::size_t> component{0, 0, 0, 1, 1, 2};
  const std::set<std::pair<std::size_t, std::size_t>> tried{{2, 3}};
  PairSelectionParams p;
  p.expansion_per_station = 1;
  const auto pairs = expansionPairs(similarityMatrix(layouts), component, tried, p);
  ASSERT_FALSE(pairs.empty());
  std::vector<int> used(6, 0);
  for (const auto& c : pairs) {
    EXPECT_NE(component[c.a], component[c.b]);
    EXPECT_FALSE(c.a == 2 && c.b == 3);
    EXPECT_LE(++used[c.a], 1);
    EXPECT_LE(++used[c.b], 1);
  }
}

}  // namespace
}  // namespace plumb
