#include <gtest/gtest.h>

#include "common/error.hpp"
#include "features/facades/opening_detection.hpp"
#include "features/planes/plane_extraction.hpp"
#include "synthetic_scenes.hpp"

namespace plumb {
namespace {

/// Truth corners of the synthetic window, seen from inside the room (looking at +X):
/// right is -Y, so bottom-left has the larger y.
std::array<Eigen::Vector3d, 4> windowCorners(const test::RoomSpec& s, const Eigen::Vector3d& off) {
  const double x = s.max.x();
  const auto& w = test::kWindow;
  return {Eigen::Vector3d(x, w[1], w[2]) + off, Eigen::Vector3d(x, w[0], w[2]) + off,
          Eigen::Vector3d(x, w[0], w[3]) + off, Eigen::Vector3d(x, w[1], w[3]) + off};
}

double maxCornerError(const Opening& o, const std::array<Eigen::Vector3d, 4>& truth) {
  double e = 0;
  for (int i = 0; i < 4; ++i) e = std::max(e, (o.corners[i] - truth[i]).norm());
  return e;
}

TEST(Openings, RayTracingFindsTheWindowAndInteriorPoints) {
  test::RoomSpec spec;
  const PointCloud cloud = test::makeRoom(spec);
  const auto planes = extractPlanes(cloud, {}).planes;
  OpeningDetectionParams p;
  p.source = OpeningSource::RayTracing;
  const auto r = detectOpenings(cloud, planes, p);
  EXPECT_TRUE(r.ray_tracing_ran);
  EXPECT_GE(r.facades.size(), 4u);  // the four walls (+ the surface outside), not floor/ceiling
  ASSERT_EQ(r.openings.size(), 1u);
  EXPECT_LT(maxCornerError(r.openings[0], windowCorners(spec, Eigen::Vector3d::Zero())), 0.05);
  // Every point beyond the window (x > max + 1) is an interior point, and nothing else.
  std::size_t beyond = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) beyond += cloud.world(i).x() > spec.max.x() + 1.0;
  EXPECT_EQ(r.interior_points.size(), beyond);
  const auto& f = planes[r.openings[0].facade];
  EXPECT_TRUE(f.isVertical(3.0));
}

TEST(Openings, WithoutSensorOriginsRayTracingReportsThatItCannotRun) {
  test::RoomSpec spec;
  spec.sensor_origins = false;
  spec.outside = false;
  const PointCloud cloud = test::makeRoom(spec);
  const auto planes = extractPlanes(cloud, {}).planes;
  OpeningDetectionParams p;
  p.source = OpeningSource::RayTracing;
  EXPECT_THROW(detectOpenings(cloud, planes, p), InputError);
  // Auto: says so, and still finds the window as a hole of the wall polygon.
  p.source = OpeningSource::Auto;
  const auto r = detectOpenings(cloud, planes, p);
  EXPECT_FALSE(r.ray_tracing_ran);
  ASSERT_FALSE(r.messages.empty());
  EXPECT_NE(r.messages[0].find("sensor origins"), std::string::npos);
  EXPECT_TRUE(r.interior_points.empty());
  ASSERT_EQ(r.openings.size(), 1u);
  EXPECT_LT(maxCornerError(r.openings[0], windowCorners(spec, Eigen::Vector3d::Zero())), 0.05);
}

}  // namespace
}  // namespace plumb
