// Building the level-of-detail cache from a generated 3-station georeferenced E57: every
// point kept once to the quantum with its station, intensity and colour, node capacity and
// sampling, the same tree whether built in memory or through spill files, same bytes twice.
#include <gtest/gtest.h>

#include <set>

#include "common/error.hpp"

#include "io/lod/lod_builder.hpp"
#include "io/lod/lod_format.hpp"
#include "io/lod/lod_sample.hpp"
#include "lod_test_data.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

namespace fs = std::filesystem;

LodCacheParams smallNodes(double budget_mb = 256) {
  LodCacheParams p;
  p.node_capacity = 1000;
  p.grid_cells = 32;
  p.memory_budget_mb = budget_mb;
  p.chunk_points = 4096;
  return p;
}

class LodBuild : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = test::scratchDir("lod_build");
    source = test::writeSurvey(dir, 3, 30000);
  }
  fs::path dir, source;
};

TEST_F(LodBuild, EveryPointOnceWithStationIntensityColourToTheQuantum) {
  const LodCacheBuildResult r = buildLodCache(source, dir / "cache", smallNodes());
  EXPECT_EQ(r.points, 3u * 30020u);
  EXPECT_EQ(r.points, test::readPointCount(source));
  EXPECT_EQ(r.spilled_points, 0u);  // fits the default budget: built in memory
  const auto cache = test::openValid(source, dir / "cache");
  ASSERT_TRUE(cache);
  const LodHierarchy& h = cache->hierarchy();
  ASSERT_EQ(h.stations.size(), 3u);
  EXPECT_EQ(h.stations[2].name, "station 2");
  EXPECT_TRUE(h.has_intensity && h.has_rgb);
  EXPECT_GT(h.grid.origin.x(), 650000);  // national-grid coordinates, not a local frame
  EXPECT_GT(h.grid.origin.y(), 6850000);
  const auto expected = test::expectedRecords(source, h.grid);
  const auto cached = test::cachedRecords(*cache);
  ASSERT_EQ(cached.size(), expected.size());
  EXPECT_TRUE(cached == expected);  // same multiset: quantised positions, stations, intensity, rgb
  EXPECT_GT(r.max_depth, 1);
}

TEST_F(LodBuild, NodesRespectCapacityAndSampleOnePointPerCell) {
  const LodCacheParams params = smallNodes();
  buildLodCache(source, dir / "cache", params);
  const auto cache = test::openValid(source, dir / "cache");
  ASSERT_TRUE(cache);
  const LodHierarchy& h = cache->hierarchy();
  ASSERT_GT(h.nodes.size(), 20u);
  std::size_t inner = 0;
  for (const LodNode& n : h.nodes) {
    EXPECT_LE(n.point_count, params.node_capacity) << "node " << n.id;
    EXPECT_GT(n.point_count, 0u);
    if (n.leaf()) continue;
    ++inner;
    // An inner node holds at most one point per cell of its grid: its spacing.
    const LodNodePoints pts = cache->readNode(n.id);
    std::set<std::array<std::int64_t, 3>> cells;
    const double cell = n.spacing / h.grid.quantum;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      std::array<std::int64_t, 3> c{};
      for (int a = 0; a < 3; ++a)
        c[a] = std::llround((pts.world(i)[a] - h.grid.origin[a]) / h.grid.quantum) / static_cast<std::int64_t>(cell);
      EXPECT_TRUE(cells.insert(c).second) << "two points in one cell of node " << n.id;
      EXPECT_TRUE((pts.world(i).array() >= n.bounds.min.array() - 1e-9).all() &&
                  (pts.world(i).array() <= n.bounds.max.array() + 1e-9).all());
    }
    if (n.parent != kNoLodNode) {
      EXPECT_DOUBLE_EQ(h.nodes[n.parent].spacing, 2 * n.spacing);
    }
  }
  EXPECT_GT(inner, 3u);
}

TEST_F(LodBuild, SpilledBuildKeepsEveryPointWithinItsMemoryBudget) {
  // 0.3 MB: about 4700 points in memory, so the file goes through bucket files, some split again.
  const LodCacheBuildResult r = buildLodCache(source, dir / "cache", smallNodes(0.3));
  EXPECT_GT(r.spilled_points, 0u);
  EXPECT_LE(r.largest_in_memory, 4700u);
  const auto cache = test::openValid(source, dir / "cache");
  ASSERT_TRUE(cache);
  for (const LodNode& n : cache->hierarchy().nodes) EXPECT_LE(n.point_count, 1000u);
  EXPECT_TRUE(test::cachedRecords(*cache) == test::expectedRecords(source, cache->hierarchy().grid));
  EXPECT_FALSE(fs::exists(r.directory / "spill"));  // temporary buckets removed
}

TEST_F(LodBuild, SameInputSameBytes) {
  const auto a = buildLodCache(source, dir / "a", smallNodes(0.3));
  const auto b = buildLodCache(source, dir / "b", smallNodes(0.3));
  for (const char* name : {kLodIndexFile, kLodPointsFile}) {
    const std::string x = test::readAll(a.directory / name), y = test::readAll(b.directory / name);
    EXPECT_GT(x.size(), 100u);
    EXPECT_TRUE(x == y) << name << " differs between two builds";
  }
  EXPECT_EQ(a.bytes, fs::file_size(a.directory / kLodIndexFile) + fs::file_size(a.directory / kLodPointsFile));
}

TEST_F(LodBuild, CancelLeavesNoCacheNorTemporaryFolder) {
  const fs::path root = dir / "cache";
  Progress progress([&](double fraction, std::string_view) {
    if (fraction > 0.4) progress.cancel();
  });
  EXPECT_THROW(buildLodCache(source, root, smallNodes(0.3), &progress), Canceled);
  EXPECT_FALSE(openLodCache(source, root).valid());
  EXPECT_EQ(openLodCache(source, root).state, LodCacheState::missing);
  ASSERT_TRUE(fs::exists(root));
  EXPECT_TRUE(fs::is_empty(root)) << "a temporary build folder was left behind";
}

TEST_F(LodBuild, AbandonedBuildFoldersAreRemovedAndDamagedSourcesNamed) {
  const fs::path root = dir / "cache";
  // A folder left by a build whose process is gone (pid 999999999 is above pid_max).
  const fs::path abandoned = lodCacheDirectory(source, root).string() + ".building-999999999-0";
  fs::create_directories(abandoned / "spill");
  buildLodCache(source, root, smallNodes());
  EXPECT_FALSE(fs::exists(abandoned));
  // A file cut in the middle of its points: readDataset's error, and the valid cache stays.
  const std::string bytes = test::readAll(source);
  test::writeAll(source, bytes.substr(0, bytes.size() / 2));
  try {
    buildLodCache(source, root, smallNodes());
    ADD_FAILURE() << "no error for a truncated source";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("survey.e57"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::exists(lodCacheDirectory(source, root) / kLodIndexFile));
  EXPECT_EQ(std::distance(fs::directory_iterator(root), fs::directory_iterator()), 1);
}

TEST_F(LodBuild, ProgressReachesOneAndBadParametersAreRefused) {
  double last = 0;
  Progress progress([&](double fraction, std::string_view) { last = fraction; });
  buildLodCache(source, dir / "cache", smallNodes(), &progress);
  EXPECT_DOUBLE_EQ(last, 1.0);
  LodCacheParams bad = smallNodes();
  bad.grid_cells = 100;  // not a power of two
  EXPECT_THROW(buildLodCache(source, dir / "cache2", bad), InputError);
  bad = smallNodes();
  bad.quantum = 0;
  EXPECT_THROW(buildLodCache(source, dir / "cache2", bad), InputError);
}

TEST(LodCellSet, InsertsEachKeyOnce) {
  LodCellSet set;
  for (std::uint32_t k = 0; k < 5000; ++k) EXPECT_TRUE(set.insert(k * 7919u % 100003u));
  for (std::uint32_t k = 0; k < 5000; ++k) EXPECT_FALSE(set.insert(k * 7919u % 100003u));
  EXPECT_EQ(set.size(), 5000u);
}

}  // namespace
}  // namespace plumb
