#include "simulated_scans.hpp"

#include <algorithm>

#include "model/dataset.hpp"
#include "simulation/mms_scanner.hpp"
#include "simulation/presets.hpp"
#include "simulation/scan_scene.hpp"
#include "simulation/tls_scanner.hpp"

namespace plumb::test {

PointCloud indoorTls(const GeneratedBuilding& b, double step_deg, double noise_mm, int max_stations) {
  const ScanScene scene(b.model, b.glass_triangles);
  TlsParams p;
  p.azimuth_step_deg = step_deg;
  p.elevation_step_deg = step_deg;
  p.noise_mm = noise_mm;
  Dataset d;
  int k = 0;
  for (const auto& station : roomCentres(b.spec)) {
    if (k >= max_stations) break;
    d.scans.push_back(simulateTls(scene, station, p, 100 + k++));
  }
  return d.merged(true);
}

PointCloud outdoorMms(const GeneratedBuilding& b, double noise_mm) {
  const ScanScene scene(b.model, b.glass_triangles);
  MmsParams p;
  p.noise_mm = noise_mm;
  const Trajectory traj = streetTrajectory(b.truth.footprint, p);
  Scan s = simulateMms(scene, traj, p, 11);
  return std::move(s.cloud);
}

TriangleMesh meshWithoutGlass(const GeneratedBuilding& b) {
  TriangleMesh m = b.model.mesh;
  m.triangles.clear();
  for (std::size_t t = 0; t < b.model.mesh.triangles.size(); ++t)
    if (t >= b.glass_triangles.size() || !b.glass_triangles[t]) m.triangles.push_back(b.model.mesh.triangles[t]);
  return m;
}

double pointSegmentDistance(const Eigen::Vector3d& p, const Segment3D& s) {
  const Eigen::Vector3d d = s.b - s.a;
  const double t = std::clamp((p - s.a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (s.a + t * d - p).norm();
}

}  // namespace plumb::test
