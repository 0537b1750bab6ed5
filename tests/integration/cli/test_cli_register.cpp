// plumb-cli register end to end on simulated data (plumb-cli simulate): the transform against
// truth.json, the report, --params / --print-params, and the failures (unreadable input, too
// few features, ambiguous result): non-zero exit, one explanation, outputs left untouched.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <sstream>

#include "demo_truth.hpp"
#include "support/cli_runner.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;
using plumb::test::CliResult;
using plumb::test::plumbCli;
using plumb::test::readAll;
using plumb::test::scratchDir;
using plumb::test::transformOf;
using plumb::test::writeAll;

namespace {

/// Axis-aligned closed box room (floor, ceiling, 4 walls) sampled every 5 cm with 2 mm noise,
/// shifted by `shift`: symmetric under a half turn, so no registration can pick one answer.
void writeBoxPly(const fs::path& path, const Eigen::Vector3d& size, const Eigen::Vector3d& shift,
                 unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.002);
  std::vector<Eigen::Vector3d> pts;
  const double step = 0.05;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (double a = 0; a <= size[u] + 1e-9; a += step)
      for (double b = 0; b <= size[v] + 1e-9; b += step)
        for (double side : {0.0, size[axis]}) {
          Eigen::Vector3d p;
          p[axis] = side;
          p[u] = a;
          p[v] = b;
          pts.push_back(p + shift + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
        }
  }
  std::ostringstream s;
  s << "ply\nformat ascii 1.0\nelement vertex " << pts.size()
    << "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  for (const auto& p : pts) s << p.x() << " " << p.y() << " " << p.z() << "\n";
  writeAll(path, s.str());
}

/// A flat 3 m x 3 m patch: one plane only.
void writePlanePly(const fs::path& path) {
  std::ostringstream s;
  s << "ply\nformat ascii 1.0\nelement vertex 3600\nproperty float x\nproperty float y\n"
       "property float z\nend_header\n";
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j) s << i * 0.05 << " " << j * 0.05 << " 0\n";
  writeAll(path, s.str());
}

std::size_t lineCount(const std::string& s) { return std::size_t(std::count(s.begin(), s.end(), '\n')); }

}  // namespace

// Scan to BIM: four TLS stations of the generated "house", moved by a random half-turn-range
// yaw and up to 15 m, registered onto the model file; the transform must undo the
// perturbation recorded in truth.json.
TEST(CliRegister, SimulatedScanToModelMatchesTruth) {
  const fs::path dir = scratchDir("cli_register_bim");
  const CliResult sim = plumbCli(dir, "simulate --preset house --tls-rooms --perturb 180,15 --seed 5 "
                                "--tls-azimuth-step 0.6 --tls-elevation-step 0.6 -o sim");
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const auto truth = nlohmann::json::parse(readAll(dir / "sim/truth.json"));
  ASSERT_EQ(truth.at("datasets").at(0).at("file"), "indoor.e57");
  const Eigen::Matrix4d expected = transformOf(truth["datasets"][0]["transform"]["matrix"]).matrix();

  // Distance options are checked before anything is read or written.
  const CliResult no_output = plumbCli(dir, "register sim/indoor.e57 sim/model.ply --distances");
  EXPECT_EQ(no_output.exit_code, 1);
  EXPECT_NE(no_output.err.find("--distances needs -o"), std::string::npos) << no_output.err;
  const CliResult bad_max = plumbCli(dir, "register sim/indoor.e57 sim/model.ply -o x.e57 --distances --distance-max 0");
  EXPECT_EQ(bad_max.exit_code, 1);
  EXPECT_NE(bad_max.err.find("--distance-max"), std::string::npos) << bad_max.err;
  EXPECT_FALSE(fs::exists(dir / "x.e57"));

  const CliResult r = plumbCli(dir, "register sim/indoor.e57 sim/model.ply --seed 3 --transform T.json "
                              "--report R.json -o registered.e57 --distances");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Eigen::Matrix4d got =
      transformOf(nlohmann::json::parse(readAll(dir / "T.json"))["matrix"]).matrix();
  const Eigen::Matrix3d dR = got.topLeftCorner<3, 3>().transpose() * expected.topLeftCorner<3, 3>();
  EXPECT_LT(Eigen::AngleAxisd(dR).angle() * 180.0 / M_PI, 0.05);
  // Error at the scanned rooms (the model frame's ground floor lies within ~15 m of the origin).
  for (const Eigen::Vector3d& x : {Eigen::Vector3d(0, 0, 1.5), Eigen::Vector3d(10, 8, 1.5)}) {
    const Eigen::Vector3d p = expected.topLeftCorner<3, 3>().transpose() *
                              (x - expected.topRightCorner<3, 1>());  // data point mapping to x
    const Eigen::Vector3d y = got.topLeftCorner<3, 3>() * p + got.topRightCorner<3, 1>();
    EXPECT_LT((y - x).norm(), 0.02) << "at model point " << x.transpose();
  }
  const auto report = nlohmann::json::parse(readAll(dir / "R.json"));
  EXPECT_TRUE(report.at("success").get<bool>());
  EXPECT_EQ(report.at("verdict_level"), "usable");
  EXPECT_EQ(report.at("exit_code"), 0);
  ASSERT_GE(report.at("candidates").size(), 1u);
  EXPECT_EQ(report.at("candidates").at(0).at("role"), "chosen");
  EXPECT_EQ(report.at("method"), "segments");
  EXPECT_NE(report.at("verdict").get<std::string>().find("succeeded"), std::string::npos);
  EXPECT_LT(report.at("points").at("rms_m").get<double>(), 0.01);
  EXPECT_GT(report.at("points").at("overlap_ratio").get<double>(), 0.5);
  EXPECT_TRUE((transformOf(report.at("transform")).matrix() - got).cwiseAbs().maxCoeff() < 1e-9);
  EXPECT_NE(r.out.find("method: segments, status: success"), std::string::npos) << r.out;
  // The registered dataset is written, said so with the writer's count, and readable: 4 scans.
  EXPECT_NE(r.out.find("wrote registered.e57 ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" points, 4 scan(s))"), std::string::npos) << r.out;
  const CliResult info = plumbCli(dir, "info registered.e57");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("scans:     4\n"), std::string::npos) << info.out;
  // --distances: every scan carries the "distance" field, signed (points on both sides of the
  // model's surfaces, 2 mm noise), within the default 0.1 m radius; the independent E57 parser
  // sees it as a float32 prototype field.
  const auto described = nlohmann::json::parse(plumbCli(dir, "info registered.e57 --json").out);
  for (const auto& scan : described.at(0).at("scans")) {
    const auto fields = scan.at("fields").get<std::vector<std::string>>();
    EXPECT_NE(std::find(fields.begin(), fields.end(), "distance"), fields.end()) << scan.dump();
  }
  const fs::path inspect = dir / "inspect.txt";
  ASSERT_EQ(std::system(("python3 " PLUMB_E57_INSPECT " '" + (dir / "registered.e57").string() + "' > '" +
                         inspect.string() + "'").c_str()), 0);
  const std::string parsed = readAll(inspect);
  EXPECT_NE(parsed.find("plumb:distance:Float/single"), std::string::npos) << parsed;

  // Check visually (exit 3): without refinement the degrees of freedom are not checked on the
  // points; the results are written and the warning is repeated on stderr.
  const CliResult unrefined = plumbCli(dir, "register sim/indoor.e57 sim/model.ply --seed 3 --no-refine "
                                      "--transform T3.json --report R3.json");
  EXPECT_EQ(unrefined.exit_code, 3) << unrefined.err;
  EXPECT_NE(unrefined.err.find("check visually (exit 3)"), std::string::npos) << unrefined.err;
  EXPECT_NE(unrefined.err.find("warning: refinement was off"), std::string::npos) << unrefined.err;
  EXPECT_NE(unrefined.out.find("verdict: check visually (exit 3)"), std::string::npos) << unrefined.out;
  EXPECT_TRUE(fs::exists(dir / "T3.json"));
  const auto r3 = nlohmann::json::parse(readAll(dir / "R3.json"));
  EXPECT_EQ(r3.at("verdict_level"), "check-visually");
  EXPECT_EQ(r3.at("exit_code"), 3);
}

// --print-params writes the defaults with the one seed at the top level (no group has its
// own); --params reads it back; flags override the file; a group seed from an older file is
// accepted when it equals the top-level seed, refused (naming the file and the key) otherwise;
// unknown keys are refused, naming the file.
TEST(CliRegister, ParamsFileRoundTripAndSeedInOnePlace) {
  const fs::path dir = scratchDir("cli_register_params");
  const CliResult d = plumbCli(dir, "register --print-params");
  ASSERT_EQ(d.exit_code, 0) << d.err;
  const auto defaults = nlohmann::json::parse(d.out);
  EXPECT_EQ(defaults.at("method"), "auto");
  EXPECT_EQ(defaults.at("seed"), 1);
  for (const auto& [key, group] : defaults.items())
    if (group.is_object()) EXPECT_FALSE(group.contains("seed")) << key;

  auto edited = defaults;
  edited["method"] = "planes";
  edited["seed"] = 9;
  edited["refinement"]["voxel"] = 0.07;
  writeAll(dir / "p.json", edited.dump(2));
  const CliResult back = plumbCli(dir, "register --params p.json --print-params");
  ASSERT_EQ(back.exit_code, 0) << back.err;
  EXPECT_EQ(nlohmann::json::parse(back.out), edited);
  const CliResult over = plumbCli(dir, "register --params p.json --seed 4 --method segments --print-params");
  ASSERT_EQ(over.exit_code, 0) << over.err;
  const auto o = nlohmann::json::parse(over.out);
  EXPECT_EQ(o.at("method"), "segments");
  EXPECT_EQ(o.at("seed"), 4);
  EXPECT_EQ(o.at("refinement").at("voxel"), 0.07);

  auto older = edited;  // as written before the groups lost their seeds
  for (const char* group : {"plane-extraction", "planes", "openings", "segments", "refinement"})
    older[group]["seed"] = 9;
  writeAll(dir / "older.json", older.dump(2));
  const CliResult old_ok = plumbCli(dir, "register --params older.json --print-params");
  ASSERT_EQ(old_ok.exit_code, 0) << old_ok.err;
  EXPECT_EQ(nlohmann::json::parse(old_ok.out), edited);
  writeAll(dir / "seed.json", R"({"seed": 2, "plane-extraction": {"seed": 42}})");
  const CliResult bad_seed = plumbCli(dir, "register --params seed.json --print-params");
  EXPECT_EQ(bad_seed.exit_code, 1);
  EXPECT_NE(bad_seed.err.find("seed.json"), std::string::npos) << bad_seed.err;
  EXPECT_NE(bad_seed.err.find("\"plane-extraction\".\"seed\" = 42"), std::string::npos) << bad_seed.err;
  EXPECT_EQ(lineCount(bad_seed.err), 1u) << bad_seed.err;
  writeAll(dir / "unknown.json", R"({"planes": {"no-such-key": 1}})");
  const CliResult unknown = plumbCli(dir, "register --params unknown.json --print-params");
  EXPECT_EQ(unknown.exit_code, 1);
  EXPECT_NE(unknown.err.find("no-such-key"), std::string::npos) << unknown.err;
  writeAll(dir / "broken.json", "{\"planes\": ");
  const CliResult broken = plumbCli(dir, "register --params broken.json --print-params");
  EXPECT_EQ(broken.exit_code, 1);
  EXPECT_EQ(lineCount(broken.err), 1u) << broken.err;
  EXPECT_NE(broken.err.find("broken.json: is not valid JSON"), std::string::npos) << broken.err;
}

// --set GROUP.KEY=VALUE reaches every schema parameter, nested ones (rotation enumeration,
// clustering, segment distance) and the top level included, after --params and before the
// flags; a bad key or value is a one-line error naming it (issue 18).
TEST(CliRegister, SetReachesNestedAndTopLevelParameters) {
  const fs::path dir = scratchDir("cli_register_set");
  writeAll(dir / "p.json", R"({"planes": {"max-tilt": 7}})");
  const CliResult r = plumbCli(dir, "register --print-params --params p.json --set planes.max-tilt=5 "
                                    "--set segments.robust-distance=0.2 --set agreement-rotation=1.5 "
                                    "--set segment-detection.snap-angle=25 --set plane-extraction.local-cell=0.8 "
                                    "--set seed=8 --seed 9");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("planes").at("max-tilt"), 5.0);
  EXPECT_EQ(j.at("segments").at("robust-distance"), 0.2);
  EXPECT_EQ(j.at("agreement-rotation"), 1.5);
  EXPECT_EQ(j.at("segment-detection").at("snap-angle"), 25.0);
  EXPECT_EQ(j.at("plane-extraction").at("local-cell"), 0.8);
  EXPECT_EQ(j.at("seed"), 9);  // --seed after --set
  for (const char* bad : {"planes.no-such-key=1", "planes.max-tilt=100", "nogroup.max-tilt=1", "planes.seed=1"}) {
    const CliResult e = plumbCli(dir, std::string("register --print-params --set ") + bad);
    EXPECT_EQ(e.exit_code, 1) << bad;
    EXPECT_EQ(lineCount(e.err), 1u) << e.err;
    EXPECT_NE(e.err.find(std::string("--set ") + bad), std::string::npos) << e.err;
  }
}

// Failures exit non-zero with an explanation and never touch an existing output.
// Issue 12: --seed is a whole number in the schemas' seed range; the error names the option
// and the range (on main -1 became 18446744073709551615).
TEST(CliRegister, SeedOutsideItsRangeIsRefused) {
  const auto dir = scratchDir("cli_register_seed");
  for (const char* seed : {"-1", "1.5", "1e300", "nan"}) {
    const CliResult r = plumbCli(dir, std::string("register --print-params --seed ") + seed);
    EXPECT_EQ(r.exit_code, 1) << seed << ": " << r.out << r.err;
    EXPECT_NE(r.err.find("--seed:"), std::string::npos) << seed << ": " << r.err;
    EXPECT_TRUE(r.err.find("[0, 9e+15]") != std::string::npos ||
                r.err.find("whole number") != std::string::npos || r.err.find("expects a number") != std::string::npos)
        << seed << ": " << r.err;
  }
  EXPECT_EQ(plumbCli(dir, "register --print-params --seed 9000000000000000").exit_code, 0);
}

TEST(CliRegister, FailuresExplainAndLeaveOutputsUntouched) {
  const fs::path dir = scratchDir("cli_register_fail");
  writeBoxPly(dir / "a.ply", {6, 4, 3}, {0, 0, 0}, 1);
  writeBoxPly(dir / "b.ply", {6, 4, 3}, {0.3, -0.2, 0}, 2);
  writePlanePly(dir / "plane.ply");
  writeAll(dir / "bad.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n1\n");
  auto reset = [&] {
    writeAll(dir / "out.ply", "precious");
    writeAll(dir / "T.json", "precious");
  };
  auto untouched = [&](const std::string& what) {
    EXPECT_EQ(readAll(dir / "out.ply"), "precious") << what;
    EXPECT_EQ(readAll(dir / "T.json"), "precious") << what;
  };

  // Ambiguous: the box maps onto itself by a half turn; refined point overlap cannot decide.
  reset();
  const CliResult amb = plumbCli(dir, "register a.ply b.ply -o out.ply --transform T.json --report R.json");
  EXPECT_EQ(amb.exit_code, 2) << amb.err;
  EXPECT_NE(amb.err.find("registration failed: Registration FAILED (ambiguous)"), std::string::npos)
      << amb.err;
  EXPECT_NE(amb.err.find("no output written"), std::string::npos) << amb.err;
  untouched("ambiguous");
  const auto report = nlohmann::json::parse(readAll(dir / "R.json"));
  EXPECT_FALSE(report.at("success").get<bool>());
  EXPECT_EQ(report.at("status"), "ambiguous");
  EXPECT_EQ(report.at("verdict_level"), "failed");
  EXPECT_EQ(report.at("exit_code"), 2);
  // Every candidate placement is listed: the box and the box turned by a half turn.
  EXPECT_GE(report.at("candidates").size(), 2u) << report.dump(2);
  EXPECT_NE(amb.out.find("candidate 2 ("), std::string::npos) << amb.out;

  // Too few features: one plane cannot fix a pose.
  reset();
  const CliResult few = plumbCli(dir, "register plane.ply b.ply -o out.ply --transform T.json");
  EXPECT_EQ(few.exit_code, 2) << few.err;
  EXPECT_NE(few.err.find("(too few features)"), std::string::npos) << few.err;
  untouched("too few features");

  // Degenerate: ICP of a plane onto itself converges, but in-plane shifts and the rotation
  // about the normal are free: it fails and names them (issue 13, degenerate suite).
  reset();
  const CliResult flat =
      plumbCli(dir, "register plane.ply plane.ply --method icp -o out.ply --transform T.json --report R.json");
  EXPECT_EQ(flat.exit_code, 2) << flat.err;
  EXPECT_NE(flat.err.find("Registration FAILED (degenerate)"), std::string::npos) << flat.err;
  EXPECT_NE(flat.err.find("rotation about vertical"), std::string::npos) << flat.err;
  untouched("degenerate");
  EXPECT_EQ(nlohmann::json::parse(readAll(dir / "R.json")).at("status"), "degenerate");

  // Unreadable input: one line naming the file and what is wrong.
  reset();
  const CliResult bad = plumbCli(dir, "register bad.ply b.ply -o out.ply --transform T.json");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_EQ(lineCount(bad.err), 1u) << bad.err;
  EXPECT_NE(bad.err.find("bad.ply: vertex element has no x, y and z"), std::string::npos) << bad.err;
  untouched("unreadable");
  const CliResult missing = plumbCli(dir, "register missing.ply b.ply -o out.ply");
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_NE(missing.err.find("missing.ply"), std::string::npos) << missing.err;
  untouched("missing");
}
