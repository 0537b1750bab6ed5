// plumb-cli features: runs the real executable on the real room scan and a real IFC model.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_runner.hpp"
#include "support/test_support.hpp"

using plumb::test::CliResult;
using plumb::test::plumbCli;
using plumb::test::shellQuote;

namespace {

TEST(CliFeatures, PlanesAndSegmentsOfTheRoomScanAsJsonAndPly) {
  const auto dir = plumb::test::scratchDir("cli_features");
  const std::string scan = shellQuote(plumb::test::sharedData("pcd/room_scan1.pcd").string());
  const auto json_path = dir / "room.json";
  const CliResult r =
      plumbCli(dir, "features " + scan + " --planes --segments --set distance-threshold=0.05 -o " +
                        shellQuote(json_path.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(plumb::test::readAll(json_path));
  ASSERT_TRUE(j.at("planes").is_array());
  EXPECT_GE(j.at("planes").size(), 6u);
  EXPECT_TRUE(j.at("openings").empty());  // not asked for
  ASSERT_TRUE(j.at("segments").is_array());
  const auto& p0 = j.at("planes")[0];
  EXPECT_NEAR(std::hypot(p0.at("normal")[0].get<double>(), p0.at("normal")[1].get<double>(),
                         p0.at("normal")[2].get<double>()), 1.0, 1e-9);
  EXPECT_GT(p0.at("inlier_count").get<int>(), 1000);
  EXPECT_GE(p0.at("rings")[0].size(), 3u);
  // Openings without sensor origins: says so on stdout, still succeeds (holes only).
  const CliResult o = plumbCli(
      dir, "features " + scan + " --openings -o " + shellQuote((dir / "room.ply").string()));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(o.out.find("ray tracing cannot run"), std::string::npos) << o.out;
  EXPECT_EQ(plumb::test::readAll(dir / "room.ply").rfind("ply\nformat ascii 1.0\n", 0), 0u);
}

TEST(CliFeatures, SharpEdgesOfAnIfcModel) {
  const auto dir = plumb::test::scratchDir("cli_features_ifc");
  const auto out = dir / "duplex.json";
  const CliResult r =
      plumbCli(dir, "features " + shellQuote(plumb::test::sharedData("ifc/duplex.ifc").string()) +
                        " --segments -o " + shellQuote(out.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(plumb::test::readAll(out));
  ASSERT_GT(j.at("segments").size(), 100u);
  for (const auto& s : j.at("segments")) EXPECT_EQ(s.at("support").get<double>(), 0.0);  // exact model edges
}

TEST(CliFeatures, ExactPlanesAndOpeningsOfAnIfcModel) {
  const auto dir = plumb::test::scratchDir("cli_features_ifc_planes");
  const auto out = dir / "duplex_planes.json";
  const CliResult r =
      plumbCli(dir, "features " + shellQuote(plumb::test::sharedData("ifc/duplex.ifc").string()) +
                        " --planes --openings -o " + shellQuote(out.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(plumb::test::readAll(out));
  ASSERT_GT(j.at("planes").size(), 100u) << r.out;
  EXPECT_FALSE(j.at("facades").empty()) << r.out;
  // Each IfcWindow/IfcDoor element with a wall face gives one opening per face (one or two).
  const auto at = r.out.find(" IfcWindow/IfcDoor elements, ");
  ASSERT_NE(at, std::string::npos) << r.out;
  const std::size_t from = r.out.rfind("from ", at) + 5;
  const std::size_t elements = std::stoul(r.out.substr(from, at - from));
  const std::size_t without = std::stoul(r.out.substr(at + 29));
  EXPECT_GE(j.at("openings").size(), elements - without) << r.out;
  EXPECT_LE(j.at("openings").size(), 2 * (elements - without)) << r.out;
  for (const auto& o : j.at("openings")) {
    const int f = o.at("facade").get<int>();
    ASSERT_GE(f, 0);
    ASSERT_LT(f, int(j.at("planes").size()));
  }
  for (const auto& p : j.at("planes")) EXPECT_GE(p.at("area").get<double>(), 0.1);
}

TEST(CliFeatures, ErrorsAreOneLineAndNonZero) {
  const auto dir = plumb::test::scratchDir("cli_features_err");
  const std::string scan = shellQuote(plumb::test::sharedData("pcd/room_scan1.pcd").string());
  const CliResult none = plumbCli(dir, "features " + scan);
  EXPECT_NE(none.exit_code, 0);
  const CliResult bad = plumbCli(dir, "features " + scan + " --planes --set no-such-key=1");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("unknown feature parameter 'no-such-key'"), std::string::npos) << bad.err;
  const CliResult range =
      plumbCli(dir, "features " + scan + " --planes --set distance-threshold=5");
  EXPECT_EQ(range.exit_code, 1);
  EXPECT_EQ(std::count(range.err.begin(), range.err.end(), '\n'), 1) << range.err;
  // The seed is --seed (as for register), not a plane-extraction parameter (issue 18).
  const CliResult group_seed = plumbCli(dir, "features " + scan + " --planes --set seed=3");
  EXPECT_EQ(group_seed.exit_code, 1);
  EXPECT_NE(group_seed.err.find("unknown feature parameter 'seed'"), std::string::npos) << group_seed.err;
  const CliResult seed = plumbCli(dir, "features " + scan + " --planes --seed -1");
  EXPECT_EQ(seed.exit_code, 1);
  EXPECT_NE(seed.err.find("--seed:"), std::string::npos) << seed.err;
  const CliResult ext =
      plumbCli(dir, "features " + scan + " --planes -o " + shellQuote((dir / "x.txt").string()));
  EXPECT_EQ(ext.exit_code, 1);
  EXPECT_NE(ext.err.find("x.txt"), std::string::npos) << ext.err;
}

}  // namespace
