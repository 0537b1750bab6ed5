// The README's demo, the way a user runs it: `plumb-cli simulate --demo` (4 perturbed TLS
// stations inside the house, one MMS loop outside, written as E57 files), then
// `plumb-cli register indoor.e57 outdoor.e57` (openings method, 2023 §III). Checks the
// transform against truth.json (rotation < 0.1 deg, translation < 2 cm at the building's
// corners), the measured wall thickness against the house's exterior walls
// (ground_truth.json), and the registered E57 (4 scans, all points).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <regex>

#include "cli_runner.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;
using plumb::test::CliResult;
using plumb::test::plumbCli;
using plumb::test::readAll;
using plumb::test::scratchDir;

namespace {

nlohmann::json readJson(const fs::path& p) { return nlohmann::json::parse(readAll(p)); }

Eigen::Isometry3d transformOf(const nlohmann::json& matrix) {
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = matrix.at(r).at(c).get<double>();
  return Eigen::Isometry3d(m);
}

/// truth.json: the transform mapping dataset `name` back to the model frame.
Eigen::Isometry3d truthOf(const nlohmann::json& truth, const std::string& name) {
  for (const auto& d : truth.at("datasets"))
    if (d.at("name") == name) return transformOf(d.at("transform").at("matrix"));
  ADD_FAILURE() << "truth.json has no dataset '" << name << "'";
  return Eigen::Isometry3d::Identity();
}

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

TEST(CliIndoorOutdoor, DemoIndoorRegistersOntoOutdoor) {
  const fs::path dir = scratchDir("cli_indoor_outdoor");
  const auto t0 = std::chrono::steady_clock::now();
  const CliResult sim = plumbCli(dir, "simulate --demo -o demo");
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const double t_sim = seconds(t0);

  // The MMS trajectory (per-point sensor origins) survives the E57 file: the openings'
  // ray tracing needs it on the outdoor side.
  const CliResult info_out = plumbCli(dir, "info demo/outdoor.e57");
  ASSERT_EQ(info_out.exit_code, 0) << info_out.err;
  EXPECT_NE(info_out.out.find("sensor_x sensor_y sensor_z"), std::string::npos) << info_out.out;

  const auto t1 = std::chrono::steady_clock::now();
  const CliResult reg = plumbCli(dir, "register demo/indoor.e57 demo/outdoor.e57 --transform T.json "
                                      "--report R.json -o registered.e57");
  const double t_reg = seconds(t1);
  ASSERT_EQ(reg.exit_code, 0) << reg.err;
  std::printf("simulate %.1f s, register %.1f s\n", t_sim, t_reg);

  // Expected indoor -> outdoor: indoor -> model, then model -> outdoor.
  const nlohmann::json truth = readJson(dir / "demo" / "truth.json");
  const Eigen::Isometry3d expected = truthOf(truth, "outdoor").inverse() * truthOf(truth, "indoor");
  const Eigen::Isometry3d T = transformOf(readJson(dir / "T.json").at("matrix"));
  const double rot_deg =
      Eigen::AngleAxisd(T.linear() * expected.linear().transpose()).angle() * 180.0 / M_PI;

  // Translation error at the building's outline corners (ground and eaves), in the indoor
  // frame: the worst place of the whole building, not only its centre.
  const nlohmann::json gt = readJson(dir / "demo" / "ground_truth.json");
  const Eigen::Isometry3d model_to_indoor = truthOf(truth, "indoor").inverse();
  double trans_m = 0.0;
  for (const auto& v : gt.at("footprint"))
    for (double z : {0.0, 3.0}) {
      const Eigen::Vector3d p = model_to_indoor * Eigen::Vector3d(v.at(0).get<double>(), v.at(1).get<double>(), z);
      trans_m = std::max(trans_m, (T * p - expected * p).norm());
    }
  std::printf("rotation error %.4f deg, translation error %.4f m (worst outline corner)\n", rot_deg, trans_m);
  EXPECT_LT(rot_deg, 0.1);
  EXPECT_LT(trans_m, 0.02);
  ASSERT_FALSE(gt.at("footprint").empty());

  // The report: openings method with the wall thickness measured (not assumed).
  const nlohmann::json report = readJson(dir / "R.json");
  EXPECT_TRUE(report.at("success").get<bool>());
  EXPECT_EQ(report.at("method"), "openings");
  const auto& figures = report.at("figures");
  EXPECT_EQ(figures.at("wall thickness measured").get<double>(), 1.0);
  const double wall = gt.at("exterior_wall_thickness").get<double>();
  const double thickness = figures.at("wall thickness (m)").get<double>();
  std::printf("wall thickness %.4f m (house exterior walls %.3f m)\n", thickness, wall);
  EXPECT_NEAR(thickness, wall, 0.02);

  // The registered E57: the 4 indoor scans, every point.
  const CliResult info_in = plumbCli(dir, "info demo/indoor.e57");
  const CliResult info_reg = plumbCli(dir, "info registered.e57");
  ASSERT_EQ(info_reg.exit_code, 0) << info_reg.err;
  const std::regex scans(R"(\n  scans:\s+(\d+)\n  points:\s+(\d+))");
  std::smatch m_in, m_reg;
  ASSERT_TRUE(std::regex_search(info_in.out, m_in, scans)) << info_in.out;
  ASSERT_TRUE(std::regex_search(info_reg.out, m_reg, scans)) << info_reg.out;
  EXPECT_EQ(m_reg[1].str(), "4");
  EXPECT_EQ(m_reg[2].str(), m_in[2].str());
}
