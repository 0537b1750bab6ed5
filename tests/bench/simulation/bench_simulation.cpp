// Ray-casting throughput of the scanner simulator (issue 4 target: >= 2 M rays/s on 2 cores
// for a 50k-triangle model). For each backend (CGAL AABB tree, Embree when compiled in) and
// 1 and 2 TBB threads:
//   1. pure ray casting (RayCaster::castAll on precomputed incoherent rays: uniform
//      directions from room centres) against preset big-office (~48.6k triangles, indoor)
//      and the shared duplex.ifc (~25k triangles, imported through assimp);
//   2. the full simulation: one TLS station (0.36 deg grid, 417k pulses) and a 20 s MMS loop
//      around it (50 Hz x 720 pulses = 720k pulses) in/around big-office, output clouds included.
// Acceleration-structure builds are timed separately and never inside the ray timings.
// Each timing is the best of --repeat runs (default 3) to damp other processes' load; the
// load average is printed at start and end. Mrays/CPU-s divides by the process CPU time of
// that run (all threads): it does not count time spent waiting for a core on a loaded machine.
// Usage: bench_simulation [--rays N] [--repeat R] [--backend cgal|embree|all]
//                         [--no-full]   (default 2,000,000 rays per run)
#include <tbb/global_control.h>

#include <time.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include "io/mesh/mesh_io.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/mms_scanner.hpp"
#include "simulation/presets.hpp"
#include "simulation/pulse_random.hpp"
#include "simulation/tls_scanner.hpp"
#include "support/test_support.hpp"

using namespace plumb;
using Clock = std::chrono::steady_clock;

namespace {

struct Options {
  std::size_t rays = 2000000;
  int repeat = 3;
  bool cgal = true, embree = true, full = true;
};

std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

std::vector<RayCasterBackend> backends(const Options& o) {
  std::vector<RayCasterBackend> out;
  if (o.cgal) out.push_back(RayCasterBackend::Cgal);
  if (o.embree && RayCaster::embreeAvailable()) out.push_back(RayCasterBackend::Embree);
  return out;
}

double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Best wall time of `repeat` calls of f, and the CPU time (all threads) of that call. The CPU
// time does not count waiting for a core, so it is a load-independent check of the work done.
struct Timing {
  double wall = 1e30, cpu = 0;
};
template <class F>
Timing bestOf(int repeat, F&& f) {
  Timing best;
  for (int i = 0; i < repeat; ++i) {
    const auto t0 = Clock::now();
    const double c0 = cpuSeconds();
    f();
    const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
    if (wall < best.wall) best = {wall, cpuSeconds() - c0};
  }
  return best;
}

// Rays from points inside the model (room centres if given), uniform directions.
std::vector<Ray> makeRays(std::size_t n, const std::vector<Eigen::Vector3d>& origins) {
  std::vector<Ray> rays(n);
  for (std::size_t i = 0; i < n; ++i) {
    sim::PulseRandom rng(1, i);
    const double z = 2 * rng.uniform() - 1, phi = 2 * M_PI * rng.uniform(), r = std::sqrt(1 - z * z);
    rays[i] = {origins[i % origins.size()], Eigen::Vector3d(r * std::cos(phi), r * std::sin(phi), z)};
  }
  return rays;
}

void pureRays(const Options& o, const std::string& label, const TriangleMesh& mesh, const std::vector<bool>& skip,
              const std::vector<Ray>& rays) {
  for (auto backend : backends(o)) {
    const auto t0 = Clock::now();
    const RayCaster caster(mesh, skip, backend);
    const double build = std::chrono::duration<double>(Clock::now() - t0).count();
    for (int threads : {1, 2}) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
      std::vector<RayHit> hits;
      caster.castAll(std::vector<Ray>(rays.begin(), rays.begin() + std::min<std::size_t>(rays.size(), 10000)), hits);
      const Timing s = bestOf(o.repeat, [&] { caster.castAll(rays, hits); });
      std::size_t hit = 0;
      for (const auto& h : hits) hit += h.hit();
      const double m = static_cast<double>(rays.size()) * 1e-6;
      std::printf("rays  %-20s %-9s %6zu tris  build %6.3f s  threads %d  %7.3f Mrays/s  %7.3f Mrays/CPU-s  (%zu rays, %.1f%% hit)\n",
                  label.c_str(), RayCaster::backendName(backend).c_str(), mesh.triangleCount(), build, threads,
                  m / s.wall, m / s.cpu, rays.size(),
                  100.0 * static_cast<double>(hit) / static_cast<double>(rays.size()));
      std::fflush(stdout);
    }
  }
}

void fullSimulation(const Options& o, const GeneratedBuilding& big, const Eigen::Vector3d& station) {
  MmsParams mp;
  mp.speed *= streetTrajectory(big.truth.footprint, mp).duration() / 20.0;  // one loop in 20 s
  const Trajectory traj = streetTrajectory(big.truth.footprint, mp);
  for (auto backend : backends(o)) {
    ScanSceneOptions so;
    so.backend = backend;
    const auto t0 = Clock::now();
    const ScanScene scene(big.model, big.glass_triangles, so);
    const double build = std::chrono::duration<double>(Clock::now() - t0).count();
    const std::string name = RayCaster::backendName(backend);
    for (int threads : {1, 2}) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
      TlsParams tp;
      Scan tls;
      const Timing st = bestOf(o.repeat, [&] { tls = simulateTls(scene, station, tp, 1); });
      const double pulses = static_cast<double>(tls.cloud.grid_rows) * tls.cloud.grid_columns;
      std::printf("TLS   big-office station   %-9s scene build %6.3f s  threads %d  %7.3f Mrays/s  %7.3f Mrays/CPU-s  (%.0f pulses, %zu points, %.3f s)\n",
                  name.c_str(), build, threads, pulses / st.wall * 1e-6, pulses / st.cpu * 1e-6, pulses, tls.cloud.size(), st.wall);
      Scan mms;
      const Timing sm = bestOf(o.repeat, [&] { mms = simulateMms(scene, traj, mp, 1); });
      const double mpulses = static_cast<double>(mms.cloud.grid_rows) * mms.cloud.grid_columns;
      std::printf("MMS   big-office 20 s loop %-9s scene build %6.3f s  threads %d  %7.3f Mrays/s  %7.3f Mrays/CPU-s  (%.0f pulses, %zu points, %.3f s)\n",
                  name.c_str(), build, threads, mpulses / sm.wall * 1e-6, mpulses / sm.cpu * 1e-6, mpulses, mms.cloud.size(), sm.wall);
      std::fflush(stdout);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const char* next = i + 1 < argc ? argv[i + 1] : "";
    if (a == "--rays") o.rays = std::stoul(next), ++i;
    else if (a == "--repeat") o.repeat = std::max(1, std::stoi(next)), ++i;
    else if (a == "--backend") {
      o.cgal = std::strcmp(next, "embree") != 0;
      o.embree = std::strcmp(next, "cgal") != 0;
      ++i;
    } else if (a == "--no-full") o.full = false;
  }
  std::printf("load average at start: %s\n", loadAverage().c_str());

  const auto t0 = Clock::now();
  const GeneratedBuilding big = generateBuilding(buildingPreset("big-office"));
  std::printf("generate big-office: %zu triangles, %zu elements, %zu sharp edges in %.3f s\n",
              big.model.mesh.triangleCount(), big.model.elements.size(), big.truth.sharp_edges.size(),
              std::chrono::duration<double>(Clock::now() - t0).count());
  std::vector<Eigen::Vector3d> origins;
  for (int s = 0; s < big.spec.storeys; ++s)
    for (const auto& c : roomCentres(big.spec, s)) origins.push_back(c);
  pureRays(o, "big-office (indoor)", big.model.mesh, big.glass_triangles, makeRays(o.rays, origins));

  try {
    const BimModel duplex = readMesh(test::sharedData("ifc/duplex.ifc"));
    const Eigen::Vector3d c = duplex.mesh.bounds().center();
    std::vector<Eigen::Vector3d> d{c, c + Eigen::Vector3d(2, 1, 0), c - Eigen::Vector3d(2, 1, 0)};
    pureRays(o, "duplex.ifc", duplex.mesh, {}, makeRays(o.rays, d));
  } catch (const std::exception& e) {
    std::printf("duplex.ifc skipped: %s\n", e.what());
  }

  if (o.full) fullSimulation(o, big, origins[7]);
  std::printf("load average at end: %s\n", loadAverage().c_str());
  return 0;
}
