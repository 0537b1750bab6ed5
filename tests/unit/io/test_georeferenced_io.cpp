// Georeferenced coordinates through every writer and reader (issue 12): Lambert-93 sized
// (x ~ 651,000, y ~ 6,860,000), a UTM northing above 2^23 (float32 step 1 m there) and a cloud
// 60 km wide must come back within the README claim, 0.1 mm (LAS and E57 integers: half their
// quantum). Readers must also choose a sensible offset when record 0 is NaN or (0,0,0).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "io/io.hpp"
#include "support/test_support.hpp"

using namespace plumb;

namespace {

constexpr double kClaim = 1e-4;  // README: coordinates survive to 0.1 mm
static_assert(kClaim == kCoordinatePrecision, "README claim and core constant differ");
constexpr double kQuantum = 1e-4;  // WriteOptions::scaled_precision default (E57, LAS)

/// n points over `span` metres around `centre` with sub-millimetre decimals (exact doubles).
std::vector<Eigen::Vector3d> survey(const Eigen::Vector3d& centre, double span, int n) {
  std::vector<Eigen::Vector3d> v;
  for (int i = 0; i < n; ++i) {
    const double f = static_cast<double>(i) / (n - 1) - 0.5;
    v.push_back(centre + Eigen::Vector3d(f * span + 0.123456 * (i % 7), f * span * 0.5 - 0.0654321 * (i % 5),
                                         0.0371 * (i % 11)));
  }
  return v;
}

/// A dataset holding exactly `truth` (offset chosen like a reader, residuals kept).
Dataset datasetOf(const std::vector<Eigen::Vector3d>& truth) {
  PointCloud c;
  c.offset = offsetFromSample(truth);
  c.positions.resize(truth.size());
  c.position_residuals.resize(truth.size());
  for (std::size_t i = 0; i < truth.size(); ++i) c.setLocal(i, truth[i] - c.offset);
  c.dropNegligibleResiduals();
  return Dataset::fromCloud(std::move(c));
}

/// Largest per-axis difference between the merged dataset and `truth`, point by point.
double maxError(const Dataset& d, const std::vector<Eigen::Vector3d>& truth) {
  const PointCloud c = d.merged();
  EXPECT_EQ(c.size(), truth.size());
  double e = 0;
  for (std::size_t i = 0; i < std::min(c.size(), truth.size()); ++i)
    e = std::max(e, (c.world(i) - truth[i]).cwiseAbs().maxCoeff());
  return e;
}

struct Case {
  const char* name;
  Eigen::Vector3d centre;
  double span;
};
const Case kCases[] = {{"lambert93", {651000.0, 6860000.0, 40.0}, 500.0},
                       {"utm_north", {512345.678, 9123456.789, 42.0}, 300.0},
                       {"span60km", {650000.0, 6860000.0, 40.0}, 60000.0}};

/// LAS and E57 integers: half their quantum (plus the 1 µm residuals a cloud may drop).
double tolerance(const std::string& ext) {
  return ext == ".las" || ext == ".e57" ? 0.5 * kQuantum + 3 * PointCloud::kResidualTolerance : kClaim;
}

}  // namespace

TEST(GeoreferencedIo, RoundTripThroughEveryFormat) {
  const auto dir = test::scratchDir("georeferenced_io");
  for (const Case& k : kCases) {
    const auto truth = survey(k.centre, k.span, 2001);
    const Dataset d = datasetOf(truth);
    for (const char* ext : {".ply", ".pcd", ".xyz", ".csv", ".e57", ".las"}) {
      const auto path = dir / (std::string(k.name) + ext);
      writeDataset(path, d);
      const double e = maxError(readDataset(path), truth);
      std::printf("[precision] %-10s %-5s max error %.3g m\n", k.name, ext, e);
      EXPECT_LE(e, tolerance(ext)) << k.name << ext;
    }
    WriteOptions ascii;
    ascii.binary = false;
    writeDataset(dir / (std::string(k.name) + "_ascii.ply"), d, ascii);
    EXPECT_LE(maxError(readDataset(dir / (std::string(k.name) + "_ascii.ply")), truth), kClaim) << k.name;
  }
}

TEST(GeoreferencedIo, SmallCloudsKeepFloatFilesAndExactValues) {
  const auto dir = test::scratchDir("georeferenced_small");
  const auto truth = survey({10.0, 20.0, 1.0}, 50.0, 101);
  Dataset d = datasetOf(truth);
  writeDataset(dir / "small.ply", d);
  EXPECT_NE(test::readAll(dir / "small.ply").find("property float x"), std::string::npos);
  const Dataset back = readDataset(dir / "small.ply");
  EXPECT_EQ(back.scans[0].cloud.offset, Eigen::Vector3d::Zero());
  EXPECT_LE(maxError(back, truth), 1e-5);  // float32 at 35 m: 2 µm step
}

TEST(GeoreferencedIo, MultiScanE57WithGridPosesMerges) {
  // Stations stored in their own frames, posed in Lambert-93 with rotations.
  const auto dir = test::scratchDir("georeferenced_e57_poses");
  Dataset d;
  std::vector<Eigen::Vector3d> truth;
  for (int k = 0; k < 3; ++k) {
    Scan s;
    s.name = "station " + std::to_string(k);
    s.pose = RigidTransform::fromYaw(0.3 + 0.7 * k, {651000.1234 + 35.0 * k, 6860000.5678 - 12.5 * k, 40.25});
    s.has_pose = true;
    for (const auto& p : survey({0.0, 0.0, 1.5}, 80.0, 301)) {
      const Eigen::Vector3f stored = p.cast<float>();
      s.cloud.positions.push_back(stored);
      truth.push_back(s.pose.apply(stored.cast<double>()));
    }
    d.scans.push_back(std::move(s));
  }
  writeDataset(dir / "stations.e57", d);
  const Dataset back = readDataset(dir / "stations.e57");
  ASSERT_EQ(back.scans.size(), 3u);
  const double e = maxError(back, truth);
  std::printf("[precision] e57 3 posed stations merged: max error %.3g m\n", e);
  EXPECT_LE(e, std::sqrt(3.0) * 0.5 * kQuantum + 1e-9);  // rotated quantum of the scan frame
  // Written again as one cloud (the writer merges the stations): compared with what was read.
  const PointCloud m = back.merged();
  std::vector<Eigen::Vector3d> read;
  for (std::size_t i = 0; i < m.size(); ++i) read.push_back(m.world(i));
  for (const char* ext : {".ply", ".pcd", ".xyz", ".las"}) {
    writeDataset(dir / (std::string("merged") + ext), back);
    EXPECT_LE(maxError(readDataset(dir / (std::string("merged") + ext)), read), tolerance(ext)) << ext;
  }
}

TEST(GeoreferencedIo, OddFirstRecordDoesNotDecideTheOffset) {
  const auto dir = test::scratchDir("georeferenced_first_record");
  const std::string rows = "5000000.1234 651000.5678 40.4321\n5000001.2345 651002.3456 41.5432\n";
  for (const char* first : {"nan nan nan\n", "0 0 0\n"}) {
    const std::string tag = first[0] == 'n' ? "nan" : "zero";
    test::writeAll(dir / (tag + ".ply"), "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\n"
                                         "property double y\nproperty double z\nend_header\n" +
                                             std::string(first) + rows);
    test::writeAll(dir / (tag + ".xyz"), std::string(first) + rows);
    test::writeAll(dir / (tag + ".pcd"), "VERSION .7\nFIELDS x y z\nSIZE 8 8 8\nTYPE F F F\nCOUNT 1 1 1\n"
                                         "WIDTH 3\nHEIGHT 1\nPOINTS 3\nDATA ascii\n" +
                                             std::string(first) + rows);
    // Binary PLY with the same records.
    std::string bin = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\n"
                      "property double y\nproperty double z\nend_header\n";
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double values[9] = {tag == "nan" ? nan : 0.0, tag == "nan" ? nan : 0.0, tag == "nan" ? nan : 0.0,
                              5000000.1234, 651000.5678, 40.4321, 5000001.2345, 651002.3456, 41.5432};
    bin.append(reinterpret_cast<const char*>(values), sizeof values);
    test::writeAll(dir / (tag + "_bin.ply"), bin);
    for (const char* ext : {".ply", "_bin.ply", ".xyz", ".pcd"}) {
      const PointCloud c = readDataset(dir / (tag + ext)).merged();
      const std::size_t base = c.size() == 2 ? 0 : 1;  // PCD drops the NaN record
      ASSERT_EQ(c.size() - base, 2u) << tag << ext;
      EXPECT_LE((c.world(base) - Eigen::Vector3d(5000000.1234, 651000.5678, 40.4321)).cwiseAbs().maxCoeff(), kClaim)
          << tag << ext << " offset " << c.offset.transpose();
      EXPECT_LE((c.world(base + 1) - Eigen::Vector3d(5000001.2345, 651002.3456, 41.5432)).cwiseAbs().maxCoeff(),
                kClaim)
          << tag << ext;
    }
  }
}
