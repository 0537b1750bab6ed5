// `plumb-cli simulate` end to end: files written, scans read back through the I/O layer lie
// on the ground-truth planes once truth.json's transform is applied, interior points are
// present in the outdoor scan, and errors are one line naming the problem.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "io/io.hpp"
#include "simulation/ground_truth_json.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

int runCli(const std::string& args, const std::filesystem::path& log) {
  const std::string cmd = std::string(PLUMB_CLI_PATH) + " " + args + " > " + log.string() + " 2>&1";
  return WEXITSTATUS(std::system(cmd.c_str()));
}

double nearestPlane(const BuildingTruth& t, const Eigen::Vector3d& x) {
  double best = 1e30;
  for (const auto& p : t.planes) best = std::min(best, std::abs(p.normal.dot(x) - p.offset));
  return std::min(best, std::abs(x.z()));  // the ground
}

TEST(CliSimulate, WritesScansModelAndConsistentTruth) {
  const auto dir = test::scratchDir("cli-simulate");
  ASSERT_EQ(runCli("simulate --preset two-rooms --tls 2,2.5,1.5 --tls 6,2.5,1.5 --mms --mms-line-rate 10 "
                   "--tls-azimuth-step 1 --tls-elevation-step 1 --perturb 40,3 --seed 5 --noise-mm 2 -o " +
                       (dir / "out").string(),
                   dir / "log.txt"),
            0)
      << test::readAll(dir / "log.txt");
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
    if (d["name"] == "indoor") EXPECT_GT(t.rotationAngleDeg(), 0.01);  // it was moved
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
  ASSERT_EQ(runCli(common + "--seed 3 -o " + (dir / "a").string(), dir / "a.txt"), 0);
  ASSERT_EQ(runCli(common + "--seed 3 -o " + (dir / "b").string(), dir / "b.txt"), 0);
  ASSERT_EQ(runCli(common + "--seed 4 -o " + (dir / "c").string(), dir / "c.txt"), 0);
  EXPECT_EQ(test::readAll(dir / "a" / "indoor.ply"), test::readAll(dir / "b" / "indoor.ply"));
  EXPECT_NE(test::readAll(dir / "a" / "indoor.ply"), test::readAll(dir / "c" / "indoor.ply"));
  EXPECT_EQ(test::readAll(dir / "a" / "truth.json"), test::readAll(dir / "b" / "truth.json"));
}

TEST(CliSimulate, ErrorsAreOneLine) {
  const auto dir = test::scratchDir("cli-simulate-errors");
  EXPECT_NE(runCli("simulate --preset castle --mms -o " + (dir / "x").string(), dir / "e1.txt"), 0);
  EXPECT_NE(test::readAll(dir / "e1.txt").find("castle"), std::string::npos);
  EXPECT_NE(runCli("simulate --preset house --tls 1,2 -o " + (dir / "x").string(), dir / "e2.txt"), 0);
  EXPECT_NE(test::readAll(dir / "e2.txt").find("--tls"), std::string::npos);
  EXPECT_NE(runCli("simulate --preset house -o " + (dir / "x").string(), dir / "e3.txt"), 0);
  EXPECT_NE(test::readAll(dir / "e3.txt").find("nothing to scan"), std::string::npos);
  EXPECT_EQ(runCli("simulate --list-presets", dir / "list.txt"), 0);
  EXPECT_NE(test::readAll(dir / "list.txt").find("non-manhattan"), std::string::npos);
}

}  // namespace
}  // namespace plumb
