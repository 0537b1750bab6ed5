// Plane extraction on a real indoor scan (PCL tutorial room_scan1.pcd, shared/data/README.md).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "features/planes/plane_extraction.hpp"
#include "io/io.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

TEST(FeaturesReal, RoomScanDominantWallDirectionsAreOrthogonal) {
  const Dataset d = readDataset(test::sharedData("pcd/room_scan1.pcd"));
  const PointCloud cloud = d.merged();
  ASSERT_EQ(cloud.size(), 112586u);  // README: 112,586 points
  PlaneExtractionParams p;
  p.distance_threshold = 0.05;  // real robot scan: centimetre noise
  p.min_inliers = 500;
  const auto r = extractPlanes(cloud, p);
  // Vertical planes, weighted by inliers; the two largest directions (modulo sign) that are
  // more than 30 degrees apart.
  std::vector<const PlanarPolygon*> walls;
  for (const auto& pl : r.planes)
    if (pl.isVertical(5.0)) walls.push_back(&pl);
  ASSERT_GE(walls.size(), 2u);
  const Eigen::Vector3d a = walls[0]->normal;
  const PlanarPolygon* second = nullptr;
  for (const auto* w : walls)
    if (std::abs(w->normal.dot(a)) < std::cos(30.0 * M_PI / 180.0)) {
      second = w;
      break;
    }
  ASSERT_NE(second, nullptr);
  const double angle = std::acos(std::abs(a.dot(second->normal))) * 180.0 / M_PI;
  std::cout << "room_scan1: " << r.planes.size() << " polygons, " << walls.size()
            << " vertical, dominant wall directions " << angle << " deg apart\n";
  EXPECT_NEAR(angle, 90.0, 2.0);
}

}  // namespace
}  // namespace plumb
