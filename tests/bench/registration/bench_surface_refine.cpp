// bench_surface_refine (issue 14, "refinement against the surface, not samples"): simulated
// TLS stations (0.5 deg steps, 3 mm noise, sensor origins) inside duplex.ifc and the generated
// "house" preset, each moved by random levelled poses (acceptance_scenarios.hpp), refined
// against the model with refinement.model-surface = samples and = triangles:
//   truth     the refinement started at the truth (it must stay there),
//   offset    started 0.3 deg / 3 cm off the truth (random axis and direction),
//   pipeline  the whole registration (auto), unless --no-pipeline.
// Prints per station and surface the median and max rotation error (deg), translation error
// at the source centroid (mm) and the median time per refinement / registration (s).
//
//   bench_surface_refine [--poses N] [--models duplex,house] [--no-pipeline] [--huber M]
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
  Errors truth[2], off[2], pipe[2];
};

void runStation(const Model& m, std::size_t k, int poses, bool pipeline, const PipelineParams& base,
                Totals& tot) {
  const PointCloud cloud = scanStation(m, m.stations[k], 900 + k);
  std::printf("\n== %s station %zu (%.1f, %.1f, %.1f): %zu points\n", m.name.c_str(), k,
              m.stations[k].x(), m.stations[k].y(), m.stations[k].z(), cloud.size());
  for (int si = 0; si < 2; ++si) {
    PipelineParams p = base;
    p.refinement.model_surface = kSurfaces[si].kind;
    auto t0 = std::chrono::steady_clock::now();
    const RefineTarget target = kSurfaces[si].kind == RefineParams::ModelSurface::Triangles
                                    ? RefineTarget(m.model.mesh, p.refinement)
                                    : RefineTarget(m.samples, p.refinement);
    const double prep = secondsSince(t0);
    std::mt19937_64 rng(77 + k);
    Errors truth, off, pipe;
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
      // The offset about the source centroid: x -> gt(x), then moved about gt(c).
      const RigidTransform d = offset(rng, 0.3, 0.03);
      const Eigen::Vector3d gc = gt.apply(c);
      const RigidTransform start = RigidTransform(Eigen::Matrix3d::Identity(), gc) * d *
                                   RigidTransform(Eigen::Matrix3d::Identity(), -gc) * gt;
      t0 = std::chrono::steady_clock::now();
      const RefineResult b = refineRegistration(moved, target, start, p.refinement);
      off.add(poseError(b.transform, gt, c), secondsSince(t0));
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
        std::printf("  pipeline %s FAILED: %s\n", kSurfaces[si].name, r.report.verdict.c_str());
        continue;
      }
      pipe.add(poseError(r.transform(), gt, c), s);
    }
    std::printf(" surface %s (%s; target prepared in %.3f s)\n", kSurfaces[si].name, surface.c_str(), prep);
    printRow("refine from the truth", truth);
    printRow("refine from 0.3 deg / 3 cm off", off);
    if (pipeline) printRow("pipeline (auto)", pipe);
    tot.truth[si].append(truth);
    tot.off[si].append(off);
    tot.pipe[si].append(pipe);
  }
}

}  // namespace

int main(int argc, char** argv) {
  int poses = 10;
  bool pipeline = true;
  std::vector<std::string> models = {"duplex", "house"};
  PipelineParams base = acceptanceParams();
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--poses") poses = std::stoi(next());
    else if (a == "--no-pipeline") pipeline = false;
    else if (a == "--huber") base.refinement.huber = std::stod(next());
    else if (a == "--models") {
      models.clear();
      std::string list = next();
      for (std::size_t s = 0, e; s <= list.size(); s = e + 1) {
        e = std::min(list.find(',', s), list.size());
        models.push_back(list.substr(s, e - s));
      }
    } else {
      std::fprintf(stderr, "usage: bench_surface_refine [--poses N] [--models duplex,house] [--no-pipeline] [--huber M]\n");
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
    for (std::size_t k = 0; k < m.stations.size(); ++k) runStation(m, k, poses, pipeline, base, tot);
  }
  std::printf("\n== all stations\n");
  for (int si = 0; si < 2; ++si) {
    std::printf(" surface %s\n", kSurfaces[si].name);
    printRow("refine from the truth", tot.truth[si]);
    printRow("refine from 0.3 deg / 3 cm off", tot.off[si]);
    if (pipeline) printRow("pipeline (auto)", tot.pipe[si]);
  }
  return 0;
}
