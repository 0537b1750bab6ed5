// plumb-cli on models that crash assimp: `info` and `simulate --model` end with exit status 1
// and one error line naming the file; the import time limit comes from PLUMB_IMPORT_TIMEOUT.
// An IFC4 file assimp refuses is read by IFC++: `info` and the BIM's own features work on it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdlib>

#include "support/cli_runner.hpp"
#include "support/damaged_models.hpp"
#include "support/test_support.hpp"

using plumb::test::CliResult;
using plumb::test::plumbCli;
using plumb::test::readAll;
using plumb::test::scratchDir;
using plumb::test::sharedData;
using plumb::test::shellQuote;

TEST(CliModelImport, DamagedIfcIsAnErrorNotACrash) {
  const auto dir = scratchDir("cli_model_damaged");
  const auto ifc = plumb::test::duplexWithout(dir, "#8961=", "duplex_no_8961.ifc");
  const CliResult info = plumbCli(dir, "info " + shellQuote(ifc.string()));
  EXPECT_EQ(info.exit_code, 1) << info.err;
  EXPECT_NE(info.err.find("plumb-cli: error: " + ifc.string() + ": assimp crashed (SIGSEGV"), std::string::npos)
      << info.err;
  EXPECT_NE(info.err.find("#8961"), std::string::npos) << info.err;
  const CliResult sim = plumbCli(dir, "simulate --model " + shellQuote(ifc.string()) + " --tls 0,0,1 -o out");
  EXPECT_EQ(sim.exit_code, 1) << sim.err;
  EXPECT_NE(sim.err.find("duplex_no_8961.ifc"), std::string::npos) << sim.err;
  EXPECT_NE(sim.err.find("assimp crashed"), std::string::npos) << sim.err;
}

TEST(CliModelImport, TimeLimitFromTheEnvironment) {
  // One 100,000-vertex polygon keeps assimp busy for minutes; the limit stops it after 3 s.
  const auto dir = scratchDir("cli_model_timeout");
  const auto obj = plumb::test::hugePolygonObj(dir, 100000);
  setenv("PLUMB_IMPORT_TIMEOUT", "3", 1);
  const CliResult r = plumbCli(dir, "info " + shellQuote(obj.string()));
  unsetenv("PLUMB_IMPORT_TIMEOUT");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find(obj.string() + ": importing this model took longer than the time limit of 3 s"),
            std::string::npos) << r.err;
}

TEST(CliModelImport, Ifc4ThatAssimpRefusesIsReadByIfcpp) {
  // AC20-FZK-Haus.ifc: IfcWall 13, IfcWindow 11, IfcDoor 5 (shared/data/README.md).
  const auto dir = scratchDir("cli_model_ifcpp");
  const std::string fzk = shellQuote(sharedData("ifc/AC20-FZK-Haus.ifc").string());
  const CliResult info = plumbCli(dir, "info --json " + fzk);
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const auto j = nlohmann::json::parse(info.out)[0];
  EXPECT_EQ(j["element_types"]["IfcWall"], 13);
  EXPECT_EQ(j["element_types"]["IfcWindow"], 11);
  EXPECT_EQ(j["element_types"]["IfcDoor"], 5);
  EXPECT_GT(j["triangles"].get<int>(), 5000);

  const auto out = dir / "fzk_features.json";
  const CliResult f = plumbCli(dir, "features " + fzk + " --planes --openings -o " + shellQuote(out.string()));
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const auto fs = nlohmann::json::parse(readAll(out));
  // All 16 windows and doors on a wall, each on both wall faces.
  EXPECT_NE(f.out.find("from 16 IfcWindow/IfcDoor elements, 0 without a wall face"), std::string::npos) << f.out;
  EXPECT_EQ(fs["openings"].size(), 32u) << f.out;
  EXPECT_GE(fs["planes"].size(), 20u) << f.out;
}
