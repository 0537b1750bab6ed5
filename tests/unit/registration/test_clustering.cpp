#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "registration/clustering/direction_clustering.hpp"
#include "registration/common/rotation_from_directions.hpp"
#include "unit/registration/synthetic_building.hpp"

using namespace plumb;

TEST(DirectionClustering, GroupsWallsFloorsAndFindsHorizontal) {
  const FeatureSet f = test::roomFeatures(test::asymmetricRooms());
  const auto r = clusterPlaneNormals(f.planes, {});
  ASSERT_EQ(r.clusters.size(), 3u);
  ASSERT_GE(r.horizontal, 0);
  EXPECT_NEAR(std::abs(r.clusters[r.horizontal].direction.z()), 1.0, 1e-9);
  std::size_t members = 0;
  for (const auto& c : r.clusters) members += c.members.size();
  EXPECT_EQ(members, f.planes.size());
}

TEST(DirectionClustering, SignInvariantMeanAndOneAngleTolerance) {
  // Directions within 5° of X with both signs, and one at 30° that must stay out at 10°.
  std::vector<DirectionItem> items;
  for (int k = -2; k <= 2; ++k) {
    const double a = k * 2.0 * M_PI / 180.0;
    items.push_back({Eigen::Vector3d(std::cos(a), std::sin(a), 0) * (k % 2 ? -1.0 : 1.0), 1.0});
  }
  items.push_back({Eigen::Vector3d(std::cos(0.5236), std::sin(0.5236), 0), 0.5});
  DirectionClusteringParams p;
  p.max_clusters = 1;
  const auto r = clusterDirections(items, p);
  ASSERT_EQ(r.clusters.size(), 1u);
  EXPECT_EQ(r.clusters[0].members.size(), 5u);
  EXPECT_EQ(r.cluster_of_item.back(), -1);
  EXPECT_NEAR(std::abs(r.clusters[0].direction.x()), 1.0, 1e-9);
}

TEST(RotationEnumeration, ContainsTheTrueRotationForAnyYaw) {
  const std::vector<Eigen::Vector3d> src = {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(),
                                            Eigen::Vector3d::UnitY()};
  for (double yaw_deg : {-179.0, -95.0, 0.0, 37.0, 170.0}) {
    const Eigen::Matrix3d R =
        Eigen::AngleAxisd(yaw_deg * M_PI / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    std::vector<Eigen::Vector3d> tgt;
    for (const auto& d : src) tgt.push_back(R * d);
    tgt[1] = -tgt[1];  // cluster signs are arbitrary
    std::swap(tgt[1], tgt[2]);
    const auto cands = enumerateRotations(src, tgt, {});
    EXPECT_EQ(cands.size(), 4u);  // 2 pairings x 2 signs, Z kept up
    double best = 1e9;
    for (const auto& c : cands)
      best = std::min(best, Eigen::AngleAxisd(c.rotation.transpose() * R).angle());
    EXPECT_LT(best, 1e-9) << yaw_deg;
  }
}

TEST(RotationEnumeration, UpDownFlipWhenAllowed) {
  const std::vector<Eigen::Vector3d> src = {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(),
                                            Eigen::Vector3d::UnitY()};
  RotationEnumerationParams p;
  p.allow_up_down_flip = true;
  EXPECT_EQ(enumerateRotations(src, src, p).size(), 8u);
  p.up_axis_known = false;
  EXPECT_EQ(enumerateRotations(src, src, p).size(), 24u);  // the cube's rotation group
}
