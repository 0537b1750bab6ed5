// A mobile scan from another tool (LAS: GPS time per point, no sensor origins) plus the
// vehicle trajectory as a separate file: `plumb-cli simulate --demo` writes trajectory.txt,
// `convert outdoor.e57 outdoor.las` drops the per-point origins (LAS has no field for them)
// and keeps the times; `register indoor.e57 outdoor.las` then fails (the openings method
// cannot ray-trace without origins: wall thickness not measured), and succeeds with
// `--target-trajectory trajectory.txt` within 0.1 deg / 2 cm of truth.json.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "support/cli_runner.hpp"
#include "demo_truth.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;
using plumb::test::CliResult;
using plumb::test::indoorOutdoorError;
using plumb::test::plumbCli;
using plumb::test::readAll;
using plumb::test::readJson;
using plumb::test::scratchDir;
using plumb::test::transformOf;
using plumb::test::writeAll;

namespace {

/// "t x y z" lines of a trajectory file (comments skipped).
std::vector<std::array<double, 4>> trajectoryLines(const fs::path& p) {
  std::vector<std::array<double, 4>> rows;
  std::istringstream in(readAll(p));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    std::array<double, 4> r{};
    for (auto& v : r) ss >> v;
    EXPECT_FALSE(ss.fail()) << line;
    rows.push_back(r);
  }
  return rows;
}

}  // namespace

TEST(CliTrajectory, LasWithoutOriginsRegistersWithTheTrajectoryFile) {
  const fs::path dir = scratchDir("cli_trajectory");
  const CliResult sim = plumbCli(dir, "simulate --demo -o demo");
  ASSERT_EQ(sim.exit_code, 0) << sim.err;

  // simulate wrote the trajectory it drove and lists it in truth.json.
  const nlohmann::json truth = readJson(dir / "demo" / "truth.json");
  ASSERT_TRUE(truth.contains("trajectory")) << truth.dump();
  EXPECT_EQ(truth.at("trajectory").at("file"), "trajectory.txt");
  const auto rows = trajectoryLines(dir / "demo" / "trajectory.txt");
  ASSERT_GE(rows.size(), 4u);
  EXPECT_EQ(rows.size(), truth.at("trajectory").at("samples").get<std::size_t>());
  for (std::size_t i = 1; i < rows.size(); ++i) EXPECT_GT(rows[i][0], rows[i - 1][0]) << i;
  EXPECT_NEAR(rows.front()[1], rows.back()[1], 1e-9);  // a closed loop around the house
  EXPECT_NEAR(rows.front()[2], rows.back()[2], 1e-9);

  // LAS keeps the GPS times but not the sensor origins.
  const CliResult conv = plumbCli(dir, "convert demo/outdoor.e57 demo/outdoor.las");
  ASSERT_EQ(conv.exit_code, 0) << conv.err;
  const CliResult info = plumbCli(dir, "info demo/outdoor.las");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("timestamp"), std::string::npos) << info.out;
  EXPECT_EQ(info.out.find("sensor_x"), std::string::npos) << info.out;

  // Without origins: fails, writes nothing.
  const CliResult bare = plumbCli(dir, "register demo/indoor.e57 demo/outdoor.las --transform T0.json -o reg0.e57");
  EXPECT_NE(bare.exit_code, 0) << bare.out;
  EXPECT_NE(bare.err.find("registration failed"), std::string::npos) << bare.err;
  EXPECT_FALSE(fs::exists(dir / "T0.json"));
  EXPECT_FALSE(fs::exists(dir / "reg0.e57"));

  // With the trajectory: the origins come back, the registration meets the demo's accuracy.
  const CliResult reg = plumbCli(dir, "register demo/indoor.e57 demo/outdoor.las --target-trajectory "
                                      "demo/trajectory.txt --transform T.json --report R.json");
  ASSERT_EQ(reg.exit_code, 0) << reg.err;
  const auto err = indoorOutdoorError(dir / "demo", transformOf(readJson(dir / "T.json").at("matrix")));
  std::printf("with --target-trajectory: rotation error %.4f deg, translation error %.4f m (worst outline corner)\n",
              err.rotation_deg, err.translation_m);
  EXPECT_LT(err.rotation_deg, 0.1);
  EXPECT_LT(err.translation_m, 0.02);
  ASSERT_GT(err.corners, 0u);
  const nlohmann::json report = readJson(dir / "R.json");
  EXPECT_EQ(report.at("method"), "openings");
  EXPECT_EQ(report.at("figures").at("wall thickness measured").get<double>(), 1.0);

  // A trajectory on another time base (GPS week seconds vs time since start): a clear error.
  {
    std::ostringstream shifted;
    shifted.precision(17);
    for (const auto& r : rows) shifted << r[0] + 345600.0 << " " << r[1] << " " << r[2] << " " << r[3] << "\n";
    writeAll(dir / "shifted.txt", shifted.str());
  }
  const CliResult mismatch = plumbCli(dir, "register demo/indoor.e57 demo/outdoor.las --target-trajectory "
                                           "shifted.txt --transform T1.json");
  EXPECT_EQ(mismatch.exit_code, 1);
  EXPECT_NE(mismatch.err.find("shifted.txt"), std::string::npos) << mismatch.err;
  EXPECT_NE(mismatch.err.find("outside the trajectory's time range"), std::string::npos) << mismatch.err;
  EXPECT_FALSE(fs::exists(dir / "T1.json"));

  // A trajectory for a model side is refused.
  const CliResult model = plumbCli(dir, "register demo/model.ply demo/outdoor.las --source-trajectory "
                                        "demo/trajectory.txt --transform T2.json");
  EXPECT_EQ(model.exit_code, 1);
  EXPECT_NE(model.err.find("is a model"), std::string::npos) << model.err;
  EXPECT_FALSE(fs::exists(dir / "T2.json"));
}
