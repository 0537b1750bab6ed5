// Simulated scanners: plausibility (hit ratio, points on truth planes, interior points seen
// through windows), determinism, perturbation truth, ray caster backends agree.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/mms_scanner.hpp"
#include "simulation/perturbation.hpp"
#include "simulation/presets.hpp"
#include "simulation/tls_scanner.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

TlsParams coarseTls(double noise_mm) {
  TlsParams p;
  p.azimuth_step_deg = 1.0;
  p.elevation_step_deg = 1.0;
  p.noise_mm = noise_mm;
  return p;
}

// Distance from x to the nearest truth plane.
double nearestPlane(const BuildingTruth& t, const Eigen::Vector3d& x) {
  double best = 1e30;
  for (const auto& p : t.planes) best = std::min(best, std::abs(p.normal.dot(x) - p.offset));
  return best;
}

void expectSameCloud(const Scan& a, const Scan& b) {
  ASSERT_EQ(a.cloud.size(), b.cloud.size());
  EXPECT_TRUE(a.cloud.positions == b.cloud.positions);
  EXPECT_TRUE(a.cloud.column == b.cloud.column);
  EXPECT_TRUE(a.cloud.timestamps == b.cloud.timestamps);
  EXPECT_TRUE(a.cloud.classification == b.cloud.classification);
}

// make() run with one thread, then with all threads.
template <class F>
auto oneAndAllThreads(F make) {
  decltype(make()) one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = make();
  }
  return std::make_pair(std::move(one), make());
}

TEST(Tls, HitRatioIndoorsIsCloseToOne) {
  const auto b = generateBuilding(buildingPreset("two-rooms"));
  ScanSceneOptions opaque;
  opaque.glass_transparent = false;
  const ScanScene scene(b.model, b.glass_triangles, opaque);
  TlsParams p = coarseTls(2.0);
  p.keep_misses = true;
  const auto station = roomCentres(b.spec)[1];  // the room without the entrance door
  const Scan s = simulateTls(scene, station, p, 7);
  ASSERT_EQ(s.cloud.size(), static_cast<std::size_t>(s.cloud.grid_rows * s.cloud.grid_columns));
  std::size_t valid = 0;
  for (const auto& q : s.cloud.positions) valid += std::isfinite(q.x());
  const double ratio = static_cast<double>(valid) / static_cast<double>(s.cloud.size());
  EXPECT_GT(ratio, 0.97);  // only the interior door lets rays out (into the other closed room)
  EXPECT_EQ(s.cloud.grid_columns, 360);
  EXPECT_EQ(s.cloud.grid_rows, 151);
  EXPECT_TRUE(s.has_pose);
  EXPECT_TRUE(s.pose.translation().isApprox(station));
}

TEST(Tls, PointsLieOnTruthPlanesWithinNoise) {
  for (const char* name : {"house", "non-manhattan"}) {
    SCOPED_TRACE(name);
    const auto b = generateBuilding(buildingPreset(name));
    const ScanScene scene(b.model, b.glass_triangles);
    const double sigma = 0.003;
    const Scan s = simulateTls(scene, roomCentres(b.spec)[0], coarseTls(sigma * 1e3), 3);
    ASSERT_GT(s.cloud.size(), 10000u);
    std::size_t within = 0;
    double sum2 = 0.0;
    for (std::size_t i = 0; i < s.cloud.size(); ++i) {
      const double d = nearestPlane(b.truth, s.pose.apply(s.cloud.positions[i].cast<double>()));
      within += d < 4 * sigma;
      sum2 += std::min(d, 4 * sigma) * std::min(d, 4 * sigma);
    }
    EXPECT_GT(static_cast<double>(within) / static_cast<double>(s.cloud.size()), 0.99);
    // The noise is there: RMS distance to the nearest plane is close to sigma (a point may
    // sit nearer another plane, hence the loose lower bound).
    const double rms = std::sqrt(sum2 / static_cast<double>(s.cloud.size()));
    EXPECT_GT(rms, 0.6 * sigma);
    EXPECT_LT(rms, 1.2 * sigma);
    // Without noise every point is on a plane (float storage: < 0.1 mm).
    const Scan exact = simulateTls(scene, roomCentres(b.spec)[0], coarseTls(0.0), 3);
    for (std::size_t i = 0; i < exact.cloud.size(); i += 7)
      ASSERT_LT(nearestPlane(b.truth, exact.pose.apply(exact.cloud.positions[i].cast<double>())), 1e-4);
  }
}

TEST(Tls, DeterministicForASeedWhateverTheThreads) {
  const auto b = generateBuilding(buildingPreset("two-rooms"));
  const ScanScene scene(b.model, b.glass_triangles);
  const auto station = roomCentres(b.spec)[0];
  TlsParams p = coarseTls(5.0);
  p.incidence_dropout = true;
  const auto [one, two] = oneAndAllThreads([&] { return simulateTls(scene, station, p, 42); });
  const Scan other = simulateTls(scene, station, p, 43);
  expectSameCloud(one, two);
  EXPECT_FALSE(other.cloud.positions == one.cloud.positions);
}

TEST(Tls, IncidenceDropoutRemovesGrazingReturns) {
  const auto b = generateBuilding(buildingPreset("office-floor"));
  const ScanScene scene(b.model, b.glass_triangles);
  TlsParams p = coarseTls(0.0);
  const auto station = roomCentres(b.spec)[5];  // a corridor cell
  const auto all = simulateTls(scene, station, p, 1).cloud.size();
  p.incidence_dropout = true;
  p.dropout_start_deg = 60.0;
  const auto kept = simulateTls(scene, station, p, 1).cloud.size();
  EXPECT_LT(kept, all * 98 / 100);
  EXPECT_GT(kept, all / 3);
}

TEST(RayCaster, BackendsAgree) {
  if (!RayCaster::embreeAvailable()) {
    // Only CGAL is built: check it against a brute-force plane intersection on a box.
    BimModel m = generateBuilding(buildingPreset("two-rooms")).model;
    const RayCaster c(m.mesh, {}, RayCasterBackend::Cgal);
    const RayHit h = c.cast({{2.0, 2.5, 1.5}, Eigen::Vector3d::UnitX()});
    ASSERT_TRUE(h.hit());
    EXPECT_NEAR(h.distance, 4.0 - 0.075 - 2.0, 1e-9);  // interior wall face at x = 3.925
    return;
  }
  const auto b = generateBuilding(buildingPreset("house"));
  const RayCaster cgal(b.model.mesh, b.glass_triangles, RayCasterBackend::Cgal);
  const RayCaster embree(b.model.mesh, b.glass_triangles, RayCasterBackend::Embree);
  std::vector<Ray> rays;
  const Eigen::Vector3d o = roomCentres(b.spec)[2];
  for (int i = 0; i < 5000; ++i) {
    const double az = i * 0.0137, el = std::sin(i * 0.731) * 1.4;
    rays.push_back({o, Eigen::Vector3d(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el))});
  }
  std::vector<RayHit> a, e;
  cgal.castAll(rays, a);
  embree.castAll(rays, e);
  std::size_t same = 0, hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    hits += a[i].hit();
    same += a[i].hit() == e[i].hit() && (!a[i].hit() || std::abs(a[i].distance - e[i].distance) < 1e-6);
  }
  EXPECT_GT(hits, 4000u);
  EXPECT_GE(same, rays.size() - 5);  // edge-grazing rays may pick a neighbouring triangle
  EXPECT_NEAR(cgal.cast({{2.0, 1.0, 1.5}, Eigen::Vector3d::UnitX()}).distance, 4.5 - 0.075 - 2.0, 1e-9);
  // Through the interior door (centred at y = 2) and the glass of the window behind it.
  EXPECT_FALSE(cgal.cast({{2.0, 2.0, 1.5}, Eigen::Vector3d::UnitX()}).hit());
}

TEST(Mms, InteriorPointsAppearThroughWindows) {
  const auto b = generateBuilding(buildingPreset("house"));
  const ScanScene scene(b.model, b.glass_triangles);
  MmsParams p;
  p.line_rate_hz = 20;
  p.pulses_per_line = 720;
  const Trajectory traj = streetTrajectory(b.truth.footprint, p);
  const Scan s = simulateMms(scene, traj, p, 5);
  ASSERT_GT(s.cloud.size(), 20000u);
  ASSERT_TRUE(s.cloud.hasSensorOrigins());
  ASSERT_TRUE(s.cloud.hasTimestamps());
  EXPECT_EQ(s.cloud.grid_columns, 720);
  // Interior points: strictly inside the outer walls (by more than the wall thickness).
  const Bounds fp = [&] { Bounds x; for (const auto& q : b.truth.footprint) x.extend(q); return x; }();
  std::size_t interior = 0, ground = 0, building = 0;
  for (std::size_t i = 0; i < s.cloud.size(); ++i) {
    const Eigen::Vector3d x = s.cloud.world(i);
    ground += s.cloud.classification[i] == 2;
    building += s.cloud.classification[i] == 6;
    interior += x.x() > fp.min.x() + 0.5 && x.x() < fp.max.x() - 0.5 && x.y() > fp.min.y() + 0.5 &&
                x.y() < fp.max.y() - 0.5 && x.z() > 0.3 && x.z() < 5.9;
  }
  EXPECT_GT(interior, 500u);
  EXPECT_GT(ground, 1000u);
  EXPECT_GT(building, interior);
  // Every point is at its range from its sensor origin, within 4 sigma of a truth plane or the ground.
  std::size_t ok = 0;
  for (std::size_t i = 0; i < s.cloud.size(); ++i) {
    const Eigen::Vector3d x = s.cloud.world(i);
    ok += std::min(nearestPlane(b.truth, x), std::abs(x.z())) < 0.04;
  }
  EXPECT_GT(static_cast<double>(ok) / static_cast<double>(s.cloud.size()), 0.99);
  // Opaque glass: no interior points at all.
  ScanSceneOptions opaque;
  opaque.glass_transparent = false;
  const Scan closed = simulateMms(ScanScene(b.model, b.glass_triangles, opaque), traj, p, 5);
  std::size_t closed_interior = 0;
  for (std::size_t i = 0; i < closed.cloud.size(); ++i) {
    const Eigen::Vector3d x = closed.cloud.world(i);
    closed_interior += x.x() > fp.min.x() + 0.5 && x.x() < fp.max.x() - 0.5 && x.y() > fp.min.y() + 0.5 &&
                       x.y() < fp.max.y() - 0.5 && x.z() > 0.3 && x.z() < 5.9;
  }
  EXPECT_LT(closed_interior, interior / 5);  // only through the open entrance door
}

TEST(Mms, DeterministicForASeedWhateverTheThreads) {
  const auto b = generateBuilding(buildingPreset("house"));
  const ScanScene scene(b.model, b.glass_triangles);
  MmsParams p;
  p.line_rate_hz = 10;
  const Trajectory traj = streetTrajectory(b.truth.footprint, p);
  const auto [one, two] = oneAndAllThreads([&] { return simulateMms(scene, traj, p, 9); });
  EXPECT_GT(one.cloud.size(), 10000u);
  expectSameCloud(one, two);
}

// castAll traces fixed chunks as packets: the same hits for 1 and 2 threads, on both backends,
// and (off triangle edges) the same hits as single casts.
TEST(RayCaster, CastAllIsIndependentOfThreadsAndMatchesCast) {
  const auto b = generateBuilding(buildingPreset("office-floor"));
  std::vector<Ray> rays;
  const auto centres = roomCentres(b.spec);
  for (int i = 0; i < 20000; ++i) {
    const double az = i * 2.399963, z = std::sin(i * 0.917);
    const double r = std::sqrt(1 - z * z);
    rays.push_back({centres[static_cast<std::size_t>(i) % centres.size()],
                    Eigen::Vector3d(r * std::cos(az), r * std::sin(az), z)});
  }
  std::vector<RayCasterBackend> backends{RayCasterBackend::Cgal};
  if (RayCaster::embreeAvailable()) backends.push_back(RayCasterBackend::Embree);
  for (auto backend : backends) {
    SCOPED_TRACE(RayCaster::backendName(backend));
    const RayCaster caster(b.model.mesh, b.glass_triangles, backend);
    const auto [one, two] = oneAndAllThreads([&] {
      std::vector<RayHit> hits;
      caster.castAll(rays, hits, 40.0, 0.1);
      return hits;
    });
    std::size_t same = 0, single_same = 0, hits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      same += one[i].triangle == two[i].triangle && one[i].distance == two[i].distance;
      hits += one[i].hit();
      const RayHit c = caster.cast(rays[i], 40.0, 0.1);
      single_same += c.hit() == one[i].hit() && (!c.hit() || std::abs(c.distance - one[i].distance) < 1e-9);
    }
    EXPECT_EQ(same, rays.size());
    EXPECT_GT(hits, rays.size() * 9 / 10);
    EXPECT_GE(single_same, rays.size() - 10);
  }
}

TEST(Mms, TrajectoryFileAndErrors) {
  const auto dir = test::scratchDir("simulation-trajectory");
  test::writeAll(dir / "ok.txt", "# t x y z\n0 0 0 2\n1.5, 3, 0, 2\n3 3 3 2\n");
  const Trajectory t = readTrajectory(dir / "ok.txt");
  ASSERT_EQ(t.times.size(), 3u);
  Eigen::Vector3d pos, heading;
  t.sample(0.75, pos, heading);
  EXPECT_TRUE(pos.isApprox(Eigen::Vector3d(1.5, 0, 2)));
  EXPECT_TRUE(heading.isApprox(Eigen::Vector3d::UnitX()));
  test::writeAll(dir / "bad.txt", "0 0 0 2\n1 2 3\n");
  try {
    readTrajectory(dir / "bad.txt");
    FAIL() << "no error";
  } catch (const FileError& e) {
    EXPECT_EQ(e.where().line.value_or(0), 2u);
  }
}

TEST(Perturbation, TruthRecoversTheUnperturbedScan) {
  const auto b = generateBuilding(buildingPreset("two-rooms"));
  const ScanScene scene(b.model, b.glass_triangles);
  Dataset d;
  d.scans.push_back(simulateTls(scene, roomCentres(b.spec)[0], coarseTls(2.0), 9));
  const PointCloud before = scanInDatasetFrame(d.scans[0]);
  const RigidTransform p = randomPerturbation(30.0, 2.0, 11);
  EXPECT_GT(p.rotationAngleDeg(), 0.0);
  EXPECT_LE(p.rotationAngleDeg(), 30.0 + 1e-9);
  EXPECT_LE(p.translation().cwiseAbs().maxCoeff(), 2.0);
  const RigidTransform truth = perturbDataset(d, p);
  PointCloud after = scanInDatasetFrame(d.scans[0]);
  EXPECT_GT((after.world(0) - before.world(0)).norm(), 1e-3);
  after.transform(truth);
  for (std::size_t i = 0; i < before.size(); i += 101)
    ASSERT_LT((after.world(i) - before.world(i)).norm(), 1e-4);
  EXPECT_TRUE(randomPerturbation(30.0, 2.0, 11).matrix().isApprox(p.matrix()));
}

}  // namespace
}  // namespace plumb
