// Refinement against the model surface (issue 14): point-to-triangle correspondences on the
// triangles the scan's stations see (registration/refine/triangle_target.hpp), against the
// refinement on points sampled on the model.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cstdio>

#include "model/dataset.hpp"
#include "registration/refine/icp_refinement.hpp"
#include "registration/refine/triangle_target.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/presets.hpp"
#include "simulation/scan_scene.hpp"
#include "simulation/tls_scanner.hpp"

using namespace plumb;

namespace {

/// Solid boxes (walls, slabs) as a mesh wound outwards: each triangle's normal points out of
/// its box.
BimModel solidBoxes(const std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>& boxes) {
  BimModel m;
  for (const auto& [lo, hi] : boxes) {
    const auto base = std::uint32_t(m.mesh.vertices.size());
    for (int k = 0; k < 8; ++k)
      m.mesh.vertices.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
    const int f[12][3] = {{0, 3, 1}, {0, 2, 3}, {4, 7, 6}, {4, 5, 7}, {0, 5, 4}, {0, 1, 5},
                          {2, 7, 3}, {2, 6, 7}, {0, 6, 2}, {0, 4, 6}, {1, 7, 5}, {1, 3, 7}};
    for (const auto& t : f) m.mesh.triangles.push_back({base + t[0], base + t[1], base + t[2]});
  }
  m.triangle_element.assign(m.mesh.triangles.size(), 0);
  m.elements.push_back({"IfcWall", "boxes", ""});
  return m;
}

/// A 12 cm thick wall (y in [0, 0.12]) standing on a floor, with a wall at x = 0: the station
/// at (2, -2, 1.2) sees the wall's face y = 0 only, and nothing else holds the scan along y.
BimModel thinWallScene() {
  return solidBoxes({{{0, 0, 0}, {4, 0.12, 2.5}}, {{-1, -5, -0.1}, {5, 4, 0}}, {{-0.12, -4.12, 0}, {0, 0.12, 2.5}}});
}
const Eigen::Vector3d kStation(2.0, -2.0, 1.2);

PointCloud scanFrom(const BimModel& model, const Eigen::Vector3d& station, const std::vector<bool>& glass = {}) {
  const ScanScene scene(model, glass);
  TlsParams tp;
  tp.azimuth_step_deg = tp.elevation_step_deg = 0.5;
  tp.noise_mm = 3.0;
  Dataset d;
  d.scans.push_back(simulateTls(scene, station, tp, 5));
  PointCloud c = d.merged(true);  // sensor origins from the station pose
  c.removeNonFinite();
  return c;
}

/// Triangle t of the first box (the thin wall) lies in the plane y = v.
bool wallFaceAt(const TriangleMesh& m, std::uint32_t t, double v) {
  if (t >= 12) return false;
  for (auto i : m.triangles[t])
    if (std::abs(m.vertices[i].y() - v) > 1e-9) return false;
  return true;
}

RigidTransform shiftY(double dy) { return RigidTransform(Eigen::Matrix3d::Identity(), {0.0, dy, 0.0}); }

}  // namespace

TEST(SurfaceRefinement, TheHiddenFaceOfAThinWallIsNotVisible) {
  const BimModel model = thinWallScene();
  const PointCloud scan = scanFrom(model, kStation);
  ASSERT_TRUE(scan.hasSensorOrigins());
  const Eigen::Vector3d origin = model.mesh.bounds().center();
  const refine_detail::TriangleTarget target(model.mesh, origin);
  refine_detail::SourceRays rays;
  for (std::size_t i = 0; i < scan.size(); i += 7) {
    rays.points.push_back(scan.world(i) - origin);
    rays.origins.push_back(scan.offset + scan.sensor_origins[i].cast<double>() - origin);
  }
  // Under a pose 8 cm into the wall (the scan's wall points nearer the far face).
  const auto v = refine_detail::visibleTriangles(target.caster(), rays, Eigen::Matrix3d::Identity(),
                                                 Eigen::Vector3d(0.0, 0.08, 0.0));
  int near_face = 0, far_face = 0;
  for (auto t : v.triangles) {
    near_face += wallFaceAt(model.mesh, t, 0.0);
    far_face += wallFaceAt(model.mesh, t, 0.12);
  }
  EXPECT_EQ(near_face, 2);
  EXPECT_EQ(far_face, 0);
  EXPECT_EQ(v.back_facing, 0u);  // outward winding: every first hit is a front face
  EXPECT_LT(v.triangles.size(), model.mesh.triangles.size() / 2);
}

// Started with the scan pushed 8 cm into the 12 cm wall, its points lie nearer the hidden face:
// points sampled on the model (both faces) pull the scan onto it; the visible triangles pull it
// back to the truth.
TEST(SurfaceRefinement, AScanOfOneWallFaceDoesNotMatchTheOtherFace) {
  const BimModel model = thinWallScene();
  const PointCloud scan = scanFrom(model, kStation);
  RefineParams p;
  const RefineResult r = refineRegistration(scan, RefineTarget(model.mesh, p), shiftY(0.08), p);
  const RefineResult s = refineRegistration(scan, RefineTarget(sampleMeshSurface(model.mesh, 0.05, 1), p),
                                            shiftY(0.08), p);
  const double r_m = RigidTransform::translationError(r.transform, RigidTransform());
  const double s_m = RigidTransform::translationError(s.transform, RigidTransform());
  std::printf("visible triangles: %.2f mm, %.4f deg; samples: %.2f mm\n", 1000 * r_m,
              RigidTransform::rotationErrorDeg(r.transform, RigidTransform()), 1000 * s_m);
  EXPECT_EQ(r.surface, "visible triangles");
  EXPECT_LT(r_m, 0.002);
  EXPECT_LT(RigidTransform::rotationErrorDeg(r.transform, RigidTransform()), 0.01);
  EXPECT_GT(s_m, 0.1);  // the trap is real: the samples path ends on the hidden face
}

// Without sensor origins every triangle is a candidate, but a point behind its closest triangle
// by more than kFacingTolerance does not match it: inside the wall, nearer the hidden face, it
// matches nothing; in front of the seen face, it matches that face.
TEST(SurfaceRefinement, WithoutSensorOriginsOnlyFrontFacesMatch) {
  const BimModel model = thinWallScene();
  const refine_detail::TriangleTarget target(model.mesh, Eigen::Vector3d::Zero());
  const auto surface = target.frontFacingSurface();
  Eigen::Vector3d q, n;
  EXPECT_FALSE(surface->nearest({2.0, 0.08, 1.2}, 0.5, q, n));  // 4 cm behind the hidden face
  ASSERT_TRUE(surface->nearest({2.0, -0.03, 1.2}, 0.5, q, n));   // 3 cm in front of the seen face
  EXPECT_NEAR(q.y(), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(n.y()), 1.0, 1e-12);
  ASSERT_TRUE(surface->nearest({2.0, 0.01, 1.2}, 0.5, q, n));  // 1 cm behind: noise, kept
  EXPECT_NEAR(q.y(), 0.0, 1e-12);
  PointCloud scan = scanFrom(model, kStation);
  scan.sensor_origins.clear();
  RefineParams p;
  const RefineResult r = refineRegistration(scan, RefineTarget(model.mesh, p), shiftY(0.01), p);
  EXPECT_EQ(r.surface, "front-facing triangles");
  EXPECT_LT(RigidTransform::translationError(r.transform, RigidTransform()), 0.002);
}

// The house preset, one ground-floor station (3 mm noise): from 0.3 deg / 3 cm off, the
// refinement on the visible triangles ends within 0.01 deg and 2 mm of the truth, and stays
// there when started at the truth; the samples path is printed beside it.
TEST(SurfaceRefinement, ConvergesToTheTruthOnAGeneratedHouse) {
  GeneratedBuilding b = generateBuilding(buildingPreset("house"));
  const Eigen::Vector3d station = roomCentres(b.spec, 0).front();
  const PointCloud scan = scanFrom(b.model, station, b.glass_triangles);
  const Eigen::Vector3d c = scan.bounds().center();
  const RigidTransform off = RigidTransform(Eigen::Matrix3d::Identity(), c + Eigen::Vector3d(0.02, -0.02, 0.01)) *
                             RigidTransform(Eigen::AngleAxisd(0.3 * M_PI / 180, Eigen::Vector3d(1, 2, 3).normalized())
                                                .toRotationMatrix(),
                                            -c);
  RefineParams p;
  const RefineTarget triangles(b.model.mesh, p);
  const RefineTarget samples(sampleMeshSurface(b.model.mesh, 0.05, 1), p);
  for (const RigidTransform& start : {off, RigidTransform()}) {
    const RefineResult t = refineRegistration(scan, triangles, start, p);
    const RefineResult s = refineRegistration(scan, samples, start, p);
    const double t_rot = RigidTransform::rotationErrorDeg(t.transform, RigidTransform());
    const double t_mm = 1000 * (t.transform.apply(c) - c).norm();
    std::printf("triangles: %.4f deg %.2f mm; samples: %.4f deg %.2f mm\n", t_rot, t_mm,
                RigidTransform::rotationErrorDeg(s.transform, RigidTransform()),
                1000 * (s.transform.apply(c) - c).norm());
    EXPECT_LT(t_rot, 0.01);
    EXPECT_LT(t_mm, 2.0);
    EXPECT_TRUE(t.converged);
  }
}
