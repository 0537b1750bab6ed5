// The level-of-detail cache of real files from the shared data: an airborne LAS (110,000
// points, intensity and colour, UTM coordinates) and E57s written by CloudCompare and
// libE57Format (two scans; the bunny), every point kept to the quantum, built through spill
// files (1 MB budget).
#include <gtest/gtest.h>

#include "io/lod/lod_builder.hpp"
#include "io/lod/lod_select.hpp"
#include "lod_test_data.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

std::shared_ptr<const LodCache> expectWholeFile(const std::filesystem::path& file, const std::filesystem::path& root,
                                                std::size_t capacity, std::uint64_t points) {
  LodCacheParams p;
  p.node_capacity = capacity;
  p.memory_budget_mb = 1;
  const LodCacheBuildResult r = buildLodCache(file, root, p);
  EXPECT_EQ(r.points, points) << file;
  const auto cache = test::openValid(file, root);
  if (!cache) return cache;
  for (const LodNode& n : cache->hierarchy().nodes) EXPECT_LE(n.point_count, capacity);
  EXPECT_TRUE(test::cachedRecords(*cache) == test::expectedRecords(file, cache->hierarchy().grid)) << file;
  return cache;
}

TEST(LodReal, AutzenLasKeepsEveryPointAndATopViewStartsAtTheRoot) {
  const auto file = test::sharedData("las/autzen_trim.las");
  const auto cache = expectWholeFile(file, test::scratchDir("lod_real"), 5000, 110000);
  ASSERT_TRUE(cache);
  const LodHierarchy& h = cache->hierarchy();
  EXPECT_TRUE(h.has_intensity && h.has_rgb);
  EXPECT_GT(h.nodes.size(), 22u);  // 110,000 points in nodes of at most 5000
  // Orthographic, looking down on the whole tile: clip x, y = +-1 at the tile's edges, z from
  // the eye 1000 m above the centre down to 2000 m below it.
  LodView top;
  const Eigen::Vector3d c = h.bounds.center(), half = h.bounds.size() / 2;
  top.eye = c + Eigen::Vector3d(0, 0, 1000);
  top.view_projection = Eigen::Matrix4d::Identity();
  top.view_projection(0, 0) = 1 / half.x(), top.view_projection(0, 3) = -c.x() / half.x();
  top.view_projection(1, 1) = 1 / half.y(), top.view_projection(1, 3) = -c.y() / half.y();
  top.view_projection(2, 2) = 1 / 1500.0, top.view_projection(2, 3) = -(c.z() - 500) / 1500.0;
  top.metres_per_pixel = 0.5;
  LodSelectParams p;
  p.point_budget = 20000;
  const LodSelection s = selectLodNodes(h, top, p);
  ASSERT_FALSE(s.nodes.empty());
  EXPECT_EQ(s.nodes.front(), 0u);
  EXPECT_LE(s.points, 20000u);
  EXPECT_TRUE(s.budget_reached);
}

TEST(LodReal, E57ScansKeepTheirStations) {
  const auto two = test::sharedData("e57/A_B.e57");
  const auto root = test::scratchDir("lod_real");
  const auto cache = expectWholeFile(two, root / "ab", 16, 6);
  ASSERT_TRUE(cache);
  EXPECT_EQ(cache->hierarchy().stations.size(), 2u);
  expectWholeFile(test::sharedData("e57/libe57format_reference_bunnyDouble.e57"), root / "bunny",
                  2000, 30571);
}

}  // namespace
}  // namespace plumb
