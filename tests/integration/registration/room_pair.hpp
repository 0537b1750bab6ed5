#pragma once
// The real pair room_scan1.pcd / room_scan2.pcd (PCL NDT tutorial, shared/data/README.md), as
// the real-pair and the tilted-source tests read it and compare transforms on it.
#include <cmath>
#include <string>

#include "io/io.hpp"
#include "model/point_cloud.hpp"
#include "model/rigid_transform.hpp"
#include "support/test_support.hpp"

namespace plumb::test {

/// pcd/<name> of the shared data, scans merged, non-finite points removed.
inline PointCloud loadSharedPcd(const std::string& name) {
  PointCloud c = readDataset(sharedData("pcd/" + name)).merged();
  c.removeNonFinite();
  return c;
}

/// RMS distance between where x and y put every 10th point of `c`: a difference of transforms
/// that does not depend on where the origin is.
inline double rmsDisplacement(const RigidTransform& x, const RigidTransform& y, const PointCloud& c) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < c.size(); i += 10, ++n)
    sum += (x.apply(c.world(i)) - y.apply(c.world(i))).squaredNorm();
  return std::sqrt(sum / double(n));
}

}  // namespace plumb::test
