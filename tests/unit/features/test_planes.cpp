#include <gtest/gtest.h>

#include <cmath>

#include "common/error.hpp"
#include "features/planes/plane_extraction.hpp"
#include "synthetic_scenes.hpp"

namespace plumb {
namespace {

struct FacePlane {
  Eigen::Vector3d n;
  double d;  // world
};

std::vector<FacePlane> roomFaces(const test::RoomSpec& s, const Eigen::Vector3d& offset) {
  std::vector<FacePlane> f;
  for (int a = 0; a < 3; ++a) {
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    n[a] = 1;
    f.push_back({n, s.min[a] + offset[a]});
    f.push_back({n, s.max[a] + offset[a]});
  }
  return f;
}

/// Index of the detected plane matching a truth plane (1 degree, 2 cm), or -1.
int match(const std::vector<PlanarPolygon>& planes, const FacePlane& t) {
  for (std::size_t k = 0; k < planes.size(); ++k) {
    const double c = std::abs(planes[k].normal.dot(t.n));
    const double d = planes[k].normal.dot(t.n) > 0 ? planes[k].offset : -planes[k].offset;
    if (c >= std::cos(M_PI / 180.0) && std::abs(d - t.d) <= 0.02) return static_cast<int>(k);
  }
  return -1;
}

test::RoomSpec smallRoom() {
  test::RoomSpec s;
  s.outside = false;
  s.spacing = 0.04;
  return s;
}

TEST(Planes, MsacFindsEveryFaceOfANoisyRoom) {
  const auto spec = smallRoom();
  const PointCloud cloud = test::makeRoom(spec);
  PlaneExtractionParams p;
  p.detector = PlaneDetector::Msac;
  const auto r = extractPlanes(cloud, p);
  EXPECT_EQ(r.detector_used, PlaneDetector::Msac);
  for (const auto& f : roomFaces(spec, Eigen::Vector3d::Zero())) EXPECT_GE(match(r.planes, f), 0) << f.n.transpose() << " " << f.d;
  // Six faces, nothing else large.
  int large = 0;
  for (const auto& pl : r.planes) large += pl.area > 2.0;
  EXPECT_EQ(large, 6);
}

TEST(Planes, WindowWallPolygonHasTheWindowAsAHole) {
  const auto spec = smallRoom();
  const PointCloud cloud = test::makeRoom(spec);
  const auto r = extractPlanes(cloud, {});
  const FacePlane wall{Eigen::Vector3d::UnitX(), spec.max.x()};
  const int k = match(r.planes, wall);
  ASSERT_GE(k, 0);
  const auto& poly = r.planes[k];
  ASSERT_EQ(poly.rings.size(), 2u);
  // Outer counter-clockwise, hole clockwise.
  double a0 = 0, a1 = 0;
  for (int ring = 0; ring < 2; ++ring) {
    const auto& rr = poly.rings[ring];
    double a = 0;
    for (std::size_t i = 0; i < rr.size(); ++i) {
      const auto& p = rr[i];
      const auto& q = rr[(i + 1) % rr.size()];
      a += 0.5 * (p.x() * q.y() - q.x() * p.y());
    }
    (ring ? a1 : a0) = a;
  }
  EXPECT_GT(a0, 0);
  EXPECT_LT(a1, 0);
  const double wall_area = (spec.max.y() - spec.min.y()) * (spec.max.z() - spec.min.z());
  const double window_area = (test::kWindow[1] - test::kWindow[0]) * (test::kWindow[3] - test::kWindow[2]);
  EXPECT_NEAR(poly.area, wall_area - window_area, 0.08 * wall_area);
  // Hole vertices lie on the window outline (within one sample spacing).
  for (const auto& uv : poly.rings[1]) {
    const Eigen::Vector3d p = poly.to3d(uv);
    const double dy = std::min(std::abs(p.y() - test::kWindow[0]), std::abs(p.y() - test::kWindow[1]));
    const double dz = std::min(std::abs(p.z() - test::kWindow[2]), std::abs(p.z() - test::kWindow[3]));
    EXPECT_LT(std::min(dy, dz), spec.spacing + 0.01);
  }
}

TEST(Planes, DeterministicForASeed) {
  const PointCloud cloud = test::makeRoom(smallRoom());
  PlaneExtractionParams p;
  const auto a = extractPlanes(cloud, p, 3);
  const auto b = extractPlanes(cloud, p, 3);
  ASSERT_EQ(a.planes.size(), b.planes.size());
  for (std::size_t k = 0; k < a.planes.size(); ++k) {
    EXPECT_EQ(a.planes[k].inlier_count, b.planes[k].inlier_count);
    EXPECT_EQ(a.planes[k].offset, b.planes[k].offset);
  }
  EXPECT_EQ(a.point_plane, b.point_plane);
}

TEST(Planes, TheSeedArgumentDrivesTheSamples) {
  // Few hypotheses scored on a small random subset: the draws show in the inlier sets, so
  // another seed assigns some point differently (the seed is not ignored).
  const PointCloud cloud = test::makeRoom(smallRoom());
  PlaneExtractionParams p;
  p.iterations = 10;
  p.score_sample = 1000;
  p.auto_threshold = false;
  const auto a = extractPlanes(cloud, p, 1);
  int differing = 0;
  for (std::uint64_t seed = 2; seed <= 4; ++seed)
    differing += extractPlanes(cloud, p, seed).point_plane != a.point_plane;
  EXPECT_GE(differing, 1) << "three other seeds all gave seed 1's planes";
}

TEST(Planes, CoplanarSeparatedPartsBecomeSeparatePolygons) {
  // Two 2x2 m squares in z = 0, 1 m apart.
  PointCloud cloud;
  for (double x = 0; x < 5; x += 0.03)
    for (double y = 0; y < 2; y += 0.03)
      if (x < 2 || x > 3) cloud.positions.emplace_back(float(x), float(y), 0.f);
  PlaneExtractionParams p;
  p.min_inliers = 100;
  const auto r = extractPlanes(cloud, p);
  EXPECT_EQ(r.planes_detected, 1u);
  ASSERT_EQ(r.planes.size(), 2u);
  EXPECT_NEAR(r.planes[0].area, 4.0, 0.3);
  EXPECT_NEAR(r.planes[1].area, 4.0, 0.3);
}

TEST(Planes, SensorTopologyOnAnOrganizedScan) {
  // Organized grid: rows over z, columns over a path that turns a corner (two walls).
  PointCloud cloud;
  const int rows = 60, cols = 200;
  cloud.grid_rows = rows;
  cloud.grid_columns = cols;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const double s = c * 0.03, z = r * 0.03;
      const Eigen::Vector3f p = s < 3.0 ? Eigen::Vector3f(float(s), 0.f, float(z))
                                        : Eigen::Vector3f(3.f, float(s - 3.0), float(z));
      cloud.positions.push_back(p);
      cloud.row.push_back(r);
      cloud.column.push_back(c);
    }
  PlaneExtractionParams p;
  p.min_inliers = 200;
  p.detector = PlaneDetector::SensorTopology;
  const auto r = extractPlanes(cloud, p);
  EXPECT_EQ(r.detector_used, PlaneDetector::SensorTopology);
  ASSERT_GE(r.planes.size(), 2u);
  EXPECT_NEAR(std::abs(r.planes[0].normal.y()) + std::abs(r.planes[1].normal.y()), 1.0, 1e-3);
  EXPECT_GT(r.planes[0].inlier_count + r.planes[1].inlier_count, std::size_t(rows * cols * 9 / 10));
  PlaneExtractionParams bad;
  bad.detector = PlaneDetector::SensorTopology;
  EXPECT_THROW(extractPlanes(test::makeRoom(smallRoom()), bad), InputError);
}

TEST(Planes, RegionGrowingAlternativeFindsTheWalls) {
  const auto spec = smallRoom();
  const PointCloud cloud = test::makeRoom(spec);
  PlaneExtractionParams p;
  p.detector = PlaneDetector::RegionGrowing;
  const auto r = extractPlanes(cloud, p);
  int found = 0;
  for (const auto& f : roomFaces(spec, Eigen::Vector3d::Zero())) found += match(r.planes, f) >= 0;
  EXPECT_GE(found, 5);
}

TEST(Planes, AContrarioPicksAThresholdAndFindsTheRoom) {
  const auto spec = smallRoom();
  const PointCloud cloud = test::makeRoom(spec);
  PlaneExtractionParams p;
  p.auto_threshold = true;
  p.threshold_candidates = 4;
  const auto r = extractPlanes(cloud, p);
  // One of the four candidates 5, 13.6, 36.8, 100 mm, exactly.
  bool candidate = false;
  for (double c : {0.005, 0.005 * std::pow(20.0, 1.0 / 3), 0.005 * std::pow(20.0, 2.0 / 3), 0.1})
    candidate |= std::abs(r.distance_threshold_used - c) < 1e-12;
  EXPECT_TRUE(candidate) << r.distance_threshold_used;
  int found = 0;
  for (const auto& f : roomFaces(spec, Eigen::Vector3d::Zero())) found += match(r.planes, f) >= 0;
  EXPECT_EQ(found, 6);
}

TEST(Planes, AContrarioRangeMustBeOrdered) {
  PlaneExtractionParams p;
  p.auto_threshold = true;
  p.threshold_range_min = 0.05;
  p.threshold_range_max = 0.01;
  try {
    extractPlanes(test::makeRoom(smallRoom()), p);
    FAIL() << "an inverted candidate range must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("threshold-min"), std::string::npos) << e.what();
  }
}

TEST(Planes, InvalidParamsAreRejected) {
  PlaneExtractionParams p;
  p.distance_threshold = -1;
  EXPECT_THROW(extractPlanes(PointCloud{}, p), InputError);
  const auto& s = PlaneExtractionParams::schema();
  EXPECT_NE(s.find("distance-threshold"), nullptr);
  EXPECT_NE(s.find("detector"), nullptr);
}

TEST(Planes, CancelStopsTheExtraction) {
  const PointCloud cloud = test::makeRoom(smallRoom());
  Progress progress;
  progress.cancel();
  EXPECT_THROW(extractPlanes(cloud, {}, kDefaultSeed, &progress), Canceled);
}

}  // namespace
}  // namespace plumb
