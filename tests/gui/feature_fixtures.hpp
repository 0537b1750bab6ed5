#pragma once
// Known features shared by the GUI tests: a wall with a window, and an eave line above it.
#include <memory>

#include "model/feature_set.hpp"

namespace plumb::test {

/// A 10 m x 6 m vertical wall in the plane y = 0 (`inliers` points), a 2 m x 2 m window
/// (x 2..4 m, z 1..3 m) 1 cm in front of it (y = -0.01), and, if `eave`, a 10 m segment
/// from (0, 0, 7) to (10, 0, 7).
inline std::shared_ptr<FeatureSet> wallWithWindow(std::size_t inliers, bool eave) {
  auto features = std::make_shared<FeatureSet>();
  PlanarPolygon wall;
  wall.normal = Eigen::Vector3d::UnitY();
  wall.origin = Eigen::Vector3d::Zero();
  wall.u_axis = Eigen::Vector3d::UnitX();
  wall.v_axis = Eigen::Vector3d::UnitZ();
  wall.rings = {{{0, 0}, {10, 0}, {10, 6}, {0, 6}}};
  wall.area = 60.0;
  wall.inlier_count = inliers;
  features->planes.push_back(wall);
  Opening window;
  window.corners = {Eigen::Vector3d(2, -0.01, 1), Eigen::Vector3d(4, -0.01, 1),
                    Eigen::Vector3d(4, -0.01, 3), Eigen::Vector3d(2, -0.01, 3)};
  window.facade = 0;
  features->openings.push_back(window);
  if (eave) {
    Segment3D s;
    s.a = Eigen::Vector3d(0, 0, 7);
    s.b = Eigen::Vector3d(10, 0, 7);
    features->segments.push_back(s);
  }
  return features;
}

}  // namespace plumb::test
