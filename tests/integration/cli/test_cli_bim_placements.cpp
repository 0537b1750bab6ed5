// Scan-to-BIM placements a user must never get wrong (issue 14), the way a user runs them:
// `plumb-cli simulate` inside a real IFC, then `plumb-cli register` onto that IFC.
//   - duplex.ifc's upper stair: the same stair exists in the mirrored dwelling. The global
//     answer lies a floor too low and the free space rules it out; a copy of it is chosen, and
//     the copies of that chosen placement (the truth among them) must be searched too: the
//     answer is "ambiguous" with the truth listed, never usable in the other dwelling.
//   - AC20-FZK-Haus.ifc's 12.5 m2 room, symmetric but for its door and window, delivered in a
//     tilted scanner frame (not levelled): its up direction is estimated, so the room can be
//     placed upside down or turned onto itself, and the plane matching prefers the upside-down
//     placement here (53 m2 against 50 m2). Never usable there: placed on the truth, or
//     ambiguous with the truth among the candidates (found among the upside-down copies).
//     (Seen through its transparent windows the scan holds the terrain outside: the truth
//     explains 0.86 of it and the upside-down placement 0.83, not decisive.)
//   - IfcOpenHouse's single room under its 45-degree gable roof, in tilted scanner frames: the
//     walls and the two roof pitches are four directions 45 degrees apart about the ridge, and
//     the right up direction's plane matching is itself ambiguous between the truth and its
//     half turn. That runner-up must be refined too: placed within 0.05 degree and 1 cm.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include <fstream>
#include <iostream>
#include <utility>

#include "demo_truth.hpp"
#include "support/cli_runner.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;
using plumb::test::CliResult;
using plumb::test::plumbCli;
using plumb::test::readAll;
using plumb::test::scratchDir;
using plumb::test::shellQuote;
using plumb::test::transformOf;

namespace {

std::string sharedIfc(const std::string& name) {
  return shellQuote(plumb::test::sharedData("ifc/" + name).string());
}

plumb::test::RegistrationError errorAt(const fs::path& dir, const Eigen::Isometry3d& T,
                                       const Eigen::Vector3d& station) {
  return plumb::test::modelFrameError(plumb::test::readJson(dir / "sim/truth.json"), "indoor", T,
                                      {station + Eigen::Vector3d(2, 2, 0), station - Eigen::Vector3d(2, 2, 0)});
}

/// sim/indoor.e57 turned by `degrees` about `axis` (and shifted) into tilted.e57: a scanner
/// frame that is not levelled. Returns the tilt (tilted = tilt * original).
Eigen::Isometry3d writeTilted(const fs::path& dir, double degrees, const Eigen::Vector3d& axis) {
  Eigen::Isometry3d tilt = Eigen::Isometry3d::Identity();
  tilt.linear() = Eigen::AngleAxisd(degrees * M_PI / 180.0, axis.normalized()).toRotationMatrix();
  tilt.translation() = Eigen::Vector3d(3.0, -7.0, 2.0);
  {
    std::ofstream f(dir / "tilt.txt");
    f.precision(17);
    f << tilt.matrix() << "\n";
  }
  const CliResult conv = plumbCli(dir, "convert sim/indoor.e57 tilted.e57 --transform tilt.txt");
  EXPECT_EQ(conv.exit_code, 0) << conv.err;
  return tilt;
}

}  // namespace

TEST(CliBimPlacements, ADuplexStairIsNeverPlacedInTheMirroredDwelling) {
  const fs::path dir = scratchDir("cli_bim_placements");
  const std::string model = sharedIfc("duplex.ifc");
  const Eigen::Vector3d station(1.38, -5.31, 4.62);
  const CliResult sim = plumbCli(dir, "simulate --model " + model + " --tls 1.38,-5.31,4.62 --perturb 180,5 "
                                      "--seed 2 --tls-azimuth-step 0.5 --tls-elevation-step 0.5 -o sim");
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const CliResult r = plumbCli(dir, "register sim/indoor.e57 " + model + " --report R.json");
  EXPECT_EQ(r.exit_code, 2) << "must not be usable: the stair is repeated in the other dwelling\n" << r.err;
  const nlohmann::json report = nlohmann::json::parse(readAll(dir / "R.json"));
  EXPECT_EQ(report.at("status"), "ambiguous");
  double best_rotation = 1e9, best_translation = 1e9;
  for (const auto& c : report.at("candidates")) {
    const auto e = errorAt(dir, transformOf(c.at("transform")), station);
    if (e.translation_m < best_translation) best_rotation = e.rotation_deg, best_translation = e.translation_m;
  }
  std::cout << "closest candidate to the truth: " << best_rotation << " deg, " << best_translation * 1000 << " mm\n";
  EXPECT_LT(best_rotation, 0.05);
  EXPECT_LT(best_translation, 0.01);
}

TEST(CliBimPlacements, ATiltedScanOfASymmetricRoomIsNeverPlacedUpsideDownOrTurned) {
  const fs::path dir = scratchDir("cli_bim_placements");
  const std::string model = sharedIfc("AC20-FZK-Haus.ifc");
  const Eigen::Vector3d station(5.12, 8.12, 1.5);
  const CliResult sim = plumbCli(dir, "simulate --model " + model + " --tls 5.12,8.12,1.5 --perturb 180,5 "
                                      "--seed 3 --tls-azimuth-step 0.5 --tls-elevation-step 0.5 -o sim");
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  // The scanner frame tilted by 117 degrees about an oblique axis (not levelled, not Y-up).
  const Eigen::Isometry3d tilt = writeTilted(dir, 117.0, Eigen::Vector3d(1, 2, 3));
  const CliResult r = plumbCli(dir, "register tilted.e57 " + model + " --transform T.json --report R.json");
  EXPECT_NE(r.err.find("not levelled"), std::string::npos) << r.err;
  // A transform of the tilted scan composed with the tilt is one of the original scan.
  const auto error = [&](const Eigen::Isometry3d& T) { return errorAt(dir, T * tilt, station); };
  if (r.exit_code == 0) {
    const auto e = error(transformOf(plumb::test::readJson(dir / "T.json")["matrix"]));
    std::cout << "tilted FZK room placed: " << e.rotation_deg << " deg, " << e.translation_m * 1000 << " mm\n";
    EXPECT_LT(e.rotation_deg, 0.05);
    EXPECT_LT(e.translation_m, 0.01);
    return;
  }
  // Otherwise an honest failure: ambiguous, the truth among the candidates (an upside-down
  // copy searched too: the scan's up direction is only estimated).
  ASSERT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("upside down"), std::string::npos) << r.err;
  const nlohmann::json report = nlohmann::json::parse(readAll(dir / "R.json"));
  EXPECT_EQ(report.at("status"), "ambiguous");
  bool listed = false;
  for (const auto& c : report.at("candidates")) {
    const auto e = error(transformOf(c.at("transform")));
    listed = listed || (e.rotation_deg < 0.05 && e.translation_m < 0.01);
  }
  EXPECT_TRUE(listed) << "the truth is not among the candidates\n" << r.err;
}

TEST(CliBimPlacements, ATiltedRoomUnderAGableRoofIsPlaced) {
  const fs::path dir = scratchDir("cli_bim_placements_gable");
  const std::string model = sharedIfc("IfcOpenHouse_IFC4.ifc");
  const Eigen::Vector3d station(3.62, 1.12, 1.5);
  const CliResult sim = plumbCli(dir, "simulate --model " + model + " --tls 3.62,1.12,1.5 --perturb 180,5 "
                                      "--seed 3 --tls-azimuth-step 0.5 --tls-elevation-step 0.5 -o sim");
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  // Two of the tilts that came out "contradicted" before (session 18: 1 of 6 random tilts
  // placed), and one that put a roof pitch's normal 9 degrees from Z: taken as levelled under
  // the old 10-degree level tolerance, it failed (orientation.level-tolerance, now 3).
  const std::pair<double, Eigen::Vector3d> tilts[] = {{117.0, Eigen::Vector3d(1, 2, 3)},
                                                      {60.0, Eigen::Vector3d(1, 0, 0)},
                                                      {135.0, Eigen::Vector3d(0, 1, 1)}};
  for (const auto& [degrees, axis] : tilts) {
    const Eigen::Isometry3d tilt = writeTilted(dir, degrees, axis);
    const CliResult r = plumbCli(dir, "register tilted.e57 " + model + " --transform T.json");
    ASSERT_EQ(r.exit_code, 0) << degrees << " deg about (" << axis.transpose() << ")\n" << r.err;
    const auto e = errorAt(dir, transformOf(plumb::test::readJson(dir / "T.json")["matrix"]) * tilt, station);
    std::cout << "tilted " << degrees << " deg: " << e.rotation_deg << " deg, " << e.translation_m * 1000 << " mm\n";
    EXPECT_LT(e.rotation_deg, 0.05) << degrees;
    EXPECT_LT(e.translation_m, 0.01) << degrees;
  }
}
