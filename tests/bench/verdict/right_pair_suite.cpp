// Right-pair suite: the acceptance scenarios of issue 6 (acceptance_scenarios.hpp: same data,
// same random poses, same tolerance) and the real room pair room_scan1/room_scan2 both ways
// (correct when both directions succeed and compose to the identity within 0.1 deg / 1 cm,
// test_real_pair.cpp's criterion: the pair has no independent ground truth).
#include <algorithm>
#include <chrono>
#include <cstdio>

#include "acceptance_scenarios.hpp"
#include "io/io.hpp"
#include "pair_runner.hpp"
#include "report_figures.hpp"
#include "suites.hpp"
#include "support/test_support.hpp"

namespace plumb::verdict {

namespace {

PairRecord scenarioRecord(const test::Scenario& s, const RigidTransform& pose, int i,
                          const PipelineParams& params) {
  const test::CaseOutcome o = test::runPlumbCase(s, pose, params);
  PairOutcome po{o.report, qualityReportToJson(o.report), o.seconds_total};
  PairRecord r = recordOf("right-pair", s.name, i, po);
  if (o.reported_success) {
    r.rotation_error_deg = o.error.rotation_deg;
    r.translation_error_m = o.error.translation_m;
  }
  r.correct = o.correct();
  r.confident_wrong = r.level == Level::Usable && !o.correct();
  r.group = r.correct ? "right" : "missed";
  return r;
}

PointCloud loadRoomScan(const std::string& name) {
  PointCloud c = readDataset(test::sharedData("pcd/" + name)).merged();
  c.removeNonFinite();
  return c;
}

PairOutcome registerClouds(const PointCloud& source, const PointCloud& target,
                           const PipelineParams& params) {
  const auto t0 = std::chrono::steady_clock::now();
  RegistrationSide s, t;
  s.cloud = &source;
  t.cloud = &target;
  PairOutcome o;
  o.report = registerData(s, t, params).report;
  o.json = qualityReportToJson(o.report);
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return o;
}

std::vector<PairRecord> realPairRecords(const PipelineParams& params) {
  const PointCloud a = loadRoomScan("room_scan1.pcd"), b = loadRoomScan("room_scan2.pcd");
  const PairOutcome ba = registerClouds(b, a, params), ab = registerClouds(a, b, params);
  const RigidTransform loop = ab.report.transform * ba.report.transform;
  const bool both = ab.report.success && ba.report.success;
  const bool consistent = both && loop.rotationAngleDeg() < 0.1 && loop.translation().norm() < 0.01;
  std::vector<PairRecord> out{recordOf("right-pair", "real room_scan2 -> room_scan1", 0, ba),
                              recordOf("right-pair", "real room_scan1 -> room_scan2", 0, ab)};
  for (auto& r : out) {
    if (both) {
      r.rotation_error_deg = loop.rotationAngleDeg();
      r.translation_error_m = loop.translation().norm();
    }
    r.correct = consistent;
    r.confident_wrong = r.level == Level::Usable && !consistent;
    r.group = r.correct ? "right" : "missed";
  }
  return out;
}

void printRecord(const PairRecord& r) {
  std::printf("  [right-pair] %-32s pose %2d: %-19s %-12s rot %.4f deg trans %.4f m  %.1f s\n",
              r.pair.c_str(), r.seed, levelName(r.level).c_str(), r.status.c_str(),
              r.rotation_error_deg.value_or(-1), r.translation_error_m.value_or(-1), r.seconds);
  std::fflush(stdout);
}

}  // namespace

std::vector<PairRecord> runRightPairSuite(const std::vector<std::string>& scenarios, int poses,
                                          bool real_pair, std::uint64_t seed_offset) {
  const PipelineParams params = test::acceptanceParams();
  std::vector<PairRecord> out;
  for (std::size_t k = 0; k < scenarios.size(); ++k) {
    const test::Scenario s = test::makeScenario(scenarios[k], params);
    std::printf("  [data] scenario %s: simulation %.1f s, target features %.1f s\n",
                s.name.c_str(), s.seconds_simulation, s.seconds_target_features);
    // The acceptance test's seeds (11, 12, 13, 14 in scenarioNames() order).
    const auto names = test::scenarioNames();
    const auto index = std::find(names.begin(), names.end(), scenarios[k]) - names.begin();
    const auto cases = test::randomPoses(poses, 11 + index + seed_offset);
    for (int i = 0; i < poses; ++i) {
      out.push_back(scenarioRecord(s, cases[i], i, params));
      printRecord(out.back());
    }
  }
  if (real_pair)
    for (auto& r : realPairRecords(params)) {
      printRecord(r);
      out.push_back(std::move(r));
    }
  return out;
}

}  // namespace plumb::verdict
