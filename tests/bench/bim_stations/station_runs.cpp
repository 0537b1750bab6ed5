#include "station_runs.hpp"

#include <cstdio>
#include <functional>
#include <stdexcept>

#include "acceptance_scenarios.hpp"
#include "model/dataset.hpp"
#include "pair_runner.hpp"
#include "placement_oracle.hpp"
#include "quality/quality_report.hpp"
#include "simulation/tls_scanner.hpp"

namespace plumb::bimst {

const char* setName(PoseSet s) { return s == PoseSet::Yaw ? "yaw" : "3d"; }

std::vector<PoseSet> parseSets(const std::string& list) {
  std::vector<PoseSet> out;
  for (const std::string& name : splitList(list)) {
    if (name == "yaw") out.push_back(PoseSet::Yaw);
    else if (name == "3d") out.push_back(PoseSet::Any3d);
    else throw std::invalid_argument("unknown pose set '" + name + "' (yaw, 3d)");
  }
  return out;
}

const char* outcomeName(Outcome o) {
  switch (o) {
    case Outcome::Placed: return "placed";
    case Outcome::AmbiguousRepeat: return "ambiguous-repeat";
    case Outcome::Failed: return "failed";
    case Outcome::Wrong: break;
  }
  return "WRONG";
}

namespace {

std::uint64_t stationSeed(const CatalogueStation& s, const RunParams& p) {
  const Eigen::Vector3i cm = (100.0 * s.position).cast<int>();
  return p.seed ^ std::hash<std::string>{}(s.model) ^ (std::uint64_t(cm.x()) * 73856093u) ^
         (std::uint64_t(cm.y()) * 19349663u) ^ (std::uint64_t(cm.z()) * 83492791u);
}

PointCloud scanAt(const StationModel& m, const Eigen::Vector3d& station, std::uint64_t seed,
                  const RunParams& p) {
  TlsParams tp;
  tp.azimuth_step_deg = tp.elevation_step_deg = p.tls_step_deg;
  tp.noise_mm = p.noise_mm;
  Dataset d;
  d.scans.push_back(simulateTls(*m.scene, station, tp, seed));
  PointCloud c = d.merged(true);
  c.removeNonFinite();
  return c;
}

bool nearTruth(const RigidTransform& t, const RigidTransform& truth, const Eigen::Vector3d& c,
               const RunParams& p) {
  const test::PoseError e = test::poseError(t, truth, c);
  return e.rotation_deg < p.listed_rotation_deg && e.translation_m < p.listed_translation_m;
}

/// Whether a surface of the model lies between a and b (they are in different rooms).
bool separated(const ScanScene& scene, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const double d = (b - a).norm();
  return d > 1e-6 && scene.caster().cast(Ray{a, (b - a) / d}, d).hit();
}

/// Whether the truth is among the reported placements, and whether another reported placement
/// puts the room where the model genuinely repeats it (model frame -> model frame: P * pose),
/// elsewhere or onto itself.
void checkPlacements(const verdict::PairOutcome& o, const StationModel& m, const Eigen::Vector3d& station,
                     const RigidTransform& pose, const RunParams& p, RunRecord& r) {
  const RigidTransform truth = pose.inverse();
  const Eigen::Vector3d c = pose.apply(station);
  for (const RigidTransform& t : verdict::reportedPlacements(o)) {
    if (nearTruth(t, truth, c, p)) {
      r.truth_listed = true;
      continue;
    }
    const RigidTransform q = t * pose;
    if (r.genuine_repeat || !verdict::rangeAgreement(*m.bare_scene, *m.bare_scene, {station}, q).genuine())
      continue;
    const bool elsewhere = separated(*m.bare_scene, station, q.apply(station));
    r.genuine_repeat = elsewhere;
    r.self_symmetric = r.self_symmetric || !elsewhere;
  }
}

Outcome outcomeOf(const RunRecord& r, const RunParams& p) {
  if (r.reported_success)
    return r.rotation_deg < p.max_rotation_deg && r.translation_m < p.max_translation_m ? Outcome::Placed
                                                                                         : Outcome::Wrong;
  return r.status == "ambiguous" && r.truth_listed && r.genuine_repeat ? Outcome::AmbiguousRepeat
                                                                       : Outcome::Failed;
}

RunRecord runPose(const test::Scenario& scan, const StationModel& m, const CatalogueStation& s,
                  const RigidTransform& pose, const RunParams& p) {
  RunRecord r{s.model, s.type, s.position};
  r.points = scan.source.size();
  const test::CaseOutcome c = test::runPlumbCase(scan, pose, p.pipeline);
  r.seconds = c.seconds_total;
  r.level = c.level;
  r.status = c.status;
  r.method = c.method;
  r.log = c.log;
  for (const PlacementCandidate& k : c.report.candidates) {  // each candidate against the truth
    const test::PoseError e = test::poseError(k.transform, pose.inverse(), pose.apply(s.position));
    const Eigen::AngleAxisd err(k.transform.rotation() * pose.rotation());  // truth = pose^-1
    char line[240];
    std::snprintf(line, sizeof line,
                  "candidate %s (%s): %.4f deg about (%.2f, %.2f, %.2f), %.1f mm from the truth, overlap %.4f",
                  k.role.c_str(), k.label.c_str(), e.rotation_deg, err.axis().x(), err.axis().y(),
                  err.axis().z(), 1000.0 * e.translation_m, k.overlap);
    r.log.push_back(line);
  }
  r.reported_success = c.reported_success;
  if (r.reported_success) {
    const test::PoseError e = test::poseError(c.report.transform, pose.inverse(), pose.apply(s.position));
    r.rotation_deg = e.rotation_deg;
    r.translation_m = e.translation_m;
  }
  const verdict::PairOutcome o{c.report, qualityReportToJson(c.report), r.seconds};
  checkPlacements(o, m, s.position, pose, p, r);
  r.outcome = outcomeOf(r, p);
  return r;
}

void printRun(const RunRecord& r) {
  std::printf("  [run] %-28s %-8s (%6.1f, %6.1f, %5.1f) %-3s pose %2d: %-16s %-14s %-26s rot %8.4f deg "
              "trans %7.1f mm  listed %d repeat %d self-symmetric %d  %s  %.1f s\n",
              r.model.c_str(), typeName(r.type), r.station.x(), r.station.y(), r.station.z(), setName(r.set),
              r.pose, outcomeName(r.outcome), r.level.c_str(), r.status.substr(0, 26).c_str(), r.rotation_deg,
              1000.0 * r.translation_m, int(r.truth_listed), int(r.genuine_repeat), int(r.self_symmetric),
              r.method.c_str(), r.seconds);
  std::fflush(stdout);
}

}  // namespace

std::vector<RunRecord> runStation(const StationModel& m, const CatalogueStation& s, const RunParams& p) {
  const std::uint64_t seed = stationSeed(s, p);
  test::Scenario scan;  // the station's scan onto the whole model (runPlumbCase's input)
  scan.name = s.model + " " + typeName(s.type);
  scan.source = scanAt(m, s.position, seed, p);
  scan.model = m.model;
  scan.target_features = m.features;
  scan.target_samples = m.samples;
  std::vector<RunRecord> out;
  for (PoseSet set : p.sets) {
    const auto poses = set == PoseSet::Yaw ? test::randomPoses(p.poses, seed + 1, p.max_shift)
                                           : test::randomPoses3d(p.poses, seed + 2, p.max_shift);
    for (int i = 0; i < p.poses; ++i) {
      RunRecord r = runPose(scan, m, s, poses[std::size_t(i)], p);
      r.set = set;
      r.pose = i;
      printRun(r);
      if (p.print_log && !isSuccess(r.outcome))
        for (const std::string& line : r.log) std::printf("      | %s\n", line.c_str());
      out.push_back(std::move(r));
    }
  }
  return out;
}

}  // namespace plumb::bimst
