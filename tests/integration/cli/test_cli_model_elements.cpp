// plumb-cli register --model-elements (issue 14, registration on chosen elements): a simulated
// scan of the generated L-shaped building registered onto its walls and slabs only lands on
// the truth, and the reports say what the registration rests on; walls alone leave the height
// free and fail as degenerate; a filter naming nothing in the model is a one-line error.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include <iostream>

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

/// The simulated scan of the L-shaped preset, moved by a random yaw and shift (truth.json), in
/// the test case's own folder (scratchDir).
fs::path simulatedScan() {
  const fs::path dir = scratchDir("cli_model_elements");
  const CliResult sim = plumbCli(dir, "simulate --preset l-shaped --tls-rooms --perturb 180,15 --seed 5 "
                                "--tls-azimuth-step 0.6 --tls-elevation-step 0.6 -o sim");
  EXPECT_EQ(sim.exit_code, 0) << sim.err;
  return dir;
}

/// The registration written to dir/T.json lands within the bar (0.05 deg, 1 cm) of
/// sim/truth.json at the model points `corners`; prints the errors after `what`.
void expectOnTruth(const fs::path& dir, const std::vector<Eigen::Vector3d>& corners, const std::string& what) {
  const plumb::test::RegistrationError e = plumb::test::modelFrameError(
      plumb::test::readJson(dir / "sim/truth.json"), "indoor", transformOf(plumb::test::readJson(dir / "T.json")["matrix"]),
      corners);
  EXPECT_LT(e.rotation_deg, 0.05);
  EXPECT_LT(e.translation_m, 0.01);
  std::cout << what << ": rotation error " << e.rotation_deg << " deg, translation error "
            << e.translation_m * 1000 << " mm\n";
}

std::vector<std::string> usedTypes(const nlohmann::json& selection) {
  std::vector<std::string> types;
  for (const auto& u : selection.at("used")) types.push_back(u.at("type"));
  return types;
}

}  // namespace

TEST(CliModelElements, WallsAndSlabsRegisterAndTheReportNamesThem) {
  const fs::path dir = simulatedScan();
  const CliResult r = plumbCli(dir, "register sim/indoor.e57 sim/model.ply --model-elements IfcWall,IfcSlab "
                              "--transform T.json --report R.json --report R.html");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("restricted to types IfcWall, IfcSlab: 15 of 28 elements"), std::string::npos) << r.err;
  // At two far corners of the L's rooms.
  expectOnTruth(dir, {Eigen::Vector3d(2, 2, 1.5), Eigen::Vector3d(10, 8, 1.5)}, "walls+slabs");
  const auto selection = nlohmann::json::parse(readAll(dir / "R.json")).at("model_elements");
  EXPECT_EQ(selection.at("filter").at("types"), (std::vector<std::string>{"IfcWall", "IfcSlab"}));
  EXPECT_EQ(usedTypes(selection), (std::vector<std::string>{"IfcSlab", "IfcWall"}));
  EXPECT_EQ(selection.at("elements_used"), 15);
  EXPECT_EQ(selection.at("elements_in_model"), 28);
  EXPECT_LT(selection.at("triangles_used").get<int>(), selection.at("triangles_in_model").get<int>());
  const std::string html = readAll(dir / "R.html");
  EXPECT_NE(html.find("Registration rests on"), std::string::npos);
  EXPECT_NE(html.find("restricted to types IfcWall, IfcSlab: 15 of 28 elements"), std::string::npos);
}

TEST(CliModelElements, WallsAloneLeaveTheHeightFree) {
  const fs::path dir = simulatedScan();
  const CliResult r = plumbCli(dir, "register sim/indoor.e57 sim/model.ply --model-elements IfcWall --report R.json");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("translation along vertical"), std::string::npos) << r.err;
  const auto selection = nlohmann::json::parse(readAll(dir / "R.json")).at("model_elements");
  EXPECT_EQ(usedTypes(selection), (std::vector<std::string>{"IfcWall"}));
}

TEST(CliModelElements, FilterMatchingNothingIsAnError) {
  const fs::path dir = simulatedScan();
  const CliResult type = plumbCli(dir, "register sim/indoor.e57 sim/model.ply --model-elements IfcColumn "
                                 "--transform T.json");
  EXPECT_EQ(type.exit_code, 1);
  EXPECT_NE(type.err.find("sim/model.ply: no element of type 'IfcColumn' (the model has IfcDoor, IfcSlab, "
                          "IfcWall, IfcWindow)"), std::string::npos) << type.err;
  EXPECT_FALSE(fs::exists(dir / "T.json"));
  const CliResult id = plumbCli(dir, "register sim/indoor.e57 sim/model.ply --model-element-ids no-such-id");
  EXPECT_EQ(id.exit_code, 1);
  EXPECT_NE(id.err.find("no element has the GlobalId or name 'no-such-id'"), std::string::npos) << id.err;
  const CliResult cloud = plumbCli(dir, "register sim/model.ply sim/indoor.e57 --model-elements IfcWall");
  EXPECT_EQ(cloud.exit_code, 1);
  EXPECT_NE(cloud.err.find("is a point cloud"), std::string::npos) << cloud.err;
}

// Storeys of a real IFC (AC20-FZK-Haus.ifc, IFC4, read by IFC++): a ground-floor room
// registered onto "Erdgeschoss" alone lands on the truth, and the report names the storey; a
// storey the model lacks is an error listing the model's storeys. (duplex.ifc would not do:
// its two dwellings are the same under a half turn, so a scan of both is honestly ambiguous.)
TEST(CliModelElements, OneStoreyOfARealIfcRegistersAndTheReportNamesIt) {
  const fs::path dir = scratchDir("cli_model_storeys");
  const std::string model = shellQuote(plumb::test::sharedData("ifc/AC20-FZK-Haus.ifc").string());
  const CliResult sim = plumbCli(dir, "simulate --model " + model + " --tls 3,3,1.5 "
                                "--perturb 180,5 --seed 7 --tls-azimuth-step 0.5 --tls-elevation-step 0.5 -o sim");
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const CliResult r = plumbCli(dir, "register sim/indoor.e57 " + model +
                                        " --model-storeys erdgeschoss --transform T.json --report R.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expectOnTruth(dir, {Eigen::Vector3d(0, 0, 1.5), Eigen::Vector3d(6, 6, 1.5)}, "Erdgeschoss of AC20-FZK-Haus.ifc");
  const auto selection = nlohmann::json::parse(readAll(dir / "R.json")).at("model_elements");
  EXPECT_EQ(selection.at("filter").at("storeys"), (std::vector<std::string>{"erdgeschoss"}));
  EXPECT_LT(selection.at("elements_used").get<int>(), selection.at("elements_in_model").get<int>());
  EXPECT_GE(selection.at("elements_used").get<int>(), 9 + 9 + 5);  // its walls, windows and doors at least

  const CliResult attic = plumbCli(dir, "register sim/indoor.e57 " + model + " --model-storeys Attic");
  EXPECT_EQ(attic.exit_code, 1);
  EXPECT_NE(attic.err.find("no element on a storey named 'Attic' (the model's storeys: Dachgeschoss, Erdgeschoss)"),
            std::string::npos) << attic.err;
}
