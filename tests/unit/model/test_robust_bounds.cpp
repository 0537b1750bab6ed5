// Robust bounds (robust_bounds.hpp): a house scan with a few far returns is framed on the
// house, in the dataset frame (scan poses and georeferenced offsets applied).
#include <gtest/gtest.h>

#include <cmath>

#include "model/robust_bounds.hpp"

namespace plumb {
namespace {

/// A 10 x 8 m floor of 0.1 m spacing at z = 0, plus `far` returns 100 m away.
PointCloud floorWithOutliers(int far) {
  PointCloud c;
  for (int i = 0; i <= 100; ++i)
    for (int j = 0; j <= 80; ++j) c.positions.push_back(Eigen::Vector3f(0.1f * i, 0.1f * j, 0.0f));
  for (int k = 0; k < far; ++k) c.positions.push_back(Eigen::Vector3f(100.0f + k, -100.0f, 30.0f));
  return c;
}

TEST(RobustBounds, FarReturnsDoNotWidenTheFrame) {
  Dataset d;
  d.scans.push_back({});
  d.scans[0].cloud = floorWithOutliers(5);
  const Bounds exact = d.bounds();
  EXPECT_GT(exact.size().x(), 100.0) << "the exact bounds keep the outliers";
  const Bounds b = robustBounds(datasetSamples(d));
  // 1 % trimmed at each end, then a 5 % margin: about the floor's own extent.
  EXPECT_NEAR(b.min.x(), -0.4, 0.15);
  EXPECT_NEAR(b.max.x(), 10.4, 0.15);
  EXPECT_NEAR(b.min.y(), -0.3, 0.15);
  EXPECT_NEAR(b.max.y(), 8.3, 0.15);
  EXPECT_LT(b.size().z(), 0.05) << "a flat floor: the 1 cm minimum margin";
}

TEST(RobustBounds, InTheDatasetFrameAtNationalGridCoordinates) {
  Dataset d;
  d.scans.push_back({});
  d.scans[0].cloud = floorWithOutliers(0);
  d.scans[0].cloud.offset = {651000.0, 6860000.0, 40.0};
  d.scans[0].pose = RigidTransform::fromYaw(M_PI / 2, {10.0, 0.0, 0.0});
  const Bounds b = robustBounds(datasetSamples(d), 0.0, 0.05);  // no tail: the whole floor
  // Rotated by 90 deg about z then shifted: x' = -y + 10, y' = x.
  EXPECT_NEAR(b.center().x(), -6860000.0 - 4.0 + 10.0, 0.01);
  EXPECT_NEAR(b.center().y(), 651000.0 + 5.0, 0.01);
  EXPECT_NEAR(b.size().x(), 8.0 * 1.1, 0.02);
  EXPECT_NEAR(b.size().y(), 10.0 * 1.1, 0.02);
}

TEST(RobustBounds, NonFiniteSamplesAreIgnoredAndNoneGivesEmpty) {
  EXPECT_TRUE(robustBounds({}).empty());
  const double nan = std::nan("");
  EXPECT_TRUE(robustBounds({{nan, 0, 0}}).empty());
  const Bounds b = robustBounds({{nan, 0, 0}, {1, 2, 3}}, 0.01, 0.0);
  EXPECT_NEAR(b.min.x(), 0.99, 1e-12);
  EXPECT_NEAR(b.max.z(), 3.01, 1e-12);
}

}  // namespace
}  // namespace plumb
