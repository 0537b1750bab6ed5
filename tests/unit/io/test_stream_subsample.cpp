// The voxel subsample built while streaming (io/stream/stream_subsample.hpp): one centroid per
// occupied voxel of each scan, and coarsening on the way (max_points) gives exactly the
// subsample at the coarser voxel.
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <tuple>

#include "io/io.hpp"
#include "io/stream/point_count.hpp"
#include "io/stream/stream_subsample.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

// Two posed stations of random points in a 6 m x 4 m x 3 m box, 2 mm float steps.
Dataset twoStations(std::size_t per_scan) {
  Dataset d;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 2; ++k) {
    Scan s;
    s.name = "station " + std::to_string(k);
    s.pose = RigidTransform::fromQuaternion(Eigen::Quaterniond(Eigen::AngleAxisd(0.5 * k, Eigen::Vector3d::UnitZ())),
                                            Eigen::Vector3d(100.0 + 3 * k, 50.0, 2.0));
    s.has_pose = true;
    for (std::size_t i = 0; i < per_scan; ++i) {
      s.cloud.positions.push_back(Eigen::Vector3f(6 * u(rng), 4 * u(rng), 3 * u(rng)));
      s.cloud.intensity.push_back(static_cast<float>(u(rng)));
    }
    d.scans.push_back(std::move(s));
  }
  return d;
}

// Voxel centroids of one cloud computed directly (the reference): key -> (sum, count).
std::map<std::tuple<long, long, long>, std::pair<Eigen::Vector3d, int>> centroids(const PointCloud& c,
                                                                                  const Eigen::Vector3d& anchor,
                                                                                  double voxel) {
  std::map<std::tuple<long, long, long>, std::pair<Eigen::Vector3d, int>> m;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Eigen::Vector3d d = c.world(i) - anchor;
    const auto key = std::make_tuple(long(std::floor(d.x() / voxel)), long(std::floor(d.y() / voxel)),
                                     long(std::floor(d.z() / voxel)));
    auto& e = m[key];
    if (e.second == 0) e.first.setZero();
    e.first += c.world(i);
    ++e.second;
  }
  return m;
}

void expectCentroids(const PointCloud& sub, const PointCloud& full, double voxel) {
  const Eigen::Vector3d anchor = full.world(0).array().round().matrix();
  const auto ref = centroids(full, anchor, voxel);
  ASSERT_EQ(sub.size(), ref.size());
  std::vector<Eigen::Vector3d> expected;
  for (const auto& [key, e] : ref) expected.push_back(e.first / e.second);
  std::vector<Eigen::Vector3d> got;
  for (std::size_t i = 0; i < sub.size(); ++i) got.push_back(sub.world(i));
  const auto less = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::tie(a.x(), a.y(), a.z()) < std::tie(b.x(), b.y(), b.z());
  };
  std::sort(expected.begin(), expected.end(), less);
  std::sort(got.begin(), got.end(), less);
  for (std::size_t i = 0; i < got.size(); ++i) ASSERT_LT((got[i] - expected[i]).norm(), 1e-5) << i;
}

TEST(StreamSubsample, OneCentroidPerOccupiedVoxelOfEachScan) {
  const auto dir = test::scratchDir("stream_subsample");
  const auto path = dir / "two.e57";
  writeDataset(path, twoStations(30000));
  const Dataset whole = readDataset(path);
  StreamOptions small;
  small.chunk_points = 4096;  // many chunks a scan
  const SubsampleResult r = subsampleDataset(path, SubsampleParams{0.5, 0}, small);
  EXPECT_EQ(r.points_read, 60000u);
  EXPECT_DOUBLE_EQ(r.voxel, 0.5);
  ASSERT_EQ(r.data.scans.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    SCOPED_TRACE(k);
    EXPECT_EQ(r.data.scans[k].name, whole.scans[k].name);
    EXPECT_TRUE(r.data.scans[k].pose.matrix().isApprox(whole.scans[k].pose.matrix()));
    EXPECT_TRUE(r.data.scans[k].cloud.hasIntensity());
    expectCentroids(r.data.scans[k].cloud, whole.scans[k].cloud, 0.5);
  }
  EXPECT_EQ(r.points_kept, r.data.pointCount());
  // At most the voxels a 6 x 4 x 3 m box can touch on a 0.5 m grid of any alignment, per scan.
  EXPECT_LE(r.points_kept, 2u * 13 * 9 * 7);
}

TEST(StreamSubsample, CoarseningOnTheWayIsTheCoarseSubsample) {
  const auto dir = test::scratchDir("stream_subsample_coarse");
  const auto path = dir / "two.e57";
  writeDataset(path, twoStations(30000));
  StreamOptions small;
  small.chunk_points = 4096;
  const SubsampleResult fine = subsampleDataset(path, SubsampleParams{0.125, 0}, small);
  ASSERT_GT(fine.points_kept, 1000u);
  // A limit below the fine subsample doubles the voxel until it fits: 0.125 -> 0.25 -> 0.5 ...
  const SubsampleResult limited = subsampleDataset(path, SubsampleParams{0.125, 1000}, small);
  EXPECT_LE(limited.points_kept, 1000u);
  EXPECT_GT(limited.voxel, 0.125);
  const SubsampleResult direct = subsampleDataset(path, SubsampleParams{limited.voxel, 0}, small);
  EXPECT_EQ(limited.points_kept, direct.points_kept);
  for (std::size_t k = 0; k < 2; ++k) {
    const PointCloud& a = limited.data.scans[k].cloud;
    const PointCloud& b = direct.data.scans[k].cloud;
    ASSERT_EQ(a.size(), b.size());
    double worst = 0;
    for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, (a.world(i) - b.world(i)).norm());
    EXPECT_LT(worst, 1e-5) << "scan " << k;  // same cells in the same order, same centroids
  }
}

TEST(StreamSubsample, PointCountComesFromTheHeader) {
  const auto dir = test::scratchDir("stream_point_count");
  writeDataset(dir / "two.e57", twoStations(5000));
  writeDataset(dir / "two.las", twoStations(5000));
  writeDataset(dir / "two.ply", twoStations(5000));
  for (const char* name : {"two.e57", "two.las", "two.ply"}) {
    const PointCountEstimate e = estimatePointCount(dir / name);
    EXPECT_EQ(e.points, 10000u) << name;
    EXPECT_TRUE(e.from_header) << name;
    EXPECT_FALSE(e.model) << name;
  }
}

}  // namespace
}  // namespace plumb
