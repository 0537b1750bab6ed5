// The subsample of a file from its level-of-detail cache (issue 16: a reopen in seconds): the
// same scans, names and poses as the file's streamed subsample, within the point limit, at a
// voxel within one doubling of it, each scan covering the same space; a file whose points
// carry normals (what the cache does not keep) is refused with the reason.
#include <gtest/gtest.h>

#include "io/io.hpp"
#include "io/lod/lod_builder.hpp"
#include "io/lod/lod_subsample.hpp"
#include "lod_test_data.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

namespace fs = std::filesystem;

LodCacheParams smallNodes() {
  LodCacheParams p;
  p.node_capacity = 1000;
  p.grid_cells = 32;
  p.chunk_points = 4096;
  return p;
}

Bounds worldBounds(const Scan& s) {
  Bounds b;
  for (std::size_t i = 0; i < s.cloud.size(); ++i) b.extend(s.pose.apply(s.cloud.world(i)));
  return b;
}

TEST(LodSubsample, TheCacheGivesTheFileSubsampleScansWithinTheLimit) {
  const fs::path dir = test::scratchDir("lod_subsample");
  const fs::path source = test::writeSurvey(dir, 3, 30000);
  buildLodCache(source, dir / "cache", smallNodes());
  const auto cache = test::openValid(source, dir / "cache");
  ASSERT_TRUE(cache);
  SubsampleParams params;
  params.voxel = 0.02;
  params.max_points = 20000;
  const SubsampleResult streamed = subsampleDataset(source, params);
  const LodSubsampleResult r = subsampleFromLodCache(source, *cache, params);
  ASSERT_TRUE(r.subsample) << r.why_not;
  const SubsampleResult& s = *r.subsample;
  EXPECT_EQ(s.points_read, test::readPointCount(source));  // what the file holds
  EXPECT_LE(s.points_kept, params.max_points);
  EXPECT_GT(s.points_kept, params.max_points / 4);
  EXPECT_GE(r.levels, 1);
  EXPECT_LT(r.points_from_cache, s.points_read);  // not the whole file
  EXPECT_LE(double(r.points_from_cache), kLodSubsampleReadFactor * double(params.max_points) + 1000.0);
  EXPECT_GE(s.voxel, streamed.voxel / 2);
  EXPECT_LE(s.voxel, streamed.voxel * 2);
  ASSERT_EQ(s.data.scans.size(), streamed.data.scans.size());
  for (std::size_t k = 0; k < s.data.scans.size(); ++k) {
    const Scan& a = s.data.scans[k];
    const Scan& b = streamed.data.scans[k];
    EXPECT_EQ(a.name, b.name);
    EXPECT_TRUE(a.pose.matrix().isApprox(b.pose.matrix(), 1e-12)) << a.name;
    EXPECT_TRUE(a.cloud.hasIntensity()) << a.name;
    EXPECT_GT(a.cloud.size(), b.cloud.size() / 4) << a.name;
    const Bounds x = worldBounds(a), y = worldBounds(b);
    EXPECT_LT((x.min - y.min).norm(), 2 * s.voxel + 0.05) << a.name;
    EXPECT_LT((x.max - y.max).norm(), 2 * s.voxel + 0.05) << a.name;
    EXPECT_GT(x.min.x(), 650000);  // the scan frame back to national-grid coordinates by its pose
  }
}

TEST(LodSubsample, AFileWithNormalsIsStreamedInstead) {
  const fs::path dir = test::scratchDir("lod_subsample");
  Dataset d;
  Scan scan;
  scan.name = "with normals";
  for (int i = 0; i < 5000; ++i) {
    scan.cloud.positions.emplace_back(float(i % 100) * 0.05f, float(i / 100) * 0.05f, 0.0f);
    scan.cloud.normals.emplace_back(0.0f, 0.0f, 1.0f);
  }
  d.scans.push_back(scan);
  const fs::path source = dir / "normals.ply";
  writeDataset(source, d);
  buildLodCache(source, dir / "cache", smallNodes());
  const auto cache = test::openValid(source, dir / "cache");
  ASSERT_TRUE(cache);
  SubsampleParams params;
  params.max_points = 1000;
  const LodSubsampleResult r = subsampleFromLodCache(source, *cache, params);
  EXPECT_FALSE(r.subsample);
  EXPECT_NE(r.why_not.find("normals"), std::string::npos) << r.why_not;
}

}  // namespace
}  // namespace plumb
