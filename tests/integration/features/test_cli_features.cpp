// plumb-cli features: runs the real executable on the real room scan and a real IFC model.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <sys/wait.h>

#include "support/test_support.hpp"

namespace {

struct CliRun {
  int code = -1;
  std::string out, err;
};

std::string quote(const std::string& s) { return "'" + s + "'"; }

CliRun cli(const std::string& args, const std::filesystem::path& dir) {
  const auto err = dir / "stderr.txt";
  const std::string cmd = std::string(PLUMB_CLI_PATH) + " " + args + " 2>" + quote(err.string());
  CliRun r;
  FILE* p = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf;
  while (std::size_t n = fread(buf.data(), 1, buf.size(), p)) r.out.append(buf.data(), n);
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = plumb::test::readAll(err);
  return r;
}

TEST(CliFeatures, PlanesAndSegmentsOfTheRoomScanAsJsonAndPly) {
  const auto dir = plumb::test::scratchDir("cli_features");
  const std::string scan = quote(plumb::test::sharedData("pcd/room_scan1.pcd").string());
  const auto json_path = dir / "room.json";
  const CliRun r = cli("features " + scan + " --planes --segments --set distance-threshold=0.05 -o " +
                           quote(json_path.string()),
                       dir);
  ASSERT_EQ(r.code, 0) << r.err;
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
  const CliRun o = cli("features " + scan + " --openings -o " + quote((dir / "room.ply").string()), dir);
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_NE(o.out.find("ray tracing cannot run"), std::string::npos) << o.out;
  EXPECT_EQ(plumb::test::readAll(dir / "room.ply").rfind("ply\nformat ascii 1.0\n", 0), 0u);
}

TEST(CliFeatures, SharpEdgesOfAnIfcModel) {
  const auto dir = plumb::test::scratchDir("cli_features_ifc");
  const auto out = dir / "duplex.json";
  const CliRun r = cli("features " + quote(plumb::test::sharedData("ifc/duplex.ifc").string()) + " --segments -o " +
                           quote(out.string()),
                       dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(plumb::test::readAll(out));
  ASSERT_GT(j.at("segments").size(), 100u);
  for (const auto& s : j.at("segments")) EXPECT_EQ(s.at("support").get<double>(), 0.0);  // exact model edges
}

TEST(CliFeatures, ErrorsAreOneLineAndNonZero) {
  const auto dir = plumb::test::scratchDir("cli_features_err");
  const std::string scan = quote(plumb::test::sharedData("pcd/room_scan1.pcd").string());
  const CliRun none = cli("features " + scan, dir);
  EXPECT_NE(none.code, 0);
  const CliRun bad = cli("features " + scan + " --planes --set no-such-key=1", dir);
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("unknown feature parameter 'no-such-key'"), std::string::npos) << bad.err;
  const CliRun range = cli("features " + scan + " --planes --set distance-threshold=5", dir);
  EXPECT_EQ(range.code, 1);
  EXPECT_EQ(std::count(range.err.begin(), range.err.end(), '\n'), 1) << range.err;
  const CliRun ext = cli("features " + scan + " --planes -o " + quote((dir / "x.txt").string()), dir);
  EXPECT_EQ(ext.code, 1);
  EXPECT_NE(ext.err.find("x.txt"), std::string::npos) << ext.err;
}

}  // namespace
