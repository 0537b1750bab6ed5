// Clipping boxes and slices (clip_box.hpp): exactly the points inside, faces included, in the
// dataset frame at national-grid coordinates, every attribute kept.
#include <gtest/gtest.h>

#include "model/clip_box.hpp"

namespace plumb {
namespace {

/// A 2 x 2 m floor of 0.1 m spacing (21 x 21 points) at z = 0 and the same at z = 3 (a ceiling),
/// at national-grid coordinates, turned by the scan pose; intensity = point index.
Dataset floorAndCeiling() {
  Dataset d;
  d.scans.push_back({});
  Scan& s = d.scans[0];
  s.cloud.offset = {651000.0, 6860000.0, 40.0};
  s.pose = RigidTransform::fromYaw(M_PI / 2, {0, 0, 0});
  for (int z : {0, 3})
    for (int i = 0; i <= 20; ++i)
      for (int j = 0; j <= 20; ++j) {
        s.cloud.positions.push_back(Eigen::Vector3f(0.1f * i, 0.1f * j, float(z)));
        s.cloud.intensity.push_back(float(s.cloud.intensity.size()));
      }
  return d;
}

TEST(ClipBox, APlanSliceKeepsExactlyOneLevel) {
  const Dataset d = floorAndCeiling();
  const double floor_z = 40.0, ceiling_z = 43.0;
  EXPECT_EQ(countInside(d, slab(2, floor_z, 0.2)), 441u);
  EXPECT_EQ(countInside(d, slab(2, ceiling_z, 0.2)), 441u);
  EXPECT_EQ(countInside(d, slab(2, 41.5, 2.0)), 0u) << "between the levels";
  EXPECT_EQ(countInside(d, slab(2, 41.5, 3.0)), 882u) << "faces included";
  // A registration applied to the whole dataset moves what is inside.
  EXPECT_EQ(countInside(d, slab(2, ceiling_z + 5.0, 0.2), RigidTransform::fromYaw(0.0, {0, 0, 5.0})), 441u);
  EXPECT_EQ(countInside(d, slab(2, ceiling_z, 0.2), RigidTransform::fromYaw(0.0, {0, 0, 5.0})), 0u);
  const Dataset ceiling = clipDataset(d, slab(2, ceiling_z, 0.2));
  ASSERT_EQ(ceiling.scans[0].cloud.size(), 441u);
  EXPECT_EQ(ceiling.scans[0].cloud.intensity[0], 441.0f) << "attributes follow their points";
  EXPECT_EQ(ceiling.scans[0].pose.matrix(), d.scans[0].pose.matrix());
  EXPECT_NEAR(ceiling.scans[0].pose.apply(ceiling.scans[0].cloud.world(0)).z(), ceiling_z, 1e-9);
}

TEST(ClipBox, ASectionCutsAcrossOneAxisInTheDatasetFrame) {
  const Dataset d = floorAndCeiling();
  // The pose turns local x into world y: local column i = 10 (x = 1 m) lies at world y = 6860001.
  const ClipBox section = slab(1, 651000.0 + 1.0, 0.05);
  EXPECT_EQ(countInside(d, section), 2u * 21u) << "one row of points on each level";
  const ClipBox wrong_axis = slab(0, 651000.0 + 1.0, 0.05);
  EXPECT_EQ(countInside(d, wrong_axis), 0u) << "world x is -local y - 6860000: nothing there";
  ClipBox box;
  box.min = {-6860000.0 - 0.55, 651000.0 + 0.45, 39.0};
  box.max = {-6860000.0 - 0.25, 651000.0 + 0.75, 41.0};
  EXPECT_EQ(countInside(d, box), 3u * 3u) << "x' = -y - 6860000 in [-0.55, -0.25], y' = x in [0.45, 0.75]";
}

}  // namespace
}  // namespace plumb
