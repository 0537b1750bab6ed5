#include <algorithm>

#include "acceptance_scenarios.hpp"

#include <Eigen/Geometry>

#include <chrono>
#include <cstdio>
#include <cmath>
#include <random>

#include "common/error.hpp"
#include "io/io.hpp"
#include "model/dataset.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/mms_scanner.hpp"
#include "simulation/presets.hpp"
#include "simulation/scan_scene.hpp"
#include "simulation/tls_scanner.hpp"
#include "support/test_support.hpp"
#include "common/stopwatch.hpp"

namespace plumb::test {

namespace {

TlsParams tlsParams(double noise_mm) {
  TlsParams p;
  p.azimuth_step_deg = 0.5;  // ~200 k points per station: a coarse but real TLS setting
  p.elevation_step_deg = 0.5;
  p.noise_mm = noise_mm;
  return p;
}

PointCloud scanStations(const ScanScene& scene, const std::vector<Eigen::Vector3d>& stations,
                        double noise_mm, std::uint64_t seed) {
  Dataset d;
  for (std::size_t i = 0; i < stations.size(); ++i)
    d.scans.push_back(simulateTls(scene, stations[i], tlsParams(noise_mm), seed + i));
  PointCloud c = d.merged(true);  // static scans: sensor origins from the station poses
  c.removeNonFinite();
  return c;
}

/// Centre of the interior door between the first two ground-floor rooms (wall mid-plane),
/// at the room stations' height.
Eigen::Vector3d doorwayStation(const GeneratedBuilding& b, const Eigen::Vector3d& room_a,
                               const Eigen::Vector3d& room_b) {
  const Eigen::Vector3d mid = 0.5 * (room_a + room_b);
  double best = 1e9;
  Eigen::Vector3d out = mid;
  for (const auto& o : b.truth.openings) {
    if (o.element_type != "IfcDoor" || o.face != "interior" || o.storey != 0) continue;
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const auto& k : o.corners) c += 0.25 * k;
    // Move from the face to the wall's middle plane.
    c -= 0.5 * b.spec.interior_wall_thickness * o.face_normal;
    const double d = (c - mid).head<2>().norm();
    if (d < best) {
      best = d;
      out = Eigen::Vector3d(c.x(), c.y(), room_a.z());
    }
  }
  return out;
}

}  // namespace

PointCloud presetIndoorScans(const std::string& preset, std::uint64_t seed) {
  const GeneratedBuilding b = generateBuilding(buildingPreset(preset));
  const ScanScene scene(b.model, b.glass_triangles);
  return scanStations(scene, roomCentres(b.spec, 0), 3.0, seed);
}

PointCloud presetOutdoorScan(const std::string& preset, std::uint64_t seed) {
  const GeneratedBuilding b = generateBuilding(buildingPreset(preset));
  const ScanScene scene(b.model, b.glass_triangles);
  MmsParams mp;  // profiler noise stays the MMS's own (10 mm)
  Scan mms = simulateMms(scene, streetTrajectory(b.truth.footprint, mp), mp, seed);
  mms.cloud.removeNonFinite();
  return std::move(mms.cloud);
}

std::vector<std::string> scenarioNames() {
  return {"indoor-indoor", "indoor-outdoor", "bim-generated", "bim-duplex"};
}

PipelineParams acceptanceParams() { return PipelineParams{}; }

Scenario makeScenario(const std::string& name, const PipelineParams& params, double noise_mm) {
  Scenario s;
  s.name = name;
  auto t0 = std::chrono::steady_clock::now();
  if (name.rfind("bim-duplex", 0) == 0) {
    s.model = std::make_shared<BimModel>(readModel(sharedData("ifc/duplex.ifc")));
    const ScanScene scene(*s.model);
    // Living rooms of the two dwellings (ground floor 0..2.8 m; found by casting coarse scans
    // from a 1 m grid: no miss, no surface closer than 0.8 m).
    const Eigen::Vector3d unit_a(5.0, -4.0, 1.5), unit_b(4.0, -14.0, 1.5);
    if (name == "bim-duplex")
      s.source = scanStations(scene, {unit_a, unit_b}, noise_mm, 700);
    else if (name == "bim-duplex-unit-a" || name == "bim-duplex-unit-b")
      s.source = scanStations(scene, {name.back() == 'a' ? unit_a : unit_b}, noise_mm, 710);
    else
      throw InputError("unknown scenario '" + name + "'");
  } else {
    const GeneratedBuilding b = generateBuilding(buildingPreset("house"));
    const ScanScene scene(b.model, b.glass_triangles);
    const auto rooms = roomCentres(b.spec, 0);
    if (name == "indoor-indoor") {
      s.source = scanStations(scene, {rooms[0]}, noise_mm, 100);
      s.target = scanStations(scene, {doorwayStation(b, rooms[0], rooms[1])}, noise_mm, 200);
    } else if (name == "indoor-outdoor") {
      s.source = scanStations(scene, rooms, noise_mm, 300);
      MmsParams mp;  // profiler noise stays the MMS's own (10 mm)
      Scan mms = simulateMms(scene, streetTrajectory(b.truth.footprint, mp), mp, 11);
      s.target = std::move(mms.cloud);
      s.target.removeNonFinite();
    } else if (name == "bim-generated") {
      s.source = scanStations(scene, rooms, noise_mm, 400);
      s.model = std::make_shared<BimModel>(b.model);
    } else {
      throw InputError("unknown scenario '" + name + "'");
    }
  }
  s.seconds_simulation = secondsSince(t0);
  t0 = std::chrono::steady_clock::now();
  RegistrationSide side;
  if (s.model) {
    side.model = s.model.get();
    s.target_samples = sampleMeshSurface(s.model->mesh, params.model_sample_spacing, params.seed);
  } else {
    side.cloud = &s.target;
  }
  s.target_features = extractFeatures(side, params, /*with_segments=*/false);
  s.seconds_target_features = secondsSince(t0);
  return s;
}

std::vector<RigidTransform> randomPoses(int n, std::uint64_t seed, double max_shift) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<RigidTransform> out;
  for (int i = 0; i < n; ++i) {
    const double yaw = (-180.0 + 360.0 * u(rng)) * M_PI / 180.0;
    const double r = max_shift * std::sqrt(u(rng)), a = 2 * M_PI * u(rng);
    const Eigen::Vector3d t(r * std::cos(a), r * std::sin(a), -1.0 + 2.0 * u(rng));
    out.emplace_back(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix(), t);
  }
  return out;
}

std::vector<RigidTransform> randomPoses3d(int n, std::uint64_t seed, double max_shift) {
  std::vector<RigidTransform> out = randomPoses(n, seed, max_shift);
  std::mt19937_64 rng(seed ^ 0x3d3d3d3dULL);
  std::normal_distribution<double> g(0.0, 1.0);
  for (auto& pose : out) {
    Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));  // uniform on SO(3) once normalised
    q.normalize();
    pose = RigidTransform(q.toRotationMatrix(), pose.translation());
  }
  return out;
}

PoseError poseError(const RigidTransform& est, const RigidTransform& truth,
                    const Eigen::Vector3d& c) {
  return {RigidTransform::rotationErrorDeg(est, truth), (est.apply(c) - truth.apply(c)).norm()};
}

CaseOutcome runPlumbCase(const Scenario& s, const RigidTransform& pose,
                         const PipelineParams& params) {
  const auto t0 = std::chrono::steady_clock::now();
  PointCloud moved = s.source;
  moved.transform(pose);
  RegistrationSide src, tgt;
  src.cloud = &moved;
  if (s.model) {
    tgt.model = s.model.get();
    tgt.model_samples = &s.target_samples;
  } else {
    tgt.cloud = &s.target;
  }
  tgt.features = &s.target_features;
  const PipelineResult r = registerData(src, tgt, params);
  CaseOutcome o;
  o.seconds_total = secondsSince(t0);
  o.reported_success = r.success();
  o.method = r.method_used;
  o.verdict = r.report.verdict;
  o.status = r.report.status;
  o.visibility = r.report.visibility;
  o.overlap = r.report.overlap_ratio;
  o.level = verdictLevelName(r.report.level);
  o.log = r.log;
  if (r.candidates.size() > 1) {
    char line[200];
    for (const auto& c : r.candidates) {
      std::snprintf(line, sizeof line, "%s%s overlap %.4f RMS %.4f m cost %.4f", o.candidates.empty() ? "" : "; ",
                    c.role.c_str(), c.overlap, c.point_rms, c.fit_cost);
      o.candidates += line;
    }
  }
  o.seconds_features = r.seconds_features;
  o.seconds_global = r.seconds_global;
  o.seconds_refine = r.seconds_refine;
  o.report = r.report;
  if (r.report.refined)
    o.min_resistance = *std::min_element(r.report.direction_resistance.begin(),
                                         r.report.direction_resistance.end());
  if (o.reported_success)
    o.error = poseError(r.transform(), pose.inverse(), moved.bounds().center());
  return o;
}

}  // namespace plumb::test
