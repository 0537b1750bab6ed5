// bench_surface_refine (issue 14, "refinement against the surface, not samples"): simulated
// TLS stations (0.5 deg steps, 3 mm noise, sensor origins) inside duplex.ifc and the generated
// "house" preset, each moved by random levelled poses (acceptance_scenarios.hpp), refined
// against the model with refinement.model-surface = samples and = triangles:
//   truth     the refinement started at the truth (it must stay there),
//   offset    started 0.3 deg / 3 cm and 1 deg / 10 cm off the truth (random axis and
//             direction); triangles also with the visible set found once (under the start)
//             instead of at each stage,
//   pipeline  the whole registration (auto), unless --no-pipeline.
// Prints per station and surface the median and max rotation error (deg), translation error
// at the source centroid (mm) and the median time per refinement / registration (s).
//
//   bench_surface_refine [--poses N] [--models duplex,house] [--stations 0,2] [--no-pipeline]
//                        [--huber M] [--detail] [--surface samples|triangles]
#include <Eigen/Geometry>

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "acceptance_scenarios.hpp"
#include "common/stopwatch.hpp"
#include "io/io.hpp"
#include "model/dataset.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/presets.hpp"
#include "simulation/scan_scene.hpp"
#include "simulation/tls_scanner.hpp"
#include "support/test_support.hpp"

using namespace plumb;
using namespace plumb::test;

namespace {

struct Model {
  std::string name;
  BimModel model;
  std::vector<bool> glass;
  std::vector<Eigen::Vector3d> stations;
  FeatureSet features;
  PointCloud samples;
};

Model duplexModel() {
  Model m{"duplex", readModel(sharedData("ifc/duplex.ifc")), {}, {}, {}, {}};
  // Living rooms of both dwellings (acceptance_scenarios.cpp) and the first unit's upper floor.
  m.stations = {{5.0, -4.0, 1.5}, {4.0, -14.0, 1.5}, {5.0, -4.0, 4.3}};
  return m;
}

Model houseModel() {
  GeneratedBuilding b = generateBuilding(buildingPreset("house"));
  Model m{"house", std::move(b.model), std::move(b.glass_triangles), {}, {}, {}};
  m.stations = roomCentres(b.spec, 0);
  if (m.stations.size() > 3) m.stations.resize(3);
  return m;
}

PointCloud scanStation(const Model& m, const Eigen::Vector3d& station, std::uint64_t seed) {
  const ScanScene scene(m.model, m.glass);
  TlsParams tp;
  tp.azimuth_step_deg = tp.elevation_step_deg = 0.5;
  tp.noise_mm = 3.0;
  Dataset d;
  d.scans.push_back(simulateTls(scene, station, tp, seed));
  PointCloud c = d.merged(true);
  c.removeNonFinite();
  return c;
}

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
double maxOf(const std::vector<double>& v) { return v.empty() ? std::nan("") : *std::max_element(v.begin(), v.end()); }

struct Errors {
  std::vector<double> rot, trans_mm, seconds;
  int failed = 0;
  void add(const PoseError& e, double s) {
    rot.push_back(e.rotation_deg);
    trans_mm.push_back(1000.0 * e.translation_m);
    seconds.push_back(s);
  }
  void append(const Errors& o) {
    rot.insert(rot.end(), o.rot.begin(), o.rot.end());
    trans_mm.insert(trans_mm.end(), o.trans_mm.begin(), o.trans_mm.end());
    seconds.insert(seconds.end(), o.seconds.begin(), o.seconds.end());
    failed += o.failed;
  }
};

void printRow(const std::string& what, const Errors& e) {
  std::printf("  %-34s n %3zu fail %2d  rot med %.4f max %.4f deg  trans med %6.2f max %6.2f mm  time med %.3f s\n",
              what.c_str(), e.rot.size(), e.failed, median(e.rot), maxOf(e.rot), median(e.trans_mm),
              maxOf(e.trans_mm), median(e.seconds));
  std::fflush(stdout);
}

/// A small random offset: `deg` about a random axis, `m` in a random direction.
RigidTransform offset(std::mt19937_64& rng, double deg, double m) {
  std::normal_distribution<double> g(0.0, 1.0);
  const Eigen::Vector3d axis = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
  const Eigen::Vector3d dir = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
  return RigidTransform(Eigen::AngleAxisd(deg * M_PI / 180.0, axis).toRotationMatrix(), m * dir);
}

struct Surface {
  const char* name;
  RefineParams::ModelSurface kind;
};
const Surface kSurfaces[] = {{"samples", RefineParams::ModelSurface::Samples},
                             {"triangles", RefineParams::ModelSurface::Triangles}};

struct Totals {
  Errors truth[2], off[2], far[2], far_once, pipe[2];
  std::vector<double> visibility_seconds;
};

/// `gt` moved by `d` about the point gt(c).
RigidTransform startNear(const RigidTransform& gt, const Eigen::Vector3d& c, const RigidTransform& d) {
  const Eigen::Vector3d gc = gt.apply(c);
  return RigidTransform(Eigen::Matrix3d::Identity(), gc) * d * RigidTransform(Eigen::Matrix3d::Identity(), -gc) * gt;
}

bool detail = false;  ///< --detail: every pipeline case with its candidates and log
std::string only_surface;  ///< --surface NAME: only that surface

void runStation(const Model& m, std::size_t k, int poses, bool pipeline, const PipelineParams& base,
                Totals& tot) {
  const PointCloud cloud = scanStation(m, m.stations[k], 900 + k);
  std::printf("\n== %s station %zu (%.1f, %.1f, %.1f): %zu points\n", m.name.c_str(), k,
              m.stations[k].x(), m.stations[k].y(), m.stations[k].z(), cloud.size());
  for (int si = 0; si < 2; ++si) {
    if (!only_surface.empty() && only_surface != kSurfaces[si].name) continue;
    PipelineParams p = base;
    p.refinement.model_surface = kSurfaces[si].kind;
    auto t0 = std::chrono::steady_clock::now();
    const RefineTarget target = kSurfaces[si].kind == RefineParams::ModelSurface::Triangles
                                    ? RefineTarget(m.model.mesh, p.refinement)
                                    : RefineTarget(m.samples, p.refinement);
    const double prep = secondsSince(t0);
    std::mt19937_64 rng(77 + k);
    Errors truth, off, far, far_once, pipe;
    std::string surface;
    for (const RigidTransform& pose : randomPoses(poses, 500 + k)) {
      PointCloud moved = cloud;
      moved.transform(pose);
      const RigidTransform gt = pose.inverse();
      const Eigen::Vector3d c = moved.bounds().center();
      t0 = std::chrono::steady_clock::now();
      const RefineResult a = refineRegistration(moved, target, gt, p.refinement);
      truth.add(poseError(a.transform, gt, c), secondsSince(t0));
      surface = a.surface + ", " + std::to_string(a.target_points) + " used";
      if (a.visibility_seconds > 0) tot.visibility_seconds.push_back(a.visibility_seconds);
      const RigidTransform small = startNear(gt, c, offset(rng, 0.3, 0.03));
      t0 = std::chrono::steady_clock::now();
      const RefineResult b = refineRegistration(moved, target, small, p.refinement);
      off.add(poseError(b.transform, gt, c), secondsSince(t0));
      const RigidTransform large = startNear(gt, c, offset(rng, 1.0, 0.10));
      t0 = std::chrono::steady_clock::now();
      const RefineResult f = refineRegistration(moved, target, large, p.refinement);
      far.add(poseError(f.transform, gt, c), secondsSince(t0));
      if (kSurfaces[si].kind == RefineParams::ModelSurface::Triangles) {
        RefineParams once = p.refinement;
        once.visibility_per_stage = false;
        t0 = std::chrono::steady_clock::now();
        const RefineResult g = refineRegistration(moved, target, large, once);
        far_once.add(poseError(g.transform, gt, c), secondsSince(t0));
      }
      if (!pipeline) continue;
      RegistrationSide src, tgt;
      src.cloud = &moved;
      tgt.model = &m.model;
      tgt.features = &m.features;
      tgt.model_samples = &m.samples;
      t0 = std::chrono::steady_clock::now();
      const PipelineResult r = registerData(src, tgt, p);
      const double s = secondsSince(t0);
      if (!r.success()) {
        ++pipe.failed;
        std::printf("  pipeline %s: %s\n", kSurfaces[si].name, r.report.status.c_str());
        continue;
      }
      const PoseError e = poseError(r.transform(), gt, c);
      pipe.add(e, s);
      if (!withinTolerance(e) || detail) {
        std::printf("  pipeline %s returned %.4f deg %.1f mm (%s):", kSurfaces[si].name, e.rotation_deg,
                    1000 * e.translation_m, r.report.status.c_str());
        for (const auto& cand : r.candidates)
          std::printf(" [%s %s: overlap %.4f RMS %.4f fit cost %.4f]", cand.role.c_str(), cand.label.c_str(),
                      cand.overlap, cand.point_rms, cand.fit_cost);
        std::printf("\n");
        for (const auto& line : r.log)
          if (detail) std::printf("    %s\n", line.c_str());
      }
    }
    std::printf(" surface %s (%s; target prepared in %.3f s)\n", kSurfaces[si].name, surface.c_str(), prep);
    printRow("refine from the truth", truth);
    printRow("refine from 0.3 deg / 3 cm off", off);
    printRow("refine from 1 deg / 10 cm off", far);
    if (!far_once.rot.empty()) printRow("  the same, visibility once", far_once);
    if (pipeline) printRow("pipeline (auto)", pipe);
    tot.truth[si].append(truth);
    tot.off[si].append(off);
    tot.far[si].append(far);
    tot.far_once.append(far_once);
    tot.pipe[si].append(pipe);
  }
}

}  // namespace

int main(int argc, char** argv) {
  int poses = 10;
  bool pipeline = true;
  std::vector<std::string> models = {"duplex", "house"};
  PipelineParams base = acceptanceParams();
  std::string stations;  // --stations 0,2: only these station indices
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--poses") poses = std::stoi(next());
    else if (a == "--no-pipeline") pipeline = false;
    else if (a == "--detail") detail = true;
    else if (a == "--surface") only_surface = next();
    else if (a == "--stations") stations = next();
    else if (a == "--huber") base.refinement.huber = std::stod(next());
    else if (a == "--models") {
      models.clear();
      std::string list = next();
      for (std::size_t s = 0, e; s <= list.size(); s = e + 1) {
        e = std::min(list.find(',', s), list.size());
        models.push_back(list.substr(s, e - s));
      }
    } else {
      std::fprintf(stderr, "usage: bench_surface_refine [--poses N] [--models duplex,house] [--stations 0,2] "
                           "[--no-pipeline] [--huber M] [--detail] [--surface samples|triangles]\n");
      return 1;
    }
  }
  Totals tot;
  for (const std::string& name : models) {
    Model m = name == "duplex" ? duplexModel() : houseModel();
    RegistrationSide side;
    side.model = &m.model;
    m.features = extractFeatures(side, base, false);
    m.samples = sampleMeshSurface(m.model.mesh, base.model_sample_spacing, base.seed);
    std::printf("\n### %s: %zu triangles, %zu samples\n", m.name.c_str(), m.model.mesh.triangles.size(),
                m.samples.size());
    for (std::size_t k = 0; k < m.stations.size(); ++k)
      if (stations.empty() || stations.find(std::to_string(k)) != std::string::npos)
        runStation(m, k, poses, pipeline, base, tot);
  }
  std::printf("\n== all stations\n");
  for (int si = 0; si < 2; ++si) {
    std::printf(" surface %s\n", kSurfaces[si].name);
    printRow("refine from the truth", tot.truth[si]);
    printRow("refine from 0.3 deg / 3 cm off", tot.off[si]);
    printRow("refine from 1 deg / 10 cm off", tot.far[si]);
    if (si == 1) printRow("  the same, visibility once", tot.far_once);
    if (pipeline) printRow("pipeline (auto)", tot.pipe[si]);
  }
  std::printf("visible triangles: %zu refinements, median %.4f s finding them (all stages)\n",
              tot.visibility_seconds.size(), median(tot.visibility_seconds));
  return 0;
}
