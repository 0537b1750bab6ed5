// Calibration of the free-space verdict (docs/VERDICT.md "Free space"). Registers right pairs
// (acceptance scenarios at random poses, the real room pair both ways, overlapping parts of a
// real scan) and wrong pairs (indoor scans of one building onto another building's outdoor
// scan, indoor scan or model) with the free-space rule switched off (fail and warn ratios 1),
// and prints the contradiction ratios, expected overlap and times of every pair that the
// pipeline reported as a success, then min / median / max per group.
//   bench_visibility [--right] [--wrong] [--real] [--presets] [--poses N] [--timing]
//   bench_visibility --truth   (each preset's TLS against its own MMS at the truth)
// With no group flag every group runs. --timing: evidence on 300k + 300k points (both
// directions, house indoor TLS vs its MMS loop at the truth), time and table memory.
#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "acceptance_scenarios.hpp"
#include "io/io.hpp"
#include "quality/station_range_images.hpp"
#include "registration/auto/registration_input.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/presets.hpp"
#include "support/test_support.hpp"

using namespace plumb;

namespace {

struct Row {
  std::string group, name;
  bool success = false;  ///< the pipeline's verdict without the free-space rule
  bool correct = true;   ///< right pairs: within the acceptance tolerance
  std::string status;
  VisibilitySummary v;
  double overlap = 0.0;
  RigidTransform transform;
};

std::vector<Row> rows;

PipelineParams measuringParams() {
  PipelineParams p;
  p.visibility.fail_ratio = 1.0;  // measure only: the rule never fires
  p.visibility.warn_ratio = 1.0;
  return p;
}

std::string fig(double v) {
  if (v < 0) return "   -  ";
  std::ostringstream o;
  o << std::fixed << std::setprecision(3) << v;
  return o.str();
}

double ratioOf(const VisibilityEvidence& e) {
  return e.available && e.visible > 0 ? e.contradiction_ratio : -1.0;
}

void print(const Row& r) {
  std::cout << std::left << std::setw(8) << r.group << std::setw(44) << r.name << std::right
            << std::setw(20) << r.status << (r.correct ? "" : " WRONG-ANSWER")
            << "  used " << fig(r.v.contradiction_ratio) << "  s->t " << fig(ratioOf(r.v.source_in_target))
            << " (vis " << r.v.source_in_target.visible << ")  t->s "
            << fig(ratioOf(r.v.target_in_source)) << " (vis " << r.v.target_in_source.visible
            << ")  expected " << fig(r.v.expected_overlap) << "  achieved " << fig(r.overlap)
            << "  secs " << std::setprecision(3)
            << r.v.source_in_target.seconds + r.v.target_in_source.seconds << std::endl;
}

void record(Row r) {
  print(r);
  rows.push_back(std::move(r));
}

Row run(const std::string& group, const std::string& name, const RegistrationSide& s,
        const RegistrationSide& t) {
  const PipelineResult r = registerData(s, t, measuringParams());
  Row row;
  row.group = group;
  row.name = name;
  row.success = r.success();
  row.status = r.report.status;
  row.v = r.report.visibility;
  row.overlap = r.report.overlap_ratio;
  row.transform = r.transform();
  return row;
}

void rightScenarios(int poses) {
  const PipelineParams p = measuringParams();
  for (const auto& name : test::scenarioNames()) {
    const test::Scenario s = test::makeScenario(name, p);
    int k = 0;
    for (const auto& pose : test::randomPoses(poses, 17)) {
      const test::CaseOutcome o = test::runPlumbCase(s, pose, p);
      Row r;
      r.group = "right";
      r.name = name + " pose " + std::to_string(k++);
      r.success = o.reported_success;
      r.correct = !o.confidentWrong();
      r.status = o.status;
      r.v = o.visibility;
      r.overlap = o.overlap;
      record(r);
    }
  }
}

RegistrationInput fileInput(const std::string& rel) {
  return makeRegistrationInput(readDataset(test::sharedData(rel)), RigidTransform());
}

/// Part of a single-station scan whose azimuth about the viewpoint is in [from, to) degrees.
PointCloud azimuthPart(const PointCloud& c, const Eigen::Vector3d& v, double from, double to) {
  std::vector<std::size_t> keep;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Eigen::Vector3d d = c.world(i) - v;
    const double az = std::atan2(d.y(), d.x()) * 180.0 / M_PI + 180.0;
    if (az >= from && az < to) keep.push_back(i);
  }
  return c.subset(keep);
}

void realPairs() {
  const RegistrationInput a = fileInput("pcd/room_scan1.pcd");
  const RegistrationInput b = fileInput("pcd/room_scan2.pcd");
  record(run("real", "room_scan2 -> room_scan1", b.side(), a.side()));
  record(run("real", "room_scan1 -> room_scan2", a.side(), b.side()));
  // Overlapping parts of one real scan (its viewpoint is both sides' station), one moved.
  for (const RegistrationInput* in : {&a, &b}) {
    const Eigen::Vector3d vp = *in->viewpoint;
    PointCloud left = azimuthPart(in->cloud, vp, 0, 230);
    const PointCloud right = azimuthPart(in->cloud, vp, 130, 360);
    const RigidTransform pose(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
                              Eigen::Vector3d(3, -2, 0.5));
    left.transform(pose);
    RegistrationSide s, t;
    s.cloud = &left;
    s.viewpoint = pose.apply(vp);
    t.cloud = &right;
    t.viewpoint = vp;
    Row r = run("real", std::string(in == &a ? "room_scan1" : "room_scan2") +
                            " 0-230 deg -> 130-360 deg", s, t);
    record(r);
  }
}

void wrongPairs() {
  const auto house_mms = test::presetOutdoorScan("house", 11);
  const auto house_tls = test::presetIndoorScans("house", 300);
  const BimModel duplex = readModel(test::sharedData("ifc/duplex.ifc"));
  const BimModel lshaped_model = generateBuilding(buildingPreset("l-shaped")).model;
  auto cloudSide = [](const PointCloud& c) {
    RegistrationSide s;
    s.cloud = &c;
    return s;
  };
  auto modelSide = [](const BimModel& m) {
    RegistrationSide s;
    s.model = &m;
    return s;
  };
  record(run("wrong", "house TLS -> duplex.ifc", cloudSide(house_tls), modelSide(duplex)));
  record(run("wrong", "house TLS -> l-shaped model", cloudSide(house_tls), modelSide(lshaped_model)));
  for (const std::string preset : {"l-shaped", "office-floor", "u-shaped", "two-rooms",
                                   "non-manhattan"}) {
    const PointCloud tls = test::presetIndoorScans(preset, 500);
    record(run("wrong", preset + " TLS -> house MMS", cloudSide(tls), cloudSide(house_mms)));
    if (preset == "l-shaped" || preset == "two-rooms")
      record(run("wrong", preset + " TLS -> house TLS", cloudSide(tls), cloudSide(house_tls)));
    if (preset == "two-rooms")
      record(run("wrong", preset + " TLS -> duplex.ifc", cloudSide(tls), modelSide(duplex)));
  }
  const PointCloud lshaped_mms = test::presetOutdoorScan("l-shaped", 12);
  record(run("wrong", "house TLS -> l-shaped MMS", cloudSide(house_tls), cloudSide(lshaped_mms)));
}

/// Other buildings' right pairs (their TLS onto their own MMS loop and model, moved by a
/// pose) and wrong pairs between them.
void presetPairs() {
  const RigidTransform pose = test::randomPoses(1, 23).front();
  const BimModel duplex = readModel(test::sharedData("ifc/duplex.ifc"));
  std::map<std::string, PointCloud> mms;
  for (const std::string preset : {"l-shaped", "office-floor", "u-shaped"}) {
    PointCloud tls = test::presetIndoorScans(preset, 600);
    mms[preset] = test::presetOutdoorScan(preset, 13);
    const BimModel model = generateBuilding(buildingPreset(preset)).model;
    const Eigen::Vector3d centre = pose.apply(tls.bounds().center());
    PointCloud moved = tls;
    moved.transform(pose);
    RegistrationSide s, t, m;
    s.cloud = &moved;
    t.cloud = &mms[preset];
    m.model = &model;
    for (const RegistrationSide* target : {&t, &m}) {
      Row row = run("right", preset + (target == &t ? " TLS -> own MMS" : " TLS -> own model"), s,
                    *target);
      row.correct = !row.success || test::withinTolerance(test::poseError(
                                        row.transform, pose.inverse(), centre));
      record(row);
    }
    RegistrationSide d;
    d.model = &duplex;
    record(run("wrong", preset + " TLS -> duplex.ifc", s, d));
    for (const auto& [other, cloud] : mms) {
      if (other == preset) continue;
      RegistrationSide o;
      o.cloud = &cloud;
      record(run("wrong", preset + " TLS -> " + other + " MMS", s, o));
    }
  }
}

void summary() {
  std::map<std::string, std::vector<double>> used, st, ts, ex;
  for (const Row& r : rows) {
    if (!r.success) continue;  // failed anyway: no transform to judge
    const std::string g = r.group == "wrong" || !r.correct ? "wrong" : "right";
    if (r.v.conclusive()) used[g].push_back(r.v.contradiction_ratio);
    if (ratioOf(r.v.source_in_target) >= 0) st[g].push_back(ratioOf(r.v.source_in_target));
    if (ratioOf(r.v.target_in_source) >= 0) ts[g].push_back(ratioOf(r.v.target_in_source));
    if (r.v.expected_overlap >= 0) ex[g].push_back(r.v.expected_overlap);
  }
  auto line = [](const char* what, std::vector<double> v) {
    std::sort(v.begin(), v.end());
    std::cout << "  " << std::left << std::setw(34) << what << std::right;
    if (v.empty()) {
      std::cout << "n 0\n";
      return;
    }
    std::cout << "n " << v.size() << "  min " << fig(v.front()) << "  median "
              << fig(v[v.size() / 2]) << "  max " << fig(v.back()) << "\n";
  };
  for (const char* g : {"right", "wrong"}) {
    std::cout << g << " pairs reported as success before the free-space rule:\n";
    line("contradiction ratio used", used[g]);
    line("source in target's free space", st[g]);
    line("target in source's free space", ts[g]);
    line("expected overlap", ex[g]);
  }
}

/// Evidence on 300k + 300k points, both directions, at the truth.
void timing() {
  PointCloud tls = test::presetIndoorScans("house", 300);
  PointCloud mms = test::presetOutdoorScan("house", 11);
  tls = tls.subset(regularSample(tls.size(), 300000));
  mms = mms.subset(regularSample(mms.size(), 300000));
  const VisibilityParams p;
  // Wall time depends on what else runs on the machine; the process CPU time does not.
  for (int rep = 0; rep < 3; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    const StationRangeImages mms_images(mms, std::nullopt, p);
    const StationRangeImages tls_images(tls, std::nullopt, p);
    const double build_cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
    const auto a = freeSpaceEvidence(mms, std::nullopt, tls, std::nullopt, RigidTransform(), p);
    const auto b = freeSpaceEvidence(tls, std::nullopt, mms, std::nullopt, RigidTransform(), p);
    const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC - build_cpu;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cout << "300k TLS + 300k MMS, both directions: CPU " << cpu << " s (of which building "
              << "the two range images " << build_cpu << " s), wall " << a.seconds + b.seconds
              << " s (tls in mms " << a.seconds << " s, " << a.stations
              << " stations; mms in tls " << b.seconds << " s, " << b.stations
              << " stations); ratios " << a.contradiction_ratio << " / " << b.contradiction_ratio
              << " (" << s << " s with the separate builds)\n";
  }
  std::cout << "bin tables: MMS " << StationRangeImages(mms, std::nullopt, p).memoryBytes() / 1e6
            << " MB, TLS " << StationRangeImages(tls, std::nullopt, p).memoryBytes() / 1e6
            << " MB\n";
}

/// Each preset's TLS survey against its own MMS loop at the truth (no registration): the
/// floor of the contradiction ratio for right indoor/outdoor pairs.
void truthPairs() {
  const VisibilityParams p;
  for (const std::string preset : {"house", "l-shaped", "office-floor", "u-shaped"}) {
    const PointCloud tls = test::presetIndoorScans(preset, 300);
    const PointCloud mms = test::presetOutdoorScan(preset, 11);
    const auto a = freeSpaceEvidence(mms, std::nullopt, tls, std::nullopt, RigidTransform(), p);
    const auto b = freeSpaceEvidence(tls, std::nullopt, mms, std::nullopt, RigidTransform(), p);
    std::cout << "truth  " << std::left << std::setw(14) << preset << std::right
              << " TLS in MMS free space " << fig(a.contradiction_ratio) << " (vis " << a.visible
              << ", " << a.stations << " stations, " << a.seconds << " s)  MMS in TLS "
              << fig(b.contradiction_ratio) << " (vis " << b.visible << ")\n";
  }
}

/// Where the contradicting points of `tested` lie in `observer`'s free space (diagnosis).
void dumpContradictions(const PointCloud& observer, const std::optional<Eigen::Vector3d>& vp,
                        const PointCloud& tested, const RigidTransform& t) {
  const VisibilityParams p;
  const StationRangeImages images(observer, vp, p);
  std::map<int, int> by_z;
  int shown = 0;
  for (std::size_t i : regularSample(tested.size(), 30000)) {
    if (vp && (tested.world(i) - *vp).norm() < p.min_sensor_distance) continue;
    const Eigen::Vector3d q = t.apply(tested.world(i));
    if (images.classify(q) != Sighting::Contradicting) continue;
    ++by_z[static_cast<int>(std::floor(q.z() * 2))];
    if (shown++ < 15) std::cout << "  contradicting " << q.transpose() << "\n";
  }
  for (auto [z, n] : by_z) std::cout << "  z " << z / 2.0 << ": " << n << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  bool right = false, wrong = false, real = false, time = false, presets = false;
  int poses = 3;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--right")) right = true;
    else if (!std::strcmp(argv[i], "--wrong")) wrong = true;
    else if (!std::strcmp(argv[i], "--real")) real = true;
    else if (!std::strcmp(argv[i], "--timing")) time = true;
    else if (!std::strcmp(argv[i], "--presets")) presets = true;
    else if (!std::strcmp(argv[i], "--truth")) {
      truthPairs();
      return 0;
    }
    else if (!std::strcmp(argv[i], "--poses") && i + 1 < argc) poses = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--dump")) {
      const PointCloud tls = test::presetIndoorScans("house", 300);
      const PointCloud mms = test::presetOutdoorScan("house", 11);
      std::cout << "house MMS points in the house TLS free space, at the truth:\n";
      dumpContradictions(tls, std::nullopt, mms, RigidTransform());
      std::cout << "house TLS points in the house MMS free space, at the truth:\n";
      dumpContradictions(mms, std::nullopt, tls, RigidTransform());
      const RegistrationInput a = fileInput("pcd/room_scan1.pcd");
      const RegistrationInput b = fileInput("pcd/room_scan2.pcd");
      const PipelineResult r = registerData(b.side(), a.side(), measuringParams());
      std::cout << "room_scan2 points in room_scan1's free space:\n";
      dumpContradictions(a.cloud, a.viewpoint, b.cloud, r.transform());
      return 0;
    }
  }
  if (time) {
    timing();
    if (!right && !wrong && !real && !presets) return 0;
  }
  if (!right && !wrong && !real && !presets) right = wrong = real = presets = true;
  if (presets) presetPairs();
  if (real) realPairs();
  if (wrong) wrongPairs();
  if (right) rightScenarios(poses);
  summary();
  return 0;
}
