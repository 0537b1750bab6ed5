#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "registration/planes/plane_hypotheses.hpp"
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

// --- The hypothesis steps alone (registration/planes/plane_hypotheses.hpp) ---

namespace {
namespace prd = plumb::planes_registration_detail;

DirectionClusteringResult clustersAlong(const std::vector<Eigen::Vector3d>& directions) {
  DirectionClusteringResult c;
  for (std::size_t k = 0; k < directions.size(); ++k)
    c.clusters.push_back({directions[k].normalized(), double(directions.size() - k), {int(k)}});
  return c;
}
}  // namespace

TEST(PlaneHypotheses, AssociationsAreMatchedAndIndependent) {
  const double deg = M_PI / 180;
  const auto cs = clustersAlong({
      {1, 0, 0},                          // 0: chosen first
      {std::cos(20 * deg), std::sin(20 * deg), 0},  // 1: within 30° of the first
      {0, 1, 0},                          // 2: not matched by the rotation
      {0, 1, 0.1},                        // 3: chosen second
      {1, 1, 0.05},                       // 4: nearly in the plane of the first two
      {0.2, 0.1, 1},                      // 5: chosen third
      {0, 0, 1},                          // 6: three are enough
  });
  RotationCandidate rot;
  rot.rotation = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  rot.target_of_source = {0, 1, -1, 2, 3, 4, 5};
  const auto a = prd::independentAssociations(cs, rot);
  ASSERT_EQ(a.clusters, (std::vector<int>{0, 3, 5}));
  ASSERT_EQ(a.directions.size(), 3u);
  for (int q = 0; q < 3; ++q)
    EXPECT_NEAR((a.directions[q] - rot.rotation * cs.clusters[a.clusters[q]].direction).norm(), 0.0, 1e-15);
  // Without a third direction out of the plane, fewer than three.
  rot.target_of_source = {0, 1, -1, 2, 3, -1, -1};
  EXPECT_EQ(prd::independentAssociations(cs, rot).clusters, (std::vector<int>{0, 3}));
}

TEST(PlaneHypotheses, TranslationOfThreePlanePairsAndIllConditionedTriples) {
  // Eq. 21 rows n_i · t = rhs_i of three tilted planes with a known translation.
  Eigen::Matrix3d N;
  N.row(0) = Eigen::Vector3d(1, 0.1, 0).normalized().transpose();
  N.row(1) = Eigen::Vector3d(-0.2, 1, 0.05).normalized().transpose();
  N.row(2) = Eigen::Vector3d(0.1, 0, 1).normalized().transpose();
  const Eigen::Vector3d truth(2.5, -1.25, 0.4);
  const auto t = prd::solveTranslation(N, N * truth, 0.2);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR((*t - truth).norm(), 0.0, 1e-12);
  // Two nearly parallel normals: the translation along their common direction is not
  // determined, the triple is rejected.
  N.row(1) = Eigen::Vector3d(1, 0.15, 0).normalized().transpose();
  EXPECT_FALSE(prd::solveTranslation(N, N * truth, 0.2).has_value());
  EXPECT_TRUE(prd::solveTranslation(N, N * truth, 0.0).has_value());
}
