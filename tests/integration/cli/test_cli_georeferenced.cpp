// plumb-cli keeps georeferenced coordinates (issue 12): `convert --transform` with a pose in
// the grid, and `convert` merging an E57 whose stations are posed in the grid, must write
// every point within the README claim, 0.1 mm (LAS: half its 0.1 mm quantum). Each is run in
// Lambert-93, at a UTM northing above 2^23 (float32 steps by 1 m there) and over 60 km.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "io/io.hpp"
#include "support/cli_runner.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;
using namespace plumb;
using plumb::test::CliResult;
using plumb::test::plumbCli;
using plumb::test::scratchDir;
using plumb::test::shellQuote;
using plumb::test::writeAll;

namespace {

constexpr double kClaim = 1e-4;  // README: coordinates survive to 0.1 mm
static_assert(kClaim == kCoordinatePrecision, "README claim and core constant differ");

/// Points of a station `width` metres wide with millimetre decimals, in its own frame.
std::vector<Eigen::Vector3d> station(int n, double width = 60.0) {
  std::vector<Eigen::Vector3d> v;
  for (int i = 0; i < n; ++i)
    v.push_back({-width / 2 + width * i / (n - 1) + 0.001 * (i % 7), 12.345 - 0.25 * (i % 13), 1.5 + 0.01 * (i % 17)});
  return v;
}

/// Where the data sits: a grid origin, the station width and the spacing between stations.
struct GridCase {
  const char* name;
  Eigen::Vector3d origin;
  double width;    ///< metres covered by one station
  double spacing;  ///< metres between merged stations (x and y)
};

const GridCase kCases[] = {
    {"Lambert-93", {651000.1234, 6860000.5678, 40.25}, 60.0, 40.0},
    {"UTM northing above 2^23", {500000.1234, 9123456.7891, 40.25}, 60.0, 40.0},
    {"60 km extent", {651000.1234, 6860000.5678, 40.25}, 60000.0, 20000.0},
};

double maxError(const fs::path& file, const std::vector<Eigen::Vector3d>& truth) {
  const PointCloud c = readDataset(file).merged();
  EXPECT_EQ(c.size(), truth.size()) << file;
  double e = 0;
  for (std::size_t i = 0; i < std::min(c.size(), truth.size()); ++i)
    e = std::max(e, (c.world(i) - truth[i]).cwiseAbs().maxCoeff());
  std::printf("[precision] %s: max error %.3g m\n", file.filename().c_str(), e);
  return e;
}

/// LAS integers: half the 0.1 mm quantum (plus the 1 µm residuals a cloud may drop).
double tolerance(const std::string& ext) { return ext == ".las" ? 0.5e-4 + 3 * PointCloud::kResidualTolerance : kClaim; }

void convertWithTransform(const GridCase& g) {
  const fs::path dir = scratchDir(std::string("cli_georeferenced_transform_") + std::to_string(&g - kCases));
  const auto local = station(500, g.width);
  std::ostringstream ply;
  ply.precision(17);
  ply << "ply\nformat ascii 1.0\nelement vertex " << local.size()
      << "\nproperty double x\nproperty double y\nproperty double z\nend_header\n";
  for (const auto& p : local) ply << p.x() << " " << p.y() << " " << p.z() << "\n";
  writeAll(dir / "station.ply", ply.str());
  const RigidTransform t = RigidTransform::fromYaw(0.5, g.origin);
  writeTransformFile(dir / "T.json", t);
  std::vector<Eigen::Vector3d> truth;
  for (const auto& p : local) truth.push_back(t.apply(p));
  for (const std::string ext : {".ply", ".xyz", ".pcd", ".las", ".e57"}) {
    const CliResult r = plumbCli(dir, "convert station.ply moved" + ext + " --transform T.json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_LE(maxError(dir / ("moved" + ext), truth), tolerance(ext)) << ext;
  }
}

void convertGridPosedStations(const GridCase& g) {
  const fs::path dir = scratchDir(std::string("cli_georeferenced_merge_") + std::to_string(&g - kCases));
  Dataset d;
  std::vector<Eigen::Vector3d> truth;
  for (int k = 0; k < 3; ++k) {
    Scan s;
    s.name = "station" + std::to_string(k);
    s.pose = RigidTransform::fromYaw(0.2 + 0.9 * k, g.origin + Eigen::Vector3d(g.spacing * k, 0.4 * g.spacing * k, 0));
    s.has_pose = true;
    for (const auto& p : station(400, g.width)) {
      const Eigen::Vector3f stored = p.cast<float>();
      s.cloud.positions.push_back(stored);
      truth.push_back(s.pose.apply(stored.cast<double>()));
    }
    d.scans.push_back(std::move(s));
  }
  WriteOptions exact;
  exact.e57_float_positions = true;  // the stations' float coordinates exactly
  writeDataset(dir / "stations.e57", d, exact);
  for (const std::string ext : {".ply", ".xyz", ".pcd", ".las"}) {
    const CliResult r = plumbCli(dir, "convert stations.e57 merged" + ext);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_LE(maxError(dir / ("merged" + ext), truth), tolerance(ext)) << ext;
  }
}

}  // namespace

TEST(CliGeoreferenced, ConvertWithLargeTranslationTransform) {
  for (const GridCase& g : kCases) {
    SCOPED_TRACE(g.name);
    convertWithTransform(g);
  }
}

TEST(CliGeoreferenced, ConvertMergesGridPosedE57Stations) {
  for (const GridCase& g : kCases) {
    SCOPED_TRACE(g.name);
    convertGridPosedStations(g);
  }
}

TEST(CliGeoreferenced, RegisterOutputOntoAGridModel) {
  // Scan to BIM where the model sits in Lambert-93: the registered export (`register -o`)
  // must be the transform of the scan's points, without float rounding at 6.86e6.
  const fs::path dir = scratchDir("cli_georeferenced_register");
  const CliResult sim = plumbCli(dir, "simulate --preset house --tls-rooms --perturb 180,15 --seed 5 "
                                      "--tls-azimuth-step 0.6 --tls-elevation-step 0.6 -o sim");
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  writeTransformFile(dir / "G.json", RigidTransform(Eigen::Matrix3d::Identity(), {651000.1234, 6860000.5678, 40.25}));
  CliResult r = plumbCli(dir, "convert sim/model.ply grid_model.ply --transform G.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = plumbCli(dir, "register sim/indoor.e57 grid_model.ply --seed 3 --transform T.json -o registered.ply");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const RigidTransform t = readTransformFile(dir / "T.json");
  EXPECT_GT(t.translation().norm(), 6e6);
  const PointCloud scan = readDataset(dir / "sim/indoor.e57").merged();
  std::vector<Eigen::Vector3d> truth;
  for (std::size_t i = 0; i < scan.size(); ++i) truth.push_back(t.apply(scan.world(i)));
  EXPECT_LE(maxError(dir / "registered.ply", truth), kClaim);
}
