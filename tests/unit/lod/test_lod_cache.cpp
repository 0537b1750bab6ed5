// Opening a level-of-detail cache: reused while the source is unchanged, rebuilt when it is
// touched or rewritten, and every kind of damage (truncated points, garbage or truncated
// index, another version, flipped bytes, points outside their node) is a reason or a
// FileError, never a crash. Concurrent reads of one cache agree with serial ones.
#include <gtest/gtest.h>

#include <random>
#include <thread>

#include "common/error.hpp"
#include "io/lod/lod_builder.hpp"
#include "lod_test_data.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

namespace fs = std::filesystem;

class LodCacheFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = test::scratchDir("lod_cache");
    source = test::writeSurvey(dir, 2, 8000);
    LodCacheParams p;
    p.node_capacity = 500;
    built = buildLodCache(source, dir / "cache", p);
    index = built.directory / kLodIndexFile;
    points = built.directory / kLodPointsFile;
  }
  LodCacheState state() const { return openLodCache(source, dir / "cache").state; }
  fs::path dir, source, index, points;
  LodCacheBuildResult built;
};

TEST_F(LodCacheFiles, ReusedUntilTheSourceChanges) {
  const auto first = openLodCache(source, dir / "cache");
  ASSERT_TRUE(first.valid()) << first.reason;
  EXPECT_EQ(first.cache->hierarchy().points, 16040u);
  EXPECT_EQ(first.cache->bytesOnDisk(), built.bytes);
  EXPECT_EQ(first.cache->directory(), lodCacheDirectory(source, dir / "cache"));
  // Touched: same bytes, new modification time.
  fs::last_write_time(source, fs::last_write_time(source) + std::chrono::seconds(5));
  const auto touched = openLodCache(source, dir / "cache");
  EXPECT_EQ(touched.state, LodCacheState::source_changed);
  EXPECT_NE(touched.reason.find("modification time"), std::string::npos) << touched.reason;
  buildLodCache(source, dir / "cache");
  EXPECT_EQ(state(), LodCacheState::valid);
  // Rewritten with other points: size differs.
  test::writeSurvey(dir, 2, 9000, 3);
  const auto rewritten = openLodCache(source, dir / "cache");
  EXPECT_EQ(rewritten.state, LodCacheState::source_changed);
  EXPECT_NE(rewritten.reason.find("size changed"), std::string::npos) << rewritten.reason;
  buildLodCache(source, dir / "cache");
  const auto rebuilt = test::openValid(source, dir / "cache");
  ASSERT_TRUE(rebuilt);
  EXPECT_EQ(rebuilt->hierarchy().points, 18040u);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir / "cache"), fs::directory_iterator()), 1);
}

TEST_F(LodCacheFiles, MissingCacheOrSourceSaysWhy) {
  EXPECT_EQ(openLodCache(source, dir / "elsewhere").state, LodCacheState::missing);
  fs::remove(source);
  const auto gone = openLodCache(source, dir / "cache");
  EXPECT_EQ(gone.state, LodCacheState::source_changed);
  EXPECT_FALSE(gone.reason.empty());
}

TEST_F(LodCacheFiles, TruncatedPointFileIsDamaged) {
  fs::resize_file(points, fs::file_size(points) - 7);
  const auto r = openLodCache(source, dir / "cache");
  EXPECT_EQ(r.state, LodCacheState::damaged);
  EXPECT_NE(r.reason.find(kLodPointsFile), std::string::npos) << r.reason;
  EXPECT_FALSE(r.cache);
  buildLodCache(source, dir / "cache");  // the rebuild replaces it
  EXPECT_EQ(state(), LodCacheState::valid);
}

TEST_F(LodCacheFiles, GarbageOrTruncatedIndexIsDamagedAtEveryLength) {
  const std::string good = test::readAll(index);
  for (std::size_t n = 0; n < good.size(); n += 1 + n / 8) {
    test::writeAll(index, good.substr(0, n));
    EXPECT_EQ(state(), LodCacheState::damaged) << "index cut at " << n << " bytes";
  }
  std::mt19937 rng(5);
  std::string garbage(good.size(), '\0');
  for (char& c : garbage) c = static_cast<char>(rng());
  test::writeAll(index, garbage);
  const auto r = openLodCache(source, dir / "cache");
  EXPECT_EQ(r.state, LodCacheState::damaged);
  EXPECT_NE(r.reason.find(kLodIndexFile), std::string::npos) << r.reason;
}

TEST_F(LodCacheFiles, FlippedIndexBytesNeverOpen) {
  const std::string good = test::readAll(index);
  std::mt19937 rng(9);
  for (int trial = 0; trial < 300; ++trial) {
    std::string bad = good;
    bad[rng() % bad.size()] ^= static_cast<char>(1 + rng() % 255);
    test::writeAll(index, bad);
    const LodCacheState s = state();
    EXPECT_TRUE(s == LodCacheState::damaged || s == LodCacheState::version) << "trial " << trial;
  }
}

TEST_F(LodCacheFiles, AnotherVersionIsRebuilt) {
  std::string bytes = test::readAll(index);
  bytes[8] = static_cast<char>(kLodFormatVersion + 1);
  test::writeAll(index, bytes);
  const auto r = openLodCache(source, dir / "cache");
  EXPECT_EQ(r.state, LodCacheState::version);
  EXPECT_NE(r.reason.find("format version"), std::string::npos) << r.reason;
}

TEST_F(LodCacheFiles, DamagedPointsInsideTheFileAreAnErrorWhenRead) {
  const auto cache = test::openValid(source, dir / "cache");
  ASSERT_TRUE(cache);
  const LodNode& root = cache->hierarchy().nodes.at(0);
  const LodNode& child = cache->hierarchy().nodes.at(1);
  // Overwrite the root's first x with a value outside the root cube.
  std::string bytes = test::readAll(points);
  for (int b = 0; b < 4; ++b) bytes[root.data_offset + b] = '\xff';
  // And a child's first point with one from another place of the octree.
  for (int b = 0; b < 12; ++b) bytes[child.data_offset + b] = '\0';
  test::writeAll(points, bytes);
  const auto reopened = test::openValid(source, dir / "cache");  // sizes still agree
  ASSERT_TRUE(reopened);
  try {
    reopened->readNode(0);
    ADD_FAILURE() << "no error for a point outside its node";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("outside the node"), std::string::npos) << e.what();
  }
  if (child.key.xyz != std::array<std::uint32_t, 3>{0, 0, 0}) {
    EXPECT_THROW(reopened->readNode(1), FileError);
  }
  EXPECT_THROW(reopened->readNode(static_cast<std::uint32_t>(cache->hierarchy().nodes.size())), InputError);
}

TEST_F(LodCacheFiles, ConcurrentReadsAgreeWithSerialOnes) {
  const auto cache = test::openValid(source, dir / "cache");
  ASSERT_TRUE(cache);
  const std::size_t n = cache->hierarchy().nodes.size();
  ASSERT_GT(n, 8u);
  std::vector<std::uint64_t> serial(n), parallel(n);
  const auto digest = [&](std::uint32_t id) {
    const LodNodePoints p = cache->readNode(id);
    std::uint64_t h = p.size();
    for (std::size_t i = 0; i < p.size(); ++i) h = h * 31 + static_cast<std::uint64_t>(p.quanta[i][0] * 7 + p.station[i]);
    return h;
  };
  for (std::uint32_t i = 0; i < n; ++i) serial[i] = digest(i);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (std::size_t i = t; i < n; i += 4) parallel[i] = digest(static_cast<std::uint32_t>(i));
    });
  for (auto& th : threads) th.join();
  EXPECT_EQ(serial, parallel);
}

TEST_F(LodCacheFiles, NodePointsAsACloudKeepTheExactCoordinates) {
  const auto cache = test::openValid(source, dir / "cache");
  ASSERT_TRUE(cache);
  const LodNodePoints pts = cache->readNode(0);
  const PointCloud c = pts.toPointCloud();
  ASSERT_EQ(c.size(), pts.size());
  ASSERT_TRUE(c.hasScanId() && c.hasIntensity() && c.hasColors());
  double worst = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    worst = std::max(worst, (c.world(i) - pts.world(i)).cwiseAbs().maxCoeff());
    EXPECT_EQ(c.scan_id[i], pts.station[i]);
  }
  EXPECT_LT(worst, 1e-6);
  EXPECT_GT(c.offset.x(), 650000);
}

}  // namespace
}  // namespace plumb
