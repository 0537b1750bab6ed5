// Ray-casting throughput of the scanner simulator: rays/s against a ~50k-triangle generated
// building (preset big-office) and the shared duplex.ifc, for each backend (CGAL AABB tree,
// Embree when compiled in) with 1 and 2 TBB threads; then a full TLS station end to end.
// Usage: bench_simulation [--rays N]   (default 2,000,000 rays per run)
#include <tbb/global_control.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "io/mesh/mesh_io.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/presets.hpp"
#include "simulation/pulse_random.hpp"
#include "simulation/tls_scanner.hpp"
#include "support/test_support.hpp"

using namespace plumb;
using Clock = std::chrono::steady_clock;

namespace {

// Rays from points inside the model's bounds (room centres if given), uniform directions.
std::vector<Ray> makeRays(std::size_t n, const std::vector<Eigen::Vector3d>& origins) {
  std::vector<Ray> rays(n);
  for (std::size_t i = 0; i < n; ++i) {
    sim::PulseRandom rng(1, i);
    const double z = 2 * rng.uniform() - 1, phi = 2 * M_PI * rng.uniform(), r = std::sqrt(1 - z * z);
    rays[i] = {origins[i % origins.size()], Eigen::Vector3d(r * std::cos(phi), r * std::sin(phi), z)};
  }
  return rays;
}

void run(const std::string& label, const TriangleMesh& mesh, const std::vector<bool>& skip,
         const std::vector<Ray>& rays) {
  for (auto backend : {RayCasterBackend::Cgal, RayCasterBackend::Embree}) {
    if (backend == RayCasterBackend::Embree && !RayCaster::embreeAvailable()) continue;
    const auto t0 = Clock::now();
    const RayCaster caster(mesh, skip, backend);
    const double build = std::chrono::duration<double>(Clock::now() - t0).count();
    for (int threads : {1, 2}) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
      std::vector<RayHit> hits;
      caster.castAll(std::vector<Ray>(rays.begin(), rays.begin() + std::min<std::size_t>(rays.size(), 1000)), hits);  // warm-up
      const auto t1 = Clock::now();
      caster.castAll(rays, hits);
      const double s = std::chrono::duration<double>(Clock::now() - t1).count();
      std::size_t hit = 0;
      for (const auto& h : hits) hit += h.hit();
      std::printf("%-22s %-10s %zu tris  build %6.3f s  threads %d  %8.3f Mrays/s  (%zu rays, %.1f%% hit)\n",
                  label.c_str(), RayCaster::backendName(backend).c_str(), mesh.triangleCount(), build, threads,
                  static_cast<double>(rays.size()) / s * 1e-6, rays.size(), 100.0 * static_cast<double>(hit) / static_cast<double>(rays.size()));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t n = 2000000;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--rays") == 0) n = std::stoul(argv[i + 1]);

  const auto t0 = Clock::now();
  const GeneratedBuilding big = generateBuilding(buildingPreset("big-office"));
  std::printf("generate big-office: %zu triangles, %zu elements, %zu sharp edges in %.3f s\n",
              big.model.mesh.triangleCount(), big.model.elements.size(), big.truth.sharp_edges.size(),
              std::chrono::duration<double>(Clock::now() - t0).count());
  std::vector<Eigen::Vector3d> origins;
  for (int s = 0; s < big.spec.storeys; ++s)
    for (const auto& c : roomCentres(big.spec, s)) origins.push_back(c);
  run("big-office (indoor)", big.model.mesh, big.glass_triangles, makeRays(n, origins));

  try {
    const BimModel duplex = readMesh(test::sharedData("ifc/duplex.ifc"));
    const Eigen::Vector3d c = duplex.mesh.bounds().center();
    std::vector<Eigen::Vector3d> o{c, c + Eigen::Vector3d(2, 1, 0), c - Eigen::Vector3d(2, 1, 0)};
    run("duplex.ifc", duplex.mesh, {}, makeRays(n, o));
  } catch (const std::exception& e) {
    std::printf("duplex.ifc skipped: %s\n", e.what());
  }

  // End to end: one TLS station (0.36 deg grid: 1000 x 418 pulses) in the big office.
  const ScanScene scene(big.model, big.glass_triangles);
  TlsParams p;
  const auto t2 = Clock::now();
  const Scan scan = simulateTls(scene, origins[7], p, 1);
  const double s = std::chrono::duration<double>(Clock::now() - t2).count();
  const double pulses = static_cast<double>(scan.cloud.grid_rows) * scan.cloud.grid_columns;
  std::printf("TLS station big-office (%s, all threads): %.0f pulses, %zu points in %.3f s = %.3f Mpulses/s\n",
              RayCaster::backendName(scene.caster().backend()).c_str(), pulses, scan.cloud.size(), s, pulses / s * 1e-6);
  return 0;
}
