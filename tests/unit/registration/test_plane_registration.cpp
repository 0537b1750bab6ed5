#include <gtest/gtest.h>

#include <random>

#include "registration/planes/plane_registration.hpp"
#include "unit/registration/random_pose_trials.hpp"
#include "unit/registration/synthetic_building.hpp"

using namespace plumb;

namespace {
FeatureSet roomsSubset(const std::vector<int>& idx) {
  const auto all = test::asymmetricRooms();
  std::vector<test::Room> rooms;
  for (int i : idx) rooms.push_back(all[i]);
  return test::roomFeatures(rooms);
}
}  // namespace

TEST(PlaneRegistration, RecoversRandomPosesWithNoiseDropsAndOutliers) {
  test::Perturbation pert;
  pert.drop_fraction = 0.15;
  const int ok = test::randomPoseSuccesses(
      11, 20, pert, [](const FeatureSet& source, const FeatureSet& target, int) {
        PlaneRegistrationParams p;
        // Two storeys: with unsigned normals the ceilings at 2.8 m and the floors above at
        // 3.0 m are the same plane up to the slab; the synthetic normals face the rooms like
        // normals oriented towards indoor scanners.
        p.oriented_normals = true;
        return registerPlanes(source.planes, target.planes, p);
      });
  EXPECT_GE(ok, 19) << "successes out of 20";
}

TEST(PlaneRegistration, PartialOverlapIndoorIndoor) {
  // Two stations on the ground floor seeing overlapping sets of rooms, unoriented normals.
  const FeatureSet a = roomsSubset({0, 1, 2});
  const FeatureSet b = roomsSubset({1, 2, 3});
  std::mt19937_64 rng(5);
  int ok = 0;
  for (int run = 0; run < 10; ++run) {
    const RigidTransform pose = test::randomPose(rng);
    FeatureSet source = test::perturb(a, {}, rng);
    const FeatureSet target = test::perturb(b, {}, rng);
    source.transform(pose.inverse());
    const auto r = registerPlanes(source.planes, target.planes, {});
    const bool good = RigidTransform::rotationErrorDeg(r.transform, pose) < 0.1 &&
                      RigidTransform::translationError(r.transform, pose) < 0.02;
    if (r.ok()) {
      EXPECT_TRUE(good) << run << ": " << r.message << " rot err "
                        << RigidTransform::rotationErrorDeg(r.transform, pose) << " trans err "
                        << RigidTransform::translationError(r.transform, pose) << " truth score "
                        << planeSimilarity(source.planes, target.planes, pose, {});
    }
    ok += r.ok() && good;
  }
  EXPECT_GE(ok, 9);
}

TEST(PlaneRegistration, SymmetricRoomIsReportedAmbiguousNotConfident) {
  // A single empty box room without windows has a 180° symmetry about Z: two transforms explain
  // the data equally well, so the result must not be a confident success.
  const FeatureSet box = test::roomFeatures({{{0, 0, 0}, {6, 4, 3}}}, false);
  const RigidTransform pose = RigidTransform::fromYaw(0.7, {3, -2, 0.5});
  FeatureSet source = box;
  source.transform(pose.inverse());
  const auto r = registerPlanes(source.planes, box.planes, {});
  EXPECT_EQ(r.status, RegistrationStatus::Ambiguous) << r.message;
  ASSERT_TRUE(r.runner_up.has_value());
  EXPECT_LT(r.relative_gap, 0.05);
}

TEST(PlaneRegistration, TooFewDirectionsIsAFailure) {
  // Only parallel walls: translation along the walls is undetermined.
  std::vector<PlanarPolygon> walls;
  for (int i = 0; i < 4; ++i)
    walls.push_back(test::makeRectPolygon({0, double(i), 0}, {1, 0, 0}, {0, 0, 1}, 5, 3));
  const auto r = registerPlanes(walls, walls, {});
  EXPECT_EQ(r.status, RegistrationStatus::TooFewFeatures) << r.message;
}
