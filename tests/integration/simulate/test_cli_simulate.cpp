// `plumb-cli simulate` end to end: files written, scans read back through the I/O layer lie
// on the ground-truth planes once truth.json's transform is applied, interior points are
// present in the outdoor scan, and errors are one line naming the problem.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

#include "io/io.hpp"
#include "simulation/ground_truth_json.hpp"
#include "support/cli_runner.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

double nearestPlane(const BuildingTruth& t, const Eigen::Vector3d& x) {
  double best = 1e30;
  for (const auto& p : t.planes) best = std::min(best, std::abs(p.normal.dot(x) - p.offset));
  return std::min(best, std::abs(x.z()));  // the ground
}

TEST(CliSimulate, WritesScansModelAndConsistentTruth) {
  const auto dir = test::scratchDir("cli-simulate");
  const test::CliResult sim = test::plumbCli(
      dir, "simulate --preset two-rooms --tls 2,2.5,1.5 --tls 6,2.5,1.5 --mms --mms-line-rate 10 "
           "--tls-azimuth-step 1 --tls-elevation-step 1 --perturb 40,3 --seed 5 --noise-mm 2 -o " +
               (dir / "out").string());
  ASSERT_EQ(sim.exit_code, 0) << sim.out << sim.err;
  for (const char* f : {"indoor.e57", "outdoor.e57", "model.ply", "model.obj", "ground_truth.json", "truth.json"})
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / f)) << f;
  const auto truth = nlohmann::json::parse(test::readAll(dir / "out" / "truth.json"));
  ASSERT_EQ(truth["datasets"].size(), 2u);
  EXPECT_EQ(truth["scans"].size(), 3u);
  const BuildingTruth gt = readBuildingTruth(dir / "out" / "ground_truth.json");

  for (const auto& d : truth["datasets"]) {
    SCOPED_TRACE(d["file"].get<std::string>());
    const RigidTransform t = transformFromJson(d["transform"].dump());
    Dataset data = readDataset(dir / "out" / d["file"].get<std::string>());
    EXPECT_EQ(data.scans.size(), d["scans"].size());
    PointCloud cloud = data.merged();
    EXPECT_EQ(cloud.size(), d["points"].get<std::size_t>());
    if (d["name"] == "indoor") {
      EXPECT_GT(t.rotationAngleDeg(), 0.01);  // it was moved
    }
    // Before applying the truth the indoor points are off the planes; after, on them.
    cloud.transform(t);
    std::size_t on = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i) on += nearestPlane(gt, cloud.world(i)) < 0.05;
    EXPECT_GT(static_cast<double>(on) / static_cast<double>(cloud.size()), 0.99);
  }
  const BimModel model = readModel(dir / "out" / "model.ply");
  EXPECT_EQ(model.mesh.triangleCount(), 1626u + 0u);  // two-rooms: see test_simulation
}

TEST(CliSimulate, SameSeedSameScans) {
  const auto dir = test::scratchDir("cli-simulate-seed");
  const std::string common = "simulate --preset non-manhattan --tls-rooms --tls-azimuth-step 2 --tls-elevation-step 2 --perturb 10,1 --format ply ";
  ASSERT_EQ(test::plumbCli(dir, common + "--seed 3 -o " + (dir / "a").string()).exit_code, 0);
  ASSERT_EQ(test::plumbCli(dir, common + "--seed 3 -o " + (dir / "b").string()).exit_code, 0);
  ASSERT_EQ(test::plumbCli(dir, common + "--seed 4 -o " + (dir / "c").string()).exit_code, 0);
  EXPECT_EQ(test::readAll(dir / "a" / "indoor.ply"), test::readAll(dir / "b" / "indoor.ply"));
  EXPECT_NE(test::readAll(dir / "a" / "indoor.ply"), test::readAll(dir / "c" / "indoor.ply"));
  EXPECT_EQ(test::readAll(dir / "a" / "truth.json"), test::readAll(dir / "b" / "truth.json"));
}

TEST(CliSimulate, ErrorsAreOneLine) {
  const auto dir = test::scratchDir("cli-simulate-errors");
  // Exit code, and what it printed (stdout then stderr) must contain `expected`.
  auto expectRun = [&dir](const std::string& args, bool ok, const std::string& expected) {
    const test::CliResult r = test::plumbCli(dir, args);
    EXPECT_EQ(r.exit_code == 0, ok) << args;
    EXPECT_NE((r.out + r.err).find(expected), std::string::npos) << args << ": " << r.out << r.err;
  };
  expectRun("simulate --preset castle --mms -o " + (dir / "x").string(), false, "castle");
  expectRun("simulate --preset house --tls 1,2 -o " + (dir / "x").string(), false, "--tls");
  expectRun("simulate --preset house -o " + (dir / "x").string(), false, "nothing to scan");
  expectRun("simulate --list-presets", true, "non-manhattan");
}

// Issue 12: every numeric option is range-checked before any work, and the error names the
// option and the accepted range. On main `--tls nan,nan,nan` and `--tls 1e308,0,0` aborted
// inside Embree; a negative or absurd --noise-mm and seeds -1 or 1.5 were accepted.
TEST(CliSimulate, NumericOptionsOutsideTheirRangeAreRefused) {
  const auto dir = test::scratchDir("cli-simulate-ranges");
  const std::string base = "simulate --preset two-rooms -o " + (dir / "x").string() + " ";
  struct Case {
    const char* args;
    const char* option;
    const char* range;
  };
  const Case cases[] = {{"--tls nan,nan,nan", "--tls:", "[-1e+07, 1e+07]"},
                        {"--tls 1e308,0,0", "--tls:", "[-1e+07, 1e+07]"},
                        {"--tls 2,2,inf", "--tls:", "[-1e+07, 1e+07]"},
                        {"--tls 2,2,1.5 --noise-mm -1", "--noise-mm:", "[0, 100]"},
                        {"--tls 2,2,1.5 --noise-mm 1e9", "--noise-mm:", "[0, 100]"},
                        {"--tls 2,2,1.5 --noise-mm nan", "--noise-mm:", "[0, 100]"},
                        {"--tls 2,2,1.5 --seed -1", "--seed:", "[0, 9e+15]"},
                        {"--tls 2,2,1.5 --seed 1.5", "--seed:", "whole number"},
                        {"--tls 2,2,1.5 --perturb nan,1", "--perturb:", "[0, 180]"},
                        {"--tls 2,2,1.5 --perturb 10,-1", "--perturb:", "[0, 1000]"},
                        {"--tls 2,2,1.5 --tls-noise-mm 1e308", "tls-noise-mm", "[0, 100]"}};
  for (const Case& c : cases) {
    const test::CliResult r = test::plumbCli(dir, base + c.args);
    EXPECT_EQ(r.exit_code, 1) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.option), std::string::npos) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.range), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x")) << c.args << ": nothing may be written";
  }
}

}  // namespace
}  // namespace plumb
