// plumb-cli info / convert: output, JSON, exit codes, one-line errors, atomic outputs.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>

#include "support/cli_runner.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;
using plumb::test::CliResult;
using plumb::test::plumbCli;
using plumb::test::readAll;
using plumb::test::scratchDir;
using plumb::test::sharedData;
using plumb::test::shellQuote;
using plumb::test::writeAll;

namespace {
std::size_t lines(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }
}  // namespace

TEST(CliInfo, TextBlocksPerFile) {
  const auto dir = scratchDir("cli_info");
  const CliResult r = plumbCli(dir, shellQuote(sharedData("pcd/room_scan1.pcd")) + " " +
                                        shellQuote(sharedData("ifc/duplex.ifc")));
  EXPECT_NE(r.exit_code, 0) << "usage without subcommand must fail";  // CLI11 usage error code
  const CliResult i = plumbCli(dir, "info " + shellQuote(sharedData("pcd/room_scan1.pcd")) + " " +
                                        shellQuote(sharedData("ifc/duplex.ifc")));
  ASSERT_EQ(i.exit_code, 0) << i.err;
  EXPECT_NE(i.out.find("room_scan1.pcd\n  format:    pcd\n  scans:     1\n  points:    112586\n"), std::string::npos) << i.out;
  EXPECT_NE(i.out.find("    IfcWall: 57\n"), std::string::npos) << i.out;
  EXPECT_NE(i.out.find("  bounds:    min -13.7998 -6.4928 -1.3517"), std::string::npos) << i.out;
  EXPECT_TRUE(i.err.empty()) << i.err;
}

TEST(CliInfo, JsonAndPartialFailure) {
  const auto dir = scratchDir("cli_info_json");
  writeAll(dir / "empty.ply", "");
  const CliResult r = plumbCli(dir, "info --json " + shellQuote(sharedData("pcd/capture0001.pcd")) +
                                        " " + shellQuote((dir / "empty.ply").string()) + " " +
                                        shellQuote(sharedData("ifc/tested_sample_project.ifc")));
  EXPECT_EQ(r.exit_code, 1);  // one file failed
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("empty.ply: file is empty"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.size(), 3u);
  EXPECT_EQ(j[0]["points"], 307200);
  EXPECT_EQ(j[0]["scans"][0]["finite_points"], 249647);
  EXPECT_EQ(j[0]["scans"][0]["grid"], nlohmann::json({480, 640}));
  EXPECT_TRUE(j[1].contains("error"));
  EXPECT_EQ(j[2]["kind"], "model");
  EXPECT_EQ(j[2]["element_types"]["IfcWindow"], 9);
  EXPECT_GT(j[2]["triangles"].get<int>(), 1000);
}

TEST(CliConvert, PcdToPlyWithTransform) {
  const auto dir = scratchDir("cli_convert");
  writeAll(dir / "t.json", R"({"matrix": [[1,0,0,100],[0,1,0,-50],[0,0,1,2],[0,0,0,1]]})");
  const auto out = dir / "room.ply";
  CliResult r = plumbCli(dir, "convert " + shellQuote(sharedData("pcd/room_scan1.pcd")) + " " +
                                  shellQuote(out.string()) + " --transform " +
                                  shellQuote((dir / "t.json").string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = plumbCli(dir, "info --json " + shellQuote(out.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out)[0];
  EXPECT_EQ(j["points"], 112586);
  EXPECT_NEAR(j["bounds"]["min"][0].get<double>(), -13.7998 + 100, 1e-3);
  EXPECT_NEAR(j["bounds"]["max"][1].get<double>(), 7.9796 - 50, 1e-3);
  EXPECT_NEAR(j["bounds"]["max"][2].get<double>(), 1.7091 + 2, 1e-3);
}

TEST(CliConvert, FailureNeverDestroysExistingOutput) {
  const auto dir = scratchDir("cli_convert_fail");
  const auto out = dir / "out.ply";
  writeAll(out, "precious");
  writeAll(dir / "bad.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 5\nHEIGHT 1\nPOINTS 5\nDATA binary\nxx");
  CliResult r = plumbCli(
      dir, "convert " + shellQuote((dir / "bad.pcd").string()) + " " + shellQuote(out.string()));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("bad.pcd: truncated data: expected 5 points"), std::string::npos) << r.err;
  EXPECT_EQ(readAll(out), "precious");
  writeAll(dir / "t.json", R"({"matrix": [[2,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]})");  // not rigid
  r = plumbCli(dir, "convert " + shellQuote(sharedData("pcd/room_scan1.pcd")) + " " +
                        shellQuote(out.string()) + " --transform " +
                        shellQuote((dir / "t.json").string()));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(readAll(out), "precious");
  const auto obj = dir / "out.obj";
  writeAll(obj, "precious");
  r = plumbCli(dir, "convert " + shellQuote(sharedData("pcd/room_scan1.pcd")) + " " +
                        shellQuote(obj.string()));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("out.obj: cannot write a point cloud as OBJ"), std::string::npos) << r.err;
  EXPECT_EQ(readAll(obj), "precious");
  for (const auto& e : fs::directory_iterator(dir))  // no temporary files left
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

TEST(CliConvert, SplitScansAndModels) {
  const auto dir = scratchDir("cli_convert_split");
  CliResult r = plumbCli(dir, "convert --split " + shellQuote(sharedData("e57/A_B.e57")) + " " +
                                  shellQuote((dir / "s.ply").string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "s_0_B2_-_Cloud.ply"));
  EXPECT_TRUE(fs::exists(dir / "s_1_A4_-_Cloud.ply"));
  r = plumbCli(dir, "info --json " + shellQuote((dir / "s_1_A4_-_Cloud.ply").string()));
  EXPECT_EQ(nlohmann::json::parse(r.out)[0]["points"], 4);
  r = plumbCli(dir, "convert " + shellQuote(sharedData("ifc/duplex.ifc")) + " " +
                        shellQuote((dir / "duplex.ply").string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = plumbCli(dir, "info --json " + shellQuote((dir / "duplex.ply").string()));
  const auto j = nlohmann::json::parse(r.out)[0];
  EXPECT_EQ(j["element_types"]["IfcWall"], 57);
  EXPECT_EQ(j["element_types"]["IfcDoor"], 14);
  // assimp refuses this IFC4 file; IFC++ reads it.
  r = plumbCli(dir, "convert " + shellQuote(sharedData("ifc/AC20-FZK-Haus.ifc")) + " " +
                        shellQuote((dir / "fzk.ply").string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = plumbCli(dir, "info --json " + shellQuote((dir / "fzk.ply").string()));
  EXPECT_EQ(nlohmann::json::parse(r.out)[0]["element_types"]["IfcWindow"], 11);
  // Neither parser reads this one: one error line, no output file.
  writeAll(dir / "bad.ifc", "ISO-10303-21;\nHEADER;\nthis is not STEP\n");
  r = plumbCli(dir, "convert " + shellQuote((dir / "bad.ifc").string()) + " " + shellQuote((dir / "bad.ply").string()));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(lines(r.err), 1u);
  EXPECT_NE(r.err.find("bad.ifc"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "bad.ply"));
}
