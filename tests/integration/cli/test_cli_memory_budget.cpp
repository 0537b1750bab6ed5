// plumb-cli register above the memory budget (issue 16): with a budget far below the file's
// whole-file cost the source is registered on a voxel subsample built while streaming, and
// -o streams the full-resolution file again with the transform applied. The verdict and the
// transform must be those of the whole-file registration (0.01 degree, 2 mm at the rooms).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include "demo_truth.hpp"
#include "support/cli_runner.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;
using plumb::test::CliResult;
using plumb::test::plumbCli;
using plumb::test::readAll;
using plumb::test::scratchDir;
using plumb::test::transformOf;

namespace {

Eigen::Isometry3d transformFile(const fs::path& p) {
  return transformOf(nlohmann::json::parse(readAll(p)).at("matrix"));
}

/// Largest displacement between two transforms over the scanned rooms' extent.
double worstShift(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, const Eigen::Isometry3d& truth) {
  double worst = 0;
  for (const Eigen::Vector3d& x : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 8, 3), Eigen::Vector3d(10, 0, 0),
                                   Eigen::Vector3d(0, 8, 3)}) {
    const Eigen::Vector3d p = truth.inverse() * x;  // the data point that belongs at model point x
    worst = std::max(worst, (a * p - b * p).norm());
  }
  return worst;
}

}  // namespace

TEST(CliMemoryBudget, TinyBudgetRegistersTheSubsampleLikeTheWholeFile) {
  const fs::path dir = scratchDir("cli_memory_budget");
  const CliResult sim = plumbCli(dir, "simulate --preset house --tls-rooms --perturb 40,5 --seed 5 "
                                      "--tls-azimuth-step 0.3 --tls-elevation-step 0.3 -o sim");
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const auto truth = nlohmann::json::parse(readAll(dir / "sim/truth.json"));
  const Eigen::Isometry3d expected = transformOf(truth.at("datasets").at(0).at("transform").at("matrix"));

  const CliResult whole = plumbCli(dir, "register sim/indoor.e57 sim/model.ply --seed 3 --memory-budget 100000 "
                                        "--transform T0.json --report R0.json -o whole.e57");
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  EXPECT_EQ(whole.err.find("exceed the memory budget"), std::string::npos) << whole.err;

  const CliResult streamed = plumbCli(dir, "register sim/indoor.e57 sim/model.ply --seed 3 --memory-budget 1 "
                                           "--transform T1.json --report R1.json -o streamed.e57");
  ASSERT_EQ(streamed.exit_code, 0) << streamed.err;
  EXPECT_NE(streamed.err.find("exceed the memory budget (1 MB): registering a"), std::string::npos) << streamed.err;

  const auto r0 = nlohmann::json::parse(readAll(dir / "R0.json"));
  const auto r1 = nlohmann::json::parse(readAll(dir / "R1.json"));
  EXPECT_EQ(r1.at("verdict_level"), r0.at("verdict_level"));
  EXPECT_EQ(r1.at("method"), r0.at("method"));
  const Eigen::Isometry3d t0 = transformFile(dir / "T0.json"), t1 = transformFile(dir / "T1.json");
  const double rotation_deg = Eigen::AngleAxisd(t0.linear().transpose() * t1.linear()).angle() * 180 / M_PI;
  EXPECT_LT(rotation_deg, 0.01);
  EXPECT_LT(worstShift(t0, t1, expected), 0.002);

  // -o of the streamed route: the full-resolution file (every point, every scan), as written
  // by the whole-file route.
  const CliResult info0 = plumbCli(dir, "info whole.e57 --json");
  const CliResult info1 = plumbCli(dir, "info streamed.e57 --json");
  ASSERT_EQ(info0.exit_code, 0) << info0.err;
  ASSERT_EQ(info1.exit_code, 0) << info1.err;
  const auto j0 = nlohmann::json::parse(info0.out).at(0), j1 = nlohmann::json::parse(info1.out).at(0);
  EXPECT_EQ(j1.at("points"), j0.at("points"));
  EXPECT_EQ(j1.at("scans").size(), j0.at("scans").size());
  const CliResult src = plumbCli(dir, "info sim/indoor.e57 --json");
  EXPECT_EQ(nlohmann::json::parse(src.out).at(0).at("points"), j1.at("points"));
}

// convert and info refuse to read a file whole above the budget, naming the file and the
// budget, instead of exhausting the machine; a bad budget names the option.
TEST(CliMemoryBudget, WholeFileReadsAboveTheBudgetAreRefused) {
  const fs::path dir = scratchDir("cli_memory_budget_refuse");
  std::string ply = "ply\nformat ascii 1.0\nelement vertex 30000\nproperty float x\nproperty float y\n"
                    "property float z\nend_header\n";
  for (int i = 0; i < 30000; ++i) ply += std::to_string(i % 100) + " " + std::to_string(i / 100) + " 0\n";
  plumb::test::writeAll(dir / "p.ply", ply);
  const CliResult ok = plumbCli(dir, "convert p.ply p.xyz --memory-budget 100");
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  const CliResult bad = plumbCli(dir, "convert p.ply p2.xyz --memory-budget 0.5");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("p.ply"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("above the memory budget"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir / "p2.xyz"));
  const CliResult range = plumbCli(dir, "info p.ply --memory-budget=-3");
  EXPECT_EQ(range.exit_code, 1);
  EXPECT_NE(range.err.find("--memory-budget"), std::string::npos) << range.err;
}
